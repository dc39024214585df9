//! Wavefront OBJ meshes, written and read.
//!
//! OBJ is the plainest mesh format every 3-D viewer and modeller opens. It is a few kinds of
//! text lines, so it is written and parsed by hand rather than through a crate.
//!
//! Writing: `v` lines for the points, `vn` lines for one normal per point (see
//! `mesh/normals.rs`) and `f a//a b//b c//c` lines for the triangles (see
//! `mesh/triangulate.rs` for a sample grid), all counter-clockwise seen from the side the
//! normals point to. The first line is a comment: `# karkas surface, NU x NV samples` for a
//! sample grid, `# karkas mesh, N vertices, M triangles` for a general mesh. The seam of a
//! closed sample grid (its last row or column repeating the first) is welded: the repeated
//! samples are not written and the triangles along the seam share the first row's (column's)
//! vertices (the comment then says `closed in u` / `closed in v`), so the mesh is closed for
//! mesh tools.
//!
//! Reading, one line at a time (each line bounded, see [`crate::input`]; what is kept is
//! charged against the memory cap as it grows; a line that is not UTF-8 is refused only when
//! it is one of the lines read, so names in another encoding pass):
//! - as a mesh ([`read_obj_mesh`], [`parse_obj_mesh`]): `v` and `f` lines. A `v` line holds
//!   `x y z`, `x y z w` or `x y z r g b` (the vertex colours some scanners and MeshLab write,
//!   also `x y z r g b a`): the position is `x y z` as written. `w` is the weight of a
//!   rational curve's control point in the OBJ specification, not a homogeneous coordinate,
//!   so it is not divided out (as Blender, meshio and trimesh read it). `f` corners are `a`,
//!   `a/b`, `a//c` or `a/b/c`, negative indices counting back from the last vertex. A face of
//!   n > 3 corners (quads, n-gons) becomes the n - 2 triangles of the fan from its first
//!   corner: right for the convex polygons exporters write (a concave polygon would need its
//!   own triangulation, which OBJ files do not carry). `vn` normals are kept when every corner
//!   of every face uses the normal of the same index as its vertex (as karkas writes them),
//!   otherwise normals are recomputed. Lines of other kinds (`vt`, `vp`, `l`, `p`, `g`, `o`,
//!   `s`, `usemtl`, `mtllib`, curves and surfaces) are skipped;
//! - as a point set ([`parse_obj_vertices`]): only the `v` lines (faces, normals and texture
//!   coordinates are not needed to measure distances and are skipped).

use std::io::{self, BufRead, Write};
use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError, Location};
use crate::input::{check_held, excerpt, not_utf8_message, read_line_bytes, Input};
use crate::lines::parse_coordinate;
use crate::mesh::normals::grid_normals;
use crate::mesh::shared_vertices::SharedVertices;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::triangulate::{check_grid, GridSeams};
use crate::write::write_atomic;

/// Writes the `nu x nv` sample grid `points` (row-major, `u` outer) as an OBJ mesh at `path`,
/// atomically, its seams welded (see the module docs). A `points.len()` other than `nu * nv`
/// is an [`IoError::InvalidMesh`]
/// ([`MeshError::PointCount`](crate::mesh::error::MeshError::PointCount)), nothing written.
pub fn write_surface_obj(
    path: &Path,
    nu: usize,
    nv: usize,
    points: &[Point3],
) -> Result<(), IoError> {
    check_grid(nu, nv, points.len()).map_err(IoError::invalid_mesh(path))?;
    write_atomic(path, |out| render_surface_obj(nu, nv, points, out))
}

/// Writes the OBJ text of the `nu x nv` sample grid `points` into `out`, its seams welded.
///
/// Fails with [`io::ErrorKind::InvalidInput`] (carrying [`MeshError::PointCount`](crate::mesh::error::MeshError::PointCount)) when
/// `points.len() != nu * nv`.
pub fn render_surface_obj(
    nu: usize,
    nv: usize,
    points: &[Point3],
    out: &mut dyn Write,
) -> io::Result<()> {
    check_grid(nu, nv, points.len()).map_err(|e| io::Error::new(io::ErrorKind::InvalidInput, e))?;
    let seams = GridSeams::detect(nu, nv, points);
    writeln!(out, "{}", surface_comment(seams))?;
    let kept = move |k: &usize| !seams.welds() || seams.is_kept(*k);
    let positions = (0..points.len()).filter(kept).map(|k| points[k]);
    let normals = grid_normals(nu, nv, points)
        .enumerate()
        .filter(|(k, _)| kept(k))
        .map(|(_, n)| n);
    render_body(positions, normals, seams.triangles(), out)
}

/// The first line of the OBJ file of a sample grid.
fn surface_comment(seams: GridSeams) -> String {
    let closed = match (seams.closed_u, seams.closed_v) {
        (false, false) => "",
        (true, false) => ", closed in u (seam welded)",
        (false, true) => ", closed in v (seam welded)",
        (true, true) => ", closed in u and v (seams welded)",
    };
    format!(
        "# karkas surface, {} x {} samples{closed}",
        seams.nu, seams.nv
    )
}

/// Writes the triangle mesh `mesh` as OBJ at `path`, atomically (see the module docs; normals
/// from the mesh or face-averaged, see [`TriangleMesh::vertex_normals`]). A mesh failing
/// [`TriangleMesh::validate`] is an [`IoError::InvalidMesh`], nothing written.
pub fn write_mesh_obj(path: &Path, mesh: &TriangleMesh) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    write_atomic(path, |out| render_mesh_obj(mesh, out))
}

/// Writes the OBJ text of `mesh` into `out` (the mesh is assumed valid; the seams of a
/// grid-shaped mesh are welded).
pub fn render_mesh_obj(mesh: &TriangleMesh, out: &mut dyn Write) -> io::Result<()> {
    let shared = SharedVertices::of(mesh);
    match mesh.grid {
        Some(_) => writeln!(out, "{}", surface_comment(shared.seams()))?,
        None => writeln!(
            out,
            "# karkas mesh, {} vertices, {} triangles",
            mesh.positions.len(),
            mesh.triangles.len()
        )?,
    }
    let triangles = shared.triangles().map(|t| t.map(|k| k as usize));
    render_body(shared.positions(), shared.normals(), triangles, out)
}

/// The `v`, `vn` and `f` lines of a mesh (0-based `triangles`, written 1-based).
fn render_body(
    positions: impl Iterator<Item = Point3>,
    normals: impl Iterator<Item = Point3>,
    triangles: impl Iterator<Item = [usize; 3]>,
    out: &mut dyn Write,
) -> io::Result<()> {
    for p in positions {
        writeln!(out, "v {} {} {}", p[0], p[1], p[2])?;
    }
    for n in normals {
        writeln!(out, "vn {} {} {}", n[0], n[1], n[2])?;
    }
    for t in triangles {
        let [p, q, r] = t.map(|k| k + 1);
        writeln!(out, "f {p}//{p} {q}//{q} {r}//{r}")?;
    }
    Ok(())
}

/// Reads the OBJ mesh of `input` (see the module docs), one line at a time.
pub fn read_obj_mesh(input: &mut Input) -> Result<TriangleMesh, IoError> {
    let name = input.name.clone();
    obj_mesh(input, &name)
}

/// The mesh of OBJ `text` (see the module docs); `path` names the file in errors.
pub fn parse_obj_mesh(text: &str, path: &Path) -> Result<TriangleMesh, IoError> {
    obj_mesh(&mut text.as_bytes(), path)
}

/// The bytes a mesh of these sizes keeps (positions, normals, index triples).
fn held(positions: usize, normals: usize, triangles: usize) -> u128 {
    (positions as u128 + normals as u128) * 24 + triangles as u128 * 12
}

/// The mesh of the OBJ lines of `reader`, named `name` in errors.
fn obj_mesh<R: BufRead + ?Sized>(reader: &mut R, name: &Path) -> Result<TriangleMesh, IoError> {
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut triangles: Vec<[u32; 3]> = Vec::new();
    let mut normals_match = true;
    let mut corners = Vec::new();
    let mut lines = ObjLines::new(reader, name);
    while let Some((line, text)) = lines.next()? {
        let at = Location::new(name, line);
        let mut fields = text.split_whitespace();
        match fields.next() {
            Some("v") => positions.push(vertex(fields, at)?),
            Some("vn") => normals.push(normal(fields, at)?),
            Some("f") => {
                corners.clear();
                for corner in fields {
                    let mut parts = corner.split('/');
                    let v = obj_index(parts.next().unwrap_or(""), positions.len(), at)?;
                    let n = parts.nth(1).filter(|s| !s.is_empty());
                    match n {
                        Some(n) => {
                            let n = obj_index(n, normals.len(), at)?;
                            normals_match &= n == v;
                        }
                        None => normals_match = false,
                    }
                    corners.push(v);
                }
                if corners.len() < 3 {
                    return Err(at.error(format!(
                        "a face needs at least 3 corners, found {}",
                        corners.len()
                    )));
                }
                for w in 1..corners.len() - 1 {
                    triangles.push([corners[0], corners[w], corners[w + 1]]);
                }
            }
            _ => continue,
        }
        check_held(name, held(positions.len(), normals.len(), triangles.len()))?;
    }
    if positions.is_empty() {
        return Err(no_vertices(name));
    }
    if !(normals_match && normals.len() == positions.len()) {
        normals.clear();
    }
    Ok(TriangleMesh {
        positions,
        normals,
        triangles,
        grid: None,
    })
}

/// The vertices (`v` lines) of OBJ `text`; `path` names the file in errors.
pub fn parse_obj_vertices(text: &str, path: &Path) -> Result<Vec<Point3>, IoError> {
    let mut points = Vec::new();
    let mut bytes = text.as_bytes();
    let mut lines = ObjLines::new(&mut bytes, path);
    while let Some((line, text)) = lines.next()? {
        let mut fields = text.split_whitespace();
        if fields.next() == Some("v") {
            points.push(vertex(fields, Location::new(path, line))?);
        }
    }
    if points.is_empty() {
        return Err(no_vertices(path));
    }
    Ok(points)
}

/// The lines of an OBJ file, each bounded (see [`read_line_bytes`]), its comment (`# ...`)
/// and a leading byte-order mark removed.
struct ObjLines<'a, R: BufRead + ?Sized> {
    reader: &'a mut R,
    name: &'a Path,
    bytes: Vec<u8>,
    line: usize,
}

impl<'a, R: BufRead + ?Sized> ObjLines<'a, R> {
    fn new(reader: &'a mut R, name: &'a Path) -> Self {
        ObjLines {
            reader,
            name,
            bytes: Vec::new(),
            line: 0,
        }
    }

    /// The next line's number and content, `None` at the end.
    fn next(&mut self) -> Result<Option<(usize, &str)>, IoError> {
        self.line += 1;
        if !read_line_bytes(self.reader, self.name, &mut self.bytes, self.line)? {
            return Ok(None);
        }
        let Ok(text) = std::str::from_utf8(&self.bytes) else {
            // Names (`o`, `g`, `usemtl`, comments) in another encoding are skipped like the
            // rest of their lines; the lines read are plain ASCII.
            let keyword = self
                .bytes
                .split(u8::is_ascii_whitespace)
                .find(|w| !w.is_empty());
            if matches!(keyword, Some(b"v" | b"vn" | b"f")) {
                return Err(Location::new(self.name, self.line).error(not_utf8_message()));
            }
            return Ok(Some((self.line, "")));
        };
        let text = if self.line == 1 {
            text.trim_start_matches('\u{feff}')
        } else {
            text
        };
        Ok(Some((self.line, text.split('#').next().unwrap_or(""))))
    }
}

/// The error for a file without `v` lines.
fn no_vertices(path: &Path) -> IoError {
    data_error(path, "no vertices ('v x y z' lines) found")
}

/// The position of a `v` line's numbers `fields` at `at`: `x y z`, `x y z w`, `x y z r g b`
/// or `x y z r g b a` (see the module docs); every field must be a finite number.
fn vertex<'a>(fields: impl Iterator<Item = &'a str>, at: Location<'_>) -> Result<Point3, IoError> {
    let mut p = Point3::ZERO;
    let mut count = 0;
    for (k, field) in fields.enumerate() {
        let value = parse_coordinate(field, k + 2, at)?;
        if k < 3 {
            p[k] = value;
        }
        count += 1;
    }
    match count {
        3 | 4 | 6 | 7 => Ok(p),
        0..=2 => Err(at.error(format!(
            "a vertex needs 3 coordinates (x y z [w]), found {count}"
        ))),
        _ => Err(at.error(format!(
            "a vertex is x y z, x y z w or x y z r g b [a]: found {count} numbers"
        ))),
    }
}

/// The normal of a `vn` line's numbers `fields` at `at` (3 numbers; a fourth is ignored).
fn normal<'a>(fields: impl Iterator<Item = &'a str>, at: Location<'_>) -> Result<Point3, IoError> {
    let mut n = Point3::ZERO;
    let mut count = 0;
    for (k, field) in fields.enumerate() {
        let value = parse_coordinate(field, k + 2, at)?;
        if k < 3 {
            n[k] = value;
        }
        count += 1;
    }
    if !(3..=4).contains(&count) {
        return Err(at.error(format!("'vn' needs 3 coordinates, found {count}")));
    }
    Ok(n)
}

/// The 0-based index of an OBJ index field (1-based, or negative from the end) among `count`.
fn obj_index(field: &str, count: usize, at: Location<'_>) -> Result<u32, IoError> {
    let value: i64 = field
        .parse()
        .map_err(|_| at.error(format!("'{}' is not a vertex index", excerpt(field))))?;
    let index = if value > 0 {
        value - 1
    } else {
        count as i64 + value
    };
    if value == 0 || index < 0 || index >= count as i64 || index > u32::MAX as i64 {
        return Err(at.error(format!(
            "index {value} does not name one of the {count} vertices defined so far"
        )));
    }
    Ok(index as u32)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The mesh writer gives the same text as the grid writer.
    #[test]
    fn mesh_writer_matches_grid_writer() {
        let grid = karkas::Grid::from_fn(3, 2, |a, b| {
            Point3::new([a as f64, b as f64, (a * b) as f64])
        });
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
        let (mut a, mut b) = (Vec::new(), Vec::new());
        render_surface_obj(3, 2, grid.as_slice(), &mut a).unwrap();
        render_mesh_obj(&mesh, &mut b).unwrap();
        assert_eq!(String::from_utf8(a).unwrap(), String::from_utf8(b).unwrap());
        // A general mesh says what it holds in the comment line; the body is the same.
        let general = TriangleMesh { grid: None, ..mesh };
        let mut c = Vec::new();
        render_mesh_obj(&general, &mut c).unwrap();
        let text = String::from_utf8(c).unwrap();
        assert!(text.starts_with("# karkas mesh, 6 vertices, 4 triangles\nv 0 0 0\n"));
    }

    #[test]
    fn faces_fans_and_normals() {
        let grid = karkas::Grid::from_fn(3, 4, |a, b| {
            Point3::new([a as f64, b as f64 * 0.5, (a * b) as f64 * 0.25])
        });
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
        let mut text = Vec::new();
        render_mesh_obj(&mesh, &mut text).unwrap();
        let back = parse_obj_mesh(std::str::from_utf8(&text).unwrap(), Path::new("m.obj")).unwrap();
        assert_eq!(back.triangles, mesh.triangles);
        assert_eq!(back.normals.len(), 12);
        let quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1/1 2/2 3/3 -1/4\n";
        let back = parse_obj_mesh(quad, Path::new("q.obj")).unwrap();
        assert_eq!(back.triangles, vec![[0, 1, 2], [0, 2, 3]]);
        assert!(back.normals.is_empty());
        let e = parse_obj_mesh("v 0 0 0\nf 1 2 3\n", Path::new("q.obj")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "q.obj:2: index 2 does not name one of the 1 vertices defined so far"
        );
    }

    #[test]
    fn vertices_are_read_and_errors_name_the_line() {
        let text = "# a mesh\nv 0 0 0\nvn 0 0 1\nv 1 2 3 1.0\nf 1 2 1\n";
        let pts = parse_obj_vertices(text, Path::new("m.obj")).unwrap();
        assert_eq!(pts, vec![Point3::ZERO, Point3::new([1.0, 2.0, 3.0])]);
        let e = parse_obj_vertices("v 1 2\n", Path::new("m.obj")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "m.obj:1: a vertex needs 3 coordinates (x y z [w]), found 2"
        );
        let e = parse_obj_vertices("v 1 2 nan\n", Path::new("m.obj")).unwrap_err();
        assert_eq!(e.to_string(), "m.obj:1: non-finite value 'nan' in column 4");
        assert!(parse_obj_vertices("f 1 2 3\n", Path::new("m.obj")).is_err());
    }
}

//! Wavefront OBJ meshes, written and read.
//!
//! OBJ is the plainest mesh format every 3-D viewer and modeller opens. It is a few kinds of
//! text lines, so it is written and parsed by hand rather than through a crate.
//!
//! Writing: `v` lines for the points, `vn` lines for one normal per point (see
//! `mesh/normals.rs`) and `f a//a b//b c//c` lines for the triangles (see
//! `mesh/triangulate.rs` for a sample grid), all counter-clockwise seen from the side the
//! normals point to. The first line is a comment: `# karkas surface, NU x NV samples` for a
//! sample grid, `# karkas mesh, N vertices, M triangles` for a general mesh. The seam points of
//! a closed surface are written twice (no welding).
//!
//! Reading:
//! - as a mesh ([`parse_obj_mesh`]): `v` and `f` lines (`f` corners as `a`, `a/b`, `a//c` or
//!   `a/b/c`, negative indices counting back from the last vertex; polygons split into fans);
//!   `vn` normals are kept when every corner of every face uses the normal of the same index as
//!   its vertex (as karkas writes them), otherwise normals are recomputed;
//! - as a point set ([`parse_obj_vertices`]): only the `v x y z [w]` lines (faces, normals and
//!   texture coordinates are not needed to measure distances and are skipped).

use std::io::{self, Write};
use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError, Location};
use crate::lines::{parse_coordinate, strip_bom};
use crate::mesh::normals::grid_normals;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::triangulate::{check_grid, grid_triangles};
use crate::write::write_atomic;

/// Writes the `nu x nv` sample grid `points` (row-major, `u` outer) as an OBJ mesh at `path`,
/// atomically. A `points.len()` other than `nu * nv` is an [`IoError::InvalidMesh`]
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

/// Writes the OBJ text of the `nu x nv` sample grid `points` into `out`.
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
    writeln!(out, "# karkas surface, {nu} x {nv} samples")?;
    render_body(
        points,
        grid_normals(nu, nv, points),
        grid_triangles(nu, nv),
        out,
    )
}

/// Writes the triangle mesh `mesh` as OBJ at `path`, atomically (see the module docs; normals
/// from the mesh or face-averaged, see [`TriangleMesh::vertex_normals`]). A mesh failing
/// [`TriangleMesh::validate`] is an [`IoError::InvalidMesh`], nothing written.
pub fn write_mesh_obj(path: &Path, mesh: &TriangleMesh) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    write_atomic(path, |out| render_mesh_obj(mesh, out))
}

/// Writes the OBJ text of `mesh` into `out` (the mesh is assumed valid).
pub fn render_mesh_obj(mesh: &TriangleMesh, out: &mut dyn Write) -> io::Result<()> {
    match mesh.grid {
        Some((nu, nv)) => writeln!(out, "# karkas surface, {nu} x {nv} samples")?,
        None => writeln!(
            out,
            "# karkas mesh, {} vertices, {} triangles",
            mesh.positions.len(),
            mesh.triangles.len()
        )?,
    }
    let triangles = mesh.triangles.iter().map(|t| t.map(|k| k as usize));
    render_body(
        &mesh.positions,
        mesh.vertex_normals().into_iter(),
        triangles,
        out,
    )
}

/// The `v`, `vn` and `f` lines of a mesh (0-based `triangles`, written 1-based).
fn render_body(
    positions: &[Point3],
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

/// The mesh of OBJ `text` (see the module docs); `path` names the file in errors.
pub fn parse_obj_mesh(text: &str, path: &Path) -> Result<TriangleMesh, IoError> {
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut triangles = Vec::new();
    let mut normals_match = true;
    for (k, line) in strip_bom(text).lines().enumerate() {
        let line = line.split('#').next().unwrap_or("");
        let mut fields = line.split_whitespace();
        let at = Location::new(path, k + 1);
        match fields.next() {
            Some(kind @ ("v" | "vn")) => {
                let p = vector(fields, at, |found| {
                    format!("'{kind}' needs 3 coordinates, found {found}")
                })?;
                if kind == "v" {
                    positions.push(p);
                } else {
                    normals.push(p);
                }
            }
            Some("f") => {
                let mut corners = Vec::new();
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
            _ => {}
        }
    }
    if positions.is_empty() {
        return Err(no_vertices(path));
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
    for (k, line) in strip_bom(text).lines().enumerate() {
        let line = line.split('#').next().unwrap_or("");
        let mut fields = line.split_whitespace();
        if fields.next() != Some("v") {
            continue;
        }
        let at = Location::new(path, k + 1);
        points.push(vector(fields, at, |found| {
            format!("a vertex needs 3 coordinates (x y z [w]), found {found}")
        })?);
    }
    if points.is_empty() {
        return Err(no_vertices(path));
    }
    Ok(points)
}

/// The error for a file without `v` lines.
fn no_vertices(path: &Path) -> IoError {
    data_error(path, "no vertices ('v x y z' lines) found")
}

/// The first three of the 3 or 4 numbers `fields` of a `v` or `vn` line at `at`; `miscount`
/// words the error for another count.
fn vector<'a>(
    fields: impl Iterator<Item = &'a str>,
    at: Location<'_>,
    miscount: impl Fn(usize) -> String,
) -> Result<Point3, IoError> {
    let coords: Vec<&str> = fields.collect();
    if !(3..=4).contains(&coords.len()) {
        return Err(at.error(miscount(coords.len())));
    }
    let mut p = Point3::ZERO;
    for c in 0..3 {
        p[c] = parse_coordinate(coords[c], c + 2, at)?;
    }
    Ok(p)
}

/// The 0-based index of an OBJ index field (1-based, or negative from the end) among `count`.
fn obj_index(field: &str, count: usize, at: Location<'_>) -> Result<u32, IoError> {
    let value: i64 = field
        .parse()
        .map_err(|_| at.error(format!("'{field}' is not a vertex index")))?;
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

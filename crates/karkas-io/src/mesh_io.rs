//! Triangle meshes in and out by format: [`write_mesh`] picks the writer of an
//! [`OutputFormat`], [`read_mesh`] reads an OBJ, STL (binary or ASCII) or PLY mesh, and
//! [`read_surface_samples`] reads a sampled surface CSV `u,v,x,y,z` back into its grid.
//!
//! Readers, for converting between formats:
//! - OBJ: `v` and `f` lines (`f` corners as `a`, `a/b`, `a//c` or `a/b/c`, negative indices
//!   counting back from the last vertex; polygons split into fans); `vn` normals are kept when
//!   every corner of every face uses the normal of the same index as its vertex (as karkas
//!   writes them), otherwise normals are recomputed.
//! - STL: through `stl_io` (binary or ASCII; equal corners are merged into one vertex).
//! - PLY: `ascii` and `binary_little_endian`/`binary_big_endian` with any scalar property types;
//!   `x y z` of `element vertex`, `nx ny nz` when present, and the index list of
//!   `element face` (polygons split into fans); other elements and properties are skipped.
//!
//! Written by hand except STL: the PLY crates are unmaintained or build dynamic property maps,
//! and OBJ face parsing is a few lines.

use std::path::Path;

use karkas::{Grid, Point3};

use crate::error::{data_error, IoError, Location};
use crate::format::OutputFormat;
use crate::lines::{csv_rows, parse_coordinate, read_text, strip_bom};
use crate::mesh::TriangleMesh;

/// Writes `mesh` at `path` in `format` (one of [`OutputFormat::MESHES`]; binary STL and PLY),
/// atomically. Another format is an [`IoError::UnknownExtension`].
pub fn write_mesh(path: &Path, format: OutputFormat, mesh: &TriangleMesh) -> Result<(), IoError> {
    match format {
        OutputFormat::Obj => crate::obj::write_mesh_obj(path, mesh),
        OutputFormat::Stl => crate::stl::write_mesh_stl(path, mesh, false),
        OutputFormat::Ply => {
            crate::ply::write_mesh_ply(path, mesh, crate::ply::PlyEncoding::BinaryLittleEndian)
        }
        OutputFormat::Vtk => crate::vtk::write_mesh_vtk(path, mesh),
        OutputFormat::Vts => crate::vtk::write_mesh_vts(path, mesh),
        OutputFormat::Glb => crate::glb::write_mesh_glb(path, mesh),
        _ => Err(IoError::UnknownExtension {
            path: path.to_path_buf(),
            allowed: ".obj, .stl, .ply, .vtk, .vts, .glb".to_owned(),
        }),
    }
}

/// Writes the sampled surface `grid` (row-major, `u` outer) as a mesh at `path` in `format`
/// (see [`write_mesh`]).
pub fn write_surface_mesh(
    path: &Path,
    format: OutputFormat,
    grid: &Grid<Point3>,
) -> Result<(), IoError> {
    let mesh = TriangleMesh::from_grid(grid).map_err(|e| IoError::Write {
        path: path.to_path_buf(),
        source: std::io::Error::new(std::io::ErrorKind::InvalidInput, e.to_string()),
    })?;
    write_mesh(path, format, &mesh)
}

/// Reads the triangle mesh of `path` by its extension: `.obj`, `.stl` or `.ply`.
pub fn read_mesh(path: &Path) -> Result<TriangleMesh, IoError> {
    let ext = path
        .extension()
        .and_then(|e| e.to_str())
        .map(str::to_ascii_lowercase);
    let mesh = match ext.as_deref() {
        Some("obj") => parse_obj_mesh(&read_text(path)?, path)?,
        Some("stl") => read_stl(path)?,
        Some("ply") => {
            let bytes = std::fs::read(path).map_err(|source| IoError::Open {
                path: path.to_path_buf(),
                source,
            })?;
            parse_ply(&bytes, path)?
        }
        _ => return Err(data_error(path, "not a mesh file (use .obj, .stl or .ply)")),
    };
    if mesh.triangles.is_empty() {
        return Err(data_error(path, "the mesh has no faces"));
    }
    Ok(mesh)
}

fn read_stl(path: &Path) -> Result<TriangleMesh, IoError> {
    let file = std::fs::File::open(path).map_err(|source| IoError::Open {
        path: path.to_path_buf(),
        source,
    })?;
    let mut reader = std::io::BufReader::new(file);
    let indexed = stl_io::read_stl(&mut reader)
        .map_err(|e| data_error(path, format!("not a readable STL file: {e}")))?;
    let positions: Vec<Point3> = indexed
        .vertices
        .iter()
        .map(|v| Point3::new([v[0] as f64, v[1] as f64, v[2] as f64]))
        .collect();
    if !positions.iter().all(|p| p.is_finite()) {
        return Err(data_error(path, "a vertex is not finite"));
    }
    let triangles = indexed
        .faces
        .iter()
        .map(|f| f.vertices.map(|k| k as u32))
        .collect();
    let mesh = TriangleMesh {
        positions,
        normals: Vec::new(),
        triangles,
        grid: None,
    };
    mesh.validate().map_err(|m| data_error(path, m))?;
    Ok(mesh)
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
                let coords: Vec<&str> = fields.collect();
                if coords.len() < 3 || coords.len() > 4 {
                    return Err(at.error(format!(
                        "'{kind}' needs 3 coordinates, found {}",
                        coords.len()
                    )));
                }
                let mut p = Point3::ZERO;
                for c in 0..3 {
                    p[c] = parse_coordinate(coords[c], c + 2, at)?;
                }
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
        return Err(data_error(path, "no vertices ('v x y z' lines) found"));
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

/// A PLY scalar type.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn parse(name: &str) -> Option<Scalar> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }
}

/// A property of a PLY element: a scalar, or a list (count type, item type).
#[derive(Clone, Debug)]
struct Property {
    name: String,
    scalar: Scalar,
    list_count: Option<Scalar>,
}

#[derive(Clone, Debug)]
struct Element {
    name: String,
    count: usize,
    properties: Vec<Property>,
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum PlyFormat {
    Ascii,
    Little,
    Big,
}

/// The values of a PLY body, read one at a time.
struct PlyBody<'a> {
    format: PlyFormat,
    bytes: &'a [u8],
    at: usize,
    /// ASCII tokens (for the ascii format).
    tokens: std::str::SplitAsciiWhitespace<'a>,
}

impl PlyBody<'_> {
    fn value(&mut self, scalar: Scalar) -> Option<f64> {
        if self.format == PlyFormat::Ascii {
            return self.tokens.next()?.parse::<f64>().ok();
        }
        let size = scalar.size();
        let raw = self.bytes.get(self.at..self.at + size)?;
        self.at += size;
        let mut buf = [0u8; 8];
        buf[..size].copy_from_slice(raw);
        if self.format == PlyFormat::Big {
            buf[..size].reverse();
        }
        let b2 = [buf[0], buf[1]];
        let b4 = [buf[0], buf[1], buf[2], buf[3]];
        Some(match scalar {
            Scalar::I8 => buf[0] as i8 as f64,
            Scalar::U8 => buf[0] as f64,
            Scalar::I16 => i16::from_le_bytes(b2) as f64,
            Scalar::U16 => u16::from_le_bytes(b2) as f64,
            Scalar::I32 => i32::from_le_bytes(b4) as f64,
            Scalar::U32 => u32::from_le_bytes(b4) as f64,
            Scalar::F32 => f32::from_le_bytes(b4) as f64,
            Scalar::F64 => f64::from_le_bytes(buf),
        })
    }
}

/// The mesh of the PLY file `bytes` (see the module docs); `path` names the file in errors.
pub fn parse_ply(bytes: &[u8], path: &Path) -> Result<TriangleMesh, IoError> {
    let header_end = bytes
        .windows(10)
        .position(|w| w == b"end_header")
        .ok_or_else(|| data_error(path, "not a PLY file: no 'end_header' line"))?;
    let header = std::str::from_utf8(&bytes[..header_end])
        .map_err(|_| data_error(path, "the PLY header is not text"))?;
    let body_start = bytes[header_end..]
        .iter()
        .position(|&b| b == b'\n')
        .map_or(bytes.len(), |k| header_end + k + 1);
    let mut format = None;
    let mut elements: Vec<Element> = Vec::new();
    for (k, line) in header.lines().enumerate() {
        let at = Location::new(path, k + 1);
        let words: Vec<&str> = line.split_whitespace().collect();
        match words.as_slice() {
            ["ply"] | [] => {}
            ["comment", ..] | ["obj_info", ..] => {}
            ["format", f, _] => {
                format = Some(match *f {
                    "ascii" => PlyFormat::Ascii,
                    "binary_little_endian" => PlyFormat::Little,
                    "binary_big_endian" => PlyFormat::Big,
                    _ => return Err(at.error(format!("unknown PLY format '{f}'"))),
                })
            }
            ["element", name, count] => elements.push(Element {
                name: (*name).to_owned(),
                count: count
                    .parse()
                    .map_err(|_| at.error(format!("'{count}' is not an element count")))?,
                properties: Vec::new(),
            }),
            ["property", rest @ ..] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| at.error("a property before any element"))?;
                let bad = || at.error(format!("malformed property line '{line}'"));
                let property = match rest {
                    ["list", count, item, name] => Property {
                        name: (*name).to_owned(),
                        scalar: Scalar::parse(item).ok_or_else(bad)?,
                        list_count: Some(Scalar::parse(count).ok_or_else(bad)?),
                    },
                    [ty, name] => Property {
                        name: (*name).to_owned(),
                        scalar: Scalar::parse(ty).ok_or_else(bad)?,
                        list_count: None,
                    },
                    _ => return Err(bad()),
                };
                element.properties.push(property);
            }
            _ => return Err(at.error(format!("unknown PLY header line '{line}'"))),
        }
    }
    let format = format.ok_or_else(|| data_error(path, "the PLY header has no 'format' line"))?;
    let body_bytes = &bytes[body_start.min(bytes.len())..];
    let text = if format == PlyFormat::Ascii {
        std::str::from_utf8(body_bytes)
            .map_err(|_| data_error(path, "the ASCII PLY body is not text"))?
    } else {
        ""
    };
    let mut body = PlyBody {
        format,
        bytes: body_bytes,
        at: 0,
        tokens: text.split_ascii_whitespace(),
    };
    let truncated = |what: &str| {
        data_error(
            path,
            format!("the PLY body ends early or is malformed in element '{what}'"),
        )
    };
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut triangles = Vec::new();
    for element in &elements {
        let find = |n: &str| element.properties.iter().position(|p| p.name == n);
        let xyz = [find("x"), find("y"), find("z")];
        let nxyz = [find("nx"), find("ny"), find("nz")];
        let is_vertex = element.name == "vertex";
        let is_face = element.name == "face";
        if is_vertex && xyz.iter().any(Option::is_none) {
            return Err(data_error(path, "the PLY vertices have no x, y, z"));
        }
        // Cap the reservation by what the body can hold (one byte per value at least).
        let reserve = element.count.min(body_bytes.len());
        if is_vertex {
            positions.reserve(reserve);
        }
        let mut values = vec![0.0; element.properties.len()];
        let mut list = Vec::new();
        for _ in 0..element.count {
            let mut face_list = None;
            for (k, property) in element.properties.iter().enumerate() {
                match property.list_count {
                    None => {
                        values[k] = body
                            .value(property.scalar)
                            .ok_or_else(|| truncated(&element.name))?
                    }
                    Some(count_type) => {
                        let count = body
                            .value(count_type)
                            .ok_or_else(|| truncated(&element.name))?;
                        if !(0.0..=1e6).contains(&count) {
                            return Err(truncated(&element.name));
                        }
                        list.clear();
                        for _ in 0..count as usize {
                            list.push(
                                body.value(property.scalar)
                                    .ok_or_else(|| truncated(&element.name))?,
                            );
                        }
                        if is_face
                            && (property.name == "vertex_indices"
                                || property.name == "vertex_index")
                        {
                            face_list = Some(list.clone());
                        }
                    }
                }
            }
            if is_vertex {
                let get = |i: [Option<usize>; 3]| i.map(|k| k.map_or(0.0, |k| values[k]));
                let p = Point3::new(get(xyz));
                if !p.is_finite() {
                    return Err(data_error(
                        path,
                        format!("vertex {} is not finite", positions.len()),
                    ));
                }
                positions.push(p);
                if nxyz.iter().all(Option::is_some) {
                    normals.push(Point3::new(get(nxyz)));
                }
            }
            if let Some(corners) = face_list {
                if corners.len() < 3 {
                    return Err(data_error(
                        path,
                        format!("face {} has fewer than 3 corners", triangles.len()),
                    ));
                }
                let index = |v: f64| {
                    if v >= 0.0 && v <= u32::MAX as f64 && v.fract() == 0.0 {
                        Ok(v as u32)
                    } else {
                        Err(data_error(path, format!("'{v}' is not a vertex index")))
                    }
                };
                let first = index(corners[0])?;
                for w in 1..corners.len() - 1 {
                    triangles.push([first, index(corners[w])?, index(corners[w + 1])?]);
                }
            }
        }
    }
    if positions.is_empty() {
        return Err(data_error(path, "no PLY vertices found"));
    }
    let mesh = TriangleMesh {
        positions,
        normals,
        triangles,
        grid: None,
    };
    mesh.validate().map_err(|m| data_error(path, m))?;
    Ok(mesh)
}

/// Reads a sampled surface CSV (header `u,v,x,y,z`, `u` outer, as the surface commands write
/// it) back into its grid: the rows of one `u` value form one grid row.
pub fn read_surface_samples(path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_surface_samples(&read_text(path)?, path)
}

/// Reads a sampled surface from CSV `text` (see [`read_surface_samples`]).
pub fn parse_surface_samples(text: &str, path: &Path) -> Result<Grid<Point3>, IoError> {
    let rows = csv_rows(strip_bom(text), path)?;
    let Some((header, data)) = rows.split_first() else {
        return Err(data_error(path, "no surface samples found"));
    };
    let names = ["u", "v", "x", "y", "z"];
    let mut columns = [0usize; 5];
    for (c, name) in names.iter().enumerate() {
        columns[c] = header
            .fields
            .iter()
            .position(|f| f.eq_ignore_ascii_case(name))
            .ok_or_else(|| {
                Location::new(path, header.line).error(format!(
                    "the header has no column '{name}' (expected u,v,x,y,z)"
                ))
            })?;
    }
    let mut us = Vec::with_capacity(data.len());
    let mut points = Vec::with_capacity(data.len());
    for row in data {
        let at = Location::new(path, row.line);
        let mut values = [0.0; 5];
        for c in 0..5 {
            let field = row
                .fields
                .get(columns[c])
                .ok_or_else(|| at.error(format!("missing column {}", columns[c] + 1)))?;
            values[c] = parse_coordinate(field, columns[c] + 1, at)?;
        }
        us.push(values[0]);
        points.push(Point3::new([values[2], values[3], values[4]]));
    }
    let Some(&first_u) = us.first() else {
        return Err(data_error(path, "no surface samples found"));
    };
    // The first run of equal u is one grid row; every later row must be as long.
    let nv = us.iter().take_while(|&&u| u == first_u).count();
    let nu = points.len() / nv;
    for (k, row) in data.iter().enumerate() {
        let start = us[k - k % nv];
        let fresh = k % nv == 0 && k > 0 && us[k] == us[k - 1];
        if us[k] != start || fresh || k >= nu * nv {
            return Err(Location::new(path, row.line).error(format!(
                "not a grid of rows of {nv} samples with equal u (u is the outer index)"
            )));
        }
    }
    Grid::from_row_major(nu, nv, points).map_err(|e| data_error(path, e.to_string()))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ply::{render_mesh_ply, PlyEncoding};

    fn sample_mesh() -> TriangleMesh {
        let grid = Grid::from_fn(3, 4, |a, b| {
            Point3::new([a as f64, b as f64 * 0.5, (a * b) as f64 * 0.25])
        });
        TriangleMesh::from_grid(&grid).unwrap()
    }

    #[test]
    fn ply_round_trips_in_every_encoding() {
        let mesh = sample_mesh();
        for encoding in [PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian] {
            let mut bytes = Vec::new();
            render_mesh_ply(&mesh, encoding, &mut bytes).unwrap();
            let back = parse_ply(&bytes, Path::new("m.ply")).unwrap();
            assert_eq!(back.positions, mesh.positions);
            assert_eq!(back.triangles, mesh.triangles);
            assert_eq!(back.normals.len(), mesh.positions.len());
        }
        let e = parse_ply(b"ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\nend_header\n1 2 3\n", Path::new("m.ply")).unwrap_err();
        assert!(e.to_string().contains("ends early"), "{e}");
    }

    #[test]
    fn obj_faces_fans_and_normals() {
        let mut text = Vec::new();
        crate::obj::render_mesh_obj(&sample_mesh(), &mut text).unwrap();
        let back = parse_obj_mesh(std::str::from_utf8(&text).unwrap(), Path::new("m.obj")).unwrap();
        assert_eq!(back.triangles, sample_mesh().triangles);
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
    fn surface_samples_read_back_into_their_grid() {
        let text = "u,v,x,y,z\n0,0,1,2,3\n0,1,4,5,6\n0,2,7,8,9\n1,0,1,1,1\n1,1,2,2,2\n1,2,3,3,3\n";
        let grid = parse_surface_samples(text, Path::new("s.csv")).unwrap();
        assert_eq!((grid.rows(), grid.cols()), (2, 3));
        assert_eq!(*grid.get(1, 2), Point3::new([3.0, 3.0, 3.0]));
        let ragged = "u,v,x,y,z\n0,0,1,2,3\n0,1,4,5,6\n1,0,1,1,1\n2,1,2,2,2\n";
        let e = parse_surface_samples(ragged, Path::new("s.csv")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "s.csv:5: not a grid of rows of 2 samples with equal u (u is the outer index)"
        );
        let long = "u,v,x,y,z\n0,0,1,2,3\n0,1,4,5,6\n0,2,1,1,1\n1,1,2,2,2\n";
        assert!(parse_surface_samples(long, Path::new("s.csv")).is_err());
        let wrong =
            parse_surface_samples("i,j,x,y,z\n0,0,1,2,3\n", Path::new("g.csv")).unwrap_err();
        assert!(wrong.to_string().contains("no column 'u'"));
    }
}

//! Stanford PLY meshes, written (binary little-endian or ASCII) and read (any encoding).
//!
//! PLY is the mesh format of scanning and point-cloud tools (MeshLab, CloudCompare, Open3D,
//! meshio, trimesh). The header is a few text lines and the body a fixed record layout, so it
//! is written and parsed directly; the PLY crates in the ecosystem are unmaintained or build a
//! dynamic property map per element, which costs more than the format itself.
//!
//! Writing: `element vertex N` with `double x y z` and `float nx ny nz` (per-vertex normals,
//! taken from the mesh or averaged over the faces, see
//! [`TriangleMesh::vertex_normals`]), then `element face M` with
//! `property list uchar uint vertex_indices`, three indices per face. Positions are written as
//! doubles so that a file read back gives the samples exactly (binary) or to the shortest
//! round-trip decimal (ASCII).
//!
//! Reading: `ascii` and `binary_little_endian`/`binary_big_endian` with any scalar property
//! types; `x y z` of `element vertex`, `nx ny nz` when present, and the index list of
//! `element face` (polygons split into fans); other elements and properties are skipped.

use std::io::{self, Write};
use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError, Location};
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::write::write_atomic;

/// The body encoding of a PLY file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PlyEncoding {
    /// `format binary_little_endian 1.0` (compact, exact).
    #[default]
    BinaryLittleEndian,
    /// `format ascii 1.0` (readable).
    Ascii,
}

/// Writes `mesh` as PLY at `path`, atomically. A mesh failing
/// [`TriangleMesh::validate`] is an [`IoError::InvalidMesh`] and nothing is written.
pub fn write_mesh_ply(
    path: &Path,
    mesh: &TriangleMesh,
    encoding: PlyEncoding,
) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    write_atomic(path, |out| render_mesh_ply(mesh, encoding, out))
}

/// Writes the PLY bytes of `mesh` into `out` (the mesh is assumed valid).
pub fn render_mesh_ply(
    mesh: &TriangleMesh,
    encoding: PlyEncoding,
    out: &mut dyn Write,
) -> io::Result<()> {
    let format = match encoding {
        PlyEncoding::BinaryLittleEndian => "binary_little_endian",
        PlyEncoding::Ascii => "ascii",
    };
    write!(
        out,
        "ply\nformat {format} 1.0\ncomment karkas mesh\n\
         element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         property float nx\nproperty float ny\nproperty float nz\n\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        mesh.positions.len(),
        mesh.triangles.len()
    )?;
    let normals = mesh.vertex_normals();
    match encoding {
        PlyEncoding::BinaryLittleEndian => {
            for (p, n) in mesh.positions.iter().zip(&normals) {
                for c in 0..3 {
                    out.write_all(&p[c].to_le_bytes())?;
                }
                for c in 0..3 {
                    out.write_all(&(n[c] as f32).to_le_bytes())?;
                }
            }
            for t in &mesh.triangles {
                out.write_all(&[3u8])?;
                for k in t {
                    out.write_all(&k.to_le_bytes())?;
                }
            }
        }
        PlyEncoding::Ascii => {
            for (p, n) in mesh.positions.iter().zip(&normals) {
                writeln!(
                    out,
                    "{} {} {} {} {} {}",
                    p[0], p[1], p[2], n[0] as f32, n[1] as f32, n[2] as f32
                )?;
            }
            for t in &mesh.triangles {
                writeln!(out, "3 {} {} {}", t[0], t[1], t[2])?;
            }
        }
    }
    Ok(())
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

/// The mesh of the PLY file `bytes` (see the module docs, "Reading"); `path` names the file in errors.
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
    let mut positions = Vec::new();
    let mut normals = Vec::new();
    let mut triangles = Vec::new();
    for element in &elements {
        let truncated = || {
            let what = &element.name;
            data_error(
                path,
                format!("the PLY body ends early or is malformed in element '{what}'"),
            )
        };
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
                    None => values[k] = body.value(property.scalar).ok_or_else(truncated)?,
                    Some(count_type) => {
                        let count = body.value(count_type).ok_or_else(truncated)?;
                        if !(0.0..=1e6).contains(&count) {
                            return Err(truncated());
                        }
                        list.clear();
                        for _ in 0..count as usize {
                            list.push(body.value(property.scalar).ok_or_else(truncated)?);
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
    TriangleMesh {
        positions,
        normals,
        triangles,
        grid: None,
    }
    .checked_read(path)
}

/// Reads the PLY file `path` as a mesh.
pub fn read_ply(path: &Path) -> Result<TriangleMesh, IoError> {
    let bytes = std::fs::read(path).map_err(IoError::open(path))?;
    parse_ply(&bytes, path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Grid;

    fn square() -> TriangleMesh {
        let grid = Grid::from_fn(2, 2, |a, b| Point3::new([a as f64, b as f64, 0.5]));
        TriangleMesh::from_grid(&grid).unwrap()
    }

    /// The whole ASCII file of a 2 x 2 grid, written out by hand.
    #[test]
    fn ascii_golden() {
        let mut out = Vec::new();
        render_mesh_ply(&square(), PlyEncoding::Ascii, &mut out).unwrap();
        let expected = "ply\nformat ascii 1.0\ncomment karkas mesh\nelement vertex 4\n\
            property double x\nproperty double y\nproperty double z\n\
            property float nx\nproperty float ny\nproperty float nz\nelement face 2\n\
            property list uchar uint vertex_indices\nend_header\n\
            0 0 0.5 0 0 1\n0 1 0.5 0 0 1\n1 0 0.5 0 0 1\n1 1 0.5 0 0 1\n3 0 2 3\n3 0 3 1\n";
        assert_eq!(String::from_utf8(out).unwrap(), expected);
    }

    /// The binary body has 4 * (3 * 8 + 3 * 4) vertex bytes and 2 * 13 face bytes, and the
    /// first vertex's z and the last face read back.
    #[test]
    fn binary_layout() {
        let mut out = Vec::new();
        render_mesh_ply(&square(), PlyEncoding::BinaryLittleEndian, &mut out).unwrap();
        let header_end = out.windows(11).position(|w| w == b"end_header\n").unwrap() + 11;
        let body = &out[header_end..];
        assert_eq!(body.len(), 4 * 36 + 2 * 13);
        let z = f64::from_le_bytes(body[16..24].try_into().unwrap());
        assert_eq!(z, 0.5);
        let last = &body[4 * 36 + 13..];
        assert_eq!(last[0], 3);
        let idx: Vec<u32> = last[1..]
            .chunks(4)
            .map(|c| u32::from_le_bytes(c.try_into().unwrap()))
            .collect();
        assert_eq!(idx, vec![0, 3, 1]);
    }

    #[test]
    fn ply_round_trips_in_every_encoding() {
        let grid = Grid::from_fn(3, 4, |a, b| {
            Point3::new([a as f64, b as f64 * 0.5, (a * b) as f64 * 0.25])
        });
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
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
}

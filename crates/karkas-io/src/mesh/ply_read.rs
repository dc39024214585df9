//! Reading Stanford PLY meshes, in any of the three encodings, from a file or standard input.
//!
//! The header is read line by line (each line bounded, the whole header at most
//! [`MAX_HEADER_BYTES`]); its first line must be `ply` (otherwise: "not a PLY file: the first
//! line is '...'"). Accepted: `format ascii|binary_little_endian|binary_big_endian 1.0`,
//! `comment` and `obj_info` lines (and any other line, a comment without its keyword as some
//! exporters wrote), `element NAME COUNT`, scalar properties of every PLY type
//! under both spellings (`char uchar short ushort int uint float double` and `int8 uint8 int16
//! uint16 int32 uint32 float32 float64`) and list properties `property list COUNT_TYPE
//! ITEM_TYPE NAME` with any of those types.
//!
//! Read: `x y z` of `element vertex` (other vertex properties, such as normals' siblings,
//! colours or texture coordinates, are skipped; `nx ny nz` are kept as the normals when all
//! three are there) and the index list `vertex_indices` (or `vertex_index`) of `element
//! face`, a polygon of n corners becoming the fan of n - 2 triangles from its first corner.
//! Every other element, and every other list property (in any element), is skipped value by
//! value in each encoding.
//!
//! Bounded memory: after the header the body is read whole within the memory cap
//! ([`Input::read_bytes`]); before anything is allocated, the element counts of the header
//! are checked against the bytes the body has (each record takes at least one byte per
//! property in ASCII, the sizes of its scalars and list counts in binary) and what the mesh
//! will keep against [`check_held`].
//!
//! Hand-written: the PLY crates in the ecosystem are unmaintained or build a dynamic property
//! map per element, which costs more than the format itself.

use std::io::BufRead;
use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError, Location};
use crate::input::{check_held, excerpt, read_line_bytes, Input};
use crate::mesh::triangle_mesh::TriangleMesh;

/// The longest PLY header read, in bytes (1 MiB).
pub const MAX_HEADER_BYTES: usize = 1 << 20;

/// The most items a list property may hold.
const MAX_LIST_ITEMS: f64 = 1e6;

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

/// An element of a PLY header: its name, record count and properties.
#[derive(Clone, Debug)]
struct Element {
    name: String,
    count: u64,
    properties: Vec<Property>,
}

impl Element {
    /// The fewest body bytes one record takes in `format`.
    fn min_record_bytes(&self, format: PlyFormat) -> u128 {
        self.properties
            .iter()
            .map(|p| match format {
                PlyFormat::Ascii => 1,
                _ => p.list_count.unwrap_or(p.scalar).size() as u128,
            })
            .sum()
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
enum PlyFormat {
    Ascii,
    Little,
    Big,
}

/// A PLY header: the body's encoding and the elements in order.
#[derive(Debug)]
struct Header {
    format: PlyFormat,
    elements: Vec<Element>,
}

/// Reads the PLY file `path` (`-`: standard input) as a mesh.
pub fn read_ply(path: &Path) -> Result<TriangleMesh, IoError> {
    read_ply_from(&mut Input::open(path)?)
}

/// Reads the PLY mesh of `input` (see the module docs).
pub fn read_ply_from(input: &mut Input) -> Result<TriangleMesh, IoError> {
    let name = input.name.clone();
    let header = read_header(input, &name)?;
    let body = input.read_bytes()?;
    parse_body(&header, &body, &name)
}

/// The mesh of the PLY file `bytes` (see the module docs); `path` names the file in errors.
pub fn parse_ply(bytes: &[u8], path: &Path) -> Result<TriangleMesh, IoError> {
    let mut reader = bytes;
    let header = read_header(&mut reader, path)?;
    parse_body(&header, reader, path)
}

/// Reads the first line of a PLY file into `buf`: `ply`, else the error that this is no PLY.
fn read_magic<R: BufRead + ?Sized>(
    reader: &mut R,
    path: &Path,
    buf: &mut Vec<u8>,
) -> Result<(), IoError> {
    let not_ply = |what: &str| data_error(path, format!("not a PLY file: {what}"));
    match read_line_bytes(reader, path, buf, 1) {
        Ok(true) => {}
        Ok(false) => return Err(not_ply("the input is empty")),
        Err(_) => {
            return Err(not_ply(
                "the first line is binary data or longer than 1 MiB",
            ))
        }
    }
    let first = String::from_utf8_lossy(buf);
    if first.trim() != "ply" {
        let first = excerpt(first.trim_end_matches(['\r', '\n']));
        return Err(not_ply(&format!("the first line is '{first}'")));
    }
    Ok(())
}

/// Reads the header of a PLY file from `reader` up to its `end_header` line.
fn read_header<R: BufRead + ?Sized>(reader: &mut R, path: &Path) -> Result<Header, IoError> {
    let mut buf = Vec::new();
    read_magic(reader, path, &mut buf)?;
    let mut format = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut header_bytes = buf.len();
    let mut line = 1;
    loop {
        line += 1;
        if !read_line_bytes(reader, path, &mut buf, line)? {
            return Err(data_error(path, "the PLY header has no 'end_header' line"));
        }
        header_bytes += buf.len();
        let at = Location::new(path, line);
        if header_bytes > MAX_HEADER_BYTES {
            return Err(at.error("a PLY header longer than 1 MiB"));
        }
        let text = std::str::from_utf8(&buf).map_err(|_| at.error("the PLY header is not text"))?;
        let words: Vec<&str> = text.split_whitespace().collect();
        let quoted = || excerpt(text.trim());
        match words.as_slice() {
            ["end_header"] => break,
            [] => {}
            ["comment", ..] | ["obj_info", ..] => {}
            ["format", f, _] => {
                format = Some(match *f {
                    "ascii" => PlyFormat::Ascii,
                    "binary_little_endian" => PlyFormat::Little,
                    "binary_big_endian" => PlyFormat::Big,
                    _ => return Err(at.error(format!("unknown PLY format '{}'", excerpt(f)))),
                })
            }
            ["element", name, count] => elements.push(Element {
                name: (*name).to_owned(),
                count: count.parse().map_err(|_| {
                    at.error(format!("'{}' is not an element count", excerpt(count)))
                })?,
                properties: Vec::new(),
            }),
            ["property", rest @ ..] => {
                let element = elements
                    .last_mut()
                    .ok_or_else(|| at.error("a property before any element"))?;
                let bad = || at.error(format!("malformed property line '{}'", quoted()));
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
            // Any other line is a comment without its keyword (Blender 2.4 wrote such lines);
            // a misspelt element or property shows as a body that does not match the header.
            _ => {}
        }
    }
    let format = format.ok_or_else(|| data_error(path, "the PLY header has no 'format' line"))?;
    Ok(Header { format, elements })
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

/// Checks the header's counts against the body's size and the memory cap (see the module
/// docs), before anything is allocated.
fn check_counts(header: &Header, body: &[u8], path: &Path) -> Result<(), IoError> {
    let mut needed: u128 = 0;
    let mut held = body.len() as u128;
    for element in &header.elements {
        needed += element.count as u128 * element.min_record_bytes(header.format);
        if needed > body.len() as u128 {
            return Err(data_error(
                path,
                format!(
                    "the PLY header declares {} '{}' elements, more than its body of {} bytes \
                     can hold",
                    element.count,
                    excerpt(&element.name),
                    body.len()
                ),
            ));
        }
        held += element.count as u128
            * match element.name.as_str() {
                "vertex" => 48,
                "face" => 12,
                _ => 0,
            };
    }
    check_held(path, held)
}

/// The mesh of the PLY `body` described by `header`.
fn parse_body(header: &Header, body_bytes: &[u8], path: &Path) -> Result<TriangleMesh, IoError> {
    check_counts(header, body_bytes, path)?;
    let format = header.format;
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
    for element in &header.elements {
        if element.properties.is_empty() {
            continue;
        }
        let truncated = || {
            let what = excerpt(&element.name);
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
        // The counts were checked against the body's size above.
        let count = element.count as usize;
        if is_vertex {
            positions.reserve(count);
        } else if is_face {
            triangles.reserve(count);
        }
        let mut values = vec![0.0; element.properties.len()];
        let mut list = Vec::new();
        let mut face_list = Vec::new();
        for _ in 0..count {
            let lists = (&mut list, &mut face_list);
            let is_polygon = read_row(&mut body, element, &mut values, lists, &truncated)?;
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
            if is_polygon {
                push_polygon(&face_list, &mut triangles, path)?;
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

/// Reads one row of `element` from `body`: its scalar properties into `values`, and its lists
/// into `list`, a face's vertex indices into `face` (then true).
fn read_row(
    body: &mut PlyBody<'_>,
    element: &Element,
    values: &mut [f64],
    (list, face): (&mut Vec<f64>, &mut Vec<f64>),
    truncated: &impl Fn() -> IoError,
) -> Result<bool, IoError> {
    let is_face = element.name == "face";
    let mut is_polygon = false;
    for (k, property) in element.properties.iter().enumerate() {
        match property.list_count {
            None => values[k] = body.value(property.scalar).ok_or_else(truncated)?,
            Some(count_type) => {
                let items = body.value(count_type).ok_or_else(truncated)?;
                if !(0.0..=MAX_LIST_ITEMS).contains(&items) || items.fract() != 0.0 {
                    return Err(truncated());
                }
                list.clear();
                for _ in 0..items as usize {
                    list.push(body.value(property.scalar).ok_or_else(truncated)?);
                }
                if is_face && (property.name == "vertex_indices" || property.name == "vertex_index")
                {
                    std::mem::swap(face, list);
                    is_polygon = true;
                }
            }
        }
    }
    Ok(is_polygon)
}

/// Adds the triangles of the polygon `corners` (vertex indices as read): the fan from its
/// first corner.
fn push_polygon(
    corners: &[f64],
    triangles: &mut Vec<[u32; 3]>,
    path: &Path,
) -> Result<(), IoError> {
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
    Ok(())
}

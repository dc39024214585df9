//! Reading STL meshes, binary or ASCII, from a file or standard input.
//!
//! The input is read whole ([`Input::read_bytes`], within the memory cap), then:
//! - binary when its size is exactly `84 + 50 n` bytes for the count `n` at bytes 80..84,
//!   even when its 80-byte header starts with `solid` (some exporters write that);
//! - otherwise ASCII when it starts with `solid` (after a byte-order mark or blanks): a bare
//!   `solid`, `solid<TAB>name`, CRLF line ends and several solids one after the other are all
//!   read, every solid's facets into the one mesh; keywords in any letter case; the facet
//!   normals are not used; a facet loop of more than 3 vertices becomes the fan of triangles
//!   from its first vertex;
//! - otherwise binary, trailing bytes after the counted triangles ignored; a count the file
//!   is too short for is refused before anything is allocated.
//!
//! Equal corners are merged into one vertex (by their exact coordinates, `-0` equal to `0`),
//! so the mesh has shared vertices like the other formats; it has no normals. What the mesh
//! will keep is charged against the memory cap ([`check_held`]) before it is allocated
//! (binary) or as it grows (ASCII).
//!
//! Hand-written: `stl_io` decides binary against ASCII by the first five bytes only (so a
//! bare `solid` line or CRLF ends fail with "failed to fill whole buffer"), reads only the
//! first solid, and reads from a seekable file.

use std::collections::HashMap;
use std::io;
use std::path::Path;

use karkas::Point3;

use crate::error::{data_error, IoError};
use crate::input::{check_held, excerpt, read_line_bytes, Input};
use crate::mesh::triangle_mesh::TriangleMesh;

/// The bytes of a binary STL header and triangle count.
const HEADER: usize = 84;
/// The bytes of one binary STL triangle record.
const RECORD: usize = 50;
/// The bytes a mesh keeps per triangle at most while it is read: three new vertices (24
/// bytes each and about 40 in the merging table) and one index triple.
const HELD_PER_TRIANGLE: u128 = 3 * (24 + 40) + 12;

/// Reads the STL file `path` (`-`: standard input; binary or ASCII) as a mesh without
/// normals.
pub fn read_stl(path: &Path) -> Result<TriangleMesh, IoError> {
    read_stl_from(&mut Input::open(path)?)
}

/// Reads the STL mesh of `input` (see the module docs).
pub fn read_stl_from(input: &mut Input) -> Result<TriangleMesh, IoError> {
    let bytes = input.read_bytes()?;
    parse_stl(&bytes, &input.name)
}

/// The mesh of the STL file `bytes` (see the module docs); `path` names it in errors.
pub fn parse_stl(bytes: &[u8], path: &Path) -> Result<TriangleMesh, IoError> {
    let declared = bytes
        .get(80..HEADER)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64);
    let size = bytes.len() as u64;
    let exact = declared.is_some_and(|n| HEADER as u64 + RECORD as u64 * n == size);
    if !exact && starts_with_solid(bytes) {
        return parse_ascii(bytes, path, declared);
    }
    let Some(n) = declared else {
        return Err(decode(
            path,
            format!(
                "{size} bytes: too short for a binary STL (84 bytes at least) and not an \
                 ASCII STL (no 'solid' line)"
            ),
        ));
    };
    let needed = HEADER as u64 + RECORD as u64 * n;
    if needed > size {
        return Err(decode(
            path,
            format!(
                "the binary header counts {n} triangles, which need {needed} bytes, but the \
                 input has {size}"
            ),
        ));
    }
    check_held(path, size as u128 + n as u128 * HELD_PER_TRIANGLE)?;
    let mut mesh = MergedMesh::with_capacity(n as usize);
    for (k, record) in bytes[HEADER..needed as usize]
        .chunks_exact(RECORD)
        .enumerate()
    {
        let value = |i: usize| {
            let at = 12 + 4 * i;
            f32::from_le_bytes([record[at], record[at + 1], record[at + 2], record[at + 3]]) as f64
        };
        let corners =
            [0, 1, 2].map(|c| Point3::new([value(3 * c), value(3 * c + 1), value(3 * c + 2)]));
        if !corners.iter().all(|p| p.is_finite()) {
            return Err(data_error(
                path,
                format!("triangle {k}: a vertex is not finite"),
            ));
        }
        mesh.push_polygon(&corners, path)?;
    }
    mesh.finish(path)
}

/// True when `bytes` start with `solid` (any case), after a byte-order mark and blanks.
fn starts_with_solid(bytes: &[u8]) -> bool {
    let bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    let start = bytes
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(bytes.len());
    bytes[start..]
        .get(..5)
        .is_some_and(|w| w.eq_ignore_ascii_case(b"solid"))
}

/// An [`IoError::Decode`] of an STL file saying `message`.
fn decode(path: &Path, message: impl Into<String>) -> IoError {
    IoError::Decode {
        path: path.to_path_buf(),
        format: "STL",
        source: io::Error::new(io::ErrorKind::InvalidData, message.into()),
    }
}

/// The mesh of an ASCII STL (see the module docs); `declared` is the binary count the
/// bytes 80..84 would hold, for the message about a damaged binary file.
fn parse_ascii(bytes: &[u8], path: &Path, declared: Option<u64>) -> Result<TriangleMesh, IoError> {
    let mut reader = bytes;
    let mut buf = Vec::new();
    let mut mesh = MergedMesh::with_capacity(0);
    let mut facet: Option<Vec<Point3>> = None;
    let mut line = 0;
    loop {
        line += 1;
        let more = read_line_bytes(&mut reader, path, &mut buf, line).map_err(|e| {
            match (
                declared,
                buf.contains(&0) || bytes[..bytes.len().min(HEADER)].contains(&0),
            ) {
                (Some(n), true) => decode(
                    path,
                    format!(
                        "it starts with 'solid' but holds binary data, and its {} bytes are not \
                         84 + 50 x {n} for the {n} triangles its binary header counts (a \
                         damaged binary STL)",
                        bytes.len()
                    ),
                ),
                _ => e,
            }
        })?;
        if !more {
            break;
        }
        let text = std::str::from_utf8(&buf)
            .map_err(|_| decode(path, format!("line {line}: not text")))?;
        let text = text.trim_start_matches('\u{feff}');
        let mut words = text.split_ascii_whitespace();
        let Some(keyword) = words.next() else {
            continue;
        };
        let at = |message: String| decode(path, format!("line {line}: {message}"));
        match keyword.to_ascii_lowercase().as_str() {
            "solid" | "endsolid" if facet.is_some() => {
                return Err(at(format!("'{keyword}' inside a facet (no 'endfacet')")));
            }
            "solid" | "endsolid" => {}
            "facet" => {
                if facet.is_some() {
                    return Err(at("'facet' inside a facet (no 'endfacet')".to_owned()));
                }
                facet = Some(Vec::with_capacity(3));
            }
            "outer" | "endloop" if facet.is_some() => {}
            "vertex" => {
                let Some(corners) = facet.as_mut() else {
                    return Err(at("'vertex' outside a facet".to_owned()));
                };
                let values: Vec<&str> = words.by_ref().take(4).collect();
                if values.len() != 3 {
                    return Err(at(format!(
                        "'vertex' needs 3 numbers, found {}",
                        values.len()
                    )));
                }
                let mut p = Point3::ZERO;
                for (c, v) in values.iter().enumerate() {
                    p[c] = match v.parse::<f64>() {
                        Ok(x) if x.is_finite() => x,
                        _ => return Err(at(format!("'{}' is not a finite number", excerpt(v)))),
                    };
                }
                if corners.len() >= 1 << 16 {
                    return Err(at("a facet of more than 65536 vertices".to_owned()));
                }
                corners.push(p);
            }
            "endfacet" => {
                let Some(corners) = facet.take() else {
                    return Err(at("'endfacet' outside a facet".to_owned()));
                };
                if corners.len() < 3 {
                    return Err(at(format!(
                        "a facet needs 3 vertices, found {}",
                        corners.len()
                    )));
                }
                mesh.push_polygon(&corners, path)?;
                check_held(path, bytes.len() as u128 + mesh.held())?;
            }
            _ => {
                return Err(at(format!(
                    "unexpected '{}' (an ASCII STL line is solid, facet normal, outer loop, \
                     vertex, endloop, endfacet or endsolid)",
                    excerpt(keyword)
                )))
            }
        }
    }
    if facet.is_some() {
        return Err(decode(
            path,
            "the input ends inside a facet (no 'endfacet')",
        ));
    }
    mesh.finish(path)
}

/// A mesh built corner by corner, equal corners merged into one vertex.
struct MergedMesh {
    positions: Vec<Point3>,
    triangles: Vec<[u32; 3]>,
    index: HashMap<[u64; 3], u32>,
}

impl MergedMesh {
    fn with_capacity(triangles: usize) -> Self {
        MergedMesh {
            positions: Vec::with_capacity(triangles / 2),
            triangles: Vec::with_capacity(triangles),
            index: HashMap::with_capacity(triangles / 2),
        }
    }

    /// What the mesh keeps so far, in bytes (as [`HELD_PER_TRIANGLE`] counts it).
    fn held(&self) -> u128 {
        self.positions.len() as u128 * (24 + 40) + self.triangles.len() as u128 * 12
    }

    /// The vertex at `p`, added when new.
    fn vertex(&mut self, p: Point3) -> u32 {
        // `+ 0.0` turns -0 into 0, so both are one vertex.
        let key = [p[0] + 0.0, p[1] + 0.0, p[2] + 0.0].map(f64::to_bits);
        let next = self.positions.len() as u32;
        let k = *self.index.entry(key).or_insert(next);
        if k == next {
            self.positions.push(p);
        }
        k
    }

    /// The triangles of the polygon `corners` (3 or more): the fan from its first corner.
    /// More vertices than 32-bit indices address is an error.
    fn push_polygon(&mut self, corners: &[Point3], path: &Path) -> Result<(), IoError> {
        if self.positions.len() + corners.len() > u32::MAX as usize {
            return Err(data_error(
                path,
                "more vertices than 32-bit mesh indices can address",
            ));
        }
        let ids: Vec<u32> = corners.iter().map(|&p| self.vertex(p)).collect();
        for w in 1..ids.len() - 1 {
            self.triangles.push([ids[0], ids[w], ids[w + 1]]);
        }
        Ok(())
    }

    fn finish(self, path: &Path) -> Result<TriangleMesh, IoError> {
        TriangleMesh {
            positions: self.positions,
            normals: Vec::new(),
            triangles: self.triangles,
            grid: None,
        }
        .checked_read(path)
    }
}

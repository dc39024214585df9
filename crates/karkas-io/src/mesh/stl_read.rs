//! Reading STL meshes, binary or ASCII, from a file or standard input, in one pass.
//!
//! The first 84 bytes decide:
//! - a header that does not start with `solid` is binary: the triangle records are read one
//!   at a time, as many as the count at bytes 80..84 says (trailing bytes are not read); an
//!   input that ends before them is refused, saying how many bytes the count needs;
//! - a header that starts with `solid` (after a byte-order mark or blanks) is binary when the
//!   input is exactly `84 + 50 n` bytes for that count `n`, or longer and holding binary data
//!   (a NUL byte; trailing bytes then ignored): some exporters start binary headers with
//!   `solid`. Those bytes are read, when the memory cap allows them, and one more to see the
//!   end;
//! - otherwise it is ASCII, read line by line (each line bounded): a bare `solid`,
//!   `solid<TAB>name`, CRLF line ends and several solids one after the other are all read,
//!   every solid's facets into the one mesh; keywords in any letter case; solid names in any
//!   encoding; the facet normals are not used; a facet loop of more than 3 vertices becomes the fan of triangles from its
//!   first vertex.
//!
//! Equal corners are merged into one vertex (by their exact coordinates, `-0` equal to `0`),
//! so the mesh has shared vertices like the other formats; it has no normals. What the mesh
//! keeps is charged against the memory cap ([`check_held`]) as it grows, and nothing is
//! allocated from the header's count beyond a small first capacity.
//!
//! Hand-written: `stl_io` decides binary against ASCII by the first five bytes only (so a
//! bare `solid` line or CRLF ends fail with "failed to fill whole buffer"), reads only the
//! first solid, and needs a seekable file.

use std::collections::HashMap;
use std::io::{self, BufRead, Cursor, Read};
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
/// The triangles between two checks of what a binary read keeps.
const CHECK_EVERY: u64 = 4096;

/// Reads the STL file `path` (`-`: standard input; binary or ASCII) as a mesh without
/// normals.
pub fn read_stl(path: &Path) -> Result<TriangleMesh, IoError> {
    read_stl_from(&mut Input::open(path)?)
}

/// The mesh of the STL file `bytes` (see the module docs); `path` names it in errors.
pub fn parse_stl(bytes: &[u8], path: &Path) -> Result<TriangleMesh, IoError> {
    read_stl_from(&mut Input::from_reader(path, Cursor::new(bytes.to_vec())))
}

/// Reads the STL mesh of `input` (see the module docs).
pub fn read_stl_from(input: &mut Input) -> Result<TriangleMesh, IoError> {
    let name = input.name.clone();
    let path = name.as_path();
    let head = read_up_to(input, HEADER as u64, path)?;
    let declared = head
        .get(80..HEADER)
        .map(|b| u32::from_le_bytes([b[0], b[1], b[2], b[3]]) as u64);
    let head_is_binary = head.contains(&0);
    if starts_with_solid(&head) {
        let Some(n) = declared else {
            return parse_ascii(&mut Cursor::new(head).chain(input), path, None);
        };
        let body = RECORD as u64 * n;
        if check_held(path, body as u128 + n as u128 * HELD_PER_TRIANGLE).is_err() {
            let hint = head_is_binary.then_some(n);
            return parse_ascii(&mut Cursor::new(head).chain(input), path, hint);
        }
        let records = read_up_to(input, body + 1, path)?;
        let binary = head_is_binary || records.contains(&0);
        // Exactly the counted records, or more of them with binary data (trailing bytes after
        // the records, as some exporters write, are ignored as for other binary headers).
        if records.len() as u64 == body || (records.len() as u64 > body && binary) {
            return read_binary(&mut records.as_slice(), n, path);
        }
        let hint = binary.then_some(n);
        let bytes = [head, records].concat();
        return parse_ascii(&mut Cursor::new(bytes).chain(input), path, hint);
    }
    let Some(n) = declared else {
        return Err(decode(
            path,
            format!(
                "{} bytes: too short for a binary STL (84 bytes at least) and not an ASCII \
                 STL (no 'solid' line)",
                head.len()
            ),
        ));
    };
    read_binary(input, n, path)
}

/// Up to `limit` bytes of `reader` (fewer at its end).
fn read_up_to(reader: &mut impl Read, limit: u64, path: &Path) -> Result<Vec<u8>, IoError> {
    let mut bytes = Vec::new();
    reader
        .take(limit)
        .read_to_end(&mut bytes)
        .map_err(IoError::open(path))?;
    Ok(bytes)
}

/// The `n` binary triangle records of `reader` (after the 84-byte header).
fn read_binary(reader: &mut impl Read, n: u64, path: &Path) -> Result<TriangleMesh, IoError> {
    let mut mesh = MergedMesh::with_capacity(n.min(1 << 16) as usize);
    let mut record = [0u8; RECORD];
    for k in 0..n {
        let got = fill(reader, &mut record).map_err(IoError::open(path))?;
        if got < RECORD {
            let needed = HEADER as u64 + RECORD as u64 * n;
            let size = HEADER as u64 + RECORD as u64 * k + got as u64;
            return Err(decode(
                path,
                format!(
                    "the binary header counts {n} triangles, which need {needed} bytes, but \
                     the input has {size}"
                ),
            ));
        }
        let value = |i: usize| {
            let at = 12 + 4 * i;
            let b = [record[at], record[at + 1], record[at + 2], record[at + 3]];
            f32::from_le_bytes(b) as f64
        };
        let corners = [0, 1, 2].map(|c| Point3::new([0, 1, 2].map(|x| value(3 * c + x))));
        if !corners.iter().all(|p| p.is_finite()) {
            return Err(data_error(
                path,
                format!("triangle {k}: a vertex is not finite"),
            ));
        }
        mesh.push_polygon(&corners, path)?;
        if k % CHECK_EVERY == 0 {
            check_held(path, mesh.held())?;
        }
    }
    check_held(path, mesh.held())?;
    mesh.finish(path)
}

/// Fills `buf` from `reader`; the number of bytes read, fewer than `buf.len()` only at the
/// end of the input.
fn fill(reader: &mut impl Read, buf: &mut [u8]) -> io::Result<usize> {
    let mut got = 0;
    while got < buf.len() {
        match reader.read(&mut buf[got..]) {
            Ok(0) => break,
            Ok(k) => got += k,
            Err(e) if e.kind() == io::ErrorKind::Interrupted => {}
            Err(e) => return Err(e),
        }
    }
    Ok(got)
}

/// True when `bytes` start with `solid` (any case), after a byte-order mark and blanks.
fn starts_with_solid(bytes: &[u8]) -> bool {
    let bytes = bytes.strip_prefix(b"\xef\xbb\xbf").unwrap_or(bytes);
    let start = bytes.trim_ascii_start();
    start.len() >= 5 && start[..5].eq_ignore_ascii_case(b"solid")
}

/// An [`IoError::Decode`] of an STL file saying `message`.
fn decode(path: &Path, message: impl Into<String>) -> IoError {
    IoError::Decode {
        path: path.to_path_buf(),
        format: "STL",
        source: io::Error::new(io::ErrorKind::InvalidData, message.into()),
    }
}

/// The mesh of the ASCII STL lines of `reader` (see the module docs). `damaged_binary` is
/// the count of a binary header whose bytes were seen: binary data in the lines is then
/// reported as a damaged binary STL.
fn parse_ascii<R: BufRead + ?Sized>(
    reader: &mut R,
    path: &Path,
    damaged_binary: Option<u64>,
) -> Result<TriangleMesh, IoError> {
    let mut buf = Vec::new();
    let mut mesh = MergedMesh::with_capacity(0);
    let mut facet: Option<Vec<Point3>> = None;
    let mut line = 0;
    loop {
        line += 1;
        let more =
            read_line_bytes(reader, path, &mut buf, line).map_err(|e| match damaged_binary {
                Some(n) => damaged(path, n),
                None => e,
            })?;
        if !more {
            break;
        }
        // Solid names in another encoding than UTF-8 are common; only keywords and numbers
        // are read.
        let text = String::from_utf8_lossy(&buf);
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
                let p = vertex_point(words).map_err(at)?;
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
                check_held(path, mesh.held())?;
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

/// The error of binary data in a file that starts with `solid` and whose binary header counts
/// `n` triangles, but whose size does not fit them.
fn damaged(path: &Path, n: u64) -> IoError {
    decode(
        path,
        format!(
            "it starts with 'solid' but holds binary data, and its size is not 84 + 50 x {n} \
             bytes for the {n} triangles its binary header counts (a damaged binary STL)"
        ),
    )
}

/// The point of an ASCII STL `vertex` line from the `words` after its keyword.
fn vertex_point<'a>(words: impl Iterator<Item = &'a str>) -> Result<Point3, String> {
    let values: Vec<&str> = words.take(4).collect();
    if values.len() != 3 {
        return Err(format!("'vertex' needs 3 numbers, found {}", values.len()));
    }
    let mut p = Point3::ZERO;
    for (c, v) in values.iter().enumerate() {
        p[c] = match v.parse::<f64>() {
            Ok(x) if x.is_finite() => x,
            _ => return Err(format!("'{}' is not a finite number", excerpt(v))),
        };
    }
    Ok(p)
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

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
//! round-trip decimal (ASCII). The seam of a closed sample grid is welded (see
//! `mesh/shared_vertices.rs`).
//!
//! Reading (every encoding, from a file or standard input) is in `mesh/ply_read.rs`.

use std::io::{self, Write};
use std::path::Path;

use crate::error::IoError;
use crate::mesh::shared_vertices::SharedVertices;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::write::write_atomic;

pub use crate::mesh::ply_read::{parse_ply, read_ply, read_ply_from, MAX_HEADER_BYTES};

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
    let shared = SharedVertices::of(mesh);
    write!(
        out,
        "ply\nformat {format} 1.0\ncomment karkas mesh\n\
         element vertex {}\nproperty double x\nproperty double y\nproperty double z\n\
         property float nx\nproperty float ny\nproperty float nz\n\
         element face {}\nproperty list uchar uint vertex_indices\nend_header\n",
        shared.vertex_count(),
        shared.triangle_count()
    )?;
    match encoding {
        PlyEncoding::BinaryLittleEndian => {
            for (p, n) in shared.positions().zip(shared.normals()) {
                for c in 0..3 {
                    out.write_all(&p[c].to_le_bytes())?;
                }
                for c in 0..3 {
                    out.write_all(&(n[c] as f32).to_le_bytes())?;
                }
            }
            for t in shared.triangles() {
                out.write_all(&[3u8])?;
                for k in t {
                    out.write_all(&k.to_le_bytes())?;
                }
            }
        }
        PlyEncoding::Ascii => {
            for (p, n) in shared.positions().zip(shared.normals()) {
                writeln!(
                    out,
                    "{} {} {} {} {} {}",
                    p[0], p[1], p[2], n[0] as f32, n[1] as f32, n[2] as f32
                )?;
            }
            for t in shared.triangles() {
                writeln!(out, "3 {} {} {}", t[0], t[1], t[2])?;
            }
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::{Grid, Point3};

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

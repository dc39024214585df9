//! STL meshes, written (binary or ASCII) and read (either).
//!
//! STL is what 3-D printers and most CAD and mesh tools take in. Binary files are written
//! with the `stl_io` crate (binary STL: an 80-byte header, the triangle
//! count, and one 50-byte record per triangle: facet normal, three vertices, all `f32`); ASCII
//! (`solid` / `facet normal` / `outer loop` / `vertex` lines) is written directly since
//! `stl_io` writes binary only.
//!
//! Facet normals are the triangles' own (see `mesh/normals.rs`, zero when degenerate). A sample
//! grid is triangulated as in `mesh/triangulate.rs`; its triangles are produced one at a time
//! as they are written, so no copy of the mesh is held in memory. A closed surface is passed
//! with its first row and column repeated at the end, so the cells cover the seam; the repeated
//! points are exact copies, and the mesh is closed in the sense STL knows (its edges meet at
//! equal vertex coordinates).
//!
//! A grid mesh with a pole line (see `mesh/closed.rs`) is written with its poles closed by
//! fans, without zero-area triangles.
//!
//! Reading (binary or ASCII, from a file or standard input) is in `mesh/stl_read.rs`.

use std::borrow::Cow;
use std::io;
use std::path::Path;

use karkas::Point3;
use stl_io::{Normal, Triangle, Vertex};

use crate::error::IoError;
use crate::mesh::closed::{has_poles, weld_grid_mesh};
use crate::mesh::error::MeshError;
use crate::mesh::normals::triangle_normal;
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::triangulate::{check_grid, grid_triangles};
use crate::write::write_atomic;

pub use crate::mesh::stl_read::{parse_stl, read_stl, read_stl_from};

/// Writes the `nu x nv` sample grid `points` (row-major, `u` outer) as a binary STL mesh at
/// `path`, atomically.
///
/// Errors ([`IoError::InvalidMesh`], nothing written): `points.len() != nu * nv`
/// ([`MeshError::PointCount`]), or more triangles than binary STL can count
/// (`2 (nu - 1)(nv - 1) > 2^32 - 1`, [`MeshError::TooManyTriangles`]).
pub fn write_surface_stl(
    path: &Path,
    nu: usize,
    nv: usize,
    points: &[Point3],
) -> Result<(), IoError> {
    let checked = check_grid(nu, nv, points.len()).and_then(|()| {
        let triangles = grid_triangles(nu, nv).len();
        match u32::try_from(triangles) {
            Ok(_) => Ok(()),
            Err(_) => Err(MeshError::TooManyTriangles { triangles }),
        }
    });
    checked.map_err(IoError::invalid_mesh(path))?;
    let triangles = grid_triangles(nu, nv).map(|t| triangle(t.map(|k| points[k])));
    write_atomic(path, |out| stl_io::write_stl(&mut &mut *out, triangles))
}

/// The STL triangle with these corners and their unit normal (zero when degenerate).
fn triangle(corners: [Point3; 3]) -> Triangle {
    let f32s = |p: Point3| [p[0] as f32, p[1] as f32, p[2] as f32];
    Triangle {
        normal: Normal::new(f32s(triangle_normal(corners))),
        vertices: corners.map(|p| Vertex::new(f32s(p))),
    }
}

/// Writes the triangle mesh `mesh` as STL at `path`, atomically: binary, or ASCII when `ascii`
/// (see the module docs). A mesh failing [`TriangleMesh::validate`] is an
/// [`IoError::InvalidMesh`], nothing written.
pub fn write_mesh_stl(path: &Path, mesh: &TriangleMesh, ascii: bool) -> Result<(), IoError> {
    mesh.check_writable(path)?;
    let mesh = poles_welded(mesh);
    let mesh = mesh.as_ref();
    if ascii {
        write_atomic(path, |out| render_mesh_stl_ascii(mesh, out))
    } else {
        let triangles = mesh
            .triangles
            .iter()
            .map(|t| triangle(t.map(|k| mesh.positions[k as usize])));
        write_atomic(path, |out| stl_io::write_stl(&mut &mut *out, triangles))
    }
}

/// Writes the ASCII STL text of `mesh` into `out` (the mesh is assumed valid).
pub fn render_mesh_stl_ascii(mesh: &TriangleMesh, out: &mut dyn io::Write) -> io::Result<()> {
    let mesh = poles_welded(mesh);
    writeln!(out, "solid karkas")?;
    for t in &mesh.triangles {
        let n = mesh.face_normal(*t);
        writeln!(out, "facet normal {} {} {}\n  outer loop", n[0], n[1], n[2])?;
        for &k in t {
            let p = mesh.positions[k as usize];
            writeln!(out, "    vertex {} {} {}", p[0], p[1], p[2])?;
        }
        writeln!(out, "  endloop\nendfacet")?;
    }
    writeln!(out, "endsolid karkas")
}

/// `mesh`, or, for a grid with a pole line, its general mesh with the poles closed by fans
/// (`mesh/closed.rs`), so that no triangle has zero area.
fn poles_welded(mesh: &TriangleMesh) -> Cow<'_, TriangleMesh> {
    if has_poles(mesh) {
        Cow::Owned(weld_grid_mesh(mesh))
    } else {
        Cow::Borrowed(mesh)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ascii_golden() {
        let grid = karkas::Grid::from_fn(2, 2, |a, b| Point3::new([a as f64, b as f64, 0.0]));
        let mesh = TriangleMesh::from_grid(&grid).unwrap();
        let mut out = Vec::new();
        render_mesh_stl_ascii(&mesh, &mut out).unwrap();
        let expected = "solid karkas\nfacet normal 0 0 1\n  outer loop\n    vertex 0 0 0\n\
            \x20   vertex 1 0 0\n    vertex 1 1 0\n  endloop\nendfacet\nfacet normal 0 0 1\n\
            \x20 outer loop\n    vertex 0 0 0\n    vertex 1 1 0\n    vertex 0 1 0\n  endloop\n\
            endfacet\nendsolid karkas\n";
        assert_eq!(String::from_utf8(out).unwrap(), expected);
        // stl_io reads it back as two faces over four vertices.
        let mut text = Vec::new();
        render_mesh_stl_ascii(&mesh, &mut text).unwrap();
        let read = stl_io::read_stl(&mut std::io::Cursor::new(text)).unwrap();
        assert_eq!((read.faces.len(), read.vertices.len()), (2, 4));
    }

    /// The grid writer and the mesh writer give the same binary file.
    #[test]
    fn surface_and_mesh_writers_agree() {
        let dir = tempfile::tempdir().unwrap();
        let grid = karkas::Grid::from_fn(3, 4, |a, b| Point3::new([a as f64, b as f64, 0.0]));
        let (a, b) = (dir.path().join("a.stl"), dir.path().join("b.stl"));
        write_surface_stl(&a, 3, 4, grid.as_slice()).unwrap();
        write_mesh_stl(&b, &TriangleMesh::from_grid(&grid).unwrap(), false).unwrap();
        let bytes = std::fs::read(&a).unwrap();
        assert_eq!(bytes.len(), 84 + 12 * 50);
        assert_eq!(bytes, std::fs::read(&b).unwrap());
        // u along x, v along y: every facet normal is +z.
        let read = stl_io::read_stl(&mut std::io::Cursor::new(bytes)).unwrap();
        assert_eq!(read.faces.len(), 12);
        for f in &read.faces {
            assert_eq!(f.normal, Normal::new([0.0, 0.0, 1.0]));
        }
    }
}

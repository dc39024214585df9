//! A sampled surface as a binary STL triangle mesh.
//!
//! STL is what 3-D printers and most CAD and mesh tools take in. The file is written with the
//! `stl_io` crate (binary STL: an 80-byte header, the triangle count, and one 50-byte record
//! per triangle: facet normal, three vertices, all `f32`).
//!
//! The mesh is the sample grid itself (`nu x nv` points, row-major, `u` outer), two triangles
//! per grid cell, split and oriented as in [`crate::obj`]: counter-clockwise seen from the side
//! of `d/du x d/dv`, which is the facet normal written (zero for a degenerate triangle). A closed
//! surface is passed with its first row and column repeated at the end, so the cells cover the
//! seam; the repeated points are exact copies, and the mesh is closed in the sense STL knows (its
//! edges meet at equal vertex coordinates). Triangles are produced one at a time as they are
//! written: no copy of the mesh is held in memory.

use std::io;
use std::path::Path;

use karkas::Point3;
use stl_io::{Normal, Triangle, Vertex};

use crate::error::IoError;
use crate::mesh::TriangleMesh;
use crate::write::write_atomic;

/// Writes the `nu x nv` sample grid `points` (row-major, `u` outer) as a binary STL mesh at
/// `path`, atomically.
///
/// Errors ([`IoError::Write`], nothing written): `points.len() != nu * nv`, or more triangles
/// than binary STL can count (`2 (nu - 1)(nv - 1) > 2^32 - 1`).
pub fn write_surface_stl(
    path: &Path,
    nu: usize,
    nv: usize,
    points: &[Point3],
) -> Result<(), IoError> {
    let error = |message: String| IoError::Write {
        path: path.to_path_buf(),
        source: io::Error::new(io::ErrorKind::InvalidInput, message),
    };
    let triangles = SurfaceTriangles::new(nu, nv, points).map_err(error)?;
    write_atomic(path, |out| stl_io::write_stl(&mut &mut *out, triangles))
}

/// The triangles of a sample grid, produced on demand.
#[derive(Clone, Debug)]
pub struct SurfaceTriangles<'a> {
    nv: usize,
    points: &'a [Point3],
    /// Index of the next triangle: cell `k / 2` (row-major over `(nu-1) x (nv-1)`), half `k % 2`.
    next: usize,
    count: usize,
}

impl<'a> SurfaceTriangles<'a> {
    /// The triangles of the `nu x nv` grid `points`; the error says why there are none to write.
    pub fn new(nu: usize, nv: usize, points: &'a [Point3]) -> Result<Self, String> {
        if nu.checked_mul(nv) != Some(points.len()) {
            return Err(format!(
                "{} points do not form a {nu} x {nv} grid",
                points.len()
            ));
        }
        let count = 2 * nu.saturating_sub(1) * nv.saturating_sub(1);
        if u32::try_from(count).is_err() {
            return Err(format!(
                "{count} triangles are more than binary STL can hold"
            ));
        }
        Ok(SurfaceTriangles {
            nv,
            points,
            next: 0,
            count,
        })
    }
}

impl Iterator for SurfaceTriangles<'_> {
    type Item = Triangle;

    fn next(&mut self) -> Option<Triangle> {
        if self.next >= self.count {
            return None;
        }
        let (cell, half) = (self.next / 2, self.next % 2);
        self.next += 1;
        let cols = self.nv - 1;
        let (a, b) = (cell / cols, cell % cols);
        let at = |a: usize, b: usize| self.points[a * self.nv + b];
        // The same split as the OBJ writer: (a,b) (a+1,b) (a+1,b+1) and (a,b) (a+1,b+1) (a,b+1).
        let corners = if half == 0 {
            [at(a, b), at(a + 1, b), at(a + 1, b + 1)]
        } else {
            [at(a, b), at(a + 1, b + 1), at(a, b + 1)]
        };
        Some(triangle(corners))
    }

    fn size_hint(&self) -> (usize, Option<usize>) {
        let left = self.count - self.next;
        (left, Some(left))
    }
}

impl ExactSizeIterator for SurfaceTriangles<'_> {}

/// The STL triangle with these corners and their unit normal (zero when degenerate).
fn triangle(corners: [Point3; 3]) -> Triangle {
    let (e1, e2) = (corners[1] - corners[0], corners[2] - corners[0]);
    let n = Point3::new([
        e1[1] * e2[2] - e1[2] * e2[1],
        e1[2] * e2[0] - e1[0] * e2[2],
        e1[0] * e2[1] - e1[1] * e2[0],
    ]);
    let len = n.norm();
    let n = if len > 0.0 && len.is_finite() {
        n * (1.0 / len)
    } else {
        Point3::ZERO
    };
    let f32s = |p: Point3| [p[0] as f32, p[1] as f32, p[2] as f32];
    Triangle {
        normal: Normal::new(f32s(n)),
        vertices: corners.map(|p| Vertex::new(f32s(p))),
    }
}

/// Writes the triangle mesh `mesh` as STL at `path`, atomically: binary (through `stl_io`) or
/// ASCII (`solid` / `facet normal` / `outer loop` / `vertex` lines, written directly since
/// `stl_io` writes binary only). Facet normals are the triangles' own (zero when degenerate).
/// A mesh failing [`TriangleMesh::validate`] is an [`IoError::Write`], nothing written.
pub fn write_mesh_stl(path: &Path, mesh: &TriangleMesh, ascii: bool) -> Result<(), IoError> {
    crate::mesh_check(path, mesh)?;
    if ascii {
        write_atomic(path, |out| render_mesh_stl_ascii(mesh, out))
    } else {
        let triangles = mesh.triangles.iter().map(|t| {
            let at = |k: u32| mesh.positions[k as usize];
            triangle([at(t[0]), at(t[1]), at(t[2])])
        });
        write_atomic(path, |out| stl_io::write_stl(&mut &mut *out, triangles))
    }
}

/// Writes the ASCII STL text of `mesh` into `out` (the mesh is assumed valid).
pub fn render_mesh_stl_ascii(mesh: &TriangleMesh, out: &mut dyn io::Write) -> io::Result<()> {
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn triangle_count_and_orientation() {
        // The unit square in the x-y plane, u along x, v along y: normals +z.
        let pts: Vec<Point3> = (0..3)
            .flat_map(|a| (0..4).map(move |b| Point3::new([a as f64, b as f64, 0.0])))
            .collect();
        let tris: Vec<Triangle> = SurfaceTriangles::new(3, 4, &pts).unwrap().collect();
        assert_eq!(tris.len(), 2 * 2 * 3);
        for t in &tris {
            assert_eq!(t.normal, Normal::new([0.0, 0.0, 1.0]));
        }
        assert!(SurfaceTriangles::new(3, 3, &pts).is_err());
        assert_eq!(SurfaceTriangles::new(1, 12, &pts).unwrap().len(), 0);
    }

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
}

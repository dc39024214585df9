//! What a writer of a format with shared vertices (OBJ, PLY, glTF) emits for a mesh: its
//! vertices and triangles as they are, or, for the mesh of a sample grid whose last row
//! (column) repeats its first, the mesh with that seam welded (see `mesh/triangulate.rs`):
//! the repeated samples are not written and the triangles along the seam use the first
//! row's (column's) vertices, so that mesh tools see one closed surface.
//!
//! A grid whose first or last row (column) is one point (a pole) is written as the general
//! mesh of `mesh/closed.rs` instead, its poles closed by fans. Otherwise nothing is copied:
//! positions, normals and triangles are produced on demand from the mesh (normals are
//! computed once when the mesh has none).

use std::borrow::Cow;

use karkas::Point3;

use crate::mesh::closed::{has_poles, weld_grid_mesh};
use crate::mesh::triangle_mesh::TriangleMesh;
use crate::mesh::triangulate::GridSeams;

/// The vertices and triangles of a mesh as a format with shared vertices writes them.
pub(crate) struct SharedVertices<'a> {
    mesh: Cow<'a, TriangleMesh>,
    seams: GridSeams,
    normals: Cow<'a, [Point3]>,
}

impl<'a> SharedVertices<'a> {
    /// The mesh `mesh` (assumed valid), its grid seams welded when it has a grid shape.
    pub(crate) fn of(mesh: &'a TriangleMesh) -> SharedVertices<'a> {
        let mesh = if has_poles(mesh) {
            Cow::Owned(weld_grid_mesh(mesh))
        } else {
            Cow::Borrowed(mesh)
        };
        let n = mesh.positions.len();
        let seams = match mesh.grid {
            Some((nu, nv)) => GridSeams::detect(nu, nv, &mesh.positions),
            None => GridSeams::open(n, 1),
        };
        let normals = match &mesh {
            Cow::Borrowed(m) if m.normals.len() == n => Cow::Borrowed(m.normals.as_slice()),
            _ => Cow::Owned(mesh.vertex_normals()),
        };
        SharedVertices {
            mesh,
            seams,
            normals,
        }
    }

    /// The seams welded (none for a general mesh).
    pub fn seams(&self) -> GridSeams {
        self.seams
    }

    /// The number of vertices written.
    pub fn vertex_count(&self) -> usize {
        if self.seams.welds() {
            self.seams.vertex_count()
        } else {
            self.mesh.positions.len()
        }
    }

    /// The number of triangles written.
    pub fn triangle_count(&self) -> usize {
        self.mesh.triangles.len()
    }

    /// The vertex positions, in order.
    pub fn positions(&self) -> impl Iterator<Item = Point3> + '_ {
        self.kept(&self.mesh.positions)
    }

    /// One unit normal per vertex, in order.
    pub fn normals(&self) -> impl Iterator<Item = Point3> + '_ {
        self.kept(&self.normals)
    }

    /// The triangles over the vertices written.
    pub fn triangles(&self) -> impl Iterator<Item = [u32; 3]> + '_ {
        let seams = self.seams;
        let welds = seams.welds();
        self.mesh.triangles.iter().map(move |t| {
            if welds {
                t.map(|k| seams.vertex(k as usize) as u32)
            } else {
                *t
            }
        })
    }

    /// The items of `values` (one per sample) that are vertices of their own.
    fn kept<'b>(&self, values: &'b [Point3]) -> impl Iterator<Item = Point3> + 'b {
        let seams = self.seams;
        let welds = seams.welds();
        values
            .iter()
            .enumerate()
            .filter(move |(k, _)| !welds || seams.is_kept(*k))
            .map(|(_, p)| *p)
    }
}

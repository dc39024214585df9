//! A triangle mesh in memory: the common form every mesh writer takes, built from a sampled
//! surface grid or read from a mesh file.
//!
//! A sampled surface (`nu x nv` points, row-major, `u` outer) becomes the mesh of its grid: one
//! vertex per sample, one normal per vertex and two triangles per grid cell (see
//! `mesh/normals.rs` and `mesh/triangulate.rs`). The grid shape is kept, so writers of
//! structured formats (VTK structured grids) can use it, and writers of formats with shared
//! vertices (OBJ, PLY, glTF) weld the seam of a closed grid (`mesh/shared_vertices.rs`).
//!
//! Memory: `nu nv` positions and normals and `2 (nu-1)(nv-1)` index triples, O(nu nv).

use std::path::Path;

use karkas::{Grid, Point3};

use crate::error::IoError;
use crate::mesh::error::MeshError;
use crate::mesh::normals::{averaged_normals, grid_normals, triangle_normal};
use crate::mesh::triangulate::grid_triangles;

/// A triangle mesh: vertices, optional per-vertex normals, triangles as vertex index triples.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TriangleMesh {
    /// The vertex positions.
    pub positions: Vec<Point3>,
    /// One unit normal per vertex, or empty when the mesh has none.
    pub normals: Vec<Point3>,
    /// The triangles, each three 0-based indices into `positions`, counter-clockwise seen
    /// from the side the normals point to.
    pub triangles: Vec<[u32; 3]>,
    /// `(rows, cols)` when the vertices are a row-major sample grid (set by
    /// [`TriangleMesh::from_grid`]), `None` for a general mesh.
    pub grid: Option<(usize, usize)>,
}

impl TriangleMesh {
    /// The mesh of a sampled surface grid (see the module docs); an error
    /// ([`MeshError::TooManyVertices`]) when the grid has `2^32` or more samples.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::{Grid, Point};
    /// use karkas_io::mesh::TriangleMesh;
    ///
    /// // A 3 x 4 grid of samples: 12 vertices and 2 x 3 cells of two triangles each.
    /// let grid = Grid::from_fn(3, 4, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let mesh = TriangleMesh::from_grid(&grid).expect("a small grid");
    /// assert_eq!((mesh.positions.len(), mesh.triangles.len()), (12, 12));
    /// ```
    pub fn from_grid(grid: &Grid<Point3>) -> Result<TriangleMesh, MeshError> {
        let (nu, nv) = (grid.rows(), grid.cols());
        let points = grid.as_slice();
        if u32::try_from(points.len()).is_err() {
            return Err(MeshError::TooManyVertices {
                vertices: points.len(),
            });
        }
        Ok(TriangleMesh {
            positions: points.to_vec(),
            normals: grid_normals(nu, nv, points).collect(),
            triangles: grid_triangles(nu, nv)
                .map(|t| t.map(|k| k as u32))
                .collect(),
            grid: Some((nu, nv)),
        })
    }

    /// Turns the mesh over: the triangles' winding is reversed and the normals negated, so
    /// the other side of the surface faces out. A grid-shaped mesh stays one: each row of
    /// samples is reversed (the `v` direction runs backwards), which reverses every triangle
    /// of [`TriangleMesh::from_grid`] and keeps structured formats consistent.
    pub fn flip_orientation(&mut self) {
        for n in &mut self.normals {
            *n = -*n;
        }
        match self.grid {
            Some((rows, cols))
                if cols > 0
                    && rows.checked_mul(cols) == Some(self.positions.len())
                    && self.triangles.len() == grid_triangles(rows, cols).len() =>
            {
                self.positions
                    .chunks_mut(cols)
                    .for_each(<[Point3]>::reverse);
                if self.normals.len() == self.positions.len() {
                    self.normals.chunks_mut(cols).for_each(<[Point3]>::reverse);
                }
            }
            _ => {
                for t in &mut self.triangles {
                    t.swap(1, 2);
                }
            }
        }
    }

    /// The unit normal of triangle `t` (`(b - a) x (c - a)` normalised; zero when degenerate
    /// or an index is out of range).
    pub fn face_normal(&self, t: [u32; 3]) -> Point3 {
        let at = |k: u32| self.positions.get(k as usize).copied();
        match (at(t[0]), at(t[1]), at(t[2])) {
            (Some(a), Some(b), Some(c)) => triangle_normal([a, b, c]),
            _ => Point3::ZERO,
        }
    }

    /// Per-vertex normals: the given ones, or (when the mesh has none) the area-weighted mean
    /// of the normals of the triangles around each vertex (`0 0 1` for a vertex on no
    /// triangle of positive area).
    pub fn vertex_normals(&self) -> Vec<Point3> {
        if self.normals.len() == self.positions.len() {
            return self.normals.clone();
        }
        averaged_normals(&self.positions, &self.triangles)
    }

    /// The checks every writer relies on: every index in range, normals absent or one per
    /// vertex, at most `2^32 - 1` vertices, a grid shape matching the vertex count.
    pub fn validate(&self) -> Result<(), MeshError> {
        let n = self.positions.len();
        if !self.normals.is_empty() && self.normals.len() != n {
            return Err(MeshError::NormalCount {
                normals: self.normals.len(),
                vertices: n,
            });
        }
        if u32::try_from(n).is_err() {
            return Err(MeshError::TooManyVertices { vertices: n });
        }
        if let Some((k, t)) = self
            .triangles
            .iter()
            .enumerate()
            .find(|(_, t)| t.iter().any(|&i| i as usize >= n))
        {
            return Err(MeshError::IndexOutOfRange {
                triangle: k,
                corners: *t,
                vertices: n,
            });
        }
        if let Some((rows, cols)) = self.grid {
            if rows.checked_mul(cols) != Some(n) {
                return Err(MeshError::GridShape {
                    vertices: n,
                    rows,
                    cols,
                });
            }
        }
        Ok(())
    }

    /// [`TriangleMesh::validate`] for a writer of `path`: [`IoError::InvalidMesh`] when a
    /// check fails.
    pub(crate) fn check_writable(&self, path: &Path) -> Result<(), IoError> {
        self.validate().map_err(IoError::invalid_mesh(path))
    }

    /// [`TriangleMesh::validate`] for a mesh read from `path`: [`IoError::MalformedMesh`] when
    /// a check fails.
    pub(crate) fn checked_read(self, path: &Path) -> Result<TriangleMesh, IoError> {
        match self.validate() {
            Ok(()) => Ok(self),
            Err(source) => Err(IoError::MalformedMesh {
                path: path.to_path_buf(),
                source,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane(nu: usize, nv: usize) -> Grid<Point3> {
        Grid::from_fn(nu, nv, |a, b| Point3::new([a as f64, b as f64, 0.0]))
    }

    #[test]
    fn grid_mesh_counts_orientation_and_normals() {
        let mesh = TriangleMesh::from_grid(&plane(3, 4)).unwrap();
        assert_eq!(mesh.positions.len(), 12);
        assert_eq!(mesh.triangles.len(), 2 * 2 * 3);
        assert_eq!(mesh.grid, Some((3, 4)));
        mesh.validate().unwrap();
        // u along x, v along y: d/du x d/dv = +z, and every triangle turns counter-clockwise
        // seen from +z.
        for n in &mesh.normals {
            assert_eq!(*n, Point3::new([0.0, 0.0, 1.0]));
        }
        for t in &mesh.triangles {
            assert_eq!(mesh.face_normal(*t), Point3::new([0.0, 0.0, 1.0]));
        }
        assert_eq!(mesh.triangles[0], [0, 4, 5]);
        assert_eq!(mesh.triangles[1], [0, 5, 1]);
    }

    #[test]
    fn flipping_reverses_winding_and_normals() {
        let grid = Grid::from_fn(3, 4, |a, b| Point3::new([a as f64, b as f64, 0.0]));
        let mut mesh = TriangleMesh::from_grid(&grid).unwrap();
        mesh.flip_orientation();
        mesh.validate().unwrap();
        let down = Point3::new([0.0, 0.0, -1.0]);
        assert!(mesh.normals.iter().all(|n| *n == down));
        assert!(mesh.triangles.iter().all(|t| mesh.face_normal(*t) == down));
        // Row 0 runs backwards now; the grid shape is kept.
        assert_eq!(mesh.positions[0], Point3::new([0.0, 3.0, 0.0]));
        assert_eq!(mesh.grid, Some((3, 4)));
        // A general mesh: corners swapped.
        let mut general = TriangleMesh {
            grid: None,
            ..TriangleMesh::from_grid(&grid).unwrap()
        };
        general.flip_orientation();
        assert_eq!(general.triangles[0], [0, 5, 4]);
        assert!(general
            .triangles
            .iter()
            .all(|t| general.face_normal(*t) == down));
    }

    #[test]
    fn vertex_normals_without_given_normals_average_faces() {
        let mut mesh = TriangleMesh::from_grid(&plane(2, 2)).unwrap();
        mesh.normals.clear();
        for n in mesh.vertex_normals() {
            assert_eq!(n, Point3::new([0.0, 0.0, 1.0]));
        }
        mesh.triangles.push([0, 1, 9]);
        assert!(mesh
            .validate()
            .unwrap_err()
            .to_string()
            .contains("out of range"));
    }
}

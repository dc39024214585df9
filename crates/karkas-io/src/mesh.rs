//! A triangle mesh in memory: the common form every mesh writer takes, built from a sampled
//! surface grid or read from a mesh file.
//!
//! A sampled surface (`nu x nv` points, row-major, `u` outer) becomes the mesh of its grid: one
//! vertex per sample, one normal per vertex (as in [`crate::obj`]: the normalised cross product of
//! the grid differences along `u` and `v`, wrapped across a seam where the last row or column
//! repeats the first), and two triangles per grid cell, `(a,b) (a+1,b) (a+1,b+1)` and
//! `(a,b) (a+1,b+1) (a,b+1)`, counter-clockwise seen from the side the normals point to. The
//! grid shape is kept, so writers of structured formats (VTK structured grids) can use it.
//!
//! Memory: `nu nv` positions and normals and `2 (nu-1)(nv-1)` index triples, O(nu nv).

use karkas::{Grid, Point3};

use crate::obj::grid_normals;

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

/// Why a grid cannot become a mesh: more vertices than 32-bit indices can address.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct TooLarge {
    /// The number of vertices asked for.
    pub vertices: usize,
}

impl std::fmt::Display for TooLarge {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(
            f,
            "{} vertices are more than 32-bit mesh indices can address",
            self.vertices
        )
    }
}

impl TriangleMesh {
    /// The mesh of a sampled surface grid (see the module docs); an error when the grid has
    /// `2^32` or more samples.
    pub fn from_grid(grid: &Grid<Point3>) -> Result<TriangleMesh, TooLarge> {
        let (nu, nv) = (grid.rows(), grid.cols());
        let points = grid.as_slice();
        if u32::try_from(points.len()).is_err() {
            return Err(TooLarge {
                vertices: points.len(),
            });
        }
        let normals = grid_normals(nu, nv, points);
        let index = |a: usize, b: usize| (a * nv + b) as u32;
        let mut triangles = Vec::with_capacity(2 * nu.saturating_sub(1) * nv.saturating_sub(1));
        for a in 0..nu.saturating_sub(1) {
            for b in 0..nv.saturating_sub(1) {
                let (p, q, r, s) = (
                    index(a, b),
                    index(a + 1, b),
                    index(a + 1, b + 1),
                    index(a, b + 1),
                );
                triangles.push([p, q, r]);
                triangles.push([p, r, s]);
            }
        }
        Ok(TriangleMesh {
            positions: points.to_vec(),
            normals,
            triangles,
            grid: Some((nu, nv)),
        })
    }

    /// The unit normal of triangle `t` (`(b - a) x (c - a)` normalised; zero when degenerate
    /// or an index is out of range).
    pub fn face_normal(&self, t: [u32; 3]) -> Point3 {
        let at = |k: u32| self.positions.get(k as usize).copied();
        let (Some(a), Some(b), Some(c)) = (at(t[0]), at(t[1]), at(t[2])) else {
            return Point3::ZERO;
        };
        let n = cross(b - a, c - a);
        let len = n.norm();
        if len > 0.0 && len.is_finite() {
            n * (1.0 / len)
        } else {
            Point3::ZERO
        }
    }

    /// Per-vertex normals: the given ones, or (when the mesh has none) the area-weighted mean
    /// of the normals of the triangles around each vertex (`0 0 1` for a vertex on no
    /// triangle of positive area).
    pub fn vertex_normals(&self) -> Vec<Point3> {
        if self.normals.len() == self.positions.len() {
            return self.normals.clone();
        }
        let mut sums = vec![Point3::ZERO; self.positions.len()];
        for t in &self.triangles {
            let at = |k: u32| self.positions.get(k as usize).copied();
            if let (Some(a), Some(b), Some(c)) = (at(t[0]), at(t[1]), at(t[2])) {
                let n = cross(b - a, c - a); // length = twice the area
                for &k in t {
                    sums[k as usize] += n;
                }
            }
        }
        sums.into_iter()
            .map(|n| {
                let len = n.norm();
                if len > 0.0 && len.is_finite() {
                    n * (1.0 / len)
                } else {
                    Point3::new([0.0, 0.0, 1.0])
                }
            })
            .collect()
    }

    /// The checks every writer relies on: every index in range, normals absent or one per
    /// vertex. The error says what is wrong.
    pub fn validate(&self) -> Result<(), String> {
        if !self.normals.is_empty() && self.normals.len() != self.positions.len() {
            return Err(format!(
                "{} normals for {} vertices",
                self.normals.len(),
                self.positions.len()
            ));
        }
        if u32::try_from(self.positions.len()).is_err() {
            return Err(TooLarge {
                vertices: self.positions.len(),
            }
            .to_string());
        }
        let n = self.positions.len();
        if let Some((k, t)) = self
            .triangles
            .iter()
            .enumerate()
            .find(|(_, t)| t.iter().any(|&i| i as usize >= n))
        {
            return Err(format!(
                "triangle {k} has vertex index {:?} out of range (0..{n})",
                t
            ));
        }
        if let Some((rows, cols)) = self.grid {
            if rows.checked_mul(cols) != Some(n) {
                return Err(format!("{n} vertices do not form a {rows} x {cols} grid"));
            }
        }
        Ok(())
    }
}

/// The cross product `p x q`.
pub(crate) fn cross(p: Point3, q: Point3) -> Point3 {
    Point3::new([
        p[1] * q[2] - p[2] * q[1],
        p[2] * q[0] - p[0] * q[2],
        p[0] * q[1] - p[1] * q[0],
    ])
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
    fn vertex_normals_without_given_normals_average_faces() {
        let mut mesh = TriangleMesh::from_grid(&plane(2, 2)).unwrap();
        mesh.normals.clear();
        for n in mesh.vertex_normals() {
            assert_eq!(n, Point3::new([0.0, 0.0, 1.0]));
        }
        mesh.triangles.push([0, 1, 9]);
        assert!(mesh.validate().unwrap_err().contains("out of range"));
    }
}

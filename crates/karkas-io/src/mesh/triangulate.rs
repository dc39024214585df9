//! The triangles of a sample grid, in the one order and orientation every mesh writer uses.
//!
//! A sampled surface (`nu x nv` points, row-major, `u` outer) is the mesh of its grid: two
//! triangles per grid cell `(a, b)`, `(a,b) (a+1,b) (a+1,b+1)` and `(a,b) (a+1,b+1) (a,b+1)`,
//! cells in row-major order, counter-clockwise seen from the side of `d/du x d/dv`. A closed
//! surface is passed with its first row and column repeated at the end, so the cells cover
//! the seam.
//!
//! Seams ([`GridSeams`]): when the last sample row (column) coincides with the first, within
//! `1e-12` of the model's size, the direction is closed (a closed surface sampled over its
//! whole period, as `surface ll --closed-u`, `surface bicubic --closed-v`, `surface dps-tube`
//! and Coons surfaces of closed curves give). Writers of formats with shared vertices (OBJ,
//! PLY, glTF) weld the seam: the repeated row (column) is not written and the triangles
//! along the seam use the first row's (column's) vertices, so mesh tools see one closed
//! surface. The geometry says it, not a flag: by the time samples reach a writer the surface
//! is gone, and samples whose ends coincide are one surface whichever command made them.
//!
//! The triangles are produced on demand (O(1) memory); there are `2 (nu-1)(nv-1)` of them.

use karkas::Point3;

use crate::mesh::error::MeshError;

/// The triangles of the `nu x nv` sample grid as triples of 0-based row-major sample indices,
/// produced on demand (see the module docs).
pub(crate) fn grid_triangles(nu: usize, nv: usize) -> impl ExactSizeIterator<Item = [usize; 3]> {
    let cols = nv.saturating_sub(1);
    let cells = nu.saturating_sub(1) * cols;
    (0..2 * cells).map(move |k| {
        let (cell, half) = (k / 2, k % 2);
        let (a, b) = (cell / cols, cell % cols);
        let index = |a: usize, b: usize| a * nv + b;
        if half == 0 {
            [index(a, b), index(a + 1, b), index(a + 1, b + 1)]
        } else {
            [index(a, b), index(a + 1, b + 1), index(a, b + 1)]
        }
    })
}

/// The closed directions of a `nu x nv` sample grid, and the vertex numbering with their
/// seams welded (see the module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct GridSeams {
    /// The sample rows.
    pub nu: usize,
    /// The sample columns.
    pub nv: usize,
    /// The last row coincides with the first (and `nu >= 3`).
    pub closed_u: bool,
    /// The last column coincides with the first (and `nv >= 3`).
    pub closed_v: bool,
}

impl GridSeams {
    /// The seams of the `nu x nv` grid `points` (`points.len() == nu * nv`): a direction is
    /// closed when its last line of samples is its first within `1e-12` times the largest
    /// coordinate. O(nu + nv) after one pass for the scale.
    pub(crate) fn detect(nu: usize, nv: usize, points: &[Point3]) -> GridSeams {
        if nu.checked_mul(nv) != Some(points.len()) {
            return GridSeams::open(nu, nv);
        }
        let scale = points.iter().fold(0.0_f64, |s, p| s.max(p.max_abs()));
        let tolerance = 1e-12 * scale;
        let at = |a: usize, b: usize| points[a * nv + b];
        let closed_u = nu >= 3 && (0..nv).all(|b| at(0, b).distance(at(nu - 1, b)) <= tolerance);
        let closed_v = nv >= 3 && (0..nu).all(|a| at(a, 0).distance(at(a, nv - 1)) <= tolerance);
        GridSeams {
            nu,
            nv,
            closed_u,
            closed_v,
        }
    }

    /// A grid without seams (every sample its own vertex).
    pub(crate) fn open(nu: usize, nv: usize) -> GridSeams {
        GridSeams {
            nu,
            nv,
            closed_u: false,
            closed_v: false,
        }
    }

    /// True when some seam is welded.
    pub fn welds(&self) -> bool {
        self.closed_u || self.closed_v
    }

    /// The rows and columns of vertices kept: the repeated last row (column) of a closed
    /// direction is dropped.
    pub fn kept(&self) -> (usize, usize) {
        (
            self.nu - usize::from(self.closed_u),
            self.nv - usize::from(self.closed_v),
        )
    }

    /// The number of vertices with the seams welded.
    pub fn vertex_count(&self) -> usize {
        let (ku, kv) = self.kept();
        ku * kv
    }

    /// True when the sample of row-major index `k` is a vertex of its own (not a repeat).
    pub fn is_kept(&self, k: usize) -> bool {
        let (ku, kv) = self.kept();
        k / self.nv < ku && k % self.nv < kv
    }

    /// The welded vertex of the sample of row-major index `k`.
    pub fn vertex(&self, k: usize) -> usize {
        let (ku, kv) = self.kept();
        let (a, b) = (k / self.nv, k % self.nv);
        (a % ku) * kv + b % kv
    }

    /// The triangles of the grid (as [`grid_triangles`]) over the welded vertices.
    pub fn triangles(self) -> impl ExactSizeIterator<Item = [usize; 3]> {
        grid_triangles(self.nu, self.nv).map(move |t| t.map(|k| self.vertex(k)))
    }
}

/// [`MeshError::PointCount`] unless `points == nu * nv`.
pub(crate) fn check_grid(nu: usize, nv: usize, points: usize) -> Result<(), MeshError> {
    if nu.checked_mul(nv) == Some(points) {
        Ok(())
    } else {
        Err(MeshError::PointCount {
            points,
            rows: nu,
            cols: nv,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn counts_order_and_degenerate_grids() {
        let t: Vec<[usize; 3]> = grid_triangles(3, 4).collect();
        assert_eq!(t.len(), 2 * 2 * 3);
        assert_eq!(t[0], [0, 4, 5]);
        assert_eq!(t[1], [0, 5, 1]);
        assert_eq!(t[11], [6, 11, 7]);
        assert_eq!(grid_triangles(1, 12).len(), 0);
        assert_eq!(grid_triangles(5, 1).len(), 0);
        assert_eq!(grid_triangles(0, 0).len(), 0);
    }

    #[test]
    fn seams_are_detected_and_welded() {
        // A ring around z: 3 rows along z, 5 columns around, the last column the first.
        let (nu, nv) = (3, 5);
        let points: Vec<Point3> = (0..nu * nv)
            .map(|k| {
                let (a, b) = (k / nv, k % nv);
                let phi = std::f64::consts::FRAC_PI_2 * (b % 4) as f64;
                Point3::new([phi.cos(), phi.sin(), a as f64])
            })
            .collect();
        let seams = GridSeams::detect(nu, nv, &points);
        assert!(!seams.closed_u && seams.closed_v);
        assert_eq!(seams.kept(), (3, 4));
        assert_eq!(seams.vertex_count(), 12);
        assert_eq!(seams.vertex(4), 0);
        assert_eq!(seams.vertex(5), 4);
        assert!(!seams.is_kept(4) && seams.is_kept(5));
        let t: Vec<[usize; 3]> = seams.triangles().collect();
        assert_eq!(t.len(), 2 * 2 * 4);
        // The last cell of the first row closes over the seam: (0,3) (1,3) (1,0).
        assert_eq!(t[6], [3, 7, 4]);
        assert!(t.iter().flatten().all(|&k| k < 12));
        // Every edge of the welded ring is used by one or two triangles, never more.
        let mut edges = std::collections::HashMap::new();
        for tri in &t {
            for e in 0..3 {
                let (p, q) = (tri[e], tri[(e + 1) % 3]);
                *edges.entry((p.min(q), p.max(q))).or_insert(0) += 1;
            }
        }
        assert!(edges.values().all(|&n| n <= 2));
        assert_eq!(edges.values().filter(|&&n| n == 1).count(), 8);
        // A plane has no seam; a grid of two rows cannot close.
        let plane: Vec<Point3> = (0..6).map(|k| Point3::new([k as f64, 0.0, 0.0])).collect();
        assert!(!GridSeams::detect(2, 3, &plane).welds());
        let pair = vec![Point3::ZERO; 6];
        assert_eq!(GridSeams::detect(2, 3, &pair).kept(), (2, 2));
    }
}

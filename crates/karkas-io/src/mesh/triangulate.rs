//! The triangles of a sample grid, in the one order and orientation every mesh writer uses.
//!
//! A sampled surface (`nu x nv` points, row-major, `u` outer) is the mesh of its grid: two
//! triangles per grid cell `(a, b)`, `(a,b) (a+1,b) (a+1,b+1)` and `(a,b) (a+1,b+1) (a,b+1)`,
//! cells in row-major order, counter-clockwise seen from the side of `d/du x d/dv`. A closed
//! surface is passed with its first row and column repeated at the end, so the cells cover
//! the seam (the seam points are not welded).
//!
//! The triangles are produced on demand (O(1) memory); there are `2 (nu-1)(nv-1)` of them.

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
}

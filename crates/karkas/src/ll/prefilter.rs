//! The interpolating variant of LL approximation (Aulchenko et al., system (6); docs/methods.md §1.2).
//!
//! The LL curve through control points `r` passes at node `i` through
//! `d_L r_{i-1} + (1 - 2 d_L) r_i + d_L r_{i+1}`. To make it pass through given points
//! `p_i`, solve that tridiagonal system for `r*`: first and last rows are the identity for an
//! open polygon (the end extrapolation makes `D_1 = D_K = 0`), and the system is cyclic for a
//! closed one. It is strictly diagonally dominant (`d_L <= 1/8`), so the Thomas algorithm (and
//! Sherman–Morrison for the cyclic case) is stable: `O(K)` time, one scratch vector.
//!
//! The interpolating curve keeps the smoothness `C^L` but no longer the monotonicity and
//! no-oscillation guarantees of the approximating scheme.

use super::frame::extend;
use crate::solve::{solve_cyclic_tridiagonal, solve_tridiagonal};
use crate::{Grid, Point, Result};

/// Replaces the `K` node values `p` by the control values `r*` whose LL curve interpolates
/// them. For `closed`, `values[K-1]` must equal `values[0]` (the repeated node); it is set
/// to the solved `r*_1` again.
pub fn interpolation_controls<const D: usize>(
    values: &mut [Point<D>],
    d_l: f64,
    closed: bool,
) -> Result<()> {
    let k = values.len();
    let off = d_l;
    let diag = 1.0 - 2.0 * d_l;
    if closed {
        let n = k - 1;
        solve_cyclic_tridiagonal(|_| (off, diag, off), &mut values[..n])?;
        values[n] = values[0];
        Ok(())
    } else {
        solve_tridiagonal(
            |i| {
                if i == 0 || i + 1 == k {
                    (0.0, 1.0, 0.0)
                } else {
                    (off, diag, off)
                }
            },
            values,
        )
    }
}

/// The node values of the LL curve over control values `values` (formula (5)):
/// `d_L r_{i-1} + (1 - 2 d_L) r_i + d_L r_{i+1}`, the operator that
/// [`interpolation_controls`] inverts. An open polygon's ends are its end points exactly (the
/// end extrapolation makes `D_1 = D_K = 0`); a closed polygon (`values[K-1] == values[0]`)
/// wraps, and its repeated node gets the same value as the first.
pub(crate) fn node_values<const D: usize>(
    values: &[Point<D>],
    d_l: f64,
    closed: bool,
) -> Vec<Point<D>> {
    let k = values.len();
    let extended = extend(values, closed);
    let mut out: Vec<Point<D>> = extended
        .windows(3)
        .map(|w| w[0] * d_l + w[1] * (1.0 - 2.0 * d_l) + w[2] * d_l)
        .collect();
    if !closed {
        out[0] = values[0];
        out[k - 1] = values[k - 1];
    }
    out
}

/// Applies a 1-D operation on node sequences to every row of `grid` (closed as `closed_v`),
/// then to every column (closed as `closed_u`): the separable form of the surface's node
/// operator and of its inverse.
pub(crate) fn along_rows_then_columns<const D: usize>(
    grid: &mut Grid<Point<D>>,
    (closed_u, closed_v): (bool, bool),
    mut apply: impl FnMut(&mut [Point<D>], bool) -> Result<()>,
) -> Result<()> {
    let (kx, ky) = (grid.rows(), grid.cols());
    for i in 0..kx {
        apply(&mut grid.as_mut_slice()[i * ky..(i + 1) * ky], closed_v)?;
    }
    let mut column = vec![Point::ZERO; kx];
    for j in 0..ky {
        for (i, c) in column.iter_mut().enumerate() {
            *c = *grid.get(i, j);
        }
        apply(&mut column, closed_u)?;
        for (i, c) in column.iter().enumerate() {
            *grid.get_mut(i, j) = *c;
        }
    }
    Ok(())
}

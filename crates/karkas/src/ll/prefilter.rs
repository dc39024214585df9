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

use crate::solve::{solve_cyclic_tridiagonal, solve_tridiagonal};
use crate::{Point, Result};

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

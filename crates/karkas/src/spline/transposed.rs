//! The transposed solve of a [`SlopeSystem`]: the weights of the values in a combination of
//! the slopes, which is how the cardinal functions of a spline are evaluated.
//!
//! The slopes are a linear map of the values, `m = S y` (clamped end slopes taken as zero).
//! A spline's `k`-th derivative at `t` is `a(t) . y + c(t) . m` with `a`, `c` the Hermite
//! weights of the piece holding `t` (two nonzero entries each), so the weights of all
//! cardinal functions at `t` are `a(t) + S^T c(t)`: one transposed solve with the same
//! factorization, `O(n)`, never the dense `n x n` table of all cardinal functions.

use super::system::{Shape, SlopeSystem};

impl SlopeSystem {
    /// Solves `A^T x = c` in place, `A = L U` the Thomas factorization of the solved matrix
    /// (Sherman–Morrison not included): `U^T y = c` forward, then `L^T x = y` backward.
    pub(super) fn sweep_transposed(&self, x: &mut [f64]) {
        let len = self.inv_pivot.len();
        for r in 1..len {
            x[r] -= self.upper_prime[r - 1] * x[r - 1];
        }
        x[len - 1] *= self.inv_pivot[len - 1];
        for r in (0..len.saturating_sub(1)).rev() {
            x[r] = (x[r] - self.lower[r + 1] * x[r + 1]) * self.inv_pivot[r];
        }
    }

    /// Adds `R^T x` to `weights`: the right-hand side of the row of unknown `first + r` is
    /// `R_r . (y_{prev}, y_c, y_{c+1})`.
    fn add_rows_transposed(&self, first: usize, x: &[f64], weights: &mut [f64]) {
        for (r, (w, &xr)) in self.rhs.iter().zip(x).enumerate() {
            let c = first + r;
            let prev = match (c, self.wrap) {
                (0, wrap) => wrap,
                _ => Some(c - 1),
            };
            if let Some(pk) = prev {
                weights[pk] += w[0] * xr;
            }
            weights[c] += w[1] * xr;
            if c + 1 < self.n {
                weights[c + 1] += w[2] * xr;
            }
        }
    }

    /// Adds to `weights` (one per value `y_0..y_{n-1}`) the weights `S^T c` such that
    /// `c . m = (S^T c) . y` for the slopes `m` of any values `y`, clamped end slopes taken as
    /// zero. `c` (one per slope) is used as scratch. For a periodic system the last value is
    /// the first one repeated: its weight is left in `weights[n - 1]` for the caller to add
    /// to `weights[0]`. `O(n)`.
    pub(crate) fn add_transposed(&self, c: &mut [f64], weights: &mut [f64]) {
        let n = self.n;
        debug_assert!(c.len() == n && weights.len() == n);
        let len = self.rhs.len();
        match &self.shape {
            Shape::Segment { h } => {
                // m_0 = m_1 = (y_1 - y_0) / h.
                let g = (c[0] + c[1]) * (1.0 / h);
                weights[0] -= g;
                weights[1] += g;
            }
            Shape::Parabola { h } => {
                // m_0 = 2 delta_0 - m_1, m_2 = 2 delta_1 - m_1.
                let g0 = c[0] * (2.0 / h[0]);
                let g2 = c[2] * (2.0 / h[1]);
                weights[0] -= g0;
                weights[1] += g0 - g2;
                weights[2] += g2;
                let mut x = [c[1] - c[0] - c[2]];
                self.sweep_transposed(&mut x);
                self.add_rows_transposed(1, &x, weights);
            }
            // Every slope zero: no weight of any value.
            Shape::Constant => {}
            Shape::CyclicPair => {
                // m_0 = (2 r_0 - r_1) / 3, m_1 = (2 r_1 - r_0) / 3, m_2 = m_0.
                let c0 = c[0] + c[2];
                let x = [(c0 * 2.0 - c[1]) / 3.0, (c[1] * 2.0 - c0) / 3.0];
                self.add_rows_transposed(0, &x, weights);
            }
            Shape::Cyclic {
                zt,
                denom,
                corner_bottom,
                ..
            } => {
                c[0] += c[n - 1];
                let x = &mut c[..len];
                self.sweep_transposed(x);
                // (B + w v^T)^T = B^T + v w^T, w = (-2, 0, .., corner_bottom).
                let factor = (-2.0 * x[0] + corner_bottom * x[len - 1]) / denom;
                for (xk, &zk) in x.iter_mut().zip(zt) {
                    *xk -= zk * factor;
                }
                self.add_rows_transposed(0, &c[..len], weights);
            }
            Shape::Tridiagonal { first, ends } => {
                if let Some([(a0, b0, start), (a1, b1, end)]) = ends {
                    // The not-a-knot end slopes (3.11), (3.12) from the solved ones.
                    let (c0, cl) = (c[0], c[n - 1]);
                    c[1] += a0 * c0;
                    c[2] += b0 * c0;
                    c[n - 2] += a1 * cl;
                    c[n - 3] += b1 * cl;
                    for &(k, w) in start {
                        weights[k] += w * c0;
                    }
                    for &(k, w) in end {
                        weights[k] += w * cl;
                    }
                }
                let x = &mut c[*first..*first + len];
                self.sweep_transposed(x);
                self.add_rows_transposed(*first, &c[*first..*first + len], weights);
            }
        }
    }
}

//! Symmetric positive definite banded systems with a dense border: the cyclic band of a
//! periodic spline fit.
//!
//! `K = [A B; B^T C]` with `A` banded (`n x n`, [`BandedSpd`]), `B` dense `n x m` and `C`
//! dense `m x m`, `m` small. Periodic splines couple their last unknowns with their first
//! ones: ordering the unknowns of the seam last makes the matrix banded except for those
//! `m` rows and columns (the seam's unknowns must number at least the width of a coupling
//! window less one, so that no window couples two inner unknowns across the seam). Solved by the Schur complement (block elimination):
//! `A Y = B`, `S = C - B^T Y`, then `x_2 = S^{-1} (b_2 - B^T A^{-1} b_1)` and
//! `x_1 = A^{-1} b_1 - Y x_2`; `O(n w^2 + n w m + m^3)`. `S` is positive definite when `K`
//! is, so both factorizations are Cholesky's.
//!
//! Written next to [`BandedSpd`] for the same reason (no maintained crate factors a banded
//! matrix); the border is the low-rank correction of a cyclic band, as the Sherman–Morrison
//! correction of [`solve_cyclic_tridiagonal`](super::solve_cyclic_tridiagonal) is of a
//! cyclic tridiagonal one.

use super::BandedSpd;
use crate::{Error, Result};

/// A symmetric banded matrix with `m` dense last rows and columns.
#[derive(Clone, Debug)]
pub struct BorderedSpd {
    band: BandedSpd,
    border: usize,
    /// `B`, row-major (`n x m`); after [`factor`](Self::factor), `Y = A^{-1} B`.
    side: Vec<f64>,
    /// `B` kept for the solve (`B^T y`).
    coupling: Vec<f64>,
    /// `C`, row-major; after factoring, the Cholesky factor of `S` (lower triangle).
    corner: Vec<f64>,
    column: Vec<f64>,
}

impl BorderedSpd {
    /// A zero matrix of order `inner + border` whose first `inner` unknowns form a band of
    /// `width` stored diagonals.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::solve::BorderedSpd;
    ///
    /// // [[4, 1, 1], [1, 4, 1], [1, 1, 4]] x = [6, 6, 6] has x = [1, 1, 1]: a band of two
    /// // unknowns and a border of one, as the seam of a cyclic system.
    /// let mut matrix = BorderedSpd::new(2, 2, 1);
    /// for (i, j, value) in [(0, 0, 4.0), (1, 0, 1.0), (1, 1, 4.0), (2, 0, 1.0), (2, 1, 1.0), (2, 2, 4.0)] {
    ///     matrix.add(i, j, value);
    /// }
    /// matrix.factor()?;
    /// let mut x = [6.0, 6.0, 6.0];
    /// matrix.solve_factored(&mut x);
    /// assert!(x.iter().all(|v| (v - 1.0).abs() < 1e-12), "{x:?}");
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(inner: usize, width: usize, border: usize) -> Self {
        BorderedSpd {
            band: BandedSpd::new(inner, width),
            border,
            side: vec![0.0; inner * border],
            coupling: vec![0.0; inner * border],
            corner: vec![0.0; border * border],
            column: vec![0.0; inner],
        }
    }

    /// The order of the matrix.
    pub fn size(&self) -> usize {
        self.band.size() + self.border
    }

    /// Sets every entry to zero.
    pub fn clear(&mut self) {
        self.band.clear();
        self.side.fill(0.0);
        self.coupling.fill(0.0);
        self.corner.fill(0.0);
    }

    /// Adds `value` to `K[i][j]` (and, by symmetry, `K[j][i]`); add each off-diagonal pair
    /// once.
    ///
    /// # Panics
    /// When an entry of the inner block lies outside the band or an index is out of range.
    pub fn add(&mut self, i: usize, j: usize, value: f64) {
        let n = self.band.size();
        let m = self.border;
        let (lo, hi) = if i <= j { (i, j) } else { (j, i) };
        assert!(hi < n + m, "entry outside the matrix");
        if hi < n {
            self.band.add(i, j, value);
        } else if lo < n {
            self.coupling[lo * m + hi - n] += value;
        } else {
            let (a, b) = (lo - n, hi - n);
            self.corner[a * m + b] += value;
            if a != b {
                self.corner[b * m + a] += value;
            }
        }
    }

    /// Factors in place. Fails with [`Error::SingularSystem`] at the first pivot that is not
    /// positive (clear and refill the matrix then).
    pub fn factor(&mut self) -> Result<()> {
        let (n, m) = (self.band.size(), self.border);
        self.band.factor()?;
        for c in 0..m {
            for r in 0..n {
                self.column[r] = self.coupling[r * m + c];
            }
            self.band.solve_factored(&mut self.column);
            for r in 0..n {
                self.side[r * m + c] = self.column[r];
            }
        }
        // S = C - B^T Y, then its Cholesky factor in the lower triangle.
        for a in 0..m {
            for b in 0..=a {
                let dot: f64 = (0..n)
                    .map(|r| self.coupling[r * m + a] * self.side[r * m + b])
                    .sum();
                self.corner[a * m + b] -= dot;
            }
        }
        for a in 0..m {
            for b in 0..=a {
                let mut acc = self.corner[a * m + b];
                for k in 0..b {
                    acc -= self.corner[a * m + k] * self.corner[b * m + k];
                }
                if a == b {
                    if !(acc.is_finite() && acc > 0.0) {
                        return Err(Error::SingularSystem {
                            row: n + a,
                            pivot: acc,
                        });
                    }
                    self.corner[a * m + a] = acc.sqrt();
                } else {
                    self.corner[a * m + b] = acc / self.corner[b * m + b];
                }
            }
        }
        Ok(())
    }

    /// Solves `K x = b` in place with the factor from [`factor`](Self::factor).
    ///
    /// # Panics
    /// When `b.len()` is not the order of the matrix.
    #[allow(clippy::needless_range_loop)] // index arithmetic on the factor reads clearer
    pub fn solve_factored(&self, b: &mut [f64]) {
        let (n, m) = (self.band.size(), self.border);
        assert_eq!(b.len(), n + m, "right-hand side of the wrong length");
        let (inner, outer) = b.split_at_mut(n);
        self.band.solve_factored(inner);
        for (a, x) in outer.iter_mut().enumerate() {
            *x -= (0..n)
                .map(|r| self.coupling[r * m + a] * inner[r])
                .sum::<f64>();
        }
        for a in 0..m {
            let mut acc = outer[a];
            for k in 0..a {
                acc -= self.corner[a * m + k] * outer[k];
            }
            outer[a] = acc / self.corner[a * m + a];
        }
        for a in (0..m).rev() {
            let mut acc = outer[a];
            for k in a + 1..m {
                acc -= self.corner[k * m + a] * outer[k];
            }
            outer[a] = acc / self.corner[a * m + a];
        }
        for (r, x) in inner.iter_mut().enumerate() {
            *x -= (0..m).map(|a| self.side[r * m + a] * outer[a]).sum::<f64>();
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn solves_a_cyclic_band_as_a_dense_solve_does() {
        // K = sum of rank-one terms on cyclic windows of 4 unknowns, plus the identity:
        // SPD, banded except where the windows wrap around.
        let n = 11;
        let mut k = vec![vec![0.0; n]; n];
        let mut bordered = BorderedSpd::new(n - 3, 4, 3);
        let mut state = 7u64;
        let mut rand = || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
            ((state >> 11) as f64) / (1u64 << 53) as f64 - 0.5
        };
        // Unknown u of the cycle sits at (u + n - 3) % n: the seam's three (a window less
        // one) last, so that no window couples two inner unknowns across the seam.
        let at = |u: usize| (u + n - 3) % n;
        for start in 0..n {
            let row: Vec<f64> = (0..4).map(|_| rand()).collect();
            for a in 0..4 {
                for b in 0..4 {
                    let (i, j) = (at((start + a) % n), at((start + b) % n));
                    k[i][j] += row[a] * row[b];
                    if a >= b {
                        bordered.add(i, j, row[a] * row[b]);
                    }
                }
            }
        }
        for i in 0..n {
            k[i][i] += 1.0;
            bordered.add(i, i, 1.0);
        }
        let b: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut x = b.clone();
        bordered.factor().unwrap();
        bordered.solve_factored(&mut x);
        for i in 0..n {
            let r: f64 = (0..n).map(|j| k[i][j] * x[j]).sum::<f64>() - b[i];
            assert!(r.abs() < 1e-12, "row {i}: residual {r}");
        }
    }
}

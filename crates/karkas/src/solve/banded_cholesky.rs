//! Symmetric positive definite banded systems by Cholesky factorization.
//!
//! `K x = b` for a symmetric `n x n` matrix with `K[i][j] = 0` when `|i - j| >= w`, stored as
//! its lower band (`w` numbers per row). Factorization `K = L L^T` in place, `O(n w^2)`;
//! the solve `O(n w)`; nothing is allocated after [`BandedSpd::new`]. A pivot that is not
//! positive means the matrix is not positive definite: [`Error::SingularSystem`], which the
//! Newton steps of the fit answer by damping more.
//!
//! Hand-written for the same reason as the banded least-squares solver: no maintained Rust
//! crate factors a banded matrix (faer and nalgebra factor dense or general sparse ones).

use crate::{Error, Result};

/// A symmetric banded matrix (lower band stored), to be assembled, factored and solved.
#[derive(Clone, Debug)]
pub struct BandedSpd {
    size: usize,
    width: usize,
    /// Row `i`: `band[i * width + d]` is `K[i][i - d]`, `d < width`.
    band: Vec<f64>,
}

impl BandedSpd {
    /// A zero `size x size` matrix with `width` stored diagonals (the main one included).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::solve::BandedSpd;
    ///
    /// // [[4, 2], [2, 5]] x = [8, 12] has x = [1, 2].
    /// let mut matrix = BandedSpd::new(2, 2);
    /// matrix.add(0, 0, 4.0);
    /// matrix.add(1, 0, 2.0);
    /// matrix.add(1, 1, 5.0);
    /// matrix.factor()?;
    /// let mut x = [8.0, 12.0];
    /// matrix.solve_factored(&mut x);
    /// assert!((x[0] - 1.0).abs() < 1e-12 && (x[1] - 2.0).abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(size: usize, width: usize) -> Self {
        let width = width.max(1);
        BandedSpd {
            size,
            width,
            band: vec![0.0; size * width],
        }
    }

    /// The order of the matrix.
    pub fn size(&self) -> usize {
        self.size
    }

    /// Sets every entry to zero.
    pub fn clear(&mut self) {
        self.band.fill(0.0);
    }

    /// Adds `value` to `K[i][j]` (and, by symmetry, `K[j][i]`); add each off-diagonal pair
    /// once.
    ///
    /// # Panics
    /// When `|i - j|` is not inside the band or an index is out of range.
    #[inline]
    pub fn add(&mut self, i: usize, j: usize, value: f64) {
        let (hi, lo) = if i >= j { (i, j) } else { (j, i) };
        assert!(
            hi - lo < self.width && hi < self.size,
            "entry outside the band"
        );
        self.band[hi * self.width + (hi - lo)] += value;
    }

    /// `K[i][i]`.
    pub fn diagonal(&self, i: usize) -> f64 {
        self.band[i * self.width]
    }

    /// Factors in place into `L L^T`. Fails with [`Error::SingularSystem`] at the first pivot
    /// that is not positive (the matrix is then left partly factored: clear and refill it).
    pub fn factor(&mut self) -> Result<()> {
        let w = self.width;
        for i in 0..self.size {
            let first = i.saturating_sub(w - 1);
            for j in first..=i {
                // K[i][j] - sum_k L[i][k] L[j][k], k from max(first_i, first_j) to j - 1.
                let mut acc = self.band[i * w + (i - j)];
                let k0 = first.max(j.saturating_sub(w - 1));
                for k in k0..j {
                    acc -= self.band[i * w + (i - k)] * self.band[j * w + (j - k)];
                }
                if j == i {
                    if !(acc.is_finite() && acc > 0.0) {
                        return Err(Error::SingularSystem { row: i, pivot: acc });
                    }
                    self.band[i * w] = acc.sqrt();
                } else {
                    self.band[i * w + (i - j)] = acc / self.band[j * w];
                }
            }
        }
        Ok(())
    }

    /// Solves `K x = b` in place (`b` becomes `x`) with the factor from
    /// [`factor`](Self::factor).
    ///
    /// # Panics
    /// When `b.len() != size`.
    #[allow(clippy::needless_range_loop)] // index arithmetic on the band reads clearer
    pub fn solve_factored(&self, b: &mut [f64]) {
        assert_eq!(b.len(), self.size, "right-hand side of the wrong length");
        let w = self.width;
        for i in 0..self.size {
            let first = i.saturating_sub(w - 1);
            let mut acc = b[i];
            for k in first..i {
                acc -= self.band[i * w + (i - k)] * b[k];
            }
            b[i] = acc / self.band[i * w];
        }
        for i in (0..self.size).rev() {
            let last = (i + w).min(self.size);
            let mut acc = b[i];
            for k in i + 1..last {
                acc -= self.band[k * w + (k - i)] * b[k];
            }
            b[i] = acc / self.band[i * w];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    #[allow(clippy::needless_range_loop)]
    fn solves_a_banded_spd_system() {
        // K = B^T B + I for a random banded B: SPD with half-bandwidth 2.
        let n = 12;
        let mut k = vec![vec![0.0; n]; n];
        let mut state = 3u64;
        let mut rand = || {
            state = state.wrapping_mul(6364136223846793005).wrapping_add(1);
            ((state >> 11) as f64) / (1u64 << 53) as f64 - 0.5
        };
        for r in 0..n - 2 {
            let row = [rand(), rand(), rand()];
            for a in 0..3 {
                for b in 0..3 {
                    k[r + a][r + b] += row[a] * row[b];
                }
            }
        }
        let mut m = BandedSpd::new(n, 3);
        for i in 0..n {
            k[i][i] += 1.0;
            for j in i.saturating_sub(2)..=i {
                m.add(i, j, k[i][j]);
            }
        }
        let x: Vec<f64> = (0..n).map(|i| (i as f64 * 0.7).sin()).collect();
        let mut b: Vec<f64> = (0..n)
            .map(|i| (0..n).map(|j| k[i][j] * x[j]).sum())
            .collect();
        m.factor().unwrap();
        m.solve_factored(&mut b);
        for i in 0..n {
            assert!((b[i] - x[i]).abs() < 1e-12);
        }
    }

    #[test]
    fn indefinite_matrices_are_refused() {
        let mut m = BandedSpd::new(2, 2);
        m.add(0, 0, 1.0);
        m.add(1, 0, 2.0);
        m.add(1, 1, 1.0);
        assert!(matches!(
            m.factor(),
            Err(Error::SingularSystem { row: 1, .. })
        ));
    }
}

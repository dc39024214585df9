//! Banded linear least squares by Givens rotations, rows streamed one at a time.
//!
//! Minimizes `|A x - B|^2` (Frobenius norm, `B` with `m` columns) for an `n`-column matrix `A`
//! whose every row has its nonzeros within `w` consecutive columns. Each row is rotated into
//! an upper-triangular band `R` (`n x w`) as it arrives, the way FITPACK builds its spline
//! fits: `O(w^2)` per row, `O(n w^2)` for the back substitution, `O(n (w + m))` memory, and no
//! matrix of the rows is ever stored. Rows may come in any order; the result does not depend
//! on it (up to rounding).
//!
//! Why rotations and not the normal equations: the fits of karkas weight some rows by the
//! square root of a penalty `p` that grows to `1e12` and beyond; the normal equations square
//! the condition number, the orthogonal triangularization does not (the weighting method for
//! equality-constrained least squares is stable with it). No maintained Rust crate offers a
//! banded QR or a banded least-squares solve (faer and nalgebra factor dense or general
//! sparse matrices; their sparse QR would store the rows and a fill-reducing ordering the band
//! does not need), so the routine is written here; it is short and tested against dense
//! solves.

use crate::{Error, Result};

/// A diagonal of `R` smaller than this times the largest diagonal counts as zero.
const RANK_TOLERANCE: f64 = 1e-13;

/// A streaming banded least-squares problem: add rows, then [`solve`](Self::solve).
///
/// All buffers are allocated once by [`new`](Self::new) and reused after
/// [`clear`](Self::clear); adding rows and solving allocate nothing.
#[derive(Clone, Debug)]
pub struct BandedLeastSquares {
    cols: usize,
    width: usize,
    rhs_cols: usize,
    /// Row `k` of `R`: entries for columns `k..k + width`.
    band: Vec<f64>,
    /// Row `k` of the rotated right-hand side.
    rhs: Vec<f64>,
    /// Which rows of `R` have received a row yet.
    filled: Vec<bool>,
    /// Sum of squares of the parts of the right-hand sides the rotations moved out of `R`'s
    /// span: the residual of the least-squares solution (per right-hand-side column).
    residual_sq: Vec<f64>,
    row: Vec<f64>,
    row_rhs: Vec<f64>,
}

impl BandedLeastSquares {
    /// An empty problem with `cols` unknowns, rows at most `width` columns wide, and
    /// `rhs_cols` right-hand sides.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::solve::BandedLeastSquares;
    ///
    /// // The least-squares constant through 1, 2 and 6 is their mean, 3.
    /// let mut problem = BandedLeastSquares::new(1, 1, 1);
    /// for y in [1.0, 2.0, 6.0] {
    ///     problem.add_row(0, &[1.0], &[y]);
    /// }
    /// let mut x = [0.0];
    /// problem.solve(&mut x)?;
    /// assert!((x[0] - 3.0).abs() < 1e-12);
    /// assert!((problem.residual_sq()[0] - 14.0).abs() < 1e-9); // 4 + 1 + 9
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(cols: usize, width: usize, rhs_cols: usize) -> Self {
        let width = width.max(1);
        BandedLeastSquares {
            cols,
            width,
            rhs_cols,
            band: vec![0.0; cols * width],
            rhs: vec![0.0; cols * rhs_cols],
            filled: vec![false; cols],
            residual_sq: vec![0.0; rhs_cols],
            row: vec![0.0; width],
            row_rhs: vec![0.0; rhs_cols],
        }
    }

    /// The number of unknowns.
    pub fn cols(&self) -> usize {
        self.cols
    }

    /// Forgets every row added, keeping the buffers.
    pub fn clear(&mut self) {
        self.band.fill(0.0);
        self.rhs.fill(0.0);
        self.filled.fill(false);
        self.residual_sq.fill(0.0);
    }

    /// Adds the row `values` (its entry `j` in column `first + j`) with right-hand side `rhs`.
    ///
    /// Any order of rows gives the same solution, but the cost is `O(w^2)` per row only when
    /// rows come in nondecreasing order of `first` (as FITPACK sorts them): a row that starts
    /// before rows already added is rotated through every later row of `R` it meets.
    ///
    /// # Panics
    /// When `values.len() > width`, `rhs.len() != rhs_cols`, or a nonzero value falls past the
    /// last column: these are programming errors of the caller, not user input.
    #[allow(clippy::needless_range_loop)] // the rotation pairs two arrays by index
    pub fn add_row(&mut self, first: usize, values: &[f64], rhs: &[f64]) {
        let w = self.width;
        assert!(values.len() <= w, "row wider than the band");
        assert_eq!(rhs.len(), self.rhs_cols, "wrong number of right-hand sides");
        // The row is kept relative to the current pivot column `col`: `row[l]` is column
        // `col + l`. Rotating against row `col` of R (band `col..col + w`) leaves the row's
        // nonzeros in `col + 1..col + w`, so shifting by one keeps it `w` wide.
        self.row.fill(0.0);
        self.row[..values.len()].copy_from_slice(values);
        self.row_rhs.copy_from_slice(rhs);
        let mut end = values.iter().rposition(|&v| v != 0.0).map_or(0, |e| e + 1);
        assert!(first + end <= self.cols, "row reaches past the last column");
        let mut col = first;
        while end > 0 {
            let value = self.row[0];
            if value != 0.0 {
                let band_row = &mut self.band[col * w..col * w + w];
                let rhs_row = &mut self.rhs[col * self.rhs_cols..(col + 1) * self.rhs_cols];
                if !self.filled[col] {
                    // An empty row of R takes the rest of this row as it is.
                    band_row.copy_from_slice(&self.row);
                    rhs_row.copy_from_slice(&self.row_rhs);
                    self.filled[col] = true;
                    return;
                }
                let pivot = band_row[0];
                let radius = pivot.hypot(value);
                let (c, s) = (pivot / radius, value / radius);
                band_row[0] = radius;
                // The rotated row is written one place to the left: its column `col` is
                // now zero, and the next pivot column is `col + 1`.
                for l in 1..w {
                    let (a, b) = (band_row[l], self.row[l]);
                    band_row[l] = c * a + s * b;
                    self.row[l - 1] = c * b - s * a;
                }
                for (a, b) in rhs_row.iter_mut().zip(self.row_rhs.iter_mut()) {
                    let (x, y) = (*a, *b);
                    *a = c * x + s * y;
                    *b = c * y - s * x;
                }
                end = w.min(self.cols - col);
            } else {
                self.row.copy_within(1.., 0);
            }
            self.row[w - 1] = 0.0;
            end -= 1;
            col += 1;
        }
        for (acc, r) in self.residual_sq.iter_mut().zip(&self.row_rhs) {
            *acc += r * r;
        }
    }

    /// The squared residual `|A x - b|^2` of the least-squares solution, per right-hand side
    /// (known before solving: it is what the rotations moved out of the span of `A`).
    pub fn residual_sq(&self) -> &[f64] {
        &self.residual_sq
    }

    /// Solves by back substitution into `x` (`cols * rhs_cols` values, unknown-major:
    /// `x[k * rhs_cols + c]` is unknown `k` of right-hand side `c`).
    ///
    /// Fails with [`Error::SingularSystem`] when a diagonal of `R` vanishes (relative to the
    /// largest): the rows do not determine every unknown.
    ///
    /// # Panics
    /// When `x.len() != cols * rhs_cols`.
    pub fn solve(&self, x: &mut [f64]) -> Result<()> {
        let (w, m) = (self.width, self.rhs_cols);
        assert_eq!(
            x.len(),
            self.cols * m,
            "solution buffer of the wrong length"
        );
        let largest = (0..self.cols).fold(0.0f64, |a, k| a.max(self.band[k * w].abs()));
        let floor = largest * RANK_TOLERANCE;
        for k in (0..self.cols).rev() {
            let row = &self.band[k * w..k * w + w];
            let pivot = row[0];
            if !(pivot.is_finite() && pivot.abs() > floor) {
                return Err(Error::SingularSystem { row: k, pivot });
            }
            for c in 0..m {
                let mut acc = self.rhs[k * m + c];
                for l in 1..w.min(self.cols - k) {
                    acc -= row[l] * x[(k + l) * m + c];
                }
                x[k * m + c] = acc / pivot;
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dense least squares by the normal equations and Gaussian elimination with pivoting.
    #[allow(clippy::needless_range_loop)]
    fn dense(a: &[Vec<f64>], b: &[f64], n: usize) -> Vec<f64> {
        let mut m = vec![vec![0.0; n + 1]; n];
        for (row, &rhs) in a.iter().zip(b) {
            for i in 0..n {
                for j in 0..n {
                    m[i][j] += row[i] * row[j];
                }
                m[i][n] += row[i] * rhs;
            }
        }
        for c in 0..n {
            let p = (c..n)
                .max_by(|&i, &j| m[i][c].abs().total_cmp(&m[j][c].abs()))
                .unwrap();
            m.swap(c, p);
            for r in 0..n {
                if r != c {
                    let f = m[r][c] / m[c][c];
                    for k in c..=n {
                        m[r][k] -= f * m[c][k];
                    }
                }
            }
        }
        (0..n).map(|i| m[i][n] / m[i][i]).collect()
    }

    #[test]
    fn matches_a_dense_solve_in_any_row_order() {
        let (n, w) = (9, 4);
        let mut state = 7u64;
        let mut rand = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((state >> 11) as f64) / (1u64 << 53) as f64 - 0.5
        };
        let mut rows = Vec::new();
        for first in 0..=n - w {
            for _ in 0..3 {
                let vals: Vec<f64> = (0..w).map(|_| rand()).collect();
                rows.push((first, vals, [rand(), rand()]));
            }
        }
        // Sorted, reversed, and shuffled orders.
        let mut orders: Vec<Vec<usize>> = vec![(0..rows.len()).collect()];
        orders.push((0..rows.len()).rev().collect());
        let mut shuffled: Vec<usize> = (0..rows.len()).collect();
        for i in (1..shuffled.len()).rev() {
            let j = ((rand() + 0.5) * (i + 1) as f64) as usize;
            shuffled.swap(i, j.min(i));
        }
        orders.push(shuffled);
        for order in orders {
            let mut ls = BandedLeastSquares::new(n, w, 2);
            for &r in &order {
                let (first, vals, rhs) = &rows[r];
                ls.add_row(*first, vals, rhs);
            }
            let mut x = vec![0.0; 2 * n];
            ls.solve(&mut x).unwrap();
            for c in 0..2 {
                let a: Vec<Vec<f64>> = rows
                    .iter()
                    .map(|(first, vals, _)| {
                        let mut full = vec![0.0; n];
                        full[*first..*first + w].copy_from_slice(vals);
                        full
                    })
                    .collect();
                let b: Vec<f64> = rows.iter().map(|r| r.2[c]).collect();
                let reference = dense(&a, &b, n);
                for k in 0..n {
                    assert!((x[k * 2 + c] - reference[k]).abs() < 1e-10, "{order:?}");
                }
                let res: f64 = a
                    .iter()
                    .zip(&b)
                    .map(|(row, rhs)| {
                        let ax: f64 = (0..n).map(|k| row[k] * x[k * 2 + c]).sum();
                        (ax - rhs).powi(2)
                    })
                    .sum();
                assert!((res - ls.residual_sq()[c]).abs() < 1e-10 * (1.0 + res));
            }
        }
    }

    #[test]
    fn undetermined_unknowns_are_reported() {
        let mut ls = BandedLeastSquares::new(3, 2, 1);
        ls.add_row(0, &[1.0, 1.0], &[1.0]);
        ls.add_row(0, &[1.0, -1.0], &[0.0]);
        let mut x = vec![0.0; 3];
        assert!(matches!(
            ls.solve(&mut x),
            Err(Error::SingularSystem { row: 2, .. })
        ));
    }
}

//! Thomas algorithm and its cyclic (Sherman–Morrison) variant, `O(n)`.

use crate::{Error, Point, Result};

/// Pivots below this (relative to the row's size) are treated as singular.
const PIVOT_TOLERANCE: f64 = 1e-300;

/// Solves `T x = rhs` in place for a tridiagonal `T` of size `n = rhs.len()`.
///
/// `coef(i)` returns `(lower_i, diag_i, upper_i)`: row `i` reads
/// `lower_i x_{i-1} + diag_i x_i + upper_i x_{i+1} = rhs_i` (`lower_0` and `upper_{n-1}` are
/// ignored). No pivoting: meant for diagonally dominant systems, for which it is stable.
/// Fails with [`Error::SingularSystem`] on a vanishing pivot.
pub fn solve_tridiagonal<const D: usize>(
    coef: impl Fn(usize) -> (f64, f64, f64),
    rhs: &mut [Point<D>],
) -> Result<()> {
    let n = rhs.len();
    if n == 0 {
        return Ok(());
    }
    let mut upper_prime = vec![0.0; n];
    let (_, d0, u0) = coef(0);
    if d0.abs() <= PIVOT_TOLERANCE {
        return Err(Error::SingularSystem { row: 0, pivot: d0 });
    }
    upper_prime[0] = u0 / d0;
    rhs[0] *= 1.0 / d0;
    for i in 1..n {
        let (l, d, u) = coef(i);
        let pivot = d - l * upper_prime[i - 1];
        if pivot.abs() <= PIVOT_TOLERANCE || !pivot.is_finite() {
            return Err(Error::SingularSystem { row: i, pivot });
        }
        let inv = 1.0 / pivot;
        upper_prime[i] = u * inv;
        let prev = rhs[i - 1];
        rhs[i] = rhs[i].add_scaled(-l, prev) * inv;
    }
    for i in (0..n - 1).rev() {
        let next = rhs[i + 1];
        rhs[i] = rhs[i].add_scaled(-upper_prime[i], next);
    }
    Ok(())
}

/// Solves `T x = rhs` in place for a cyclic tridiagonal `T` of size `n = rhs.len() >= 3`.
///
/// `coef(i)` returns `(lower_i, diag_i, upper_i)` with the wrap-around entries
/// `lower_0 = T[0][n-1]` and `upper_{n-1} = T[n-1][0]`. Sherman–Morrison on top of
/// [`solve_tridiagonal`]: two Thomas sweeps, `O(n)`.
///
/// Errors: fewer than 3 unknowns ([`Error::TooFewPoints`]), a vanishing pivot
/// ([`Error::SingularSystem`]).
pub fn solve_cyclic_tridiagonal<const D: usize>(
    coef: impl Fn(usize) -> (f64, f64, f64),
    rhs: &mut [Point<D>],
) -> Result<()> {
    let n = rhs.len();
    if n < 3 {
        return Err(Error::TooFewPoints {
            what: "a cyclic tridiagonal system",
            needed: 3,
            got: n,
        });
    }
    let (corner_top, d0, _) = coef(0); // T[0][n-1]
    let (_, dn, corner_bottom) = coef(n - 1); // T[n-1][0]
    let gamma = if d0 == 0.0 { -1.0 } else { -d0 };
    // T = B + w z^T with w = (gamma, 0, .., corner_bottom), z = (1, 0, .., corner_top / gamma).
    let modified = |i: usize| {
        let (l, d, u) = coef(i);
        if i == 0 {
            (0.0, d - gamma, u)
        } else if i == n - 1 {
            (l, dn - corner_bottom * corner_top / gamma, 0.0)
        } else {
            (l, d, u)
        }
    };
    solve_tridiagonal(modified, rhs)?;
    let mut w = vec![Point([0.0]); n];
    w[0] = Point([gamma]);
    w[n - 1] = Point([corner_bottom]);
    solve_tridiagonal(modified, &mut w)?;
    let ratio = corner_top / gamma;
    let denom = 1.0 + w[0][0] + ratio * w[n - 1][0];
    if denom.abs() <= PIVOT_TOLERANCE {
        return Err(Error::SingularSystem {
            row: n - 1,
            pivot: denom,
        });
    }
    let factor = (rhs[0] + rhs[n - 1] * ratio) * (1.0 / denom);
    for (x, wi) in rhs.iter_mut().zip(&w) {
        *x = x.add_scaled(-wi[0], factor);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Dense Gaussian elimination with partial pivoting: the slow reference.
    fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<f64>) -> Vec<f64> {
        let n = b.len();
        for c in 0..n {
            let p = (c..n)
                .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
                .unwrap();
            a.swap(c, p);
            b.swap(c, p);
            let pivot_row = a[c].clone();
            for r in c + 1..n {
                let f = a[r][c] / pivot_row[c];
                for (x, p) in a[r][c..].iter_mut().zip(&pivot_row[c..]) {
                    *x -= f * p;
                }
                b[r] -= f * b[c];
            }
        }
        let mut x = vec![0.0; n];
        for r in (0..n).rev() {
            let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k]).sum();
            x[r] = (b[r] - s) / a[r][r];
        }
        x
    }

    fn coefs(i: usize) -> (f64, f64, f64) {
        let f = i as f64;
        (0.3 + 0.01 * f, 2.0 + (f * 0.7).sin(), -0.4 + 0.02 * f)
    }

    #[test]
    fn thomas_matches_dense() {
        let n = 9;
        let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 1.3).cos()).collect();
        let mut a = vec![vec![0.0; n]; n];
        for (i, row) in a.iter_mut().enumerate() {
            let (l, d, u) = coefs(i);
            row[i] = d;
            if i > 0 {
                row[i - 1] = l;
            }
            if i + 1 < n {
                row[i + 1] = u;
            }
        }
        let expect = dense_solve(a, rhs.clone());
        let mut x: Vec<Point<1>> = rhs.iter().map(|&r| Point([r])).collect();
        solve_tridiagonal(coefs, &mut x).unwrap();
        for (xi, ei) in x.iter().zip(&expect) {
            assert!((xi[0] - ei).abs() < 1e-13, "{} vs {}", xi[0], ei);
        }
    }

    #[test]
    fn cyclic_matches_dense() {
        for n in [3usize, 4, 11] {
            let rhs: Vec<f64> = (0..n).map(|i| (i as f64 * 0.9).sin() + 0.2).collect();
            let mut a = vec![vec![0.0; n]; n];
            for (i, row) in a.iter_mut().enumerate() {
                let (l, d, u) = coefs(i);
                row[i] += d;
                row[(i + n - 1) % n] += l;
                row[(i + 1) % n] += u;
            }
            let expect = dense_solve(a, rhs.clone());
            let mut x: Vec<Point<1>> = rhs.iter().map(|&r| Point([r])).collect();
            solve_cyclic_tridiagonal(coefs, &mut x).unwrap();
            for (xi, ei) in x.iter().zip(&expect) {
                assert!((xi[0] - ei).abs() < 1e-12, "n={n}: {} vs {}", xi[0], ei);
            }
        }
    }

    #[test]
    fn singular_is_an_error() {
        let mut x = vec![Point([1.0]); 3];
        let r = solve_tridiagonal(|_| (1.0, 0.0, 1.0), &mut x);
        assert!(matches!(r, Err(Error::SingularSystem { row: 0, .. })));
        let mut y = vec![Point([1.0]); 2];
        assert!(solve_cyclic_tridiagonal(|_| (1.0, 4.0, 1.0), &mut y).is_err());
    }
}

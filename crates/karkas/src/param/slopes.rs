//! The 1-D cubic spline in Hermite form: node slopes from the end conditions (seed 004,
//! (3.10)–(3.12); METHODS.md §5), and the Hermite basis.
//!
//! With knots `t_0 < .. < t_{n-1}`, steps `h_k = t_{k+1} - t_k`, divided differences
//! `delta_k = (y_{k+1} - y_k) / h_k`, `lambda_i = h_i / (h_{i-1} + h_i)`, `mu_i = 1 - lambda_i`
//! and the three-point derivative `y'_i = lambda_i delta_{i-1} + mu_i delta_i`, C^2 continuity
//! at an inner knot reads
//!
//! `lambda_i m_{i-1} + 2 m_i + mu_i m_{i+1} = 3 y'_i`.
//!
//! Not-a-knot ends (the third derivative is continuous at `t_1` and `t_{n-2}`) give
//! `m_0 = (g^2 - 1) m_1 + g^2 m_2 + 2 (delta_0 - g^2 delta_1)` with `g = h_0 / h_1` ((3.11);
//! likewise (3.12) at the other end). Eliminating `m_0` from the row of `t_1` leaves the
//! diagonally dominant row `(1 + g) m_1 + g m_2 = y'_1 + 2 g delta_1` of (3.10), so the
//! unknowns `m_1..m_{n-2}` solve a tridiagonal system without pivoting in `O(n)`, and the end
//! slopes follow. (The OCR of (3.10) swaps the indices of `gamma_N`; re-derived here.)
//! Natural ends (`2 m_0 + m_1 = 3 delta_0`), clamped ends (given slopes) and periodic ends
//! (a cyclic tridiagonal system, Sherman–Morrison) complete the set. The results agree with
//! any standard cubic spline of the same end conditions (tests against SciPy's
//! `CubicSpline`).

use crate::solve::{solve_cyclic_tridiagonal, solve_tridiagonal};
use crate::{Error, Point, Result};

/// The end conditions of a 1-D cubic spline.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SplineEnds<const D: usize> {
    /// The third derivative is continuous at the second and the second-to-last knots (the
    /// seed's (3.10)–(3.12)). With 3 points the spline is the parabola through them, with 2 the
    /// segment.
    NotAKnot,
    /// Zero second derivative at both ends.
    Natural,
    /// Given first derivatives at the two ends.
    Clamped {
        /// `P'(t_0)`.
        start: Point<D>,
        /// `P'(t_{n-1})`.
        end: Point<D>,
    },
    /// Periodic: the last value repeats the first and the curve is `C^2` across the seam.
    Periodic,
}

/// Fills `slopes` with the node derivatives `m_k = P'(t_k)` of the cubic spline through
/// `(knots[k], values[k])` with end conditions `ends`.
///
/// The caller guarantees `knots` strictly increasing, `knots.len() == values.len() ==
/// slopes.len() >= 2` (and `>= 3` for periodic ends, whose last value is taken to repeat the
/// first). Errors only on a vanishing pivot (impossible for increasing knots).
pub(crate) fn spline_slopes<const D: usize>(
    knots: &[f64],
    values: &[Point<D>],
    ends: &SplineEnds<D>,
    slopes: &mut [Point<D>],
) -> Result<()> {
    let n = knots.len();
    debug_assert!(n >= 2 && values.len() == n && slopes.len() == n);
    let h = |k: usize| knots[k + 1] - knots[k];
    let delta = |k: usize| (values[k + 1] - values[k]) * (1.0 / h(k));
    // The C^2 row of inner knot i: (lambda, mu, 3 y'_i).
    let inner = |i: usize| {
        let (hp, hc) = (h(i - 1), h(i));
        let lambda = hc / (hp + hc);
        let mu = 1.0 - lambda;
        (lambda, mu, (delta(i - 1) * lambda + delta(i) * mu) * 3.0)
    };
    match ends {
        SplineEnds::Periodic => return periodic_slopes(knots, values, slopes),
        SplineEnds::NotAKnot if n <= 3 => {
            if n == 2 {
                let d = delta(0);
                slopes.fill(d);
            } else {
                // The parabola through three points: its slope at t_1 is the three-point
                // derivative, and each segment's mean slope is its divided difference.
                let (_, _, r) = inner(1);
                let m1 = r * (1.0 / 3.0);
                slopes[1] = m1;
                slopes[0] = delta(0) * 2.0 - m1;
                slopes[2] = delta(1) * 2.0 - m1;
            }
            return Ok(());
        }
        SplineEnds::NotAKnot => {
            let gs = h(0) / h(1);
            let ge = h(n - 2) / h(n - 3);
            for (k, s) in slopes.iter_mut().enumerate().take(n - 1).skip(1) {
                *s = if k == 1 {
                    let (lambda, mu, _) = inner(1);
                    (delta(0) * lambda + delta(1) * mu).add_scaled(2.0 * gs, delta(1))
                } else if k == n - 2 {
                    let (lambda, mu, _) = inner(k);
                    (delta(k - 1) * lambda + delta(k) * mu).add_scaled(2.0 * ge, delta(k - 1))
                } else {
                    inner(k).2
                };
            }
            // Rows 1..=n-2 of the reduced system (3.10), indexed from 0.
            let coef = |r: usize| {
                let k = r + 1;
                if k == 1 {
                    (0.0, 1.0 + gs, gs)
                } else if k == n - 2 {
                    (ge, 1.0 + ge, 0.0)
                } else {
                    let (lambda, mu, _) = inner(k);
                    (lambda, 2.0, mu)
                }
            };
            solve_tridiagonal(coef, &mut slopes[1..n - 1])?;
            let (gs2, ge2) = (gs * gs, ge * ge);
            slopes[0] = (slopes[1] * (gs2 - 1.0) + slopes[2] * gs2)
                .add_scaled(2.0, delta(0))
                .add_scaled(-2.0 * gs2, delta(1));
            slopes[n - 1] = (slopes[n - 2] * (ge2 - 1.0) + slopes[n - 3] * ge2)
                .add_scaled(2.0, delta(n - 2))
                .add_scaled(-2.0 * ge2, delta(n - 3));
            return Ok(());
        }
        SplineEnds::Natural => {
            slopes[0] = delta(0) * 3.0;
            slopes[n - 1] = delta(n - 2) * 3.0;
        }
        SplineEnds::Clamped { start, end } => {
            slopes[0] = *start;
            slopes[n - 1] = *end;
        }
    }
    for (k, s) in slopes.iter_mut().enumerate().take(n - 1).skip(1) {
        *s = inner(k).2;
    }
    let natural = matches!(ends, SplineEnds::Natural);
    let coef = |k: usize| {
        if k == 0 {
            if natural {
                (0.0, 2.0, 1.0)
            } else {
                (0.0, 1.0, 0.0)
            }
        } else if k == n - 1 {
            if natural {
                (1.0, 2.0, 0.0)
            } else {
                (0.0, 1.0, 0.0)
            }
        } else {
            let (lambda, mu, _) = inner(k);
            (lambda, 2.0, mu)
        }
    };
    solve_tridiagonal(coef, slopes)
}

/// Periodic slopes: unknowns `m_0..m_{n-2}`, `m_{n-1} = m_0`, the C^2 row at every knot with
/// the steps wrapping around.
fn periodic_slopes<const D: usize>(
    knots: &[f64],
    values: &[Point<D>],
    slopes: &mut [Point<D>],
) -> Result<()> {
    let n = knots.len();
    let p = n - 1; // distinct points
    let h = |k: usize| knots[k + 1] - knots[k];
    let delta = |k: usize| (values[k + 1] - values[k]) * (1.0 / h(k));
    let prev = |i: usize| if i == 0 { p - 1 } else { i - 1 };
    let row = |i: usize| {
        let (hp, hc) = (h(prev(i)), h(i));
        let lambda = hc / (hp + hc);
        (lambda, 1.0 - lambda)
    };
    for (i, s) in slopes.iter_mut().enumerate().take(p) {
        let (lambda, mu) = row(i);
        *s = (delta(prev(i)) * lambda + delta(i) * mu) * 3.0;
    }
    match p {
        0 | 1 => {
            return Err(Error::TooFewPoints {
                what: "a periodic cubic spline (distinct points)",
                needed: 2,
                got: p,
            })
        }
        2 => {
            // Both neighbours of each knot are the other knot: 2 m0 + m1 = r0, m0 + 2 m1 = r1.
            let (r0, r1) = (slopes[0], slopes[1]);
            slopes[0] = (r0 * 2.0 - r1) * (1.0 / 3.0);
            slopes[1] = (r1 * 2.0 - r0) * (1.0 / 3.0);
        }
        _ => {
            let coef = |i: usize| {
                let (lambda, mu) = row(i);
                (lambda, 2.0, mu)
            };
            solve_cyclic_tridiagonal(coef, &mut slopes[..p])?;
        }
    }
    slopes[n - 1] = slopes[0];
    Ok(())
}

/// Weights of `[y_k, y_{k+1}, m_k, m_{k+1}]` in the `order`-th derivative (per unit of the
/// parameter) of the cubic Hermite segment of length `h` at local coordinate `s` in `[0, 1]`
/// ((3.7): `phi_1 = (1-s)^2 (1+2s)`, `phi_2 = s^2 (3-2s)`, `phi_3 = s (1-s)^2`,
/// `phi_4 = -s^2 (1-s)`, slopes weighted by `h`).
#[inline]
pub(crate) fn hermite_weights(s: f64, h: f64, order: usize) -> [f64; 4] {
    let s2 = s * s;
    let (w, scale) = match order {
        0 => (
            [
                1.0 - s2 * (3.0 - 2.0 * s),
                s2 * (3.0 - 2.0 * s),
                s * (1.0 - s) * (1.0 - s),
                s2 * (s - 1.0),
            ],
            1.0,
        ),
        1 => (
            [
                6.0 * s * (s - 1.0),
                6.0 * s * (1.0 - s),
                1.0 - 4.0 * s + 3.0 * s2,
                s * (3.0 * s - 2.0),
            ],
            1.0 / h,
        ),
        2 => (
            [12.0 * s - 6.0, 6.0 - 12.0 * s, 6.0 * s - 4.0, 6.0 * s - 2.0],
            1.0 / (h * h),
        ),
        3 => ([12.0, -12.0, 6.0, 6.0], 1.0 / (h * h * h)),
        _ => return [0.0; 4],
    };
    [
        w[0] * scale,
        w[1] * scale,
        w[2] * scale * h,
        w[3] * scale * h,
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64) -> Point<1> {
        Point([x])
    }

    #[test]
    fn cubics_are_reproduced_by_not_a_knot() {
        // Not-a-knot reproduces every cubic exactly, on any knots.
        let f = |t: f64| 1.0 - 2.0 * t + 0.5 * t * t - 0.3 * t * t * t;
        let df = |t: f64| -2.0 + t - 0.9 * t * t;
        for n in [2usize, 3, 4, 5, 9] {
            let knots: Vec<f64> = (0..n).map(|k| (k as f64).powf(1.3) * 0.7 - 0.2).collect();
            let values: Vec<Point<1>> = knots.iter().map(|&t| p(f(t))).collect();
            let mut m = vec![p(0.0); n];
            spline_slopes(&knots, &values, &SplineEnds::NotAKnot, &mut m).unwrap();
            if n >= 4 {
                for (t, mk) in knots.iter().zip(&m) {
                    assert!(
                        (mk[0] - df(*t)).abs() < 1e-12,
                        "n={n}: {} vs {}",
                        mk[0],
                        df(*t)
                    );
                }
            }
        }
    }

    #[test]
    fn hermite_weights_are_derivatives_of_each_other() {
        let h = 0.7;
        let eps = 1e-6;
        for order in 0..3 {
            for s in [0.1, 0.5, 0.8] {
                let a = hermite_weights(s + eps, h, order);
                let b = hermite_weights(s - eps, h, order);
                let d = hermite_weights(s, h, order + 1);
                for k in 0..4 {
                    let fd = (a[k] - b[k]) / (2.0 * eps * h);
                    assert!(
                        (fd - d[k]).abs() < 1e-6,
                        "order {order} k {k}: {fd} vs {}",
                        d[k]
                    );
                }
            }
        }
        assert_eq!(hermite_weights(0.3, 1.0, 4), [0.0; 4]);
    }
}

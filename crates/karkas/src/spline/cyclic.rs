//! The periodic slopes of one line of values in two passes (no stored factorization).
//!
//! **Method.** The periodic rows of the [module docs](super), each multiplied by
//! `(h_{i-1} + h_i) / 2` so that forming them takes no division:
//!
//! `h_i / 2 m_{i-1} + (h_{i-1} + h_i) m_i + h_{i-1} / 2 m_{i+1} = 3/2 (h_i delta_{i-1} + h_{i-1} delta_i)`,
//!
//! indices modulo the `p = n - 1` distinct points. The cyclic system is solved by Gaussian
//! elimination in its own order, without Sherman–Morrison: the forward pass eliminates the
//! rows `0..p-2` top down, carrying the fill of the last column (`m_{p-1}`, the seam
//! neighbour of row 0) as one number per row, and at the same time eliminates the first
//! unknowns from the last row; the last slope is then the quotient of two numbers and one
//! backward pass gives the rest. (The "periodic Thomas algorithm": the LU factors of the
//! cyclic matrix are those of the tridiagonal part plus a last column and a last row.)
//!
//! The rows are strictly diagonally dominant (`h_{i-1} + h_i > h_i / 2 + h_{i-1} / 2`), so no
//! pivoting is needed; the fill column and the last row's fill shrink geometrically along
//! the elimination (each step by at most 2/3, whatever the knots). Once both are below
//! `2^-60` (relative) they are dropped: the slopes move by less than `2^-58` of the largest
//! one, far below the rounding of the solve, and the remaining rows are a plain tridiagonal
//! sweep that never computes on subnormal numbers.
//!
//! Against [`SlopeSystem`](super::SlopeSystem) (which keeps the factorization for many lines
//! and for the transposed solve), this forms the rows from the knots as it goes, solves all
//! `D` coordinates in the same sweep, reads the knots and values once and stores one number
//! per row besides the slopes: one forward and one backward pass instead of forming the rows,
//! factoring, four sweeps and a correction pass. The results agree to rounding (tests
//! against a dense solve and against the factored system).

use crate::{Error, Point, Result};

/// Fill below this (relative to the row's pivot scale) is dropped; see the module docs.
const FILL_FLOOR: f64 = 1.0 / (1u64 << 60) as f64;

/// The slopes of the periodic cubic spline through `values` at `knots`
/// (`n = knots.len() >= 4`, `values[n - 1] == values[0]`); `slopes[n - 1]` repeats
/// `slopes[0]`. `O(n)`.
///
/// Fails with [`Error::SingularSystem`] only on knots whose steps are not finite and
/// positive (the callers have checked them).
pub(crate) fn periodic_slopes<const D: usize>(
    knots: &[f64],
    values: &[Point<D>],
) -> Result<Vec<Point<D>>> {
    let n = knots.len();
    debug_assert!(n >= 4 && values.len() == n);
    let p = n - 1;
    let step = |k: usize| knots[k + 1] - knots[k];
    let divided = |k: usize, h: f64| (values[k + 1] - values[k]) * (1.0 / h);
    // The last row (unknown p - 1): its coefficient of m_0, its diagonal, its right-hand side
    // (eliminated as the forward pass goes), and its coefficient of m_{p-2}.
    let (h_pen, h_last) = (step(p - 2), step(p - 1));
    let (d_pen, d_last) = (divided(p - 2, h_pen), divided(p - 1, h_last));
    let last_row = LastRow {
        e: 0.5 * h_pen,
        d: h_pen + h_last,
        f: (d_pen * h_last + d_last * h_pen) * 1.5,
    };
    let mut forward = eliminate_forward(knots, values, last_row, (h_last, d_last))?;
    forward.last_row.e = if forward.filling {
        forward.last_row.e
    } else {
        0.0
    } + 0.5 * h_last;
    substitute_back(forward)
}

/// The last row `e m_i + d m_{p-1} = f` while the forward pass eliminates its first unknowns.
struct LastRow<const D: usize> {
    e: f64,
    d: f64,
    f: Point<D>,
}

/// The rows `0..p-1` after the forward pass, and the last row with them eliminated.
struct Forward<const D: usize> {
    /// Row i normalised: `m_i + upper[i] m_{i+1} + fill[i] m_{p-1} = slopes[i]` (`fill`
    /// shorter where it was dropped).
    upper: Vec<f64>,
    fill: Vec<f64>,
    slopes: Vec<Point<D>>,
    /// Whether the fill was still carried at the last row (else `last_row.e` is dropped too).
    filling: bool,
    last_row: LastRow<D>,
}

/// The forward pass over the rows `0..p-1`, starting from the step and divided difference of
/// the seam's last piece (`h_{p-1}`, `delta_{p-1}`).
fn eliminate_forward<const D: usize>(
    knots: &[f64],
    values: &[Point<D>],
    LastRow {
        mut e,
        mut d,
        mut f,
    }: LastRow<D>,
    (mut hp, mut dp): (f64, Point<D>),
) -> Result<Forward<D>> {
    let p = knots.len() - 1;
    // (Filled as they come: no pass to zero them first.)
    let mut upper = Vec::with_capacity(p - 1);
    let mut slopes = Vec::with_capacity(p + 1);
    let mut fill: Vec<f64> = Vec::new();
    let mut filling = true;
    // Row 0's coefficient of m_{p-1} is its "lower" one: start the fill at -1 times it.
    let (mut u_prev, mut s_prev, mut y_prev) = (0.0, -1.0, Point::ZERO);
    let rows = knots.windows(2).zip(values.windows(2)).take(p - 1);
    for (i, (t, v)) in rows.enumerate() {
        let hc = t[1] - t[0];
        let dc = (v[1] - v[0]) * (1.0 / hc);
        let (lower, diag, above) = (0.5 * hc, hp + hc, 0.5 * hp);
        let rhs = (dp * hc + dc * hp) * 1.5;
        let pivot = diag - lower * u_prev;
        if !(pivot > 0.0 && pivot <= f64::MAX) {
            return Err(Error::SingularSystem { row: i, pivot });
        }
        // The chain from row to row is u: its own division, off the one of 1 / pivot.
        let u = above / pivot;
        let inv = 1.0 / pivot;
        let y = rhs.add_scaled(-lower, y_prev) * inv;
        upper.push(u);
        slopes.push(y);
        let mut s = 0.0;
        if filling {
            s = -lower * s_prev * inv;
            fill.push(s);
            if i + 2 < p {
                // Eliminate m_i from the last row.
                f = f.add_scaled(-e, y);
                d -= e * s;
                e = -e * u;
                filling = s.abs() > FILL_FLOOR || e.abs() > FILL_FLOOR * d;
            }
        }
        (hp, dp) = (hc, dc);
        (u_prev, s_prev, y_prev) = (u, s, y);
    }
    let last_row = LastRow { e, d, f };
    Ok(Forward {
        upper,
        fill,
        slopes,
        filling,
        last_row,
    })
}

/// The last slope from the last row (row `p - 2` reaches `m_{p-1}` through both its upper and
/// its fill coefficient), then the backward pass, and `m_{n-1} = m_0`.
fn substitute_back<const D: usize>(forward: Forward<D>) -> Result<Vec<Point<D>>> {
    let Forward {
        upper,
        fill,
        mut slopes,
        last_row: LastRow { e, d, f },
        ..
    } = forward;
    let p = upper.len() + 1;
    let g = upper[p - 2] + fill.get(p - 2).copied().unwrap_or(0.0);
    let y_pen = slopes[p - 2];
    let f = f.add_scaled(-e, y_pen);
    let d = d - e * g;
    if !(d > 0.0 && d.is_finite()) {
        return Err(Error::SingularSystem {
            row: p - 1,
            pivot: d,
        });
    }
    let last = f * (1.0 / d);
    slopes.push(last);
    slopes[p - 2] = y_pen.add_scaled(-g, last);
    let k = fill.len().min(p - 2);
    for i in (k..p - 2).rev() {
        slopes[i] = slopes[i].add_scaled(-upper[i], slopes[i + 1]);
    }
    for i in (0..k).rev() {
        slopes[i] = slopes[i]
            .add_scaled(-upper[i], slopes[i + 1])
            .add_scaled(-fill[i], last);
    }
    slopes.push(slopes[0]);
    Ok(slopes)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::{SlopeSystem, SplineEnds};

    /// The slopes by a dense solve of the periodic rows as printed in the module docs of
    /// `spline` (unscaled: `lambda_i m_{i-1} + 2 m_i + mu_i m_{i+1} = 3 (lambda_i
    /// delta_{i-1} + mu_i delta_i)`), Gaussian elimination with partial pivoting, one
    /// coordinate at a time.
    fn dense_slopes<const D: usize>(knots: &[f64], values: &[Point<D>]) -> Vec<Point<D>> {
        let p = knots.len() - 1;
        let h = |i: usize| knots[i % p + 1] - knots[i % p];
        let column = |c: usize| -> Vec<f64> {
            let delta = |i: usize| (values[i % p + 1][c] - values[i % p][c]) / h(i);
            // The augmented matrix [A | r].
            let mut a = vec![vec![0.0; p + 1]; p];
            for (i, row) in a.iter_mut().enumerate() {
                let (hp, hc) = (h(i + p - 1), h(i));
                let lambda = hc / (hp + hc);
                let mu = hp / (hp + hc);
                row[(i + p - 1) % p] += lambda;
                row[i] += 2.0;
                row[(i + 1) % p] += mu;
                row[p] = 3.0 * (lambda * delta(i + p - 1) + mu * delta(i));
            }
            for col in 0..p {
                let pivot = (col..p)
                    .max_by(|&x, &y| a[x][col].abs().total_cmp(&a[y][col].abs()))
                    .unwrap();
                a.swap(col, pivot);
                let top = a[col].clone();
                for row in a.iter_mut().skip(col + 1) {
                    let factor = row[col] / top[col];
                    for (x, &y) in row.iter_mut().zip(&top).skip(col) {
                        *x -= factor * y;
                    }
                }
            }
            let mut x = vec![0.0; p + 1];
            for row in (0..p).rev() {
                let s: f64 = (row + 1..p).map(|k| a[row][k] * x[k]).sum();
                x[row] = (a[row][p] - s) / a[row][row];
            }
            x[p] = x[0];
            x
        };
        let columns: Vec<Vec<f64>> = (0..D).map(column).collect();
        (0..=p)
            .map(|k| Point(std::array::from_fn(|c| columns[c][k])))
            .collect()
    }

    /// Closed 3-D data on `n` knots (the last value repeats the first) with steps that vary
    /// by the factor `spread` (1: even steps).
    fn ring(n: usize, spread: f64) -> (Vec<f64>, Vec<Point<3>>) {
        let mut knots = vec![0.0];
        for k in 1..n {
            let w = 1.0 + (spread - 1.0) * (0.5 + 0.5 * (k as f64 * 2.39).sin());
            knots.push(knots[k - 1] + w);
        }
        let span = knots[n - 1];
        let mut values: Vec<Point<3>> = knots
            .iter()
            .map(|&t| {
                let s = std::f64::consts::TAU * t / span;
                Point([
                    s.cos() * (1.0 + 0.3 * (7.0 * s).sin()),
                    s.sin(),
                    0.2 * (3.0 * s).cos(),
                ])
            })
            .collect();
        values[n - 1] = values[0];
        (knots, values)
    }

    fn max_difference(a: &[Point<3>], b: &[Point<3>]) -> f64 {
        a.iter()
            .zip(b)
            .map(|(x, y)| (*x - *y).max_abs())
            .fold(0.0, f64::max)
    }

    #[test]
    fn equals_a_dense_solve_of_the_periodic_rows() {
        for n in [4usize, 5, 6, 7, 9, 16, 41, 150] {
            for spread in [1.0, 3.0, 1e3, 1e-3] {
                let (knots, values) = ring(n, spread);
                let got = periodic_slopes(&knots, &values).unwrap();
                let expect = dense_slopes(&knots, &values);
                let scale = expect.iter().fold(1.0f64, |m, s| m.max(s.max_abs()));
                let err = max_difference(&got, &expect);
                assert!(
                    err < 1e-13 * scale,
                    "n={n} spread={spread}: {err:e} (scale {scale:e})"
                );
                assert_eq!(got[n - 1], got[0]);
            }
        }
    }

    /// At 10^5 knots (the fill dropped after a few dozen rows), against the factored system
    /// with Sherman–Morrison, and the C^2 joins checked from the Hermite pieces.
    #[test]
    fn equals_the_factored_system_on_many_knots_and_is_c2() {
        for spread in [1.0, 40.0] {
            let n = 100_001;
            let (knots, values) = ring(n, spread);
            let got = periodic_slopes(&knots, &values).unwrap();
            let mut expect = vec![Point::ZERO; n];
            SlopeSystem::new(&knots, &SplineEnds::<3>::Periodic)
                .unwrap()
                .solve(&values, &mut expect, 1, None);
            // The factored system weighs the values without forming their differences: its
            // rounding is that of |y| / h, not of the slopes.
            let min_step = knots
                .windows(2)
                .map(|w| w[1] - w[0])
                .fold(f64::MAX, f64::min);
            let size = values.iter().fold(0.0f64, |m, y| m.max(y.max_abs()));
            let scale = expect
                .iter()
                .fold(size / min_step, |m, s| m.max(s.max_abs()));
            let err = max_difference(&got, &expect);
            assert!(
                err < 1e-14 * scale,
                "spread={spread}: {err:e} (scale {scale:e})"
            );
            // Second derivatives at both ends of every piece: equal at every knot, the seam
            // included.
            let second = |k: usize| {
                let h = knots[k + 1] - knots[k];
                let d = (values[k + 1] - values[k]) * (1.0 / h);
                let (m0, m1) = (got[k], got[k + 1]);
                let start = (d * 6.0 - m0 * 4.0 - m1 * 2.0) * (1.0 / h);
                let end = (m0 * 2.0 + m1 * 4.0 - d * 6.0) * (1.0 / h);
                (start, end)
            };
            let mut jump = 0.0f64;
            let mut size = 0.0f64;
            for k in 0..n - 1 {
                let (start_next, _) = second((k + 1) % (n - 1));
                let (_, end) = second(k);
                jump = jump.max((start_next - end).max_abs());
                size = size.max(end.max_abs());
            }
            assert!(
                jump < 1e-9 * size,
                "spread={spread}: jump {jump:e} of {size:e}"
            );
        }
    }

    /// Steps alternating between 1 and 10^6 make the fill shrink slowly (by up to 2/3 per
    /// row): it must still be dropped, and the result still agree with the dense solve.
    #[test]
    fn uneven_steps_drop_the_fill_and_agree() {
        let n = 400;
        let mut knots = vec![0.0];
        for k in 1..n {
            knots.push(knots[k - 1] + if k % 2 == 0 { 1.0 } else { 1e6 });
        }
        let (_, mut values) = ring(n, 1.0);
        values[n - 1] = values[0];
        let got = periodic_slopes(&knots, &values).unwrap();
        let expect = dense_slopes(&knots, &values);
        let scale = expect.iter().fold(0.0f64, |m, s| m.max(s.max_abs()));
        let err = max_difference(&got, &expect);
        assert!(err < 1e-12 * scale, "{err:e} (scale {scale:e})");
    }
}

//! The evaluation kernel of [`CubicSpline`](super::CubicSpline): the piece lookup and the
//! Hermite combination (Kuznetsov and Filatov, (3.7)), written once over
//! [`Lane`] so that batches run four parameters per step in `f64x4`
//! and single points run the same arithmetic on one `f64` (equal bits).
//!
//! - The derivative order is a const parameter: the weights of each order are their own
//!   straight-line code, no branch per point.
//! - The local coordinate is `s = (t - t_k) * (1 / h_k)` with the inverse steps stored once:
//!   no division per point.
//! - The piece holding `t` is found from the previous parameter's piece (sorted batches: `O(1)`),
//!   else, when the knots are close to uniform, from the guess `(t - t_0) / step` (a multiply by
//!   the stored inverse step) corrected by at most one piece, else by binary search. Every path
//!   returns the one piece `k` with `t_k <= t < t_{k+1}` (the first piece below `t_0`, the
//!   last from `t_{n-1}` on, the first for NaN).

use crate::core::lanes::{f64x4, Lane, LANES};
use crate::Point;

/// The first guess of the piece lookup on nearly uniform knots: piece `(t - start) * inv_step`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct UniformGuess {
    start: f64,
    inv_step: f64,
}

impl UniformGuess {
    /// The guess for `knots` (at least 2) when every knot is within a quarter step of its
    /// uniform position, so that the guess is off by at most one piece; `None` otherwise.
    pub(super) fn new(knots: &[f64]) -> Option<Self> {
        let last = knots.len() - 1;
        let step = (knots[last] - knots[0]) / last as f64;
        let near = knots
            .iter()
            .enumerate()
            .all(|(k, &t)| (t - (knots[0] + k as f64 * step)).abs() <= 0.25 * step);
        (near && step > 0.0 && step.is_finite()).then(|| UniformGuess {
            start: knots[0],
            inv_step: 1.0 / step,
        })
    }
}

/// True when `t` lies on piece `k` of `knots` (`t_k <= t < t_{k+1}`, the first piece open
/// below, the last open above).
#[inline(always)]
fn holds(knots: &[f64], t: f64, k: usize) -> bool {
    let last = knots.len() - 2;
    (k == 0 || knots[k] <= t) && (k == last || t < knots[k + 1])
}

/// The piece of `t` on `knots`: the guess corrected by one piece when it holds, else a
/// binary search (equal to `partition_point(x <= t) - 1`, clamped to the pieces).
#[inline]
pub(super) fn piece_of(knots: &[f64], guess: Option<UniformGuess>, t: f64) -> usize {
    let last = knots.len() - 2;
    if let Some(g) = guess {
        // `as usize` saturates: below the start (and NaN) gives 0, +inf the last piece.
        let k = (((t - g.start) * g.inv_step) as usize).min(last);
        let k = if k > 0 && t < knots[k] {
            k - 1
        } else if k < last && t >= knots[k + 1] {
            k + 1
        } else {
            k
        };
        if holds(knots, t, k) {
            return k;
        }
    }
    knots
        .partition_point(|&x| x <= t)
        .saturating_sub(1)
        .min(last)
}

/// The piece of `t`, trying `hint` and the piece after it before [`piece_of`].
#[inline]
pub(super) fn piece_near(knots: &[f64], guess: Option<UniformGuess>, t: f64, hint: usize) -> usize {
    if holds(knots, t, hint) {
        hint
    } else if hint + 2 < knots.len() && holds(knots, t, hint + 1) {
        hint + 1
    } else {
        piece_of(knots, guess, t)
    }
}

/// The Hermite weights `[y_k, m_k, y_{k+1}, m_{k+1}]` on the unit piece, differentiated
/// `ORDER` times in `s` (`ORDER <= 3`): [`hermite_basis`](crate::spline::hermite_basis)
/// with `h = 1`, operation for operation.
#[inline(always)]
fn unit_weights<T: Lane, const ORDER: usize>(s: T) -> [T; 4] {
    let c = T::splat;
    match ORDER {
        0 => {
            let s2 = s * s;
            let y = c(1.0) - s;
            let v1 = s2 * (c(3.0) - c(2.0) * s);
            [c(1.0) - v1, s * y * y, v1, (s2 * y).neg()]
        }
        1 => {
            let s2 = s * s;
            let d = c(6.0) * s * (c(1.0) - s);
            [
                d.neg(),
                c(1.0) - c(4.0) * s + c(3.0) * s2,
                d,
                c(3.0) * s2 - c(2.0) * s,
            ]
        }
        2 => {
            let d = c(12.0) * s - c(6.0);
            [d, c(6.0) * s - c(4.0), d.neg(), c(6.0) * s - c(2.0)]
        }
        _ => [c(12.0), c(6.0), c(-12.0), c(6.0)],
    }
}

/// One coordinate of the `ORDER`-th derivative on a piece of step `h` (`inv_h = 1 / h`):
/// the combination in `s`, then one factor `1 / h` per order (the weights `1 / h^k` of the
/// basis in `t` overflow or underflow for steps near `1e150` or `1e-150`, the derivative
/// itself does not). The values enter through their difference (the weights of `y_k` and
/// `y_{k+1}` sum to 1 for the values and to 0 for the derivatives), so that values offset
/// far from zero keep their digits: `y_k + (y_{k+1} - y_k) w_2 + ...`.
#[inline(always)]
fn combine<T: Lane, const ORDER: usize>(w: &[T; 4], [y0, m0, y1, m1]: [T; 4], h: T, inv_h: T) -> T {
    let mut d = (y1 - y0) * w[2] + (m0 * h) * w[1] + (m1 * h) * w[3];
    if ORDER == 0 {
        d = y0 + d;
    }
    for _ in 0..ORDER {
        d = d * inv_h;
    }
    d
}

/// The spline's data as the kernel reads it.
pub(super) struct Pieces<'a, const D: usize> {
    pub(super) knots: &'a [f64],
    pub(super) inv_steps: &'a [f64],
    pub(super) values: &'a [Point<D>],
    pub(super) slopes: &'a [Point<D>],
}

impl<const D: usize> Pieces<'_, D> {
    /// The `ORDER`-th derivative (`ORDER <= 3`) at local coordinate `s` of piece `k`.
    #[inline(always)]
    pub(super) fn at<const ORDER: usize>(&self, k: usize, s: f64) -> Point<D> {
        let h = self.knots[k + 1] - self.knots[k];
        let inv_h = self.inv_steps[k];
        let w = unit_weights::<f64, ORDER>(s);
        Point(std::array::from_fn(|c| {
            let ends = [
                self.values[k][c],
                self.slopes[k][c],
                self.values[k + 1][c],
                self.slopes[k + 1][c],
            ];
            combine::<f64, ORDER>(&w, ends, h, inv_h)
        }))
    }

    /// The operands of four parameters on the pieces `k`: gathered lane by lane, or
    /// broadcast once when the four share a piece (sorted parameters, nearly always).
    #[inline(always)]
    pub(super) fn operands(&self, k: [usize; LANES]) -> Operands<D> {
        if k.iter().all(|&j| j == k[0]) {
            let k = k[0];
            let start = self.knots[k];
            let ends = |c: usize| {
                [
                    self.values[k][c],
                    self.slopes[k][c],
                    self.values[k + 1][c],
                    self.slopes[k + 1][c],
                ]
                .map(f64x4::splat)
            };
            return Operands {
                start: f64x4::splat(start),
                h: f64x4::splat(self.knots[k + 1] - start),
                inv_h: f64x4::splat(self.inv_steps[k]),
                ends: std::array::from_fn(ends),
            };
        }
        let gather = |f: &dyn Fn(usize) -> f64| f64x4::new(k.map(f));
        let start = gather(&|k| self.knots[k]);
        Operands {
            start,
            h: gather(&|k| self.knots[k + 1]) - start,
            inv_h: gather(&|k| self.inv_steps[k]),
            ends: std::array::from_fn(|c| {
                [
                    gather(&|k| self.values[k][c]),
                    gather(&|k| self.slopes[k][c]),
                    gather(&|k| self.values[k + 1][c]),
                    gather(&|k| self.slopes[k + 1][c]),
                ]
            }),
        }
    }
}

/// What four parameters need of their pieces, lane by lane: the piece start `t_k`, its step
/// `h`, `1 / h`, and per coordinate `[y_k, m_k, y_{k+1}, m_{k+1}]`.
#[derive(Clone, Copy)]
pub(super) struct Operands<const D: usize> {
    start: f64x4,
    h: f64x4,
    inv_h: f64x4,
    ends: [[f64x4; 4]; D],
}

impl<const D: usize> Operands<D> {
    /// The `ORDER`-th derivative (`ORDER <= 3`) at the four parameters `t` (already wrapped).
    #[inline(always)]
    pub(super) fn at4<const ORDER: usize>(&self, t: f64x4, out: &mut [Point<D>]) {
        let s = (t - self.start) * self.inv_h;
        let w = unit_weights::<f64x4, ORDER>(s);
        for c in 0..D {
            let d = combine::<f64x4, ORDER>(&w, self.ends[c], self.h, self.inv_h).to_array();
            for (p, x) in out.iter_mut().zip(d) {
                p.0[c] = x;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::hermite_basis;

    /// The unit weights are `hermite_basis` on a unit piece, bit for bit.
    #[test]
    fn unit_weights_are_the_hermite_basis() {
        for s in [0.0, 1e-300, 0.1, 0.37, 0.5, 0.999, 1.0, 1.5, -0.25] {
            let expect: [[f64; 4]; 4] = std::array::from_fn(|k| hermite_basis(s, 1.0, k));
            let got = [
                unit_weights::<f64, 0>(s),
                unit_weights::<f64, 1>(s),
                unit_weights::<f64, 2>(s),
                unit_weights::<f64, 3>(s),
            ];
            for k in 0..4 {
                for c in 0..4 {
                    assert_eq!(
                        got[k][c].to_bits(),
                        expect[k][c].to_bits(),
                        "s={s} k={k} c={c}"
                    );
                }
            }
        }
    }

    /// The reference: the piece by binary search.
    fn piece_by_search(knots: &[f64], t: f64) -> usize {
        knots
            .partition_point(|&x| x <= t)
            .saturating_sub(1)
            .min(knots.len() - 2)
    }

    /// At every knot, one ulp either side of it, outside the ends and at NaN and infinities,
    /// the uniform guess and the hint find the piece the binary search finds: on uniform
    /// knots whose sums are inexact (steps 0.1, 1/3), on knots a quarter step off uniform
    /// (the guess is then off by one), and on knots far from uniform (no guess).
    #[test]
    fn lookups_find_the_piece_of_the_binary_search() {
        let n = 200;
        let sets: Vec<Vec<f64>> = vec![
            (0..n).map(|k| k as f64 * 0.1).collect(),
            (0..n).map(|k| k as f64 / 3.0 - 7.0).collect(),
            (0..n).map(|k| k as f64 / (n - 1) as f64).collect(),
            (0..n)
                .map(|k| {
                    k as f64
                        + if k % 2 == 1 { 0.2499 } else { -0.2499 } * f64::from(k > 0 && k < n - 1)
                })
                .collect(),
            (0..n).map(|k| (k as f64).powi(2)).collect(),
            vec![0.0, 1.0],
        ];
        for (set, knots) in sets.iter().enumerate() {
            let guess = UniformGuess::new(knots);
            assert_eq!(guess.is_some(), set != 4, "set {set}");
            let mut ts = vec![f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -1e300, 1e300];
            for &x in knots {
                ts.extend([
                    x,
                    x.next_up(),
                    x.next_down(),
                    x + 0.5 * (knots[1] - knots[0]),
                ]);
            }
            for &t in &ts {
                let expect = piece_by_search(knots, t);
                assert_eq!(piece_of(knots, guess, t), expect, "set {set} t={t:e}");
                for hint in [
                    0,
                    expect.saturating_sub(1),
                    expect,
                    (expect + 1).min(knots.len() - 2),
                ] {
                    assert_eq!(
                        piece_near(knots, guess, t, hint),
                        expect,
                        "set {set} t={t:e} hint {hint}"
                    );
                }
            }
        }
    }

    /// Four lanes equal four single evaluations bit for bit, every order, on four pieces
    /// (gathered operands) and on one (broadcast operands).
    #[test]
    fn four_lanes_equal_single_points() {
        let knots = [0.0, 0.3, 1.1, 1.15, 2.0];
        let inv_steps: Vec<f64> = knots.windows(2).map(|w| 1.0 / (w[1] - w[0])).collect();
        let values: Vec<Point<2>> = (0..5)
            .map(|k| Point([(k as f64).sin(), k as f64 * 0.7]))
            .collect();
        let slopes: Vec<Point<2>> = (0..5).map(|k| Point([(k as f64).cos(), -0.0])).collect();
        let p = Pieces {
            knots: &knots,
            inv_steps: &inv_steps,
            values: &values,
            slopes: &slopes,
        };
        for t in [[0.1, 1.12, -0.5, 2.7], [0.31, 0.5, 0.7, 1.0999]] {
            let k = t.map(|t| piece_of(&knots, None, t));
            fn check<const O: usize>(p: &Pieces<'_, 2>, k: [usize; 4], t: [f64; 4]) {
                let mut four = [Point([0.0; 2]); 4];
                p.operands(k).at4::<O>(f64x4::new(t), &mut four);
                for l in 0..4 {
                    let one = p.at::<O>(k[l], (t[l] - p.knots[k[l]]) * p.inv_steps[k[l]]);
                    for c in 0..2 {
                        assert_eq!(four[l][c].to_bits(), one[c].to_bits(), "order {O} lane {l}");
                    }
                }
            }
            check::<0>(&p, k, t);
            check::<1>(&p, k, t);
            check::<2>(&p, k, t);
            check::<3>(&p, k, t);
        }
    }
}

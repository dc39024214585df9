//! 1-D cubic interpolating splines on arbitrary increasing knots (Kuznetsov and Filatov,
//! (3.6)–(3.12); the method is described in [`crate::spline`]).
//!
//! A [`CubicSpline`] stores the knots, the values and the node slopes (Hermite form); the
//! slopes come from one `O(n)` tridiagonal solve of [`crate::spline`] for the chosen
//! [`SplineEnds`]. Guarantees:
//! passes through every point at its knot; `C^2` everywhere (`C^2` across the seam when
//! periodic); not-a-knot reproduces every cubic polynomial exactly. Evaluation is `O(log n)`
//! (binary search for the piece) plus a handful of multiply-adds.

use super::parameterization::{curve_parameters, CurveParameterization};
use super::spline_eval::{piece_near, piece_of, Pieces, UniformGuess};
use crate::core::knots::{check_knots, check_min_gap, Knots};
use crate::core::lanes::{f64x4, load4, CmpGe, CmpLt, LANES};
use crate::core::parallel::for_each_chunk;
use crate::core::{with_shared_end, Curve, Interval, PiecewiseCurve, Side};
use crate::spline::{hermite_basis, not_a_knot_slopes, periodic_slopes, SlopeSystem, SplineEnds};
use crate::{Error, Point, Result};

/// A cubic interpolating spline `t -> P(t)` in R^D on knots `t_0 < .. < t_{n-1}`.
///
/// Outside `[t_0, t_{n-1}]` an open spline continues the polynomial of its first or last
/// piece (as SciPy's `CubicSpline` does) and a periodic one wraps by its period.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSpline<const D: usize> {
    knots: Knots,
    values: Vec<Point<D>>,
    slopes: Vec<Point<D>>,
    periodic: bool,
    /// `1 / (t_{k+1} - t_k)` of every piece: evaluation multiplies, never divides.
    inv_steps: Vec<f64>,
    /// The first guess of the piece lookup when the knots are close to uniform.
    guess: Option<UniformGuess>,
}

impl<const D: usize> CubicSpline<D> {
    /// The cubic spline through `(knots[k], values[k])` with end conditions `ends`.
    ///
    /// Periodic ends through two knots (one value, repeated) give the constant, as SciPy's
    /// `CubicSpline` does.
    ///
    /// Errors: fewer than 2 points, lengths that differ
    /// ([`Error::CountMismatch`]), knots not finite and strictly increasing or closer than
    /// `1e-12` of their span ([`Error::InvalidKnot`]), or so close that the values'
    /// differences over them overflow the slopes (`InvalidKnot` naming the knot that ends
    /// the smallest gap), a non-finite value or clamped end derivative, and for periodic
    /// ends a last value that does not repeat the first (relative tolerance `1e-12`,
    /// [`Error::OpenPeriodicData`]).
    ///
    /// ```
    /// use karkas::param::{CubicSpline, SplineEnds};
    /// use karkas::{Curve, Point};
    ///
    /// // Not-a-knot ends reproduce a cubic: y = x^3 through five points.
    /// let knots = [0.0, 1.0, 2.0, 3.0, 4.0];
    /// let values: Vec<Point<1>> = knots.iter().map(|&x: &f64| Point([x.powi(3)])).collect();
    /// let spline = CubicSpline::new(&knots, &values, SplineEnds::NotAKnot)?;
    /// assert!((spline.eval(2.5).0[0] - 2.5f64.powi(3)).abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(knots: &[f64], values: &[Point<D>], ends: SplineEnds<D>) -> Result<Self> {
        Self::from_owned(knots.to_vec(), values.to_vec(), ends, false)
    }

    /// [`new`](Self::new) on owned knots and values (no copies of them are made);
    /// `finite_values`: the caller has checked every value finite.
    fn from_owned(
        knots: Vec<f64>,
        values: Vec<Point<D>>,
        ends: SplineEnds<D>,
        finite_values: bool,
    ) -> Result<Self> {
        let n = knots.len();
        let periodic = matches!(ends, SplineEnds::Periodic);
        // Periodic through two knots is the constant of the one value (as SciPy's).
        let needed = 2;
        if n < needed {
            return Err(Error::TooFewPoints {
                what: "a cubic spline",
                needed,
                got: n,
            });
        }
        if values.len() != n {
            return Err(Error::CountMismatch {
                what: "knots of a cubic spline (one per value)",
                expected: values.len(),
                got: n,
            });
        }
        check_parameters(&knots)?;
        if !finite_values {
            if let Some(index) = values.iter().position(|p| !p.is_finite()) {
                return Err(Error::NonFinitePoint { index });
            }
        }
        if let SplineEnds::Clamped { start, end } = ends {
            if let Some(&value) = start.0.iter().chain(&end.0).find(|x| !x.is_finite()) {
                return Err(Error::InvalidSetting {
                    name: "clamped end derivative",
                    value,
                    reason: "the clamped end derivatives must be finite",
                });
            }
        }
        let mut values = values;
        if periodic {
            let seam = values[n - 1] - values[0];
            if seam != Point::ZERO && seam.max_abs() > 1e-12 * max_abs(&values) {
                return Err(Error::OpenPeriodicData {
                    what: "a periodic spline",
                    item: "value",
                });
            }
            values[n - 1] = values[0];
        }
        let clamped = match ends {
            SplineEnds::Clamped { start, end } => Some((start, end)),
            _ => None,
        };
        let slopes = if periodic && n >= 4 {
            periodic_slopes(&knots, &values)?
        } else {
            let mut slopes = vec![Point::ZERO; n];
            if matches!(ends, SplineEnds::NotAKnot) && n >= 4 {
                not_a_knot_slopes(&knots, &values, &mut slopes)?;
            } else {
                SlopeSystem::new(&knots, &ends)?.solve(&values, &mut slopes, 1, clamped);
            }
            slopes
        };
        if !slopes.iter().all(|m| m.is_finite()) {
            return Err(overflow_at_smallest_gap(&[&knots]));
        }
        let inv_steps = knots.windows(2).map(|w| 1.0 / (w[1] - w[0])).collect();
        let guess = UniformGuess::new(&knots);
        Ok(CubicSpline {
            knots: Knots::from_checked(knots),
            values,
            slopes,
            periodic,
            inv_steps,
            guess,
        })
    }

    /// The cubic spline through `points` with parameters by the rule `parameterization`
    /// (starting at 0). With periodic ends the curve is closed: if the last point repeats the
    /// first (relative tolerance `1e-12`) it is the seam, otherwise the first point is
    /// appended. With other ends, a first and last point that coincide by the shared-end rule
    /// ([`crate::core::shared_end`]: within `1e-6` of the points' size, a sharp trailing edge)
    /// are both replaced by their midpoint, so the curve closes there exactly with a corner.
    ///
    /// Errors: those of [`curve_parameters`] and [`new`](Self::new).
    ///
    /// ```
    /// use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
    /// use karkas::{Curve, Point};
    ///
    /// // A closed curve through eight points of the unit circle, C^2 across the seam.
    /// let pts: Vec<Point<2>> = (0..8)
    ///     .map(|k| {
    ///         let a = std::f64::consts::TAU * k as f64 / 8.0;
    ///         Point([a.cos(), a.sin()])
    ///     })
    ///     .collect();
    /// let curve = CubicSpline::through(&pts, CurveParameterization::ChordLength, SplineEnds::Periodic)?;
    /// assert!(curve.is_closed());
    /// let d = curve.domain();
    /// assert!(curve.eval(d.start).distance(curve.eval(d.end)) < 1e-12);
    /// assert!((curve.eval(d.uniform(1, 3)).norm() - 1.0).abs() < 1e-2);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn through(
        points: &[Point<D>],
        parameterization: CurveParameterization,
        ends: SplineEnds<D>,
    ) -> Result<Self> {
        // Room for the seam point: no second copy of the points when it is appended.
        let mut pts = Vec::with_capacity(points.len() + 1);
        if matches!(ends, SplineEnds::Periodic) {
            pts.extend_from_slice(points);
            if let (Some(&first), Some(&last)) = (pts.first(), pts.last()) {
                if last != first && (last - first).max_abs() > 1e-12 * max_abs(&pts) {
                    pts.push(first);
                }
            }
        } else {
            pts.extend_from_slice(&with_shared_end(points));
        }
        // curve_parameters fails on any point that is not finite.
        let knots = curve_parameters(&pts, parameterization)?;
        Self::from_owned(knots, pts, ends, true)
    }

    /// The knots `t_0 < .. < t_{n-1}`.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The interpolated values (`values[k] = P(t_k)`).
    pub fn values(&self) -> &[Point<D>] {
        &self.values
    }

    /// The node slopes `m_k = P'(t_k)`.
    pub fn slopes(&self) -> &[Point<D>] {
        &self.slopes
    }

    /// The piece holding `t` and the local coordinate `s = (t - t_k) / h_k` (a multiply by
    /// the stored inverse step). A periodic spline wraps `t` first; a knot belongs to the
    /// piece on `side` of it.
    #[inline]
    fn locate(&self, t: f64, side: Side) -> (usize, f64) {
        let last = self.knots.len() - 2;
        let t = if self.periodic {
            let w = self.domain().wrap(t);
            if side == Side::Below && w <= self.knots[0] {
                return (last, 1.0);
            }
            w
        } else {
            t
        };
        let k = match side {
            Side::Above => piece_of(&self.knots, self.guess, t),
            Side::Below => self
                .knots
                .partition_point(|&x| x < t)
                .saturating_sub(1)
                .min(last),
        };
        (k, (t - self.knots[k]) * self.inv_steps[k])
    }

    /// The kernel's view of the spline.
    #[inline]
    fn pieces(&self) -> Pieces<'_, D> {
        Pieces {
            knots: &self.knots,
            inv_steps: &self.inv_steps,
            values: &self.values,
            slopes: &self.slopes,
        }
    }

    /// The `ORDER`-th derivative (`ORDER <= 3`) at every parameter of `ts` into `out`,
    /// serially, four parameters per step; sorted parameters find their piece in `O(1)`.
    /// Equal bit for bit to [`deriv_on_piece`](Self::deriv_on_piece) at each parameter.
    fn deriv_batch<const ORDER: usize>(&self, ts: &[f64], out: &mut [Point<D>]) {
        let domain = self.domain();
        let pieces = self.pieces();
        let (knots, guess) = (&self.knots[..], self.guess);
        let wrap = |t: f64| if self.periodic { domain.wrap(t) } else { t };
        let last = knots.len() - 2;
        // The piece of the last four parameters that shared one: its bounds (open at the
        // ends of the knots) and its operands, broadcast.
        let bounds = |k: usize| {
            let lo = if k == 0 { f64::NEG_INFINITY } else { knots[k] };
            let hi = if k == last {
                f64::INFINITY
            } else {
                knots[k + 1]
            };
            (f64x4::splat(lo), f64x4::splat(hi))
        };
        let mut hint = 0;
        let (mut lo, mut hi) = bounds(0);
        let mut shared = pieces.operands([0; LANES]);
        let mut t4 = ts.chunks_exact(LANES);
        let mut o4 = out.chunks_exact_mut(LANES);
        for (tc, oc) in (&mut t4).zip(&mut o4) {
            let tv = if self.periodic {
                f64x4::new([wrap(tc[0]), wrap(tc[1]), wrap(tc[2]), wrap(tc[3])])
            } else {
                load4(tc)
            };
            // All four on the shared piece (NaN never is): `t_k <= t < t_{k+1}` lane-wise.
            if (tv.cmp_ge(lo) & tv.cmp_lt(hi)).all() {
                shared.at4::<ORDER>(tv, oc);
                continue;
            }
            let t = tv.to_array();
            let mut k = [0; LANES];
            for l in 0..LANES {
                hint = piece_near(knots, guess, t[l], hint);
                k[l] = hint;
            }
            if k.iter().all(|&j| j == k[0]) {
                (lo, hi) = bounds(k[0]);
                shared = pieces.operands(k);
                shared.at4::<ORDER>(tv, oc);
            } else {
                pieces.operands(k).at4::<ORDER>(tv, oc);
            }
        }
        for (p, &t) in o4.into_remainder().iter_mut().zip(t4.remainder()) {
            let t = wrap(t);
            hint = piece_near(knots, guess, t, hint);
            *p = pieces.at::<ORDER>(hint, (t - knots[hint]) * self.inv_steps[hint]);
        }
    }

    #[inline]
    fn deriv_on_piece(&self, (k, s): (usize, f64), order: usize) -> Point<D> {
        // The derivative in `s` on the unit interval, then divided by `h` once per order: the
        // weights `1/h^k` of `hermite_basis` overflow or underflow for the third derivative
        // when `h` is near 1e150 or 1e-150 (chord parameters of such coordinates), while the
        // derivative itself is representable.
        let pieces = self.pieces();
        match order {
            0 => pieces.at::<0>(k, s),
            1 => pieces.at::<1>(k, s),
            2 => pieces.at::<2>(k, s),
            3 => pieces.at::<3>(k, s),
            _ => {
                let h = self.knots[k + 1] - self.knots[k];
                let w = hermite_basis(s, 1.0, order);
                let mut d = self.values[k] * w[0]
                    + self.values[k + 1] * w[2]
                    + (self.slopes[k] * h) * w[1]
                    + (self.slopes[k + 1] * h) * w[3];
                for _ in 0..4 {
                    d *= self.inv_steps[k];
                }
                d
            }
        }
    }
}

impl<const D: usize> Curve<D> for CubicSpline<D> {
    fn domain(&self) -> Interval {
        self.knots.domain()
    }

    fn is_closed(&self) -> bool {
        self.periodic
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.deriv_on_piece(self.locate(t, Side::Above), 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        self.deriv_on_piece(self.locate(t, Side::Above), k)
    }

    fn eval_with_derivatives(&self, t: f64) -> [Point<D>; 3] {
        let at = self.locate(t, Side::Above);
        [0, 1, 2].map(|k| self.deriv_on_piece(at, k))
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.knots.to_vec(),
            2,
        ))
    }

    /// Equal to [`eval`](Curve::eval) at every parameter; in parallel above
    /// a size threshold, `O(1)` per parameter when they are sorted.
    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        self.deriv_into(ts, 0, out);
    }

    /// Equal to [`deriv`](Curve::deriv) at every parameter; in parallel above a size
    /// threshold, `O(1)` per parameter when they are sorted.
    fn deriv_into(&self, ts: &[f64], k: usize, out: &mut [Point<D>]) {
        crate::core::assert_buffer_len(ts.len(), out.len());
        // The order is resolved once per batch: each kernel is straight-line code.
        for_each_chunk(ts, out, |t, o| match k {
            0 => self.deriv_batch::<0>(t, o),
            1 => self.deriv_batch::<1>(t, o),
            2 => self.deriv_batch::<2>(t, o),
            3 => self.deriv_batch::<3>(t, o),
            _ => {
                for (p, &t) in o.iter_mut().zip(t) {
                    *p = self.deriv(t, k);
                }
            }
        });
    }
}

impl<const D: usize> PiecewiseCurve<D> for CubicSpline<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.knots.to_vec()
    }

    fn continuity(&self) -> usize {
        2
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        self.deriv_on_piece(self.locate(t, side), k)
    }
}

/// The smallest gap between consecutive parameters, as a part of their whole span: closer
/// knots make slopes overflow and the system singular.
const MIN_RELATIVE_KNOT_GAP: f64 = 1e-12;

/// The largest absolute coordinate of `points` (NaN ignored), one running maximum per
/// coordinate so that the maxima do not wait on each other.
fn max_abs<const D: usize>(points: &[Point<D>]) -> f64 {
    let most = points.iter().fold([0.0f64; D], |mut m, p| {
        for (m, c) in m.iter_mut().zip(p.0) {
            *m = m.max(c.abs());
        }
        m
    });
    most.into_iter().fold(0.0, f64::max)
}

/// The smallest gap allowed between knots spanning `span`: [`MIN_RELATIVE_KNOT_GAP`] of it,
/// and never below the smallest normal float (a subnormal gap has no finite reciprocal, and
/// the B-spline weights divide by it).
fn min_knot_gap(span: f64) -> f64 {
    (MIN_RELATIVE_KNOT_GAP * span).max(f64::MIN_POSITIVE)
}

/// Fails unless `knots` (at least 2) are finite, strictly increasing, and no gap is below
/// [`min_knot_gap`] of their span ([`Error::InvalidKnot`]).
pub(super) fn check_parameters(knots: &[f64]) -> Result<()> {
    // One pass that only says yes: finite ends and every gap positive and at least the
    // smallest allowed make the knots finite, strictly increasing and far enough apart.
    // Anything else goes through the checks below, which name the first fault.
    if let [first, .., last] = knots {
        let span = last - first;
        let floor = min_knot_gap(span);
        let apart = knots
            .windows(2)
            .fold(true, |ok, w| ok & (w[1] - w[0] >= floor));
        if apart && first.is_finite() && span.is_finite() {
            return Ok(());
        }
    }
    check_knots(knots, 2, "a cubic spline (knots)")?;
    let span = knots[knots.len() - 1] - knots[0];
    check_min_gap(
        knots,
        min_knot_gap(span),
        "closer than 1e-12 of the knot span (or than the smallest normal float) to the knot before it",
    )
}

/// The error of a spline or surface whose coefficients overflowed: coordinate differences
/// over a knot gap too small for them (a gap of `4e-308` under a difference of `425`). Names
/// the knot that ends the smallest gap of all `knot_lists`.
pub(super) fn overflow_at_smallest_gap(knot_lists: &[&[f64]]) -> Error {
    let (_, index, value) = knot_lists
        .iter()
        .flat_map(|knots| (1..knots.len()).map(|k| (knots[k] - knots[k - 1], k, knots[k])))
        .fold(
            (f64::INFINITY, 0, 0.0),
            |a, b| if b.0 < a.0 { b } else { a },
        );
    Error::InvalidKnot {
        index,
        value,
        reason: "too close to the knot before it for the values' differences: the slopes overflow",
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knots_closer_than_the_smallest_normal_float_are_refused() {
        // A subnormal gap passed the relative floor (1e-12 of a subnormal span is 0) and gave
        // a bicubic surface whose evaluation was NaN.
        let err = check_parameters(&[1.5e-323, 1.43e-322]).unwrap_err();
        assert!(err.to_string().contains("knot"), "{err}");
        assert!(check_parameters(&[0.0, f64::MIN_POSITIVE]).is_ok());
    }

    /// The same bits, or both NaN (the sign and payload of a NaN depend on which operand the
    /// compiler puts first, in vector code as in scalar code).
    fn same_bits(a: f64, b: f64) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    /// Batches (serial and parallel, sorted and not, outside the domain, NaN; four-lane steps
    /// and the remainder) equal the one-point calls bitwise: both run the same kernel
    /// (`spline_eval`), in `f64x4` and in `f64`.
    #[test]
    fn batches_equal_single_calls_bitwise() {
        let n = 300;
        let points: Vec<Point<3>> = (0..n)
            .map(|k| {
                let s = k as f64 * 0.05;
                Point([s.cos(), (2.0 * s).sin(), 0.1 * s * s])
            })
            .collect();
        let ring: Vec<Point<3>> = (0..n)
            .map(|k| {
                let s = k as f64 * std::f64::consts::TAU / n as f64;
                Point([s.cos(), s.sin(), 0.3 * (3.0 * s).sin()])
            })
            .collect();
        let open = CubicSpline::through(
            &points,
            CurveParameterization::ChordLength,
            SplineEnds::NotAKnot,
        )
        .unwrap();
        let closed = CubicSpline::through(
            &ring,
            CurveParameterization::Centripetal,
            SplineEnds::Periodic,
        )
        .unwrap();
        for curve in [&open, &closed] {
            let d = curve.domain();
            let m = 70_001; // above the parallel threshold
            let mut ts: Vec<f64> = (0..m)
                .map(|i| d.start - 0.1 + (d.length() + 0.2) * i as f64 / (m - 1) as f64)
                .collect();
            ts[7] = f64::NAN;
            ts[8] = d.end;
            ts[9] = d.start;
            let mut shuffled = ts.clone();
            for i in 0..m {
                shuffled.swap(i, (i * 7919) % m);
            }
            for ts in [&ts, &shuffled, &ts[..100].to_vec(), &ts[..7].to_vec()] {
                for k in 0..6 {
                    let mut out = vec![Point::ZERO; ts.len()];
                    curve.deriv_into(ts, k, &mut out);
                    for (&t, p) in ts.iter().zip(&out) {
                        let e = curve.deriv(t, k);
                        for c in 0..3 {
                            assert!(same_bits(p[c], e[c]), "t={t} k={k}: {} vs {}", p[c], e[c]);
                        }
                    }
                }
                let mut out = vec![Point::ZERO; ts.len()];
                curve.eval_into(ts, &mut out);
                assert!(ts.iter().zip(&out).all(|(&t, p)| {
                    let e = curve.eval(t);
                    (0..3).all(|c| same_bits(p[c], e[c]))
                }));
            }
        }
    }
}

//! Many arc lengths of one curve: the lengths of its polynomial pieces measured once.
//!
//! [`arc_length`](fn@super::arc_length) integrates `|P'|` over every piece between its two parameters, so `m`
//! intervals of a curve of `n` pieces cost `O(m n)`. An [`ArcLengthTable`] integrates each
//! piece once (adaptive Gauss–Legendre, as [`arc_length`](fn@super::arc_length) does) and keeps the cumulative
//! lengths `S_k = s(t_0, t_k)` at the breakpoints; then
//! `s(a, b) = s(t_0, b) - s(t_0, a)` with `s(t_0, t) = S_k + ∫_{t_k}^t |P'|` on the piece
//! `[t_k, t_{k+1}]` holding `t`: a binary search and one short quadrature per end, `O(log n)`.
//! The inverse finds the piece holding the target length by binary search in `S` and solves
//! on it as [`inverse_arc_length`](super::inverse_arc_length) does.
//!
//! Accuracy: the piece lengths are measured to a quarter of the stated accuracy in all, each
//! partial piece to a quarter, so a length (a difference of two cumulative lengths) is within
//! the stated accuracy.

use super::arc_length::{piece_length, solve_on_piece, split_points};
use crate::core::parallel::for_each_chunk;
use crate::core::Curve;

/// The cumulative lengths of a curve at its breakpoints, for fast repeated arc lengths.
///
/// ```
/// use karkas::geometry::{arc_length, ArcLengthTable};
/// use karkas::{param::CubicSpline, spline::SplineEnds, Point};
/// let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 0.0]), Point([3.0, 1.0])];
/// let c = CubicSpline::new(&[0.0, 1.0, 2.0, 3.0], &pts, SplineEnds::NotAKnot).unwrap();
/// let table = ArcLengthTable::new(&c, 1e-12);
/// let direct = arc_length(&c, 0.5, 2.5, 1e-12);
/// assert!((table.arc_length(&c, 0.5, 2.5) - direct).abs() < 2e-12);
/// ```
#[derive(Clone, Debug)]
pub struct ArcLengthTable {
    /// Breakpoints `t_0 < .. < t_n` (the domain's ends first and last).
    breaks: Vec<f64>,
    /// `S_k`, the length from `t_0` to `t_k` (`S_0 = 0`, `S_n` the whole length).
    cumulative: Vec<f64>,
    /// The accuracy of the partial pieces.
    partial_accuracy: f64,
    closed: bool,
}

impl ArcLengthTable {
    /// Measures every piece of `curve` (its breakpoints, or 16 parts per unit of domain when
    /// it has none) to within `accuracy` in all (absolute, in length units; non-positive asks
    /// for the best the quadrature gives).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineCurve;
    /// use karkas::geometry::ArcLengthTable;
    /// use karkas::Point;
    ///
    /// // The polyline (0, 0) - (3, 0) - (3, 4) is 7 long.
    /// let control = vec![Point([0.0, 0.0]), Point([3.0, 0.0]), Point([3.0, 4.0])];
    /// let polyline = BSplineCurve::new(1, vec![0.0, 0.0, 1.0, 2.0, 2.0], control)?;
    /// let table = ArcLengthTable::new(&polyline, 1e-12);
    /// assert!((table.total() - 7.0).abs() < 1e-9);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new<C: Curve<D> + ?Sized, const D: usize>(curve: &C, accuracy: f64) -> Self {
        let domain = curve.domain();
        let closed = curve.is_closed() && domain.length() > 0.0;
        let breaks = split_points(curve, domain.start, domain.end);
        let accuracy = accuracy.max(0.0);
        let total = domain.length();
        let mut cumulative = Vec::with_capacity(breaks.len());
        cumulative.push(0.0);
        let mut sum = 0.0;
        for w in breaks.windows(2) {
            let share = if total > 0.0 {
                0.25 * accuracy * (w[1] - w[0]) / total
            } else {
                0.0
            };
            sum += piece_length(curve, w[0], w[1], share);
            cumulative.push(sum);
        }
        ArcLengthTable {
            breaks,
            cumulative,
            partial_accuracy: 0.25 * accuracy,
            closed,
        }
    }

    /// The whole length of the curve (over its domain).
    pub fn total(&self) -> f64 {
        self.cumulative.last().copied().unwrap_or(0.0)
    }

    /// The length of `curve` (the curve the table was made of) from `t0` to `t1`, negative
    /// when `t1 < t0`, with the conventions of [`arc_length`](fn@super::arc_length): clamped to the domain of an open
    /// curve, wrapping (a whole turn per period) on a closed one; NaN for NaN parameters.
    pub fn arc_length<C: Curve<D> + ?Sized, const D: usize>(
        &self,
        curve: &C,
        t0: f64,
        t1: f64,
    ) -> f64 {
        if t0.is_nan() || t1.is_nan() {
            return f64::NAN;
        }
        self.length_to(curve, t1) - self.length_to(curve, t0)
    }

    /// The parameter reached after walking `length` from `t0`, with the conventions of
    /// [`inverse_arc_length`](super::inverse_arc_length) (stops at an open curve's ends, goes
    /// round a closed one and wraps into the domain). Accurate to about the table's accuracy.
    pub fn inverse<C: Curve<D> + ?Sized, const D: usize>(
        &self,
        curve: &C,
        t0: f64,
        length: f64,
    ) -> f64 {
        if t0.is_nan() || length.is_nan() {
            return f64::NAN;
        }
        let (start, end) = (self.breaks[0], self.breaks[self.breaks.len() - 1]);
        let total = self.total();
        if self.closed {
            let period = end - start;
            let turns = ((t0 - start) / period).floor();
            let base = self.within_period(curve, t0 - turns * period);
            let mut target = base + length;
            if total > 0.0 {
                target = target.rem_euclid(total);
            }
            let t = self.parameter_at(curve, target);
            return if t >= end { start } else { t };
        }
        let base = self.length_to(curve, t0);
        let target = base + length;
        if target >= total {
            return end;
        }
        if target <= 0.0 {
            return start;
        }
        self.parameter_at(curve, target)
    }

    /// The lengths from `t0` to every `t1s[i]`, into `out[i]` (in parallel for large
    /// batches; the results do not depend on the number of threads).
    ///
    /// # Panics
    /// When `t1s.len() != out.len()`.
    pub fn arc_lengths_into<C: Curve<D> + Sync + ?Sized, const D: usize>(
        &self,
        curve: &C,
        t0: f64,
        t1s: &[f64],
        out: &mut [f64],
    ) {
        crate::core::assert_buffer_len(t1s.len(), out.len());
        let base = self.length_to(curve, t0);
        for_each_chunk(t1s, out, |ts, o| {
            for (o, &t1) in o.iter_mut().zip(ts) {
                *o = if t0.is_nan() || t1.is_nan() {
                    f64::NAN
                } else {
                    self.length_to(curve, t1) - base
                };
            }
        });
    }

    /// The parameters reached after walking every `lengths[i]` from `t0`, into `out[i]`
    /// ([`inverse`](Self::inverse) of each, in parallel for large batches).
    ///
    /// # Panics
    /// When `lengths.len() != out.len()`.
    pub fn inverses_into<C: Curve<D> + Sync + ?Sized, const D: usize>(
        &self,
        curve: &C,
        t0: f64,
        lengths: &[f64],
        out: &mut [f64],
    ) {
        crate::core::assert_buffer_len(lengths.len(), out.len());
        for_each_chunk(lengths, out, |ls, o| {
            for (o, &s) in o.iter_mut().zip(ls) {
                *o = self.inverse(curve, t0, s);
            }
        });
    }

    /// `s(t_0, t)`: clamped to the domain of an open curve; on a closed one whole periods add
    /// the whole length each.
    fn length_to<C: Curve<D> + ?Sized, const D: usize>(&self, curve: &C, t: f64) -> f64 {
        let (start, end) = (self.breaks[0], self.breaks[self.breaks.len() - 1]);
        if !self.closed {
            return self.within_period(curve, t.clamp(start, end));
        }
        let period = end - start;
        let turns = ((t - start) / period).floor();
        turns * self.total() + self.within_period(curve, t - turns * period)
    }

    /// `s(t_0, t)` for `t` in the domain.
    fn within_period<C: Curve<D> + ?Sized, const D: usize>(&self, curve: &C, t: f64) -> f64 {
        let last = self.breaks.len() - 1;
        if t >= self.breaks[last] {
            return self.cumulative[last];
        }
        let k = self.breaks.partition_point(|&b| b <= t).saturating_sub(1);
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        if t <= a {
            return self.cumulative[k];
        }
        let share = self.partial_accuracy * ((t - a) / (b - a)).min(1.0);
        self.cumulative[k] + piece_length(curve, a, t, share)
    }

    /// The parameter at length `target` in `[0, total]` from the domain start.
    fn parameter_at<C: Curve<D> + ?Sized, const D: usize>(&self, curve: &C, target: f64) -> f64 {
        let last = self.breaks.len() - 1;
        let k = self
            .cumulative
            .partition_point(|&s| s <= target)
            .saturating_sub(1)
            .min(last - 1);
        let (a, b) = (self.breaks[k], self.breaks[k + 1]);
        let piece = self.cumulative[k + 1] - self.cumulative[k];
        let remaining = (target - self.cumulative[k]).clamp(0.0, piece);
        solve_on_piece(curve, a, b, piece, remaining, self.partial_accuracy)
    }
}

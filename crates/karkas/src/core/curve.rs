//! The curve traits.

use super::{uniform_into, Interval, Point, PolynomialPieces};

/// Which side of a breakpoint a one-sided derivative is taken from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The piece that ends at the breakpoint (limit from below).
    Below,
    /// The piece that starts at the breakpoint (limit from above).
    Above,
}

/// A parametric curve `t -> P(t)` in R^D over a closed parameter interval.
///
/// Evaluation outside [`domain`](Curve::domain) is defined by each implementation and
/// documented there (closed curves wrap by their period).
pub trait Curve<const D: usize> {
    /// The parameter interval the curve is meant to be used on.
    fn domain(&self) -> Interval;

    /// True when the curve is closed and periodic with period `domain().length()`.
    fn is_closed(&self) -> bool;

    /// The period of a closed curve, `None` for an open one.
    fn period(&self) -> Option<f64> {
        self.is_closed().then(|| self.domain().length())
    }

    /// The point at parameter `t`.
    fn eval(&self, t: f64) -> Point<D>;

    /// The `k`-th derivative `d^k P / dt^k` at `t` (`k = 0` is the point itself).
    /// At a breakpoint of a piecewise curve whose `k`-th derivative jumps, the value from
    /// [`Side::Above`] is returned (from below at the upper end of the domain).
    fn deriv(&self, t: f64, k: usize) -> Point<D>;

    /// The point and its first two derivatives at `t`, `[P(t), P'(t), P''(t)]`, as
    /// [`deriv`](Curve::deriv) gives them. Curves that locate their piece before evaluating
    /// override it to locate once (Newton's method on a distance needs all three per step).
    fn eval_with_derivatives(&self, t: f64) -> [Point<D>; 3] {
        [self.eval(t), self.deriv(t, 1), self.deriv(t, 2)]
    }

    /// The curve's polynomial pieces (degree, breakpoints, continuity) when it is a piecewise
    /// polynomial of its parameter; `None` (the default) when it is not or is not known to
    /// be. Used for exact B-spline export of surfaces built from curves
    /// ([`bspline`](crate::bspline)).
    fn polynomial_pieces(&self) -> Option<PolynomialPieces> {
        None
    }

    /// Evaluates at every parameter of `ts` into `out`.
    ///
    /// # Panics
    /// When `ts.len() != out.len()`.
    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        super::assert_buffer_len(ts.len(), out.len());
        for (p, &t) in out.iter_mut().zip(ts) {
            *p = self.eval(t);
        }
    }

    /// The `k`-th derivative at every parameter of `ts`, into `out`.
    ///
    /// # Panics
    /// When `ts.len() != out.len()`.
    fn deriv_into(&self, ts: &[f64], k: usize, out: &mut [Point<D>]) {
        super::assert_buffer_len(ts.len(), out.len());
        for (p, &t) in out.iter_mut().zip(ts) {
            *p = self.deriv(t, k);
        }
    }

    /// Samples `out.len()` points uniformly in the parameter over the domain, ends included,
    /// writing the parameters into `ts` and the points into `out`.
    ///
    /// # Panics
    /// When `ts.len() != out.len()`.
    fn sample_into(&self, ts: &mut [f64], out: &mut [Point<D>]) {
        uniform_into(self.domain(), ts);
        self.eval_into(ts, out);
    }
}

/// A curve made of pieces joined at breakpoints: polynomial pieces, or the rational pieces
/// of a [`NurbsCurve`](crate::bspline::NurbsCurve).
pub trait PiecewiseCurve<const D: usize>: Curve<D> {
    /// The breakpoints inside the domain and the two domain ends, ascending.
    fn breakpoints(&self) -> Vec<f64>;

    /// The order `k` of continuity at the breakpoints: derivatives `0..=k` are continuous.
    fn continuity(&self) -> usize;

    /// The `k`-th derivative at `t` taken on the piece on `side` of `t` (the polynomial of
    /// that piece, extended to `t`). Away from breakpoints both sides agree.
    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D>;
}

//! B-spline curves: degree, clamped knot vector, control points, de Boor evaluation.

use crate::core::knots::check_order;
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
use crate::{Error, Point, Result};

/// The largest degree of a [`BSplineCurve`] or [`BSplineSurface`](super::BSplineSurface):
/// `2 L` for the largest LL order `L = 64`.
pub const MAX_DEGREE: usize = 128;

/// A non-rational B-spline curve of degree `p` with a clamped knot vector.
///
/// The knot vector has `n + p + 1` entries for `n` control points; its first `p + 1` and
/// last `p + 1` entries are equal (clamped), so the curve starts at the first control point
/// and ends at the last. The domain is `[knots[p], knots[n]]`. Evaluation outside the domain
/// clamps the parameter. A closed karkas curve is exported over one period as such a clamped
/// open curve whose ends coincide ([`is_closed`](Curve::is_closed) reports it).
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineCurve<const D: usize> {
    degree: usize,
    knots: Vec<f64>,
    control: Vec<Point<D>>,
    closed: bool,
}

/// Checks what every B-spline's knot vector of degree `degree` for `count` control points
/// must be: the degree in `1..=MAX_DEGREE`, at least `degree + 1` control points, `count +
/// degree + 1` knots, finite and nondecreasing (knots repeat in a B-spline's knot vector).
pub(super) fn check_sizes(degree: usize, knots: &[f64], count: usize) -> Result<()> {
    if degree == 0 || degree > MAX_DEGREE {
        return Err(Error::InvalidOrder {
            order: degree,
            reason: "a B-spline degree must be in 1..=128",
        });
    }
    if count < degree + 1 {
        return Err(Error::TooFewPoints {
            what: "a B-spline (control points)",
            needed: degree + 1,
            got: count,
        });
    }
    if knots.len() != count + degree + 1 {
        return Err(Error::CountMismatch {
            what: "knots of a B-spline (control points + degree + 1)",
            expected: count + degree + 1,
            got: knots.len(),
        });
    }
    check_order(knots, false)
}

/// Checks a clamped knot vector of degree `degree` for `count` control points.
pub(crate) fn check_knots(degree: usize, knots: &[f64], count: usize) -> Result<()> {
    let invalid = |index: usize, reason: &'static str| Error::InvalidKnot {
        index,
        value: knots.get(index).copied().unwrap_or(f64::NAN),
        reason,
    };
    check_sizes(degree, knots, count)?;
    let (first, last) = (knots[0], knots[knots.len() - 1]);
    if knots[..=degree].iter().any(|&k| k != first) {
        return Err(invalid(
            degree,
            "the first degree + 1 knots must be equal (clamped)",
        ));
    }
    if knots[count..].iter().any(|&k| k != last) {
        return Err(invalid(
            count,
            "the last degree + 1 knots must be equal (clamped)",
        ));
    }
    if last <= first {
        return Err(invalid(
            knots.len() - 1,
            "the knot vector spans an empty domain",
        ));
    }
    if let Some(k) = (degree + 1..count).find(|&k| knots[k + degree] == knots[k]) {
        return Err(invalid(k, "an inner knot repeats more than degree times"));
    }
    Ok(())
}

/// The knot span `s` (`knots[s] <= t < knots[s + 1]`, `degree <= s < count`) holding `t`,
/// which must lie in the domain; the domain end belongs to the last nonempty span.
pub(crate) fn find_span(degree: usize, knots: &[f64], count: usize, t: f64) -> usize {
    if t >= knots[count] {
        let mut s = count - 1;
        while s > degree && knots[s] == knots[s + 1] {
            s -= 1;
        }
        return s;
    }
    // First index in degree+1..=count with knots[index] > t, minus one.
    let upper = knots[degree + 1..=count].partition_point(|&k| k <= t) + degree + 1;
    (upper - 1).clamp(degree, count - 1)
}

/// The de Boor algorithm on the `degree + 1` control points of span `span`, written into
/// `work` (which must hold `degree + 1` points): the point at `t`.
pub(crate) fn de_boor<const D: usize>(
    degree: usize,
    knots: &[f64],
    control: impl Fn(usize) -> Point<D>,
    span: usize,
    t: f64,
    work: &mut [Point<D>],
) -> Point<D> {
    for (j, w) in work.iter_mut().enumerate().take(degree + 1) {
        *w = control(span - degree + j);
    }
    for r in 1..=degree {
        for j in (r..=degree).rev() {
            let i = span - degree + j;
            let denominator = knots[i + degree + 1 - r] - knots[i];
            let alpha = if denominator > 0.0 {
                (t - knots[i]) / denominator
            } else {
                0.0
            };
            work[j] = work[j - 1] * (1.0 - alpha) + work[j] * alpha;
        }
    }
    work[degree]
}

impl<const D: usize> BSplineCurve<D> {
    /// The B-spline of degree `degree` over the clamped knot vector `knots` with control
    /// points `control` (`knots.len() == control.len() + degree + 1`).
    ///
    /// Errors: degree 0, fewer than `degree + 1` control points, a knot count that does not
    /// match, knots that are not finite, decrease, are not clamped, span an empty domain or
    /// repeat more than `degree` times inside; a non-finite control point.
    ///
    /// ```
    /// use karkas::bspline::BSplineCurve;
    /// use karkas::{Curve, Point};
    ///
    /// // The quadratic Bezier arc from (0, 0) to (2, 0) with its middle control point at (1, 2).
    /// let control = vec![Point([0.0, 0.0]), Point([1.0, 2.0]), Point([2.0, 0.0])];
    /// let curve = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], control)?;
    /// assert!(curve.eval(0.5).distance(Point([1.0, 1.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(degree: usize, knots: Vec<f64>, control: Vec<Point<D>>) -> Result<Self> {
        check_knots(degree, &knots, control.len())?;
        if let Some(index) = control.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        Ok(BSplineCurve {
            degree,
            knots,
            control,
            closed: false,
        })
    }

    /// One period of a closed curve as a clamped B-spline whose first and last control points
    /// coincide (to `1e-12` of the largest coordinate); [`is_closed`](Curve::is_closed)
    /// reports it.
    ///
    /// Errors: those of [`new`](Self::new), and ends that do not coincide.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineCurve;
    /// use karkas::{Curve, Point};
    ///
    /// // A unit square as a closed polyline (degree 1): the last control point repeats the first.
    /// let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]].map(Point);
    /// let knots = vec![0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0];
    /// let closed = BSplineCurve::new_closed(1, knots.clone(), square.to_vec())?;
    /// assert!(closed.is_closed());
    /// assert!(BSplineCurve::new_closed(1, knots, square[..4].iter().chain(&square[1..2]).copied().collect()).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new_closed(degree: usize, knots: Vec<f64>, control: Vec<Point<D>>) -> Result<Self> {
        let curve = Self::new(degree, knots, control)?;
        let (first, last) = (curve.control[0], curve.control[curve.control.len() - 1]);
        let scale = curve
            .control
            .iter()
            .fold(0.0_f64, |a, p| a.max(p.max_abs()));
        if (first - last).max_abs() > 1e-12 * scale {
            return Err(Error::InvalidSetting {
                name: "closed B-spline end gap",
                value: (first - last).max_abs(),
                reason: "the first and last control points of a closed curve must coincide",
            });
        }
        Ok(curve.with_closed(true))
    }

    /// The closed curve made of this curve and the straight segment from its end back to its
    /// start (a blunt trailing edge closed by the edge): one clamped B-spline of the same
    /// degree, closed ([`is_closed`](Curve::is_closed)), whose knot at the end of this curve
    /// gets multiplicity `p` (a `C^0` corner there; the start is the other corner). The
    /// segment's `p + 1` control points are evenly spaced on it, so its parameter runs
    /// linearly, over a share of the domain equal to its length over the control polygon's.
    ///
    /// Errors: ends that already coincide (within `1e-12` of the largest coordinate:
    /// nothing to close, [`Error::InvalidSetting`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineCurve;
    /// use karkas::{Curve, Point};
    /// // A quadratic arch from (0, 0) to (2, 0), closed by the segment along the x axis.
    /// let arch = BSplineCurve::new(
    ///     2,
    ///     vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
    ///     vec![Point([0.0, 0.0]), Point([1.0, 2.0]), Point([2.0, 0.0])],
    /// )?;
    /// let closed = arch.closed_by_segment()?;
    /// assert!(closed.is_closed());
    /// let end = closed.domain().end;
    /// assert_eq!(closed.eval(end), Point([0.0, 0.0]));
    /// assert_eq!(closed.eval(1.0), Point([2.0, 0.0]));
    /// // Halfway along the segment (parameter linear on it).
    /// let middle = closed.eval(0.5 * (1.0 + end));
    /// assert!((middle - Point([1.0, 0.0])).max_abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn closed_by_segment(&self) -> Result<Self> {
        let p = self.degree;
        let n = self.control.len();
        let (first, last) = (self.control[0], self.control[n - 1]);
        let scale = self.control.iter().fold(0.0_f64, |a, q| a.max(q.max_abs()));
        let gap = first.distance(last);
        if gap <= 1e-12 * scale {
            return Err(Error::InvalidSetting {
                name: "closing segment",
                value: gap,
                reason: "the ends of the curve already coincide: there is no segment to close",
            });
        }
        let polygon: f64 = self.control.windows(2).map(|w| w[0].distance(w[1])).sum();
        let (start, end) = (self.knots[p], self.knots[n]);
        let closing = end + (end - start) * gap / polygon.max(gap);
        let mut knots = self.knots[..n + p].to_vec();
        knots.extend(std::iter::repeat_n(closing, p + 1));
        let mut control = self.control.clone();
        control.extend((1..p).map(|k| last.lerp(first, k as f64 / p as f64)));
        control.push(first);
        Self::new_closed(p, knots, control)
    }

    /// Marks the curve as one period of a closed curve (its ends coincide).
    pub(crate) fn with_closed(mut self, closed: bool) -> Self {
        self.closed = closed;
        self
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The clamped knot vector (`n + p + 1` values).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The control points.
    pub fn control_points(&self) -> &[Point<D>] {
        &self.control
    }

    /// The distinct knots with their multiplicities, ascending (the ends have `p + 1`).
    pub fn distinct_knots(&self) -> Vec<(f64, usize)> {
        distinct_knots(&self.knots)
    }

    /// A curve from parts known to be valid (checked by the callers' construction).
    pub(crate) fn from_parts(degree: usize, knots: Vec<f64>, control: Vec<Point<D>>) -> Self {
        BSplineCurve {
            degree,
            knots,
            control,
            closed: false,
        }
    }
}

/// The distinct values of a sorted knot vector with their multiplicities.
pub(crate) fn distinct_knots(knots: &[f64]) -> Vec<(f64, usize)> {
    let mut out: Vec<(f64, usize)> = Vec::new();
    for &k in knots {
        match out.last_mut() {
            Some((v, m)) if *v == k => *m += 1,
            _ => out.push((k, 1)),
        }
    }
    out
}

/// Evaluates the `k`-th derivative of the B-spline `(degree, knots, control)` at `t` (on the
/// span holding `t`, [`span_deriv`]).
fn deriv_of<const D: usize>(
    degree: usize,
    knots: &[f64],
    control: &[Point<D>],
    t: f64,
    k: usize,
) -> Point<D> {
    let n = control.len();
    let t = t.clamp(knots[degree], knots[n]);
    let span = find_span(degree, knots, n, t);
    if k == 0 {
        let mut work = [Point::ZERO; MAX_DEGREE + 1];
        return de_boor(degree, knots, |i| control[i], span, t, &mut work);
    }
    span_deriv(degree, knots, control, span, t, k)
}

impl<const D: usize> Curve<D> for BSplineCurve<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.knots[self.degree], self.knots[self.control.len()])
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn eval(&self, t: f64) -> Point<D> {
        deriv_of(self.degree, &self.knots, &self.control, t, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        deriv_of(self.degree, &self.knots, &self.control, t, k)
    }

    fn polynomial_pieces(&self) -> Option<super::PolynomialPieces> {
        let distinct = self.distinct_knots();
        let n = distinct.len();
        Some(super::PolynomialPieces {
            degree: self.degree,
            breaks: distinct.iter().map(|d| d.0).collect(),
            continuity: distinct[1..n - 1]
                .iter()
                .map(|d| self.degree.saturating_sub(d.1))
                .collect(),
        })
    }
}

/// The `k`-th derivative at `t` of the polynomial of span `span` (`knots[span] <= t <=
/// knots[span + 1]` or its continuation): the span's `p + 1` controls differenced `k` times,
/// then de Boor's algorithm of degree `p - k` on them (no allocation).
fn span_deriv<const D: usize>(
    degree: usize,
    knots: &[f64],
    control: &[Point<D>],
    span: usize,
    t: f64,
    k: usize,
) -> Point<D> {
    if k > degree {
        return Point::ZERO;
    }
    let mut work = [Point::ZERO; MAX_DEGREE + 1];
    for (j, w) in work.iter_mut().enumerate().take(degree + 1) {
        *w = control[span - degree + j];
    }
    // Difference k times: after step r, work[j] (j >= r) is the control of degree p - r for
    // basis index span - degree + j.
    for r in 1..=k {
        let p = degree + 1 - r;
        for j in (r..=degree).rev() {
            let i = span - degree + j;
            let denominator = knots[i + p] - knots[i];
            work[j] = if denominator > 0.0 {
                (work[j] - work[j - 1]) * (p as f64 / denominator)
            } else {
                Point::ZERO
            };
        }
    }
    let q = degree - k;
    // De Boor of degree q on work[k..=degree] (basis indices span - q ..= span).
    for r in 1..=q {
        for j in (k + r..=degree).rev() {
            let i = span - degree + j;
            let denominator = knots[i + q + 1 - r] - knots[i];
            let alpha = if denominator > 0.0 {
                (t - knots[i]) / denominator
            } else {
                0.0
            };
            work[j] = work[j - 1] * (1.0 - alpha) + work[j] * alpha;
        }
    }
    work[degree]
}

impl<const D: usize> PiecewiseCurve<D> for BSplineCurve<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.distinct_knots().iter().map(|d| d.0).collect()
    }

    fn continuity(&self) -> usize {
        let distinct = self.distinct_knots();
        let n = distinct.len();
        distinct[1..n - 1]
            .iter()
            .map(|d| self.degree.saturating_sub(d.1))
            .min()
            .unwrap_or(self.degree)
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        let n = self.control.len();
        let p = self.degree;
        let t = t.clamp(self.knots[p], self.knots[n]);
        let mut span = find_span(p, &self.knots, n, t);
        if side == Side::Below {
            // The span ending at t when t is a knot (and not the domain start).
            while span > p && self.knots[span] >= t {
                span -= 1;
            }
        }
        span_deriv(p, &self.knots, &self.control, span, t, k)
    }
}

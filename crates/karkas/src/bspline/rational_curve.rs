//! Rational B-spline (NURBS) curves: `C(t) = sum N_i(t) w_i P_i / sum N_i(t) w_i` over any
//! knot vector, clamped or not (Piegl and Tiller, *The NURBS Book*, (4.1)); derivatives of
//! every order by the quotient rule (A4.2), exact sub-curves by knot insertion (A5.1).

use super::rational::{check_general_knots, check_weights, rational_curve_derivatives};
use super::span_basis::{
    local_derivatives, span_of, Homogeneous, Linear, MAX_SPAN, SMALL_SPAN, TINY_SPAN,
};
use super::{BSplineCurve, ToBSplineCurve};
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
use crate::{Error, Point, Result};

/// A rational B-spline curve of degree `p`: control points `P_i`, positive weights `w_i` and
/// a nondecreasing knot vector of `n + p + 1` values (clamped or not; see
/// `check_general_knots` in `bspline/rational.rs`).
///
/// The domain is `[knots[p], knots[n]]`; outside it an open curve continues its end pieces
/// (rational functions, whose denominator may vanish far away) and a closed one wraps the
/// parameter by its period. Equal weights give the polynomial B-spline of the
/// same control points. Affine maps act on the control points alone.
///
/// ```
/// use karkas::bspline::NurbsCurve;
/// use karkas::{Curve, Point3};
/// // A quarter of the unit circle: weights 1, sqrt(2)/2, 1.
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let arc = NurbsCurve::new(
///     2,
///     vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
///     vec![Point3::new([1.0, 0.0, 0.0]), Point3::new([1.0, 1.0, 0.0]), Point3::new([0.0, 1.0, 0.0])],
///     vec![1.0, w, 1.0],
/// )
/// .unwrap();
/// for t in [0.1, 0.5, 0.9] {
///     assert!((arc.eval(t).norm() - 1.0).abs() < 1e-15);
/// }
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsCurve<const D: usize> {
    degree: usize,
    knots: Vec<f64>,
    control: Vec<Point<D>>,
    weights: Vec<f64>,
    /// `w_i P_i`, the homogeneous numerator's control points.
    weighted: Vec<Point<D>>,
    closed: bool,
}

impl<const D: usize> NurbsCurve<D> {
    /// The curve of degree `degree` over `knots` with control points `control` and weights
    /// `weights` (one per control point).
    ///
    /// Errors: a degree outside `1..=128`, fewer than `degree + 1` control points, counts that
    /// do not match ([`Error::CountMismatch`]), knots that are not finite, decrease, span an
    /// empty domain or repeat too often ([`Error::InvalidKnot`]), a non-finite control point
    /// ([`Error::NonFinitePoint`]), a weight that is not finite and positive
    /// ([`Error::InvalidWeight`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::NurbsCurve;
    /// use karkas::{Curve, Point};
    ///
    /// // The quarter circle as a rational quadratic: the middle weight is cos(45 degrees).
    /// let control = vec![Point([1.0, 0.0]), Point([1.0, 1.0]), Point([0.0, 1.0])];
    /// let weights = vec![1.0, std::f64::consts::FRAC_1_SQRT_2, 1.0];
    /// let arc = NurbsCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], control, weights)?;
    /// assert!((arc.eval(0.3).norm() - 1.0).abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        degree: usize,
        knots: Vec<f64>,
        control: Vec<Point<D>>,
        weights: Vec<f64>,
    ) -> Result<Self> {
        check_general_knots(degree, &knots, control.len())?;
        if weights.len() != control.len() {
            return Err(Error::CountMismatch {
                what: "weights of a rational B-spline (one per control point)",
                expected: control.len(),
                got: weights.len(),
            });
        }
        if let Some(index) = control.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        check_weights(&weights)?;
        let weighted = control.iter().zip(&weights).map(|(&p, &w)| p * w).collect();
        Ok(NurbsCurve {
            degree,
            knots,
            control,
            weights,
            weighted,
            closed: false,
        })
    }

    /// A curve from parts known to be valid (checked by the caller's construction).
    pub(crate) fn from_checked_parts(
        degree: usize,
        knots: Vec<f64>,
        control: Vec<Point<D>>,
        weights: Vec<f64>,
    ) -> Self {
        debug_assert!(check_general_knots(degree, &knots, control.len()).is_ok());
        let weighted = control.iter().zip(&weights).map(|(&p, &w)| p * w).collect();
        NurbsCurve {
            degree,
            knots,
            control,
            weights,
            weighted,
            closed: false,
        }
    }

    /// The polynomial B-spline `curve` with every weight 1 (exactly the same curve).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::{BSplineCurve, NurbsCurve};
    /// use karkas::{Curve, Point};
    ///
    /// let control = vec![Point([0.0, 0.0]), Point([1.0, 2.0]), Point([2.0, 0.0])];
    /// let curve = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], control)?;
    /// let nurbs = NurbsCurve::from_bspline(&curve);
    /// assert!(!nurbs.is_rational());
    /// assert!(nurbs.eval(0.25).distance(curve.eval(0.25)) < 1e-14);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn from_bspline(curve: &BSplineCurve<D>) -> Self {
        let n = curve.control_points().len();
        NurbsCurve {
            degree: curve.degree(),
            knots: curve.knots().to_vec(),
            control: curve.control_points().to_vec(),
            weights: vec![1.0; n],
            weighted: curve.control_points().to_vec(),
            closed: curve.is_closed(),
        }
    }

    /// The same curve marked closed (periodic with the domain's length: evaluation wraps) or
    /// open. Marking it closed is the caller's statement that its ends join.
    pub fn with_closed(mut self, closed: bool) -> Self {
        self.closed = closed;
        self
    }

    /// The degree `p`.
    pub fn degree(&self) -> usize {
        self.degree
    }

    /// The knot vector (`n + p + 1` values).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The control points `P_i`.
    pub fn control_points(&self) -> &[Point<D>] {
        &self.control
    }

    /// The weights `w_i`.
    pub fn weights(&self) -> &[f64] {
        &self.weights
    }

    /// True when the weights differ (the curve is not a polynomial B-spline).
    pub fn is_rational(&self) -> bool {
        self.weights.iter().any(|&w| w != self.weights[0])
    }

    /// True when the knot vector is clamped (its first and last `p + 1` knots equal), so that
    /// the curve starts at its first control point and ends at its last.
    pub fn is_clamped(&self) -> bool {
        let (p, k) = (self.degree, &self.knots);
        k[..=p].iter().all(|&x| x == k[0])
            && k[k.len() - p - 1..].iter().all(|&x| x == k[k.len() - 1])
    }

    /// The polynomial B-spline equal to this curve, when its weights are all equal and its
    /// knots clamped (`None` otherwise).
    pub fn to_bspline(&self) -> Option<BSplineCurve<D>> {
        if self.is_rational() || !self.is_clamped() {
            return None;
        }
        BSplineCurve::new(self.degree, self.knots.clone(), self.control.clone())
            .ok()
            .map(|c| c.with_closed(self.closed))
    }

    /// The curve with its control points mapped by `f`, which must be affine for the result to
    /// be the image of the curve (rotations, translations, scalings, placements).
    pub fn map_points<const E: usize>(&self, f: impl Fn(Point<D>) -> Point<E>) -> NurbsCurve<E> {
        let control: Vec<Point<E>> = self.control.iter().map(|&p| f(p)).collect();
        let weighted = control
            .iter()
            .zip(&self.weights)
            .map(|(&p, &w)| p * w)
            .collect();
        NurbsCurve {
            degree: self.degree,
            knots: self.knots.clone(),
            control,
            weights: self.weights.clone(),
            weighted,
            closed: self.closed,
        }
    }

    /// The same point set run the other way: `C'(t) = C(a + b - t)` on the same domain
    /// `[a, b]`.
    pub fn reversed(&self) -> Self {
        let d = self.domain();
        let knots = self
            .knots
            .iter()
            .rev()
            .map(|&k| d.start + d.end - k)
            .collect();
        let mut out = NurbsCurve {
            degree: self.degree,
            knots,
            control: self.control.iter().rev().copied().collect(),
            weights: self.weights.iter().rev().copied().collect(),
            weighted: self.weighted.iter().rev().copied().collect(),
            closed: self.closed,
        };
        // a + b - k may round differently from the original ends; the domain stays [a, b].
        let (p, n) = (out.degree, out.control.len());
        let ends = (out.knots[p], out.knots[n]);
        for k in out.knots.iter_mut() {
            if *k == ends.0 {
                *k = d.start;
            } else if *k == ends.1 {
                *k = d.end;
            }
        }
        out
    }

    /// The derivatives `C^(k)(t)`, `k = 0..out.len()`, into `out` (`out[0]` is the point).
    /// `t` is wrapped (closed) or clamped into the domain. Allocation-free up to order 15.
    pub fn derivatives_into(&self, t: f64, out: &mut [Point<D>]) {
        let t = self.parameter(t);
        let span = span_of(self.degree, &self.knots, self.control.len(), t);
        self.derivatives_on_span(t, span, out);
    }

    /// [`derivatives_into`](Self::derivatives_into) with the rational piece of knot span
    /// `span` (continued to `t`).
    fn derivatives_on_span(&self, t: f64, span: usize, out: &mut [Point<D>]) {
        if self.degree < TINY_SPAN {
            self.derivatives_on_span_in::<TINY_SPAN>(t, span, out);
        } else if self.degree < SMALL_SPAN {
            self.derivatives_on_span_in::<SMALL_SPAN>(t, span, out);
        } else {
            self.derivatives_on_span_in::<MAX_SPAN>(t, span, out);
        }
    }

    /// [`derivatives_on_span`](Self::derivatives_on_span) with working arrays of `N` values
    /// (more than the degree).
    fn derivatives_on_span_in<const N: usize>(&self, t: f64, span: usize, out: &mut [Point<D>]) {
        if out.is_empty() {
            return;
        }
        let p = self.degree;
        let top = (out.len() - 1).min(p);
        let first = span - p;
        let mut local = [Homogeneous::<D>::ZERO; N];
        for (c, h) in local[..=p].iter_mut().enumerate() {
            *h = Homogeneous {
                point: self.weighted[first + c],
                weight: self.weights[first + c],
            };
        }
        let mut homogeneous = [Homogeneous::<D>::ZERO; N];
        local_derivatives(p, &self.knots, span, t, &local, &mut homogeneous[..=top]);
        let mut w = [0.0; N];
        for (k, a) in out.iter_mut().enumerate() {
            if k > top {
                *a = Point::ZERO;
            } else {
                *a = homogeneous[k].point;
                w[k] = homogeneous[k].weight;
            }
        }
        rational_curve_derivatives(out, &w[..=top]);
    }

    /// `t` wrapped into the domain (closed), or as it is (open: the end pieces continue).
    fn parameter(&self, t: f64) -> f64 {
        if self.closed {
            self.domain().wrap(t)
        } else {
            t
        }
    }

    /// The exact sub-curve over `[a, b]` (inside the domain, `a < b`): knots inserted at both
    /// ends up to multiplicity `p` (A5.1 on the homogeneous control points), the rest cut.
    /// The result is clamped, open, and evaluates as this curve on `[a, b]`.
    ///
    /// Errors: `a` and `b` not finite, not increasing or outside the domain
    /// ([`Error::InvalidSetting`]).
    pub fn segment(&self, a: f64, b: f64) -> Result<Self> {
        let d = self.domain();
        let bad = |value, reason| Error::InvalidSetting {
            name: "a sub-curve's end",
            value,
            reason,
        };
        if !(a.is_finite() && b.is_finite() && a < b) {
            return Err(bad(
                if a.is_finite() { b } else { a },
                "the ends must be finite and increase",
            ));
        }
        if a < d.start || b > d.end {
            return Err(bad(
                if a < d.start { a } else { b },
                "outside the curve's domain",
            ));
        }
        let mut curve = self.clone();
        curve.closed = false;
        curve.clamp_at(a);
        curve.clamp_at(b);
        let p = curve.degree;
        // The first knot equal to a, the last equal to b.
        let first = curve.knots.partition_point(|&k| k < a);
        let last = curve.knots.partition_point(|&k| k <= b);
        let knots: Vec<f64> = curve.knots[first..last].to_vec();
        let count = knots.len() - p - 1;
        let control = curve.control[first..first + count].to_vec();
        let weights = curve.weights[first..first + count].to_vec();
        NurbsCurve::new(p, knots, control, weights)
    }

    /// Inserts `t` until its multiplicity is `p + 1` (at a domain end) or `p` (inside): the
    /// curve then passes through a control point at `t`.
    fn clamp_at(&mut self, t: f64) {
        let p = self.degree;
        let present = self.knots.iter().filter(|&&k| k == t).count();
        let wanted = p + 1;
        for _ in present..wanted {
            self.insert_knot(t);
        }
    }

    /// Inserts the knot `t` once (Boehm's algorithm, A5.1 with `r = 1`), on the homogeneous
    /// control points: the curve does not change.
    fn insert_knot(&mut self, t: f64) {
        let p = self.degree;
        let n = self.control.len();
        // The span with knots[k] <= t < knots[k + 1] among all knots (not just the domain).
        let k = (self.knots.partition_point(|&x| x <= t).max(1) - 1).min(n + p - 1);
        let mut weighted = Vec::with_capacity(n + 1);
        let mut weights = Vec::with_capacity(n + 1);
        for i in 0..=n {
            if i + p <= k {
                weighted.push(self.weighted[i]);
                weights.push(self.weights[i]);
            } else if i > k {
                weighted.push(self.weighted[i - 1]);
                weights.push(self.weights[i - 1]);
            } else {
                let gap = self.knots[i + p] - self.knots[i];
                let alpha = if gap > 0.0 {
                    (t - self.knots[i]) / gap
                } else {
                    0.0
                };
                if alpha <= 0.0 || i == n {
                    // t at or before knots[i] (at the domain's end, i may be n: no P_n).
                    weighted.push(self.weighted[i - 1]);
                    weights.push(self.weights[i - 1]);
                } else {
                    weighted.push(self.weighted[i - 1] * (1.0 - alpha) + self.weighted[i] * alpha);
                    weights.push(self.weights[i - 1] * (1.0 - alpha) + self.weights[i] * alpha);
                }
            }
        }
        self.knots.insert(k + 1, t);
        self.control = weighted
            .iter()
            .zip(&weights)
            .map(|(&a, &w)| a * (1.0 / w))
            .collect();
        self.weighted = weighted;
        self.weights = weights;
    }
}

impl<const D: usize> PiecewiseCurve<D> for NurbsCurve<D> {
    /// The distinct knots inside the domain and its ends.
    fn breakpoints(&self) -> Vec<f64> {
        let d = self.domain();
        let mut out = vec![d.start];
        for &k in &self.knots {
            if k > *out.last().unwrap_or(&d.start) && k < d.end {
                out.push(k);
            }
        }
        out.push(d.end);
        out
    }

    /// `p - m` for the largest multiplicity `m` of a knot inside the domain (`p - 1` when
    /// there is none: a single piece is smooth, and `p - 1` is what every inner knot of
    /// multiplicity 1 gives).
    fn continuity(&self) -> usize {
        let d = self.domain();
        let mut largest = 1;
        let mut run = 0;
        for (i, &k) in self.knots.iter().enumerate() {
            run = if i > 0 && self.knots[i - 1] == k {
                run + 1
            } else {
                1
            };
            if k > d.start && k < d.end {
                largest = largest.max(run);
            }
        }
        self.degree.saturating_sub(largest)
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        let t = self.parameter(t);
        let (p, n) = (self.degree, self.control.len());
        let mut span = span_of(p, &self.knots, n, t);
        if side == Side::Below && span > p && self.knots[span] == t {
            span -= 1;
            while span > p && self.knots[span] == self.knots[span + 1] {
                span -= 1;
            }
        }
        let mut out = vec![Point::ZERO; k + 1];
        self.derivatives_on_span(t, span, &mut out);
        out[k]
    }
}

impl<const D: usize> ToBSplineCurve<D> for NurbsCurve<D> {
    /// The polynomial B-spline when the weights are equal and the knots clamped
    /// ([`NurbsCurve::to_bspline`]); [`Error::NotExactlyConvertible`] otherwise.
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        NurbsCurve::to_bspline(self).ok_or_else(|| Error::NotExactlyConvertible {
            what: "a rational B-spline curve",
            reason: "its weights differ or its knots are not clamped (no polynomial form)".into(),
        })
    }
}

impl<const D: usize> Curve<D> for NurbsCurve<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.knots[self.degree], self.knots[self.control.len()])
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn eval(&self, t: f64) -> Point<D> {
        let mut out = [Point::ZERO; 1];
        self.derivatives_into(t, &mut out);
        out[0]
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        if k < 3 {
            return self.eval_with_derivatives(t)[k];
        }
        let mut out = vec![Point::ZERO; k + 1];
        self.derivatives_into(t, &mut out);
        out[k]
    }

    fn eval_with_derivatives(&self, t: f64) -> [Point<D>; 3] {
        let mut out = [Point::ZERO; 3];
        self.derivatives_into(t, &mut out);
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point3;

    /// A rational cubic over unclamped, uneven knots with strongly varying weights.
    fn curve() -> NurbsCurve<3> {
        let knots = vec![-0.4, -0.1, 0.0, 0.3, 0.35, 1.1, 1.6, 2.0, 2.2, 2.9];
        let control: Vec<Point3> = (0..6)
            .map(|i| {
                let x = i as f64;
                Point3::new([x, (1.3 * x).sin() * 2.0, 0.3 * x * x - 1.0])
            })
            .collect();
        let weights = vec![1.0, 3.5, 0.2, 1.7, 0.9, 2.4];
        NurbsCurve::new(3, knots, control, weights).unwrap()
    }

    /// The curve's point from its homogeneous form by de Boor's algorithm in four
    /// coordinates, an evaluation independent of the basis routine and the quotient rule.
    fn homogeneous_de_boor(c: &NurbsCurve<3>, t: f64) -> Point3 {
        let p = c.degree();
        let k = c.knots();
        let n = c.control_points().len();
        let s = (p..n)
            .rev()
            .find(|&s| k[s] <= t && k[s] < k[s + 1])
            .unwrap();
        let mut d: Vec<[f64; 4]> = (0..=p)
            .map(|j| {
                let i = s - p + j;
                let w = c.weights()[i];
                let q = c.control_points()[i];
                [q[0] * w, q[1] * w, q[2] * w, w]
            })
            .collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = s - p + j;
                let alpha = (t - k[i]) / (k[i + p + 1 - r] - k[i]);
                let previous = d[j - 1];
                for (x, y) in d[j].iter_mut().zip(previous) {
                    *x = (1.0 - alpha) * y + alpha * *x;
                }
            }
        }
        let h = d[p];
        Point3::new([h[0] / h[3], h[1] / h[3], h[2] / h[3]])
    }

    #[test]
    fn points_equal_de_boor_in_homogeneous_coordinates() {
        let c = curve();
        let d = c.domain();
        assert_eq!((d.start, d.end), (0.3, 1.6));
        for i in 0..=200 {
            let t = d.uniform(i, 201).min(1.599_999);
            let got = c.eval(t);
            let want = homogeneous_de_boor(&c, t);
            assert!(got.distance(want) < 1e-13, "t {t}: {got:?} {want:?}");
        }
    }

    #[test]
    fn derivatives_match_differences_to_the_fourth_order() {
        let c = curve();
        let h = 1e-5;
        for t in [0.32, 0.5, 0.9, 1.3, 1.55] {
            let mut here = [Point3::ZERO; 6];
            let mut ahead = [Point3::ZERO; 6];
            let mut behind = [Point3::ZERO; 6];
            c.derivatives_into(t, &mut here);
            c.derivatives_into(t + h, &mut ahead);
            c.derivatives_into(t - h, &mut behind);
            for k in 1..5 {
                let fd = (ahead[k - 1] - behind[k - 1]) * (0.5 / h);
                let scale = 1.0 + here[k].norm();
                assert!(
                    fd.distance(here[k]) < 1e-5 * scale * 10f64.powi(k as i32),
                    "t {t} k {k}: {fd:?} {:?}",
                    here[k]
                );
                assert_eq!(c.deriv(t, k), here[k]);
            }
        }
    }

    #[test]
    fn equal_weights_give_the_polynomial_bspline() {
        let knots = vec![0.0, 0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0, 1.0];
        let control: Vec<Point3> = (0..5)
            .map(|i| Point3::new([i as f64, (i * i) as f64 * 0.3, 1.0 / (1.0 + i as f64)]))
            .collect();
        let b = BSplineCurve::new(3, knots.clone(), control.clone()).unwrap();
        let scaled = NurbsCurve::new(3, knots, control, vec![2.5; 5]).unwrap();
        let unit = NurbsCurve::from_bspline(&b);
        assert!(!scaled.is_rational() && scaled.is_clamped());
        for i in 0..=50 {
            let t = i as f64 / 50.0;
            for k in 0..=4 {
                let want = b.deriv(t, k);
                for c in [&scaled, &unit] {
                    let got = c.deriv(t, k);
                    assert!(
                        got.distance(want) < 1e-11 * (1.0 + want.norm()),
                        "t {t} k {k}"
                    );
                }
            }
        }
        assert_eq!(unit.to_bspline().unwrap(), b);
    }

    #[test]
    fn derivatives_keep_their_digits_on_short_spans() {
        // Spans 1000 times shorter than others, coordinates far from the origin: the second
        // derivative as the polynomial B-spline's derivative control points give it.
        let mut breaks = vec![0.0, 0.3, 0.3005, 0.301, 0.3015, 0.6, 1.0];
        breaks.dedup();
        let mut knots = vec![0.0; 3];
        knots.extend(&breaks);
        knots.extend([1.0; 3]);
        let n = knots.len() - 4;
        let control: Vec<Point3> = (0..n)
            .map(|i| {
                Point3::new([
                    100.0 + (i as f64 * 0.9).sin(),
                    50.0 + 0.3 * i as f64,
                    (i as f64).sqrt(),
                ])
            })
            .collect();
        let b = BSplineCurve::new(3, knots.clone(), control.clone()).unwrap();
        let c = NurbsCurve::new(3, knots, control, vec![1.0; n]).unwrap();
        let scale = (0..=1000)
            .map(|k| b.deriv(k as f64 / 1000.0, 2).norm())
            .fold(0.0, f64::max);
        for k in 0..=1000 {
            let t = 0.2995 + 0.0025 * k as f64 / 1000.0;
            let (x, y) = (c.deriv(t, 2), b.deriv(t, 2));
            assert!(
                x.distance(y) < 1e-12 * scale,
                "t {t}: {x:?} {y:?} (scale {scale})"
            );
        }
    }

    #[test]
    fn segments_and_reversal_keep_the_points() {
        let c = curve();
        let s = c.segment(0.4, 1.5).unwrap();
        assert_eq!((s.domain().start, s.domain().end), (0.4, 1.5));
        assert!(s.is_clamped());
        for i in 0..=100 {
            let t = 0.4 + 1.1 * i as f64 / 100.0;
            assert!(s.eval(t).distance(c.eval(t)) < 1e-13, "t {t}");
            assert!(s.deriv(t, 1).distance(c.deriv(t, 1)) < 1e-10 * (1.0 + c.deriv(t, 1).norm()));
        }
        // The whole domain: the clamped form of the unclamped curve.
        let whole = c.segment(0.3, 1.6).unwrap();
        assert!(whole.control_points()[0].distance(c.eval(0.3)) < 1e-13);
        assert!(whole.control_points()[5].distance(c.eval(1.6)) < 1e-13);
        let r = c.reversed();
        for t in [0.3, 0.4, 1.1, 1.6] {
            assert!(r.eval(1.9 - t).distance(c.eval(t)) < 1e-13);
        }
        assert!(c.segment(0.5, 0.5).is_err());
        assert!(c.segment(0.0, 0.5).is_err());
        assert!(c.segment(f64::NAN, 0.5).is_err());
    }

    #[test]
    fn bad_parts_are_refused() {
        let p = vec![Point3::ZERO; 3];
        let k = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        assert!(matches!(
            NurbsCurve::new(2, k.clone(), p.clone(), vec![1.0; 2]),
            Err(Error::CountMismatch { .. })
        ));
        assert!(matches!(
            NurbsCurve::new(2, k.clone(), p.clone(), vec![1.0, -1.0, 1.0]),
            Err(Error::InvalidWeight { index: 1, .. })
        ));
        let mut bad = p.clone();
        bad[2][1] = f64::INFINITY;
        assert!(matches!(
            NurbsCurve::new(2, k, bad, vec![1.0; 3]),
            Err(Error::NonFinitePoint { index: 2 })
        ));
    }
}

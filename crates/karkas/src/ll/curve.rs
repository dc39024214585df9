//! LL curves (Aulchenko et al., formulas (3)–(6); docs/methods.md §1.2).
//!
//! An LL curve of order `L` through the support polygon `r_1..r_K` is, on segment `i`,
//! `P_i(xi) = c_-(xi) r_{i-1} + c_0(xi) r_i + c_+(xi) r_{i+1}`, with the kernel weights of
//! [`LlKernel`]. Guarantees: `C^L` at segment borders; inside each segment the curve lies in
//! the convex hull of the three points, is affine-invariant, bends only one way (each
//! coordinate's second derivative keeps the sign of `D_i = r_{i-1} - 2 r_i + r_{i+1}`) and is
//! monotone wherever the three points are; it deviates from node `r_i` by exactly
//! `d_L D_i`. An open curve passes through `r_1` and `r_K`.
//!
//! Evaluation is `O(1)` per point: each segment is stored as `P = A + xi B + h(xi) C` with
//! `A = (r_{i-1} + r_i)/2`, `B = r_i - r_{i-1}`, `C = D_i / 2`, and batches are evaluated with
//! the kernel specialised to the order (1..=12) at compile time.

use super::axis::NodeAxis;
use super::batch::segment_and_kernel;
use super::frame::{close, coincide, extend, model_scale, validate};
use super::kernel::{pow_n, LlKernel};
use super::prefilter::interpolation_controls;
use crate::core::lanes::{f64x4, load4, CmpGt, CmpLt, LANES};
use crate::core::parallel::for_each_chunk;
use crate::core::PolynomialPieces;
use crate::core::{with_shared_end, Curve, Interval, PiecewiseCurve, Side};
use crate::{Error, Point, Result};

/// One segment in power form: `P(xi) = a + xi b + h(xi) c`.
#[derive(Clone, Copy, Debug, PartialEq)]
struct Segment<const D: usize> {
    a: Point<D>,
    b: Point<D>,
    c: Point<D>,
}

/// An LL curve of order `L` in R^D, open or closed.
///
/// Parameter `t` follows the paper: node `i` at `t = i/(K+1)`, domain `[1/(K+1), K/(K+1)]`.
/// Outside the domain an open curve is clamped to its end points and a closed curve wraps.
#[derive(Clone, Debug, PartialEq)]
pub struct LlCurve<const D: usize> {
    kernel: LlKernel,
    axis: NodeAxis,
    /// `r_0..r_{K+1}`.
    extended: Vec<Point<D>>,
    /// Segment `i` (1-based) at index `i - 1`.
    segments: Vec<Segment<D>>,
}

impl<const D: usize> LlCurve<D> {
    /// The LL approximation of order `order` over the support polygon `points`.
    ///
    /// With `closed`, the polygon is closed: if the last point repeats the first it is the
    /// paper's `r_K = r_1`; otherwise the last point is joined to the first (K counts the
    /// repeated point either way). An open polygon whose first and last points coincide by
    /// the shared-end rule ([`crate::core::shared_end`]: within `1e-6` of the points' size,
    /// a sharp trailing edge) has both replaced by their midpoint, so the curve's ends meet
    /// there exactly.
    ///
    /// Errors: fewer than 3 points (3 distinct ones when closed), a non-finite coordinate,
    /// `order` outside `1..=64`.
    ///
    /// ```
    /// use karkas::{ll::LlCurve, Curve, Point};
    ///
    /// let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 0.0]), Point([3.0, 1.0])];
    /// let curve = LlCurve::new(&pts, 5, false)?; // order 5: C^5, open
    /// let d = curve.domain(); // [1/5, 4/5]: the first and last nodes
    /// assert!(curve.eval(d.start).distance(pts[0]) < 1e-12);
    /// assert!(curve.eval(d.end).distance(pts[3]) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(points: &[Point<D>], order: usize, closed: bool) -> Result<Self> {
        let kernel = LlKernel::new(order)?;
        let control = Self::support_polygon(points, closed)?;
        Ok(Self::from_control(kernel, control, closed))
    }

    /// The interpolating LL curve: passes through every point of `points` at its node
    /// `t_i = i/(K+1)`. The control polygon is found by the `O(K)` solve of system (6).
    /// Same closing rule and errors as [`new`](Self::new).
    ///
    /// ```
    /// use karkas::{ll::LlCurve, Curve, Point};
    ///
    /// let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 0.0]), Point([3.0, 1.0])];
    /// let curve = LlCurve::interpolating(&pts, 3, false)?;
    /// for (i, p) in pts.iter().enumerate() {
    ///     let node = (i + 1) as f64 / (pts.len() + 1) as f64; // t_i = i / (K + 1), from 1
    ///     assert!(curve.eval(node).distance(*p) < 1e-12);
    /// }
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn interpolating(points: &[Point<D>], order: usize, closed: bool) -> Result<Self> {
        let kernel = LlKernel::new(order)?;
        let mut control = Self::support_polygon(points, closed)?;
        interpolation_controls(&mut control, kernel.d_l(), closed)?;
        Ok(Self::from_control(kernel, control, closed))
    }

    /// Validates and, when `closed`, closes the input polygon.
    pub(super) fn support_polygon(points: &[Point<D>], closed: bool) -> Result<Vec<Point<D>>> {
        validate(points, "an LL curve")?;
        let mut control = if closed {
            points.to_vec()
        } else {
            with_shared_end(points).into_owned()
        };
        if closed {
            let scale = model_scale(points);
            let repeats = coincide(points[0], points[points.len() - 1], scale);
            close(&mut control, repeats);
            if control.len() < 4 {
                return Err(Error::TooFewPoints {
                    what: "a closed LL curve (distinct points)",
                    needed: 3,
                    got: control.len() - 1,
                });
            }
        }
        Ok(control)
    }

    /// Builds the curve from a ready control polygon (`r_K == r_1` when closed).
    pub(crate) fn from_control(kernel: LlKernel, control: Vec<Point<D>>, closed: bool) -> Self {
        let axis = NodeAxis::new(control.len(), closed);
        let extended = extend(&control, closed);
        let segments = extended
            .windows(3)
            .map(|w| Segment {
                a: (w[0] + w[1]) * 0.5,
                b: w[1] - w[0],
                c: (w[0] + w[2] - w[1] * 2.0) * 0.5,
            })
            .collect();
        LlCurve {
            kernel,
            axis,
            extended,
            segments,
        }
    }

    /// The order `L`.
    pub fn order(&self) -> usize {
        self.kernel.order()
    }

    /// The kernel `h` of this curve's order.
    pub fn kernel(&self) -> &LlKernel {
        &self.kernel
    }

    /// The node grid of the parameter.
    pub fn axis(&self) -> NodeAxis {
        self.axis
    }

    /// The control polygon `r_1..r_K` (for a closed curve the last repeats the first; for the
    /// interpolating variant these are the solved `r*`).
    pub fn control_points(&self) -> &[Point<D>] {
        &self.extended[1..self.extended.len() - 1]
    }

    /// The extended polygon `r_0..r_{K+1}` (end extensions included).
    pub(crate) fn extended_points(&self) -> &[Point<D>] {
        &self.extended
    }

    /// The `k`-th derivative on segment `i` (1-based) at local coordinate `xi`, per unit `t`.
    #[inline]
    fn deriv_on_segment(&self, i: usize, xi: f64, k: usize) -> Point<D> {
        if k == 0 {
            let s = &self.segments[i - 1];
            return s.a.add_scaled(xi, s.b).add_scaled(self.kernel.h(xi), s.c);
        }
        let w = self.kernel.weights(xi, k);
        let r = &self.extended[i - 1..=i + 1];
        let p = r[0] * w[0] + r[1] * w[1] + r[2] * w[2];
        p * pow_n(self.axis.scale(), k)
    }

    /// Batch evaluation with the kernel specialised to order `L`, four parameters per step:
    /// the parameters are brought into the domain and turned into segment, `xi` and `h(xi)`
    /// in `f64x4` ([`segment_and_kernel`]); four that share a segment combine its
    /// coefficients in `f64x4` too, others point by point (the same operations either way).
    fn eval_batch<const L: usize>(&self, ts: &[f64], out: &mut [Point<D>]) {
        let coeffs: [f64; L] = core::array::from_fn(|k| self.kernel.value_coeffs()[k]);
        let axis = self.axis;
        let nodes = axis.nodes();
        let d = axis.domain();
        let (start, end) = (f64x4::splat(d.start), f64x4::splat(d.end));
        let (scale, half) = (f64x4::splat(axis.scale()), f64x4::splat(0.5));
        // `as usize` saturates and maps NaN to 0; the clamp keeps the index valid.
        let point = |i: f64, xi: f64, h: f64| {
            let s = &self.segments[(i as usize).clamp(1, nodes) - 1];
            s.a.add_scaled(xi, s.b).add_scaled(h, s.c)
        };
        let mut t4 = ts.chunks_exact(LANES);
        let mut o4 = out.chunks_exact_mut(LANES);
        // The segment of the last four parameters that shared one, with its coefficients.
        let mut shared_segment = f64::NAN;
        let mut shared = [[f64x4::splat(0.0); 3]; D];
        for (tc, oc) in (&mut t4).zip(&mut o4) {
            let t = load4(tc);
            let t = if axis.is_closed() {
                f64x4::new(t.to_array().map(|t| axis.reduce(t)))
            } else {
                // The clamp of `Interval::clamp`: NaN stays NaN.
                let t = t.cmp_lt(start).blend(start, t);
                t.cmp_gt(end).blend(end, t)
            };
            let [i, xi4, h4] = segment_and_kernel::<f64x4, L>(t * scale + half, &coeffs);
            let i = i.to_array();
            if i.iter().all(|&j| j == i[0]) {
                // One segment for the four (sorted parameters, nearly always): its
                // coefficients broadcast once per segment, the combination in `f64x4`.
                if shared_segment != i[0] {
                    let s = &self.segments[(i[0] as usize).clamp(1, nodes) - 1];
                    shared =
                        std::array::from_fn(|c| [s.a.0[c], s.b.0[c], s.c.0[c]].map(f64x4::splat));
                    shared_segment = i[0];
                }
                for (c, [a, b, cc]) in shared.iter().enumerate() {
                    let x = (*a + xi4 * *b + h4 * *cc).to_array();
                    for (p, x) in oc.iter_mut().zip(x) {
                        p.0[c] = x;
                    }
                }
            } else {
                let (xi, h) = (xi4.to_array(), h4.to_array());
                for (l, p) in oc.iter_mut().enumerate() {
                    *p = point(i[l], xi[l], h[l]);
                }
            }
        }
        for (p, &t) in o4.into_remainder().iter_mut().zip(t4.remainder()) {
            let s = axis.reduce(t) * axis.scale() + 0.5;
            let [i, xi, h] = segment_and_kernel::<f64, L>(s, &coeffs);
            *p = point(i, xi, h);
        }
    }
}

impl<const D: usize> Curve<D> for LlCurve<D> {
    fn domain(&self) -> Interval {
        self.axis.domain()
    }

    fn is_closed(&self) -> bool {
        self.axis.is_closed()
    }

    fn eval(&self, t: f64) -> Point<D> {
        let (i, xi) = self.axis.locate(t);
        self.deriv_on_segment(i, xi, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        let (i, xi) = self.axis.locate(t);
        self.deriv_on_segment(i, xi, k)
    }

    fn polynomial_pieces(&self) -> Option<PolynomialPieces> {
        Some(PolynomialPieces::uniform_continuity(
            2 * self.order(),
            self.axis.breakpoints(),
            self.order(),
        ))
    }

    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_buffer_len(ts.len(), out.len());
        // Large batches run in parallel chunks.
        for_each_chunk(ts, out, |ts, out| match self.kernel.order() {
            1 => self.eval_batch::<1>(ts, out),
            2 => self.eval_batch::<2>(ts, out),
            3 => self.eval_batch::<3>(ts, out),
            4 => self.eval_batch::<4>(ts, out),
            5 => self.eval_batch::<5>(ts, out),
            6 => self.eval_batch::<6>(ts, out),
            7 => self.eval_batch::<7>(ts, out),
            8 => self.eval_batch::<8>(ts, out),
            9 => self.eval_batch::<9>(ts, out),
            10 => self.eval_batch::<10>(ts, out),
            11 => self.eval_batch::<11>(ts, out),
            12 => self.eval_batch::<12>(ts, out),
            _ => {
                for (p, &t) in out.iter_mut().zip(ts) {
                    *p = self.eval(t);
                }
            }
        });
    }
}

impl<const D: usize> PiecewiseCurve<D> for LlCurve<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.axis.breakpoints()
    }

    fn continuity(&self) -> usize {
        self.kernel.order()
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        let (i, xi) = self.axis.locate_on_side(t, side);
        self.deriv_on_segment(i, xi, k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn batch_and_single_evaluation_agree_for_every_order() {
        let pts: Vec<Point<3>> = (0..9)
            .map(|i| {
                let f = i as f64;
                Point([f.cos() * 3.0, f * f * 0.1, (2.0 * f).sin()])
            })
            .collect();
        for order in 1..=14 {
            for closed in [false, true] {
                let c = LlCurve::new(&pts, order, closed).unwrap();
                let ts: Vec<f64> = (0..=200).map(|k| -0.1 + 1.2 * k as f64 / 200.0).collect();
                let mut out = vec![Point::ZERO; ts.len()];
                c.eval_into(&ts, &mut out);
                for (&t, p) in ts.iter().zip(&out) {
                    assert!(p.distance(c.eval(t)) < 1e-13, "order {order} t {t}");
                }
            }
        }
    }

    /// The four-lane steps (one shared segment, or gathered point by point) give the bits of
    /// the one-parameter remainder path, for sorted and shuffled parameters, open and closed,
    /// outside the domain and at NaN (NaN payloads aside).
    #[test]
    fn four_lane_steps_equal_the_remainder_path_bitwise() {
        let pts: Vec<Point<3>> = (0..40)
            .map(|i| {
                let f = i as f64 * 0.3;
                Point([f.cos() * 3.0, f * f * 0.1, (2.0 * f).sin()])
            })
            .collect();
        for closed in [false, true] {
            let c = LlCurve::new(&pts, 5, closed).unwrap();
            let mut ts: Vec<f64> = (0..=4001)
                .map(|k| -0.05 + 1.1 * k as f64 / 4001.0)
                .collect();
            ts[100] = f64::NAN;
            let mut shuffled = ts.clone();
            for i in 0..shuffled.len() {
                shuffled.swap(i, (i * 7919) % ts.len());
            }
            for ts in [&ts, &shuffled] {
                let mut out = vec![Point::ZERO; ts.len()];
                c.eval_into(ts, &mut out);
                for (&t, p) in ts.iter().zip(&out) {
                    let mut one = [Point::ZERO];
                    c.eval_into(&[t], &mut one);
                    for k in 0..3 {
                        let (a, b) = (p[k], one[0][k]);
                        assert!(
                            a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan()),
                            "t={t}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn parameters_outside_the_domain_never_panic() {
        let pts = [Point([0.0, 0.0]), Point([1.0, 2.0]), Point([2.0, 0.0])];
        let c = LlCurve::new(&pts, 2, false).unwrap();
        assert!(!c.eval(f64::NAN).is_finite());
        // Open curves clamp: far outside the domain is the end point.
        assert!(c.eval(f64::INFINITY).distance(pts[2]) < 1e-15);
        assert!(c.eval(-1e300).distance(pts[0]) < 1e-15);
    }
}

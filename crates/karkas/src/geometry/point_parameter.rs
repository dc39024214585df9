//! The parameter of a point that lies on a curve, found locally.
//!
//! A CAD file bounds each edge by two vertices that lie on the edge's curve (to the file's
//! precision), and reading it needs their parameters. The global search of
//! [`CurveProjector`](super::CurveProjector) certifies its answer by the arc lengths of a
//! sampled polyline, measured by quadrature: on a rational curve (which tells no polynomial
//! pieces, so 256 segments are measured) that costs about 2 ms a curve, most of the time it
//! takes to read a model made of NURBS. A point on the curve needs no certificate of that
//! kind: a foot at distance `d <= tolerance` is a global minimum of the distance to within
//! `tolerance`, since no point of the curve is nearer than 0.
//!
//! So [`parameter_on_curve`] samples the curve at `SAMPLES` parameters evenly spread over its
//! domain, takes the sample nearest the point, and solves `g(t) = (P(t) - q) . P'(t) = 0` on
//! the two sample intervals beside it by Newton's method safeguarded by bisection (the
//! projector's own root finder). It answers only when the foot found is within `tolerance`
//! of the point; otherwise (a point off the curve, or a curve that passes the point between
//! two samples far from the nearest one) it answers `None`, and the caller runs the global
//! search. Parameters are wrapped into the domain on a closed curve, as the projector does.

use super::curve_nearest::bracketed_newton;
use crate::core::Curve;
use crate::Point;

/// The samples the nearest start is taken from.
const SAMPLES: usize = 256;

/// The parameter of `q` on `curve` when `q` lies within `tolerance` of it, found from the
/// nearest of `SAMPLES` samples (see the module docs); `None` when no foot within
/// `tolerance` is found that way, or `q` or a sample is not finite.
///
/// ```
/// use karkas::bspline::BSplineCurve;
/// use karkas::geometry::parameter_on_curve;
/// use karkas::Point;
///
/// let curve = BSplineCurve::new(
///     2,
///     vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
///     vec![Point([0.0, 0.0]), Point([1.0, 2.0]), Point([2.0, 0.0])],
/// )?;
/// let t = parameter_on_curve(&curve, Point([1.5, 0.75]), 1e-12).unwrap();
/// assert!((t - 0.75).abs() < 1e-14);
/// assert_eq!(parameter_on_curve(&curve, Point([1.0, 3.0]), 1e-12), None);
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn parameter_on_curve<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    q: Point<D>,
    tolerance: f64,
) -> Option<f64> {
    let domain = curve.domain();
    let length = domain.length();
    if !(q.is_finite() && length > 0.0 && length.is_finite()) {
        return None;
    }
    let closed = curve.is_closed();
    let params: Vec<f64> = (0..=SAMPLES)
        .map(|k| domain.uniform(k, SAMPLES + 1))
        .collect();
    let mut nearest = (f64::INFINITY, 0);
    for (k, &t) in params.iter().enumerate() {
        let d = curve.eval(t).distance_sq(q);
        if !d.is_finite() {
            return None;
        }
        if d < nearest.0 {
            nearest = (d, k);
        }
    }
    let j = nearest.1;
    let mut best = (nearest.0.sqrt(), params[j]);
    // The sample intervals beside sample `j`; across the seam too on a closed curve.
    let mut beside = Vec::with_capacity(3);
    if j > 0 {
        beside.push(j - 1);
    }
    if j < SAMPLES {
        beside.push(j);
    }
    if closed && j == 0 {
        beside.push(SAMPLES - 1);
    } else if closed && j == SAMPLES {
        beside.push(0);
    }
    for i in beside {
        if let Some((distance, t)) = foot_between(curve, q, params[i], params[i + 1]) {
            if distance < best.0 {
                best = (distance, t);
            }
        }
    }
    // A NaN distance is no answer either.
    (best.0 <= tolerance).then(|| if closed { domain.wrap(best.1) } else { best.1 })
}

/// The foot of `q` on `curve` between `a < b`, where `g` goes from negative to positive there:
/// its distance and parameter.
fn foot_between<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    q: Point<D>,
    a: f64,
    b: f64,
) -> Option<(f64, f64)> {
    let g = |t: f64| (curve.eval(t) - q).dot(curve.deriv(t, 1));
    if !(g(a) <= 0.0 && g(b) > 0.0) {
        return None;
    }
    let floor = 4.0 * f64::EPSILON * a.abs().max(b.abs());
    let t = bracketed_newton(a, b, 0.5 * (a + b), floor, floor, |t| {
        let [p, d1, d2] = curve.eval_with_derivatives(t);
        let r = p - q;
        (r.dot(d1), d1.norm_sq() + r.dot(d2))
    });
    Some((curve.eval(t).distance(q), t))
}

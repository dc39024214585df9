//! Curvature and torsion of a curve from its derivatives (the Frenet formulas).
//!
//! With `P' = dP/dt`, `P''`, `P'''` at `t`:
//!
//! - in 2-D, `κ = (x' y'' - y' x'') / |P'|^3`, positive where the curve turns
//!   counter-clockwise;
//! - in any other dimension, `κ = sqrt(|P'|^2 |P''|^2 - (P' . P'')^2) / |P'|^3 >= 0`
//!   (`|P' x P''| / |P'|^3` in 3-D);
//! - in 3-D, the torsion `τ = (P' x P'') . P''' / |P' x P''|^2`.
//!
//! Where the curve is singular (`P' = 0`) the curvature is NaN; the torsion is NaN where
//! `P' x P'' = 0` (a straight stretch or a singular point), as the Frenet frame is undefined.

use crate::core::Curve;
use crate::Point3;

/// The curvature of `curve` at `t` (signed in 2-D, positive for a counter-clockwise turn;
/// non-negative in any other dimension); NaN where `P'(t) = 0`.
///
/// ```
/// use karkas::geometry::curvature;
/// use karkas::{ll::LlCurve, Point};
/// // A straight line has no curvature.
/// let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 2.0]), Point([3.0, 3.0])];
/// let line = LlCurve::new(&pts, 3, false).unwrap();
/// assert!(curvature(&line, 0.4).abs() < 1e-12);
/// ```
pub fn curvature<C: Curve<D> + ?Sized, const D: usize>(curve: &C, t: f64) -> f64 {
    let d1 = curve.deriv(t, 1);
    let d2 = curve.deriv(t, 2);
    curvature_from(d1, d2)
}

/// The curvature from the first two derivatives (see [`curvature`]).
pub(crate) fn curvature_from<const D: usize>(d1: crate::Point<D>, d2: crate::Point<D>) -> f64 {
    // On the curve scaled by 1 / sigma (its curvature sigma times the true one), so that
    // |P'|^3 neither overflows nor underflows at extreme scales.
    let sigma = largest_coordinate(&d1);
    if !(sigma.is_finite() && sigma > 0.0) {
        return f64::NAN;
    }
    let scale = 1.0 / sigma;
    let (d1, d2) = (d1 * scale, d2 * scale);
    let speed_sq = d1.norm_sq();
    if speed_sq.is_nan() || speed_sq <= 0.0 {
        return f64::NAN;
    }
    let speed3 = speed_sq * speed_sq.sqrt();
    let k = if D == 2 {
        (d1[0] * d2[1] - d1[1] * d2[0]) / speed3
    } else {
        let dot = d1.dot(d2);
        (speed_sq * d2.norm_sq() - dot * dot).max(0.0).sqrt() / speed3
    };
    k * scale
}

/// The largest absolute coordinate of `p`.
fn largest_coordinate<const D: usize>(p: &crate::Point<D>) -> f64 {
    p.0.iter().fold(0.0, |m: f64, x| m.max(x.abs()))
}

/// The cross product `a x b` of two vectors in space.
pub fn cross(a: Point3, b: Point3) -> Point3 {
    Point3::new([
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ])
}

/// The torsion of a space curve at `t`, `(P' x P'') . P''' / |P' x P''|^2`: positive where the
/// curve winds like a right-handed helix; NaN where `P' x P'' = 0`.
pub fn torsion<C: Curve<3> + ?Sized>(curve: &C, t: f64) -> f64 {
    let (d1, d2, d3) = (curve.deriv(t, 1), curve.deriv(t, 2), curve.deriv(t, 3));
    // On the curve scaled by 1 / sigma (its torsion sigma times the true one), so that the
    // products neither overflow nor underflow at extreme scales.
    let sigma = largest_coordinate(&d1);
    if !(sigma.is_finite() && sigma > 0.0) {
        return f64::NAN;
    }
    let scale = 1.0 / sigma;
    let (d1, d2, d3) = (d1 * scale, d2 * scale, d3 * scale);
    let b = cross(d1, d2);
    let b2 = b.norm_sq();
    // Below this the binormal is rounding noise (relative to |P'|^2 |P''|^2).
    if b2.is_nan() || b2 <= 1e-28 * d1.norm_sq() * d2.norm_sq() || b2 == 0.0 {
        return f64::NAN;
    }
    b.dot(d3) / b2 * scale
}

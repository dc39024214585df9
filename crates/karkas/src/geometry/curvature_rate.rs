//! The rate of change of curvature along the arc, `dκ/ds`, in closed form from the first
//! three derivatives (differentiating the Frenet formulas of [`curvature`](fn@super::curvature)).
//!
//! With `v = |P'|`, `a = P' . P''`:
//!
//! - in 2-D, `κ = c / v^3` with `c = x' y'' - y' x''`, so `dκ/ds = (c' v^2 - 3 c a) / v^6`
//!   with `c' = x' y''' - y' x'''`;
//! - in any other dimension, `κ = w / v^3` with `w^2 = W = v^2 |P''|^2 - a^2`, so
//!   `dκ/ds = (w' v^2 - 3 w a) / v^6` with `w' = W' / (2 w)` and
//!   `W' = 2 v^2 (P'' . P''') - 2 a (P' . P''')` (taken as 0 where `w = 0`, a zero of the
//!   non-negative curvature, where `κ` has a corner).
//!
//! Both are evaluated after a change of parameter and of length unit that brings `P'`, `P''`
//! and `P'''` to order one, so that `v^6` and the products of derivatives do not underflow.

use crate::core::{Curve, PiecewiseCurve, Side};
use crate::Point;

/// The curvature and its rate along the arc `(κ, dκ/ds)` from the first three derivatives
/// (NaN where `P' = 0`).
pub(crate) fn curvature_and_rate<const D: usize>(
    d1: Point<D>,
    d2: Point<D>,
    d3: Point<D>,
) -> (f64, f64) {
    let sigma = d1.max_abs();
    if !(sigma.is_finite() && sigma > 0.0) {
        return (f64::NAN, f64::NAN);
    }
    // Reparameterize by `t = τ u` with `τ = σ / |P''|` and scale space by `λ = σ τ`, so that
    // the three derivatives are all of order one whatever the units of `t` and of space
    // (chord parameters of coordinates near 1e150 give `P'''` near 1e-300, whose products
    // underflow); `κ` scales by `λ` and `dκ/ds` by `λ^2`, undone at the end.
    let rho = d2.max_abs();
    let (d1, d2, d3, scale) = if rho.is_finite() && rho > 0.0 {
        (
            d1 * (1.0 / sigma),
            d2 * (1.0 / rho),
            d3 * ((1.0 / rho) * (sigma / rho)),
            (rho / sigma) / sigma,
        )
    } else {
        let scale = 1.0 / sigma;
        (d1 * scale, d2 * scale, d3 * scale, scale)
    };
    let v2 = d1.norm_sq();
    let a = d1.dot(d2);
    let (c, dc) = if D == 2 {
        (d1[0] * d2[1] - d1[1] * d2[0], d1[0] * d3[1] - d1[1] * d3[0])
    } else {
        let w2 = (v2 * d2.norm_sq() - a * a).max(0.0);
        let w = w2.sqrt();
        let dw2 = 2.0 * v2 * d2.dot(d3) - 2.0 * a * d1.dot(d3);
        (w, if w > 0.0 { dw2 / (2.0 * w) } else { 0.0 })
    };
    let v = v2.sqrt();
    let k = c / (v2 * v);
    let rate = (dc * v2 - 3.0 * c * a) / (v2 * v2 * v2);
    (k * scale, rate * scale * scale)
}

/// The curvature and `dκ/ds` at `t` (signed curvature in 2-D, non-negative otherwise).
///
/// ```
/// use karkas::geometry::curvature_rate;
/// use karkas::{ll::LlCurve, Point};
/// let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 2.0]), Point([3.0, 3.0])];
/// let line = LlCurve::new(&pts, 3, false).unwrap();
/// let (k, rate) = curvature_rate(&line, 0.4);
/// assert!(k.abs() < 1e-12 && rate.abs() < 1e-12);
/// ```
pub fn curvature_rate<C: Curve<D> + ?Sized, const D: usize>(curve: &C, t: f64) -> (f64, f64) {
    curvature_and_rate(curve.deriv(t, 1), curve.deriv(t, 2), curve.deriv(t, 3))
}

/// The curvature and `dκ/ds` at `t` on the piece on `side` of `t` (the one-sided limits at a
/// breakpoint).
pub fn curvature_rate_on_side<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    t: f64,
    side: Side,
) -> (f64, f64) {
    curvature_and_rate(
        curve.deriv_on_side(t, 1, side),
        curve.deriv_on_side(t, 2, side),
        curve.deriv_on_side(t, 3, side),
    )
}

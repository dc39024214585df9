//! Exact B-spline form of `C^2` cubic splines and bicubic interpolating surfaces (Kuznetsov,
//! Filatov): degree 3, simple inner knots, from the Hermite data of the nodes.

use super::{BicubicSurface, CubicSpline};
use crate::bspline::{
    hermite_curve, knot_vector, tensor_controls, BSplineCurve, BSplineSurface, ToBSplineCurve,
    ToBSplineSurface,
};
use crate::core::{Curve, Surface};
use crate::Result;

/// `C^2` cubic splines (any end conditions): degree 3, simple inner knots. A periodic spline
/// is exported over its one period as a clamped curve whose ends coincide.
impl<const D: usize> ToBSplineCurve<D> for CubicSpline<D> {
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        Ok(
            hermite_curve(self.knots(), self.values(), self.slopes(), 1)?
                .with_closed(self.is_closed()),
        )
    }
}

/// Bicubic interpolating splines: degree 3 by 3, simple inner knots (`C^2` in each
/// direction), from the Hermite data of the nodes (the Bezier net of each patch is
/// `b_ab = r + A h_u/3 r_u + B h_v/3 r_v + A B h_u h_v/9 r_uv` at the patch corner nearest
/// to Bezier point `(a, b)`, `A, B` in `{0, 1, -1, 0}` by distance and side).
impl<const D: usize> ToBSplineSurface<D> for BicubicSurface<D> {
    fn to_bspline(&self) -> Result<BSplineSurface<D>> {
        let (ku, kv) = (self.knots_u(), self.knots_v());
        let mult_u = vec![1; ku.len() - 2];
        let mult_v = vec![1; kv.len() - 2];
        let knots_u = knot_vector(3, ku, &mult_u);
        let knots_v = knot_vector(3, kv, &mult_v);
        let side = |a: usize| -> (usize, f64) {
            match a {
                0 => (0, 0.0),
                1 => (0, 1.0),
                2 => (1, -1.0),
                _ => (1, 0.0),
            }
        };
        let patch = |k: usize, l: usize, a: usize, b: usize| {
            let (di, sa) = side(a);
            let (dj, sb) = side(b);
            let (i, j) = (k + di, l + dj);
            let (hu, hv) = (ku[k + 1] - ku[k], kv[l + 1] - kv[l]);
            let r = self.node(i, j);
            let (ru, rv, ruv) = self.node_derivatives(i, j);
            r.add_scaled(sa * hu / 3.0, ru)
                .add_scaled(sb * hv / 3.0, rv)
                .add_scaled(sa * sb * hu * hv / 9.0, ruv)
        };
        let control = tensor_controls((3, ku, &knots_u), (3, kv, &knots_v), patch);
        Ok(BSplineSurface::new((3, knots_u), (3, knots_v), control)?
            .with_closed(self.is_closed_u(), self.is_closed_v()))
    }
}

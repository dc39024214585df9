//! Exact B-spline form of `C^2` cubic splines and bicubic interpolating surfaces (Kuznetsov,
//! Filatov): degree 3, simple inner knots, from the Hermite data of the nodes.

use super::{BicubicSurface, CubicSpline};
use crate::bspline::{
    hermite_curve, BSplineCurve, BSplineSurface, ToBSplineCurve, ToBSplineSurface,
};
use crate::core::{Curve, Grid, Surface};
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
/// direction). The surface is held in this form; its control net is returned as it is.
impl<const D: usize> ToBSplineSurface<D> for BicubicSurface<D> {
    fn to_bspline(&self) -> Result<BSplineSurface<D>> {
        let (knots_u, knots_v, net) = self.bspline_parts();
        let (rows, cols) = (self.knots_u().len() + 2, self.knots_v().len() + 2);
        let control = Grid::from_row_major(rows, cols, net.to_vec())?;
        Ok(
            BSplineSurface::new((3, knots_u.to_vec()), (3, knots_v.to_vec()), control)?
                .with_closed(self.is_closed_u(), self.is_closed_v()),
        )
    }
}

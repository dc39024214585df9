//! Exact B-spline form of cubic splines of defect 2 (Pavlov): degree 3, every inner knot
//! doubled.

use super::HermiteSpline;
use crate::bspline::{hermite_curve, BSplineCurve, ToBSplineCurve};
use crate::Result;

/// Cubic splines of defect 2: degree 3, every inner knot doubled (`C^1`).
impl<const D: usize> ToBSplineCurve<D> for HermiteSpline<D> {
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        hermite_curve(self.knots(), self.values(), self.derivatives(), 2)
    }
}

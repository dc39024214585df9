//! Arc length, its inverse and curvature as methods of every curve: [`CurveGeometry`], implemented
//! for every [`Curve`] (bring it into scope with `use karkas::geometry::CurveGeometry`).
//!
//! An extension trait rather than default methods of `Curve`, so that the curve traits in
//! `core` do not depend on the geometry built on them.

use super::arc_length::{arc_length, inverse_arc_length};
use super::curvature::curvature;
use crate::core::Curve;

/// Arc length, inverse arc length and curvature of a curve (see [`arc_length`],
/// [`inverse_arc_length`] and [`curvature`]).
pub trait CurveGeometry<const D: usize>: Curve<D> {
    /// The arc length from `t0` to `t1` (negative when `t1 < t0`) to within `accuracy`
    /// (absolute): adaptive Gauss–Legendre quadrature of `|P'|` on every polynomial piece.
    fn arc_length(&self, t0: f64, t1: f64, accuracy: f64) -> f64 {
        arc_length(self, t0, t1, accuracy)
    }

    /// The parameter reached after walking `length` along the curve from `t0` (backwards
    /// when negative), to within `accuracy` in length: stops at the domain end of an open
    /// curve, wraps on a closed one.
    fn inverse_arc_length(&self, t0: f64, length: f64, accuracy: f64) -> f64 {
        inverse_arc_length(self, t0, length, accuracy)
    }

    /// The curvature at `t`: signed in 2-D (positive for a counter-clockwise turn),
    /// non-negative otherwise; NaN where `P' = 0`.
    fn curvature(&self, t: f64) -> f64 {
        curvature(self, t)
    }
}

impl<C: Curve<D> + ?Sized, const D: usize> CurveGeometry<D> for C {}

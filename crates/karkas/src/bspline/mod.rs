//! Exact B-spline form of every piecewise polynomial curve and surface of karkas
//! (docs/methods.md §6): how they leave the program for CAD (STEP and IGES B-spline entities)
//! without approximation.
//!
//! [`BSplineCurve`] and [`BSplineSurface`] are non-rational B-splines with clamped knot
//! vectors, evaluated by de Boor's algorithm (independently of the types they come from).
//! [`ToBSplineCurve`] / [`ToBSplineSurface`] convert; each type implements them in its own
//! module (`ll/bspline.rs`, `fit/bspline.rs`, `param/bspline.rs`, `coons/bspline.rs`) with the
//! helpers of this module, which knows none of them:
//!
//! | type | degree | inner knot multiplicity |
//! |---|---|---|
//! | [`LlCurve`](crate::ll::LlCurve), [`LlSurface`](crate::ll::LlSurface) of order `L` | `2L` | `L` (`C^L` joins) |
//! | [`HermiteSpline`](crate::fit::HermiteSpline) (defect 2) | 3 | 2 (`C^1`) |
//! | [`CubicSpline`](crate::param::CubicSpline) (not-a-knot, natural, clamped, periodic) | 3 | 1 (`C^2`) |
//! | [`BicubicSurface`](crate::param::BicubicSurface) | 3 x 3 | 1 x 1 |
//! | [`CoonsSurface`](crate::coons::CoonsSurface) over piecewise polynomial data | largest of blends and curves | `degree - continuity` per merged breakpoint |
//!
//! Method: each type gives its Bezier pieces in closed form (LL: the Bernstein coefficients
//! of the kernel `h`, all positive; Hermite and bicubic: the Hermite-to-Bezier rule; Coons:
//! interpolation in each cell); the pieces are then joined into one B-spline by blossoming
//! (`bezier.rs`), which is exact for pieces that join with the continuity the
//! knot vector encodes. Cost: `O(n p^2)` for `n` pieces of degree `p` (`O(n p^2 q^2)`-ish for
//! surfaces, linear in the number of patches).
//!
//! Closed curves and closed surface directions are exported over one period as clamped
//! open B-splines whose ends coincide (not as periodic B-splines).
//!
//! Guarantee: the B-spline evaluates to the same points as the original to rounding (tests
//! check `1e-12` relative to the data's size, derivatives included).
//!
//! Rational B-splines ([`NurbsCurve`], [`NurbsSurface`]: weights, any knot vector, clamped or
//! not) carry what CAD files give: their evaluation and derivatives of every order follow
//! Piegl and Tiller's *The NURBS Book* (basis functions A2.2/A2.3 in `span_basis.rs`, the
//! quotient rule A4.2/A4.4 in `rational.rs`, knot insertion A5.1); [`conic`] and [`sweep`]
//! convert lines, circles, ellipses, planes, cylinders, cones, spheres, tori, extrusions and
//! revolutions to them exactly (A7.1, A8.1). Every karkas B-spline is a NURBS with unit
//! weights ([`NurbsCurve::from_bspline`], [`NurbsSurface::from_bspline`]).
//!
//! Hand-written: the B-spline crates available evaluate and fit, but none converts these
//! piecewise polynomial types with prescribed knot multiplicities; de Boor's algorithm and
//! blossoming are a few dozen lines.

mod basis;
mod bezier;
pub mod conic;
mod curve;
mod rational;
mod rational_curve;
mod rational_surface;
mod span_basis;
mod surface;
pub mod sweep;

pub use crate::core::PolynomialPieces;
pub(crate) use basis::cubic_span_weights;
pub(crate) use bezier::{
    bspline_controls, hermite_curve, knot_vector, split_scalar, tensor_controls,
};
pub use curve::{BSplineCurve, MAX_DEGREE};
pub use rational_curve::NurbsCurve;
pub use rational_surface::{NurbsSurface, SecondOrder};
pub use surface::BSplineSurface;

use crate::Result;

/// Conversion of a piecewise polynomial curve to its exact B-spline form.
pub trait ToBSplineCurve<const D: usize> {
    /// The B-spline equal to this curve over its domain.
    fn to_bspline(&self) -> Result<BSplineCurve<D>>;
}

/// Conversion of a piecewise polynomial surface to its exact B-spline form.
pub trait ToBSplineSurface<const D: usize> {
    /// The B-spline surface equal to this surface over its domain.
    fn to_bspline(&self) -> Result<BSplineSurface<D>>;
}

impl<const D: usize> ToBSplineCurve<D> for BSplineCurve<D> {
    /// The curve itself.
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        Ok(self.clone())
    }
}

//! Parameterization and cubic / bicubic spline interpolation (Kuznetsov, Filatov,
//! "Parametrization of surfaces by the continuation method"; docs/methods.md §5).
//!
//! Points measured on a curve or a surface become a smooth curve or surface only after
//! parameters are chosen, and the paper shows that the choice decides the error. This module
//! has the paper's pipeline for point data:
//!
//! - [`curve_parameters`], [`grid_parameters`]: uniform, chord-length (along two grid lines
//!   through an origin node, the paper's rule, or averaged over all lines) and centripetal
//!   parameters, `O(n)` / `O(N M)`;
//! - [`CubicSpline`]: 1-D cubic interpolating splines on any increasing knots with
//!   not-a-knot (the paper's (3.10)–(3.12)), natural, clamped or periodic ends; one `O(n)`
//!   tridiagonal solve;
//! - [`BicubicSurface`]: the bicubic interpolant of a grid, the surface of the Hermite form
//!   (3.6)–(3.9) held as its B-spline control net (a spline solve along every column, then
//!   along every row of the result), `O(N M)`; not-a-knot ends, periodic in a closed
//!   direction;
//! - [`condition_measure`], [`BicubicSurface::condition_measures`]: how well the parameters
//!   condition the continuation system (2.3), the paper's measure (2.4) extended to tangents
//!   of any length (`1` exactly for arc lengths along orthogonal directions, Theorem 2.1);
//!   [`paper_condition_measure`], [`BicubicSurface::paper_condition_measures`]: the paper's
//!   `|D|` itself (the sine of the angle between the parameter lines).
//! - [`relay_grid`]: a grid re-laid along the lines of curvature of its own bicubic
//!   interpolant, spaced by arc length (the paper's best parameters, Theorem 2.1).
//!
//! The paper's table of errors (frames from [`crate::implicit`], measured with
//! [`crate::measure`]) is an experiment built on this module: the CLI's `demo` runs it.
//!
//! ```
//! use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
//! use karkas::{Curve, Point2};
//! let pts = [Point2::new([0.0, 0.0]), Point2::new([1.0, 2.0]), Point2::new([3.0, 3.0]),
//!            Point2::new([4.0, 1.0])];
//! let spline = CubicSpline::through(&pts, CurveParameterization::ChordLength,
//!                                   SplineEnds::NotAKnot).unwrap();
//! // It passes through every point at its chord-length parameter.
//! let t = spline.knots()[2];
//! assert!(spline.eval(t).distance(pts[2]) < 1e-14);
//! ```

mod bicubic;
mod bspline;
mod condition;
mod grid_controls;
mod names;
mod parameterization;
mod relay;
mod spline;
mod spline_eval;

pub use crate::spline::SplineEnds;
pub use bicubic::{BicubicEnds, BicubicSurface};
pub use condition::{condition_measure, paper_condition_measure, ConditionSummary};
pub use parameterization::{
    curve_parameters, grid_parameters, CurveParameterization, GridParameterization,
};
pub use relay::{relay_grid, relay_surface, RelaidGrid, RelayOptions, DEFAULT_SUBSTEPS};
pub use spline::CubicSpline;

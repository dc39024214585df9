//! Shared core types: points, intervals, grids, and the curve and surface traits that every
//! method of karkas implements and every consumer (sampling, sections, export) relies on.

mod curve;
mod grid;
mod grid_points;
mod interval;
pub mod knots;
pub(crate) mod lanes;
pub(crate) mod parallel;
mod pieces;
mod point;
mod sampling;
mod shared_end;
mod surface;

pub use curve::{Curve, PiecewiseCurve, Side};
pub use grid::Grid;
pub use interval::Interval;
pub use knots::Knots;
pub use pieces::PolynomialPieces;
pub use point::{Point, Point2, Point3};
pub use sampling::uniform_into;
pub(crate) use sampling::{assert_buffer_len, assert_grid_len};
pub use shared_end::{shared_end, with_shared_end, SHARED_END_TOLERANCE};
pub use surface::{ParameterLine, PiecewiseSurface, Surface};

//! Differential geometry of any [`Curve`](crate::Curve) and [`Surface`](crate::Surface):
//! arc length and its inverse, curvature and torsion, unit normals and principal
//! curvatures, and the closest point of a curve or surface to given points.
//!
//! - [`arc_length`](fn@arc_length): `∫ |P'(t)| dt` by adaptive Gauss–Legendre quadrature on each polynomial
//!   piece (split at the breakpoints, where `P'` may have kinks), to a stated absolute
//!   accuracy; the inverse (the parameter reached after a given length) by safeguarded Newton
//!   on the length function. The methods of [`CurveGeometry`] (implemented for every
//!   curve) call these. [`ArcLengthTable`] measures every piece once for many lengths of
//!   one curve (`O(log n)` each).
//! - [`curvature`](fn@curvature): the Frenet curvature (signed in 2-D) and torsion (3-D) from the first
//!   three derivatives.
//! - [`curvature_rate`](fn@curvature_rate): `dκ/ds` in closed form from the first three derivatives.
//! - [`fairness`]: the fairness figures of a piecewise curve (length, curvature range,
//!   curvature extrema and inflections, largest distance from the input polygon,
//!   `∫ (dκ/ds)^2 ds`).
//! - [`curve_nearest`]: the globally nearest point of a curve: candidates from a sampled
//!   polyline in a k-d tree (the `kiddo` crate), refined by safeguarded Newton on
//!   `(P(t) - q) . P'(t) = 0` per candidate segment; large batches share one proof per cell
//!   of a grid (`nearest_grid`: a run of segments on which the squared distance is convex
//!   for the whole cell, bounded by `segment_polynomials`).
//! - [`enclosed_volume`]: the volume a closed surface encloses (the divergence theorem, by
//!   Gauss–Legendre on its polynomial cells; planar caps by their area vectors) and the
//!   plane of a closed polygon.
//! - [`points_out_of_order`]: whether a point list follows one curve in its order.
//! - [`parameter_on_curve`]: the parameter of a point that lies on a curve (a CAD vertex on its
//!   edge), by Newton's method from the nearest of a few samples, without the global search's
//!   arc lengths.
//! - [`surface_frame`]: the unit normal and the principal curvatures and directions from the
//!   first and second fundamental forms.
//! - [`surface_nearest`]: the globally nearest point of a surface, candidates from a sampled
//!   grid in a k-d tree refined by Newton's method.
//! - [`mesh_parameters`](mod@mesh_parameters): the sample grid of a triangle mesh within a
//!   chordal tolerance of a surface, refined where it bends.

pub mod arc_length;
mod arc_length_table;
pub mod curvature;
pub mod curvature_rate;
mod curve_geometry;
pub mod curve_nearest;
pub mod enclosed_volume;
pub mod fairness;
#[cfg(test)]
mod fairness_tests;
pub mod mesh_parameters;
mod nearest_grid;
mod point_order;
mod point_parameter;
mod polygon_distance;
mod quadrature;
mod segment_polynomials;
mod sign_changes;
pub mod surface_frame;
pub mod surface_nearest;

pub use arc_length::{arc_length, inverse_arc_length};
pub use arc_length_table::ArcLengthTable;
pub use curvature::{cross, curvature, torsion};
pub use curvature_rate::{curvature_rate, curvature_rate_on_side};
pub use curve_geometry::CurveGeometry;
pub use curve_nearest::{CurveNearest, CurveProjector};
pub use enclosed_volume::{area_vector, flux_volume, polygon_plane, Plane};
pub use fairness::{curvature_profile, curve_fairness, CurvatureSample, CurveFairness};
pub use mesh_parameters::{mesh_parameters, surface_size, MeshParameters};
pub use point_order::points_out_of_order;
pub use point_parameter::parameter_on_curve;
pub use surface_frame::{normal, principal_curvatures, PrincipalCurvatures};
pub use surface_nearest::{SurfaceNearest, SurfaceProjector};

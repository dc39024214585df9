//! # karkas
//!
//! Smooth parametric curves and surfaces from point frames: ordered points, grids of points,
//! networks of curves, implicit equations.
//!
//! The crate is the geometry only (no files, no printing). It is organised by layer:
//!
//! - [`core`]: points, intervals, grids, and the [`Curve`] / [`Surface`] traits every method
//!   implements;
//! - [`solve`]: the banded linear solvers the methods need;
//! - [`ll`]: the LL-approximation of curves and surfaces (Aulchenko, Latypov, Nikulichev):
//!   oscillation-free, monotone, `C^L` curves and surfaces on a uniform parameter grid, and
//!   their interpolating variant, and the paper's surface variation method;
//! - [`coons`]: generalized Coons surfaces (Chashnikov): the Boolean sum over any blending
//!   families and curves, with the bilinear and bicubic Coons, Gordon (Lagrange and
//!   cubic-spline blending) and composite Coons surfaces as instances;
//! - [`section`]: plane sections and isolines of any [`Surface`];
//! - [`dps`]: discrete periodic splines with vector coefficients (Malozemov, Khorokhonov,
//!   Chashnikov): closed discrete curves from poles or through nodes, and closed tubes;
//! - [`param`]: parameterizations, 1-D cubic splines and bicubic interpolation of grids
//!   (Kuznetsov, Filatov);
//! - [`implicit`]: implicit surfaces `F(x, y, z) = 0`, their principal curvatures, and node
//!   grids traced along lines of curvature (or turned nets) by continuation;
//! - [`bspline`]: exact B-spline form of every piecewise polynomial curve and surface (for
//!   CAD export);
//! - [`geometry`]: arc length and its inverse, curvature and torsion of curves, normals and
//!   principal curvatures of surfaces, and global closest points on curves and surfaces;
//! - [`measure`]: the two-sided Hausdorff distance between surfaces and point sets.
//! - [`loft`]: surfaces through placed sections (wings, blades, hulls): compatible sections
//!   on one knot vector, spanwise rules, aerosandbox's wing placement.
//! - [`fit`]: fitting measured points with C^1 cubic Hermite splines (cubic splines of defect
//!   2) whose second-derivative jumps are bounded (Pavlov).
//! - [`fair`]: the fairest `C^2` cubic B-spline within a hard tolerance of measured points
//!   (least `∫ (dκ/ds)^2 ds`), or of an existing curve.
//!
//! ```
//! use karkas::{ll::LlCurve, Curve, Point};
//! let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 0.0]), Point([3.0, 1.0])];
//! let curve = LlCurve::new(&pts, 3, false).unwrap();
//! // An open LL curve passes through its first and last points at the ends of its domain.
//! let d = curve.domain();
//! assert!(curve.eval(d.start).distance(pts[0]) < 1e-15);
//! assert!(curve.eval(d.end).distance(pts[3]) < 1e-15);
//! ```

pub mod bspline;
pub mod coons;
pub mod core;
pub mod dps;
mod error;
pub mod fair;
pub mod fit;
pub mod geometry;
pub mod implicit;
pub mod ll;
pub mod loft;
pub mod measure;
pub mod param;
pub mod section;
pub mod shape;
pub mod solve;
pub mod spline;

pub use crate::core::{
    Curve, Grid, Interval, ParameterLine, PiecewiseCurve, PiecewiseSurface, Point, Point2, Point3,
    Side, Surface,
};
pub use error::{Error, Result};

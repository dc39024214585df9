//! LL-approximation of curves and surfaces (Aulchenko, Latypov, Nikulichev;
//! docs/methods.md §1).
//!
//! A uniform parameter grid, one polynomial segment of degree `2L` per input point, joined
//! with `C^L` continuity. The approximating scheme is oscillation-free and monotone (it bends
//! only where the support polygon bends, and never overshoots three consecutive points); the
//! interpolating variant passes through the points at the price of those two guarantees.
//!
//! - [`LlKernel`]: the kernel `h` of order `L` (§1.1);
//! - [`LlCurve`]: open and closed curves in any dimension (§1.2);
//! - [`LlSurface`]: tensor-product surfaces, each direction open or closed (§1.3);
//! - [`interpolation_controls`]: the `O(K)` solve of the interpolating variant;
//! - [`LlCurve::within`], [`LlSurface::within`]: between the two, a curve or surface that
//!   passes within a given distance of every point without raising `L` ([`WithinFit`]);
//! - [`vary`]: the surface variation method (§1.5): a coordinate matrix varied through new
//!   row sums, column sums and total, with chosen entries fixed.
//!
//! Sections of LL surfaces go through [`crate::section`]; the paper's fast path (a section
//! `x = const` when `x` depends on `u` only, formula (21)) is the LL surface's
//! [`Surface::level_parameter_lines`](crate::Surface::level_parameter_lines).

mod axis;
mod batch;
mod bspline;
mod curve;
mod frame;
mod kernel;
mod level_lines;
mod prefilter;
mod surface;
mod variation;
mod within;

pub use axis::NodeAxis;
pub use curve::LlCurve;
pub use kernel::{LlKernel, MAX_ORDER};
pub use prefilter::interpolation_controls;
pub use surface::LlSurface;
pub use variation::{complete_sums, vary, FixedEntries, SumTargets, SumsProblem, VariationOptions};
pub use within::WithinFit;

/// The order `L` used when none is given (the command line's `--order`, Python's `order=`):
/// `C^3` curves and surfaces of degree 6 pieces, smooth enough for curvature plots and
/// close to the polygon.
pub const DEFAULT_ORDER: usize = 3;

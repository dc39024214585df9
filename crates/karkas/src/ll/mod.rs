//! LL-approximation of curves and surfaces (seed 000: Aulchenko, Latypov, Nikulichev;
//! METHODS.md §1).
//!
//! A uniform parameter grid, one polynomial segment of degree `2L` per input point, joined
//! with `C^L` continuity. The approximating scheme is oscillation-free and monotone (it bends
//! only where the support polygon bends, and never overshoots three consecutive points); the
//! interpolating variant passes through the points at the price of those two guarantees.
//!
//! - [`LlKernel`]: the kernel `h` of order `L` (§1.1);
//! - [`LlCurve`]: open and closed curves in any dimension (§1.2);
//! - [`LlSurface`]: tensor-product surfaces, each direction open or closed (§1.3);
//! - [`interpolation_controls`]: the `O(K)` solve of the interpolating variant.

mod axis;
mod curve;
mod frame;
mod kernel;
mod prefilter;
mod surface;

pub use axis::NodeAxis;
pub use curve::LlCurve;
pub use kernel::{LlKernel, MAX_ORDER};
pub use prefilter::interpolation_controls;
pub use surface::LlSurface;

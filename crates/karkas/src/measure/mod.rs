//! Distances between surfaces and point sets: the two-sided Hausdorff distance (Kuznetsov and Filatov,
//! formula (3.14); docs/methods.md §5), the error measure of the paper's experiments.
//!
//! `Delta(E, F) = max( max_{P in E} min_{Q in F} |P - Q|, max_{P in F} min_{Q in E} |P - Q| )`.
//!
//! - [`hausdorff_sets`]: between two finite point sets, with a k-d tree (the `kiddo`
//!   crate): `O((n + m) log(n + m))`;
//! - [`hausdorff_surface_implicit`]: between a parametric surface and a patch of an implicit
//!   surface. The parametric side is sampled densely and every sample is projected onto
//!   `F = 0` exactly (Newton along the gradient, then tangential corrections to the closest
//!   point); the implicit patch is given by points on it (e.g. a dense
//!   [`trace_net`](crate::implicit::trace_net)), each of which is brought to its closest point
//!   on the parametric surface by Newton's method on `|W(u, v) - Q|^2`, started from the
//!   nearest sample. Both directions are therefore exact up to how densely the maximum is
//!   searched, not up to the sampling distance;
//! - [`distance_to_implicit`]: one direction only, from points to `F = 0`.
//!
//! Every result says where the distance is attained ([`DirectedDistance`]).

mod sets;
mod surface;

pub use sets::{hausdorff_sets, DirectedDistance, Hausdorff, PointCloud};
pub use surface::{
    distance_to_implicit, hausdorff_points_implicit, hausdorff_surface_implicit, ClosestPoint,
};

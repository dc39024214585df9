//! Generalized Coons, Gordon and composite Coons surfaces (Chashnikov, "Composite
//! and generalized Coons surfaces"; docs/methods.md §2).
//!
//! **The operator.** For each parameter direction a [`BlendingFamily`]: linear functionals
//! `L_i` ([`Functional`]: the value at a point, a derivative at a point, ...) and functions
//! `H_j` with `L_i(H_j) = delta_ij` (formulas (5), (6)). Given curve families `f_i(v)` and
//! `g_j(u)` (any [`Curve`](crate::Curve)) satisfying the compatibility conditions (8)
//! `L^u_i(g_j) = L^v_j(f_i)`, the generalized Coons surface is the Boolean sum (9)
//!
//! ```text
//! c(u,v) = sum_i H^u_i(u) f_i(v) + sum_j H^v_j(v) g_j(u) - sum_i sum_j H^u_i(u) H^v_j(v) L^u_i(g_j)
//! ```
//!
//! ([`CoonsSurface::new`]). Proposition 1: `L^u_i c(., v) = f_i(v)` and `L^v_j c(u, .) = g_j(u)`.
//!
//! **The instances**, each a constructor over a [`CurveNetwork`] (v-curves `a_i` along `v` at
//! `u = u_i`, u-curves `b_j` along `u` at `v = v_j`):
//! - [`CoonsSurface::bilinear`] (Chashnikov's §3 case 1), [`CoonsSurface::bicubic`] (Chashnikov's §3 case 2, with
//!   cross-derivatives on the four borders);
//! - [`CoonsSurface::gordon`]: Lagrange blending (Chashnikov's §3 case 3); oscillates with many curves;
//! - [`CoonsSurface::gordon_spline`]: cubic-spline cardinal blending (natural or not-a-knot;
//!   periodic in a closed direction), what CAD kernels use for curve networks;
//! - [`CoonsSurface::composite`]: the composite Coons surface with cross-derivative curves
//!   `A_i`, `B_j` (11) and the piecewise Hermite blending (17)–(18): `C^1`, satisfies (14), and
//!   equals the patch-by-patch surface (13) (Proposition 2).
//!
//! **Twists.** Chashnikov's §4 builds the cross-derivative curves from twist vectors `d_ij`:
//! `A_i(v_j) = b_j'(u_i)`, `A_i'(v_j) = d_ij`, `B_j(u_i) = a_i'(v_j)`, `B_j'(u_i) = d_ij`
//! ([`CrossDerivatives::from_twists`]: piecewise cubic Hermite curves of these data, so (11)
//! holds by construction and the surface has `S_uv(u_i, v_j) = d_ij`). Omitted twists are
//! derived by the spline-of-derivatives rule ([`derived_twists`]: the mean of the
//! derivatives of the not-a-knot, periodic when closed, splines through the curves' tangents
//! `b_j'(u_i)` over `j` and `a_i'(v_j)` over `i`; exact for bicubic and bilinear polynomial
//! surfaces); omitted cross-derivative curves are those of the derived twists.
//!
//! ```
//! use karkas::coons::{curve_ref, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve};
//! use karkas::{Point3, Surface};
//! // Four straight borders of a twisted quadrilateral: v-curves at u = 0, 1; u-curves at v = 0, 1.
//! let p = |x: f64, y: f64, z: f64| Point3::new([x, y, z]);
//! let edge = |a: Point3, b: Point3| curve_ref(PolylineCurve::new(&[a, b], &[0.0, 1.0]).unwrap());
//! let (p00, p10, p01, p11) = (p(0., 0., 0.), p(1., 0., 0.), p(0., 1., 0.), p(1., 1., 1.));
//! let unit = NetworkAxis::open(vec![0.0, 1.0])?;
//! let network = CurveNetwork::new(
//!     unit.clone(),
//!     vec![edge(p00, p01), edge(p10, p11)],
//!     unit,
//!     vec![edge(p00, p10), edge(p01, p11)],
//! )?;
//! let coons = CoonsSurface::bilinear(&network, 1e-9)?;
//! // The bilinear Coons surface of straight borders is the hyperbolic paraboloid z = u v.
//! assert!((coons.eval(0.5, 0.5)[2] - 0.25).abs() < 1e-15);
//! // A border that misses a corner is an error naming the pair.
//! let bad = CurveNetwork::new(
//!     NetworkAxis::open(vec![0.0, 1.0])?,
//!     vec![edge(p00, p01), edge(p10, p(1., 1., 2.))],
//!     NetworkAxis::open(vec![0.0, 1.0])?,
//!     vec![edge(p00, p10), edge(p01, p11)],
//! )?;
//! let error = CoonsSurface::bilinear(&bad, 1e-9).unwrap_err().to_string();
//! assert!(error.starts_with("v-curve 1 and u-curve 1 disagree at (u=1, v=1)"));
//! # Ok::<(), karkas::Error>(())
//! ```
//!
//! **Compatibility.** Every constructor checks (8) (which for the composite family is (11))
//! at every pair of curves with a tolerance relative to the model size, and fails with
//! [`Error::IncompatibleCurves`](crate::Error::IncompatibleCurves) naming the two curves, the
//! crossing and the condition: never a silently wrong surface. Asked to
//! ([`Compatibility::Repair`] in place of the tolerance), it makes the data compatible
//! instead: both sides of every condition snap to their mean, each curve moved by the blend
//! `sum_j H_j c_j` of its corrections (exact by (5)), and reports the largest correction
//! ([`CoonsSurface::repair`]).
//!
//! **Curves from points.** [`PointNetwork`] turns point lists into a network: interpolating
//! cubic-spline curves ([`CubicSpline`](crate::param::CubicSpline), or LL curves of Aulchenko et al.), crossings found as
//! shared points, node values from the crossing parameters (see its docs for every rule).
//!
//! **Cost.** Building: `O(m n)` functional evaluations for the check. A point: `O(m + n)`
//! curve evaluations. A grid `NU x NV` ([`Surface::eval_grid_into`](crate::Surface)): each
//! curve is sampled once per line of its direction, blending weights once per line, then
//! `O(nnz_u + nnz_v)` per point (8 for the composite surface). Families: see
//! [`BlendingFamily`].
//!
//! Hand-written: no maintained crate offers Coons/Gordon surfaces over arbitrary curve types
//! and blending schemes; the cubic-spline cardinal functions are evaluated with the
//! tridiagonal solvers of [`solve`](crate::solve) rather than a spline crate because the
//! Boolean sum needs all cardinal functions at a parameter (a transposed solve), not one
//! interpolant.

mod blended;
mod blending;
mod bspline;
mod cross_derivative;
mod curves;
mod functional;
mod instances;
mod kind;
mod network;
mod points;
mod polyline;
mod surface;
mod twists;
mod warp;

pub use blending::{
    hermite_cubic, BlendingFamily, CubicHermiteBlending, LagrangeBlending, LlBlending,
    PiecewiseHermiteBlending, SplineBlending, SplineEnds,
};
pub use bspline::MAX_SAMPLED_DEGREE;
pub use cross_derivative::{Along, SurfaceCrossDerivative};
pub use curves::{curve_ref, AffineCurve, CurveRef};
pub use functional::Functional;
pub use instances::DERIVED_CROSS_ENDS;
pub use kind::{CoonsKind, CROSSING_TOLERANCE, POINT_NETWORK_TOLERANCE};
pub use network::{CrossDerivatives, CurveNetwork, NetworkAxis};
pub use points::{CurveFit, PointNetwork};
pub use polyline::PolylineCurve;
pub use surface::{Compatibility, CoonsSurface, FamilyRef, Repair, DEFAULT_TOLERANCE};
pub use twists::derived_twists;

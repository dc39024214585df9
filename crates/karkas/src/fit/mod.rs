//! Fitting measured points with cubic splines of defect 2 whose second-derivative jumps are
//! bounded (N. N. Pavlov, "On the approximation of space curves by cubic parametric
//! splines"; docs/methods.md §4).
//!
//! Measured contours are noisy and unevenly spread; a C^1 cubic Hermite spline
//! ([`HermiteSpline`]: values `R_L` and derivatives `H_L` at knots `0 = T_1 < ... < T_N = 1`)
//! follows them with few knots, and bounding `f(q) = sum_L delta_L |J_L|^2 <= eps` (the
//! jumps `J_L` of the second derivative, formula (2) of the paper) keeps it from bending
//! sharply where the data are thin; `delta_L = 0` keeps a chosen knot a corner.
//!
//! - [`fit_curve`]: the fit on given knots. Minimizes `H(q) = sum_i min_t |R(t) - r_i|^2`
//!   (foot-point distances) plus a small bending term `lambda int |R''|^2 dt`
//!   ([`FitOptions::fairness`]) subject to the bound, by the paper's penalty method (`p` from
//!   the paper's bound `p >= H(q*)/eps`, raised until the bound holds, or chosen so that the
//!   bound is active, see [`PenaltyRule`]); for each `p`, Newton's method on the coefficients
//!   with the foot-point parameters eliminated (Gauss–Newton on both jointly, the diagonal
//!   parameter block solved out, curvature terms kept; banded), safeguarded by
//!   Levenberg–Marquardt damping and by the paper's alternation of a banded least-squares
//!   solve with the projection of every point onto the curve; chord-length start; the ends
//!   pinned to the first and last points, or at their common point when they coincide (a
//!   closed profile: [`FitEnds`]).
//! - On real data ([`FitOptions::ordered`], [`FitOptions::smoothing`], [`estimate_noise`]):
//!   the foot-point parameters are kept in the order of the points, the noise is estimated
//!   from the points and the bending weight made dimensionless (size, turning, points per
//!   piece) and proportional to the noise (its noise part falling off at the ends, where the
//!   term's natural end condition would pull the curve), the open ends are held on their
//!   tangent lines where the points towards them say they lie, or at one point where they meet
//!   ([`FitEnds::Auto`]); the result carries the estimate and
//!   [`FitWarning`]s from the shape guards ([`shape_warnings`]: crossings, excess turning,
//!   sparse pieces, empty spans; docs/methods.md §4, "On real and noisy data").
//! - [`fit_curve_adaptive`]: knots placed automatically (uniform in chord length, then a
//!   knot into every piece whose worst point lies beyond the tolerance, round after round)
//!   until a tolerance on the largest deviation holds, or the deviation stalls (noise), with
//!   a warning naming the best fit reached.
//! - [`fit_closed_curve`], [`fit_closed_curve_adaptive`]: the same spline periodic over a
//!   closed contour, `C^1` across the seam (docs/methods.md §4, "Closed curves").
//!
//! Why the bending term: the foot-point distances do not change when the points slide
//! along the curve, so the unconstrained problem is nearly flat along reparameterizations:
//! without a regularization the derivatives `H_L` drift, and a bound on the jumps is met by
//! slowing the curve where it bends and spending the parameter range on a fold between
//! sparse points (a NACA 2412 fit on 17 knots came out 2.5e-2 from the true contour while
//! 1e-5 from every point). The term is weighted `lambda = rho n` on sparse pieces (`rho = 3e-11` by default, see
//! [`estimate_noise`] for the whole weight),
//! far below the data term.
//!
//! Guarantees (tested): the parameters do not decrease along the points; every inner foot
//! point outside a pooled run is a local minimizer of the distance (residual orthogonal to
//! the tangent, second-order condition); the gradient of
//! `H + p f + lambda S` with respect to the coefficients vanishes at the result when iterated
//! to convergence ([`FitOptions::settle_tolerance`] 0); `eps -> 0` tends to the C^2 least-squares
//! cubic spline on the same knots and a large `eps` gives the unconstrained C^1 fit; on a
//! NACA section with known truth the fit approaches the true contour as knots are added.
//! The objective is not convex in the parameters: the result is a local minimum reached
//! from chord-length parameters, or the best sound one of several starts
//! ([`FitOptions::starts`]).
//!
//! Complexity: each iteration is `O(n D^2)` for `n` points in R^D (one pass to assemble the
//! banded Newton system, one to project the points from their previous foot points, `O(1)`
//! curve evaluations each) plus `O(N D^3)` for `N` knots (banded Cholesky, `5 D + 1`
//! diagonals); a few iterations suffice (10^5 noisy points of a spiral, 200 knots: about 0.2 s
//! without the bound, 1.5 s with an active one; `cargo bench -p karkas-bench --bench fit`).

mod adaptive;
mod bspline;
mod closed;
mod closed_system;
mod coarse;
mod ends;
mod faults;
mod fixed;
mod gradient;
mod guards;
mod hermite;
mod knots;
mod multistart;
mod newton;
mod noise;
mod order;
mod penalty;
mod power;
mod problem;
mod project;
mod project_all;
mod prune;
mod refine;
mod result;
mod session;
mod solver;
mod through_points;
mod unit_scale;

pub use adaptive::{fit_curve_adaptive, AdaptiveFit, AdaptiveStop};
pub use closed::{closed_bspline, fit_closed_curve, fit_closed_curve_adaptive};
pub use guards::{polyline_crossings, shape_warnings, PolylineCrossing};
pub use hermite::HermiteSpline;
pub use knots::{check_knots, knots_from_list, start_parameters, uniform_knots, StartParameters};
pub use noise::{estimate_noise, NoiseEstimate};
pub use penalty::{
    fit_curve, shared_end, work_bytes_per_knot, FitEnds, FitOptions, PenaltyRule, DEFAULT_FAIRNESS,
    DEFAULT_SETTLE_TOLERANCE, DEFAULT_SMOOTHING, SHARED_END_TOLERANCE, TOLERANCE_SMOOTHING,
};
pub use result::{CurveFit, FitWarning, FitWarningKind};

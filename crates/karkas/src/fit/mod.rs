//! Fitting measured points with cubic splines of defect 2 whose second-derivative jumps are
//! bounded (seed 003: N. N. Pavlov, "On the approximation of space curves by cubic parametric
//! splines"; METHODS.md §4).
//!
//! Measured contours are noisy and unevenly spread; a C^1 cubic Hermite spline
//! ([`HermiteSpline`]: values `R_L` and derivatives `H_L` at knots `0 = T_1 < ... < T_N = 1`)
//! follows them with few knots, and bounding `f(q) = sum_L delta_L |J_L|^2 <= eps` (the
//! jumps `J_L` of the second derivative, formula (2) of the seed) keeps it from bending
//! sharply where the data are thin; `delta_L = 0` keeps a chosen knot a corner.
//!
//! - [`fit_curve`]: the fit on given knots. Minimizes `H(q) = sum_i min_t |R(t) - r_i|^2`
//!   (foot-point distances) subject to the bound, by the seed's penalty method (`p` from the
//!   bound `p >= H(q*)/eps` of the seed, raised until the bound holds, then lowered to where
//!   it is active, see [`PenaltyRule`]); for each `p`, Gauss–Newton on coefficients and
//!   parameters together, safeguarded by the seed's alternation of a banded least-squares
//!   solve with the projection of every point onto the curve; chord-length start.
//! - [`fit_curve_adaptive`]: knots placed automatically (uniform in chord length, then
//!   refined where the deviation is largest) until a tolerance on the largest deviation
//!   holds.
//!
//! Guarantees (tested): every inner foot point is a local minimizer of the distance
//! (residual orthogonal to the tangent, second-order condition); the gradient of `H + p f`
//! with respect to the coefficients vanishes at the result; `eps -> 0` tends to the C^2
//! least-squares cubic spline on the same knots and a large `eps` gives the unconstrained C^1
//! fit. The objective is not convex in the parameters: the result is a local minimum
//! reached from chord-length parameters.
//!
//! Complexity: each inner iteration is `O(n D^3)` for `n` points in R^D (banded Givens
//! solves, width `6 D`) plus the projections, `O(1)` amortized per point; the number of
//! iterations does not grow with `n`.

mod adaptive;
mod hermite;
mod knots;
mod penalty;
mod project;
mod solver;

pub use adaptive::{fit_curve_adaptive, AdaptiveFit};
pub use hermite::HermiteSpline;
pub use knots::{check_knots, start_parameters, uniform_knots, StartParameters, MIN_KNOT_SPACING};
pub use penalty::{fit_curve, CurveFit, FitOptions, PenaltyRule};

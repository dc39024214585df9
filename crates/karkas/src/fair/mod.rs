//! The fairest curve within a tolerance of measured points (docs/methods.md §8).
//!
//! [`fair_curve`] finds a `C^2` cubic B-spline `r` whose distance from every input point is at
//! most `T` and whose curvature-variation energy
//!
//! ```text
//! E = ∫ (dκ/ds)^2 ds
//! ```
//!
//! is least (locally: the problem is not convex). `E` is the figure
//! [`curve_fairness`](crate::geometry::curve_fairness) reports and the one a designer's
//! curvature plot shows: it is zero on straight lines and circular arcs, and every curvature
//! extremum the curve does not need costs it, so a curve that bends no more than the points
//! demand comes out with the curvature extrema and inflections of the shape the points
//! sample, not of their noise. `∫ κ^2 ds` (the elastic energy that smoothing splines minimize
//! in its linearized form `∫ |r''|^2`) would instead flatten the curve where it bends most
//! and leaves small curvature waves cheap; `E` is also the energy of Moreton and Séquin's
//! minimum-variation curves.
//!
//! Representation: a cubic B-spline with simple inner knots (`C^2`, its curvature
//! continuous), one span per three points, the spans following the points (denser where the
//! points are), clamped at the ends of an open curve, periodic for a closed one; corners
//! ([`FairOptions::corners`]) split the curve into pieces faired apart and joined `C^0`
//! at the corner points (triple knots).
//!
//! Method (see `fair/solver.rs` and `fair/objective.rs`): the points are centred and scaled to size one
//! (so that the result moves with the points and does not depend on their units),
//! parameterized by chord length; a least-squares spline, reweighted until every point is
//! within `0.9 T` of its parameter's point, starts a logarithmic-barrier method on
//! `t (E + α ∫ |r'''|^2 dt) - sum ln(T^2 - |r(u_i) - p_i|^2)` with Gauss–Newton steps, the
//! parameters moved to the foot points after every step. The barrier first bounds the error
//! across the curve (a slab around the tangent, `|e_⊥|^2 + β (e . τ)^2 < T^2`, so that the
//! curve may slide along itself: the squared-distance idea of Wang, Pottmann and Liu); that
//! result is kept when every point is then strictly inside its ball `|r(u_i) - p_i| < T`,
//! otherwise the method runs again with the balls, whose every iterate keeps every point
//! strictly inside: the hard bound holds either way.
//!
//! Cost: `O(n)` per Newton step for `n` points (banded systems of width `4 D`, `8 D` closed),
//! but about 480 Newton steps for a noisy airfoil (every barrier stage runs its cap: the
//! parameters move after every step); a 200-point airfoil takes 120-210 ms of one core
//! (BENCHMARKS.md, "Fairing speed"; `cargo bench -p karkas-bench --bench fair`), well above the
//! 10 ms aimed at.
//!
//! The problem is not convex and the barrier ends in a local minimum; where that minimum's
//! energy is above the energy of the cubic spline through the points (sparse points under a
//! tolerance far below their spacing can end in a near-cusp between the quadrature nodes),
//! that spline is returned instead (no corners and no kept tangents), so the energy after
//! fairing is never above the one reported before.
//!
//! Guarantees (tested): every point within `T` of the curve (at its parameter, and so on
//! dense samples); the energy at most the interpolating spline's where it is the fallback; ends and tangent directions kept when asked; corners passed through; the
//! result equal to the one at the origin plus the offset for points moved far from it (to
//! 64 units in the last place of the offset: the points are taken from their bounding box's
//! corner, exactly); on noisy airfoils the energy at most that of SciPy's and Open
//! CASCADE's curves within `T` (bench/fair_airfoils.py; the counts of curvature extrema and
//! inflections match the benchmark's truth in too few cases, BENCHMARKS.md).

mod blocks;
mod layout;
mod objective;
mod options;
mod piece;
mod result;
mod shape;
mod solver;
mod space;

pub use options::{FairEnds, FairOptions, RESOLUTION_ULPS};
pub use result::{fair_curve, fair_existing_curve, FairCurve};

//! Plane sections and isolines of surfaces (Aulchenko et al., formulas (21)–(23); docs/methods.md §1.4).
//!
//! Engineers cut a surface into sections: stations `x = const` of a fuselage, waterlines
//! `z = const`, buttocks `y = const`, or any plane `n . p = c`. This module cuts **any**
//! [`Surface`](crate::Surface) (the level set of any [`LevelFunction`] of the surface point, a
//! [`Plane`] being the usual one) and returns every piece of the section as a polyline with
//! its surface parameters, closed or open.
//!
//! Two paths, as in the paper:
//! - **fast path** (formula (21)): when the surface reports the section as whole parameter
//!   lines through [`Surface::level_parameter_lines`](crate::Surface::level_parameter_lines)
//!   (an LL surface does when `n . r_ij` depends on the row only, as `x` does in the paper's
//!   grids), the section is `v -> P(u*, v)` for each root `u*`, sampled to the tolerance;
//! - **general path** (formulas (22)–(23)): the level curve `F(u, v) = 0` is traced in the
//!   parameter plane by predictor-corrector continuation (see `trace.rs`), started from every
//!   crossing found on the edges of a coarse grid of cells, both ways, to the border of the
//!   domain or until it closes (closed directions are crossed), each piece once. A border
//!   line that is one point in space (a pole: the nose of a body of revolution, where a grid
//!   row collapses) is that point: a curve reaching it ends there, and the two pieces meeting
//!   at a pole are joined into one curve through it (a plane through a body's nose and tail
//!   cuts one closed loop).
//!
//! Guarantees: every reported point is `surface.eval(u, v)` at its reported parameters and
//! lies on the level set to rounding (Newton is run to `1e-14` of the values' size); the
//! polyline stays within the tolerance of the true curve: the trace aims at it from the turn of
//! the tangent, then every chord is measured against the section arc it spans at seven points
//! (Newton's method from the parameters between its ends) and split until its chord error is
//! within the tolerance (see `chords.rs`); every piece that crosses an edge of the coarse grid is found, and traced
//! once. Nothing loops forever: steps are bounded per piece, and a trace that meets a singular
//! point (a saddle or a tangency of the plane), cannot follow a sharp turn or runs out of
//! steps stops with a [`SectionWarning`].
//!
//! Cost: sampling the grid once per [`Sectioner`] (`(cells_u + 1)(cells_v + 1)` evaluations),
//! then per section one pass over the samples, about ten evaluations per crossed grid edge, a
//! few per continuation step (the number of steps grows like `length / sqrt(tolerance)`) and
//! seven corrections per chord to measure it.
//!
//! Hand-written: continuation of implicit curves on parametric surfaces is small, and no
//! maintained crate traces level sets of a user's surface evaluator.

mod chords;
mod lines;
mod plane;
mod result;
mod sample_grid;
mod scan;
mod sectioner;
mod trace;

pub use plane::{LevelFunction, Plane};
pub use result::{Section, SectionCurve, SectionWarning};
pub use sectioner::{
    cells_for_grid, plane_section, SectionOptions, Sectioner, DEFAULT_RELATIVE_TOLERANCE,
    MAX_CELLS, MIN_RELATIVE_TOLERANCE,
};

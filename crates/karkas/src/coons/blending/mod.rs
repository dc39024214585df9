//! Blending families: functions `H_1..H_m` of one parameter paired with functionals
//! `L_1..L_m` such that `L_i(H_j) = delta_ij` (Chashnikov, formulas (2), (5), (16)–(18)).
//!
//! A family is what one parameter direction of a Coons-type surface needs: the functionals say
//! which data of a curve family the surface reproduces, the functions blend the data in between.
//! Any linear interpolation scheme is a family, so every family plugged into the Boolean sum
//! gives a Gordon-type surface:
//!
//! | family | functionals | functions | cost per parameter |
//! |---|---|---|---|
//! | [`LagrangeBlending`] | values at nodes | Lagrange basis (bilinear Coons for two nodes) | `O(m^2)` (`m` nodes; meant for few) |
//! | [`CubicHermiteBlending`] | value, derivative, derivative, value at the two ends | the cubic Hermite polynomials (3) | `O(1)` |
//! | [`PiecewiseHermiteBlending`] | value and derivative at every node | (17)–(18), 4 nonzero at any parameter | `O(m)` to write, 4 nonzero |
//! | [`SplineBlending`] | values at nodes | cubic-spline cardinal functions: natural, not-a-knot or periodic | `O(m)`: one tridiagonal solve |
//! | [`LlBlending`] | values at uniform nodes | LL interpolating cardinal functions (Aulchenko et al.) | `O(m)` |

mod hermite;
mod lagrange;
mod ll;
mod spline;

pub use crate::spline::hermite_cubic;
pub use crate::spline::SplineEnds;
pub use hermite::{CubicHermiteBlending, PiecewiseHermiteBlending};
pub use lagrange::LagrangeBlending;
pub use ll::LlBlending;
pub use spline::SplineBlending;

use super::Functional;
use crate::core::{knots, Interval, Side};
use core::fmt::Debug;
use core::ops::Range;

/// A family of blending functions `H_0..H_{m-1}` of one parameter and the functionals
/// `L_0..L_{m-1}` they are dual to: `L_i(H_j) = delta_ij` (the paper's (5)).
///
/// Implementations evaluate every function of the family at one parameter at a time, which is
/// what a surface needs per sample line; they never allocate per point.
pub trait BlendingFamily: Debug + Send + Sync {
    /// The number of functions `m` (equal to the number of functionals).
    fn len(&self) -> usize;

    /// True when the family has no functions (no family of this crate is empty).
    fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The parameter interval the family is defined on.
    fn domain(&self) -> Interval;

    /// True when the functions are periodic with period `domain().length()`.
    fn is_periodic(&self) -> bool;

    /// The functionals `L_0..L_{m-1}`, in the order of the functions.
    fn functionals(&self) -> &[Functional];

    /// Writes `H_j^(k)(t)` for `j = 0..m` into `out[..m]` and returns the range of `j` outside
    /// which the written values are zero (a local family touches only a few).
    ///
    /// `t` is first brought into the domain: wrapped by the period for a periodic family,
    /// clamped otherwise. At a breakpoint of a piecewise family the piece above is used (the
    /// piece below at the upper end). NaN gives NaN weights, never a panic.
    ///
    /// # Panics
    /// When `out.len() < self.len()`.
    fn eval_into(&self, t: f64, k: usize, out: &mut [f64]) -> Range<usize>;

    /// The pieces all functions of the family share (degree, breakpoints, continuity) when
    /// they are piecewise polynomials; `None` (the default) otherwise. Used for exact
    /// B-spline export ([`bspline`](crate::bspline)).
    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        None
    }
}

/// `t` brought into `domain`: wrapped when `periodic`, clamped otherwise.
#[inline]
pub(crate) fn reduce(domain: Interval, periodic: bool, t: f64) -> f64 {
    if periodic {
        domain.wrap(t)
    } else {
        domain.clamp(t)
    }
}

/// The piece `l` of ascending `nodes` (at least two) holding `t`, `0 <= l <= nodes.len() - 2`,
/// and the local coordinate `s = (t - nodes[l]) / (nodes[l+1] - nodes[l])`. A node belongs to
/// the piece above it, the last node to the last piece ([`knots::locate`]).
#[inline]
pub(crate) fn locate(nodes: &[f64], t: f64) -> (usize, f64) {
    knots::locate(nodes, false, t, Side::Above)
}

/// `x^n` by repeated multiplication (small `n`).
#[inline]
pub(crate) fn powi(x: f64, n: usize) -> f64 {
    (0..n).fold(1.0, |p, _| p * x)
}

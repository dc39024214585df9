//! The result of a fit of Pavlov's defect-2 spline (docs/methods.md §4): the spline, the foot
//! parameters and distances of the points, the figures of the penalty method, the noise
//! estimate and the warnings of the shape guards.

use super::hermite::HermiteSpline;
use super::noise::NoiseEstimate;
use std::fmt;

/// The result of a fit.
#[derive(Clone, Debug)]
pub struct CurveFit<const D: usize> {
    /// The fitted spline on `[0, 1]`.
    pub spline: HermiteSpline<D>,
    /// The foot parameter `t_i` of every point (`t_1 = 0`, `t_n = 1`).
    pub parameters: Vec<f64>,
    /// The distance of every point from the curve, `|R(t_i) - r_i|`.
    pub distances: Vec<f64>,
    /// `H`: the sum of squared distances.
    pub data_term: f64,
    /// `f = sum delta_L |J_L|^2` achieved.
    pub jump_sum: f64,
    /// The penalty `p` of the final minimization (0 for the unconstrained fit).
    pub penalty: f64,
    /// The paper's bound `H(q*) / eps` (0 when no penalty was needed).
    pub seed_bound: f64,
    /// `delta_L` per knot (0 at the ends and at corners).
    pub weights: Vec<f64>,
    /// `lambda`, the weight of the bending energy (see [`estimate_noise`](super::estimate_noise)).
    pub bending_weight: f64,
    /// `S` achieved: the bending energy `int |R''(t)|^2 dt` with each piece's share weighted
    /// by [`CurveFit::bending_shares`] (the plain energy when every share is 1).
    pub bending_energy: f64,
    /// The share of `lambda` on each piece: 1 away from the ends, less towards them where the
    /// noise part of the weight falls off (docs/methods.md §4, "The smoothing falls off at the
    /// ends").
    pub bending_shares: Vec<f64>,
    /// Inner iterations done in all.
    pub iterations: usize,
    /// The noise, size and turning of the points (see [`estimate_noise`](super::estimate_noise)).
    pub noise: NoiseEstimate,
    /// What the distances do not show: crossings, excess turning, pieces with too few
    /// points (see [`FitWarning`]).
    pub warnings: Vec<FitWarning>,
}

impl<const D: usize> CurveFit<D> {
    /// The largest distance of a point from the curve.
    pub fn max_distance(&self) -> f64 {
        self.distances.iter().fold(0.0, |m, d| m.max(*d))
    }

    /// The root mean square of the distances.
    pub fn rms_distance(&self) -> f64 {
        (self.data_term / self.distances.len() as f64).sqrt()
    }

    /// `H + p f + lambda S`, the objective of the last minimization.
    pub fn objective(&self) -> f64 {
        self.data_term + self.penalty * self.jump_sum + self.bending_weight * self.bending_energy
    }
}

/// What a [`FitWarning`] is about.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum FitWarningKind {
    /// The fitted curve crosses itself where the point polygon does not.
    SelfIntersection,
    /// The fitted curve turns more than the point polygon plus a margin.
    ExcessTurning,
    /// Two adjacent pieces hold fewer than 3 points between them (the paper's condition for
    /// a determined fit).
    SparsePieces,
    /// A knot span holds no point.
    EmptySpan,
    /// The tolerance mode stopped before every point was within the tolerance.
    ToleranceNotMet,
}

impl FitWarningKind {
    /// The kind's name in summaries (`self_intersection`, `excess_turning`, ...).
    pub fn name(self) -> &'static str {
        match self {
            FitWarningKind::SelfIntersection => "self_intersection",
            FitWarningKind::ExcessTurning => "excess_turning",
            FitWarningKind::SparsePieces => "sparse_pieces",
            FitWarningKind::EmptySpan => "empty_span",
            FitWarningKind::ToleranceNotMet => "tolerance_not_met",
        }
    }
}

/// A warning about a fit: its kind, where on the curve (a parameter in `[0, 1]`) and a
/// sentence for the user that names the place.
#[derive(Clone, Debug, PartialEq)]
pub struct FitWarning {
    /// What the warning is about.
    pub kind: FitWarningKind,
    /// Where: the curve parameter of the place (for a crossing, the first of its two).
    pub parameter: f64,
    /// The message, e.g. "the curve crosses itself at (1.0012, 0.0003) (t = 0.012 and
    /// t = 0.987)".
    pub message: String,
}

impl fmt::Display for FitWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.message)
    }
}

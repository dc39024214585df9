//! Shape guards of a fit (docs/methods.md §4, "shape guards"): what a designer must be told
//! about a fitted curve that the distances alone do not show.

use std::fmt;

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

//! The summary of `karkas curve fit`: one text line on standard error, and with `--json` one
//! JSON object on standard output, with the same figures.

use karkas::fit::CurveFit;
use serde::Serialize;
use std::time::Duration;

/// A warning of the fit in the summary.
#[derive(Debug, Serialize)]
pub struct WarningSummary {
    /// The kind's name (`self_intersection`, `excess_turning`, `sparse_pieces`, `empty_span`,
    /// `tolerance_not_met`).
    pub kind: &'static str,
    /// Where on the curve.
    pub parameter: f64,
    /// The sentence printed on standard error.
    pub message: String,
}

/// The figures of a fit.
#[derive(Debug, Serialize)]
pub struct FitSummary {
    /// The input file.
    pub input: String,
    /// The number of points.
    pub points: usize,
    /// The number of knots (a closed fit: those of one period, its seam counted at both
    /// ends).
    pub knots: usize,
    /// A closed (periodic) fit (`--closed`).
    pub closed: bool,
    /// The largest distance of a point from the curve.
    pub max_deviation: f64,
    /// The root mean square of the distances.
    pub rms_deviation: f64,
    /// The jump sum `f` achieved.
    pub f: f64,
    /// The penalty `p` of the last minimization.
    pub p: f64,
    /// The noise estimated from the points (per coordinate).
    pub noise: f64,
    /// The weight of the bending term.
    pub bending_weight: f64,
    /// With `--tolerance`: the tolerance and whether every point is within it.
    pub tolerance: Option<f64>,
    /// See `tolerance`.
    pub tolerance_met: Option<bool>,
    /// The warnings of the fit.
    pub warnings: Vec<WarningSummary>,
    /// The time of the fit alone, in seconds.
    pub seconds: f64,
}

impl FitSummary {
    /// The summary of `fit` of the points of `input`.
    pub fn new<const D: usize>(
        input: String,
        fit: &CurveFit<D>,
        tolerance: Option<f64>,
        time: Duration,
    ) -> Self {
        let max_deviation = fit.max_distance();
        FitSummary {
            input,
            points: fit.distances.len(),
            knots: fit.spline.knots().len(),
            closed: false,
            max_deviation,
            rms_deviation: fit.rms_distance(),
            f: fit.jump_sum,
            p: fit.penalty,
            noise: fit.noise.sigma,
            bending_weight: fit.bending_weight,
            tolerance,
            tolerance_met: tolerance.map(|tol| max_deviation <= tol),
            warnings: fit
                .warnings
                .iter()
                .map(|w| WarningSummary {
                    kind: w.kind.name(),
                    parameter: w.parameter,
                    message: w.message.clone(),
                })
                .collect(),
            seconds: time.as_secs_f64(),
        }
    }

    /// The text line (after "wrote OUTPUT (N samples); ").
    pub fn line(&self) -> String {
        format!(
            "{} knots, max deviation {:.6e}, rms {:.6e}, f = {:.6e}, p = {:.6e}, noise {:.3e}, fitted in {:.1} ms",
            self.knots,
            self.max_deviation,
            self.rms_deviation,
            self.f,
            self.p,
            self.noise,
            self.seconds * 1e3
        )
    }
}

//! The last step of the tolerance mode of Pavlov's defect-2 fit (docs/methods.md §4): knots
//! that the tolerance does not need are taken out again, one at a time, each removal kept
//! when the refit (warm-started from the foot parameters) still has every point within the
//! tolerance and neither crosses itself nor turns too much (the shape guards). Every trial is a fit, so the pass runs only on small problems (points times
//! knots at most [`PRUNE_WORK`]).

use super::guards::shape_faults;
use super::penalty::Settings;
use super::penalty::{fit_checked, knot_weights};
use super::result::CurveFit;
use super::session::Session;
use crate::Result;

/// The largest product of points and knots for which the pass runs.
pub(crate) const PRUNE_WORK: usize = 200_000;

/// `fit` (which meets `tolerance`) with the inner knots it does not need removed, the
/// corners kept.
pub(crate) fn prune<const D: usize>(
    session: &Session<'_, D>,
    tolerance: f64,
    options: &Settings<'_>,
    mut fit: CurveFit<D>,
    start: impl Fn(&[f64]) -> Vec<f64>,
) -> Result<CurveFit<D>> {
    let points = session.points;
    if points.len() * fit.spline.knots().len() > PRUNE_WORK {
        return Ok(fit);
    }
    let mut at = 1;
    while at + 1 < fit.spline.knots().len() {
        let knots = fit.spline.knots();
        let corner = options
            .corners
            .iter()
            .any(|&c| (c - knots[at]).abs() <= 1e-9);
        if corner {
            at += 1;
            continue;
        }
        let mut fewer = knots.to_vec();
        fewer.remove(at);
        let weights = knot_weights(&fewer, options.corners)?;
        let trial = fit_checked(
            points,
            &fewer,
            &weights,
            start(&fit.parameters),
            options,
            &fit.noise,
        );
        match trial {
            Ok(trial)
                if trial.max_distance() <= tolerance && shape_faults(points, &trial).is_empty() =>
            {
                fit = trial
            }
            _ => at += 1,
        }
    }
    Ok(fit)
}

//! Several starts of Pavlov's system (4) on given knots (N. N. Pavlov; docs/methods.md §4,
//! "Starts"; [`super::FitOptions::starts`]).
//!
//! The data term `H(q) = sum_i min_t |R(t) - r_i|^2` is not convex in the foot-point
//! parameters, and the iteration reaches the local minimum nearest its start. The paper
//! starts from chord length; other starting parameterizations of the same points (cumulative
//! chords to other powers) can lead to a lower `H`, often through a curve that loops between
//! sparse points, which karkas refuses. So each start is fitted in full and the fit with the
//! smallest `H` among the sound ones (no crossing of itself, no turning beyond its points:
//! [`shape_faults`]) is kept; when none is sound, the first start's fit, whose warnings
//! then say what is wrong.

use super::guards::shape_faults;
use super::knots::start_parameters_for;
use super::noise::NoiseEstimate;
use super::result::CurveFit;
use super::StartParameters;
use crate::{Point, Result};

/// The powers of the cumulative chords the starts after the first take, in order: the
/// centripetal and uniform rules, then between and beyond them.
const START_POWERS: [f64; 7] = [0.5, 0.0, 0.75, 0.25, 1.5, 0.875, 0.625];

/// The most starts a fit takes: the first and one per power.
pub(crate) const MOST_STARTS: usize = START_POWERS.len() + 1;

/// The fits by `fit_from` (a fit from starting parameters) from the first `starts` starts
/// (the first from `first_rule`, the others from [`START_POWERS`]); the sound one with the
/// smallest data term, or the first. A start whose fit fails is passed over; the first
/// start's failure is returned when every start fails.
pub(crate) fn best_of_starts<const D: usize>(
    points: &[Point<D>],
    first_rule: &StartParameters,
    starts: usize,
    noise: &NoiseEstimate,
    fit_from: impl Fn(Vec<f64>) -> Result<CurveFit<D>>,
) -> Result<CurveFit<D>> {
    let first = start_parameters_for(points, first_rule, noise.sigma).and_then(&fit_from);
    let sound = |fit: &CurveFit<D>| shape_faults(points, fit).is_empty();
    let mut best: Option<CurveFit<D>> = first.as_ref().ok().filter(|f| sound(f)).cloned();
    for &power in START_POWERS.iter().take(starts.saturating_sub(1)) {
        let rule = StartParameters::ChordPower(power);
        let Ok(fit) = start_parameters_for(points, &rule, noise.sigma).and_then(&fit_from) else {
            continue;
        };
        let lower = best.as_ref().is_none_or(|b| fit.data_term < b.data_term);
        if lower && sound(&fit) {
            best = Some(fit);
        }
    }
    match best {
        Some(fit) => Ok(fit),
        None => first,
    }
}

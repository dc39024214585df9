//! Knots placed automatically until a tolerance on the largest deviation holds (the tolerance
//! mode of Pavlov's defect-2 fit, docs/methods.md §4).
//!
//! Start from a few knots uniform in the parameter (the starting parameters are chord
//! lengths, so these are uniform in chord length), plus the corners; fit; then, round after
//! round, put one knot into every piece whose worst point lies beyond the tolerance, at that
//! point's foot parameter (see `refine`), and fit again from the previous fit's foot
//! parameters, each round's fit capped at [`ROUND_ITERATIONS`] Newton iterations. A round at
//! most doubles the pieces, so the knots a curve needs are reached in about `log2` of their
//! count rounds.
//!
//! Stop rules, the first that holds ([`AdaptiveStop`]): every point within the tolerance;
//! the tolerance below twice the noise estimated from the points
//! ([`NoiseEstimate`](super::NoiseEstimate)) with the RMS distance at the noise (within a
//! factor 1.5) and no longer falling (by 2% a round); the largest deviation not down by 10% over the last three rounds
//! (noise, or data the curve cannot follow); the knots at one per two points (then the
//! spline has as many coefficients as the points have coordinates); no piece over the
//! tolerance that can be split (no point or too short).
//!
//! The smoothing ([`FitOptions::smoothing`]) is sized by that noise estimate: a tolerance
//! below twice the estimate asks for a curve closer to the points than the smoothing lets it
//! come, and on sparse points the estimate is partly the curve's own bending, so the
//! smoothing is left out then; when the refinement stalls with it, it goes on without it from
//! the best fit.
//!
//! A fit that crosses itself or turns more than its points (a hook past a sharp trailing
//! edge, a loop between sparse points) is made sound where possible: more smoothing on its
//! knots, the same knots from the starting parameters, uniform knots up to the cap, knots
//! added at the faults, a knot taken out beside an empty span, or at last a curve through
//! some of the points that turns as they do, which may take more knots than the cap (see
//! `faults`); a fit that met the tolerance stays within it, and one that missed it within its
//! deviation (when the curve through the points comes within the tolerance after all, the
//! tolerance is met).
//!
//! When the tolerance is met on a small problem (points times knots at most 2e5), the knots
//! it does not need are taken out again one at a time (see `prune`).
//!
//! When the tolerance is not met the fit with the lowest largest deviation is returned (one
//! with fewer knots when it lies within 1% of the lowest) with a
//! [`FitWarningKind::ToleranceNotMet`] warning that names it and why the refinement stopped.
//!
//! Cost: each fit is `O(n)` per iteration for `n` points and at most [`ROUND_ITERATIONS`]
//! iterations; the rounds number about `log2(N / 4)` for `N` knots plus the stall window,
//! so the whole is about `O(n log N)`.

use super::faults::{sound_fit, Repairs};
use super::guards::with_warnings;
use super::knots::{start_parameters_for, uniform_with_corners, warm_parameters};
use super::noise::estimate_noise;
use super::penalty::Settings;
use super::penalty::{
    check_inputs, check_settings, fit_checked, pinned_ends, FitEnds, FitOptions,
    TOLERANCE_SMOOTHING,
};
use super::prune::prune;
use super::refine::{refined_knots, worst_per_piece};
use super::result::{CurveFit, FitWarning, FitWarningKind};
use super::session::Session;
use super::unit_scale::UnitScale;
use crate::{Error, Point, Result};

/// The most Newton iterations of one round's fit: each round starts from the previous
/// fit's foot parameters, and the distances of a fit stopped early are still the true
/// distances of its curve, so the tolerance is judged honestly; the fits made before the
/// knots suffice need not be minimal.
const ROUND_ITERATIONS: usize = 20;
/// Rounds over which the largest deviation must fall by [`STALL_GAIN`].
const STALL_ROUNDS: usize = 3;
/// The largest deviation stalls when it stays above this share of its value
/// [`STALL_ROUNDS`] rounds before.
const STALL_GAIN: f64 = 0.9;
/// A tolerance below this many noise deviations is out of reach without following the noise.
const NOISE_FLOOR: f64 = 2.0;
/// The fit is at the noise when its RMS distance is within this factor of the noise
/// deviation (either way).
const AT_NOISE: f64 = 1.5;
/// The RMS distance has settled when a round lowers it by less than 2%: the shape is
/// followed and only the noise is left.
const RMS_GAIN: f64 = 0.98;
/// A fit with fewer knots is kept when its largest deviation is within this factor of a
/// later one's.
const KEEP_FEWER: f64 = 1.01;

/// Why [`fit_curve_adaptive`] stopped adding knots.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AdaptiveStop {
    /// Every point lies within the tolerance.
    Met,
    /// The tolerance is below twice the estimated noise and the fit's RMS distance is at the
    /// noise (within a factor 1.5) and fell by less than 2% in the last round: more knots
    /// would follow the noise.
    NoiseLevel,
    /// The largest deviation fell by less than 10% over the last three rounds.
    Stalled,
    /// The refinement reached one knot per two points (the repair of a fit that crosses
    /// itself or turns too much can then take more: a curve through some of the points).
    KnotCap,
    /// No piece beyond the tolerance holds a point or room to be split (or,
    /// without the bending term, a split left the spline undetermined).
    NoSplittablePiece,
}

impl AdaptiveStop {
    /// A clause for the warning, e.g. "the deviation stalled near the noise level 1.0e-3".
    fn describe<const D: usize>(self, best: &CurveFit<D>) -> String {
        let sigma = best.noise.sigma;
        let rms = best.rms_distance();
        let near_noise = sigma > 0.0 && rms <= AT_NOISE * sigma && rms >= sigma / AT_NOISE;
        match self {
            AdaptiveStop::Met => "the tolerance was met".to_string(),
            AdaptiveStop::NoiseLevel => format!(
                "the tolerance is below twice the noise level {sigma:.1e} and the fit has reached it"
            ),
            AdaptiveStop::Stalled if near_noise => {
                format!("the deviation stalled near the noise level {sigma:.1e}")
            }
            AdaptiveStop::Stalled => {
                "the deviation stopped falling as knots were added".to_string()
            }
            AdaptiveStop::KnotCap => "the refinement reached one knot per two points".to_string(),
            AdaptiveStop::NoSplittablePiece => {
                "no piece beyond the tolerance can be split further".to_string()
            }
        }
    }
}

/// The result of [`fit_curve_adaptive`].
#[derive(Clone, Debug)]
pub struct AdaptiveFit<const D: usize> {
    /// The fit returned: the first that met the tolerance, or else the one with the lowest
    /// largest deviation (on the knots it chose: `fit.spline.knots()`). When the tolerance
    /// was not met, its `warnings` hold a [`FitWarningKind::ToleranceNotMet`].
    pub fit: CurveFit<D>,
    /// True when every point lies within the tolerance of the curve.
    pub tolerance_met: bool,
    /// The refinement rounds: the fits made on growing knots, the first one included (the
    /// trials of the pruning pass not).
    pub rounds: usize,
    /// Why the knots stopped being added.
    pub stop: AdaptiveStop,
}

/// Fits with knots chosen automatically until every point lies within `tolerance` of the
/// curve, or until more knots stop helping (see the [module docs](crate::fit) and
/// [`AdaptiveStop`]). `options` as for [`fit_curve`](super::fit_curve); the corners become
/// knots.
///
/// Errors: a tolerance that is not positive and finite ([`Error::InvalidSetting`]), and those
/// of [`fit_curve`](super::fit_curve) for the first fit.
///
/// A sine arc fitted to 1e-5 with as few knots as that needs:
///
/// ```
/// use karkas::fit::{fit_curve_adaptive, FitOptions};
/// use karkas::Point;
///
/// let points: Vec<Point<2>> = (0..=60)
///     .map(|k| {
///         let x = k as f64 / 60.0;
///         Point([x, (3.0 * x).sin()])
///     })
///     .collect();
/// let result = fit_curve_adaptive(&points, 1e-5, &FitOptions::default())?;
/// assert!(result.tolerance_met);
/// assert!(result.fit.distances.iter().all(|&d| d <= 1e-5));
/// assert!(result.fit.spline.knots().len() < 20);
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn fit_curve_adaptive<const D: usize>(
    points: &[Point<D>],
    tolerance: f64,
    options: &FitOptions,
) -> Result<AdaptiveFit<D>> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "must be positive and finite",
        });
    }
    check_settings(&Settings::of(options))?;
    let unit = UnitScale::of(points);
    let (scaled, scaled_options) = (unit.points(points), Settings::in_fit_units(options, unit));
    let (best, stop, rounds) = adaptive_rounds(&scaled, unit.length(tolerance), &scaled_options)?;
    if stop == AdaptiveStop::Met {
        return Ok(AdaptiveFit {
            fit: with_warnings(points, unit.restore(best, pinned_ends(points, options))),
            tolerance_met: true,
            rounds,
            stop,
        });
    }
    let mut best = with_warnings(points, unit.restore(best, pinned_ends(points, options)));
    let worst_at = best
        .distances
        .iter()
        .enumerate()
        .fold(
            (0, -1.0),
            |(i, m), (j, &d)| if d > m { (j, d) } else { (i, m) },
        )
        .0;
    let message = format!(
        "tolerance {tolerance:e} not met: the best fit reached max deviation {:.3e} with {} knots (stopped: {})",
        best.max_distance(),
        best.spline.knots().len(),
        stop.describe(&best)
    );
    best.warnings.push(FitWarning {
        kind: FitWarningKind::ToleranceNotMet,
        parameter: best.parameters[worst_at],
        message,
    });
    Ok(AdaptiveFit {
        fit: best,
        tolerance_met: false,
        rounds,
        stop,
    })
}

/// The rounds of [`fit_curve_adaptive`] on points brought to unit size: the best fit
/// (without warnings), why the rounds stopped, and how many there were.
fn adaptive_rounds<const D: usize>(
    points: &[Point<D>],
    tolerance: f64,
    options: &Settings<'_>,
) -> Result<(CurveFit<D>, AdaptiveStop, usize)> {
    let asked = options.smoothing.unwrap_or(TOLERANCE_SMOOTHING);
    let iterations = options.max_iterations;
    // The smoothing is sized by the noise estimated from the points: a tolerance below twice
    // that estimate asks for a curve closer to the points than the smoothing would let it
    // come (and on sparse points the estimate is partly the curve's own bending).
    let noise = estimate_noise(points);
    let sigma = noise.sigma;
    // The ends are not held at an estimate: every point, the first and the last included,
    // must come within the tolerance. Ends that coincide are pinned there (a closed
    // profile), unless the caller freed them.
    let options = &Settings {
        max_iterations: options.max_iterations.min(ROUND_ITERATIONS),
        ends: match options.ends {
            FitEnds::Auto => FitEnds::Shared,
            other => other,
        },
        // With no noise found the smoothing weighs nothing: it is none, so that the rounds
        // are those of `--smoothing 0` (no second pass without it).
        smoothing: Some(if sigma == 0.0 || tolerance < NOISE_FLOOR * sigma {
            0.0
        } else {
            asked
        }),
        ..*options
    };
    let start = start_parameters_for(points, options.start, sigma)?;
    let knots = first_knots(points.len(), options.corners);
    let weights = check_inputs(points, &knots, options)?;
    let first = fit_checked(points, &knots, &weights, start, options, &noise)?;
    // The points are checked: every refit from here on checks only its knots.
    let session = Session { points, noise };
    let cap = (points.len() / 2).max(knots.len());
    let mut rounds = 1;
    let (mut stop, mut best) = refine(&session, tolerance, options, cap, first, &mut rounds)?;
    let held_off = matches!(stop, AdaptiveStop::Stalled | AdaptiveStop::NoiseLevel);
    if held_off && options.smoothing.is_some_and(|s| s > 0.0) {
        // The smoothing is sized by the noise estimated from the points, which on sparse
        // points is partly the curve's own bending: go on without it from the best fit.
        let plain = &Settings {
            smoothing: Some(0.0),
            ..*options
        };
        let start = warm_parameters(&best.parameters);
        let refit = session.refit(best.spline.knots(), start, plain)?;
        rounds += 1;
        let kept = best;
        (stop, best) = refine(&session, tolerance, plain, cap, refit, &mut rounds)?;
        if stop != AdaptiveStop::Met && kept.max_distance() <= best.max_distance() * KEEP_FEWER {
            best = kept;
        }
    }
    let repairs = Repairs {
        asked,
        cap,
        iterations,
        through_points: stop != AdaptiveStop::NoiseLevel,
    };
    best = sound_fit(&session, tolerance, options, repairs, best)?;
    if best.max_distance() <= tolerance {
        // (The repair of a faulty fit can meet the tolerance that the rounds did not.)
        stop = AdaptiveStop::Met;
    }
    if stop == AdaptiveStop::Met {
        best = prune(&session, tolerance, options, best, warm_parameters)?;
    }
    Ok((best, stop, rounds))
}

/// Adds knots round after round from `fit` until a stop rule holds; returns the rule and the
/// fit to keep: the one that met the tolerance, or the one with the lowest largest deviation
/// (an earlier one with fewer knots when within [`KEEP_FEWER`]).
fn refine<const D: usize>(
    session: &Session<'_, D>,
    tolerance: f64,
    options: &Settings<'_>,
    cap: usize,
    mut fit: CurveFit<D>,
    rounds: &mut usize,
) -> Result<(AdaptiveStop, CurveFit<D>)> {
    let mut history = vec![fit.max_distance()];
    let mut rms_history = vec![fit.rms_distance()];
    let mut best = fit.clone();
    let stop = loop {
        if fit.max_distance() <= tolerance {
            return Ok((AdaptiveStop::Met, fit));
        }
        let sigma = fit.noise.sigma;
        let rms_settled = rms_history.len() > 1
            && rms_history[rms_history.len() - 1] > RMS_GAIN * rms_history[rms_history.len() - 2];
        let rms = fit.rms_distance();
        // (An RMS distance far below the estimate says the estimate is the curve's own
        // bending between sparse points, not noise.)
        let at_noise = rms <= AT_NOISE * sigma && rms >= sigma / AT_NOISE;
        if tolerance < NOISE_FLOOR * sigma && at_noise && rms_settled {
            break AdaptiveStop::NoiseLevel;
        }
        if history.len() > STALL_ROUNDS {
            let before = history[history.len() - 1 - STALL_ROUNDS];
            let recent = history[history.len() - STALL_ROUNDS..]
                .iter()
                .fold(f64::INFINITY, |m, &d| m.min(d));
            if recent > STALL_GAIN * before {
                break AdaptiveStop::Stalled;
            }
        }
        let knots = fit.spline.knots().to_vec();
        if knots.len() >= cap {
            break AdaptiveStop::KnotCap;
        }
        let worst = worst_per_piece(&fit.spline, &fit.parameters, &fit.distances);
        let mut budget = cap - knots.len();
        let next = loop {
            let (finer, added) = refined_knots(&knots, &worst, tolerance, budget);
            if added == 0 {
                break None;
            }
            let start = warm_parameters(&fit.parameters);
            match session.refit(&finer, start, options) {
                Ok(next) => break Some(next),
                // Without the bending term a split can leave a piece undetermined: try
                // fewer new knots, the worst pieces first.
                Err(Error::SingularSystem { .. }) if added > 1 => budget = added / 2,
                Err(Error::SingularSystem { .. }) => break None,
                Err(e) => return Err(e),
            }
        };
        let Some(next) = next else {
            break AdaptiveStop::NoSplittablePiece;
        };
        *rounds += 1;
        fit = next;
        history.push(fit.max_distance());
        rms_history.push(fit.rms_distance());
        if fit.max_distance() * KEEP_FEWER < best.max_distance() {
            best = fit.clone();
        }
    };
    Ok((stop, best))
}

/// The first knots: a few uniform ones (up to 4 pieces, one per four points) and the corners.
fn first_knots(points: usize, corners: &[f64]) -> Vec<f64> {
    uniform_with_corners((points / 4).clamp(1, 4) + 1, corners)
}

#[cfg(test)]
mod checked_once {
    use crate::fit::noise::estimate_noise;
    use crate::fit::penalty::checks;
    use crate::fit::penalty::Settings;
    use crate::fit::prune::prune;
    use crate::fit::session::Session;
    use crate::fit::{fit_curve, fit_curve_adaptive, uniform_knots, FitOptions};
    use crate::Point;

    /// 120 points of a thin, cambered profile-like curve (sharp at one end, blunt at the
    /// other): the tolerance fit needs several rounds of knots.
    fn profile() -> Vec<Point<2>> {
        (0..120)
            .map(|i| {
                let s = i as f64 / 119.0;
                let x = 1.0 - (std::f64::consts::PI * s).cos();
                let thickness = 0.12 * (x / 2.0).sqrt() * (1.0 - x / 2.0);
                Point([x, 0.05 * (std::f64::consts::PI * s).sin() + thickness])
            })
            .collect()
    }

    #[test]
    fn a_tolerance_fit_checks_its_points_once() {
        let points = profile();
        let before = checks::so_far();
        let result = fit_curve_adaptive(&points, 1e-6, &FitOptions::default()).unwrap();
        // Several rounds: each refit would count once more if it checked the points.
        assert!(result.rounds >= 3, "{} rounds", result.rounds);
        assert_eq!(checks::so_far() - before, 1);
    }

    #[test]
    fn a_fit_on_given_knots_checks_its_points_once() {
        let points = profile();
        let before = checks::so_far();
        fit_curve(&points, &uniform_knots(9), &FitOptions::default()).unwrap();
        assert_eq!(checks::so_far() - before, 1);
    }

    #[test]
    fn the_pruning_refits_without_checking_the_points() {
        let points = profile();
        let noise = estimate_noise(&points);
        let session = Session {
            points: &points,
            noise,
        };
        let defaults = FitOptions::default();
        let options = Settings::of(&defaults);
        let start = crate::fit::start_parameters(&points, options.start).unwrap();
        let fit = session.refit(&uniform_knots(30), start, &options).unwrap();
        let before = checks::so_far();
        let tolerance = 2.0 * fit.max_distance();
        let pruned = prune(&session, tolerance, &options, fit, |t| t.to_vec()).unwrap();
        // Knots came out (every removal is a refit), and none of the refits checked the points.
        assert!(pruned.spline.knots().len() < 30);
        assert_eq!(checks::so_far(), before);
    }
}

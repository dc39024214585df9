//! Closed fits: Pavlov's defect-2 cubic spline fitted to points around a closed contour
//! (a frame, a section of a fuselage or hull), periodic and `C^1` across the seam
//! (docs/methods.md §4, "Closed curves").
//!
//! The period is the open problem with the last knot's value and derivative identified with
//! the first's (`R_M = R_0`, `H_M = H_0`): one knot's unknowns fewer, the jump `J_0` of the
//! seam knot bounded like every other (a `--corner` may name it: 0 or 1), the foot
//! parameters wrapping over the period. A defect-2 cubic is `C^1` at every knot, the seam
//! included; its second derivative jumps by what the bound allows (`C^2` as `eps -> 0`).
//!
//! - The seam is the first point's parameter, `t_1 = 0`, held there (as the open fit holds
//!   its end points): its distance is measured to `R(0)`, an upper bound of its foot-point
//!   distance. A last point that repeats the first (within
//!   [`SHARED_END_TOLERANCE`](super::SHARED_END_TOLERANCE) of the size) is dropped.
//! - Start: closed chord length, `t_i = s_i / L` with `s_i` the polygon length from the
//!   first point and `L` the length of the closed polygon (the closing chord included).
//! - Minimization: the paper's alternation of the least-squares spline with the parameters
//!   held ([`PeriodicSystem`], a cyclic band solved with the seam's unknowns as a dense
//!   border) and the projection of every other point onto the curve, until the objective
//!   `H + p f + lambda S` stops falling (relative `1e-12`) or after
//!   [`FitOptions::max_iterations`] rounds; the bending weight `lambda` as the open fit's
//!   ([`estimate_noise`]), with no fall-off (a closed curve has no ends).
//! - A bound `eps` on `f`: the paper's rule, `p = H(q*) / eps` times 10 until `f <= eps`
//!   ([`PenaltyRule`](super::PenaltyRule) is not consulted: the active-bound search is the
//!   open fit's).
//! - Tolerance mode ([`fit_closed_curve_adaptive`]): a few uniform knots, then a knot at the
//!   middle of every piece (the seam's last piece included) whose worst point lies beyond
//!   the tolerance, round after round, until the tolerance holds, the deviation stalls, or
//!   a knot per two points; the smoothing defaults to the given-knots value (0.1).
//!
//! Each round is `O(n D)` for `n` points plus `O(M)` for `M` pieces.

use super::adaptive::{AdaptiveFit, AdaptiveStop};
use super::closed_system::{periodic_foot_point, periodic_jumps, PeriodicSystem};
use super::knots::{check_knots, uniform_with_corners, MIN_KNOT_SPACING};
use super::noise::estimate_noise;
use super::penalty::Settings;
use super::penalty::{check_settings, shared_end, FitOptions, DEFAULT_SMOOTHING};
use super::result::{CurveFit, FitWarning, FitWarningKind};
use super::unit_scale::UnitScale;
use crate::bspline::{BSplineCurve, ToBSplineCurve};
use crate::{Error, Point, Result};

/// The alternation stops when the objective falls by less than this share twice running.
const SETTLED: f64 = 1e-12;
/// `w`: the weight of the along-curve part of a point's error in the squared-distance
/// metric of a step.
const ALONG_WEIGHT: f64 = 0.05;
/// Raising `p` tenfold at most this often.
const PENALTY_RAISES: usize = 30;
/// Rounds of the tolerance mode without a better fit (by 1%) before it stops.
const STALLED_ROUNDS: usize = 3;

/// Fits a closed periodic defect-2 cubic spline to `points` around a closed contour, on the
/// `knots` of one period (`0 = T_0 < ... < T_M = 1`, at least 3).
///
/// `options` as for [`fit_curve`](super::fit_curve), but `ends`, `start`, `ordered`,
/// `settle_tolerance` and `penalty` do not apply: the seam is the first point (`t = 0`), the
/// start closed chord length; `corners` may name any knot, `0` or `1` the seam. The result's
/// spline has `R(1) = R(0)` and `R'(1) = R'(0)` exactly; `weights[0]` is the seam's
/// `delta`, `weights[M]` 0 (the seam is counted once); parameters lie in `[0, 1)`.
///
/// Errors: fewer than 3 points or fewer points than pieces ([`Error::TooFewPoints`]),
/// non-finite points, bad knots or settings, a corner that is not a knot.
///
/// ```
/// use karkas::fit::{fit_closed_curve, uniform_knots, FitOptions};
/// use karkas::{Curve, Point};
/// // 40 points of an ellipse, fitted on 13 knots (12 pieces) of one period.
/// let points: Vec<Point<2>> = (0..40)
///     .map(|i| {
///         let a = std::f64::consts::TAU * i as f64 / 40.0;
///         Point([3.0 * a.cos(), a.sin()])
///     })
///     .collect();
/// let fit = fit_closed_curve(&points, &uniform_knots(13), &FitOptions::default())?;
/// assert!(fit.max_distance() < 1e-3);
/// // Periodic and C^1 across the seam.
/// let s = &fit.spline;
/// assert_eq!(s.eval(0.0), s.eval(1.0));
/// assert_eq!(s.deriv(0.0, 1), s.deriv(1.0, 1));
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn fit_closed_curve<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    options: &FitOptions,
) -> Result<CurveFit<D>> {
    let points = one_period(points)?;
    check_knots(knots)?;
    check_settings(&Settings::of(options))?;
    let deltas = seam_deltas(knots, &options.corners)?;
    check_count(points, knots.len() - 1)?;
    let unit = UnitScale::of(points);
    let scaled = unit.points(points);
    let scaled_options = Settings::in_fit_units(options, unit);
    let smoothing = options.smoothing.unwrap_or(DEFAULT_SMOOTHING);
    let params = closed_chord_length(&scaled)?;
    let fit = fit_period(&scaled, knots, &deltas, &scaled_options, smoothing, params)?;
    Ok(unit.restore(fit, None))
}

/// Fits a closed curve with knots placed until every point lies within `tolerance`: a few
/// uniform knots, then a knot at the middle of every piece (the seam's included) whose worst
/// point lies beyond the tolerance, round after round, until the tolerance holds, the
/// deviation stalls, or there is a knot per two points; `options` as for
/// [`fit_closed_curve`], the corners becoming knots. When the tolerance is not met, the best fit carries a
/// [`FitWarningKind::ToleranceNotMet`].
///
/// Errors: a tolerance that is not positive and finite, and those of [`fit_closed_curve`].
///
/// ```
/// use karkas::fit::{fit_closed_curve_adaptive, FitOptions};
/// use karkas::Point;
/// // A superellipse frame, |x|^3 + |y|^3 = 1, to 1e-3.
/// let points: Vec<Point<2>> = (0..80)
///     .map(|i| {
///         let a = std::f64::consts::TAU * i as f64 / 80.0;
///         let (c, s) = (a.cos(), a.sin());
///         Point([c.signum() * c.abs().powf(2.0 / 3.0), s.signum() * s.abs().powf(2.0 / 3.0)])
///     })
///     .collect();
/// let result = fit_closed_curve_adaptive(&points, 1e-3, &FitOptions::default())?;
/// assert!(result.tolerance_met);
/// assert!(result.fit.distances.iter().all(|&d| d <= 1e-3));
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn fit_closed_curve_adaptive<const D: usize>(
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
    let points = one_period(points)?;
    check_settings(&Settings::of(options))?;
    let n = points.len();
    let mut knots = uniform_with_corners((n / 4).clamp(3, 6) + 1, &options.corners);
    seam_deltas(&knots, &options.corners)?;
    check_count(points, knots.len() - 1)?;
    let unit = UnitScale::of(points);
    let scaled = unit.points(points);
    let scaled_options = Settings::in_fit_units(options, unit);
    // The open fit's tolerance-mode smoothing (0.3) holds a coarse closed frame away from
    // its tolerance (the noise estimate reads its bends as noise): the given-knots default.
    let smoothing = options.smoothing.unwrap_or(DEFAULT_SMOOTHING);
    let tol = unit.length(tolerance);
    let mut params = closed_chord_length(&scaled)?;
    let mut best: Option<CurveFit<D>> = None;
    let (mut rounds, mut since_better) = (0, 0);
    let stop = loop {
        rounds += 1;
        let deltas = seam_deltas(&knots, &options.corners)?;
        let fit = fit_period(&scaled, &knots, &deltas, &scaled_options, smoothing, params)?;
        params = fit.parameters.clone();
        let worst = fit.max_distance();
        if best
            .as_ref()
            .is_none_or(|b| worst < 0.99 * b.max_distance())
        {
            best = Some(fit.clone());
            since_better = 0;
        } else {
            since_better += 1;
        }
        if worst <= tol {
            best = Some(fit);
            break AdaptiveStop::Met;
        }
        if since_better >= STALLED_ROUNDS {
            break AdaptiveStop::Stalled;
        }
        let middles = middles_beyond(&fit, &knots, tol);
        if middles.is_empty() {
            break AdaptiveStop::NoSplittablePiece;
        }
        if 2 * (knots.len() - 1 + middles.len()) > n {
            break AdaptiveStop::KnotCap;
        }
        knots.extend(middles);
        knots.sort_by(f64::total_cmp);
    };
    let Some(best) = best else {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "no fit was made",
        });
    };
    let mut fit = unit.restore(best, None);
    let tolerance_met = stop == AdaptiveStop::Met;
    if !tolerance_met {
        warn_unmet(&mut fit, tolerance, stop);
    }
    Ok(AdaptiveFit {
        fit,
        tolerance_met,
        rounds,
        stop,
    })
}

/// The middles of the pieces of `knots` whose worst point of `fit` lies beyond `tol`, where
/// the piece is long enough to split.
fn middles_beyond<const D: usize>(fit: &CurveFit<D>, knots: &[f64], tol: f64) -> Vec<f64> {
    let pieces = knots.len() - 1;
    let mut beyond = vec![false; pieces];
    for (&t, &d) in fit.parameters.iter().zip(&fit.distances) {
        if d > tol {
            beyond[fit.spline.locate(t).0.min(pieces - 1)] = true;
        }
    }
    (0..pieces)
        .filter(|&k| beyond[k] && knots[k + 1] - knots[k] > 2.0 * MIN_KNOT_SPACING)
        .map(|k| 0.5 * (knots[k] + knots[k + 1]))
        .collect()
}

/// Adds to `fit` the warning that `tolerance` was not met (the rounds ended on `stop`).
fn warn_unmet<const D: usize>(fit: &mut CurveFit<D>, tolerance: f64, stop: AdaptiveStop) {
    let worst_at = (0..fit.distances.len())
        .max_by(|&a, &b| fit.distances[a].total_cmp(&fit.distances[b]))
        .unwrap_or(0);
    let message = format!(
        "tolerance {tolerance:e} not met: the best closed fit reached max deviation {:.3e} \
         with {} knots (stopped: {stop:?})",
        fit.max_distance(),
        fit.spline.knots().len(),
    );
    fit.warnings.push(FitWarning {
        kind: FitWarningKind::ToleranceNotMet,
        parameter: fit.parameters[worst_at],
        message,
    });
}

/// The closed B-spline of a closed fit's spline (degree 3, inner knots doubled, first and
/// last control points equal; [`Curve::is_closed`](crate::Curve::is_closed) true), as STEP,
/// IGES and DXF write closed curves.
///
/// Errors: a spline whose ends do not coincide ([`Error::InvalidSetting`]).
pub fn closed_bspline<const D: usize>(spline: &super::HermiteSpline<D>) -> Result<BSplineCurve<D>> {
    let open = spline.to_bspline()?;
    BSplineCurve::new_closed(
        open.degree(),
        open.knots().to_vec(),
        open.control_points().to_vec(),
    )
}

/// The points of one period: a last point that repeats the first dropped; at least 3.
///
/// Runs once per closed fit call (its rounds check only their knots), as
/// [`check_inputs`](super::penalty::check_inputs) does for the open fit, and is counted with it.
fn one_period<const D: usize>(points: &[Point<D>]) -> Result<&[Point<D>]> {
    #[cfg(test)]
    super::penalty::checks::count();
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinitePoint { index });
    }
    let (period, what) = match shared_end(points) {
        Some(_) => (
            &points[..points.len() - 1],
            "a closed fit (after dropping its last point, which repeats the first)",
        ),
        None => (points, "a closed fit"),
    };
    if period.len() < 3 {
        return Err(Error::TooFewPoints {
            what,
            needed: 3,
            got: period.len(),
        });
    }
    Ok(period)
}

/// Refuses fewer points than pieces (the spline would follow nothing between them).
fn check_count<const D: usize>(points: &[Point<D>], pieces: usize) -> Result<()> {
    if pieces < 2 {
        return Err(Error::InvalidKnot {
            index: 1,
            value: 1.0,
            reason: "a closed fit needs at least 3 knots (2 pieces) in the period",
        });
    }
    if points.len() < pieces {
        return Err(Error::TooFewPoints {
            what: "a closed fit (one point per piece of the period)",
            needed: pieces,
            got: points.len(),
        });
    }
    Ok(())
}

/// `delta_L` per knot `0..M` of the period: 1, 0 at corners (0 or 1 name the seam knot 0),
/// 0 at knot `M` (the seam counted once).
fn seam_deltas(knots: &[f64], corners: &[f64]) -> Result<Vec<f64>> {
    let m = knots.len() - 1;
    let mut deltas = vec![1.0; m + 1];
    deltas[m] = 0.0;
    for &corner in corners {
        let at = knots
            .iter()
            .position(|&k| (k - corner).abs() <= 1e-9)
            .ok_or(Error::InvalidSetting {
                name: "corner",
                value: corner,
                reason: "not a knot",
            })?;
        deltas[at % m] = 0.0;
    }
    Ok(deltas)
}

/// Closed chord-length parameters: the polygon length from the first point over the length
/// of the closed polygon.
fn closed_chord_length<const D: usize>(points: &[Point<D>]) -> Result<Vec<f64>> {
    let mut params = Vec::with_capacity(points.len());
    let mut length = 0.0;
    params.push(0.0);
    for w in points.windows(2) {
        length += w[0].distance(w[1]);
        params.push(length);
    }
    let total = length + points[points.len() - 1].distance(points[0]);
    if !(total > 0.0 && total.is_finite()) {
        return Err(Error::TooFewPoints {
            what: "a closed fit (distinct points)",
            needed: 3,
            got: 1,
        });
    }
    for t in &mut params {
        *t /= total;
    }
    Ok(params)
}

/// The fit of one period on points brought to unit size, from `params`: the alternation at
/// `p = 0`, then, when the jumps exceed `eps`, at the paper's `p*` times 10 until they do not.
fn fit_period<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    deltas: &[f64],
    options: &Settings<'_>,
    smoothing: f64,
    mut params: Vec<f64>,
) -> Result<CurveFit<D>> {
    let m = knots.len() - 1;
    let mut closed_loop = points.to_vec();
    closed_loop.push(points[0]);
    let noise = estimate_noise(&closed_loop);
    let lambda = noise.bending_weight(points.len(), m, options.fairness, smoothing);
    let mut period = Period {
        system: PeriodicSystem::new(knots),
        points,
        deltas,
        lambda,
        options,
        iterations: 0,
    };
    let mut result = period.alternate(0.0, &mut params)?;
    let (mut penalty, mut seed_bound) = (0.0, 0.0);
    if options.eps.is_finite() && result.jump_sum > options.eps {
        seed_bound = result.data / options.eps;
        penalty = seed_bound.max(f64::MIN_POSITIVE);
        for _ in 0..PENALTY_RAISES {
            result = period.alternate(penalty, &mut params)?;
            if result.jump_sum <= options.eps {
                break;
            }
            penalty *= 10.0;
        }
    }
    let mut weights = deltas.to_vec();
    weights[m] = 0.0;
    Ok(CurveFit {
        spline: result.spline,
        parameters: params,
        distances: result.distances,
        data_term: result.data,
        jump_sum: result.jump_sum,
        penalty,
        seed_bound,
        weights,
        bending_weight: lambda,
        bending_energy: result.bending,
        bending_shares: vec![1.0; m],
        iterations: period.iterations,
        noise,
        warnings: Vec::new(),
    })
}

/// The fit of one period under way: its periodic system, data and iterations spent.
struct Period<'a, const D: usize> {
    system: PeriodicSystem<D>,
    points: &'a [Point<D>],
    deltas: &'a [f64],
    lambda: f64,
    options: &'a Settings<'a>,
    iterations: usize,
}

impl<const D: usize> Period<'_, D> {
    /// Alternates at the penalty `p` from `params` (kept up to date) until the objective
    /// stalls twice or the iterations run out: each step in the squared-distance metric
    /// along the last spline's tangents, the plain step where that one overshot.
    fn alternate(&mut self, p: f64, params: &mut Vec<f64>) -> Result<Alternation<D>> {
        let mut last: Option<Alternation<D>> = None;
        let mut stalls = 0;
        for _ in 0..self.options.max_iterations.max(1) {
            self.iterations += 1;
            let tangents = last.as_ref().map(|l| unit_tangents(&l.spline, params));
            let metric = tangents.as_deref().map(|t| (t, ALONG_WEIGHT));
            let mut trial_params = params.clone();
            let mut next = self.step(&mut trial_params, metric, p)?;
            if let Some(l) = &last {
                if next.objective > l.objective {
                    // The squared-distance step overshot: the plain alternation step, which
                    // never raises the objective.
                    trial_params = params.clone();
                    next = self.step(&mut trial_params, None, p)?;
                }
            }
            let gain = last
                .as_ref()
                .map_or(f64::INFINITY, |l| l.objective - next.objective);
            if next.objective.is_finite()
                && last.as_ref().is_none_or(|l| next.objective <= l.objective)
            {
                *params = trial_params;
                last = Some(next);
            }
            let objective = last.as_ref().map_or(0.0, |l| l.objective);
            if gain <= SETTLED * objective {
                stalls += 1;
            } else {
                stalls = 0;
            }
            if stalls >= 2 || !self.options.foot_points {
                break;
            }
        }
        last.ok_or(Error::InvalidSetting {
            name: "max_iterations",
            value: 0.0,
            reason: "must be at least 1",
        })
    }

    /// One [`step`] of this period's fit at the penalty `p`.
    fn step(
        &mut self,
        params: &mut [f64],
        metric: Option<(&[Point<D>], f64)>,
        p: f64,
    ) -> Result<Alternation<D>> {
        step(
            &mut self.system,
            self.points,
            params,
            metric,
            self.deltas,
            (p, self.lambda),
            self.options,
        )
    }
}

/// The unit tangents of `spline` at `params`.
fn unit_tangents<const D: usize>(
    spline: &super::HermiteSpline<D>,
    params: &[f64],
) -> Vec<Point<D>> {
    params
        .iter()
        .map(|&t| {
            let d = crate::Curve::deriv(spline, t, 1);
            d * (1.0 / d.norm().max(f64::MIN_POSITIVE))
        })
        .collect()
}

/// The outcome of one alternation.
struct Alternation<const D: usize> {
    spline: super::HermiteSpline<D>,
    distances: Vec<f64>,
    data: f64,
    jump_sum: f64,
    bending: f64,
    objective: f64,
}

/// One step: the spline for the parameters held (in the metric given), then every point but
/// the first projected onto it; the figures after the projection.
fn step<const D: usize>(
    system: &mut PeriodicSystem<D>,
    points: &[Point<D>],
    params: &mut [f64],
    metric: Option<(&[Point<D>], f64)>,
    deltas: &[f64],
    (p, lambda): (f64, f64),
    options: &Settings<'_>,
) -> Result<Alternation<D>> {
    let m = deltas.len() - 1;
    let spline = system.solve(points, params, metric, deltas, p, lambda)?;
    let mut distances = Vec::with_capacity(points.len());
    distances.push(spline.values()[0].distance(points[0]));
    for (i, r) in points.iter().enumerate().skip(1) {
        let (t, d) = if options.foot_points {
            periodic_foot_point(&spline, *r, params[i])
        } else {
            (
                params[i],
                crate::Curve::eval(&spline, params[i]).distance(*r),
            )
        };
        params[i] = t;
        distances.push(d);
    }
    let jumps = periodic_jumps(&spline);
    let jump_sum: f64 = (0..m).map(|l| deltas[l] * jumps[l].norm_sq()).sum();
    let data: f64 = distances.iter().map(|d| d * d).sum();
    let bending = spline.bending_energy();
    Ok(Alternation {
        objective: data + p * jump_sum + lambda * bending,
        spline,
        distances,
        data,
        jump_sum,
        bending,
    })
}

#[cfg(test)]
mod tests {
    use super::super::penalty::checks;
    use super::{fit_closed_curve, fit_closed_curve_adaptive};
    use crate::fit::{uniform_knots, FitOptions};
    use crate::Point;

    /// 60 points of an ellipse with a bump: the tolerance fit needs several rounds.
    fn frame() -> Vec<Point<2>> {
        (0..60)
            .map(|i| {
                let a = std::f64::consts::TAU * i as f64 / 60.0;
                let bump = 0.2 * (-(a - 1.0) * (a - 1.0) * 8.0).exp();
                Point([3.0 * a.cos(), a.sin() + bump])
            })
            .collect()
    }

    #[test]
    fn a_closed_tolerance_fit_checks_its_points_once() {
        let points = frame();
        let before = checks::so_far();
        let result = fit_closed_curve_adaptive(&points, 1e-6, &FitOptions::default()).unwrap();
        // Several rounds: each would count once more if it checked the points.
        assert!(result.rounds >= 3, "{} rounds", result.rounds);
        assert_eq!(checks::so_far() - before, 1);
    }

    #[test]
    fn a_closed_fit_on_given_knots_checks_its_points_once() {
        let points = frame();
        let before = checks::so_far();
        fit_closed_curve(&points, &uniform_knots(9), &FitOptions::default()).unwrap();
        assert_eq!(checks::so_far() - before, 1);
    }
}

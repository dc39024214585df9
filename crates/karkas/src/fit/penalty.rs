//! The fit on given knots: the penalty method of Pavlov around the inner solver.
//!
//! Minimize `H(q) + lambda S(q)` (the sum of squared foot-point distances plus the small
//! bending term of [`FitOptions::fairness`]) subject to `f(q) = sum_L delta_L |J_L|^2 <= eps`:
//!
//! 1. the unconstrained fit `q_H` (`p = 0`) is found first, from the least-squares fit at the
//!    starting parameters (dense points: from the fit of a subset, see
//!    [`warm_start`]): when `f(q_H) <= eps` it is the answer (the paper's "the problem
//!    reduces to finding `q_H`");
//! 2. otherwise `q*` is the fit on the knots `{0, corners, 1}` only, which has no jump at any
//!    knot with `delta_L = 1` (so `f(q*) = 0`), and the paper's bound is
//!    `p* = (H + lambda S)(q*) / eps` (proved for global minimizers of `H + lambda S + p f`);
//!    with [`PenaltyRule::SeedBound`] `p = p*`, multiplied by 10 until `f(q_p) <= eps` holds
//!    for the minimizer found;
//! 3. with [`PenaltyRule::ActiveBound`] (the default) `p` is chosen so that `f(q_p)` meets
//!    `eps` to a relative [`FitOptions::eps_tolerance`]: that `q_p` satisfies the optimality
//!    conditions of the constrained problem (`grad (H + lambda S) + p grad f = 0`, `f = eps`,
//!    `p` its multiplier), so its `H + lambda S` is the lowest the bound allows; the paper's
//!    `p*` over-penalizes, and its fit can lie farther from the points than `eps` requires.
//!    The search for `p` rides on the Newton iteration: every step takes the `p` for which
//!    the jump sum after the step meets the bound (a scalar search costing banded
//!    factorizations only, see [`Penalty::Target`]), starting from the least-squares fit at
//!    the starting parameters whose jump sum meets the bound. That search meets the bound
//!    only to its own accuracy, so the `p` of the last step is the multiplier only
//!    approximately: the fit is then polished at `p` held (a few Newton steps to a
//!    stationary point of `H + lambda S + p f`), `p` moved by secant steps on `ln f` against
//!    `ln p` until `f` lands in the tolerance again (usually one to three). Should the
//!    iteration end outside the tolerance (iteration cap), the paper's rule takes over from
//!    the `p` found.
//!
//! Every `q_p` is found by [`Solver::minimize`], warm-started from the previous one.
//! Cost: a few inner minimizations, each `O(n)` per iteration.

use super::coarse::warm_start;
use super::ends::end_pins;
use super::guards::with_warnings;
use super::hermite::HermiteSpline;
use super::knots::{check_knots, start_parameters_for, StartParameters};
use super::multistart::{best_of_starts, MOST_STARTS};
use super::noise::{estimate_noise, NoiseEstimate};
use super::power::PowerForm;
use super::problem::{Problem, State, Taper};
use super::result::CurveFit;
use super::solver::{Penalty, Solver, Stop};
use super::unit_scale::UnitScale;
use crate::{Curve, Error, Point, Result};

pub use crate::core::{shared_end, SHARED_END_TOLERANCE};

/// Iterations spent on the feasible reference `q*` of the paper's bound.
const REFERENCE_ITERATIONS: usize = 5;
/// The free phase of the unconstrained fit, when the ordered phase follows it, stops once a
/// step lowers `F` by less than this times `sigma^2` per coefficient of the spline. Fitting
/// noise, `F` drops by about `sigma^2` per coefficient, and a change `delta` of the curve
/// moves `F` by about `n delta^2`: so a step below this moves the curve by about a fifth of
/// its own standard error, `sigma sqrt(K / n)` for `K` coefficients. There the free steps
/// mostly slide the foot points along the curve, and the ordered phase can start from
/// them (10^5 points of a noisy spiral on 1808 knots: 9 free steps to convergence, the last
/// seven lowering `F` by 0.2% in all; 2 with the rule). Few pieces with many points each
/// move in steps that are small against `F` but large against this, and run to
/// convergence; exact points (`sigma` about 0) too.
const FREE_DECREASE_PER_COEFFICIENT: f64 = 0.04;
/// ... and by less than this share of `F`: where the noise estimate is mostly shape (a
/// sparse digitized section, whose second differences are its curvature, not noise) the
/// rule above would stop on steps that still shape the curve.
const FREE_DECREASE_SHARE: f64 = 1e-3;
/// Iterations of the unconstrained fit with ordered parameters, after the free one.
const ORDERED_ITERATIONS: usize = 8;
/// ... and they stop once a step lowers `F` by less than this share of it.
const ORDERED_MIN_GAIN: f64 = 1e-4;
/// ... or once a step moves the curve across itself (`HermiteSpline::moved_across`) by less
/// than this share of its standard error ([`standard_error`]). After the first ordered step
/// (which brings the ends to their pins) such steps slide pooled runs of foot points along a
/// curve that stays, from the pinned ends a few knots a step. 10^6 noisy points of a spiral
/// (sigma 2.9e-4) on 20 000 knots: 8 ordered steps, none moving the curve by more than 1.2%
/// of its standard error; with the rule 1, 4.5 s against 2.2 s on one thread, the largest
/// distance from the true curve 5.72e-4 both ways and the RMS 2.99e-5 against 3.02e-5. The
/// free phase keeps its own rule: there steps this small can still be shaping a dense,
/// strongly curved stretch (a nose in cosine spacing under noise of 1e-3 of the chord).
const MOVE_SHARE: f64 = 0.1;
/// Minimizations at a held `p` that polish the active bound's fit, at most.
const POLISH_STEPS: usize = 8;

/// The default of [`FitOptions::fairness`].
pub const DEFAULT_FAIRNESS: f64 = 3e-11;
/// The inner minimization may stop once an undamped step moves no point's distance by more
/// than this share of the size of the points (see [`FitOptions::settle_tolerance`]).
const SETTLED_SHARE_OF_SIZE: f64 = 1e-7;
/// The smoothing of a fit on given knots when [`FitOptions::smoothing`] is `None`.
pub const DEFAULT_SMOOTHING: f64 = 0.1;
/// The smoothing of the tolerance mode ([`fit_curve_adaptive`](super::fit_curve_adaptive))
/// when [`FitOptions::smoothing`] is `None`.
pub const TOLERANCE_SMOOTHING: f64 = 0.3;
/// The default of [`FitOptions::settle_tolerance`].
pub const DEFAULT_SETTLE_TOLERANCE: f64 = 1e-2;

/// How the penalty `p` is chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PenaltyRule {
    /// Lower `p` from the paper's bound until the constraint is active (`f` within
    /// [`FitOptions::eps_tolerance`] of `eps`): the solution of the constrained problem.
    #[default]
    ActiveBound,
    /// The paper's rule: `p = H(q*) / eps`, times 10 until `f <= eps`.
    SeedBound,
}

/// Settings of [`fit_curve`].
#[derive(Clone, Debug, PartialEq)]
pub struct FitOptions {
    /// The bound on `f = sum delta_L |J_L|^2`; `f64::INFINITY` (the default) for none: the
    /// unconstrained C^1 fit.
    pub eps: f64,
    /// Inner knots that stay corners (`delta_L = 0`: no bound on their jump). Each must equal
    /// a knot (to `1e-9`).
    pub corners: Vec<f64>,
    /// How `p` is chosen.
    pub penalty: PenaltyRule,
    /// How the points get their starting parameters (chord length by default).
    pub start: StartParameters,
    /// `true` (default): foot-point distances, each point projected onto the curve. `false`:
    /// the starting parameters are kept (an ordinary least-squares fit with given parameters).
    pub foot_points: bool,
    /// The most iterations of the inner minimization per value of `p` (default 200).
    pub max_iterations: usize,
    /// [`PenaltyRule::ActiveBound`] stops when `(1 - eps_tolerance) eps <= f <= eps`
    /// (default `1e-3`).
    pub eps_tolerance: f64,
    /// `rho`: the objective gets the bending energy `lambda int |R''(t)|^2 dt` with
    /// `lambda = rho n` for `n` points on sparse pieces, less on dense ones (see
    /// [`estimate_noise`]; default [`DEFAULT_FAIRNESS`], `3e-11`; 0 for none).
    ///
    /// Why: the foot-point distances do not change when the points slide along the curve, so
    /// without it the unconstrained problem has (nearly) flat directions, the derivatives
    /// `H_L` can drift without bound, and a bound on the jumps can be met by slowing the
    /// curve down where it bends and spending the parameter range on a fold between two
    /// sparse points. The bending energy is smallest for a parameterization that is even
    /// where the curve is straight and slow where it bends, and it penalizes folds. With the
    /// weight proportional to `n` it stays as small relative to the data term however many
    /// points there are; its pull on the shape is about `rho |R''''(t)|` (a few `1e-6` of
    /// the chord on a NACA section at the default).
    pub fairness: f64,
    /// Where the ends lie ([`FitEnds`]; default [`FitEnds::Auto`]: ends whose points
    /// coincide, a closed profile, pinned at that point; other ends of a noisy fit held where
    /// the points towards them say).
    pub ends: FitEnds,
    /// The inner minimization stops once an undamped step changes no point's distance by
    /// more than `settle_tolerance` times the RMS distance (default
    /// [`DEFAULT_SETTLE_TOLERANCE`], `1e-2`), or when the gradient of the objective vanishes
    /// (relative `1e-12`) or no progress is made; 0 leaves only the last two rules. The objective is nearly flat along
    /// reparameterizations of the curve (points sliding along it), where the iteration would
    /// creep for many steps with the shape already settled.
    pub settle_tolerance: f64,
    /// Keep the foot-point parameters in the order of the points (default `true`): a run of
    /// points whose foot points come out of order shares one parameter (their weighted mean,
    /// see docs/methods.md §4). Measured points follow the curve in their order, so their
    /// parameters cannot decrease; without it a noisy cloud at a sharp end or between close
    /// points lets the curve fold back to serve points out of order (a hook or a loop).
    pub ordered: bool,
    /// `s`: the bending weight grows with the noise estimated from the points,
    /// `lambda = (fairness + s (sigma / L)^2) n tau` (see [`estimate_noise`]; 0 for none), the
    /// noise part falling off over the last stretch at either end (docs/methods.md §4, "The
    /// smoothing falls off at the ends"). Noise makes the fit follow it with the freedom of a
    /// defect-2 spline (two coefficients per knot); the term evens that out in proportion to
    /// the noise, and vanishes on exact points. `None` (the default): [`DEFAULT_SMOOTHING`]
    /// (0.1) on given knots, [`TOLERANCE_SMOOTHING`] (0.3) in the tolerance mode. On given
    /// knots less smoothing brings a noisy fit closer to the true curve (the term's bias
    /// across the curve grows with it); the tolerance mode places its knots where the points
    /// are farthest, and there more smoothing keeps wavy coordinates from making the curve
    /// turn to and fro.
    pub smoothing: Option<f64>,
    /// Starts of Pavlov's system (4) on given knots ([`fit_curve`]; default 1, the paper's
    /// chord-length start, or [`FitOptions::start`]): with `N > 1` the fit is solved again
    /// from `N - 1` more starting parameterizations (cumulative chords to the powers 0.5, 0,
    /// 0.75, 0.25, 1.5, 0.875, 0.625, in that order) and the fit with the smallest data term
    /// `H` among those that neither cross themselves nor turn beyond their points is kept;
    /// when none is sound, the first. At most 8. The objective is not convex in the
    /// parameters, so another start can reach a lower `H` (docs/methods.md §4, "Starts").
    /// The tolerance mode and closed fits start from their own rules and leave it unused.
    pub starts: usize,
}

/// Where the ends of a fit lie (docs/methods.md §4, "Ends").
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FitEnds {
    /// Ends whose points coincide (the first and last points within
    /// [`SHARED_END_TOLERANCE`] of the points' size: a closed profile, a sharp trailing edge)
    /// are pinned at that point, so that the curve closes there with a corner; other ends of
    /// a noisy fit are held on their tangent lines where the points towards them say they lie
    /// (noisy points beyond an end pull it outward; two ends that the noise does not tell
    /// apart are held at their common point: `fit/ends.rs`); the ends of a fit on exact
    /// points lie where the foot points put them.
    #[default]
    Auto,
    /// Ends whose points coincide are pinned at that point, as [`FitEnds::Auto`]; other ends
    /// lie where the foot points put them (the tolerance mode, which holds every point, the
    /// ends included, within its tolerance).
    Shared,
    /// Pinned to the first and last points (`R(0) = r_1`, `R(1) = r_n`): for a contour
    /// sampled from known end points.
    Pinned,
    /// Where the foot points put them, whether the end points coincide or not.
    Free,
}

impl Default for FitOptions {
    fn default() -> Self {
        FitOptions {
            eps: f64::INFINITY,
            corners: Vec::new(),
            penalty: PenaltyRule::default(),
            start: StartParameters::default(),
            foot_points: true,
            max_iterations: 200,
            eps_tolerance: 1e-3,
            fairness: DEFAULT_FAIRNESS,
            ends: FitEnds::Auto,
            settle_tolerance: DEFAULT_SETTLE_TOLERANCE,
            ordered: true,
            smoothing: None,
            starts: 1,
        }
    }
}

/// Checks the points, the knots and the settings of a fit call; returns `delta_L` per knot.
/// Runs once per public fit call: its refits check only their knots ([`knot_weights`]).
pub(crate) fn check_inputs<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    options: &Settings<'_>,
) -> Result<Vec<f64>> {
    #[cfg(test)]
    checks::count();
    if points.len() < 3 {
        return Err(Error::TooFewPoints {
            what: "a fit",
            needed: 3,
            got: points.len(),
        });
    }
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinitePoint { index });
    }
    check_knots(knots)?;
    check_settings(options)?;
    corner_weights(knots, options.corners)
}

/// Checks `knots` of a refit (its points and settings checked by [`check_inputs`]); returns
/// `delta_L` per knot.
pub(crate) fn knot_weights(knots: &[f64], corners: &[f64]) -> Result<Vec<f64>> {
    check_knots(knots)?;
    corner_weights(knots, corners)
}

/// `delta_L` per knot: 1, 0 at the end knots and at the `corners` (each an inner knot).
fn corner_weights(knots: &[f64], corners: &[f64]) -> Result<Vec<f64>> {
    let mut weights = vec![1.0; knots.len()];
    weights[0] = 0.0;
    weights[knots.len() - 1] = 0.0;
    for &corner in corners {
        let at = knots[1..knots.len() - 1]
            .iter()
            .position(|&k| (k - corner).abs() <= 1e-9)
            .ok_or(Error::InvalidSetting {
                name: "corner",
                value: corner,
                reason: "not an inner knot",
            })?;
        weights[at + 1] = 0.0;
    }
    Ok(weights)
}

/// The count of [`check_inputs`] calls on this thread, for the tests that a fit call checks
/// its inputs once.
#[cfg(test)]
pub(crate) mod checks {
    use std::cell::Cell;

    thread_local! {
        static CHECKS: Cell<usize> = const { Cell::new(0) };
    }

    /// Counts one check.
    pub(crate) fn count() {
        CHECKS.with(|c| c.set(c.get() + 1));
    }

    /// The checks on this thread so far.
    pub(crate) fn so_far() -> usize {
        CHECKS.with(Cell::get)
    }
}

/// Checks `eps`, the tolerance on it, the iteration count and the corner values.
pub(crate) fn check_settings(options: &Settings<'_>) -> Result<()> {
    if options.eps.is_nan() || options.eps <= 0.0 {
        return Err(Error::InvalidSetting {
            name: "eps",
            value: options.eps,
            reason: "must be positive (infinity for no bound)",
        });
    }
    if !(options.eps_tolerance > 0.0 && options.eps_tolerance < 1.0) {
        return Err(Error::InvalidSetting {
            name: "eps_tolerance",
            value: options.eps_tolerance,
            reason: "must lie strictly between 0 and 1",
        });
    }
    if !(options.fairness >= 0.0 && options.fairness.is_finite()) {
        return Err(Error::InvalidSetting {
            name: "fairness",
            value: options.fairness,
            reason: "must be zero or positive and finite",
        });
    }
    if let Some(smoothing) = options.smoothing {
        if !(smoothing >= 0.0 && smoothing.is_finite()) {
            return Err(Error::InvalidSetting {
                name: "smoothing",
                value: smoothing,
                reason: "must be zero or positive and finite",
            });
        }
    }
    if !(options.settle_tolerance >= 0.0 && options.settle_tolerance < 1.0) {
        return Err(Error::InvalidSetting {
            name: "settle_tolerance",
            value: options.settle_tolerance,
            reason: "must lie in [0, 1)",
        });
    }
    if !(1..=MOST_STARTS).contains(&options.starts) {
        return Err(Error::InvalidSetting {
            name: "starts",
            value: options.starts as f64,
            reason: "must be 1 to 8",
        });
    }
    if options.max_iterations == 0 {
        return Err(Error::InvalidSetting {
            name: "max_iterations",
            value: 0.0,
            reason: "must be at least 1",
        });
    }
    for &corner in options.corners {
        if !(corner > 0.0 && corner < 1.0) {
            return Err(Error::InvalidSetting {
                name: "corner",
                value: corner,
                reason: "must lie strictly between 0 and 1",
            });
        }
    }
    Ok(())
}

/// The bytes a fit works in per knot of its spline in `dimension` coordinates: the knot and
/// its spline values and derivatives, the Newton solver's per-piece blocks (16 and `16 d^2`
/// numbers, twice), its vectors of `2 d` unknowns and the banded normal equations (bandwidth
/// `4 d`): `8 (32 + 48 d^2 + 2 d (16 + 8 d))`. A front end checks a count of knots against
/// the memory it allows before the knots are made.
///
/// ```
/// use karkas::fit::work_bytes_per_knot;
/// assert_eq!(work_bytes_per_knot(2), 2816);
/// assert_eq!(work_bytes_per_knot(3), 5632);
/// ```
pub fn work_bytes_per_knot(dimension: usize) -> u128 {
    let d = dimension as u128;
    8 * (32 + 48 * d * d + 2 * d * (16 + 8 * d))
}

/// Fits a C^1 cubic Hermite spline on `knots` (`0 = T_1 < ... < T_N = 1`) to the ordered
/// `points`, minimizing the sum of squared foot-point distances subject to
/// `sum delta_L |J_L|^2 <= options.eps` (see the [module docs](crate::fit)).
///
/// Errors: fewer than 3 points, a non-finite coordinate, all points coinciding; invalid
/// knots ([`Error::InvalidKnot`]); invalid settings ([`Error::InvalidSetting`]);
/// [`Error::SingularSystem`] when the points cannot determine the spline (possible only
/// without the bending term, `fairness: 0`: the unconstrained fit then needs points on every
/// piece, about three per pair of neighbouring pieces).
///
/// Forty-one points of a half circle on five uniform knots:
///
/// ```
/// use karkas::fit::{fit_curve, FitOptions};
/// use karkas::{Curve, Point};
///
/// let points: Vec<Point<2>> = (0..=40)
///     .map(|k| {
///         let a = std::f64::consts::PI * k as f64 / 40.0;
///         Point([a.cos(), a.sin()])
///     })
///     .collect();
/// let fit = fit_curve(&points, &[0.0, 0.25, 0.5, 0.75, 1.0], &FitOptions::default())?;
/// assert!(fit.distances.iter().all(|&d| d < 1e-3));
/// assert!((fit.spline.eval(0.5).norm() - 1.0).abs() < 1e-3);
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn fit_curve<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    options: &FitOptions,
) -> Result<CurveFit<D>> {
    let weights = check_inputs(points, knots, &Settings::of(options))?;
    let unit = UnitScale::of(points);
    let scaled = unit.points(points);
    let settings = Settings::in_fit_units(options, unit);
    let noise = estimate_noise(&scaled);
    let fit = if settings.starts > 1 {
        best_of_starts(&scaled, settings.start, settings.starts, &noise, |start| {
            fit_checked(&scaled, knots, &weights, start, &settings, &noise)
        })
    } else {
        let start = start_parameters_for(&scaled, settings.start, noise.sigma)?;
        fit_checked(&scaled, knots, &weights, start, &settings, &noise)
    };
    // The moved copy of the points is released before the shape guards look at the fit.
    drop(scaled);
    fit.map(|fit| with_warnings(points, unit.restore(fit, pinned_ends(points, options))))
}

/// The standard error of a least-squares spline on `knots` knots (`2 knots` coefficients per
/// coordinate) fitted to the `n` points of `state`: `s sqrt(2 knots / n)`, with `s` the
/// smaller of the noise estimate and the RMS distance of the points from the fit (on sparse
/// points the estimate from second differences is mostly the curve's own curvature). 0 when
/// not finite, and when the points lie farther apart on average than `s` along the curve
/// (its length taken between the values at the knots): runs of foot points pool only where
/// the noise along the curve exceeds the spacing of the points; elsewhere every foot point
/// shapes the curve.
fn standard_error<const D: usize>(noise: &NoiseEstimate, state: &State<D>, knots: usize) -> f64 {
    let n = state.dist_sq.len() as f64;
    let spread = noise.sigma.min((state.data_term() / n).sqrt());
    let length: f64 = state
        .spline
        .values()
        .windows(2)
        .map(|w| (w[1] - w[0]).norm())
        .sum();
    // False also when either side is NaN.
    let pooled = length < spread * (n - 1.0);
    if !pooled {
        return 0.0;
    }
    let error = spread * (2.0 * knots as f64 / n).sqrt();
    if error.is_finite() {
        error
    } else {
        0.0
    }
}

/// The points `options` pins the ends to (the values a restored fit keeps exactly): the first
/// and last points for [`FitEnds::Pinned`], their common point for ends that coincide under
/// [`FitEnds::Auto`] and [`FitEnds::Shared`].
pub(crate) fn pinned_ends<const D: usize>(
    points: &[Point<D>],
    options: &FitOptions,
) -> Option<[Point<D>; 2]> {
    match (options.ends, points.first(), points.last()) {
        (FitEnds::Pinned, Some(&first), Some(&last)) => Some([first, last]),
        (FitEnds::Auto | FitEnds::Shared, _, _) => shared_end(points).map(|p| [p, p]),
        _ => None,
    }
}

/// The fit after the inputs were checked, `noise` estimated from the points: the
/// unconstrained fit ([`Run::unconstrained`]); when its jumps exceed the bound, the paper's
/// bound `p*` from a feasible reference ([`feasible_reference`]), then the active bound
/// ([`Run::active_bound`]) or the paper's rule ([`Run::paper_rule`]).
pub(crate) fn fit_checked<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    weights: &[f64],
    start: Vec<f64>,
    options: &Settings<'_>,
    noise: &NoiseEstimate,
) -> Result<CurveFit<D>> {
    let mut state = State::<D>::blank(knots, start.clone());
    let mut run = Run::new(points, knots, weights, start, *options, *noise, &state);
    if run.unconstrained(&mut state)? {
        return Ok(run.finish(state, 0.0, 0.0));
    }
    // The constrained fit runs with free foot points (with ordered ones the search for `p`
    // creeps: the pooled runs slow the Newton model down); its parameters are ordered at the
    // end, the spline kept.
    run.solver.set_ordered(false);
    // 2. The paper's bound from a feasible q*: the fit on the knots {0, corners, 1}.
    let coarse = reference_knots(knots, weights);
    let (reference, exact) = feasible_reference(run.problem, &coarse, knots, &run.start, run.stop);
    if reference <= 0.0 {
        // The points lie exactly on a spline without bounded jumps: it is the answer.
        return Ok(run.finish(exact, 0.0, 0.0));
    }
    let seed_bound = reference / options.eps;
    // The constrained fit starts again from the starting parameters: the unconstrained fit
    // can be far from the bound, and its foot points no guide.
    let mut p = seed_bound;
    state.params.copy_from_slice(&run.start);
    run.solver.solve_fixed(&mut state, p)?;
    run.solver.project(&mut state);
    if options.penalty == PenaltyRule::ActiveBound {
        match run.active_bound(&mut state, p)? {
            Active::Met(met, p) => return Ok(run.finish(*met, p, seed_bound)),
            // Not settled in the window (iteration cap): hold the p found, raised if need be,
            // but never below the paper's p* (a search that collapsed towards 0 would
            // otherwise leave the paper's rule 40 decades short).
            Active::Missed(found) => p = found.max(seed_bound).max(f64::MIN_POSITIVE),
        }
    }
    run.paper_rule(state, p, seed_bound)
}

/// The knots `{0, corners, 1}` of `knots` (`weights` 0 at a corner): a spline on them has no
/// jump at any knot with `delta_L = 1`.
fn reference_knots(knots: &[f64], weights: &[f64]) -> Vec<f64> {
    let mut coarse: Vec<f64> = knots
        .iter()
        .zip(weights)
        .enumerate()
        .filter(|&(l, (_, &w))| l == 0 || l + 1 == knots.len() || w == 0.0)
        .map(|(_, (&k, _))| k)
        .collect();
    coarse.dedup();
    coarse
}

/// How the active bound ended.
enum Active<const D: usize> {
    /// Within the window of the bound: the fit and its `p`.
    Met(Box<State<D>>, f64),
    /// Outside it (iteration cap): the `p` found.
    Missed(f64),
}

/// One fit on given knots under way: the problem, its solver, the stopping rule and the
/// iterations spent.
struct Run<'a, const D: usize> {
    points: &'a [Point<D>],
    knots: &'a [f64],
    weights: &'a [f64],
    start: Vec<f64>,
    options: Settings<'a>,
    noise: NoiseEstimate,
    problem: Problem<'a, D>,
    solver: Solver<'a, D>,
    stop: Stop,
    iterations: usize,
}

impl<'a, const D: usize> Run<'a, D> {
    /// The problem of `options` on `points` and `knots`, its bending weight from `noise`, and
    /// its solver on the spline of `state`.
    fn new(
        points: &'a [Point<D>],
        knots: &'a [f64],
        weights: &'a [f64],
        start: Vec<f64>,
        options: Settings<'a>,
        noise: NoiseEstimate,
        state: &State<D>,
    ) -> Self {
        let (fairness, smoothing) = noise.bending_parts(
            points.len(),
            knots.len() - 1,
            options.fairness,
            options.smoothing.unwrap_or(DEFAULT_SMOOTHING),
        );
        let problem = Problem {
            points,
            delta: weights,
            bending: fairness + smoothing,
            taper: Taper::towards_ends(fairness, smoothing, points.len()),
            pins: match options.ends {
                FitEnds::Pinned => Some([points[0], points[points.len() - 1]]),
                FitEnds::Auto | FitEnds::Shared => shared_end(points).map(|p| [p, p]),
                FitEnds::Free => None,
            },
            foot_points: options.foot_points,
            ordered: options.ordered,
        };
        let stop = Stop {
            floor: SETTLED_SHARE_OF_SIZE * noise.size,
            ..Stop::new(options.max_iterations, options.settle_tolerance)
        };
        let solver = Solver::new(
            Problem {
                ordered: false,
                ..problem
            },
            &state.spline,
        );
        Run {
            points,
            knots,
            weights,
            start,
            options,
            noise,
            problem,
            solver,
            stop,
            iterations: 0,
        }
    }

    /// The result from `state` at the penalty `p` (every point projected once more).
    fn finish(&mut self, state: State<D>, p: f64, seed_bound: f64) -> CurveFit<D> {
        let state = projected(&mut self.solver, self.problem.ordered, state);
        self.solver.release_trial();
        self.start = Vec::new();
        let taper = self.problem.taper;
        let data_term = state.data_term();
        // The squared distances become the distances in place.
        let mut distances = state.dist_sq;
        for d in &mut distances {
            *d = d.sqrt();
        }
        CurveFit {
            jump_sum: state.spline.jump_penalty(self.weights),
            bending_energy: taper.bending_energy(&state.spline),
            bending_shares: self
                .knots
                .windows(2)
                .map(|w| taper.share(w[0], w[1]))
                .collect(),
            bending_weight: self.problem.bending,
            data_term,
            distances,
            parameters: state.params,
            spline: state.spline,
            penalty: p,
            seed_bound,
            weights: self.weights.to_vec(),
            iterations: self.iterations,
            noise: self.noise,
            warnings: Vec::new(),
        }
    }

    /// `f`, the weighted sum of squared jumps of `state`.
    fn jumps(&self, state: &State<D>) -> f64 {
        state.spline.jump_penalty(self.weights)
    }

    /// Step 1: The unconstrained fit, into `state`: `true` when it meets the bound (the answer).
    ///
    /// First with every foot point free (the Newton model is exact for free foot points, and
    /// converges in a few steps, see [`Run::free_phase`]), then with the parameters ordered
    /// from there ([`Run::ordered_phase`]). Dense points start from the fit of a subset
    /// ([`warm_start`]). Between the two phases the ends of a noisy fit are pinned at their
    /// estimates ([`Run::estimated_ends`]); they stay pinned for the rest of the fit, the
    /// constrained one included. Too few points for it: `state` is the fit with the jumps
    /// held to zero.
    fn unconstrained(&mut self, state: &mut State<D>) -> Result<bool> {
        let free = Problem {
            ordered: false,
            ..self.problem
        };
        let first = match warm_start(&free, &self.start, self.stop, state) {
            Some(done) => {
                self.iterations += done;
                Ok(())
            }
            None => self.solver.solve_fixed(state, 0.0),
        };
        match first {
            Ok(()) => {
                self.free_phase(state)?;
                self.estimated_ends(state)?;
                if self.problem.ordered {
                    self.ordered_phase(state)?;
                }
                Ok(self.jumps(state) <= self.options.eps)
            }
            Err(e) if self.options.eps.is_infinite() => Err(e),
            Err(_) => {
                // Too few points for the unconstrained fit: start from the fit with the jumps
                // held to zero (always determined when the points determine one cubic).
                state.params.copy_from_slice(&self.start);
                self.solver.solve_fixed(state, 1.0)?;
                self.solver.project(state);
                Ok(false)
            }
        }
    }

    /// The free phase: every foot point free; with the ordered phase to follow, until a step
    /// lowers `F` by less than [`FREE_DECREASE_PER_COEFFICIENT`] `sigma^2` per coefficient
    /// and [`FREE_DECREASE_SHARE`] of `F`.
    fn free_phase(&mut self, state: &mut State<D>) -> Result<()> {
        self.solver.project(state);
        let coefficients = (2 * D * self.knots.len()) as f64;
        let hand_over = FREE_DECREASE_PER_COEFFICIENT * coefficients * self.noise.sigma.powi(2);
        let free_stop = Stop {
            min_decrease: if self.problem.ordered && hand_over.is_finite() {
                hand_over
            } else {
                0.0
            },
            decrease_share: FREE_DECREASE_SHARE,
            ..self.stop
        };
        self.iterations += self
            .solver
            .minimize(state, Penalty::Fixed(0.0), free_stop)?
            .0;
        Ok(())
    }

    /// The ends of a noisy fit under [`FitEnds::Auto`], not pinned otherwise, held from here
    /// on where the points say ([`end_pins`]); without the ordered phase the free fit runs
    /// again from there.
    fn estimated_ends(&mut self, state: &mut State<D>) -> Result<()> {
        let estimate = self.options.ends == FitEnds::Auto
            && self.problem.pins.is_none()
            && self.problem.foot_points;
        let Some(pins) = estimate
            .then(|| end_pins(self.points, self.noise.sigma, &state.spline))
            .flatten()
        else {
            return Ok(());
        };
        self.problem.pins = Some(pins);
        self.solver.set_pins(pins, state);
        if !self.problem.ordered {
            self.solver.project(state);
            self.iterations += self
                .solver
                .minimize(state, Penalty::Fixed(0.0), self.stop)?
                .0;
        }
        Ok(())
    }

    /// The ordered phase: the parameters ordered (runs pooled out of order) for at most
    /// [`ORDERED_ITERATIONS`] steps. Every projection orders the parameters, so the result is
    /// ordered however many steps run, and the pooled runs, which the model treats as free
    /// foot points, slow it down; it also ends on a step that hardly moves the curve
    /// ([`MOVE_SHARE`]).
    fn ordered_phase(&mut self, state: &mut State<D>) -> Result<()> {
        self.solver.set_ordered(true);
        self.solver.project(state);
        let ordered = Stop {
            max_iterations: self.stop.max_iterations.min(ORDERED_ITERATIONS),
            min_gain: ORDERED_MIN_GAIN,
            min_move: MOVE_SHARE * standard_error(&self.noise, state, self.knots.len()),
            ..self.stop
        };
        self.iterations += self.solver.minimize(state, Penalty::Fixed(0.0), ordered)?.0;
        Ok(())
    }

    /// Step 3: The active bound, from the fit at the paper's `p*` in `state` (stiff, so that the
    /// foot points settle on a smooth curve first): `p` is then chosen at every Newton step,
    /// and the fit polished ([`Run::polish`]).
    fn active_bound(&mut self, state: &mut State<D>, p: f64) -> Result<Active<D>> {
        let stop = self.stop;
        let (eps, tolerance) = (self.options.eps, self.options.eps_tolerance);
        let settle = Stop {
            tolerance: stop.tolerance.max(DEFAULT_SETTLE_TOLERANCE),
            ..stop
        };
        self.iterations += self.solver.minimize(state, Penalty::Fixed(p), settle)?.0;
        let lowest = (1.0 - tolerance) * eps;
        let penalty = Penalty::Target {
            target: penalty_target(eps, tolerance),
            lowest,
            highest: eps,
            guess: p,
        };
        let (done, found) = self.solver.minimize(state, penalty, stop)?;
        self.iterations += done;
        let f = self.jumps(state);
        if f <= eps && f >= lowest {
            return self.polish(state, found);
        }
        Ok(Active::Missed(found))
    }

    /// The fit of the active bound polished. The search for `p` rides on the steps, so the
    /// `found` is the multiplier only to the accuracy of that search: the fit is polished at
    /// `p` held (a stationary point of `H + lambda S + p f`), `p` moved by secant steps on
    /// `ln f` against `ln p` until `f` lands in the window again; when it does not within
    /// [`POLISH_STEPS`], `state` at `found` stands.
    fn polish(&mut self, state: &mut State<D>, found: f64) -> Result<Active<D>> {
        let (eps, tolerance) = (self.options.eps, self.options.eps_tolerance);
        let lowest = (1.0 - tolerance) * eps;
        let ln_target = penalty_target(eps, tolerance).ln();
        let (mut ln_p, mut slope, mut last) = (found.ln(), -1.0, None::<(f64, f64)>);
        let mut polished = state.clone();
        // (p = 0: the bound is not active for the model, nothing to polish.)
        let steps = if found > 0.0 { POLISH_STEPS } else { 0 };
        for _ in 0..steps {
            let p = ln_p.exp();
            self.iterations += self
                .solver
                .minimize(&mut polished, Penalty::Fixed(p), self.stop)?
                .0;
            let f = self.jumps(&polished);
            if f <= eps && f >= lowest {
                return Ok(Active::Met(Box::new(polished), p));
            }
            let miss = f.max(f64::MIN_POSITIVE).ln() - ln_target;
            if let Some((ln_p0, miss0)) = last {
                if ln_p != ln_p0 && miss != miss0 {
                    slope = ((miss - miss0) / (ln_p - ln_p0)).min(-1e-3);
                }
            }
            last = Some((ln_p, miss));
            ln_p -= miss / slope;
        }
        Ok(Active::Met(
            Box::new(std::mem::replace(state, polished)),
            found,
        ))
    }

    /// The paper's rule from `state`: `p`, times 10 until the bound holds.
    fn paper_rule(
        mut self,
        mut state: State<D>,
        mut p: f64,
        seed_bound: f64,
    ) -> Result<CurveFit<D>> {
        for _ in 0..=40 {
            self.iterations += self
                .solver
                .minimize(&mut state, Penalty::Fixed(p), self.stop)?
                .0;
            if self.jumps(&state) <= self.options.eps {
                return Ok(self.finish(state, p, seed_bound));
            }
            p *= 10.0;
        }
        Err(unreachable_bound(self.options.eps))
    }
}

/// `state` with every point projected once more onto its spline, the parameters ordered when
/// `ordered`: the alternation step may keep held parameters (when the ordered projection
/// loses to them), and the constrained fit runs with free foot points; the reported
/// parameters are foot points (or ordered runs of them).
fn projected<const D: usize>(
    solver: &mut Solver<'_, D>,
    ordered: bool,
    mut state: State<D>,
) -> State<D> {
    solver.set_ordered(ordered);
    solver.project(&mut state);
    state
}

/// The jump sum aimed at for the active bound: the middle of its window.
fn penalty_target(eps: f64, tolerance: f64) -> f64 {
    eps * (1.0 - 0.5 * tolerance)
}

/// The error for a bound that the penalty could not enforce.
fn unreachable_bound(eps: f64) -> Error {
    Error::InvalidSetting {
        name: "eps",
        value: eps,
        reason: "the jump bound could not be met (the penalty grew past 1e40 times its start)",
    }
}

/// `(H + lambda S)(q*)` of a feasible `q*` (no jump at any knot with `delta_L = 1`): the fit on
/// the knots `coarse` carried over to `knots` (the same curve, values and derivatives at the
/// finer knots), or, when that fit cannot be made, the straight segment from the first point
/// to the last; and that `q*` (the answer when `H + lambda S` vanishes).
fn feasible_reference<const D: usize>(
    problem: Problem<D>,
    coarse: &[f64],
    knots: &[f64],
    start: &[f64],
    stop: Stop,
) -> (f64, State<D>) {
    let no_weights = vec![0.0; coarse.len()];
    let coarse_problem = Problem {
        delta: &no_weights,
        ..problem
    };
    let mut state = State::<D>::blank(coarse, start.to_vec());
    let mut solver = Solver::new(coarse_problem, &state.spline);
    let fitted = solver.solve_fixed(&mut state, 0.0).is_ok() && {
        solver.project(&mut state);
        // Any feasible q* gives a valid bound: a few iterations suffice.
        let stop = Stop {
            max_iterations: stop.max_iterations.min(REFERENCE_ITERATIONS),
            ..stop
        };
        solver
            .minimize(&mut state, Penalty::Fixed(0.0), stop)
            .is_ok()
    };
    let spline = if fitted {
        HermiteSpline::from_parts(
            knots.to_vec(),
            knots.iter().map(|&t| state.spline.eval(t)).collect(),
            knots.iter().map(|&t| state.spline.deriv(t, 1)).collect(),
        )
    } else {
        let (a, b) = (problem.points[0], problem.points[problem.points.len() - 1]);
        HermiteSpline::from_parts(
            knots.to_vec(),
            knots.iter().map(|&t| a.add_scaled(t, b - a)).collect(),
            vec![b - a; knots.len()],
        )
    };
    let mut lifted = State {
        spline,
        params: if fitted { state.params } else { start.to_vec() },
        dist_sq: vec![0.0; start.len()],
        order: Default::default(),
    };
    let mut form = PowerForm::new(&lifted.spline);
    super::project_all::project(problem.points, problem.projection(), &mut lifted, &mut form);
    let value = lifted.data_term() + problem.bending_term(&lifted.spline);
    (value, lifted)
}

// The settings one fit runs with: the caller's options in the units of the fit, with the
// decisions the library takes for its own rounds and refits (fewer iterations, shared ends,
// more smoothing, a stiffer bending weight) made on this private copy, never on the public
// options.

/// [`FitOptions`] as one fit runs with them: every field but the corners and the starting
/// rule copied (the struct is `Copy`, so an internal decision is a struct update, not a
/// clone of the caller's options), `eps` in the units of the fit.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Settings<'a> {
    /// The bound on the jump sum, in the units of the fit.
    pub eps: f64,
    pub corners: &'a [f64],
    pub penalty: PenaltyRule,
    pub start: &'a StartParameters,
    pub foot_points: bool,
    pub max_iterations: usize,
    pub eps_tolerance: f64,
    pub fairness: f64,
    pub ends: FitEnds,
    pub settle_tolerance: f64,
    pub ordered: bool,
    pub smoothing: Option<f64>,
    pub starts: usize,
}

impl<'a> Settings<'a> {
    /// `options` for points divided by `unit`'s scale: the bound `eps` on the squared jumps
    /// scales with them; the other settings are dimensionless.
    pub(crate) fn in_fit_units<const D: usize>(
        options: &'a FitOptions,
        unit: UnitScale<D>,
    ) -> Self {
        let eps = if unit.scale() == 1.0 {
            options.eps
        } else {
            unit.squared_length(options.eps)
        };
        Settings {
            eps,
            ..Settings::of(options)
        }
    }

    /// `options` as they are.
    pub(crate) fn of(options: &'a FitOptions) -> Self {
        let FitOptions {
            eps,
            ref corners,
            penalty,
            ref start,
            foot_points,
            max_iterations,
            eps_tolerance,
            fairness,
            ends,
            settle_tolerance,
            ordered,
            smoothing,
            starts,
        } = *options;
        Settings {
            eps,
            corners,
            penalty,
            start,
            foot_points,
            max_iterations,
            eps_tolerance,
            fairness,
            ends,
            settle_tolerance,
            ordered,
            smoothing,
            starts,
        }
    }
}

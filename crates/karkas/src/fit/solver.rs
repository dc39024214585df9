//! The inner problem of the penalty method: minimize
//!
//! ```text
//! F(q) = sum_i min_t |R(t) - r_i|^2 + p sum_L delta_L |J_L|^2 + lambda int |R''|^2 dt
//! ```
//!
//! over the spline coefficients `q = {R_L, H_L}` (the last term is the bending energy, see
//! [`FitOptions::fairness`](super::FitOptions::fairness)), optionally with the end values
//! pinned to the first and last points, with `p` held or chosen per step ([`Penalty`]).
//!
//! - Newton's method on the reduced objective (the `t_i` eliminated by projection, see
//!   [`newton`](super::newton) and [`gradient`](super::gradient)): each iteration assembles the banded Hessian in one pass over
//!   the points, solves it by banded Cholesky, moves the coefficients and re-projects every
//!   point from its previous foot point ([`foot_point_near`](super::project::foot_point_near)).
//! - Levenberg–Marquardt damping (Marquardt's scaling): a step is taken only when the true
//!   objective, after re-projecting every point, decreases; the damping follows the ratio of
//!   the actual to the predicted decrease; each damping is tried with the exact model, then
//!   with the safe one (the safe one first once an exact step failed where the safe one
//!   succeeded: near the minimum the exact model's steps slide the points along the curve
//!   and are refused, each at the cost of a projection). When no damped step succeeds, the paper's alternation step (the
//!   least-squares spline with the parameters held, [`solve_fixed`], then projection) is taken
//!   instead; it never increases `F`. Near the minimum, where `F` no longer changes in
//!   floating point, a step is taken when it shrinks the gradient.
//! - The iteration stops when the gradient vanishes (relative `1e-12`), when an undamped step
//!   changes no point's distance by more than [`Stop::tolerance`] times the RMS distance,
//!   after iterations that lower neither `F` nor the gradient, after a step that moves the
//!   curve across itself by less than [`Stop::min_move`], or after
//!   [`Stop::max_iterations`]. The
//!   second rule exists because `F` is nearly flat along reparameterizations of the curve
//!   (points sliding along it): there the iterates creep, lowering `F` by tiny amounts for
//!   many iterations, while the shape and the distances have settled.
//!
//! The first and last points keep `t = 0` and `t = 1`: they anchor the ends of the curve
//! (the paper minimizes over the `t_i` of the inner points only).
//!
//! Each iteration is `O(n D^2)` for `n` points in R^D plus `O(N D^3)` for `N` knots, and
//! allocates nothing: every buffer lives in the [`Solver`].

use super::fixed::{solve_fixed, FixedScratch};
use super::gradient::{accumulate_gradient, Gradient};
use super::hermite::HermiteSpline;
use super::newton::NewtonModel;
use super::power::PowerForm;
use super::problem::{objective, penalties, Problem, Projection, State};
use super::project_all::{project, project_within};
use crate::solve::BandedLeastSquares;
use crate::{Error, Point, Result};

/// Stop when the largest gradient entry is below this times the gradient's scale.
const GRADIENT_TOLERANCE: f64 = 1e-12;
/// Stop after this many iterations in a row without progress: lowering `F` by more than
/// `PROGRESS` (relative) or the gradient by the factor `GRADIENT_PROGRESS`.
const STALLS: usize = 3;
/// See `STALLS`.
const PROGRESS: f64 = 1e-13;
/// See `STALLS`.
const GRADIENT_PROGRESS: f64 = 0.99;
/// Damping values tried per iteration before the alternation step is taken instead.
const DAMPING_TRIES: usize = 6;
/// The damping of the first Newton step.
const INITIAL_DAMPING: f64 = 1e-6;
/// A step counts for the settled-distances test only when damped by at most this (a damped
/// step is short, and its small changes say nothing about convergence).
const SETTLED_DAMPING: f64 = 1e-3;

/// How the penalty `p` is set during a minimization.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Penalty {
    /// `p` held.
    Fixed(f64),
    /// `p` chosen at every Newton step so that the jump sum after the step meets `target`
    /// (the bound made active), starting next to `guess`.
    Target {
        /// The jump sum aimed at.
        target: f64,
        /// The iteration ends only with the jump sum in `[lowest, highest]`.
        lowest: f64,
        /// See `lowest`.
        highest: f64,
        /// Where the search of the first step starts.
        guess: f64,
    },
}

/// When the inner minimization stops.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Stop {
    /// The most iterations.
    pub max_iterations: usize,
    /// Stop once an undamped step changes no distance by more than this times the RMS
    /// distance (0: never).
    pub tolerance: f64,
    /// ... or by more than this (an absolute floor: changes far below the size of the
    /// points say nothing about the shape; 0 for none).
    pub floor: f64,
    /// Stop once a step lowers `F` by less than this share of `F` (0: never). With ordered
    /// parameters `F` keeps creeping down as pooled runs split and merge while the curve
    /// no longer moves: the rule ends that phase.
    pub min_gain: f64,
    /// ... or by less than this, absolutely, and less than `decrease_share` of `F` (0: never).
    pub min_decrease: f64,
    /// See `min_decrease`.
    pub decrease_share: f64,
    /// Stop once a step moves the curve across itself by less than this
    /// ([`HermiteSpline::moved_across`]; 0: never). With ordered parameters the steps after
    /// the curve has settled only slide pooled runs of foot points along it, and the slide
    /// travels a few knots a step: `F` falls for many steps while the shape stays.
    pub min_move: f64,
}

impl Stop {
    /// At most `max_iterations`, settled at `tolerance`; every other rule off.
    pub(crate) fn new(max_iterations: usize, tolerance: f64) -> Self {
        Stop {
            max_iterations,
            tolerance,
            floor: 0.0,
            min_gain: 0.0,
            min_decrease: 0.0,
            decrease_share: 0.0,
            min_move: 0.0,
        }
    }
}

/// Buffers and settings of the inner minimization.
pub(crate) struct Solver<'a, const D: usize> {
    problem: Problem<'a, D>,
    coord: BandedLeastSquares,
    fixed: FixedScratch<D>,
    /// The Newton model at the current state.
    model: NewtonModel<D>,
    /// The gradient at a trial state.
    trial_gradient: Gradient,
    /// Coefficients in the layout of [`BandedLeastSquares`] (`D` per unknown).
    x: Vec<f64>,
    /// The power form of the spline being projected onto.
    power: PowerForm<D>,
    trial: State<D>,
}

impl<'a, const D: usize> Solver<'a, D> {
    /// A solver for `problem` on the knots of `template` (whose coefficients only size the
    /// buffers).
    pub(crate) fn new(problem: Problem<'a, D>, template: &HermiteSpline<D>) -> Self {
        let n_knots = template.knots().len();
        let pieces = n_knots - 1;
        let unknowns = 2 * n_knots * D;
        let n = problem.points.len();
        Solver {
            problem,
            coord: BandedLeastSquares::new(2 * n_knots, 6, D),
            fixed: FixedScratch::new(n, pieces),
            model: NewtonModel::new(unknowns, pieces),
            trial_gradient: Gradient::new(unknowns),
            x: vec![0.0; unknowns],
            power: PowerForm::new(template),
            trial: State {
                spline: template.clone(),
                params: vec![0.0; n],
                dist_sq: vec![0.0; n],
                order: Default::default(),
            },
        }
    }

    /// Releases the per-point buffers of the trial state: the solver takes no further step
    /// (a fit's result is being built; only [`Solver::project`] may follow).
    pub fn release_trial(&mut self) {
        self.trial.params = Vec::new();
        self.trial.dist_sq = Vec::new();
        self.trial.order = Default::default();
    }

    /// Keeps the foot-point parameters in the order of the points from now on (or not).
    pub fn set_ordered(&mut self, ordered: bool) {
        self.problem.ordered = ordered;
    }

    /// Pins the end values to `pins` from now on, and moves the ends of `state.spline` there
    /// (its parameters and distances are left for the next projection).
    pub fn set_pins(&mut self, pins: [Point<D>; 2], state: &mut State<D>) {
        self.problem.pins = Some(pins);
        let (values, _) = state.spline.coefficients_mut();
        let last = values.len() - 1;
        values[0] = pins[0];
        values[last] = pins[1];
    }

    /// `F = H + p f + lambda S` of a state.
    pub fn objective(&self, state: &State<D>, p: f64) -> f64 {
        objective(&self.problem, state, p)
    }

    /// The least-squares spline for the parameters of `state` held fixed, into
    /// `state.spline` (distances not refreshed).
    ///
    /// Errors: [`Error::SingularSystem`] when the points and the other rows do not determine
    /// every coefficient (too few points on some pieces).
    pub fn solve_fixed(&mut self, state: &mut State<D>, p: f64) -> Result<()> {
        solve_fixed(
            &self.problem,
            &mut self.coord,
            &mut self.fixed,
            &mut self.x,
            state,
            p,
        )
    }

    /// Re-projects every inner point onto `state.spline` from its current parameter (the ends
    /// keep theirs), and refreshes the squared distances.
    pub fn project(&mut self, state: &mut State<D>) {
        project(
            self.problem.points,
            self.problem.projection(),
            state,
            &mut self.power,
        );
    }

    /// The state `state + step` into `self.trial`, projected; returns its `F`, or infinity
    /// as soon as it is sure to exceed `budget` (the projection is then left unfinished: a
    /// step that went astray costs little).
    fn step_into_trial(&mut self, state: &State<D>, p: f64, budget: f64) -> f64 {
        self.trial.params.copy_from_slice(&state.params);
        copy_coefficients(&state.spline, &mut self.trial.spline);
        let step = self.model.step();
        let (values, derivatives) = self.trial.spline.coefficients_mut();
        for (k, (v, d)) in values.iter_mut().zip(derivatives.iter_mut()).enumerate() {
            for c in 0..D {
                v[c] += step[2 * k * D + c];
                d[c] += step[(2 * k + 1) * D + c];
            }
        }
        let penalties = penalties(&self.problem, &self.trial.spline, p);
        let finished = project_within(
            self.problem.points,
            self.problem.projection(),
            &mut self.trial,
            &mut self.power,
            budget - penalties,
        );
        if finished {
            self.trial.data_term() + penalties
        } else {
            f64::INFINITY
        }
    }

    /// The paper's alternation step into `self.trial`: the least-squares spline for the
    /// parameters of `state`, then projection; returns its `F` (infinite when the solve
    /// fails).
    fn alternation_into_trial(&mut self, state: &State<D>, p: f64) -> f64 {
        let trial = &mut self.trial;
        trial.params.copy_from_slice(&state.params);
        copy_coefficients(&state.spline, &mut trial.spline);
        let solved = solve_fixed(
            &self.problem,
            &mut self.coord,
            &mut self.fixed,
            &mut self.x,
            trial,
            p,
        );
        if solved.is_err() {
            return f64::INFINITY;
        }
        let projection = self.problem.projection();
        if !projection.ordered {
            project(self.problem.points, projection, trial, &mut self.power);
            return objective(&self.problem, trial, p);
        }
        // The ordered projection solves a quadratic model of the distances, so it may lose
        // against the parameters held: keep whichever is lower, so that the step never
        // raises F (the held parameters are ordered already). The held parameters are those
        // of `state`, so they are copied back from there, not kept a second time.
        let held = Projection {
            foot_points: false,
            ..projection
        };
        project(self.problem.points, held, trial, &mut self.power);
        let kept = objective(&self.problem, trial, p);
        project(self.problem.points, projection, trial, &mut self.power);
        let moved = objective(&self.problem, trial, p);
        if moved <= kept {
            return moved;
        }
        trial.params.copy_from_slice(&state.params);
        project(self.problem.points, held, trial, &mut self.power);
        kept
    }

    /// Minimizes `F` from `state` (whose parameters are already foot points, or fixed
    /// ones), with `p` held or chosen per step (see [`Penalty`]); returns the iterations done
    /// and the final `p`. Each iteration tries damped Newton steps ([`Solver::newton_tries`])
    /// and, when none lowers `F`, one alternation step ([`Solver::alternation_step`]).
    ///
    /// Errors: [`Error::SingularSystem`] when the parameters are held and the least-squares
    /// problem does not determine the spline.
    pub fn minimize(
        &mut self,
        state: &mut State<D>,
        penalty: Penalty,
        stop: Stop,
    ) -> Result<(usize, f64)> {
        let (mut p, window) = match penalty {
            Penalty::Fixed(p) => (p, None),
            Penalty::Target {
                guess,
                lowest,
                highest,
                ..
            } => (guess, Some((lowest, highest))),
        };
        if let (false, Penalty::Fixed(p)) = (self.problem.foot_points, penalty) {
            self.solve_fixed(state, p)?;
            self.project(state);
            return Ok((1, p));
        }
        let delta = self.problem.delta;
        let in_window = |s: &State<D>| match window {
            None => true,
            Some((lo, hi)) => {
                let f = s.spline.jump_penalty(delta);
                f >= lo && f <= hi
            }
        };
        // Which model goes first: the exact one, until a step of the exact model failed
        // where the safe one at the same damping succeeded.
        let mut damping = Damping {
            mu: INITIAL_DAMPING,
            prefer_safe: false,
        };
        let mut stalls = 0;
        let mut last_gradient = f64::INFINITY;
        for iteration in 0..stop.max_iterations {
            self.model.assemble(&self.problem, state);
            let (g, scale) = self.model.gradient().size(p);
            if g < GRADIENT_PROGRESS * last_gradient {
                stalls = 0;
            }
            last_gradient = g;
            let current = self.objective(state, p);
            if !current.is_finite() || (g <= GRADIENT_TOLERANCE * scale && in_window(state)) {
                return Ok((iteration, p));
            }
            let step = match self.newton_tries(state, penalty, p, current, &mut damping, stop)? {
                Some(step) => Some(step),
                None => self.alternation_step(state, p, current, &mut damping, stop),
            };
            if let Some(step) = &step {
                p = step.p;
            }
            if !step.as_ref().is_some_and(|s| s.progress) {
                stalls += 1;
            }
            if stalls > STALLS {
                return Ok((iteration + 1, p));
            }
            if let Some(step) = step {
                if (step.settled || step.unmoved) && in_window(state) {
                    return Ok((iteration + 1, p));
                }
                let (gain, current) = (step.gain, step.value);
                let small = gain < stop.min_gain * current.abs()
                    || (gain < stop.min_decrease && gain < stop.decrease_share * current.abs());
                if small && in_window(state) {
                    return Ok((iteration + 1, p));
                }
            }
        }
        Ok((stop.max_iterations, p))
    }

    /// One damped Newton step from `state` (whose `F` at `p` is `current`), taken into
    /// `state`: each damping is tried with both models, the preferred one first; `None` when
    /// no damping lowers `F`.
    fn newton_tries(
        &mut self,
        state: &mut State<D>,
        penalty: Penalty,
        p: f64,
        current: f64,
        damping: &mut Damping,
        stop: Stop,
    ) -> Result<Option<Accepted>> {
        for attempt in 0..2 * DAMPING_TRIES {
            let safe = (attempt % 2 == 1) != damping.prefer_safe;
            let problem = &self.problem;
            let mu = damping.mu;
            let tried = match penalty {
                Penalty::Fixed(p) => self
                    .model
                    .newton_step(problem, state, p, mu, safe)
                    .map(|x| (p, x)),
                Penalty::Target { target, .. } => {
                    self.model.target_step(problem, state, target, p, mu, safe)
                }
            };
            if attempt % 2 == 1 {
                damping.mu = (mu * 8.0).max(1e-10);
            }
            let (p_try, predicted) = match tried {
                Ok(found) => found,
                Err(Error::SingularSystem { .. }) => continue,
                Err(e) => return Err(e),
            };
            let before = if p_try == p {
                current
            } else {
                self.objective(state, p_try)
            };
            let budget = before + 8.0 * f64::EPSILON * before.abs();
            let value = self.step_into_trial(state, p_try, budget);
            let lower = value < before;
            // Near the minimum F stops changing in floating point before the gradient
            // vanishes: there a step that keeps F to rounding and shrinks the gradient is
            // taken.
            let level = !lower && value <= before + 4.0 * f64::EPSILON * before.abs() && {
                accumulate_gradient(&self.problem, &self.trial, &mut self.trial_gradient);
                self.trial_gradient.size(p_try).0
                    < GRADIENT_PROGRESS * self.model.gradient().size(p_try).0
            };
            if lower || level {
                damping.prefer_safe |= safe && attempt % 2 == 1;
                let ratio = (before - value) / predicted.max(f64::MIN_POSITIVE);
                damping.mu = if ratio > 0.75 {
                    (mu * 0.25).max(1e-15)
                } else if ratio < 0.25 {
                    mu * 2.0
                } else {
                    mu
                };
                let settled = mu <= SETTLED_DAMPING
                    && settled_distances(&state.dist_sq, &self.trial.dist_sq, stop);
                let unmoved = still(stop, state, &self.trial);
                std::mem::swap(state, &mut self.trial);
                return Ok(Some(Accepted {
                    gain: before - value,
                    progress: before - value > PROGRESS * value.abs(),
                    settled,
                    unmoved,
                    p: p_try,
                    value,
                }));
            }
        }
        Ok(None)
    }

    /// One alternation step from `state` (whose `F` at `p` is `current`), taken into `state`
    /// when it lowers `F`; the damping raised to at least `1e-4` for the next Newton step.
    fn alternation_step(
        &mut self,
        state: &mut State<D>,
        p: f64,
        current: f64,
        damping: &mut Damping,
        stop: Stop,
    ) -> Option<Accepted> {
        let value = self.alternation_into_trial(state, p);
        damping.mu = damping.mu.max(1e-4);
        if value >= current || value.is_nan() {
            return None;
        }
        let unmoved = still(stop, state, &self.trial);
        std::mem::swap(state, &mut self.trial);
        Some(Accepted {
            gain: current - value,
            progress: current - value > PROGRESS * value.abs(),
            settled: false,
            unmoved,
            p,
            value: current,
        })
    }
}

/// The damping of the Newton steps, carried from step to step.
struct Damping {
    /// The Levenberg-Marquardt damping of the next try.
    mu: f64,
    /// Whether the safe model goes first.
    prefer_safe: bool,
}

/// A step taken by [`Solver::minimize`].
struct Accepted {
    /// How much it lowered `F`.
    gain: f64,
    /// Whether that is more than rounding.
    progress: bool,
    /// Whether no distance moved by more than the tolerance of the stop.
    settled: bool,
    /// Whether it moved the curve across itself by less than `min_move`.
    unmoved: bool,
    /// The penalty after the step.
    p: f64,
    /// `F` that the stopping rules compare the gain with.
    value: f64,
}

/// Whether the accepted step from `old` to `new` moved the curve across itself by less than
/// `stop.min_move`.
fn still<const D: usize>(stop: Stop, old: &State<D>, new: &State<D>) -> bool {
    stop.min_move > 0.0 && new.spline.moved_across(&old.spline) < stop.min_move
}

/// Whether no distance changed by more than `stop.tolerance` times the RMS of the new
/// distances, or by more than `stop.floor` (from squared distances `old` and `new`).
fn settled_distances(old: &[f64], new: &[f64], stop: Stop) -> bool {
    let tolerance = stop.tolerance;
    if tolerance <= 0.0 {
        return false;
    }
    let mut largest: f64 = 0.0;
    let mut sum = 0.0;
    for (a, b) in old.iter().zip(new) {
        largest = largest.max((a.sqrt() - b.sqrt()).abs());
        sum += b;
    }
    largest <= (tolerance * (sum / new.len().max(1) as f64).sqrt()).max(stop.floor)
}

/// Copies values and derivatives of `from` into `to` (same knots).
pub(crate) fn copy_coefficients<const D: usize>(
    from: &HermiteSpline<D>,
    to: &mut HermiteSpline<D>,
) {
    let (values, derivatives) = to.coefficients_mut();
    values.copy_from_slice(from.values());
    derivatives.copy_from_slice(from.derivatives());
}

//! The fit on given knots: the penalty method of seed 003 around the inner solver.
//!
//! Minimize `H(q)` (sum of squared foot-point distances) subject to
//! `f(q) = sum_L delta_L |J_L|^2 <= eps`:
//!
//! 1. the unconstrained fit `q_H` (`p = 0`) is tried first: when `f(q_H) <= eps` it is the
//!    answer (the seed's "the problem reduces to finding `q_H`");
//! 2. otherwise `q*` is the fit on the knots `{0, corners, 1}` only, which has no jump at any
//!    knot with `delta_L = 1` (so `f(q*) = 0`), and `p = H(q*) / eps` (the seed's bound,
//!    proved for global minimizers of `H + p f`); `p` is multiplied by 10 until
//!    `f(q_p) <= eps` holds for the minimizer found;
//! 3. with [`PenaltyRule::ActiveBound`] (the default) `p` is then lowered, by a safeguarded
//!    secant search on `log f` against `log p`, to where `f(q_p)` meets `eps` to a relative
//!    [`FitOptions::eps_tolerance`]: that `q_p` satisfies the optimality conditions of the
//!    constrained problem (`grad H + p grad f = 0`, `f = eps`, `p` its multiplier), so its `H`
//!    is the lowest the bound allows; the seed's `p` over-penalizes, and its fit can lie
//!    farther from the points than `eps` requires. [`PenaltyRule::SeedBound`] stops at step 2.
//!
//! Every `q_p` is found by [`Solver::minimize`], warm-started from the previous one.

use super::hermite::HermiteSpline;
use super::knots::{check_knots, start_parameters, StartParameters};
use super::solver::{Solver, State};
use crate::{Curve, Error, Point, Result};

/// Iterations spent on the feasible reference `q*` of the seed's bound.
const REFERENCE_ITERATIONS: usize = 20;

/// How the penalty `p` is chosen.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum PenaltyRule {
    /// Lower `p` from the seed's bound until the constraint is active (`f` within
    /// [`FitOptions::eps_tolerance`] of `eps`): the solution of the constrained problem.
    #[default]
    ActiveBound,
    /// The seed's rule: `p = H(q*) / eps`, times 10 until `f <= eps`.
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
        }
    }
}

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
    /// The seed's bound `H(q*) / eps` (0 when no penalty was needed).
    pub seed_bound: f64,
    /// `delta_L` per knot (0 at the ends and at corners).
    pub weights: Vec<f64>,
    /// Inner iterations done in all.
    pub iterations: usize,
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

    /// `H + p f`, the objective of the last minimization.
    pub fn objective(&self) -> f64 {
        self.data_term + self.penalty * self.jump_sum
    }
}

/// Checks the points and settings shared by every fit; returns `delta_L` per knot.
pub(crate) fn check_inputs<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    options: &FitOptions,
) -> Result<Vec<f64>> {
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
    let mut weights = vec![1.0; knots.len()];
    weights[0] = 0.0;
    weights[knots.len() - 1] = 0.0;
    for &corner in &options.corners {
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

/// Checks `eps`, the tolerance on it, the iteration count and the corner values.
pub(crate) fn check_settings(options: &FitOptions) -> Result<()> {
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
    if options.max_iterations == 0 {
        return Err(Error::InvalidSetting {
            name: "max_iterations",
            value: 0.0,
            reason: "must be at least 1",
        });
    }
    for &corner in &options.corners {
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

/// Fits a C^1 cubic Hermite spline on `knots` (`0 = T_1 < ... < T_N = 1`) to the ordered
/// `points`, minimizing the sum of squared foot-point distances subject to
/// `sum delta_L |J_L|^2 <= options.eps` (see the [module docs](self)).
///
/// Errors: fewer than 3 points, a non-finite coordinate, all points coinciding; invalid
/// knots ([`Error::InvalidKnot`]); invalid settings ([`Error::InvalidSetting`]);
/// [`Error::SingularSystem`] when the points cannot determine the spline (the unconstrained
/// fit, `eps = infinity`, needs points on every piece: about three per pair of neighbouring
/// pieces).
pub fn fit_curve<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    options: &FitOptions,
) -> Result<CurveFit<D>> {
    let weights = check_inputs(points, knots, options)?;
    let start = start_parameters(points, &options.start)?;
    fit_checked(points, knots, &weights, start, options)
}

/// A state on `knots` with zero coefficients and the given parameters.
fn blank_state<const D: usize>(knots: &[f64], params: Vec<f64>) -> State<D> {
    let n = knots.len();
    State {
        spline: HermiteSpline::from_parts(
            knots.to_vec(),
            vec![Point::ZERO; n],
            vec![Point::ZERO; n],
        ),
        dist_sq: vec![0.0; params.len()],
        params,
    }
}

/// The fit after the inputs were checked.
pub(crate) fn fit_checked<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    weights: &[f64],
    start: Vec<f64>,
    options: &FitOptions,
) -> Result<CurveFit<D>> {
    let mut state = blank_state::<D>(knots, start.clone());
    let mut solver = Solver::new(points, weights, options.foot_points, &state.spline);
    let mut iterations = 0;
    let finish = |state: State<D>, p: f64, seed_bound: f64, iterations: usize| CurveFit {
        jump_sum: state.spline.jump_penalty(weights),
        data_term: state.data_term(),
        distances: state.dist_sq.iter().map(|d| d.sqrt()).collect(),
        parameters: state.params,
        spline: state.spline,
        penalty: p,
        seed_bound,
        weights: weights.to_vec(),
        iterations,
    };

    // 1. The unconstrained fit.
    let unconstrained = solver.solve_fixed(&start, 0.0, &mut state.spline);
    match unconstrained {
        Ok(()) => {
            solver.project(&mut state);
            iterations += solver.minimize(&mut state, 0.0, options.max_iterations)?;
            if state.spline.jump_penalty(weights) <= options.eps {
                return Ok(finish(state, 0.0, 0.0, iterations));
            }
        }
        Err(e) if options.eps.is_infinite() => return Err(e),
        Err(_) => {}
    }

    // 2. The seed's bound from a feasible q*: the fit on the knots {0, corners, 1}.
    let mut coarse: Vec<f64> = knots
        .iter()
        .zip(weights)
        .enumerate()
        .filter(|&(l, (_, &w))| l == 0 || l + 1 == knots.len() || w == 0.0)
        .map(|(_, (&k, _))| k)
        .collect();
    coarse.dedup();
    let (reference_h, reference) = feasible_reference(points, &coarse, knots, &start, options);
    if reference_h <= 0.0 {
        if let Some(exact) = reference {
            // The points lie exactly on a spline without bounded jumps: it is the answer.
            return Ok(finish(exact, 0.0, 0.0, iterations));
        }
    }
    let seed_bound = reference_h / options.eps;
    let mut p = seed_bound;
    state.params.copy_from_slice(&start);
    solver.solve_fixed(&start, p, &mut state.spline)?;
    solver.project(&mut state);
    let mut raised = 0;
    loop {
        iterations += solver.minimize(&mut state, p, options.max_iterations)?;
        if state.spline.jump_penalty(weights) <= options.eps {
            break;
        }
        raised += 1;
        if raised > 40 {
            return Err(Error::InvalidSetting {
                name: "eps",
                value: options.eps,
                reason: "the jump bound could not be met (the penalty grew past 1e40 times the seed's bound)",
            });
        }
        p *= 10.0;
    }
    if options.penalty == PenaltyRule::SeedBound {
        return Ok(finish(state, p, seed_bound, iterations));
    }

    // 3. Lower p until the bound is active.
    let eps = options.eps;
    let target_lo = (1.0 - options.eps_tolerance) * eps;
    let mut best = (p, state.clone());
    let f_of = |s: &State<D>| s.spline.jump_penalty(weights);
    if f_of(&best.1) >= target_lo {
        return Ok(finish(best.1, best.0, seed_bound, iterations));
    }
    // Bracket: (p_lo, f_lo > eps) and (p_hi, f_hi <= eps), in logarithms.
    let (mut p_hi, mut f_hi) = (p, f_of(&state));
    let mut lower: Option<(f64, f64)> = None;
    let floor = seed_bound * 1e-16;
    let mut probe = p_hi;
    while lower.is_none() {
        probe /= 100.0;
        if probe < floor {
            break;
        }
        state = best.1.clone();
        iterations += solver.minimize(&mut state, probe, options.max_iterations)?;
        let f = f_of(&state);
        if f > eps {
            lower = Some((probe, f));
        } else {
            p_hi = probe;
            f_hi = f;
            best = (probe, state.clone());
            if f >= target_lo {
                return Ok(finish(state, probe, seed_bound, iterations));
            }
        }
    }
    let Some((mut p_lo, mut f_lo)) = lower else {
        return Ok(finish(best.1, best.0, seed_bound, iterations));
    };
    let log_eps = eps.ln();
    // Illinois-modified regula falsi on phi(x) = ln f - ln eps, x = ln p.
    let (mut side_lo, mut side_hi) = (
        f_lo.ln() - log_eps,
        f_hi.max(f64::MIN_POSITIVE).ln() - log_eps,
    );
    let mut last_moved_hi: Option<bool> = None;
    for _ in 0..60 {
        let (x_lo, x_hi) = (p_lo.ln(), p_hi.ln());
        let mut x = if side_lo.is_finite() && side_hi.is_finite() && side_lo != side_hi {
            x_lo - side_lo * (x_hi - x_lo) / (side_hi - side_lo)
        } else {
            0.5 * (x_lo + x_hi)
        };
        if !(x > x_lo && x < x_hi) {
            x = 0.5 * (x_lo + x_hi);
        }
        let probe = x.exp();
        // Warm start from the feasible side (the lowest feasible p so far).
        state = best.1.clone();
        iterations += solver.minimize(&mut state, probe, options.max_iterations)?;
        let f = f_of(&state);
        let side = f.max(f64::MIN_POSITIVE).ln() - log_eps;
        if f <= eps {
            p_hi = probe;
            side_hi = side;
            best = (probe, state.clone());
            if f >= target_lo {
                break;
            }
            if last_moved_hi == Some(true) {
                side_lo *= 0.5;
            }
            last_moved_hi = Some(true);
        } else {
            p_lo = probe;
            f_lo = f;
            side_lo = f_lo.ln() - log_eps;
            if last_moved_hi == Some(false) {
                side_hi *= 0.5;
            }
            last_moved_hi = Some(false);
        }
        if (p_hi / p_lo).ln() < 1e-12 {
            break;
        }
    }
    Ok(finish(best.1, best.0, seed_bound, iterations))
}

/// `H(q*)` of the fit on the knots `coarse` (which carry no bounded jump) and that fit
/// carried over to `knots` (the same curve: values and derivatives at the finer knots), or
/// `H(0)` of `q* = 0` when that fit cannot be made (the seed's crude bound).
fn feasible_reference<const D: usize>(
    points: &[Point<D>],
    coarse: &[f64],
    knots: &[f64],
    start: &[f64],
    options: &FitOptions,
) -> (f64, Option<State<D>>) {
    let no_weights = vec![0.0; coarse.len()];
    let fallback: f64 = points.iter().map(|p| p.norm_sq()).sum();
    let mut state = blank_state::<D>(coarse, start.to_vec());
    let mut solver = Solver::new(points, &no_weights, options.foot_points, &state.spline);
    if solver.solve_fixed(start, 0.0, &mut state.spline).is_err() {
        return (fallback, None);
    }
    solver.project(&mut state);
    // Any feasible q* gives a valid bound: a few iterations suffice.
    if solver
        .minimize(
            &mut state,
            0.0,
            options.max_iterations.min(REFERENCE_ITERATIONS),
        )
        .is_err()
    {
        return (fallback, None);
    }
    let h = state.data_term();
    if h > fallback {
        return (fallback, None);
    }
    let fine = HermiteSpline::from_parts(
        knots.to_vec(),
        knots.iter().map(|&t| state.spline.eval(t)).collect(),
        knots.iter().map(|&t| state.spline.deriv(t, 1)).collect(),
    );
    let lifted = State {
        spline: fine,
        params: state.params,
        dist_sq: state.dist_sq,
    };
    (h, Some(lifted))
}

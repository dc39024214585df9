//! The fairer's solver on one spline space: a feasible start, then the barrier method
//! (docs/methods.md §8).
//!
//! 1. **Start**: the weighted least-squares spline (a small `R` term keeps it defined),
//!    its weights raised on the points farther than `0.7 T` until every point is within
//!    `0.9 T` of its parameter's point; the parameters are the foot points, updated
//!    between rounds.
//! 2. **Barrier**: for `t = t_0, 10 t_0, ...`, Newton's method on `Ψ_t` (Gauss–Newton matrix,
//!    backtracking until `Ψ_t` falls by a quarter of the predicted decrease, every trial point
//!    strictly inside every ball), then the parameters moved to the foot points (which only
//!    brings every point nearer); until `n / t`, the duality gap of the convexified problem,
//!    is below `10^-3 E`.
//!
//! Every iterate keeps every point strictly within `T` of its parameter's point, hence of the
//! curve: the bound is held by construction, not checked after the fact.
//!
//! Hand-written: the subproblems are banded (every term touches four consecutive controls)
//! and solved by the banded Cholesky of [`crate::solve`] in `O(m)`; general QP and conic
//! solvers factor a sparse KKT system anew at every step and would own the
//! non-convex outer loop no better.

use super::blocks::Blocks;
use super::layout::Layout;
use super::objective::{bound_sq, Basis, Objective, Shape};
use super::shape::demanded_signs;
use super::space::Space;
use crate::solve::BandedSpd;
use crate::{Point, Result};
use std::cmp::Ordering;

/// The share of `T` within which the start puts every point.
const START_SHARE: f64 = 0.9;
/// Points farther than this share of `T` get their weight raised at the start.
const START_TARGET: f64 = 0.7;
/// Rounds of the start's reweighting.
const START_ROUNDS: usize = 40;
/// The weight `λ` of `R` in the start's least squares (sizes of order one).
const START_SMOOTHNESS: f64 = 1e-7;
/// The factor `t` grows by between barrier stages.
const BARRIER_GROWTH: f64 = 10.0;
/// The barrier stops when `n / t` is below this share of `E`.
const BARRIER_GAP: f64 = 1e-3;
/// Newton steps per barrier stage, at most.
const NEWTON_STEPS: usize = 40;

/// A Newton decrement below this ends a stage.
const NEWTON_DECREMENT: f64 = 1e-7;
/// Barrier stages, at most.
const BARRIER_STAGES: usize = 12;
/// The first weight `ρ` of the penalty on the wrong sign of `dκ/ds` (times 100 a round).
const SHAPE_PENALTY: f64 = 1e2;
/// Passes of finding the demanded extrema and asking for their signs.
const SHAPE_PASSES: usize = 2;
/// Rounds of the sign penalty per pass.
const SHAPE_ROUNDS: usize = 3;
/// The margin asked of `dκ/ds sqrt(|r'|)` on its side of zero, a share of its mean square.
const SHAPE_MARGIN: f64 = 1e-4;
/// Foot-point updates after the slab's barrier, before the points are checked against
/// their balls.
const FINAL_PROJECTIONS: usize = 4;
/// Newton steps of a foot-point update.
const PROJECTION_STEPS: usize = 4;

/// The state of one solve: the controls, the unknowns and the point parameters.
pub(crate) struct Solve<'a, const D: usize> {
    pub(crate) space: &'a Space,
    pub(crate) layout: &'a Layout<D>,
    pub(crate) points: &'a [Point<D>],
    pub(crate) tolerance: f64,
    pub(crate) alpha: f64,
    /// Points whose parameter stays put (kept ends).
    pub(crate) pinned: &'a [bool],
    pub(crate) params: Vec<f64>,
    /// The span and the value and slope weights at every parameter (kept with `params`).
    pub(crate) basis: Vec<Basis>,
    pub(crate) controls: Vec<Point<D>>,
    pub(crate) shape: Option<Shape>,
    /// Whether the barrier bounds the error across the curve only (see [`Objective::slab`]).
    pub(crate) slab: bool,
}

impl<const D: usize> Solve<'_, D> {
    fn objective(&self) -> Objective<'_, D> {
        Objective {
            space: self.space,
            layout: self.layout,
            points: self.points,
            basis: &self.basis,
            tolerance: self.tolerance,
            alpha: self.alpha,
            shape: self.shape.as_ref(),
            slab: self.slab,
        }
    }

    /// Solves the banded system `h dx = -g`, damping the diagonal when the matrix is not
    /// positive definite in floating point.
    fn newton_step(h: &mut BandedSpd, g: &[f64]) -> Option<Vec<f64>> {
        let n = h.size();
        let diagonal: Vec<f64> = (0..n).map(|i| h.diagonal(i)).collect();
        let scale = diagonal.iter().fold(0.0_f64, |a, &b| a.max(b.abs()));
        let mut shift = 0.0;
        for _ in 0..8 {
            let mut trial = h.clone();
            if shift > 0.0 {
                for i in 0..n {
                    trial.add(i, i, shift);
                }
            }
            if trial.factor().is_ok() {
                let mut dx: Vec<f64> = g.iter().map(|v| -v).collect();
                trial.solve_factored(&mut dx);
                return Some(dx);
            }
            shift = if shift == 0.0 {
                1e-12 * scale
            } else {
                shift * 100.0
            };
        }
        None
    }

    /// The feasible start: reweighted least squares until every point is within
    /// `START_SHARE T` of its parameter's point. Returns whether it got there.
    pub(crate) fn start(&mut self) -> Result<bool> {
        let n = self.points.len();
        let mut weights = vec![1.0 / (self.tolerance * self.tolerance); n];
        let mut g = vec![0.0; self.layout.size()];
        let mut h = BandedSpd::new(self.layout.size(), self.layout.width());
        let mut x = self.layout.unknowns(&self.controls);
        for _ in 0..START_ROUNDS {
            self.objective().assemble_least_squares(
                &self.controls,
                &weights,
                START_SMOOTHNESS,
                &mut g,
                &mut h,
            );
            let Some(dx) = Self::newton_step(&mut h, &g) else {
                return Ok(false);
            };
            for (a, b) in x.iter_mut().zip(&dx) {
                *a += b;
            }
            self.layout.controls_into(&x, &mut self.controls);
            self.project();
            let distances = self.objective().distances(&self.controls);
            let worst = distances.iter().fold(0.0_f64, |a, &b| a.max(b));
            if worst < START_SHARE * self.tolerance {
                return Ok(true);
            }
            for (w, d) in weights.iter_mut().zip(&distances) {
                let ratio = d / (START_TARGET * self.tolerance);
                if ratio > 1.0 {
                    *w *= ratio * ratio;
                }
            }
        }
        Ok(false)
    }

    /// The barrier method from a feasible start: first with the bound taken across the curve
    /// (a slab around the tangent at every point's parameter, so that the curve may slide
    /// along itself while the parameters follow to the foot points), kept when every point
    /// then lies within `T` of its parameter's point; otherwise again with the balls.
    pub(crate) fn fair(&mut self) {
        let (controls, params) = (self.controls.clone(), self.params.clone());
        self.slab = true;
        self.fair_stages();
        for _ in 0..FINAL_PROJECTIONS {
            self.project();
        }
        self.slab = false;
        let distances = self.objective().distances(&self.controls);
        if distances.iter().all(|&d| d < self.tolerance) {
            return;
        }
        self.controls = controls;
        self.params = params;
        self.refresh_basis();
        self.fair_stages();
    }

    /// The barrier method from a feasible start, then the same with the signs of `dκ/ds`
    /// the points demand (see [`demanded_signs`]).
    fn fair_stages(&mut self) {
        let n = self.points.len() as f64;
        let first = self.objective().parts(&self.controls);
        let t = n / first.fairing(self.alpha).max(f64::MIN_POSITIVE);
        let t = self.stages(t, BARRIER_STAGES);
        let changes = |solve: &Self| {
            let samples = solve.objective().node_samples(&solve.controls);
            samples
                .rate
                .windows(2)
                .filter(|w| w[0] * w[1] < 0.0)
                .count()
        };
        for _ in 0..SHAPE_PASSES {
            let (saved_controls, saved_params) = (self.controls.clone(), self.params.clone());
            let before = changes(self);
            let samples = self.objective().node_samples(&self.controls);
            let Some((signs, _)) = demanded_signs(
                &samples.curvature,
                &samples.rate,
                &samples.s,
                samples.length,
                self.tolerance,
                self.space.closed(),
            ) else {
                break;
            };
            let scale = (samples.rate.iter().map(|r| r * r).sum::<f64>()
                / samples.rate.len() as f64)
                .sqrt();
            let mut rho = SHAPE_PENALTY;
            for _ in 0..SHAPE_ROUNDS {
                self.shape = Some(Shape {
                    signs: signs.clone(),
                    rho,
                    margin: SHAPE_MARGIN * scale,
                });
                self.stages(t, 1);
                rho *= 100.0;
            }
            self.shape = None;
            if changes(self) >= before {
                // The signs asked could not be had within the tolerance: keep the curve of
                // least energy.
                self.controls = saved_controls;
                self.params = saved_params;
                self.refresh_basis();
                break;
            }
        }
        self.shape = None;
    }

    /// Barrier stages from `t`, at most `stages` of them, until the gap is small; returns the
    /// last `t`.
    fn stages(&mut self, mut t: f64, stages: usize) -> f64 {
        let size = self.layout.size();
        let mut g = vec![0.0; size];
        let mut h = BandedSpd::new(size, self.layout.width());
        let mut x = self.layout.unknowns(&self.controls);
        let mut trial_controls = self.controls.clone();
        let mut blocks = Blocks::new(self.space.spans());
        let n = self.points.len() as f64;
        for stage in 0..stages {
            for _ in 0..NEWTON_STEPS {
                let objective = self.objective();
                objective.assemble(&self.controls, t, &mut blocks, &mut g, &mut h);
                let Some(dx) = Self::newton_step(&mut h, &g) else {
                    break;
                };
                let decrement: f64 = -g.iter().zip(&dx).map(|(a, b)| a * b).sum::<f64>();
                if decrement.is_nan() || decrement <= NEWTON_DECREMENT {
                    break;
                }
                let before = objective.parts(&self.controls).value(t, self.alpha);
                let mut step = 1.0;
                let mut accepted = false;
                while step > 1e-10 {
                    let trial: Vec<f64> = x.iter().zip(&dx).map(|(a, b)| a + step * b).collect();
                    self.layout.controls_into(&trial, &mut trial_controls);
                    let after = objective.parts(&trial_controls).value(t, self.alpha);
                    if after.is_finite() && after <= before - 0.25 * step * decrement {
                        x = trial;
                        accepted = true;
                        break;
                    }
                    step *= 0.5;
                }
                if !accepted {
                    break;
                }
                self.controls.copy_from_slice(&trial_controls);
                self.project();
            }
            self.project();
            x = self.layout.unknowns(&self.controls);
            let parts = self.objective().parts(&self.controls);
            if n / t <= BARRIER_GAP * parts.fairing(self.alpha) || stage + 1 == stages {
                break;
            }
            t *= BARRIER_GROWTH;
        }
        t
    }

    /// Recomputes the span and value weights of every parameter.
    pub(crate) fn refresh_basis(&mut self) {
        let space = self.space;
        self.basis.clear();
        self.basis.extend(self.params.iter().map(|&u| {
            let (k, s) = space.locate(u);
            (k, space.weights(k, s, 0), space.weights(k, s, 1))
        }));
    }

    /// Moves every point's parameter towards its foot point by a few safeguarded Newton
    /// steps on `(r(u) - p) . r'(u) = 0`, keeping a step only when it brings the point
    /// nearer.
    pub(crate) fn project(&mut self) {
        let space = self.space;
        let controls = &self.controls;
        let t2 = self.tolerance * self.tolerance;
        for (i, (u, &p)) in self.params.iter_mut().zip(self.points).enumerate() {
            if self.pinned[i] {
                continue;
            }
            let at = |t: f64, d: usize| {
                let (k, s) = space.locate(t);
                space.eval(controls, k, s, d)
            };
            let mut best = at(*u, 0).distance_sq(p);
            for _ in 0..PROJECTION_STEPS {
                let e = at(*u, 0) - p;
                let d1 = at(*u, 1);
                let d2 = at(*u, 2);
                let slope = d1.norm_sq() + e.dot(d2);
                let f = e.dot(d1);
                let step = if slope > 0.0 {
                    -f / slope
                } else {
                    -f / d1.norm_sq().max(f64::MIN_POSITIVE)
                };
                let (k, _) = space.locate(*u);
                let limit = space.width(k);
                let next = space.wrap(*u + step.clamp(-limit, limit));
                let e = at(next, 0) - p;
                let d = e.norm_sq();
                if d.is_nan()
                    || d >= best
                    || (self.slab
                        && bound_sq(e, unit(at(next, 1))).partial_cmp(&t2) != Some(Ordering::Less))
                {
                    break;
                }
                best = d;
                *u = next;
            }
        }
        self.refresh_basis();
    }
}

/// `d` over its length (zero when it is zero).
fn unit<const D: usize>(d: Point<D>) -> Point<D> {
    let length = d.norm();
    if length > 0.0 {
        d * (1.0 / length)
    } else {
        Point::ZERO
    }
}

//! The Newton model of the inner problem: Hessian blocks and damped steps (the gradient is in
//! [`gradient`](super::gradient)).
//!
//! At foot points the half gradient of `F = H + p f + lambda S` with respect to the
//! coefficients is `sum_i A_i^T e_i + p sum_L delta_L a_L J_L + lambda G q` (`A_i` the basis
//! values at `t_i`, `e_i = R(t_i) - r_i`, `a_L` the coefficients of `J_L`, `G` the Gram matrix
//! of the basis' second derivatives); the points' parameters do not appear because each is a
//! minimizer (envelope theorem). Differentiating the foot-point condition `e . R' = 0`
//! implicitly gives the half Hessian
//!
//! ```text
//! sum_i (A_i^T A_i - v_i v_i^T / h_i) + p sum_L delta_L a_L a_L^T + lambda G,
//! v_i = A_i^T R' + B_i^T e_i,   h_i = |R'|^2 + e_i . R''
//! ```
//!
//! (`B_i` the basis derivatives): Gauss–Newton on `(q, t)` jointly with the diagonal
//! `t`-block eliminated, curvature terms kept. Points at an end of the domain, the first and
//! last points, and points whose parameters are held keep only `A_i^T A_i`. The exact `h_i`
//! drops below `|R'|^2` on the concave side of the curve, where it makes the point's term
//! indefinite (singular at the centre of curvature); the safe model raises it to `|R'|^2`
//! there, which drops the tangential part (the squared-distance model of Wang, Pottmann and
//! Liu, "Fitting B-spline curves to point clouds by curvature-based squared distance
//! minimization", 2006). The solver tries the exact model first.
//!
//! The Hessian is banded (unknowns interleaved as `(2 L + a) D + c`, `5 D + 1` diagonals):
//! one pass over the points accumulates it piece by piece into small dense blocks, which are
//! then scattered into a banded Cholesky factorization ([`BandedSpd`]): `O(n D^2)` for the
//! points, `O(N D^3)` for the `N` knots.

use super::gradient::{accumulate_gradient, piece_coefficients, pinned, Gradient};
use super::hermite::{bending_gram, hermite_basis, jump_coefficients};
use super::problem::{Problem, State};
use crate::core::parallel::PARALLEL_THRESHOLD;
use crate::solve::BandedSpd;
use crate::{Point, Result};
use rayon::prelude::*;

/// Secant and bisection steps of the search for `p`, at most.
const SEARCH_STEPS: usize = 100;
/// Decades the bracket of `p` is widened by, at most, on either side of the guess.
const BRACKET_DECADES: usize = 60;
/// A tenfold penalty that lowers the logarithm of the jump sum after the step by less than
/// this has saturated (see [`NewtonModel::target_step`]).
const SATURATED: f64 = 1e-6;

/// The Newton model of the inner problem at a state: the per-piece Hessian blocks of `H`,
/// the gradient, and the damped step, with their buffers (allocated once per fit).
pub(crate) struct NewtonModel<const D: usize> {
    hessian: BandedSpd,
    /// Per piece: `sum A^T A` of its points, 4 x 4 (the same for every coordinate).
    separable: Vec<f64>,
    /// Per piece: `-sum v v^T / h` of its points, `4 D x 4 D`.
    coupled: Vec<f64>,
    /// The same with the safe `h` (see the module docs).
    coupled_safe: Vec<f64>,
    /// The gradient at the current state.
    gradient: Gradient,
    /// The Newton step, interleaved layout.
    step: Vec<f64>,
    /// The damping added to each diagonal entry.
    damping: Vec<f64>,
}

impl<const D: usize> NewtonModel<D> {
    /// Buffers for `unknowns` coefficients on `pieces` pieces (none per point: the piece of
    /// a point is found again where it is needed).
    pub(crate) fn new(unknowns: usize, pieces: usize) -> Self {
        NewtonModel {
            hessian: BandedSpd::new(unknowns, 5 * D + 1),
            separable: vec![0.0; pieces * 16],
            coupled: vec![0.0; pieces * 16 * D * D],
            coupled_safe: vec![0.0; pieces * 16 * D * D],
            gradient: Gradient::new(unknowns),
            step: vec![0.0; unknowns],
            damping: vec![0.0; unknowns],
        }
    }

    /// The gradient at the state last assembled.
    pub fn gradient(&self) -> &Gradient {
        &self.gradient
    }

    /// The last step computed, interleaved layout.
    pub fn step(&self) -> &[f64] {
        &self.step
    }

    /// Accumulates the gradient and the per-piece Hessian blocks of `H` at `state` (see the
    /// module docs).
    ///
    /// A piece's blocks gather the terms of the points on it, in the order of the points; with
    /// many points, ranges of pieces are filled in parallel (each by a scan of all points), so
    /// the blocks do not depend on the number of threads.
    pub fn assemble(&mut self, problem: &Problem<D>, state: &State<D>) {
        accumulate_gradient(problem, state, &mut self.gradient);
        let spline = &state.spline;
        let pieces = spline.knots().len() - 1;
        let params = &state.params;
        let n = params.len();
        let kernel = BlockKernel { problem, state };
        let (sep, coupled, safe) = (16, 16 * D * D, 16 * D * D);
        let threads = rayon::current_num_threads();
        if n < PARALLEL_THRESHOLD || threads < 2 || pieces < 2 {
            kernel.fill(
                0..pieces,
                0..n,
                &mut self.separable,
                &mut self.coupled,
                &mut self.coupled_safe,
            );
            return;
        }
        // Ranges of pieces holding about equal numbers of points, each with its own slices
        // of the blocks and the span of the indices of its points (short: the parameters are
        // nearly sorted).
        let ranges = (2 * threads).min(pieces);
        let mut bounds: Vec<usize> = (0..=ranges)
            .map(|r| {
                if r == ranges {
                    pieces
                } else {
                    spline.piece_near(params[r * n / ranges], 0)
                }
            })
            .collect();
        bounds[0] = 0;
        for r in 1..bounds.len() {
            bounds[r] = bounds[r].max(bounds[r - 1]);
        }
        let mut spans = vec![(usize::MAX, 0); ranges];
        let mut k = 0;
        for (i, &t) in params.iter().enumerate() {
            k = spline.piece_near(t, k);
            let r = bounds.partition_point(|&b| b <= k) - 1;
            let span = &mut spans[r.min(ranges - 1)];
            *span = (span.0.min(i), i + 1);
        }
        let mut jobs = Vec::with_capacity(ranges);
        let (mut a, mut b, mut c) = (
            &mut self.separable[..],
            &mut self.coupled[..],
            &mut self.coupled_safe[..],
        );
        for (w, &(lo, hi)) in bounds.windows(2).zip(&spans) {
            let len = w[1] - w[0];
            let (a0, a1) = std::mem::take(&mut a).split_at_mut(len * sep);
            let (b0, b1) = std::mem::take(&mut b).split_at_mut(len * coupled);
            let (c0, c1) = std::mem::take(&mut c).split_at_mut(len * safe);
            jobs.push((w[0]..w[1], lo.min(hi)..hi, a0, b0, c0));
            (a, b, c) = (a1, b1, c1);
        }
        jobs.into_par_iter()
            .for_each(|(range, span, a, b, c)| kernel.fill(range, span, a, b, c));
    }

    /// The damped Newton step from the assembled blocks into `self.step`; returns the
    /// decrease of `F` the quadratic model predicts; `safe` picks the safe model (see the
    /// module docs).
    ///
    /// Errors: [`Error::SingularSystem`](crate::Error::SingularSystem) when the damped matrix is not positive definite
    /// (the caller damps more).
    pub fn newton_step(
        &mut self,
        problem: &Problem<D>,
        state: &State<D>,
        p: f64,
        mu: f64,
        safe: bool,
    ) -> Result<f64> {
        self.fill_hessian(problem, state, p, safe);
        let unknowns = self.step.len();
        let pinned = |j: usize| pinned(problem, unknowns, j);
        let k_mat = &mut self.hessian;
        let size = k_mat.size();
        let floor = (0..size).fold(0.0f64, |m, j| m.max(k_mat.diagonal(j))) * 1e-12;
        for j in 0..size {
            if pinned(j) {
                self.damping[j] = 0.0;
                k_mat.add(j, j, 1.0);
                continue;
            }
            let d = mu * k_mat.diagonal(j).max(floor);
            self.damping[j] = d;
            k_mat.add(j, j, d);
        }
        k_mat.factor()?;
        for (j, x) in self.step.iter_mut().enumerate() {
            *x = -self.gradient.at(j, p);
        }
        k_mat.solve_factored(&mut self.step);
        // F(q + x) - F(q) ~ 2 g.x + x^T K x = g.x - x^T M x for (K + M) x = -g.
        let mut predicted = 0.0;
        for j in 0..size {
            let x = self.step[j];
            predicted += -self.gradient.at(j, p) * x + self.damping[j] * x * x;
        }
        Ok(predicted)
    }

    /// The Hessian `K` of the Newton model at `p` into `self.hessian`, from the assembled
    /// blocks (the safe coupling when `safe`), the bending terms and the jump terms; pinned
    /// unknowns left out.
    fn fill_hessian(&mut self, problem: &Problem<D>, state: &State<D>, p: f64, safe: bool) {
        let spline = &state.spline;
        let knots = spline.knots();
        let w4 = 4 * D;
        let k_mat = &mut self.hessian;
        k_mat.clear();
        let unknowns = self.step.len();
        let pinned = |j: usize| pinned(problem, unknowns, j);
        let mut add = |i: usize, j: usize, value: f64| {
            if !pinned(i) && !pinned(j) {
                k_mat.add(i, j, value);
            }
        };
        for k in 0..knots.len() - 1 {
            let base = 2 * k * D;
            let sep = &self.separable[16 * k..16 * k + 16];
            let coupled = if safe {
                &self.coupled_safe
            } else {
                &self.coupled
            };
            let block = &coupled[w4 * w4 * k..w4 * w4 * (k + 1)];
            let lambda = problem.bending_on(knots, k);
            let g = if lambda > 0.0 {
                bending_gram(knots[k + 1] - knots[k])
            } else {
                [[0.0; 4]; 4]
            };
            for x in 0..w4 {
                let (a, c) = (x / D, x % D);
                for y in 0..=x {
                    let (b, d) = (y / D, y % D);
                    let mut value = block[w4 * x + y];
                    if c == d {
                        value += sep[4 * a.max(b) + a.min(b)] + lambda * g[a][b];
                    }
                    add(base + x, base + y, value);
                }
            }
        }
        for l in 1..knots.len() - 1 {
            let w = p * problem.delta[l];
            if w.is_nan() || w <= 0.0 {
                continue;
            }
            let coef = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
            let base = 2 * (l - 1) * D;
            for (a, &ca) in coef.iter().enumerate() {
                for (b, &cb) in coef.iter().enumerate().take(a + 1) {
                    for c in 0..D {
                        add(base + a * D + c, base + b * D + c, w * ca * cb);
                    }
                }
            }
        }
    }

    /// `f` of the spline of `state` moved by the step in `self.step`.
    pub fn jump_sum_after_step(&self, problem: &Problem<D>, state: &State<D>) -> f64 {
        let knots = state.spline.knots();
        let (values, derivatives) = (state.spline.values(), state.spline.derivatives());
        let mut f = 0.0;
        for l in 1..knots.len() - 1 {
            let w = problem.delta[l];
            if w <= 0.0 {
                continue;
            }
            let coef = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
            let mut j = Point::<D>::ZERO;
            for (slot, &a) in coef.iter().enumerate() {
                let knot = l - 1 + slot / 2;
                let base = (2 * knot + slot % 2) * D;
                let q = if slot % 2 == 0 {
                    values[knot]
                } else {
                    derivatives[knot]
                };
                for c in 0..D {
                    j[c] += a * (q[c] + self.step[base + c]);
                }
            }
            f += w * j.norm_sq();
        }
        f
    }

    /// The damped Newton step whose `p` makes the jump sum after the step meet `target`
    /// (to a relative `1e-6`), into `self.step`; returns `(p, predicted decrease)`. The jump
    /// sum after the step does not increase with `p`, so `p` is found by a safeguarded secant
    /// search on `ln f` against `ln p`, starting next to `guess`; every trial is one banded
    /// factorization of order `2 N D` (no pass over the points). When even `p -> 0` keeps
    /// the jump sum below the target, `p = 0`.
    ///
    /// Errors: [`Error::SingularSystem`](crate::Error::SingularSystem) as for the Newton step.
    #[allow(clippy::too_many_arguments)]
    pub fn target_step(
        &mut self,
        problem: &Problem<D>,
        state: &State<D>,
        target: f64,
        guess: f64,
        mu: f64,
        safe: bool,
    ) -> Result<(f64, f64)> {
        let search = Search {
            problem,
            state,
            ln_target: target.ln(),
            mu,
            safe,
        };
        let start = if guess > 0.0 && guess.is_finite() {
            guess.ln()
        } else {
            0.0
        };
        let p = match self.bracket(&search, start)? {
            Bracket::Around(bracket) => self.regula_falsi(&search, bracket)?.exp(),
            Bracket::Ended(p) => p,
        };
        let predicted = self.newton_step(problem, state, p, mu, safe)?;
        Ok((p, predicted))
    }

    /// The bracket around the root of `phi` ([`Search::phi`], decreasing in `x = ln p`),
    /// stepping by decades from `start`.
    fn bracket(&mut self, search: &Search<'_, '_, D>, start: f64) -> Result<Bracket> {
        let decade = std::f64::consts::LN_10;
        let first = search.phi(self, start)?;
        let mut x = start;
        if first > 0.0 {
            let (mut lo, mut f_lo) = (start, first);
            loop {
                x += decade;
                let v = search.phi(self, x)?;
                if v <= 0.0 {
                    return Ok(Bracket::Around([lo, f_lo, x, v]));
                }
                if v >= f_lo - SATURATED {
                    // A tenfold penalty no longer lowers the jump sum of the step (the
                    // damping limits it): the target is out of reach of this step, and a
                    // larger penalty would only grow without use.
                    return Ok(Bracket::Ended(lo.exp()));
                }
                (lo, f_lo) = (x, v);
                if x > start + BRACKET_DECADES as f64 * decade {
                    // The target is out of reach: the largest penalty tried.
                    return Ok(Bracket::Ended(x.exp()));
                }
            }
        }
        let (mut hi, mut f_hi) = (start, first);
        loop {
            x -= decade;
            let v = search.phi(self, x)?;
            if v > 0.0 {
                return Ok(Bracket::Around([x, v, hi, f_hi]));
            }
            (hi, f_hi) = (x, v);
            if x < start - BRACKET_DECADES as f64 * decade {
                // The bound is not active for this model.
                return Ok(Bracket::Ended(0.0));
            }
        }
    }

    /// The root of `phi` in the bracket `[lo, phi(lo), hi, phi(hi)]` by the
    /// Illinois-modified regula falsi; `hi` stays on the feasible side and is returned.
    fn regula_falsi(&mut self, search: &Search<'_, '_, D>, bracket: [f64; 4]) -> Result<f64> {
        let [mut lo, mut f_lo, mut hi, mut f_hi] = bracket;
        let mut side = 0i8;
        for _ in 0..SEARCH_STEPS {
            if f_hi.abs() < 1e-6 || hi - lo < 1e-13 * (1.0 + hi.abs()) {
                break;
            }
            let mut x = hi - f_hi * (hi - lo) / (f_hi - f_lo);
            if !(x > lo && x < hi) {
                x = 0.5 * (lo + hi);
            }
            let v = search.phi(self, x)?;
            if v <= 0.0 {
                (hi, f_hi) = (x, v);
                if side == 1 {
                    f_lo *= 0.5;
                }
                side = 1;
            } else {
                (lo, f_lo) = (x, v);
                if side == -1 {
                    f_hi *= 0.5;
                }
                side = -1;
            }
        }
        Ok(hi)
    }
}

/// The outcome of [`NewtonModel::bracket`].
enum Bracket {
    /// `[lo, phi(lo), hi, phi(hi)]`: `lo` with `phi > 0`, `hi` with `phi <= 0`.
    Around([f64; 4]),
    /// The search ended on this `p` without a root: the target out of reach of this step,
    /// or the bound not active for this model (`p = 0`).
    Ended(f64),
}

/// The search of [`NewtonModel::target_step`] for its `p`.
struct Search<'s, 'a, const D: usize> {
    problem: &'s Problem<'a, D>,
    state: &'s State<D>,
    /// `ln` of the jump sum aimed at.
    ln_target: f64,
    mu: f64,
    safe: bool,
}

impl<const D: usize> Search<'_, '_, D> {
    /// `ln f - ln target` after the Newton step of `model` at `p = e^x`.
    fn phi(&self, model: &mut NewtonModel<D>, x: f64) -> Result<f64> {
        model.newton_step(self.problem, self.state, x.exp(), self.mu, self.safe)?;
        Ok(model
            .jump_sum_after_step(self.problem, self.state)
            .max(f64::MIN_POSITIVE)
            .ln()
            - self.ln_target)
    }
}

/// Fills the Hessian blocks of a range of pieces (see [`NewtonModel::assemble`]).
struct BlockKernel<'s, 'a, const D: usize> {
    problem: &'s Problem<'a, D>,
    state: &'s State<D>,
}

impl<const D: usize> BlockKernel<'_, '_, D> {
    /// The blocks of pieces `range` (slices of `separable`, `coupled`, `coupled_safe` that
    /// start at piece `range.start`), zeroed and then accumulated from the points of indices
    /// `span` (which holds every point on those pieces).
    fn fill(
        &self,
        range: std::ops::Range<usize>,
        span: std::ops::Range<usize>,
        separable: &mut [f64],
        coupled: &mut [f64],
        coupled_safe: &mut [f64],
    ) {
        separable.fill(0.0);
        coupled.fill(0.0);
        coupled_safe.fill(0.0);
        let spline = &self.state.spline;
        let knots = spline.knots();
        let n = self.problem.points.len();
        let (first_t, last_t) = (knots[0], knots[knots.len() - 1]);
        let projection = self.problem.projection();
        // With ordered parameters, a run of points pooled to one parameter moves as one: its
        // `t` is eliminated jointly (see `Run`).
        let mut run: Option<Run<D>> = None;
        let mut k = 0;
        for i in span {
            let (r, t) = (&self.problem.points[i], self.state.params[i]);
            k = spline.piece_near(t, k);
            if !range.contains(&k) {
                continue;
            }
            let local = k - range.start;
            let h = knots[k + 1] - knots[k];
            let s = (t - knots[k]) / h;
            let b0 = hermite_basis(s, h, 0);
            let sep = &mut separable[16 * local..16 * local + 16];
            for a in 0..4 {
                for b in 0..=a {
                    sep[4 * a + b] += b0[a] * b0[b];
                }
            }
            let free = projection.is_free(i, n) && t > first_t && t < last_t;
            if !free {
                continue;
            }
            let Some(point) = coupling(spline, (k, local), t, (s, h), r, &b0) else {
                continue;
            };
            match &mut run {
                Some(open) if projection.ordered && open.t == t && open.local == local => {
                    open.pool(&point)
                }
                _ => {
                    if let Some(done) = run.replace(point) {
                        done.subtract(coupled, coupled_safe);
                    }
                }
            }
        }
        if let Some(done) = run {
            done.subtract(coupled, coupled_safe);
        }
    }
}

/// The coupling term of the free point `r` at `t` on piece `k` (`local` in the range of
/// pieces filled), at `s` of the piece of length `h` (`b0` its basis values); `None` where
/// the curve does not move (zero speed).
fn coupling<const D: usize>(
    spline: &super::hermite::HermiteSpline<D>,
    (k, local): (usize, usize),
    t: f64,
    (s, h): (f64, f64),
    r: &Point<D>,
    b0: &[f64; 4],
) -> Option<Run<D>> {
    let b1 = hermite_basis(s, h, 1);
    let b2 = hermite_basis(s, h, 2);
    let q = piece_coefficients(spline, k);
    let (mut e, mut d1, mut d2) = (-*r, Point::<D>::ZERO, Point::<D>::ZERO);
    for a in 0..4 {
        e = e.add_scaled(b0[a], q[a]);
        d1 = d1.add_scaled(b1[a], q[a]);
        d2 = d2.add_scaled(b2[a], q[a]);
    }
    let speed_sq = d1.norm_sq();
    let exact = speed_sq + e.dot(d2);
    if speed_sq <= 0.0 {
        return None;
    }
    // `v` in the interleaved layout: entry `a D + c`.
    let mut v = [[0.0; D]; 4];
    for (a, va) in v.iter_mut().enumerate() {
        for c in 0..D {
            va[c] = b0[a] * d1[c] + b1[a] * e[c];
        }
    }
    Some(Run {
        local,
        t,
        v,
        exact,
        safe: exact.max(speed_sq),
    })
}

/// The coupling term of one point, or of a run of points pooled to one parameter by the
/// ordering ([`super::order`]): the run's points share `t`, so eliminating it gives
/// `-(sum v_i)(sum v_i)^T / sum h_i` where free points give `-sum v_i v_i^T / h_i` (by
/// Cauchy–Schwarz the free model is the more optimistic one: it lets every pooled point slide
/// on its own, and its steps are refused).
struct Run<const D: usize> {
    /// The piece, relative to the range being filled.
    local: usize,
    /// The shared parameter.
    t: f64,
    /// `sum v_i`, interleaved layout (`v[a][c]` is entry `a D + c`).
    v: [[f64; D]; 4],
    /// `sum h_i` (exact model).
    exact: f64,
    /// `sum max(h_i, |R'|^2)` (safe model).
    safe: f64,
}

impl<const D: usize> Run<D> {
    /// Adds a point with the same parameter.
    fn pool(&mut self, other: &Run<D>) {
        for (a, b) in self.v.iter_mut().zip(&other.v) {
            for c in 0..D {
                a[c] += b[c];
            }
        }
        self.exact += other.exact;
        self.safe += other.safe;
    }

    /// Subtracts the run's term from the blocks of its piece.
    fn subtract(&self, coupled: &mut [f64], coupled_safe: &mut [f64]) {
        let w4 = 4 * D;
        let v = self.v.as_flattened();
        let block_range = w4 * w4 * self.local..w4 * w4 * (self.local + 1);
        let inv_safe = 1.0 / self.safe;
        let inv_exact = if self.exact > 0.0 {
            1.0 / self.exact
        } else {
            0.0
        };
        let block = &mut coupled[block_range.clone()];
        let safe = &mut coupled_safe[block_range];
        for (x, &vx) in v.iter().enumerate() {
            let row = w4 * x..w4 * x + x + 1;
            for ((b, s), &vy) in block[row.clone()].iter_mut().zip(&mut safe[row]).zip(v) {
                let vv = vx * vy;
                *b -= vv * inv_exact;
                *s -= vv * inv_safe;
            }
        }
    }
}

#[cfg(test)]
mod run_tests {
    use super::Run;

    fn run(t: f64, v: [[f64; 2]; 4], h: f64, speed_sq: f64) -> Run<2> {
        Run {
            local: 1,
            t,
            v,
            exact: h,
            safe: h.max(speed_sq),
        }
    }

    #[test]
    fn a_pooled_run_is_eliminated_through_its_one_parameter() {
        let v1 = [[1.0, -2.0], [0.5, 0.0], [3.0, 1.0], [-1.0, 2.0]];
        let v2 = [[0.0, 1.0], [2.0, -1.0], [1.0, 1.0], [0.5, 0.5]];
        let (h1, h2) = (2.0, 0.5);
        let mut pooled = run(0.3, v1, h1, 1.0);
        pooled.pool(&run(0.3, v2, h2, 1.0));
        let w = 8;
        let (mut exact, mut safe) = (vec![0.0; 2 * w * w], vec![0.0; 2 * w * w]);
        pooled.subtract(&mut exact, &mut safe);
        let sum: Vec<f64> = v1
            .as_flattened()
            .iter()
            .zip(v2.as_flattened())
            .map(|(a, b)| a + b)
            .collect();
        for x in 0..w {
            for y in 0..w {
                let got = exact[w * w + w * x + y];
                if y > x {
                    // Only the lower triangle is accumulated.
                    assert_eq!(got, 0.0);
                    continue;
                }
                // -(v1 + v2)(v1 + v2)^T / (h1 + h2), not -v1 v1^T / h1 - v2 v2^T / h2.
                let expected = -sum[x] * sum[y] / (h1 + h2);
                assert!((got - expected).abs() <= 1e-15 * expected.abs().max(1.0));
                // The safe model raises each h to |R'|^2 = 1 first: 2 + 1.
                let safe_expected = -sum[x] * sum[y] / 3.0;
                let got = safe[w * w + w * x + y];
                assert!((got - safe_expected).abs() <= 1e-15 * safe_expected.abs().max(1.0));
            }
        }
        // The first piece's blocks are untouched.
        assert!(exact[..w * w].iter().all(|&e| e == 0.0));
    }
}

//! The inner problem of the penalty method: for a fixed `p`, minimize
//! `F(q) = sum_i min_t |R(t) - r_i|^2 + p sum_L delta_L |J_L|^2` over the spline
//! coefficients `q = {R_L, H_L}`.
//!
//! Two steps, both banded least-squares solves ([`BandedLeastSquares`]):
//!
//! - the alternation step of the seed: with the parameters `t_i` held, `F` is quadratic in
//!   `q` and separates by coordinate; one Givens triangularization of width 6 with `D`
//!   right-hand sides (unknowns ordered `R_0, H_0, R_1, H_1, ...`) gives the minimizer, then
//!   every point is projected onto the new curve ([`foot_point`]);
//! - Gauss–Newton on `(q, t)` together, with the `t_i` eliminated: at a foot point the
//!   residual is orthogonal to the tangent, and minimizing the linearized residual over
//!   `dt_i` leaves its normal part, `P_i (e_i + A_i dq)` with `P_i = I - u_i u_i^T`
//!   (tangent-distance rows); the coordinates couple, so the unknowns are interleaved
//!   (`(2L + a) D + c`) and the band is `6 D` wide. Levenberg–Marquardt damping (rows
//!   `sqrt(mu diag)`, Marquardt's scaling by the column norms) keeps the step safe; a step
//!   is taken only when the true objective, after re-projecting every point, decreases, and
//!   the alternation step is the fallback. Gauss–Newton converges fast where the alternation
//!   alone crawls along the curve.
//!
//! The first and last points keep `t = 0` and `t = 1`: they anchor the ends of the curve
//! (the seed minimizes over the `t_i` of the inner points only).
//!
//! Each iteration is `O(n D^2 w + N D^3)` for `n` points and `N` knots, with `w = 6 D`, and
//! allocates nothing: every buffer lives in the [`Solver`].

use super::hermite::{hermite_basis, jump_coefficients, HermiteSpline};
use super::project::foot_point;
use crate::solve::{BandedLeastSquares, BandedSpd};
use crate::{Curve, Error, Point, Result};

/// Stop when the largest gradient entry is below this times the gradient's scale.
const GRADIENT_TOLERANCE: f64 = 1e-12;
/// Stop after this many iterations in a row without progress.
const STALLS: usize = 3;
/// An iteration lowering `F` by less than this (relative) makes no progress.
const PROGRESS: f64 = 1e-12;
/// Damping tries per iteration before the alternation step is taken instead.
const DAMPING_TRIES: usize = 8;

/// A spline and the parameters and squared distances of the data points on it.
#[derive(Clone, Debug)]
pub(crate) struct State<const D: usize> {
    pub spline: HermiteSpline<D>,
    pub params: Vec<f64>,
    pub dist_sq: Vec<f64>,
}

impl<const D: usize> State<D> {
    /// `H`: the sum of squared distances.
    pub fn data_term(&self) -> f64 {
        self.dist_sq.iter().sum()
    }
}

/// The points grouped by the piece their parameter falls on (a counting sort), so that the
/// least-squares rows can be added in the order of their first column.
#[derive(Clone, Debug, Default)]
struct PieceIndex {
    /// Point indices, piece by piece.
    order: Vec<usize>,
    /// `order[start[k]..start[k + 1]]` are the points on piece `k`.
    start: Vec<usize>,
    /// The piece of every point.
    piece: Vec<usize>,
}

impl PieceIndex {
    fn new(points: usize, pieces: usize) -> Self {
        PieceIndex {
            order: vec![0; points],
            start: vec![0; pieces + 1],
            piece: vec![0; points],
        }
    }

    fn build<const D: usize>(&mut self, spline: &HermiteSpline<D>, params: &[f64]) {
        self.start.fill(0);
        for (slot, &t) in self.piece.iter_mut().zip(params) {
            *slot = spline.locate(t).0;
            self.start[*slot + 1] += 1;
        }
        for k in 1..self.start.len() {
            self.start[k] += self.start[k - 1];
        }
        // Fill using `start` as running cursors, then shift it back.
        for (i, &k) in self.piece.iter().enumerate() {
            self.order[self.start[k]] = i;
            self.start[k] += 1;
        }
        for k in (1..self.start.len()).rev() {
            self.start[k] = self.start[k - 1];
        }
        self.start[0] = 0;
    }

    fn on_piece(&self, k: usize) -> &[usize] {
        &self.order[self.start[k]..self.start[k + 1]]
    }
}

/// Buffers and settings of the inner minimization.
pub(crate) struct Solver<'a, const D: usize> {
    points: &'a [Point<D>],
    /// `delta_L`, one per knot (the end knots' entries are unused).
    delta: &'a [f64],
    /// Project the points (foot-point distances) or keep their parameters.
    project: bool,
    coord: BandedLeastSquares,
    hessian: BandedSpd,
    index: PieceIndex,
    x: Vec<f64>,
    abs_sum: Vec<f64>,
    /// `v_i` of the Newton step, `4 D` numbers.
    local: Vec<f64>,
    trial: State<D>,
}

impl<'a, const D: usize> Solver<'a, D> {
    /// A solver for `points` on the knots of `template` (whose coefficients only size the
    /// buffers).
    pub fn new(
        points: &'a [Point<D>],
        delta: &'a [f64],
        project: bool,
        template: &HermiteSpline<D>,
    ) -> Self {
        let n_knots = template.knots().len();
        let unknowns = 2 * n_knots;
        Solver {
            points,
            delta,
            project,
            coord: BandedLeastSquares::new(unknowns, 6, D),
            hessian: BandedSpd::new(unknowns * D, 5 * D + 1),
            index: PieceIndex::new(points.len(), n_knots - 1),
            x: vec![0.0; unknowns * D],
            abs_sum: vec![0.0; unknowns * D],
            local: vec![0.0; 4 * D],
            trial: State {
                spline: template.clone(),
                params: vec![0.0; points.len()],
                dist_sq: vec![0.0; points.len()],
            },
        }
    }

    /// `F = H + p f` of a state.
    pub fn objective(&self, state: &State<D>, p: f64) -> f64 {
        objective(self.delta, state, p)
    }

    /// The least-squares spline for the parameters `params` held fixed, into `out`.
    ///
    /// Errors: [`Error::SingularSystem`] when the points and jump rows do not determine
    /// every coefficient (too few points on some pieces for the penalty given).
    pub fn solve_fixed(
        &mut self,
        params: &[f64],
        p: f64,
        out: &mut HermiteSpline<D>,
    ) -> Result<()> {
        self.index.build(out, params);
        solve_fixed(
            &mut self.coord,
            &mut self.x,
            &self.index,
            self.points,
            self.delta,
            params,
            p,
            out,
        )
    }

    /// Re-projects every inner point onto `state.spline` from its current parameter (the ends
    /// keep theirs), and refreshes the squared distances.
    pub fn project(&self, state: &mut State<D>) {
        project(self.points, self.project, state);
    }

    /// The gradient of `F` with respect to the coefficients at `state` (envelope theorem: the
    /// parameters are foot points), as `(max |g_k|, max_k sum |terms of g_k|)`.
    pub fn gradient(&mut self, state: &State<D>, p: f64) -> (f64, f64) {
        gradient(
            self.points,
            self.delta,
            state,
            p,
            &mut self.x,
            &mut self.abs_sum,
        )
    }

    /// The damped Newton step at `state` into `self.x` (interleaved layout).
    ///
    /// The Hessian of the reduced objective `sum_i min_t |R(t) - r_i|^2 + p f` (halved), by
    /// implicit differentiation of the foot-point condition `e . R' = 0`, is
    /// `sum_i (A_i^T A_i - v_i v_i^T / h_i) + p sum_L delta_L a_L a_L^T`, with `A_i` the
    /// basis values at `t_i`, `v_i = A_i^T R' + B_i^T e_i` (`B_i` the basis derivatives),
    /// `h_i = |R'|^2 + e_i . R''`; it is banded (`5 D + 1` diagonals). Points whose foot point
    /// is not a strict minimum (`h_i <= 0`) keep only `A_i^T A_i`. Damping adds
    /// `mu max(K_jj, floor)` to the diagonal (Marquardt's scaling); a matrix that is not
    /// positive definite fails the factorization and the caller damps more.
    fn newton_step(&mut self, state: &State<D>, p: f64, mu: f64) -> Result<()> {
        let spline = &state.spline;
        let knots = spline.knots();
        let n = self.points.len();
        let k_mat = &mut self.hessian;
        k_mat.clear();
        let g = &mut self.x;
        g.fill(0.0);
        let v = &mut self.local;
        for (i, (r, &t)) in self.points.iter().zip(&state.params).enumerate() {
            let (k, s) = spline.locate(t);
            let h = knots[k + 1] - knots[k];
            let [pt, d1, d2] = spline.jet_on_piece(k, s);
            let e = pt - *r;
            let b0 = hermite_basis(s, h, 0);
            let b1 = hermite_basis(s, h, 1);
            let base = 2 * k * D;
            for (a, &pa) in b0.iter().enumerate() {
                for c in 0..D {
                    g[base + a * D + c] += pa * e[c];
                }
                for (b, &pb) in b0.iter().enumerate().take(a + 1) {
                    for c in 0..D {
                        k_mat.add(base + a * D + c, base + b * D + c, pa * pb);
                    }
                }
            }
            let curvature = d1.norm_sq() + e.dot(d2);
            let free =
                self.project && i > 0 && i + 1 < n && t > knots[0] && t < knots[knots.len() - 1];
            if free && curvature > 0.0 {
                for a in 0..4 {
                    for c in 0..D {
                        v[a * D + c] = b0[a] * d1[c] + b1[a] * e[c];
                    }
                }
                let inv = 1.0 / curvature;
                for x in 0..4 * D {
                    for y in 0..=x {
                        k_mat.add(base + x, base + y, -v[x] * v[y] * inv);
                    }
                }
            }
        }
        for l in 1..knots.len() - 1 {
            let w = p * self.delta[l];
            if w.is_nan() || w <= 0.0 {
                continue;
            }
            let jl = spline.jump_measure(l);
            let coef = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
            let base = 2 * (l - 1) * D;
            for (a, &ca) in coef.iter().enumerate() {
                for c in 0..D {
                    g[base + a * D + c] += w * jl[c] * ca;
                }
                for (b, &cb) in coef.iter().enumerate().take(a + 1) {
                    for c in 0..D {
                        k_mat.add(base + a * D + c, base + b * D + c, w * ca * cb);
                    }
                }
            }
        }
        if mu > 0.0 {
            let size = k_mat.size();
            let floor = (0..size).fold(0.0f64, |m, j| m.max(k_mat.diagonal(j))) * 1e-12;
            for j in 0..size {
                let d = k_mat.diagonal(j);
                k_mat.add(j, j, mu * d.max(floor));
            }
        }
        k_mat.factor()?;
        for x in g.iter_mut() {
            *x = -*x;
        }
        k_mat.solve_factored(g);
        Ok(())
    }

    /// The state `state + x` (the step in `self.x`) into `self.trial`, projected.
    fn step_into_trial(&mut self, state: &State<D>) {
        self.trial.params.copy_from_slice(&state.params);
        copy_coefficients(&state.spline, &mut self.trial.spline);
        let (values, derivatives) = self.trial.spline.coefficients_mut();
        for (k, (v, d)) in values.iter_mut().zip(derivatives.iter_mut()).enumerate() {
            for c in 0..D {
                v[c] += self.x[2 * k * D + c];
                d[c] += self.x[(2 * k + 1) * D + c];
            }
        }
        project(self.points, self.project, &mut self.trial);
    }

    /// Minimizes `F` for the penalty `p` from `state` (whose parameters are already foot
    /// points, or fixed ones); returns the iterations done.
    pub fn minimize(
        &mut self,
        state: &mut State<D>,
        p: f64,
        max_iterations: usize,
    ) -> Result<usize> {
        if !self.project {
            self.index.build(&state.spline, &state.params);
            solve_fixed(
                &mut self.coord,
                &mut self.x,
                &self.index,
                self.points,
                self.delta,
                &state.params,
                p,
                &mut state.spline,
            )?;
            project(self.points, false, state);
            return Ok(1);
        }
        let mut current = self.objective(state, p);
        let (mut g, mut scale) = self.gradient(state, p);
        let mut mu = 1e-4;
        let mut stalls = 0;
        for iteration in 0..max_iterations {
            if g <= GRADIENT_TOLERANCE * scale || !current.is_finite() {
                return Ok(iteration);
            }
            let mut accepted = false;
            for _ in 0..DAMPING_TRIES {
                match self.newton_step(state, p, mu) {
                    Ok(()) => {}
                    Err(Error::SingularSystem { .. }) => {
                        mu = (mu * 10.0).max(1e-10);
                        continue;
                    }
                    Err(e) => return Err(e),
                }
                self.step_into_trial(state);
                let value = objective(self.delta, &self.trial, p);
                // Near the minimum F stops changing in floating point before the gradient
                // vanishes: there a step that keeps F (to rounding) and shrinks the gradient
                // counts as progress.
                let level = value <= current + 4.0 * f64::EPSILON * current.abs();
                let (g_trial, scale_trial) = if value < current || level {
                    gradient(
                        self.points,
                        self.delta,
                        &self.trial,
                        p,
                        &mut self.x,
                        &mut self.abs_sum,
                    )
                } else {
                    (f64::INFINITY, 0.0)
                };
                if value < current || (level && g_trial < 0.5 * g) {
                    std::mem::swap(state, &mut self.trial);
                    let gained = current - value > PROGRESS * current.abs() || g_trial < 0.5 * g;
                    stalls = if gained { 0 } else { stalls + 1 };
                    current = value;
                    (g, scale) = (g_trial, scale_trial);
                    mu = (mu * 0.25).max(1e-15);
                    accepted = true;
                    break;
                }
                mu *= 8.0;
            }
            if !accepted {
                // The alternation step of the seed: never increases F.
                self.trial.params.copy_from_slice(&state.params);
                copy_coefficients(&state.spline, &mut self.trial.spline);
                self.index.build(&state.spline, &state.params);
                let solved = solve_fixed(
                    &mut self.coord,
                    &mut self.x,
                    &self.index,
                    self.points,
                    self.delta,
                    &state.params,
                    p,
                    &mut self.trial.spline,
                );
                let mut moved = false;
                if solved.is_ok() {
                    project(self.points, self.project, &mut self.trial);
                    let value = objective(self.delta, &self.trial, p);
                    if value < current {
                        std::mem::swap(state, &mut self.trial);
                        moved = current - value > PROGRESS * current.abs();
                        current = value;
                        (g, scale) = self.gradient(state, p);
                    }
                }
                mu = 1e-4;
                stalls = if moved { 0 } else { stalls + 1 };
            }
            if stalls >= STALLS {
                return Ok(iteration + 1);
            }
        }
        Ok(max_iterations)
    }
}

/// The least-squares spline for fixed parameters (see [`Solver::solve_fixed`]); `index`
/// groups the points by piece for `params`.
#[allow(clippy::too_many_arguments)]
fn solve_fixed<const D: usize>(
    coord: &mut BandedLeastSquares,
    x: &mut [f64],
    index: &PieceIndex,
    points: &[Point<D>],
    delta: &[f64],
    params: &[f64],
    p: f64,
    out: &mut HermiteSpline<D>,
) -> Result<()> {
    coord.clear();
    let knots = out.knots();
    for k in 0..knots.len() - 1 {
        let h = knots[k + 1] - knots[k];
        for &i in index.on_piece(k) {
            let b = hermite_basis(out.local(k, params[i]), h, 0);
            coord.add_row(2 * k, &b, &points[i].0);
        }
        let l = k + 1;
        if l + 1 < knots.len() {
            let w = (p * delta[l]).sqrt();
            if w > 0.0 {
                let c = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
                coord.add_row(2 * (l - 1), &c.map(|v| v * w), &[0.0; D]);
            }
        }
    }
    coord.solve(x)?;
    let (values, derivatives) = out.coefficients_mut();
    for (k, (v, d)) in values.iter_mut().zip(derivatives.iter_mut()).enumerate() {
        for c in 0..D {
            v[c] = x[2 * k * D + c];
            d[c] = x[(2 * k + 1) * D + c];
        }
    }
    Ok(())
}

/// The gradient of `F` with respect to the coefficients at `state` (envelope theorem: the
/// parameters are foot points), as `(max |g_k|, max_k sum |terms of g_k|)`.
pub(crate) fn gradient<const D: usize>(
    points: &[Point<D>],
    delta: &[f64],
    state: &State<D>,
    p: f64,
    g: &mut [f64],
    abs_sum: &mut [f64],
) -> (f64, f64) {
    g.fill(0.0);
    abs_sum.fill(0.0);
    let spline = &state.spline;
    let knots = spline.knots();
    for (r, &t) in points.iter().zip(&state.params) {
        let (k, s) = spline.locate(t);
        let e = spline.deriv_on_piece(k, s, 0) - *r;
        let b = hermite_basis(s, knots[k + 1] - knots[k], 0);
        for (slot, &phi) in b.iter().enumerate() {
            for c in 0..D {
                let v = 2.0 * e[c] * phi;
                let j = (2 * k + slot) * D + c;
                g[j] += v;
                abs_sum[j] += v.abs();
            }
        }
    }
    for l in 1..knots.len() - 1 {
        let w = p * delta[l];
        if w > 0.0 {
            let jl = spline.jump_measure(l);
            let coef = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
            for (slot, &a) in coef.iter().enumerate() {
                for c in 0..D {
                    let v = 2.0 * w * jl[c] * a;
                    let j = (2 * (l - 1) + slot) * D + c;
                    g[j] += v;
                    abs_sum[j] += v.abs();
                }
            }
        }
    }
    let largest = g.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    let scale = abs_sum.iter().fold(0.0f64, |m, v| m.max(*v));
    (largest, scale)
}

/// `F = H + p f` of a state, with `delta_L` per knot.
pub(crate) fn objective<const D: usize>(delta: &[f64], state: &State<D>, p: f64) -> f64 {
    let f = if p > 0.0 {
        state.spline.jump_penalty(delta)
    } else {
        0.0
    };
    state.data_term() + p * f
}

/// Re-projects every inner point of `points` onto `state.spline` from its current parameter
/// when `foot_points` (the ends keep theirs), and refreshes the squared distances.
pub(crate) fn project<const D: usize>(
    points: &[Point<D>],
    foot_points: bool,
    state: &mut State<D>,
) {
    let n = points.len();
    for (i, r) in points.iter().enumerate() {
        let t = state.params[i];
        if foot_points && i > 0 && i + 1 < n {
            let (t, d) = foot_point(&state.spline, *r, t);
            state.params[i] = t;
            state.dist_sq[i] = d;
        } else {
            state.dist_sq[i] = state.spline.eval(t).distance_sq(*r);
        }
    }
}

/// Copies values and derivatives of `from` into `to` (same knots).
fn copy_coefficients<const D: usize>(from: &HermiteSpline<D>, to: &mut HermiteSpline<D>) {
    let (values, derivatives) = to.coefficients_mut();
    values.copy_from_slice(from.values());
    derivatives.copy_from_slice(from.derivatives());
}

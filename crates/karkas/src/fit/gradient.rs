//! The half gradient of the inner problem's objective `F = H + p f + lambda S` with respect
//! to the spline coefficients (Pavlov's fit; see [`newton`](super::newton) for the model it
//! belongs to): `sum_i A_i^T e_i + p sum_L delta_L a_L J_L + lambda G q` at foot points
//! (`A_i` the basis values at `t_i`, `e_i = R(t_i) - r_i`, `a_L` the coefficients of `J_L`,
//! `G` the Gram matrix of the basis' second derivatives), in the interleaved layout of the
//! unknowns, zero at pinned end values. With many points the data terms are summed over
//! fixed parts of the points in parallel, then part by part, so that the sums do not depend
//! on the number of threads.

use super::hermite::{bending_gram, hermite_basis, jump_coefficients, HermiteSpline};
use super::problem::{Problem, State};
use crate::core::parallel::{part_size, FIXED_PARTS, PARALLEL_THRESHOLD};
use crate::Point;
use rayon::prelude::*;
use std::ops::Range;

/// The half gradient of `F = H + p f + lambda S` in two parts, `base` (of `H + lambda S`) and
/// `jump` (of `f`, per unit `p`), with the sums of the absolute values of their terms (the
/// scale of the relative gradient test); interleaved layout, zero at pinned unknowns.
#[derive(Clone, Debug)]
pub(crate) struct Gradient {
    base: Vec<f64>,
    base_abs: Vec<f64>,
    jump: Vec<f64>,
    jump_abs: Vec<f64>,
    /// The data terms of each part of many points, and their absolute values (allocated
    /// at the first use).
    parts: Vec<(Vec<f64>, Vec<f64>)>,
}

impl Gradient {
    /// A zero gradient of `unknowns` entries.
    pub(crate) fn new(unknowns: usize) -> Self {
        Gradient {
            base: vec![0.0; unknowns],
            base_abs: vec![0.0; unknowns],
            jump: vec![0.0; unknowns],
            jump_abs: vec![0.0; unknowns],
            parts: Vec::new(),
        }
    }

    /// Entry `j` for the penalty `p`.
    #[inline]
    pub fn at(&self, j: usize, p: f64) -> f64 {
        self.base[j] + p * self.jump[j]
    }

    /// `(max_k |g_k|, max_k sum |terms of g_k|)` for the penalty `p`.
    pub fn size(&self, p: f64) -> (f64, f64) {
        let mut largest: f64 = 0.0;
        let mut scale: f64 = 0.0;
        for j in 0..self.base.len() {
            largest = largest.max(self.at(j, p).abs());
            scale = scale.max(self.base_abs[j] + p * self.jump_abs[j]);
        }
        (largest, scale)
    }
}

/// The coefficients `[R_k, H_k, R_{k+1}, H_{k+1}]` of piece `k`.
#[inline]
pub(crate) fn piece_coefficients<const D: usize>(
    spline: &HermiteSpline<D>,
    k: usize,
) -> [Point<D>; 4] {
    let (v, d) = (spline.values(), spline.derivatives());
    [v[k], d[k], v[k + 1], d[k + 1]]
}

/// Whether unknown `j` (interleaved layout, `unknowns` in all) is an end value held by a pin.
#[inline]
pub(crate) fn pinned<const D: usize>(problem: &Problem<D>, unknowns: usize, j: usize) -> bool {
    problem.pins.is_some() && (j < D || (j >= unknowns - 2 * D && j < unknowns - D))
}

/// The gradient of `F` at `state` into `out`.
pub(crate) fn accumulate_gradient<const D: usize>(
    problem: &Problem<D>,
    state: &State<D>,
    out: &mut Gradient,
) {
    let spline = &state.spline;
    for v in [
        &mut out.base,
        &mut out.base_abs,
        &mut out.jump,
        &mut out.jump_abs,
    ] {
        v.fill(0.0);
    }
    add_all_points(problem, state, out);
    add_jumps(problem, spline, out);
    if problem.bending > 0.0 {
        add_bending(problem, spline, out);
    }
    let unknowns = out.base.len();
    for j in 0..unknowns {
        if pinned(problem, unknowns, j) {
            out.base[j] = 0.0;
            out.jump[j] = 0.0;
        }
    }
}

/// The data terms of every point added to `out` (in fixed parts on many points, summed in
/// order).
fn add_all_points<const D: usize>(problem: &Problem<D>, state: &State<D>, out: &mut Gradient) {
    let n = problem.points.len();
    if n < PARALLEL_THRESHOLD {
        add_points(problem, state, 0..n, &mut out.base, &mut out.base_abs);
    } else {
        // Fixed parts, summed in order: the sums do not depend on the number of threads.
        let size = part_size(n);
        let unknowns = out.base.len();
        out.parts
            .resize_with(FIXED_PARTS, || (vec![0.0; unknowns], vec![0.0; unknowns]));
        out.parts
            .par_iter_mut()
            .enumerate()
            .for_each(|(p, (base, base_abs))| {
                base.fill(0.0);
                base_abs.fill(0.0);
                let range = (p * size).min(n)..((p + 1) * size).min(n);
                add_points(problem, state, range, base, base_abs);
            });
        for (base, base_abs) in &out.parts {
            for (o, v) in out.base.iter_mut().zip(base) {
                *o += v;
            }
            for (o, v) in out.base_abs.iter_mut().zip(base_abs) {
                *o += v;
            }
        }
    }
}

/// The jump terms `w_L J_L dJ_L/dq` added to `out`.
fn add_jumps<const D: usize>(problem: &Problem<D>, spline: &HermiteSpline<D>, out: &mut Gradient) {
    let knots = spline.knots();
    for l in 1..knots.len() - 1 {
        let w = problem.delta[l];
        if w.is_nan() || w <= 0.0 {
            continue;
        }
        let jl = spline.jump_measure(l);
        let coef = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
        let base = 2 * (l - 1) * D;
        for (a, &ca) in coef.iter().enumerate() {
            for c in 0..D {
                let term = w * jl[c] * ca;
                out.jump[base + a * D + c] += term;
                out.jump_abs[base + a * D + c] += term.abs();
            }
        }
    }
}

/// The bending terms `lambda G q` of every piece added to `out`.
fn add_bending<const D: usize>(
    problem: &Problem<D>,
    spline: &HermiteSpline<D>,
    out: &mut Gradient,
) {
    let knots = spline.knots();
    for k in 0..knots.len() - 1 {
        let lambda = problem.bending_on(knots, k);
        let g = bending_gram(knots[k + 1] - knots[k]);
        let q = piece_coefficients(spline, k);
        let base = 2 * k * D;
        for (a, row) in g.iter().enumerate() {
            let gq = row
                .iter()
                .zip(&q)
                .fold(Point::<D>::ZERO, |acc, (&gab, qb)| acc.add_scaled(gab, *qb));
            for c in 0..D {
                let term = lambda * gq[c];
                out.base[base + a * D + c] += term;
                out.base_abs[base + a * D + c] += term.abs();
            }
        }
    }
}

/// The data terms `A_i^T e_i` of the points in `range`, and their absolute values, added to
/// `base` and `base_abs`.
fn add_points<const D: usize>(
    problem: &Problem<D>,
    state: &State<D>,
    range: Range<usize>,
    base: &mut [f64],
    base_abs: &mut [f64],
) {
    let spline = &state.spline;
    let knots = spline.knots();
    let mut k = 0;
    for i in range {
        let (r, t) = (problem.points[i], state.params[i]);
        k = spline.piece_near(t, k);
        let h = knots[k + 1] - knots[k];
        let b0 = hermite_basis((t - knots[k]) / h, h, 0);
        let q = piece_coefficients(spline, k);
        let mut e = -r;
        for a in 0..4 {
            e = e.add_scaled(b0[a], q[a]);
        }
        let first = 2 * k * D;
        for (a, &phi) in b0.iter().enumerate() {
            for c in 0..D {
                let term = phi * e[c];
                base[first + a * D + c] += term;
                base_abs[first + a * D + c] += term.abs();
            }
        }
    }
}

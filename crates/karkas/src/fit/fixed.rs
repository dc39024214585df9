//! The least-squares spline for parameters held fixed: the alternation step of Pavlov.
//!
//! With every `t_i` held, `F = sum_i |R(t_i) - r_i|^2 + p sum_L delta_L |J_L|^2 + lambda S` is
//! a linear least-squares problem in the coefficients, the same for every coordinate: rows
//! `A_i` (the four Hermite basis values at `t_i`), `sqrt(p delta_L)` times the coefficients of
//! `J_L` (formula (2) of the paper), and two rows per piece for the bending energy
//! (`S = h |R''(mid)|^2 + h^3 |R'''|^2 / 12` on a piece). The unknowns are ordered
//! `R_0, H_0, R_1, H_1, ...`, so every row lies within 6 consecutive columns; the rows are
//! added piece by piece (points grouped by a counting sort) to the banded Givens solver
//! ([`BandedLeastSquares`]), `O(n)` in all. Pinned end values move to the right-hand side.
//! Orthogonal transformations keep the rows weighted by a large `sqrt(p)` accurate.
//!
//! With many points (from [`PARALLEL_THRESHOLD`]) the rows of each piece, which all lie on
//! its four columns, are first rotated into their own 4 x 4 triangular factor
//! ([`PieceFactor`]), the pieces in parallel; only these factors and the jump rows go
//! through the banded solver. The factor of a piece is the same least-squares problem up to
//! its residual, so the solution is the same up to rounding, and it does not depend on the
//! number of threads (each piece is rotated on its own, in the order of its points).

use super::hermite::{hermite_basis, jump_coefficients, HermiteSpline};
use super::problem::{Problem, State};
use crate::core::parallel::PARALLEL_THRESHOLD;
use crate::solve::BandedLeastSquares;
use crate::{Point, Result};
use rayon::prelude::*;

/// The points grouped by the piece their parameter falls on (a counting sort), so that the
/// least-squares rows can be added in the order of their first column. Parameters in order
/// (the usual case) need no sort: the points of a piece are a run of indices, and no index
/// per point is kept.
#[derive(Clone, Debug, Default)]
struct PieceIndex {
    /// Point indices, piece by piece; empty when the parameters are in order.
    order: Vec<usize>,
    /// `order[start[k]..start[k + 1]]` (or those indices themselves, when `order` is empty)
    /// are the points on piece `k`.
    start: Vec<usize>,
}

impl PieceIndex {
    pub(crate) fn new(pieces: usize) -> Self {
        PieceIndex {
            order: Vec::new(),
            start: vec![0; pieces + 1],
        }
    }

    /// Groups the points by the piece of their parameter `params` on `spline`.
    fn build<const D: usize>(&mut self, spline: &HermiteSpline<D>, params: &[f64]) {
        let pieces = || {
            params.iter().scan(0, move |k, &t| {
                *k = spline.piece_near(t, *k);
                Some(*k)
            })
        };
        self.start.fill(0);
        for k in pieces() {
            self.start[k + 1] += 1;
        }
        for k in 1..self.start.len() {
            self.start[k] += self.start[k - 1];
        }
        if params.windows(2).all(|pair| pair[0] <= pair[1]) {
            self.order = Vec::new();
            return;
        }
        self.order.resize(params.len(), 0);
        // Fill using `start` as running cursors, then shift it back.
        for (i, k) in pieces().enumerate() {
            self.order[self.start[k]] = i;
            self.start[k] += 1;
        }
        for k in (1..self.start.len()).rev() {
            self.start[k] = self.start[k - 1];
        }
        self.start[0] = 0;
    }

    /// The indices of the points on piece `k`, in order.
    fn on_piece(&self, k: usize) -> impl Iterator<Item = usize> + '_ {
        let range = self.start[k]..self.start[k + 1];
        let (run, sorted) = if self.order.is_empty() {
            (range, &[][..])
        } else {
            (0..0, &self.order[range])
        };
        run.chain(sorted.iter().copied())
    }
}

/// Pieces per task when the pieces are rotated into their factors in parallel.
const PIECES_PER_TASK: usize = 64;

/// Scratch space of [`solve_fixed`], sized for one problem.
#[derive(Clone, Debug)]
pub(crate) struct FixedScratch<const D: usize> {
    index: PieceIndex,
    /// The factor of every piece (used with many points).
    factors: Vec<PieceFactor<D>>,
}

impl<const D: usize> FixedScratch<D> {
    pub(crate) fn new(points: usize, pieces: usize) -> Self {
        let parallel = points >= PARALLEL_THRESHOLD;
        FixedScratch {
            index: PieceIndex::new(pieces),
            factors: vec![PieceFactor::EMPTY; if parallel { pieces } else { 0 }],
        }
    }
}

/// The upper-triangular factor of least-squares rows on four columns with `D` right-hand
/// sides, built by Givens rotations as the rows arrive (fixed size, so the rotations unroll;
/// the band solver's general rows would cost twice as much).
#[derive(Clone, Copy, Debug)]
pub(crate) struct PieceFactor<const D: usize> {
    /// Row `j`: its entries in columns `j..4` (the others zero).
    r: [[f64; 4]; 4],
    rhs: [[f64; D]; 4],
    /// Which rows have received a row yet.
    filled: [bool; 4],
}

impl<const D: usize> PieceFactor<D> {
    const EMPTY: Self = PieceFactor {
        r: [[0.0; 4]; 4],
        rhs: [[0.0; D]; 4],
        filled: [false; 4],
    };

    /// Rotates the row `values` with right-hand sides `rhs` into the factor.
    fn add(&mut self, values: [f64; 4], rhs: [f64; D]) {
        let (mut row, mut rhs) = (values, rhs);
        for j in 0..4 {
            let value = row[j];
            if value == 0.0 {
                continue;
            }
            if !self.filled[j] {
                self.r[j] = row;
                self.rhs[j] = rhs;
                self.filled[j] = true;
                return;
            }
            let pivot = self.r[j][j];
            let radius = radius(pivot, value);
            let (c, s) = (pivot / radius, value / radius);
            self.r[j][j] = radius;
            row[j] = 0.0;
            for (a, b) in self.r[j][j + 1..].iter_mut().zip(&mut row[j + 1..]) {
                let (x, y) = (*a, *b);
                *a = c * x + s * y;
                *b = c * y - s * x;
            }
            for (a, b) in self.rhs[j].iter_mut().zip(rhs.iter_mut()) {
                let (x, y) = (*a, *b);
                *a = c * x + s * y;
                *b = c * y - s * x;
            }
        }
    }
}

/// `sqrt(a^2 + b^2)`, directly when the sum of squares neither overflows nor falls below the
/// normal range (then it is as accurate as `hypot`, and much faster), by `hypot` otherwise.
#[inline]
fn radius(a: f64, b: f64) -> f64 {
    let sum = a * a + b * b;
    if (f64::MIN_POSITIVE..f64::INFINITY).contains(&sum) {
        sum.sqrt()
    } else {
        a.hypot(b)
    }
}

/// A least-squares row (entry `j` in column `first + j` of the per-coordinate layout
/// `R_0, H_0, R_1, H_1, ...`, `last_col` the column of the last value) with the pinned end
/// values moved to the right-hand side.
fn pinned_row<const D: usize, const W: usize>(
    pins: Option<[Point<D>; 2]>,
    last_col: usize,
    first: usize,
    values: [f64; W],
    rhs: Point<D>,
) -> ([f64; W], Point<D>) {
    let (mut row, mut rhs) = (values, rhs);
    if let Some([start, end]) = pins {
        for (slot, v) in row.iter_mut().enumerate() {
            let col = first + slot;
            if col == 0 || col == last_col {
                let pin = if col == 0 { start } else { end };
                rhs = rhs.add_scaled(-*v, pin);
                *v = 0.0;
            }
        }
    }
    (row, rhs)
}

/// Calls `row(values, rhs)` for every row of piece `k` on its four columns `2k..2k + 4`: its
/// points, in order, then its two bending rows; pinned values moved to the right-hand side.
fn piece_rows<const D: usize>(
    problem: &Problem<D>,
    state: &State<D>,
    index: &PieceIndex,
    k: usize,
    mut row: impl FnMut([f64; 4], Point<D>),
) {
    let knots = state.spline.knots();
    let last_col = 2 * (knots.len() - 1);
    let h = knots[k + 1] - knots[k];
    let mut add = |values: [f64; 4], rhs: Point<D>| {
        let (values, rhs) = pinned_row(problem.pins, last_col, 2 * k, values, rhs);
        row(values, rhs);
    };
    for i in index.on_piece(k) {
        let b = hermite_basis(state.spline.local(k, state.params[i]), h, 0);
        add(b, problem.points[i]);
    }
    if problem.bending > 0.0 {
        let lambda = problem.bending_on(knots, k);
        let wm = (lambda * h).sqrt();
        let wt = (lambda * h / 12.0).sqrt() * h;
        add(hermite_basis(0.5, h, 2).map(|v| v * wm), Point::ZERO);
        add(hermite_basis(0.5, h, 3).map(|v| v * wt), Point::ZERO);
    }
}

/// The least-squares spline for the parameters of `state` held fixed, into `state.spline`
/// (the distances not refreshed); `coord`, `scratch` and `x`
/// are scratch space sized for the problem.
///
/// Errors: [`Error::SingularSystem`](crate::Error::SingularSystem) when the rows do not
/// determine every coefficient (too few points on some pieces).
pub(crate) fn solve_fixed<const D: usize>(
    problem: &Problem<D>,
    coord: &mut BandedLeastSquares,
    scratch: &mut FixedScratch<D>,
    x: &mut [f64],
    state: &mut State<D>,
    p: f64,
) -> Result<()> {
    let FixedScratch { index, factors } = scratch;
    index.build(&state.spline, &state.params);
    let (index, state_ref) = (&*index, &*state);
    if !factors.is_empty() {
        factors
            .par_chunks_mut(PIECES_PER_TASK)
            .enumerate()
            .for_each(|(task, chunk)| {
                for (j, out) in chunk.iter_mut().enumerate() {
                    *out = PieceFactor::EMPTY;
                    let k = task * PIECES_PER_TASK + j;
                    piece_rows(problem, state_ref, index, k, |values, rhs| {
                        out.add(values, rhs.0)
                    });
                }
            });
    }
    coord.clear();
    let knots = state_ref.spline.knots();
    let last_col = 2 * (knots.len() - 1);
    let pins = problem.pins;
    if let Some([start, _]) = pins {
        coord.add_row(0, &[1.0], &start.0);
    }
    for k in 0..knots.len() - 1 {
        if let Some(f) = factors.get(k) {
            for j in (0..4).filter(|&j| f.filled[j]) {
                coord.add_row(2 * k + j, &f.r[j][j..], &f.rhs[j]);
            }
        } else {
            piece_rows(problem, state_ref, index, k, |values, rhs| {
                coord.add_row(2 * k, &values, &rhs.0)
            });
        }
        let l = k + 1;
        if l + 1 < knots.len() {
            let w = (p * problem.delta[l]).sqrt();
            if w > 0.0 {
                let c = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
                let first = 2 * (l - 1);
                let (values, rhs) =
                    pinned_row(pins, last_col, first, c.map(|v| v * w), Point::ZERO);
                coord.add_row(first, &values, &rhs.0);
            }
        }
    }
    if let Some([_, end]) = pins {
        coord.add_row(last_col, &[1.0], &end.0);
    }
    coord.solve(x)?;
    let (values, derivatives) = state.spline.coefficients_mut();
    for (k, (v, d)) in values.iter_mut().zip(derivatives.iter_mut()).enumerate() {
        for c in 0..D {
            v[c] = x[2 * k * D + c];
            d[c] = x[(2 * k + 1) * D + c];
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::problem::Taper;

    /// The least-squares spline of `points` at `params` on `knots`, with the rows of each
    /// piece rotated into its factor first (`factored`) or streamed to the band solver.
    fn solve(
        problem: &Problem<2>,
        knots: &[f64],
        params: &[f64],
        p: f64,
        factored: bool,
    ) -> Vec<f64> {
        let pieces = knots.len() - 1;
        let mut scratch = FixedScratch::new(params.len(), pieces);
        scratch.factors = vec![PieceFactor::EMPTY; if factored { pieces } else { 0 }];
        let mut coord = BandedLeastSquares::new(2 * knots.len(), 6, 2);
        let mut x = vec![0.0; 4 * knots.len()];
        let mut state = State::<2>::blank(knots, params.to_vec());
        solve_fixed(problem, &mut coord, &mut scratch, &mut x, &mut state, p).unwrap();
        x
    }

    #[test]
    fn piece_factors_give_the_streamed_solution() {
        // Uneven knots; a piece with no point and one with a single point (their factors
        // are rank deficient: the neighbours, the jump rows and the bending rows determine
        // the spline); pinned ends; an active penalty.
        let knots = [0.0, 0.1, 0.25, 0.3, 0.33, 0.6, 0.8, 1.0];
        let mut params: Vec<f64> = (0..400)
            .map(|i| i as f64 / 399.0)
            .filter(|t| !(0.25..0.33).contains(t))
            .collect();
        params.push(0.31);
        params.sort_by(f64::total_cmp);
        let points: Vec<Point<2>> = params
            .iter()
            .enumerate()
            .map(|(i, &t)| {
                let wiggle = 1e-3 * ((i * 7919 % 101) as f64 / 101.0 - 0.5);
                Point([(3.0 * t).cos() + wiggle, (2.0 * t).sin() - wiggle])
            })
            .collect();
        let delta = vec![0.0, 1.0, 1.0, 0.0, 1.0, 1.0, 1.0, 0.0];
        for (pins, p) in [
            (None, 0.0),
            (Some([points[0], points[points.len() - 1]]), 1e-3),
        ] {
            let problem = Problem {
                points: &points,
                delta: &delta,
                bending: 1e-6,
                taper: Taper::NONE,
                pins,
                foot_points: false,
                ordered: false,
            };
            let streamed = solve(&problem, &knots, &params, p, false);
            let factored = solve(&problem, &knots, &params, p, true);
            let scale = streamed.iter().fold(0.0f64, |m, v| m.max(v.abs()));
            for (a, b) in streamed.iter().zip(&factored) {
                assert!((a - b).abs() <= 1e-9 * scale, "{a} vs {b}");
            }
        }
    }

    #[test]
    fn radius_holds_where_the_squares_overflow_or_underflow() {
        for scale in [1.0, 1e200, 1e-200, 1e-310] {
            let r = radius(3.0 * scale, -4.0 * scale);
            assert!(
                (r - 5.0 * scale).abs() <= 4.0 * f64::EPSILON * 5.0 * scale,
                "{r:e}"
            );
        }
        assert_eq!(radius(0.0, -2.0), 2.0);
        assert_eq!(radius(0.0, 0.0), 0.0);
    }
}

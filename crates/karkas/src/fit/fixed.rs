//! The least-squares spline for parameters held fixed: the alternation step of seed 003.
//!
//! With every `t_i` held, `F = sum_i |R(t_i) - r_i|^2 + p sum_L delta_L |J_L|^2 + lambda S` is
//! a linear least-squares problem in the coefficients, the same for every coordinate: rows
//! `A_i` (the four Hermite basis values at `t_i`), `sqrt(p delta_L)` times the coefficients of
//! `J_L` (formula (2) of the seed), and two rows per piece for the bending energy
//! (`S = h |R''(mid)|^2 + h^3 |R'''|^2 / 12` on a piece). The unknowns are ordered
//! `R_0, H_0, R_1, H_1, ...`, so every row lies within 6 consecutive columns; the rows are
//! added piece by piece (points grouped by a counting sort) to the banded Givens solver
//! ([`BandedLeastSquares`]), `O(n)` in all. Pinned end values move to the right-hand side.
//! Orthogonal transformations keep the rows weighted by a large `sqrt(p)` accurate.

use super::hermite::{hermite_basis, jump_coefficients};
use super::solver::{Problem, State};
use crate::solve::BandedLeastSquares;
use crate::{Point, Result};

/// The points grouped by the piece their parameter falls on (a counting sort), so that the
/// least-squares rows can be added in the order of their first column.
#[derive(Clone, Debug, Default)]
pub(crate) struct PieceIndex {
    /// Point indices, piece by piece.
    order: Vec<usize>,
    /// `order[start[k]..start[k + 1]]` are the points on piece `k`.
    start: Vec<usize>,
}

impl PieceIndex {
    pub fn new(points: usize, pieces: usize) -> Self {
        PieceIndex {
            order: vec![0; points],
            start: vec![0; pieces + 1],
        }
    }

    fn build(&mut self, piece: &[usize]) {
        self.start.fill(0);
        for &k in piece {
            self.start[k + 1] += 1;
        }
        for k in 1..self.start.len() {
            self.start[k] += self.start[k - 1];
        }
        // Fill using `start` as running cursors, then shift it back.
        for (i, &k) in piece.iter().enumerate() {
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

/// Adds a least-squares row (entry `j` in column `first + j` of the per-coordinate layout
/// `R_0, H_0, R_1, H_1, ...`) with the pinned end values moved to the right-hand side.
fn add_row<const D: usize>(
    coord: &mut BandedLeastSquares,
    pins: Option<[Point<D>; 2]>,
    first: usize,
    values: &[f64],
    rhs: Point<D>,
) {
    let mut row = [0.0; 6];
    row[..values.len()].copy_from_slice(values);
    let mut rhs = rhs;
    if let Some([start, end]) = pins {
        let last_col = coord.cols() - 2;
        for (slot, v) in row.iter_mut().enumerate().take(values.len()) {
            let col = first + slot;
            if col == 0 || col == last_col {
                let pin = if col == 0 { start } else { end };
                rhs = rhs.add_scaled(-*v, pin);
                *v = 0.0;
            }
        }
    }
    coord.add_row(first, &row[..values.len()], &rhs.0);
}

/// The least-squares spline for the parameters of `state` held fixed, into `state.spline`
/// (the pieces of the parameters refreshed, the distances not); `coord`, `index` and `x` are
/// scratch space sized for the problem.
///
/// Errors: [`Error::SingularSystem`](crate::Error::SingularSystem) when the rows do not
/// determine every coefficient (too few points on some pieces).
pub(crate) fn solve_fixed<const D: usize>(
    problem: &Problem<D>,
    coord: &mut BandedLeastSquares,
    index: &mut PieceIndex,
    x: &mut [f64],
    state: &mut State<D>,
    p: f64,
) -> Result<()> {
    for (k, &t) in state.piece.iter_mut().zip(&state.params) {
        *k = state.spline.piece_near(t, *k);
    }
    index.build(&state.piece);
    coord.clear();
    let knots = state.spline.knots();
    let last_col = 2 * (knots.len() - 1);
    let pins = problem.pins;
    if let Some([start, _]) = pins {
        coord.add_row(0, &[1.0], &start.0);
    }
    for k in 0..knots.len() - 1 {
        let h = knots[k + 1] - knots[k];
        for &i in index.on_piece(k) {
            let b = hermite_basis(state.spline.local(k, state.params[i]), h, 0);
            add_row(coord, pins, 2 * k, &b, problem.points[i]);
        }
        if problem.bending > 0.0 {
            let mid = hermite_basis(0.5, h, 2);
            let third = hermite_basis(0.5, h, 3);
            let wm = (problem.bending * h).sqrt();
            let wt = (problem.bending * h / 12.0).sqrt() * h;
            add_row(coord, pins, 2 * k, &mid.map(|v| v * wm), Point::ZERO);
            add_row(coord, pins, 2 * k, &third.map(|v| v * wt), Point::ZERO);
        }
        let l = k + 1;
        if l + 1 < knots.len() {
            let w = (p * problem.delta[l]).sqrt();
            if w > 0.0 {
                let c = jump_coefficients(knots[l] - knots[l - 1], knots[l + 1] - knots[l]);
                add_row(coord, pins, 2 * (l - 1), &c.map(|v| v * w), Point::ZERO);
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

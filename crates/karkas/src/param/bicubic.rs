//! Bicubic interpolation of a grid in Hermite form (Kuznetsov and Filatov, (3.3)–(3.13); the
//! 1-D splines are those of [`crate::spline`]).
//!
//! On the cell `[u_i, u_{i+1}] x [v_j, v_{j+1}]` the surface is `W = phi(s)^T F phi(t)` (3.6)
//! with the Hermite basis `phi` of (3.7), (3.9) and the 4 x 4 matrix (3.8) of node values
//! `r`, u-slopes `r_u`, v-slopes `r_v` and twists `r_uv` at the four corners. The unknown
//! derivatives come from `2N + M` one-dimensional spline solves (the paper's three steps):
//!
//! 1. a spline in `u` along every column `v = v_j` gives `r_u` (M solves);
//! 2. a spline in `v` along every row `u = u_i` gives `r_v` (N solves);
//! 3. a spline in `v` of the `r_u` of every row gives `r_uv` (N solves).
//!
//! Each solve is tridiagonal (not-a-knot ends eliminated as in (3.10)–(3.12), or cyclic for a
//! closed direction), so construction is `O(N M)`. Guarantees: `W(u_i, v_j) = r_ij` at every
//! node; every partial derivative `D^{a,b} W` with `a, b <= 2` is continuous; every line
//! `u = u_i` and `v = v_j` is the 1-D cubic spline of its nodes; with not-a-knot ends a
//! bicubic polynomial is reproduced exactly.
//!
//! Grid evaluation ([`Surface::eval_grid_into`]) combines the two node rows of a sample row
//! once (`O(M)`), then costs 4 multiply-adds per point; the `v` weights of every sample
//! column are computed once per call.

use super::condition::{node_measures, ConditionSummary};
use super::grid_slopes::{solve_columns, solve_rows};
use super::parameterization::{grid_parameters, GridParameterization};
use super::spline::check_parameters;
use crate::core::knots::locate;
use crate::core::parallel::for_each_row_block;
use crate::core::{Grid, Interval, PiecewiseSurface, Side, Surface};
use crate::spline::{hermite_basis, SlopeSystem, SplineEnds};
use crate::{Error, Point, Result};

/// A bicubic interpolating spline surface over a grid `r_ij` (row `i` at `u_i`, column `j`
/// at `v_j`), each direction open (not-a-knot ends) or closed (periodic).
///
/// Outside the domain an open direction continues its end patches' polynomials and a closed
/// one wraps by its period.
#[derive(Clone, Debug, PartialEq)]
pub struct BicubicSurface<const D: usize> {
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    closed_u: bool,
    closed_v: bool,
    /// The node values `r_ij` ((3.8); a closed direction repeats its first line).
    values: Grid<Point<D>>,
    /// `m^(1,0) = dW/du` at the nodes, row-major like `values`.
    ru: Vec<Point<D>>,
    /// `m^(0,1) = dW/dv`.
    rv: Vec<Point<D>>,
    /// `m^(1,1) = d^2 W / du dv`.
    ruv: Vec<Point<D>>,
}

impl<const D: usize> BicubicSurface<D> {
    /// The bicubic interpolant of `grid` with parameters by `parameterization`.
    ///
    /// A closed direction is closed like a curve: if the last row (column) repeats the first
    /// (relative tolerance `1e-12`) it is the seam, otherwise the first is appended; the
    /// parameters include the closing step.
    ///
    /// Errors: fewer than 2 rows or columns (3 distinct when closed), a non-finite point
    /// (named by its cell), coincident consecutive lines ([`Error::CoincidentGridLines`]),
    /// parameters closer than `1e-12` of their span ([`Error::InvalidKnot`], e.g. from one far
    /// outlier).
    pub fn new(
        grid: &Grid<Point<D>>,
        parameterization: GridParameterization,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        grid.check_points(2, WHAT)?;
        let grid = grid.closed(closed_u, closed_v, WHAT_CLOSED)?;
        Self::on_closed_grid(grid, parameterization, closed_u, closed_v)
    }

    /// [`new`](Self::new) on an owned grid: an open surface keeps `grid` as its values
    /// without copying it (a closed direction copies it once, to close it).
    pub fn from_grid(
        grid: Grid<Point<D>>,
        parameterization: GridParameterization,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        grid.check_points(2, WHAT)?;
        let grid = if closed_u || closed_v {
            grid.closed(closed_u, closed_v, WHAT_CLOSED)?
        } else {
            grid
        };
        Self::on_closed_grid(grid, parameterization, closed_u, closed_v)
    }

    /// The parameters of the (already closed) `grid`, checked, then [`build`](Self::build).
    fn on_closed_grid(
        grid: Grid<Point<D>>,
        parameterization: GridParameterization,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        let (us, vs) = grid_parameters(&grid, parameterization)?;
        // Parameters spanning many orders of magnitude (a far outlier) are refused here.
        check_parameters(&us)?;
        check_parameters(&vs)?;
        Self::build(grid, us, vs, closed_u, closed_v)
    }

    /// The bicubic interpolant of `grid` on given knots (`knots_u.len() == rows`,
    /// `knots_v.len() == cols`). In a closed direction the last row (column) must repeat the
    /// first.
    ///
    /// Errors: as [`new`](Self::new), plus knots that do not fit the grid
    /// ([`Error::CountMismatch`]) or do not increase ([`Error::InvalidKnot`]), a closed
    /// direction whose last line does not repeat the first ([`Error::OpenPeriodicData`]).
    pub fn from_knots(
        grid: &Grid<Point<D>>,
        knots_u: &[f64],
        knots_v: &[f64],
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        Self::check_knots_fit(grid, knots_u, knots_v)?;
        let closed = grid.closed(closed_u, closed_v, WHAT_CLOSED)?;
        Self::on_closed_knots(grid, closed, knots_u, knots_v, closed_u, closed_v)
    }

    /// [`from_knots`](Self::from_knots) on an owned grid: an open surface keeps `grid` as
    /// its values without copying it.
    pub fn from_grid_knots(
        grid: Grid<Point<D>>,
        knots_u: &[f64],
        knots_v: &[f64],
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        Self::check_knots_fit(&grid, knots_u, knots_v)?;
        if closed_u || closed_v {
            let closed = grid.closed(closed_u, closed_v, WHAT_CLOSED)?;
            return Self::on_closed_knots(&grid, closed, knots_u, knots_v, closed_u, closed_v);
        }
        Self::build(grid, knots_u.to_vec(), knots_v.to_vec(), false, false)
    }

    /// The checks of [`from_knots`](Self::from_knots) before closing the grid.
    fn check_knots_fit(grid: &Grid<Point<D>>, knots_u: &[f64], knots_v: &[f64]) -> Result<()> {
        grid.check_points(2, WHAT)?;
        Error::check_counts(&[
            ("knots in u (one per grid row)", grid.rows(), knots_u.len()),
            (
                "knots in v (one per grid column)",
                grid.cols(),
                knots_v.len(),
            ),
        ])?;
        check_parameters(knots_u)?;
        check_parameters(knots_v)
    }

    /// `closed` (the closed `grid`) built on the given knots, refused when closing added a
    /// line (the knots were given for the grid as it is).
    fn on_closed_knots(
        grid: &Grid<Point<D>>,
        closed: Grid<Point<D>>,
        knots_u: &[f64],
        knots_v: &[f64],
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        if closed.rows() != grid.rows() || closed.cols() != grid.cols() {
            return Err(Error::OpenPeriodicData {
                what: "a closed direction",
                item: "grid line",
            });
        }
        Self::build(
            closed,
            knots_u.to_vec(),
            knots_v.to_vec(),
            closed_u,
            closed_v,
        )
    }

    /// The three steps of the paper: `2N + M` spline solves.
    fn build(
        grid: Grid<Point<D>>,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        let cols = grid.cols();
        let ends = |closed: bool| -> SplineEnds<D> {
            if closed {
                SplineEnds::Periodic
            } else {
                SplineEnds::NotAKnot
            }
        };
        let (ends_u, ends_v) = (ends(closed_u), ends(closed_v));
        let system_u = SlopeSystem::new(&knots_u, &ends_u)?;
        let system_v = SlopeSystem::new(&knots_v, &ends_v)?;
        // Step 1: r_u along every column, all columns in sweeps over the grid rows.
        let ru = solve_columns(&system_u, &grid);
        // Steps 2 and 3: r_v and r_uv along every row.
        let rv = solve_rows(&system_v, grid.as_slice(), cols);
        let ruv = solve_rows(&system_v, &ru, cols);
        Ok(BicubicSurface {
            knots_u,
            knots_v,
            closed_u,
            closed_v,
            values: grid,
            ru,
            rv,
            ruv,
        })
    }

    /// The knots `u_0 < .. < u_{N-1}` (a closed direction includes the seam twice).
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }

    /// The knots `v_0 < .. < v_{M-1}`.
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }

    /// The interpolated node `r_ij` (of the closed grid).
    pub fn node(&self, i: usize, j: usize) -> Point<D> {
        *self.values.get(i, j)
    }

    /// The node derivatives `(m^(1,0), m^(0,1), m^(1,1))` at node `(i, j)` ((3.8)).
    pub fn node_derivatives(&self, i: usize, j: usize) -> (Point<D>, Point<D>, Point<D>) {
        let k = i * self.values.cols() + j;
        (self.ru[k], self.rv[k], self.ruv[k])
    }

    /// The condition measure of the parameters at every node of the (closed) grid: the
    /// extension of Kuznetsov and Filatov's (2.4) in [`condition_measure`](super::condition_measure) from the node
    /// tangents `W_u`, `W_v` (`1` exactly for arc lengths along orthogonal directions,
    /// Theorem 2.1; smaller for skewed or stretched parameters). `O(N M)`.
    pub fn condition_measures(&self) -> Grid<f64> {
        let cols = self.values.cols();
        node_measures(self.values.rows(), cols, |i, j| {
            let k = i * cols + j;
            (self.ru[k], self.rv[k])
        })
    }

    /// The smallest and mean condition measure of [`condition_measures`](Self::condition_measures)
    /// and the worst node, over the distinct nodes (a closed direction's repeated seam line
    /// counted once).
    pub fn condition_summary(&self) -> ConditionSummary {
        let measures = self.condition_measures();
        let rows = measures.rows() - usize::from(self.closed_u);
        let cols = measures.cols() - usize::from(self.closed_v);
        // A grid has at least 2 lines in each direction (3 distinct when closed): never empty.
        ConditionSummary::of(&measures, rows, cols).unwrap_or(ConditionSummary {
            min: f64::NAN,
            mean: f64::NAN,
            worst: (0, 0),
            nodes: 0,
        })
    }

    /// The value and `v`-slope of the line `u = const` at node column `j`, combined from the
    /// two node rows `i`, `i + 1` with the u-weights `w`.
    #[inline]
    fn column_data(&self, i: usize, j: usize, w: &[f64; 4]) -> (Point<D>, Point<D>) {
        let cols = self.values.cols();
        let (a, b) = (i * cols + j, (i + 1) * cols + j);
        let r = self.values.as_slice();
        (
            r[a] * w[0] + r[b] * w[1] + self.ru[a] * w[2] + self.ru[b] * w[3],
            self.rv[a] * w[0] + self.rv[b] * w[1] + self.ruv[a] * w[2] + self.ruv[b] * w[3],
        )
    }

    /// Fills `values` and `slopes` with the value and `v`-slope of the line `u = const` at
    /// every node column, from node rows `i`, `i + 1` with the u-weights `w` (`O(M)`).
    fn combine_rows(
        &self,
        i: usize,
        w: &[f64; 4],
        values: &mut [Point<D>],
        slopes: &mut [Point<D>],
    ) {
        let cols = self.values.cols();
        let (upper, lower) = (i * cols..(i + 1) * cols, (i + 1) * cols..(i + 2) * cols);
        let r = self.values.as_slice();
        let rows = r[upper.clone()].iter().zip(&r[lower.clone()]);
        let u_slopes = self.ru[upper.clone()].iter().zip(&self.ru[lower.clone()]);
        for ((q, (&a, &b)), (&ua, &ub)) in values.iter_mut().zip(rows).zip(u_slopes) {
            *q = a * w[0] + b * w[1] + ua * w[2] + ub * w[3];
        }
        let v_slopes = self.rv[upper.clone()].iter().zip(&self.rv[lower.clone()]);
        let twists = self.ruv[upper].iter().zip(&self.ruv[lower]);
        for ((qv, (&a, &b)), (&ua, &ub)) in slopes.iter_mut().zip(v_slopes).zip(twists) {
            *qv = a * w[0] + b * w[1] + ua * w[2] + ub * w[3];
        }
    }

    fn deriv_on_cell(
        &self,
        (i, s): (usize, f64),
        (j, t): (usize, f64),
        ku: usize,
        kv: usize,
    ) -> Point<D> {
        let wu = hermite_weights(s, self.knots_u[i + 1] - self.knots_u[i], ku);
        let wv = hermite_weights(t, self.knots_v[j + 1] - self.knots_v[j], kv);
        let (q0, s0) = self.column_data(i, j, &wu);
        let (q1, s1) = self.column_data(i, j + 1, &wu);
        q0 * wv[0] + q1 * wv[1] + s0 * wv[2] + s1 * wv[3]
    }
}

/// The Hermite weights of [`hermite_basis`] in the order `[y_k, y_{k+1}, m_k, m_{k+1}]`
/// (values first, as the rows of (3.8)).
#[inline]
fn hermite_weights(s: f64, h: f64, k: usize) -> [f64; 4] {
    let [v0, d0, v1, d1] = hermite_basis(s, h, k);
    [v0, v1, d0, d1]
}

/// The input named in the errors of a grid too small (in total, in a closed direction).
const WHAT: &str = "a bicubic surface (in each grid direction)";
const WHAT_CLOSED: &str = "a closed direction of a bicubic surface (distinct grid lines)";

impl<const D: usize> Surface<D> for BicubicSurface<D> {
    fn domain_u(&self) -> Interval {
        Interval::new(self.knots_u[0], self.knots_u[self.knots_u.len() - 1])
    }

    fn domain_v(&self) -> Interval {
        Interval::new(self.knots_v[0], self.knots_v[self.knots_v.len() - 1])
    }

    fn is_closed_u(&self) -> bool {
        self.closed_u
    }

    fn is_closed_v(&self) -> bool {
        self.closed_v
    }

    fn eval(&self, u: f64, v: f64) -> Point<D> {
        self.deriv(u, v, 0, 0)
    }

    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        self.deriv_on_cell(
            locate(&self.knots_u, self.closed_u, u, Side::Above),
            locate(&self.knots_v, self.closed_v, v, Side::Above),
            ku,
            kv,
        )
    }

    fn eval_grid_into(&self, us: &[f64], vs: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_grid_len(us.len(), vs.len(), out.len());
        let columns: Vec<(usize, [f64; 4])> = vs
            .iter()
            .map(|&v| {
                let (j, t) = locate(&self.knots_v, self.closed_v, v, Side::Above);
                (
                    j,
                    hermite_weights(t, self.knots_v[j + 1] - self.knots_v[j], 0),
                )
            })
            .collect();
        let cols = self.values.cols();
        let row_len = vs.len().max(1);
        for_each_row_block(out, row_len, |first, block| {
            let mut values = vec![Point::ZERO; cols];
            let mut slopes = vec![Point::ZERO; cols];
            for (&u, out_row) in us[first..].iter().zip(block.chunks_exact_mut(row_len)) {
                let (i, s) = locate(&self.knots_u, self.closed_u, u, Side::Above);
                let wu = hermite_weights(s, self.knots_u[i + 1] - self.knots_u[i], 0);
                self.combine_rows(i, &wu, &mut values, &mut slopes);
                for (p, &(j, w)) in out_row.iter_mut().zip(&columns) {
                    *p = values[j] * w[0]
                        + values[j + 1] * w[1]
                        + slopes[j] * w[2]
                        + slopes[j + 1] * w[3];
                }
            }
        });
    }
}

impl<const D: usize> PiecewiseSurface<D> for BicubicSurface<D> {
    fn breakpoints_u(&self) -> Vec<f64> {
        self.knots_u.clone()
    }

    fn breakpoints_v(&self) -> Vec<f64> {
        self.knots_v.clone()
    }

    fn continuity(&self) -> usize {
        2
    }

    fn deriv_on_side(
        &self,
        u: f64,
        v: f64,
        ku: usize,
        kv: usize,
        side_u: Side,
        side_v: Side,
    ) -> Point<D> {
        self.deriv_on_cell(
            locate(&self.knots_u, self.closed_u, u, side_u),
            locate(&self.knots_v, self.closed_v, v, side_v),
            ku,
            kv,
        )
    }
}

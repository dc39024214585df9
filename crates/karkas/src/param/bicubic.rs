//! Bicubic interpolation of a grid (Kuznetsov and Filatov, (3.3)–(3.13); the 1-D splines
//! are those of [`crate::spline`]).
//!
//! The paper writes the surface on the cell `[u_i, u_{i+1}] x [v_j, v_{j+1}]` as
//! `W = phi(s)^T F phi(t)` (3.6), with the Hermite basis `phi` of (3.7), (3.9) and the 4 x 4
//! matrix (3.8) of node values `r`, u-slopes `r_u`, v-slopes `r_v` and twists `r_uv` at the
//! four corners, found by one-dimensional spline solves (its three steps). The same surface is
//! a tensor-product cubic B-spline with a simple knot at every node parameter: karkas keeps
//! that form, `(N + 2) x (M + 2)` control points for `N x M` nodes, one point per node where
//! the Hermite form needs four (`grid_controls.rs`: a spline in `u` along every column, then
//! one in `v` along every row of the result, each turned into its B-spline coefficients).
//!
//! Each solve is tridiagonal (not-a-knot ends eliminated as in (3.10)–(3.12), or cyclic for a
//! closed direction), so construction is `O(N M)`. Guarantees: `W(u_i, v_j) = r_ij` at every
//! node; every partial derivative `D^{a,b} W` with `a, b <= 2` is continuous; every line
//! `u = u_i` and `v = v_j` is the 1-D cubic spline of its nodes; with not-a-knot ends a
//! bicubic polynomial is reproduced exactly. A closed direction is held over one period as a
//! clamped B-spline whose ends join with `C^2` continuity, and evaluation wraps by the period.
//!
//! Grid evaluation ([`Surface::eval_grid_into`]) combines the four control rows of a sample
//! row once (`O(M)`), then costs 4 multiply-adds per point; the `v` weights of every sample
//! column are computed once per call.

use super::condition::{
    condition_measure, node_measures, paper_condition_measure, ConditionSummary,
};
use super::grid_controls::control_net;
use super::parameterization::{grid_parameters, GridParameterization};
use super::spline::{check_parameters, overflow_at_smallest_gap};
use crate::bspline::{cubic_span_weights, knot_vector};
use crate::core::knots::locate;
use crate::core::parallel::for_each_row_block;
use crate::core::{Grid, Interval, PiecewiseSurface, Side, Surface};
use crate::spline::{SlopeSystem, SplineEnds};
use crate::{Error, Point, Result};

/// The end conditions of the open directions of a [`BicubicSurface`] (a closed direction is
/// periodic whatever they are).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum BicubicEnds {
    /// The third derivative is continuous across the second and the second-to-last grid line
    /// (Kuznetsov and Filatov's (3.10)–(3.12); SciPy's `not-a-knot`): a bicubic polynomial is
    /// reproduced exactly.
    #[default]
    NotAKnot,
    /// The second derivative across the boundary is zero on every open boundary line (SciPy's
    /// `natural`): the surface flattens towards its open edges.
    Natural,
}

/// A bicubic interpolating spline surface over a grid `r_ij` (row `i` at `u_i`, column `j`
/// at `v_j`), each direction open (not-a-knot ends) or closed (periodic).
///
/// Outside the domain an open direction continues its end patches' polynomials and a closed
/// one wraps by its period.
#[derive(Clone, Debug, PartialEq)]
pub struct BicubicSurface<const D: usize> {
    closed_u: bool,
    closed_v: bool,
    /// The clamped cubic knot vectors over the node parameters (each node a simple knot; the
    /// parameters themselves are the entries between the three repeated ones at each end).
    clamped_u: Vec<f64>,
    clamped_v: Vec<f64>,
    /// The node values `r_ij` ((3.8); a closed direction repeats its first line).
    values: Grid<Point<D>>,
    /// The B-spline control points, row-major, `knots_v.len() + 2` a row.
    net: Vec<Point<D>>,
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
    ///
    /// ```
    /// use karkas::param::{BicubicSurface, GridParameterization};
    /// use karkas::{Grid, Point, Surface};
    ///
    /// // Nodes of z = x y on a 5 x 7 grid; uniform parameters u = i, v = j.
    /// let grid = Grid::from_fn(5, 7, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let surface = BicubicSurface::new(&grid, GridParameterization::Uniform, false, false)?;
    /// let p = surface.eval(2.0, 3.0); // a node: the surface passes through it
    /// assert!(p.distance(Point([2.0, 3.0, 6.0])) < 1e-12);
    /// let q = surface.eval(1.5, 2.5); // between nodes: a bicubic reproduces x y exactly
    /// assert!((q.0[2] - 1.5 * 2.5).abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
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

    /// [`new`](Self::new) with the end conditions `ends` in every open direction (`new` is
    /// this with [`BicubicEnds::NotAKnot`]).
    ///
    /// Errors: as [`new`](Self::new).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::param::{BicubicEnds, BicubicSurface, GridParameterization};
    /// use karkas::{Grid, Point, Surface};
    ///
    /// // z = x^3 along u: not-a-knot ends reproduce the cubic, natural ends bend it.
    /// let grid = Grid::from_fn(5, 2, |i, j| Point([i as f64, j as f64, (i * i * i) as f64]));
    /// let (u, v) = (GridParameterization::Uniform, false);
    /// let exact = BicubicSurface::with_ends(&grid, u, v, v, BicubicEnds::NotAKnot)?;
    /// let natural = BicubicSurface::with_ends(&grid, u, v, v, BicubicEnds::Natural)?;
    /// assert!((exact.eval(0.5, 0.0).0[2] - 0.125).abs() < 1e-12);
    /// assert!((natural.eval(0.5, 0.0).0[2] - 0.125).abs() > 1e-2);
    /// assert!(natural.eval(1.0, 1.0).distance(Point([1.0, 1.0, 1.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn with_ends(
        grid: &Grid<Point<D>>,
        parameterization: GridParameterization,
        closed_u: bool,
        closed_v: bool,
        ends: BicubicEnds,
    ) -> Result<Self> {
        grid.check_points(2, WHAT)?;
        let grid = grid.closed(closed_u, closed_v, WHAT_CLOSED)?;
        let (us, vs) = grid_parameters(&grid, parameterization)?;
        check_parameters(&us)?;
        check_parameters(&vs)?;
        Self::build_with_ends(grid, us, vs, closed_u, closed_v, ends)
    }

    /// [`new`](Self::new) on an owned grid: an open surface keeps `grid` as its values
    /// without copying it (a closed direction copies it once, to close it).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::param::{BicubicSurface, GridParameterization};
    /// use karkas::{Grid, Point, Surface};
    ///
    /// let grid = Grid::from_fn(4, 3, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let surface = BicubicSurface::from_grid(grid, GridParameterization::Uniform, false, false)?;
    /// // Uniform parameters: node (i, j) sits at (u, v) = (i, j).
    /// assert!(surface.eval(2.0, 1.0).distance(Point([2.0, 1.0, 2.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::param::BicubicSurface;
    /// use karkas::{Grid, Point, Surface};
    ///
    /// let grid = Grid::from_fn(3, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let surface = BicubicSurface::from_knots(&grid, &[0.0, 1.0, 4.0], &[0.0, 2.0], false, false)?;
    /// assert!(surface.eval(4.0, 2.0).distance(Point([2.0, 1.0, 0.0])) < 1e-12);
    /// assert!(BicubicSurface::from_knots(&grid, &[0.0, 1.0], &[0.0, 2.0], false, false).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
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
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::param::BicubicSurface;
    /// use karkas::{Grid, Point, Surface};
    ///
    /// let grid = Grid::from_fn(3, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let surface = BicubicSurface::from_grid_knots(grid, &[0.0, 1.0, 4.0], &[0.0, 2.0], false, false)?;
    /// assert!(surface.eval(1.0, 0.0).distance(Point([1.0, 0.0, 0.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
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

    /// The control net: a spline solve along every column, then along every row of the
    /// result.
    fn build(
        grid: Grid<Point<D>>,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        Self::build_with_ends(
            grid,
            knots_u,
            knots_v,
            closed_u,
            closed_v,
            BicubicEnds::NotAKnot,
        )
    }

    /// [`build`](Self::build) with the end conditions `open_ends` in the open directions.
    fn build_with_ends(
        grid: Grid<Point<D>>,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        closed_u: bool,
        closed_v: bool,
        open_ends: BicubicEnds,
    ) -> Result<Self> {
        let ends = |closed: bool| -> SplineEnds<D> {
            match (closed, open_ends) {
                (true, _) => SplineEnds::Periodic,
                (false, BicubicEnds::NotAKnot) => SplineEnds::NotAKnot,
                (false, BicubicEnds::Natural) => SplineEnds::Natural,
            }
        };
        let (ends_u, ends_v) = (ends(closed_u), ends(closed_v));
        let system_u = SlopeSystem::new(&knots_u, &ends_u)?;
        let system_v = SlopeSystem::new(&knots_v, &ends_v)?;
        let net = control_net((&system_u, &knots_u), (&system_v, &knots_v), &grid);
        if !net.iter().all(|c| c.is_finite()) {
            // Coordinate differences over a gap too small for them overflow the slopes.
            return Err(overflow_at_smallest_gap(&[&knots_u, &knots_v]));
        }
        let clamped = |knots: &[f64]| knot_vector(3, knots, &vec![1; knots.len() - 2]);
        Ok(BicubicSurface {
            clamped_u: clamped(&knots_u),
            clamped_v: clamped(&knots_v),
            closed_u,
            closed_v,
            values: grid,
            net,
        })
    }

    /// The knots `u_0 < .. < u_{N-1}` (a closed direction includes the seam twice).
    pub fn knots_u(&self) -> &[f64] {
        &self.clamped_u[3..self.clamped_u.len() - 3]
    }

    /// The knots `v_0 < .. < v_{M-1}`.
    pub fn knots_v(&self) -> &[f64] {
        &self.clamped_v[3..self.clamped_v.len() - 3]
    }

    /// The interpolated node `r_ij` (of the closed grid).
    pub fn node(&self, i: usize, j: usize) -> Point<D> {
        *self.values.get(i, j)
    }

    /// The node derivatives `(m^(1,0), m^(0,1), m^(1,1))` at node `(i, j)` ((3.8)).
    pub fn node_derivatives(&self, i: usize, j: usize) -> (Point<D>, Point<D>, Point<D>) {
        let (cu, cv) = (
            node_cell(i, self.knots_u().len()),
            node_cell(j, self.knots_v().len()),
        );
        (
            self.deriv_on_cell(cu, cv, 1, 0),
            self.deriv_on_cell(cu, cv, 0, 1),
            self.deriv_on_cell(cu, cv, 1, 1),
        )
    }

    /// The B-spline form: clamped cubic knot vectors (a simple knot at every node parameter)
    /// and the `(N + 2) x (M + 2)` control points, row-major.
    pub(crate) fn bspline_parts(&self) -> (&[f64], &[f64], &[Point<D>]) {
        (&self.clamped_u, &self.clamped_v, &self.net)
    }

    /// The condition measure of the parameters at every node of the (closed) grid: the
    /// extension of Kuznetsov and Filatov's (2.4) in [`condition_measure`](super::condition_measure) from the node
    /// tangents `W_u`, `W_v` (`1` exactly for arc lengths along orthogonal directions,
    /// Theorem 2.1; smaller for skewed or stretched parameters). `O(N M)`.
    pub fn condition_measures(&self) -> Grid<f64> {
        self.node_measures_by(condition_measure)
    }

    /// The paper's own measure (2.4), `|D|` for unit rows, at every node of the (closed)
    /// grid: the sine of the angle between the parameter lines
    /// ([`paper_condition_measure`](super::paper_condition_measure)); it does not see
    /// stretched parameters, which [`condition_measures`](Self::condition_measures) does.
    /// `O(N M)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::param::{BicubicSurface, GridParameterization};
    /// use karkas::{Grid, Point};
    ///
    /// // Rows 2 apart with uniform parameters: orthogonal lines (|D| = 1), stretched u (1/2).
    /// let grid = Grid::from_fn(3, 3, |i, j| Point([2.0 * i as f64, j as f64, 0.0]));
    /// let s = BicubicSurface::new(&grid, GridParameterization::Uniform, false, false)?;
    /// assert!(s.paper_condition_measures().as_slice().iter().all(|&d| (d - 1.0).abs() < 1e-12));
    /// assert!((s.condition_summary().min - 0.5).abs() < 1e-12);
    /// assert!((s.paper_condition_summary().min - 1.0).abs() < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn paper_condition_measures(&self) -> Grid<f64> {
        self.node_measures_by(paper_condition_measure)
    }

    /// The measure `measure` of the node tangents at every node of the (closed) grid.
    fn node_measures_by(&self, measure: fn(Point<D>, Point<D>) -> f64) -> Grid<f64> {
        // The value and first-derivative weights of every node line, computed once.
        let lines = |count: usize, weights: &dyn Fn(usize, f64, usize) -> [f64; 4]| {
            (0..count)
                .map(|k| {
                    let (cell, s) = node_cell(k, count);
                    (cell, weights(cell, s, 0), weights(cell, s, 1))
                })
                .collect::<Vec<_>>()
        };
        let rows = lines(self.knots_u().len(), &|i, s, k| self.weights_u(i, s, k));
        let cols = lines(self.knots_v().len(), &|j, t, k| self.weights_v(j, t, k));
        let tangents = |i: usize, j: usize| {
            let ((ci, u0, u1), (cj, v0, v1)) = (&rows[i], &cols[j]);
            (
                self.combine_on_cell(*ci, *cj, u1, v0),
                self.combine_on_cell(*ci, *cj, u0, v1),
            )
        };
        node_measures(rows.len(), cols.len(), tangents, measure)
    }

    /// The smallest and mean condition measure of [`condition_measures`](Self::condition_measures)
    /// and the worst node, over the distinct nodes (a closed direction's repeated seam line
    /// counted once).
    pub fn condition_summary(&self) -> ConditionSummary {
        self.summary_of(&self.condition_measures())
    }

    /// [`condition_summary`](Self::condition_summary) of the paper's measure
    /// [`paper_condition_measures`](Self::paper_condition_measures).
    pub fn paper_condition_summary(&self) -> ConditionSummary {
        self.summary_of(&self.paper_condition_measures())
    }

    /// The summary of node `measures` over the distinct nodes.
    fn summary_of(&self, measures: &Grid<f64>) -> ConditionSummary {
        let rows = measures.rows() - usize::from(self.closed_u);
        let cols = measures.cols() - usize::from(self.closed_v);
        // A grid has at least 2 lines in each direction (3 distinct when closed): never empty.
        ConditionSummary::of(measures, rows, cols).unwrap_or(ConditionSummary {
            min: f64::NAN,
            mean: f64::NAN,
            worst: (0, 0),
            nodes: 0,
        })
    }

    /// The weights of the four control rows of cell `i` for the `k`-th `u`-derivative at
    /// local coordinate `s`.
    #[inline]
    fn weights_u(&self, i: usize, s: f64, k: usize) -> [f64; 4] {
        cubic_span_weights(&self.clamped_u[i + 1..i + 7], s, k)
    }

    /// The weights of the four control columns of cell `j` (see [`weights_u`](Self::weights_u)).
    #[inline]
    fn weights_v(&self, j: usize, t: f64, k: usize) -> [f64; 4] {
        cubic_span_weights(&self.clamped_v[j + 1..j + 7], t, k)
    }

    /// Fills `line` with the control points of the curve `u = const` (all `M + 2` of them):
    /// control rows `i..i + 4` combined with the weights `w`.
    ///
    /// Runs over the coordinates as one flat array (so it vectorizes), with the arithmetic of
    /// `deriv_on_cell`.
    fn combine_rows(&self, i: usize, w: &[f64; 4], line: &mut [Point<D>]) {
        let stride = line.len() * D;
        let rows: &[f64] = bytemuck::cast_slice(&self.net);
        let rows = &rows[i * stride..(i + 4) * stride];
        let (r0, rest) = rows.split_at(stride);
        let (r1, rest) = rest.split_at(stride);
        let (r2, r3) = rest.split_at(stride);
        let line: &mut [f64] = bytemuck::cast_slice_mut(line);
        for ((((q, &a), &b), &c), &d) in line.iter_mut().zip(r0).zip(r1).zip(r2).zip(r3) {
            *q = a * w[0] + b * w[1] + c * w[2] + d * w[3];
        }
    }

    fn deriv_on_cell(
        &self,
        (i, s): (usize, f64),
        (j, t): (usize, f64),
        ku: usize,
        kv: usize,
    ) -> Point<D> {
        self.combine_on_cell(i, j, &self.weights_u(i, s, ku), &self.weights_v(j, t, kv))
    }

    /// The control points of cell `(i, j)` combined with the weights `wu` of its rows and `wv`
    /// of its columns.
    #[inline]
    fn combine_on_cell(&self, i: usize, j: usize, wu: &[f64; 4], wv: &[f64; 4]) -> Point<D> {
        let stride = self.knots_v().len() + 2;
        // Rows first, as in `combine_rows`, so a grid evaluation gives the same bits.
        let row = |a: usize| &self.net[(i + a) * stride + j..][..4];
        let (r0, r1, r2, r3) = (row(0), row(1), row(2), row(3));
        let c: [Point<D>; 4] =
            std::array::from_fn(|b| r0[b] * wu[0] + r1[b] * wu[1] + r2[b] * wu[2] + r3[b] * wu[3]);
        c[0] * wv[0] + c[1] * wv[1] + c[2] * wv[2] + c[3] * wv[3]
    }
}

/// The cell of node `k` of `count` and its local coordinate there: the start of its cell, the
/// last node the end of the last cell.
#[inline]
fn node_cell(k: usize, count: usize) -> (usize, f64) {
    (k.min(count - 2), if k + 1 >= count { 1.0 } else { 0.0 })
}

/// The input named in the errors of a grid too small (in total, in a closed direction).
const WHAT: &str = "a bicubic surface (in each grid direction)";
const WHAT_CLOSED: &str = "a closed direction of a bicubic surface (distinct grid lines)";

impl<const D: usize> Surface<D> for BicubicSurface<D> {
    fn domain_u(&self) -> Interval {
        Interval::new(self.knots_u()[0], self.knots_u()[self.knots_u().len() - 1])
    }

    fn domain_v(&self) -> Interval {
        Interval::new(self.knots_v()[0], self.knots_v()[self.knots_v().len() - 1])
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
            locate(self.knots_u(), self.closed_u, u, Side::Above),
            locate(self.knots_v(), self.closed_v, v, Side::Above),
            ku,
            kv,
        )
    }

    fn eval_grid_into(&self, us: &[f64], vs: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_grid_len(us.len(), vs.len(), out.len());
        let columns: Vec<(usize, [f64; 4])> = vs
            .iter()
            .map(|&v| {
                let (j, t) = locate(self.knots_v(), self.closed_v, v, Side::Above);
                (j, self.weights_v(j, t, 0))
            })
            .collect();
        let stride = self.knots_v().len() + 2;
        let row_len = vs.len().max(1);
        for_each_row_block(out, row_len, |first, block| {
            let mut line = vec![Point::ZERO; stride];
            for (&u, out_row) in us[first..].iter().zip(block.chunks_exact_mut(row_len)) {
                let (i, s) = locate(self.knots_u(), self.closed_u, u, Side::Above);
                self.combine_rows(i, &self.weights_u(i, s, 0), &mut line);
                for (p, &(j, w)) in out_row.iter_mut().zip(&columns) {
                    let c = &line[j..j + 4];
                    *p = c[0] * w[0] + c[1] * w[1] + c[2] * w[2] + c[3] * w[3];
                }
            }
        });
    }
}

impl<const D: usize> PiecewiseSurface<D> for BicubicSurface<D> {
    fn breakpoints_u(&self) -> Vec<f64> {
        self.knots_u().to_vec()
    }

    fn breakpoints_v(&self) -> Vec<f64> {
        self.knots_v().to_vec()
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
            locate(self.knots_u(), self.closed_u, u, side_u),
            locate(self.knots_v(), self.closed_v, v, side_v),
            ku,
            kv,
        )
    }
}

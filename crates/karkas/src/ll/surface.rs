//! LL surfaces (Aulchenko et al., formulas (11)–(20); docs/methods.md §1.3).
//!
//! The tensor product of the curve scheme: on the cell around node `(i, j)`,
//! `P(xi, eta) = sum_{a,b in {-,0,+}} c_a(xi) c_b(eta) r_{i+a, j+b}`. Rows and columns are
//! extended as in (20) (`r_{i,0} = 2 r_{i,1} - r_{i,2}`, corners by the same rule applied
//! twice), or periodically in a closed direction. Every line `u = const` and `v = const` is an
//! LL curve of the other variable; all partial derivatives up to order `L` in each variable
//! are continuous; the grid corners are interpolated.
//!
//! Grid evaluation costs `O(Ky)` per sample row plus 9 multiply-adds per point: rows are
//! combined first (the column curve's control points at this `u`), then columns, with the
//! weights of every sample line computed once. The interpolating variant solves the 1-D
//! system (6) along every row, then every column: `O(Kx Ky)`.

use super::axis::NodeAxis;
use super::curve::LlCurve;
use super::frame::extend;
use super::kernel::{pow_n, LlKernel};
use super::prefilter::{along_rows_then_columns, interpolation_controls};
use crate::core::parallel::for_each_row_block;
use crate::core::{Grid, Interval, ParameterLine, PiecewiseSurface, Side, Surface};
use crate::{Point, Result};

/// An LL surface of order `L` over a grid `r_ij`, `i = 1..Kx` (parameter `u`, rows),
/// `j = 1..Ky` (parameter `v`, columns), each direction open or closed.
///
/// Parameters follow the paper: node `(i, j)` at `(i/(Kx+1), j/(Ky+1))`. Outside the domain
/// an open direction is clamped and a closed one wraps.
#[derive(Clone, Debug, PartialEq)]
pub struct LlSurface<const D: usize> {
    kernel: LlKernel,
    axis_u: NodeAxis,
    axis_v: NodeAxis,
    /// `r_{0..Kx+1, 0..Ky+1}`.
    extended: Grid<Point<D>>,
}

impl<const D: usize> LlSurface<D> {
    /// The LL approximation of order `order` over `grid` (rows along `u`).
    ///
    /// A closed direction is closed like a curve: if the last row (column) repeats the first
    /// it is the paper's `r_K = r_1`, otherwise the first is appended.
    ///
    /// Errors: fewer than 3 rows or columns (3 distinct when closed), a non-finite point
    /// (named by its cell), `order` outside `1..=64`.
    ///
    /// ```
    /// use karkas::{ll::LlSurface, Grid, Point, Surface};
    ///
    /// // A 6 x 8 grid of the plane z = x + y: the LL surface of a plane is that plane.
    /// let grid = Grid::from_fn(6, 8, |i, j| Point([i as f64, j as f64, (i + j) as f64]));
    /// let surface = LlSurface::new(&grid, 3, false, false)?;
    /// let (u, v) = (surface.domain_u().uniform(3, 7), surface.domain_v().uniform(2, 5));
    /// let p = surface.eval(u, v);
    /// assert!((p.0[2] - (p.0[0] + p.0[1])).abs() < 1e-9);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        grid: &Grid<Point<D>>,
        order: usize,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        Self::build(grid, order, (closed_u, closed_v), false)
    }

    /// The interpolating LL surface: passes through every grid point at its node. Solves the
    /// tridiagonal system (6) along every row, then every column. Same rules as
    /// [`new`](Self::new).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::{ll::LlSurface, Grid, Point, Surface};
    ///
    /// // Through every node of a 5 x 6 grid of the saddle z = x y.
    /// let grid = Grid::from_fn(5, 6, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let surface = LlSurface::interpolating(&grid, 2, false, false)?;
    /// // The nodes spread evenly over the domain: node (2, 3) of the 5 x 6 grid.
    /// let (u, v) = (surface.domain_u().uniform(2, 5), surface.domain_v().uniform(3, 6));
    /// assert!(surface.eval(u, v).distance(*grid.get(2, 3)) < 1e-9);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn interpolating(
        grid: &Grid<Point<D>>,
        order: usize,
        closed_u: bool,
        closed_v: bool,
    ) -> Result<Self> {
        Self::build(grid, order, (closed_u, closed_v), true)
    }

    /// Validates and closes the input grid, solves for the interpolating controls when
    /// `interpolate`, and extends.
    fn build(
        grid: &Grid<Point<D>>,
        order: usize,
        (closed_u, closed_v): (bool, bool),
        interpolate: bool,
    ) -> Result<Self> {
        let kernel = LlKernel::new(order)?;
        grid.check_points(3, "an LL surface (in each grid direction)")?;
        let mut control = grid.closed(
            closed_u,
            closed_v,
            "a closed direction of an LL surface (distinct rows or columns)",
        )?;
        if interpolate {
            let d_l = kernel.d_l();
            along_rows_then_columns(&mut control, (closed_u, closed_v), |line, closed| {
                interpolation_controls(line, d_l, closed)
            })?;
        }
        Ok(Self::from_control(kernel, control, closed_u, closed_v))
    }

    /// Builds the surface from a ready control grid (closed directions already repeat).
    pub(super) fn from_control(
        kernel: LlKernel,
        control: Grid<Point<D>>,
        closed_u: bool,
        closed_v: bool,
    ) -> Self {
        let (kx, ky) = (control.rows(), control.cols());
        let rows: Vec<Vec<Point<D>>> = (0..kx).map(|i| extend(control.row(i), closed_v)).collect();
        let mut extended = Grid::from_fn(kx + 2, ky + 2, |_, _| Point::ZERO);
        let mut column = vec![Point::ZERO; kx];
        for j in 0..ky + 2 {
            for (c, row) in column.iter_mut().zip(&rows) {
                *c = row[j];
            }
            for (i, p) in extend(&column, closed_u).into_iter().enumerate() {
                *extended.get_mut(i, j) = p;
            }
        }
        LlSurface {
            kernel,
            axis_u: NodeAxis::new(kx, closed_u),
            axis_v: NodeAxis::new(ky, closed_v),
            extended,
        }
    }

    /// The order `L`.
    pub fn order(&self) -> usize {
        self.kernel.order()
    }

    /// The node grid of `u` (rows).
    pub fn axis_u(&self) -> NodeAxis {
        self.axis_u
    }

    /// The node grid of `v` (columns).
    pub fn axis_v(&self) -> NodeAxis {
        self.axis_v
    }

    /// The control point `r_ij` (0-based `i < Kx`, `j < Ky`; the interpolating variant's
    /// solved `r*`).
    pub fn control_point(&self, i: usize, j: usize) -> Point<D> {
        *self.extended.get(i + 1, j + 1)
    }

    /// The kernel `h` of this surface's order.
    pub fn kernel(&self) -> &LlKernel {
        &self.kernel
    }

    /// The extended control grid `r_{0..Kx+1, 0..Ky+1}`.
    pub(crate) fn extended(&self) -> &Grid<Point<D>> {
        &self.extended
    }

    /// The line `u = const` as an LL curve of `v`: its control points are the row
    /// combinations `Q_j = sum_a c_a(xi) r_{i+a, j}`.
    pub fn curve_at_u(&self, u: f64) -> LlCurve<D> {
        let (i, xi) = self.axis_u.locate(u);
        let w = self.kernel.weights(xi, 0);
        let control = self.combine_rows(i, w);
        let ky = self.axis_v.nodes();
        LlCurve::from_control(
            self.kernel.clone(),
            control[1..=ky].to_vec(),
            self.axis_v.is_closed(),
        )
    }

    /// The line `v = const` as an LL curve of `u`.
    pub fn curve_at_v(&self, v: f64) -> LlCurve<D> {
        let (j, eta) = self.axis_v.locate(v);
        let w = self.kernel.weights(eta, 0);
        let control = (1..=self.axis_u.nodes())
            .map(|i| {
                let r = &self.extended.row(i)[j - 1..=j + 1];
                r[0] * w[0] + r[1] * w[1] + r[2] * w[2]
            })
            .collect();
        LlCurve::from_control(self.kernel.clone(), control, self.axis_u.is_closed())
    }

    /// `sum_a w[a] r_{i-1+a, .}` over the whole extended row (Ky + 2 points).
    fn combine_rows(&self, i: usize, w: [f64; 3]) -> Vec<Point<D>> {
        let mut out = vec![Point::ZERO; self.extended.cols()];
        self.combine_rows_into(i, w, &mut out);
        out
    }

    #[inline]
    fn combine_rows_into(&self, i: usize, w: [f64; 3], out: &mut [Point<D>]) {
        let (r0, r1, r2) = (
            self.extended.row(i - 1),
            self.extended.row(i),
            self.extended.row(i + 1),
        );
        for (j, q) in out.iter_mut().enumerate() {
            *q = r0[j] * w[0] + r1[j] * w[1] + r2[j] * w[2];
        }
    }

    /// The partial derivative on cell `(i, j)` at local `(xi, eta)`, per unit `u`, `v`.
    fn deriv_on_cell(
        &self,
        (i, xi): (usize, f64),
        (j, eta): (usize, f64),
        ku: usize,
        kv: usize,
    ) -> Point<D> {
        let wu = self.kernel.weights(xi, ku);
        let wv = self.kernel.weights(eta, kv);
        let mut p = Point::ZERO;
        for (a, &wa) in wu.iter().enumerate() {
            let row = &self.extended.row(i - 1 + a)[j - 1..=j + 1];
            p = p.add_scaled(wa, row[0] * wv[0] + row[1] * wv[1] + row[2] * wv[2]);
        }
        p * (pow_n(self.axis_u.scale(), ku) * pow_n(self.axis_v.scale(), kv))
    }
}

impl<const D: usize> Surface<D> for LlSurface<D> {
    fn domain_u(&self) -> Interval {
        self.axis_u.domain()
    }

    fn domain_v(&self) -> Interval {
        self.axis_v.domain()
    }

    fn is_closed_u(&self) -> bool {
        self.axis_u.is_closed()
    }

    fn is_closed_v(&self) -> bool {
        self.axis_v.is_closed()
    }

    fn eval(&self, u: f64, v: f64) -> Point<D> {
        self.deriv_on_cell(self.axis_u.locate(u), self.axis_v.locate(v), 0, 0)
    }

    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        self.deriv_on_cell(self.axis_u.locate(u), self.axis_v.locate(v), ku, kv)
    }

    /// Lines `u = u*` when `normal . r_ij` is constant along every row (the paper's grids,
    /// where `x` depends on the row only), lines `v = v*` when it is constant along every
    /// column; the roots of the 1-D LL function (21) are found exactly
    /// (see `ll/level_lines.rs`).
    fn level_parameter_lines(&self, normal: Point<D>, level: f64) -> Option<Vec<ParameterLine>> {
        self.level_lines(normal, level)
    }

    fn eval_grid_into(&self, us: &[f64], vs: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_grid_len(us.len(), vs.len(), out.len());
        let columns: Vec<(usize, [f64; 3])> = vs
            .iter()
            .map(|&v| {
                let (j, eta) = self.axis_v.locate(v);
                (j, self.kernel.weights(eta, 0))
            })
            .collect();
        let row_len = vs.len().max(1);
        for_each_row_block(out, row_len, |first, block| {
            let mut row = vec![Point::ZERO; self.extended.cols()];
            for (&u, out_row) in us[first..].iter().zip(block.chunks_exact_mut(row_len)) {
                let (i, xi) = self.axis_u.locate(u);
                self.combine_rows_into(i, self.kernel.weights(xi, 0), &mut row);
                for (p, &(j, w)) in out_row.iter_mut().zip(&columns) {
                    *p = row[j - 1] * w[0] + row[j] * w[1] + row[j + 1] * w[2];
                }
            }
        });
    }
}

impl<const D: usize> PiecewiseSurface<D> for LlSurface<D> {
    fn breakpoints_u(&self) -> Vec<f64> {
        self.axis_u.breakpoints()
    }

    fn breakpoints_v(&self) -> Vec<f64> {
        self.axis_v.breakpoints()
    }

    fn continuity(&self) -> usize {
        self.kernel.order()
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
            self.axis_u.locate_on_side(u, side_u),
            self.axis_v.locate_on_side(v, side_v),
            ku,
            kv,
        )
    }
}

//! Tensor-product B-spline surfaces.

use super::curve::{check_knots, de_boor, distinct_knots, find_span, BSplineCurve, MAX_DEGREE};
use crate::core::{Curve, Grid, Interval, Surface};
use crate::{Error, Point, Result};

/// A non-rational tensor-product B-spline surface with clamped knot vectors in `u` and `v`.
///
/// Control point `(i, j)` (row `i` along `u`, column `j` along `v`) weighs
/// `N_i^p(u) N_j^q(v)`. Domain `[knots_u[p], knots_u[nu]] x [knots_v[q], knots_v[nv]]`;
/// parameters outside are clamped. A closed karkas direction is exported over one period as
/// a clamped open direction whose first and last control lines coincide.
#[derive(Clone, Debug, PartialEq)]
pub struct BSplineSurface<const D: usize> {
    degree_u: usize,
    degree_v: usize,
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    control: Grid<Point<D>>,
    closed_u: bool,
    closed_v: bool,
}

impl<const D: usize> BSplineSurface<D> {
    /// The surface of degrees `(degree_u, degree_v)` over clamped knot vectors with the
    /// control grid `control` (`rows + degree_u + 1 == knots_u.len()`, same for columns).
    ///
    /// Errors: as [`BSplineCurve::new`] in each direction; a non-finite control point
    /// ([`Error::NonFiniteCell`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineSurface;
    /// use karkas::{Grid, Point, Surface};
    ///
    /// // The bilinear patch through (0,0,0), (1,0,0), (0,1,0), (1,1,1): z = u v.
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let patch = BSplineSurface::new(linear.clone(), linear.clone(), control.clone())?;
    /// assert!(patch.eval(0.5, 0.5).distance(Point([0.5, 0.5, 0.25])) < 1e-14);
    /// // Three knots are too few for two control points of degree 1.
    /// assert!(BSplineSurface::new((1, vec![0.0, 1.0, 1.0]), linear, control).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        (degree_u, knots_u): (usize, Vec<f64>),
        (degree_v, knots_v): (usize, Vec<f64>),
        control: Grid<Point<D>>,
    ) -> Result<Self> {
        check_knots(degree_u, &knots_u, control.rows())?;
        check_knots(degree_v, &knots_v, control.cols())?;
        if let Some(k) = control.as_slice().iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFiniteCell {
                row: k / control.cols(),
                col: k % control.cols(),
            });
        }
        Ok(BSplineSurface {
            degree_u,
            degree_v,
            knots_u,
            knots_v,
            control,
            closed_u: false,
            closed_v: false,
        })
    }

    /// Marks directions as one period of a closed direction.
    pub(crate) fn with_closed(mut self, closed_u: bool, closed_v: bool) -> Self {
        self.closed_u = closed_u;
        self.closed_v = closed_v;
        self
    }

    /// The degree in `u`.
    pub fn degree_u(&self) -> usize {
        self.degree_u
    }

    /// The degree in `v`.
    pub fn degree_v(&self) -> usize {
        self.degree_v
    }

    /// The clamped knot vector in `u`.
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }

    /// The clamped knot vector in `v`.
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }

    /// The control grid (rows along `u`).
    pub fn control_points(&self) -> &Grid<Point<D>> {
        &self.control
    }

    /// The distinct `u` knots with multiplicities.
    pub fn distinct_knots_u(&self) -> Vec<(f64, usize)> {
        distinct_knots(&self.knots_u)
    }

    /// The distinct `v` knots with multiplicities.
    pub fn distinct_knots_v(&self) -> Vec<(f64, usize)> {
        distinct_knots(&self.knots_v)
    }

    /// The iso-line `u = const` as a B-spline curve of `v` (its control points are the
    /// column combinations at `u`).
    pub fn curve_at_u(&self, u: f64) -> BSplineCurve<D> {
        let (p, rows, cols) = (self.degree_u, self.control.rows(), self.control.cols());
        let u = u.clamp(self.knots_u[p], self.knots_u[rows]);
        let span = find_span(p, &self.knots_u, rows, u);
        let mut work = [Point::ZERO; MAX_DEGREE + 1];
        let control = (0..cols)
            .map(|j| {
                de_boor(
                    p,
                    &self.knots_u,
                    |i| *self.control.get(i, j),
                    span,
                    u,
                    &mut work,
                )
            })
            .collect();
        BSplineCurve::from_parts(self.degree_v, self.knots_v.clone(), control)
    }

    /// The iso-line `v = const` as a B-spline curve of `u`.
    pub fn curve_at_v(&self, v: f64) -> BSplineCurve<D> {
        let (q, rows, cols) = (self.degree_v, self.control.rows(), self.control.cols());
        let v = v.clamp(self.knots_v[q], self.knots_v[cols]);
        let span = find_span(q, &self.knots_v, cols, v);
        let mut work = [Point::ZERO; MAX_DEGREE + 1];
        let control = (0..rows)
            .map(|i| {
                de_boor(
                    q,
                    &self.knots_v,
                    |j| *self.control.get(i, j),
                    span,
                    v,
                    &mut work,
                )
            })
            .collect();
        BSplineCurve::from_parts(self.degree_u, self.knots_u.clone(), control)
    }
}

impl<const D: usize> Surface<D> for BSplineSurface<D> {
    fn domain_u(&self) -> Interval {
        Interval::new(
            self.knots_u[self.degree_u],
            self.knots_u[self.control.rows()],
        )
    }

    fn domain_v(&self) -> Interval {
        Interval::new(
            self.knots_v[self.degree_v],
            self.knots_v[self.control.cols()],
        )
    }

    fn is_closed_u(&self) -> bool {
        self.closed_u
    }

    fn is_closed_v(&self) -> bool {
        self.closed_v
    }

    fn eval(&self, u: f64, v: f64) -> Point<D> {
        let (p, q) = (self.degree_u, self.degree_v);
        let (rows, cols) = (self.control.rows(), self.control.cols());
        let u = u.clamp(self.knots_u[p], self.knots_u[rows]);
        let v = v.clamp(self.knots_v[q], self.knots_v[cols]);
        let su = find_span(p, &self.knots_u, rows, u);
        let sv = find_span(q, &self.knots_v, cols, v);
        let mut column = [Point::ZERO; MAX_DEGREE + 1];
        let mut work = [Point::ZERO; MAX_DEGREE + 1];
        for (a, c) in column.iter_mut().enumerate().take(p + 1) {
            let i = su - p + a;
            *c = de_boor(
                q,
                &self.knots_v,
                |j| *self.control.get(i, j),
                sv,
                v,
                &mut work,
            );
        }
        de_boor(p, &self.knots_u, |i| column[i + p - su], su, u, &mut work)
    }

    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        if ku == 0 && kv == 0 {
            return self.eval(u, v);
        }
        // The v-derivative of the u-derivative line: iso-curve at v, differentiated in u,
        // then the same for v. Built per call (derivatives are not on a hot path).
        let at_v = self.derivative_in_v(kv);
        at_v.curve_at_v(v).deriv(u, ku)
    }
}

impl<const D: usize> BSplineSurface<D> {
    /// The partial derivative `d^(ku+kv) S / du^ku dv^kv` as a B-spline surface (degrees
    /// lowered by `ku` and `kv`, at least 0), built once for evaluating it at many points
    /// (each [`Surface::deriv`] call builds it anew).
    pub fn derivative_surface(&self, ku: usize, kv: usize) -> BSplineSurface<D> {
        self.derivative_in_v(kv).derivative_in_u(ku)
    }

    /// The surface differentiated `k` times in `u` (as [`Self::derivative_in_v`]).
    fn derivative_in_u(&self, k: usize) -> BSplineSurface<D> {
        let mut s = self.clone();
        for _ in 0..k {
            if s.degree_u == 0 {
                break;
            }
            let p = s.degree_u;
            let (rows, cols) = (s.control.rows(), s.control.cols());
            let control = Grid::from_fn(rows - 1, cols, |i, j| {
                let span = s.knots_u[i + p + 1] - s.knots_u[i + 1];
                if span > 0.0 {
                    (*s.control.get(i + 1, j) - *s.control.get(i, j)) * (p as f64 / span)
                } else {
                    Point::ZERO
                }
            });
            s = BSplineSurface {
                degree_u: p - 1,
                degree_v: s.degree_v,
                knots_u: s.knots_u[1..s.knots_u.len() - 1].to_vec(),
                knots_v: s.knots_v,
                control,
                closed_u: false,
                closed_v: false,
            };
        }
        s
    }

    /// The surface differentiated `k` times in `v` (degree `q - k`, at least 0; a degree-0
    /// direction is piecewise constant, which de Boor's algorithm evaluates as is).
    fn derivative_in_v(&self, k: usize) -> BSplineSurface<D> {
        let mut s = self.clone();
        for _ in 0..k {
            if s.degree_v == 0 {
                break;
            }
            let q = s.degree_v;
            let (rows, cols) = (s.control.rows(), s.control.cols());
            let control = Grid::from_fn(rows, cols - 1, |i, j| {
                let span = s.knots_v[j + q + 1] - s.knots_v[j + 1];
                if span > 0.0 {
                    (*s.control.get(i, j + 1) - *s.control.get(i, j)) * (q as f64 / span)
                } else {
                    Point::ZERO
                }
            });
            s = BSplineSurface {
                degree_u: s.degree_u,
                degree_v: q - 1,
                knots_u: s.knots_u,
                knots_v: s.knots_v[1..s.knots_v.len() - 1].to_vec(),
                control,
                closed_u: false,
                closed_v: false,
            };
        }
        s
    }
}

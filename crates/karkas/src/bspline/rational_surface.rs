//! Rational tensor-product B-spline (NURBS) surfaces: `S(u, v) = sum N_i(u) N_j(v) w_ij P_ij
//! / sum N_i(u) N_j(v) w_ij` over any knot vectors (Piegl and Tiller, *The NURBS Book*,
//! (4.15)); partial derivatives of every order by the quotient rule (A4.4).

use super::rational::{check_general_knots, check_weights, rational_surface_derivatives};
use super::span_basis::{
    basis_derivative, local_derivatives, span_of, Homogeneous, Linear, MAX_SPAN, SMALL_SPAN,
    TINY_SPAN,
};
use super::{BSplineSurface, NurbsCurve, ToBSplineSurface};
use crate::core::{Grid, Interval, Surface};
use crate::{Error, Point, Result};

/// A rational tensor-product B-spline surface: control grid `P_ij` (row `i` along `u`,
/// column `j` along `v`), positive weights `w_ij`, knot vectors in `u` and `v` (clamped or
/// not).
///
/// Domain `[knots_u[p], knots_u[nu]] x [knots_v[q], knots_v[nv]]`; outside it an open
/// direction continues its end pieces and a closed one wraps the parameter. Equal weights give the polynomial B-spline
/// surface of the same control grid.
///
/// ```
/// use karkas::bspline::NurbsSurface;
/// use karkas::{Grid, Point3, Surface};
/// // A quarter of the unit cylinder x^2 + y^2 = 1, 0 <= z <= 2.
/// let w = std::f64::consts::FRAC_1_SQRT_2;
/// let ring = [[1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
/// let control = Grid::from_fn(3, 2, |i, j| Point3::new([ring[i][0], ring[i][1], 2.0 * j as f64]));
/// let weights = Grid::from_fn(3, 2, |i, _| if i == 1 { w } else { 1.0 });
/// let s = NurbsSurface::new(
///     (2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
///     (1, vec![0.0, 0.0, 1.0, 1.0]),
///     control,
///     weights,
/// )
/// .unwrap();
/// let p = s.eval(0.3, 0.5);
/// assert!((p[0].hypot(p[1]) - 1.0).abs() < 1e-15 && (p[2] - 1.0).abs() < 1e-15);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct NurbsSurface<const D: usize> {
    degree_u: usize,
    degree_v: usize,
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
    control: Grid<Point<D>>,
    weights: Grid<f64>,
    /// `w_ij P_ij`.
    weighted: Grid<Point<D>>,
    closed_u: bool,
    closed_v: bool,
}

/// The first and second partial derivatives of a surface at one point, with the point:
/// what Newton's method on a distance and the normal and curvatures need.
pub type SecondOrder<const D: usize> = [Point<D>; 6];

impl<const D: usize> NurbsSurface<D> {
    /// The surface of degrees `(degree_u, degree_v)` over `knots_u`, `knots_v` with the
    /// control grid `control` (`rows + degree_u + 1 == knots_u.len()`, same for columns) and
    /// the weights `weights` (same shape).
    ///
    /// Errors: as [`NurbsCurve::new`] in each direction; a weight grid of another shape
    /// ([`Error::CountMismatch`]); a non-finite control point ([`Error::NonFiniteCell`]); a
    /// weight that is not finite and positive ([`Error::InvalidWeight`], row-major index).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::NurbsSurface;
    /// use karkas::{Grid, Point, Surface};
    ///
    /// // The bilinear patch z = u v with unit weights.
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let weights = Grid::from_fn(2, 2, |_, _| 1.0);
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let patch = NurbsSurface::new(linear.clone(), linear.clone(), control.clone(), weights)?;
    /// assert!(patch.eval(0.5, 0.5).distance(Point([0.5, 0.5, 0.25])) < 1e-14);
    /// let bad = Grid::from_fn(2, 2, |_, _| -1.0);
    /// assert!(NurbsSurface::new(linear.clone(), linear, control, bad).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        (degree_u, knots_u): (usize, Vec<f64>),
        (degree_v, knots_v): (usize, Vec<f64>),
        control: Grid<Point<D>>,
        weights: Grid<f64>,
    ) -> Result<Self> {
        check_general_knots(degree_u, &knots_u, control.rows())?;
        check_general_knots(degree_v, &knots_v, control.cols())?;
        if (weights.rows(), weights.cols()) != (control.rows(), control.cols()) {
            return Err(Error::CountMismatch {
                what: "weights of a rational B-spline surface (one per control point)",
                expected: control.rows() * control.cols(),
                got: weights.rows() * weights.cols(),
            });
        }
        if let Some(k) = control.as_slice().iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFiniteCell {
                row: k / control.cols(),
                col: k % control.cols(),
            });
        }
        check_weights(weights.as_slice())?;
        let weighted = Grid::from_fn(control.rows(), control.cols(), |i, j| {
            *control.get(i, j) * *weights.get(i, j)
        });
        Ok(NurbsSurface {
            degree_u,
            degree_v,
            knots_u,
            knots_v,
            control,
            weights,
            weighted,
            closed_u: false,
            closed_v: false,
        })
    }

    /// The polynomial B-spline surface `surface` with every weight 1.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::{BSplineSurface, NurbsSurface};
    /// use karkas::{Grid, Point, Surface};
    ///
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, (i * j) as f64]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let surface = BSplineSurface::new(linear.clone(), linear, control)?;
    /// let nurbs = NurbsSurface::from_bspline(&surface);
    /// assert!(nurbs.eval(0.2, 0.7).distance(surface.eval(0.2, 0.7)) < 1e-14);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn from_bspline(surface: &BSplineSurface<D>) -> Self {
        let control = surface.control_points().clone();
        NurbsSurface {
            degree_u: surface.degree_u(),
            degree_v: surface.degree_v(),
            knots_u: surface.knots_u().to_vec(),
            knots_v: surface.knots_v().to_vec(),
            weights: Grid::from_fn(control.rows(), control.cols(), |_, _| 1.0),
            weighted: control.clone(),
            control,
            closed_u: surface.is_closed_u(),
            closed_v: surface.is_closed_v(),
        }
    }

    /// The same surface with its directions marked closed (periodic) or open.
    pub fn with_closed(mut self, closed_u: bool, closed_v: bool) -> Self {
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

    /// The knot vector in `u`.
    pub fn knots_u(&self) -> &[f64] {
        &self.knots_u
    }

    /// The knot vector in `v`.
    pub fn knots_v(&self) -> &[f64] {
        &self.knots_v
    }

    /// The control grid (rows along `u`).
    pub fn control_points(&self) -> &Grid<Point<D>> {
        &self.control
    }

    /// The weights (same shape as the control grid).
    pub fn weights(&self) -> &Grid<f64> {
        &self.weights
    }

    /// True when the weights differ.
    pub fn is_rational(&self) -> bool {
        let w = self.weights.as_slice();
        w.iter().any(|&x| x != w[0])
    }

    /// True when both knot vectors are clamped.
    pub fn is_clamped(&self) -> bool {
        let clamped = |p: usize, k: &[f64]| {
            k[..=p].iter().all(|&x| x == k[0])
                && k[k.len() - p - 1..].iter().all(|&x| x == k[k.len() - 1])
        };
        clamped(self.degree_u, &self.knots_u) && clamped(self.degree_v, &self.knots_v)
    }

    /// The polynomial B-spline surface equal to this one, when its weights are all equal and
    /// its knots clamped (`None` otherwise).
    pub fn to_bspline(&self) -> Option<BSplineSurface<D>> {
        if self.is_rational() || !self.is_clamped() {
            return None;
        }
        BSplineSurface::new(
            (self.degree_u, self.knots_u.clone()),
            (self.degree_v, self.knots_v.clone()),
            self.control.clone(),
        )
        .ok()
    }

    /// The surface with its control points mapped by the affine map `f`.
    pub fn map_points<const E: usize>(&self, f: impl Fn(Point<D>) -> Point<E>) -> NurbsSurface<E> {
        let (rows, cols) = (self.control.rows(), self.control.cols());
        let control = Grid::from_fn(rows, cols, |i, j| f(*self.control.get(i, j)));
        let weighted = Grid::from_fn(rows, cols, |i, j| {
            *control.get(i, j) * *self.weights.get(i, j)
        });
        NurbsSurface {
            degree_u: self.degree_u,
            degree_v: self.degree_v,
            knots_u: self.knots_u.clone(),
            knots_v: self.knots_v.clone(),
            control,
            weights: self.weights.clone(),
            weighted,
            closed_u: self.closed_u,
            closed_v: self.closed_v,
        }
    }

    /// The iso-curve `v = const` (a curve of `u`) or `u = const` (a curve of `v`), exact: its
    /// homogeneous control points are those of the grid's lines combined at the fixed
    /// parameter.
    pub fn iso_curve(&self, along_u: bool, at: f64) -> NurbsCurve<D> {
        let (rows, cols) = (self.control.rows(), self.control.cols());
        let (p, knots, _count, lines, fixed_degree, fixed_knots, fixed_count) = if along_u {
            let v = self.domain_v().clamp(self.parameter_v(at));
            (
                self.degree_u,
                &self.knots_u,
                rows,
                rows,
                self.degree_v,
                &self.knots_v,
                (cols, v),
            )
        } else {
            let u = self.domain_u().clamp(self.parameter_u(at));
            (
                self.degree_v,
                &self.knots_v,
                cols,
                cols,
                self.degree_u,
                &self.knots_u,
                (rows, u),
            )
        };
        let (n_fixed, t) = fixed_count;
        let span = span_of(fixed_degree, fixed_knots, n_fixed, t);
        let mut basis = [0.0; MAX_SPAN];
        basis_derivative(fixed_degree, fixed_knots, span, t, 0, &mut basis);
        let mut control = Vec::with_capacity(lines);
        let mut weights = Vec::with_capacity(lines);
        for line in 0..lines {
            let mut a = Point::ZERO;
            let mut w = 0.0;
            for (c, &b) in basis[..=fixed_degree].iter().enumerate() {
                let other = span - fixed_degree + c;
                let (i, j) = if along_u {
                    (line, other)
                } else {
                    (other, line)
                };
                a += *self.weighted.get(i, j) * b;
                w += *self.weights.get(i, j) * b;
            }
            control.push(a * (1.0 / w));
            weights.push(w);
        }
        let closed = if along_u {
            self.closed_u
        } else {
            self.closed_v
        };
        // The knots are the surface's; the weights positive combinations of positive weights.
        NurbsCurve::from_checked_parts(p, knots.clone(), control, weights).with_closed(closed)
    }

    /// `u` wrapped into the domain in a closed direction, as it is in an open one.
    fn parameter_u(&self, u: f64) -> f64 {
        if self.closed_u {
            self.domain_u().wrap(u)
        } else {
            u
        }
    }

    /// `v` wrapped into the domain in a closed direction, as it is in an open one.
    fn parameter_v(&self, v: f64) -> f64 {
        if self.closed_v {
            self.domain_v().wrap(v)
        } else {
            v
        }
    }

    /// The partial derivatives `S_{k,l}` for `k <= nu`, `l <= nv` at `(u, v)` into `out`
    /// (`out[k * (nv + 1) + l]`, which must hold `(nu + 1)(nv + 1)` points).
    pub fn derivatives_into(&self, u: f64, v: f64, nu: usize, nv: usize, out: &mut [Point<D>]) {
        let (u, v) = (self.parameter_u(u), self.parameter_v(v));
        let (p, q) = (self.degree_u, self.degree_v);
        let (rows, cols) = (self.control.rows(), self.control.cols());
        let su = span_of(p, &self.knots_u, rows, u);
        let sv = span_of(q, &self.knots_v, cols, v);
        let stride = nv + 1;
        // Along v first: the v-derivatives of every row of the span's homogeneous points.
        let mut rows_d = vec![Homogeneous::<D>::ZERO; (p + 1) * stride];
        let mut local = [Homogeneous::<D>::ZERO; MAX_SPAN];
        for a in 0..=p {
            let i = su - p + a;
            for (c, h) in local[..=q].iter_mut().enumerate() {
                *h = self.homogeneous(i, sv - q + c);
            }
            local_derivatives(
                q,
                &self.knots_v,
                sv,
                v,
                &local,
                &mut rows_d[a * stride..(a + 1) * stride],
            );
        }
        // Then along u, for every order in v.
        let mut w = vec![0.0; (nu + 1) * stride];
        let mut column = vec![Homogeneous::<D>::ZERO; nu + 1];
        for l in 0..=nv {
            for (a, h) in local[..=p].iter_mut().enumerate() {
                *h = rows_d[a * stride + l];
            }
            local_derivatives(p, &self.knots_u, su, u, &local, &mut column);
            for (k, h) in column.iter().enumerate() {
                out[k * stride + l] = h.point;
                w[k * stride + l] = h.weight;
            }
        }
        rational_surface_derivatives(&mut out[..(nu + 1) * stride], &w, nu, nv);
    }

    /// The homogeneous control point `(w P, w)` of row `i`, column `j`.
    #[inline]
    fn homogeneous(&self, i: usize, j: usize) -> Homogeneous<D> {
        Homogeneous {
            point: *self.weighted.get(i, j),
            weight: *self.weights.get(i, j),
        }
    }

    /// `[S, S_u, S_v, S_uu, S_uv, S_vv]` at `(u, v)`, without allocating.
    pub fn second_order(&self, u: f64, v: f64) -> SecondOrder<D> {
        if self.degree_u < TINY_SPAN && self.degree_v < TINY_SPAN {
            self.second_order_in::<TINY_SPAN>(u, v)
        } else if self.degree_u < SMALL_SPAN && self.degree_v < SMALL_SPAN {
            self.second_order_in::<SMALL_SPAN>(u, v)
        } else {
            self.second_order_in::<MAX_SPAN>(u, v)
        }
    }

    /// The point at `(u, v)` with working arrays of `N` values (more than either degree).
    fn eval_in<const N: usize>(&self, u: f64, v: f64) -> Point<D> {
        let (u, v) = (self.parameter_u(u), self.parameter_v(v));
        let (p, q) = (self.degree_u, self.degree_v);
        let (rows, cols) = (self.control.rows(), self.control.cols());
        let su = span_of(p, &self.knots_u, rows, u);
        let sv = span_of(q, &self.knots_v, cols, v);
        let mut bu = [0.0; N];
        let mut bv = [0.0; N];
        basis_derivative(p, &self.knots_u, su, u, 0, &mut bu);
        basis_derivative(q, &self.knots_v, sv, v, 0, &mut bv);
        let mut a = Point::ZERO;
        let mut w = 0.0;
        for (r, &bur) in bu[..=p].iter().enumerate() {
            let i = su - p + r;
            let mut line = Point::ZERO;
            let mut line_w = 0.0;
            for (c, &b) in bv[..=q].iter().enumerate() {
                let j = sv - q + c;
                line += *self.weighted.get(i, j) * b;
                line_w += *self.weights.get(i, j) * b;
            }
            a += line * bur;
            w += line_w * bur;
        }
        a * (1.0 / w)
    }

    /// [`second_order`](NurbsSurface::second_order) with working arrays of `N` values (more
    /// than either degree).
    fn second_order_in<const N: usize>(&self, u: f64, v: f64) -> SecondOrder<D> {
        let (u, v) = (self.parameter_u(u), self.parameter_v(v));
        let (p, q) = (self.degree_u, self.degree_v);
        let (rows, cols) = (self.control.rows(), self.control.cols());
        let su = span_of(p, &self.knots_u, rows, u);
        let sv = span_of(q, &self.knots_v, cols, v);
        // The v-derivatives 0..=2 of every row of the span, then those along u.
        let mut rows_d = [[Homogeneous::<D>::ZERO; 3]; N];
        let mut local = [Homogeneous::<D>::ZERO; N];
        for (a, row) in rows_d[..=p].iter_mut().enumerate() {
            let i = su - p + a;
            for (c, h) in local[..=q].iter_mut().enumerate() {
                *h = self.homogeneous(i, sv - q + c);
            }
            local_derivatives(q, &self.knots_v, sv, v, &local, row);
        }
        let mut a = [[Point::<D>::ZERO; 3]; 3];
        let mut w = [[0.0; 3]; 3];
        let mut column = [Homogeneous::<D>::ZERO; 3];
        for l in 0..3 {
            for (x, row) in local[..=p].iter_mut().zip(&rows_d[..=p]) {
                *x = row[l];
            }
            local_derivatives(p, &self.knots_u, su, u, &local, &mut column[..3 - l]);
            for k in 0..3 - l {
                a[k][l] = column[k].point;
                w[k][l] = column[k].weight;
            }
        }
        let inv = 1.0 / w[0][0];
        let s = a[0][0] * inv;
        let su_ = (a[1][0] - s * w[1][0]) * inv;
        let sv_ = (a[0][1] - s * w[0][1]) * inv;
        let suu = (a[2][0] - su_ * (2.0 * w[1][0]) - s * w[2][0]) * inv;
        let svv = (a[0][2] - sv_ * (2.0 * w[0][1]) - s * w[0][2]) * inv;
        let suv = (a[1][1] - su_ * w[0][1] - sv_ * w[1][0] - s * w[1][1]) * inv;
        [s, su_, sv_, suu, suv, svv]
    }
}

impl<const D: usize> ToBSplineSurface<D> for NurbsSurface<D> {
    /// The polynomial B-spline surface when the weights are equal and the knots clamped
    /// ([`NurbsSurface::to_bspline`]); [`Error::NotExactlyConvertible`] otherwise.
    fn to_bspline(&self) -> Result<BSplineSurface<D>> {
        NurbsSurface::to_bspline(self).ok_or_else(|| Error::NotExactlyConvertible {
            what: "a rational B-spline surface",
            reason: "its weights differ or its knots are not clamped (no polynomial form)".into(),
        })
    }
}

impl<const D: usize> Surface<D> for NurbsSurface<D> {
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
        if self.degree_u < TINY_SPAN && self.degree_v < TINY_SPAN {
            self.eval_in::<TINY_SPAN>(u, v)
        } else if self.degree_u < SMALL_SPAN && self.degree_v < SMALL_SPAN {
            self.eval_in::<SMALL_SPAN>(u, v)
        } else {
            self.eval_in::<MAX_SPAN>(u, v)
        }
    }

    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        if ku + kv <= 2 {
            let s = self.second_order(u, v);
            return match (ku, kv) {
                (0, 0) => s[0],
                (1, 0) => s[1],
                (0, 1) => s[2],
                (2, 0) => s[3],
                (1, 1) => s[4],
                _ => s[5],
            };
        }
        let mut out = vec![Point::ZERO; (ku + 1) * (kv + 1)];
        self.derivatives_into(u, v, ku, kv, &mut out);
        out[ku * (kv + 1) + kv]
    }

    fn second_order(&self, u: f64, v: f64) -> [Point<D>; 6] {
        NurbsSurface::second_order(self, u, v)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Curve, Point3};

    /// A rational surface of degrees 3 x 2 over unclamped knots in u, clamped in v.
    fn surface() -> NurbsSurface<3> {
        let knots_u = vec![-0.3, -0.2, 0.0, 0.0, 0.45, 1.0, 1.2, 1.3, 1.7];
        let knots_v = vec![0.0, 0.0, 0.0, 0.6, 2.0, 2.0, 2.0];
        let control = Grid::from_fn(5, 4, |i, j| {
            let (x, y) = (i as f64, j as f64);
            Point3::new([x + 0.1 * y, y - 0.2 * x, (x * 0.7).sin() * (y * 0.4).cos()])
        });
        let weights = Grid::from_fn(5, 4, |i, j| 0.4 + ((i * 7 + j * 3) % 5) as f64 * 0.6);
        NurbsSurface::new((3, knots_u), (2, knots_v), control, weights).unwrap()
    }

    /// The point by tensor-product sums in homogeneous coordinates with Cox–de Boor values
    /// from the definition (the recursive N_{i,p}), independent of the span routines.
    fn by_definition(s: &NurbsSurface<3>, u: f64, v: f64) -> Point3 {
        fn n(knots: &[f64], i: usize, p: usize, t: f64) -> f64 {
            if p == 0 {
                return if knots[i] <= t && t < knots[i + 1] {
                    1.0
                } else {
                    0.0
                };
            }
            let mut out = 0.0;
            let a = knots[i + p] - knots[i];
            if a > 0.0 {
                out += (t - knots[i]) / a * n(knots, i, p - 1, t);
            }
            let b = knots[i + p + 1] - knots[i + 1];
            if b > 0.0 {
                out += (knots[i + p + 1] - t) / b * n(knots, i + 1, p - 1, t);
            }
            out
        }
        let (mut a, mut w) = (Point3::ZERO, 0.0);
        for i in 0..s.control_points().rows() {
            for j in 0..s.control_points().cols() {
                let b = n(s.knots_u(), i, s.degree_u(), u) * n(s.knots_v(), j, s.degree_v(), v);
                a += *s.control_points().get(i, j) * (b * s.weights().get(i, j));
                w += b * s.weights().get(i, j);
            }
        }
        a * (1.0 / w)
    }

    #[test]
    fn points_equal_the_definition() {
        let s = surface();
        assert_eq!((s.domain_u().start, s.domain_u().end), (0.0, 1.0));
        for a in 0..=20 {
            for b in 0..=20 {
                let (u, v) = (0.999 * a as f64 / 20.0, 1.999 * b as f64 / 20.0);
                let got = s.eval(u, v);
                let want = by_definition(&s, u, v);
                assert!(got.distance(want) < 1e-13, "({u}, {v}) {got:?} {want:?}");
            }
        }
    }

    #[test]
    fn partial_derivatives_match_differences_and_agree_between_routines() {
        let s = surface();
        let h = 1e-5;
        for (u, v) in [(0.1, 0.3), (0.7, 1.5), (0.93, 0.9)] {
            let mut table = vec![Point3::ZERO; 4 * 4];
            s.derivatives_into(u, v, 3, 3, &mut table);
            let at = |k: usize, l: usize| table[k * 4 + l];
            let second = s.second_order(u, v);
            let pairs = [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)];
            for (m, &(k, l)) in pairs.iter().enumerate() {
                let scale = 1.0 + at(k, l).norm();
                assert!(second[m].distance(at(k, l)) < 1e-12 * scale, "{k} {l}");
            }
            for k in 0..3 {
                for l in 0..3 {
                    let mut ahead = vec![Point3::ZERO; 16];
                    let mut behind = vec![Point3::ZERO; 16];
                    s.derivatives_into(u + h, v, 3, 3, &mut ahead);
                    s.derivatives_into(u - h, v, 3, 3, &mut behind);
                    let fd = (ahead[k * 4 + l] - behind[k * 4 + l]) * (0.5 / h);
                    let want = at(k + 1, l);
                    assert!(fd.distance(want) < 1e-4 * (1.0 + want.norm()), "u: {k} {l}");
                    s.derivatives_into(u, v + h, 3, 3, &mut ahead);
                    s.derivatives_into(u, v - h, 3, 3, &mut behind);
                    let fd = (ahead[k * 4 + l] - behind[k * 4 + l]) * (0.5 / h);
                    let want = at(k, l + 1);
                    assert!(fd.distance(want) < 1e-4 * (1.0 + want.norm()), "v: {k} {l}");
                }
            }
            assert_eq!(s.deriv(u, v, 2, 1), at(2, 1));
        }
    }

    #[test]
    fn iso_curves_are_exact() {
        let s = surface();
        let c = s.iso_curve(true, 0.77);
        let d = s.iso_curve(false, 0.31);
        for k in 0..=10 {
            let t = k as f64 / 10.0;
            assert!(c.eval(t).distance(s.eval(t, 0.77)) < 1e-13);
            assert!(d.eval(2.0 * t).distance(s.eval(0.31, 2.0 * t)) < 1e-13);
        }
    }

    #[test]
    fn equal_weights_give_the_polynomial_surface() {
        let grid = Grid::from_fn(4, 3, |i, j| {
            Point3::new([i as f64, j as f64, (i * j) as f64 * 0.2])
        });
        let b = BSplineSurface::new(
            (3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]),
            (2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
            grid,
        )
        .unwrap();
        let n = NurbsSurface::from_bspline(&b);
        for (u, v) in [(0.2, 0.9), (0.6, 0.1)] {
            for (ku, kv) in [(0, 0), (1, 0), (0, 1), (1, 1), (2, 1), (3, 2)] {
                let (x, y) = (n.deriv(u, v, ku, kv), b.deriv(u, v, ku, kv));
                assert!(x.distance(y) < 1e-12 * (1.0 + y.norm()), "{ku} {kv}");
            }
        }
        assert_eq!(n.to_bspline().unwrap(), b);
    }
}

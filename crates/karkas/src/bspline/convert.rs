//! Exact conversion of the LL, Hermite, cubic-spline and bicubic types.

use super::bezier::{bspline_controls, hermite_bezier, knot_vector, split_scalar};
use super::{BSplineCurve, BSplineSurface, ToBSplineCurve, ToBSplineSurface};
use crate::core::{Curve, Grid, Surface};
use crate::fit::HermiteSpline;
use crate::ll::{LlCurve, LlKernel, LlSurface, NodeAxis};
use crate::param::{BicubicSurface, CubicSpline};
use crate::{Point, Result};

/// The Bernstein coefficients (degree `2L`) of the LL kernel `h`.
///
/// `h = xi^(L+1) sum_{k<L} e_k (1-xi)^k` with `e_k = eps_k (L-k)`; multiplying each term by
/// `(xi + (1-xi))^(L-1-k)` makes it homogeneous of degree `2L`, and the coefficient of
/// `xi^a (1-xi)^(2L-a)` divided by `C(2L, a)` is the Bernstein coefficient. Every term is
/// positive: no cancellation.
pub(crate) fn kernel_bernstein(kernel: &LlKernel) -> Vec<f64> {
    let l = kernel.order();
    let p = 2 * l;
    let e = kernel.value_coeffs();
    let mut beta = vec![0.0; p + 1];
    for m in 0..l {
        let a = l + 1 + m;
        let sum: f64 = (0..l - m).map(|k| e[k] * binomial(l - 1 - k, m)).sum();
        beta[a] = sum / binomial(p, a);
    }
    beta
}

fn binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    (0..k).fold(1.0, |acc, m| acc * (n - m) as f64 / (m + 1) as f64)
}

/// The Bezier coefficients (degree `2L`) of the three LL weights `c_-`, `c_0`, `c_+` on each
/// piece of an LL direction: piece `q` is segment `q + 1` (1-based), the first piece its
/// upper half, the last its lower half.
struct LlPieceWeights {
    /// `[c_-, c_0, c_+]` Bezier coefficients on a full segment, a first and a last piece.
    full: [Vec<f64>; 3],
    first: [Vec<f64>; 3],
    last: [Vec<f64>; 3],
    pieces: usize,
}

impl LlPieceWeights {
    fn new(kernel: &LlKernel, axis: NodeAxis) -> Self {
        let beta = kernel_bernstein(kernel);
        let p = beta.len() - 1;
        let minus: Vec<f64> = (0..=p)
            .map(|a| (1.0 - 2.0 * a as f64 / p as f64 + beta[a]) * 0.5)
            .collect();
        let middle: Vec<f64> = (0..=p)
            .map(|a| (1.0 + 2.0 * a as f64 / p as f64 - 2.0 * beta[a]) * 0.5)
            .collect();
        let plus: Vec<f64> = beta.iter().map(|b| b * 0.5).collect();
        let full = [minus, middle, plus];
        let first = full.clone().map(|c| split_scalar(&c, 0.5, false));
        let last = full.clone().map(|c| split_scalar(&c, 0.5, true));
        LlPieceWeights {
            full,
            first,
            last,
            pieces: axis.nodes(),
        }
    }

    /// The weights of piece `q`.
    fn of(&self, q: usize) -> &[Vec<f64>; 3] {
        if q == 0 {
            &self.first
        } else if q + 1 == self.pieces {
            &self.last
        } else {
            &self.full
        }
    }
}

/// Degree `2L`, the breakpoints of the LL axis, multiplicity `L` at the inner ones.
fn ll_knots(kernel: &LlKernel, axis: NodeAxis) -> (usize, Vec<f64>, Vec<f64>) {
    let l = kernel.order();
    let breaks = axis.breakpoints();
    let multiplicity = vec![l; breaks.len() - 2];
    let knots = knot_vector(2 * l, &breaks, &multiplicity);
    (2 * l, breaks, knots)
}

/// LL curves: degree `2L`, knots at the segment borders with multiplicity `L` (the curve is
/// `C^L` there, METHODS.md §6), over the working domain `[1/(K+1), K/(K+1)]`. A closed curve
/// is exported over its one period as a clamped curve whose ends coincide.
impl<const D: usize> ToBSplineCurve<D> for LlCurve<D> {
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        let axis = self.axis();
        let weights = LlPieceWeights::new(self.kernel(), axis);
        let (degree, breaks, knots) = ll_knots(self.kernel(), axis);
        let r = self.extended_points();
        let control = bspline_controls(degree, &breaks, &knots, |q, a| {
            let w = weights.of(q);
            r[q] * w[0][a] + r[q + 1] * w[1][a] + r[q + 2] * w[2][a]
        });
        Ok(BSplineCurve::new(degree, knots, control)?.with_closed(self.is_closed()))
    }
}

/// LL surfaces: the tensor product of the curve conversion (degree `2L` and multiplicity `L`
/// in each direction).
impl<const D: usize> ToBSplineSurface<D> for LlSurface<D> {
    fn to_bspline(&self) -> Result<BSplineSurface<D>> {
        let (axis_u, axis_v) = (self.axis_u(), self.axis_v());
        let wu = LlPieceWeights::new(self.kernel(), axis_u);
        let wv = LlPieceWeights::new(self.kernel(), axis_v);
        let (p, breaks_u, knots_u) = ll_knots(self.kernel(), axis_u);
        let (q, breaks_v, knots_v) = ll_knots(self.kernel(), axis_v);
        let r = self.extended();
        let patch = |k: usize, l: usize, a: usize, b: usize| {
            let (gu, gv) = (wu.of(k), wv.of(l));
            let mut sum = Point::ZERO;
            for (da, gua) in gu.iter().enumerate() {
                for (db, gvb) in gv.iter().enumerate() {
                    sum = sum.add_scaled(gua[a] * gvb[b], *r.get(k + da, l + db));
                }
            }
            sum
        };
        let control = tensor_controls((p, &breaks_u, &knots_u), (q, &breaks_v, &knots_v), patch);
        Ok(BSplineSurface::new((p, knots_u), (q, knots_v), control)?
            .with_closed(self.is_closed_u(), self.is_closed_v()))
    }
}

/// The control grid of the tensor-product B-spline equal to the Bezier patches
/// `patch(k, l, a, b)` (patch `(k, l)` on `[bu_k, bu_{k+1}] x [bv_l, bv_{l+1}]`, Bezier point
/// `(a, b)`): converted along `u` for every Bezier row of every `v` piece, then along `v`.
pub(crate) fn tensor_controls<const D: usize>(
    (p, breaks_u, knots_u): (usize, &[f64], &[f64]),
    (q, breaks_v, knots_v): (usize, &[f64], &[f64]),
    patch: impl Fn(usize, usize, usize, usize) -> Point<D>,
) -> Grid<Point<D>> {
    let pieces_v = breaks_v.len() - 1;
    // rows[l * (q + 1) + b][i]: u-control i of the Bezier row b of v-piece l.
    let rows: Vec<Vec<Point<D>>> = (0..pieces_v)
        .flat_map(|l| (0..=q).map(move |b| (l, b)))
        .map(|(l, b)| bspline_controls(p, breaks_u, knots_u, |k, a| patch(k, l, a, b)))
        .collect();
    let nu = knots_u.len() - p - 1;
    let columns: Vec<Vec<Point<D>>> = (0..nu)
        .map(|i| bspline_controls(q, breaks_v, knots_v, |l, b| rows[l * (q + 1) + b][i]))
        .collect();
    let nv = knots_v.len() - q - 1;
    Grid::from_fn(nu, nv, |i, j| columns[i][j])
}

/// Cubic Hermite data on `knots` as a B-spline with inner multiplicity `multiplicity`
/// (2 for `C^1`, 1 for `C^2` data).
fn hermite_curve<const D: usize>(
    knots: &[f64],
    values: &[Point<D>],
    derivatives: &[Point<D>],
    multiplicity: usize,
) -> Result<BSplineCurve<D>> {
    let mult = vec![multiplicity; knots.len() - 2];
    let knot_vec = knot_vector(3, knots, &mult);
    let control = bspline_controls(3, knots, &knot_vec, |k, a| {
        hermite_bezier(
            values[k],
            derivatives[k],
            values[k + 1],
            derivatives[k + 1],
            knots[k + 1] - knots[k],
        )[a]
    });
    BSplineCurve::new(3, knot_vec, control)
}

/// Cubic splines of defect 2: degree 3, every inner knot doubled (`C^1`).
impl<const D: usize> ToBSplineCurve<D> for HermiteSpline<D> {
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        hermite_curve(self.knots(), self.values(), self.derivatives(), 2)
    }
}

/// `C^2` cubic splines (any end conditions): degree 3, simple inner knots. A periodic spline
/// is exported over its one period as a clamped curve whose ends coincide.
impl<const D: usize> ToBSplineCurve<D> for CubicSpline<D> {
    fn to_bspline(&self) -> Result<BSplineCurve<D>> {
        Ok(
            hermite_curve(self.knots(), self.values(), self.slopes(), 1)?
                .with_closed(self.is_closed()),
        )
    }
}

/// Bicubic interpolating splines: degree 3 by 3, simple inner knots (`C^2` in each
/// direction), from the Hermite data of the nodes (the Bezier net of each patch is
/// `b_ab = r + A h_u/3 r_u + B h_v/3 r_v + A B h_u h_v/9 r_uv` at the patch corner nearest
/// to Bezier point `(a, b)`, `A, B` in `{0, 1, -1, 0}` by distance and side).
impl<const D: usize> ToBSplineSurface<D> for BicubicSurface<D> {
    fn to_bspline(&self) -> Result<BSplineSurface<D>> {
        let (ku, kv) = (self.knots_u(), self.knots_v());
        let mult_u = vec![1; ku.len() - 2];
        let mult_v = vec![1; kv.len() - 2];
        let knots_u = knot_vector(3, ku, &mult_u);
        let knots_v = knot_vector(3, kv, &mult_v);
        let side = |a: usize| -> (usize, f64) {
            match a {
                0 => (0, 0.0),
                1 => (0, 1.0),
                2 => (1, -1.0),
                _ => (1, 0.0),
            }
        };
        let patch = |k: usize, l: usize, a: usize, b: usize| {
            let (di, sa) = side(a);
            let (dj, sb) = side(b);
            let (i, j) = (k + di, l + dj);
            let (hu, hv) = (ku[k + 1] - ku[k], kv[l + 1] - kv[l]);
            let r = self.node(i, j);
            let (ru, rv, ruv) = self.node_derivatives(i, j);
            r.add_scaled(sa * hu / 3.0, ru)
                .add_scaled(sb * hv / 3.0, rv)
                .add_scaled(sa * sb * hu * hv / 9.0, ruv)
        };
        let control = tensor_controls((3, ku, &knots_u), (3, kv, &knots_v), patch);
        Ok(BSplineSurface::new((3, knots_u), (3, knots_v), control)?
            .with_closed(self.is_closed_u(), self.is_closed_v()))
    }
}

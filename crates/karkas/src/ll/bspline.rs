//! Exact B-spline form of LL curves and surfaces (Aulchenko, Latypov, Nikulichev): degree
//! `2L`, knots at the segment borders with multiplicity `L`, the Bezier pieces from the
//! Bernstein coefficients of the kernel `h` (all positive), joined by blossoming
//! ([`crate::bspline`]).

use super::{LlCurve, LlKernel, LlSurface, NodeAxis};
use crate::bspline::{
    bspline_controls, knot_vector, split_scalar, tensor_controls, BSplineCurve, BSplineSurface,
    ToBSplineCurve, ToBSplineSurface,
};
use crate::core::{Curve, Surface};
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
/// `C^L` there, docs/methods.md §6), over the working domain `[1/(K+1), K/(K+1)]`. A closed curve
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

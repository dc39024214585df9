//! The exact B-spline form of a curve or surface on flat buffers, as SciPy takes it
//! (`scipy.interpolate.BSpline(t, c, k)`, `NdBSpline((tu, tv), c, (ku, kv))`), and its
//! evaluation beyond the domain.
//!
//! The library converts every piecewise polynomial curve and surface to a clamped B-spline
//! (`karkas::bspline`, METHODS.md "exact B-spline form"); here the result is kept with the
//! dimension erased, differentiated (the derivative of a B-spline of degree `p` is the
//! B-spline of degree `p - 1` on the knots without the first and the last, with coefficients
//! `p (c[i+1] - c[i]) / (t[i+p+1] - t[i+1])`, de Boor, "A Practical Guide to Splines", ch. X)
//! and evaluated by de Boor's algorithm on the first or last nonempty knot span for
//! parameters below or above the domain: the end polynomial pieces continued, which is
//! SciPy's `extrapolate=True` rule and gives SciPy's values to rounding.

use karkas::bspline::{BSplineCurve, BSplineSurface};
use karkas::Point;

/// A B-spline curve of any dimension: knots `t`, coefficients `c` (`n x d`, row-major),
/// degree `k`, with `t.len() == n + k + 1`.
#[derive(Clone, Debug)]
pub struct FlatBSpline {
    /// The knot vector.
    pub knots: Vec<f64>,
    /// The coefficients, `n` rows of `dim` values.
    pub coefs: Vec<f64>,
    /// The degree.
    pub degree: usize,
    /// The dimension of the values.
    pub dim: usize,
}

impl FlatBSpline {
    /// The flat form of a library B-spline curve.
    pub fn of<const D: usize>(b: &BSplineCurve<D>) -> Self {
        FlatBSpline {
            knots: b.knots().to_vec(),
            coefs: b.control_points().iter().flat_map(|p| p.0).collect(),
            degree: b.degree(),
            dim: D,
        }
    }

    /// The number of coefficients.
    pub fn count(&self) -> usize {
        self.coefs.len() / self.dim
    }

    /// The `nu`-th derivative as a B-spline (degree `max(k - nu, 0)`; zero beyond the degree).
    pub fn derivative(&self, nu: usize) -> Self {
        let mut b = self.clone();
        // Past degree + 1 steps every coefficient is zero already.
        for _ in 0..nu.min(self.degree + 1) {
            b = b.differentiated();
        }
        b
    }

    /// The first derivative.
    fn differentiated(&self) -> Self {
        let (p, d, n) = (self.degree, self.dim, self.count());
        if p == 0 {
            return FlatBSpline {
                coefs: vec![0.0; self.coefs.len()],
                ..self.clone()
            };
        }
        let t = &self.knots;
        let mut coefs = Vec::with_capacity((n - 1) * d);
        for i in 0..n - 1 {
            let span = t[i + p + 1] - t[i + 1];
            let scale = if span > 0.0 { p as f64 / span } else { 0.0 };
            for j in 0..d {
                coefs.push(scale * (self.coefs[(i + 1) * d + j] - self.coefs[i * d + j]));
            }
        }
        FlatBSpline {
            knots: t[1..t.len() - 1].to_vec(),
            coefs,
            degree: p - 1,
            dim: d,
        }
    }

    /// The value at `t` into `out` (`dim` values), the end pieces continued outside the domain.
    pub fn eval_into(&self, t: f64, out: &mut [f64]) {
        let span = span_of(&self.knots, self.degree, self.count(), t);
        de_boor(
            &self.knots,
            self.degree,
            self.dim,
            |i| &self.coefs[i * self.dim..(i + 1) * self.dim],
            span,
            t,
            out,
        );
    }
}

/// The knot span `s` (`degree <= s < count`, `knots[s] < knots[s + 1]`) whose polynomial
/// gives the value at `t`: the span holding `t`, the first nonempty one below the domain, the
/// last one at and above its end (SciPy's rule).
fn span_of(knots: &[f64], degree: usize, count: usize, t: f64) -> usize {
    let mut first = degree;
    while first + 1 < count && knots[first] == knots[first + 1] {
        first += 1;
    }
    let mut last = count - 1;
    while last > degree && knots[last] == knots[last + 1] {
        last -= 1;
    }
    if t.is_nan() || t < knots[first + 1] {
        return first;
    }
    if t >= knots[last] {
        return last;
    }
    // knots[s] <= t < knots[s + 1] inside; skip empty spans (partition_point finds the last
    // knot <= t, which starts a nonempty span).
    let s = knots[..=count].partition_point(|&k| k <= t) - 1;
    s.clamp(first, last)
}

/// De Boor's algorithm on span `span` at `t` (any real `t`: the span's polynomial), into `out`.
fn de_boor<'a>(
    knots: &[f64],
    degree: usize,
    dim: usize,
    coef: impl Fn(usize) -> &'a [f64],
    span: usize,
    t: f64,
    out: &mut [f64],
) {
    let mut work: Vec<f64> = (0..=degree)
        .flat_map(|j| coef(span - degree + j).iter().copied())
        .collect();
    for r in 1..=degree {
        for j in (r..=degree).rev() {
            let i = span - degree + j;
            let denominator = knots[i + degree + 1 - r] - knots[i];
            let alpha = if denominator > 0.0 {
                (t - knots[i]) / denominator
            } else {
                0.0
            };
            for c in 0..dim {
                work[j * dim + c] =
                    work[(j - 1) * dim + c] * (1.0 - alpha) + work[j * dim + c] * alpha;
            }
        }
    }
    out.copy_from_slice(&work[degree * dim..(degree + 1) * dim]);
}

/// A tensor-product B-spline surface of any dimension: knots `(tu, tv)`, coefficients
/// `nu x nv x d` (row-major, `u` outer: NdBSpline's layout), degrees `(ku, kv)`.
#[derive(Clone, Debug)]
pub struct FlatBSplineSurface {
    /// The knot vectors in u and v.
    pub knots: (Vec<f64>, Vec<f64>),
    /// The coefficients, `nu x nv` points of `dim` values, `u` outer.
    pub coefs: Vec<f64>,
    /// The counts `(nu, nv)` of coefficients.
    pub counts: (usize, usize),
    /// The degrees in u and v.
    pub degrees: (usize, usize),
    /// The dimension of the values.
    pub dim: usize,
}

impl FlatBSplineSurface {
    /// The flat form of a library B-spline surface.
    pub fn of<const D: usize>(b: &BSplineSurface<D>) -> Self {
        let grid = b.control_points();
        FlatBSplineSurface {
            knots: (b.knots_u().to_vec(), b.knots_v().to_vec()),
            coefs: grid
                .as_slice()
                .iter()
                .flat_map(|p: &Point<D>| p.0)
                .collect(),
            counts: (grid.rows(), grid.cols()),
            degrees: (b.degree_u(), b.degree_v()),
            dim: D,
        }
    }

    /// The partial derivative `d^(du+dv) / du^du dv^dv` as a B-spline surface.
    pub fn derivative(&self, du: usize, dv: usize) -> Self {
        let (nu, nv) = self.counts;
        let d = self.dim;
        // In v: every row u = i is a curve with nv coefficients.
        let mut rows: Vec<FlatBSpline> = (0..nu)
            .map(|i| FlatBSpline {
                knots: self.knots.1.clone(),
                coefs: self.coefs[i * nv * d..(i + 1) * nv * d].to_vec(),
                degree: self.degrees.1,
                dim: d,
            })
            .map(|row| row.derivative(dv))
            .collect();
        let nv2 = rows[0].count();
        let (tv, kv) = (rows[0].knots.clone(), rows[0].degree);
        // In u: the columns, as a curve of dimension nv2 * d.
        let column = FlatBSpline {
            knots: self.knots.0.clone(),
            coefs: rows.iter_mut().flat_map(|r| r.coefs.drain(..)).collect(),
            degree: self.degrees.0,
            dim: nv2 * d,
        }
        .derivative(du);
        FlatBSplineSurface {
            counts: (column.count(), nv2),
            knots: (column.knots, tv),
            degrees: (column.degree, kv),
            coefs: column.coefs,
            dim: d,
        }
    }

    /// The value at `(u, v)` into `out` (`dim` values), the end pieces continued outside.
    pub fn eval_into(&self, u: f64, v: f64, out: &mut [f64]) {
        let (nu, nv) = self.counts;
        let (ku, kv) = self.degrees;
        let d = self.dim;
        let (tu, tv) = (&self.knots.0, &self.knots.1);
        let su = span_of(tu, ku, nu, u);
        let sv = span_of(tv, kv, nv, v);
        // Along v on the ku + 1 rows of the span, then along u.
        let mut column = vec![0.0; nu * d];
        for i in su - ku..=su {
            let row = &self.coefs[i * nv * d..(i + 1) * nv * d];
            de_boor(
                tv,
                kv,
                d,
                |j| &row[j * d..(j + 1) * d],
                sv,
                v,
                &mut column[i * d..(i + 1) * d],
            );
        }
        de_boor(tu, ku, d, |i| &column[i * d..(i + 1) * d], su, u, out);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A cubic with one inner knot, the coefficients of t^3 on [0, 2]: continued exactly.
    #[test]
    fn end_pieces_continue_and_differentiate() {
        // t^3 on knots [0,0,0,0,1,2,2,2,2]: coefficients by blossoming t1 t2 t3.
        let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0, 2.0];
        let blossom = |i: usize| knots[i + 1] * knots[i + 2] * knots[i + 3];
        let b = FlatBSpline {
            coefs: (0..5).map(blossom).collect(),
            knots: knots.clone(),
            degree: 3,
            dim: 1,
        };
        let mut out = [0.0];
        for t in [-1.5, 0.0, 0.3, 1.0, 1.7, 2.0, 3.25] {
            b.eval_into(t, &mut out);
            assert!((out[0] - t * t * t).abs() < 1e-12 * (1.0 + t * t * t).abs());
            b.derivative(1).eval_into(t, &mut out);
            assert!((out[0] - 3.0 * t * t).abs() < 1e-12 * (1.0 + t * t).abs());
            b.derivative(3).eval_into(t, &mut out);
            assert!((out[0] - 6.0).abs() < 1e-12);
            b.derivative(4).eval_into(t, &mut out);
            assert_eq!(out[0], 0.0);
        }
    }
}

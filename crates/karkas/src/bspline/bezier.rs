//! From Bezier pieces to one B-spline: knot vectors from the pieces' continuity, control
//! points by blossoming (de Boor–Fix / polar forms).
//!
//! A piecewise polynomial of degree `p` on breakpoints `b_0 < .. < b_n`, `C^{c_k}` at the
//! inner breakpoint `b_k`, is a B-spline over the clamped knot vector with `b_k` repeated
//! `p - c_k` times. Its control point `P_j` is the blossom (polar form) of the polynomial on
//! any nonempty knot span inside the support of `N_j`, evaluated at the knots
//! `t_{j+1}, .., t_{j+p}`. With the polynomial in Bezier form on `[b_k, b_{k+1}]`, arguments
//! equal to `b_k` or `b_{k+1}` only select Bezier points (exactly); every other argument is one
//! de Casteljau step outside `[0, 1]`. The span is chosen to need the fewest such steps (none
//! for Hermite and bicubic pieces; at most `L/2` for LL pieces), so the conversion adds only
//! a few rounding errors to the Bezier points.

use super::BSplineCurve;
use crate::core::Grid;
use crate::{Point, Result};

/// The clamped knot vector of degree `degree` over `breaks` with the inner multiplicities
/// `multiplicity` (one per inner breakpoint, each in `1..=degree`).
pub(crate) fn knot_vector(degree: usize, breaks: &[f64], multiplicity: &[usize]) -> Vec<f64> {
    let n = breaks.len() - 1;
    let mut knots = vec![breaks[0]; degree + 1];
    for k in 1..n {
        knots.extend(std::iter::repeat_n(breaks[k], multiplicity[k - 1]));
    }
    knots.extend(std::iter::repeat_n(breaks[n], degree + 1));
    knots
}

/// The control points of the B-spline equal to the Bezier pieces `bezier(k, a)` (piece `k`
/// on `[breaks[k], breaks[k+1]]`, Bezier point `a` in `0..=degree`) over `knots`
/// (from [`knot_vector`]). The pieces must join with the continuity the knots encode.
pub(crate) fn bspline_controls<const D: usize>(
    degree: usize,
    breaks: &[f64],
    knots: &[f64],
    bezier: impl Fn(usize, usize) -> Point<D>,
) -> Vec<Point<D>> {
    let count = knots.len() - degree - 1;
    // The piece of each nonempty knot span.
    let piece_of_span = |s: usize| -> Option<usize> {
        if knots[s] < knots[s + 1] {
            Some(breaks.partition_point(|&b| b <= knots[s]) - 1)
        } else {
            None
        }
    };
    let mut work = vec![Point::ZERO; degree + 1];
    let mut args = Vec::with_capacity(degree);
    (0..count)
        .map(|j| {
            let window = &knots[j + 1..j + degree + 1];
            // The span in j..=j+degree needing the fewest extrapolated arguments, then the
            // smallest extrapolation.
            let mut best: Option<(usize, usize, f64)> = None;
            for s in j..=j + degree {
                let Some(k) = piece_of_span(s) else { continue };
                let (a, b) = (breaks[k], breaks[k + 1]);
                let outside = window.iter().filter(|&&t| t != a && t != b).count();
                let reach = window
                    .iter()
                    .map(|&t| ((t - a) / (b - a) - 0.5).abs())
                    .fold(0.0, f64::max);
                if best.is_none_or(|(_, o, r)| (outside, reach) < (o, r)) {
                    best = Some((k, outside, reach));
                }
            }
            let k = best.map_or(0, |b| b.0);
            let (a, b) = (breaks[k], breaks[k + 1]);
            args.clear();
            args.extend(window.iter().map(|&t| {
                if t == a {
                    0.0
                } else if t == b {
                    1.0
                } else {
                    (t - a) / (b - a)
                }
            }));
            for (i, w) in work.iter_mut().enumerate() {
                *w = bezier(k, i);
            }
            blossom(&mut work, &args)
        })
        .collect()
}

/// The blossom of the Bezier polygon `points` (degree `points.len() - 1`) at `args` (one per
/// degree): de Casteljau with a different parameter at each level. Overwrites `points`.
pub(crate) fn blossom<const D: usize>(points: &mut [Point<D>], args: &[f64]) -> Point<D> {
    let mut len = points.len();
    for &s in args {
        for i in 0..len - 1 {
            points[i] = if s == 0.0 {
                points[i]
            } else if s == 1.0 {
                points[i + 1]
            } else {
                points[i] * (1.0 - s) + points[i + 1] * s
            };
        }
        len -= 1;
    }
    points[0]
}

/// Splits the scalar Bezier coefficients `c` (on `[0, 1]`) at `s` and returns the part on
/// `[0, s]` (`left`) or `[s, 1]`.
pub(crate) fn split_scalar(c: &[f64], s: f64, left: bool) -> Vec<f64> {
    let p = c.len() - 1;
    let mut work = c.to_vec();
    let mut out = vec![0.0; p + 1];
    for r in 0..=p {
        if left {
            out[r] = work[0];
        } else {
            out[p - r] = work[p - r];
        }
        for i in 0..p - r {
            work[i] = work[i] * (1.0 - s) + work[i + 1] * s;
        }
    }
    out
}

/// The cubic Hermite piece on an interval of length `h` with end values `r0`, `r1` and end
/// derivatives `d0`, `d1` (per unit parameter), as its four Bezier points.
pub(crate) fn hermite_bezier<const D: usize>(
    r0: Point<D>,
    d0: Point<D>,
    r1: Point<D>,
    d1: Point<D>,
    h: f64,
) -> [Point<D>; 4] {
    [
        r0,
        r0.add_scaled(h / 3.0, d0),
        r1.add_scaled(-h / 3.0, d1),
        r1,
    ]
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
pub(crate) fn hermite_curve<const D: usize>(
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

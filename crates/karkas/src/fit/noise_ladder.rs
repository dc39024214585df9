//! The residual ladder the noise estimate reads (docs/methods.md §4, "The noise").
//!
//! A *window* of order `k` is `2k + 1` points `r_{i - k m}, ..., r_{i + k m}` (stride `m`)
//! around the point `r_i`. In the frame of the window's chord (origin at its first point, `d`
//! the unit chord) every point has an along coordinate `s_j` and an across part `c_j` (the
//! rest, `D - 1` coordinates); the `s_j` must increase (the window is a graph over its
//! chord), and the across part of the middle point is compared with the polynomial of degree
//! `2k - 1` through the other `2k` points, evaluated at its `s`:
//! `e = c_i - sum_j l_j(s_i) c_j` (`l_j` the Lagrange basis). Order 1 is the distance of `r_i`
//! from the chord of its neighbours.
//!
//! Under independent noise of `sigma` per coordinate, `e` has (to first order in the noise)
//! the covariance `sigma^2 C` with
//! `C = (1 + g_i g_i^T) + sum_j l_j^2 (1 + g_j g_j^T)` on the across space, `g_j` the
//! interpolant's slope at `s_j` (a point moved along the chord by `delta` moves its across
//! value by `-g delta`). `|e|_C = sqrt(e^T C^{-1} e)` is therefore `sigma` times a `chi`
//! variable with `D - 1` degrees of freedom, whatever the spacing, the order or the window's
//! bend; on exact points it is the interpolation error, which falls with the order wherever
//! the points resolve the curve (the window turns little) and stays or grows where they do
//! not (a sparse nose, a corner).
//!
//! Each *rung* of the ladder (one order over many windows) gives the median of `|e|_C` over
//! the median of `chi_{D-1}` (an estimate of `sigma` if the residuals were noise), the share
//! of consecutive windows whose across residuals point opposite ways (after turning the first
//! by the rotation that takes its chord to the second's: noise flips it at random, at least
//! half the time; a curve's own bending keeps its side over runs of windows), and the ratio of
//! the lower quartile to the median against that of `chi_{D-1}` (1 for noise; far below 1
//! where the residuals span decades, as an exact curve's do between its well and poorly
//! resolved stretches; far above where they are all alike, as on a uniformly sampled arc).
//!
//! Hand-written: no crate offers residuals of local polynomial interpolation with their noise
//! propagated; the windows hold at most `2 MAX_ORDER + 1 = 9` points.

use crate::Point;

/// The highest order: windows of up to 9 points, interpolants of degree up to 7.
pub(super) const MAX_ORDER: usize = 4;
/// Points of the largest window.
const MAX_WINDOW: usize = 2 * MAX_ORDER + 1;

/// One window's residual.
#[derive(Clone, Copy, Debug)]
struct WindowResidual<const D: usize> {
    /// `|e|_C`: the residual measured against its own noise propagation.
    size: f64,
    /// `e`, the across residual in the coordinates of the points.
    across: Point<D>,
    /// The unit chord of the window.
    chord: Point<D>,
    /// Whether the middle point projects outside the chord (possible at order 1 only).
    outside: bool,
}

/// The residual of the window of order `k` and stride `stride` whose first point is
/// `first`, in coordinates divided by `unit`, or `None` where the window is not a graph
/// over its chord (from order 2 on: its along coordinates do not increase) or a propagation
/// is not finite.
fn window_residual<const D: usize>(
    points: &[Point<D>],
    unit: f64,
    first: usize,
    stride: usize,
    k: usize,
) -> Option<WindowResidual<D>> {
    let width = 2 * k + 1;
    let origin = points[first];
    // Coordinates relative to the window's first point, in units of `unit`.
    let at = |j: usize| (points[first + j * stride] - origin) * (1.0 / unit);
    let chord = at(width - 1);
    let length = chord.norm();
    if !(length > 0.0 && length.is_finite()) {
        return None;
    }
    let d = chord * (1.0 / length);
    let mut s = [0.0; MAX_WINDOW];
    let mut c = [Point::<D>::ZERO; MAX_WINDOW];
    for j in 0..width {
        let r = at(j);
        s[j] = r.dot(d);
        c[j] = r.add_scaled(-s[j], d);
        // Order 1 compares the middle point with the line through the other two, wherever it
        // projects; from order 2 on the window must be a graph over its chord.
        if k > 1 && j > 0 {
            let increasing = s[j] > s[j - 1];
            if !increasing {
                return None;
            }
        }
    }
    // The other points: every j but the middle k.
    let mut other_slots = [0usize; MAX_WINDOW];
    for (slot, j) in other_slots.iter_mut().zip((0..width).filter(|&j| j != k)) {
        *slot = j;
    }
    let others = &other_slots[..width - 1];
    let x = s[k];
    // Barycentric weights of the nodes, Lagrange weights at x and their derivatives.
    let mut bary = [0.0; MAX_WINDOW];
    for &j in others {
        let product: f64 = others
            .iter()
            .filter(|&&m| m != j)
            .map(|&m| s[j] - s[m])
            .product();
        bary[j] = 1.0 / product;
    }
    let mut prediction = Point::<D>::ZERO;
    let mut slope_at_x = Point::<D>::ZERO;
    let mut basis = [0.0; MAX_WINDOW];
    for &j in others {
        let (mut l, mut inverse_sum) = (1.0, 0.0);
        for &m in others.iter().filter(|&&m| m != j) {
            l *= (x - s[m]) / (s[j] - s[m]);
            inverse_sum += 1.0 / (x - s[m]);
        }
        basis[j] = l;
        prediction = prediction.add_scaled(l, c[j]);
        slope_at_x = slope_at_x.add_scaled(l * inverse_sum, c[j]);
    }
    let e = c[k] - prediction;
    // C on the across space, with d d^T added so that it is invertible on the whole space.
    let mut cov = [[0.0; D]; D];
    let mut add = |weight: f64, g: Point<D>, with_identity: bool| {
        for (a, row) in cov.iter_mut().enumerate() {
            for (b, entry) in row.iter_mut().enumerate() {
                let identity = if with_identity {
                    f64::from(u8::from(a == b)) - d[a] * d[b]
                } else {
                    0.0
                };
                *entry += weight * (identity + g[a] * g[b]);
            }
        }
    };
    add(1.0, slope_at_x, true);
    for &i in others {
        // The interpolant's slope at node i (barycentric differentiation).
        let mut slope = Point::<D>::ZERO;
        for &j in others.iter().filter(|&&j| j != i) {
            let entry = bary[j] / bary[i] / (s[i] - s[j]);
            slope = slope.add_scaled(entry, c[j] - c[i]);
        }
        add(basis[i] * basis[i], slope, true);
    }
    add(1.0, d, false);
    let size_sq = quadratic_form_of_inverse(cov, e)?;
    Some(WindowResidual {
        size: size_sq.max(0.0).sqrt(),
        across: e,
        chord: d,
        outside: !(x > 0.0 && x < length),
    })
}

/// `e^T C^{-1} e` by the Cholesky factors of the symmetric positive definite `C`, or `None`
/// where it is not (numerically) positive definite or not finite.
fn quadratic_form_of_inverse<const D: usize>(mut c: [[f64; D]; D], e: Point<D>) -> Option<f64> {
    for j in 0..D {
        let diagonal = c[j][..j].iter().fold(c[j][j], |d, x| d - x * x);
        if !(diagonal > 0.0 && diagonal.is_finite()) {
            return None;
        }
        let pivot = diagonal.sqrt();
        c[j][j] = pivot;
        for i in j + 1..D {
            let entry = c[i][..j]
                .iter()
                .zip(&c[j][..j])
                .fold(c[i][j], |e, (a, b)| e - a * b);
            c[i][j] = entry / pivot;
        }
    }
    // Forward substitution L y = e; then e^T C^{-1} e = |y|^2.
    let mut y = [0.0; D];
    let mut sum = 0.0;
    for i in 0..D {
        let mut value = e[i];
        for m in 0..i {
            value -= c[i][m] * y[m];
        }
        y[i] = value / c[i][i];
        sum += y[i] * y[i];
    }
    sum.is_finite().then_some(sum)
}

/// `v` turned by the rotation in the plane of the unit vectors `from` and `to` that takes
/// `from` to `to` (the identity when they coincide, a half turn when they are opposite).
fn transported<const D: usize>(v: Point<D>, from: Point<D>, to: Point<D>) -> Point<D> {
    let cos = from.dot(to);
    let normal = to.add_scaled(-cos, from);
    let length = normal.norm();
    let turns = length > 1e-12;
    if !turns {
        return if cos < 0.0 { -v } else { v };
    }
    let w = normal * (1.0 / length);
    let sin = (1.0 - cos * cos).max(0.0).sqrt();
    let (a, b) = (v.dot(from), v.dot(w));
    let rest = v.add_scaled(-a, from).add_scaled(-b, w);
    rest.add_scaled(cos * a - sin * b, from)
        .add_scaled(sin * a + cos * b, w)
}

/// What one order of windows says (see the module documentation).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Rung {
    /// The median of `|e|_C` over that of `chi_{D-1}`: `sigma` if the residuals are noise.
    pub sigma: f64,
    /// The share of consecutive windows whose residuals point opposite ways.
    pub flips: f64,
    /// The lower quartile of `|e|_C` over its median, divided by the same ratio of
    /// `chi_{D-1}`.
    pub spread: f64,
    /// Windows measured.
    pub windows: usize,
    /// Pairs of consecutive windows compared for `flips`.
    pub pairs: usize,
    /// The share of windows whose middle point projects outside their chord (order 1 only):
    /// none on a curve that turns by less than a half turn over three points, many where the
    /// noise exceeds the spacing.
    pub outside: f64,
}

/// The rung of order `k` over the windows centred at `centres` (increasing), the window at
/// `centres[c]` with stride `strides[c]`, in coordinates divided by `unit`; `None` with fewer than 3 windows measured.
pub(super) fn rung<const D: usize>(
    points: &[Point<D>],
    unit: f64,
    centres: &[usize],
    strides: &[usize],
    k: usize,
) -> Option<Rung> {
    let n = points.len();
    let mut sizes = Vec::with_capacity(centres.len());
    let (mut flips, mut pairs, mut outside) = (0usize, 0usize, 0usize);
    let mut previous: Option<WindowResidual<D>> = None;
    for (&i, &m) in centres.iter().zip(strides) {
        let reach = k * m;
        if i < reach || i + reach >= n {
            continue;
        }
        let Some(window) = window_residual(points, unit, i - reach, m, k) else {
            continue;
        };
        sizes.push(window.size);
        outside += usize::from(window.outside);
        if let Some(before) = previous {
            pairs += 1;
            if transported(before.across, before.chord, window.chord).dot(window.across) < 0.0 {
                flips += 1;
            }
        }
        previous = Some(window);
    }
    if sizes.len() < 3 {
        return None;
    }
    let (median_unit, quartile_unit) = chi_quantiles(D.saturating_sub(1));
    let windows = sizes.len();
    let median = *sizes.select_nth_unstable_by(windows / 2, f64::total_cmp).1;
    let quartile = *sizes.select_nth_unstable_by(windows / 4, f64::total_cmp).1;
    Some(Rung {
        sigma: median / median_unit,
        flips: flips as f64 / pairs.max(1) as f64,
        spread: if median > 0.0 {
            (quartile / median) / (quartile_unit / median_unit)
        } else {
            0.0
        },
        windows,
        pairs,
        outside: outside as f64 / windows as f64,
    })
}

/// The median and the lower quartile of the `chi` distribution with `dof` degrees of
/// freedom: exact for 1 (a half-normal) and 2 (a Rayleigh variable), by the Wilson–Hilferty
/// approximation beyond.
fn chi_quantiles(dof: usize) -> (f64, f64) {
    match dof {
        0 | 1 => (0.674_489_750_196_081_7, 0.318_639_363_964_375_1),
        2 => (1.177_410_022_515_474_7, 0.758_527_616_440_916_7),
        _ => {
            let nu = dof as f64;
            let at = |z: f64| {
                let a = 2.0 / (9.0 * nu);
                (nu * (1.0 - a + z * a.sqrt()).powi(3)).sqrt()
            };
            (at(0.0), at(-0.674_489_750_196_081_7))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Point2, Point3};

    #[test]
    fn a_polynomial_graph_leaves_no_residual() {
        // y = x^3 - x on uneven x from -1 to 1 (a horizontal chord): order 2 (a cubic through
        // 4 points) reproduces it.
        let xs = [-1.0, -0.6, 0.2, 0.5, 1.0];
        let points: Vec<Point2> = xs
            .iter()
            .map(|&x| Point2::new([x, x * x * x - x]))
            .collect();
        let residual = window_residual(&points, 1.0, 0, 1, 2).unwrap();
        assert!(residual.size < 1e-13, "{residual:?}");
        // Order 1 sees the bend.
        let chord = window_residual(&points, 1.0, 1, 1, 1).unwrap();
        assert!(chord.size > 1e-3, "{chord:?}");
    }

    #[test]
    fn order_one_is_the_distance_from_the_chord() {
        // (0, 0), (1, 1), (3, 0): the middle point lies 1 above the chord, its projection
        // at u = 1/3, so e = 1 with the Lagrange weights 2/3 and 1/3; the interpolant through
        // the other two points is the chord itself (slope 0), so C = 1 + 4/9 + 1/9.
        let points = [
            Point2::new([0.0, 0.0]),
            Point2::new([1.0, 1.0]),
            Point2::new([3.0, 0.0]),
        ];
        let residual = window_residual(&points, 1.0, 0, 1, 1).unwrap();
        let expected = 1.0 / (1.0f64 + 1.0 / 9.0 + 4.0 / 9.0).sqrt();
        assert!((residual.size - expected).abs() < 1e-14, "{residual:?}");
    }

    #[test]
    fn the_quadratic_form_is_that_of_the_inverse() {
        let c = [[4.0, 1.0, 0.5], [1.0, 3.0, 0.2], [0.5, 0.2, 2.0]];
        let e = Point3::new([1.0, -2.0, 0.5]);
        // C^{-1} e solved by hand (Cramer's rule).
        let det = |m: [[f64; 3]; 3]| {
            m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
                - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
                + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
        };
        let full = det(c);
        let x: Vec<f64> = (0..3)
            .map(|col| {
                let mut m = c;
                for row in 0..3 {
                    m[row][col] = e[row];
                }
                det(m) / full
            })
            .collect();
        let expected = e[0] * x[0] + e[1] * x[1] + e[2] * x[2];
        let got = quadratic_form_of_inverse(c, e).unwrap();
        assert!((got - expected).abs() < 1e-13, "{got} {expected}");
        assert!(
            quadratic_form_of_inverse([[1.0, 2.0], [2.0, 1.0]], Point2::new([1.0, 0.0])).is_none()
        );
    }

    #[test]
    fn transport_turns_with_the_chord() {
        let from = Point2::new([1.0, 0.0]);
        let to = Point2::new([0.0, 1.0]);
        let v = transported(Point2::new([0.0, 1.0]), from, to);
        assert!(v.distance(Point2::new([-1.0, 0.0])) < 1e-15);
        let same = transported(
            Point3::new([0.3, 0.2, 0.1]),
            Point3::new([0.0, 0.0, 1.0]),
            Point3::new([0.0, 0.0, 1.0]),
        );
        assert_eq!(same, Point3::new([0.3, 0.2, 0.1]));
    }
}

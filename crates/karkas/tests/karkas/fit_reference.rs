//! The reference of the fit tests: data with known truth and slow independent references
//! (Bezier evaluation of Hermite pieces, dense least squares).
#![allow(clippy::needless_range_loop)]

use crate::common::{dense_solve_vector, Rng};
use karkas::Point2;

/// A point of the NACA 4-digit section `m p t` (camber m, its position p, thickness t, as
/// fractions of the chord), closed trailing edge, at `beta in [0, 2 pi]`: x = (1 + cos beta)/2,
/// upper surface for beta <= pi (trailing edge to leading edge), lower surface after.
pub fn naca(m: f64, p: f64, t: f64, beta: f64) -> Point2 {
    let x = 0.5 * (1.0 + beta.cos());
    let yt = 5.0
        * t
        * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
            - 0.1036 * x.powi(4));
    let (yc, slope) = if x < p {
        (
            m / (p * p) * (2.0 * p * x - x * x),
            2.0 * m / (p * p) * (p - x),
        )
    } else {
        let q = (1.0 - p) * (1.0 - p);
        (
            m / q * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
            2.0 * m / q * (p - x),
        )
    };
    let theta = slope.atan();
    let side = if beta <= std::f64::consts::PI {
        1.0
    } else {
        -1.0
    };
    Point2::new([x - side * yt * theta.sin(), yc + side * yt * theta.cos()])
}

/// Distance from `q` to the polyline `line`, searching segments `from..to`.
pub fn polyline_distance(line: &[Point2], q: Point2, from: usize, to: usize) -> (f64, usize) {
    let mut best = (f64::INFINITY, from);
    for k in from..to.min(line.len() - 1) {
        let (a, b) = (line[k], line[k + 1]);
        let ab = b - a;
        let s = ((q - a).dot(ab) / ab.norm_sq().max(1e-300)).clamp(0.0, 1.0);
        let d = q.distance(a.add_scaled(s, ab));
        if d < best.0 {
            best = (d, k);
        }
    }
    best
}

/// The Hermite piece on `[t0, t1]` with end values `r0, r1` and derivatives `h0, h1`,
/// evaluated at `t` through its Bezier form and de Casteljau (independent of the library's
/// power-basis formulas).
pub fn hermite_piece(
    t0: f64,
    t1: f64,
    r0: Point2,
    h0: Point2,
    r1: Point2,
    h1: Point2,
    t: f64,
) -> Point2 {
    let h = t1 - t0;
    let s = (t - t0) / h;
    let mut c = [
        r0,
        r0.add_scaled(h / 3.0, h0),
        r1.add_scaled(-h / 3.0, h1),
        r1,
    ];
    for level in (1..4).rev() {
        for k in 0..level {
            c[k] = c[k].lerp(c[k + 1], s);
        }
    }
    c[0]
}

/// Dense least squares `min |A x - b|` by the normal equations (small, well-scaled problems).
pub fn least_squares(rows: &[Vec<f64>], rhs: &[f64]) -> Vec<f64> {
    let n = rows[0].len();
    let mut a = vec![vec![0.0; n]; n];
    let mut b = vec![0.0; n];
    for (row, &y) in rows.iter().zip(rhs) {
        for i in 0..n {
            b[i] += row[i] * y;
            for j in 0..n {
                a[i][j] += row[i] * row[j];
            }
        }
    }
    dense_solve_vector(a, b)
}

/// The cubic C^2 spline basis on `knots` (truncated powers, centred at 1/2 for conditioning):
/// `1, u, u^2, u^3, (t - T_j)_+^3` for the inner knots, `u = t - 1/2`.
pub fn c2_basis(knots: &[f64], t: f64) -> Vec<f64> {
    let u = t - 0.5;
    let mut b = vec![1.0, u, u * u, u * u * u];
    for &k in &knots[1..knots.len() - 1] {
        b.push((t - k).max(0.0).powi(3));
    }
    b
}

/// An open test curve with noise: a piece of a widening spiral, `n` points, fixed seed.
pub fn noisy_spiral(n: usize, noise: f64, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let s = i as f64 / (n - 1) as f64;
            let a = 2.5 * s;
            Point2::new([
                (1.0 + 0.5 * s) * a.cos() + noise * rng.normal(),
                (1.0 + 0.5 * s) * a.sin() + noise * rng.normal(),
            ])
        })
        .collect()
}

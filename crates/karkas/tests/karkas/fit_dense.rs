//! Dense fits, which start from the fit of a subset of their points (every `k`-th, with the
//! same bending weight per point; from `4 * 32` points per piece): the result keeps its
//! parameters in order and averages the noise away inside the curve. (That the warm start
//! ends as low as the cold start is tested next to it, in `fit/coarse.rs`.)

use crate::common::Rng;
use crate::fit_reference::noisy_spiral;
use karkas::fit::{fit_curve, uniform_knots, FitOptions};
use karkas::{Curve, Point2};

/// The spiral of `noisy_spiral` without noise, at `s`.
fn spiral(s: f64) -> Point2 {
    let a = 2.5 * s;
    Point2::new([(1.0 + 0.5 * s) * a.cos(), (1.0 + 0.5 * s) * a.sin()])
}

/// The largest distance from the noise-free spiral over `[a, b]` of its parameter (2001
/// samples) to a dense polyline of the whole fit; with `[0, 1]` also the other way round.
fn distance_to_truth(fit: &dyn Curve<2>, a: f64, b: f64) -> f64 {
    let fitted: Vec<Point2> = (0..=20_000)
        .map(|i| fit.eval(i as f64 / 20_000.0))
        .collect();
    let truth: Vec<Point2> = (0..=2000)
        .map(|i| spiral(a + (b - a) * i as f64 / 2000.0))
        .collect();
    let one_way = |from: &[Point2], to: &[Point2]| {
        from.iter()
            .map(|p| {
                to.iter()
                    .map(|q| p.distance(*q))
                    .fold(f64::INFINITY, f64::min)
            })
            .fold(0.0f64, f64::max)
    };
    let back = if a == 0.0 && b == 1.0 {
        let dense: Vec<Point2> = (0..=20_000).map(|i| spiral(i as f64 / 20_000.0)).collect();
        one_way(
            &fitted[..].iter().step_by(10).copied().collect::<Vec<_>>(),
            &dense,
        )
    } else {
        0.0
    };
    one_way(&truth, &fitted).max(back)
}

#[test]
fn a_dense_noisy_fit_lies_near_the_truth_with_ordered_parameters() {
    let sigma = 1e-3;
    let points = noisy_spiral(20_000, sigma, 5);
    for knots in [uniform_knots(8), uniform_knots(40)] {
        let fit = fit_curve(&points, &knots, &FitOptions::default()).unwrap();
        assert!(fit.parameters.windows(2).all(|w| w[0] <= w[1]));
        // The noise averages over hundreds of points per piece: away from the ends (2% of
        // the parameter each) the fit lies well inside one sigma of the truth; an end is
        // held by its last point alone, so it stays within a few sigma.
        let inner = distance_to_truth(&fit.spline, 0.02, 0.98);
        assert!(
            inner < 0.2 * sigma,
            "{} knots: {inner:e} from the truth",
            knots.len()
        );
        let whole = distance_to_truth(&fit.spline, 0.0, 1.0);
        assert!(
            whole < 3.0 * sigma,
            "{} knots: {whole:e} at the ends",
            knots.len()
        );
    }
}

/// Fits `n` points of the spiral with noise 1e-3 (seed `seed`) on `knots` uniform knots with
/// the defaults, and asserts that it took at most `max_steps` steps, that its parameters are
/// in order, and that it lies within 0.35 sigma of the truth inside and within 2 sigma at
/// the ends.
fn assert_dense_fit(n: usize, seed: u64, knots: usize, max_steps: usize) {
    let sigma = 1e-3;
    let points = noisy_spiral(n, sigma, seed);
    let fit = fit_curve(&points, &uniform_knots(knots), &FitOptions::default()).unwrap();
    assert!(fit.iterations <= max_steps, "{} steps", fit.iterations);
    assert!(fit.parameters.windows(2).all(|w| w[0] <= w[1]));
    let inner = distance_to_truth(&fit.spline, 0.02, 0.98);
    assert!(inner < 0.35 * sigma, "{inner:e} from the truth");
    let whole = distance_to_truth(&fit.spline, 0.0, 1.0);
    assert!(whole < 2.0 * sigma, "{whole:e} at the ends");
}

#[test]
fn the_free_phase_hands_over_once_its_steps_only_slide_the_points() {
    // 50 noisy points per piece (no warm start). With the free phase iterated to convergence
    // the fit took 17 steps here. Handed over to the ordered phase once a free step lowers F
    // by less than 0.04 sigma^2 per coefficient (and 0.1% of F), it takes 4, and the curve
    // lies as near the truth (0.27 sigma inside, against 0.28).
    assert_dense_fit(20_000, 11, 401, 8);
}

#[test]
fn ordered_steps_that_only_slide_the_foot_points_end_the_phase() {
    // 50 noisy points per piece, spaced far closer than the noise: the foot points pool in
    // runs, and once the ends are pinned the ordered steps slide those runs along a curve
    // that no longer moves. The phase ends once a step moves the curve across itself by less
    // than a tenth of its standard error: the fit took 14 steps here before the rule, 8 with
    // it.
    assert_dense_fit(200_000, 13, 4001, 9);
}

#[test]
fn open_ends_on_dense_knots_lie_within_the_noise_of_the_true_ends() {
    // 25 points a piece, as FITPACK's knots give them on noisy dense points. The bending
    // term's natural end condition (R'' = 0) pulls such ends across the curve: with the
    // whole weight at the ends they lie 1.07 noise deviations from the true ends (RMS, these
    // 6 seeds); with its noise part falling off there (docs/methods.md §4, "The smoothing
    // falls off at the ends"), 0.39.
    let sigma = 2.9e-4;
    let mut squares = Vec::new();
    for seed in 1..=6 {
        let points = noisy_spiral(10_000, sigma, seed);
        let fit = fit_curve(&points, &uniform_knots(400), &FitOptions::default()).unwrap();
        for t in [0.0, 1.0] {
            squares.push(fit.spline.eval(t).distance(spiral(t)).powi(2) / (sigma * sigma));
        }
    }
    let rms = (squares.iter().sum::<f64>() / squares.len() as f64).sqrt();
    assert!(
        rms < 0.8,
        "the ends lie {rms:.2} noise deviations from the true ends (RMS)"
    );
}

/// The upper half of the ellipse `x = 0.5 cos(theta)`, `y = 0.2 sin(theta)` (chord 1) at `n`
/// points uniform in `theta`, with Gaussian noise of `sigma` per coordinate.
fn noisy_half_ellipse(n: usize, sigma: f64, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let theta = std::f64::consts::PI * i as f64 / (n - 1) as f64;
            Point2::new([
                0.5 * theta.cos() + sigma * rng.normal(),
                0.2 * theta.sin() + sigma * rng.normal(),
            ])
        })
        .collect()
}

/// The distance of `q` from the whole ellipse of `noisy_half_ellipse` (Newton's method on
/// the foot-point condition from the point's eccentric angle).
fn distance_to_ellipse(q: Point2) -> f64 {
    let (a, b) = (0.5, 0.2);
    let mut theta = (q[1] / b).atan2(q[0] / a);
    for _ in 0..20 {
        let (s, c) = theta.sin_cos();
        let (dx, dy) = (a * c - q[0], b * s - q[1]);
        let (tx, ty) = (-a * s, b * c);
        let g = dx * tx + dy * ty;
        let h = tx * tx + ty * ty + dx * (-a * c) + dy * (-b * s);
        theta -= g / h.max(1e-3 * (tx * tx + ty * ty));
    }
    Point2::new([a * theta.cos(), b * theta.sin()]).distance(q)
}

/// The largest and the RMS distance from the true ellipse of 20001 samples of `fit`,
/// uniform in its parameter.
fn ellipse_error(fit: &dyn Curve<2>) -> (f64, f64) {
    let d: Vec<f64> = (0..=20_000)
        .map(|i| distance_to_ellipse(fit.eval(i as f64 / 20_000.0)))
        .collect();
    let rms = (d.iter().map(|x| x * x).sum::<f64>() / d.len() as f64).sqrt();
    (d.iter().fold(0.0f64, |m, &x| m.max(x)), rms)
}

#[test]
fn four_times_the_noisy_points_land_no_farther_from_the_truth() {
    // 10 knots, noise 1e-4 of the chord: 2,800 and 11,000 points per piece. With the noise
    // share of the bending weight falling as (64 / m)^2 at every density m, the weight fell
    // against the data term as 1 / n^2, small loops through the noise band paid, and on
    // seed 1 the fit of 10^5 points landed farther from the ellipse than that of 2.5 x 10^4
    // (RMS 1.1e-5 against 4.0e-6, largest 6.9e-5 against 1.0e-5). The RMS distance falls
    // with more points; the largest is set by the spline's own error on 9 pieces and by
    // the ends (held by a few points whatever n), so it may only not grow by much.
    let sigma = 1e-4;
    let knots = uniform_knots(10);
    for seed in [1, 2] {
        let [few, many] = [25_000, 100_000].map(|n| {
            let points = noisy_half_ellipse(n, sigma, seed);
            let fit = fit_curve(&points, &knots, &FitOptions::default()).unwrap();
            ellipse_error(&fit.spline)
        });
        assert!(
            many.1 <= few.1 && many.0 <= 1.5 * few.0,
            "seed {seed}: 10^5 points {:.2e} / {:.2e} from the truth (largest / RMS), \
             2.5 x 10^4 {:.2e} / {:.2e}",
            many.0,
            many.1,
            few.0,
            few.1
        );
        // Both well inside the noise: the fit averages thousands of points a piece.
        assert!(many.0 < 0.5 * sigma, "seed {seed}: {:.2e}", many.0);
    }
}

//! Noise-aware fitting (docs/methods.md §4): foot-point parameters kept in the order of the
//! points, the noise estimated from the points, and a bending weight that neither pulls the
//! ends of exact data in nor lets a noisy fit follow the noise.

use crate::common::Rng;
use crate::fit_reference::{naca, polyline_distance};
use karkas::fit::{fit_curve, uniform_knots, FitOptions};
use karkas::{Curve, Point2};
use std::f64::consts::PI;

/// `n` points of NACA 2412 in cosine spacing from the trailing edge over the upper surface,
/// Gaussian noise of `sigma` per coordinate on every point.
fn noisy_section(n: usize, sigma: f64, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let p = naca(0.02, 0.4, 0.12, 2.0 * PI * i as f64 / (n - 1) as f64);
            Point2::new([p[0] + sigma * rng.normal(), p[1] + sigma * rng.normal()])
        })
        .collect()
}

/// The largest distance from samples of `curve` to the true contour (a dense polyline).
fn distance_to_truth<C: Curve<2>>(curve: &C) -> f64 {
    let truth: Vec<Point2> = (0..=20_000)
        .map(|k| naca(0.02, 0.4, 0.12, 2.0 * PI * k as f64 / 20_000.0))
        .collect();
    (0..=2000)
        .map(|k| polyline_distance(&truth, curve.eval(k as f64 / 2000.0), 0, truth.len()).0)
        .fold(0.0, f64::max)
}

#[test]
fn parameters_follow_the_order_of_the_points() {
    // Dense noisy points at both ends and at the nose: noise 1e-3 against spacings down to
    // 1e-6, where foot points found one by one come out of order.
    let points = noisy_section(2000, 1e-3, 11);
    let ordered = fit_curve(&points, &uniform_knots(32), &FitOptions::default()).unwrap();
    assert!(ordered.parameters.windows(2).all(|p| p[0] <= p[1]));
    let free = FitOptions {
        ordered: false,
        ..Default::default()
    };
    let unordered = fit_curve(&points, &uniform_knots(32), &free).unwrap();
    let reversals = unordered
        .parameters
        .windows(2)
        .filter(|p| p[1] < p[0])
        .count();
    assert!(reversals > 100, "{reversals}");
}

#[test]
fn the_noise_is_estimated_and_reported() {
    for sigma in [1e-4, 1e-3] {
        let points = noisy_section(1000, sigma, 5);
        let fit = fit_curve(&points, &uniform_knots(20), &FitOptions::default()).unwrap();
        assert!(
            (fit.noise.sigma / sigma - 1.0).abs() < 0.25,
            "sigma {sigma}: {:?}",
            fit.noise
        );
        // The weight grows with the square of the noise (the floor is negligible here).
        assert!(fit.bending_weight > 0.0);
    }
    let exact = noisy_section(1000, 0.0, 5);
    let fit = fit_curve(&exact, &uniform_knots(20), &FitOptions::default()).unwrap();
    assert!(fit.noise.sigma < 1e-5, "{:?}", fit.noise);
}

#[test]
fn a_long_winding_curve_keeps_its_ends() {
    // Three turns of a spiral, exact points: the bending term used to pull the ends in by
    // 6e-3 (1e-9 without it).
    let n = 100_000;
    let points: Vec<Point2> = (0..n)
        .map(|i| {
            let s = i as f64 / (n - 1) as f64;
            let a = 6.0 * PI * s;
            Point2::new([(1.0 + s) * a.cos(), (1.0 + s) * a.sin()])
        })
        .collect();
    let fit = fit_curve(&points, &uniform_knots(200), &FitOptions::default()).unwrap();
    assert!(fit.max_distance() < 1e-5, "{}", fit.max_distance());
    assert!(fit.spline.eval(0.0).distance(points[0]) < 1e-5);
    assert!(fit.spline.eval(1.0).distance(points[n - 1]) < 1e-5);
}

#[test]
fn smoothing_brings_a_noisy_fit_closer_to_the_truth() {
    // NACA 2412, 1000 points, noise 1e-3, 32 knots: without smoothing the fit follows the
    // noise; the default smoothing halves its distance from the true contour at least.
    let points = noisy_section(1000, 1e-3, 3);
    let rough = FitOptions {
        smoothing: Some(0.0),
        ..Default::default()
    };
    let plain = fit_curve(&points, &uniform_knots(32), &rough).unwrap();
    let smooth = fit_curve(&points, &uniform_knots(32), &FitOptions::default()).unwrap();
    let (a, b) = (
        distance_to_truth(&plain.spline),
        distance_to_truth(&smooth.spline),
    );
    eprintln!("without smoothing {a:.3e}, with {b:.3e}");
    assert!(b < a, "without smoothing {a:.3e}, with {b:.3e}");
    assert!(b < 1e-3, "{b:.3e}");
}

#[test]
fn smoothing_and_fairness_are_scale_free() {
    let points = noisy_section(500, 1e-3, 9);
    let unit = fit_curve(&points, &uniform_knots(12), &FitOptions::default()).unwrap();
    for scale in [1e-100, 1e100] {
        let scaled: Vec<Point2> = points.iter().map(|&p| p * scale).collect();
        let fit = fit_curve(&scaled, &uniform_knots(12), &FitOptions::default()).unwrap();
        assert!((fit.noise.sigma / (scale * unit.noise.sigma) - 1.0).abs() < 1e-9);
        let ratio = fit.max_distance() / (scale * unit.max_distance());
        assert!((ratio - 1.0).abs() < 1e-6, "{scale}: {ratio}");
    }
}

#[test]
fn noisy_open_ends_stay_at_the_true_edge() {
    // NACA 2412 closed at the trailing edge (1, 0), 5000 points in cosine spacing, noise 1e-3,
    // 32 knots: the points beyond each end pull a free end outward along the tangent; the
    // estimated ends stay closer to the true edge (RMS over both ends of 6 noisy sets).
    let sigma = 1e-3;
    let edge = Point2::new([1.0, 0.0]);
    let rms_of_ends = |options: &FitOptions| {
        let mut sum = 0.0;
        for seed in 0..6 {
            let points = noisy_section(5000, sigma, 100 + seed);
            let fit = fit_curve(&points, &uniform_knots(32), options).unwrap();
            eprintln!(
                "{:?} {:?} noise {:e}",
                fit.spline.eval(0.0),
                fit.spline.eval(1.0),
                fit.noise.sigma
            );
            sum += fit.spline.eval(0.0).distance_sq(edge) + fit.spline.eval(1.0).distance_sq(edge);
        }
        (sum / 12.0).sqrt()
    };
    let free = rms_of_ends(&FitOptions {
        ends: karkas::fit::FitEnds::Free,
        ..Default::default()
    });
    let estimated = rms_of_ends(&FitOptions::default());
    eprintln!("ends from the true edge: free {free:.3e}, estimated {estimated:.3e}");
    assert!(estimated < 0.6 * sigma, "{estimated:.3e}");
    assert!(
        estimated < 0.7 * free,
        "free {free:.3e}, estimated {estimated:.3e}"
    );
}

#[test]
fn ends_that_meet_are_held_at_one_point() {
    // The section is closed at its trailing edge: the two end estimates agree within the
    // noise, and both ends are held at their common point, nearer the edge than the first
    // and the last point.
    let sigma = 1e-3;
    let points = noisy_section(3000, sigma, 21);
    let fit = fit_curve(&points, &uniform_knots(24), &FitOptions::default()).unwrap();
    let (start, end) = (fit.spline.eval(0.0), fit.spline.eval(1.0));
    let edge = Point2::new([1.0, 0.0]);
    eprintln!(
        "{start:?} {end:?}; first and last point {:?} {:?}",
        points[0], points[2999]
    );
    assert!(start.distance(end) < 1e-12, "{start:?} {end:?}");
    assert!(start.distance(edge) < 0.5 * sigma, "{start:?}");
}

#[test]
fn estimated_ends_move_along_the_tangent_only() {
    // Ends apart (the section without its last fifth, so the lower surface ends at
    // x = 0.65): each pinned end differs from the free fit's end along the free fit's tangent
    // there (within the change of the tangent between the two fits).
    let mut points = noisy_section(3000, 1e-3, 21);
    points.truncate(2400);
    let knots = uniform_knots(24);
    let free = fit_curve(
        &points,
        &knots,
        &FitOptions {
            ends: karkas::fit::FitEnds::Free,
            ..Default::default()
        },
    )
    .unwrap();
    let held = fit_curve(&points, &knots, &FitOptions::default()).unwrap();
    for (t, sign) in [(0.0, 1.0), (1.0, -1.0)] {
        let tangent = free.spline.deriv(t, 1) * sign;
        let tangent = tangent * (1.0 / tangent.norm());
        let moved = held.spline.eval(t) - free.spline.eval(t);
        let across = (moved[0] * tangent[1] - moved[1] * tangent[0]).abs();
        eprintln!(
            "end {t}: moved {:.3e}, across the tangent {across:.3e}",
            moved.norm()
        );
        assert!(
            moved.norm() > 1e-5,
            "the end did not move: {:.3e}",
            moved.norm()
        );
        assert!(across < 0.05 * moved.norm() + 1e-6, "{across:.3e}");
    }
}

#[test]
fn the_default_smoothing_depends_on_the_mode() {
    // `smoothing: None` is DEFAULT_SMOOTHING on given knots and TOLERANCE_SMOOTHING in the
    // tolerance mode (bitwise), and the two differ on noisy points.
    use karkas::fit::{fit_curve_adaptive, DEFAULT_SMOOTHING, TOLERANCE_SMOOTHING};
    const { assert!(DEFAULT_SMOOTHING < TOLERANCE_SMOOTHING) };
    let points = noisy_section(600, 1e-3, 21);
    let with = |s: Option<f64>| FitOptions {
        smoothing: s,
        ..Default::default()
    };
    let knots = uniform_knots(16);
    let given = |s| fit_curve(&points, &knots, &with(s)).unwrap().distances;
    assert_eq!(given(None), given(Some(DEFAULT_SMOOTHING)));
    assert_ne!(given(None), given(Some(TOLERANCE_SMOOTHING)));
    let tolerance = |s| {
        fit_curve_adaptive(&points, 4e-3, &with(s))
            .unwrap()
            .fit
            .distances
    };
    assert_eq!(tolerance(None), tolerance(Some(TOLERANCE_SMOOTHING)));
    assert_ne!(tolerance(None), tolerance(Some(DEFAULT_SMOOTHING)));
}

#[test]
fn on_exact_sparse_points_the_defaults_are_the_papers_method() {
    // Exact points of NACA 2412 (cosine spacing, a sharp trailing edge at both ends) and of
    // a spiral of two turns, 12 to 60 of them: no noise is found, and the default fit on
    // given knots and in the tolerance mode is the one without smoothing, to the bit.
    use karkas::fit::fit_curve_adaptive;
    let section = |n: usize| -> Vec<Point2> {
        (0..n)
            .map(|i| naca(0.02, 0.4, 0.12, 2.0 * PI * i as f64 / (n - 1) as f64))
            .collect()
    };
    let spiral = |n: usize| -> Vec<Point2> {
        (0..n)
            .map(|i| {
                let a = 4.0 * PI * i as f64 / (n - 1) as f64;
                Point2::new([(1.0 + 0.5 * a) * a.cos(), (1.0 + 0.5 * a) * a.sin()])
            })
            .collect()
    };
    let none = FitOptions {
        smoothing: Some(0.0),
        ..Default::default()
    };
    for n in [12, 30, 60] {
        for points in [section(n), spiral(n)] {
            let knots = uniform_knots((n / 3).max(4));
            let default = fit_curve(&points, &knots, &FitOptions::default()).unwrap();
            assert_eq!(default.noise.sigma, 0.0, "{n}");
            let plain = fit_curve(&points, &knots, &none).unwrap();
            assert_eq!(default.spline, plain.spline, "{n}");
            let size = default.noise.size;
            let adaptive = fit_curve_adaptive(&points, 1e-3 * size, &FitOptions::default());
            let plain = fit_curve_adaptive(&points, 1e-3 * size, &none);
            assert_eq!(
                adaptive.unwrap().fit.spline,
                plain.unwrap().fit.spline,
                "{n}"
            );
        }
    }
}

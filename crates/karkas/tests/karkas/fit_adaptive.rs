//! The tolerance mode of the fit (`fit_curve_adaptive`, docs/methods.md §4): NACA 2412
//! sampled at cosine spacing, exact and with Gaussian noise. The deviations are checked
//! against a dense polyline of the fitted curve (not the fit's own distances), the noisy fit
//! against the true contour.

use crate::common::Rng;
use crate::fit_reference::{naca, polyline_distance};
use karkas::fit::{fit_curve_adaptive, AdaptiveStop, FitOptions, FitWarningKind};
use karkas::{Curve, Point2};
use std::f64::consts::PI;

/// `n` points of NACA 2412 from the trailing edge round the nose and back, the inner ones
/// with Gaussian noise of `sigma` per coordinate.
fn section(n: usize, sigma: f64, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let p = naca(0.02, 0.4, 0.12, 2.0 * PI * i as f64 / (n - 1) as f64);
            if sigma > 0.0 && i > 0 && i + 1 < n {
                Point2::new([p[0] + sigma * rng.normal(), p[1] + sigma * rng.normal()])
            } else {
                p
            }
        })
        .collect()
}

/// The largest distance of `points` from a polyline of 20001 samples of `curve`.
fn max_distance_to<C: Curve<2>>(curve: &C, points: &[Point2]) -> f64 {
    let line: Vec<Point2> = (0..=20000)
        .map(|k| curve.eval(k as f64 / 20000.0))
        .collect();
    points
        .iter()
        .map(|&q| polyline_distance(&line, q, 0, line.len()).0)
        .fold(0.0, f64::max)
}

#[test]
fn exact_section_meets_the_tolerance_with_few_knots() {
    let points = section(200, 0.0, 1);
    for tol in [1e-3, 1e-4, 1e-5] {
        let a = fit_curve_adaptive(&points, tol, &FitOptions::default()).unwrap();
        assert!(a.tolerance_met, "tol {tol}");
        assert_eq!(a.stop, AdaptiveStop::Met);
        // The polyline lies within 1e-8 of the curve at this sampling.
        let measured = max_distance_to(&a.fit.spline, &points);
        assert!(measured <= tol + 1e-8, "tol {tol}: {measured}");
        // A cubic with knots every few points: far fewer knots than points.
        let knots = a.fit.spline.knots().len();
        assert!(knots <= 40, "tol {tol}: {knots} knots");
        assert!(a.rounds <= 10, "tol {tol}: {} rounds", a.rounds);
        assert!(a
            .fit
            .warnings
            .iter()
            .all(|w| w.kind != FitWarningKind::ToleranceNotMet));
    }
}

#[test]
fn a_looser_tolerance_never_takes_more_knots() {
    let points = section(400, 0.0, 1);
    let knots = |tol: f64| {
        let a = fit_curve_adaptive(&points, tol, &FitOptions::default()).unwrap();
        assert!(a.tolerance_met);
        a.fit.spline.knots().len()
    };
    let (loose, mid, tight) = (knots(1e-3), knots(1e-4), knots(1e-5));
    assert!(loose <= mid && mid <= tight, "{loose} {mid} {tight}");
    assert!(loose < tight);
}

#[test]
fn unreachable_tolerance_on_noisy_points_stops_with_a_warning() {
    let sigma = 1e-3;
    let n = 1000;
    let points = section(n, sigma, 7);
    let a = fit_curve_adaptive(&points, 2e-4, &FitOptions::default()).unwrap();
    assert!(!a.tolerance_met);
    assert!(
        matches!(a.stop, AdaptiveStop::NoiseLevel | AdaptiveStop::Stalled),
        "{:?}",
        a.stop
    );
    let knots = a.fit.spline.knots().len();
    assert!(knots < n / 4, "{knots} knots");
    let warning = a
        .fit
        .warnings
        .iter()
        .find(|w| w.kind == FitWarningKind::ToleranceNotMet)
        .expect("a tolerance warning");
    assert!(
        warning.message.starts_with("tolerance 2e-4 not met"),
        "{warning}"
    );
    assert!(
        warning.message.contains(&format!("{knots} knots")),
        "{warning}"
    );
    assert!(warning.message.contains("noise level"), "{warning}");
    // The warning's place is the worst point's foot parameter.
    let worst = a
        .fit
        .distances
        .iter()
        .enumerate()
        .max_by(|x, y| x.1.total_cmp(y.1))
        .unwrap()
        .0;
    assert_eq!(warning.parameter, a.fit.parameters[worst]);
    // Beyond the noise: a worst point several sigma out (independent of the fit's figures).
    assert!(max_distance_to(&a.fit.spline, &points) > 2.0 * sigma);
    // The curve kept stays near the true contour (within twice the noise: no wild folds).
    let truth = section(4000, 0.0, 0);
    let line: Vec<Point2> = (0..=8000)
        .map(|k| a.fit.spline.eval(k as f64 / 8000.0))
        .collect();
    let off = truth
        .iter()
        .map(|&q| polyline_distance(&line, q, 0, line.len()).0)
        .fold(0.0, f64::max);
    assert!(off < 2.0 * sigma, "{off}");
}

#[test]
fn corners_stay_knots_and_tolerance_is_checked() {
    let points = section(200, 0.0, 1);
    let options = FitOptions {
        corners: vec![0.5],
        ..Default::default()
    };
    let a = fit_curve_adaptive(&points, 1e-4, &options).unwrap();
    assert!(a
        .fit
        .spline
        .knots()
        .iter()
        .any(|&k| (k - 0.5).abs() < 1e-12));
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(fit_curve_adaptive(&points, bad, &FitOptions::default()).is_err());
    }
}

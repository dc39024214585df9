//! Closed fits (`fit_closed_curve`, `fit_closed_curve_adaptive`, docs/methods.md §4 "Closed
//! curves"): an ellipse (a = 3, b = 1) exact and noisy, at the origin and far from it, judged
//! by the distance of the fitted curve from the exact ellipse (found by Newton's method on the
//! ellipse's angle, not by the fit); the seam's C^1 by finite differences of the returned
//! curve; a superellipse frame in the tolerance mode, checked against a dense polyline.

use crate::common::Rng;
use crate::fit_reference::polyline_distance;
use karkas::fit::{
    closed_bspline, fit_closed_curve, fit_closed_curve_adaptive, uniform_knots, FitOptions,
};
use karkas::{Curve, Point2};
use std::f64::consts::TAU;

/// `n` points of the ellipse `(a cos u, b sin u) + centre`, `u` uniform from 0, with
/// Gaussian noise of `sigma` per coordinate.
fn ellipse(n: usize, sigma: f64, centre: [f64; 2], seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let u = TAU * i as f64 / n as f64;
            Point2::new([
                centre[0] + 3.0 * u.cos() + sigma * rng.normal(),
                centre[1] + u.sin() + sigma * rng.normal(),
            ])
        })
        .collect()
}

/// The distance of `q` from the ellipse `x^2/9 + y^2 = 1` around `centre`.
fn ellipse_distance(q: Point2, centre: [f64; 2]) -> f64 {
    let (x, y) = (q[0] - centre[0], q[1] - centre[1]);
    let (a, b) = (3.0, 1.0);
    let mut best = f64::INFINITY;
    for start in 0..64 {
        let mut u = TAU * start as f64 / 64.0;
        for _ in 0..50 {
            let (c, s) = (u.cos(), u.sin());
            let (dx, dy) = (a * c - x, b * s - y);
            let g = dx * (-a * s) + dy * (b * c);
            let gp = (a * s).powi(2) + (b * c).powi(2) + dx * (-a * c) + dy * (-b * s);
            if gp <= 0.0 {
                break;
            }
            u -= g / gp;
        }
        best = best.min((a * u.cos() - x).hypot(b * u.sin() - y));
    }
    best
}

/// The largest distance of 4000 samples of `curve` over its period from the ellipse.
fn curve_to_ellipse(curve: &impl Curve<2>, centre: [f64; 2]) -> f64 {
    (0..4000)
        .map(|k| ellipse_distance(curve.eval(k as f64 / 4000.0), centre))
        .fold(0.0, f64::max)
}

/// The first derivative at the start of piece `[a, b]` from values at `a + k d`
/// (`k = 0..3`, `d = (b - a) / 4`), and at its end from `b - k d`: the one-sided third-order
/// differences, exact on a cubic piece up to rounding.
fn one_sided_derivatives(curve: &impl Curve<2>, a: f64, b: f64, at_start: bool) -> Point2 {
    let d = (b - a) / 4.0;
    let (t0, dir) = if at_start { (a, 1.0) } else { (b, -1.0) };
    let r = |k: f64| curve.eval(t0 + dir * k * d);
    (r(1.0) * 18.0 - r(0.0) * 11.0 - r(2.0) * 9.0 + r(3.0) * 2.0) * (dir / (6.0 * d))
}

#[test]
fn an_ellipse_is_fitted_closed_and_c1_across_the_seam() {
    for (sigma, centre) in [
        (0.0, [0.0, 0.0]),
        (0.0, [1e3, -5e2]),
        (1e-3, [0.0, 0.0]),
        (1e-3, [1e3, -5e2]),
    ] {
        for pieces in [10, 16] {
            let points = ellipse(40, sigma, centre, 11);
            let knots = uniform_knots(pieces + 1);
            let fit = fit_closed_curve(&points, &knots, &FitOptions::default()).unwrap();
            let s = &fit.spline;
            // Shape: the curve lies near the exact ellipse (cubic error on exact points,
            // the noise's order on noisy ones).
            let off = curve_to_ellipse(s, centre);
            // (No noise is found on the exact points, so the fit is the plain least-squares
            // one: 5.4e-4 off on 10 pieces, its cubic error.)
            let bound = if sigma == 0.0 { 7e-4 } else { 3e-3 };
            assert!(off < bound, "sigma {sigma}, {centre:?}, {pieces}: {off:e}");
            // The seam: value and first derivative equal on both sides.
            let size = 6.0;
            let gap = s.eval(0.0).distance(s.eval(1.0));
            assert!(gap <= 1e-9 * size, "{gap:e}");
            let k = s.knots();
            let right = one_sided_derivatives(s, k[0], k[1], true);
            let left = one_sided_derivatives(s, k[pieces - 1], k[pieces], false);
            let speed = right.norm();
            assert!(speed > 1.0, "{speed}");
            assert!(
                right.distance(left) <= 1e-9 * size,
                "sigma {sigma}, {centre:?}: derivative jump {:e}",
                right.distance(left)
            );
            // The closed B-spline is the same curve, flagged closed.
            let b = closed_bspline(s).unwrap();
            assert!(b.is_closed());
            for t in [0.0, 0.137, 0.5, 0.999] {
                let (d0, d1) = (b.domain().start, b.domain().end);
                let p = b.eval(d0 + t * (d1 - d0));
                assert!(p.distance(s.eval(t)) < 1e-9 * size);
            }
        }
    }
}

#[test]
fn a_repeated_first_point_gives_the_same_curve() {
    for centre in [[0.0, 0.0], [1e3, -5e2]] {
        let points = ellipse(40, 1e-3, centre, 5);
        let mut repeated = points.clone();
        repeated.push(points[0]);
        let knots = uniform_knots(13);
        let a = fit_closed_curve(&points, &knots, &FitOptions::default()).unwrap();
        let b = fit_closed_curve(&repeated, &knots, &FitOptions::default()).unwrap();
        assert_eq!(a.spline, b.spline);
        let a = fit_closed_curve_adaptive(&points, 1e-3, &FitOptions::default()).unwrap();
        let b = fit_closed_curve_adaptive(&repeated, 1e-3, &FitOptions::default()).unwrap();
        assert_eq!(a.fit.spline, b.fit.spline);
    }
}

/// `n` points of the frame `|x / a|^e + |y / b|^e = 1` (a fuselage-like section, flat at
/// the sides) around `centre`, starting at the top.
fn frame(n: usize, e: f64, centre: [f64; 2]) -> Vec<Point2> {
    (0..n)
        .map(|i| {
            let u = TAU * i as f64 / n as f64 + TAU / 4.0;
            let (c, s) = (u.cos(), u.sin());
            Point2::new([
                centre[0] + 1.8 * c.signum() * c.abs().powf(2.0 / e),
                centre[1] + 2.1 * s.signum() * s.abs().powf(2.0 / e),
            ])
        })
        .collect()
}

#[test]
fn a_frame_meets_the_tolerance_at_every_point() {
    // (60 points of the first frame to 1e-4 stop at the knot cap, 6e-4 reached: not
    // asked here.)
    for (n, e, centre, tols) in [
        (60, 2.5, [0.0, 0.0], &[1e-3][..]),
        (97, 3.0, [12.0, 0.4], &[1e-3, 1e-4][..]),
        (150, 2.2, [-350.0, 80.0], &[1e-3, 1e-4][..]),
        (90, 2.5, [1e3, -5e2], &[1e-3, 1e-4][..]),
    ] {
        for &tol in tols {
            let points = frame(n, e, centre);
            let result = fit_closed_curve_adaptive(&points, tol, &FitOptions::default()).unwrap();
            assert!(result.tolerance_met, "{n} {e} {tol}: {:?}", result.stop);
            // Judged on a dense polyline of the curve, not the fit's own distances.
            let s = &result.fit.spline;
            let line: Vec<Point2> = (0..=40000).map(|k| s.eval(k as f64 / 40000.0)).collect();
            let worst = points
                .iter()
                .map(|&q| polyline_distance(&line, q, 0, line.len()).0)
                .fold(0.0, f64::max);
            assert!(worst <= tol * 1.001, "{n} {e} {tol}: {worst:e}");
            assert!(s.eval(0.0).distance(s.eval(1.0)) < 1e-12 * 400.0);
        }
    }
}

#[test]
fn a_jump_bound_holds_across_the_seam() {
    let points = ellipse(40, 1e-3, [0.0, 0.0], 3);
    let knots = uniform_knots(11);
    let free = fit_closed_curve(&points, &knots, &FitOptions::default()).unwrap();
    let eps = free.jump_sum / 100.0;
    let options = FitOptions {
        eps,
        ..FitOptions::default()
    };
    let bounded = fit_closed_curve(&points, &knots, &options).unwrap();
    assert!(bounded.penalty > 0.0);
    assert!(bounded.jump_sum <= eps, "{} > {eps}", bounded.jump_sum);
    // The seam knot's jump is in the sum: the second derivative's jump there is as small
    // as the bound makes the others.
    let s = &bounded.spline;
    let seam = (s.deriv(1e-12, 2) - s.deriv(1.0 - 1e-12, 2)).norm();
    let inner = (s.deriv(0.5 + 1e-12, 2) - s.deriv(0.5 - 1e-12, 2)).norm();
    let free_seam = (free.spline.deriv(1e-12, 2) - free.spline.deriv(1.0 - 1e-12, 2)).norm();
    assert!(
        seam < 0.2 * free_seam,
        "{seam:e} vs {free_seam:e} (inner {inner:e})"
    );
}

#[test]
fn too_few_points_and_bad_corners_are_refused() {
    let points = ellipse(8, 0.0, [0.0, 0.0], 1);
    assert!(fit_closed_curve(&points, &uniform_knots(12), &FitOptions::default()).is_err());
    assert!(fit_closed_curve(&points[..2], &uniform_knots(3), &FitOptions::default()).is_err());
    let options = FitOptions {
        corners: vec![0.3],
        ..FitOptions::default()
    };
    assert!(fit_closed_curve(&points, &uniform_knots(5), &options).is_err());
}

#[test]
fn too_few_points_after_dropping_a_repeated_last_point_say_so() {
    let p = Point2::new([1.0, 2.0]);
    let q = Point2::new([3.0, 4.0]);
    let dropped = "a closed fit (after dropping its last point, which repeats the first) \
                   needs at least 3 points, got 2";
    for points in [vec![p, p, p], vec![p, q, p]] {
        let knots = uniform_knots(5);
        let by_knots = fit_closed_curve(&points, &knots, &FitOptions::default());
        let by_tolerance = fit_closed_curve_adaptive(&points, 1e-3, &FitOptions::default());
        for result in [by_knots.map(|_| ()), by_tolerance.map(|_| ())] {
            assert_eq!(result.unwrap_err().to_string(), dropped);
        }
    }
    // Two points, nothing dropped: the plain message.
    let two = fit_closed_curve(&[p, q], &uniform_knots(5), &FitOptions::default());
    assert_eq!(
        two.unwrap_err().to_string(),
        "a closed fit needs at least 3 points, got 2"
    );
}

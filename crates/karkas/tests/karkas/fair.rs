//! The fairest curve within a tolerance (`karkas::fair`): the hard bound on dense samples,
//! the energy and the curvature extrema before and after, kept ends, tangents and corners,
//! closed curves, curves given instead of points, points far from the origin, bad input.

use crate::common::{hydrofoil, nearest_by_sampling, Rng};
use crate::fit_reference::naca;
use karkas::fair::{fair_curve, fair_existing_curve, FairEnds, FairOptions};
use karkas::param::{CubicSpline, CurveParameterization};
use karkas::spline::SplineEnds;
use karkas::{Curve, Error, Point, Point2, Point3};
use std::f64::consts::PI;

/// NACA 2412 at `n` points in cosine spacing with Gaussian noise `sigma` (seeded).
fn noisy_naca(n: usize, sigma: f64, seed: u64) -> Vec<Point2> {
    let mut rng = Rng::new(seed);
    (0..n)
        .map(|i| {
            let p = naca(0.02, 0.4, 0.12, 2.0 * PI * i as f64 / (n - 1) as f64);
            Point([p[0] + sigma * rng.normal(), p[1] + sigma * rng.normal()])
        })
        .collect()
}

/// The largest distance of `points` from `curve`, by 20000 samples refined by golden section
/// (independent of the fairer's own parameters).
fn largest_distance<C: Curve<2>>(curve: &C, points: &[Point2]) -> f64 {
    points
        .iter()
        .map(|&q| nearest_by_sampling(curve, q, 20000))
        .fold(0.0, f64::max)
}

#[test]
fn the_bound_holds_on_dense_samples_and_the_curve_is_fairer() {
    for (sigma, seed) in [(1e-5, 1), (1e-4, 2), (3e-4, 3)] {
        let points = noisy_naca(201, sigma, seed);
        let tolerance = 3.0 * sigma;
        let fair = fair_curve(&points, &FairOptions::new(tolerance)).unwrap();
        let sampled = largest_distance(&fair.curve, &points);
        assert!(
            sampled <= tolerance * (1.0 + 1e-9),
            "sigma {sigma}: a point {sampled:.6e} from the curve, T {tolerance:.6e}"
        );
        assert!(fair.max_distance() <= tolerance);
        let (before, after) = (fair.fairness_before().unwrap(), fair.fairness());
        assert!(
            after.fairness_energy < 0.1 * before.fairness_energy,
            "sigma {sigma}: energy {:.3e} before, {:.3e} after",
            before.fairness_energy,
            after.fairness_energy
        );
        assert!(
            after.curvature_extrema * 5 < before.curvature_extrema,
            "sigma {sigma}: {} extrema before, {} after",
            before.curvature_extrema,
            after.curvature_extrema
        );
        assert_eq!(
            after.curvature_jump, 0.0,
            "a C^2 curve has no curvature jumps"
        );
    }
}

/// NACA 0012 at `n` exact points in cosine spacing (a symmetric section: no inflection).
fn sparse_naca0012(n: usize) -> Vec<Point2> {
    (0..n)
        .map(|i| naca(0.0, 0.4, 0.12, 2.0 * PI * i as f64 / (n - 1) as f64))
        .collect()
}

#[test]
fn sparse_points_under_a_tight_tolerance_are_never_made_less_fair() {
    // Tolerances far below the points' spacing, where every curve within them nearly
    // interpolates: the fairer once returned near-cusps (energies of 1e19 to 1e27 against
    // the interpolant's 0.13 on the hydrofoil) and kinks at the points (16 inflections on a
    // 21-point NACA 0012, whose interpolant has none).
    let cases: Vec<(&str, Vec<Point2>, f64)> = vec![
        ("hydrofoil", hydrofoil(), 3e-3),
        ("hydrofoil", hydrofoil(), 3e-2),
        ("hydrofoil", hydrofoil(), 10.0),
        ("NACA 0012, 12 points", sparse_naca0012(12), 1e-4),
        ("NACA 0012, 21 points", sparse_naca0012(21), 1e-5),
        ("NACA 0012, 21 points", sparse_naca0012(21), 1e-4),
        ("NACA 0012, 31 points", sparse_naca0012(31), 1e-4),
    ];
    for (name, points, tolerance) in cases {
        let fair = fair_curve(&points, &FairOptions::new(tolerance)).unwrap();
        let (before, after) = (fair.fairness_before().unwrap(), fair.fairness());
        assert!(
            after.fairness_energy <= before.fairness_energy * (1.0 + 1e-9),
            "{name} at T {tolerance}: energy {:.4e} before, {:.4e} after",
            before.fairness_energy,
            after.fairness_energy
        );
        assert!(
            after.inflections <= before.inflections,
            "{name} at T {tolerance}: {} inflections before, {} after",
            before.inflections,
            after.inflections
        );
        let sampled = largest_distance(&fair.curve, &points);
        assert!(
            sampled <= tolerance * (1.0 + 1e-9),
            "{name} at T {tolerance}: a point {sampled:.4e} from the curve"
        );
        // The same choice at scales whose energies (1/size^3) leave the floating-point range.
        for scale in [1e-150, 1e-120, 1e90] {
            let small: Vec<Point2> = points.iter().map(|&p| p * scale).collect();
            let tiny = fair_curve(&small, &FairOptions::new(tolerance * scale)).unwrap();
            let size = fair
                .curve
                .control_points()
                .iter()
                .fold(0.0f64, |m, c| m.max(c.max_abs()));
            assert_eq!(
                tiny.curve.control_points().len(),
                fair.curve.control_points().len()
            );
            for (a, b) in tiny
                .curve
                .control_points()
                .iter()
                .zip(fair.curve.control_points())
            {
                assert!(
                    (*a * (1.0 / scale) - *b).max_abs() < 1e-9 * size,
                    "{name} at T {tolerance}, scale {scale}: {a:?} against {b:?}"
                );
            }
        }
    }
}

#[test]
fn a_noisy_helix_in_space_is_faired_within_the_bound() {
    let mut rng = Rng::new(11);
    let sigma = 1e-3;
    let points: Vec<Point3> = (0..120)
        .map(|i| {
            let a = i as f64 * 0.1;
            Point([a.cos(), a.sin(), 0.2 * a]) + rng.point::<3>() * sigma
        })
        .collect();
    let fair = fair_curve(&points, &FairOptions::new(4.0 * sigma)).unwrap();
    assert!(fair.max_distance() <= 4.0 * sigma);
    // Every point within T of the curve on dense samples.
    let samples: Vec<Point3> = (0..=40000)
        .map(|k| fair.curve.eval(k as f64 / 40000.0))
        .collect();
    for p in &points {
        let d = samples
            .iter()
            .map(|s| s.distance(*p))
            .fold(f64::INFINITY, f64::min);
        assert!(d <= 4.0 * sigma + 2e-5, "a point {d:.3e} from the samples");
    }
    let (before, after) = (fair.fairness_before().unwrap(), fair.fairness());
    assert!(after.fairness_energy < 0.1 * before.fairness_energy);
    assert_eq!(after.inflections, 0);
}

#[test]
fn kept_ends_and_tangents_are_kept() {
    let points = noisy_naca(101, 1e-4, 5);
    let n = points.len();
    let kept = FairOptions {
        ends: FairEnds::Kept,
        ..FairOptions::new(3e-4)
    };
    let fair = fair_curve(&points, &kept).unwrap();
    assert!(fair.curve.eval(0.0).distance(points[0]) < 1e-14);
    assert!(fair.curve.eval(1.0).distance(points[n - 1]) < 1e-14);
    let tangents = FairOptions {
        ends: FairEnds::KeptWithTangents,
        ..FairOptions::new(3e-4)
    };
    let fair = fair_curve(&points, &tangents).unwrap();
    assert!(fair.curve.eval(0.0).distance(points[0]) < 1e-14);
    assert!(fair.curve.eval(1.0).distance(points[n - 1]) < 1e-14);
    let start = fair.curve.deriv(0.0, 1);
    let end = fair.curve.deriv(1.0, 1);
    let (first, last) = (points[1] - points[0], points[n - 1] - points[n - 2]);
    let sine = |a: Point2, b: Point2| (a[0] * b[1] - a[1] * b[0]) / (a.norm() * b.norm());
    assert!(sine(start, first).abs() < 1e-12 && start.dot(first) > 0.0);
    assert!(sine(end, last).abs() < 1e-12 && end.dot(last) > 0.0);
    assert!(fair.max_distance() <= 3e-4);
}

#[test]
fn corners_are_passed_through_with_a_triple_knot() {
    // Two noisy arcs meeting at a corner at (1, 0).
    let mut rng = Rng::new(7);
    let mut points: Vec<Point2> = (0..40)
        .map(|i| {
            let a = PI * i as f64 / 39.0;
            Point([-a.cos(), -0.5 * a.sin()])
        })
        .collect();
    let corner = points.len() - 1;
    points.extend((1..40).map(|i| {
        let x = 1.0 + i as f64 / 39.0;
        Point([x, 0.3 * (x - 1.0).powi(2)])
    }));
    for p in points.iter_mut() {
        *p += Point([rng.normal(), rng.normal()]) * 1e-4;
    }
    let options = FairOptions {
        corners: vec![corner],
        ..FairOptions::new(5e-4)
    };
    let fair = fair_curve(&points, &options).unwrap();
    let t = fair.parameters[corner];
    assert!(fair.curve.eval(t).distance(points[corner]) < 1e-12);
    let triple = fair
        .curve
        .distinct_knots()
        .iter()
        .any(|&(k, m)| (k - t).abs() < 1e-14 && m == 3);
    assert!(
        triple,
        "no triple knot at the corner {t}: {:?}",
        fair.curve.distinct_knots()
    );
    assert!(largest_distance(&fair.curve, &points) <= 5e-4 * (1.0 + 1e-9));
}

#[test]
fn a_closed_noisy_ellipse_gives_a_closed_c2_curve_with_fewer_extrema() {
    let mut rng = Rng::new(3);
    let n = 80;
    let points: Vec<Point2> = (0..n)
        .map(|i| {
            let a = 2.0 * PI * i as f64 / n as f64;
            Point([
                2.0 * a.cos() + 1e-3 * rng.normal(),
                a.sin() + 1e-3 * rng.normal(),
            ])
        })
        .collect();
    let options = FairOptions {
        closed: true,
        ..FairOptions::new(4e-3)
    };
    let fair = fair_curve(&points, &options).unwrap();
    assert!(fair.curve.is_closed());
    assert!(fair.curve.eval(0.0).distance(fair.curve.eval(1.0)) < 1e-14);
    for k in 1..=2 {
        let (a, b) = (fair.curve.deriv(0.0, k), fair.curve.deriv(1.0, k));
        assert!(
            a.distance(b) < 1e-8 * a.norm().max(1.0),
            "derivative {k}: {a:?} {b:?}"
        );
    }
    assert!(largest_distance(&fair.curve, &points) <= 4e-3 * (1.0 + 1e-9));
    let (before, after) = (fair.fairness_before().unwrap(), fair.fairness());
    assert_eq!(after.inflections, 0);
    assert!(
        after.curvature_extrema * 3 <= before.curvature_extrema,
        "{} extrema before, {} after",
        before.curvature_extrema,
        after.curvature_extrema
    );
}

#[test]
fn an_existing_curve_is_faired_through_its_samples() {
    // The spline through noisy points of an airfoil: wavy curvature.
    let points = noisy_naca(61, 2e-4, 9);
    let wavy = CubicSpline::through(
        &points,
        CurveParameterization::ChordLength,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    let options = FairOptions {
        ends: FairEnds::KeptWithTangents,
        ..FairOptions::new(5e-4)
    };
    let fair = fair_existing_curve(&wavy, 300, &options).unwrap();
    assert_eq!(fair.points.len(), 300);
    let d = wavy.domain();
    assert!(fair.curve.eval(0.0).distance(wavy.eval(d.start)) < 1e-14);
    let (a, b) = (fair.curve.deriv(0.0, 1), wavy.deriv(d.start, 1));
    assert!((a[0] * b[1] - a[1] * b[0]).abs() < 1e-12 * a.norm() * b.norm());
    assert!(largest_distance(&fair.curve, &fair.points) <= 5e-4 * (1.0 + 1e-9));
    let before = karkas::geometry::curve_fairness(&wavy, &fair.points);
    let after = fair.fairness();
    assert!(after.fairness_energy < 0.5 * before.fairness_energy);
    assert!(after.curvature_extrema < before.curvature_extrema);
}

/// Points moved far from the origin give the same curve moved, to 64 units in the last place
/// of the offset, for every offset from 1e3 to 1e8 and with free ends, kept ends and tangents,
/// a corner and a closed curve. The points lie on the grid of 2^-26 so that every moved point
/// is exactly the point plus the offset: the comparison is of the fairer, not of the rounding
/// of the input.
#[test]
fn points_far_from_the_origin_give_the_same_curve_moved() {
    let grid = |p: Point2| Point(p.0.map(|c| (c * 2f64.powi(26)).round() / 2f64.powi(26)));
    let airfoil: Vec<Point2> = noisy_naca(101, 1e-4, 4).into_iter().map(grid).collect();
    let mut rng = Rng::new(9);
    let ellipse: Vec<Point2> = (0..60)
        .map(|i| {
            let a = 2.0 * PI * i as f64 / 60.0;
            grid(Point([
                0.8 * a.cos() + 1e-4 * rng.normal(),
                0.3 * a.sin() + 1e-4 * rng.normal(),
            ]))
        })
        .collect();
    let cases = [
        ("free ends", &airfoil, FairOptions::new(3e-4)),
        (
            "kept ends and tangents",
            &airfoil,
            FairOptions {
                ends: FairEnds::KeptWithTangents,
                ..FairOptions::new(3e-4)
            },
        ),
        (
            "a corner",
            &airfoil,
            FairOptions {
                corners: vec![50],
                ..FairOptions::new(3e-4)
            },
        ),
        (
            "closed",
            &ellipse,
            FairOptions {
                closed: true,
                ..FairOptions::new(3e-4)
            },
        ),
    ];
    for (name, points, options) in cases {
        let base = fair_curve(points, &options).unwrap();
        for offset in [1e3, 1e4, 1e5, 1e6, 1e7, 1e8] {
            let shift = Point([offset, -0.5 * offset]);
            let moved: Vec<Point2> = points.iter().map(|&p| p + shift).collect();
            assert!(moved
                .iter()
                .zip(points.iter())
                .all(|(m, p)| *m - shift == *p));
            let fair = fair_curve(&moved, &options).unwrap();
            // The spacing of the doubles at the offset.
            let ulp = 2f64.powi(offset.log2().floor() as i32 - 52);
            let mut worst: f64 = 0.0;
            for k in 0..=1000 {
                let t = k as f64 / 1000.0;
                let expected = base.curve.eval(t) + shift;
                worst = worst.max((fair.curve.eval(t) - expected).max_abs());
            }
            assert!(
                worst <= 64.0 * ulp,
                "{name}, offset {offset:e}: moved by {worst:.3e} ({:.1} units in the last place)",
                worst / ulp
            );
        }
    }
}

#[test]
fn bad_input_is_refused_naming_the_cause() {
    let points = noisy_naca(41, 1e-4, 1);
    for bad in [0.0, -1.0, f64::NAN, f64::INFINITY] {
        assert!(matches!(
            fair_curve(&points, &FairOptions::new(bad)),
            Err(Error::InvalidSetting {
                name: "tolerance",
                ..
            })
        ));
    }
    // Below what the coordinates resolve.
    let far: Vec<Point2> = points.iter().map(|&p| p + Point([1e9, 0.0])).collect();
    let err = fair_curve(&far, &FairOptions::new(1e-8)).unwrap_err();
    assert!(err.to_string().contains("resolve"), "{err}");
    let mut nan = points.clone();
    nan[7] = Point([f64::NAN, 0.0]);
    assert!(matches!(
        fair_curve(&nan, &FairOptions::new(1e-3)),
        Err(Error::NonFinitePoint { index: 7 })
    ));
    assert!(matches!(
        fair_curve(&points[..3], &FairOptions::new(1e-3)),
        Err(Error::TooFewPoints { .. })
    ));
    let shuffled: Vec<Point2> = (0..41).map(|i| points[(i * 17) % 41]).collect();
    let err = fair_curve(&shuffled, &FairOptions::new(1e-3)).unwrap_err();
    assert!(matches!(err, Error::PointsOutOfOrder { .. }));
    assert!(err.to_string().starts_with("points not in order"), "{err}");
    for corners in [vec![0], vec![40], vec![5, 5], vec![9, 3]] {
        let options = FairOptions {
            corners,
            ..FairOptions::new(1e-3)
        };
        assert!(matches!(
            fair_curve(&points, &options),
            Err(Error::InvalidSetting { name: "corner", .. })
        ));
    }
}

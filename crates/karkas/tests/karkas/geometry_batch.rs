//! Arc lengths of polynomial curves against high-precision references, the arc-length table
//! against the direct integral, and global projection against brute force near a cusp and on
//! the far side of closed curves.
//!
//! References: the lengths of the cubic `(t, t^3 - t)` were computed with mpmath at 40
//! digits (`mpmath.quad(lambda t: sqrt(1 + (3 t^2 - 1)^2), [a, sqrt(3)/3, b])`); the cusp
//! `(t^2, t^3)` has the closed form `2 (13^{3/2} - 8) / 27` over `[-1, 1]`.

use std::f64::consts::TAU;

use karkas::geometry::{arc_length, ArcLengthTable, CurveGeometry, CurveProjector};
use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use karkas::{Curve, Point2};

use crate::common::nearest_by_sampling;

/// The not-a-knot cubic spline through `f` at the parameters `ts`: exactly the cubic `f`.
fn cubic_through(ts: &[f64], f: impl Fn(f64) -> Point2) -> CubicSpline<2> {
    let pts: Vec<Point2> = ts.iter().map(|&t| f(t)).collect();
    CubicSpline::new(ts, &pts, SplineEnds::NotAKnot).unwrap()
}

fn wavy_cubic() -> CubicSpline<2> {
    cubic_through(&[0.0, 0.5, 1.0, 1.5, 2.0], |t| {
        Point2::new([t, t * t * t - t])
    })
}

fn cusp() -> CubicSpline<2> {
    cubic_through(&[-1.0, -0.5, 0.0, 0.5, 1.0], |t| {
        Point2::new([t * t, t * t * t])
    })
}

#[test]
fn cubic_arc_length_to_1e_12_relative() {
    let c = wavy_cubic();
    for (a, b, reference) in [
        (0.0, 2.0, 7.413_645_111_500_688),
        (0.25, 1.75, 4.667_052_644_014_485),
    ] {
        let direct = c.arc_length(a, b, 1e-13);
        let table = ArcLengthTable::new(&c, 1e-13).arc_length(&c, a, b);
        for got in [direct, table] {
            assert!(
                (got - reference).abs() <= 1e-12 * reference,
                "{got} vs {reference}"
            );
        }
    }
    let cusp = cusp();
    let reference = 2.0 * (13f64.powf(1.5) - 8.0) / 27.0;
    let got = cusp.arc_length(-1.0, 1.0, 1e-13);
    assert!(
        (got - reference).abs() <= 1e-12 * reference,
        "{got} vs {reference}"
    );
}

#[test]
fn circle_arcs_to_1e_12_relative() {
    // The periodic cubic spline through a circle is not a circle: measure true arcs on an
    // exact parametric circle instead (radius 2, arcs of every size up to several turns).
    struct Circle;
    impl Curve<2> for Circle {
        fn domain(&self) -> karkas::Interval {
            karkas::Interval::new(0.0, TAU)
        }
        fn is_closed(&self) -> bool {
            true
        }
        fn eval(&self, t: f64) -> Point2 {
            Point2::new([2.0 * t.cos(), 2.0 * t.sin()])
        }
        fn deriv(&self, t: f64, k: usize) -> Point2 {
            let (s, c) = t.sin_cos();
            let v = match k % 4 {
                0 => [c, s],
                1 => [-s, c],
                2 => [-c, -s],
                _ => [s, -c],
            };
            Point2::new([2.0 * v[0], 2.0 * v[1]])
        }
    }
    let table = ArcLengthTable::new(&Circle, 1e-13);
    for (a, b) in [
        (0.0, 1e-3),
        (0.3, 1.0),
        (1.0, 6.0),
        (-2.0, 15.0),
        (5.0, 0.5),
    ] {
        let reference = 2.0 * (b - a);
        for got in [
            arc_length(&Circle, a, b, 1e-13),
            table.arc_length(&Circle, a, b),
        ] {
            assert!(
                (got - reference).abs() <= 1e-12 * reference.abs(),
                "[{a}, {b}]: {got} vs {reference}"
            );
        }
    }
}

#[test]
fn the_table_agrees_with_the_direct_integral_and_inverts_it() {
    let pts: Vec<Point2> = (0..40)
        .map(|k| {
            let th = TAU * k as f64 / 40.0;
            let r = 1.0 + 0.3 * (5.0 * th).cos();
            Point2::new([r * th.cos(), r * th.sin()])
        })
        .collect();
    let closed = CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::Periodic,
    )
    .unwrap();
    let open = CubicSpline::through(
        &pts,
        CurveParameterization::Centripetal,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    for curve in [&closed, &open] {
        let d = curve.domain();
        let table = ArcLengthTable::new(curve, 1e-11);
        let direct_total = arc_length(curve, d.start, d.end, 1e-12);
        assert!((table.total() - direct_total).abs() < 1e-11);
        let ts: Vec<f64> = (0..97)
            .map(|k| d.start - 0.5 * d.length() + 2.0 * d.length() * k as f64 / 96.0)
            .collect();
        let mut batch = vec![0.0; ts.len()];
        table.arc_lengths_into(curve, ts[3], &ts, &mut batch);
        for (i, &t1) in ts.iter().enumerate() {
            let direct = arc_length(curve, ts[3], t1, 1e-12);
            assert!((table.arc_length(curve, ts[3], t1) - direct).abs() < 1e-10);
            assert!(
                (batch[i] - direct).abs() < 1e-10,
                "{t1}: {} vs {direct}",
                batch[i]
            );
        }
        let lengths: Vec<f64> = (0..41)
            .map(|k| -1.2 * direct_total + 0.06 * direct_total * k as f64)
            .collect();
        let mut params = vec![0.0; lengths.len()];
        table.inverses_into(curve, 0.3, &lengths, &mut params);
        for (&s, &t) in lengths.iter().zip(&params) {
            let direct = curve.inverse_arc_length(0.3, s, 1e-12);
            // Parameters from two methods, compared through the lengths they reach.
            let reached = arc_length(curve, direct, t, 1e-12).abs();
            assert!(reached < 1e-9, "{s}: {t} vs {direct}");
        }
    }
    assert!(table_nan(&closed));
}

fn table_nan(c: &CubicSpline<2>) -> bool {
    let table = ArcLengthTable::new(c, 1e-10);
    table.arc_length(c, f64::NAN, 1.0).is_nan() && table.inverse(c, 0.0, f64::NAN).is_nan()
}

#[test]
fn projection_near_a_cusp_is_global() {
    let c = cusp();
    let projector = CurveProjector::new(&c, 0.0).unwrap();
    let queries = [
        Point2::new([0.0, 0.0]),
        Point2::new([-1e-3, 0.0]),
        Point2::new([-0.2, 1e-4]),
        Point2::new([1e-4, 1e-6]),
        Point2::new([0.01, -1e-3]),
        Point2::new([0.05, 0.0]),
        Point2::new([0.3, 0.0]),
        Point2::new([0.25, 0.124]),
        Point2::new([-0.5, -0.3]),
    ];
    for q in queries {
        let near = projector.nearest(q);
        let reference = nearest_by_sampling(&c, q, 200_000);
        assert!(
            near.distance <= reference + 1e-12,
            "{q:?}: {} vs {reference}",
            near.distance
        );
        assert!(c.eval(near.t).distance(near.point) < 1e-15);
    }
}

#[test]
fn projection_onto_the_far_side_of_closed_curves_is_global() {
    // A thin closed loop: points inside reach both sides; points outside near the seam.
    let pts: Vec<Point2> = (0..60)
        .map(|k| {
            let th = TAU * k as f64 / 60.0;
            Point2::new([3.0 * th.cos(), 0.2 * th.sin() + 0.05 * (3.0 * th).sin()])
        })
        .collect();
    let c = CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::Periodic,
    )
    .unwrap();
    let projector = CurveProjector::new(&c, 0.0).unwrap();
    let mut worst: f64 = 0.0;
    for k in 0..400 {
        let (x, y) = (
            -3.5 + 7.0 * (k % 20) as f64 / 19.0,
            -0.6 + 1.2 * (k / 20) as f64 / 19.0,
        );
        let q = Point2::new([x, y]);
        let near = projector.nearest(q);
        let reference = nearest_by_sampling(&c, q, 100_000);
        assert!(
            near.distance <= reference + 1e-12,
            "{q:?}: {} vs {reference}",
            near.distance
        );
        worst = worst.max(reference - near.distance);
        assert!((0.0..c.domain().end).contains(&near.t));
    }
    assert!(worst < 1e-9, "{worst}");
}

#[test]
fn value_and_derivatives_at_once_equal_the_separate_calls() {
    let open = wavy_cubic();
    let pts: Vec<Point2> = (0..12)
        .map(|k| {
            let th = TAU * k as f64 / 12.0;
            Point2::new([th.cos(), 0.5 * th.sin()])
        })
        .collect();
    let closed = CubicSpline::through(
        &pts,
        CurveParameterization::Centripetal,
        SplineEnds::Periodic,
    )
    .unwrap();
    for curve in [&open, &closed] {
        let d = curve.domain();
        // Knots, points between them and outside the domain (extension or wrap).
        for k in -8..=40 {
            let t = d.start + d.length() * k as f64 / 32.0;
            let [p, d1, d2] = curve.eval_with_derivatives(t);
            assert_eq!(p, curve.eval(t), "{t}");
            assert_eq!(d1, curve.deriv(t, 1), "{t}");
            assert_eq!(d2, curve.deriv(t, 2), "{t}");
        }
    }
}

#[test]
fn third_derivatives_and_curvature_rates_hold_at_extreme_scales() {
    let pts: Vec<Point2> = (0..30)
        .map(|k| {
            let th = TAU * k as f64 / 30.0;
            Point2::new([th.cos() + 0.2 * (3.0 * th).cos(), 0.6 * th.sin()])
        })
        .collect();
    let unit = CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::Periodic,
    )
    .unwrap();
    for scale in [1e150, 1e-150] {
        let scaled: Vec<Point2> = pts.iter().map(|&p| p * scale).collect();
        let c = CubicSpline::through(
            &scaled,
            CurveParameterization::ChordLength,
            SplineEnds::Periodic,
        )
        .unwrap();
        for k in 0..50 {
            let t = unit.domain().length() * (k as f64 + 0.3) / 50.0;
            // With chord parameters, P^(j) scales by scale^(1 - j).
            let d3 = c.deriv(t * scale, 3) * scale * scale;
            let reference = unit.deriv(t, 3);
            assert!(
                (d3 - reference).norm() <= 1e-9 * reference.norm().max(1.0),
                "{scale} {t}"
            );
            let (k1, r1) = karkas::geometry::curvature_rate(&unit, t);
            let (k2, r2) = karkas::geometry::curvature_rate(&c, t * scale);
            assert!(
                (k2 * scale - k1).abs() <= 1e-9 * k1.abs().max(1.0),
                "{scale} {t}"
            );
            assert!(
                (r2 * scale * scale - r1).abs() <= 1e-9 * r1.abs().max(1.0),
                "{scale} {t}"
            );
        }
    }
}

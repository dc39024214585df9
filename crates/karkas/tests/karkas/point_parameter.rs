//! `geometry::parameter_on_curve`: a point on a curve gets the global search's parameter;
//! a point off it, or one the nearest sample cannot reach, is left to the global search.

use karkas::bspline::conic::elliptic_arc;
use karkas::bspline::NurbsCurve;
use karkas::geometry::parameter_on_curve;
use karkas::geometry::CurveProjector;
use karkas::Point3;
use karkas::{Curve, Point};
use std::f64::consts::TAU;

/// A circle of radius 2 far from the origin, clamped (as karkas writes one), marked closed
/// (as the readers mark a curve whose ends meet).
fn clamped_circle() -> NurbsCurve<3> {
    let (x, y) = (Point3::new([2.0, 0.0, 0.0]), Point3::new([0.0, 0.0, 2.0]));
    elliptic_arc(Point3::new([1e3, -5.0, 3.0]), x, y, (0.0, TAU))
        .unwrap()
        .with_closed(true)
}

/// The same circle as Open CASCADE writes one converted to NURBS: three arcs of a third of
/// a turn, double inner knots, one knot outside the domain `[0, 2 pi]` at each end.
fn periodic_circle() -> NurbsCurve<3> {
    let third = TAU / 3.0;
    let knots = vec![
        -third,
        0.0,
        0.0,
        third,
        third,
        2.0 * third,
        2.0 * third,
        TAU,
        TAU,
        TAU + third,
    ];
    let control = (0..7)
        .map(|k| {
            let angle = k as f64 * TAU / 6.0;
            let r = if k % 2 == 0 { 2.0 } else { 4.0 };
            Point3::new([1e3 + r * angle.cos(), -5.0, 3.0 + r * angle.sin()])
        })
        .collect();
    let weights = (0..7).map(|k| if k % 2 == 0 { 1.0 } else { 0.5 }).collect();
    NurbsCurve::new(2, knots, control, weights)
        .unwrap()
        .with_closed(true)
}

#[test]
fn points_on_rational_circles_get_the_global_searchs_parameters() {
    for c in [clamped_circle(), periodic_circle()] {
        let d = c.domain();
        assert!(c.is_closed());
        let projector = CurveProjector::new(&c, 0.0).unwrap();
        for k in 0..=500 {
            let t = d.start + d.length() * (k as f64 / 500.0);
            let q = c.eval(t);
            let found = parameter_on_curve(&c, q, 1e-9).unwrap();
            let global = projector.nearest(q).t;
            assert!(c.eval(found).distance(q) < 1e-12, "t {t}: {found}");
            assert!(
                d.start <= found && found < d.end,
                "{found} outside [start, end)"
            );
            // The seam's two parameters are one point: the search may take either.
            let apart = (found - global).abs();
            assert!(
                apart < 1e-12 || (apart - d.length()).abs() < 1e-12,
                "t {t}: {found} against {global}"
            );
        }
    }
}

#[test]
fn a_point_off_the_curve_is_left_to_the_global_search() {
    let c = periodic_circle();
    let beside = |dx: f64| Point3::new([1002.0 + dx, -5.0, 3.0]);
    assert_eq!(parameter_on_curve(&c, beside(1e-6), 1e-9), None);
    assert!(parameter_on_curve(&c, beside(1e-10), 1e-9).is_some());
    // The centre: every point of the circle is as near, none within the tolerance.
    assert_eq!(
        parameter_on_curve(&c, Point3::new([1e3, -5.0, 3.0]), 1e-9),
        None
    );
    assert_eq!(
        parameter_on_curve(&c, Point3::new([f64::NAN, 0.0, 0.0]), 1e-9),
        None
    );
}

#[test]
fn a_curve_that_comes_back_near_the_point_keeps_the_foot_on_it() {
    // A narrow hairpin: the point on one branch is 1e-3 from the other, closer than the
    // sample spacing along the curve; the foot found is on the point's own branch.
    let curve = karkas::bspline::BSplineCurve::new(
        2,
        vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        vec![Point([0.0, 0.0]), Point([2.0, 1e-3]), Point([0.0, 2e-3])],
    )
    .unwrap();
    let mut answered = 0;
    for k in 0..=100 {
        let t = k as f64 / 100.0;
        let q = curve.eval(t);
        // Where the nearest sample is on the other branch, no answer (the global search
        // then runs); an answer is always on the point's own branch.
        if let Some(found) = parameter_on_curve(&curve, q, 1e-12) {
            assert!(curve.eval(found).distance(q) <= 1e-12, "t {t}: {found}");
            assert!((found - t).abs() < 1e-9, "t {t}: {found}");
            answered += 1;
        }
    }
    assert!(answered > 50, "{answered} of 101 answered");
}

//! The shared-end rule (`karkas::core::SHARED_END_TOLERANCE`: first and last points within
//! `1e-6` of the diagonal of the points' bounding box are one point) holds for every curve
//! method alike: the fit in its three modes, the interpolating spline and the LL curve
//! (approximating, interpolating and within a distance). A cambered NACA section with its two
//! trailing-edge points moved apart across the edge by 0.99e-6 of the diagonal closes
//! exactly in every method; by 1.01e-6 it stays open in every method. Swept over scales and
//! offsets from the origin (the rule is relative).

use crate::fit_reference::naca;
use karkas::core::{shared_end, SHARED_END_TOLERANCE};
use karkas::fit::{fit_curve, fit_curve_adaptive, uniform_knots, FitOptions};
use karkas::ll::LlCurve;
use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use karkas::{Curve, Point, Point2};
use std::f64::consts::PI;

/// 81 points of NACA 2412 (cosine spacing), scaled by `scale` and moved by `offset`, the two
/// trailing-edge points pushed apart across the edge (in y) so that they lie `share` of the
/// bounding-box diagonal apart.
fn foil(share: f64, scale: f64, offset: Point2) -> Vec<Point2> {
    let n = 81;
    let mut pts: Vec<Point2> = (0..n)
        .map(|k| naca(0.02, 0.4, 0.12, 2.0 * PI * k as f64 / (n - 1) as f64) * scale + offset)
        .collect();
    // The formula's two trailing-edge points differ by rounding (1e-17): one point.
    let edge = pts[0].lerp(pts[n - 1], 0.5);
    let (first, last) = (edge, edge);
    let diagonal = |p: &[Point2]| {
        let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
        for q in p {
            for c in 0..2 {
                lo[c] = lo[c].min(q[c]);
                hi[c] = hi[c].max(q[c]);
            }
        }
        ((hi[0] - lo[0]).powi(2) + (hi[1] - lo[1]).powi(2)).sqrt()
    };
    let half = 0.5 * share * diagonal(&pts);
    pts[0] = first + Point([0.0, half]);
    pts[n - 1] = last - Point([0.0, half]);
    let gap = pts[0].distance(pts[n - 1]) / diagonal(&pts);
    assert!(
        (gap / share - 1.0).abs() < 1e-6,
        "gap {gap:e} for {share:e}"
    );
    pts
}

/// The distance between the curve's two ends, as a share of `size`.
fn end_gap<C: Curve<2>>(curve: &C, size: f64) -> f64 {
    let d = curve.domain();
    curve.eval(d.start).distance(curve.eval(d.end)) / size
}

/// Every method's end gap (name, share of the scale) on `points`.
fn gaps(points: &[Point2], scale: f64) -> Vec<(&'static str, f64)> {
    let options = FitOptions::default();
    let knots = uniform_knots(12);
    let fit = fit_curve(points, &knots, &options).unwrap().spline;
    let adaptive = fit_curve_adaptive(points, 1e-4 * scale, &options).unwrap();
    let spline = CubicSpline::through(
        points,
        CurveParameterization::ChordLength,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    let natural = CubicSpline::through(
        points,
        CurveParameterization::Centripetal,
        SplineEnds::Natural,
    )
    .unwrap();
    let ll = LlCurve::new(points, 5, false).unwrap();
    let ll_interp = LlCurve::interpolating(points, 5, false).unwrap();
    let ll_within = LlCurve::within(points, 5, false, 1e-4 * scale)
        .unwrap()
        .shape;
    vec![
        ("fit on given knots", end_gap(&fit, scale)),
        ("fit to a tolerance", end_gap(&adaptive.fit.spline, scale)),
        ("spline (not-a-knot)", end_gap(&spline, scale)),
        ("spline (natural)", end_gap(&natural, scale)),
        ("LL", end_gap(&ll, scale)),
        ("LL interpolating", end_gap(&ll_interp, scale)),
        ("LL within", end_gap(&ll_within, scale)),
    ]
}

#[test]
fn ends_just_inside_the_rule_meet_in_every_method_and_just_outside_stay_apart() {
    for (scale, offset) in [
        (1.0, Point([0.0, 0.0])),
        (250.0, Point([-4000.0, 1200.0])),
        (1e-3, Point([0.5, -0.25])),
    ] {
        let inside = foil(0.99 * SHARED_END_TOLERANCE, scale, offset);
        assert!(shared_end(&inside).is_some());
        for (method, gap) in gaps(&inside, scale) {
            assert!(
                gap < 1e-12,
                "{method} at scale {scale}: ends {gap:e} apart, not closed"
            );
        }
        let outside = foil(1.01 * SHARED_END_TOLERANCE, scale, offset);
        assert!(shared_end(&outside).is_none());
        for (method, gap) in gaps(&outside, scale) {
            // The interpolants keep their end points; the fit's free ends land near them.
            assert!(
                gap > 1e-7,
                "{method} at scale {scale}: ends {gap:e} apart, closed"
            );
        }
    }
}

//! The shape guards of a fit (docs/methods.md §4): crossings of the fitted curve where the
//! points do not cross, turning beyond the point polygon's, sparse pieces and empty knot spans.
//! Splines that loop or hook are built directly (a cubic piece with a known loop) and checked
//! against crossings and turning found here by brute force; fits of clean contours (NACA 2412,
//! a closed circle), of points that cross themselves (a nodal cubic, Pavlov's hydrofoil) must
//! raise no crossing or turning warning.

use crate::common::hydrofoil;
use crate::fit_reference::naca;
use karkas::fit::{
    estimate_noise, fit_curve, shape_warnings, uniform_knots, CurveFit, FitOptions, FitWarning,
    FitWarningKind, HermiteSpline,
};
use karkas::{Curve, Point2};
use std::f64::consts::PI;

/// A fit result around a given spline, with the given foot parameters.
fn fit_around(spline: HermiteSpline<2>, points: &[Point2], parameters: Vec<f64>) -> CurveFit<2> {
    let distances: Vec<f64> = points
        .iter()
        .zip(&parameters)
        .map(|(p, &t)| spline.eval(t).distance(*p))
        .collect();
    CurveFit {
        data_term: distances.iter().map(|d| d * d).sum(),
        distances,
        parameters,
        jump_sum: 0.0,
        penalty: 0.0,
        seed_bound: 0.0,
        weights: vec![0.0; spline.knots().len()],
        bending_weight: 0.0,
        bending_energy: 0.0,
        bending_shares: vec![1.0; spline.pieces()],
        iterations: 0,
        noise: estimate_noise(points),
        warnings: Vec::new(),
        spline,
    }
}

fn of_kind(warnings: &[FitWarning], kind: FitWarningKind) -> Vec<&FitWarning> {
    warnings.iter().filter(|w| w.kind == kind).collect()
}

/// The proper crossings of a polyline, by testing every pair of segments: (point, i, j).
fn brute_crossings(line: &[Point2]) -> Vec<(Point2, usize, usize)> {
    let orient = |o: Point2, p: Point2, q: Point2| {
        (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
    };
    let mut out = Vec::new();
    for i in 0..line.len() - 1 {
        for j in i + 2..line.len() - 1 {
            let (a, b, c, d) = (line[i], line[i + 1], line[j], line[j + 1]);
            let (o1, o2) = (orient(a, b, c), orient(a, b, d));
            let (o3, o4) = (orient(c, d, a), orient(c, d, b));
            if o1 * o2 < 0.0 && o3 * o4 < 0.0 {
                out.push((a.lerp(b, o3 / (o3 - o4)), i, j));
            }
        }
    }
    out
}

/// The absolute turning of a curve's tangent over `[a, b]`, from the unwrapped angle of the
/// derivative at `samples + 1` points.
fn brute_turning<C: Curve<2>>(curve: &C, a: f64, b: f64, samples: usize) -> f64 {
    let mut total = 0.0;
    let mut last: Option<f64> = None;
    for k in 0..=samples {
        let d = curve.deriv(a + (b - a) * k as f64 / samples as f64, 1);
        let angle = d[1].atan2(d[0]);
        if let Some(previous) = last {
            let mut step = angle - previous;
            step -= (step / (2.0 * PI)).round() * 2.0 * PI;
            total += step.abs();
        }
        last = Some(angle);
    }
    total
}

/// The cubic Bezier (0,0), (2,1), (-1,1), (1,0) (which loops) as one Hermite piece.
fn looped_piece() -> HermiteSpline<2> {
    HermiteSpline::new(
        vec![0.0, 1.0],
        vec![Point2::new([0.0, 0.0]), Point2::new([1.0, 0.0])],
        vec![Point2::new([6.0, 3.0]), Point2::new([6.0, -3.0])],
    )
    .unwrap()
}

/// Points along the chord of the looped piece, at uniform parameters.
fn chord_points(n: usize) -> (Vec<Point2>, Vec<f64>) {
    let ts: Vec<f64> = (0..n).map(|k| k as f64 / (n - 1) as f64).collect();
    (ts.iter().map(|&t| Point2::new([t, 0.0])).collect(), ts)
}

#[test]
fn a_loop_where_the_points_run_straight_is_a_crossing_and_excess_turning() {
    let spline = looped_piece();
    let truth: Vec<Point2> = (0..=4000).map(|k| spline.eval(k as f64 / 4000.0)).collect();
    let found = brute_crossings(&truth);
    assert_eq!(found.len(), 1, "the piece loops once: {found:?}");
    let (point, i, j) = found[0];
    let (ta, tb) = (i as f64 / 4000.0, j as f64 / 4000.0);
    let (points, params) = chord_points(11);
    let warnings = shape_warnings(&points, &fit_around(spline.clone(), &points, params));
    let crossings = of_kind(&warnings, FitWarningKind::SelfIntersection);
    assert_eq!(crossings.len(), 1, "{warnings:#?}");
    let w = crossings[0];
    assert!(
        (w.parameter - ta).abs() < 5e-4,
        "t = {} vs {ta}",
        w.parameter
    );
    let at = spline.eval(w.parameter);
    assert!(at.distance(point) < 1e-4, "{at:?} vs {point:?}");
    assert!(
        w.message.contains(&format!("t = {:.2}", ta)[..6]),
        "{}",
        w.message
    );
    assert!(
        w.message.contains(&format!("{:.2}", tb)[..3]),
        "{}",
        w.message
    );
    // The loop turns the tangent by more than 2 pi - the start and end angles; the chord
    // not at all.
    let turning = brute_turning(&spline, 0.0, 1.0, 100_000);
    assert!(turning > 4.0, "{turning}");
    let turns = of_kind(&warnings, FitWarningKind::ExcessTurning);
    assert!(!turns.is_empty(), "{warnings:#?}");
    assert!(
        turns
            .iter()
            .any(|w| w.message.contains(&format!("{:.2}", turning)[..3])),
        "{turning}: {turns:#?}"
    );
}

#[test]
fn a_hook_past_the_first_point_is_excess_turning_there() {
    // Points along the x-axis from (1, 0) back to (0, 0), like the upper surface from a
    // trailing edge; the curve leaves (1, 0) outwards, turns around and comes back: a hook of
    // about pi past the first point.
    let spline = HermiteSpline::new(
        vec![0.0, 0.5, 1.0],
        vec![
            Point2::new([1.0, 0.0]),
            Point2::new([0.5, 0.0]),
            Point2::new([0.0, 0.0]),
        ],
        vec![
            Point2::new([1.0, 0.2]),
            Point2::new([-1.0, 0.0]),
            Point2::new([-1.0, 0.0]),
        ],
    )
    .unwrap();
    let hook = brute_turning(&spline, 0.0, 0.5, 100_000);
    assert!(hook > 2.5, "{hook}");
    let params: Vec<f64> = (0..=10).map(|k| k as f64 / 10.0).collect();
    let points: Vec<Point2> = params
        .iter()
        .map(|&t| Point2::new([1.0 - t, 0.0]))
        .collect();
    let warnings = shape_warnings(&points, &fit_around(spline, &points, params));
    let turns = of_kind(&warnings, FitWarningKind::ExcessTurning);
    assert!(!turns.is_empty(), "{warnings:#?}");
    assert!(turns.iter().all(|w| w.parameter < 0.5), "{turns:#?}");
    assert!(
        turns
            .iter()
            .any(|w| w.message.contains(&format!("{:.2}", hook)[..3])),
        "{hook}: {turns:#?}"
    );
}

#[test]
fn a_polygon_that_turns_back_itself_excuses_the_turn_of_the_curve() {
    // A hairpin: the points go out along y = 0 and back along y = 0.2; the curve turns
    // about pi around the bend, as the polygon does.
    let mut points: Vec<Point2> = (0..=10)
        .map(|k| Point2::new([k as f64 * 0.1, 0.0]))
        .collect();
    points.extend((0..=10).map(|k| Point2::new([1.0 - k as f64 * 0.1, 0.2])));
    let fit = fit_curve(&points, &uniform_knots(8), &FitOptions::default()).unwrap();
    no_shape_warnings(&fit.warnings, "hairpin");
}

fn no_shape_warnings(warnings: &[FitWarning], what: &str) {
    let shape: Vec<_> = warnings
        .iter()
        .filter(|w| {
            matches!(
                w.kind,
                FitWarningKind::SelfIntersection | FitWarningKind::ExcessTurning
            )
        })
        .collect();
    assert!(shape.is_empty(), "{what}: {shape:#?}");
}

#[test]
fn a_clean_naca_fit_with_closed_trailing_edge_raises_no_shape_warning() {
    let points: Vec<Point2> = (0..200)
        .map(|k| naca(0.02, 0.4, 0.12, 2.0 * PI * k as f64 / 199.0))
        .collect();
    assert!(points[0].distance(points[199]) < 1e-12);
    let options = FitOptions {
        eps: 1e-3,
        ends: karkas::fit::FitEnds::Pinned,
        ..Default::default()
    };
    for knots in [9, 17, 33] {
        let fit = fit_curve(&points, &uniform_knots(knots), &options).unwrap();
        assert!(fit.max_distance() < 1e-2);
        // The ends meet: that is no crossing.
        no_shape_warnings(&fit.warnings, &format!("{knots} knots"));
        assert!(
            fit.warnings.is_empty(),
            "{knots} knots: {:#?}",
            fit.warnings
        );
        assert_eq!(fit.warnings, shape_warnings(&points, &fit));
    }
}

#[test]
fn a_closed_circle_whose_ends_coincide_raises_no_shape_warning() {
    let points: Vec<Point2> = (0..=60)
        .map(|k| {
            let a = 2.0 * PI * k as f64 / 60.0;
            Point2::new([a.cos(), a.sin()])
        })
        .collect();
    for ends in [
        karkas::fit::FitEnds::Free,
        karkas::fit::FitEnds::Auto,
        karkas::fit::FitEnds::Pinned,
    ] {
        let options = FitOptions {
            ends,
            ..Default::default()
        };
        let fit = fit_curve(&points, &uniform_knots(9), &options).unwrap();
        let shape = shape_warnings(&points, &fit);
        no_shape_warnings(&shape, &format!("ends {ends:?}"));
        // The ends coincide (to 1e-15 here): the default closes the circle at their common
        // point; Pinned pins each end to its own point.
        let values = fit.spline.values();
        let (first, last) = (values[0], values[values.len() - 1]);
        match ends {
            karkas::fit::FitEnds::Auto => {
                assert!(first.distance(points[0]) < 1e-15);
                assert_eq!(first, last);
            }
            karkas::fit::FitEnds::Pinned => {
                assert_eq!(first, points[0]);
                assert_eq!(last, points[points.len() - 1]);
            }
            _ => {}
        }
    }
}

#[test]
fn points_that_cross_themselves_excuse_the_crossing_of_their_fit() {
    // The nodal cubic (t^2 - 1, t^3 - t) crosses itself at the origin (t = -1 and t = 1).
    let points: Vec<Point2> = (0..=80)
        .map(|k| {
            let t = -1.55 + 3.1 * k as f64 / 80.0;
            Point2::new([t * t - 1.0, t * t * t - t])
        })
        .collect();
    assert_eq!(brute_crossings(&points).len(), 1);
    let fit = fit_curve(&points, &uniform_knots(9), &FitOptions::default()).unwrap();
    assert!(fit.max_distance() < 1e-3, "{}", fit.max_distance());
    let samples: Vec<Point2> = (0..=4000)
        .map(|k| fit.spline.eval(k as f64 / 4000.0))
        .collect();
    let c = brute_crossings(&samples);
    assert_eq!(c.len(), 1, "the fit crosses too");
    no_shape_warnings(&fit.warnings, "nodal cubic");
}

#[test]
fn the_hydrofoil_whose_points_cross_raises_no_crossing_where_they_do() {
    let points = hydrofoil();
    assert_eq!(points.len(), 20);
    let polygon = brute_crossings(&points);
    assert!(!polygon.is_empty(), "the printed points cross themselves");
    let options = FitOptions {
        eps: 0.01,
        ..Default::default()
    };
    let fit = fit_curve(&points, &[0.0, 0.445, 0.449, 0.587, 1.0], &options).unwrap();
    for w in of_kind(&fit.warnings, FitWarningKind::SelfIntersection) {
        let at = fit.spline.eval(w.parameter);
        let near = polygon
            .iter()
            .map(|c| c.0.distance(at))
            .fold(f64::INFINITY, f64::min);
        assert!(
            near > 20.0,
            "a crossing warned where the points cross: {w:?}"
        );
    }
}

#[test]
fn sparse_pieces_and_empty_spans_are_named() {
    // A straight spline on 4 pieces; points on the first and the last piece only.
    let spline = HermiteSpline::new(
        uniform_knots(5),
        (0..5)
            .map(|k| Point2::new([k as f64 * 0.25, 0.0]))
            .collect(),
        vec![Point2::new([1.0, 0.0]); 5],
    )
    .unwrap();
    let params = vec![0.0, 0.1, 0.2, 0.8, 0.9, 1.0];
    let points: Vec<Point2> = params.iter().map(|&t| Point2::new([t, 0.0])).collect();
    let warnings = shape_warnings(&points, &fit_around(spline, &points, params));
    let empty = of_kind(&warnings, FitWarningKind::EmptySpan);
    assert_eq!(empty.len(), 1, "{warnings:#?}");
    assert!((empty[0].parameter - 0.5).abs() < 1e-12);
    assert!(
        empty[0].message.contains("spans 2 to 3"),
        "{}",
        empty[0].message
    );
    let sparse = of_kind(&warnings, FitWarningKind::SparsePieces);
    assert_eq!(sparse.len(), 1, "{warnings:#?}");
    assert!((sparse[0].parameter - 0.5).abs() < 1e-12);
    assert!(
        sparse[0].message.contains("knot 3"),
        "{}",
        sparse[0].message
    );
    assert!(
        sparse[0].message.contains("0 points"),
        "{}",
        sparse[0].message
    );
    assert_eq!(warnings.len(), 2, "{warnings:#?}");
}

#[test]
fn a_fit_on_knots_with_an_empty_span_warns() {
    // 30 points on a parabola; the knots 0.50 and 0.51 leave no point between them.
    let points: Vec<Point2> = (0..30)
        .map(|k| {
            let x = if k < 15 {
                k as f64 / 30.0
            } else {
                (k as f64 + 1.0) / 31.0
            };
            Point2::new([x, x * x])
        })
        .collect();
    let mut params: Vec<f64> = Vec::new();
    let fit = fit_curve(
        &points,
        &[0.0, 0.25, 0.5, 0.5001, 0.75, 1.0],
        &FitOptions::default(),
    )
    .unwrap();
    params.extend(&fit.parameters);
    let inside = params
        .iter()
        .filter(|&&t| (0.5..0.5001).contains(&t))
        .count();
    let empty = of_kind(&fit.warnings, FitWarningKind::EmptySpan);
    assert_eq!(
        inside == 0,
        !empty.is_empty(),
        "{inside} points inside: {:#?}",
        fit.warnings
    );
    assert!(!empty.is_empty(), "{:#?}", fit.warnings);
    assert!(empty.iter().any(|w| (w.parameter - 0.50005).abs() < 1e-9));
}

#[test]
fn a_bow_tie_crosses_once_in_its_middle() {
    use karkas::fit::polyline_crossings;
    let p = |x: f64, y: f64| Point2::new([x, y]);
    let found = polyline_crossings(&[p(0.0, 0.0), p(2.0, 2.0), p(2.0, 0.0), p(0.0, 2.0)]);
    assert_eq!(found.len(), 1);
    assert_eq!((found[0].first, found[0].second), (0, 2));
    assert!((found[0].at[0] - 1.0).abs() < 1e-15 && (found[0].at[1] - 1.0).abs() < 1e-15);
    assert!(polyline_crossings(&[p(0.0, 0.0), p(1.0, 0.0), p(1.0, 1.0), p(0.0, 1.0)]).is_empty());
}

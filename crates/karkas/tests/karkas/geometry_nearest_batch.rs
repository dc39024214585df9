//! Projection of large batches (which share certificates by grid cells) against the
//! one-point search and against brute force: open and closed cubic splines, a cusp, a thin
//! loop whose far side is near, LL curves of degree 6, a polyline with corners, a helix in
//! 3-D and scales from 1e-150 to 1e150.

use std::f64::consts::TAU;

use karkas::bspline::BSplineCurve;
use karkas::geometry::{CurveNearest, CurveProjector};
use karkas::ll::LlCurve;
use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use karkas::{Curve, Point, Point2};

use crate::common::nearest_by_sampling;

/// A deterministic sequence in [0, 1) (the golden-ratio additive recurrence).
fn unit(k: usize, shift: f64) -> f64 {
    (shift + k as f64 * 0.618_033_988_749_894_9).fract()
}

/// `n` queries: most within `band` of the curve on either side, the rest anywhere in the
/// curve's box grown by half its size, and one NaN.
fn queries<C: Curve<2>>(c: &C, n: usize, band: f64) -> Vec<Point2> {
    let d = c.domain();
    let samples: Vec<Point2> = (0..=256)
        .map(|k| c.eval(d.start + d.length() * k as f64 / 256.0))
        .collect();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in &samples {
        for k in 0..2 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let size = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let mut qs: Vec<Point2> = (0..n)
        .map(|k| {
            if k % 5 == 4 {
                Point2::new([
                    lo[0] - 0.5 * size + 2.0 * size * unit(k, 0.3),
                    lo[1] - 0.5 * size + 2.0 * size * unit(k, 0.7),
                ])
            } else {
                let t = d.start + d.length() * unit(k, 0.1);
                let (p, d1) = (c.eval(t), c.deriv(t, 1));
                let normal = Point2::new([-d1[1], d1[0]]) * (1.0 / d1.norm().max(1e-300));
                p + normal * (band * size * (2.0 * unit(k, 0.37) - 1.0))
            }
        })
        .collect();
    qs[n / 2] = Point2::new([f64::NAN, 0.0]);
    qs
}

/// The batch equals the one-point search at every query: the same distance to `1e-13` of
/// the curve's size (both are Newton's method to round-off on the same segment, or on two
/// segments meeting at the foot), feet on the curve at their parameters.
fn batch_agrees<C: Curve<D> + Sync + ?Sized, const D: usize>(
    c: &C,
    qs: &[Point<D>],
    size: f64,
) -> Vec<CurveNearest<D>> {
    let projector = CurveProjector::new(c, 0.0).unwrap();
    let batch = projector.nearest_all(qs);
    assert_eq!(batch.len(), qs.len());
    let d = c.domain();
    for (q, got) in qs.iter().zip(&batch) {
        let one = projector.nearest(*q);
        if !q.is_finite() {
            assert!(got.distance.is_nan() && got.t.is_nan());
            continue;
        }
        assert!(
            (got.distance - one.distance).abs() <= 1e-13 * size,
            "{q:?}: batch {} vs one {}",
            got.distance,
            one.distance
        );
        assert!(got.t >= d.start && got.t <= d.end, "{q:?}: t = {}", got.t);
        assert!(c.eval(got.t).distance(got.point) <= 1e-14 * size);
        assert!((got.point.distance(*q) - got.distance).abs() <= 1e-14 * size);
    }
    batch
}

/// Every 97th query of the batch is no farther than brute force finds (to `1e-12`).
fn not_beaten<C: Curve<2>>(c: &C, qs: &[Point2], batch: &[CurveNearest<2>], size: f64) {
    for (q, got) in qs.iter().zip(batch).step_by(97) {
        if q.is_finite() {
            let reference = nearest_by_sampling(c, *q, 20_000);
            assert!(
                got.distance <= reference + 1e-12 * size,
                "{q:?}: {} vs brute force {reference}",
                got.distance
            );
        }
    }
}

fn rose(n: usize, scale: f64) -> CubicSpline<2> {
    let pts: Vec<Point2> = (0..=n)
        .map(|k| {
            let th = TAU * (k % n) as f64 / n as f64;
            let r = 1.0 + 0.3 * (5.0 * th).cos();
            Point2::new([r * th.cos(), r * th.sin()]) * scale
        })
        .collect();
    CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::Periodic,
    )
    .unwrap()
}

#[test]
fn closed_and_open_splines_project_in_batches_as_one_by_one() {
    let closed = rose(200, 1.0);
    let qs = queries(&closed, 20_000, 0.05);
    let batch = batch_agrees(&closed, &qs, 1.3);
    not_beaten(&closed, &qs, &batch, 1.3);

    let pts: Vec<Point2> = (0..40)
        .map(|k| {
            let t = k as f64 / 39.0;
            Point2::new([3.0 * t, (9.0 * t).sin() * (1.0 - t)])
        })
        .collect();
    let open = CubicSpline::through(
        &pts,
        CurveParameterization::Centripetal,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    let qs = queries(&open, 20_000, 0.1);
    let batch = batch_agrees(&open, &qs, 3.0);
    not_beaten(&open, &qs, &batch, 3.0);
    // Points left of and below the start (where the curve leaves up and to the right)
    // project onto the start.
    let beyond: Vec<Point2> = (0..5000)
        .map(|k| Point2::new([-1.0 - unit(k, 0.2), -unit(k, 0.6)]))
        .collect();
    for got in batch_agrees(&open, &beyond, 3.0) {
        assert_eq!(got.t, open.domain().start);
    }
}

#[test]
fn a_cusp_and_a_thin_loop_project_in_batches_as_one_by_one() {
    let ts = [-1.0, -0.5, 0.0, 0.5, 1.0];
    let pts: Vec<Point2> = ts
        .iter()
        .map(|&t| Point2::new([t * t, t * t * t]))
        .collect();
    let cusp = CubicSpline::new(&ts, &pts, SplineEnds::NotAKnot).unwrap();
    let qs = queries(&cusp, 8192, 0.2);
    let batch = batch_agrees(&cusp, &qs, 1.0);
    not_beaten(&cusp, &qs, &batch, 1.0);

    let pts: Vec<Point2> = (0..60)
        .map(|k| {
            let th = TAU * k as f64 / 60.0;
            Point2::new([3.0 * th.cos(), 0.2 * th.sin() + 0.05 * (3.0 * th).sin()])
        })
        .collect();
    let thin = CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::Periodic,
    )
    .unwrap();
    let qs = queries(&thin, 20_000, 0.05);
    let batch = batch_agrees(&thin, &qs, 3.0);
    not_beaten(&thin, &qs, &batch, 3.0);
}

#[test]
fn ll_curves_and_polylines_project_in_batches_as_one_by_one() {
    let pts: Vec<Point2> = (0..30)
        .map(|k| {
            let th = TAU * k as f64 / 30.0;
            Point2::new([th.cos() + 0.3 * (2.0 * th).cos(), th.sin()])
        })
        .collect();
    for closed in [false, true] {
        let ll = LlCurve::new(&pts, 3, closed).unwrap();
        let qs = queries(&ll, 10_000, 0.1);
        let batch = batch_agrees(&ll, &qs, 2.6);
        not_beaten(&ll, &qs, &batch, 2.6);
    }
    // Degree 1: corners at every knot, where the distance's derivative jumps.
    let knots: Vec<f64> = [0.0, 0.0]
        .into_iter()
        .chain((1..12).map(|k| k as f64))
        .chain([12.0, 12.0])
        .collect();
    let polyline = BSplineCurve::new(1, knots, pts[..13].to_vec()).unwrap();
    let qs = queries(&polyline, 10_000, 0.1);
    let batch = batch_agrees(&polyline, &qs, 2.6);
    not_beaten(&polyline, &qs, &batch, 2.6);
}

#[test]
fn a_helix_projects_in_batches_as_one_by_one() {
    let pts: Vec<Point<3>> = (0..80)
        .map(|k| {
            let t = 4.0 * TAU * k as f64 / 79.0;
            Point([t.cos(), t.sin(), 0.1 * t])
        })
        .collect();
    let helix = CubicSpline::through(
        &pts,
        CurveParameterization::ChordLength,
        SplineEnds::NotAKnot,
    )
    .unwrap();
    let qs: Vec<Point<3>> = (0..10_000)
        .map(|k| {
            let t = helix.domain().length() * unit(k, 0.1);
            let p = helix.eval(t);
            let off = Point([unit(k, 0.2) - 0.5, unit(k, 0.5) - 0.5, unit(k, 0.8) - 0.5]);
            p + off * 0.6
        })
        .collect();
    batch_agrees(&helix, &qs, 2.6);
}

#[test]
fn batches_agree_at_extreme_scales() {
    for scale in [1e-150, 1e150] {
        let c = rose(100, scale);
        let qs = queries(&c, 8192, 0.05);
        let batch = batch_agrees(&c, &qs, 1.3 * scale);
        let unit_curve = rose(100, 1.0);
        let unit_qs: Vec<Point2> = qs.iter().map(|&q| q * (1.0 / scale)).collect();
        let unit_batch = CurveProjector::new(&unit_curve, 0.0)
            .unwrap()
            .nearest_all(&unit_qs);
        for (got, reference) in batch.iter().zip(&unit_batch) {
            if got.distance.is_finite() {
                assert!(
                    (got.distance / scale - reference.distance).abs() <= 1e-12,
                    "{} vs {}",
                    got.distance / scale,
                    reference.distance
                );
            }
        }
    }
}

//! LL approximation within a given distance of the points (docs/methods.md §1.2–1.3, system
//! (6) with targets near the points): every node within the distance, the plain
//! approximation when the distance allows it, the interpolating variant in the limit, and the
//! order and smoothness of every LL curve and surface.
//!
//! Node values are measured on the reference curve (surface) built from the definition over
//! the result's control points, and compared with the reference plain approximation.

use crate::common::{assert_near, max_abs, Rng};
use crate::ll_reference::{check_curve_borders, surface_grid, RefCurve, RefSurface};
use crate::ll_surface::check_surface_borders;
use karkas::ll::{LlCurve, LlSurface};
use karkas::{Curve, Error, Grid, Point, Surface};

/// A noisy open curve: a sine sampled at 25 points with noise of 0.05.
fn noisy_curve() -> Vec<Point<2>> {
    let mut rng = Rng::new(2000);
    (0..25)
        .map(|i| {
            let x = 0.25 * i as f64;
            Point([x + 0.02 * rng.signed(), x.sin() + 0.05 * rng.signed()])
        })
        .collect()
}

/// A noisy closed curve in space (no repeated point).
fn noisy_loop() -> Vec<Point<3>> {
    let mut rng = Rng::new(4);
    (0..20)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / 20.0;
            Point([
                2.0 * a.cos() + 0.05 * rng.signed(),
                a.sin() + 0.05 * rng.signed(),
                0.1 * rng.signed(),
            ])
        })
        .collect()
}

/// The node values `P_i(1/2)` of the reference LL curve over `control` (`r_1..r_K`).
fn reference_nodes<const D: usize>(control: &[Point<D>], l: usize, closed: bool) -> Vec<Point<D>> {
    let r = RefCurve::new(control, l, closed);
    (1..=r.k()).map(|i| r.seg(i, 0.5, 0)).collect()
}

/// Checks the curve `LlCurve::within(points, l, closed, d)` at every node against the
/// reference: within `d`; where the plain approximation is within `d`, its node value; else
/// at distance `d` on the segment from the point to the plain node value. Returns the
/// measured largest deviation.
fn check_curve_within<const D: usize>(points: &[Point<D>], l: usize, closed: bool, d: f64) -> f64 {
    let fit = LlCurve::within(points, l, closed, d).unwrap();
    let plain = reference_nodes(points, l, closed);
    let got = reference_nodes(fit.shape.control_points(), l, closed);
    let tol = 1e-12 * max_abs(points);
    let what = format!("L = {l}, closed {closed}, D = {d:e}");
    let mut largest = 0.0f64;
    let mut pulled = 0;
    for (i, r) in points.iter().enumerate() {
        let deviation = got[i].distance(*r);
        largest = largest.max(deviation);
        assert!(
            deviation <= d + tol,
            "{what}: node {} at {deviation:e}",
            i + 1
        );
        // The library's own evaluation at the node agrees with the reference.
        let t = fit.shape.axis().node(i + 1);
        assert_near(fit.shape.eval(t), got[i], tol, &what);
        let plain_deviation = plain[i].distance(*r);
        if plain_deviation <= d {
            assert_near(
                got[i],
                plain[i],
                tol,
                &format!("{what}: node {} kept", i + 1),
            );
        } else {
            pulled += 1;
            let want = *r + (plain[i] - *r) * (d / plain_deviation);
            assert_near(got[i], want, tol, &format!("{what}: node {} pulled", i + 1));
        }
    }
    assert_eq!(fit.pulled_nodes, pulled, "{what}");
    assert_eq!(fit.nodes, points.len(), "{what}");
    assert!((fit.largest_deviation - largest).abs() <= tol, "{what}");
    let plain_largest = points
        .iter()
        .zip(&plain)
        .map(|(r, p)| r.distance(*p))
        .fold(0.0, f64::max);
    assert!((fit.plain_deviation - plain_largest).abs() <= tol, "{what}");
    largest
}

/// The largest node deviation of the reference plain approximation.
fn plain_deviation<const D: usize>(points: &[Point<D>], l: usize, closed: bool) -> f64 {
    let nodes = reference_nodes(points, l, closed);
    points
        .iter()
        .zip(&nodes)
        .map(|(r, p)| r.distance(*p))
        .fold(0.0, f64::max)
}

const FRACTIONS: [f64; 6] = [0.99, 0.7, 0.4, 0.15, 0.03, 1e-3];

#[test]
fn curve_passes_every_node_within_the_distance() {
    let open = noisy_curve();
    let closed = noisy_loop();
    for l in [1, 2, 3, 5, 8] {
        let top = plain_deviation(&open, l, false);
        assert!(top > 0.01, "the noisy data should bend: {top}");
        for f in FRACTIONS {
            let largest = check_curve_within(&open, l, false, f * top);
            // The distance is reached (the target is on the ball's surface), not undershot.
            assert!(largest >= f * top * (1.0 - 1e-9), "L = {l}, f = {f}");
        }
        let top = plain_deviation(&closed, l, true);
        for f in FRACTIONS {
            check_curve_within(&closed, l, true, f * top);
        }
    }
}

#[test]
fn distance_above_the_plain_deviation_gives_the_plain_approximation() {
    let open = noisy_curve();
    let closed = noisy_loop();
    for l in [1, 3, 6] {
        for factor in [1.0 + 1e-9, 2.0, 1e6] {
            let d = factor * plain_deviation(&open, l, false);
            let fit = LlCurve::within(&open, l, false, d).unwrap();
            assert_eq!(fit.pulled_nodes, 0);
            assert_eq!(fit.shape, LlCurve::new(&open, l, false).unwrap());
            assert_eq!(fit.largest_deviation, fit.plain_deviation);
            let d = factor * plain_deviation(&closed, l, true);
            let fit = LlCurve::within(&closed, l, true, d).unwrap();
            assert_eq!(fit.shape, LlCurve::new(&closed, l, true).unwrap());
        }
    }
    // Just under it, the farthest node is pulled in and the curve changes.
    let d = 0.999 * plain_deviation(&open, 3, false);
    let fit = LlCurve::within(&open, 3, false, d).unwrap();
    assert!(fit.pulled_nodes >= 1);
    assert_ne!(fit.shape, LlCurve::new(&open, 3, false).unwrap());
}

#[test]
fn tiny_distance_approaches_the_interpolating_curve() {
    for closed in [false, true] {
        let pts: Vec<Point<2>> = if closed {
            noisy_loop().iter().map(|p| Point([p[0], p[1]])).collect()
        } else {
            noisy_curve()
        };
        for l in [1, 3, 7] {
            let interp = LlCurve::interpolating(&pts, l, closed).unwrap();
            let top = plain_deviation(&pts, l, closed);
            let mut previous = f64::INFINITY;
            for d in [1e-2, 1e-4, 1e-6, 1e-9].map(|f| f * top) {
                let fit = LlCurve::within(&pts, l, closed, d).unwrap();
                let gap = fit
                    .shape
                    .control_points()
                    .iter()
                    .zip(interp.control_points())
                    .map(|(a, b)| a.distance(*b))
                    .fold(0.0, f64::max);
                // System (6) has inverse norm at most 1/(1 - 4 d_L) <= 2: the controls move
                // at most twice as far as the targets, which are within d of the points.
                assert!(
                    gap <= 2.0 * d * (1.0 + 1e-9) + 1e-13,
                    "L {l}: {gap:e} at D = {d:e}"
                );
                assert!(
                    gap < previous,
                    "L {l}: should approach, {gap:e} at D = {d:e}"
                );
                previous = gap;
            }
        }
    }
}

#[test]
fn within_keeps_the_order_degree_and_smoothness() {
    let pts = noisy_curve();
    for l in [1, 2, 4, 7] {
        let d = 0.2 * plain_deviation(&pts, l, false);
        let fit = LlCurve::within(&pts, l, false, d).unwrap();
        assert_eq!(fit.shape.order(), l);
        let pieces = fit.shape.polynomial_pieces().unwrap();
        assert_eq!(pieces.degree, 2 * l);
        let r = RefCurve::new(fit.shape.control_points(), l, false);
        check_curve_borders(&fit.shape, &r, &format!("within, L = {l}"));
    }
}

#[test]
fn monotone_data_may_lose_monotonicity_once_nodes_are_pulled_in() {
    // A monotone step: the plain approximation is monotone (methods.md §1.2); the paper warns
    // that curves built on the solution of (6) need not be, and this one overshoots.
    let pts: Vec<Point<2>> = [0.0, 0.0, 0.0, 1.0, 1.0, 1.0]
        .iter()
        .enumerate()
        .map(|(i, &y)| Point([i as f64, y]))
        .collect();
    let l = 2;
    let ts: Vec<f64> = {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let dom = c.domain();
        (0..=2000)
            .map(|k| dom.start + dom.length() * k as f64 / 2000.0)
            .collect()
    };
    let y_range = |c: &LlCurve<2>| {
        ts.iter()
            .map(|&t| c.eval(t)[1])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), y| {
                (lo.min(y), hi.max(y))
            })
    };
    let top = plain_deviation(&pts, l, false);
    let plain = LlCurve::within(&pts, l, false, top * 1.01).unwrap();
    let (lo, hi) = y_range(&plain.shape);
    assert!(lo >= -1e-15 && hi <= 1.0 + 1e-15, "plain: {lo} {hi}");
    let near = LlCurve::within(&pts, l, false, 0.01 * top).unwrap();
    let (lo, hi) = y_range(&near.shape);
    assert!(lo < -1e-3 && hi > 1.0 + 1e-3, "pulled in: {lo} {hi}");
}

#[test]
fn distance_must_be_positive_and_finite() {
    let pts = noisy_curve();
    let grid = surface_grid(4, 5, false, false);
    for d in [0.0, -0.1, f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        let e = LlCurve::within(&pts, 3, false, d).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidSetting {
                    name: "distance",
                    ..
                }
            ),
            "{d}: {e}"
        );
        let e = LlSurface::within(&grid, 3, false, false, d).unwrap_err();
        assert!(
            matches!(
                e,
                Error::InvalidSetting {
                    name: "distance",
                    ..
                }
            ),
            "{d}: {e}"
        );
    }
    // The usual input errors come first.
    assert!(matches!(
        LlCurve::within(&pts[..2], 3, false, 0.1),
        Err(Error::TooFewPoints { .. })
    ));
    assert!(matches!(
        LlCurve::within(&pts, 0, false, 0.1),
        Err(Error::InvalidOrder { .. })
    ));
}

// ------------------------------------------------------------------------------------------
// Surfaces
// ------------------------------------------------------------------------------------------

/// A noisy bent sheet, or a noisy tube closed in `u`.
fn noisy_grid(closed_u: bool) -> Grid<Point<3>> {
    let mut rng = Rng::new(if closed_u { 77 } else { 31 });
    let base = surface_grid(7, 6, closed_u, false);
    Grid::from_fn(7, 6, |i, j| *base.get(i, j) + rng.point::<3>() * 0.04)
}

/// The node values of the reference surface over the control grid of `s`.
fn surface_nodes(s: &LlSurface<3>, rows: usize, cols: usize, closed_u: bool) -> Grid<Point<3>> {
    let control = Grid::from_fn(rows + closed_u as usize, cols, |i, j| s.control_point(i, j));
    let r = RefSurface::new(&control, s.order(), closed_u, false);
    Grid::from_fn(rows, cols, |i, j| r.cell((i + 1, 0.5), (j + 1, 0.5), 0, 0))
}

#[test]
fn surface_passes_every_node_within_the_distance() {
    for closed_u in [false, true] {
        let g = noisy_grid(closed_u);
        let (rows, cols) = (g.rows(), g.cols());
        let tol = 1e-12 * max_abs(g.as_slice());
        for l in [1, 3, 6] {
            let plain = LlSurface::new(&g, l, closed_u, false).unwrap();
            let plain_nodes = surface_nodes(&plain, rows, cols, closed_u);
            let deviation =
                |n: &Grid<Point<3>>, i: usize, j: usize| n.get(i, j).distance(*g.get(i, j));
            let top = (0..rows * cols)
                .map(|k| deviation(&plain_nodes, k / cols, k % cols))
                .fold(0.0, f64::max);
            assert!(top > 0.01, "the noisy grid should bend: {top}");
            for f in FRACTIONS {
                let d = f * top;
                let what = format!("closed_u {closed_u}, L = {l}, D = {d:e}");
                let fit = LlSurface::within(&g, l, closed_u, false, d).unwrap();
                assert_eq!(fit.shape.order(), l);
                assert_eq!(fit.nodes, rows * cols);
                assert!((fit.plain_deviation - top).abs() <= tol, "{what}");
                let nodes = surface_nodes(&fit.shape, rows, cols, closed_u);
                let (au, av) = (fit.shape.axis_u(), fit.shape.axis_v());
                let mut largest = 0.0f64;
                let mut pulled = 0;
                for i in 0..rows {
                    for j in 0..cols {
                        let got = *nodes.get(i, j);
                        let dev = deviation(&nodes, i, j);
                        largest = largest.max(dev);
                        assert!(dev <= d + tol, "{what}: node ({i},{j}) at {dev:e}");
                        let at = fit.shape.eval(au.node(i + 1), av.node(j + 1));
                        assert_near(at, got, tol, &what);
                        let plain_dev = deviation(&plain_nodes, i, j);
                        if plain_dev <= d {
                            assert_near(got, *plain_nodes.get(i, j), tol, &what);
                        } else {
                            pulled += 1;
                            let r = *g.get(i, j);
                            let want = r + (*plain_nodes.get(i, j) - r) * (d / plain_dev);
                            assert_near(got, want, tol, &what);
                        }
                    }
                }
                assert_eq!(fit.pulled_nodes, pulled, "{what}");
                assert!((fit.largest_deviation - largest).abs() <= tol, "{what}");
                assert!(largest >= d * (1.0 - 1e-9), "{what}: {largest:e}");
            }
            // Above the plain deviation: the plain surface itself.
            let fit = LlSurface::within(&g, l, closed_u, false, top * (1.0 + 1e-9)).unwrap();
            assert_eq!(fit.pulled_nodes, 0);
            assert_eq!(fit.shape, plain);
        }
    }
}

#[test]
fn surface_tiny_distance_approaches_the_interpolating_surface_and_stays_c_l() {
    let g = noisy_grid(false);
    for l in [1, 2, 4] {
        let interp = LlSurface::interpolating(&g, l, false, false).unwrap();
        let fit = LlSurface::within(&g, l, false, false, 1e-9).unwrap();
        for i in 0..g.rows() {
            for j in 0..g.cols() {
                // The separable inverse has norm at most 4: controls within 4 D.
                let gap = fit
                    .shape
                    .control_point(i, j)
                    .distance(interp.control_point(i, j));
                assert!(gap <= 4e-9 * (1.0 + 1e-6), "L {l}: ({i},{j}) {gap:e}");
            }
        }
        let mid = LlSurface::within(&g, l, false, false, 0.01).unwrap();
        assert!(mid.pulled_nodes > 0);
        let control = Grid::from_fn(g.rows(), g.cols(), |i, j| mid.shape.control_point(i, j));
        let r = RefSurface::new(&control, l, false, false);
        check_surface_borders(&mid.shape, &r, &format!("within, L = {l}"));
    }
}

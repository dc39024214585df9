//! Exact B-spline conversion: every converted type evaluates to the same points (and
//! derivatives) as the original, to 1e-12 relative to the data's size.

use karkas::bspline::{BSplineCurve, BSplineSurface, ToBSplineCurve, ToBSplineSurface};
use karkas::coons::{CoonsSurface, CurveFit, PointNetwork, SplineEnds as CoonsEnds};
use karkas::fit::HermiteSpline;
use karkas::ll::{LlCurve, LlKernel, LlSurface};
use karkas::param::{BicubicSurface, CubicSpline, SplineEnds};
use karkas::{Curve, Error, Grid, Point, Point3, Surface};
use proptest::prelude::*;

use crate::common::linspace;

/// The largest coordinate magnitude of `points` (at least 1e-300).
fn size<const D: usize>(points: &[Point<D>]) -> f64 {
    points.iter().map(|p| p.norm()).fold(1e-300, f64::max)
}

/// Parameters strictly inside the pieces of `breaks` (derivatives may jump at breaks).
fn inner_params(breaks: &[f64], per_piece: usize) -> Vec<f64> {
    breaks
        .windows(2)
        .flat_map(|w| {
            (1..=per_piece).map(move |k| w[0] + (w[1] - w[0]) * k as f64 / (per_piece + 1) as f64)
        })
        .collect()
}

fn distinct(knots: &[f64]) -> Vec<f64> {
    let mut d = knots.to_vec();
    d.dedup();
    d
}

/// Compares a curve with its B-spline: values everywhere, derivatives `1..=max_k` inside
/// the pieces, each scaled by `size * rate^k`.
fn compare_curves<const D: usize>(
    original: &dyn Curve<D>,
    bspline: &BSplineCurve<D>,
    data_size: f64,
    rate: f64,
    max_k: usize,
) {
    let d = original.domain();
    assert!((bspline.domain().start - d.start).abs() <= 1e-15 * d.length().max(1.0));
    assert!((bspline.domain().end - d.end).abs() <= 1e-15 * d.length().max(1.0));
    for t in linspace(d.start, d.end, 98) {
        let err = original.eval(t).distance(bspline.eval(t));
        assert!(err <= 1e-12 * data_size, "t {t}: value error {err:e}");
    }
    for t in inner_params(&distinct(bspline.knots()), 3) {
        for k in 1..=max_k {
            let err = original.deriv(t, k).distance(bspline.deriv(t, k));
            let scale = data_size * rate.powi(k as i32);
            assert!(
                err <= 1e-12 * scale,
                "t {t}, k {k}: error {err:e} scale {scale:e}"
            );
        }
    }
}

/// Compares a surface with its B-spline at a grid of points, and the first partials inside
/// the cells.
fn compare_surfaces<const D: usize>(
    original: &dyn Surface<D>,
    bspline: &BSplineSurface<D>,
    data_size: f64,
    rate: f64,
) {
    let (du, dv) = (original.domain_u(), original.domain_v());
    for u in linspace(du.start, du.end, 24) {
        for v in linspace(dv.start, dv.end, 20) {
            let err = original.eval(u, v).distance(bspline.eval(u, v));
            assert!(err <= 1e-12 * data_size, "({u}, {v}): value error {err:e}");
        }
    }
    let us = inner_params(&distinct(bspline.knots_u()), 1);
    let vs = inner_params(&distinct(bspline.knots_v()), 1);
    for &u in us.iter().step_by(3) {
        for &v in vs.iter().step_by(3) {
            for (ku, kv) in [(1, 0), (0, 1), (1, 1)] {
                let err = original
                    .deriv(u, v, ku, kv)
                    .distance(bspline.deriv(u, v, ku, kv));
                let scale = data_size * rate.powi((ku + kv) as i32);
                assert!(err <= 1e-12 * scale, "({u},{v}) d{ku}{kv}: {err:e}");
            }
        }
    }
}

fn multiplicities(knots: &[f64]) -> Vec<usize> {
    let mut out: Vec<usize> = Vec::new();
    for w in knots.windows(2) {
        if out.is_empty() {
            out.push(1);
        }
        if w[1] == w[0] {
            *out.last_mut().unwrap() += 1;
        } else {
            out.push(1);
        }
    }
    out
}

#[test]
fn kernel_bernstein_form_reproduces_h() {
    // Independent check: the Bezier points of the order-L LL curve of the scalar data
    // r = (0, 0, 1) are h/2 on segment 2 ... evaluated through the B-spline of a curve.
    for order in 1..=8 {
        let kernel = LlKernel::new(order).unwrap();
        // A 1-D LL curve whose middle segment is P = h(xi)/2 * D with D = 1: points 0, 0, 1
        // give on segment 2: a = 0, b = 0, c = (0 + 1 - 0)/2.
        let pts = [Point([0.0]), Point([0.0]), Point([1.0]), Point([3.0])];
        let curve = LlCurve::new(&pts, order, false).unwrap();
        let b = curve.to_bspline().unwrap();
        assert_eq!(b.degree(), 2 * order);
        let m = multiplicities(b.knots());
        assert_eq!(m[0], 2 * order + 1);
        assert_eq!(*m.last().unwrap(), 2 * order + 1);
        assert!(m[1..m.len() - 1].iter().all(|&k| k == order), "{m:?}");
        for xi in linspace(0.0, 1.0, 41) {
            let t = (xi + 1.5) / 5.0; // segment 2 of K = 4 nodes
            let expected = kernel.h(xi) / 2.0;
            let got = b.eval(t)[0];
            assert!((got - expected).abs() < 1e-14, "L {order}, xi {xi}");
        }
    }
}

#[test]
fn bspline_evaluation_matches_cox_de_boor_basis() {
    // Slow reference: the Cox–de Boor recursion for every basis function.
    fn basis(i: usize, p: usize, knots: &[f64], t: f64) -> f64 {
        if p == 0 {
            let last = knots[knots.len() - 1];
            let inside = knots[i] <= t && t < knots[i + 1];
            let at_end = t == last && knots[i] < knots[i + 1] && knots[i + 1] == last;
            return f64::from(u8::from(inside || at_end));
        }
        let mut s = 0.0;
        if knots[i + p] > knots[i] {
            s += (t - knots[i]) / (knots[i + p] - knots[i]) * basis(i, p - 1, knots, t);
        }
        if knots[i + p + 1] > knots[i + 1] {
            s += (knots[i + p + 1] - t) / (knots[i + p + 1] - knots[i + 1])
                * basis(i + 1, p - 1, knots, t);
        }
        s
    }
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.3, 0.3, 0.5, 0.9, 1.0, 1.0, 1.0, 1.0];
    let control: Vec<Point<2>> = (0..8)
        .map(|i| Point([(i as f64).sin() * 3.0, (i * i) as f64 * 0.1]))
        .collect();
    let c = BSplineCurve::new(3, knots.clone(), control.clone()).unwrap();
    for t in linspace(0.0, 1.0, 51) {
        let expected = control
            .iter()
            .enumerate()
            .fold(Point::ZERO, |s, (i, p)| s + *p * basis(i, 3, &knots, t));
        assert!(c.eval(t).distance(expected) < 1e-14, "t {t}");
    }
    // Derivative against a central difference.
    let h = 1e-6;
    for t in [0.1, 0.4, 0.7] {
        let fd = (c.eval(t + h) - c.eval(t - h)) * (0.5 / h);
        assert!(c.deriv(t, 1).distance(fd) < 1e-6, "t {t}");
    }
}

#[test]
fn invalid_bspline_data_are_errors() {
    let p = |x: f64| Point([x, 0.0]);
    let ok = || vec![p(0.0), p(1.0), p(2.0)];
    assert!(BSplineCurve::new(2, vec![0., 0., 0., 1., 1., 1.], ok()).is_ok());
    assert!(BSplineCurve::new(0, vec![0., 1., 2., 3.], ok()).is_err());
    assert!(BSplineCurve::new(2, vec![0., 0., 0., 1., 1.], ok()).is_err());
    assert!(BSplineCurve::new(2, vec![0., 0., 0.5, 1., 1., 1.], ok()).is_err());
    assert!(BSplineCurve::new(2, vec![0., 0., 0., 0., 0., 0.], ok()).is_err());
    assert!(BSplineCurve::new(2, vec![0., 0., 0., f64::NAN, 1., 1.], ok()).is_err());
    assert!(BSplineCurve::new(
        2,
        vec![0., 0., 0., 1., 1., 1.],
        vec![p(0.), p(f64::NAN), p(1.)]
    )
    .is_err());
    assert!(BSplineCurve::new(3, vec![0.0; 4], vec![p(0.0)]).is_err());
}

fn point3() -> impl Strategy<Value = Point3> {
    prop::array::uniform3(-100.0..100.0f64).prop_map(Point)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn ll_curves_convert_exactly(
        pts in prop::collection::vec(point3(), 4..12),
        order in 1usize..7,
        closed in any::<bool>(),
        interpolating in any::<bool>(),
    ) {
        let curve = if interpolating {
            LlCurve::interpolating(&pts, order, closed)
        } else {
            LlCurve::new(&pts, order, closed)
        };
        let Ok(curve) = curve else { return Ok(()) };
        let b = curve.to_bspline().unwrap();
        prop_assert_eq!(b.is_closed(), closed);
        let s = size(curve.control_points()) * 4.0;
        let rate = (curve.axis().nodes() + 1) as f64;
        compare_curves(&curve, &b, s, rate, order.min(3));
    }

    #[test]
    fn ll_surfaces_convert_exactly(
        rows in 3usize..7,
        cols in 3usize..6,
        seed in prop::collection::vec(-50.0..50.0f64, 3 * 36),
        order in 1usize..5,
        closed_u in any::<bool>(),
        closed_v in any::<bool>(),
        interpolating in any::<bool>(),
    ) {
        let grid = Grid::from_fn(rows, cols, |i, j| {
            let k = 3 * (i * 6 + j);
            Point([seed[k] + 100.0 * i as f64, seed[k + 1] + 100.0 * j as f64, seed[k + 2]])
        });
        let surface = if interpolating {
            LlSurface::interpolating(&grid, order, closed_u, closed_v)
        } else {
            LlSurface::new(&grid, order, closed_u, closed_v)
        };
        let Ok(surface) = surface else { return Ok(()) };
        let b = surface.to_bspline().unwrap();
        prop_assert_eq!(b.degree_u(), 2 * order);
        let s = size(grid.as_slice()) * 8.0;
        let rate = (rows.max(cols) + 2) as f64;
        compare_surfaces(&surface, &b, s, rate);
    }

    #[test]
    fn hermite_splines_convert_exactly(
        values in prop::collection::vec(point3(), 2..9),
        derivs in prop::collection::vec(point3(), 9),
        gaps in prop::collection::vec(0.05..2.0f64, 9),
    ) {
        let n = values.len();
        let mut knots = vec![-0.3];
        for g in &gaps[..n - 1] {
            knots.push(knots[knots.len() - 1] + g);
        }
        let spline = HermiteSpline::new(knots.clone(), values.clone(), derivs[..n].to_vec()).unwrap();
        let b = spline.to_bspline().unwrap();
        prop_assert_eq!(b.degree(), 3);
        let m = multiplicities(b.knots());
        prop_assert!(m[1..m.len() - 1].iter().all(|&k| k == 2));
        let s = size(&values).max(size(&derivs));
        compare_curves(&spline, &b, s * 4.0, 20.0, 3);
    }

    #[test]
    fn cubic_splines_convert_exactly(
        values in prop::collection::vec(point3(), 3..10),
        gaps in prop::collection::vec(0.05..2.0f64, 10),
        ends in 0usize..4,
    ) {
        let n = values.len();
        let mut knots = vec![1.0];
        for g in &gaps[..n - 1] {
            knots.push(knots[knots.len() - 1] + g);
        }
        let mut values = values;
        let ends = match ends {
            0 => SplineEnds::NotAKnot,
            1 => SplineEnds::Natural,
            2 => SplineEnds::Clamped { start: values[1], end: values[0] },
            _ => {
                values[n - 1] = values[0];
                SplineEnds::Periodic
            }
        };
        let Ok(spline) = CubicSpline::new(&knots, &values, ends) else { return Ok(()) };
        let b = spline.to_bspline().unwrap();
        let m = multiplicities(b.knots());
        prop_assert!(m[1..m.len() - 1].iter().all(|&k| k == 1));
        let s = size(&values) * 4.0;
        compare_curves(&spline, &b, s, 40.0, 2);
    }

    #[test]
    fn bicubic_surfaces_convert_exactly(
        rows in 2usize..7,
        cols in 2usize..6,
        seed in prop::collection::vec(-1.0..1.0f64, 3 * 36 + 12),
        closed_u in any::<bool>(),
    ) {
        let mut knots_u = vec![0.0];
        for i in 1..rows {
            knots_u.push(knots_u[i - 1] + 0.2 + seed[108 + i].abs());
        }
        let knots_v: Vec<f64> = (0..cols).map(|j| j as f64 * 0.7 + seed[j].abs() * 0.1).collect();
        let closed_u = closed_u && rows >= 4;
        let grid = Grid::from_fn(rows, cols, |i, j| {
            let i = if closed_u && i == rows - 1 { 0 } else { i };
            let k = 3 * (i * 6 + j);
            Point([seed[k] * 10.0 + 30.0 * i as f64, seed[k + 1] * 10.0 + 30.0 * j as f64, seed[k + 2] * 20.0])
        });
        let Ok(surface) = BicubicSurface::from_knots(&grid, &knots_u, &knots_v, closed_u, false) else {
            return Ok(());
        };
        let b = surface.to_bspline().unwrap();
        prop_assert_eq!((b.degree_u(), b.degree_v()), (3, 3));
        compare_surfaces(&surface, &b, size(grid.as_slice()) * 8.0, 10.0);
    }
}

/// A smooth test surface sampled along a network whose curves cross at equal point
/// indices (so no warp is needed).
fn network_lists(m: usize, n: usize, per: usize) -> (Vec<Vec<Point3>>, Vec<Vec<Point3>>) {
    let s = |u: f64, v: f64| Point([3.0 * u, 2.0 * v, (2.0 * u).sin() * (1.0 + v * v)]);
    let steps_v = (n - 1) * per;
    let steps_u = (m - 1) * per;
    let v_lists = (0..m)
        .map(|i| {
            let u = i as f64 / (m - 1) as f64;
            (0..=steps_v)
                .map(|k| s(u, k as f64 / steps_v as f64))
                .collect()
        })
        .collect();
    let u_lists = (0..n)
        .map(|j| {
            let v = j as f64 / (n - 1) as f64;
            (0..=steps_u)
                .map(|k| s(k as f64 / steps_u as f64, v))
                .collect()
        })
        .collect();
    (v_lists, u_lists)
}

#[test]
fn coons_surfaces_over_splines_convert_exactly() {
    let (v_lists, u_lists) = network_lists(4, 3, 4);
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    let n = net.network();
    let surfaces = [
        (
            "composite",
            CoonsSurface::composite(n, None, 1e-6).unwrap(),
            2,
        ),
        (
            "gordon-spline",
            CoonsSurface::gordon_spline(n, CoonsEnds::NotAKnot, 1e-6).unwrap(),
            1,
        ),
        ("gordon", CoonsSurface::gordon(n, 1e-6).unwrap(), 1),
    ];
    for (name, surface, inner_multiplicity) in surfaces {
        let b = surface
            .to_bspline()
            .unwrap_or_else(|e| panic!("{name}: {e}"));
        assert_eq!(b.degree_u(), 3, "{name}");
        let mu = multiplicities(b.knots_u());
        // The network nodes carry the blending's multiplicity (C^1 Hermite: 2), the curves'
        // own breakpoints multiplicity 1 (C^2 splines).
        let inner = &mu[1..mu.len() - 1];
        assert_eq!(
            inner.iter().max(),
            Some(&inner_multiplicity),
            "{name}: {mu:?}"
        );
        assert!(inner.iter().all(|&k| k >= 1), "{name}: {mu:?}");
        compare_surfaces(&surface, &b, 4.0, 12.0);
    }
    // Bilinear and bicubic Coons on the four borders.
    let (v4, u4) = network_lists(2, 2, 12);
    let net = PointNetwork::new(&v4, &u4, CurveFit::CubicSpline, 1e-9).unwrap();
    for surface in [
        CoonsSurface::bilinear(net.network(), 1e-6).unwrap(),
        CoonsSurface::bicubic(net.network(), None, 1e-6).unwrap(),
    ] {
        let b = surface.to_bspline().unwrap();
        compare_surfaces(&surface, &b, 4.0, 30.0);
    }
}

#[test]
fn coons_surfaces_over_ll_curves_convert_exactly() {
    let (v_lists, u_lists) = network_lists(3, 3, 3);
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::Ll(2), 1e-9).unwrap();
    let surface = CoonsSurface::gordon_spline(net.network(), CoonsEnds::NotAKnot, 1e-3).unwrap();
    let b = surface.to_bspline().unwrap();
    assert_eq!((b.degree_u(), b.degree_v()), (4, 4));
    compare_surfaces(&surface, &b, 4.0, 12.0);
}

#[test]
fn warped_networks_are_refused_not_approximated() {
    // Crossings at unequal point indices: the curves are reparameterized by a cubic warp.
    let s = |u: f64, v: f64| Point([3.0 * u, 2.0 * v, u * v]);
    let v_lists: Vec<Vec<Point3>> = (0..3)
        .map(|i| {
            let u = i as f64 / 2.0;
            let mut vs = vec![0.0, 0.1, 0.2, 0.5, 1.0];
            if i == 1 {
                vs = vec![0.0, 0.3, 0.5, 0.8, 1.0];
            }
            vs.iter().map(|&v| s(u, v)).collect()
        })
        .collect();
    let u_lists: Vec<Vec<Point3>> = [0.0, 0.5, 1.0]
        .iter()
        .map(|&v| (0..=4).map(|k| s(k as f64 / 4.0, v)).collect())
        .collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    let surface = CoonsSurface::gordon_spline(net.network(), CoonsEnds::NotAKnot, 1e-3).unwrap();
    match surface.to_bspline() {
        Err(Error::NotExactlyConvertible { reason, .. }) => {
            // The message names the way to an exact form and the mesh alternative.
            assert!(
                reason.contains("as many points between consecutive crossings")
                    && reason.contains("--mesh-tolerance"),
                "{reason}"
            )
        }
        other => panic!("expected NotExactlyConvertible, got {other:?}"),
    }
}

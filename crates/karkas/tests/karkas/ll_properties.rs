//! Property tests of LL curves and surfaces (docs/methods.md §1.2–1.3): affine invariance, the
//! convex hull of three consecutive points, interpolation, periodicity, batch evaluation.
//! Fixed seed and case count, so CI runs are reproducible.

use crate::common::{assert_near, linspace, max_abs};
use crate::ll_reference::RefCurve;
use karkas::ll::{LlCurve, LlSurface};
use karkas::{Curve, Grid, Point, Surface};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

fn config() -> Config {
    Config {
        cases: 128,
        rng_seed: RngSeed::Fixed(0x11_2024),
        failure_persistence: None,
        ..Config::default()
    }
}

fn points<const D: usize>(min: usize, max: usize) -> impl Strategy<Value = Vec<Point<D>>> {
    prop::collection::vec(prop::array::uniform::<_, D>(-10.0..10.0f64), min..=max)
        .prop_map(|v| v.into_iter().map(Point).collect())
}

/// `x -> A x + b` with `A` well conditioned (|det A| >= 0.2, entries in [-3, 3]).
fn affine<const D: usize>() -> impl Strategy<Value = ([[f64; D]; D], [f64; D])> {
    (
        prop::array::uniform::<_, D>(prop::array::uniform::<_, D>(-3.0..3.0f64)),
        prop::array::uniform::<_, D>(-20.0..20.0f64),
    )
        .prop_filter("well-conditioned map", |(a, _)| det(a).abs() >= 0.2)
}

fn det<const D: usize>(a: &[[f64; D]; D]) -> f64 {
    match D {
        2 => a[0][0] * a[1][1] - a[0][1] * a[1][0],
        3 => {
            a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1])
                - a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0])
                + a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0])
        }
        _ => unreachable!(),
    }
}

fn apply<const D: usize>(m: &([[f64; D]; D], [f64; D]), p: Point<D>, translate: bool) -> Point<D> {
    Point(core::array::from_fn(|r| {
        let lin: f64 = (0..D).map(|c| m.0[r][c] * p[c]).sum();
        lin + if translate { m.1[r] } else { 0.0 }
    }))
}

fn build<const D: usize>(p: &[Point<D>], l: usize, closed: bool, interp: bool) -> LlCurve<D> {
    if interp {
        LlCurve::interpolating(p, l, closed).unwrap()
    } else {
        LlCurve::new(p, l, closed).unwrap()
    }
}

fn check_affine<const D: usize>(
    pts: &[Point<D>],
    m: &([[f64; D]; D], [f64; D]),
    l: usize,
    closed: bool,
    interp: bool,
) {
    let moved: Vec<Point<D>> = pts.iter().map(|&p| apply(m, p, true)).collect();
    let a = build(pts, l, closed, interp);
    let b = build(&moved, l, closed, interp);
    assert_eq!(a.axis(), b.axis());
    let scale = max_abs(&moved) + 100.0;
    let d = a.domain();
    for t in linspace(d.start, d.end, 41) {
        let want = apply(m, a.eval(t), true);
        assert_near(b.eval(t), want, 1e-11 * scale, "curve of moved points");
        let want = apply(m, a.deriv(t, 1), false);
        assert_near(
            b.deriv(t, 1),
            want,
            1e-11 * scale * a.axis().scale() * 3.0,
            "tangent",
        );
    }
}

proptest! {
    #![proptest_config(config())]

    #[test]
    fn curves_are_affine_invariant_2d(
        pts in points::<2>(3, 12), m in affine::<2>(), l in 1usize..=12,
        closed in any::<bool>(), interp in any::<bool>(),
    ) {
        check_affine(&pts, &m, l, closed, interp);
    }

    #[test]
    fn curves_are_affine_invariant_3d(
        pts in points::<3>(3, 12), m in affine::<3>(), l in 1usize..=12,
        closed in any::<bool>(), interp in any::<bool>(),
    ) {
        check_affine(&pts, &m, l, closed, interp);
    }

    /// Each point of segment i lies in the triangle r_{i-1}, r_i, r_{i+1}: barycentric
    /// coordinates computed here, independent of the kernel weights.
    #[test]
    fn segments_lie_in_the_convex_hull_of_three_points(
        pts in points::<2>(3, 12), l in 1usize..=12, closed in any::<bool>(),
    ) {
        let c = LlCurve::new(&pts, l, closed).unwrap();
        let r = RefCurve::new(&pts, l, closed);
        let scale = r.size();
        let cross = |u: Point<2>, v: Point<2>| u[0] * v[1] - u[1] * v[0];
        for i in 1..=r.k() {
            let (a, b, e) = (r.ext[i - 1], r.ext[i], r.ext[i + 1]);
            let area = cross(b - a, e - a);
            for xi in linspace(0.0, 1.0, 21) {
                let t = r.param(i, xi);
                if !c.domain().contains(t) {
                    continue;
                }
                let p = c.eval(t);
                let tol = 1e-12 * scale * scale;
                if area.abs() > 1e-6 * scale * scale {
                    let la = cross(b - p, e - p) / area;
                    let lb = cross(e - p, a - p) / area;
                    let le = cross(a - p, b - p) / area;
                    let eps = tol / area.abs();
                    prop_assert!(la >= -eps && lb >= -eps && le >= -eps,
                        "segment {i}, xi {xi}: barycentric ({la}, {lb}, {le})");
                } else {
                    // Nearly collinear: on the line, inside the bounding box.
                    prop_assert!(cross(p - a, e - a).abs() <= 1e-6 * scale * scale);
                    for k in 0..2 {
                        let lo = a[k].min(b[k]).min(e[k]) - 1e-12 * scale;
                        let hi = a[k].max(b[k]).max(e[k]) + 1e-12 * scale;
                        prop_assert!(p[k] >= lo && p[k] <= hi);
                    }
                }
            }
        }
    }

    /// In 3-D: the kernel's weights are >= 0 (to rounding), sum to 1, and rebuild the point.
    #[test]
    fn points_are_convex_combinations_3d(
        pts in points::<3>(3, 10), l in 1usize..=12, closed in any::<bool>(),
    ) {
        let c = LlCurve::new(&pts, l, closed).unwrap();
        let r = RefCurve::new(&pts, l, closed);
        for i in 1..=r.k() {
            for xi in linspace(0.0, 1.0, 17) {
                let t = r.param(i, xi);
                if !c.domain().contains(t) || (c.is_closed() && t >= c.domain().end) {
                    continue;
                }
                let w = c.kernel().weights(xi, 0);
                prop_assert!(w.iter().all(|&x| x >= -2.0 * l as f64 * f64::EPSILON));
                prop_assert!((w.iter().sum::<f64>() - 1.0).abs() <= 1e-15);
                let p = r.ext[i - 1] * w[0] + r.ext[i] * w[1] + r.ext[i + 1] * w[2];
                assert_near(c.eval(t), p, 1e-13 * r.size(), "convex combination");
            }
        }
    }

    #[test]
    fn interpolating_curves_pass_through_all_points(
        pts in points::<3>(3, 16), l in 1usize..=12, closed in any::<bool>(),
    ) {
        let c = LlCurve::interpolating(&pts, l, closed).unwrap();
        let tol = 1e-11 * max_abs(&pts);
        for (i, p) in pts.iter().enumerate() {
            assert_near(c.eval(c.axis().node(i + 1)), *p, tol, "interpolated point");
        }
    }

    #[test]
    fn closed_curves_are_periodic(
        pts in points::<2>(3, 12), l in 1usize..=12, interp in any::<bool>(),
        t in 0.0..1.0f64, m in -3i32..=3,
    ) {
        let c = build(&pts, l, true, interp);
        let per = c.period().unwrap();
        let scale = max_abs(c.control_points());
        assert_near(c.eval(t + m as f64 * per), c.eval(t), 1e-12 * scale, "P(t + m period)");
        let s1 = scale * c.axis().scale() * 4.0;
        assert_near(c.deriv(t + m as f64 * per, 1), c.deriv(t, 1), 1e-11 * s1, "P'");
        let d = c.domain();
        assert_near(c.eval(d.end), c.eval(d.start), 1e-13 * scale, "closes");
    }

    #[test]
    fn batch_evaluation_equals_pointwise(
        pts in points::<3>(3, 12), l in 1usize..=20, closed in any::<bool>(),
        ts in prop::collection::vec(-0.5..1.5f64, 0..300),
    ) {
        let c = LlCurve::new(&pts, l, closed).unwrap();
        let mut ts = ts;
        ts.extend([c.domain().start, c.domain().end]);
        ts.extend(karkas::PiecewiseCurve::breakpoints(&c));
        let mut out = vec![Point::ZERO; ts.len()];
        c.eval_into(&ts, &mut out);
        let tol = 1e-13 * max_abs(&pts);
        for (p, &t) in out.iter().zip(&ts) {
            assert_near(*p, c.eval(t), tol, "eval_into");
        }
    }

    #[test]
    fn surfaces_are_affine_invariant_and_interpolate(
        rows in 3usize..=6, cols in 3usize..=6, cu in any::<bool>(), cv in any::<bool>(),
        l in 1usize..=12, m in affine::<3>(),
        vals in prop::collection::vec(prop::array::uniform::<_, 3>(-5.0..5.0f64), 36),
    ) {
        let g = Grid::from_fn(rows, cols, |i, j| Point(vals[i * 6 + j]));
        let moved = Grid::from_fn(rows, cols, |i, j| apply(&m, *g.get(i, j), true));
        let scale = max_abs(moved.as_slice()) + 100.0;
        for interp in [false, true] {
            let (a, b) = if interp {
                (LlSurface::interpolating(&g, l, cu, cv).unwrap(),
                 LlSurface::interpolating(&moved, l, cu, cv).unwrap())
            } else {
                (LlSurface::new(&g, l, cu, cv).unwrap(), LlSurface::new(&moved, l, cu, cv).unwrap())
            };
            let (du, dv) = (a.domain_u(), a.domain_v());
            for u in linspace(du.start, du.end, 7) {
                for v in linspace(dv.start, dv.end, 7) {
                    let want = apply(&m, a.eval(u, v), true);
                    assert_near(b.eval(u, v), want, 1e-11 * scale, "surface of moved grid");
                }
            }
            if interp {
                for i in 0..rows {
                    for j in 0..cols {
                        let p = b.eval(b.axis_u().node(i + 1), b.axis_v().node(j + 1));
                        assert_near(p, *moved.get(i, j), 1e-11 * scale, "interpolated grid");
                    }
                }
            }
        }
    }
}

//! Properties across the methods: finite valid input never gives NaN; the linear methods
//! commute with similarity maps (rotate, scale, translate the data and the result moves the
//! same way); evaluation outside the domain does what each type documents (clamp, wrap or
//! continue the end pieces). Also the regression tests of inputs the fuzz targets found.

use karkas::coons::{CoonsSurface, CurveFit, PointNetwork, SplineEnds as NetEnds};
use karkas::dps::DiscreteSpline;
use karkas::fit::{fit_curve, FitOptions};
use karkas::ll::{LlCurve, LlSurface};
use karkas::param::{BicubicSurface, CubicSpline, GridParameterization, SplineEnds};
use karkas::{Curve, Error, Grid, Point, Surface};
use proptest::prelude::*;
use proptest::test_runner::{Config, RngSeed};

fn config(cases: u32) -> Config {
    Config {
        cases,
        rng_seed: RngSeed::Fixed(0x11_0011),
        failure_persistence: None,
        ..Config::default()
    }
}

/// A similarity map of space: rotation about z by `angle`, then about x by `tilt`, scale `s`,
/// shift `b`.
#[derive(Clone, Copy, Debug)]
struct Similarity {
    angle: f64,
    tilt: f64,
    s: f64,
    b: [f64; 3],
}

impl Similarity {
    fn apply<const D: usize>(&self, p: Point<D>) -> Point<D> {
        let mut q = [0.0; 3];
        q[..D].copy_from_slice(&p.0[..D]);
        let (c, s) = (self.angle.cos(), self.angle.sin());
        let (x, y) = (c * q[0] - s * q[1], s * q[0] + c * q[1]);
        let (ct, st) = (self.tilt.cos(), self.tilt.sin());
        let (y, z) = if D == 3 {
            (ct * y - st * q[2], st * y + ct * q[2])
        } else {
            (y, 0.0)
        };
        let r = [x, y, z];
        let mut out = [0.0; D];
        for k in 0..D {
            out[k] = self.s * r[k] + self.b[k];
        }
        Point(out)
    }
}

fn similarity() -> impl Strategy<Value = Similarity> {
    (
        -3.0..3.0f64,
        -1.5..1.5f64,
        prop_oneof![0.01..0.1f64, 0.5..5.0f64, 100.0..1000.0f64],
        prop::array::uniform3(-50.0..50.0f64),
    )
        .prop_map(|(angle, tilt, s, b)| Similarity { angle, tilt, s, b })
}

fn points<const D: usize>(min: usize, max: usize) -> impl Strategy<Value = Vec<Point<D>>> {
    prop::collection::vec(prop::array::uniform::<_, D>(-10.0..10.0f64), min..=max)
        .prop_map(|v| v.into_iter().map(Point).collect())
}

/// Increasing knots with gaps in [0.2, 2].
fn knots(n: usize) -> impl Strategy<Value = Vec<f64>> {
    prop::collection::vec(0.2..2.0f64, n).prop_map(|gaps| {
        gaps.iter()
            .scan(0.0, |t, g| {
                let k = *t;
                *t += g;
                Some(k)
            })
            .collect()
    })
}

fn close<const D: usize>(a: Point<D>, b: Point<D>, scale: f64) -> bool {
    (a - b).max_abs() <= 1e-9 * scale.max(1.0)
}

proptest! {
    #![proptest_config(config(48))]

    #[test]
    fn cubic_spline_on_given_knots_is_similarity_invariant(
        (t, p) in (4usize..12).prop_flat_map(|n| (knots(n), points::<3>(n, n))),
        map in similarity(),
        x in 0.0..1.0f64,
    ) {
        let moved: Vec<_> = p.iter().map(|&q| map.apply(q)).collect();
        let a = CubicSpline::new(&t, &p, SplineEnds::NotAKnot).unwrap();
        let b = CubicSpline::new(&t, &moved, SplineEnds::NotAKnot).unwrap();
        let u = a.domain().start + x * a.domain().length();
        let (pa, pb) = (a.eval(u), b.eval(u));
        prop_assert!(pa.is_finite() && pb.is_finite());
        prop_assert!(close(map.apply(pa), pb, 100.0 * map.s));
    }

    #[test]
    fn bicubic_on_given_knots_is_similarity_invariant(
        (ku, kv, g) in (3usize..6, 3usize..6).prop_flat_map(|(r, c)| {
            (knots(r), knots(c), points::<3>(r * c, r * c))
        }),
        map in similarity(),
        (x, y) in (0.0..1.0f64, 0.0..1.0f64),
    ) {
        let (r, c) = (ku.len(), kv.len());
        let grid = Grid::from_row_major(r, c, g.clone()).unwrap();
        let moved = Grid::from_row_major(r, c, g.iter().map(|&q| map.apply(q)).collect()).unwrap();
        let a = BicubicSurface::from_knots(&grid, &ku, &kv, false, false).unwrap();
        let b = BicubicSurface::from_knots(&moved, &ku, &kv, false, false).unwrap();
        let (du, dv) = (a.domain_u(), a.domain_v());
        let (u, v) = (du.start + x * du.length(), dv.start + y * dv.length());
        let (pa, pb) = (a.eval(u, v), b.eval(u, v));
        prop_assert!(pa.is_finite() && pb.is_finite());
        prop_assert!(close(map.apply(pa), pb, 1000.0 * map.s));
    }

    #[test]
    fn discrete_spline_is_similarity_invariant(
        p in points::<3>(2, 9),
        map in similarity(),
        order in 1usize..5,
        n in 2usize..6,
    ) {
        let moved: Vec<_> = p.iter().map(|&q| map.apply(q)).collect();
        for interpolate in [false, true] {
            let build = if interpolate { DiscreteSpline::interpolating } else { DiscreteSpline::from_poles };
            let (Ok(a), Ok(b)) = (build(&p, order, n), build(&moved, order, n)) else {
                // Interpolation is refused only where the symbol vanishes, for both alike.
                prop_assert!(build(&p, order, n).is_err() && build(&moved, order, n).is_err());
                continue;
            };
            for (pa, pb) in a.to_values().into_iter().zip(b.to_values()) {
                prop_assert!(pa.is_finite());
                prop_assert!(close(map.apply(pa), pb, 1e3 * map.s));
            }
        }
    }

    #[test]
    fn ll_surface_is_similarity_invariant_and_finite(
        (r, c, g) in (3usize..6, 3usize..6).prop_flat_map(|(r, c)| (Just(r), Just(c), points::<3>(r * c, r * c))),
        map in similarity(),
        (x, y) in (-0.5..1.5f64, -0.5..1.5f64),
        order in 1usize..6,
        interpolate in any::<bool>(),
    ) {
        let grid = Grid::from_row_major(r, c, g.clone()).unwrap();
        let moved = Grid::from_row_major(r, c, g.iter().map(|&q| map.apply(q)).collect()).unwrap();
        let build = if interpolate { LlSurface::interpolating } else { LlSurface::new };
        let a = build(&grid, order, false, false).unwrap();
        let b = build(&moved, order, false, false).unwrap();
        let (du, dv) = (a.domain_u(), a.domain_v());
        let (u, v) = (du.start + x * du.length(), dv.start + y * dv.length());
        let (pa, pb) = (a.eval(u, v), b.eval(u, v));
        prop_assert!(pa.is_finite() && a.deriv(u, v, 1, 1).is_finite());
        prop_assert!(close(map.apply(pa), pb, 1e3 * map.s));
        // Outside the domain an open direction clamps.
        prop_assert_eq!(a.eval(u.clamp(du.start, du.end), v.clamp(dv.start, dv.end)), pa);
    }

    #[test]
    fn coons_surfaces_through_point_networks_are_similarity_invariant(
        wobble in prop::collection::vec(-0.2..0.2f64, 9),
        map in similarity(),
        (x, y) in (0.0..1.0f64, 0.0..1.0f64),
    ) {
        // A 3 x 3 network on the grid points (i, j, h(i, j)).
        let h = |i: usize, j: usize| wobble[3 * i + j];
        let node = |i: usize, j: usize| Point([i as f64, j as f64, h(i, j)]);
        let v_curves: Vec<Vec<Point<3>>> = (0..3).map(|i| (0..3).map(|j| node(i, j)).collect()).collect();
        let u_curves: Vec<Vec<Point<3>>> = (0..3).map(|j| (0..3).map(|i| node(i, j)).collect()).collect();
        let m = |f: &Vec<Vec<Point<3>>>| -> Vec<Vec<Point<3>>> {
            f.iter().map(|c| c.iter().map(|&p| map.apply(p)).collect()).collect()
        };
        let a = PointNetwork::new(&v_curves, &u_curves, CurveFit::CubicSpline, 1e-6).unwrap();
        let b = PointNetwork::new(&m(&v_curves), &m(&u_curves), CurveFit::CubicSpline, 1e-6).unwrap();
        for kind in 0..2 {
            let build = |n: &PointNetwork<3>| match kind {
                0 => CoonsSurface::gordon_spline(n.network(), NetEnds::NotAKnot, 1e-4),
                _ => CoonsSurface::composite(n.network(), None, 1e-4),
            };
            let (sa, sb) = (build(&a).unwrap(), build(&b).unwrap());
            let (du, dv) = (sa.domain_u(), sa.domain_v());
            let (u, v) = (du.start + x * du.length(), dv.start + y * dv.length());
            let (pa, pb) = (sa.eval(u, v), sb.eval(u, v));
            prop_assert!(pa.is_finite());
            prop_assert!(close(map.apply(pa), pb, 100.0 * map.s));
            // Open directions clamp outside the domain.
            prop_assert_eq!(sa.eval(du.end + 1.0, dv.start - 1.0), sa.eval(du.end, dv.start));
        }
    }

    #[test]
    fn fits_of_finite_points_are_finite(p in points::<2>(3, 30), eps in prop_oneof![Just(f64::INFINITY), 1e-4..1.0f64]) {
        let options = FitOptions { eps, max_iterations: 30, ..FitOptions::default() };
        match fit_curve(&p, &[0.0, 0.5, 1.0], &options) {
            Ok(fit) => {
                for k in 0..=20 {
                    prop_assert!(fit.spline.eval(k as f64 / 20.0).is_finite());
                }
                prop_assert!(fit.max_distance().is_finite());
            }
            // Only degenerate data may be refused.
            Err(e) => prop_assert!(
                matches!(e, Error::TooFewPoints { .. } | Error::SingularSystem { .. }),
                "{e}"
            ),
        }
    }

    #[test]
    fn ll_curves_clamp_open_and_wrap_closed(p in points::<2>(4, 12), t in -3.0..3.0f64, order in 1usize..6) {
        let open = LlCurve::new(&p, order, false).unwrap();
        let d = open.domain();
        prop_assert_eq!(open.eval(t), open.eval(d.clamp(t)));
        prop_assert!(open.eval(t).is_finite());
        let closed = LlCurve::new(&p, order, true).unwrap();
        let period = closed.domain().length();
        prop_assert!(close(closed.eval(t), closed.eval(t + period), 10.0));
    }
}

#[test]
fn cubic_spline_outside_the_domain_continues_the_end_pieces() {
    // Documented: outside the domain an open spline continues its end polynomials, so a
    // not-a-knot spline through a cubic reproduces it there too.
    let t = [0.0, 1.0, 2.5, 3.0, 4.0];
    let f = |x: f64| Point([x * x * x - 2.0 * x, 1.0 - x * x]);
    let values: Vec<_> = t.iter().map(|&x| f(x)).collect();
    let s = CubicSpline::new(&t, &values, SplineEnds::NotAKnot).unwrap();
    for x in [-1.0, 5.0] {
        assert!((s.eval(x) - f(x)).max_abs() < 1e-9, "{x}");
    }
}

/// Found by the `splines` fuzz target: one far outlier in a 4 x 4 grid made averaged-chord
/// parameters span 1e148 with the first gaps near 1e3, and the bicubic surface evaluated to
/// NaN. Such parameters are now refused.
#[test]
fn regression_bicubic_parameters_from_a_far_outlier() {
    let mut grid = Grid::from_fn(4, 4, |i, j| {
        Point([
            i as f64 * 1000.0,
            j as f64 * 1000.0,
            ((i * j) % 3) as f64 * 1000.0,
        ])
    });
    *grid.get_mut(3, 3) = Point([-9.87e148; 3]);
    let e = BicubicSurface::new(&grid, GridParameterization::AveragedChord, false, true);
    assert!(
        matches!(e, Err(Error::InvalidKnot { index: 1, .. })),
        "{e:?}"
    );
}

#[test]
fn knots_closer_than_1e_12_of_the_span_are_refused() {
    let values = [Point([0.0]), Point([1.0]), Point([0.0])];
    let e = CubicSpline::new(&[0.0, 1e-13, 1.0], &values, SplineEnds::Natural);
    assert!(
        matches!(e, Err(Error::InvalidKnot { index: 1, .. })),
        "{e:?}"
    );
    assert!(CubicSpline::new(&[0.0, 1e-11, 1.0], &values, SplineEnds::Natural).is_ok());
}

/// Found by the `expression` fuzz target: projecting a point with a NaN coordinate onto
/// `x = 0` returned that NaN point as a foot point. Non-finite points are now refused.
#[test]
fn regression_projecting_a_non_finite_point() {
    use karkas::implicit::{project_onto, ExpressionSurface};
    let plane = ExpressionSurface::parse("x").unwrap();
    let e = project_onto(&plane, Point([792.0, -1526.0, f64::NAN]));
    assert!(matches!(e, Err(Error::NonFiniteArgument { .. })), "{e:?}");
    let foot = project_onto(&plane, Point([792.0, -1526.0, 3.0])).unwrap();
    assert_eq!(foot.0, [0.0, -1526.0, 3.0]);
}

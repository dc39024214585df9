//! Bicubic interpolation (Kuznetsov and Filatov, (3.3)–(3.13)): against SciPy, node reproduction, C^2
//! continuity across every patch border, periodic seams, grid evaluation.

use karkas::param::{BicubicSurface, GridParameterization};
use karkas::{Grid, PiecewiseSurface, Point, Point3, Side, Surface};
use proptest::prelude::*;

const U: [f64; 5] = [0.0, 0.4, 1.1, 1.5, 2.3];
const V: [f64; 6] = [0.0, 0.3, 0.9, 1.6, 2.0, 2.8];
const UQ: [f64; 4] = [0.1, 0.7, 1.5, 2.0];
const VQ: [f64; 3] = [0.05, 1.0, 2.5];

/// `z(u, v) = sin(u) cos(v) + 0.1 u^2 v` on the knots `U x V`.
fn z(u: f64, v: f64) -> f64 {
    u.sin() * v.cos() + 0.1 * u * u * v
}

/// The tensor-product not-a-knot spline by SciPy, row-major over `UQ x VQ`:
/// `Z = sin(u)[:, None] * cos(v)[None, :] + 0.1 * u[:, None]**2 * v[None, :]`,
/// `CubicSpline(u, CubicSpline(v, Z, axis=1)(vq, kv), axis=0)(uq, ku).ravel()`.
const SCIPY: [(usize, usize, &[f64]); 5] = [
    (
        0,
        0,
        &[
            0.1004379142680184,
            0.055291468169503415,
            -0.0782916907005344,
            0.6452182425513897,
            0.3966198488164409,
            -0.3947966628800841,
            1.0078644902184781,
            0.763985835770073,
            -0.23957035108262503,
            0.9333619243781048,
            0.8939614514972336,
            0.2649308970102853,
        ],
    ),
    (
        1,
        0,
        &[
            0.9983571799000062,
            0.5593874948093958,
            -0.7526680640192273,
            0.7710702282141012,
            0.5532219976560119,
            -0.2649198935097954,
            0.09068784755680276,
            0.3409332577174336,
            0.6890867993006352,
            -0.3914465253796082,
            0.17748281654242673,
            1.3311301032665142,
        ],
    ),
    (
        0,
        1,
        &[
            -0.0035176599992557235,
            -0.08359690511127077,
            -0.05942943180894998,
            0.020074123819191318,
            -0.492660860474529,
            -0.337920277858508,
            0.1801503241205103,
            -0.6148471277771096,
            -0.37492129347043646,
            0.3588968586438629,
            -0.36969018245135554,
            -0.1498066428468635,
        ],
    ),
    (
        1,
        1,
        &[
            -0.024883098423334766,
            -0.8204729924439225,
            -0.5803683623809961,
            0.10561528813708257,
            -0.5038820555829352,
            -0.3199391280293028,
            0.2965938931610424,
            0.23621784350709277,
            0.25443900138726977,
            0.4185159291643166,
            0.7467260269296149,
            0.6476740345663046,
        ],
    ),
    (
        2,
        1,
        &[
            0.20703275933940726,
            0.3316942121816305,
            0.29407207514501627,
            0.22796186252865042,
            0.7236089106883272,
            0.5740253726939628,
            0.24310196661485642,
            1.0071198320428962,
            0.776543465602374,
            0.24458617739824043,
            1.0349129016471925,
            0.7963966671137651,
        ],
    ),
];

fn scalar_surface() -> BicubicSurface<1> {
    let grid = Grid::from_fn(U.len(), V.len(), |i, j| Point([z(U[i], V[j])]));
    BicubicSurface::from_knots(&grid, &U, &V, false, false).unwrap()
}

#[test]
fn tensor_product_not_a_knot_matches_scipy() {
    let s = scalar_surface();
    for (ku, kv, expected) in SCIPY {
        for (a, &u) in UQ.iter().enumerate() {
            for (b, &v) in VQ.iter().enumerate() {
                let e = expected[a * VQ.len() + b];
                let got = s.deriv(u, v, ku, kv)[0];
                assert!(
                    (got - e).abs() <= 1e-12 * e.abs().max(1.0),
                    "D^({ku},{kv}) at ({u}, {v}): {got} vs SciPy {e}"
                );
            }
        }
    }
}

#[test]
fn bicubic_polynomials_are_reproduced() {
    let f = |u: f64, v: f64| 1.0 + u - 2.0 * v + u * v * v - 0.5 * u * u * u * v * v * v;
    let us = [-1.0, -0.2, 0.5, 0.9, 2.0];
    let vs = [0.0, 0.25, 1.0, 1.2, 1.9, 3.0];
    let grid = Grid::from_fn(5, 6, |i, j| Point([f(us[i], vs[j])]));
    let s = BicubicSurface::from_knots(&grid, &us, &vs, false, false).unwrap();
    for (u, v) in [(-0.7, 0.1), (0.6, 1.1), (1.7, 2.9), (0.0, 0.0)] {
        assert!((s.eval(u, v)[0] - f(u, v)).abs() < 1e-12);
    }
}

/// A wavy open sheet of `rows x cols` points with uneven spacing.
fn sheet(rows: usize, cols: usize) -> Grid<Point3> {
    Grid::from_fn(rows, cols, |i, j| {
        let (x, y) = (
            i as f64 + 0.3 * (j as f64).sin(),
            j as f64 * (1.0 + 0.1 * i as f64),
        );
        Point::new([x, y, (0.7 * x).sin() * (0.4 * y).cos()])
    })
}

fn assert_c2_across_borders(s: &BicubicSurface<3>) {
    let (bu, bv) = (s.breakpoints_u(), s.breakpoints_v());
    let inner_u = &bu[1..bu.len() - 1];
    let inner_v = &bv[1..bv.len() - 1];
    let mid_v: Vec<f64> = bv.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    let mid_u: Vec<f64> = bu.windows(2).map(|w| 0.5 * (w[0] + w[1])).collect();
    for ku in 0..=2 {
        for kv in 0..=2 {
            for &u in inner_u {
                for &v in mid_v.iter().chain(inner_v) {
                    let a = s.deriv_on_side(u, v, ku, kv, Side::Below, Side::Above);
                    let b = s.deriv_on_side(u, v, ku, kv, Side::Above, Side::Above);
                    assert!(
                        (a - b).max_abs() < 1e-9,
                        "D^({ku},{kv}) jumps across u = {u}"
                    );
                }
            }
            for &v in inner_v {
                for &u in &mid_u {
                    let a = s.deriv_on_side(u, v, ku, kv, Side::Above, Side::Below);
                    let b = s.deriv_on_side(u, v, ku, kv, Side::Above, Side::Above);
                    assert!(
                        (a - b).max_abs() < 1e-9,
                        "D^({ku},{kv}) jumps across v = {v}"
                    );
                }
            }
        }
    }
}

#[test]
fn open_surface_interpolates_and_is_c2() {
    let grid = sheet(7, 9);
    for param in [
        GridParameterization::Uniform,
        GridParameterization::default(),
        GridParameterization::AveragedChord,
        GridParameterization::Centripetal,
    ] {
        let s = BicubicSurface::new(&grid, param, false, false).unwrap();
        for (i, &u) in s.knots_u().iter().enumerate() {
            for (j, &v) in s.knots_v().iter().enumerate() {
                assert!(s.eval(u, v).distance(*grid.get(i, j)) < 1e-12);
            }
        }
        assert_eq!(s.continuity(), 2);
        assert_c2_across_borders(&s);
    }
}

#[test]
fn closed_directions_are_periodic_and_c2_across_the_seam() {
    // A torus-like ring: closed in v (last column not repeated), open in u.
    let grid = Grid::from_fn(5, 8, |i, j| {
        let a = std::f64::consts::TAU * j as f64 / 8.0;
        let r = 2.0 + 0.3 * i as f64;
        Point::new([r * a.cos(), r * a.sin(), i as f64 * 0.5])
    });
    let s = BicubicSurface::new(&grid, GridParameterization::AveragedChord, false, true).unwrap();
    assert!(s.is_closed_v() && !s.is_closed_u());
    assert_eq!(s.knots_v().len(), 9);
    let dv = s.domain_v();
    for u in [s.knots_u()[1], 0.37] {
        for ku in 0..=2 {
            for kv in 0..=2 {
                let a = s.deriv_on_side(u, dv.end, ku, kv, Side::Above, Side::Below);
                let b = s.deriv_on_side(u, dv.start, ku, kv, Side::Above, Side::Above);
                assert!(
                    (a - b).max_abs() < 1e-9,
                    "D^({ku},{kv}) jumps across the seam"
                );
            }
        }
        assert!(s.eval(u, 0.3 + dv.length()).distance(s.eval(u, 0.3)) < 1e-12);
    }
    assert_c2_across_borders(&s);
    // The repeated column is recognised as the seam: the same surface.
    let repeated = Grid::from_fn(5, 9, |i, j| *grid.get(i, j % 8));
    let t =
        BicubicSurface::new(&repeated, GridParameterization::AveragedChord, false, true).unwrap();
    assert_eq!(t.knots_v(), s.knots_v());
    assert!(t.eval(0.4, 1.1).distance(s.eval(0.4, 1.1)) < 1e-14);
}

#[test]
fn grid_evaluation_agrees_with_pointwise() {
    let s =
        BicubicSurface::new(&sheet(6, 5), GridParameterization::default(), false, false).unwrap();
    let (nu, nv) = (13, 11);
    let mut us = vec![0.0; nu];
    let mut vs = vec![0.0; nv];
    let mut out = vec![Point3::ZERO; nu * nv];
    s.sample_grid_into(&mut us, &mut vs, &mut out);
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            assert!(out[a * nv + b].distance(s.eval(u, v)) < 1e-13);
        }
    }
}

#[test]
fn twists_do_not_depend_on_the_order_of_the_steps() {
    // Step 3 splines r_u along v; splining r_v along u instead gives the same twists (the
    // tensor product commutes): a check of the three-step algorithm against its transpose.
    let grid = sheet(6, 7);
    let s = BicubicSurface::new(&grid, GridParameterization::AveragedChord, false, false).unwrap();
    let t = BicubicSurface::from_knots(&grid.transposed(), s.knots_v(), s.knots_u(), false, false)
        .unwrap();
    for i in 0..6 {
        for j in 0..7 {
            let (ru, rv, ruv) = s.node_derivatives(i, j);
            // In the transposed surface u and v trade places.
            let (sv, su, suv) = t.node_derivatives(j, i);
            assert!((ru - su).max_abs() < 1e-12 && (rv - sv).max_abs() < 1e-12);
            assert!((ruv - suv).max_abs() < 1e-11, "twist at ({i}, {j})");
        }
    }
}

#[test]
fn bad_grids_are_errors() {
    use karkas::Error;
    let mut g = sheet(4, 4);
    *g.get_mut(2, 1) = Point::new([f64::NAN, 0.0, 0.0]);
    assert_eq!(
        BicubicSurface::new(&g, GridParameterization::Uniform, false, false),
        Err(Error::NonFiniteCell { row: 2, col: 1 })
    );
    let line = Grid::from_fn(1, 4, |_, j| Point::new([j as f64, 0.0, 0.0]));
    assert!(BicubicSurface::new(&line, GridParameterization::Uniform, false, false).is_err());
    let small = sheet(3, 2);
    assert!(BicubicSurface::new(&small, GridParameterization::Uniform, false, true).is_err());
    let twice = Grid::from_fn(3, 3, |i, j| Point::new([(i.min(1)) as f64, j as f64, 0.0]));
    assert_eq!(
        BicubicSurface::new(&twice, GridParameterization::default(), false, false),
        Err(Error::CoincidentGridLines {
            direction: "i",
            index: 1
        })
    );
    assert!(BicubicSurface::from_knots(
        &sheet(3, 3),
        &[0.0, 1.0, 1.0],
        &[0.0, 1.0, 2.0],
        false,
        false
    )
    .is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn every_node_is_reproduced(
        rows in 2usize..7,
        cols in 2usize..7,
        seed in 0u64..1000,
    ) {
        let value = |i: usize, j: usize, k: u64| {
            let x = (seed * 31 + k * 7 + (i * 13 + j * 5) as u64) as f64;
            (x * 0.618).sin()
        };
        let grid = Grid::from_fn(rows, cols, |i, j| {
            Point::new([i as f64 + 0.2 * value(i, j, 0), j as f64 + 0.2 * value(i, j, 1),
                        value(i, j, 2)])
        });
        let s = BicubicSurface::new(&grid, GridParameterization::AveragedChord, false, false)
            .unwrap();
        for i in 0..rows {
            for j in 0..cols {
                let p = s.eval(s.knots_u()[i], s.knots_v()[j]);
                prop_assert!(p.distance(*grid.get(i, j)) < 1e-12);
            }
        }
    }
}

/// A grid large enough for the parallel paths (column blocks, row solves, row blocks of the
/// grid evaluation): the node slopes equal those of the 1-D splines of the grid lines (to
/// rounding), and the grid evaluation equals point evaluation bitwise.
#[test]
fn large_grids_match_line_splines_and_grid_evaluation_is_point_evaluation() {
    use karkas::param::{CubicSpline, SplineEnds};
    let (n, m) = (230, 190);
    let grid = Grid::from_fn(n, m, |i, j| {
        let (x, y) = (i as f64 / n as f64, j as f64 / m as f64);
        Point3::new([x + 0.1 * x * x, y, (5.0 * x).sin() * (3.0 * y).cos()])
    });
    let surface = BicubicSurface::new(&grid, GridParameterization::default(), false, false)
        .expect("valid grid");
    let same = |a: Point3, b: Point3| (0..3).all(|c| a[c].to_bits() == b[c].to_bits());
    // The node slopes are derived from the B-spline form: equal to rounding.
    let close = |a: Point3, b: Point3| a.distance(b) <= 1e-12 * (1.0 + b.norm());
    for j in [0, 1, 77, m - 1] {
        let column: Vec<Point3> = (0..n).map(|i| *grid.get(i, j)).collect();
        let spline = CubicSpline::new(surface.knots_u(), &column, SplineEnds::NotAKnot).unwrap();
        for i in 0..n {
            assert!(
                close(surface.node_derivatives(i, j).0, spline.slopes()[i]),
                "ru {i} {j}"
            );
        }
    }
    for i in [0, 101, n - 1] {
        let spline =
            CubicSpline::new(surface.knots_v(), grid.row(i), SplineEnds::NotAKnot).unwrap();
        for j in 0..m {
            assert!(
                close(surface.node_derivatives(i, j).1, spline.slopes()[j]),
                "rv {i} {j}"
            );
        }
    }
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let us: Vec<f64> = (0..301).map(|k| du.uniform(k, 301)).collect();
    let vs: Vec<f64> = (0..257).map(|k| dv.uniform(k, 257)).collect();
    let mut out = vec![Point3::ZERO; us.len() * vs.len()];
    surface.eval_grid_into(&us, &vs, &mut out);
    for (a, &u) in us.iter().enumerate() {
        for (b, &v) in vs.iter().enumerate() {
            assert!(
                same(out[a * vs.len() + b], surface.eval(u, v)),
                "({u}, {v})"
            );
        }
    }
}

#[test]
fn large_surfaces_do_not_depend_on_the_thread_count() {
    // Above the parallel threshold: with one thread the work runs on the calling thread,
    // with more it is split; the net and a grid evaluation are the same bits either way.
    let (n, m) = (260, 230);
    let grid = Grid::from_fn(n, m, |i, j| {
        let (x, y) = (i as f64 / n as f64, j as f64 / m as f64);
        Point3::new([
            x + 0.2 * x * x,
            y + 0.05 * (3.0 * x).sin(),
            (6.0 * x).sin() * (4.0 * y).cos(),
        ])
    });
    let on = |threads: usize| {
        let pool = rayon::ThreadPoolBuilder::new()
            .num_threads(threads)
            .build()
            .expect("a thread pool");
        pool.install(|| {
            let s = BicubicSurface::new(&grid, GridParameterization::default(), false, false)
                .expect("valid grid");
            let (du, dv) = (s.domain_u(), s.domain_v());
            let us: Vec<f64> = (0..401).map(|k| du.uniform(k, 401)).collect();
            let vs: Vec<f64> = (0..333).map(|k| dv.uniform(k, 333)).collect();
            let mut out = vec![Point3::ZERO; us.len() * vs.len()];
            s.eval_grid_into(&us, &vs, &mut out);
            let bits: Vec<u64> = out.iter().flat_map(|p| p.0.map(f64::to_bits)).collect();
            (s, bits)
        })
    };
    let (one, one_bits) = on(1);
    for threads in [2, 3] {
        let (other, other_bits) = on(threads);
        assert!(
            one == other,
            "the surface on 1 and {threads} threads differs"
        );
        assert!(
            one_bits == other_bits,
            "the grid evaluation on 1 and {threads} threads differs"
        );
    }
}

#[test]
fn knots_a_subnormal_gap_apart_are_refused() {
    // Found by the `splines` fuzz target: the surface was built and evaluated to NaN.
    let grid = Grid::from_fn(2, 2, |i, j| {
        Point3::new([i as f64, j as f64, (i * j) as f64])
    });
    let made =
        BicubicSurface::from_knots(&grid, &[1.5e-323, 1.43e-322], &[-85.75, 15.0], false, false);
    assert!(made.is_err(), "{made:?}");
    // A normal gap of 4.5e-308 under coordinate differences of 425: the slopes overflow.
    let far = Grid::from_fn(2, 2, |i, j| Point3::new([425.0 * i as f64, j as f64, 0.0]));
    let made =
        BicubicSurface::from_knots(&far, &[1.5e-323, 4.45e-308], &[-85.75, 15.0], false, false);
    assert!(made.is_err(), "{made:?}");
}

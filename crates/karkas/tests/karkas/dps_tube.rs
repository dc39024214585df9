//! Tube surfaces by formula (3) of Malozemov et al. (the paper's §4–5; docs/methods.md §3): the skeleton lies on the
//! surface (conditions (2)), tensor-product discrete splines are reproduced exactly, and bad
//! skeletons are errors naming what is wrong.

use crate::common::Rng;
use crate::dps_reference::bspline_by_convolution;
use karkas::dps::{compatibility_residual, TubeSurface, COMPATIBILITY_TOLERANCE};
use karkas::{Error, Grid, Point, Point3};
use std::f64::consts::TAU;

/// A skeleton cut from a surface `s(p, q)`: `f_i = s(i n1, .)`, `g_j = s(., j n2)`.
fn skeleton(
    m1: usize,
    n1: usize,
    m2: usize,
    n2: usize,
    s: impl Fn(usize, usize) -> Point3,
) -> (Grid<Point3>, Grid<Point3>) {
    let along = Grid::from_fn(m1, m2 * n2, |i, q| s(i * n1, q));
    let across = Grid::from_fn(m2, m1 * n1, |j, p| s(p, j * n2));
    (along, across)
}

/// A bumpy torus sampled on the N1 x N2 grid.
fn bumpy_torus(big_n1: usize, big_n2: usize) -> impl Fn(usize, usize) -> Point3 {
    move |p, q| {
        let u = TAU * p as f64 / big_n1 as f64;
        let v = TAU * q as f64 / big_n2 as f64;
        let r = 3.0 + (1.0 + 0.3 * (3.0 * v).sin()) * u.cos();
        Point([
            r * v.cos(),
            r * v.sin(),
            0.8 * u.sin() + 0.2 * (2.0 * v).cos(),
        ])
    }
}

#[test]
fn skeleton_lies_on_the_surface() {
    for (m1, n1, m2, n2, r1, r2) in [(2, 5, 3, 40, 2, 2), (4, 3, 5, 6, 1, 3), (3, 4, 2, 7, 4, 1)] {
        let (big_n1, big_n2) = (m1 * n1, m2 * n2);
        let (along, across) = skeleton(m1, n1, m2, n2, bumpy_torus(big_n1, big_n2));
        let tube = TubeSurface::new(&along, &across, n1, n2, r1, r2).unwrap();
        assert_eq!(tube.periods(), (big_n1, big_n2));
        assert_eq!(tube.values().rows(), big_n1);
        for i in 0..m1 {
            for q in 0..big_n2 {
                let d = tube.value(i * n1, q).distance(*along.get(i, q));
                assert!(d < 1e-12, "c(i n1, q) != f_i(q) at i={i} q={q}: {d:e}");
            }
        }
        for j in 0..m2 {
            for p in 0..big_n1 {
                let d = tube.value(p, j * n2).distance(*across.get(j, p));
                assert!(d < 1e-12, "c(p, j n2) != g_j(p) at j={j} p={p}: {d:e}");
            }
        }
        // Periodic in both indices, and the closed grid repeats the seams exactly.
        assert_eq!(tube.value(big_n1 + 1, 2 * big_n2 + 3), tube.value(1, 3));
        let closed = tube.closed_grid();
        assert_eq!((closed.rows(), closed.cols()), (big_n1 + 1, big_n2 + 1));
        assert_eq!(closed.get(big_n1, 2), closed.get(0, 2));
        assert_eq!(closed.get(1, big_n2), closed.get(1, 0));
    }
}

#[test]
fn tensor_product_splines_are_reproduced() {
    // c*(p, q) = sum_{a,b} w_ab Q_r1(p - a n1) Q_r2(q - b n2): every line p = const and
    // q = const of it is a discrete spline of the right order, so formula (3) returns c*.
    let (m1, n1, m2, n2, r1, r2) = (3, 4, 4, 5, 2, 3);
    let (big_n1, big_n2) = (m1 * n1, m2 * n2);
    let q1 = bspline_by_convolution(m1, n1, r1);
    let q2 = bspline_by_convolution(m2, n2, r2);
    let mut rng = Rng::new(31);
    let weights: Vec<Point3> = rng.points(m1 * m2);
    let exact = |p: usize, q: usize| {
        let mut s = Point::ZERO;
        for a in 0..m1 {
            for b in 0..m2 {
                let wa = q1[(p + big_n1 - a * n1) % big_n1];
                let wb = q2[(q + big_n2 - b * n2) % big_n2];
                s = s.add_scaled(wa * wb, weights[a * m2 + b]);
            }
        }
        s
    };
    let (along, across) = skeleton(m1, n1, m2, n2, exact);
    let tube = TubeSurface::new(&along, &across, n1, n2, r1, r2).unwrap();
    assert_eq!(tube.orders(), (r1, r2));
    assert_eq!(tube.steps(), (n1, n2));
    for p in 0..big_n1 {
        for q in 0..big_n2 {
            let d = tube.value(p, q).distance(exact(p, q));
            assert!(d < 1e-13, "p={p} q={q}: {d:e}");
        }
    }
}

#[test]
fn incompatible_skeleton_names_the_pair() {
    let (m1, n1, m2, n2) = (3, 4, 4, 5);
    let (mut along, across) = skeleton(m1, n1, m2, n2, bumpy_torus(m1 * n1, m2 * n2));
    // Move f_2 at q = 3 n2 (where it must meet g_3) by 1e-3.
    along.get_mut(2, 3 * n2)[1] += 1e-3;
    match TubeSurface::new(&along, &across, n1, n2, 2, 2) {
        Err(Error::IncompatibleSkeleton {
            along: 2,
            across: 3,
            distance,
            tolerance,
        }) => {
            assert!((distance - 1e-3).abs() < 1e-12);
            // Relative to the diagonal of the skeleton's bounding box.
            let all: Vec<Point3> = along
                .as_slice()
                .iter()
                .chain(across.as_slice())
                .copied()
                .collect();
            let extent = |c: usize| {
                let lo = all.iter().map(|p| p[c]).fold(f64::INFINITY, f64::min);
                let hi = all.iter().map(|p| p[c]).fold(f64::NEG_INFINITY, f64::max);
                hi - lo
            };
            let diagonal = (0..3).map(|c| extent(c).powi(2)).sum::<f64>().sqrt();
            assert!((tolerance - COMPATIBILITY_TOLERANCE * diagonal).abs() < 1e-20);
        }
        other => panic!("expected IncompatibleSkeleton (2, 3), got {other:?}"),
    }
    let residual = compatibility_residual(&along, &across, n1, n2).unwrap();
    assert!((residual - 1e-3).abs() < 1e-12);
    // A mismatch far below the tolerance (relative to the model size) is accepted.
    along.get_mut(2, 3 * n2)[1] -= 1e-3 - 1e-14;
    assert!(TubeSurface::new(&along, &across, n1, n2, 2, 2).is_ok());
}

#[test]
fn bad_skeletons_are_errors() {
    let (m1, n1, m2, n2) = (2, 5, 3, 4);
    let (along, across) = skeleton(m1, n1, m2, n2, bumpy_torus(m1 * n1, m2 * n2));
    // Steps that do not match the curve lengths.
    assert!(matches!(
        TubeSurface::new(&along, &across, n1, n2 + 1, 2, 2),
        Err(Error::SkeletonLength {
            family: "along",
            expected: 15,
            got: 12,
            ..
        })
    ));
    assert!(matches!(
        TubeSurface::new(&along, &across, n1 - 1, n2, 2, 2),
        Err(Error::SkeletonLength {
            family: "across",
            expected: 8,
            got: 10,
            ..
        })
    ));
    assert_eq!(
        TubeSurface::new(&along, &across, 1, n2, 2, 2),
        Err(Error::InvalidStep { step: 1 })
    );
    assert!(matches!(
        TubeSurface::new(&along, &across, n1, n2, 0, 2),
        Err(Error::InvalidOrder { order: 0, .. })
    ));
    assert!(matches!(
        TubeSurface::new(&along, &across, n1, n2, 2, 0),
        Err(Error::InvalidOrder { order: 0, .. })
    ));
    // One curve along.
    let one = Grid::from_fn(1, m2 * n2, |_, q| *along.get(0, q));
    assert_eq!(
        TubeSurface::new(&one, &across, n1, n2, 2, 2),
        Err(Error::TooFewCurves {
            family: "along",
            needed: 2,
            got: 1
        })
    );
    // A non-finite point.
    let mut nan = across.clone();
    nan.get_mut(1, 7)[2] = f64::NAN;
    assert_eq!(
        TubeSurface::new(&along, &nan, n1, n2, 2, 2),
        Err(Error::NonFiniteSkeletonPoint {
            family: "across",
            curve: 1,
            sample: 7
        })
    );
    assert!(compatibility_residual(&one, &across, n1, n2).is_err());
}

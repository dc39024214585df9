//! Twist vectors of composite Coons surfaces (Chashnikov's §4: the cross-derivative curves
//! `A_i`, `B_j` from `d_ij`): given twists are the surface's `S_uv` at the nodes, derived
//! twists (the spline-of-derivatives rule) are exact for bicubic and bilinear polynomial
//! surfaces, and bad twist grids are errors.

use std::sync::Arc;

use crate::common::linspace;
use crate::coons_reference::{assert_close, network, tube, wavy_sheet, Analytic, Term, F1};
use karkas::coons::{derived_twists, CoonsSurface, CrossDerivatives, NetworkAxis, SplineEnds};
use karkas::{Error, Grid, Point3, Surface};

/// `S_uv` of `s` at the nodes: its exact twists.
fn exact_twists(s: &Analytic, u_axis: &NetworkAxis, v_axis: &NetworkAxis) -> Grid<Point3> {
    let (un, vn) = (u_axis.nodes(), v_axis.nodes());
    Grid::from_fn(un.len(), vn.len(), |i, j| s.deriv(un[i], vn[j], 1, 1))
}

fn term(coord: usize, coefficient: f64, fu: F1, fv: F1) -> Term {
    Term {
        coord,
        coefficient,
        fu,
        fv,
    }
}

/// A polynomial surface of degree 3 in `u` and in `v`.
fn bicubic_polynomial() -> Analytic {
    use F1::*;
    Analytic {
        terms: vec![
            term(0, 1.0, Pow(1), One),
            term(0, 0.1, Pow(2), Pow(1)),
            term(1, 1.0, One, Pow(1)),
            term(1, -0.2, Pow(1), Pow(3)),
            term(2, 0.3, Pow(3), Pow(2)),
            term(2, -0.5, Pow(2), Pow(3)),
            term(2, 0.2, Pow(3), Pow(3)),
            term(2, 1.0, Pow(1), Pow(1)),
        ],
    }
}

/// The bilinear sheet `(u, v, 0.5 + 0.3 u - 0.2 v + 0.7 u v)`.
fn bilinear_polynomial() -> Analytic {
    use F1::*;
    Analytic {
        terms: vec![
            term(0, 1.0, Pow(1), One),
            term(1, 1.0, One, Pow(1)),
            term(2, 0.5, One, One),
            term(2, 0.3, Pow(1), One),
            term(2, -0.2, One, Pow(1)),
            term(2, 0.7, Pow(1), Pow(1)),
        ],
    }
}

#[test]
fn derived_twists_are_exact_for_bicubic_and_bilinear_polynomial_surfaces() {
    let cases = [
        (
            "bicubic",
            Arc::new(bicubic_polynomial()),
            NetworkAxis::open(vec![-1.0, 0.2, 0.9, 1.4, 2.0]).unwrap(),
            NetworkAxis::open(vec![0.0, 0.7, 1.2, 2.5]).unwrap(),
        ),
        (
            "bilinear",
            Arc::new(bilinear_polynomial()),
            NetworkAxis::open(vec![0.0, 1.5]).unwrap(),
            NetworkAxis::open(vec![-0.5, 0.4, 1.0]).unwrap(),
        ),
    ];
    for (name, s, ua, va) in cases {
        let net = network(&s, &ua, &va);
        let derived = derived_twists(&net).unwrap();
        let exact = exact_twists(&s, &ua, &va);
        assert_eq!(
            (derived.rows(), derived.cols()),
            (exact.rows(), exact.cols())
        );
        for (d, e) in derived.as_slice().iter().zip(exact.as_slice()) {
            assert_close(*d, *e, 1e-11 * (1.0 + e.norm()), name);
        }
        // The composite surface of the derived twists is then the polynomial surface itself
        // (piecewise Hermite blending reproduces cubics).
        let c = CoonsSurface::composite(&net, None, 1e-9).unwrap();
        let (du, dv) = (ua.domain(), va.domain());
        for u in linspace(du.start, du.end, 17) {
            for v in linspace(dv.start, dv.end, 13) {
                assert_close(c.eval(u, v), s.eval(u, v), 1e-11, name);
            }
        }
    }
    // Not exact for a surface that is no polynomial: the rule is an estimate.
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 0.8, 1.6, 2.3, 3.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 0.7, 1.3, 2.0]).unwrap(),
    );
    let derived = derived_twists(&network(&s, &ua, &va)).unwrap();
    let exact = exact_twists(&s, &ua, &va);
    let worst = derived
        .as_slice()
        .iter()
        .zip(exact.as_slice())
        .map(|(d, e)| d.distance(*e))
        .fold(0.0, f64::max);
    assert!(worst > 1e-3, "{worst}");
}

#[test]
fn given_twists_are_the_surface_twists_and_bring_it_closer() {
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 0.8, 1.6, 2.3, 3.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 0.7, 1.3, 2.0]).unwrap(),
    );
    let net = network(&s, &ua, &va);
    let twists = exact_twists(&s, &ua, &va);
    let cross = CrossDerivatives::from_twists(&net, &twists).unwrap();
    let with = CoonsSurface::composite(&net, Some(&cross), 1e-9).unwrap();
    let without = CoonsSurface::composite(&net, None, 1e-9).unwrap();
    let gordon = CoonsSurface::gordon_spline(&net, SplineEnds::NotAKnot, 1e-9).unwrap();
    let derived = derived_twists(&net).unwrap();
    for (i, &u) in ua.nodes().iter().enumerate() {
        for (j, &v) in va.nodes().iter().enumerate() {
            // S_uv(u_i, v_j) = d_ij, and the cross-derivatives at the node are the curves'
            // tangents (conditions (11)).
            assert_close(with.deriv(u, v, 1, 1), *twists.get(i, j), 1e-10, "twist");
            assert_close(
                without.deriv(u, v, 1, 1),
                *derived.get(i, j),
                1e-10,
                "derived",
            );
            assert_close(with.deriv(u, v, 1, 0), s.deriv(u, v, 1, 0), 1e-12, "S_u");
            assert_close(with.deriv(u, v, 0, 1), s.deriv(u, v, 0, 1), 1e-12, "S_v");
        }
    }
    let (du, dv) = (ua.domain(), va.domain());
    let error = |c: &CoonsSurface<3>| {
        let mut worst: f64 = 0.0;
        for u in linspace(du.start, du.end, 61) {
            for v in linspace(dv.start, dv.end, 41) {
                worst = worst.max(c.eval(u, v).distance(s.eval(u, v)));
            }
        }
        worst
    };
    let (e_with, e_without, e_gordon) = (error(&with), error(&without), error(&gordon));
    assert!(
        e_with < 0.8 * e_without && e_with < 0.8 * e_gordon,
        "exact twists {e_with:e}, derived {e_without:e}, spline Gordon {e_gordon:e}"
    );
}

#[test]
fn twists_around_a_closed_direction_close_smoothly() {
    let s = Arc::new(tube());
    let tau = std::f64::consts::TAU;
    let ua = NetworkAxis::open(vec![0.0, 1.0, 2.2, 3.0]).unwrap();
    let va = NetworkAxis::closed(vec![0.0, 1.2, 2.5, 3.9, 5.1], tau).unwrap();
    let net = network(&s, &ua, &va);
    let twists = exact_twists(&s, &ua, &va);
    let cross = CrossDerivatives::from_twists(&net, &twists).unwrap();
    assert!(cross.v_curves.iter().all(|a| a.is_closed()));
    let c = CoonsSurface::composite(&net, Some(&cross), 1e-9).unwrap();
    let e = 1e-7;
    for u in linspace(0.1, 2.9, 8) {
        for kv in 0..2 {
            let jump = c.deriv(u, tau - e, 0, kv).distance(c.deriv(u, e, 0, kv));
            assert!(jump < 1e-5, "u={u} kv={kv}: {jump}");
        }
    }
    for (i, &u) in ua.nodes().iter().enumerate() {
        // The seam node v_0 = 0 from below (one period on) and from above.
        assert_close(c.deriv(u, 0.0, 1, 1), *twists.get(i, 0), 1e-10, "at 0");
        assert_close(c.deriv(u, tau, 1, 1), *twists.get(i, 0), 1e-10, "at tau");
    }
}

#[test]
fn twist_grids_of_the_wrong_shape_or_not_finite_are_errors() {
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 1.0, 2.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 1.0]).unwrap(),
    );
    let net = network(&s, &ua, &va);
    let transposed = Grid::from_fn(2, 3, |_, _| Point3::ZERO);
    match CrossDerivatives::from_twists(&net, &transposed) {
        Err(Error::CountMismatch {
            what,
            expected,
            got,
        }) => {
            assert_eq!(
                (what, expected, got),
                ("rows of twists (one per v-curve)", 3, 2)
            );
        }
        other => panic!("unexpected {other:?}"),
    }
    let mut nan = exact_twists(&s, &ua, &va);
    *nan.get_mut(2, 1) = Point3::new([0.0, f64::NAN, 0.0]);
    assert!(matches!(
        CrossDerivatives::from_twists(&net, &nan),
        Err(Error::NonFiniteCell { row: 2, col: 1 })
    ));
}

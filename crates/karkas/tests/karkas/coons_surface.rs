//! Generalized Coons surfaces (Chashnikov, docs/methods.md §2): Proposition 1 for every instance and
//! for the generic Boolean sum over every blending family, exact reproduction of surfaces in
//! the span of the blending functions, grid evaluation, curve types (LL curves, polylines),
//! parameters outside the domain.

use std::sync::Arc;

use crate::common::linspace;
use crate::coons_reference::{
    assert_close, cubic_in_u, exact_cross, iso, network, torus, wavy_sheet, Analytic, Dir,
};
use karkas::coons::{
    curve_ref, derived_twists, CoonsSurface, CubicHermiteBlending, CurveNetwork, CurveRef,
    FamilyRef, LagrangeBlending, LlBlending, NetworkAxis, PiecewiseHermiteBlending, PolylineCurve,
    SplineBlending, SplineEnds, DEFAULT_TOLERANCE,
};
use karkas::ll::LlCurve;
use karkas::{Interval, Point3, Surface};

/// Proposition 1, checked against independent expectations: along every curve `i` of the
/// u-family's functionals `L^u_i = d^k/du^k at u_i`, `d^kv/dv^kv (d^k c/du^k)(u_i, v)` must
/// equal `expect_v(L^u_i, v, kv)` for `kv = 0, 1, 2`; the same for the v-family.
fn check_proposition_1(
    c: &CoonsSurface<3>,
    expect_v: &dyn Fn(f64, usize, f64, usize) -> Point3,
    expect_u: &dyn Fn(f64, usize, f64, usize) -> Point3,
    tol: f64,
    what: &str,
) {
    let (du, dv) = (c.domain_u(), c.domain_v());
    for (i, l) in c.u_family().functionals().iter().enumerate() {
        for v in linspace(dv.start, dv.end, 23) {
            for kv in 0..=2 {
                let got = c.deriv(l.at(), v, l.order(), kv);
                let want = expect_v(l.at(), l.order(), v, kv);
                let scale = 1.0 + want.norm();
                assert_close(
                    got,
                    want,
                    tol * scale,
                    &format!("{what}: L^u_{i}, v={v}, kv={kv}"),
                );
            }
        }
    }
    for (j, l) in c.v_family().functionals().iter().enumerate() {
        for u in linspace(du.start, du.end, 23) {
            for ku in 0..=2 {
                let got = c.deriv(u, l.at(), ku, l.order());
                let want = expect_u(l.at(), l.order(), u, ku);
                let scale = 1.0 + want.norm();
                assert_close(
                    got,
                    want,
                    tol * scale,
                    &format!("{what}: L^v_{j}, u={u}, ku={ku}"),
                );
            }
        }
    }
}

/// Proposition 1 against the closed-form surface the data came from.
fn check_against_surface(c: &CoonsSurface<3>, s: &Analytic, tol: f64, what: &str) {
    check_proposition_1(
        c,
        &|at, k, v, kv| s.deriv(at, v, k, kv),
        &|at, k, u, ku| s.deriv(u, at, ku, k),
        tol,
        what,
    );
}

/// The generic Boolean sum of `s`'s data for any two families: `f_i = L^u_i` of `s` (a
/// function of `v`), `g_j = L^v_j` of `s`.
fn boolean_sum(s: &Arc<Analytic>, u: FamilyRef, v: FamilyRef) -> CoonsSurface<3> {
    let (du, dv) = (u.domain(), v.domain());
    let f = u
        .functionals()
        .iter()
        .map(|l| iso(s, Dir::V, l.at(), l.order(), dv, v.is_periodic()))
        .collect();
    let g = v
        .functionals()
        .iter()
        .map(|l| iso(s, Dir::U, l.at(), l.order(), du, u.is_periodic()))
        .collect();
    CoonsSurface::new(u, v, f, g, DEFAULT_TOLERANCE).unwrap()
}

#[test]
fn proposition_1_for_the_boolean_sum_over_every_family_pair() {
    let s = Arc::new(wavy_sheet());
    let u_nodes = [0.0, 0.6, 1.5, 2.2, 3.0];
    let v_nodes = [0.0, 0.5, 1.1, 2.0];
    let families_u: Vec<(&str, FamilyRef)> = vec![
        (
            "lagrange",
            Arc::new(LagrangeBlending::new(&u_nodes).unwrap()),
        ),
        (
            "hermite",
            Arc::new(CubicHermiteBlending::new(0.0, 3.0).unwrap()),
        ),
        (
            "piecewise hermite",
            Arc::new(PiecewiseHermiteBlending::new(&u_nodes).unwrap()),
        ),
        (
            "natural",
            Arc::new(SplineBlending::new(&u_nodes, SplineEnds::Natural).unwrap()),
        ),
        (
            "not-a-knot",
            Arc::new(SplineBlending::new(&u_nodes, SplineEnds::NotAKnot).unwrap()),
        ),
        (
            "ll",
            Arc::new(LlBlending::new(0.0, 3.0, 6, 3, false).unwrap()),
        ),
    ];
    let families_v: Vec<(&str, FamilyRef)> = vec![
        (
            "lagrange",
            Arc::new(LagrangeBlending::new(&v_nodes).unwrap()),
        ),
        (
            "piecewise hermite",
            Arc::new(PiecewiseHermiteBlending::new(&v_nodes).unwrap()),
        ),
        (
            "not-a-knot",
            Arc::new(SplineBlending::new(&v_nodes, SplineEnds::NotAKnot).unwrap()),
        ),
        (
            "hermite",
            Arc::new(CubicHermiteBlending::new(0.0, 2.0).unwrap()),
        ),
    ];
    for (nu, fu) in &families_u {
        for (nv, fv) in &families_v {
            let c = boolean_sum(&s, fu.clone(), fv.clone());
            check_against_surface(&c, &s, 1e-9, &format!("{nu} x {nv}"));
        }
    }
}

#[test]
fn proposition_1_for_periodic_families() {
    let s = Arc::new(torus());
    let tau = std::f64::consts::TAU;
    let u: FamilyRef = Arc::new(
        SplineBlending::new(&[0.0, 1.0, 2.5, 4.0, 5.0, tau], SplineEnds::Periodic).unwrap(),
    );
    let v: FamilyRef = Arc::new(LlBlending::new(0.0, tau, 7, 4, true).unwrap());
    let c = boolean_sum(&s, u, v);
    assert!(c.is_closed_u() && c.is_closed_v());
    check_against_surface(&c, &s, 1e-9, "periodic spline x closed LL");
    // Periodic in both parameters.
    for (u, v) in [(0.3, 1.1), (2.0, 5.9), (6.0, 0.2)] {
        assert_close(c.eval(u + tau, v - tau), c.eval(u, v), 1e-12, "period");
    }
}

/// The network of the sheet on uneven nodes and its instances.
fn sheet_network() -> (Arc<Analytic>, NetworkAxis, NetworkAxis, CurveNetwork<3>) {
    let s = Arc::new(wavy_sheet());
    let u_axis = NetworkAxis::open(vec![0.0, 0.6, 1.5, 2.2, 3.0]).unwrap();
    let v_axis = NetworkAxis::open(vec![0.0, 0.5, 1.1, 2.0]).unwrap();
    let net = network(&s, &u_axis, &v_axis);
    (s, u_axis, v_axis, net)
}

#[test]
fn proposition_1_for_every_instance() {
    let (s, u_axis, v_axis, net) = sheet_network();
    let tol = 1e-9;
    let gordon = CoonsSurface::gordon(&net, DEFAULT_TOLERANCE).unwrap();
    check_against_surface(&gordon, &s, tol, "gordon");
    for ends in [SplineEnds::Natural, SplineEnds::NotAKnot] {
        let c = CoonsSurface::gordon_spline(&net, ends, DEFAULT_TOLERANCE).unwrap();
        check_against_surface(&c, &s, tol, &format!("gordon spline {ends:?}"));
    }
    let cross = exact_cross(&s, &u_axis, &v_axis);
    let composite = CoonsSurface::composite(&net, Some(&cross), DEFAULT_TOLERANCE).unwrap();
    check_against_surface(&composite, &s, tol, "composite");
    assert_eq!(composite.u_family().len(), 10);
    assert_eq!(composite.v_family().len(), 8);

    // Two-by-two networks: bilinear and bicubic Coons on [0.5, 2] x [0.25, 1.5].
    let u2 = NetworkAxis::open(vec![0.5, 2.0]).unwrap();
    let v2 = NetworkAxis::open(vec![0.25, 1.5]).unwrap();
    let net2 = network(&s, &u2, &v2);
    let bilinear = CoonsSurface::bilinear(&net2, DEFAULT_TOLERANCE).unwrap();
    check_against_surface(&bilinear, &s, tol, "bilinear");
    let cross2 = exact_cross(&s, &u2, &v2);
    let bicubic = CoonsSurface::bicubic(&net2, Some(&cross2), DEFAULT_TOLERANCE).unwrap();
    check_against_surface(&bicubic, &s, tol, "bicubic");
    // The paper's order of the bicubic functionals: value, derivative, derivative, value.
    let orders: Vec<(f64, usize)> = bicubic
        .u_family()
        .functionals()
        .iter()
        .map(|l| (l.at(), l.order()))
        .collect();
    assert_eq!(orders, [(0.5, 0), (0.5, 1), (2.0, 1), (2.0, 0)]);
}

/// The piecewise cubic Hermite interpolant of `values` and `slopes` at `nodes`, its
/// derivative of order `k` at `t` (the piece above a node, the last piece at the end).
fn hermite_interpolant(
    nodes: &[f64],
    values: &[Point3],
    slopes: &[Point3],
    t: f64,
    k: usize,
) -> Point3 {
    let l = (0..nodes.len() - 1)
        .rev()
        .find(|&l| t >= nodes[l])
        .unwrap_or(0)
        .min(nodes.len() - 2);
    let h = nodes[l + 1] - nodes[l];
    let s = (t - nodes[l]) / h;
    // Coefficients of 1, s, s^2, s^3 of H_1..H_4 (the paper's (3)).
    let basis = [
        [1.0, 0.0, -3.0, 2.0],
        [0.0, 1.0, -2.0, 1.0],
        [0.0, 0.0, -1.0, 1.0],
        [0.0, 0.0, 3.0, -2.0],
    ];
    let eval = |c: &[f64; 4]| -> f64 {
        (k..4)
            .map(|p| {
                let falling: f64 = (0..k).map(|q| (p - q) as f64).product();
                c[p] * falling * s.powi((p - k) as i32)
            })
            .sum::<f64>()
            / h.powi(k as i32)
    };
    values[l] * eval(&basis[0])
        + slopes[l] * (h * eval(&basis[1]))
        + slopes[l + 1] * (h * eval(&basis[2]))
        + values[l + 1] * eval(&basis[3])
}

#[test]
fn derived_cross_derivatives_come_from_the_derived_twists() {
    // Chashnikov's §4: A_i(v_j) = b_j'(u_i), A_i'(v_j) = d_ij, here with the derived twists,
    // and A_i the cubic Hermite curve of these data between the nodes (same for B_j).
    let (s, u_axis, v_axis, net) = sheet_network();
    let composite = CoonsSurface::composite(&net, None, DEFAULT_TOLERANCE).unwrap();
    let d = derived_twists(&net).unwrap();
    let (un, vn) = (u_axis.nodes(), v_axis.nodes());
    let a_cross = |i: usize, v: f64, kv: usize| {
        let values: Vec<Point3> = vn.iter().map(|&vj| s.deriv(un[i], vj, 1, 0)).collect();
        hermite_interpolant(vn, &values, d.row(i), v, kv)
    };
    let b_cross = |j: usize, u: f64, ku: usize| {
        let values: Vec<Point3> = un.iter().map(|&ui| s.deriv(ui, vn[j], 0, 1)).collect();
        let slopes: Vec<Point3> = (0..un.len()).map(|i| *d.get(i, j)).collect();
        hermite_interpolant(un, &values, &slopes, u, ku)
    };
    let node = |nodes: &[f64], at: f64| nodes.iter().position(|&x| x == at).unwrap();
    check_proposition_1(
        &composite,
        &|at, k, v, kv| {
            if k == 0 {
                s.deriv(at, v, 0, kv)
            } else {
                a_cross(node(un, at), v, kv)
            }
        },
        &|at, k, u, ku| {
            if k == 0 {
                s.deriv(u, at, ku, 0)
            } else {
                b_cross(node(vn, at), u, ku)
            }
        },
        1e-9,
        "composite with derived cross-derivatives",
    );
}

#[test]
fn surfaces_in_the_span_of_the_blending_are_reproduced() {
    // (I - P)(I - Q) S = 0 when S's u-lines lie in the span of the u-blending: a surface
    // cubic in u is reproduced by the bicubic, composite, Lagrange Gordon (4 nodes in u) and
    // not-a-knot spline Gordon surfaces; a bilinear sheet by the bilinear Coons surface.
    let s = Arc::new(cubic_in_u());
    let u_axis = NetworkAxis::open(vec![-1.0, 0.2, 0.9, 2.0]).unwrap();
    let v_axis = NetworkAxis::open(vec![0.0, 0.7, 1.2, 2.5]).unwrap();
    let net = network(&s, &u_axis, &v_axis);
    let cross = exact_cross(&s, &u_axis, &v_axis);
    let surfaces = [
        ("gordon", CoonsSurface::gordon(&net, 1e-9).unwrap()),
        (
            "spline",
            CoonsSurface::gordon_spline(&net, SplineEnds::NotAKnot, 1e-9).unwrap(),
        ),
        (
            "composite",
            CoonsSurface::composite(&net, Some(&cross), 1e-9).unwrap(),
        ),
    ];
    for (name, c) in &surfaces {
        for u in linspace(-1.0, 2.0, 31) {
            for v in linspace(0.0, 2.5, 17) {
                assert_close(c.eval(u, v), s.eval(u, v), 1e-11, name);
            }
        }
    }
    let u2 = NetworkAxis::open(vec![-1.0, 2.0]).unwrap();
    let v2 = NetworkAxis::open(vec![0.0, 2.5]).unwrap();
    let bicubic = CoonsSurface::bicubic(
        &network(&s, &u2, &v2),
        Some(&exact_cross(&s, &u2, &v2)),
        1e-9,
    )
    .unwrap();
    for u in linspace(-1.0, 2.0, 13) {
        for v in linspace(0.0, 2.5, 13) {
            assert_close(bicubic.eval(u, v), s.eval(u, v), 1e-11, "bicubic");
        }
    }
    // A hyperbolic paraboloid is its own bilinear Coons surface, and straight borders give it.
    let corners = [
        Point3::new([0.0, 0.0, 0.0]),
        Point3::new([2.0, 0.0, 1.0]),
        Point3::new([0.0, 3.0, -1.0]),
        Point3::new([2.0, 3.0, 2.0]),
    ];
    let segment = |a: Point3, b: Point3| -> CurveRef<3> {
        curve_ref(PolylineCurve::new(&[a, b], &[0.0, 1.0]).unwrap())
    };
    let unit = NetworkAxis::open(vec![0.0, 1.0]).unwrap();
    let net = CurveNetwork::new(
        unit.clone(),
        vec![
            segment(corners[0], corners[2]),
            segment(corners[1], corners[3]),
        ],
        unit,
        vec![
            segment(corners[0], corners[1]),
            segment(corners[2], corners[3]),
        ],
    )
    .unwrap();
    let c = CoonsSurface::bilinear(&net, 1e-9).unwrap();
    for u in linspace(0.0, 1.0, 7) {
        for v in linspace(0.0, 1.0, 7) {
            let want = corners[0] * ((1.0 - u) * (1.0 - v))
                + corners[1] * (u * (1.0 - v))
                + corners[2] * ((1.0 - u) * v)
                + corners[3] * (u * v);
            assert_close(c.eval(u, v), want, 1e-14, "hyperbolic paraboloid");
        }
    }
}

#[test]
fn grid_evaluation_equals_pointwise_evaluation() {
    let (s, u_axis, v_axis, net) = sheet_network();
    let cross = exact_cross(&s, &u_axis, &v_axis);
    let torus = Arc::new(torus());
    let tau = std::f64::consts::TAU;
    let closed_u = NetworkAxis::closed(vec![0.0, 1.3, 2.9, 4.4], tau).unwrap();
    let closed_v = NetworkAxis::closed(vec![0.0, 2.0, 3.5, 5.0, 5.6], tau).unwrap();
    let torus_net = network(&torus, &closed_u, &closed_v);
    let surfaces = [
        CoonsSurface::gordon(&net, 1e-6).unwrap(),
        CoonsSurface::gordon_spline(&net, SplineEnds::Natural, 1e-6).unwrap(),
        CoonsSurface::composite(&net, Some(&cross), 1e-6).unwrap(),
        CoonsSurface::gordon(&torus_net, 1e-6).unwrap(),
        CoonsSurface::gordon_spline(&torus_net, SplineEnds::Natural, 1e-6).unwrap(),
        CoonsSurface::composite(&torus_net, None, 1e-6).unwrap(),
    ];
    for c in &surfaces {
        let (du, dv) = (c.domain_u(), c.domain_v());
        // Parameters beyond the domain too: clamped or wrapped.
        let us = linspace(du.start - 0.3, du.end + 0.3, 37);
        let vs = linspace(dv.start - 0.2, dv.end + 0.4, 29);
        let mut grid = vec![Point3::ZERO; us.len() * vs.len()];
        c.eval_grid_into(&us, &vs, &mut grid);
        for (a, &u) in us.iter().enumerate() {
            for (b, &v) in vs.iter().enumerate() {
                assert_close(grid[a * vs.len() + b], c.eval(u, v), 1e-12, "grid");
            }
        }
        // Derivatives on a grid, inside the domain (clamping makes one-sided derivatives
        // outside it meaningless).
        let us = linspace(du.start, du.end, 13);
        let vs = linspace(dv.start, dv.end, 11);
        let mut grid = vec![Point3::ZERO; us.len() * vs.len()];
        for (ku, kv) in [(1, 0), (0, 1), (1, 1), (2, 0)] {
            c.deriv_grid_into(&us, &vs, ku, kv, &mut grid);
            for (a, &u) in us.iter().enumerate() {
                for (b, &v) in vs.iter().enumerate() {
                    let want = c.deriv(u, v, ku, kv);
                    let tol = 1e-11 * (1.0 + want.norm());
                    assert_close(grid[a * vs.len() + b], want, tol, "derivative grid");
                }
            }
        }
    }
}

#[test]
fn open_directions_clamp_and_closed_ones_wrap() {
    let (_, _, _, net) = sheet_network();
    let c = CoonsSurface::gordon(&net, 1e-6).unwrap();
    assert_eq!(c.domain_u(), Interval::new(0.0, 3.0));
    assert_eq!(c.eval(-5.0, 0.7), c.eval(0.0, 0.7));
    assert_eq!(c.eval(1.0, 9.0), c.eval(1.0, 2.0));
    assert!(!c.eval(f64::NAN, 0.5).is_finite());
}

#[test]
fn any_curve_type_is_boundary_data() {
    // LL curves and polylines, each with its own parameter interval, stretched onto the
    // network's: the surface passes through them.
    let pts =
        |f: &dyn Fn(f64) -> Point3| -> Vec<Point3> { (0..9).map(|k| f(k as f64 / 8.0)).collect() };
    let a0 = pts(&|t| Point3::new([0.0, 2.0 * t, 0.3 * (3.0 * t).sin()]));
    let a1 = pts(&|t| Point3::new([2.0, 2.0 * t, 0.5 * t * t]));
    let b0 = pts(&|t| Point3::new([2.0 * t, 0.0, 0.2 * (2.0 * t).sin() * (2.0 * t - 2.0)]));
    let b1 = pts(&|t| Point3::new([2.0 * t, 2.0, 0.3 * (3.0f64).sin() * (1.0 - t) + 0.5 * t]));
    let ll = |p: &[Point3]| curve_ref(LlCurve::interpolating(p, 4, false).unwrap());
    let poly = |p: &[Point3]| curve_ref(PolylineCurve::chord_length(p).unwrap());
    let unit = NetworkAxis::open(vec![0.0, 1.0]).unwrap();
    let v_curves = vec![ll(&a0), poly(&a1)];
    let u_curves = vec![poly(&b0), ll(&b1)];
    let net = CurveNetwork::new(unit.clone(), v_curves.clone(), unit, u_curves.clone()).unwrap();
    let c = CoonsSurface::bilinear(&net, 1e-9).unwrap();
    for t in linspace(0.0, 1.0, 41) {
        let on = |curve: &CurveRef<3>| {
            let d = curve.domain();
            curve.eval(d.start + t * d.length())
        };
        assert_close(c.eval(0.0, t), on(&v_curves[0]), 1e-12, "v-curve 0 (LL)");
        assert_close(
            c.eval(1.0, t),
            on(&v_curves[1]),
            1e-12,
            "v-curve 1 (polyline)",
        );
        assert_close(
            c.eval(t, 0.0),
            on(&u_curves[0]),
            1e-12,
            "u-curve 0 (polyline)",
        );
        assert_close(c.eval(t, 1.0), on(&u_curves[1]), 1e-12, "u-curve 1 (LL)");
    }
}

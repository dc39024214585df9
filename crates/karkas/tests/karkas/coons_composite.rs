//! Composite Coons surfaces (Chashnikov's §4–5): Proposition 2 against the patch-by-patch
//! surface (13) written here from the paper's formulas (4) and (12), the properties (14)
//! (C^1, interpolated curves and cross-derivatives), closed directions, and the
//! compatibility errors of (8) / (11).

use std::sync::Arc;

use crate::common::linspace;
use crate::coons_reference::{
    assert_close, exact_cross, iso, network, tube, wavy_sheet, Analytic, Dir, Term, F1,
};
use karkas::coons::{CoonsSurface, CrossDerivatives, CurveNetwork, NetworkAxis, SplineEnds};
use karkas::{Error, Interval, Point3, Surface};

/// The cubic Hermite polynomials of the paper's (3), written out again.
fn hermite(x: f64) -> [f64; 4] {
    [
        2.0 * x * x * x - 3.0 * x * x + 1.0,
        x * x * x - 2.0 * x * x + x,
        x * x * x - x * x,
        -2.0 * x * x * x + 3.0 * x * x,
    ]
}

/// The patch-by-patch composite Coons surface (13) of the network of `s` on the nodes, with
/// the exact cross-derivatives `A_i = s_u(u_i, .)`, `B_j = s_v(., v_j)`. On the patch
/// `[u_i, u_{i+1}] x [v_j, v_{j+1}]` the bicubic Coons surface (4) of the boundary curves (12)
/// in the local parameters `x, y` in `[0, 1]` (derivatives per unit of `x`, `y`: the paper's
/// integer nodes have `h = 1`).
fn patch_by_patch(s: &Analytic, us: &[f64], vs: &[f64], alpha: f64, beta: f64) -> Point3 {
    let piece = |nodes: &[f64], t: f64| {
        (0..nodes.len() - 1)
            .find(|&i| t <= nodes[i + 1])
            .unwrap_or(nodes.len() - 2)
    };
    let (i, j) = (piece(us, alpha), piece(vs, beta));
    let (u0, u1, v0, v1) = (us[i], us[i + 1], vs[j], vs[j + 1]);
    let (hu, hv) = (u1 - u0, v1 - v0);
    let (x, y) = ((alpha - u0) / hu, (beta - v0) / hv);
    let (u, v) = (alpha, beta);
    // (12): f_1 = a_i, f_2 = A_i, f_3 = A_{i+1}, f_4 = a_{i+1} at the point's v.
    let f = [
        s.deriv(u0, v, 0, 0),
        s.deriv(u0, v, 1, 0) * hu,
        s.deriv(u1, v, 1, 0) * hu,
        s.deriv(u1, v, 0, 0),
    ];
    let g = [
        s.deriv(u, v0, 0, 0),
        s.deriv(u, v0, 0, 1) * hv,
        s.deriv(u, v1, 0, 1) * hv,
        s.deriv(u, v1, 0, 0),
    ];
    // L_k(g_l): L_1 g = g(0), L_2 g = g'(0), L_3 g = g'(1), L_4 g = g(1), in x.
    let at_u = [(u0, 0), (u0, 1), (u1, 1), (u1, 0)];
    let at_v = [(v0, 0), (v0, 1), (v1, 1), (v1, 0)];
    let (hx, hy) = (hermite(x), hermite(y));
    let mut c = Point3::ZERO;
    for k in 0..4 {
        c = c + f[k] * hx[k] + g[k] * hy[k];
        for l in 0..4 {
            let (uk, ku) = at_u[k];
            let (vl, kv) = at_v[l];
            let corner = s.deriv(uk, vl, ku, kv) * (hu.powi(ku as i32) * hv.powi(kv as i32));
            c -= corner * (hx[k] * hy[l]);
        }
    }
    c
}

#[test]
fn proposition_2_generalized_equals_patch_by_patch() {
    let s = Arc::new(wavy_sheet());
    // The paper's integer nodes (m = 3, n = 2), then uneven ones.
    let cases = [
        (vec![0.0, 1.0, 2.0, 3.0], vec![0.0, 1.0, 2.0]),
        (vec![0.0, 0.4, 1.5, 1.9, 3.0], vec![-0.5, 0.3, 0.6, 2.0]),
    ];
    for (un, vn) in cases {
        let (ua, va) = (
            NetworkAxis::open(un.clone()).unwrap(),
            NetworkAxis::open(vn.clone()).unwrap(),
        );
        let c = CoonsSurface::composite(
            &network(&s, &ua, &va),
            Some(&exact_cross(&s, &ua, &va)),
            1e-9,
        )
        .unwrap();
        let (du, dv) = (ua.domain(), va.domain());
        // Interior points, patch borders and corners.
        let mut alphas = linspace(du.start, du.end, 29);
        alphas.extend_from_slice(&un);
        let mut betas = linspace(dv.start, dv.end, 23);
        betas.extend_from_slice(&vn);
        for &a in &alphas {
            for &b in &betas {
                let want = patch_by_patch(&s, &un, &vn, a, b);
                assert_close(c.eval(a, b), want, 1e-12, &format!("({a}, {b})"));
            }
        }
    }
}

#[test]
fn bicubic_coons_is_the_one_patch_composite() {
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.2, 1.7]).unwrap(),
        NetworkAxis::open(vec![0.1, 1.3]).unwrap(),
    );
    let (net, cross) = (network(&s, &ua, &va), exact_cross(&s, &ua, &va));
    let bicubic = CoonsSurface::bicubic(&net, Some(&cross), 1e-9).unwrap();
    let composite = CoonsSurface::composite(&net, Some(&cross), 1e-9).unwrap();
    for u in linspace(0.2, 1.7, 11) {
        for v in linspace(0.1, 1.3, 11) {
            assert_close(bicubic.eval(u, v), composite.eval(u, v), 1e-13, "bicubic");
            assert_close(
                bicubic.eval(u, v),
                patch_by_patch(&s, &[0.2, 1.7], &[0.1, 1.3], u, v),
                1e-13,
                "bicubic vs (4)",
            );
        }
    }
}

#[test]
fn composite_surface_is_c1_with_the_given_cross_derivatives() {
    // (14): s in C^1, s_uv continuous; s(u_i, .) = a_i, s_u(u_i, .) = A_i (and in v). The
    // second derivative across a patch border jumps in general (so the test can tell C^1
    // from C^2).
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 0.8, 1.6, 3.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 0.9, 2.0]).unwrap(),
    );
    let c = CoonsSurface::composite(
        &network(&s, &ua, &va),
        Some(&exact_cross(&s, &ua, &va)),
        1e-9,
    )
    .unwrap();
    let e = 1e-7;
    let mut biggest_jump: f64 = 0.0;
    for &u in &ua.nodes()[1..3] {
        for v in linspace(0.05, 1.95, 9) {
            for (ku, kv) in [(0, 0), (1, 0), (0, 1), (1, 1)] {
                let below = c.deriv(u - e, v, ku, kv);
                let above = c.deriv(u + e, v, ku, kv);
                assert_close(below, above, 1e-5, &format!("C^1 across u = {u}"));
            }
            assert_close(c.deriv(u, v, 1, 0), s.deriv(u, v, 1, 0), 1e-12, "s_u = A_i");
            let jump = c.deriv(u - e, v, 2, 0).distance(c.deriv(u + e, v, 2, 0));
            biggest_jump = biggest_jump.max(jump);
        }
    }
    assert!(biggest_jump > 1e-3, "s_uu should jump: {biggest_jump}");
    let u = 1.1;
    let v = va.nodes()[1];
    for (ku, kv) in [(1, 0), (0, 1), (1, 1)] {
        assert_close(
            c.deriv(u, v - e, ku, kv),
            c.deriv(u, v + e, ku, kv),
            1e-5,
            "C^1 in v",
        );
    }
    assert_close(c.deriv(u, v, 0, 1), s.deriv(u, v, 0, 1), 1e-12, "s_v = B_j");
}

#[test]
fn closed_directions_close_smoothly() {
    // A tube: open along u, closed around v (period 2 pi). Composite (cross-derivatives from
    // the derived twists, periodic splines around), spline Gordon and Lagrange Gordon all pass through
    // the network; the composite is C^1 and the spline Gordon C^2 across the seam v = 0, the
    // Lagrange one only C^0.
    let s = Arc::new(tube());
    let tau = std::f64::consts::TAU;
    let ua = NetworkAxis::open(vec![0.0, 1.0, 2.2, 3.0]).unwrap();
    let va = NetworkAxis::closed(vec![0.0, 1.2, 2.5, 3.9, 5.1], tau).unwrap();
    let net = network(&s, &ua, &va);
    let composite = CoonsSurface::composite(&net, None, 1e-9).unwrap();
    let spline = CoonsSurface::gordon_spline(&net, SplineEnds::NotAKnot, 1e-9).unwrap();
    let lagrange = CoonsSurface::gordon(&net, 1e-9).unwrap();
    for c in [&composite, &spline, &lagrange] {
        assert!(!c.is_closed_u() && c.is_closed_v());
        assert_eq!(c.domain_v(), Interval::new(0.0, tau));
        for u in linspace(0.0, 3.0, 13) {
            for &v in va.nodes() {
                assert_close(c.eval(u, v), s.eval(u, v), 1e-12, "u-curves");
            }
            for v in linspace(0.0, tau, 17) {
                for &ui in ua.nodes() {
                    assert_close(c.eval(ui, v), s.eval(ui, v), 1e-12, "v-curves");
                }
                assert_close(c.eval(u, v + tau), c.eval(u, v), 1e-12, "periodic");
            }
        }
    }
    let e = 1e-7;
    let seam = |c: &CoonsSurface<3>, kv: usize| {
        linspace(0.1, 2.9, 8)
            .into_iter()
            .map(|u| c.deriv(u, tau - e, 0, kv).distance(c.deriv(u, e, 0, kv)))
            .fold(0.0, f64::max)
    };
    assert!(seam(&composite, 1) < 1e-5, "composite C^1 seam");
    assert!(
        seam(&spline, 1) < 1e-5 && seam(&spline, 2) < 1e-4,
        "spline C^2 seam"
    );
    assert!(seam(&lagrange, 1) > 1e-3, "Lagrange seam has a kink");
}

#[test]
fn incompatible_values_are_an_error_naming_the_pair() {
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 1.0, 2.0, 3.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 0.7, 1.4, 2.0]).unwrap(),
    );
    let good = network(&s, &ua, &va);
    // u-curve 2 moved by 1e-3 (the model is about 4 across): misses every v-curve.
    let moved = Arc::new(Analytic {
        terms: {
            let mut t = wavy_sheet().terms;
            t.push(Term {
                coord: 2,
                coefficient: 1e-3,
                fu: F1::One,
                fv: F1::One,
            });
            t
        },
    });
    let mut u_curves = good.u_curves().to_vec();
    u_curves[2] = iso(&moved, Dir::U, 1.4, 0, ua.domain(), false);
    let bad =
        CurveNetwork::new(ua.clone(), good.v_curves().to_vec(), va.clone(), u_curves).unwrap();
    for (kind, result) in [
        ("gordon", CoonsSurface::gordon(&bad, 1e-6)),
        (
            "spline",
            CoonsSurface::gordon_spline(&bad, SplineEnds::Natural, 1e-6),
        ),
        ("composite", CoonsSurface::composite(&bad, None, 1e-6)),
    ] {
        let e = result.expect_err(kind);
        match &e {
            Error::IncompatibleCurves {
                first,
                second,
                u,
                v,
                mismatch,
                tolerance,
                ..
            } => {
                assert_eq!(
                    (first.as_str(), second.as_str()),
                    ("v-curve 0", "u-curve 2"),
                    "{kind}"
                );
                assert_eq!((*u, *v), (0.0, 1.4), "{kind}");
                assert!((mismatch - 1e-3).abs() < 1e-12, "{kind}: {mismatch}");
                assert!(*tolerance < 1e-5, "{kind}");
            }
            other => panic!("{kind}: unexpected {other:?}"),
        }
        let text = e.to_string();
        assert!(
            text.starts_with("v-curve 0 and u-curve 2 disagree at (u=0, v=1.4): the value of u-curve 2 and the value of v-curve 0 differ by 1.000e-3"),
            "{text}"
        );
    }
    // The same move within the tolerance is accepted.
    assert!(CoonsSurface::gordon(&bad, 1e-3).is_ok());
}

#[test]
fn incompatible_cross_derivatives_are_an_error_naming_the_curves() {
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 1.0, 2.0, 3.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 1.0, 2.0]).unwrap(),
    );
    let net = network(&s, &ua, &va);
    let exact = exact_cross(&s, &ua, &va);
    // A_1 replaced by the second derivative across: wrong at every crossing with a u-curve
    // (condition (11): A_i(v_j) = b_j'(u_i)).
    let mut v_cross = exact.v_curves.clone();
    v_cross[1] = iso(&s, Dir::V, 1.0, 2, va.domain(), false);
    let cross = CrossDerivatives {
        v_curves: v_cross,
        u_curves: exact.u_curves.clone(),
    };
    let e = CoonsSurface::composite(&net, Some(&cross), 1e-6).unwrap_err();
    match &e {
        Error::IncompatibleCurves {
            first,
            second,
            u,
            v,
            condition,
            ..
        } => {
            assert_eq!(first, "the cross-derivative curve of v-curve 1");
            assert_eq!(second, "u-curve 0");
            assert_eq!((*u, *v), (1.0, 0.0));
            assert_eq!(
                condition,
                "d/du of u-curve 0 and the value of the cross-derivative curve of v-curve 1"
            );
        }
        other => panic!("unexpected {other:?}"),
    }
    // Cross-derivative counts must match the network.
    let short = CrossDerivatives {
        v_curves: exact.v_curves[..3].to_vec(),
        u_curves: exact.u_curves.clone(),
    };
    assert!(matches!(
        CoonsSurface::composite(&net, Some(&short), 1e-6),
        Err(Error::CountMismatch { .. })
    ));
}

#[test]
fn network_shapes_are_checked() {
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 1.0, 2.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 1.0]).unwrap(),
    );
    let net = network(&s, &ua, &va);
    // Bilinear and bicubic need two curves per direction.
    assert!(CoonsSurface::bilinear(&net, 1e-6).is_err());
    assert!(CoonsSurface::bicubic(&net, None, 1e-6).is_err());
    // Curve counts must match the node counts; closed curves need a closed direction.
    let too_few = CurveNetwork::new(
        ua.clone(),
        net.v_curves()[..2].to_vec(),
        va.clone(),
        net.u_curves().to_vec(),
    );
    assert!(too_few.is_err());
    let closed = iso(&s, Dir::V, 0.0, 0, va.domain(), true);
    let mixed = CurveNetwork::new(
        ua,
        vec![closed, net.v_curves()[1].clone(), net.v_curves()[2].clone()],
        va,
        net.u_curves().to_vec(),
    );
    assert!(mixed.is_err());
    assert!(NetworkAxis::open(vec![0.0, 0.0]).is_err());
    assert!(NetworkAxis::closed(vec![0.0, 1.0, 2.0], 1.5).is_err());
    assert!(NetworkAxis::closed(vec![0.0, 1.0], 3.0).is_err());
    // A negative or non-finite tolerance is refused.
    let net2 = network(
        &s,
        &NetworkAxis::open(vec![0.0, 1.0]).unwrap(),
        &NetworkAxis::open(vec![0.0, 1.0]).unwrap(),
    );
    assert!(CoonsSurface::bilinear(&net2, -1.0).is_err());
    assert!(CoonsSurface::bilinear(&net2, f64::NAN).is_err());
}

/// A curve moved by a constant vector.
struct Lifted {
    inner: karkas::coons::CurveRef<3>,
    by: Point3,
}

impl karkas::Curve<3> for Lifted {
    fn domain(&self) -> Interval {
        self.inner.domain()
    }
    fn is_closed(&self) -> bool {
        self.inner.is_closed()
    }
    fn eval(&self, t: f64) -> Point3 {
        self.inner.eval(t) + self.by
    }
    fn deriv(&self, t: f64, k: usize) -> Point3 {
        if k == 0 {
            self.eval(t)
        } else {
            self.inner.deriv(t, k)
        }
    }
}

#[test]
fn repair_snaps_to_the_mean_and_the_surface_interpolates_the_repaired_curves() {
    use karkas::coons::Compatibility;
    let s = Arc::new(wavy_sheet());
    let (ua, va) = (
        NetworkAxis::open(vec![0.0, 0.8, 1.6, 3.0]).unwrap(),
        NetworkAxis::open(vec![0.0, 0.9, 2.0]).unwrap(),
    );
    let net = network(&s, &ua, &va);
    let exact = exact_cross(&s, &ua, &va);
    // B_1 lifted by 0.01 in z: it disagrees with a_i'(v_1) by 0.01 at every u_i.
    let lift = Point3::new([0.0, 0.0, 0.01]);
    let mut u_cross = exact.u_curves.clone();
    u_cross[1] = Arc::new(Lifted {
        inner: u_cross[1].clone(),
        by: lift,
    });
    let cross = CrossDerivatives {
        v_curves: exact.v_curves.clone(),
        u_curves: u_cross,
    };
    let refused = CoonsSurface::composite(&net, Some(&cross), 1e-6).unwrap_err();
    assert!(matches!(refused, Error::IncompatibleCurves { .. }));
    let checked = CoonsSurface::composite(&net, Some(&exact), 1e-9).unwrap();
    assert!(checked.repair().is_none());

    let c = CoonsSurface::composite(&net, Some(&cross), Compatibility::Repair).unwrap();
    let repair = c.repair().unwrap();
    assert!((repair.correction - 0.005).abs() < 1e-12, "{repair:?}");
    // (Every v-curve meets the lifted B_1 with the same mismatch: any of them may be named.)
    assert!(
        repair.condition.starts_with(
            "the value of the cross-derivative curve of u-curve 1 and d/dv of v-curve "
        ),
        "{repair:?}"
    );
    assert_eq!(repair.v, 0.9);
    // Proposition 1 for the repaired curves (15): c(u_i, .) = f_2i, c_u(u_i, .) = f_2i+1,
    // c(., v_j) = g_2j, c_v(., v_j) = g_2j+1.
    for (i, &u) in ua.nodes().iter().enumerate() {
        for v in linspace(0.0, 2.0, 17) {
            let f = c.v_curves();
            assert_close(c.eval(u, v), f[2 * i].eval(v), 1e-12, "c(u_i, v)");
            assert_close(
                c.deriv(u, v, 1, 0),
                f[2 * i + 1].eval(v),
                1e-12,
                "c_u(u_i, v)",
            );
        }
    }
    for (j, &v) in va.nodes().iter().enumerate() {
        for u in linspace(0.0, 3.0, 17) {
            let g = c.u_curves();
            assert_close(c.eval(u, v), g[2 * j].eval(u), 1e-12, "c(u, v_j)");
            assert_close(
                c.deriv(u, v, 0, 1),
                g[2 * j + 1].eval(u),
                1e-12,
                "c_v(u, v_j)",
            );
        }
    }
    // The repaired data are the means: at every crossing of v = 0.9, dS/dv is the exact one
    // plus half the lift; elsewhere the surface keeps the exact data.
    for &u in ua.nodes() {
        assert_close(
            c.deriv(u, 0.9, 0, 1),
            s.deriv(u, 0.9, 0, 1) + lift * 0.5,
            1e-12,
            "mean",
        );
        assert_close(c.eval(u, 0.9), s.eval(u, 0.9), 1e-12, "crossing");
        assert_close(c.deriv(u, 0.0, 0, 1), s.deriv(u, 0.0, 0, 1), 1e-12, "B_0");
    }
}

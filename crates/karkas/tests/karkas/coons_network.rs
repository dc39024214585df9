//! Curve networks from point lists (`PointNetwork`): crossings found as shared points, node
//! values, reparameterization of unevenly sampled curves, closed families rotated to their
//! seam, cross-derivative data, and every network error.

use crate::common::linspace;
use crate::coons_reference::{tube, wavy_sheet, Analytic};
use karkas::coons::{CoonsSurface, CurveFit, PointNetwork, SplineEnds};
use karkas::{Error, Point3, Surface};

/// Points of the sheet's line `u = u` at the given `v`s (a v-curve).
fn v_curve(s: &Analytic, u: f64, vs: &[f64]) -> Vec<Point3> {
    vs.iter().map(|&v| s.eval(u, v)).collect()
}

/// Points of the line `v = v` at the given `u`s (a u-curve).
fn u_curve(s: &Analytic, v: f64, us: &[f64]) -> Vec<Point3> {
    us.iter().map(|&u| s.eval(u, v)).collect()
}

/// The largest distance between the surface and `s` at equal parameters, over a grid.
fn deviation(c: &CoonsSurface<3>, s: &Analytic, map: &dyn Fn(f64, f64) -> (f64, f64)) -> f64 {
    let (du, dv) = (c.domain_u(), c.domain_v());
    let mut worst: f64 = 0.0;
    for u in linspace(du.start, du.end, 41) {
        for v in linspace(dv.start, dv.end, 41) {
            let (a, b) = map(u, v);
            worst = worst.max(c.eval(u, v).distance(s.eval(a, b)));
        }
    }
    worst
}

#[test]
fn a_regularly_sampled_network_keeps_the_point_index_parameter() {
    // The sheet over [0, 3] x [0, 2]: 5 v-curves at u = 0, 0.75, .., 3 with 41 points each
    // (v = k/20), 3 u-curves at v = 0, 1, 2 with 33 points each (u = 3k/32). Crossings at the
    // same point indices on every curve, so the node values are the index parameters.
    let s = wavy_sheet();
    let vs = linspace(0.0, 2.0, 41);
    let us = linspace(0.0, 3.0, 33);
    let v_lists: Vec<_> = (0..5).map(|i| v_curve(&s, 0.75 * i as f64, &vs)).collect();
    let u_lists: Vec<_> = (0..3).map(|j| u_curve(&s, j as f64, &us)).collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    let n = net.network();
    assert_eq!(n.u_axis().nodes(), &[0.0, 0.25, 0.5, 0.75, 1.0]);
    assert_eq!(n.v_axis().nodes(), &[0.0, 0.5, 1.0]);
    assert!(!n.u_axis().is_closed() && !n.v_axis().is_closed());
    // Every curve passes through its points at the point-index parameters.
    for (i, list) in v_lists.iter().enumerate() {
        for (k, p) in list.iter().enumerate() {
            let got = n.v_curves()[i].eval(k as f64 / 40.0);
            assert!(got.distance(*p) < 1e-12, "v-curve {i}, point {k}");
        }
    }
    for (j, list) in u_lists.iter().enumerate() {
        for (k, p) in list.iter().enumerate() {
            let got = n.u_curves()[j].eval(k as f64 / 32.0);
            assert!(got.distance(*p) < 1e-12, "u-curve {j}, point {k}");
        }
    }
    // The spline Gordon surface through it is close to the sheet (parameters scaled).
    let c = CoonsSurface::gordon_spline(n, SplineEnds::NotAKnot, 1e-6).unwrap();
    let dev = deviation(&c, &s, &|u, v| (3.0 * u, 2.0 * v));
    assert!(dev < 0.05, "deviation {dev}");
}

#[test]
fn unevenly_sampled_curves_are_reparameterized_through_their_crossings() {
    // Each v-curve sampled differently (its own point count and spacing), but through the
    // three u-curves' lines v = 0, 0.8, 2; each u-curve likewise through the v-curves' lines.
    let s = wavy_sheet();
    let u_lines = [0.0, 1.1, 1.9, 3.0];
    let v_lines = [0.0, 0.8, 2.0];
    let samples = |lines: &[f64], per_span: &[usize], power: f64| -> Vec<f64> {
        let mut out = vec![lines[0]];
        for (w, &k) in lines.windows(2).zip(per_span) {
            for q in 1..=k {
                let x = (q as f64 / k as f64).powf(power);
                out.push(w[0] + (w[1] - w[0]) * x);
            }
        }
        out
    };
    let v_lists: Vec<_> = u_lines
        .iter()
        .enumerate()
        .map(|(i, &u)| {
            v_curve(
                &s,
                u,
                &samples(&v_lines, &[6 + i, 12 - 2 * i], 1.0 + 0.1 * i as f64),
            )
        })
        .collect();
    let u_lists: Vec<_> = v_lines
        .iter()
        .enumerate()
        .map(|(j, &v)| u_curve(&s, v, &samples(&u_lines, &[5 + j, 7, 9 - j], 1.0)))
        .collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    let n = net.network();
    let (un, vn) = (n.u_axis().nodes().to_vec(), n.v_axis().nodes().to_vec());
    // Node values: the mean crossing parameters; ends at 0 and 1.
    assert_eq!((un[0], vn[0]), (0.0, 0.0));
    assert!((un[3] - 1.0).abs() < 1e-15 && (vn[2] - 1.0).abs() < 1e-15);
    let mean_v1: f64 = (0..4)
        .map(|i| (6 + i) as f64 / (6 + i + 12 - 2 * i) as f64)
        .sum::<f64>()
        / 4.0;
    assert!((vn[1] - mean_v1).abs() < 1e-15, "{} vs {mean_v1}", vn[1]);
    // Every curve passes through its crossings exactly at the node values.
    for (i, &u) in un.iter().enumerate() {
        for (j, &v) in vn.iter().enumerate() {
            let p = s.eval(u_lines[i], v_lines[j]);
            assert!(
                n.v_curves()[i].eval(v).distance(p) < 1e-12,
                "v-curve {i} at v_{j}"
            );
            assert!(
                n.u_curves()[j].eval(u).distance(p) < 1e-12,
                "u-curve {j} at u_{i}"
            );
        }
    }
    // Smooth in the network parameter: derivatives match differences.
    for c in n.v_curves().iter().chain(n.u_curves()) {
        for t in [0.1, 0.37, 0.52, 0.9] {
            for k in 0..3 {
                let e = 1e-6;
                let fd = (c.deriv(t + e, k) - c.deriv(t - e, k)) * (0.5 / e);
                let d = c.deriv(t, k + 1);
                assert!(
                    fd.distance(d) < 1e-4 * (1.0 + d.norm()),
                    "k={k} t={t}: {fd:?} vs {d:?}"
                );
            }
        }
    }
    // All surfaces build (the network is compatible) and follow the sheet.
    for c in [
        CoonsSurface::gordon(n, 1e-6).unwrap(),
        CoonsSurface::gordon_spline(n, SplineEnds::NotAKnot, 1e-6).unwrap(),
        CoonsSurface::composite(n, None, 1e-6).unwrap(),
    ] {
        for (i, &u) in un.iter().enumerate() {
            for (j, &v) in vn.iter().enumerate() {
                let p = s.eval(u_lines[i], v_lines[j]);
                assert!(c.eval(u, v).distance(p) < 1e-12);
            }
        }
    }
}

#[test]
fn closed_curves_make_a_closed_direction_starting_at_the_first_crossing() {
    // A tube: 4 closed frames (v-curves around, 24 points each, each list starting at a
    // different point), 6 open stringers (u-curves along).
    let s = tube();
    let tau = std::f64::consts::TAU;
    let stations = [0.0, 1.0, 2.0, 3.0];
    let angles: Vec<f64> = (0..6).map(|j| tau * j as f64 / 6.0).collect();
    let v_lists: Vec<Vec<Point3>> = stations
        .iter()
        .enumerate()
        .map(|(i, &u)| {
            let mut pts: Vec<Point3> = (0..24)
                .map(|k| s.eval(u, tau * ((k + 4 * i) % 24) as f64 / 24.0))
                .collect();
            pts.push(pts[0]);
            pts
        })
        .collect();
    let u_lists: Vec<Vec<Point3>> = angles
        .iter()
        .map(|&v| u_curve(&s, v, &linspace(0.0, 3.0, 13)))
        .collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    let n = net.network();
    assert!(n.v_axis().is_closed() && !n.u_axis().is_closed());
    assert_eq!(n.v_axis().period(), Some(1.0));
    let vn = n.v_axis().nodes();
    for (j, &v) in vn.iter().enumerate() {
        assert!((v - j as f64 / 6.0).abs() < 1e-15);
    }
    let c = CoonsSurface::gordon_spline(n, SplineEnds::NotAKnot, 1e-6).unwrap();
    assert!(c.is_closed_v());
    let dev = deviation(&c, &s, &|u, v| (3.0 * u, tau * v));
    assert!(dev < 0.02, "deviation {dev}");
    // The frames start at stringer 0 after rotation.
    for (i, &u) in n.u_axis().nodes().iter().enumerate() {
        assert!(n.v_curves()[i].eval(0.0).distance(s.eval(3.0 * u, 0.0)) < 1e-12);
    }
}

#[test]
fn cross_derivative_data_follow_their_curves() {
    let s = wavy_sheet();
    let vs = linspace(0.0, 2.0, 21);
    let us = linspace(0.0, 3.0, 31);
    let v_lists: Vec<_> = (0..3).map(|i| v_curve(&s, 1.5 * i as f64, &vs)).collect();
    let u_lists: Vec<_> = (0..3).map(|j| u_curve(&s, j as f64, &us)).collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).unwrap();
    // dS/du per unit of the network's u (which runs 0..1 over u = 0..3): 3 s_u.
    let v_derivs: Vec<Vec<Point3>> = (0..3)
        .map(|i| {
            vs.iter()
                .map(|&v| s.deriv(1.5 * i as f64, v, 1, 0) * 3.0)
                .collect()
        })
        .collect();
    let u_derivs: Vec<Vec<Point3>> = (0..3)
        .map(|j| {
            us.iter()
                .map(|&u| s.deriv(u, j as f64, 0, 1) * 2.0)
                .collect()
        })
        .collect();
    let cross = net.cross_derivatives(&v_derivs, &u_derivs).unwrap();
    let n = net.network();
    // The interpolated cross-derivatives pass through the data at the points' parameters.
    for (k, d) in v_derivs[1].iter().enumerate() {
        let t = k as f64 / 20.0;
        assert!(cross.v_curves[1].eval(t).distance(*d) < 1e-12);
    }
    // Interpolated curves agree with the exact derivatives only to the interpolation error:
    // a composite surface accepts them at a tolerance of that size and refuses at 1e-9.
    let c = CoonsSurface::composite(n, Some(&cross), 1e-3).unwrap();
    assert!(c.eval(0.5, 0.5).distance(s.eval(1.5, 1.0)) < 1e-12);
    assert!(matches!(
        CoonsSurface::composite(n, Some(&cross), 1e-9),
        Err(Error::IncompatibleCurves { .. })
    ));
    // Counts must match the curves'.
    assert!(net.cross_derivatives(&v_derivs[..2], &u_derivs).is_err());
    let mut short = v_derivs.clone();
    short[0].pop();
    assert!(net.cross_derivatives(&short, &u_derivs).is_err());
}

#[test]
fn network_errors_name_the_curves() {
    let s = wavy_sheet();
    let vs = linspace(0.0, 2.0, 21);
    let us = linspace(0.0, 3.0, 31);
    let v_lists: Vec<_> = (0..3).map(|i| v_curve(&s, 1.5 * i as f64, &vs)).collect();
    let u_lists: Vec<_> = (0..3).map(|j| u_curve(&s, j as f64, &us)).collect();
    assert!(PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, 1e-9).is_ok());

    // u-curve 1 lifted off the v-curves: no common point with v-curve 0.
    let mut lifted = u_lists.clone();
    for p in &mut lifted[1] {
        p[2] += 0.01;
    }
    match PointNetwork::new(&v_lists, &lifted, CurveFit::CubicSpline, 1e-9) {
        Err(Error::NetworkCrossing {
            v_curve: 0,
            u_curve: 1,
            problem,
        }) => assert!(problem.contains("no common point"), "{problem}"),
        other => panic!("unexpected {other:?}"),
    }

    // u-curve 2 running backwards: crossed out of order.
    let mut reversed = u_lists.clone();
    reversed[2].reverse();
    match PointNetwork::new(&v_lists, &reversed, CurveFit::CubicSpline, 1e-9) {
        Err(Error::NetworkCrossing { problem, .. }) => {
            assert!(problem.contains("out of order"), "{problem}")
        }
        other => panic!("unexpected {other:?}"),
    }

    // A point of u-curve 0 repeated: it meets v-curve 1 twice.
    let mut doubled = u_lists.clone();
    let repeated = doubled[0][15];
    doubled[0].insert(16, repeated);
    match PointNetwork::new(&v_lists, &doubled, CurveFit::CubicSpline, 1e-9) {
        Err(Error::NetworkCrossing {
            v_curve: 1,
            u_curve: 0,
            problem,
        }) => assert!(problem.contains("more than once"), "{problem}"),
        other => panic!("unexpected {other:?}"),
    }

    // One closed curve among open ones, too few points, a NaN, too few curves.
    let mut mixed = v_lists.clone();
    let first = mixed[1][0];
    mixed[1].push(first);
    assert!(matches!(
        PointNetwork::new(&mixed, &u_lists, CurveFit::CubicSpline, 1e-9),
        Err(Error::MixedClosure { .. })
    ));
    let mut short = v_lists.clone();
    short[2] = vec![short[2][0], short[2][20]];
    assert!(PointNetwork::new(&short, &u_lists, CurveFit::CubicSpline, 1e-9).is_err());
    let mut nan = v_lists.clone();
    nan[0][3][1] = f64::NAN;
    assert!(PointNetwork::new(&nan, &u_lists, CurveFit::CubicSpline, 1e-9).is_err());
    assert!(PointNetwork::new(&v_lists[..1], &u_lists, CurveFit::CubicSpline, 1e-9).is_err());
    assert!(PointNetwork::new(&v_lists, &u_lists, CurveFit::CubicSpline, f64::NAN).is_err());
}

#[test]
fn messages_of_network_errors() {
    let e = Error::NetworkCrossing {
        v_curve: 2,
        u_curve: 5,
        problem: "no common point".into(),
    };
    assert_eq!(e.to_string(), "v-curve 2 and u-curve 5: no common point");
}

#[test]
fn ll_curves_are_the_other_fit() {
    // The same regular network with interpolating LL curves of order 3: through every point
    // at its index parameter; an order outside 1..=64 is an error.
    let s = wavy_sheet();
    let vs = linspace(0.0, 2.0, 21);
    let us = linspace(0.0, 3.0, 31);
    let v_lists: Vec<_> = (0..3).map(|i| v_curve(&s, 1.5 * i as f64, &vs)).collect();
    let u_lists: Vec<_> = (0..3).map(|j| u_curve(&s, j as f64, &us)).collect();
    let net = PointNetwork::new(&v_lists, &u_lists, CurveFit::Ll(3), 1e-9).unwrap();
    for (i, list) in v_lists.iter().enumerate() {
        for (k, p) in list.iter().enumerate() {
            let got = net.network().v_curves()[i].eval(k as f64 / 20.0);
            assert!(got.distance(*p) < 1e-12, "v-curve {i}, point {k}");
        }
    }
    assert!(CoonsSurface::composite(net.network(), None, 1e-6).is_ok());
    assert!(PointNetwork::new(&v_lists, &u_lists, CurveFit::Ll(0), 1e-9).is_err());
}

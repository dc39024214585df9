//! Closed LL curves (docs/methods.md §1.2): closing rule, `r_0 = r_{K-1}`, `r_{K+1} = r_2`,
//! periodicity, smoothness across the seam, C^L joins and node deviation.

use crate::common::{assert_near, linspace, max_abs};
use crate::ll_reference::{
    check_curve_borders, deriv_tol, loop2, loop3, wavy2, RefCurve, RefKernel,
};
use karkas::ll::LlCurve;
use karkas::{Curve, Point};

const ORDERS: std::ops::RangeInclusive<usize> = 1..=12;

#[test]
fn closing_appends_the_first_point_unless_it_is_repeated() {
    let pts = loop2(7);
    let mut repeated = pts.clone();
    repeated.push(pts[0]);
    for l in [1, 4, 12] {
        let a = LlCurve::new(&pts, l, true).unwrap();
        let b = LlCurve::new(&repeated, l, true).unwrap();
        assert_eq!(
            a.axis().nodes(),
            8,
            "K = n + 1 when the first point is appended"
        );
        assert_eq!(
            b.axis().nodes(),
            8,
            "K = n when the last point repeats the first"
        );
        assert!(a.is_closed() && a.axis().is_closed());
        assert_eq!(a.control_points(), &repeated[..]);
        assert_eq!(b.control_points(), &repeated[..]);
        let d = a.domain();
        assert!((d.start - 1.0 / 9.0).abs() < 1e-16 && (d.end - 8.0 / 9.0).abs() < 1e-16);
        assert!((a.period().unwrap() - 7.0 / 9.0).abs() < 1e-15);
        // The same curve, to the last bit.
        for t in linspace(-0.3, 1.3, 333) {
            assert_eq!(a.eval(t), b.eval(t), "t = {t}");
            assert_eq!(a.deriv(t, 2), b.deriv(t, 2), "t = {t}");
        }
        // A last point that only nearly repeats the first is a point of its own.
        let mut near = pts.clone();
        near.push(pts[0] + Point([1e-6, 0.0]));
        assert_eq!(LlCurve::new(&near, l, true).unwrap().axis().nodes(), 9);
    }
}

/// The curve equals the definition with the closed end rule, on the whole domain
/// (segment K included: its upper half is segment 1's, by periodicity).
fn check_against_definition<const D: usize>(pts: &[Point<D>]) {
    for l in ORDERS {
        let c = LlCurve::new(pts, l, true).unwrap();
        let r = RefCurve::new(pts, l, true);
        let k = r.k();
        let mut ts = linspace(r.node(1), r.node(k), 301);
        ts.pop(); // the domain end is the start again (wraps to segment 1)
        ts.extend((2..=k).map(|i| r.param(i, 0.0)));
        for t in ts {
            assert_near(
                c.eval(t),
                r.at(t, 0),
                1e-13 * r.size(),
                &format!("P({t}), L={l}"),
            );
            for kd in 1..=2 * l + 1 {
                let what = format!("P^({kd})({t}), L = {l}");
                assert_near(c.deriv(t, kd), r.at(t, kd), deriv_tol(&r, kd), &what);
            }
        }
        check_curve_borders(&c, &r, &format!("closed, L = {l}"));
    }
}

#[test]
fn closed_curve_matches_the_definition_2d() {
    check_against_definition(&loop2(9));
    check_against_definition(&loop2(3));
}

#[test]
fn closed_curve_matches_the_definition_3d() {
    check_against_definition(&loop3(8));
    let mut repeated = loop3(5);
    repeated.push(repeated[0]);
    check_against_definition(&repeated);
}

#[test]
fn node_deviation_uses_the_periodic_neighbours() {
    for l in ORDERS.chain([20, 64]) {
        let pts = loop3(7);
        let n = pts.len();
        let c = LlCurve::new(&pts, l, true).unwrap();
        let d_l = RefKernel::new(l).d_l;
        for i in 0..n {
            // r_0 = r_{K-1} (the last distinct point), r_{K+1} = r_2.
            let d_i = pts[(i + n - 1) % n] + pts[(i + 1) % n] - pts[i] * 2.0;
            let got = c.eval(c.axis().node(i + 1)) - pts[i];
            assert_near(got, d_i * d_l, 1e-13 * max_abs(&pts), "node deviation");
        }
        // Node K is node 1 again.
        let k = c.axis().nodes();
        assert_near(
            c.eval(c.axis().node(k)),
            c.eval(c.axis().node(1)),
            1e-15,
            "node K",
        );
    }
}

#[test]
fn closed_curves_are_periodic() {
    for l in ORDERS {
        let pts = loop2(6);
        let c = LlCurve::new(&pts, l, true).unwrap();
        let r = RefCurve::new(&pts, l, true);
        let per = c.period().unwrap();
        let d = c.domain();
        for t in linspace(d.start, d.end, 71) {
            for m in [-2.0, -1.0, 1.0, 3.0] {
                let s = t + m * per;
                for kd in 0..=l + 1 {
                    // Shifting t by whole periods moves it by a few ulp: allow for that.
                    let tol = deriv_tol(&r, kd) + 1e-14 * r.deriv_scale(kd + 1);
                    let what = format!("P^({kd})({t} + {m} period), L = {l}");
                    assert_near(c.deriv(s, kd), c.deriv(t, kd), tol, &what);
                }
            }
        }
    }
}

/// Segments K and 1 are one polynomial, so the curve is C^infinity across the seam at
/// `t_1 = t_K`: the k-th derivative just below the domain end equals the Taylor expansion
/// (exact: degree 2L) of the curve at the domain start.
#[test]
fn the_seam_is_smooth() {
    for l in ORDERS {
        for (pts, what) in [(loop2(8), "loop"), (wavy2(6), "open polygon closed")] {
            let c = LlCurve::new(&pts, l, true).unwrap();
            let r = RefCurve::new(&pts, l, true);
            let d = c.domain();
            let delta = c.axis().spacing();
            for frac in [0.05, 0.25, 0.45] {
                let h = frac * delta;
                for kd in 0..=l + 1 {
                    let mut taylor = Point::<2>::ZERO;
                    let mut size = 0.0;
                    let mut fact = 1.0;
                    for m in 0..=2 * l - kd.min(2 * l) {
                        if m > 0 {
                            fact *= m as f64;
                        }
                        let term = c.deriv(d.start, kd + m) * ((-h).powi(m as i32) / fact);
                        size += term.max_abs();
                        taylor += term;
                    }
                    let got = c.deriv(d.end - h, kd);
                    let tol = 1e-11 * size + deriv_tol(&r, kd);
                    let msg = format!("{what}: P^({kd}) at end - {frac} Delta, L = {l}");
                    assert_near(got, taylor, tol, &msg);
                    // And the reference agrees that end - h lies on segment K.
                    assert_eq!(r.locate(d.end - h).0, r.k());
                }
            }
        }
    }
}

#[test]
fn the_seam_of_an_open_curve_is_not_smooth() {
    // The check above can fail: without closing, the ends do not even meet.
    let pts = loop2(8);
    for l in [1, 5] {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let d = c.domain();
        assert!(c.eval(d.end).distance(c.eval(d.start)) > 0.1);
    }
}

//! Open LL curves (docs/methods.md §1.2): parameters, agreement with the definition, C^L joins,
//! node deviation (5), end points, no oscillation, monotonicity, straight segments.

use crate::common::{assert_near, linspace, max_abs};
use crate::ll_reference::{check_curve_borders, deriv_tol, wavy2, wavy3, RefCurve, RefKernel};
use karkas::ll::LlCurve;
use karkas::{Curve, PiecewiseCurve, Point, Side};

const ORDERS: std::ops::RangeInclusive<usize> = 1..=12;

/// Parameters inside the domain: a fine grid plus every node and border.
fn samples<const D: usize>(r: &RefCurve<D>, n: usize) -> Vec<f64> {
    let k = r.k();
    let mut ts = linspace(r.node(1), r.node(k), n);
    ts.extend((1..=k).map(|i| r.node(i)));
    ts.extend((2..=k).map(|i| r.param(i, 0.0)));
    ts
}

#[test]
fn parameters_follow_the_paper() {
    for n in [3, 4, 7, 12] {
        let pts = wavy2(n);
        let c = LlCurve::new(&pts, 3, false).unwrap();
        let a = c.axis();
        assert_eq!(a.nodes(), n);
        assert!(!a.is_closed() && !c.is_closed());
        assert_eq!(a.scale(), (n + 1) as f64);
        assert!((a.spacing() - 1.0 / (n + 1) as f64).abs() < 1e-17);
        for i in 1..=n {
            assert!((a.node(i) - i as f64 / (n + 1) as f64).abs() < 1e-16);
        }
        let d = c.domain();
        assert!((d.start - 1.0 / (n + 1) as f64).abs() < 1e-16);
        assert!((d.end - n as f64 / (n + 1) as f64).abs() < 1e-16);
        assert_eq!(c.period(), None);
        assert_eq!(c.control_points(), &pts[..]);
        assert_eq!(c.order(), 3);
    }
}

/// Value and every derivative (up to one past the degree 2L) equal the definition:
/// `P_i = c_- r_{i-1} + c_0 r_i + c_+ r_{i+1}`, `d/dt = (K+1) d/dxi`, open end rules.
fn check_against_definition<const D: usize>(pts: &[Point<D>]) {
    for l in ORDERS {
        let c = LlCurve::new(pts, l, false).unwrap();
        let r = RefCurve::new(pts, l, false);
        for t in samples(&r, 301) {
            assert_near(
                c.eval(t),
                r.at(t, 0),
                1e-13 * r.size(),
                &format!("P({t}), L={l}"),
            );
            for k in 1..=2 * l + 1 {
                let what = format!("P^({k})({t}), L = {l}");
                assert_near(c.deriv(t, k), r.at(t, k), deriv_tol(&r, k), &what);
            }
            assert_eq!(c.deriv(t, 0), c.eval(t));
        }
    }
}

#[test]
fn open_curve_matches_the_definition_2d() {
    check_against_definition(&wavy2(8));
}

#[test]
fn open_curve_matches_the_definition_3d() {
    check_against_definition(&wavy3(6));
    check_against_definition(&wavy3(3));
}

#[test]
fn derivatives_are_per_unit_t() {
    // Difference quotients of the library's own lower derivatives: independent of weights.
    let pts = wavy3(7);
    for l in ORDERS {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let r = RefCurve::new(&pts, l, false);
        for i in 1..=7 {
            for xi in [0.3, 0.55, 0.8] {
                let t = r.param(i, xi);
                if !c.domain().contains(t) {
                    continue;
                }
                let e = 1e-6 * r.node(1);
                for k in 0..3 {
                    let fd = (c.deriv(t + e, k) - c.deriv(t - e, k)) * (0.5 / e);
                    let tol = 1e-6 * r.deriv_scale(k + 1) + 1e-9 * r.deriv_scale(k) / e;
                    assert_near(fd, c.deriv(t, k + 1), tol, &format!("d/dt P^({k}), L={l}"));
                }
            }
        }
    }
}

#[test]
fn joins_are_c_l_and_the_next_derivative_jumps() {
    for l in ORDERS {
        let p2 = wavy2(9);
        let c = LlCurve::new(&p2, l, false).unwrap();
        check_curve_borders(&c, &RefCurve::new(&p2, l, false), &format!("2-D, L = {l}"));
        let p3 = wavy3(8);
        let c = LlCurve::new(&p3, l, false).unwrap();
        check_curve_borders(&c, &RefCurve::new(&p3, l, false), &format!("3-D, L = {l}"));
    }
}

/// Formula (5): `P(t_i) - r_i = d_L D_i`, `D_i = r_{i-1} + r_{i+1} - 2 r_i`, with the open
/// end rule `r_0 = 2 r_1 - r_2`, `r_{K+1} = 2 r_K - r_{K-1}` (so `D_1 = D_K = 0`).
fn check_node_deviation<const D: usize>(pts: &[Point<D>], l: usize) {
    let c = LlCurve::new(pts, l, false).unwrap();
    let d_l = RefKernel::new(l).d_l;
    let k = pts.len();
    let r0 = pts[0] * 2.0 - pts[1];
    let rk1 = pts[k - 1] * 2.0 - pts[k - 2];
    let scale = max_abs(pts);
    for i in 1..=k {
        let prev = if i == 1 { r0 } else { pts[i - 2] };
        let next = if i == k { rk1 } else { pts[i] };
        let d_i = prev + next - pts[i - 1] * 2.0;
        let t = c.axis().node(i);
        let got = c.eval(t) - pts[i - 1];
        assert_near(got, d_i * d_l, 1e-13 * scale, &format!("node {i}, L = {l}"));
        // The deviation is really there (so this check is not vacuous), except at the ends.
        if i > 1 && i < k {
            assert!(got.max_abs() > 1e-3 * d_l * d_i.max_abs());
        }
    }
}

#[test]
fn node_deviation_is_d_l_times_second_difference() {
    for l in ORDERS.chain([20, 40, 64]) {
        check_node_deviation(&wavy2(9), l);
        check_node_deviation(&wavy3(5), l);
        check_node_deviation(&wavy3(3), l);
    }
}

#[test]
fn open_curves_pass_through_their_end_points() {
    for l in ORDERS.chain([30, 64]) {
        for n in [3, 4, 10] {
            let pts = wavy3(n);
            let c = LlCurve::new(&pts, l, false).unwrap();
            let d = c.domain();
            let tol = 1e-14 * max_abs(&pts);
            assert_near(c.eval(d.start), pts[0], tol, "start");
            assert_near(c.eval(d.end), pts[n - 1], tol, "end");
            // Interior nodes are not interpolated (the data are generic).
            assert!(c.eval(c.axis().node(2)).distance(pts[1]) > 1e-3);
        }
    }
}

/// A polygon with x equally spaced (so D_x = 0 exactly), y and z bending both ways.
fn bending_polygon() -> Vec<Point<3>> {
    let y = [0.0, 1.0, 3.0, 2.0, 2.5, 0.5, -1.0, -1.2, 0.8, 1.0];
    let z = [1.0, -2.0, 0.5, 0.25, 3.0, 3.5, 1.0, 0.0, 2.0, -1.0];
    (0..y.len())
        .map(|i| Point([i as f64, y[i], z[i]]))
        .collect()
}

#[test]
fn second_derivative_keeps_the_sign_of_d_on_every_segment() {
    let pts = bending_polygon();
    for l in ORDERS {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let r = RefCurve::new(&pts, l, false);
        let tol = deriv_tol(&r, 2);
        for i in 1..=r.k() {
            let d = r.d(i);
            for xi in linspace(0.0, 1.0, 101) {
                let t = r.param(i, xi);
                if !c.domain().contains(t) {
                    continue;
                }
                // The segment's own polynomial (at a border, deriv would take the next one).
                let side = if xi < 0.5 { Side::Above } else { Side::Below };
                let p2 = c.deriv_on_side(t, 2, side);
                for a in 0..3 {
                    if d[a] == 0.0 {
                        assert!(
                            p2[a].abs() <= tol,
                            "seg {i} coord {a}: D = 0 but P'' = {}",
                            p2[a]
                        );
                    } else {
                        assert!(
                            p2[a] * d[a].signum() >= -tol,
                            "oscillation: seg {i}, coord {a}, xi {xi}, L {l}: P'' = {}, D = {}",
                            p2[a],
                            d[a]
                        );
                    }
                }
            }
        }
        // D_x = 0 everywhere: x(t) is linear, x = (K+1) t - 1.
        for t in samples(&r, 97) {
            assert!((c.eval(t)[0] - (11.0 * t - 1.0)).abs() < 1e-13);
        }
    }
}

#[test]
fn monotone_triples_give_monotone_segments() {
    // x increasing with uneven steps; y with monotone and non-monotone triples.
    let xs = [0.0, 0.3, 1.5, 1.7, 3.0, 4.5, 4.6, 6.0, 8.0];
    let ys = [0.0, 1.0, 1.2, 3.0, 2.0, 1.9, 0.5, 0.4, 2.0];
    let pts: Vec<Point<2>> = xs.iter().zip(ys).map(|(&x, y)| Point([x, y])).collect();
    let mut checked = 0;
    for l in ORDERS {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let r = RefCurve::new(&pts, l, false);
        let tol = deriv_tol(&r, 1);
        for i in 1..=r.k() {
            let (a, b, e) = (r.ext[i - 1], r.ext[i], r.ext[i + 1]);
            for coord in 0..2 {
                let dir = if a[coord] <= b[coord] && b[coord] <= e[coord] {
                    1.0
                } else if a[coord] >= b[coord] && b[coord] >= e[coord] {
                    -1.0
                } else {
                    continue;
                };
                checked += 1;
                let ts: Vec<f64> = linspace(0.0, 1.0, 201)
                    .into_iter()
                    .map(|xi| r.param(i, xi))
                    .filter(|&t| c.domain().contains(t))
                    .collect();
                for w in ts.windows(2) {
                    let step = (c.eval(w[1])[coord] - c.eval(w[0])[coord]) * dir;
                    assert!(step >= -1e-14, "seg {i} coord {coord} L {l}: step {step}");
                    assert!(c.deriv(w[0], 1)[coord] * dir >= -tol);
                }
            }
        }
    }
    assert!(
        checked > 12 * 10,
        "the data must exercise both kinds of triples"
    );
}

#[test]
fn collinear_triples_give_straight_segments() {
    // Points 2, 3, 4 (1-based) collinear with uneven spacing; 6, 7, 8 collinear, evenly spaced.
    let pts = [
        Point([0.0, 0.0]),
        Point([1.0, 2.0]),
        Point([2.0, 3.0]),
        Point([4.0, 5.0]),
        Point([5.0, 3.0]),
        Point([6.0, 1.0]),
        Point([7.0, -1.0]),
        Point([8.0, -3.0]),
        Point([9.0, 0.0]),
    ];
    let cross = |u: Point<2>, v: Point<2>| u[0] * v[1] - u[1] * v[0];
    for l in ORDERS {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let ax = c.axis();
        let seg = |i: usize| {
            linspace(0.0, 1.0, 101)
                .into_iter()
                .map(move |xi| (xi, (i as f64 - 0.5 + xi) / ax.scale()))
        };
        // Segment 3 (centre (2,3)): on the line through (1,2) with direction (1,1).
        for (_, t) in seg(3) {
            let p = c.eval(t);
            assert!(
                cross(p - pts[1], Point([1.0, 1.0])).abs() < 1e-13,
                "off the line at {t}"
            );
        }
        // Segment 7 (centre (6,1), equal steps (1,-2)): linear in t and through r_7.
        assert_near(c.eval(ax.node(7)), pts[6], 1e-14, "through r_7");
        for (xi, t) in seg(7) {
            let want = pts[6] + Point([1.0, -2.0]) * (xi - 0.5);
            assert_near(c.eval(t), want, 1e-13, "linear in t");
            assert_near(
                c.deriv(t, 1),
                Point([1.0, -2.0]) * ax.scale(),
                1e-11,
                "constant P'",
            );
        }
        // A bent triple (2,3), (4,5), (5,3) does not give a straight segment: the checks
        // above can fail.
        let p = c.eval(ax.node(4));
        assert!(cross(p - pts[2], pts[4] - pts[2]).abs() > 1e-3);
    }
}

#[test]
fn three_points_make_a_curve() {
    // The smallest open input: K = 3, one bent segment in the middle.
    let pts = [Point([0.0, 0.0]), Point([1.0, 1.0]), Point([2.0, 0.0])];
    for l in ORDERS {
        let c = LlCurve::new(&pts, l, false).unwrap();
        let d_l = RefKernel::new(l).d_l;
        assert_near(
            c.eval(0.5),
            Point([1.0, 1.0 - 2.0 * d_l]),
            1e-15,
            "middle node",
        );
        assert_near(c.eval(0.25), pts[0], 1e-15, "start");
        assert_near(c.eval(0.75), pts[2], 1e-15, "end");
    }
}

/// `deriv_on_side` at the breakpoints the curve itself reports takes the piece on the asked
/// side, and `deriv` takes the piece above (the `Curve::deriv` contract), for every K: a
/// border `(i - 1/2)/(K+1)` is not exact in floating point. With L = 1, P'' jumps at every
/// border of these data, so a wrong piece shows.
#[test]
fn one_sided_derivatives_take_the_right_piece_at_every_breakpoint() {
    for closed in [false, true] {
        for n in 3..=120 {
            let pts: Vec<Point<1>> = (0..n).map(|i| Point([(1.3 * i as f64).sin()])).collect();
            let c = LlCurve::new(&pts, 1, closed).unwrap();
            let r = RefCurve::new(&pts, 1, closed);
            let bps = c.breakpoints();
            for i in 2..=r.k() {
                let b = bps[i - 1];
                let tol = deriv_tol(&r, 2);
                let what = format!("n = {n}, closed = {closed}, border {i}");
                let below = r.seg(i - 1, 1.0, 2);
                let above = r.seg(i, 0.0, 2);
                assert!(
                    (below - above).max_abs() > 1e3 * tol,
                    "{what}: no jump in the data"
                );
                assert_near(c.deriv_on_side(b, 2, Side::Below), below, tol, &what);
                assert_near(c.deriv_on_side(b, 2, Side::Above), above, tol, &what);
                assert_near(c.deriv(b, 2), above, tol, &what);
            }
        }
    }
}

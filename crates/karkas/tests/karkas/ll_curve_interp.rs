//! The interpolating LL curve (docs/methods.md §1.2, system (6)): it passes through every input
//! point at its node, its control polygon solves (6) (checked against a dense solve), and it
//! keeps the C^L joins.

use crate::common::{assert_near, dense_solve, linspace, max_abs};
use crate::ll_reference::{check_curve_borders, loop2, loop3, wavy2, wavy3, RefCurve, RefKernel};
use karkas::ll::{interpolation_controls, LlCurve};
use karkas::{Curve, Point};

const ORDERS: std::ops::RangeInclusive<usize> = 1..=12;

/// The control points of system (6) by dense Gaussian elimination. Open: first and last rows
/// identity, rows 2..K-1 `d r_{i-1} + (1 - 2d) r_i + d r_{i+1} = p_i`. Closed (`p` without
/// the repeated point, n unknowns): the same rows, cyclically.
fn dense_controls<const D: usize>(p: &[Point<D>], d: f64, closed: bool) -> Vec<Point<D>> {
    let n = p.len();
    let mut a = vec![vec![0.0; n]; n];
    for i in 0..n {
        if !closed && (i == 0 || i == n - 1) {
            a[i][i] = 1.0;
            continue;
        }
        a[i][(i + n - 1) % n] += d;
        a[i][i] += 1.0 - 2.0 * d;
        a[i][(i + 1) % n] += d;
    }
    let b = p.iter().map(|q| q.0.to_vec()).collect();
    dense_solve(a, b)
        .into_iter()
        .map(|x| Point(core::array::from_fn(|k| x[k])))
        .collect()
}

fn check_passes_through<const D: usize>(pts: &[Point<D>], closed: bool) {
    for l in ORDERS.chain([20, 64]) {
        let c = LlCurve::interpolating(pts, l, closed).unwrap();
        let tol = 1e-12 * max_abs(pts);
        for (i, p) in pts.iter().enumerate() {
            let t = c.axis().node(i + 1);
            assert_near(c.eval(t), *p, tol, &format!("node {}, L = {l}", i + 1));
        }
        // The approximating curve of the same points does not (the check can fail).
        let a = LlCurve::new(pts, l, closed).unwrap();
        let worst = (0..pts.len())
            .map(|i| a.eval(a.axis().node(i + 1)).distance(pts[i]))
            .fold(0.0, f64::max);
        assert!(worst > 1e-3, "L = {l}: the data should bend");
    }
}

#[test]
fn interpolating_curve_passes_through_every_point() {
    check_passes_through(&wavy2(3), false);
    check_passes_through(&wavy2(17), false);
    check_passes_through(&wavy3(30), false);
    check_passes_through(&loop2(3), true);
    check_passes_through(&loop2(25), true);
    check_passes_through(&loop3(12), true);
    let mut repeated = loop3(9);
    repeated.push(repeated[0]);
    check_passes_through(&repeated, true);
}

#[test]
fn control_points_solve_system_6() {
    for l in [1, 2, 5, 12] {
        let d = RefKernel::new(l).d_l;
        for n in [3, 4, 5, 10, 30] {
            let pts = wavy3(n);
            let c = LlCurve::interpolating(&pts, l, false).unwrap();
            let want = dense_controls(&pts, d, false);
            let tol = 1e-12 * max_abs(&pts);
            for (i, (got, w)) in c.control_points().iter().zip(&want).enumerate() {
                assert_near(
                    *got,
                    *w,
                    tol,
                    &format!("open r*_{}, K = {n}, L = {l}", i + 1),
                );
            }
            // The library's solver by itself, too.
            let mut v = pts.clone();
            interpolation_controls(&mut v, d, false).unwrap();
            for (a, b) in v.iter().zip(&want) {
                assert_near(*a, *b, tol, "interpolation_controls, open");
            }

            let pts = loop2(n);
            let c = LlCurve::interpolating(&pts, l, true).unwrap();
            let want = dense_controls(&pts, d, true);
            let got = c.control_points();
            assert_eq!(got.len(), n + 1, "closed: K = n + 1");
            assert_eq!(got[n], got[0], "closed: r*_K = r*_1");
            for (i, (g, w)) in got.iter().zip(&want).enumerate() {
                assert_near(
                    *g,
                    *w,
                    tol,
                    &format!("closed r*_{}, n = {n}, L = {l}", i + 1),
                );
            }
            let mut v = pts.clone();
            v.push(pts[0]);
            interpolation_controls(&mut v, d, true).unwrap();
            for (a, b) in v.iter().zip(want.iter().chain([&want[0]])) {
                assert_near(*a, *b, tol, "interpolation_controls, closed");
            }
        }
    }
}

#[test]
fn interpolating_curve_is_the_ll_curve_of_its_controls() {
    for l in ORDERS {
        for closed in [false, true] {
            let pts = if closed { loop3(8) } else { wavy3(8) };
            let c = LlCurve::interpolating(&pts, l, closed).unwrap();
            let ctrl = c.control_points().to_vec();
            let r = RefCurve::new(&ctrl, l, closed);
            let d = c.domain();
            for t in linspace(d.start, d.end, 201) {
                let what = format!("L = {l}, closed = {closed}, t = {t}");
                assert_near(c.eval(t), r.at(t, 0), 1e-13 * r.size(), &what);
            }
            // Smoothness is kept (monotonicity is not promised, so it is not tested).
            check_curve_borders(
                &c,
                &r,
                &format!("interpolating, L = {l}, closed = {closed}"),
            );
        }
    }
}

#[test]
fn closing_rule_holds_for_the_interpolating_variant() {
    let pts = loop2(7);
    let mut repeated = pts.clone();
    repeated.push(pts[0]);
    for l in [1, 3, 9] {
        let a = LlCurve::interpolating(&pts, l, true).unwrap();
        let b = LlCurve::interpolating(&repeated, l, true).unwrap();
        assert_eq!(a.control_points(), b.control_points());
        for t in linspace(0.0, 1.0, 101) {
            assert_eq!(a.eval(t), b.eval(t));
        }
    }
}

#[test]
fn three_points_interpolated_open_and_closed() {
    let pts = [Point([0.0, 0.0]), Point([1.0, 2.0]), Point([3.0, -1.0])];
    for l in ORDERS {
        for closed in [false, true] {
            let c = LlCurve::interpolating(&pts, l, closed).unwrap();
            for (i, p) in pts.iter().enumerate() {
                assert_near(c.eval(c.axis().node(i + 1)), *p, 1e-13, "3 points");
            }
        }
    }
}

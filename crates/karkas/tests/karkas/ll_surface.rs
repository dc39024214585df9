//! LL surfaces (docs/methods.md §1.3): the tensor-product definition, formula (19) at the nodes,
//! the corner rule of (20), lines u = const / v = const are LL curves, C^L across cell borders
//! with the (L+1)-th partial jumping, interpolated grid corners, periodic closed directions,
//! grid evaluation.

use crate::common::{assert_near, linspace};
use crate::ll_reference::{surface_grid, with_repeats, RefKernel, RefSurface};
use karkas::ll::{LlCurve, LlSurface};
use karkas::{Curve, Grid, PiecewiseSurface, Point, Side, Surface};

const ORDERS: std::ops::RangeInclusive<usize> = 1..=12;
const CLOSINGS: [(bool, bool); 4] = [(false, false), (true, false), (false, true), (true, true)];

/// Sample parameters over a domain: a grid plus the breakpoints.
fn samples(d: karkas::Interval, bps: &[f64], n: usize) -> Vec<f64> {
    let mut v = linspace(d.start, d.end, n);
    v.extend_from_slice(&bps[1..bps.len() - 1]);
    v
}

#[test]
fn parameters_follow_the_paper() {
    for (cu, cv) in CLOSINGS {
        let g = surface_grid(5, 7, cu, cv);
        let s = LlSurface::new(&g, 2, cu, cv).unwrap();
        let (kx, ky) = (5 + cu as usize, 7 + cv as usize);
        assert_eq!((s.axis_u().nodes(), s.axis_v().nodes()), (kx, ky));
        assert_eq!((s.is_closed_u(), s.is_closed_v()), (cu, cv));
        let (du, dv) = (s.domain_u(), s.domain_v());
        assert!((du.start - 1.0 / (kx + 1) as f64).abs() < 1e-16);
        assert!((du.end - kx as f64 / (kx + 1) as f64).abs() < 1e-16);
        assert!((dv.start - 1.0 / (ky + 1) as f64).abs() < 1e-16);
        assert!((dv.end - ky as f64 / (ky + 1) as f64).abs() < 1e-16);
        assert_eq!(s.breakpoints_u().len(), kx + 1);
        assert_eq!(s.breakpoints_v().len(), ky + 1);
        assert_eq!(s.continuity(), 2);
        assert_eq!(s.order(), 2);
        for i in 0..kx {
            for j in 0..ky {
                assert_eq!(s.control_point(i, j), *g.get(i % 5, j % 7));
            }
        }
        // A grid that already repeats gives the same surface.
        let r = LlSurface::new(&with_repeats(&g, cu, cv), 2, cu, cv).unwrap();
        assert_eq!(r, s);
    }
}

#[test]
fn surface_matches_the_tensor_definition() {
    for (cu, cv) in CLOSINGS {
        let g = surface_grid(6, 5, cu, cv);
        for l in ORDERS {
            let s = LlSurface::new(&g, l, cu, cv).unwrap();
            let r = RefSurface::new(&g, l, cu, cv);
            let (du, dv) = (s.domain_u(), s.domain_v());
            let mut us = samples(du, &s.breakpoints_u(), 13);
            let mut vs = samples(dv, &s.breakpoints_v(), 11);
            // The domain end of a closed direction wraps to the start: leave it out.
            if cu {
                us.retain(|&u| u < du.end);
            }
            if cv {
                vs.retain(|&v| v < dv.end);
            }
            let orders = [
                (0, 0),
                (1, 0),
                (0, 1),
                (1, 1),
                (2, 3),
                (l, l),
                (l + 1, 0),
                (0, l + 1),
            ];
            for &u in &us {
                for &v in &vs {
                    for (ku, kv) in orders {
                        let what = format!("({cu},{cv}) L={l} P_({ku},{kv})({u}, {v})");
                        assert_near(
                            s.deriv(u, v, ku, kv),
                            r.at(u, v, ku, kv),
                            r.tol(ku, kv),
                            &what,
                        );
                    }
                    assert_eq!(s.eval(u, v), s.deriv(u, v, 0, 0));
                }
            }
        }
    }
}

/// Formula (19) at node (i, j): nine points numbered row by row around it.
fn formula_19(r: [Point<3>; 9], d: f64) -> Point<3> {
    let edges = r[1] + r[3] + r[5] + r[7];
    let corners = r[0] + r[2] + r[6] + r[8];
    let r9 = (corners - edges * 2.0 + r[4] * 4.0) * 0.25;
    r[4] + (edges - r[4] * 4.0) * d + r9 * (4.0 * d * d)
}

#[test]
fn nodes_follow_formula_19() {
    for l in ORDERS.chain([30, 64]) {
        let d = RefKernel::new(l).d_l;
        for (cu, cv) in CLOSINGS {
            let g = surface_grid(6, 7, cu, cv);
            let s = LlSurface::new(&g, l, cu, cv).unwrap();
            let r = RefSurface::new(&g, l, cu, cv);
            let (kx, ky) = (r.kx(), r.ky());
            for i in 1..=kx {
                for j in 1..=ky {
                    let nine = core::array::from_fn(|n| r.r(i + n / 3 - 1, j + n % 3 - 1));
                    let got = s.eval(s.axis_u().node(i), s.axis_v().node(j));
                    let what = format!("node ({i},{j}), L = {l}, closed ({cu},{cv})");
                    assert_near(got, formula_19(nine, d), 1e-13 * r.size(), &what);
                    // Interior nodes with the raw input points (no extension involved).
                    if (2..kx).contains(&i) && (2..ky).contains(&j) {
                        let raw = core::array::from_fn(|n| {
                            *g.get((i + n / 3 - 2) % g.rows(), (j + n % 3 - 2) % g.cols())
                        });
                        assert_near(got, formula_19(raw, d), 1e-13 * r.size(), &what);
                    }
                }
            }
        }
    }
}

#[test]
fn corner_rule_and_corner_interpolation() {
    let g = surface_grid(5, 6, false, false);
    for l in ORDERS {
        let s = LlSurface::new(&g, l, false, false).unwrap();
        let r = RefSurface::new(&g, l, false, false);
        let (au, av) = (s.axis_u(), s.axis_v());
        // The four grid corners are interpolated exactly.
        for (i, j) in [(0, 0), (0, 5), (4, 0), (4, 5)] {
            let p = s.eval(au.node(i + 1), av.node(j + 1));
            assert_near(
                p,
                *g.get(i, j),
                1e-14 * r.size(),
                &format!("corner ({i},{j})"),
            );
        }
        // Inside a corner cell the extended corner r_00 = 4 r_11 - 2 r_21 - 2 r_12 + r_22
        // carries the weight c_-(xi) c_-(eta) > 0: the value depends on the rule.
        for (u, v, ci, cj) in [
            (
                au.node(1) + 0.05 * au.spacing(),
                av.node(1) + 0.02 * av.spacing(),
                0,
                0,
            ),
            (
                au.node(5) - 0.03 * au.spacing(),
                av.node(6) - 0.04 * av.spacing(),
                6,
                7,
            ),
        ] {
            let want = r.at(u, v, 0, 0);
            assert_near(s.eval(u, v), want, 1e-13 * r.size(), "corner cell");
            let mut other = RefSurface::new(&g, l, false, false);
            other.ext[ci][cj] += Point([1.0, 1.0, 1.0]);
            // Near the corner node the weight is about d_L^2 (>= 1e-3 for L <= 12).
            let moved = other.at(u, v, 0, 0).distance(want);
            assert!(moved > 1e-4, "the corner rule matters: {moved:e}, L = {l}");
        }
    }
}

/// The line u = const, built here: control points `Q_j = sum_a c_a(xi) r_{i+a, j}` with the
/// kernel's weights, an LL curve of v (and v = const likewise).
#[test]
fn lines_are_ll_curves() {
    for (cu, cv) in CLOSINGS {
        let g = surface_grid(6, 5, cu, cv);
        for l in ORDERS {
            let s = LlSurface::new(&g, l, cu, cv).unwrap();
            let r = RefSurface::new(&g, l, cu, cv);
            let k = s.curve_at_u(0.5);
            let kernel = k.kernel();
            let (du, dv) = (s.domain_u(), s.domain_v());
            let tol = 1e-13 * r.size();
            for u in linspace(du.start, du.end, 9) {
                let (i, xi) = r.locate_u(u);
                let w = kernel.weights(xi, 0);
                let q: Vec<Point<3>> = (1..=r.ky())
                    .map(|j| r.r(i - 1, j) * w[0] + r.r(i, j) * w[1] + r.r(i + 1, j) * w[2])
                    .collect();
                let mine = LlCurve::new(&q, l, cv).unwrap();
                let theirs = s.curve_at_u(u);
                assert_eq!(theirs.domain(), dv);
                for v in linspace(dv.start, dv.end, 23) {
                    let p = s.eval(u, v);
                    assert_near(mine.eval(v), p, tol, &format!("u = {u} line at v = {v}"));
                    assert_near(theirs.eval(v), p, tol, "curve_at_u");
                    for kv in 1..=l + 1 {
                        let rt = r.tol(0, kv);
                        assert_near(theirs.deriv(v, kv), s.deriv(u, v, 0, kv), rt, "d/dv");
                        assert_near(mine.deriv(v, kv), s.deriv(u, v, 0, kv), rt, "mine d/dv");
                    }
                }
            }
            for v in linspace(dv.start, dv.end, 9) {
                let (j, eta) = r.locate_v(v);
                let w = kernel.weights(eta, 0);
                let q: Vec<Point<3>> = (1..=r.kx())
                    .map(|i| r.r(i, j - 1) * w[0] + r.r(i, j) * w[1] + r.r(i, j + 1) * w[2])
                    .collect();
                let mine = LlCurve::new(&q, l, cu).unwrap();
                let theirs = s.curve_at_v(v);
                for u in linspace(du.start, du.end, 23) {
                    let p = s.eval(u, v);
                    assert_near(mine.eval(u), p, tol, &format!("v = {v} line at u = {u}"));
                    assert_near(theirs.eval(u), p, tol, "curve_at_v");
                    let rt = r.tol(2, 0);
                    assert_near(theirs.deriv(u, 2), s.deriv(u, v, 2, 0), rt, "d2/du2");
                }
            }
        }
    }
}

/// Across every u-border: partials of order (ku <= L, kv <= L) agree from both sides and equal
/// the reference cells; the (L+1)-th u-partial jumps by the reference amount, which is large.
/// Then the same across v-borders, and at cell corners from all four sides.
pub fn check_surface_borders(s: &LlSurface<3>, r: &RefSurface<3>, what: &str) {
    let l = r.kernel.l;
    let (bu, bv) = (s.breakpoints_u(), s.breakpoints_v());
    let (au, av) = (s.axis_u(), s.axis_v());
    let inner = |b: &[f64]| b[1..b.len() - 1].to_vec();
    let off_v = [av.node(2), av.node(3) + 0.27 * av.spacing()];
    let off_u = [au.node(2) - 0.31 * au.spacing(), au.node(3)];
    for (n, &u) in inner(&bu).iter().enumerate() {
        let i = n + 2; // border between cells i-1 and i
        for &v in &off_v {
            let jv = r.locate_v(v);
            for ku in 0..=l + 1 {
                for kv in 0..=l {
                    let lo = s.deriv_on_side(u, v, ku, kv, Side::Below, Side::Above);
                    let hi = s.deriv_on_side(u, v, ku, kv, Side::Above, Side::Above);
                    let (rlo, rhi) = (
                        r.cell((i - 1, 1.0), jv, ku, kv),
                        r.cell((i, 0.0), jv, ku, kv),
                    );
                    let tol = r.tol(ku, kv);
                    let m = format!("{what}: P_({ku},{kv}) at u-border {i}, v = {v}");
                    assert_near(lo, rlo, tol, &m);
                    assert_near(hi, rhi, tol, &m);
                    if ku <= l {
                        assert_near(lo, hi, tol, &m);
                    } else if kv == 0 {
                        assert!((rhi - rlo).max_abs() > 1e3 * tol, "{m}: should jump");
                    }
                }
            }
        }
    }
    for (n, &v) in inner(&bv).iter().enumerate() {
        let j = n + 2;
        for &u in &off_u {
            let iu = r.locate_u(u);
            for kv in 0..=l + 1 {
                for ku in 0..=l {
                    let lo = s.deriv_on_side(u, v, ku, kv, Side::Below, Side::Below);
                    let hi = s.deriv_on_side(u, v, ku, kv, Side::Below, Side::Above);
                    let (rlo, rhi) = (
                        r.cell(iu, (j - 1, 1.0), ku, kv),
                        r.cell(iu, (j, 0.0), ku, kv),
                    );
                    let tol = r.tol(ku, kv);
                    let m = format!("{what}: P_({ku},{kv}) at v-border {j}, u = {u}");
                    assert_near(lo, rlo, tol, &m);
                    assert_near(hi, rhi, tol, &m);
                    if kv <= l {
                        assert_near(lo, hi, tol, &m);
                    } else if ku == 0 {
                        assert!((rhi - rlo).max_abs() > 1e3 * tol, "{m}: should jump");
                    }
                }
            }
        }
    }
    // Cell corners: all four one-sided limits agree up to order L in each variable.
    let sides = [Side::Below, Side::Above];
    for &u in &inner(&bu) {
        for &v in &inner(&bv) {
            for ku in 0..=l {
                for kv in 0..=l {
                    let p = s.deriv_on_side(u, v, ku, kv, Side::Above, Side::Above);
                    for su in sides {
                        for sv in sides {
                            let q = s.deriv_on_side(u, v, ku, kv, su, sv);
                            assert_near(q, p, r.tol(ku, kv), &format!("{what}: corner ({u},{v})"));
                        }
                    }
                }
            }
        }
    }
}

#[test]
fn partials_are_c_l_across_cell_borders_open() {
    let g = surface_grid(5, 6, false, false);
    for l in ORDERS {
        let s = LlSurface::new(&g, l, false, false).unwrap();
        check_surface_borders(
            &s,
            &RefSurface::new(&g, l, false, false),
            &format!("L = {l}"),
        );
    }
}

#[test]
fn partials_are_c_l_across_cell_borders_closed() {
    for (cu, cv) in [(true, true), (true, false)] {
        let g = surface_grid(5, 4, cu, cv);
        for l in [1, 2, 3, 6, 9, 12] {
            let s = LlSurface::new(&g, l, cu, cv).unwrap();
            let r = RefSurface::new(&g, l, cu, cv);
            check_surface_borders(&s, &r, &format!("closed ({cu},{cv}), L = {l}"));
        }
    }
}

#[test]
fn closed_directions_are_periodic() {
    for (cu, cv) in [(true, false), (false, true), (true, true)] {
        let g = surface_grid(5, 6, cu, cv);
        for l in [1, 2, 5, 12] {
            let s = LlSurface::new(&g, l, cu, cv).unwrap();
            let r = RefSurface::new(&g, l, cu, cv);
            let (du, dv) = (s.domain_u(), s.domain_v());
            let (pu, pv) = (du.length(), dv.length());
            for u in linspace(du.start, du.end, 17) {
                for v in linspace(dv.start, dv.end, 19) {
                    let shifts = [(cu as u8 as f64 * pu, 0.0), (0.0, cv as u8 as f64 * pv)];
                    for (su, sv) in shifts
                        .into_iter()
                        .chain([(-pu * cu as u8 as f64, 2.0 * pv * cv as u8 as f64)])
                    {
                        for (ku, kv) in [(0, 0), (1, 0), (0, 1), (l, 1)] {
                            let tol = r.tol(ku, kv)
                                + 1e-14 * (r.deriv_scale(ku + 1, kv) + r.deriv_scale(ku, kv + 1));
                            let a = s.deriv(u + su, v + sv, ku, kv);
                            assert_near(a, s.deriv(u, v, ku, kv), tol, "periodic");
                        }
                    }
                }
            }
            // Smooth across the seam: the closed direction has no border at its domain end.
            if cu {
                let h = 0.3 * s.axis_u().spacing();
                let v = dv.start + 0.37 * dv.length();
                let a = s.eval(du.end - h, v);
                let b = s.eval(du.start - h, v);
                assert_near(a, b, 1e-13 * r.size(), "seam in u");
                let fd = (s.eval(du.start + 1e-7, v) - s.eval(du.end - 1e-7, v)) * (0.5e7);
                assert_near(
                    fd,
                    s.deriv(du.start, v, 1, 0),
                    1e-5 * r.deriv_scale(1, 0),
                    "slope",
                );
            }
        }
    }
}

#[test]
fn grid_evaluation_equals_pointwise_evaluation() {
    for (cu, cv) in CLOSINGS {
        let g = surface_grid(7, 5, cu, cv);
        for l in [1, 3, 8, 12, 20] {
            let s = LlSurface::new(&g, l, cu, cv).unwrap();
            let mut us = linspace(-0.1, 1.1, 31);
            us.extend(s.breakpoints_u());
            let mut vs = linspace(-0.2, 1.05, 27);
            vs.extend(s.breakpoints_v());
            let mut out = vec![Point::ZERO; us.len() * vs.len()];
            s.eval_grid_into(&us, &vs, &mut out);
            for (a, &u) in us.iter().enumerate() {
                for (b, &v) in vs.iter().enumerate() {
                    assert_near(out[a * vs.len() + b], s.eval(u, v), 1e-13, "grid vs eval");
                }
            }
            let (mut su, mut sv) = (vec![0.0; 4], vec![0.0; 6]);
            let mut out = vec![Point::ZERO; 24];
            s.sample_grid_into(&mut su, &mut sv, &mut out);
            assert_eq!((su[0], su[3]), (s.domain_u().start, s.domain_u().end));
            assert_near(out[23], s.eval(su[3], sv[5]), 1e-13, "sample_grid_into");
        }
    }
}

#[test]
fn a_plane_grid_gives_the_plane() {
    // Affine data: every D vanishes, so the surface is the bilinear map itself.
    let g = Grid::from_fn(5, 6, |i, j| {
        Point([i as f64, j as f64, 2.0 * i as f64 - 0.5 * j as f64])
    });
    for l in [1, 4, 12] {
        let s = LlSurface::new(&g, l, false, false).unwrap();
        for u in linspace(s.domain_u().start, s.domain_u().end, 11) {
            for v in linspace(s.domain_v().start, s.domain_v().end, 13) {
                let (x, y) = (6.0 * u - 1.0, 7.0 * v - 1.0);
                assert_near(
                    s.eval(u, v),
                    Point([x, y, 2.0 * x - 0.5 * y]),
                    1e-13,
                    "plane",
                );
            }
        }
    }
}

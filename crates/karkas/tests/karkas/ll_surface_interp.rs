//! The interpolating LL surface (docs/methods.md §1.3): it passes through every grid point, and
//! its separable row-then-column solve equals a dense solve of the full 2-D system.

use crate::common::{assert_near, dense_solve, linspace, max_abs};
use crate::ll_reference::{surface_grid, with_repeats, RefSurface};
use karkas::ll::LlSurface;
use karkas::{Grid, Point, Surface};

const CLOSINGS: [(bool, bool); 4] = [(false, false), (true, false), (false, true), (true, true)];

#[test]
fn interpolating_surface_passes_through_every_grid_point() {
    for (cu, cv) in CLOSINGS {
        for (rows, cols) in [(3, 3), (5, 6), (8, 4)] {
            let base = surface_grid(rows, cols, cu, cv);
            for g in [base.clone(), with_repeats(&base, cu, cv)] {
                for l in (1..=12).chain([40, 64]) {
                    let s = LlSurface::interpolating(&g, l, cu, cv).unwrap();
                    let (au, av) = (s.axis_u(), s.axis_v());
                    let scale = max_abs(g.as_slice());
                    for i in 0..g.rows() {
                        for j in 0..g.cols() {
                            let p = s.eval(au.node(i + 1), av.node(j + 1));
                            let what = format!("({i},{j}) of {rows}x{cols}, ({cu},{cv}), L={l}");
                            assert_near(p, *g.get(i, j), 1e-12 * scale, &what);
                        }
                    }
                    // The approximating surface does not interpolate (the check can fail).
                    let a = LlSurface::new(&g, l, cu, cv).unwrap();
                    let p = a.eval(au.node(2), av.node(2));
                    assert!(p.distance(*g.get(1, 1)) > 1e-4);
                }
            }
        }
    }
}

/// The dense system: unknown control points `x` (the distinct ones), equations
/// `P(u_i, v_j) = r_ij` at every distinct node, `P` from the tensor definition with the
/// extension rules of (20) (linear in `x`, so the matrix is built column by column).
fn dense_controls(g: &Grid<Point<3>>, l: usize, cu: bool, cv: bool) -> Vec<Vec<Point<3>>> {
    let (nu, nv) = (g.rows(), g.cols());
    let n = nu * nv;
    let node_values = |x: &[f64]| -> Vec<f64> {
        let mut rows: Vec<Vec<Point<1>>> = (0..nu)
            .map(|i| (0..nv).map(|j| Point([x[i * nv + j]])).collect())
            .collect();
        if cv {
            for r in &mut rows {
                r.push(r[0]);
            }
        }
        if cu {
            rows.push(rows[0].clone());
        }
        let r = RefSurface::from_control(&rows, l, cu, cv);
        (0..n)
            .map(|k| r.cell((k / nv + 1, 0.5), (k % nv + 1, 0.5), 0, 0)[0])
            .collect()
    };
    let mut a = vec![vec![0.0; n]; n];
    for c in 0..n {
        let mut e = vec![0.0; n];
        e[c] = 1.0;
        for (row, v) in node_values(&e).into_iter().enumerate() {
            a[row][c] = v;
        }
    }
    let b = g.as_slice().iter().map(|p| p.0.to_vec()).collect();
    let x = dense_solve(a, b);
    (0..nu)
        .map(|i| {
            (0..nv)
                .map(|j| Point(core::array::from_fn(|k| x[i * nv + j][k])))
                .collect()
        })
        .collect()
}

#[test]
fn separable_solve_equals_the_dense_2d_solve() {
    for (cu, cv) in CLOSINGS {
        for (rows, cols) in [(5, 6), (3, 4)] {
            let g = surface_grid(rows, cols, cu, cv);
            for l in [1, 2, 5, 12] {
                let s = LlSurface::interpolating(&g, l, cu, cv).unwrap();
                let want = dense_controls(&g, l, cu, cv);
                let tol = 1e-12 * max_abs(g.as_slice());
                let (kx, ky) = (s.axis_u().nodes(), s.axis_v().nodes());
                for i in 0..kx {
                    for j in 0..ky {
                        let w = want[i % rows][j % cols];
                        let what = format!("r*({i},{j}), ({cu},{cv}), L = {l}");
                        assert_near(s.control_point(i, j), w, tol, &what);
                    }
                }
            }
        }
    }
}

#[test]
fn interpolating_surface_is_the_ll_surface_of_its_controls() {
    for (cu, cv) in CLOSINGS {
        let g = surface_grid(6, 5, cu, cv);
        for l in [1, 3, 7, 12] {
            let s = LlSurface::interpolating(&g, l, cu, cv).unwrap();
            let (kx, ky) = (s.axis_u().nodes(), s.axis_v().nodes());
            let ctrl: Vec<Vec<Point<3>>> = (0..kx)
                .map(|i| (0..ky).map(|j| s.control_point(i, j)).collect())
                .collect();
            let r = RefSurface::from_control(&ctrl, l, cu, cv);
            let (du, dv) = (s.domain_u(), s.domain_v());
            for u in linspace(du.start, du.end, 15) {
                for v in linspace(dv.start, dv.end, 14) {
                    let (u, v) = (u.min(du.end - 1e-9), v.min(dv.end - 1e-9));
                    for (ku, kv) in [(0, 0), (1, 1), (l, 0)] {
                        assert_near(
                            s.deriv(u, v, ku, kv),
                            r.at(u, v, ku, kv),
                            r.tol(ku, kv),
                            "ctrl",
                        );
                    }
                }
            }
        }
    }
}

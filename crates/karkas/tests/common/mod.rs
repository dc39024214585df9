//! Shared helpers of the LL integration tests: an independent reference implementation of the
//! kernel, curves and surfaces of METHODS.md §1.1–1.3 (written from the spec, not from the
//! library), deterministic test data, and a dense linear solver.
//!
//! Every figure a test compares against is computed here from the definitions: binomials
//! exactly in integers, `h` summed directly from its definition, `h'` as the incomplete beta
//! sum, higher derivatives from the exact monomial coefficients of `h`.

#![allow(dead_code, unused_imports)]

mod curve;
mod kernel;
mod surface;

pub use curve::{check_curve_borders, deriv_tol, extend, RefCurve};
pub use kernel::{binom, RefKernel, Q};
pub use surface::{surface_grid, with_repeats, RefSurface};

use karkas::Point;

// ------------------------------------------------------------------------------------------
// Data and comparisons
// ------------------------------------------------------------------------------------------

/// A generic open polygon in the plane: no three consecutive points collinear, second
/// differences varying from node to node.
pub fn wavy2(n: usize) -> Vec<Point<2>> {
    (0..n)
        .map(|i| {
            let f = i as f64;
            Point([f + 0.4 * (1.7 * f).sin(), 2.0 * (1.3 * f).cos() + 0.3 * f])
        })
        .collect()
}

/// A generic open polygon in space.
pub fn wavy3(n: usize) -> Vec<Point<3>> {
    (0..n)
        .map(|i| {
            let f = i as f64;
            Point([
                1.5 * f + 0.5 * (1.1 * f).sin(),
                3.0 * (0.9 * f).cos() - 0.2 * f,
                (2.1 * f).sin() + 0.05 * f * f,
            ])
        })
        .collect()
}

/// A closed-looking polygon (distinct points on a perturbed ellipse, no repeat).
pub fn loop2(n: usize) -> Vec<Point<2>> {
    (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            let r = 1.0 + 0.25 * (3.0 * a).sin() + 0.1 * (5.0 * a).cos();
            Point([3.0 * r * a.cos() + 0.5, 2.0 * r * a.sin() - 1.0])
        })
        .collect()
}

/// A closed space polygon (no repeat).
pub fn loop3(n: usize) -> Vec<Point<3>> {
    (0..n)
        .map(|i| {
            let a = std::f64::consts::TAU * i as f64 / n as f64;
            Point([
                2.0 * a.cos() + 0.3 * (2.0 * a).cos(),
                1.5 * a.sin() - 0.2 * (3.0 * a).sin(),
                0.7 * (2.0 * a).sin() + 0.4,
            ])
        })
        .collect()
}

/// Largest absolute coordinate over `pts` (at least 1).
pub fn max_abs<const D: usize>(pts: &[Point<D>]) -> f64 {
    pts.iter().fold(1.0, |m, p| m.max(p.max_abs()))
}

/// Asserts `|a - b|_max <= tol`.
#[track_caller]
pub fn assert_near<const D: usize>(a: Point<D>, b: Point<D>, tol: f64, what: &str) {
    let e = (a - b).max_abs();
    assert!(
        e <= tol,
        "{what}: {a:?} vs {b:?}, difference {e:e} > tolerance {tol:e}"
    );
}

/// Parameters of `n` evenly spaced samples in `[a, b]`, ends included.
pub fn linspace(a: f64, b: f64, n: usize) -> Vec<f64> {
    (0..n)
        .map(|k| a + (b - a) * k as f64 / (n - 1) as f64)
        .collect()
}

/// Dense Gaussian elimination with partial pivoting; `b` holds one right-hand side per
/// column (`b[row][col]`). The slow, obviously correct reference for the banded solves.
pub fn dense_solve(mut a: Vec<Vec<f64>>, mut b: Vec<Vec<f64>>) -> Vec<Vec<f64>> {
    let n = a.len();
    for c in 0..n {
        let p = (c..n)
            .max_by(|&i, &j| a[i][c].abs().total_cmp(&a[j][c].abs()))
            .unwrap();
        a.swap(c, p);
        b.swap(c, p);
        assert!(a[c][c].abs() > 1e-12, "singular dense system");
        let (top, rest) = a.split_at_mut(c + 1);
        let (btop, brest) = b.split_at_mut(c + 1);
        let (pivot, bpivot) = (&top[c], &btop[c]);
        for (row, brow) in rest.iter_mut().zip(brest.iter_mut()) {
            let f = row[c] / pivot[c];
            if f == 0.0 {
                continue;
            }
            for (x, p) in row[c..].iter_mut().zip(&pivot[c..]) {
                *x -= f * p;
            }
            for (x, p) in brow.iter_mut().zip(bpivot) {
                *x -= f * p;
            }
        }
    }
    let m = b[0].len();
    let mut x = vec![vec![0.0; m]; n];
    for r in (0..n).rev() {
        for col in 0..m {
            let s: f64 = (r + 1..n).map(|k| a[r][k] * x[k][col]).sum();
            x[r][col] = (b[r][col] - s) / a[r][r];
        }
    }
    x
}

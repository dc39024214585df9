//! The reference of the LL tests: an independent implementation of the kernel, curves and
//! surfaces of docs/methods.md §1.1–1.3 (written from the spec, not from the library) and
//! deterministic test data.
//!
//! Every figure a test compares against is computed here from the definitions: binomials
//! exactly in integers, `h` summed directly from its definition, `h'` as the incomplete beta
//! sum, higher derivatives from the exact monomial coefficients of `h`.

mod curve;
mod kernel;
mod surface;

pub use curve::{check_curve_borders, deriv_tol, extend, RefCurve};
pub use kernel::{binom, RefKernel, Q};
pub use surface::{surface_grid, with_repeats, RefSurface};

use karkas::Point;

// ------------------------------------------------------------------------------------------
// Data
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

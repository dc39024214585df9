//! The cubic spline core shared by the parameterization splines, the spline blending of Coons
//! surfaces and the defect-2 fits: one Hermite basis, one interpolation system, one set of
//! end conditions.
//!
//! **Method.** A cubic interpolating spline on knots `t_0 < .. < t_{n-1}` is stored in Hermite
//! form: the values `y_k` and the node slopes `m_k`, each piece the cubic of
//! [`hermite_basis`]. With steps `h_k = t_{k+1} - t_k`, divided differences
//! `delta_k = (y_{k+1} - y_k) / h_k`, `lambda_i = h_i / (h_{i-1} + h_i)`, `mu_i = 1 - lambda_i`,
//! C^2 continuity at an inner knot reads (Kuznetsov and Filatov, "Parametrization of surfaces
//! by the continuation method", (3.10))
//!
//! `lambda_i m_{i-1} + 2 m_i + mu_i m_{i+1} = 3 (lambda_i delta_{i-1} + mu_i delta_i)`.
//!
//! The [`SplineEnds`] complete the system. Not-a-knot ends (continuous third derivative at
//! `t_1` and `t_{n-2}`) give `m_0 = (g^2 - 1) m_1 + g^2 m_2 + 2 (delta_0 - g^2 delta_1)` with
//! `g = h_0 / h_1` ((3.11); likewise (3.12) at the other end); eliminating `m_0` from the row
//! of `t_1` leaves the diagonally dominant row `(1 + g) m_1 + g m_2 = y'_1 + 2 g delta_1`, so
//! the unknowns `m_1..m_{n-2}` solve a tridiagonal system without pivoting. (The printed
//! (3.10) garbles the indices of `gamma_N`; re-derived here.) Natural ends
//! (`2 m_0 + m_1 = 3 delta_0`), clamped ends (given slopes) and periodic ends (a cyclic
//! tridiagonal system, solved by Sherman–Morrison) complete the set.
//!
//! The matrix depends on the knots only: the system is factored once and then solves any
//! number of lines of values, and its transposed solve gives the cardinal functions
//! `C_j` (`C_j(t_k) = delta_jk`) that Chashnikov's spline blending of curve networks uses
//! ("Generalized Coons surfaces"): the weights of all `C_j` at `t` are `a(t) + S^T c(t)` with
//! `a`, `c` the Hermite weights of the piece and `S` the map from values to slopes.
//!
//! **Complexity.** Factoring `O(n)`; each solve `O(n)` per line of values; each transposed
//! solve (all cardinal functions at one parameter) `O(n)`.
//!
//! **Guarantees.** The spline passes through every value at its knot and is `C^2` (across the
//! seam too when periodic); not-a-knot reproduces every cubic exactly, with 3 knots it is the
//! parabola and with 2 the segment through the points. The results agree with any standard
//! cubic spline of the same end conditions (tests against SciPy's `CubicSpline`). Knots are
//! checked by the one validator of [`crate::core::knots`]; a mistake in them is the same
//! [`Error::InvalidKnot`](crate::Error::InvalidKnot) whichever method was given them:
//!
//! ```
//! use karkas::fit::{fit_curve, FitOptions};
//! use karkas::param::{CubicSpline, SplineEnds};
//! use karkas::{Error, Point};
//! let pts = [Point([0.0]), Point([1.0]), Point([0.5]), Point([2.0])];
//! let spline = CubicSpline::new(&[0.0, 2.0, 1.0, 3.0], &pts, SplineEnds::NotAKnot);
//! let fit = fit_curve(&pts, &[0.0, 0.6, 0.4, 1.0], &FitOptions::default());
//! let reason = |e: Error| match e {
//!     Error::InvalidKnot { index, reason, .. } => (index, reason),
//!     other => panic!("{other:?}"),
//! };
//! assert_eq!(reason(spline.unwrap_err()), reason(fit.unwrap_err()));
//! ```

mod cyclic;
mod ends;
mod hermite;
mod one_pass;
mod system;
mod transposed;

pub(crate) use cyclic::periodic_slopes;
pub use ends::SplineEnds;
pub use hermite::{hermite_basis, hermite_cubic};
pub(crate) use one_pass::not_a_knot_slopes;
pub(crate) use system::SlopeSystem;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point;

    /// The dense matrix `S` of the map from values to slopes, column by column.
    fn dense(system: &SlopeSystem, n: usize) -> Vec<Vec<f64>> {
        (0..n)
            .map(|j| {
                let values: Vec<Point<1>> = (0..n).map(|k| Point([f64::from(k == j)])).collect();
                let mut slopes = vec![Point::ZERO; n];
                system.solve(&values, &mut slopes, 1, None);
                slopes.iter().map(|m| m[0]).collect()
            })
            .collect()
    }

    #[test]
    fn transposed_solve_equals_the_dense_transpose() {
        let all: [SplineEnds<1>; 4] = [
            SplineEnds::NotAKnot,
            SplineEnds::Natural,
            SplineEnds::Clamped {
                start: Point::ZERO,
                end: Point::ZERO,
            },
            SplineEnds::Periodic,
        ];
        for n in [2usize, 3, 4, 5, 8, 13] {
            let knots: Vec<f64> = (0..n)
                .map(|k| k as f64 + 0.4 * ((k * k) as f64 * 0.61).sin())
                .collect();
            for ends in &all {
                if ends.is_periodic() && n < 3 {
                    continue;
                }
                let system = SlopeSystem::new(&knots, ends).unwrap();
                let columns = dense(&system, n);
                for seed in 0..3 {
                    let c: Vec<f64> = (0..n)
                        .map(|k| ((k * 7 + seed * 3) as f64 * 0.9).cos())
                        .collect();
                    let mut got = vec![0.0; n];
                    system.add_transposed(&mut c.clone(), &mut got);
                    for (j, column) in columns.iter().enumerate() {
                        let expect: f64 = column.iter().zip(&c).map(|(s, c)| s * c).sum();
                        assert!(
                            (got[j] - expect).abs() < 1e-12 * (1.0 + expect.abs()),
                            "n={n} {ends:?} j={j}: {} vs {expect}",
                            got[j]
                        );
                    }
                }
            }
        }
    }
}

//! Interpolation by a discrete periodic spline (Malozemov et al.'s §2, problem (1); docs/methods.md §3):
//! the poles `a_p` with `S_r(l n) = z(l)`, `l` in `0..m`.
//!
//! The system `sum_p a_p Q_r((l - p) n) = z(l)` is circulant, so the discrete Fourier transform
//! diagonalises it. Per coordinate,
//!
//! ```text
//! a_p = (1/m) sum_k Z(k) / T_r(k) w^(k p),   w = exp(2 pi i / m),   Z(k) = sum_l z(l) w^(-k l),
//! T_r(0) = 1,   T_r(k) = (2 sin(pi k/m))^(2r) Lambda_r(k),
//! Lambda_r(k) = sum_{q=0}^{n-1} (2 n sin(pi (q m + k)/N))^(-2r).
//! ```
//!
//! `T_r(k)` is computed as `sum_q rho_q^(2r)` with `rho_q = sin(pi k/m) / (n sin(pi (q m + k)/N))`.
//! Every `rho_q` lies in `(0, 1]` (`|sin(n x)| <= n |sin x|`), so nothing overflows for any order.
//! `T_r` is real and `T_r(k) = T_r(m - k)`, so only `k <= m/2` is needed and the transforms are
//! real-to-complex ones (the `realfft` crate over `rustfft`).
//!
//! Cost: the symbol is `O(N)` once per plan (`N/2` terms); each solve is two real FFTs of length
//! `m` per coordinate, `O(m log m)`, with no allocation. A plan is reused for many right-hand
//! sides of the same `m, n, r` (the rows and columns of a tube).

use std::f64::consts::PI;
use std::fmt;
use std::sync::Arc;

use realfft::num_complex::Complex;
use realfft::{ComplexToReal, RealFftPlanner, RealToComplex};

use rayon::prelude::*;

use super::period::check_period;
use crate::core::parallel::worth_splitting;
use crate::{Error, Point, Result};

/// A reusable solver of the interpolation problem `S_r(l n) = z(l)`, `l` in `0..m`, for one
/// `m`, `n` and order `r`.
///
/// ```
/// use karkas::dps::{DiscreteSpline, InterpolationPlan};
/// use karkas::Point;
/// let nodes = [Point([0.0, 0.0]), Point([2.0, 0.0]), Point([2.0, 1.0]), Point([0.0, 1.0])];
/// let mut plan = InterpolationPlan::new(4, 8, 2).unwrap();
/// let mut poles = [Point::ZERO; 4];
/// plan.poles_into(&nodes, &mut poles).unwrap();
/// let spline = DiscreteSpline::from_poles(&poles, 2, 8).unwrap();
/// let values = spline.to_values();
/// for (l, z) in nodes.iter().enumerate() {
///     assert!(values[8 * l].distance(*z) < 1e-13);
/// }
/// ```
#[derive(Clone)]
pub struct InterpolationPlan {
    m: usize,
    n: usize,
    order: usize,
    /// `T_r(k)` for `k` in `0..=m/2`.
    symbol: Vec<f64>,
    forward: Arc<dyn RealToComplex<f64>>,
    inverse: Arc<dyn ComplexToReal<f64>>,
    signal: Vec<f64>,
    spectrum: Vec<Complex<f64>>,
    forward_scratch: Vec<Complex<f64>>,
    inverse_scratch: Vec<Complex<f64>>,
}

impl fmt::Debug for InterpolationPlan {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.debug_struct("InterpolationPlan")
            .field("m", &self.m)
            .field("n", &self.n)
            .field("order", &self.order)
            .finish_non_exhaustive()
    }
}

impl InterpolationPlan {
    /// The plan for `m` nodes, step `n` (period `N = m n`) and order `order`.
    ///
    /// Errors: `m < 2`, `n < 2`, `order` outside `1..=`[`MAX_ORDER`](super::MAX_ORDER), `m n`
    /// overflowing.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::dps::InterpolationPlan;
    ///
    /// let plan = InterpolationPlan::new(8, 4, 2)?;
    /// assert_eq!((plan.nodes(), plan.step(), plan.order()), (8, 4, 2));
    /// assert!(InterpolationPlan::new(1, 4, 2).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(m: usize, n: usize, order: usize) -> Result<Self> {
        check_period(m, n, order, "a discrete periodic spline")?;
        let mut planner = RealFftPlanner::<f64>::new();
        let forward = planner.plan_fft_forward(m);
        let inverse = planner.plan_fft_inverse(m);
        let forward_scratch = forward.make_scratch_vec();
        let inverse_scratch = inverse.make_scratch_vec();
        Ok(InterpolationPlan {
            m,
            n,
            order,
            symbol: symbol(m, n, order),
            signal: forward.make_input_vec(),
            spectrum: forward.make_output_vec(),
            forward,
            inverse,
            forward_scratch,
            inverse_scratch,
        })
    }

    /// The number of nodes (and poles) `m`.
    pub fn nodes(&self) -> usize {
        self.m
    }

    /// The step `n` between nodes.
    pub fn step(&self) -> usize {
        self.n
    }

    /// The order `r`.
    pub fn order(&self) -> usize {
        self.order
    }

    /// The eigenvalues `T_r(k)` of the interpolation matrix `Q_r((l - p) n)`, for `k` in
    /// `0..=m/2` (the others follow from `T_r(m - k) = T_r(k)`). `T_r(0) = 1`; all lie in
    /// `(0, 1]`.
    pub fn symbol(&self) -> &[f64] {
        &self.symbol
    }

    /// Writes into `poles` the poles `a_0..a_{m-1}` of the spline with `S_r(l n) = nodes[l]`.
    ///
    /// Errors: `nodes` or `poles` not of length `m`; a non-finite node.
    pub fn poles_into<const D: usize>(
        &mut self,
        nodes: &[Point<D>],
        poles: &mut [Point<D>],
    ) -> Result<()> {
        let m = self.m;
        if nodes.len() != m {
            return Err(Error::CountMismatch {
                what: "interpolation nodes",
                expected: m,
                got: nodes.len(),
            });
        }
        if poles.len() != m {
            return Err(Error::CountMismatch {
                what: "pole buffer",
                expected: m,
                got: poles.len(),
            });
        }
        if let Some(index) = nodes.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        let scale = 1.0 / m as f64;
        for c in 0..D {
            for (s, z) in self.signal.iter_mut().zip(nodes) {
                *s = z[c];
            }
            self.forward
                .process_with_scratch(
                    &mut self.signal,
                    &mut self.spectrum,
                    &mut self.forward_scratch,
                )
                .map_err(fft_error)?;
            for (value, t) in self.spectrum.iter_mut().zip(&self.symbol) {
                *value *= scale / t;
            }
            // Exactly real, as the inverse transform requires (they are, up to rounding).
            self.spectrum[0].im = 0.0;
            if m.is_multiple_of(2) {
                self.spectrum[m / 2].im = 0.0;
            }
            self.inverse
                .process_with_scratch(
                    &mut self.spectrum,
                    &mut self.signal,
                    &mut self.inverse_scratch,
                )
                .map_err(fft_error)?;
            for (a, s) in poles.iter_mut().zip(&self.signal) {
                a[c] = *s;
            }
        }
        Ok(())
    }
}

/// An FFT failure; buffers are made by the plans themselves, so this does not happen.
fn fft_error(_: realfft::FftError) -> Error {
    Error::Internal {
        what: "an FFT of the size its plan was made for failed",
    }
}

/// `T_r(k)` for `k` in `0..=m/2` (module docs).
///
/// The sines `sin(pi (q m + k)/N) = sin(pi q/n + pi k/N)` come from the angle-addition formula
/// with `sin` and `cos` of `pi q/n` tabulated once: two multiplications instead of a sine per
/// term. For `k <= m/2` the added angle is at most `pi/(2n)`, so near `pi` (where the sum is a
/// difference) at most one bit cancels, and for `q = 0` the result is `sin(pi k/N)` exactly.
fn symbol(m: usize, n: usize, order: usize) -> Vec<f64> {
    let big_n = (m * n) as f64;
    let step: Vec<(f64, f64)> = (0..n)
        .map(|q| (PI * q as f64 / n as f64).sin_cos())
        .collect();
    let power = 2 * order as i32;
    let term = |k: usize| -> f64 {
        if k == 0 {
            return 1.0;
        }
        let (sin_k, cos_k) = (PI * k as f64 / big_n).sin_cos();
        // sin(pi k / m) / n, the numerator of every rho_q.
        let top = (PI * k as f64 / m as f64).sin() / n as f64;
        let mut sum = 0.0;
        for &(sin_q, cos_q) in &step {
            let rho = top / (sin_q * cos_k + cos_q * sin_k);
            sum += rho.powi(power);
        }
        sum
    };
    // Every k is independent: large symbols are computed in parallel (same values).
    if !worth_splitting((m / 2) * n) {
        (0..=m / 2).map(term).collect()
    } else {
        (0..m / 2 + 1)
            .into_par_iter()
            .with_min_len(1024)
            .map(term)
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn symbol_of_the_hat_is_known() {
        // r = 1: the matrix Q_1((l - p) n) is the identity (the hat vanishes at the other
        // nodes), so T_1(k) = 1 for every k.
        for (m, n) in [(2, 2), (5, 3), (8, 16)] {
            for t in symbol(m, n, 1) {
                assert!((t - 1.0).abs() < 1e-14, "m={m} n={n}: {t}");
            }
        }
    }
}

//! The LL kernel `h` of order `L` (Aulchenko et al., formulas (4), (5), (9); docs/methods.md §1.1).
//!
//! ```text
//! eps_k = C(L+k, k) / (L+k)                    k = 0..L
//! d_L   = C(2L, L) / 2^(2L+2)
//! h(xi) = xi^(L+1) sum_{k=0..L} eps_k (L-k) (1-xi)^k          degree 2L
//! h'(xi)  = 2L xi^L sum_{k=0..L-1} eps_k (1-xi)^k
//! h''(xi) = 2L C(2L-1, L) xi^(L-1) (1-xi)^(L-1)
//! ```
//!
//! `h` and `h'` are evaluated by Horner's rule in `y = 1 - xi`, where every coefficient is
//! positive: on `[0, 1]` there is no cancellation at any order. Derivatives of order `j >= 2`
//! come from the closed form of `h''` by Leibniz's rule.
//!
//! The weights of one LL segment (`P = c_- r_{i-1} + c_0 r_i + c_+ r_{i+1}`) are
//! `c_- = (1 - 2xi + h)/2`, `c_0 = (1 + 2xi - 2h)/2`, `c_+ = h/2`: non-negative, summing to 1.

use crate::{Error, Result};

/// The largest LL order accepted. Higher orders add nothing useful (the kernel tends to a
/// step) and their coefficients would overflow the exponent range of `xi^(L+1)` near 0.
pub const MAX_ORDER: usize = 64;

/// The kernel `h` of one order `L`, with its coefficients computed once.
#[derive(Clone, Debug, PartialEq)]
pub struct LlKernel {
    order: usize,
    d_l: f64,
    /// `eps_k (L - k)`, k = 0..L-1: `h = xi^(L+1) * sum value_coeffs[k] y^k`.
    value_coeffs: Vec<f64>,
    /// `2 L eps_k`, k = 0..L-1: `h' = xi^L * sum slope_coeffs[k] y^k`.
    slope_coeffs: Vec<f64>,
    /// `2L C(2L-1, L)`: `h'' = curvature_factor * xi^(L-1) y^(L-1)`.
    curvature_factor: f64,
}

/// Binomial coefficient as a float (exact for the sizes used here).
pub(crate) fn binomial(n: usize, k: usize) -> f64 {
    let k = k.min(n - k);
    (0..k).fold(1.0, |acc, m| acc * (n - m) as f64 / (m + 1) as f64)
}

/// `x^n` by repeated squaring; fully unrolled when `n` is a constant.
#[inline(always)]
pub(crate) fn pow_n(x: f64, n: usize) -> f64 {
    let mut result = 1.0;
    let mut base = x;
    let mut e = n;
    while e > 0 {
        if e & 1 == 1 {
            result *= base;
        }
        base *= base;
        e >>= 1;
    }
    result
}

/// `n (n-1) ... (n-r+1)`, the `r`-th derivative factor of `x^n`.
fn falling_factorial(n: usize, r: usize) -> f64 {
    (0..r).fold(1.0, |acc, m| acc * (n - m) as f64)
}

impl LlKernel {
    /// The kernel of order `order` (`1 <= order <= MAX_ORDER`).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::ll::LlKernel;
    ///
    /// let kernel = LlKernel::new(3)?;
    /// assert_eq!(kernel.order(), 3);
    /// assert!(LlKernel::new(0).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(order: usize) -> Result<Self> {
        if order == 0 {
            return Err(Error::InvalidOrder {
                order,
                reason: "the LL order L must be at least 1",
            });
        }
        if order > MAX_ORDER {
            return Err(Error::InvalidOrder {
                order,
                reason: "the LL order L must be at most 64",
            });
        }
        let l = order;
        let eps: Vec<f64> = (0..=l)
            .map(|k| binomial(l + k, k) / (l + k) as f64)
            .collect();
        let value_coeffs = (0..l).map(|k| eps[k] * (l - k) as f64).collect();
        let slope_coeffs = (0..l).map(|k| 2.0 * l as f64 * eps[k]).collect();
        let d_l = binomial(2 * l, l) / 2f64.powi(2 * l as i32 + 2);
        let curvature_factor = 2.0 * l as f64 * binomial(2 * l - 1, l);
        Ok(LlKernel {
            order,
            d_l,
            value_coeffs,
            slope_coeffs,
            curvature_factor,
        })
    }

    /// The order `L`.
    #[inline]
    pub fn order(&self) -> usize {
        self.order
    }

    /// `d_L`: the node deviation factor, `P_i(1/2) - r_i = d_L (r_{i-1} - 2 r_i + r_{i+1})`.
    #[inline]
    pub fn d_l(&self) -> f64 {
        self.d_l
    }

    /// The coefficients `eps_k (L - k)`, `k = 0..L-1`, of `h / xi^(L+1)` in powers of `1 - xi`.
    #[inline]
    pub fn value_coeffs(&self) -> &[f64] {
        &self.value_coeffs
    }

    /// `h(xi)`.
    #[inline]
    pub fn h(&self, xi: f64) -> f64 {
        let y = 1.0 - xi;
        let q = self
            .value_coeffs
            .iter()
            .rev()
            .fold(0.0, |acc, &a| acc * y + a);
        q * pow_n(xi, self.order + 1)
    }

    /// The `j`-th derivative `h^(j)(xi)` (`j = 0` is `h`); zero for `j > 2L`.
    pub fn derivative(&self, xi: f64, j: usize) -> f64 {
        let l = self.order;
        match j {
            0 => self.h(xi),
            1 => {
                let y = 1.0 - xi;
                let q = self
                    .slope_coeffs
                    .iter()
                    .rev()
                    .fold(0.0, |acc, &b| acc * y + b);
                q * pow_n(xi, l)
            }
            _ => {
                // h'' = c x^a y^a with a = L - 1; d^m/dx^m of x^a y^a by Leibniz.
                let a = l - 1;
                let m = j - 2;
                if m > 2 * a {
                    return 0.0;
                }
                let y = 1.0 - xi;
                let mut sum = 0.0;
                for r in m.saturating_sub(a)..=m.min(a) {
                    let s = m - r;
                    let sign = if s.is_multiple_of(2) { 1.0 } else { -1.0 };
                    sum += binomial(m, r)
                        * falling_factorial(a, r)
                        * pow_n(xi, a - r)
                        * sign
                        * falling_factorial(a, s)
                        * pow_n(y, a - s);
                }
                self.curvature_factor * sum
            }
        }
    }

    /// The weights `[c_-, c_0, c_+]` of the `k`-th derivative (in `xi`) of one segment:
    /// `P^(k)(xi) = c_- r_{i-1} + c_0 r_i + c_+ r_{i+1}`.
    #[inline]
    pub fn weights(&self, xi: f64, k: usize) -> [f64; 3] {
        match k {
            0 => {
                let h = self.h(xi);
                [0.5 * (1.0 - 2.0 * xi + h), 0.5 + xi - h, 0.5 * h]
            }
            1 => {
                let dh = self.derivative(xi, 1);
                [0.5 * dh - 1.0, 1.0 - dh, 0.5 * dh]
            }
            _ => {
                let dh = self.derivative(xi, k);
                [0.5 * dh, -dh, 0.5 * dh]
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn low_orders_match_hand_expansion() {
        // L = 1: eps_0 = 1, h = xi^2.  L = 2: eps = [1/2, 1], h = xi^3 (1 + (1 - xi)) = 2xi^3 - xi^4.
        let k1 = LlKernel::new(1).unwrap();
        let k2 = LlKernel::new(2).unwrap();
        for &x in &[0.0, 0.1, 0.37, 0.5, 0.9, 1.0] {
            assert!((k1.h(x) - x * x).abs() < 1e-15);
            assert!((k2.h(x) - (2.0 * x.powi(3) - x.powi(4))).abs() < 1e-15);
            assert!((k2.derivative(x, 1) - (6.0 * x * x - 4.0 * x.powi(3))).abs() < 1e-14);
            assert!((k2.derivative(x, 3) - (12.0 - 24.0 * x)).abs() < 1e-13);
            assert!((k2.derivative(x, 4) + 24.0).abs() < 1e-13);
            assert_eq!(k2.derivative(x, 5), 0.0);
        }
        assert_eq!(k1.d_l(), 0.125);
        assert_eq!(k2.d_l(), 3.0 / 32.0);
    }

    #[test]
    fn order_bounds_are_errors() {
        assert!(matches!(
            LlKernel::new(0),
            Err(Error::InvalidOrder { order: 0, .. })
        ));
        assert!(LlKernel::new(MAX_ORDER).is_ok());
        assert!(LlKernel::new(MAX_ORDER + 1).is_err());
    }

    #[test]
    fn pow_n_is_exact_for_small_powers() {
        assert_eq!(pow_n(3.0, 0), 1.0);
        assert_eq!(pow_n(3.0, 5), 243.0);
        assert_eq!(pow_n(0.5, 11), 0.5f64.powi(11));
    }
}

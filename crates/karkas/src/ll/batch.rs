//! The per-parameter part of batch LL evaluation (Aulchenko et al., formulas (3)–(5)): from
//! `s = t (K+1) + 1/2` to the segment, the local coordinate `xi` and the kernel value
//! `h(xi)`, written once over [`Lane`] so that a batch runs it on four parameters per step
//! in `f64x4` with float arithmetic only (no gathers, no conversions, no branches) and the
//! remainder of a batch runs the same operations on one `f64`.

use crate::core::lanes::Lane;

/// `floor(s)` for `0 <= s < 2^51`, by rounding through `2^52` (a libm call is avoided on
/// baseline x86-64, and the arithmetic stays in vector registers). Exact halves may round
/// either way, which moves a parameter on a segment border to the neighbouring segment: the
/// LL curve is continuous there, so the point is the same.
#[inline(always)]
fn floor_small<T: Lane>(s: T) -> T {
    let two_52 = T::splat(4_503_599_627_370_496.0);
    (s - T::splat(0.5) + two_52) - two_52
}

/// `x^n` by repeated squaring, the operations of [`pow_n`](super::kernel::pow_n).
#[inline(always)]
fn pow_lanes<T: Lane>(x: T, n: usize) -> T {
    let mut result = T::splat(1.0);
    let mut base = x;
    let mut e = n;
    while e > 0 {
        if e & 1 == 1 {
            result = result * base;
        }
        base = base * base;
        e >>= 1;
    }
    result
}

/// For `s = t (K+1) + 1/2` (t already in the domain): the segment number as a float, the
/// local coordinate `xi = s - segment` and `h(xi) = xi^(L+1) sum coeffs[k] (1 - xi)^k`
/// (Horner's rule in `1 - xi`, every coefficient positive).
#[inline(always)]
pub(super) fn segment_and_kernel<T: Lane, const L: usize>(s: T, coeffs: &[f64; L]) -> [T; 3] {
    let i = floor_small(s);
    let xi = s - i;
    let y = T::splat(1.0) - xi;
    let mut q = T::splat(coeffs[L - 1]);
    for &c in coeffs[..L - 1].iter().rev() {
        q = q * y + T::splat(c);
    }
    [i, xi, q * pow_lanes(xi, L + 1)]
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::lanes::f64x4;
    use crate::ll::LlKernel;

    /// Four lanes give the bits of four single parameters, and `h` is the kernel's.
    #[test]
    fn lanes_equal_single_parameters_and_the_kernel() {
        let kernel = LlKernel::new(5).unwrap();
        let coeffs: [f64; 5] = std::array::from_fn(|k| kernel.value_coeffs()[k]);
        let s = [1.5, 2.25, 7.999_999_999, 3.5];
        let four = segment_and_kernel::<f64x4, 5>(f64x4::new(s), &coeffs).map(|x| x.to_array());
        for l in 0..4 {
            let one = segment_and_kernel::<f64, 5>(s[l], &coeffs);
            for j in 0..3 {
                assert_eq!(four[j][l].to_bits(), one[j].to_bits());
            }
            assert_eq!(one[0], s[l].floor());
            assert!((one[2] - kernel.h(one[1])).abs() < 1e-15);
        }
    }
}

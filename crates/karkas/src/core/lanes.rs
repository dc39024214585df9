//! Four parameters at a time: the `f64x4` vectors of the `wide` crate (portable SIMD in safe
//! Rust: SSE2 or AVX on x86-64, NEON on AArch64, simd128 on WebAssembly, plain arrays
//! elsewhere), behind one small trait shared with plain `f64`.
//!
//! A batch kernel written once over [`Lane`] runs on four parameters per step, and the
//! one-point evaluation runs the very same operations in the same order on one: no fused
//! multiply-add is ever formed (neither `wide` nor Rust contracts `a * b + c`), so both give
//! the same bits. Negation flips the sign bit (`wide`'s own `-x` is `0 - x`, which turns
//! `-0.0` into `+0.0`).

use std::ops::{Add, Mul, Sub};

pub(crate) use wide::{f64x4, CmpGe, CmpGt, CmpLt};

/// The number of parameters of one [`f64x4`].
pub(crate) const LANES: usize = 4;

/// The four numbers of `chunk` (of length [`LANES`], e.g. from `chunks_exact`) as one vector,
/// read by one unaligned load (building it number by number goes through the stack and
/// stalls on the store forwarding).
#[inline(always)]
pub(crate) fn load4(chunk: &[f64]) -> f64x4 {
    bytemuck::pod_read_unaligned(bytemuck::cast_slice(chunk))
}

/// A number or four numbers: the arithmetic a batch kernel and its one-point form share.
pub(crate) trait Lane:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self>
{
    /// `x` in every lane.
    fn splat(x: f64) -> Self;
    /// `-self`, exactly (the sign bit flipped).
    fn neg(self) -> Self;
}

impl Lane for f64 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        x
    }
    #[inline(always)]
    fn neg(self) -> Self {
        -self
    }
}

impl Lane for f64x4 {
    #[inline(always)]
    fn splat(x: f64) -> Self {
        f64x4::splat(x)
    }
    #[inline(always)]
    fn neg(self) -> Self {
        self ^ f64x4::splat(-0.0)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn negation_keeps_signed_zeros_and_nan_payloads() {
        let x = f64x4::new([0.0, -0.0, 1.5, f64::NAN]);
        let n = Lane::neg(x).to_array();
        assert_eq!(n[0].to_bits(), (-0.0f64).to_bits());
        assert_eq!(n[1].to_bits(), 0.0f64.to_bits());
        assert_eq!(n[2], -1.5);
        assert_eq!(n[3].to_bits(), (-f64::NAN).to_bits());
    }
}

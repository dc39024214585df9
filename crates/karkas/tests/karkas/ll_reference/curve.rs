//! The reference LL curve of docs/methods.md §1.2 and the shared border checks.

use super::RefKernel;
use crate::common::{assert_near, max_abs};
use karkas::ll::LlCurve;
use karkas::{PiecewiseCurve, Point, Side};

// ------------------------------------------------------------------------------------------
// Reference curve (§1.2)
// ------------------------------------------------------------------------------------------

/// An LL curve built from the definition: closing rule, end rules, segment weights.
pub struct RefCurve<const D: usize> {
    pub kernel: RefKernel,
    /// `r_0..r_{K+1}`.
    pub ext: Vec<Point<D>>,
}

impl<const D: usize> RefCurve<D> {
    /// `points` are `r_1..r_K` (for `closed`, the first is appended unless the last equals
    /// it exactly).
    pub fn new(points: &[Point<D>], l: usize, closed: bool) -> Self {
        let mut r = points.to_vec();
        if closed && r[0] != r[r.len() - 1] {
            r.push(r[0]);
        }
        RefCurve {
            kernel: RefKernel::new(l),
            ext: extend(&r, closed),
        }
    }

    /// K.
    pub fn k(&self) -> usize {
        self.ext.len() - 2
    }

    /// `K + 1`.
    pub fn scale(&self) -> f64 {
        (self.k() + 1) as f64
    }

    /// `t_i = i / (K+1)`.
    pub fn node(&self, i: usize) -> f64 {
        i as f64 / self.scale()
    }

    /// The parameter of local coordinate `xi` on segment `i`.
    pub fn param(&self, i: usize, xi: f64) -> f64 {
        (i as f64 - 0.5 + xi) / self.scale()
    }

    /// `D_i = r_{i-1} + r_{i+1} - 2 r_i`.
    pub fn d(&self, i: usize) -> Point<D> {
        self.ext[i - 1] + self.ext[i + 1] - self.ext[i] * 2.0
    }

    /// `d^k P / dt^k` on segment `i` at `xi`.
    pub fn seg(&self, i: usize, xi: f64, k: usize) -> Point<D> {
        let w = self.kernel.weights(xi, k);
        (self.ext[i - 1] * w[0] + self.ext[i] * w[1] + self.ext[i + 1] * w[2])
            * self.scale().powi(k as i32)
    }

    /// The segment and local coordinate of `t` (inside the domain). A border (to rounding)
    /// belongs to the segment above it, as `Curve::deriv` documents.
    pub fn locate(&self, t: f64) -> (usize, f64) {
        let s = t * self.scale() + 0.5;
        let near = s.round();
        let i = if (s - near).abs() < 1e-13 {
            near
        } else {
            s.floor()
        };
        let i = (i as usize).clamp(1, self.k());
        (i, s - i as f64)
    }

    /// `d^k P / dt^k` at `t` in the domain.
    pub fn at(&self, t: f64, k: usize) -> Point<D> {
        let (i, xi) = self.locate(t);
        self.seg(i, xi, k)
    }

    /// Largest coordinate of the extended polygon (at least 1).
    pub fn size(&self) -> f64 {
        max_abs(&self.ext)
    }

    /// A magnitude for the k-th t-derivative: `(K+1)^k * size * max(max|h^(k)|, 3)`.
    pub fn deriv_scale(&self, k: usize) -> f64 {
        self.scale().powi(k as i32) * self.size() * self.kernel.max_abs(k).max(3.0)
    }
}

/// `r_0..r_{K+1}` from `r_1..r_K` by the end rules of §1.2 (closed: `r_K == r_1`).
pub fn extend<const D: usize>(r: &[Point<D>], closed: bool) -> Vec<Point<D>> {
    let k = r.len();
    let (first, last) = if closed {
        (r[k - 2], r[1])
    } else {
        (r[0] * 2.0 - r[1], r[k - 1] * 2.0 - r[k - 2])
    };
    let mut out = vec![first];
    out.extend_from_slice(r);
    out.push(last);
    out
}

// ------------------------------------------------------------------------------------------
// Shared curve checks
// ------------------------------------------------------------------------------------------

/// Error allowance for the k-th t-derivative of `r`'s curve: relative 1e-12 of its size,
/// plus the effect of a parameter that misses a breakpoint by a few ulp.
pub fn deriv_tol<const D: usize>(r: &RefCurve<D>, k: usize) -> f64 {
    1e-12 * r.deriv_scale(k) + 64.0 * f64::EPSILON * r.k() as f64 * r.deriv_scale(k + 1) / r.scale()
}

/// At every interior segment border of `c`: derivatives of order 0..=L agree from both sides
/// (docs/methods.md §1.2 "continuity up to order L"), and the (L+1)-th jumps by exactly the
/// reference amount `P_i^(L+1)(0) - P_{i-1}^(L+1)(1)`, which must be large (so that this
/// check would notice a curve that is smoother than claimed, or a wrong kernel).
pub fn check_curve_borders<const D: usize>(c: &LlCurve<D>, r: &RefCurve<D>, what: &str) {
    let l = r.kernel.l;
    let k = r.k();
    let bps = c.breakpoints();
    assert_eq!(bps.len(), k + 1, "{what}: breakpoints {bps:?}");
    assert!((bps[0] - r.node(1)).abs() < 1e-15 && (bps[k] - r.node(k)).abs() < 1e-15);
    assert_eq!(c.continuity(), l);
    for i in 2..=k {
        let b = bps[i - 1];
        assert!(
            (b - r.param(i, 0.0)).abs() < 1e-15,
            "{what}: border {i} at {b}"
        );
        for kd in 0..=l {
            let lo = c.deriv_on_side(b, kd, Side::Below);
            let hi = c.deriv_on_side(b, kd, Side::Above);
            assert_near(
                lo,
                hi,
                deriv_tol(r, kd),
                &format!("{what}: C^{kd} at border {i}"),
            );
            // And both sides are the reference (so neither side is, e.g., the same segment).
            assert_near(lo, r.seg(i - 1, 1.0, kd), deriv_tol(r, kd), what);
            assert_near(hi, r.seg(i, 0.0, kd), deriv_tol(r, kd), what);
        }
        let tol = deriv_tol(r, l + 1);
        let jump = c.deriv_on_side(b, l + 1, Side::Above) - c.deriv_on_side(b, l + 1, Side::Below);
        let want = r.seg(i, 0.0, l + 1) - r.seg(i - 1, 1.0, l + 1);
        assert_near(
            jump,
            want,
            tol,
            &format!("{what}: jump of P^(L+1) at border {i}"),
        );
        assert!(
            want.max_abs() > 1e3 * tol,
            "{what}: P^(L+1) should jump at border {i}: {want:?} vs tolerance {tol:e}"
        );
    }
}

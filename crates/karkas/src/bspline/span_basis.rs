//! The `p + 1` B-spline basis functions of any degree `p` that are nonzero on one knot span,
//! and the derivatives of a B-spline on one span: what rational curves and surfaces
//! ([`NurbsCurve`](super::NurbsCurve), [`NurbsSurface`](super::NurbsSurface)) are evaluated
//! with.
//!
//! The values are the Cox–de Boor recurrence (Piegl and Tiller, *The NURBS Book*, A2.2).
//! [`local_derivatives`] gives the derivatives of a B-spline (of homogeneous points) on one
//! span the way their (3.4)–(3.8) define them: the span's `p + 1` control points differenced
//! `k` times, `Q^(k+1)_i = (p - k) (Q^(k)_i - Q^(k)_(i-1)) / (t_(i+p-k) - t_i)`, then weighed
//! with the basis values of degree `p - k`. It differences the points before scaling by the
//! knot gaps, where weighing the points with derivatives of basis functions (A2.3 and A3.2)
//! scales first and subtracts large terms after: on a span a thousand times shorter than the
//! curve the second derivative by basis derivatives loses six digits more (measured on a
//! 285-pole wing section against Open CASCADE and a 50-digit reference). Any degree up to
//! [`MAX_DEGREE`](super::MAX_DEGREE) runs on the stack; cost `O(p^2)` per order.
//! [`basis_derivative`] keeps the basis functions' own derivatives, for tests and the
//! polynomial bases.

use core::ops::{Add, Mul, Sub};

use super::MAX_DEGREE;

/// The most basis functions on one span: `MAX_DEGREE + 1`.
pub(crate) const MAX_SPAN: usize = MAX_DEGREE + 1;

/// The working arrays of spans of degree below this are this long, not [`MAX_SPAN`]: zeroing
/// arrays of `MAX_SPAN` on every evaluation cost more than the arithmetic of a low degree.
pub(crate) const SMALL_SPAN: usize = 16;

/// The working arrays of spans of degree below this (lines, conics, cubics: most of what CAD
/// files hold) are this long: zeroing and copying arrays of [`SMALL_SPAN`] still cost more than
/// the arithmetic of degrees 1 to 3.
pub(crate) const TINY_SPAN: usize = 4;

/// Writes the `k`-th derivatives of the basis functions of degree `p` that are nonzero on the
/// span `span` (`knots[span] <= t < knots[span + 1]`, `p <= span`, `span + p + 1 <
/// knots.len()`) at `t` into `out[0..=p]`: `out[c]` belongs to the function (and control
/// point) `span - p + c`. Zero for `k > p`. `out` must hold `p + 1` values.
pub(crate) fn basis_derivative(
    p: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    k: usize,
    out: &mut [f64],
) {
    if p < TINY_SPAN {
        basis_derivative_in::<TINY_SPAN>(p, knots, span, t, k, out);
    } else if p < SMALL_SPAN {
        basis_derivative_in::<SMALL_SPAN>(p, knots, span, t, k, out);
    } else {
        basis_derivative_in::<MAX_SPAN>(p, knots, span, t, k, out);
    }
}

/// [`basis_derivative`] with working arrays of `N > p` values.
fn basis_derivative_in<const N: usize>(
    p: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    k: usize,
    out: &mut [f64],
) {
    let out = &mut out[..=p];
    out.fill(0.0);
    if k > p {
        return;
    }
    let q = p - k;
    // Cox–de Boor of degree q: n[r] = N_{span - q + r, q}(t), r = 0..=q.
    let mut left = [0.0; N];
    let mut right = [0.0; N];
    let mut n = [0.0; N];
    n[0] = 1.0;
    for j in 1..=q {
        left[j] = t - knots[span + 1 - j];
        right[j] = knots[span + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            let denominator = right[r + 1] + left[j - r];
            let temp = if denominator != 0.0 {
                n[r] / denominator
            } else {
                0.0
            };
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    // The function span - q + r is the one of index c = k + r among span - p ..= span.
    out[k..].copy_from_slice(&n[..=q]);
    // Up through degrees q + 1 ..= p: D N_{i,d} = A_i N_{i,d-1} - A_{i+1} N_{i+1,d-1} with
    // A_i = d / (t_{i+d} - t_i); at degree d - 1 the nonzero entries are c = p - d + 1 ..= p.
    let first = span - p;
    for d in q + 1..=p {
        let a = |c: usize| -> f64 {
            let i = first + c;
            let gap = knots[i + d] - knots[i];
            if gap > 0.0 {
                d as f64 / gap
            } else {
                0.0
            }
        };
        for c in p - d..=p {
            let here = if c > p - d { a(c) * out[c] } else { 0.0 };
            let next = if c < p { a(c + 1) * out[c + 1] } else { 0.0 };
            out[c] = here - next;
        }
    }
}

/// What can be differenced and weighed: a point of the homogeneous numerator with its weight.
pub(crate) trait Linear:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<f64, Output = Self>
{
    /// The zero.
    const ZERO: Self;
}

impl Linear for f64 {
    const ZERO: Self = 0.0;
}

impl<const D: usize> Linear for crate::Point<D> {
    const ZERO: Self = crate::Point([0.0; D]);
}

/// A control point of the homogeneous form: `w P` and `w`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Homogeneous<const D: usize> {
    pub point: crate::Point<D>,
    pub weight: f64,
}

impl<const D: usize> Add for Homogeneous<D> {
    type Output = Self;
    fn add(self, o: Self) -> Self {
        Homogeneous {
            point: self.point + o.point,
            weight: self.weight + o.weight,
        }
    }
}

impl<const D: usize> Sub for Homogeneous<D> {
    type Output = Self;
    fn sub(self, o: Self) -> Self {
        Homogeneous {
            point: self.point - o.point,
            weight: self.weight - o.weight,
        }
    }
}

impl<const D: usize> Mul<f64> for Homogeneous<D> {
    type Output = Self;
    fn mul(self, s: f64) -> Self {
        Homogeneous {
            point: self.point * s,
            weight: self.weight * s,
        }
    }
}

impl<const D: usize> Linear for Homogeneous<D> {
    const ZERO: Self = Homogeneous {
        point: crate::Point([0.0; D]),
        weight: 0.0,
    };
}

/// The derivatives `0..out.len()` at `t` of the B-spline of degree `p` over `knots` whose
/// control points on the span `span` are `local[0..=p]` (the points `span - p ..= span`),
/// into `out`; orders above `p` are zero. See the module docs.
pub(crate) fn local_derivatives<T: Linear>(
    p: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    local: &[T],
    out: &mut [T],
) {
    if p < TINY_SPAN {
        local_derivatives_in::<T, TINY_SPAN>(p, knots, span, t, local, out);
    } else if p < SMALL_SPAN {
        local_derivatives_in::<T, SMALL_SPAN>(p, knots, span, t, local, out);
    } else {
        local_derivatives_in::<T, MAX_SPAN>(p, knots, span, t, local, out);
    }
}

/// [`local_derivatives`] with working arrays of `N > p` values.
fn local_derivatives_in<T: Linear, const N: usize>(
    p: usize,
    knots: &[f64],
    span: usize,
    t: f64,
    local: &[T],
    out: &mut [T],
) {
    let mut work = [T::ZERO; N];
    work[..=p].copy_from_slice(&local[..=p]);
    let mut basis = [0.0; N];
    let first = span - p;
    for (k, slot) in out.iter_mut().enumerate() {
        if k > p {
            *slot = T::ZERO;
            continue;
        }
        let d = p - k;
        basis_derivative_in::<N>(d, knots, span, t, 0, &mut basis);
        let mut sum = T::ZERO;
        for (r, &b) in basis[..=d].iter().enumerate() {
            sum = sum + work[k + r] * b;
        }
        *slot = sum;
        if k < p {
            // The control points of the next derivative, degree d - 1, on the same knots.
            for j in (k + 1..=p).rev() {
                let i = first + j;
                let gap = knots[i + d] - knots[i];
                work[j] = if gap > 0.0 {
                    (work[j] - work[j - 1]) * (d as f64 / gap)
                } else {
                    T::ZERO
                };
            }
        }
    }
}

/// The knot span holding `t` for a B-spline of degree `p` with `count` control points over
/// `knots` (any knot vector, clamped or not): `knots[s] <= t < knots[s + 1]` with `p <= s <
/// count`; `t` at or beyond the domain's end gives the last nonempty span, before its start
/// the first. `O(log n)`.
pub(crate) fn span_of(p: usize, knots: &[f64], count: usize, t: f64) -> usize {
    if t >= knots[count] {
        let mut s = count - 1;
        while s > p && knots[s] == knots[s + 1] {
            s -= 1;
        }
        return s;
    }
    let upper = knots[p + 1..=count].partition_point(|&k| k <= t) + p + 1;
    let mut s = (upper - 1).clamp(p, count - 1);
    // An empty span at the start (t before the domain): the first nonempty one.
    while s < count - 1 && knots[s] == knots[s + 1] {
        s += 1;
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::basis::cubic_span_weights;

    #[test]
    fn cubic_weights_agree_with_the_cubic_routine() {
        let knots = [0.0, 0.0, 0.0, 0.0, 0.1, 3.0, 3.4, 4.0, 7.0, 7.0, 7.0, 7.0];
        let mut out = [0.0; 4];
        for span in 3..8 {
            for s in [0.0, 0.31, 0.77] {
                let t = knots[span] + s * (knots[span + 1] - knots[span]);
                for k in 0..=4 {
                    basis_derivative(3, &knots, span, t, k, &mut out);
                    let want = cubic_span_weights(&knots[span - 2..span + 4], s, k);
                    for c in 0..4 {
                        let scale = 1.0 + want[c].abs();
                        assert!(
                            (out[c] - want[c]).abs() < 1e-12 * scale,
                            "span {span} s {s} k {k} c {c}: {} {}",
                            out[c],
                            want[c]
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn derivatives_match_differences_of_values_at_high_degree() {
        // Degree 7 on an unclamped, uneven knot vector: central differences of the values.
        let knots: Vec<f64> = (0..24).map(|i| (i as f64).powf(1.3) * 0.1).collect();
        let p = 7;
        let span = 11;
        let t = 0.5 * (knots[span] + knots[span + 1]);
        let h = 1e-5;
        let value = |x: f64, k: usize| {
            let mut out = [0.0; 8];
            basis_derivative(p, &knots, span, x, k, &mut out);
            out
        };
        for k in 1..=3 {
            let (a, b, d) = (value(t + h, k - 1), value(t - h, k - 1), value(t, k));
            for c in 0..=p {
                let fd = (a[c] - b[c]) / (2.0 * h);
                assert!(
                    (fd - d[c]).abs() < 1e-5 * (1.0 + d[c].abs()),
                    "k {k} c {c}: {fd} {}",
                    d[c]
                );
            }
        }
        let sum: f64 = value(t, 0).iter().sum();
        assert!((sum - 1.0).abs() < 1e-14);
        let dsum: f64 = value(t, 2).iter().sum();
        assert!(dsum.abs() < 1e-9);
    }

    #[test]
    fn spans_skip_empty_ones() {
        let knots = [0.0, 0.0, 0.0, 1.0, 1.0, 2.0, 2.0, 2.0];
        assert_eq!(span_of(2, &knots, 5, 0.0), 2);
        assert_eq!(span_of(2, &knots, 5, 1.0), 4);
        assert_eq!(span_of(2, &knots, 5, 0.999), 2);
        assert_eq!(span_of(2, &knots, 5, 2.0), 4);
        assert_eq!(span_of(2, &knots, 5, -1.0), 2);
        // Unclamped: the domain is [knots[p], knots[count]].
        let uniform = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0];
        assert_eq!(span_of(2, &uniform, 4, 2.0), 2);
        assert_eq!(span_of(2, &uniform, 4, 3.5), 3);
        assert_eq!(span_of(2, &uniform, 4, 4.0), 3);
    }
}

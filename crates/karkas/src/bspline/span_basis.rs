//! The `p + 1` B-spline basis functions of any degree `p` that are nonzero on one knot span,
//! and their derivatives of any order, at one parameter: what rational curves and surfaces
//! ([`NurbsCurve`](super::NurbsCurve), [`NurbsSurface`](super::NurbsSurface)) weigh their
//! control points with.
//!
//! The values are the Cox–de Boor recurrence (Piegl and Tiller, *The NURBS Book*, A2.2). The
//! `k`-th derivatives follow from the values of degree `p - k` taken back through `k`
//! differentiation steps `N'_{i,d} = d / (t_{i+d} - t_i) N_{i,d-1} - d / (t_{i+d+1} - t_{i+1})
//! N_{i+1,d-1}` (their (2.9)), a quotient with a zero divisor counting as zero: the same
//! numbers as A2.3, without its `(p + 1)^2` table, so any degree up to
//! [`MAX_DEGREE`](super::MAX_DEGREE) runs on the stack. Cost `O(p^2)` per derivative order.

use super::MAX_DEGREE;

/// The most basis functions on one span: `MAX_DEGREE + 1`.
pub(crate) const MAX_SPAN: usize = MAX_DEGREE + 1;

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
    let out = &mut out[..=p];
    out.fill(0.0);
    if k > p {
        return;
    }
    let q = p - k;
    // Cox–de Boor of degree q: n[r] = N_{span - q + r, q}(t), r = 0..=q.
    let mut left = [0.0; MAX_SPAN];
    let mut right = [0.0; MAX_SPAN];
    let mut n = [0.0; MAX_SPAN];
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

//! The four cubic B-splines that are nonzero on one knot span, and their derivatives, as
//! weights of the span's four control points.
//!
//! On the span `[t_2, t_3]` of the six knots `t_0..t_5` around it, a cubic B-spline is
//! `sum_c w_c P_c` over its control points `P_0..P_3` (the span's, in order). The weights of
//! the value are the Cox–de Boor recurrence; those of the `k`-th derivative come from the
//! recurrence of degree `3 - k` taken back through the `k` differencing steps of the control
//! points (`P'_c = p (P_c - P_{c-1}) / (t_{c-1+p} - t_{c-1})` at degree `p`), as their
//! transpose. Every divisor is a knot difference spanning `[t_2, t_3]`, so none is zero.
//!
//! Hand-written: a few lines, evaluated once per sample line of a grid evaluation, where
//! the general routines of B-spline crates take any degree and allocate.

/// The weights of the `k`-th derivative at local coordinate `s` (`(t - t_2) / (t_3 - t_2)`,
/// outside `[0, 1]` for the polynomial's continuation) of the cubic B-spline on the span
/// `[t[2], t[3]]` of the six knots `t`, one per control point of the span. Zero for `k > 3`.
#[inline]
pub(crate) fn cubic_span_weights(t: &[f64], s: f64, k: usize) -> [f64; 4] {
    debug_assert!(t.len() == 6 && t[2] < t[3]);
    if k > 3 {
        return [0.0; 4];
    }
    let x = s * (t[3] - t[2]);
    let q = 3 - k;
    // Cox–de Boor of degree q on the span, offsets from t[2]: n[0..=q] for controls 3-q..=3.
    let (mut left, mut right, mut n) = ([0.0; 4], [0.0; 4], [0.0; 4]);
    n[0] = 1.0;
    for j in 1..=q {
        left[j] = x - (t[3 - j] - t[2]);
        right[j] = (t[2 + j] - t[2]) - x;
        let mut saved = 0.0;
        for r in 0..j {
            let temp = n[r] / (right[r + 1] + left[j - r]);
            n[r] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        n[j] = saved;
    }
    let mut w = [0.0; 4];
    w[k..].copy_from_slice(&n[..=q]);
    // Back through the differencing steps of degree q + 1, .., 3.
    for p in q + 1..=3 {
        let mut up = [0.0; 4];
        for c in 4 - p..=3 {
            let a = p as f64 / (t[c - 1 + p] - t[c - 1]);
            up[c] += a * w[c];
            up[c - 1] -= a * w[c];
        }
        w = up;
    }
    w
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::{knot_vector, BSplineCurve};
    use crate::core::Curve;
    use crate::Point;

    type Point1 = Point<1>;

    /// A clamped cubic over uneven breaks (one span 30x another).
    fn curve() -> (BSplineCurve<1>, Vec<f64>) {
        let breaks = [0.0, 0.1, 3.0, 3.4, 4.0, 7.0];
        let knots = knot_vector(3, &breaks, &[1; 4]);
        let control: Vec<Point1> = (0..breaks.len() + 2)
            .map(|c| Point1::new([(c as f64 * 1.3).sin() + 0.1 * c as f64]))
            .collect();
        (BSplineCurve::new(3, knots.clone(), control).unwrap(), knots)
    }

    #[test]
    fn weights_give_de_boor_and_its_derivatives() {
        let (curve, knots) = curve();
        let control = curve.control_points();
        for span in 3..knots.len() - 4 {
            if knots[span] == knots[span + 1] {
                continue;
            }
            let t = &knots[span - 2..span + 4];
            for s in [0.0, 0.3, 0.999, 1.0] {
                let at = t[2] + s * (t[3] - t[2]);
                // The third derivative jumps at a knot: at s = 1 the curve gives the next span's.
                for k in 0..=if s < 1.0 { 3 } else { 2 } {
                    let w = cubic_span_weights(t, s, k);
                    let got: f64 = (0..4).map(|c| w[c] * control[span - 3 + c].0[0]).sum();
                    let want = curve.deriv(at.min(7.0), k).0[0];
                    let scale = 1.0 + want.abs();
                    assert!(
                        (got - want).abs() < 1e-11 * scale * 100f64.powi(k as i32),
                        "span {span} s {s} k {k}: {got} against {want}"
                    );
                }
            }
        }
    }

    #[test]
    fn weights_sum_to_one_and_derivative_weights_to_zero() {
        let (_, knots) = curve();
        for span in [3, 5, 7] {
            let t = &knots[span - 2..span + 4];
            for s in [-0.5, 0.25, 1.7] {
                let sums: Vec<f64> = (0..=4)
                    .map(|k| cubic_span_weights(t, s, k).iter().sum())
                    .collect();
                assert!((sums[0] - 1.0).abs() < 1e-14, "{sums:?}");
                for &d in &sums[1..] {
                    assert!(d.abs() < 1e-9, "{sums:?}");
                }
            }
        }
        assert_eq!(cubic_span_weights(&knots[3..9], 0.5, 4), [0.0; 4]);
    }

    #[test]
    fn outside_the_span_the_polynomial_continues() {
        // The span's cubic at s = 1.5, against the span's polynomial through its values.
        let (curve, knots) = curve();
        let control = curve.control_points();
        let span = 5;
        let t = &knots[span - 2..span + 4];
        let value = |s: f64| -> f64 {
            let w = cubic_span_weights(t, s, 0);
            (0..4).map(|c| w[c] * control[span - 3 + c].0[0]).sum()
        };
        // Cubic extrapolation from four samples inside, by Lagrange.
        let nodes = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
        let at = 1.5;
        let lagrange: f64 = (0..4)
            .map(|a| {
                let l: f64 = (0..4)
                    .filter(|&b| b != a)
                    .map(|b| (at - nodes[b]) / (nodes[a] - nodes[b]))
                    .product();
                l * value(nodes[a])
            })
            .sum();
        assert!(
            (value(at) - lagrange).abs() < 1e-12,
            "{} {}",
            value(at),
            lagrange
        );
    }
}

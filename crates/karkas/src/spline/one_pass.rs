//! The not-a-knot slopes of one line of values in a single pass (no stored factorization).

use super::system::{row_rhs, tap_sum};
use crate::{Error, Point, Result};

/// The slopes of one line of not-a-knot values (`n = knots.len() >= 4`) in a single pass:
/// the same rows, factorization and sweeps as [`SlopeSystem`](super::system::SlopeSystem) with `width = 1`, in the same
/// floating-point order (bitwise equal results), but formed on the fly from the knots, so
/// that the only scratch memory is the scaled super-diagonal. `O(n)`.
///
/// Fails with [`Error::SingularSystem`] where [`SlopeSystem::new`](super::system::SlopeSystem::new) would.
pub(crate) fn not_a_knot_slopes<const D: usize>(
    knots: &[f64],
    values: &[Point<D>],
    slopes: &mut [Point<D>],
) -> Result<()> {
    let n = knots.len();
    debug_assert!(n >= 4 && values.len() == n && slopes.len() == n);
    let step = |k: usize| knots[k + 1] - knots[k];
    let (h0, h1) = (step(0), step(1));
    let (hl, hm) = (step(n - 2), step(n - 3));
    let (gs, ge) = (h0 / h1, hl / hm);
    let len = n - 2;
    let mut upper_prime = vec![0.0; len];
    let mut previous = 0.0;
    let mut hp = h0;
    for (r, up_r) in upper_prime.iter_mut().enumerate() {
        let k = r + 1;
        let hc = step(k);
        let lambda = hc / (hp + hc);
        let mu = 1.0 - lambda;
        let (lower, diag, upper, weights) = if k == 1 {
            let w = mu + 2.0 * gs;
            (
                0.0,
                1.0 + gs,
                gs,
                [-lambda / h0, lambda / h0 - w / h1, w / h1],
            )
        } else if k == n - 2 {
            let w = lambda + 2.0 * ge;
            (ge, 1.0 + ge, 0.0, [-w / hm, w / hm - mu / hl, mu / hl])
        } else {
            let weights = [
                -3.0 * lambda / hp,
                3.0 * lambda / hp - 3.0 * mu / hc,
                3.0 * mu / hc,
            ];
            (lambda, 2.0, mu, weights)
        };
        let pivot = diag - lower * previous;
        if pivot.abs() <= 1e-300 || !pivot.is_finite() {
            return Err(Error::SingularSystem { row: r, pivot });
        }
        let inv_pivot = 1.0 / pivot;
        let up = upper * inv_pivot;
        *up_r = up;
        previous = up;
        let rhs = row_rhs(values[k - 1], values[k], values[k + 1], weights);
        slopes[k] = if r == 0 {
            rhs * inv_pivot
        } else {
            rhs.add_scaled(-lower, slopes[k - 1]) * inv_pivot
        };
        hp = hc;
    }
    for r in (0..len - 1).rev() {
        let next = slopes[r + 2];
        slopes[r + 1] = slopes[r + 1].add_scaled(-upper_prime[r], next);
    }
    // The not-a-knot end slopes (3.11), (3.12) from the solved ones.
    let (gs2, ge2) = (gs * gs, ge * ge);
    let combine = |taps: [(usize, f64); 3]| tap_sum(&taps, |k| values[k]);
    let start = [
        (0, -2.0 / h0),
        (1, 2.0 / h0 + 2.0 * gs2 / h1),
        (2, -2.0 * gs2 / h1),
    ];
    let end = [
        (n - 1, 2.0 / hl),
        (n - 2, -2.0 / hl - 2.0 * ge2 / hm),
        (n - 3, 2.0 * ge2 / hm),
    ];
    slopes[0] = (slopes[1] * (gs2 - 1.0) + slopes[2] * gs2) + combine(start);
    slopes[n - 1] = (slopes[n - 2] * (ge2 - 1.0) + slopes[n - 3] * ge2) + combine(end);
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spline::{SlopeSystem, SplineEnds};

    #[test]
    fn one_pass_not_a_knot_equals_the_factored_system_bitwise() {
        for n in [4usize, 5, 6, 17, 200] {
            let knots: Vec<f64> = (0..n)
                .map(|k| k as f64 + 0.6 * ((k * k) as f64 * 0.37).sin())
                .collect();
            let values: Vec<Point<3>> = (0..n)
                .map(|k| {
                    let f = k as f64;
                    Point([(1.3 * f).sin(), (0.7 * f).cos() * f, 1e-3 * f * f])
                })
                .collect();
            let mut expect = vec![Point::ZERO; n];
            SlopeSystem::new(&knots, &SplineEnds::<3>::NotAKnot)
                .unwrap()
                .solve(&values, &mut expect, 1, None);
            let mut got = vec![Point::ZERO; n];
            not_a_knot_slopes(&knots, &values, &mut got).unwrap();
            for (g, e) in got.iter().zip(&expect) {
                for c in 0..3 {
                    assert_eq!(g[c].to_bits(), e[c].to_bits(), "n={n}: {g:?} vs {e:?}");
                }
            }
        }
    }
}

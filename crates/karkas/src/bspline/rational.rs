//! What rational curves and surfaces share: the check of a general knot vector (clamped or
//! not), the check of weights, and the quotient rule that turns the derivatives of the
//! homogeneous numerator `A = sum N w P` and denominator `w = sum N w` into those of
//! `A / w` (Piegl and Tiller, *The NURBS Book*, (4.8) and (4.20); algorithms A4.2 and A4.4).

use super::curve::check_sizes;
use crate::{Error, Point, Result};

/// Checks the knot vector of a B-spline of degree `degree` with `count` control points, as
/// rational curves and surfaces read from CAD files have them: `count + degree + 1` finite,
/// nondecreasing knots, not necessarily clamped, with a nonempty domain `[knots[degree],
/// knots[count]]`, no value repeated more than `degree + 1` times and none strictly inside
/// the domain more than `degree` times (the curve would break there).
pub(crate) fn check_general_knots(degree: usize, knots: &[f64], count: usize) -> Result<()> {
    check_sizes(degree, knots, count)?;
    let (start, end) = (knots[degree], knots[count]);
    if end <= start {
        return Err(Error::InvalidKnot {
            index: count,
            value: end,
            reason: "the knot vector spans an empty domain",
        });
    }
    let mut run = 1;
    for k in 1..knots.len() {
        run = if knots[k] == knots[k - 1] { run + 1 } else { 1 };
        let inside = knots[k] > start && knots[k] < end;
        if run > degree + 1 || (inside && run > degree) {
            return Err(Error::InvalidKnot {
                index: k,
                value: knots[k],
                reason: if inside {
                    "a knot inside the domain repeats more than degree times"
                } else {
                    "a knot repeats more than degree + 1 times"
                },
            });
        }
    }
    Ok(())
}

/// Checks that every weight is finite and positive (the error names the first that is not).
pub(crate) fn check_weights(weights: &[f64]) -> Result<()> {
    match weights.iter().position(|w| !(w.is_finite() && *w > 0.0)) {
        Some(index) => Err(Error::InvalidWeight {
            index,
            value: weights[index],
        }),
        None => Ok(()),
    }
}

/// The binomial coefficients `C(n, 0..=n)` into `row` (which must hold `n + 1` values).
pub(crate) fn binomials(n: usize, row: &mut [f64]) {
    row[0] = 1.0;
    for i in 1..=n {
        row[i] = row[i - 1] * (n + 1 - i) as f64 / i as f64;
    }
}

/// The derivatives of a rational curve from those of its homogeneous form, in place:
/// `ders[k]` holds `A^(k)` on entry and `C^(k)` on return, `k = 0..ders.len()`, where
/// `w[k]` is `w^(k)` (missing entries beyond `w.len()` are zero). (4.8), A4.2.
pub(crate) fn rational_curve_derivatives<const D: usize>(ders: &mut [Point<D>], w: &[f64]) {
    let w0 = w[0];
    let mut row = vec![0.0; 0];
    let mut small = [0.0; 16];
    for k in 0..ders.len() {
        let binom: &mut [f64] = if k < small.len() {
            &mut small[..=k]
        } else {
            row.resize(k + 1, 0.0);
            &mut row[..=k]
        };
        binomials(k, binom);
        let mut v = ders[k];
        for i in 1..=k.min(w.len() - 1) {
            v -= ders[k - i] * (binom[i] * w[i]);
        }
        ders[k] = v * (1.0 / w0);
    }
}

/// The partial derivatives of a rational surface from those of its homogeneous form, in
/// place: `ders[k * (nv + 1) + l]` holds `A_{k,l}` on entry and `S_{k,l}` on return, and
/// `w[k * (nv + 1) + l]` is `w_{k,l}`, for `k <= nu`, `l <= nv`. (4.20), A4.4.
pub(crate) fn rational_surface_derivatives<const D: usize>(
    ders: &mut [Point<D>],
    w: &[f64],
    nu: usize,
    nv: usize,
) {
    let stride = nv + 1;
    let mut bu = vec![0.0; nu + 1];
    let mut bv = vec![0.0; nv + 1];
    for k in 0..=nu {
        binomials(k, &mut bu);
        for l in 0..=nv {
            binomials(l, &mut bv);
            let mut v = ders[k * stride + l];
            for i in 0..=k {
                for j in 0..=l {
                    if i == 0 && j == 0 {
                        continue;
                    }
                    let wij = w[i * stride + j];
                    if wij != 0.0 {
                        v -= ders[(k - i) * stride + (l - j)] * (bu[i] * bv[j] * wij);
                    }
                }
            }
            ders[k * stride + l] = v * (1.0 / w[0]);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knot_vectors_are_checked_as_files_give_them() {
        // Unclamped uniform knots are fine; an inner knot of multiplicity p + 1 is not.
        assert!(check_general_knots(2, &[0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 6.0], 4).is_ok());
        assert!(check_general_knots(2, &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 3).is_ok());
        let bad = check_general_knots(2, &[0.0, 0.0, 0.0, 0.5, 0.5, 0.5, 1.0, 1.0, 1.0], 6);
        assert!(
            matches!(bad, Err(Error::InvalidKnot { index: 5, .. })),
            "{bad:?}"
        );
        assert!(matches!(
            check_general_knots(2, &[0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0], 4),
            Err(Error::InvalidKnot { index: 3, .. })
        ));
        assert!(matches!(
            check_general_knots(2, &[1.0, 1.0, 1.0, 1.0, 1.0, 1.0], 3),
            Err(Error::InvalidKnot { .. })
        ));
        assert!(matches!(
            check_general_knots(2, &[0.0; 5], 3),
            Err(Error::CountMismatch { .. })
        ));
        assert!(check_weights(&[1.0, 0.5]).is_ok());
        assert!(matches!(
            check_weights(&[1.0, 0.0, 1.0]),
            Err(Error::InvalidWeight { index: 1, .. })
        ));
        assert!(matches!(
            check_weights(&[f64::NAN]),
            Err(Error::InvalidWeight { index: 0, .. })
        ));
    }

    #[test]
    fn binomial_rows() {
        let mut row = [0.0; 7];
        binomials(6, &mut row);
        assert_eq!(row, [1.0, 6.0, 15.0, 20.0, 15.0, 6.0, 1.0]);
    }
}

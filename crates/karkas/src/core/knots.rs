//! Knot sequences: the one validator of the parameters a piecewise curve is built on, a
//! validated [`Knots`] type, and the lookup of the piece holding a parameter.
//!
//! Every method that takes knots (splines, blending families, fits, B-splines) reports a bad
//! knot the same way: [`Error::InvalidKnot`] naming the first offending knot, its value and
//! what is wrong with it. Methods with a stricter rule (a minimum gap, a fixed range) check it
//! after [`check_knots`] and report it with the same variant.

use super::{Interval, Side};
use crate::{Error, Result};
use core::ops::Deref;

/// The reason given for a knot that is NaN or infinite.
pub(crate) const NOT_FINITE: &str = "not a finite number";

/// The reason given for a knot at or below the one before it.
pub(crate) const NOT_INCREASING: &str = "not greater than the knot before it (knots must increase)";

/// The reason given for a knot below the one before it where knots may repeat.
pub(crate) const DECREASING: &str = "less than the knot before it (knots must not decrease)";

/// Fails unless `knots` are finite and increase: strictly when `strict`, otherwise they may
/// repeat. The error names the first offending knot.
pub(crate) fn check_order(knots: &[f64], strict: bool) -> Result<()> {
    for (index, &value) in knots.iter().enumerate() {
        let reason = if !value.is_finite() {
            NOT_FINITE
        } else if index > 0 && strict && value <= knots[index - 1] {
            NOT_INCREASING
        } else if index > 0 && value < knots[index - 1] {
            DECREASING
        } else {
            continue;
        };
        return Err(Error::InvalidKnot {
            index,
            value,
            reason,
        });
    }
    Ok(())
}

/// Fails unless there are at least `needed` knots ([`Error::TooFewPoints`] naming `what`) and
/// they are finite and strictly increasing ([`Error::InvalidKnot`]).
pub fn check_knots(knots: &[f64], needed: usize, what: &'static str) -> Result<()> {
    if knots.len() < needed {
        return Err(Error::TooFewPoints {
            what,
            needed,
            got: knots.len(),
        });
    }
    check_order(knots, true)
}

/// Fails with [`Error::InvalidKnot`] (giving `reason`) at the first knot closer than
/// `min_gap` to the one before it.
pub(crate) fn check_min_gap(knots: &[f64], min_gap: f64, reason: &'static str) -> Result<()> {
    match knots.windows(2).position(|w| w[1] - w[0] < min_gap) {
        Some(k) => Err(Error::InvalidKnot {
            index: k + 1,
            value: knots[k + 1],
            reason,
        }),
        None => Ok(()),
    }
}

/// Finite, strictly increasing knots `t_0 < .. < t_{n-1}`, at least two of them.
#[derive(Clone, Debug, PartialEq)]
pub struct Knots(Vec<f64>);

impl Knots {
    /// `values` as knots, at least `needed` (and at least 2) of them.
    ///
    /// Errors: too few knots ([`Error::TooFewPoints`] naming `what`), a knot that is not
    /// finite or not greater than the one before it ([`Error::InvalidKnot`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::core::Knots;
    ///
    /// let knots = Knots::new(vec![0.0, 0.5, 2.0], 2, "breakpoints")?;
    /// assert_eq!((knots.domain().start, knots.domain().end), (0.0, 2.0));
    /// assert!(Knots::new(vec![0.0, 0.0, 1.0], 2, "breakpoints").is_err()); // not increasing
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(values: Vec<f64>, needed: usize, what: &'static str) -> Result<Self> {
        check_knots(&values, needed.max(2), what)?;
        Ok(Knots(values))
    }

    /// Knots already checked by the caller.
    pub(crate) fn from_checked(values: Vec<f64>) -> Self {
        debug_assert!(values.len() >= 2 && check_order(&values, true).is_ok());
        Knots(values)
    }

    /// The knots as a slice.
    pub fn as_slice(&self) -> &[f64] {
        &self.0
    }

    /// `[t_0, t_{n-1}]`.
    pub fn domain(&self) -> Interval {
        Interval::new(self.0[0], self.0[self.0.len() - 1])
    }

    /// The piece holding `t` and the local coordinate there (see [`locate`]).
    #[inline]
    pub fn locate(&self, t: f64, closed: bool, side: Side) -> (usize, f64) {
        locate(&self.0, closed, t, side)
    }
}

impl Deref for Knots {
    type Target = [f64];

    fn deref(&self) -> &[f64] {
        &self.0
    }
}

/// Locates `t` on increasing `knots` (at least two): the piece `k` (`0 <= k <= n - 2`) and the
/// local coordinate `(t - t_k) / (t_{k+1} - t_k)`, in `[0, 1]` inside the domain and beyond it
/// outside an open one. When `closed`, `t` is first wrapped into the period. A knot belongs to
/// the piece above it (below on [`Side::Below`]), the last knot to the last piece, NaN to the
/// first. `O(log n)`.
#[inline]
pub fn locate(knots: &[f64], closed: bool, t: f64, side: Side) -> (usize, f64) {
    let last = knots.len() - 2;
    let t = if closed {
        let d = Interval::new(knots[0], knots[last + 1]);
        let w = d.wrap(t);
        if side == Side::Below && w <= knots[0] {
            return (last, 1.0);
        }
        w
    } else {
        t
    };
    let k = match side {
        Side::Above => knots.partition_point(|&x| x <= t),
        Side::Below => knots.partition_point(|&x| x < t),
    };
    let k = k.saturating_sub(1).min(last);
    (k, (t - knots[k]) / (knots[k + 1] - knots[k]))
}

/// The piece of increasing `knots` holding `t` (as [`locate`] on an open domain), trying
/// `hint` and its neighbours before a binary search (for parameters that move little between
/// calls).
#[inline]
pub(crate) fn piece_near(knots: &[f64], t: f64, hint: usize) -> usize {
    let last = knots.len() - 2;
    let inside = |k: usize| (k == 0 || t >= knots[k]) && (k == last || t < knots[k + 1]);
    if hint <= last && inside(hint) {
        return hint;
    }
    if hint < last && inside(hint + 1) {
        return hint + 1;
    }
    if hint >= 1 && hint <= last + 1 && inside(hint - 1) {
        return hint - 1;
    }
    locate(knots, false, t, Side::Above).0
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_first_offending_knot_is_named() {
        let bad = |k: &[f64], strict: bool| match check_order(k, strict) {
            Err(Error::InvalidKnot { index, reason, .. }) => (index, reason),
            other => panic!("{other:?}"),
        };
        assert_eq!(bad(&[0.0, 2.0, 1.0, 3.0], true), (2, NOT_INCREASING));
        assert_eq!(bad(&[0.0, 1.0, 1.0], true), (2, NOT_INCREASING));
        assert_eq!(bad(&[0.0, f64::NAN, 1.0], true), (1, NOT_FINITE));
        assert_eq!(bad(&[0.0, 1.0, 0.5], false), (2, DECREASING));
        assert!(check_order(&[0.0, 0.0, 1.0, 1.0], false).is_ok());
        assert!(matches!(
            check_knots(&[0.0], 2, "x"),
            Err(Error::TooFewPoints { needed: 2, .. })
        ));
        assert!(Knots::new(vec![0.0, 1.0], 2, "x").is_ok());
    }

    #[test]
    fn locate_sides_and_wrapping() {
        let k = [0.0, 1.0, 3.0];
        assert_eq!(locate(&k, false, 1.0, Side::Above), (1, 0.0));
        assert_eq!(locate(&k, false, 1.0, Side::Below), (0, 1.0));
        assert_eq!(locate(&k, false, 3.0, Side::Above), (1, 1.0));
        assert_eq!(locate(&k, true, 0.0, Side::Below), (1, 1.0));
        assert_eq!(locate(&k, true, 4.0, Side::Above), (1, 0.0));
    }
}

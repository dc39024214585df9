//! Knot sequences: validation and locating a parameter on them.

use crate::core::{Interval, Side};
use crate::{Error, Result};

/// Fails unless `knots` are finite and strictly increasing, no gap below
/// [`MIN_RELATIVE_KNOT_GAP`] of the span.
pub(crate) fn check_knots(knots: &[f64]) -> Result<()> {
    if let Some(index) = knots.iter().position(|t| !t.is_finite()) {
        return Err(Error::KnotsNotIncreasing { index });
    }
    if let Some(k) = knots.windows(2).position(|w| w[1] <= w[0]) {
        return Err(Error::KnotsNotIncreasing { index: k + 1 });
    }
    // Knots closer than this part of the span make slopes overflow and the system singular.
    let span = knots.last().copied().unwrap_or(0.0) - knots.first().copied().unwrap_or(0.0);
    match knots
        .windows(2)
        .position(|w| w[1] - w[0] < MIN_RELATIVE_KNOT_GAP * span)
    {
        Some(k) => Err(Error::InvalidKnot {
            index: k + 1,
            value: knots[k + 1],
            reason: "closer than 1e-12 of the knot span to the knot before it",
        }),
        None => Ok(()),
    }
}

/// The smallest gap between consecutive knots, as a part of the whole span.
pub(crate) const MIN_RELATIVE_KNOT_GAP: f64 = 1e-12;

/// Locates `t` on `knots`: the piece and the local coordinate in `[0, 1]` (beyond it outside
/// an open domain). A knot belongs to the piece above it (below at the end, or on `side`).
#[inline]
pub(crate) fn locate(knots: &[f64], closed: bool, t: f64, side: Side) -> (usize, f64) {
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

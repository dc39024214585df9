//! The validation shared by every discrete periodic spline: `m >= 2` nodes, step `n >= 2`,
//! order `1..=MAX_ORDER`, and a period `N = m n` that fits in `usize`.

use super::MAX_ORDER;
use crate::{Error, Result};

/// Checks `m`, `n` and `order`, returning the period `N = m n`. `what` names the object in
/// the error for too few points.
pub(crate) fn check_period(m: usize, n: usize, order: usize, what: &'static str) -> Result<usize> {
    if m < 2 {
        return Err(Error::TooFewPoints {
            what,
            needed: 2,
            got: m,
        });
    }
    if n < 2 {
        return Err(Error::InvalidStep { step: n });
    }
    check_order(order)?;
    m.checked_mul(n)
        .ok_or(Error::PeriodTooLarge { poles: m, step: n })
}

/// Checks that `order` is in `1..=MAX_ORDER`.
pub(crate) fn check_order(order: usize) -> Result<()> {
    if order == 0 {
        return Err(Error::InvalidOrder {
            order,
            reason: "a discrete spline needs order r >= 1",
        });
    }
    if order > MAX_ORDER {
        return Err(Error::InvalidOrder {
            order,
            reason: "a discrete spline allows orders up to 64",
        });
    }
    Ok(())
}

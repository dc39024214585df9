//! Preparing the support polygon of an LL curve or surface (Aulchenko et al., formulas (3), (20);
//! docs/methods.md §1.2–1.3): validation, closing, and the extra end points `r_0`, `r_{K+1}`.

use crate::{Error, Point, Result};

/// Relative distance under which two input points count as the same (the closing point of a
/// closed polygon). Relative to the largest coordinate of the input.
const COINCIDENCE: f64 = 1e-12;

/// Checks the common rules for an ordered point list: enough points, all finite.
pub(crate) fn validate<const D: usize>(points: &[Point<D>], what: &'static str) -> Result<()> {
    if points.len() < 3 {
        return Err(Error::TooFewPoints {
            what,
            needed: 3,
            got: points.len(),
        });
    }
    match points.iter().position(|p| !p.is_finite()) {
        Some(index) => Err(Error::NonFinitePoint { index }),
        None => Ok(()),
    }
}

/// The largest coordinate magnitude: the closing tolerance is relative to it at every scale.
pub(crate) fn model_scale<const D: usize>(points: &[Point<D>]) -> f64 {
    points.iter().fold(0.0f64, |m, p| m.max(p.max_abs()))
}

/// True when `a` and `b` coincide to the closing tolerance at `scale`.
pub(crate) fn coincide<const D: usize>(a: Point<D>, b: Point<D>, scale: f64) -> bool {
    (a - b).max_abs() <= COINCIDENCE * scale
}

/// For a closed direction: appends the first item unless the last one already repeats it
/// (`repeats_first`). The result has `K` items with item `K` equal to item 1.
pub(crate) fn close<T: Clone>(items: &mut Vec<T>, repeats_first: bool) {
    if repeats_first {
        let first = items[0].clone();
        if let Some(last) = items.last_mut() {
            *last = first; // exact copy, so the seam is bitwise periodic
        }
    } else {
        items.push(items[0].clone());
    }
}

/// The `K + 2` extended values `r_0..r_{K+1}` from `r_1..r_K`: linear extrapolation
/// `r_0 = 2 r_1 - r_2`, `r_{K+1} = 2 r_K - r_{K-1}` (open), or `r_0 = r_{K-1}`,
/// `r_{K+1} = r_2` (closed, `r_K == r_1`).
pub(crate) fn extend<const D: usize>(values: &[Point<D>], closed: bool) -> Vec<Point<D>> {
    let k = values.len();
    let mut out = Vec::with_capacity(k + 2);
    let (first, last) = if closed {
        (values[k - 2], values[1])
    } else {
        (
            values[0] * 2.0 - values[1],
            values[k - 1] * 2.0 - values[k - 2],
        )
    };
    out.push(first);
    out.extend_from_slice(values);
    out.push(last);
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn open_and_closed_ends() {
        let v = [Point([0.0]), Point([1.0]), Point([3.0]), Point([0.0])];
        let open = extend(&v, false);
        assert_eq!(open.first(), Some(&Point([-1.0])));
        assert_eq!(open.last(), Some(&Point([-3.0])));
        let closed = extend(&v, true);
        assert_eq!(closed.first(), Some(&Point([3.0])));
        assert_eq!(closed.last(), Some(&Point([1.0])));
    }

    #[test]
    fn closing_appends_or_keeps() {
        let mut a = vec![1, 2, 3];
        close(&mut a, false);
        assert_eq!(a, [1, 2, 3, 1]);
        let mut b = vec![1, 2, 3, 1];
        close(&mut b, true);
        assert_eq!(b, [1, 2, 3, 1]);
    }
}

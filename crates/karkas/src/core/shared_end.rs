//! The shared-end rule: when the first and last points of a curve are one point (a closed
//! profile, an airfoil's sharp trailing edge), every curve method of karkas — the fit in
//! every mode (docs/methods.md §4, "Ends"), the interpolating spline and the LL curve —
//! makes its two ends meet exactly there, a C^0 corner. One rule for all of them, so that a
//! file one method closes is closed by the others too.

use std::borrow::Cow;

use super::Point;

/// The first and last points of a curve coincide (its ends are one point: a closed profile)
/// when they lie within this fraction of the diagonal of the points' bounding box (at most,
/// inclusive).
pub const SHARED_END_TOLERANCE: f64 = 1e-6;

/// The common point of the first and last points when they coincide (within
/// [`SHARED_END_TOLERANCE`] of the diagonal of the points' bounding box; their midpoint),
/// else `None`; also `None` for fewer than 3 points.
///
/// ```
/// use karkas::core::{shared_end, SHARED_END_TOLERANCE};
/// use karkas::Point;
///
/// // Ends 0.99e-6 of the diagonal (here 1) apart are one point, 1.01e-6 are not.
/// let foil = |gap: f64| [Point([1.0, 0.5 * gap]), Point([0.0, 0.0]), Point([1.0, -0.5 * gap])];
/// assert_eq!(shared_end(&foil(0.99 * SHARED_END_TOLERANCE)), Some(Point([1.0, 0.0])));
/// assert_eq!(shared_end(&foil(1.01 * SHARED_END_TOLERANCE)), None);
/// ```
pub fn shared_end<const D: usize>(points: &[Point<D>]) -> Option<Point<D>> {
    let (first, last) = (*points.first()?, *points.last()?);
    if points.len() < 3 {
        return None;
    }
    let gap = first.distance(last);
    (gap <= SHARED_END_TOLERANCE * points_size(points)).then(|| first.lerp(last, 0.5))
}

/// `points` with the first and last point replaced by their [`shared_end`] when they
/// coincide (borrowed unchanged otherwise, and when they are already equal): the points
/// every curve method interpolates, so that its ends meet exactly.
///
/// ```
/// use karkas::core::with_shared_end;
/// use karkas::Point;
///
/// let pts = [Point([1.0, 1e-9]), Point([0.0, 0.1]), Point([0.0, -0.1]), Point([1.0, -1e-9])];
/// let closed = with_shared_end(&pts);
/// assert_eq!(closed[0], Point([1.0, 0.0]));
/// assert_eq!(closed[3], closed[0]);
/// ```
pub fn with_shared_end<const D: usize>(points: &[Point<D>]) -> Cow<'_, [Point<D>]> {
    match shared_end(points) {
        Some(end) if points[0] != end || points[points.len() - 1] != end => {
            let mut owned = points.to_vec();
            let last = owned.len() - 1;
            owned[0] = end;
            owned[last] = end;
            Cow::Owned(owned)
        }
        _ => Cow::Borrowed(points),
    }
}

/// The diagonal of the bounding box of `points`.
fn points_size<const D: usize>(points: &[Point<D>]) -> f64 {
    let (mut low, mut high) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for p in points {
        for c in 0..D {
            low[c] = low[c].min(p[c]);
            high[c] = high[c].max(p[c]);
        }
    }
    (0..D)
        .map(|c| (high[c] - low[c]).powi(2))
        .sum::<f64>()
        .sqrt()
}

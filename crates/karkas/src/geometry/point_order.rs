//! Whether a list of points follows one curve in its order: the check behind "points not in
//! order".
//!
//! A shuffled list jumps across the whole set and back: its chords are long (a good share of
//! the set's diameter) and turn back at random. An ordered list, however noisy, has chords
//! short next to the diameter where it is dense, and turns back sharply only at a few cusps
//! or corners. The count: inner points whose two chords are both longer than a tenth of the
//! diameter (the bounding box's diagonal) and turn back by more than 150 degrees; the list is
//! out of order when at least three of them, and at least one in twenty points, do.

use crate::Point;

/// A chord counts when longer than this share of the diameter.
const LONG_CHORD: f64 = 0.1;
/// A turn back by more than 150 degrees: the cosine between the chords below this.
const TURN_BACK_COSINE: f64 = -0.866;
/// The least number of turning-back chords that mean disorder.
const MIN_REVERSALS: usize = 3;
/// And the least share of the points.
const REVERSAL_SHARE: f64 = 0.05;

/// `Some(count of turning-back long chords)` when `points` look shuffled rather than listed
/// along a curve (see the module documentation), `None` when they look ordered.
///
/// ```
/// use karkas::{geometry::points_out_of_order, Point};
/// let circle: Vec<Point<2>> = (0..40)
///     .map(|i| { let a = i as f64 * 0.15; Point([a.cos(), a.sin()]) })
///     .collect();
/// assert_eq!(points_out_of_order(&circle), None);
/// let shuffled: Vec<Point<2>> = (0..40).map(|i| circle[(i * 17) % 40]).collect();
/// assert!(points_out_of_order(&shuffled).is_some());
/// ```
pub fn points_out_of_order<const D: usize>(points: &[Point<D>]) -> Option<usize> {
    // The finite points, in order, without a copy of them (the list may be millions long).
    let finite = || points.iter().copied().filter(|p| p.is_finite());
    let count = finite().count();
    if count < 3 {
        return None;
    }
    let mut all = finite();
    let first = all.next()?;
    let (mut lo, mut hi) = (first, first);
    for p in all {
        for d in 0..D {
            lo[d] = lo[d].min(p[d]);
            hi[d] = hi[d].max(p[d]);
        }
    }
    let long = LONG_CHORD * hi.distance(lo);
    if long.is_nan() || long <= 0.0 {
        return None;
    }
    let mut reversals = 0;
    let mut all = finite();
    let (mut a, mut b) = (all.next()?, all.next()?);
    for c in all {
        let (u, v) = (b - a, c - b);
        let (lu, lv) = (u.norm(), v.norm());
        if lu > long && lv > long && u.dot(v) < TURN_BACK_COSINE * lu * lv {
            reversals += 1;
        }
        (a, b) = (b, c);
    }
    let needed = MIN_REVERSALS.max((REVERSAL_SHARE * count as f64).ceil() as usize);
    (reversals >= needed).then_some(reversals)
}

//! What to fair and how: the tolerance, the ends, the corners and closure
//! ([`FairOptions`]), checked once against the points.

use crate::{Error, Point, Result};

/// The tolerance must exceed this many units in the last place of the largest coordinate.
pub const RESOLUTION_ULPS: f64 = 256.0;
/// Points per span of the fair spline (the spans follow the points: more where they are
/// dense).
pub(crate) const POINTS_PER_SPAN: f64 = 3.0;

/// What the faired curve keeps of the input at its ends.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum FairEnds {
    /// The ends are free within the tolerance like every other point.
    #[default]
    Free,
    /// The curve starts at the first point and ends at the last.
    Kept,
    /// The ends are kept, and so are the directions of the end tangents (those of the curve
    /// being faired; for points, of the first and the last chord).
    KeptWithTangents,
}

/// The options of [`fair_curve`](super::fair_curve).
#[derive(Clone, Debug, PartialEq)]
pub struct FairOptions {
    /// The largest distance `T` allowed between any input point and the curve (in the
    /// points' units).
    pub tolerance: f64,
    /// The ends (open curves; at corners the curve always passes through the corner point).
    pub ends: FairEnds,
    /// The indices (0-based) of the points where the curve may turn a corner: it passes
    /// through them, `C^0`, and is faired on each side on its own.
    pub corners: Vec<usize>,
    /// Whether the curve is closed (the points go once around; a last point equal to the
    /// first is dropped).
    pub closed: bool,
}

impl FairOptions {
    /// Options with tolerance `tolerance` and everything else by default: free ends, no
    /// corners, open.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::fair::{FairEnds, FairOptions};
    ///
    /// let options = FairOptions::new(1e-3);
    /// assert_eq!(options.tolerance, 1e-3);
    /// assert!(matches!(options.ends, FairEnds::Free) && !options.closed && options.corners.is_empty());
    /// ```
    pub fn new(tolerance: f64) -> Self {
        FairOptions {
            tolerance,
            ends: FairEnds::Free,
            corners: Vec::new(),
            closed: false,
        }
    }
}

/// The number of points one piece needs.
pub(crate) const MIN_POINTS: usize = 4;

/// Checks the options against `points` (after a closed curve's repeated last point is
/// dropped): the tolerance positive and above what the coordinates resolve, every point
/// finite, the points in order, the corners inner points in increasing order, and every piece
/// with at least four points.
pub(crate) fn check<const D: usize>(points: &[Point<D>], options: &FairOptions) -> Result<()> {
    let tolerance = options.tolerance;
    if !(tolerance.is_finite() && tolerance > 0.0) {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "it must be a positive number",
        });
    }
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinitePoint { index });
    }
    if points.len() < MIN_POINTS {
        return Err(Error::TooFewPoints {
            what: "a fair curve",
            needed: MIN_POINTS,
            got: points.len(),
        });
    }
    let largest = points.iter().fold(0.0_f64, |a, p| a.max(p.max_abs()));
    if tolerance < RESOLUTION_ULPS * f64::EPSILON * largest {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "it is below what the coordinates can resolve (256 units in the last place of the largest coordinate)",
        });
    }
    if let Some(reversals) = crate::geometry::points_out_of_order(points) {
        return Err(Error::PointsOutOfOrder { reversals });
    }
    let n = points.len();
    let mut previous: Option<usize> = None;
    for &c in &options.corners {
        let inner = if options.closed {
            c < n
        } else {
            c > 0 && c + 1 < n
        };
        if !inner || previous.is_some_and(|p| c <= p) {
            return Err(Error::InvalidSetting {
                name: "corner",
                value: c as f64,
                reason: "corners must be indices of inner points, in increasing order",
            });
        }
        previous = Some(c);
    }
    Ok(())
}

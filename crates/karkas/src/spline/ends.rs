//! The end conditions of a cubic interpolating spline.

use crate::Point;

/// The end conditions of a cubic interpolating spline with values in R^D (`D` matters only
/// for the clamped end derivatives; it defaults to 1 where only the kind of ends is given, as
/// for blending families).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum SplineEnds<const D: usize = 1> {
    /// The third derivative is continuous at the second and the second-to-last knots (the
    /// default of most libraries, e.g. SciPy's `CubicSpline`; Kuznetsov and Filatov's
    /// (3.10)–(3.12)). With 3 points the spline is the parabola through them, with 2 the
    /// segment.
    NotAKnot,
    /// Zero second derivative at both ends. Two points give a straight line.
    Natural,
    /// Given first derivatives at the two ends.
    Clamped {
        /// `P'(t_0)`.
        start: Point<D>,
        /// `P'(t_{n-1})`.
        end: Point<D>,
    },
    /// Periodic: the last knot closes the period, the last value repeats the first and the
    /// spline is `C^2` across the seam.
    Periodic,
}

impl<const D: usize> SplineEnds<D> {
    /// True for [`SplineEnds::Periodic`].
    pub fn is_periodic(&self) -> bool {
        matches!(self, SplineEnds::Periodic)
    }
}

//! The end conditions of a cubic interpolating spline.

use crate::core::shared_end;
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

    /// The ends of an open spline through `points` when none are asked (those of
    /// `curve spline`): [`Natural`](SplineEnds::Natural) where the first and last points are
    /// one point by the shared-end rule ([`shared_end`]: a closed profile, an airfoil's sharp
    /// trailing edge), [`NotAKnot`](SplineEnds::NotAKnot) otherwise.
    ///
    /// Why: at a shared end the curve has a C^0 corner between two branches. Not-a-knot ends
    /// make the first and last two pieces one cubic each, so where the last points before the
    /// corner are sparse or unevenly spaced that cubic overshoots across the other branch
    /// (SciPy's `CubicSpline` with not-a-knot ends does the same on such points); zero
    /// curvature at the corner lets each branch run into it along its last points.
    ///
    /// ```
    /// use karkas::spline::SplineEnds;
    /// use karkas::Point;
    ///
    /// let open = [Point([1.0, 0.0]), Point([0.0, 0.1]), Point([0.0, -0.1]), Point([1.0, -0.01])];
    /// let mut closed = open;
    /// closed[3] = Point([1.0, 0.0]);
    /// assert_eq!(SplineEnds::default_for(&open), SplineEnds::NotAKnot);
    /// assert_eq!(SplineEnds::default_for(&closed), SplineEnds::Natural);
    /// ```
    pub fn default_for(points: &[Point<D>]) -> Self {
        match shared_end(points) {
            Some(_) => SplineEnds::Natural,
            None => SplineEnds::NotAKnot,
        }
    }
}

//! 1-D cubic interpolating splines on arbitrary increasing knots (seed 004, (3.6)–(3.12);
//! METHODS.md §5).
//!
//! A [`CubicSpline`] stores the knots, the values and the node slopes (Hermite form); the
//! slopes come from one `O(n)` tridiagonal solve for the chosen [`SplineEnds`]. Guarantees:
//! passes through every point at its knot; `C^2` everywhere (`C^2` across the seam when
//! periodic); not-a-knot reproduces every cubic polynomial exactly. Evaluation is `O(log n)`
//! (binary search for the piece) plus a handful of multiply-adds.

use super::knots::{check_knots, locate};
use super::parameterization::{curve_parameters, CurveParameterization};
use super::slopes::{hermite_weights, SlopeSystem, SplineEnds};
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
use crate::{Error, Point, Result};

/// A cubic interpolating spline `t -> P(t)` in R^D on knots `t_0 < .. < t_{n-1}`.
///
/// Outside `[t_0, t_{n-1}]` an open spline continues the polynomial of its first or last
/// piece (as SciPy's `CubicSpline` does) and a periodic one wraps by its period.
#[derive(Clone, Debug, PartialEq)]
pub struct CubicSpline<const D: usize> {
    knots: Vec<f64>,
    values: Vec<Point<D>>,
    slopes: Vec<Point<D>>,
    periodic: bool,
}

impl<const D: usize> CubicSpline<D> {
    /// The cubic spline through `(knots[k], values[k])` with end conditions `ends`.
    ///
    /// Errors: fewer than 2 points (3 when periodic), lengths that differ, knots not finite
    /// and strictly increasing ([`Error::KnotsNotIncreasing`]), a non-finite value, and for
    /// periodic ends a last value that does not repeat the first (relative tolerance
    /// `1e-12`).
    pub fn new(knots: &[f64], values: &[Point<D>], ends: SplineEnds<D>) -> Result<Self> {
        let n = knots.len();
        let periodic = matches!(ends, SplineEnds::Periodic);
        let needed = if periodic { 3 } else { 2 };
        if n < needed {
            return Err(Error::TooFewPoints {
                what: "a cubic spline",
                needed,
                got: n,
            });
        }
        if values.len() != n {
            return Err(Error::InvalidInput(format!(
                "{n} knots for {} values",
                values.len()
            )));
        }
        check_knots(knots)?;
        if let Some(index) = values.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        if let SplineEnds::Clamped { start, end } = ends {
            if !start.is_finite() || !end.is_finite() {
                return Err(Error::InvalidInput(
                    "the clamped end derivatives must be finite".into(),
                ));
            }
        }
        let mut values = values.to_vec();
        if periodic {
            let scale = values.iter().fold(1.0f64, |m, p| m.max(p.max_abs()));
            if (values[n - 1] - values[0]).max_abs() > 1e-12 * scale {
                return Err(Error::InvalidInput(
                    "a periodic spline needs its last value to repeat the first".into(),
                ));
            }
            values[n - 1] = values[0];
        }
        let mut slopes = vec![Point::ZERO; n];
        let clamped = match ends {
            SplineEnds::Clamped { start, end } => Some((start, end)),
            _ => None,
        };
        SlopeSystem::new(knots, &ends)?.solve(&values, &mut slopes, 1, clamped);
        Ok(CubicSpline {
            knots: knots.to_vec(),
            values,
            slopes,
            periodic,
        })
    }

    /// The cubic spline through `points` with parameters by the rule `parameterization`
    /// (starting at 0). With periodic ends the curve is closed: if the last point repeats the
    /// first (relative tolerance `1e-12`) it is the seam, otherwise the first point is
    /// appended.
    ///
    /// Errors: those of [`curve_parameters`] and [`new`](Self::new).
    pub fn through(
        points: &[Point<D>],
        parameterization: CurveParameterization,
        ends: SplineEnds<D>,
    ) -> Result<Self> {
        let mut pts = points.to_vec();
        if matches!(ends, SplineEnds::Periodic) && !pts.is_empty() {
            let scale = pts.iter().fold(1.0f64, |m, p| m.max(p.max_abs()));
            let last = pts[pts.len() - 1];
            if (last - pts[0]).max_abs() > 1e-12 * scale {
                pts.push(pts[0]);
            }
        }
        let knots = curve_parameters(&pts, parameterization)?;
        Self::new(&knots, &pts, ends)
    }

    /// The knots `t_0 < .. < t_{n-1}`.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The interpolated values (`values[k] = P(t_k)`).
    pub fn values(&self) -> &[Point<D>] {
        &self.values
    }

    /// The node slopes `m_k = P'(t_k)`.
    pub fn slopes(&self) -> &[Point<D>] {
        &self.slopes
    }

    #[inline]
    fn locate(&self, t: f64, side: Side) -> (usize, f64) {
        locate(&self.knots, self.periodic, t, side)
    }

    #[inline]
    fn deriv_on_piece(&self, (k, s): (usize, f64), order: usize) -> Point<D> {
        let h = self.knots[k + 1] - self.knots[k];
        let w = hermite_weights(s, h, order);
        self.values[k] * w[0]
            + self.values[k + 1] * w[1]
            + self.slopes[k] * w[2]
            + self.slopes[k + 1] * w[3]
    }
}

impl<const D: usize> Curve<D> for CubicSpline<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.knots[0], self.knots[self.knots.len() - 1])
    }

    fn is_closed(&self) -> bool {
        self.periodic
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.deriv_on_piece(self.locate(t, Side::Above), 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        self.deriv_on_piece(self.locate(t, Side::Above), k)
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.knots.clone(),
            2,
        ))
    }
}

impl<const D: usize> PiecewiseCurve<D> for CubicSpline<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.knots.clone()
    }

    fn continuity(&self) -> usize {
        2
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        self.deriv_on_piece(self.locate(t, side), k)
    }
}

//! Sampled curves as polylines: the plainest boundary data a Coons surface can take.

use super::blending::locate;
use crate::core::knots::check_knots as check_nodes;
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
use crate::{Error, Point, Result};

/// A polyline through points `p_0..p_{K-1}` at parameters `t_0 < ... < t_{K-1}`: linear
/// between consecutive points, `C^0`.
///
/// It is closed when its last point equals its first exactly (then it is periodic with period
/// `t_{K-1} - t_0`). Outside the domain an open polyline is clamped to its end points. The
/// first derivative is the slope of the piece (the piece above at a vertex, see
/// [`Curve::deriv`]); higher derivatives are zero.
#[derive(Clone, Debug, PartialEq)]
pub struct PolylineCurve<const D: usize> {
    params: Vec<f64>,
    points: Vec<Point<D>>,
    closed: bool,
}

impl<const D: usize> PolylineCurve<D> {
    /// The polyline through `points` at `params`.
    ///
    /// Errors: fewer than two points, lengths that differ ([`Error::CountMismatch`]), a
    /// non-finite coordinate, parameters not finite and strictly increasing.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::PolylineCurve;
    /// use karkas::{Curve, Point};
    ///
    /// let points = [Point([0.0, 0.0]), Point([1.0, 0.0]), Point([1.0, 2.0])];
    /// let polyline = PolylineCurve::new(&points, &[0.0, 1.0, 3.0])?;
    /// assert!(polyline.eval(2.0).distance(Point([1.0, 1.0])) < 1e-14);
    /// assert!(PolylineCurve::new(&points, &[0.0, 1.0]).is_err()); // one parameter per point
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(points: &[Point<D>], params: &[f64]) -> Result<Self> {
        if points.len() != params.len() {
            return Err(Error::CountMismatch {
                what: "parameters of a polyline (one per point)",
                expected: points.len(),
                got: params.len(),
            });
        }
        check_nodes(params, 2, "a polyline")?;
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        Ok(PolylineCurve {
            params: params.to_vec(),
            points: points.to_vec(),
            closed: points[0] == points[points.len() - 1],
        })
    }

    /// The polyline through `points` with the normalised chord-length parameter: `t_0 = 0`,
    /// `t_{K-1} = 1`, steps proportional to the distances between consecutive points.
    ///
    /// Errors: as [`new`](Self::new); two consecutive points that coincide.
    ///
    /// ```
    /// use karkas::coons::PolylineCurve;
    /// use karkas::{Curve, Point};
    ///
    /// let line = PolylineCurve::chord_length(&[Point([0.0, 0.0]), Point([3.0, 0.0]), Point([3.0, 1.0])])?;
    /// assert!(line.eval(0.75).distance(Point([3.0, 0.0])) < 1e-12); // 3 of the length 4
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn chord_length(points: &[Point<D>]) -> Result<Self> {
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        let mut params = Vec::with_capacity(points.len());
        let mut total = 0.0;
        params.push(0.0);
        for w in points.windows(2) {
            total += w[0].distance(w[1]);
            params.push(total);
        }
        for p in &mut params {
            *p /= total;
        }
        Self::new(points, &params)
    }

    /// The points.
    pub fn points(&self) -> &[Point<D>] {
        &self.points
    }

    /// The parameters of the points.
    pub fn params(&self) -> &[f64] {
        &self.params
    }

    fn reduce(&self, t: f64) -> f64 {
        let d = self.domain();
        if self.closed {
            d.wrap(t)
        } else {
            d.clamp(t)
        }
    }

    fn on_piece(&self, l: usize, s: f64, k: usize) -> Point<D> {
        let (a, b) = (self.points[l], self.points[l + 1]);
        match k {
            0 => a.lerp(b, s),
            1 => (b - a) * (self.params[l + 1] - self.params[l]).recip(),
            _ => Point::ZERO,
        }
    }
}

impl<const D: usize> Curve<D> for PolylineCurve<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.params[0], self.params[self.params.len() - 1])
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.deriv(t, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        let (l, s) = locate(&self.params, self.reduce(t));
        self.on_piece(l, s, k)
    }

    fn polynomial_pieces(&self) -> Option<crate::core::PolynomialPieces> {
        Some(crate::core::PolynomialPieces::uniform_continuity(
            1,
            self.params.clone(),
            0,
        ))
    }
}

impl<const D: usize> PiecewiseCurve<D> for PolylineCurve<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.params.clone()
    }

    fn continuity(&self) -> usize {
        0
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        let t = self.reduce(t);
        let (mut l, mut s) = locate(&self.params, t);
        if side == Side::Below && l > 0 && s == 0.0 {
            l -= 1;
            s = 1.0;
        }
        self.on_piece(l, s, k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chord_length_polyline() {
        let pts = [Point([0.0, 0.0]), Point([3.0, 4.0]), Point([3.0, 9.0])];
        let c = PolylineCurve::chord_length(&pts).unwrap();
        assert_eq!(c.params(), &[0.0, 0.5, 1.0]);
        assert_eq!(c.eval(0.25), Point([1.5, 2.0]));
        assert_eq!(c.deriv(0.5, 1), Point([0.0, 10.0]));
        assert_eq!(c.deriv_on_side(0.5, 1, Side::Below), Point([6.0, 8.0]));
        assert_eq!(c.deriv(0.2, 2), Point([0.0, 0.0]));
        assert_eq!(c.eval(7.0), pts[2]);
        assert!(!c.is_closed());
        assert!(PolylineCurve::chord_length(&[pts[0], pts[0]]).is_err());
        assert!(PolylineCurve::new(&pts, &[0.0, 1.0]).is_err());
    }
}

//! The distance from points to the polygon of a curve's input points (a polyline, closed for
//! a closed curve): the polygon is seen as a degree-1 piecewise curve and handed to the
//! curve projector ([`CurveProjector`], a k-d tree of its vertices), so that a query costs
//! a tree search instead of a pass over every edge.

use super::curve_nearest::CurveProjector;
use crate::core::{Curve, Interval, PolynomialPieces};
use crate::Point;

/// A polyline through points at their cumulative chord lengths (consecutive repeats dropped;
/// closed by its first point when asked).
pub(crate) struct Polygon<const D: usize> {
    params: Vec<f64>,
    points: Vec<Point<D>>,
    closed: bool,
}

impl<const D: usize> Polygon<D> {
    /// The polygon through `points` (closed when `closed`); `None` when fewer than two
    /// distinct finite points remain.
    pub(crate) fn new(points: &[Point<D>], closed: bool) -> Option<Self> {
        let mut kept: Vec<Point<D>> = Vec::with_capacity(points.len() + 1);
        for &p in points.iter().filter(|p| p.is_finite()) {
            if kept.last() != Some(&p) {
                kept.push(p);
            }
        }
        let closed = closed && kept.len() > 2;
        if closed {
            if kept.first() == kept.last() {
                kept.pop();
            }
            kept.push(kept[0]);
        }
        if kept.len() < 2 {
            return None;
        }
        let mut params = Vec::with_capacity(kept.len());
        let mut total = 0.0;
        params.push(0.0);
        for w in kept.windows(2) {
            total += w[0].distance(w[1]);
            params.push(total);
        }
        (total > 0.0 && total.is_finite()).then_some(Polygon {
            params,
            points: kept,
            closed,
        })
    }

    /// The segment holding `t` (in the domain).
    fn segment(&self, t: f64) -> usize {
        let n = self.params.len();
        self.params[1..n - 1].partition_point(|&b| b <= t)
    }

    /// A projector onto the polygon.
    pub(crate) fn projector(&self) -> Option<CurveProjector<'_, Self, D>> {
        CurveProjector::new(self, 0.0).ok()
    }
}

impl<const D: usize> Curve<D> for Polygon<D> {
    fn domain(&self) -> Interval {
        Interval::new(0.0, self.params[self.params.len() - 1])
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn eval(&self, t: f64) -> Point<D> {
        let d = self.domain();
        let t = if self.closed { d.wrap(t) } else { d.clamp(t) };
        let i = self.segment(t);
        let (a, b) = (self.params[i], self.params[i + 1]);
        self.points[i].lerp(self.points[i + 1], (t - a) / (b - a))
    }
    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        match k {
            0 => self.eval(t),
            1 => {
                let d = self.domain();
                let t = if self.closed { d.wrap(t) } else { d.clamp(t) };
                let i = self.segment(t);
                (self.points[i + 1] - self.points[i])
                    * (1.0 / (self.params[i + 1] - self.params[i]))
            }
            _ => Point::ZERO,
        }
    }
    fn polynomial_pieces(&self) -> Option<PolynomialPieces> {
        Some(PolynomialPieces::uniform_continuity(
            1,
            self.params.clone(),
            0,
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn distances_to_an_open_and_a_closed_square() {
        let pts = [
            Point([0.0, 0.0]),
            Point([1.0, 0.0]),
            Point([1.0, 0.0]),
            Point([1.0, 1.0]),
            Point([0.0, 1.0]),
        ];
        let open = Polygon::new(&pts, false).unwrap();
        let p = open.projector().unwrap();
        // Nearest the missing left side: the open polygon's ends.
        assert!((p.nearest(Point([-0.5, 0.5])).distance - 0.5f64.hypot(0.5)).abs() < 1e-12);
        assert!((p.nearest(Point([0.5, 0.25])).distance - 0.25).abs() < 1e-12);
        let closed = Polygon::new(&pts, true).unwrap();
        let p = closed.projector().unwrap();
        assert!((p.nearest(Point([-0.5, 0.5])).distance - 0.5).abs() < 1e-12);
        assert!((p.nearest(Point([0.1, 0.5])).distance - 0.1).abs() < 1e-12);
        assert!(Polygon::new(&[Point([1.0, 2.0]), Point([1.0, 2.0])], false).is_none());
    }

    /// The distance from `q` to the segment `[a, b]`, exactly.
    fn segment_distance(q: Point<2>, a: Point<2>, b: Point<2>) -> f64 {
        let (ab, aq) = (b - a, q - a);
        let s = (aq.dot(ab) / ab.norm_sq()).clamp(0.0, 1.0);
        (aq - ab * s).norm()
    }

    #[test]
    fn sharp_turns_do_not_hide_the_nearest_edge() {
        // A zig-zag whose edges turn by more than 90 degrees at every vertex: the direction
        // after a vertex points back against the edge before it.
        let pts: Vec<Point<2>> = (0..40)
            .map(|k| Point([0.1 * k as f64, if k % 2 == 0 { 0.0 } else { 1.0 }]))
            .collect();
        let polygon = Polygon::new(&pts, false).unwrap();
        let p = polygon.projector().unwrap();
        for k in 0..2000 {
            let q = Point([
                -0.2 + 4.3 * (k as f64 * 0.618_034).fract(),
                -0.3 + 1.6 * (k as f64 * 0.414_214).fract(),
            ]);
            let exact = pts
                .windows(2)
                .map(|w| segment_distance(q, w[0], w[1]))
                .fold(f64::INFINITY, f64::min);
            let found = p.nearest(q).distance;
            assert!((found - exact).abs() < 1e-12, "{q:?}: {found} vs {exact}");
        }
    }
}

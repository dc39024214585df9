//! The nearest point of an edge that is a straight segment or a whole circle, in closed form.
//!
//! Machined parts are bounded mostly by straight edges (STEP `LINE`, read as degree-1 curves
//! of two control points) and circles (STEP `CIRCLE`, read as rational quadratic arcs). On a
//! segment `a + t d`, `t` in `[0, 1]`, the nearest point to `q` is at
//! `t = clamp((q - a).d / d.d, 0, 1)`. On a whole circle of centre `c`, unit normal `n` and
//! radius `R`, it is `c + R w / |w|` for the part `w` of `q - c` normal to `n` (every point is as
//! near on the axis, `w = 0`, which is left to Newton's method). The nearest-point search
//! ([`ShapeProjector`](super::ShapeProjector)) then solves such an edge once a query instead of
//! running Newton's method from each of its segments. A curve is taken as a whole circle when
//! it closes (its ends meet) and eight points of every knot span lie on the circle through
//! three of its points a third of its domain apart, as `cylinder.rs` tells a cylinder (a
//! rational quadratic span is a conic, fixed by five points).

use super::cylinder::circumcentre;
use crate::bspline::NurbsCurve;
use crate::core::Curve;
use crate::Point3;

/// The tolerance on the circle, relative to its radius plus the largest coordinate.
const TOLERANCE: f64 = 1e-12;
/// Points checked on each knot span.
const PER_SPAN: usize = 8;

/// An edge curve in closed form.
#[derive(Clone, Copy, Debug)]
pub(super) enum EdgeForm {
    /// The segment `a + t d`, `t` in `[0, 1]`.
    Segment { a: Point3, d: Point3 },
    /// A whole circle.
    Circle {
        centre: Point3,
        normal: Point3,
        radius: f64,
    },
    /// Any other curve.
    Other,
}

impl EdgeForm {
    /// The closed form of `curve`, when it has one.
    pub(super) fn of(curve: &NurbsCurve<3>) -> EdgeForm {
        let p = curve.control_points();
        let w = curve.weights();
        if curve.degree() == 1
            && p.len() == 2
            && w[0] == w[1]
            && p[0].is_finite()
            && p[1].is_finite()
        {
            let d = p[1] - p[0];
            if d.norm_sq() > 0.0 {
                return EdgeForm::Segment { a: p[0], d };
            }
            return EdgeForm::Other;
        }
        circle(curve).unwrap_or(EdgeForm::Other)
    }

    /// The point of the edge nearest `q`; `None` for [`EdgeForm::Other`] and on a circle's
    /// axis.
    pub(super) fn nearest(&self, q: Point3) -> Option<Point3> {
        match *self {
            EdgeForm::Segment { a, d } => {
                let t = ((q - a).dot(d) / d.norm_sq()).clamp(0.0, 1.0);
                Some(a + d * t)
            }
            EdgeForm::Circle {
                centre,
                normal,
                radius,
            } => {
                let r = q - centre;
                let w = r - normal * r.dot(normal);
                let length = w.norm();
                (length > 1e-9 * radius).then(|| centre + w * (radius / length))
            }
            EdgeForm::Other => None,
        }
    }
}

/// The whole circle `curve` is, as the module docs define it.
fn circle(curve: &NurbsCurve<3>) -> Option<EdgeForm> {
    if curve.degree() != 2 {
        return None;
    }
    let d = curve.domain();
    let (a, b, c) = (
        curve.eval(d.start),
        curve.eval(d.start + d.length() / 3.0),
        curve.eval(d.start + 2.0 * d.length() / 3.0),
    );
    let (centre, normal) = circumcentre(a, b, c)?;
    let radius = a.distance(centre);
    let far = curve
        .control_points()
        .iter()
        .map(|p| p.max_abs())
        .fold(0.0, f64::max);
    let tolerance = TOLERANCE * (radius + far);
    if !(radius > 0.0 && radius.is_finite()) || curve.eval(d.end).distance(a) > tolerance {
        return None;
    }
    let on_circle = |p: Point3| {
        let r = p - centre;
        r.dot(normal).abs() <= tolerance && (r.norm() - radius).abs() <= tolerance
    };
    let knots = curve.knots();
    let mut checked = 0;
    for k in knots.windows(2) {
        if !(k[1] > k[0] && k[0] >= d.start && k[1] <= d.end) {
            continue;
        }
        for i in 0..PER_SPAN {
            if !on_circle(curve.eval(k[0] + (k[1] - k[0]) * (i as f64 + 0.5) / PER_SPAN as f64)) {
                return None;
            }
            checked += 1;
        }
    }
    (checked > 0).then_some(EdgeForm::Circle {
        centre,
        normal,
        radius,
    })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::conic::{elliptic_arc, line_segment};
    use std::f64::consts::TAU;

    #[test]
    fn feet_on_segments_and_whole_circles_are_the_nearest_points() {
        let centre = Point3::new([1.0e4, -2.0e4, 350.0]);
        let x = Point3::new([0.6, 0.8, 0.0]);
        let y = Point3::new([0.0, 0.0, 1.0]);
        let mut state = 0x4f1b_bcdc_bfa5_3e0bu64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for radius in [0.05, 3.0, 700.0] {
            let whole = elliptic_arc(centre, x * radius, y * radius, (0.0, TAU)).unwrap();
            let form = EdgeForm::of(&whole);
            assert!(matches!(form, EdgeForm::Circle { .. }), "{radius}");
            // Part of a turn, and an ellipse, are not taken.
            let part = elliptic_arc(centre, x * radius, y * radius, (0.0, 0.8 * TAU)).unwrap();
            assert!(matches!(EdgeForm::of(&part), EdgeForm::Other));
            let oval = elliptic_arc(centre, x * radius, y * (1.5 * radius), (0.0, TAU)).unwrap();
            assert!(matches!(EdgeForm::of(&oval), EdgeForm::Other));
            let d = whole.domain();
            for _ in 0..500 {
                let q = centre
                    + Point3::new([next() - 0.5, next() - 0.5, next() - 0.5]) * (4.0 * radius);
                let foot = form.nearest(q).unwrap();
                // Against a dense sample of the circle.
                let sampled = (0..4000)
                    .map(|i| whole.eval(d.uniform(i, 4000)).distance(q))
                    .fold(f64::INFINITY, f64::min);
                let exact = foot.distance(q);
                assert!(exact <= sampled + 1e-12 * (radius + 3e4), "{radius}");
                assert!(
                    sampled - exact <= 1e-5 * radius,
                    "{radius}: {sampled} {exact}"
                );
                assert!((foot.distance(centre) - radius).abs() <= 1e-12 * (radius + 3e4));
            }
        }
        let a = Point3::new([5.0, -1.0, 2.0]);
        let b = Point3::new([-3.0, 4.0, 2.5]);
        let line = line_segment(a, b, (2.0, 7.0)).unwrap();
        let form = EdgeForm::of(&line);
        assert!(matches!(form, EdgeForm::Segment { .. }));
        assert!(form.nearest(a + (a - b)).unwrap().distance(a) < 1e-15);
        assert!(
            form.nearest(b + Point3::new([0.0, 0.0, 3.0]) + (b - a))
                .unwrap()
                .distance(b)
                < 1e-14
        );
        let mid = a + (b - a) * 0.25;
        let off = (b - a).cross(Point3::new([0.0, 0.0, 1.0]));
        assert!(form.nearest(mid + off).unwrap().distance(mid) < 1e-13);
    }
}

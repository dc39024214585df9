//! Whether a surface is a whole turn of a circular cylinder: a surface on which the distance
//! to any point off the axis has one local minimum.
//!
//! On a cylinder of radius `R` about an axis, a point at distance `rho > 0` from the axis is
//! at squared distance `rho^2 - 2 rho R cos(theta) + R^2 + (z - v)^2` from the surface point
//! at angle `theta` (from the point's own direction) and height `v`: over a whole turn of
//! `theta` and an interval of `v` it has one local minimum (`theta = 0`, `v` clamped to `z`),
//! and on the axis every angle is as near. Newton's method with descent (`newton_foot`) from
//! any start reaches that minimum, so the nearest-point search
//! ([`ShapeProjector`](super::ShapeProjector)) solves such a face once per query, as it does a
//! plane (`flat.rs`): when the foot is outside a trimmed face, the face's nearest point is on
//! its edges, which are searched on their own. A partial turn can have two local minima (at
//! its two ends) and is not taken.
//!
//! karkas reads a STEP `CYLINDRICAL_SURFACE` (and a cylinder written as a NURBS) as a
//! revolution: degree 1 along the axis with two columns of control points that differ by one
//! translation along the axis, and rational quadratic arcs around it. The surface is taken as a
//! cylinder when it has that form and the arc curve `S(u, v0)` lies on one circle in the plane
//! normal to the translation at eight points of every knot span: a rational quadratic span is a
//! conic, fixed by five of its points, so a span with eight points on a circle is that circle.

use crate::bspline::NurbsSurface;
use crate::core::Surface;
use crate::Point3;

/// The tolerance on the form and the circle, relative to the radius or the axis length plus
/// the largest coordinate (rounding grows with the distance from the origin).
const TOLERANCE: f64 = 1e-12;
/// Points checked on each knot span of the arcs.
const PER_SPAN: usize = 8;

/// True when `surface` is a whole turn of a circular cylinder (closed in `u`, straight in
/// `v`), as the module docs define it.
pub(super) fn is_whole_cylinder(surface: &NurbsSurface<3>) -> bool {
    if !surface.is_closed_u() || surface.degree_v() != 1 || surface.degree_u() > 2 {
        return false;
    }
    let control = surface.control_points();
    let weights = surface.weights();
    if control.cols() != 2 || control.rows() < 3 {
        return false;
    }
    let (kv, ku) = (surface.knots_v(), surface.knots_u());
    let (v0, v1) = (kv[1], kv[2]);
    let axis = *control.get(0, 1) - *control.get(0, 0);
    let length = axis.norm();
    if !(length > 0.0 && v1 > v0) {
        return false;
    }
    let same_shift = (0..control.rows()).all(|i| {
        *weights.get(i, 0) == *weights.get(i, 1)
            && (*control.get(i, 1) - *control.get(i, 0) - axis).norm()
                <= TOLERANCE * (length + control.get(i, 0).max_abs())
    });
    if !same_shift {
        return false;
    }
    let far = control
        .as_slice()
        .iter()
        .map(|p| p.max_abs())
        .fold(0.0, f64::max);
    let n = axis * (1.0 / length);
    let du = surface.domain_u();
    let at = |u: f64| surface.eval(u, v0);
    // The circle through three points a third of a turn apart.
    let (a, b, c) = (
        at(du.start),
        at(du.start + du.length() / 3.0),
        at(du.start + 2.0 * du.length() / 3.0),
    );
    let Some(centre) = circumcentre(a, b, c) else {
        return false;
    };
    let radius = a.distance(centre);
    let tolerance = TOLERANCE * (radius + far);
    // The arcs close (their first and last control points meet): a whole turn.
    let last = control.rows() - 1;
    let closes = control.get(0, 0).distance(*control.get(last, 0)) <= tolerance
        && weights.get(0, 0) == weights.get(last, 0)
        && surface.is_clamped();
    if radius.is_nan() || radius <= 0.0 || !closes {
        return false;
    }
    let on_circle = |p: Point3| {
        let r = p - centre;
        r.dot(n).abs() <= tolerance && (r.norm() - radius).abs() <= tolerance
    };
    let spans = ku
        .windows(2)
        .filter(|w| w[1] > w[0] && w[0] >= du.start && w[1] <= du.end);
    let mut checked = 0;
    for w in spans {
        for k in 0..PER_SPAN {
            let u = w[0] + (w[1] - w[0]) * (k as f64 + 0.5) / PER_SPAN as f64;
            if !on_circle(at(u)) {
                return false;
            }
            checked += 1;
        }
    }
    checked > 0
}

/// The centre of the circle through `a`, `b` and `c`, when they are not on one line.
fn circumcentre(a: Point3, b: Point3, c: Point3) -> Option<Point3> {
    let (ab, ac) = (b - a, c - a);
    let normal = ab.cross(ac);
    let n2 = normal.norm_sq();
    if n2.is_nan() || n2 <= 0.0 {
        return None;
    }
    // a + (|ab|^2 (ac x n) + |ac|^2 (n x ab)) / (2 |n|^2).
    let offset = (ac.cross(normal) * ab.norm_sq() + normal.cross(ab) * ac.norm_sq()) * (0.5 / n2);
    Some(a + offset)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::sweep::{cone, cylinder, plane, Frame};
    use std::f64::consts::TAU;

    #[test]
    fn whole_cylinders_are_told_from_other_surfaces() {
        let frame = Frame::new(
            Point3::new([105.0, -46.0, 21.5]),
            Point3::new([0.1, -0.2, 1.0]),
            Point3::new([1.0, 0.5, 0.0]),
        )
        .unwrap();
        for radius in [0.01, 2.3, 140.0] {
            let whole = cylinder(&frame, radius, (0.0, TAU), (0.0, 2.5))
                .unwrap()
                .with_closed(true, false);
            assert!(is_whole_cylinder(&whole), "{radius}");
            // A half turn is not taken, nor a whole turn not marked closed.
            let half = cylinder(&frame, radius, (0.0, 0.5 * TAU), (0.0, 2.5)).unwrap();
            assert!(!is_whole_cylinder(&half.with_closed(true, false)));
            let open = cylinder(&frame, radius, (0.0, TAU), (0.0, 2.5)).unwrap();
            assert!(!is_whole_cylinder(&open));
        }
        let cone = cone(&frame, 2.0, 0.3, (0.0, TAU), (0.0, 2.0))
            .unwrap()
            .with_closed(true, false);
        assert!(!is_whole_cylinder(&cone));
        let flat = plane(&frame, (0.0, 1.0), (0.0, 1.0)).unwrap();
        assert!(!is_whole_cylinder(&flat));
    }
}

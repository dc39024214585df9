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

/// A whole turn of a circular cylinder, with what its feet in closed form need.
///
/// The surface is `S(u, v) = C(u) + (v - v0) / (v1 - v0) * axis` with `C` a circle of radius
/// `radius` about `centre` in the plane normal to `axis`. The foot of `q` is the circle's point
/// in the direction of `q`'s radial part, moved along the axis to `q`'s height clamped to the
/// surface. Its `u` inverts the arc it lies on: on a rational quadratic Bezier span
/// `(P0, P1, P2; w0, w1, w2)` of a circle (the span's two knots each at least double), the
/// reparametrisation `s = a t / ((1 - t) + a t)`, `a = sqrt(w0 / w2)`, gives the symmetric form
/// of weights `(1, cos(alpha), 1)` over the arc of half-angle `alpha`, on which
/// `tan(phi / 2) = tan(alpha / 2) (2 t - 1)` for the angle `phi` from the arc's middle (the
/// stereographic parametrisation of the circle). Half-angle tangents are taken as
/// `y / (R + x)`, exact to rounding over the open half-circle.
#[derive(Clone, Debug)]
pub(super) struct Round {
    /// The circle's centre at `v0`.
    centre: Point3,
    /// The unit axis (along growing `v`).
    axis: Point3,
    /// The axis length from `v0` to `v1`.
    length: f64,
    radius: f64,
    v: (f64, f64),
    /// The arcs, when every span is a Bezier arc under a half-turn with positive weights.
    arcs: Option<Vec<Arc>>,
    /// `+1` when `S_u x S_v` points away from the axis, `-1` when towards it.
    outward: f64,
}

/// One Bezier span of the circle, in the frame of its middle.
#[derive(Clone, Copy, Debug)]
struct Arc {
    /// The span's knots.
    u: (f64, f64),
    /// The unit direction from the centre to the arc's middle.
    middle: Point3,
    /// The unit direction normal to `middle` in the circle's plane, towards the span's end.
    side: Point3,
    /// `tan(alpha / 2)` for the arc's half-angle `alpha`.
    half_tan: f64,
    /// `sqrt(w0 / w2)`.
    ratio: f64,
}

impl Round {
    /// The cylinder `surface` is, as the module docs define it, or `None`.
    pub(super) fn of(surface: &NurbsSurface<3>) -> Option<Round> {
        let (v, axis, length) = translation(surface)?;
        let n = axis * (1.0 / length);
        let (centre, radius, spans) = whole_circle(surface, v.0, n)?;
        let du = surface.domain_u();
        let [p, su, sv, ..] =
            surface.second_order(du.start + 0.5 * du.length() / spans.len() as f64, v.0);
        let outward = if su.cross(sv).dot(p - centre) >= 0.0 {
            1.0
        } else {
            -1.0
        };
        let arcs = if surface.degree_u() == 2 {
            spans
                .iter()
                .map(|&i| arc(surface, i, centre, n, radius))
                .collect::<Option<Vec<Arc>>>()
        } else {
            None
        };
        Some(Round {
            centre,
            axis: n,
            length,
            radius,
            v,
            arcs,
            outward,
        })
    }

    /// The parameters and the point of the surface nearest `q`, in closed form; `None` on the
    /// axis (every angle as near) or when the arcs are not Bezier spans.
    pub(super) fn foot(&self, q: Point3) -> Option<(f64, f64, Point3)> {
        let arcs = self.arcs.as_deref()?;
        let r = q - self.centre;
        let h = r.dot(self.axis);
        let radial = r - self.axis * h;
        let rho = radial.norm();
        if rho.is_nan() || rho <= 0.0 {
            return None;
        }
        let direction = radial * (1.0 / rho);
        let u = arcs.iter().find_map(|arc| arc.parameter(direction))?;
        let height = h.clamp(0.0, self.length);
        let v = self.v.0 + (self.v.1 - self.v.0) * (height / self.length);
        let v = v.clamp(self.v.0, self.v.1);
        Some((
            u,
            v,
            self.centre + self.axis * height + direction * self.radius,
        ))
    }

    /// The unit normal `S_u x S_v / |S_u x S_v|` at the surface point `p`.
    pub(super) fn normal(&self, p: Point3) -> Point3 {
        let r = p - self.centre;
        let radial = r - self.axis * r.dot(self.axis);
        radial * (self.outward / radial.norm())
    }
}

impl Arc {
    /// The parameter of the circle's point in the unit direction `d` (from the centre), when
    /// it lies on this arc.
    fn parameter(&self, d: Point3) -> Option<f64> {
        let (x, y) = (d.dot(self.middle), d.dot(self.side));
        if x <= 0.0 {
            return None;
        }
        // t in [0, 1] from tan(phi / 2) = y / (1 + x).
        let t = 0.5 * (1.0 + (y / (1.0 + x)) / self.half_tan);
        if !(-1e-12..=1.0 + 1e-12).contains(&t) {
            return None;
        }
        let t = t.clamp(0.0, 1.0);
        let s = self.ratio * t / ((1.0 - t) + self.ratio * t);
        Some((self.u.0 + s * (self.u.1 - self.u.0)).clamp(self.u.0, self.u.1))
    }
}

/// The arc of the span `[ku[i], ku[i + 1]]` of `surface`'s circle at `v0`, when it is a
/// Bezier span (both knots at least double) of positive weights under a half-turn.
fn arc(surface: &NurbsSurface<3>, i: usize, centre: Point3, n: Point3, radius: f64) -> Option<Arc> {
    let ku = surface.knots_u();
    if i < 2 || i + 2 >= ku.len() || ku[i - 1] != ku[i] || ku[i + 1] != ku[i + 2] {
        return None;
    }
    let control = surface.control_points();
    let weights = surface.weights();
    let p = [
        *control.get(i - 2, 0),
        *control.get(i - 1, 0),
        *control.get(i, 0),
    ];
    let w = [
        *weights.get(i - 2, 0),
        *weights.get(i - 1, 0),
        *weights.get(i, 0),
    ];
    if w.iter().any(|w| w.is_nan() || *w <= 0.0) {
        return None;
    }
    let flat = |x: Point3| {
        let r = x - centre;
        r - n * r.dot(n)
    };
    let middle = flat(p[1]);
    let middle = middle * (1.0 / middle.norm());
    let end = flat(p[2]) * (1.0 / radius);
    let side = end - middle * end.dot(middle);
    let side_length = side.norm();
    let x2 = end.dot(middle);
    if side_length.is_nan() || side_length <= 0.0 || x2 <= -1.0 + 1e-9 || !middle.is_finite() {
        return None;
    }
    Some(Arc {
        u: (ku[i], ku[i + 1]),
        middle,
        side: side * (1.0 / side_length),
        half_tan: side_length / (1.0 + x2),
        ratio: (w[0] / w[2]).sqrt(),
    })
}

/// True when `surface` is a whole turn of a circular cylinder (closed in `u`, straight in
/// `v`), as the module docs define it.
#[cfg(test)]
fn is_whole_cylinder(surface: &NurbsSurface<3>) -> bool {
    Round::of(surface).is_some()
}

/// The extrusion `surface` is when it is one: closed in `u`, degree 1 in `v` with two columns
/// of control points that differ by one translation (with equal weights). Its `v` interval,
/// the translation (the axis from `v0` to `v1`) and its length.
fn translation(surface: &NurbsSurface<3>) -> Option<((f64, f64), Point3, f64)> {
    if !surface.is_closed_u() || surface.degree_v() != 1 || surface.degree_u() > 2 {
        return None;
    }
    let control = surface.control_points();
    let weights = surface.weights();
    if control.cols() != 2 || control.rows() < 3 {
        return None;
    }
    let kv = surface.knots_v();
    let (v0, v1) = (kv[1], kv[2]);
    let axis = *control.get(0, 1) - *control.get(0, 0);
    let length = axis.norm();
    if !(length > 0.0 && v1 > v0) {
        return None;
    }
    let same_shift = (0..control.rows()).all(|i| {
        *weights.get(i, 0) == *weights.get(i, 1)
            && (*control.get(i, 1) - *control.get(i, 0) - axis).norm()
                <= TOLERANCE * (length + control.get(i, 0).max_abs())
    });
    same_shift.then_some(((v0, v1), axis, length))
}

/// The circle the curve `S(u, v0)` of the extrusion `surface` turns once around, in the plane
/// of unit normal `n`, checked at [`PER_SPAN`] points of every knot span: its centre, its
/// radius and the spans (indices into the `u` knots).
fn whole_circle(
    surface: &NurbsSurface<3>,
    v0: f64,
    n: Point3,
) -> Option<(Point3, f64, Vec<usize>)> {
    let control = surface.control_points();
    let weights = surface.weights();
    let ku = surface.knots_u();
    let far = control
        .as_slice()
        .iter()
        .map(|p| p.max_abs())
        .fold(0.0, f64::max);
    let du = surface.domain_u();
    let at = |u: f64| surface.eval(u, v0);
    // The circle through three points a third of a turn apart.
    let (centre, _) = circumcentre(
        at(du.start),
        at(du.start + du.length() / 3.0),
        at(du.start + 2.0 * du.length() / 3.0),
    )?;
    let radius = at(du.start).distance(centre);
    let tolerance = TOLERANCE * (radius + far);
    // The arcs close: a whole turn. With clamped knots the first and last control points
    // meet; with the unclamped knots of a periodic B-spline (as Open CASCADE writes a cylinder
    // converted to NURBS: every span a Bezier arc between double knots, one knot outside the
    // domain at each end) the curve's two ends do.
    let last = control.rows() - 1;
    let closes = if surface.is_clamped() {
        control.get(0, 0).distance(*control.get(last, 0)) <= tolerance
            && weights.get(0, 0) == weights.get(last, 0)
    } else {
        at(du.start).distance(at(du.end)) <= tolerance
    };
    if radius.is_nan() || radius <= 0.0 || !closes {
        return None;
    }
    let on_circle = |p: Point3| {
        let r = p - centre;
        r.dot(n).abs() <= tolerance && (r.norm() - radius).abs() <= tolerance
    };
    let spans: Vec<usize> = (0..ku.len() - 1)
        .filter(|&i| ku[i + 1] > ku[i] && ku[i] >= du.start && ku[i + 1] <= du.end)
        .collect();
    let on = spans.iter().all(|&i| {
        (0..PER_SPAN).all(|k| {
            on_circle(at(
                ku[i] + (ku[i + 1] - ku[i]) * (k as f64 + 0.5) / PER_SPAN as f64
            ))
        })
    });
    (on && !spans.is_empty()).then_some((centre, radius, spans))
}

/// The centre of the circle through `a`, `b`, `c` and the unit normal `(b - a) x (c - a)` of
/// its plane; `None` when the points are on one line (or not finite).
pub(super) fn circumcentre(a: Point3, b: Point3, c: Point3) -> Option<(Point3, Point3)> {
    let (ab, ac) = (b - a, c - a);
    let normal = ab.cross(ac);
    let n2 = normal.norm_sq();
    if n2.is_nan() || n2 <= 0.0 {
        return None;
    }
    // a + (|ab|^2 (ac x n) + |ac|^2 (n x ab)) / (2 |n|^2).
    let offset = (ac.cross(normal) * ab.norm_sq() + normal.cross(ab) * ac.norm_sq()) * (0.5 / n2);
    Some((a + offset, normal * (1.0 / n2.sqrt())))
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

    /// A whole cylinder as Open CASCADE writes one converted to NURBS: three arcs of a third
    /// of a turn (weights 1, 1/2, 1), double inner knots, and unclamped ends (one knot outside
    /// the domain `[0, 2 pi]` at each end), radius `radius` about `centre`, `v` in `[0, 2.5]`
    /// along `z`.
    fn periodic_cylinder(centre: Point3, radius: f64) -> NurbsSurface<3> {
        let third = TAU / 3.0;
        let knots_u = vec![
            -third,
            0.0,
            0.0,
            third,
            third,
            2.0 * third,
            2.0 * third,
            TAU,
            TAU,
            TAU + third,
        ];
        let at = |k: usize| {
            // Even k: on the circle at k * 60 degrees; odd k: the corner at twice the radius.
            let angle = k as f64 * TAU / 6.0;
            let r = if k.is_multiple_of(2) {
                radius
            } else {
                2.0 * radius
            };
            centre + Point3::new([r * angle.cos(), r * angle.sin(), 0.0])
        };
        let lift = Point3::new([0.0, 0.0, 2.5]);
        let control = crate::Grid::from_fn(7, 2, |i, j| at(i) + lift * j as f64);
        let weights =
            crate::Grid::from_fn(7, 2, |i, _| if i.is_multiple_of(2) { 1.0 } else { 0.5 });
        NurbsSurface::new(
            (2, knots_u),
            (1, vec![0.0, 0.0, 2.5, 2.5]),
            control,
            weights,
        )
        .unwrap()
        .with_closed(true, false)
    }

    #[test]
    fn a_cylinder_with_unclamped_periodic_knots_is_solved_in_closed_form() {
        let centre = Point3::new([105.0, -46.0, 21.5]);
        for radius in [0.01, 2.0, 140.0] {
            let s = periodic_cylinder(centre, radius);
            let round = Round::of(&s).expect("a whole cylinder");
            for k in 0..500 {
                let angle = 0.37 + k as f64 * 0.913;
                let rho = radius * (0.05 + 2.9 * ((k * 7919) % 1000) as f64 / 1000.0);
                let h = -1.0 + 4.5 * ((k * 104_729) % 997) as f64 / 997.0;
                let q = centre + Point3::new([rho * angle.cos(), rho * angle.sin(), h]);
                let (u, v, p) = round.foot(q).unwrap();
                let want = (rho - radius).hypot(h - h.clamp(0.0, 2.5));
                let scale = radius + 200.0;
                assert!(
                    (p.distance(q) - want).abs() <= 1e-13 * scale,
                    "{radius} {k}"
                );
                assert!(
                    s.eval(u, v).distance(p) <= 1e-13 * scale,
                    "{radius} {u} {v}"
                );
            }
        }
        // The same net with its first and last control points apart does not close.
        let mut open = periodic_cylinder(centre, 2.0);
        let moved = crate::Grid::from_fn(7, 2, |i, j| {
            let p = *open.control_points().get(i, j);
            if i == 6 {
                p + Point3::new([0.0, 0.3, 0.0])
            } else {
                p
            }
        });
        open = NurbsSurface::new(
            (2, open.knots_u().to_vec()),
            (1, open.knots_v().to_vec()),
            moved,
            open.weights().clone(),
        )
        .unwrap()
        .with_closed(true, false);
        assert!(Round::of(&open).is_none());
    }

    #[test]
    fn cylinder_feet_in_closed_form_are_the_nearest_points() {
        let frame = Frame::new(
            Point3::new([105.0, -46.0, 21.5]),
            Point3::new([0.1, -0.2, 1.0]),
            Point3::new([1.0, 0.5, 0.0]),
        )
        .unwrap();
        let mut state = 0x853c_49e6_748f_ea9bu64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for (radius, turn) in [
            (0.01, (0.0, TAU)),
            (2.3, (1.0, 1.0 + TAU)),
            (140.0, (-TAU, 0.0)),
        ] {
            // The axis either way (the turn and S_u x S_v change sides).
            for flip in [1.0, -1.0] {
                let frame = Frame::new(frame.origin, frame.z * flip, frame.x).unwrap();
                let s = cylinder(&frame, radius, turn, (-1.0, 2.5))
                    .unwrap()
                    .with_closed(true, false);
                let round = Round::of(&s).unwrap();
                for _ in 0..2000 {
                    let angle = TAU * next();
                    let rho = radius * 3.0 * next();
                    let h = -2.0 + 6.0 * next();
                    let q = frame.origin
                        + (frame.x * angle.cos() + frame.y * angle.sin()) * rho
                        + frame.z * h;
                    let (u, v, p) = round.foot(q).unwrap();
                    // The exact distance, and the point is the surface's at (u, v).
                    let axial = (h - h.clamp(-1.0, 2.5)).abs();
                    let want = (rho - radius).hypot(axial);
                    let scale = radius + 200.0;
                    assert!(
                        (p.distance(q) - want).abs() <= 1e-13 * scale,
                        "{radius} {q:?}"
                    );
                    assert!(
                        s.eval(u, v).distance(p) <= 1e-13 * scale,
                        "{radius} {u} {v}"
                    );
                    let d = s.second_order(u, v);
                    let normal = d[1].cross(d[2]);
                    let normal = normal * (1.0 / normal.norm());
                    assert!((round.normal(p) - normal).norm() < 1e-9, "{radius} {u}");
                }
            }
        }
    }
}

//! The volume a closed surface encloses, and the planes of planar boundary loops.
//!
//! By the divergence theorem, a closed, consistently oriented surface `S` encloses
//! `V = 1/3 ∮ x · n dA` (docs/methods.md §6, "Closed bodies"). Over a parametric patch this is
//! `1/3 ∫∫ S · (S_u × S_v) du dv`, a polynomial on each polynomial cell of a piecewise
//! polynomial surface, integrated here by the 8-point Gauss–Legendre rule in each variable on
//! each cell, split into `pieces` parts (exact for cells of degree up to `16 pieces / 3 - 1/3`
//! in each variable). A planar face bounded by a closed curve `C` contributes `1/3 p · A`,
//! `p` any point of its plane and `A = 1/2 ∮ C × C' dt` its area vector (exact by the same
//! rule on the curve's pieces). Poles (a side of the patch collapsed to a point) and seams
//! (two sides that are one curve) contribute nothing and need no special treatment.
//!
//! [`polygon_plane`] gives the plane of a closed polygon (Newell's normal, the polygon's area
//! vector, through the centroid) and says how far the points stray from it: a boundary loop
//! is capped by a planar face only when it lies in its plane.
//!
//! Cost: `O(cells pieces^2)` evaluations of the surface and two first derivatives.

use super::curvature::cross;
use super::quadrature::gauss8_rule;
use crate::{Curve, Point3};

/// `1/3 ∫∫ S · (S_u × S_v) du dv` over the rectangle of cells `breaks_u x breaks_v` (both
/// ascending), each cell split into `pieces x pieces` parts; `frame(u, v)` gives
/// `[S, S_u, S_v]`. The flux part of the volume of a closed surface (see the module docs):
/// positive when `S_u × S_v` points out of the body.
pub fn flux_volume(
    frame: impl Fn(f64, f64) -> [Point3; 3],
    breaks_u: &[f64],
    breaks_v: &[f64],
    pieces: usize,
) -> f64 {
    let pieces = pieces.max(1);
    let rules = |breaks: &[f64]| -> Vec<(f64, f64)> {
        breaks
            .windows(2)
            .flat_map(|w| {
                (0..pieces).flat_map(move |k| {
                    let step = (w[1] - w[0]) / pieces as f64;
                    gauss8_rule(w[0] + k as f64 * step, w[0] + (k + 1) as f64 * step)
                })
            })
            .collect()
    };
    let (us, vs) = (rules(breaks_u), rules(breaks_v));
    let mut sum = 0.0;
    for &(u, wu) in &us {
        for &(v, wv) in &vs {
            let [s, su, sv] = frame(u, v);
            sum += wu * wv * s.dot(cross(su, sv));
        }
    }
    sum / 3.0
}

/// The area vector `1/2 ∫ C × C' dt` of the curve `curve` over its domain cut at `breaks`
/// (its breakpoints, ascending; each piece split into `pieces` parts). For a closed planar
/// curve it is the normal of its plane times the area it bounds, pointing to the side from
/// which the curve runs counter-clockwise.
pub fn area_vector(curve: &impl Curve<3>, breaks: &[f64], pieces: usize) -> Point3 {
    let pieces = pieces.max(1);
    let mut sum = Point3::ZERO;
    for w in breaks.windows(2) {
        let step = (w[1] - w[0]) / pieces as f64;
        for k in 0..pieces {
            let a = w[0] + k as f64 * step;
            for (t, weight) in gauss8_rule(a, a + step) {
                sum += cross(curve.eval(t), curve.deriv(t, 1)) * weight;
            }
        }
    }
    sum * 0.5
}

/// A plane: a point on it and its unit normal.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    /// A point of the plane (for [`polygon_plane`], the points' centroid).
    pub origin: Point3,
    /// The unit normal.
    pub normal: Point3,
}

impl Plane {
    /// The signed distance of `p` from the plane (positive on the side of the normal).
    pub fn signed_distance(&self, p: Point3) -> f64 {
        (p - self.origin).dot(self.normal)
    }

    /// A unit vector in the plane (perpendicular to the normal), the first axis of the
    /// plane's own coordinates.
    pub fn x_axis(&self) -> Point3 {
        let n = self.normal;
        // The coordinate axis least aligned with the normal, made perpendicular to it.
        let k = (0..3)
            .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
            .unwrap_or(0);
        let mut e = Point3::ZERO;
        e.0[k] = 1.0;
        let x = e - n * e.dot(n);
        x * (1.0 / x.norm())
    }
}

/// The plane of the closed polygon `points` (in order, the last joined to the first): through
/// their centroid, its normal Newell's (the polygon's area vector, so that the polygon runs
/// counter-clockwise about it), and the largest distance of a point from it. `None` for
/// fewer than three points, non-finite points, or a polygon that encloses no area (points on
/// one line).
pub fn polygon_plane(points: &[Point3]) -> Option<(Plane, f64)> {
    if points.len() < 3 || points.iter().any(|p| !p.is_finite()) {
        return None;
    }
    let n = points.len() as f64;
    let centroid = points.iter().fold(Point3::ZERO, |s, &p| s + p) * (1.0 / n);
    // The area vector of the points about the centroid over their largest offset: products of
    // two lengths, which would underflow for polygons below about 1e-154 units (and overflow
    // above 1e154).
    let size = points
        .iter()
        .map(|p| (*p - centroid).max_abs())
        .fold(0.0, f64::max);
    if !(size > 0.0 && size.is_finite()) {
        return None;
    }
    let unit = |p: Point3| Point3::new((p - centroid).0.map(|c| c / size));
    let area = (0..points.len()).fold(Point3::ZERO, |s, k| {
        s + cross(unit(points[k]), unit(points[(k + 1) % points.len()]))
    });
    let length = area.norm();
    if length.is_nan() || length <= 1e-12 {
        return None;
    }
    let plane = Plane {
        origin: centroid,
        normal: area * (1.0 / length),
    };
    let deviation = points
        .iter()
        .map(|&p| plane.signed_distance(p).abs())
        .fold(0.0, f64::max);
    Some((plane, deviation))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Interval;
    use std::f64::consts::PI;

    /// A circle of radius `r` in the plane `z = h`, counter-clockwise seen from +z.
    struct Circle {
        r: f64,
        h: f64,
    }

    impl Curve<3> for Circle {
        fn domain(&self) -> Interval {
            Interval::new(0.0, 2.0 * PI)
        }
        fn is_closed(&self) -> bool {
            true
        }
        fn eval(&self, t: f64) -> Point3 {
            Point3::new([self.r * t.cos(), self.r * t.sin(), self.h])
        }
        fn deriv(&self, t: f64, k: usize) -> Point3 {
            match k % 4 {
                0 => self.eval(t),
                1 => Point3::new([-self.r * t.sin(), self.r * t.cos(), 0.0]),
                2 => Point3::new([-self.r * t.cos(), -self.r * t.sin(), 0.0]),
                _ => Point3::new([self.r * t.sin(), -self.r * t.cos(), 0.0]),
            }
        }
    }

    #[test]
    fn a_sphere_encloses_four_thirds_pi_r_cubed() {
        // S(u, v) = r (sin u cos v, sin u sin v, cos u): poles at u = 0 and u = pi, a seam at
        // v = 0; S_u x S_v points outwards.
        let r = 1.7;
        let frame = |u: f64, v: f64| {
            let (su, cu, sv, cv) = (u.sin(), u.cos(), v.sin(), v.cos());
            [
                Point3::new([r * su * cv, r * su * sv, r * cu]),
                Point3::new([r * cu * cv, r * cu * sv, -r * su]),
                Point3::new([-r * su * sv, r * su * cv, 0.0]),
            ]
        };
        let breaks_u: Vec<f64> = (0..=8).map(|k| PI * k as f64 / 8.0).collect();
        let breaks_v: Vec<f64> = (0..=16).map(|k| 2.0 * PI * k as f64 / 16.0).collect();
        let v = flux_volume(frame, &breaks_u, &breaks_v, 1);
        let exact = 4.0 / 3.0 * PI * r.powi(3);
        assert!((v - exact).abs() < 1e-10 * exact, "{v} {exact}");
    }

    #[test]
    fn a_capped_cylinder_adds_its_caps() {
        // The side S(u, v) = (r cos v, r sin v, h u), u in [0, 1]: S_u x S_v points inwards,
        // so the outward side contributes minus its flux, 2/3 of the volume; the caps the rest.
        let (r, h) = (0.8, 2.5);
        let frame = |u: f64, v: f64| {
            [
                Point3::new([r * v.cos(), r * v.sin(), h * u]),
                Point3::new([0.0, 0.0, h]),
                Point3::new([-r * v.sin(), r * v.cos(), 0.0]),
            ]
        };
        let breaks_v: Vec<f64> = (0..=12).map(|k| 2.0 * PI * k as f64 / 12.0).collect();
        let side = flux_volume(frame, &[0.0, 1.0], &breaks_v, 1);
        // Outward caps: the top (z = h) counter-clockwise seen from +z, the bottom clockwise.
        let top = area_vector(&Circle { r, h }, &breaks_v, 1);
        let bottom = area_vector(&Circle { r, h: 0.0 }, &breaks_v, 1) * -1.0;
        let caps = (Point3::new([0.0, 0.0, h]).dot(top) + Point3::ZERO.dot(bottom)) / 3.0;
        let exact = PI * r * r * h;
        assert!((top[2] - PI * r * r).abs() < 1e-12);
        assert!((caps - side - exact).abs() < 1e-10 * exact, "{side} {caps}");
    }

    #[test]
    fn the_plane_of_a_tilted_ring_and_its_deviation() {
        let n = Point3::new([1.0, 2.0, 2.0]) * (1.0 / 3.0);
        let plane = Plane {
            origin: Point3::new([5.0, -1.0, 3.0]),
            normal: n,
        };
        let (x, y) = (plane.x_axis(), cross(n, plane.x_axis()));
        assert!(x.dot(n).abs() < 1e-15 && (x.norm() - 1.0).abs() < 1e-15);
        let points: Vec<Point3> = (0..20)
            .map(|k| {
                let t = k as f64 * 0.3;
                plane.origin + x * t.cos() + y * (2.0 * t.sin())
            })
            .collect();
        let (fit, deviation) = polygon_plane(&points).unwrap();
        assert!(deviation < 1e-12, "{deviation}");
        assert!((fit.normal.dot(n) - 1.0).abs() < 1e-12);
        let mut bent = points.clone();
        bent[3] += n * 0.01;
        assert!(polygon_plane(&bent).unwrap().1 > 0.005);
        let line: Vec<Point3> = (0..5).map(|k| Point3::new([k as f64, 0.0, 0.0])).collect();
        assert!(polygon_plane(&line).is_none());
        // The same polygon at scales whose squared lengths leave the floating-point range.
        for scale in [1e-200, 1e-120, 1e120, 1e200] {
            let scaled: Vec<Point3> = points.iter().map(|&p| p * scale).collect();
            let (fit, deviation) = polygon_plane(&scaled).unwrap();
            assert!(deviation < 1e-12 * scale, "{scale}: {deviation}");
            assert!(
                (fit.normal.dot(n) - 1.0).abs() < 1e-12,
                "{scale}: {:?}",
                fit.normal
            );
        }
    }
}

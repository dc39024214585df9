//! The foot of a point on a face whose surface is a parallelogram of a plane, in closed form.
//!
//! CAD files give most faces of machined parts on planes (STEP `PLANE`, IGES 108 and 190),
//! which karkas reads as bilinear patches: degree 1 in `u` and `v`, `2 x 2` control points of
//! equal weights. When the four points form a parallelogram (`P00 + P11 = P10 + P01` to
//! rounding) the patch is affine, `S(u, v) = P00 + (u - u0) a + (v - v0) b`, and
//! `|S(u, v) - q|^2` is a convex quadratic in `(u, v)`: its one minimum is the solution of the
//! normal equations `[a.a a.b; a.b b.b] (x, y) = (a.r, b.r)`, `r = q - P00` (the orthogonal
//! projection of `q` on the plane). Newton's method from any cell of such a face reaches the
//! same point, so the nearest-point search ([`ShapeProjector`](super::ShapeProjector)) solves
//! each flat face once per query, not once per candidate cell. A foot outside the patch's
//! parameter rectangle is left to Newton's method (projected at the rectangle's sides), which
//! on a convex problem reaches the constrained minimum.

use crate::bspline::NurbsSurface;
use crate::Point3;

/// The largest twist `|P00 + P11 - P10 - P01|` of a flat patch, relative to its extent.
const TWIST_TOLERANCE: f64 = 1e-13;

/// An affine patch `P00 + (u - u0) a + (v - v0) b` over `[u0, u1] x [v0, v1]`.
#[derive(Clone, Copy, Debug)]
pub(super) struct Flat {
    origin: Point3,
    a: Point3,
    b: Point3,
    u: (f64, f64),
    v: (f64, f64),
    /// The inverse of the first fundamental form `[a.a a.b; a.b b.b]` (symmetric).
    inverse: [f64; 3],
    /// True when `a` and `b` are orthogonal (to `1e-15`): the distance then separates into a
    /// quadratic of `u` and one of `v`, and its minimum over the rectangle is the projection
    /// with each parameter clamped to its interval.
    orthogonal: bool,
    /// The unit normal `a x b / |a x b|`.
    normal: Point3,
}

impl Flat {
    /// The affine form of `surface` when it is a parallelogram of a plane, else `None`.
    pub(super) fn of(surface: &NurbsSurface<3>) -> Option<Flat> {
        if surface.degree_u() != 1 || surface.degree_v() != 1 {
            return None;
        }
        let control = surface.control_points();
        let weights = surface.weights();
        if control.rows() != 2 || control.cols() != 2 {
            return None;
        }
        let w = *weights.get(0, 0);
        if w.is_nan() || w <= 0.0 || (0..2).any(|i| (0..2).any(|j| *weights.get(i, j) != w)) {
            return None;
        }
        let (ku, kv) = (surface.knots_u(), surface.knots_v());
        let (u, v) = ((ku[1], ku[2]), (kv[1], kv[2]));
        if !(u.1 > u.0 && v.1 > v.0) {
            return None;
        }
        let (p00, p10, p01, p11) = (
            *control.get(0, 0),
            *control.get(1, 0),
            *control.get(0, 1),
            *control.get(1, 1),
        );
        let extent = p00
            .distance(p10)
            .max(p00.distance(p01))
            .max(p00.distance(p11));
        let twist = ((p00 + p11) - (p10 + p01)).norm();
        if extent.is_nan() || extent <= 0.0 || twist.is_nan() || twist > TWIST_TOLERANCE * extent {
            return None;
        }
        let a = (p10 - p00) * (1.0 / (u.1 - u.0));
        let b = (p01 - p00) * (1.0 / (v.1 - v.0));
        let (aa, ab, bb) = (a.dot(a), a.dot(b), b.dot(b));
        let det = aa * bb - ab * ab;
        if det.is_nan() || det <= 1e-12 * aa * bb {
            return None;
        }
        let normal = a.cross(b);
        let length = normal.norm();
        if length.is_nan() || length <= 0.0 {
            return None;
        }
        Some(Flat {
            origin: p00,
            a,
            b,
            u,
            v,
            inverse: [bb / det, -ab / det, aa / det],
            orthogonal: ab.abs() <= 1e-15 * (aa * bb).sqrt(),
            normal: normal * (1.0 / length),
        })
    }

    /// The parameters of `q`'s orthogonal projection on the plane, when they lie in the
    /// patch's rectangle; `None` otherwise.
    pub(super) fn foot(&self, q: Point3) -> Option<(f64, f64)> {
        let r = q - self.origin;
        let (ra, rb) = (r.dot(self.a), r.dot(self.b));
        let [i00, i01, i11] = self.inverse;
        let u = self.u.0 + (i00 * ra + i01 * rb);
        let v = self.v.0 + (i01 * ra + i11 * rb);
        ((self.u.0..=self.u.1).contains(&u) && (self.v.0..=self.v.1).contains(&v)).then_some((u, v))
    }

    /// The parameters of the patch's point nearest `q`: the projection when it lies in the
    /// rectangle, else (on an orthogonal patch) the projection clamped to the rectangle;
    /// `None` for a point beyond the rectangle of a skew patch.
    pub(super) fn nearest(&self, q: Point3) -> Option<(f64, f64)> {
        let r = q - self.origin;
        let (ra, rb) = (r.dot(self.a), r.dot(self.b));
        let [i00, i01, i11] = self.inverse;
        let u = self.u.0 + (i00 * ra + i01 * rb);
        let v = self.v.0 + (i01 * ra + i11 * rb);
        let inside = (self.u.0..=self.u.1).contains(&u) && (self.v.0..=self.v.1).contains(&v);
        (inside || self.orthogonal)
            .then(|| (u.clamp(self.u.0, self.u.1), v.clamp(self.v.0, self.v.1)))
    }

    /// The patch's point at `(u, v)`.
    pub(super) fn point(&self, u: f64, v: f64) -> Point3 {
        self.origin + self.a * (u - self.u.0) + self.b * (v - self.v.0)
    }

    /// The unit normal `S_u x S_v / |S_u x S_v|`.
    pub(super) fn normal(&self) -> Point3 {
        self.normal
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::sweep::{cylinder, plane, Frame};
    use crate::core::Surface;

    #[test]
    fn feet_are_the_orthogonal_projections() {
        // A plane turned about every axis, far from the origin.
        let z = Point3::new([0.3, -0.5, 0.81]);
        let x = Point3::new([0.9, 0.2, -0.2]);
        let frame = Frame::new(Point3::new([120.0, -40.0, 35.0]), z, x).unwrap();
        let s = plane(&frame, (-3.0, 5.0), (1.0, 2.5)).unwrap();
        let flat = Flat::of(&s).unwrap();
        let n = frame.z;
        for k in 0..100 {
            let u = -2.99 + 0.079 * k as f64;
            let v = 1.005 + 0.0149 * ((k * 7) % 100) as f64;
            let h = -2.0 + 0.04 * k as f64;
            let q = s.eval(u, v) + n * h;
            let (fu, fv) = flat.foot(q).unwrap();
            assert!((fu - u).abs() < 1e-12 && (fv - v).abs() < 1e-12, "{k}");
            assert!((s.eval(fu, fv).distance(q) - h.abs()).abs() < 1e-12, "{k}");
        }
        // Beyond the rectangle: no foot; the nearest point is on its side.
        let beyond = s.eval(-3.0, 1.7) - frame.x * 0.1 + n * 0.3;
        assert!(flat.foot(beyond).is_none());
        let (nu, nv) = flat.nearest(beyond).unwrap();
        assert!((nu + 3.0).abs() < 1e-12 && (nv - 1.7).abs() < 1e-12);
        assert!(flat.point(nu, nv).distance(s.eval(-3.0, 1.7)) < 1e-12);
        let corner = s.eval(5.0, 2.5) + frame.x * 0.2 + frame.y * 0.4 - n * 3.0;
        assert_eq!(flat.nearest(corner), Some((5.0, 2.5)));
        let su_sv = s.second_order(0.5, 1.5);
        let normal = su_sv[1].cross(su_sv[2]);
        assert!((flat.normal() - normal * (1.0 / normal.norm())).norm() < 1e-15);
        // A cylinder is not flat.
        let round = cylinder(&frame, 1.0, (0.0, 1.0), (0.0, 1.0)).unwrap();
        assert!(Flat::of(&round).is_none());
    }
}

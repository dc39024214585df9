//! Curve and surface geometry against closed forms: arc length, curvature and torsion of
//! circles, ellipses and helices, projection onto an ellipse and a cylinder, normals and
//! principal curvatures of spheres and tori, and degenerate input.

use std::f64::consts::{PI, TAU};

use karkas::geometry::{
    arc_length, principal_curvatures, torsion, CurveGeometry, CurveProjector, SurfaceProjector,
};
use karkas::param::{CubicSpline, SplineEnds};
use karkas::{Curve, Interval, Point, Point2, Point3, Surface};

/// The ellipse `(a cos t, b sin t)`, `t in [0, 2 pi)`, closed.
struct Ellipse {
    a: f64,
    b: f64,
}

impl Curve<2> for Ellipse {
    fn domain(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn is_closed(&self) -> bool {
        true
    }
    fn eval(&self, t: f64) -> Point2 {
        self.deriv(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point2 {
        // d^k/dt^k (cos t, sin t) = (cos(t + k pi/2), sin(t + k pi/2)).
        let s = t + k as f64 * PI / 2.0;
        Point([self.a * s.cos(), self.b * s.sin()])
    }
}

/// The helix `(r cos t, r sin t, c t)` on `[0, 4 pi]`, open.
struct Helix {
    r: f64,
    c: f64,
}

impl Curve<3> for Helix {
    fn domain(&self) -> Interval {
        Interval::new(0.0, 2.0 * TAU)
    }
    fn is_closed(&self) -> bool {
        false
    }
    fn eval(&self, t: f64) -> Point3 {
        self.deriv(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point3 {
        let s = t + k as f64 * PI / 2.0;
        let z = match k {
            0 => self.c * t,
            1 => self.c,
            _ => 0.0,
        };
        Point([self.r * s.cos(), self.r * s.sin(), z])
    }
}

/// The torus `((R + r cos v) cos u, (R + r cos v) sin u, r sin v)`, closed in both.
struct Torus {
    big: f64,
    small: f64,
}

fn trig(x: f64, k: usize) -> (f64, f64) {
    let s = x + k as f64 * PI / 2.0;
    (s.cos(), s.sin())
}

impl Surface<3> for Torus {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn is_closed_u(&self) -> bool {
        true
    }
    fn is_closed_v(&self) -> bool {
        true
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.deriv(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let (cu, su) = trig(u, ku);
        let (cv, sv) = trig(v, kv);
        let radial = if kv == 0 {
            self.big + self.small * cv
        } else {
            self.small * cv
        };
        let z = if ku == 0 { self.small * sv } else { 0.0 };
        Point([radial * cu, radial * su, z])
    }
}

/// The sphere of radius `r`: `(r cos v cos u, r cos v sin u, r sin v)`, `v in [-1.2, 1.2]`.
struct Sphere {
    r: f64,
}

impl Surface<3> for Sphere {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(-1.2, 1.2)
    }
    fn is_closed_u(&self) -> bool {
        true
    }
    fn is_closed_v(&self) -> bool {
        false
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.deriv(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let (cu, su) = trig(u, ku);
        let (cv, sv) = trig(v, kv);
        let z = if ku == 0 { self.r * sv } else { 0.0 };
        Point([self.r * cv * cu, self.r * cv * su, z])
    }
}

/// The cylinder `(r cos u, r sin u, v)`, `v in [0, h]`.
struct Cylinder {
    r: f64,
    h: f64,
}

impl Surface<3> for Cylinder {
    fn domain_u(&self) -> Interval {
        Interval::new(0.0, TAU)
    }
    fn domain_v(&self) -> Interval {
        Interval::new(0.0, self.h)
    }
    fn is_closed_u(&self) -> bool {
        true
    }
    fn is_closed_v(&self) -> bool {
        false
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.deriv(u, v, 0, 0)
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let (cu, su) = trig(u, ku);
        let z = match (ku, kv) {
            (0, 0) => v,
            (0, 1) => 1.0,
            _ => 0.0,
        };
        let scale = if kv == 0 { self.r } else { 0.0 };
        Point([scale * cu, scale * su, z])
    }
}

#[test]
fn circle_arc_length_and_curvature() {
    let circle = Ellipse { a: 2.0, b: 2.0 };
    for accuracy in [1e-4, 1e-8, 1e-12] {
        let whole = circle.arc_length(0.0, TAU, accuracy);
        assert!((whole - 2.0 * TAU).abs() <= accuracy, "{whole}");
    }
    // Over more than a period, and backwards.
    assert!((circle.arc_length(1.0, 1.0 + 3.0 * TAU, 1e-10) - 6.0 * TAU).abs() < 1e-10);
    assert!((circle.arc_length(2.0, 0.5, 1e-12) + 3.0).abs() < 1e-12);
    for t in [0.0, 1.0, 4.0] {
        assert!((circle.curvature(t) - 0.5).abs() < 1e-14);
    }
    // Clockwise: negative curvature in 2-D.
    let clockwise = Ellipse { a: 2.0, b: -2.0 };
    assert!((clockwise.curvature(0.3) + 0.5).abs() < 1e-14);
}

/// The perimeter of the ellipse with semi-axes 3 and 1: `4 a E(1 - b^2 / a^2)` with the
/// complete elliptic integral of the second kind.
const ELLIPSE_3_1_PERIMETER: f64 = 13.364_893_220_555_26;

#[test]
fn ellipse_arc_length_and_curvature() {
    let ellipse = Ellipse { a: 3.0, b: 1.0 };
    let perimeter = ELLIPSE_3_1_PERIMETER;
    assert!((arc_length(&ellipse, 0.0, TAU, 1e-12) - perimeter).abs() < 1e-11);
    // Curvature ab / (a^2 sin^2 + b^2 cos^2)^(3/2).
    for t in [0.0f64, 0.7, 2.0] {
        let (s, c) = t.sin_cos();
        let k = 3.0 / (9.0 * s * s + c * c).powf(1.5);
        assert!((ellipse.curvature(t) - k).abs() < 1e-13);
    }
}

#[test]
fn inverse_arc_length_walks_the_stated_length() {
    let ellipse = Ellipse { a: 3.0, b: 1.0 };
    for (t0, s) in [(0.0, 1.0), (1.0, 5.5), (2.0, -3.0), (0.5, 30.0)] {
        let t = ellipse.inverse_arc_length(t0, s, 1e-10);
        let walked = if s >= 0.0 {
            let mut t1 = t;
            while t1 < t0 {
                t1 += TAU;
            }
            let turns = (s / ELLIPSE_3_1_PERIMETER).floor();
            arc_length(&ellipse, t0, t1, 1e-12) + turns * ELLIPSE_3_1_PERIMETER
        } else {
            let mut t1 = t;
            while t1 > t0 {
                t1 -= TAU;
            }
            arc_length(&ellipse, t0, t1, 1e-12)
        };
        assert!((walked - s).abs() < 1e-9, "{t0} {s}: {walked}");
    }
    // An open curve stops at its end.
    let helix = Helix { r: 1.0, c: 0.5 };
    assert_eq!(helix.inverse_arc_length(0.0, 1e6, 1e-10), 2.0 * TAU);
    let speed = 1.25f64.sqrt();
    assert!((helix.inverse_arc_length(1.0, 2.0 * speed, 1e-12) - 3.0).abs() < 1e-11);
}

#[test]
fn helix_arc_length_curvature_and_torsion() {
    let (r, c) = (2.0, 0.5);
    let helix = Helix { r, c };
    let speed = (r * r + c * c).sqrt();
    assert!((helix.arc_length(0.0, 2.0 * TAU, 1e-12) - 2.0 * TAU * speed).abs() < 1e-11);
    let kappa = r / (r * r + c * c);
    let tau = c / (r * r + c * c);
    for t in [0.0, 1.3, 10.0] {
        assert!((helix.curvature(t) - kappa).abs() < 1e-14);
        assert!((torsion(&helix, t) - tau).abs() < 1e-14);
    }
    // Left-handed: negative torsion.
    assert!((torsion(&Helix { r, c: -c }, 1.0) + tau).abs() < 1e-14);
}

/// The nearest point of the ellipse by dense sampling and a local refinement (an
/// independent reference).
fn ellipse_reference(e: &Ellipse, q: Point2) -> f64 {
    let n = 20000;
    let mut best = (f64::INFINITY, 0.0);
    for k in 0..n {
        let t = TAU * k as f64 / n as f64;
        let d = e.eval(t).distance(q);
        if d < best.0 {
            best = (d, t);
        }
    }
    // Golden-section refinement on [t - h, t + h].
    let h = TAU / n as f64;
    let (mut lo, mut hi) = (best.1 - h, best.1 + h);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (x1, x2) = (hi - g * (hi - lo), lo + g * (hi - lo));
        if e.eval(x1).distance(q) < e.eval(x2).distance(q) {
            hi = x2;
        } else {
            lo = x1;
        }
    }
    e.eval(0.5 * (lo + hi)).distance(q)
}

#[test]
fn ellipse_projection_is_global() {
    let ellipse = Ellipse { a: 3.0, b: 1.0 };
    let projector = CurveProjector::new(&ellipse, 0.0).unwrap();
    let queries = [
        Point([0.0, 0.2]),
        Point([2.9, 0.05]),
        Point([-5.0, 3.0]),
        Point([0.1, -0.9]),
        Point([1.0, 0.0]),
        Point([-2.0, 0.1]),
    ];
    for q in queries {
        let near = projector.nearest(q);
        let reference = ellipse_reference(&ellipse, q);
        assert!(
            near.distance <= reference + 1e-12,
            "{q:?}: {} vs {reference}",
            near.distance
        );
        assert!((near.distance - reference).abs() < 1e-9);
        assert!(ellipse.eval(near.t).distance(near.point) < 1e-14);
        assert!((0.0..TAU).contains(&near.t));
    }
    // Points on the curve project onto themselves.
    for t in [0.0, 0.5, 3.0, 6.2] {
        let near = projector.nearest(ellipse.eval(t));
        assert!(near.distance < 1e-12);
        assert!((near.t - t).abs() < 1e-8);
    }
}

#[test]
fn the_centre_of_a_circle_projects_somewhere_at_the_radius() {
    let circle = Ellipse { a: 1.5, b: 1.5 };
    let projector = CurveProjector::new(&circle, 1e-12).unwrap();
    let near = projector.nearest(Point([0.0, 0.0]));
    assert!((near.distance - 1.5).abs() < 1e-12);
    let undefined = projector.nearest(Point([f64::NAN, 0.0]));
    assert!(undefined.t.is_nan() && undefined.distance.is_nan());
}

#[test]
fn open_curves_project_onto_their_ends_when_nearest() {
    let helix = Helix { r: 1.0, c: 0.2 };
    let projector = CurveProjector::new(&helix, 0.0).unwrap();
    let near = projector.nearest(Point([1.0, 0.0, -3.0]));
    assert_eq!(near.t, 0.0);
    assert!((near.distance - 3.0).abs() < 1e-14);
}

#[test]
fn a_spline_with_a_zero_length_piece_never_panics() {
    // A repeated point makes a piece of zero length.
    let pts = [
        Point([0.0, 0.0]),
        Point([1.0, 0.0]),
        Point([1.0, 0.0]),
        Point([2.0, 1.0]),
    ];
    let spline = CubicSpline::new(&[0.0, 1.0, 2.0, 3.0], &pts, SplineEnds::Natural).unwrap();
    let whole = spline.arc_length(0.0, 3.0, 1e-10);
    assert!(whole.is_finite() && whole >= 2f64.sqrt() + 1.0 - 1e-12);
    let t = spline.inverse_arc_length(0.0, 0.5 * whole, 1e-10);
    assert!((spline.arc_length(0.0, t, 1e-12) - 0.5 * whole).abs() < 1e-9);
    for t in [0.0, 0.5, 1.0, 1.5, 2.0, 3.0] {
        let _ = spline.curvature(t);
    }
    let projector = CurveProjector::new(&spline, 1e-12).unwrap();
    let near = projector.nearest(Point([1.0, 0.5]));
    assert!(near.distance.is_finite());
    assert!(projector.nearest(spline.eval(2.5)).distance < 1e-10);
    // A curve of zero length.
    let dot = CubicSpline::new(&[0.0, 1.0], &[Point([1.0, 1.0]); 2], SplineEnds::Natural).unwrap();
    assert_eq!(dot.arc_length(0.0, 1.0, 1e-10), 0.0);
    assert!(dot.curvature(0.5).is_nan());
    let near = CurveProjector::new(&dot, 0.0)
        .unwrap()
        .nearest(Point([1.0, 2.0]));
    assert!((near.distance - 1.0).abs() < 1e-15);
}

#[test]
fn sphere_and_torus_normals_and_principal_curvatures() {
    let sphere = Sphere { r: 2.0 };
    for (u, v) in [(0.0, 0.0), (1.0, 0.5), (4.0, -1.0)] {
        let pc = principal_curvatures(&sphere, u, v);
        // Outward normal; curvatures -1/r with respect to it.
        let p = sphere.eval(u, v) * 0.5;
        assert!(pc.normal.distance(p) < 1e-14);
        assert!((pc.k1 + 0.5).abs() < 1e-13 && (pc.k2 + 0.5).abs() < 1e-13);
        assert!(karkas::geometry::normal(&sphere, u, v).distance(p) < 1e-14);
    }
    let (big, small) = (3.0, 1.0);
    let torus = Torus { big, small };
    for (u, v) in [(0.0, 0.0), (0.7, 1.0), (2.0, PI), (5.0, 4.0)] {
        let pc = principal_curvatures(&torus, u, v);
        // The normal points into the tube's centre line? It is S_u x S_v normalised; compare
        // with the outward tube normal up to sign.
        let (cu, su) = (u.cos(), u.sin());
        let (cv, sv) = (v.cos(), v.sin());
        let outward = Point([cv * cu, cv * su, sv]);
        let sign = pc.normal.dot(outward);
        assert!((sign.abs() - 1.0).abs() < 1e-13);
        // With respect to the outward normal: -1/r along the tube's circle, and
        // -cos v / (R + r cos v) along the big circle.
        let mut ks = [-1.0 / small * sign, -cv / (big + small * cv) * sign];
        ks.sort_by(|a, b| b.total_cmp(a));
        assert!((pc.k1 - ks[0]).abs() < 1e-13, "{u} {v}: {} {:?}", pc.k1, ks);
        assert!((pc.k2 - ks[1]).abs() < 1e-13);
        // Directions: unit, tangent, orthogonal; the v-circle direction has k = -1/r.
        assert!(pc.dir1.dot(pc.normal).abs() < 1e-13 && pc.dir1.dot(pc.dir2).abs() < 1e-13);
        let along_v = torus.deriv(u, v, 0, 1) * (1.0 / small);
        let dir_of_tube = if (pc.k1 - (-sign / small)).abs() < 1e-12 {
            pc.dir1
        } else {
            pc.dir2
        };
        assert!((dir_of_tube.dot(along_v).abs() - 1.0).abs() < 1e-12);
    }
}

#[test]
fn projection_onto_a_cylinder() {
    let cylinder = Cylinder { r: 1.5, h: 4.0 };
    let projector = SurfaceProjector::new(&cylinder, (32, 8), 0.0).unwrap();
    for q in [
        Point([3.0, 1.0, 2.0]),
        Point([0.2, -0.3, 1.0]),
        Point([-1.0, -1.0, 3.9]),
        Point([0.0, 2.0, 6.0]),
    ] {
        let near = projector.nearest(q);
        let rho = q[0].hypot(q[1]);
        let radial = rho - 1.5;
        let over = (q[2] - 4.0).max(0.0) + (-q[2]).max(0.0);
        let expected = radial.hypot(over);
        assert!(
            (near.distance - expected).abs() < 1e-12,
            "{q:?}: {}",
            near.distance
        );
        let angle = q[1].atan2(q[0]).rem_euclid(TAU);
        assert!((near.u - angle).abs() < 1e-10, "{q:?}: {} {angle}", near.u);
        assert!((near.v - q[2].clamp(0.0, 4.0)).abs() < 1e-10);
        assert!(cylinder.eval(near.u, near.v).distance(near.point) < 1e-14);
    }
    // On the axis every ruling is nearest: any answer at distance r.
    let near = projector.nearest(Point([0.0, 0.0, 2.0]));
    assert!((near.distance - 1.5).abs() < 1e-12);
}

#[test]
fn projection_onto_a_torus_is_global() {
    let torus = Torus {
        big: 3.0,
        small: 1.0,
    };
    let projector = SurfaceProjector::new(&torus, (24, 12), 1e-13).unwrap();
    for q in [
        Point([5.0, 0.0, 0.0]),
        Point([-1.0, 2.0, 0.5]),
        Point([0.5, 0.5, 3.0]),
        Point([2.0, 2.0, -0.2]),
    ] {
        let near = projector.nearest(q);
        let rho = q[0].hypot(q[1]);
        let expected = ((rho - 3.0).hypot(q[2]) - 1.0).abs();
        assert!(
            (near.distance - expected).abs() < 1e-12,
            "{q:?}: {} {expected}",
            near.distance
        );
    }
    // Every point of the surface projects to itself.
    for (u, v) in [(0.1, 0.2), (3.0, 5.0), (6.0, 1.0)] {
        assert!(projector.nearest(torus.eval(u, v)).distance < 1e-12);
    }
}

#[test]
fn normals_and_curvatures_hold_at_extreme_scales() {
    // A sphere of radius 2e150 (or 2e-150): products of its derivatives overflow (underflow)
    // unless the frame is computed on the scaled derivatives. Curvatures scale as 1/s.
    for s in [1e150, 1e-150] {
        let sphere = Sphere { r: 2.0 * s };
        let (u, v) = (1.0, 0.5);
        let p = sphere.eval(u, v) * (0.5 / s);
        let pc = principal_curvatures(&sphere, u, v);
        assert!(pc.normal.distance(p) < 1e-14, "{s}");
        assert!(
            (pc.k1 * s + 0.5).abs() < 1e-13 && (pc.k2 * s + 0.5).abs() < 1e-13,
            "{s}"
        );
        assert!(
            karkas::geometry::normal(&sphere, u, v).distance(p) < 1e-14,
            "{s}"
        );
    }
}

#[test]
fn helix_curvature_and_torsion_hold_at_extreme_scales() {
    // A helix (r, c) scaled by s: curvature r / (r^2 + c^2) / s, torsion c / (r^2 + c^2) / s;
    // |P'|^3 alone would overflow at 1e150 and underflow at 1e-150.
    for s in [1e150, 1e-150] {
        let helix = Helix {
            r: 1.0 * s,
            c: 0.5 * s,
        };
        let (k, tau) = (1.0 / 1.25, 0.5 / 1.25);
        for t in [0.3, 2.0] {
            assert!((helix.curvature(t) * s - k).abs() < 1e-13, "{s}");
            assert!((torsion(&helix, t) * s - tau).abs() < 1e-13, "{s}");
        }
    }
}

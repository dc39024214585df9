//! The analytic surfaces of CAD files as exact rational B-spline surfaces (Piegl and Tiller,
//! *The NURBS Book*, §8.5, A8.1): planes, surfaces of linear extrusion and surfaces of
//! revolution, and through them cylinders, cones, spheres and tori, each over a rectangle of
//! its own parameters.
//!
//! Parameters follow ISO 10303-42 and Open CASCADE: a surface of revolution has the angle of
//! rotation `u` (rows of the control grid, around the axis by the right-hand rule, a
//! rational quadratic per piece of at most 90° as in [`conic`](super::conic), so `u` equals
//! the angle at every split) and the profile's parameter `v` (columns); an extrusion has the
//! curve's parameter `u` and the distance `v` along its unit direction. The elementary
//! surfaces are revolutions of their generatrix at angle 0 (in the plane of the placement's
//! `x` and `z` axes):
//!
//! | surface | generatrix `G(v)` | `S(u, v)` |
//! |---|---|---|
//! | cylinder, radius `R` | `c + R x + v z` | `c + R (cos u x + sin u y) + v z` |
//! | cone, radius `R`, half-angle `α` | `c + (R + v sin α) x + v cos α z` | `c + (R + v sin α)(cos u x + sin u y) + v cos α z` |
//! | sphere, radius `R` | `c + R cos v x + R sin v z` | `c + R cos v (cos u x + sin u y) + R sin v z` |
//! | torus, radii `R`, `r` | `c + (R + r cos v) x + r sin v z` | `c + (R + r cos v)(cos u x + sin u y) + r sin v z` |
//!
//! with `S_u x S_v` pointing away from the axis (out of the sphere and the torus's tube).

use super::conic::{arc_parts, check_sweep, elliptic_arc, line_segment};
use super::{NurbsCurve, NurbsSurface};
use crate::core::Grid;
use crate::{Error, Point3, Result};

/// A right-handed orthonormal frame: origin `c` and unit axes `x`, `y`, `z = x × y`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Frame {
    /// The origin.
    pub origin: Point3,
    /// The unit `x` axis (the reference direction, angle 0).
    pub x: Point3,
    /// The unit `y` axis.
    pub y: Point3,
    /// The unit `z` axis (the axis of revolution).
    pub z: Point3,
}

impl Frame {
    /// The frame at `origin` with axis `z` and reference direction `x` (made orthogonal to
    /// `z`), both normalized; `y = z × x`.
    ///
    /// Errors: a non-finite input, a zero axis, or a reference direction parallel to the
    /// axis ([`Error::InvalidSetting`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::sweep::Frame;
    /// use karkas::Point;
    ///
    /// // The reference direction is made orthogonal to the axis.
    /// let frame = Frame::new(Point([0.0; 3]), Point([0.0, 0.0, 2.0]), Point([1.0, 0.0, 1.0]))?;
    /// assert!(frame.x.distance(Point([1.0, 0.0, 0.0])) < 1e-14);
    /// assert!(frame.y.distance(Point([0.0, 1.0, 0.0])) < 1e-14);
    /// assert!(Frame::new(Point([0.0; 3]), Point([0.0, 0.0, 1.0]), Point([0.0, 0.0, 3.0])).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(origin: Point3, z: Point3, x: Point3) -> Result<Frame> {
        let bad = |reason| Error::InvalidSetting {
            name: "a placement's axis",
            value: z.norm(),
            reason,
        };
        if !(origin.is_finite() && z.is_finite() && x.is_finite()) {
            return Err(bad("not finite"));
        }
        let zn = z.norm();
        if zn == 0.0 {
            return Err(bad("the axis has length 0"));
        }
        let z = z * (1.0 / zn);
        let x = x - z * x.dot(z);
        let xn = x.norm();
        if xn <= 1e-12 * (1.0 + x.norm()) {
            return Err(bad("the reference direction is parallel to the axis"));
        }
        let x = x * (1.0 / xn);
        Ok(Frame {
            origin,
            x,
            y: z.cross(x),
            z,
        })
    }

    /// The point `origin + a x + b y + c z`.
    pub fn at(&self, a: f64, b: f64, c: f64) -> Point3 {
        self.origin + self.x * a + self.y * b + self.z * c
    }
}

/// The surface swept by `profile` turning about the axis through `origin` along the unit
/// vector `axis`, from angle `u0` to `u1` (`u` the angle, `v` the profile's parameter).
///
/// Errors: angles not finite, not increasing or more than a turn apart
/// ([`Error::InvalidSetting`]); a non-finite axis.
pub fn revolution(
    profile: &NurbsCurve<3>,
    origin: Point3,
    axis: Point3,
    (u0, u1): (f64, f64),
) -> Result<NurbsSurface<3>> {
    check_sweep(u0, u1)?;
    let n = axis.norm();
    if !(n > 0.0 && n.is_finite() && origin.is_finite()) {
        return Err(Error::InvalidSetting {
            name: "the axis of a surface of revolution",
            value: n,
            reason: "must be a finite nonzero vector through a finite point",
        });
    }
    let a = axis * (1.0 / n);
    let cols = profile.control_points().len();
    let mut columns = Vec::with_capacity(cols);
    let mut arc_knots = Vec::new();
    for (&p, &w) in profile.control_points().iter().zip(profile.weights()) {
        let o = origin + a * (p - origin).dot(a);
        let x = p - o;
        let y = a.cross(x);
        let (control, weights, knots) = arc_parts(o, x, y, (u0, u1));
        columns.push((
            control,
            weights.into_iter().map(|v| v * w).collect::<Vec<_>>(),
        ));
        arc_knots = knots;
    }
    let rows = columns[0].0.len();
    let control = Grid::from_fn(rows, cols, |i, j| columns[j].0[i]);
    let weights = Grid::from_fn(rows, cols, |i, j| columns[j].1[i]);
    NurbsSurface::new(
        (2, arc_knots),
        (profile.degree(), profile.knots().to_vec()),
        control,
        weights,
    )
}

/// The surface `C(u) + v d` for `v` in `[v0, v1]` (`d` the unit vector along `direction`),
/// `u` the curve's parameter.
///
/// Errors: `v0 >= v1` or not finite ([`Error::InvalidKnot`]); a zero or non-finite
/// direction ([`Error::InvalidSetting`]).
pub fn extrusion(
    curve: &NurbsCurve<3>,
    direction: Point3,
    (v0, v1): (f64, f64),
) -> Result<NurbsSurface<3>> {
    let n = direction.norm();
    if !(n > 0.0 && n.is_finite()) {
        return Err(Error::InvalidSetting {
            name: "the direction of an extrusion",
            value: n,
            reason: "must be a finite nonzero vector",
        });
    }
    let d = direction * (1.0 / n);
    let p = curve.control_points();
    let control = Grid::from_fn(p.len(), 2, |i, j| p[i] + d * if j == 0 { v0 } else { v1 });
    let weights = Grid::from_fn(p.len(), 2, |i, _| curve.weights()[i]);
    NurbsSurface::new(
        (curve.degree(), curve.knots().to_vec()),
        (1, vec![v0, v0, v1, v1]),
        control,
        weights,
    )
}

/// The plane `origin + u x + v y` (`frame`'s axes) over `[u0, u1] x [v0, v1]`: degree 1 x 1.
///
/// Errors: empty or non-finite ranges ([`Error::InvalidKnot`]).
pub fn plane(frame: &Frame, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> Result<NurbsSurface<3>> {
    let us = [u0, u1];
    let vs = [v0, v1];
    let control = Grid::from_fn(2, 2, |i, j| frame.at(us[i], vs[j], 0.0));
    NurbsSurface::new(
        (1, vec![u0, u0, u1, u1]),
        (1, vec![v0, v0, v1, v1]),
        control,
        Grid::from_fn(2, 2, |_, _| 1.0),
    )
}

/// The cylinder of radius `radius` about `frame`'s `z` axis over `[u0, u1] x [v0, v1]`
/// (see the module's table).
///
/// Errors: a radius that is not finite and positive, bad ranges.
pub fn cylinder(
    frame: &Frame,
    radius: f64,
    u: (f64, f64),
    (v0, v1): (f64, f64),
) -> Result<NurbsSurface<3>> {
    check_radius(radius, "a cylinder's radius")?;
    let g = line_segment(
        frame.at(radius, 0.0, v0),
        frame.at(radius, 0.0, v1),
        (v0, v1),
    )?;
    revolution(&g, frame.origin, frame.z, u)
}

/// The cone of radius `radius` at `v = 0` and half-angle `semi_angle` (radians, in `(-π/2,
/// π/2)`) about `frame`'s `z` axis over `[u0, u1] x [v0, v1]` (see the module's table).
///
/// Errors: a radius that is negative or not finite, a half-angle out of range, bad ranges.
pub fn cone(
    frame: &Frame,
    radius: f64,
    semi_angle: f64,
    u: (f64, f64),
    (v0, v1): (f64, f64),
) -> Result<NurbsSurface<3>> {
    if !(radius.is_finite() && radius >= 0.0) {
        return Err(Error::InvalidSetting {
            name: "a cone's radius",
            value: radius,
            reason: "must be finite and not negative",
        });
    }
    if semi_angle.is_nan() || semi_angle.abs() >= std::f64::consts::FRAC_PI_2 {
        return Err(Error::InvalidSetting {
            name: "a cone's half-angle",
            value: semi_angle,
            reason: "must lie strictly between -pi/2 and pi/2",
        });
    }
    let (s, c) = semi_angle.sin_cos();
    let at = |v: f64| frame.at(radius + v * s, 0.0, v * c);
    let g = line_segment(at(v0), at(v1), (v0, v1))?;
    revolution(&g, frame.origin, frame.z, u)
}

/// The sphere of radius `radius` centred at `frame`'s origin over `[u0, u1] x [v0, v1]`
/// (`v` the latitude, within `[-π/2, π/2]`; see the module's table).
///
/// Errors: a radius that is not finite and positive, bad ranges.
pub fn sphere(frame: &Frame, radius: f64, u: (f64, f64), v: (f64, f64)) -> Result<NurbsSurface<3>> {
    check_radius(radius, "a sphere's radius")?;
    let g = elliptic_arc(frame.origin, frame.x * radius, frame.z * radius, v)?;
    revolution(&g, frame.origin, frame.z, u)
}

/// The torus of major radius `major` (the tube's centre line) and minor radius `minor` about
/// `frame`'s `z` axis over `[u0, u1] x [v0, v1]` (see the module's table).
///
/// Errors: radii that are not finite and positive, bad ranges.
pub fn torus(
    frame: &Frame,
    major: f64,
    minor: f64,
    u: (f64, f64),
    v: (f64, f64),
) -> Result<NurbsSurface<3>> {
    check_radius(major, "a torus's major radius")?;
    check_radius(minor, "a torus's minor radius")?;
    let g = elliptic_arc(
        frame.at(major, 0.0, 0.0),
        frame.x * minor,
        frame.z * minor,
        v,
    )?;
    revolution(&g, frame.origin, frame.z, u)
}

fn check_radius(radius: f64, name: &'static str) -> Result<()> {
    if radius.is_finite() && radius > 0.0 {
        Ok(())
    } else {
        Err(Error::InvalidSetting {
            name,
            value: radius,
            reason: "must be finite and positive",
        })
    }
}

/// The unit normal `S_u × S_v / |S_u × S_v|` of a surface at `(u, v)`, `None` where it
/// degenerates (for tests and orientation checks of the sweeps).
#[cfg(test)]
fn unit_normal(s: &NurbsSurface<3>, u: f64, v: f64) -> Option<Point3> {
    use crate::Surface;
    let (su, sv) = (s.deriv(u, v, 1, 0), s.deriv(u, v, 0, 1));
    let n = su.cross(sv);
    let len = n.norm();
    (len > 1e-6 * (su.norm() + sv.norm()).powi(2)).then(|| n * (1.0 / len))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Curve, Surface};
    use std::f64::consts::PI;

    fn frame() -> Frame {
        Frame::new(
            Point3::new([10.0, -5.0, 3.0]),
            Point3::new([0.3, 0.2, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap()
    }

    /// Samples the surface on a grid and checks `distance_to_analytic(point) < tol` and that
    /// the normal points the way `outward(point)` says.
    fn check(
        s: &NurbsSurface<3>,
        analytic: impl Fn(Point3) -> f64,
        outward: impl Fn(Point3) -> Point3,
    ) {
        let (du, dv) = (s.domain_u(), s.domain_v());
        for a in 0..=30 {
            for b in 0..=30 {
                let (u, v) = (du.uniform(a, 31), dv.uniform(b, 31));
                let p = s.eval(u, v);
                assert!(analytic(p).abs() < 1e-13, "({u}, {v}): {}", analytic(p));
                if let Some(n) = unit_normal(s, u, v) {
                    let o = outward(p);
                    if o.norm() > 1e-9 {
                        assert!(n.dot(o) > 0.99 * o.norm(), "({u}, {v}): {n:?} {o:?}");
                    }
                }
            }
        }
    }

    #[test]
    fn elementary_surfaces_lie_where_their_equations_say() {
        let f = frame();
        let local = |p: Point3| {
            let d = p - f.origin;
            (d.dot(f.x), d.dot(f.y), d.dot(f.z))
        };
        let radial = |p: Point3| {
            let (a, b, c) = local(p);
            let r = a.hypot(b);
            f.x * (a / r) + f.y * (b / r) + f.z * (0.0 * c)
        };
        let cyl = cylinder(&f, 2.5, (0.0, 2.0 * PI), (-1.0, 4.0)).unwrap();
        check(
            &cyl,
            |p| {
                let (a, b, _) = local(p);
                a.hypot(b) - 2.5
            },
            radial,
        );
        // At the splits the parameter is the angle itself.
        let p = cyl.eval(PI / 2.0, 1.5);
        assert!(p.distance(f.at(0.0, 2.5, 1.5)) < 1e-13);

        let alpha = 0.4;
        let con = cone(&f, 1.0, alpha, (0.5, 2.0), (-0.5, 3.0)).unwrap();
        check(
            &con,
            |p| {
                let (a, b, c) = local(p);
                a.hypot(b) - (1.0 + c * alpha.tan())
            },
            |p| radial(p) - f.z * alpha.tan(),
        );

        let sph = sphere(&f, 3.0, (0.0, 2.0 * PI), (-PI / 2.0, PI / 2.0)).unwrap();
        check(&sph, |p| p.distance(f.origin) - 3.0, |p| p - f.origin);
        let p = sph.eval(PI, PI / 2.0 - 1e-300);
        assert!(p.distance(f.at(0.0, 0.0, 3.0)) < 1e-13);

        let tor = torus(&f, 5.0, 1.5, (0.0, 2.0 * PI), (0.0, 2.0 * PI)).unwrap();
        check(
            &tor,
            |p| {
                let (a, b, c) = local(p);
                (a.hypot(b) - 5.0).hypot(c) - 1.5
            },
            |p| {
                let (a, b, _) = local(p);
                let r = a.hypot(b);
                p - f.at(5.0 * a / r, 5.0 * b / r, 0.0)
            },
        );
        let p = tor.eval(PI, PI);
        assert!(p.distance(f.at(-3.5, 0.0, 0.0)) < 1e-13);

        let pl = plane(&f, (-1.0, 2.0), (0.0, 3.0)).unwrap();
        check(&pl, |p| (p - f.origin).dot(f.z), |_| f.z);
    }

    #[test]
    fn extrusions_and_revolutions_of_curves() {
        let f = frame();
        let arc = elliptic_arc(f.origin, f.x * 2.0, f.y, (0.0, 1.0)).unwrap();
        let e = extrusion(&arc, f.z * 7.0, (-1.0, 2.0)).unwrap();
        for (u, v) in [(0.2, -0.5), (0.9, 1.7)] {
            let want = arc.eval(u) + f.z * v;
            assert!(e.eval(u, v).distance(want) < 1e-13);
        }
        // Revolving the extrusion's profile curve a quarter turn about z moves x onto y.
        let r = revolution(&arc, f.origin, f.z, (0.0, PI / 2.0)).unwrap();
        for t in [0.1, 0.5, 0.95] {
            let p = arc.eval(t) - f.origin;
            let turned = f.origin + f.y * p.dot(f.x) - f.x * p.dot(f.y) + f.z * p.dot(f.z);
            assert!(r.eval(PI / 2.0, t).distance(turned) < 1e-13);
        }
        assert!(Frame::new(Point3::ZERO, Point3::ZERO, f.x).is_err());
        assert!(Frame::new(Point3::ZERO, f.z, f.z * 2.0).is_err());
        assert!(cylinder(&f, -1.0, (0.0, 1.0), (0.0, 1.0)).is_err());
        assert!(cone(&f, 1.0, 2.0, (0.0, 1.0), (0.0, 1.0)).is_err());
    }
}

//! Normal, principal curvatures and principal directions of an implicit surface, and the
//! projection of a point onto it.
//!
//! With `g = grad F`, `n = g / |g|` and the Hessian `H`, the normal curvature of `F = 0` in a
//! unit tangent direction `t` (measured along `n`) is `k(t) = -t^T H t / |g|` (the second
//! fundamental form of an implicit surface). In an orthonormal tangent basis `e_1, e_2` this
//! is the symmetric 2 x 2 form `A_ab = -e_a^T H e_b / |g|`; its eigenvalues are the principal
//! curvatures `k_1 >= k_2` and its eigenvectors the principal directions. `O(1)` per point.
//! At an umbilic (`k_1 = k_2`, e.g. everywhere on a sphere) every tangent direction is
//! principal; the frame then reports [`SurfaceFrame::is_umbilic`] and a fixed tangent basis.

use super::surface::ImplicitSurface;
use crate::{Error, Point3, Result};

/// Relative size of `k_1 - k_2` under which a point counts as an umbilic.
const UMBILIC_TOLERANCE: f64 = 1e-9;

/// Newton iterations allowed for a projection onto `F = 0`.
const PROJECTION_ITERATIONS: usize = 60;

/// The local geometry of `F = 0` at a point: unit normal, principal curvatures and
/// directions. `(first_direction, second_direction, normal)` is a right-handed orthonormal
/// frame.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceFrame {
    /// The point.
    pub point: Point3,
    /// `grad F / |grad F|`.
    pub normal: Point3,
    /// `|grad F|`.
    pub gradient_norm: f64,
    /// The larger principal curvature `k_1` (normal curvature along `normal`).
    pub first_curvature: f64,
    /// The smaller principal curvature `k_2 <= k_1`.
    pub second_curvature: f64,
    /// The unit principal direction of `k_1`.
    pub first_direction: Point3,
    /// The unit principal direction of `k_2`.
    pub second_direction: Point3,
}

impl SurfaceFrame {
    /// The frame of `surface` at `point` (which should lie on it; off the surface the same
    /// formulas give the frame of the level set `F = F(point)` through it).
    ///
    /// Errors: [`Error::SingularPoint`] where the gradient vanishes or is not finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::implicit::{Sphere, SurfaceFrame};
    /// use karkas::Point;
    ///
    /// // Every point of a sphere of radius 2 is umbilic with both curvatures of size 1/2.
    /// let frame = SurfaceFrame::at(&Sphere { radius: 2.0 }, Point([0.0, 0.0, 2.0]))?;
    /// assert!(frame.is_umbilic());
    /// assert!((frame.mean_curvature().abs() - 0.5).abs() < 1e-12);
    /// assert!(SurfaceFrame::at(&Sphere { radius: 2.0 }, Point([0.0, 0.0, 0.0])).is_err()); // no gradient
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn at<S: ImplicitSurface + ?Sized>(surface: &S, point: Point3) -> Result<Self> {
        let g = surface.gradient(point);
        let norm = g.norm();
        if norm.is_nan() || norm <= 1e-300 || norm.is_infinite() {
            return Err(Error::SingularPoint { point: point.0 });
        }
        let normal = g * (1.0 / norm);
        let (e1, e2) = tangent_basis(normal);
        let h = surface.hessian(point);
        let form = |a: Point3, b: Point3| {
            let mut s = 0.0;
            for r in 0..3 {
                for c in 0..3 {
                    s += a[r] * h[r][c] * b[c];
                }
            }
            -s / norm
        };
        let (a, b, c) = (form(e1, e1), form(e1, e2), form(e2, e2));
        let mean = 0.5 * (a + c);
        let radius = (0.25 * (a - c) * (a - c) + b * b).sqrt();
        let angle = 0.5 * (2.0 * b).atan2(a - c);
        let first = e1 * angle.cos() + e2 * angle.sin();
        Ok(SurfaceFrame {
            point,
            normal,
            gradient_norm: norm,
            first_curvature: mean + radius,
            second_curvature: mean - radius,
            first_direction: first,
            second_direction: cross(normal, first),
        })
    }

    /// True when the two principal curvatures agree (relative `1e-9`): every tangent
    /// direction is then principal.
    pub fn is_umbilic(&self) -> bool {
        let scale = self.first_curvature.abs().max(self.second_curvature.abs());
        self.first_curvature - self.second_curvature <= UMBILIC_TOLERANCE * scale.max(1e-300)
    }

    /// Gaussian curvature `k_1 k_2`.
    pub fn gaussian_curvature(&self) -> f64 {
        self.first_curvature * self.second_curvature
    }

    /// Mean curvature `(k_1 + k_2) / 2`.
    pub fn mean_curvature(&self) -> f64 {
        0.5 * (self.first_curvature + self.second_curvature)
    }

    /// `d` turned by `angle` (radians) about the normal, in the tangent plane:
    /// `cos(angle) d + sin(angle) (n x d)`.
    pub fn turn(&self, d: Point3, angle: f64) -> Point3 {
        d * angle.cos() + cross(self.normal, d) * angle.sin()
    }
}

/// `a x b`.
#[inline]
pub fn cross(a: Point3, b: Point3) -> Point3 {
    Point3::new([
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ])
}

/// An orthonormal basis of the plane orthogonal to the unit vector `n`, chosen from the
/// coordinate axis least aligned with `n` (deterministic, continuous away from switches).
fn tangent_basis(n: Point3) -> (Point3, Point3) {
    let k = (0..3)
        .min_by(|&a, &b| n[a].abs().total_cmp(&n[b].abs()))
        .unwrap_or(0);
    let mut axis = Point3::ZERO;
    axis[k] = 1.0;
    let e1 = cross(axis, n);
    let e1 = e1 * (1.0 / e1.norm());
    (e1, cross(n, e1))
}

/// The foot of `point` on `F = 0` by Newton's method along the gradient,
/// `p <- p - F(p) grad F(p) / |grad F(p)|^2`, to full precision.
///
/// Errors: [`Error::NonFiniteArgument`] for a non-finite `point`, [`Error::NoSurfaceNear`] when
/// the iteration does not converge (no surface near, a non-finite value, or a vanishing
/// gradient on the way), [`Error::SingularPoint`] when `point` itself is a singular point of
/// the surface.
pub fn project_onto<S: ImplicitSurface + ?Sized>(surface: &S, point: Point3) -> Result<Point3> {
    if !point.is_finite() {
        return Err(Error::NonFiniteArgument {
            what: "the point to project",
        });
    }
    let mut p = point;
    let scale = point.max_abs().max(1.0);
    let lost = || Error::NoSurfaceNear {
        point: point.0,
        residual: surface.value(point).abs(),
    };
    for iteration in 0..PROJECTION_ITERATIONS {
        let f = surface.value(p);
        let g = surface.gradient(p);
        let g2 = g.norm_sq();
        if !f.is_finite() || !g2.is_finite() {
            break;
        }
        if g2 <= 1e-300 {
            // At the point itself: a singular point; after moving: no surface found.
            return Err(if iteration == 0 && f == 0.0 {
                Error::SingularPoint { point: p.0 }
            } else {
                lost()
            });
        }
        let step = g * (f / g2);
        p -= step;
        if !p.is_finite() {
            break;
        }
        if step.norm() <= 1e-15 * scale {
            return Ok(p);
        }
    }
    Err(lost())
}

/// The closest point of `F = 0` to `point`: [`project_onto`], then tangential corrections
/// `q <- project(q + (p - q) - n (n . (p - q)))` until the offset `p - q` is normal to the
/// surface at `q` (to `1e-12` of its length, at most 20 rounds). Exact for small offsets
/// relative to the radii of curvature; errors as [`project_onto`].
pub fn closest_point_on<S: ImplicitSurface + ?Sized>(surface: &S, point: Point3) -> Result<Point3> {
    let mut q = project_onto(surface, point)?;
    for _ in 0..20 {
        let g = surface.gradient(q);
        let g2 = g.norm_sq();
        if g2 <= 1e-300 {
            return Err(Error::SingularPoint { point: q.0 });
        }
        let offset = point - q;
        let tangential = offset - g * (g.dot(offset) / g2);
        if tangential.norm() <= 1e-12 * offset.norm().max(1e-300) {
            break;
        }
        q = project_onto(surface, q + tangential)?;
    }
    Ok(q)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::implicit::{Cylinder, Hyperboloid, Sphere};

    #[test]
    fn cylinder_curvatures_are_zero_and_minus_one_over_r() {
        let c = Cylinder { radius: 2.0 };
        let p = Point3::new([2.0f64.sqrt(), 2.0f64.sqrt(), 0.3]);
        let f = SurfaceFrame::at(&c, p).unwrap();
        assert!(f.first_curvature.abs() < 1e-15);
        assert!((f.second_curvature + 0.5).abs() < 1e-15);
        assert!((f.first_direction[2].abs() - 1.0).abs() < 1e-15); // the generator
        assert!(f.second_direction[2].abs() < 1e-15); // the circle
        assert!(!f.is_umbilic());
    }

    #[test]
    fn hyperboloid_has_negative_gaussian_curvature() {
        // x^2 + y^2 - z^2 = a^2: K = -a^2 / (x^2 + y^2 + z^2)^2 (closed form).
        let h = Hyperboloid { neck_radius: 1.0 };
        for z in [0.0f64, 0.5, -1.2] {
            let r = (1.0 + z * z).sqrt();
            let p = Point3::new([r * 0.6, r * 0.8, z]);
            let f = SurfaceFrame::at(&h, p).unwrap();
            let k = -1.0 / (r * r + z * z).powi(2);
            assert!((f.gaussian_curvature() - k).abs() < 1e-14, "z = {z}");
            // The meridian (in the plane through the axis) is a principal direction.
            let azimuth = Point3::new([-0.8, 0.6, 0.0]);
            let d = f
                .first_direction
                .dot(azimuth)
                .abs()
                .min(f.second_direction.dot(azimuth).abs());
            assert!(d < 1e-12);
        }
    }

    /// `|det [alpha; beta; grad F]| / |grad F|`: the condition measure (2.4) of the
    /// continuation system (2.3) for unit `alpha`, `beta`.
    fn condition(alpha: Point3, beta: Point3, g: Point3) -> f64 {
        alpha.dot(cross(beta, g)).abs() / g.norm()
    }

    #[test]
    fn principal_frames_condition_the_continuation_system_best() {
        // Theorem 2.1: the measure reaches its maximum 1 exactly for orthonormal tangent
        // directions; the principal directions are such, turned or skewed pairs are not.
        let h = Hyperboloid { neck_radius: 1.0 };
        let p = Point3::new([1.1, 0.4, (1.1f64 * 1.1 + 0.16 - 1.0).sqrt()]);
        let f = SurfaceFrame::at(&h, p).unwrap();
        let g = h.gradient(p);
        let best = condition(f.first_direction, f.second_direction, g);
        assert!((best - 1.0).abs() < 1e-14);
        let turned = (
            f.turn(f.first_direction, 0.5),
            f.turn(f.second_direction, 0.5),
        );
        assert!((condition(turned.0, turned.1, g) - 1.0).abs() < 1e-14);
        let skewed = f.turn(f.second_direction, 30f64.to_radians());
        assert!((condition(f.first_direction, skewed, g) - 30f64.to_radians().cos()).abs() < 1e-14);
        let lifted = (f.first_direction * 0.8 + f.normal * 0.6, f.second_direction);
        assert!(condition(lifted.0, lifted.1, g) < 0.81);
    }

    #[test]
    fn sphere_is_umbilic_and_projection_finds_it() {
        let s = Sphere { radius: 3.0 };
        let f = SurfaceFrame::at(&s, Point3::new([0.0, 3.0, 0.0])).unwrap();
        assert!(f.is_umbilic());
        assert!((f.mean_curvature() + 1.0 / 3.0).abs() < 1e-15);
        let p = project_onto(&s, Point3::new([1.0, 2.0, 2.5])).unwrap();
        assert!((p.norm() - 3.0).abs() < 1e-14);
        // The foot lies on the line through the centre (the sphere's normal line).
        let dir = Point3::new([1.0, 2.0, 2.5]) * (1.0 / 11.25f64.sqrt());
        assert!(p.distance(dir * 3.0) < 1e-14);
        // On a hyperboloid the gradient path is not normal; the closest point is.
        let h = Hyperboloid { neck_radius: 1.0 };
        let far = Point3::new([1.3, 0.2, 0.9]);
        let q = closest_point_on(&h, far).unwrap();
        let n = h.gradient(q);
        assert!(cross(n, far - q).norm() < 1e-12 * n.norm());
        assert!(matches!(
            SurfaceFrame::at(&s, Point3::ZERO),
            Err(Error::SingularPoint { .. })
        ));
    }
}

//! The implicit-surface trait and the built-in shapes.

use crate::Point3;

/// A symmetric 3 x 3 matrix (a Hessian), rows in order x, y, z.
pub type Matrix3 = [[f64; 3]; 3];

/// A surface `F(x, y, z) = 0` given by a twice differentiable function `F`.
///
/// Every method must be exact (closed form, symbolic or automatic differentiation), not a
/// finite difference: curvatures are second derivatives and would lose half their digits.
pub trait ImplicitSurface {
    /// `F(p)`.
    fn value(&self, p: Point3) -> f64;

    /// `grad F(p) = (F_x, F_y, F_z)`.
    fn gradient(&self, p: Point3) -> Point3;

    /// The Hessian of `F` at `p`.
    fn hessian(&self, p: Point3) -> Matrix3;
}

/// The circular cylinder `x^2 + y^2 - R^2 = 0` around the z axis.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Cylinder {
    /// The radius `R`.
    pub radius: f64,
}

/// The one-sheet hyperboloid of revolution `x^2 + y^2 - z^2 - a^2 = 0` around the z axis
/// (the neck circle has radius `a`).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hyperboloid {
    /// The radius `a` of the neck circle.
    pub neck_radius: f64,
}

/// The sphere `x^2 + y^2 + z^2 - R^2 = 0` around the origin. Every point is an umbilic.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Sphere {
    /// The radius `R`.
    pub radius: f64,
}

/// `x^2 + y^2 + s z^2 - c` with its derivatives: the three built-in quadrics.
fn quadric_value(p: Point3, s: f64, c: f64) -> f64 {
    p[0] * p[0] + p[1] * p[1] + s * p[2] * p[2] - c
}

fn quadric_hessian(s: f64) -> Matrix3 {
    [[2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0 * s]]
}

impl ImplicitSurface for Cylinder {
    fn value(&self, p: Point3) -> f64 {
        quadric_value(p, 0.0, self.radius * self.radius)
    }

    fn gradient(&self, p: Point3) -> Point3 {
        Point3::new([2.0 * p[0], 2.0 * p[1], 0.0])
    }

    fn hessian(&self, _: Point3) -> Matrix3 {
        quadric_hessian(0.0)
    }
}

impl ImplicitSurface for Hyperboloid {
    fn value(&self, p: Point3) -> f64 {
        quadric_value(p, -1.0, self.neck_radius * self.neck_radius)
    }

    fn gradient(&self, p: Point3) -> Point3 {
        Point3::new([2.0 * p[0], 2.0 * p[1], -2.0 * p[2]])
    }

    fn hessian(&self, _: Point3) -> Matrix3 {
        quadric_hessian(-1.0)
    }
}

impl ImplicitSurface for Sphere {
    fn value(&self, p: Point3) -> f64 {
        quadric_value(p, 1.0, self.radius * self.radius)
    }

    fn gradient(&self, p: Point3) -> Point3 {
        p * 2.0
    }

    fn hessian(&self, _: Point3) -> Matrix3 {
        quadric_hessian(1.0)
    }
}

impl<S: ImplicitSurface + ?Sized> ImplicitSurface for &S {
    fn value(&self, p: Point3) -> f64 {
        (**self).value(p)
    }

    fn gradient(&self, p: Point3) -> Point3 {
        (**self).gradient(p)
    }

    fn hessian(&self, p: Point3) -> Matrix3 {
        (**self).hessian(p)
    }
}

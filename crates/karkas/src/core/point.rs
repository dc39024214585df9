//! Points and vectors of fixed dimension `D`.
//!
//! One type serves as both point and displacement: every method of karkas forms affine
//! combinations (weights summing to 1) of input points, and the difference of two points is a
//! vector of the same layout. `Point<D>` is `#[repr(transparent)]` over `[f64; D]`, so a slice of
//! points is a flat, cache-friendly array of `D * n` numbers.
//!
//! Hand-written rather than taken from a linear-algebra crate: the methods need only a handful
//! of element-wise operations on tiny fixed-size arrays, and a plain array keeps the hot loops
//! free of generic bounds.

use core::ops::{Add, AddAssign, Index, IndexMut, Mul, MulAssign, Neg, Sub, SubAssign};

/// A point (or vector) in R^D, stored as `[f64; D]`.
///
/// `Pod` and `Zeroable` let a flat `&[f64]` of `D * n` numbers be viewed as `&[Point<D>]`
/// (and back) without copying, e.g. `bytemuck::cast_slice`.
#[derive(Clone, Copy, Debug, PartialEq, bytemuck::Pod, bytemuck::Zeroable)]
#[repr(transparent)]
pub struct Point<const D: usize>(pub [f64; D]);

/// A point in the plane.
pub type Point2 = Point<2>;
/// A point in space.
pub type Point3 = Point<3>;

impl<const D: usize> Default for Point<D> {
    fn default() -> Self {
        Self::ZERO
    }
}

impl<const D: usize> Point<D> {
    /// The origin (the zero vector).
    pub const ZERO: Self = Point([0.0; D]);

    /// Wraps coordinates.
    #[inline]
    ///
    /// ```
    /// use karkas::Point;
    ///
    /// let p = Point::new([3.0, 4.0]);
    /// assert_eq!(p, Point([3.0, 4.0]));
    /// assert_eq!(p.norm(), 5.0);
    /// ```
    pub const fn new(coords: [f64; D]) -> Self {
        Point(coords)
    }

    /// The coordinates as an array.
    #[inline]
    pub const fn coords(&self) -> &[f64; D] {
        &self.0
    }

    /// Scalar product with `other`.
    #[inline]
    pub fn dot(self, other: Self) -> f64 {
        let mut s = 0.0;
        for k in 0..D {
            s += self.0[k] * other.0[k];
        }
        s
    }

    /// Squared Euclidean length.
    #[inline]
    pub fn norm_sq(self) -> f64 {
        self.dot(self)
    }

    /// Euclidean length.
    #[inline]
    pub fn norm(self) -> f64 {
        self.norm_sq().sqrt()
    }

    /// The angle between `self` and `other` as vectors, in `[0, pi]` (0 when either is zero):
    /// `atan2(|a x b|, a . b)`, accurate near 0 and pi, on the vectors divided by their
    /// largest coordinate so that lengths near 1e150 or 1e-150 neither overflow nor underflow.
    pub fn angle_to(self, other: Self) -> f64 {
        let unit = |v: Self| {
            let largest = v.0.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            if largest > 0.0 {
                v * (1.0 / largest)
            } else {
                v
            }
        };
        let (a, b) = (unit(self), unit(other));
        let dot = a.dot(b);
        let cross = if D == 2 {
            (a[0] * b[1] - a[1] * b[0]).abs()
        } else {
            (a.norm_sq() * b.norm_sq() - dot * dot).max(0.0).sqrt()
        };
        if cross == 0.0 && dot == 0.0 {
            0.0
        } else {
            cross.atan2(dot)
        }
    }

    /// Squared distance to `other`.
    #[inline]
    pub fn distance_sq(self, other: Self) -> f64 {
        (self - other).norm_sq()
    }

    /// Distance to `other`.
    #[inline]
    pub fn distance(self, other: Self) -> f64 {
        (self - other).norm()
    }

    /// Largest absolute coordinate (the max norm).
    #[inline]
    pub fn max_abs(self) -> f64 {
        self.0.iter().fold(0.0, |m, c| m.max(c.abs()))
    }

    /// True when every coordinate is finite (neither NaN nor infinite).
    #[inline]
    pub fn is_finite(self) -> bool {
        self.0.iter().all(|c| c.is_finite())
    }

    /// `self + s * v`, the fused update used in every weighted sum.
    #[inline]
    pub fn add_scaled(self, s: f64, v: Self) -> Self {
        let mut out = self;
        for k in 0..D {
            out.0[k] += s * v.0[k];
        }
        out
    }

    /// Linear interpolation `(1 - s) self + s other`.
    #[inline]
    pub fn lerp(self, other: Self, s: f64) -> Self {
        self.add_scaled(s, other - self)
    }
}

impl Point<3> {
    /// The cross product `self x other`.
    #[inline]
    pub fn cross(self, other: Self) -> Self {
        let (a, b) = (self.0, other.0);
        Point([
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ])
    }
}

impl<const D: usize> From<[f64; D]> for Point<D> {
    fn from(c: [f64; D]) -> Self {
        Point(c)
    }
}

impl<const D: usize> Index<usize> for Point<D> {
    type Output = f64;
    #[inline]
    fn index(&self, k: usize) -> &f64 {
        &self.0[k]
    }
}

impl<const D: usize> IndexMut<usize> for Point<D> {
    #[inline]
    fn index_mut(&mut self, k: usize) -> &mut f64 {
        &mut self.0[k]
    }
}

macro_rules! elementwise {
    ($tr:ident, $f:ident, $tra:ident, $fa:ident, $op_assign:tt) => {
        impl<const D: usize> $tra for Point<D> {
            #[inline]
            fn $fa(&mut self, rhs: Self) {
                for (a, b) in self.0.iter_mut().zip(rhs.0) {
                    *a $op_assign b;
                }
            }
        }
        impl<const D: usize> $tr for Point<D> {
            type Output = Self;
            #[inline]
            fn $f(mut self, rhs: Self) -> Self {
                self $op_assign rhs;
                self
            }
        }
    };
}
elementwise!(Add, add, AddAssign, add_assign, +=);
elementwise!(Sub, sub, SubAssign, sub_assign, -=);

impl<const D: usize> Mul<f64> for Point<D> {
    type Output = Self;
    #[inline]
    fn mul(mut self, s: f64) -> Self {
        for c in &mut self.0 {
            *c *= s;
        }
        self
    }
}

impl<const D: usize> Mul<Point<D>> for f64 {
    type Output = Point<D>;
    #[inline]
    fn mul(self, p: Point<D>) -> Point<D> {
        p * self
    }
}

impl<const D: usize> MulAssign<f64> for Point<D> {
    #[inline]
    fn mul_assign(&mut self, s: f64) {
        *self = *self * s;
    }
}

impl<const D: usize> Neg for Point<D> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        self * -1.0
    }
}

#[cfg(test)]
mod tests {

    #[test]
    fn angles_between_vectors_hold_at_every_scale() {
        use std::f64::consts::FRAC_PI_4;
        for scale in [1e-160, 1.0, 1e160] {
            let a = Point([1.0, 0.0, 0.0]) * scale;
            let b = Point([1.0, 1.0, 0.0]) * scale;
            assert!((a.angle_to(b) - FRAC_PI_4).abs() < 1e-15, "{scale}");
            assert!((a.angle_to(a * -1.0) - std::f64::consts::PI).abs() < 1e-15);
            let c = Point([3.0, 4.0]) * scale;
            let d = Point([-4.0, 3.0]) * scale;
            assert!((c.angle_to(d) - 2.0 * FRAC_PI_4).abs() < 1e-15, "{scale}");
        }
        assert_eq!(Point([0.0, 0.0]).angle_to(Point([1.0, 0.0])), 0.0);
        // Nearly parallel: the angle, not a rounding of acos near 1.
        let tiny = Point([1.0, 1e-12]).angle_to(Point([1.0, 0.0]));
        assert!((tiny - 1e-12).abs() < 1e-24);
    }

    use super::*;

    #[test]
    fn arithmetic_is_elementwise() {
        let a = Point([1.0, 2.0, 3.0]);
        let b = Point([4.0, -1.0, 0.5]);
        assert_eq!(a + b, Point([5.0, 1.0, 3.5]));
        assert_eq!(a - b, Point([-3.0, 3.0, 2.5]));
        assert_eq!(2.0 * a, Point([2.0, 4.0, 6.0]));
        assert_eq!(-a, Point([-1.0, -2.0, -3.0]));
        assert_eq!(a.dot(b), 4.0 - 2.0 + 1.5);
        assert_eq!(a.add_scaled(2.0, b), Point([9.0, 0.0, 4.0]));
        assert_eq!(a.lerp(b, 0.5), Point([2.5, 0.5, 1.75]));
        assert_eq!(
            Point([1.0, 0.0, 0.0]).cross(Point([0.0, 1.0, 0.0])),
            Point([0.0, 0.0, 1.0])
        );
        assert_eq!(a.cross(b).dot(a), 0.0);
        assert_eq!(Point([3.0, 4.0]).norm(), 5.0);
        assert_eq!(Point([3.0, -7.0]).max_abs(), 7.0);
        assert!(!Point([1.0, f64::NAN]).is_finite());
    }
}

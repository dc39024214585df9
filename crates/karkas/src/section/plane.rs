//! Planes and other level functions whose zero set cuts a surface.

use crate::{Error, Point, Result};

/// A scalar function of a point whose zero set cuts a surface: the section is the curve where
/// `value(P(u, v)) = 0`.
///
/// The continuation needs the gradient; the value should be a signed distance (or close to
/// one), so that the tolerances, which are lengths, mean the same for every function.
pub trait LevelFunction<const D: usize> {
    /// The function's value at `p`.
    fn value(&self, p: Point<D>) -> f64;

    /// Its gradient at `p`.
    fn gradient(&self, p: Point<D>) -> Point<D>;

    /// Bounds `(lowest, highest)` of the function over the box `lo <= p <= hi`, if known:
    /// regions of the surface whose bounding box cannot hold a zero are then skipped. `None`
    /// (the default) when not known.
    fn range_over_box(&self, lo: Point<D>, hi: Point<D>) -> Option<(f64, f64)> {
        let _ = (lo, hi);
        None
    }
}

/// The (hyper)plane `n . p = c` in R^D, stored with a unit normal so that
/// [`value`](LevelFunction::value) is the signed distance from the plane.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane<const D: usize> {
    normal: Point<D>,
    offset: f64,
}

impl<const D: usize> Plane<D> {
    /// The plane `normal . p = offset`; `normal` need not be of unit length (the plane is
    /// stored normalized: `normal / |normal|`, `offset / |normal|`).
    ///
    /// Errors: [`Error::InvalidPlane`] for a zero or non-finite normal or a non-finite offset.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::section::Plane;
    /// use karkas::Point;
    ///
    /// let plane = Plane::new(Point([0.0, 0.0, 2.0]), 4.0)?; // 2 z = 4, stored as z = 2
    /// assert_eq!((plane.normal(), plane.offset()), (Point([0.0, 0.0, 1.0]), 2.0));
    /// assert!(Plane::new(Point([0.0; 3]), 1.0).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(normal: Point<D>, offset: f64) -> Result<Self> {
        if !normal.is_finite() || !offset.is_finite() {
            return Err(Error::InvalidPlane {
                reason: "the normal and the offset must be finite",
            });
        }
        let length = normal.norm();
        if !length.is_finite() || length <= 0.0 {
            return Err(Error::InvalidPlane {
                reason: "the normal must not be zero",
            });
        }
        Ok(Plane {
            normal: Point(normal.0.map(|c| c / length)),
            offset: offset / length,
        })
    }

    /// The plane `p[axis] = value`: the isoline of one coordinate (`axis = 0` for `x = value`).
    ///
    /// Errors: [`Error::InvalidPlane`] for `axis >= D` or a non-finite value.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::section::Plane;
    /// use karkas::Point;
    ///
    /// let plane = Plane::<3>::coordinate(0, 1.5)?; // x = 1.5
    /// assert_eq!((plane.normal(), plane.offset()), (Point([1.0, 0.0, 0.0]), 1.5));
    /// assert!(Plane::<3>::coordinate(3, 1.5).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn coordinate(axis: usize, value: f64) -> Result<Self> {
        if axis >= D {
            return Err(Error::InvalidPlane {
                reason: "the coordinate index is beyond the dimension",
            });
        }
        let mut normal = Point::ZERO;
        normal[axis] = 1.0;
        Plane::new(normal, value)
    }

    /// The unit normal.
    pub fn normal(&self) -> Point<D> {
        self.normal
    }

    /// The offset `c` of `normal . p = c` (with the unit normal).
    pub fn offset(&self) -> f64 {
        self.offset
    }
}

impl<const D: usize> LevelFunction<D> for Plane<D> {
    #[inline]
    fn value(&self, p: Point<D>) -> f64 {
        self.normal.dot(p) - self.offset
    }

    #[inline]
    fn gradient(&self, _p: Point<D>) -> Point<D> {
        self.normal
    }

    /// Exact: the value at the centre plus or minus `sum |n_k| h_k` (the half-sizes `h`).
    fn range_over_box(&self, lo: Point<D>, hi: Point<D>) -> Option<(f64, f64)> {
        let centre = lo.lerp(hi, 0.5);
        let reach: f64 = (0..D)
            .map(|k| self.normal[k].abs() * 0.5 * (hi[k] - lo[k]))
            .sum();
        let value = self.value(centre);
        Some((value - reach, value + reach))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn planes_are_normalized_and_checked() {
        let p = Plane::new(Point([0.0, 3.0, 4.0]), 10.0).unwrap();
        assert_eq!(p.normal(), Point([0.0, 0.6, 0.8]));
        assert_eq!(p.offset(), 2.0);
        assert_eq!(p.value(Point([7.0, 0.0, 2.5])), 0.0);
        assert!(Plane::new(Point([0.0, 0.0, 0.0]), 1.0).is_err());
        assert!(Plane::new(Point([f64::NAN, 0.0, 1.0]), 1.0).is_err());
        assert!(Plane::new(Point([1.0, 0.0, 0.0]), f64::INFINITY).is_err());
        assert!(Plane::<3>::coordinate(3, 1.0).is_err());
        assert_eq!(
            Plane::<3>::coordinate(1, -2.0)
                .unwrap()
                .value(Point([5.0, 1.0, 9.0])),
            3.0
        );
        // Over the box [0,1]^3 the plane 3y + 4z = 10 (distance 2 from 0) ranges over the
        // values at the corners (0,0,0) and (1,1,1): -2 and -0.6.
        let (lo, hi) = p
            .range_over_box(Point([0.0, 0.0, 0.0]), Point([1.0, 1.0, 1.0]))
            .unwrap();
        assert!((lo + 2.0).abs() < 1e-15 && (hi + 0.6).abs() < 1e-15);
    }
}

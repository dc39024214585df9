//! Hausdorff distance between finite point sets with a k-d tree.

use crate::{Error, Point3, Result};
use kiddo::immutable::float::kdtree::ImmutableKdTree;
use kiddo::SquaredEuclidean;

/// The larger of the two one-sided distances, and where each is attained.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hausdorff {
    /// `max(forward.distance, backward.distance)`.
    pub distance: f64,
    /// From the first set to the second.
    pub forward: DirectedDistance,
    /// From the second set to the first.
    pub backward: DirectedDistance,
}

impl Hausdorff {
    /// Combines the two directions.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::measure::{DirectedDistance, Hausdorff};
    /// use karkas::Point;
    ///
    /// let origin = Point([0.0; 3]);
    /// let forward = DirectedDistance { distance: 1.0, from: origin, to: Point([1.0, 0.0, 0.0]) };
    /// let backward = DirectedDistance { distance: 2.0, from: Point([0.0, 2.0, 0.0]), to: origin };
    /// let both = Hausdorff::new(forward, backward);
    /// assert_eq!(both.distance, 2.0);
    /// assert_eq!(both.worst().from, Point([0.0, 2.0, 0.0]));
    /// ```
    pub fn new(forward: DirectedDistance, backward: DirectedDistance) -> Self {
        Hausdorff {
            distance: forward.distance.max(backward.distance),
            forward,
            backward,
        }
    }

    /// The direction that attains the distance.
    pub fn worst(&self) -> &DirectedDistance {
        if self.forward.distance >= self.backward.distance {
            &self.forward
        } else {
            &self.backward
        }
    }
}

/// A one-sided distance `max_{P in A} min_{Q in B} |P - Q|` and where it is attained.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct DirectedDistance {
    /// The distance.
    pub distance: f64,
    /// The point of `A` farthest from `B`.
    pub from: Point3,
    /// Its nearest point in `B`.
    pub to: Point3,
}

impl DirectedDistance {
    /// The empty maximum (distance 0, both points at the origin).
    pub const ZERO: Self = DirectedDistance {
        distance: 0.0,
        from: Point3::ZERO,
        to: Point3::ZERO,
    };

    /// Keeps the larger of `self` and the pair `(from, to)`.
    #[inline]
    pub(crate) fn keep_max(&mut self, from: Point3, to: Point3) {
        let d = from.distance(to);
        if d > self.distance {
            *self = DirectedDistance {
                distance: d,
                from,
                to,
            };
        }
    }
}

/// A point set with a k-d tree for nearest-point queries.
pub struct PointCloud {
    points: Vec<Point3>,
    tree: ImmutableKdTree<f64, u64, 3, 32>,
}

impl PointCloud {
    /// Builds the tree, `O(n log n)`.
    ///
    /// Errors: an empty set ([`Error::TooFewPoints`]), a non-finite point
    /// ([`Error::NonFinitePoint`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::measure::PointCloud;
    /// use karkas::Point;
    ///
    /// let cloud = PointCloud::new(&[Point([0.0; 3]), Point([1.0, 0.0, 0.0]), Point([0.0, 5.0, 0.0])])?;
    /// assert_eq!(cloud.nearest(Point([0.9, 0.2, 0.0])), 1);
    /// assert!(PointCloud::new(&[]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(points: &[Point3]) -> Result<Self> {
        if points.is_empty() {
            return Err(Error::TooFewPoints {
                what: "a point set",
                needed: 1,
                got: 0,
            });
        }
        if let Some(index) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::NonFinitePoint { index });
        }
        let coords: Vec<[f64; 3]> = points.iter().map(|p| p.0).collect();
        Ok(PointCloud {
            points: points.to_vec(),
            tree: ImmutableKdTree::new_from_slice(&coords),
        })
    }

    /// The points.
    pub fn points(&self) -> &[Point3] {
        &self.points
    }

    /// The index of the point nearest to `q` (`q` finite).
    pub fn nearest(&self, q: Point3) -> usize {
        let found = self.tree.nearest_one::<SquaredEuclidean>(&q.0);
        // Items are the indices given at construction.
        (found.item as usize).min(self.points.len() - 1)
    }

    /// `max_{P in from} min_{Q in self} |P - Q|` and where it is attained.
    pub fn directed_from(&self, from: &[Point3]) -> DirectedDistance {
        let mut worst = DirectedDistance::ZERO;
        for &p in from {
            worst.keep_max(p, self.points[self.nearest(p)]);
        }
        worst
    }
}

/// The two-sided Hausdorff distance between the point sets `a` and `b` ((3.14)).
///
/// Errors: an empty set, a non-finite point (its index in the set that has it).
pub fn hausdorff_sets(a: &[Point3], b: &[Point3]) -> Result<Hausdorff> {
    let (cloud_a, cloud_b) = (PointCloud::new(a)?, PointCloud::new(b)?);
    Ok(Hausdorff::new(
        cloud_b.directed_from(a),
        cloud_a.directed_from(b),
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The definition, by brute force.
    fn brute(a: &[Point3], b: &[Point3]) -> f64 {
        let directed = |x: &[Point3], y: &[Point3]| {
            x.iter()
                .map(|p| {
                    y.iter()
                        .map(|q| p.distance(*q))
                        .fold(f64::INFINITY, f64::min)
                })
                .fold(0.0, f64::max)
        };
        directed(a, b).max(directed(b, a))
    }

    #[test]
    fn agrees_with_brute_force() {
        let mut state = 0x2545_F491_4F6C_DD1Du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        let a: Vec<Point3> = (0..300)
            .map(|_| Point3::new([next(), next(), next()]))
            .collect();
        let b: Vec<Point3> = (0..200)
            .map(|_| Point3::new([next() * 1.2, next(), next() * 0.8]))
            .collect();
        let h = hausdorff_sets(&a, &b).unwrap();
        assert!((h.distance - brute(&a, &b)).abs() < 1e-15);
        let w = h.worst();
        assert!((w.from.distance(w.to) - h.distance).abs() < 1e-15);
    }

    #[test]
    fn duplicates_and_bad_sets() {
        let a = vec![Point3::new([1.0, 1.0, 1.0]); 100];
        let b = [Point3::ZERO];
        let h = hausdorff_sets(&a, &b).unwrap();
        assert!((h.distance - 3f64.sqrt()).abs() < 1e-15);
        assert!(hausdorff_sets(&a, &[]).is_err());
        let bad = [Point3::new([f64::NAN, 0.0, 0.0])];
        assert!(matches!(
            hausdorff_sets(&a, &bad),
            Err(Error::NonFinitePoint { index: 0 })
        ));
    }
}

//! Normals of triangle meshes and sample grids, computed once for every mesh writer.
//!
//! - A sample grid (`nu x nv` points, row-major, `u` outer) has one normal per sample: the
//!   normalised cross product of the grid differences along `u` and along `v` (central inside,
//!   one-sided at the borders; a zero normal, e.g. at a pole, is `0 0 1`). When the last sample
//!   row (column) coincides with the first, as for a closed surface sampled over its whole
//!   period, the differences wrap around the seam so that both copies of the seam get the same
//!   normal.
//! - A triangle `(a, b, c)` has the unit normal of `(b - a) x (c - a)` (zero when degenerate).
//! - A general mesh without normals gets, per vertex, the area-weighted mean of the normals of
//!   the triangles around it (`0 0 1` for a vertex on no triangle of positive area).
//!
//! Cost: O(1) per sample or triangle; the grid seams are detected once, in O(nu + nv).

use karkas::Point3;

use crate::mesh::triangulate::GridSeams;

/// The cross product `p x q`.
pub(crate) fn cross(p: Point3, q: Point3) -> Point3 {
    Point3::new([
        p[1] * q[2] - p[2] * q[1],
        p[2] * q[0] - p[0] * q[2],
        p[0] * q[1] - p[1] * q[0],
    ])
}

/// `n` scaled to unit length, or `fallback` when its length is zero or not finite.
fn unit_or(n: Point3, fallback: Point3) -> Point3 {
    let len = n.norm();
    if len > 0.0 && len.is_finite() {
        n * (1.0 / len)
    } else {
        fallback
    }
}

/// The unit normal of the triangle `corners` (`(b - a) x (c - a)` normalised), zero when it is
/// degenerate.
pub(crate) fn triangle_normal(corners: [Point3; 3]) -> Point3 {
    let [a, b, c] = corners;
    unit_or(cross(b - a, c - a), Point3::ZERO)
}

/// Per-vertex normals of the triangles `triangles` over `positions`: the area-weighted mean of
/// the normals of the triangles around each vertex, `0 0 1` where there is none. Triangles with
/// an index out of range are skipped.
pub(crate) fn averaged_normals(positions: &[Point3], triangles: &[[u32; 3]]) -> Vec<Point3> {
    let mut sums = vec![Point3::ZERO; positions.len()];
    for t in triangles {
        let at = |k: u32| positions.get(k as usize).copied();
        if let (Some(a), Some(b), Some(c)) = (at(t[0]), at(t[1]), at(t[2])) {
            let n = cross(b - a, c - a); // length = twice the area
            for &k in t {
                sums[k as usize] += n;
            }
        }
    }
    sums.into_iter()
        .map(|n| unit_or(n, Point3::new([0.0, 0.0, 1.0])))
        .collect()
}

/// The unit normals of every sample of the `nu x nv` grid `points` (`points.len() == nu nv`),
/// row-major, produced on demand (see the module docs).
pub(crate) fn grid_normals(
    nu: usize,
    nv: usize,
    points: &[Point3],
) -> impl Iterator<Item = Point3> + '_ {
    let grid = SampleGrid::new(nu, nv, points);
    (0..nu)
        .flat_map(move |a| (0..nv).map(move |b| (a, b)))
        .map(move |(a, b)| grid.normal(a, b))
}

/// A row-major grid of samples, for normals.
#[derive(Clone, Copy)]
struct SampleGrid<'a> {
    nu: usize,
    nv: usize,
    points: &'a [Point3],
    /// The last row coincides with the first.
    closed_u: bool,
    /// The last column coincides with the first.
    closed_v: bool,
}

impl<'a> SampleGrid<'a> {
    /// The grid of `nu x nv` `points` (`points.len() == nu * nv`), its seams detected
    /// ([`GridSeams::detect`]).
    fn new(nu: usize, nv: usize, points: &'a [Point3]) -> Self {
        let GridSeams {
            closed_u, closed_v, ..
        } = GridSeams::detect(nu, nv, points);
        SampleGrid {
            nu,
            nv,
            points,
            closed_u,
            closed_v,
        }
    }

    fn at(&self, a: usize, b: usize) -> Point3 {
        self.points[a * self.nv + b]
    }

    /// The unit normal at sample `(a, b)`: `d/du x d/dv`, or `0 0 1` when that vanishes.
    fn normal(&self, a: usize, b: usize) -> Point3 {
        let du = difference(a, self.nu, self.closed_u, |k| self.at(k, b));
        let dv = difference(b, self.nv, self.closed_v, |k| self.at(a, k));
        unit_or(cross(du, dv), Point3::new([0.0, 0.0, 1.0]))
    }
}

/// The difference of `line` across index `k` of `0..n`: central inside, one-sided at the ends
/// of an open line, wrapping over the seam (`0 == n - 1`) of a closed one.
fn difference(k: usize, n: usize, closed: bool, line: impl Fn(usize) -> Point3) -> Point3 {
    if n < 2 {
        return Point3::ZERO;
    }
    let last = n - 1;
    let (before, after) = match (k, closed) {
        (0, true) => (last - 1, 1),
        (k, true) if k == last => (last - 1, 1),
        (0, false) => (0, 1),
        (k, false) if k == last => (last - 1, last),
        (k, _) => (k - 1, k + 1),
    };
    line(after) - line(before)
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Point;

    #[test]
    fn differences_at_borders_and_seams() {
        let line = |k: usize| Point([k as f64, 0.0, 0.0]);
        assert_eq!(difference(0, 4, false, line)[0], 1.0);
        assert_eq!(difference(3, 4, false, line)[0], 1.0);
        assert_eq!(difference(1, 4, false, line)[0], 2.0);
        assert_eq!(difference(0, 4, true, line)[0], -1.0);
        assert_eq!(difference(0, 1, false, line), Point::ZERO);
    }

    #[test]
    fn cylinder_seam_normals_agree() {
        // A cylinder around z sampled over the full turn: first and last columns coincide.
        let (nu, nv) = (3, 9);
        let pts: Vec<Point3> = (0..nu)
            .flat_map(|a| {
                (0..nv).map(move |b| {
                    let phi = std::f64::consts::TAU * b as f64 / (nv - 1) as f64;
                    let phi = if b == nv - 1 { 0.0 } else { phi };
                    Point([phi.cos(), phi.sin(), a as f64])
                })
            })
            .collect();
        let grid = SampleGrid::new(nu, nv, &pts);
        let (n0, n1) = (grid.normal(1, 0), grid.normal(1, nv - 1));
        assert!(n0.distance(n1) < 1e-12);
        // Radial (up to sign): no z component, unit length, parallel to the point.
        assert!(n0[2].abs() < 1e-12 && (n0.norm() - 1.0).abs() < 1e-12);
        assert!((n0[0].abs() - 1.0).abs() < 1e-12);
    }
}

//! IGES planes (entity 108) under trimmed surfaces (144), as flat patches.
//!
//! IGES gives a plane no parameterization: `A x + B y + C z = D` in the entity's own space,
//! carried to model space by its transformation. A trimmed surface on it is bounded by the
//! model-space curves of its loops (as Open CASCADE writes it: entity 142 with no
//! parameter-space curve). karkas needs a parametric surface under every face, so the plane
//! becomes the bilinear patch over the loops' extent, widened by a hundredth of it on every
//! side: `r(s, t) = o + s e1 + t e2` with `o` the model-space image of the point of the
//! plane nearest the entity's origin and `(e1, e2)` an orthonormal frame with `e1 x e2`
//! along `(A, B, C)`, so that the face's normal is the plane's (the side Open CASCADE
//! writes outward). Its parameters are lengths in the plane; its loops are found on it by
//! projection, as for every face bounded in model space.

use karkas::bspline::NurbsSurface;
use karkas::shape::EdgeLoop;
use karkas::{Grid, Point3};

/// The share of the loops' extent the patch reaches beyond them on every side.
const MARGIN: f64 = 1e-2;

/// A plane in model space: a point and an orthonormal frame of its directions.
#[derive(Clone, Copy, Debug)]
pub(super) struct PlaneFrame {
    origin: Point3,
    e1: Point3,
    e2: Point3,
}

impl PlaneFrame {
    /// The plane `A x + B y + C z = D` of `coefficients` in an entity's own space, carried to
    /// model space by `map`; `None` when `(A, B, C)` is zero or not finite, or `map` flattens
    /// the plane.
    pub(super) fn new(coefficients: [f64; 4], map: impl Fn(Point3) -> Point3) -> Option<Self> {
        let [a, b, c, d] = coefficients;
        let normal = Point3::new([a, b, c]);
        let length = normal.norm();
        if !(length > 0.0 && length.is_finite() && d.is_finite()) {
            return None;
        }
        let n = normal * (1.0 / length);
        // The coordinate axis least along n, made perpendicular to it: u, and v = n x u, so
        // that u x v = n.
        let axis = (0..3)
            .min_by(|&i, &j| n[i].abs().total_cmp(&n[j].abs()))
            .unwrap_or(0);
        let mut helper = Point3::ZERO;
        helper[axis] = 1.0;
        let u = unit(helper - n * helper.dot(n))?;
        let v = n.cross(u);
        let local = n * (d / length);
        let origin = map(local);
        let e1 = unit(map(local + u) - origin)?;
        let along = map(local + v) - origin;
        let e2 = unit(along - e1 * along.dot(e1))?;
        Some(PlaneFrame { origin, e1, e2 })
    }

    /// The patch over the control points of `loops`' edges (a B-spline lies in the hull of
    /// its control points), widened by [`MARGIN`] of their extent; `None` when the loops
    /// have no extent in the plane.
    pub(super) fn patch_over(&self, loops: &[EdgeLoop]) -> Option<NurbsSurface<3>> {
        let mut lo = [f64::INFINITY; 2];
        let mut hi = [f64::NEG_INFINITY; 2];
        let points = loops
            .iter()
            .flat_map(|l| &l.edges)
            .flat_map(|e| e.curve.control_points());
        for &q in points {
            let d = q - self.origin;
            for (k, c) in [d.dot(self.e1), d.dot(self.e2)].into_iter().enumerate() {
                lo[k] = lo[k].min(c);
                hi[k] = hi[k].max(c);
            }
        }
        let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
        if !(extent > 0.0 && extent.is_finite()) {
            return None;
        }
        let pad = MARGIN * extent;
        self.patch([lo[0] - pad, hi[0] + pad], [lo[1] - pad, hi[1] + pad])
    }

    /// The bilinear patch `o + s e1 + t e2` over `s` in `[s0, s1]`, `t` in `[t0, t1]`.
    fn patch(&self, [s0, s1]: [f64; 2], [t0, t1]: [f64; 2]) -> Option<NurbsSurface<3>> {
        let at = |s: f64, t: f64| self.origin + self.e1 * s + self.e2 * t;
        let corners = vec![at(s0, t0), at(s0, t1), at(s1, t0), at(s1, t1)];
        let control = Grid::from_row_major(2, 2, corners).ok()?;
        let weights = Grid::from_row_major(2, 2, vec![1.0; 4]).ok()?;
        NurbsSurface::new(
            (1, vec![s0, s0, s1, s1]),
            (1, vec![t0, t0, t1, t1]),
            control,
            weights,
        )
        .ok()
    }
}

/// `d` over its length; `None` when that is 0 or not finite.
fn unit(d: Point3) -> Option<Point3> {
    let length = d.norm();
    (length > 0.0 && length.is_finite()).then(|| d * (1.0 / length))
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::shape::Edge;
    use karkas::Surface;

    fn square_loop(z: f64) -> EdgeLoop {
        let corners = [[1.0, 2.0], [4.0, 2.0], [4.0, 7.0], [1.0, 7.0], [1.0, 2.0]];
        let points: Vec<Point3> = corners
            .iter()
            .map(|c| Point3::new([c[0], c[1], z]))
            .collect();
        let curve = karkas::bspline::NurbsCurve::new(
            1,
            vec![0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 4.0],
            points,
            vec![1.0; 5],
        )
        .unwrap();
        EdgeLoop {
            edges: vec![Edge {
                curve,
                forward: true,
            }],
            outer: true,
            parameter_curves: Vec::new(),
        }
    }

    #[test]
    fn the_patch_lies_in_the_plane_covers_the_loop_and_faces_along_its_normal() {
        // z = 5 with the normal -z (A, B, C) = (0, 0, -2), moved by (10, 0, 0).
        let moved = |q: Point3| q + Point3::new([10.0, 0.0, 0.0]);
        let frame = PlaneFrame::new([0.0, 0.0, -2.0, -10.0], moved).unwrap();
        let shifted = EdgeLoop {
            edges: square_loop(5.0)
                .edges
                .into_iter()
                .map(|e| Edge {
                    curve: e.curve.map_points(moved),
                    forward: true,
                })
                .collect(),
            ..square_loop(5.0)
        };
        let patch = frame.patch_over(&[shifted]).unwrap();
        let (du, dv) = (patch.domain_u(), patch.domain_v());
        let mut xs = Vec::new();
        for i in 0..=4 {
            for j in 0..=4 {
                let (u, v) = (du.uniform(i, 5), dv.uniform(j, 5));
                let q = patch.eval(u, v);
                assert!((q[2] - 5.0).abs() < 1e-12, "{q:?}");
                let n = patch.deriv(u, v, 1, 0).cross(patch.deriv(u, v, 0, 1));
                assert!(n[2] < 0.0 && n[0].abs() + n[1].abs() < 1e-12, "{n:?}");
                xs.push((q[0], q[1]));
            }
        }
        // The loop spans x in [11, 14], y in [2, 7]; the patch reaches 1% of 5 beyond it.
        let (min_x, max_x) = xs
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.0), b.max(p.0)));
        let (min_y, max_y) = xs
            .iter()
            .fold((f64::MAX, f64::MIN), |(a, b), p| (a.min(p.1), b.max(p.1)));
        assert!(
            (min_x - 10.95).abs() < 1e-12 && (max_x - 14.05).abs() < 1e-12,
            "{min_x} {max_x}"
        );
        assert!(
            (min_y - 1.95).abs() < 1e-12 && (max_y - 7.05).abs() < 1e-12,
            "{min_y} {max_y}"
        );
    }

    #[test]
    fn a_plane_without_a_normal_or_loops_without_extent_give_none() {
        assert!(PlaneFrame::new([0.0, 0.0, 0.0, 1.0], |q| q).is_none());
        assert!(PlaneFrame::new([f64::NAN, 0.0, 1.0, 1.0], |q| q).is_none());
        let frame = PlaneFrame::new([0.0, 0.0, 1.0, 0.0], |q| q).unwrap();
        assert!(frame.patch_over(&[]).is_none());
    }
}

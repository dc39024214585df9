//! Hausdorff distance between a parametric surface and a patch of an implicit surface.

use super::sets::{DirectedDistance, Hausdorff, PointCloud};
use crate::core::{Interval, Surface};
use crate::implicit::{closest_point_on, project_onto, ImplicitSurface};
use crate::{Error, Point3, Result};

/// Newton iterations of a closest-point search on a parametric surface.
const FOOT_ITERATIONS: usize = 30;

/// The closest point of a parametric surface to a given point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ClosestPoint {
    /// Its parameter `u`.
    pub u: f64,
    /// Its parameter `v`.
    pub v: f64,
    /// The point `W(u, v)`.
    pub point: Point3,
    /// Its distance to the given point.
    pub distance: f64,
}

impl ClosestPoint {
    /// The closest point of `surface` to `q`, by Newton's method on `|W(u, v) - q|^2` from
    /// `(u0, v0)` (Gauss–Newton where the Hessian is not positive definite, steps halved until
    /// the distance decreases). Parameters stay in the domain: clamped in an open direction,
    /// wrapped in a closed one. A local search: start it from a nearby sample.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineSurface;
    /// use karkas::measure::ClosestPoint;
    /// use karkas::{Grid, Point};
    ///
    /// // The unit square of the plane z = 0, parameterized by (x, y).
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let square = BSplineSurface::new(linear.clone(), linear, control)?;
    /// let foot = ClosestPoint::search(&square, Point([0.3, 0.4, 1.0]), (0.5, 0.5));
    /// assert!((foot.distance - 1.0).abs() < 1e-9);
    /// assert!((foot.u - 0.3).abs() < 1e-6 && (foot.v - 0.4).abs() < 1e-6); // a local search
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn search<S: Surface<3> + ?Sized>(surface: &S, q: Point3, (u0, v0): (f64, f64)) -> Self {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let keep = |t: f64, d: Interval, closed: bool| if closed { d.wrap(t) } else { d.clamp(t) };
        let (mut u, mut v) = (u0, v0);
        let mut p = surface.eval(u, v);
        let mut dist2 = p.distance_sq(q);
        for _ in 0..FOOT_ITERATIONS {
            let r = p - q;
            let su = surface.deriv(u, v, 1, 0);
            let sv = surface.deriv(u, v, 0, 1);
            let (suu, suv, svv) = (
                surface.deriv(u, v, 2, 0),
                surface.deriv(u, v, 1, 1),
                surface.deriv(u, v, 0, 2),
            );
            let g = [su.dot(r), sv.dot(r)];
            let gauss = [su.dot(su), su.dot(sv), sv.dot(sv)];
            let full = [
                gauss[0] + suu.dot(r),
                gauss[1] + suv.dot(r),
                gauss[2] + svv.dot(r),
            ];
            let solve = |h: [f64; 3]| {
                let det = h[0] * h[2] - h[1] * h[1];
                (det > 0.0 && h[0] > 0.0).then(|| {
                    (
                        -(h[2] * g[0] - h[1] * g[1]) / det,
                        -(h[0] * g[1] - h[1] * g[0]) / det,
                    )
                })
            };
            let Some((mut step_u, mut step_v)) = solve(full).or_else(|| solve(gauss)) else {
                break;
            };
            let mut improved = false;
            for _ in 0..8 {
                let (nu, nv) = (
                    keep(u + step_u, du, surface.is_closed_u()),
                    keep(v + step_v, dv, surface.is_closed_v()),
                );
                let np = surface.eval(nu, nv);
                let nd2 = np.distance_sq(q);
                if nd2 < dist2 {
                    (u, v, p, dist2) = (nu, nv, np, nd2);
                    improved = true;
                    break;
                }
                step_u *= 0.5;
                step_v *= 0.5;
            }
            let scale = du.length().abs().max(dv.length().abs()).max(1e-300);
            if !improved || step_u.abs().max(step_v.abs()) <= 1e-14 * scale {
                break;
            }
        }
        ClosestPoint {
            u,
            v,
            point: p,
            distance: dist2.sqrt(),
        }
    }
}

/// `max_{P in points} dist(P, F = 0)` and where it is attained (each point's closest point
/// on `F = 0`, see [`closest_point_on`]).
///
/// Errors: no points, a non-finite point, or a point from which no surface is found.
pub fn distance_to_implicit<I: ImplicitSurface + ?Sized>(
    points: &[Point3],
    implicit: &I,
) -> Result<DirectedDistance> {
    if points.is_empty() {
        return Err(Error::TooFewPoints {
            what: "a point set",
            needed: 1,
            got: 0,
        });
    }
    let mut worst = DirectedDistance::ZERO;
    for (index, &p) in points.iter().enumerate() {
        if !p.is_finite() {
            return Err(Error::NonFinitePoint { index });
        }
        worst.keep_max(p, closest_point_on(implicit, p)?);
    }
    Ok(worst)
}

/// Lattice steps along the largest side of the points' bounding box at which the patch of
/// `F = 0` is sampled in [`hausdorff_points_implicit`].
const PATCH_LATTICE_STEPS: usize = 64;

/// The two-sided Hausdorff distance between a point set and the patch of `F = 0` it covers
/// (the rule of the command line's `hausdorff FILE --expr` and Python's
/// `hausdorff(a, expr=...)`; Kuznetsov and Filatov's (3.14), docs/methods.md §5).
///
/// Forward (set to surface): [`distance_to_implicit`], exact for each point. Backward
/// (patch to set): the patch is the part of `F = 0` inside the points' axis-aligned bounding
/// box, together with the closest points on `F = 0` of the points themselves. It is sampled
/// by the projections ([`project_onto`]) of the nodes of a lattice over the box, with
/// `PATCH_LATTICE_STEPS` (64) steps `h` along its largest side (at most `h` along the others, a
/// single node across a flat side), from the nodes whose first-order distance `|F| / |grad F|` is at most
/// `2 h`, kept where they fall in the box; each sample's distance to its nearest point of the
/// set is exact, so the backward distance is that of the samples, below the patch's own by at
/// most about `h`.
///
/// Errors: those of [`distance_to_implicit`].
pub fn hausdorff_points_implicit<I: ImplicitSurface + ?Sized>(
    points: &[Point3],
    implicit: &I,
) -> Result<Hausdorff> {
    let forward = distance_to_implicit(points, implicit)?;
    let mut patch: Vec<Point3> = points
        .iter()
        .map(|&p| closest_point_on(implicit, p))
        .collect::<Result<_>>()?;
    patch.extend(patch_samples(points, implicit));
    let backward = PointCloud::new(points)?.directed_from(&patch);
    Ok(Hausdorff::new(forward, backward))
}

/// The samples of `F = 0` inside the bounding box of `points` (finite and not empty): see
/// [`hausdorff_points_implicit`].
fn patch_samples<I: ImplicitSurface + ?Sized>(points: &[Point3], implicit: &I) -> Vec<Point3> {
    let mut lo = points[0];
    let mut hi = points[0];
    for p in points {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let side = hi - lo;
    let largest = side.max_abs();
    if !(largest > 0.0 && largest.is_finite()) {
        return Vec::new();
    }
    let h = largest / PATCH_LATTICE_STEPS as f64;
    // Steps per axis: the side over h, rounded up (0 for a flat side: one node on it).
    let steps: [usize; 3] = std::array::from_fn(|c| {
        let s = (side[c] / h).ceil();
        if s >= 1.0 {
            (s as usize).min(PATCH_LATTICE_STEPS)
        } else {
            0
        }
    });
    let node = |c: usize, k: usize| {
        if steps[c] == 0 {
            0.5 * (lo[c] + hi[c])
        } else {
            lo[c] + side[c] * k as f64 / steps[c] as f64
        }
    };
    let slack = 1e-12 * (largest + lo.max_abs().max(hi.max_abs()));
    let inside = |q: Point3| (0..3).all(|c| q[c] >= lo[c] - slack && q[c] <= hi[c] + slack);
    let mut samples = Vec::new();
    for i in 0..=steps[0] {
        for j in 0..=steps[1] {
            for k in 0..=steps[2] {
                let p = Point3::new([node(0, i), node(1, j), node(2, k)]);
                let (f, g) = (implicit.value(p), implicit.gradient(p).norm());
                let near = f.abs() <= 2.0 * h * g;
                if !near {
                    continue;
                }
                // A node from which no surface is found, or a singular one, gives no sample.
                if let Ok(q) = project_onto(implicit, p) {
                    if inside(q) {
                        samples.push(q);
                    }
                }
            }
        }
    }
    samples
}

/// The two-sided Hausdorff distance between `surface` and the patch of `F = 0` given by the
/// points `patch` (which should lie on `F = 0` and cover the patch densely).
///
/// Forward (surface to implicit): the surface is sampled on a uniform `samples.0 x
/// samples.1` parameter grid (ends included) and each sample's distance to `F = 0` is exact.
/// Backward (patch to surface): each patch point's closest point on the surface is found by
/// [`ClosestPoint::search`] from the nearest sample.
///
/// Errors: fewer than 2 samples a direction ([`Error::InvalidGridSize`]), an empty or
/// non-finite patch, a sample from which no surface `F = 0` is found.
pub fn hausdorff_surface_implicit<S: Surface<3> + ?Sized, I: ImplicitSurface + ?Sized>(
    surface: &S,
    implicit: &I,
    patch: &[Point3],
    samples: (usize, usize),
) -> Result<Hausdorff> {
    let (nu, nv) = samples;
    if nu < 2 || nv < 2 || nu.saturating_mul(nv) > 100_000_000 {
        return Err(Error::InvalidGridSize {
            what: "sample grid",
            rows: nu,
            cols: nv,
            reason: "at least 2 samples in each direction and at most 10^8 in all are needed",
        });
    }
    let mut us = vec![0.0; nu];
    let mut vs = vec![0.0; nv];
    let mut points = vec![Point3::ZERO; nu * nv];
    surface.sample_grid_into(&mut us, &mut vs, &mut points);
    let forward = distance_to_implicit(&points, implicit)?;
    let cloud = PointCloud::new(&points)?;
    let patch_cloud = PointCloud::new(patch)?; // validates the patch
    let mut backward = DirectedDistance::ZERO;
    for &q in patch_cloud.points() {
        let k = cloud.nearest(q);
        let foot = ClosestPoint::search(surface, q, (us[k / nv], vs[k % nv]));
        // The search only moves downhill from the sample, so it never loses it.
        backward.keep_max(q, foot.point);
    }
    Ok(Hausdorff::new(forward, backward))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::implicit::Sphere;
    use crate::Grid;

    /// The unit sphere as an exact parametric surface (longitude u, latitude v).
    struct SpherePatch;

    impl Surface<3> for SpherePatch {
        fn domain_u(&self) -> Interval {
            Interval::new(0.0, 1.0)
        }
        fn domain_v(&self) -> Interval {
            Interval::new(-0.5, 0.5)
        }
        fn is_closed_u(&self) -> bool {
            false
        }
        fn is_closed_v(&self) -> bool {
            false
        }
        fn eval(&self, u: f64, v: f64) -> Point3 {
            Point3::new([u.cos() * v.cos(), u.sin() * v.cos(), v.sin()]) * 1.1
        }
        fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
            // d^k cos = cos(x + k pi/2), d^k sin = sin(x + k pi/2).
            let h = core::f64::consts::FRAC_PI_2;
            let (cu, su) = ((u + ku as f64 * h).cos(), (u + ku as f64 * h).sin());
            let (cv, sv) = ((v + kv as f64 * h).cos(), (v + kv as f64 * h).sin());
            let z = if ku == 0 { sv } else { 0.0 };
            Point3::new([cu * cv, su * cv, z]) * 1.1
        }
    }

    #[test]
    fn a_scaled_patch_is_at_the_scale_difference() {
        // The parametric surface is the sphere of radius 1.1 over a patch; the exact patch is
        // the same patch of the unit sphere, so both directions give 0.1 exactly.
        let exact = Grid::from_fn(30, 30, |i, j| {
            let (u, v) = (i as f64 / 29.0, -0.5 + j as f64 / 29.0);
            Point3::new([u.cos() * v.cos(), u.sin() * v.cos(), v.sin()])
        });
        let h = hausdorff_surface_implicit(
            &SpherePatch,
            &Sphere { radius: 1.0 },
            exact.as_slice(),
            (20, 20),
        )
        .unwrap();
        assert!((h.forward.distance - 0.1).abs() < 1e-12);
        assert!((h.backward.distance - 0.1).abs() < 1e-9);
        // A patch point far outside the parametric patch is seen from the other side.
        let mut wider = exact.into_vec();
        wider.push(Point3::new([-1.0, 0.0, 0.0]));
        let h = hausdorff_surface_implicit(&SpherePatch, &Sphere { radius: 1.0 }, &wider, (20, 20))
            .unwrap();
        assert!(h.backward.distance > 1.0);
        assert_eq!(h.worst().from, Point3::new([-1.0, 0.0, 0.0]));
    }

    #[test]
    fn closest_point_search_converges() {
        let q = Point3::new([0.5, 0.5, 0.2]);
        let foot = ClosestPoint::search(&SpherePatch, q, (0.1, 0.0));
        // The closest point of a sphere lies on the ray from the centre.
        let expected = q * (1.1 / q.norm());
        assert!(foot.point.distance(expected) < 1e-10);
        assert!((foot.distance - (1.1 - q.norm())).abs() < 1e-10);
    }
}

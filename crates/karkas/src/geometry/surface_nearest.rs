//! The point of a surface nearest to a given point, found globally.
//!
//! The surface is sampled on a uniform `nu x nv` grid of parameters whose points go into a
//! k-d tree (the `kiddo` crate). For every cell the largest distance from a point of the cell
//! to its nearest corner is bounded by half the sum of the lengths of its `u` and `v` edges
//! (each measured as a two-chord polyline through the edge's midpoint, with a margin). For a
//! query `q`, the nearest grid point gives an upper bound `d_0`; only cells with a corner
//! within `d_0 + reach` can hold the nearest point. Each of them (nearest first, skipped once
//! it cannot beat the best so far) is refined by Newton's method on `|S(u, v) - q|^2 / 2`
//! from the cell centre (Gauss–Newton where the Hessian is not positive definite, steps
//! halved until the distance decreases), as in the Hausdorff measure (METHODS.md (3.14)).
//!
//! Parameters stay in the domain: clamped in an open direction, wrapped in a closed one.

use kiddo::immutable::float::kdtree::ImmutableKdTree;
use kiddo::SquaredEuclidean;
use rayon::prelude::*;

use crate::core::{Interval, Surface};
use crate::{Error, Point, Result};

/// Newton iterations per candidate cell.
const MAX_STEPS: usize = 40;
/// Step halvings per Newton iteration.
const MAX_HALVINGS: usize = 30;
/// Batches at least this large are projected in parallel.
const PARALLEL_BATCH: usize = 64;
/// Safety factor on the cell reach (edges are measured by two chords only).
const REACH_MARGIN: f64 = 1.25;

/// The point of a surface nearest to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SurfaceNearest<const D: usize> {
    /// The parameter `u` of the foot point.
    pub u: f64,
    /// The parameter `v` of the foot point.
    pub v: f64,
    /// The distance from the query point to the surface.
    pub distance: f64,
    /// The foot point `S(u, v)`.
    pub point: Point<D>,
}

impl<const D: usize> SurfaceNearest<D> {
    /// The result for a query with a NaN or infinite coordinate.
    pub const UNDEFINED: Self = SurfaceNearest {
        u: f64::NAN,
        v: f64::NAN,
        distance: f64::NAN,
        point: Point([f64::NAN; D]),
    };
}

/// A surface prepared for nearest-point queries: a sampled grid in a k-d tree.
///
/// ```
/// use karkas::geometry::SurfaceProjector;
/// use karkas::{Interval, Point3, Surface};
/// struct Plane;
/// impl Surface<3> for Plane {
///     fn domain_u(&self) -> Interval { Interval::new(0.0, 1.0) }
///     fn domain_v(&self) -> Interval { Interval::new(0.0, 1.0) }
///     fn is_closed_u(&self) -> bool { false }
///     fn is_closed_v(&self) -> bool { false }
///     fn eval(&self, u: f64, v: f64) -> Point3 { Point3::new([u, v, 0.0]) }
///     fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
///         match (ku, kv) {
///             (0, 0) => self.eval(u, v),
///             (1, 0) => Point3::new([1.0, 0.0, 0.0]),
///             (0, 1) => Point3::new([0.0, 1.0, 0.0]),
///             _ => Point3::ZERO,
///         }
///     }
/// }
/// let projector = SurfaceProjector::new(&Plane, (16, 16), 1e-12).unwrap();
/// let near = projector.nearest(Point3::new([0.3, 0.4, 2.0]));
/// assert!((near.distance - 2.0).abs() < 1e-12 && (near.u - 0.3).abs() < 1e-12);
/// ```
pub struct SurfaceProjector<'a, S: ?Sized, const D: usize> {
    surface: &'a S,
    us: Vec<f64>,
    vs: Vec<f64>,
    /// Grid points, row-major with `u` outer (`us.len() x vs.len()`).
    points: Vec<Point<D>>,
    tree: ImmutableKdTree<f64, u64, D, 32>,
    reach: f64,
    accuracy: f64,
    closed: (bool, bool),
}

impl<'a, S: Surface<D> + ?Sized, const D: usize> SurfaceProjector<'a, S, D> {
    /// Samples `surface` on `cells.0 x cells.1` cells (at least 1 x 1) and builds the tree.
    /// `accuracy` is the tolerance on the foot parameters (Newton stops when its step is
    /// below it); non-positive asks for full precision. More cells make the search more
    /// robust on wavy surfaces and each query slower to start.
    ///
    /// Errors: a non-finite domain or a grid point that is not finite
    /// ([`Error::NonFiniteArgument`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineSurface;
    /// use karkas::geometry::SurfaceProjector;
    /// use karkas::{Grid, Point};
    ///
    /// // The unit square of the plane z = 0, parameterized by (x, y).
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let square = BSplineSurface::new(linear.clone(), linear, control)?;
    /// let projector = SurfaceProjector::new(&square, (4, 4), 0.0)?;
    /// let foot = projector.nearest(Point([0.3, 0.4, 1.0]));
    /// assert!((foot.u - 0.3).abs() < 1e-9 && (foot.v - 0.4).abs() < 1e-9 && (foot.distance - 1.0).abs() < 1e-9);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(surface: &'a S, cells: (usize, usize), accuracy: f64) -> Result<Self> {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        if ![du.start, du.end, dv.start, dv.end]
            .iter()
            .all(|x| x.is_finite())
        {
            return Err(Error::NonFiniteArgument {
                what: "the surface's domain",
            });
        }
        let (nu, nv) = (cells.0.max(1) + 1, cells.1.max(1) + 1);
        let us: Vec<f64> = (0..nu).map(|k| du.uniform(k, nu)).collect();
        let vs: Vec<f64> = (0..nv).map(|k| dv.uniform(k, nv)).collect();
        let mut points = vec![Point::<D>::ZERO; nu * nv];
        surface.eval_grid_into(&us, &vs, &mut points);
        if points.iter().any(|p| !p.is_finite()) {
            return Err(Error::NonFiniteArgument {
                what: "a sample of the surface",
            });
        }
        let closed = (
            surface.is_closed_u() && du.length() > 0.0,
            surface.is_closed_v() && dv.length() > 0.0,
        );
        let mut reach: f64 = 0.0;
        let edge = |a: Point<D>, m: Point<D>, b: Point<D>| a.distance(m) + m.distance(b);
        for a in 0..nu - 1 {
            for b in 0..nv - 1 {
                let (u0, u1, v0, v1) = (us[a], us[a + 1], vs[b], vs[b + 1]);
                let (um, vm) = (0.5 * (u0 + u1), 0.5 * (v0 + v1));
                let lu = edge(
                    points[a * nv + b],
                    surface.eval(um, v0),
                    points[(a + 1) * nv + b],
                )
                .max(edge(
                    points[a * nv + b + 1],
                    surface.eval(um, v1),
                    points[(a + 1) * nv + b + 1],
                ));
                let lv = edge(
                    points[a * nv + b],
                    surface.eval(u0, vm),
                    points[a * nv + b + 1],
                )
                .max(edge(
                    points[(a + 1) * nv + b],
                    surface.eval(u1, vm),
                    points[(a + 1) * nv + b + 1],
                ));
                let diagonal = points[a * nv + b].distance(surface.eval(um, vm));
                reach = reach.max(0.5 * (lu + lv)).max(diagonal);
            }
        }
        let reach = REACH_MARGIN * reach + 1e-12 * points[0].max_abs();
        let coords: Vec<[f64; D]> = points.iter().map(|p| p.0).collect();
        Ok(SurfaceProjector {
            surface,
            tree: ImmutableKdTree::new_from_slice(&coords),
            us,
            vs,
            points,
            reach,
            accuracy: accuracy.max(0.0),
            closed,
        })
    }

    /// The nearest point of the surface to `q` ([`SurfaceNearest::UNDEFINED`] for a
    /// non-finite `q`).
    pub fn nearest(&self, q: Point<D>) -> SurfaceNearest<D> {
        if !q.is_finite() {
            return SurfaceNearest::UNDEFINED;
        }
        let (nu, nv) = (self.us.len(), self.vs.len());
        let first = (self.tree.nearest_one::<SquaredEuclidean>(&q.0).item as usize)
            .min(self.points.len() - 1);
        let mut best = SurfaceNearest {
            u: self.us[first / nv],
            v: self.vs[first % nv],
            distance: self.points[first].distance(q),
            point: self.points[first],
        };
        let radius = best.distance + self.reach;
        let mut candidates: Vec<(f64, usize)> = Vec::new();
        for found in self
            .tree
            .within_unsorted::<SquaredEuclidean>(&q.0, radius * radius)
        {
            let i = (found.item as usize).min(self.points.len() - 1);
            let (a, b) = (i / nv, i % nv);
            let d = found.distance.sqrt();
            for ca in a.saturating_sub(1)..=a.min(nu - 2) {
                for cb in b.saturating_sub(1)..=b.min(nv - 2) {
                    candidates.push((d, ca * (nv - 1) + cb));
                }
            }
        }
        candidates.sort_by(|x, y| x.0.total_cmp(&y.0).then(x.1.cmp(&y.1)));
        let mut seen = vec![false; (nu - 1) * (nv - 1)];
        for (d, cell) in candidates {
            if seen[cell] {
                continue;
            }
            seen[cell] = true;
            if d - self.reach > best.distance {
                break;
            }
            let (a, b) = (cell / (nv - 1), cell % (nv - 1));
            let start = (
                0.5 * (self.us[a] + self.us[a + 1]),
                0.5 * (self.vs[b] + self.vs[b + 1]),
            );
            let found = self.newton(q, start);
            if found.distance < best.distance {
                best = found;
            }
        }
        if self.closed.0 {
            best.u = self.surface.domain_u().wrap(best.u);
        }
        if self.closed.1 {
            best.v = self.surface.domain_v().wrap(best.v);
        }
        best
    }

    /// The nearest points to every point of `qs` (in parallel for large batches).
    pub fn nearest_all(&self, qs: &[Point<D>]) -> Vec<SurfaceNearest<D>>
    where
        S: Sync,
    {
        if qs.len() < PARALLEL_BATCH {
            qs.iter().map(|&q| self.nearest(q)).collect()
        } else {
            qs.par_iter().map(|&q| self.nearest(q)).collect()
        }
    }

    /// Newton's method on `|S - q|^2 / 2` from `(u0, v0)` ([`newton_foot`]).
    fn newton(&self, q: Point<D>, start: (f64, f64)) -> SurfaceNearest<D> {
        newton_foot(self.surface, q, start, self.closed, self.accuracy)
    }
}

/// Newton's method on `|S(u, v) - q|^2 / 2` from `(u0, v0)`: the full Hessian where it is
/// positive definite, Gauss–Newton where not, steepest descent where the first form is
/// singular, steps halved until the distance does not grow; projected in an open direction
/// (a parameter held at an end by a step pointing out stays there), wrapped in a closed one
/// (`closed`). Stops when a step is below `accuracy` (4 ulp of the domain at least) or after
/// 40 steps. The local minimum of the distance it reaches: the foot of `q` on the surface
/// when started close enough.
pub(crate) fn newton_foot<S: Surface<D> + ?Sized, const D: usize>(
    s: &S,
    q: Point<D>,
    (u0, v0): (f64, f64),
    closed: (bool, bool),
    accuracy: f64,
) -> SurfaceNearest<D> {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let keep = |t: f64, d: Interval, closed: bool| if closed { d.wrap(t) } else { d.clamp(t) };
    let (mut u, mut v) = (u0, v0);
    let mut p = s.eval(u, v);
    let mut dist2 = p.distance_sq(q);
    let floor = 4.0 * f64::EPSILON * du.length().abs().max(dv.length().abs()).max(1.0);
    let tolerance = accuracy.max(floor);
    for _ in 0..MAX_STEPS {
        let local = Quadratic::at(s, q, p, (u, v));
        let Some(step) = local.step() else {
            break;
        };
        let Some((mut step_u, mut step_v)) = local.projected(step, (u, v), (du, dv), closed) else {
            break;
        };
        if !(step_u.is_finite() && step_v.is_finite()) {
            break;
        }
        let mut improved = false;
        for _ in 0..MAX_HALVINGS {
            let nu = keep(u + step_u, du, closed.0);
            let nv = keep(v + step_v, dv, closed.1);
            let np = s.eval(nu, nv);
            let nd2 = np.distance_sq(q);
            // Near the minimum the squared distance changes by the square of the step:
            // rounding-level changes are accepted so that Newton can finish.
            if nd2 <= dist2 * (1.0 + 8.0 * f64::EPSILON) {
                (u, v, p, dist2) = (nu, nv, np, nd2);
                improved = true;
                break;
            }
            step_u *= 0.5;
            step_v *= 0.5;
        }
        if !improved || step_u.abs().max(step_v.abs()) <= tolerance {
            break;
        }
    }
    SurfaceNearest {
        u,
        v,
        distance: dist2.sqrt(),
        point: p,
    }
}

/// `|S(u, v) - q|^2 / 2` to second order at one parameter pair: its gradient `g`, the first
/// form (Gauss–Newton's Hessian) and the full Hessian (both as `[uu, uv, vv]`).
struct Quadratic {
    g: [f64; 2],
    gauss: [f64; 3],
    full: [f64; 3],
}

impl Quadratic {
    /// The quadratic at `(u, v)`, where the surface is at `p`.
    fn at<S: Surface<D> + ?Sized, const D: usize>(
        s: &S,
        q: Point<D>,
        p: Point<D>,
        (u, v): (f64, f64),
    ) -> Self {
        let r = p - q;
        let [_, su, sv, suu, suv, svv] = s.second_order(u, v);
        let g = [su.dot(r), sv.dot(r)];
        let gauss = [su.dot(su), su.dot(sv), sv.dot(sv)];
        let full = [
            gauss[0] + suu.dot(r),
            gauss[1] + suv.dot(r),
            gauss[2] + svv.dot(r),
        ];
        Quadratic { g, gauss, full }
    }

    /// The Newton step with the full Hessian where it is positive definite, Gauss–Newton's
    /// where not, steepest descent where the first form is singular; `None` where the surface
    /// has no derivative at all.
    fn step(&self) -> Option<(f64, f64)> {
        let g = self.g;
        let solve = |h: [f64; 3]| {
            let det = h[0] * h[2] - h[1] * h[1];
            (det > 0.0 && h[0] > 0.0).then(|| {
                (
                    -(h[2] * g[0] - h[1] * g[1]) / det,
                    -(h[0] * g[1] - h[1] * g[0]) / det,
                )
            })
        };
        solve(self.full).or_else(|| solve(self.gauss)).or_else(|| {
            // A singular first form (a degenerate edge): steepest descent along the
            // parameter with a non-zero derivative.
            let (eu, ev) = (self.gauss[0], self.gauss[2]);
            (eu > 0.0 || ev > 0.0).then(|| {
                (
                    if eu > 0.0 { -g[0] / eu } else { 0.0 },
                    if ev > 0.0 { -g[1] / ev } else { 0.0 },
                )
            })
        })
    }

    /// The 1-D Newton step along parameter `k` (0 for `u`, 1 for `v`) alone.
    fn one_d(&self, k: usize) -> f64 {
        let (g, h, e) = (self.g[k], self.full[2 * k], self.gauss[2 * k]);
        if h > 0.0 {
            -g / h
        } else if e > 0.0 {
            -g / e
        } else {
            0.0
        }
    }

    /// Projected Newton: a parameter held at an end of an open direction by a step pointing
    /// out of the domain stays there, and the other one takes the 1-D Newton step of the
    /// restricted problem. `None` at a corner where no 1-D step along an edge points inside.
    fn projected(
        &self,
        (step_u, step_v): (f64, f64),
        (u, v): (f64, f64),
        (du, dv): (Interval, Interval),
        closed: (bool, bool),
    ) -> Option<(f64, f64)> {
        let pushed = |t: f64, step: f64, d: Interval, closed: bool| {
            !closed && ((t <= d.start && step < 0.0) || (t >= d.end && step > 0.0))
        };
        match (
            pushed(u, step_u, du, closed.0),
            pushed(v, step_v, dv, closed.1),
        ) {
            // At a corner: the 1-D step along an edge of the domain when it points inside
            // (the full step may leave across both ends while one gradient points in).
            (true, true) => {
                let along_v = self.one_d(1);
                let along_u = self.one_d(0);
                if along_v != 0.0 && !pushed(v, along_v, dv, closed.1) {
                    Some((0.0, along_v))
                } else if along_u != 0.0 && !pushed(u, along_u, du, closed.0) {
                    Some((along_u, 0.0))
                } else {
                    None
                }
            }
            (true, false) => Some((0.0, self.one_d(1))),
            (false, true) => Some((self.one_d(0), 0.0)),
            (false, false) => Some((step_u, step_v)),
        }
    }
}

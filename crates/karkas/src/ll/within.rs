//! LL approximation within a given distance of the points (Aulchenko, Latypov, Nikulichev,
//! system (6) used for targets near the points; docs/methods.md §1.2–1.3).
//!
//! The plain LL curve misses node `i` by `d_L D_i` (formula (5)); the interpolating variant
//! passes through every node but is built on the solved points `r*` of system (6). Between the
//! two, the paper notes that an LL approximation can be made to pass within a given
//! neighbourhood of the points without raising `L`: system (6) makes the curve pass through
//! any targets `p_i`, so choose targets inside the neighbourhood. The paper leaves the choice
//! of targets open; karkas takes, for each node, the point of the closed ball of radius `D`
//! around the input point `r_i` nearest to the plain approximation's node value
//! `N_i = r_i + d_L D_i`:
//!
//! `p_i = N_i` when `|N_i - r_i| <= D`, else `p_i = r_i + (N_i - r_i) D / |N_i - r_i|`,
//!
//! and solves (6) once for the control points whose LL curve passes through the `p_i`
//! (Euclidean distance in model units; no iteration). Each node therefore moves as little
//! as the distance allows from where the plain approximation put it, and the result reaches
//! every node within `D` up to round-off. Consequences:
//!
//! - `D` at or above the plain approximation's largest node deviation: every target is the
//!   plain node value, and the result *is* the plain approximation (built without a solve);
//! - `D -> 0`: the targets tend to the points, and the result to the interpolating variant
//!   (continuously, since (6) is strictly diagonally dominant);
//! - order `L`, degree `2L` and `C^L` continuity are those of every LL curve; the
//!   convexity and monotonicity guarantees of the plain approximation are lost as soon as a
//!   node is pulled in: like the interpolating variant, the curve is built on the solved
//!   points, not on the data (the paper warns of this for system (6)).
//!
//! Surfaces take the same targets at every grid node, with the node operator and its
//! inverse applied along rows, then columns (the separable solve of the interpolating
//! surface). Cost: `O(K)` for a curve, `O(Kx Ky)` for a surface.

use super::curve::LlCurve;
use super::kernel::LlKernel;
use super::prefilter::{along_rows_then_columns, interpolation_controls, node_values};
use super::surface::LlSurface;
use crate::{Error, Grid, Point, Result};

/// An LL curve or surface built to pass within a distance of its points
/// ([`LlCurve::within`], [`LlSurface::within`]), with what the construction achieved.
#[derive(Clone, Debug, PartialEq)]
pub struct WithinFit<T> {
    /// The LL curve or surface, of the order asked for.
    pub shape: T,
    /// The largest distance from a point to the result at the point's node, measured on the
    /// result's control points by formula (5): at most the distance asked for, up to
    /// round-off.
    pub largest_deviation: f64,
    /// The largest node distance of the plain approximation of the same points.
    pub plain_deviation: f64,
    /// How many nodes the plain approximation missed by more than the distance (their targets
    /// were pulled in); 0 means the result is the plain approximation, and nothing was
    /// solved.
    pub pulled_nodes: usize,
    /// The number of distinct nodes (a closed direction's repeated node counts once).
    pub nodes: usize,
}

/// Refuses a distance that is not positive and finite.
fn check_distance(distance: f64) -> Result<()> {
    if distance > 0.0 && distance.is_finite() {
        Ok(())
    } else {
        Err(Error::InvalidSetting {
            name: "distance",
            value: distance,
            reason: "the distance from the points must be positive and finite",
        })
    }
}

/// The targets: for each point, the point of the ball of radius `distance` around it nearest
/// to its plain node value (`plain` on entry, targets on return). Returns the largest plain
/// deviation and the number of targets pulled in, over the entries `counted` accepts.
fn pull_targets<const D: usize>(
    points: &[Point<D>],
    plain: &mut [Point<D>],
    distance: f64,
    counted: impl Fn(usize) -> bool,
) -> (f64, usize) {
    let mut largest = 0.0f64;
    let mut pulled = 0;
    for (k, (r, p)) in points.iter().zip(plain.iter_mut()).enumerate() {
        let offset = *p - *r;
        let deviation = offset.norm();
        if counted(k) {
            largest = largest.max(deviation);
        }
        if deviation > distance {
            *p = r.add_scaled(distance / deviation, offset);
            if counted(k) {
                pulled += 1;
            }
        }
    }
    (largest, pulled)
}

/// The largest distance between `points` and `nodes`.
fn largest_distance<const D: usize>(points: &[Point<D>], nodes: &[Point<D>]) -> f64 {
    points
        .iter()
        .zip(nodes)
        .map(|(r, n)| r.distance(*n))
        .fold(0.0, f64::max)
}

impl<const D: usize> LlCurve<D> {
    /// The LL curve of order `order` that passes within `distance` (model units, Euclidean)
    /// of every point at its node, between the plain approximation ([`new`](Self::new)) and
    /// the interpolating variant ([`interpolating`](Self::interpolating)).
    ///
    /// Each node's target is the point within `distance` of the input point nearest to the
    /// plain approximation's node value, and system (6) is solved once for the control
    /// polygon through the targets (see the module docs of `ll/within.rs`). With `distance`
    /// at least the plain approximation's largest node deviation the result is the plain
    /// approximation. The monotonicity and convexity guarantees of the plain approximation
    /// do not hold once a node is pulled in.
    ///
    /// Errors: those of [`new`](Self::new), and [`Error::InvalidSetting`] for a distance that
    /// is not positive and finite.
    ///
    /// ```
    /// use karkas::ll::LlCurve;
    /// use karkas::{Curve, Point};
    /// let pts = [0.0, 1.0, 0.0, 1.0, 0.0].map(|y| Point([0.0, y]));
    /// let plain = LlCurve::within(&pts, 2, false, 1.0).unwrap();
    /// assert_eq!(plain.pulled_nodes, 0);
    /// assert!((plain.plain_deviation - 3.0 / 16.0).abs() < 1e-15); // 2 d_2 = 3/16
    /// let near = LlCurve::within(&pts, 2, false, 0.05).unwrap();
    /// assert_eq!(near.pulled_nodes, 3);
    /// assert!(near.largest_deviation <= 0.05 + 1e-15);
    /// let node = near.shape.eval(near.shape.axis().node(2));
    /// assert!((node.distance(pts[1]) - 0.05).abs() < 1e-12);
    /// ```
    pub fn within(
        points: &[Point<D>],
        order: usize,
        closed: bool,
        distance: f64,
    ) -> Result<WithinFit<Self>> {
        let kernel = LlKernel::new(order)?;
        let control = Self::support_polygon(points, closed)?;
        check_distance(distance)?;
        let d_l = kernel.d_l();
        let k = control.len();
        let nodes = if closed { k - 1 } else { k };
        let mut targets = node_values(&control, d_l, closed);
        let (plain_deviation, pulled_nodes) =
            pull_targets(&control, &mut targets, distance, |i| i < nodes);
        if pulled_nodes == 0 {
            return Ok(WithinFit {
                shape: Self::from_control(kernel, control, closed),
                largest_deviation: plain_deviation,
                plain_deviation,
                pulled_nodes,
                nodes,
            });
        }
        interpolation_controls(&mut targets, d_l, closed)?;
        let reached = node_values(&targets, d_l, closed);
        Ok(WithinFit {
            largest_deviation: largest_distance(&control, &reached),
            shape: Self::from_control(kernel, targets, closed),
            plain_deviation,
            pulled_nodes,
            nodes,
        })
    }
}

impl<const D: usize> LlSurface<D> {
    /// The LL surface of order `order` that passes within `distance` (model units,
    /// Euclidean) of every grid point at its node: the targets of
    /// [`LlCurve::within`] at every node, and the separable solve of
    /// [`interpolating`](Self::interpolating) through them. With `distance` at least the
    /// plain approximation's largest node deviation the result is the plain approximation
    /// ([`new`](Self::new)).
    ///
    /// Errors: those of [`new`](Self::new), and [`Error::InvalidSetting`] for a distance that
    /// is not positive and finite.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::{ll::LlSurface, Grid, Point};
    ///
    /// let grid = Grid::from_fn(6, 6, |i, j| Point([i as f64, j as f64, ((i * j) % 3) as f64]));
    /// let fit = LlSurface::within(&grid, 2, false, false, 0.1)?;
    /// assert!(fit.largest_deviation <= 0.1 * (1.0 + 1e-9));
    /// assert!(LlSurface::within(&grid, 2, false, false, -1.0).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn within(
        grid: &Grid<Point<D>>,
        order: usize,
        closed_u: bool,
        closed_v: bool,
        distance: f64,
    ) -> Result<WithinFit<Self>> {
        let kernel = LlKernel::new(order)?;
        grid.check_points(3, "an LL surface (in each grid direction)")?;
        let control = grid.closed(
            closed_u,
            closed_v,
            "a closed direction of an LL surface (distinct rows or columns)",
        )?;
        check_distance(distance)?;
        let d_l = kernel.d_l();
        let closings = (closed_u, closed_v);
        let node_grid = |values: &Grid<Point<D>>| -> Result<Grid<Point<D>>> {
            let mut out = values.clone();
            along_rows_then_columns(&mut out, closings, |line, closed| {
                let nodes = node_values(line, d_l, closed);
                line.copy_from_slice(&nodes);
                Ok(())
            })?;
            Ok(out)
        };
        let (kx, ky) = (control.rows(), control.cols());
        let distinct_rows = if closed_u { kx - 1 } else { kx };
        let distinct_cols = if closed_v { ky - 1 } else { ky };
        let distinct = |k: usize| k / ky < distinct_rows && k % ky < distinct_cols;
        let mut targets = node_grid(&control)?;
        let (plain_deviation, pulled_nodes) = pull_targets(
            control.as_slice(),
            targets.as_mut_slice(),
            distance,
            distinct,
        );
        let nodes = distinct_rows * distinct_cols;
        if pulled_nodes == 0 {
            return Ok(WithinFit {
                shape: Self::from_control(kernel, control, closed_u, closed_v),
                largest_deviation: plain_deviation,
                plain_deviation,
                pulled_nodes,
                nodes,
            });
        }
        along_rows_then_columns(&mut targets, closings, |line, closed| {
            interpolation_controls(line, d_l, closed)
        })?;
        let reached = node_grid(&targets)?;
        Ok(WithinFit {
            largest_deviation: largest_distance(control.as_slice(), reached.as_slice()),
            shape: Self::from_control(kernel, targets, closed_u, closed_v),
            plain_deviation,
            pulled_nodes,
            nodes,
        })
    }
}

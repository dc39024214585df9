//! Closed tube surfaces from two families of skeleton curves (Malozemov et al.'s §4–5, formula (3);
//! docs/methods.md §3).
//!
//! Skeleton: curves `f_i`, `i < m1`, running along the tube, each sampled at `q` in `0..N2`,
//! and curves `g_j`, `j < m2`, running across it, each sampled at `p` in `0..N1`, with
//! `N1 = m1 n1`, `N2 = m2 n2`, meeting where they must: `f_i(j n2) = g_j(i n1)`. The surface is
//! the discrete spline
//!
//! ```text
//! c(p, q) = S^(q)_{r1}(p) + S^(p)_{r2}(q)                                         (3)
//! ```
//!
//! where `S^(q)_{r1}` interpolates `f_i(q)` at `p = i n1` and `S^(p)_{r2}` interpolates
//! `h_j(p) = g_j(p) - S^(j n2)_{r1}(p)` at `q = j n2`. It is `N1`-periodic in `p`,
//! `N2`-periodic in `q`, and satisfies (2): `c(i n1, .) = f_i` and `c(., j n2) = g_j`.
//!
//! Cost: `N2` interpolations of length `m1` and `N1` of length `m2` (one reusable FFT plan per
//! direction), and `O((r1 + r2) N1 N2)` evaluation; memory one `N1 x N2` grid.

use super::interpolation::InterpolationPlan;
use super::period::check_period;
use super::spline::evaluate_into;
use crate::{Error, Grid, Point, Result};

/// Largest accepted distance between `f_i(j n2)` and `g_j(i n1)`, relative to the size of the
/// skeleton (the diagonal of its bounding box).
pub const COMPATIBILITY_TOLERANCE: f64 = 1e-9;

/// A closed tube: the discrete spline surface (3) through a skeleton of curves along and
/// across.
///
/// ```
/// use karkas::dps::TubeSurface;
/// use karkas::{Grid, Point};
/// use std::f64::consts::TAU;
/// // A torus: 2 curves along (inner and outer equator), 4 rings across.
/// let (n1, n2, m1, m2) = (4, 6, 2, 4);
/// let (big_n1, big_n2) = (m1 * n1, m2 * n2);
/// let torus = |p: usize, q: usize| {
///     let (u, v) = (TAU * p as f64 / big_n1 as f64, TAU * q as f64 / big_n2 as f64);
///     let r = 3.0 + u.cos();
///     Point([r * v.cos(), r * v.sin(), u.sin()])
/// };
/// let along = Grid::from_fn(m1, big_n2, |i, q| torus(i * n1, q));
/// let across = Grid::from_fn(m2, big_n1, |j, p| torus(p, j * n2));
/// let tube = TubeSurface::new(&along, &across, n1, n2, 2, 2).unwrap();
/// // (2): the skeleton lies on the surface.
/// assert!(tube.value(n1, 5).distance(*along.get(1, 5)) < 1e-12);
/// assert!(tube.value(3, 2 * n2).distance(*across.get(2, 3)) < 1e-12);
/// ```
#[derive(Clone, Debug, PartialEq)]
pub struct TubeSurface<const D: usize> {
    /// `c(p, q)`: row `p` in `0..N1`, column `q` in `0..N2`.
    values: Grid<Point<D>>,
    steps: (usize, usize),
    orders: (usize, usize),
}

impl<const D: usize> TubeSurface<D> {
    /// The tube (3) through the skeleton `along` (row `i` is `f_i`, `m1` rows of `N2` samples)
    /// and `across` (row `j` is `g_j`, `m2` rows of `N1` samples), with steps `n1`, `n2` and
    /// spline orders `r1` (across the tube, in `p`) and `r2` (along it, in `q`).
    ///
    /// Errors: fewer than 2 curves in a family; `n1` or `n2` below 2; an order outside
    /// `1..=`[`MAX_ORDER`](super::MAX_ORDER); along curves not of `N2 = m2 n2` samples or across
    /// curves not of `N1 = m1 n1`; a non-finite point; a pair with `f_i(j n2)` farther than
    /// [`COMPATIBILITY_TOLERANCE`] (times the skeleton's size) from `g_j(i n1)`, reported as
    /// [`Error::IncompatibleSkeleton`] naming the first such pair.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::dps::TubeSurface;
    /// use karkas::{Grid, Point};
    ///
    /// // A torus sampled on 6 x 6 points; the skeleton is every second line each way (m1 = m2 = 3).
    /// let (n1, n2) = (2, 2);
    /// let torus = |p: usize, q: usize| {
    ///     let (a, b) = (p as f64 * std::f64::consts::TAU / 6.0, q as f64 * std::f64::consts::TAU / 6.0);
    ///     Point([(2.0 + b.cos()) * a.cos(), (2.0 + b.cos()) * a.sin(), b.sin()])
    /// };
    /// let along = Grid::from_fn(3, 6, |i, q| torus(i * n1, q));
    /// let across = Grid::from_fn(3, 6, |j, p| torus(p, j * n2));
    /// let tube = TubeSurface::new(&along, &across, n1, n2, 2, 2)?;
    /// assert_eq!(tube.periods(), (6, 6));
    /// assert!(tube.value(2, 4).distance(torus(2, 4)) < 1e-9); // it passes through the skeleton
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        along: &Grid<Point<D>>,
        across: &Grid<Point<D>>,
        n1: usize,
        n2: usize,
        r1: usize,
        r2: usize,
    ) -> Result<Self> {
        let shape = SkeletonShape::check(along, across, n1, n2)?;
        check_period(shape.m1, n1, r1, "a tube (along curves)")?;
        check_period(shape.m2, n2, r2, "a tube (across curves)")?;
        let tolerance = COMPATIBILITY_TOLERANCE * skeleton_size(along, across);
        let (i, j, distance) = worst_mismatch(along, across, n1, n2);
        if distance > tolerance {
            return Err(Error::IncompatibleSkeleton {
                along: i,
                across: j,
                distance,
                tolerance,
            });
        }
        let values = formula_3(along, across, &shape, (n1, n2), (r1, r2))?;
        Ok(TubeSurface {
            values,
            steps: (n1, n2),
            orders: (r1, r2),
        })
    }

    /// The values `c(p, q)` as an `N1 x N2` grid (row `p`, column `q`).
    pub fn values(&self) -> &Grid<Point<D>> {
        &self.values
    }

    /// `c(p, q)`, indices taken modulo `N1` and `N2` (the surface is periodic in both).
    pub fn value(&self, p: usize, q: usize) -> Point<D> {
        *self
            .values
            .get(p % self.values.rows(), q % self.values.cols())
    }

    /// The steps `(n1, n2)`.
    pub fn steps(&self) -> (usize, usize) {
        self.steps
    }

    /// The orders `(r1, r2)`: in `p` (across the tube) and in `q` (along it).
    pub fn orders(&self) -> (usize, usize) {
        self.orders
    }

    /// The periods `(N1, N2)`.
    pub fn periods(&self) -> (usize, usize) {
        (self.values.rows(), self.values.cols())
    }

    /// The values with the first row and column repeated at the end: an `(N1 + 1) x (N2 + 1)`
    /// grid whose cells cover the whole closed surface, for meshing (the seam copies are exact).
    pub fn closed_grid(&self) -> Grid<Point<D>> {
        let (rows, cols) = self.periods();
        Grid::from_fn(rows + 1, cols + 1, |p, q| {
            *self.values.get(p % rows, q % cols)
        })
    }
}

/// The largest `|f_i(j n2) - g_j(i n1)|` over all pairs, for a skeleton of the right shape;
/// `0` for an empty family.
///
/// Errors: as the shape checks of [`TubeSurface::new`] (counts, lengths, finiteness).
pub fn compatibility_residual<const D: usize>(
    along: &Grid<Point<D>>,
    across: &Grid<Point<D>>,
    n1: usize,
    n2: usize,
) -> Result<f64> {
    SkeletonShape::check(along, across, n1, n2)?;
    Ok(worst_mismatch(along, across, n1, n2).2)
}

/// The counts of a checked skeleton.
struct SkeletonShape {
    m1: usize,
    m2: usize,
}

impl SkeletonShape {
    /// Checks curve counts, lengths (`N2` along, `N1` across) and finiteness.
    fn check<const D: usize>(
        along: &Grid<Point<D>>,
        across: &Grid<Point<D>>,
        n1: usize,
        n2: usize,
    ) -> Result<SkeletonShape> {
        let (m1, m2) = (along.rows(), across.rows());
        for (family, got) in [("along", m1), ("across", m2)] {
            if got < 2 {
                return Err(Error::TooFewCurves {
                    family,
                    needed: 2,
                    got,
                });
            }
        }
        for step in [n1, n2] {
            if step < 2 {
                return Err(Error::InvalidStep { step });
            }
        }
        let lengths = [
            ("along", "across", along, m2, n2),
            ("across", "along", across, m1, n1),
        ];
        for (family, other, grid, curves, step) in lengths {
            let expected = curves.checked_mul(step).ok_or(Error::PeriodTooLarge {
                poles: curves,
                step,
            })?;
            if grid.cols() != expected {
                return Err(Error::SkeletonLength {
                    family,
                    other,
                    curves,
                    step,
                    expected,
                    got: grid.cols(),
                });
            }
            for curve in 0..grid.rows() {
                if let Some(sample) = grid.row(curve).iter().position(|p| !p.is_finite()) {
                    return Err(Error::NonFiniteSkeletonPoint {
                        family,
                        curve,
                        sample,
                    });
                }
            }
        }
        Ok(SkeletonShape { m1, m2 })
    }
}

/// The pair `(i, j)` with the largest `|f_i(j n2) - g_j(i n1)|` (the first one on ties) and
/// that distance.
fn worst_mismatch<const D: usize>(
    along: &Grid<Point<D>>,
    across: &Grid<Point<D>>,
    n1: usize,
    n2: usize,
) -> (usize, usize, f64) {
    let mut worst = (0, 0, 0.0);
    for i in 0..along.rows() {
        for j in 0..across.rows() {
            let d = along.get(i, j * n2).distance(*across.get(j, i * n1));
            if d > worst.2 || d.is_nan() {
                worst = (i, j, d);
            }
        }
    }
    worst
}

/// The diagonal of the bounding box of all skeleton points.
fn skeleton_size<const D: usize>(along: &Grid<Point<D>>, across: &Grid<Point<D>>) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in along.as_slice().iter().chain(across.as_slice()) {
        for c in 0..D {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (0..D)
        .map(|c| (hi[c] - lo[c]).max(0.0).powi(2))
        .sum::<f64>()
        .sqrt()
}

/// Formula (3) on a checked, compatible skeleton.
fn formula_3<const D: usize>(
    along: &Grid<Point<D>>,
    across: &Grid<Point<D>>,
    shape: &SkeletonShape,
    (n1, n2): (usize, usize),
    (r1, r2): (usize, usize),
) -> Result<Grid<Point<D>>> {
    let (m1, m2) = (shape.m1, shape.m2);
    let (big_n1, big_n2) = (m1 * n1, m2 * n2);
    let mut values = Grid::from_fn(big_n1, big_n2, |_, _| Point::ZERO);
    let mut scratch = Vec::with_capacity(n1.max(n2));

    // First sum: for each q, the spline in p through f_i(q) at p = i n1, into column q.
    let mut plan = InterpolationPlan::new(m1, n1, r1)?;
    let mut nodes = vec![Point::ZERO; m1];
    let mut poles = vec![Point::ZERO; m1];
    let mut line = vec![Point::ZERO; big_n1];
    for q in 0..big_n2 {
        for (i, z) in nodes.iter_mut().enumerate() {
            *z = *along.get(i, q);
        }
        plan.poles_into(&nodes, &mut poles)?;
        evaluate_into(&poles, n1, r1, &mut line, &mut scratch);
        for (p, v) in line.iter().enumerate() {
            *values.get_mut(p, q) = *v;
        }
    }

    // h_j(p) = g_j(p) - S^(j n2)(p); for each p, the spline in q through h_j(p) at q = j n2,
    // added to row p.
    let h = Grid::from_fn(m2, big_n1, |j, p| {
        *across.get(j, p) - *values.get(p, j * n2)
    });
    let mut plan = InterpolationPlan::new(m2, n2, r2)?;
    let mut nodes = vec![Point::ZERO; m2];
    let mut poles = vec![Point::ZERO; m2];
    let mut line = vec![Point::ZERO; big_n2];
    for p in 0..big_n1 {
        for (j, z) in nodes.iter_mut().enumerate() {
            *z = *h.get(j, p);
        }
        plan.poles_into(&nodes, &mut poles)?;
        evaluate_into(&poles, n2, r2, &mut line, &mut scratch);
        let row = &mut values.as_mut_slice()[p * big_n2..(p + 1) * big_n2];
        for (c, v) in row.iter_mut().zip(&line) {
            *c += *v;
        }
    }
    Ok(values)
}

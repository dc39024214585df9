//! Nearest points of a large batch: cells of a grid over the queries, each certified once.
//!
//! The general search ([`CurveProjector::nearest`]) proves every answer on its own: a k-d tree
//! query, Newton's method on the segments at the nearest vertex, then a second tree query
//! for every segment that might still hold a nearer point. For a large batch most of that
//! proof can be shared by the queries that lie close together. The queries' bounding box is
//! cut into cubic cells (about [`QUERIES_PER_CELL`] queries each); the first query that
//! falls into a cell certifies it, with centre `c` and radius `r` (half its diagonal):
//!
//! 1. The general search gives the distance `d_c` from `c` to the curve, so every query `x`
//!    of the cell is within `U = d_c + r` of the curve.
//! 2. A run `J` of consecutive polyline segments around the foot of `c` is grown while the
//!    segments' lower bounds from `c` are at most `d_c + 2r`; a segment `j` outside `J` must
//!    have a lower bound above that (checked with the k-d tree), so it is farther than `U`
//!    from every query of the cell and cannot hold a nearest point.
//! 3. On every segment of `J`, `|P - x|^2` must be strictly convex for every `x` of the cell
//!    ([`SegmentPolynomials::convex_for`]), and the tangent continuous at every joint inside
//!    `J`. Then `g = (P - x) . P'` increases along `J` and has at most one root there: the
//!    distance has one local minimum on `J`, which is the global one.
//!
//! A query in a certified cell walks from the segment of the centre's foot along `J` in the
//! direction in which `g` says the distance falls, to the segment where `g` changes sign, and
//! finds the root by Newton's method on the segment's own polynomial (no piece lookup); the
//! foot is the curve's own value there. A cell that fails any check, a query that falls
//! outside its cell by rounding, and a walk that leaves `J` take the general search. So the
//! answers are those of the general search, to the tolerance of Newton's method.
//!
//! Hand-written: k-d tree crates answer nearest-vertex queries, not nearest points of a curve
//! with a certificate.

use std::sync::OnceLock;

use rayon::prelude::*;

use super::curve_nearest::{CurveNearest, CurveProjector};
use super::segment_polynomials::SegmentPolynomials;
use crate::core::Curve;
use crate::Point;

/// Batches at least this large are projected in parallel.
const PARALLEL_BATCH: usize = 256;
/// Batches at least this large share certificates by cells.
const GRID_BATCH: usize = 4096;
/// About this many queries share a cell.
const QUERIES_PER_CELL: f64 = 24.0;
/// The most cells of a grid.
const MAX_CELLS: usize = 1 << 20;
/// The longest run of segments a cell may certify.
const MAX_RUN: usize = 1 << 12;

/// What the first query of a cell found out for all of them.
#[derive(Clone, Copy)]
enum Cell {
    /// No certificate: every query takes the general search.
    General,
    /// One local minimum on the run of segments `start - before ..= start + after` (modulo
    /// the segment count on a closed curve).
    Convex { start: u32, before: u32, after: u32 },
}

impl<C: Curve<D> + ?Sized, const D: usize> CurveProjector<'_, C, D> {
    /// The nearest points to every point of `qs` (in parallel for large batches; for a
    /// batch of 4096 or more, certified by grid cells, as the module `nearest_grid`
    /// explains).
    pub fn nearest_all(&self, qs: &[Point<D>]) -> Vec<CurveNearest<D>>
    where
        C: Sync,
    {
        if qs.len() < PARALLEL_BATCH {
            return qs.iter().map(|&q| self.nearest(q)).collect();
        }
        if qs.len() >= GRID_BATCH {
            if let Some(grid) = NearestGrid::new(self, qs) {
                return qs.par_iter().map(|&q| grid.nearest(q)).collect();
            }
        }
        qs.par_iter().map(|&q| self.nearest(q)).collect()
    }
}

/// A grid over one batch of queries.
pub(super) struct NearestGrid<'p, 'a, C: ?Sized, const D: usize> {
    projector: &'p CurveProjector<'a, C, D>,
    polynomials: SegmentPolynomials<D>,
    origin: Point<D>,
    size: f64,
    radius: f64,
    dims: [usize; D],
    cells: Vec<OnceLock<Cell>>,
}

impl<'p, 'a, C: Curve<D> + ?Sized, const D: usize> NearestGrid<'p, 'a, C, D> {
    /// The grid for `queries`; `None` when the curve has no segment polynomials or the
    /// queries' box is not finite.
    pub(super) fn new(
        projector: &'p CurveProjector<'a, C, D>,
        queries: &[Point<D>],
    ) -> Option<Self> {
        let mut lo = [f64::INFINITY; D];
        let mut hi = [f64::NEG_INFINITY; D];
        for q in queries.iter().filter(|q| q.is_finite()) {
            for k in 0..D {
                lo[k] = lo[k].min(q[k]);
                hi[k] = hi[k].max(q[k]);
            }
        }
        let extent = (0..D).map(|k| hi[k] - lo[k]).fold(0.0f64, f64::max);
        if !extent.is_finite() || !lo.iter().all(|x| x.is_finite()) {
            return None;
        }
        let polynomials =
            SegmentPolynomials::new(projector.curve, &projector.params, projector.closed)?;
        let target = (queries.len() as f64 / QUERIES_PER_CELL).clamp(1.0, MAX_CELLS as f64);
        let count = |size: f64| -> f64 {
            (0..D)
                .map(|k| ((hi[k] - lo[k]) / size).floor() + 1.0)
                .product()
        };
        let mut size = if extent > 0.0 { extent } else { 1.0 };
        while extent > 0.0 && count(size * 0.8) <= target {
            size *= 0.8;
        }
        let dims = std::array::from_fn(|k| ((hi[k] - lo[k]) / size).floor() as usize + 1);
        let cells = (0..dims.iter().product::<usize>())
            .map(|_| OnceLock::new())
            .collect();
        Some(NearestGrid {
            projector,
            polynomials,
            origin: Point(lo),
            size,
            // Half the diagonal, rounded up.
            radius: 0.5 * size * (D as f64).sqrt() * (1.0 + 1e-9),
            dims,
            cells,
        })
    }

    /// The nearest point of the curve to `q`.
    pub(super) fn nearest(&self, q: Point<D>) -> CurveNearest<D>
    where
        C: Sync,
    {
        if !q.is_finite() {
            return CurveNearest::UNDEFINED;
        }
        let mut index = 0;
        let mut centre = self.origin;
        for k in 0..D {
            let i = (((q[k] - self.origin[k]) / self.size).max(0.0) as usize).min(self.dims[k] - 1);
            index = index * self.dims[k] + i;
            centre[k] += (i as f64 + 0.5) * self.size;
        }
        if q.distance(centre) > self.radius {
            return self.projector.nearest(q);
        }
        match *self.cells[index].get_or_init(|| self.certify(centre)) {
            Cell::General => self.projector.nearest(q),
            Cell::Convex {
                start,
                before,
                after,
            } => self
                .walk(q, start as usize, before as i64, after as i64)
                .unwrap_or_else(|| self.projector.nearest(q)),
        }
    }

    /// Steps 1 to 3 of the module's proof for the cell of `centre`.
    fn certify(&self, centre: Point<D>) -> Cell {
        let p = self.projector;
        let segments = p.params.len() - 1;
        let found = p.nearest(centre);
        if !found.distance.is_finite() {
            return Cell::General;
        }
        let threshold = found.distance + 2.0 * self.radius;
        let start = p
            .params
            .partition_point(|&t| t <= found.t)
            .saturating_sub(1)
            .min(segments - 1);
        let wrap = |j: i64| -> Option<usize> {
            if p.closed {
                Some(j.rem_euclid(segments as i64) as usize)
            } else {
                usize::try_from(j).ok().filter(|&j| j < segments)
            }
        };
        let near = |j: usize| p.lower_bound(centre, j) <= threshold;
        let max_run = MAX_RUN.min(segments - 1);
        let mut before = 0usize;
        while let Some(j) = wrap(start as i64 - before as i64 - 1).filter(|&j| near(j)) {
            before += 1;
            if before + 1 > max_run || !self.polynomials.smooth_start((j + 1) % segments) {
                return Cell::General;
            }
        }
        let mut after = 0usize;
        while let Some(j) = wrap(start as i64 + after as i64 + 1).filter(|&j| near(j)) {
            after += 1;
            if before + after + 1 > max_run || !self.polynomials.smooth_start(j) {
                return Cell::General;
            }
        }
        let inside = |j: usize| {
            let offset = if p.closed {
                (j + segments - start) % segments
            } else if j >= start {
                j - start
            } else {
                return start - j <= before;
            };
            offset <= after || (p.closed && segments - offset <= before)
        };
        let radius = threshold + 2.0 * p.reach;
        for v in p.vertices_within(centre, radius) {
            for j in p.segments_at(v).into_iter().flatten() {
                if !inside(j) && near(j) {
                    return Cell::General;
                }
            }
        }
        let run = (start as i64 - before as i64)..=(start as i64 + after as i64);
        if !run
            .filter_map(wrap)
            .all(|j| self.polynomials.convex_for(j, centre, self.radius))
        {
            return Cell::General;
        }
        Cell::Convex {
            start: start as u32,
            before: before as u32,
            after: after as u32,
        }
    }

    /// The nearest point to `q` on a certified run: the segment where `g` changes sign, then
    /// its root. `None` when the walk would leave the run (only by rounding).
    fn walk(&self, q: Point<D>, start: usize, before: i64, after: i64) -> Option<CurveNearest<D>> {
        let p = self.projector;
        let polys = &self.polynomials;
        let segments = p.params.len() - 1;
        let at = |offset: i64| (start as i64 + offset).rem_euclid(segments as i64) as usize;
        let mut offset = 0i64;
        let (first_start, first_end) = polys.end_slopes(start, q);
        let step: i64 = if first_start > 0.0 {
            -1
        } else if first_end <= 0.0 {
            1
        } else {
            0
        };
        let mut j = start;
        if step != 0 {
            loop {
                let (ga, gb) = polys.end_slopes(j, q);
                if step < 0 && ga <= 0.0 || step > 0 && gb > 0.0 {
                    break;
                }
                offset += step;
                if offset < -before || offset > after {
                    // The minimum is at an end of the run: an end of an open curve, or a
                    // rounding artefact.
                    let domain_end = if step < 0 { j == 0 } else { j == segments - 1 };
                    if p.closed || !domain_end {
                        return None;
                    }
                    let v = if step < 0 { j } else { j + 1 };
                    return Some(p.result(p.params[v], p.points[v], q));
                }
                j = at(offset);
            }
        }
        let (ga, gb) = polys.end_slopes(j, q);
        if !(ga <= 0.0 && gb > 0.0) {
            // `g` turned at a joint between two segments (rounding at a kink-free joint).
            return None;
        }
        // Start where q projects onto the chord.
        let [a, b] = polys.end_points(j);
        let (chord, c2) = (b - a, a.distance_sq(b));
        let s = if c2 > 0.0 {
            ((q - a).dot(chord) / c2).clamp(0.0, 1.0)
        } else {
            0.5
        };
        let v = polys.root(j, q, 2.0 * s - 1.0, p.accuracy);
        let mut t = polys.parameter(j, v).clamp(p.params[j], p.params[j + 1]);
        let point = p.curve.eval(t);
        if p.closed {
            t = p.curve.domain().wrap(t);
        }
        Some(p.result(t, point, q))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::{Interval, PolynomialPieces};
    use std::f64::consts::TAU;

    /// The closed cubic Hermite curve through `n` points of the rose `r = 1 + 0.3 cos 5θ`
    /// with its exact tangents, one piece per unit of the parameter (`C^1`).
    struct Rose {
        pieces: Vec<[Point<2>; 4]>,
    }

    impl Rose {
        fn new(n: usize) -> Self {
            let at = |k: usize| {
                let th = TAU * k as f64 / n as f64;
                let (r, dr) = (1.0 + 0.3 * (5.0 * th).cos(), -1.5 * (5.0 * th).sin());
                let (s, c) = th.sin_cos();
                let tangent = Point([dr * c - r * s, dr * s + r * c]) * (TAU / n as f64);
                (Point([r * c, r * s]), tangent)
            };
            let pieces = (0..n)
                .map(|k| {
                    let ((p0, m0), (p1, m1)) = (at(k), at(k + 1));
                    let a2 = (p1 - p0) * 3.0 - m0 * 2.0 - m1;
                    let a3 = (p0 - p1) * 2.0 + m0 + m1;
                    [p0, m0, a2, a3]
                })
                .collect();
            Rose { pieces }
        }
    }

    impl Curve<2> for Rose {
        fn domain(&self) -> Interval {
            Interval::new(0.0, self.pieces.len() as f64)
        }
        fn is_closed(&self) -> bool {
            true
        }
        fn eval(&self, t: f64) -> Point<2> {
            self.deriv(t, 0)
        }
        fn deriv(&self, t: f64, k: usize) -> Point<2> {
            let t = self.domain().wrap(t);
            let i = (t.floor() as usize).min(self.pieces.len() - 1);
            let (s, a) = (t - i as f64, &self.pieces[i]);
            let mut sum = Point::ZERO;
            for (j, c) in a.iter().enumerate().skip(k) {
                let falling: f64 = (j + 1 - k..=j).map(|x| x as f64).product();
                sum += *c * (falling * s.powi((j - k) as i32));
            }
            sum
        }
        fn polynomial_pieces(&self) -> Option<PolynomialPieces> {
            let breaks = (0..=self.pieces.len()).map(|k| k as f64).collect();
            Some(PolynomialPieces::uniform_continuity(3, breaks, 1))
        }
    }

    /// The shares of the touched cells that were certified and of the queries they held.
    fn certified_shares<C: Curve<2> + Sync>(c: &C, qs: &[Point<2>]) -> (f64, f64) {
        let projector = CurveProjector::new(c, 0.0).unwrap();
        let grid = NearestGrid::new(&projector, qs).unwrap();
        for &q in qs {
            grid.nearest(q);
        }
        let touched: Vec<Cell> = grid.cells.iter().filter_map(|c| c.get().copied()).collect();
        let convex = |c: &Cell| matches!(c, Cell::Convex { .. });
        let cells = touched.iter().filter(|c| convex(c)).count() as f64 / touched.len() as f64;
        let held = qs
            .iter()
            .filter(|q| {
                let mut index = 0;
                for k in 0..2 {
                    let i = (((q[k] - grid.origin[k]) / grid.size) as usize).min(grid.dims[k] - 1);
                    index = index * grid.dims[k] + i;
                }
                grid.cells[index].get().is_some_and(convex)
            })
            .count() as f64
            / qs.len() as f64;
        (cells, held)
    }

    #[test]
    fn cells_near_a_smooth_curve_are_certified() {
        let rose = Rose::new(400);
        let d = rose.domain();
        let qs: Vec<Point<2>> = (0..100_000)
            .map(|k| {
                let t = d.length() * (0.1 + k as f64 * 0.618_033_988_749_894_9).fract();
                let s = (0.37 + k as f64 * 0.618_033_988_749_894_9).fract();
                let (p, d1) = (rose.eval(t), rose.deriv(t, 1));
                p + Point([-d1[1], d1[0]]) * ((0.1 * s - 0.05) / d1.norm())
            })
            .collect();
        let (cells, held) = certified_shares(&rose, &qs);
        assert!(cells > 0.9, "{cells}");
        assert!(held > 0.9, "{held}");
    }

    #[test]
    fn curves_without_pieces_get_no_grid() {
        struct Circle;
        impl Curve<2> for Circle {
            fn domain(&self) -> Interval {
                Interval::new(0.0, TAU)
            }
            fn is_closed(&self) -> bool {
                true
            }
            fn eval(&self, t: f64) -> Point<2> {
                Point([t.cos(), t.sin()])
            }
            fn deriv(&self, t: f64, k: usize) -> Point<2> {
                let (s, c) = t.sin_cos();
                Point(match k % 4 {
                    0 => [c, s],
                    1 => [-s, c],
                    2 => [-c, -s],
                    _ => [s, -c],
                })
            }
        }
        let projector = CurveProjector::new(&Circle, 0.0).unwrap();
        assert!(NearestGrid::new(&projector, &[Point([0.5, 0.5]); 10]).is_none());
    }
}

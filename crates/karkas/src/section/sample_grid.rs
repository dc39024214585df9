//! The coarse grid of cells over the parameter domain: where start points are looked for, and
//! the unit in which the continuation measures parameter steps.
//!
//! Inside this module parameters are in cell units: `s = (u - u_start) / cell`, so `s` runs
//! over `[0, cells]` and whole numbers are grid lines. A closed direction is periodic with
//! period `cells`; tracing keeps `s` unwrapped and wraps only when evaluating.

use crate::core::{Interval, Surface};
use crate::Point;

/// One parameter direction of the grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Axis {
    domain: Interval,
    cells: usize,
    closed: bool,
}

impl Axis {
    pub(crate) fn new(domain: Interval, cells: usize, closed: bool) -> Self {
        Axis {
            domain,
            cells,
            closed,
        }
    }

    /// Number of cells.
    pub(crate) fn cells(&self) -> usize {
        self.cells
    }

    /// True when periodic.
    pub(crate) fn closed(&self) -> bool {
        self.closed
    }

    /// Number of distinct grid lines (vertices along this direction).
    pub(crate) fn vertices(&self) -> usize {
        if self.closed {
            self.cells
        } else {
            self.cells + 1
        }
    }

    /// Parameter length of one cell.
    pub(crate) fn cell(&self) -> f64 {
        self.domain.length() / self.cells as f64
    }

    /// The parameter at cell coordinate `s`: wrapped into the period when closed, clamped to
    /// the domain when open (the domain's ends exactly at `s = 0` and `s = cells`).
    pub(crate) fn param(&self, s: f64) -> f64 {
        let n = self.cells as f64;
        let s = if self.closed {
            s.rem_euclid(n)
        } else {
            s.clamp(0.0, n)
        };
        if s >= n {
            return if self.closed {
                self.domain.start
            } else {
                self.domain.end
            };
        }
        if s <= 0.0 {
            return self.domain.start;
        }
        self.domain.start + self.domain.length() * (s / n)
    }

    /// True when `s` lies in the domain (always, when closed).
    pub(crate) fn contains(&self, s: f64) -> bool {
        self.closed || (0.0..=self.cells as f64).contains(&s)
    }

    /// A difference of cell coordinates brought to the nearest period (closed only).
    pub(crate) fn reduce(&self, ds: f64) -> f64 {
        if self.closed {
            let n = self.cells as f64;
            ds - n * (ds / n).round()
        } else {
            ds
        }
    }

    /// The vertex (grid line) `k`, wrapped when closed; `None` outside an open direction.
    pub(crate) fn vertex(&self, k: i64) -> Option<usize> {
        if self.closed {
            Some(k.rem_euclid(self.cells as i64) as usize)
        } else if (0..=self.cells as i64).contains(&k) {
            Some(k as usize)
        } else {
            None
        }
    }

    /// The cell holding cell coordinate `s` (unwrapped; the last cell holds the far border
    /// of an open direction).
    pub(crate) fn cell_floor(&self, s: f64) -> i64 {
        let k = s.floor() as i64;
        if !self.closed && s == self.cells as f64 {
            k - 1
        } else {
            k
        }
    }

    /// The cell `k`, wrapped when closed; `None` outside an open direction.
    pub(crate) fn cell_index(&self, k: i64) -> Option<usize> {
        if self.closed {
            Some(k.rem_euclid(self.cells as i64) as usize)
        } else if (0..self.cells as i64).contains(&k) {
            Some(k as usize)
        } else {
            None
        }
    }
}

/// Cells per side of a block: the unit in which regions a plane cannot reach are skipped.
pub(crate) const BLOCK: usize = 8;

/// The bounding box of the samples of one block of `BLOCK x BLOCK` cells.
#[derive(Clone, Copy, Debug)]
pub(crate) struct BlockBox<const D: usize> {
    pub(crate) lo: Point<D>,
    pub(crate) hi: Point<D>,
}

/// A border line of an open direction along which the whole line is one point: the nose or
/// tail of a body of revolution, where a row of the grid collapses. Its parameter line is
/// one point in space, so a section through it is the point, not the line; curves that reach
/// it end there and are joined through it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Pole<const D: usize> {
    /// The direction the line is a border of (0 = u, 1 = v): the line is `s[axis] = at`.
    pub(crate) axis: usize,
    /// Its cell coordinate: 0 or the number of cells.
    pub(crate) at: f64,
    /// The point.
    pub(crate) point: Point<D>,
}

/// Largest spread of the samples of a border line (relative to the surface's size) for the
/// line to count as one point: rounding in evaluating the surface, far under any tolerance.
const POLE_SPREAD: f64 = 1e-11;

/// The surface sampled at the grid's vertices, once, for every level function to be cut.
#[derive(Clone, Debug)]
pub(crate) struct SampleGrid<const D: usize> {
    pub(crate) u: Axis,
    pub(crate) v: Axis,
    /// `u.vertices() x v.vertices()` points, `u` outer.
    pub(crate) points: Vec<Point<D>>,
    /// The largest coordinate magnitude of the samples (at least the smallest normal f64).
    pub(crate) scale: f64,
    /// The diagonal of the samples' bounding box.
    pub(crate) diagonal: f64,
    /// Bounding boxes of the blocks, `blocks_u x blocks_v`, `u` outer; a box holding a
    /// non-finite sample is infinite.
    pub(crate) blocks: Vec<BlockBox<D>>,
    /// The border lines that are one point (see [`Pole`]).
    pub(crate) poles: Vec<Pole<D>>,
}

impl<const D: usize> SampleGrid<D> {
    pub(crate) fn new<S: Surface<D> + ?Sized>(surface: &S, cells: (usize, usize)) -> Self {
        let u = Axis::new(surface.domain_u(), cells.0, surface.is_closed_u());
        let v = Axis::new(surface.domain_v(), cells.1, surface.is_closed_v());
        let us: Vec<f64> = (0..u.vertices()).map(|k| u.param(k as f64)).collect();
        let vs: Vec<f64> = (0..v.vertices()).map(|k| v.param(k as f64)).collect();
        let mut points = vec![Point::ZERO; us.len() * vs.len()];
        surface.eval_grid_into(&us, &vs, &mut points);
        let mut lo = Point([f64::INFINITY; D]);
        let mut hi = Point([f64::NEG_INFINITY; D]);
        let mut scale = f64::MIN_POSITIVE;
        for p in points.iter().filter(|p| p.is_finite()) {
            for k in 0..D {
                lo[k] = lo[k].min(p[k]);
                hi[k] = hi[k].max(p[k]);
            }
            scale = scale.max(p.max_abs());
        }
        let diagonal = if lo[0] <= hi[0] {
            (hi - lo).norm()
        } else {
            0.0
        };
        let mut grid = SampleGrid {
            u,
            v,
            points,
            scale,
            diagonal,
            blocks: Vec::new(),
            poles: Vec::new(),
        };
        grid.blocks = grid.block_boxes();
        grid.poles = grid.find_poles(surface);
        grid
    }

    /// The border lines of open directions that are one point: every vertex on the line and
    /// the middle of every cell side along it within [`POLE_SPREAD`] of the size of the
    /// surface from the line's first vertex.
    fn find_poles<S: Surface<D> + ?Sized>(&self, surface: &S) -> Vec<Pole<D>> {
        let mut poles = Vec::new();
        for axis in 0..2 {
            let (this, other) = (self.axis(axis), self.axis(1 - axis));
            if this.closed() {
                continue;
            }
            for at in [0.0, this.cells() as f64] {
                let on_line = |t: f64| {
                    let s = if axis == 0 { [at, t] } else { [t, at] };
                    let (u, v) = self.params(s);
                    surface.eval(u, v)
                };
                let first = on_line(0.0);
                let samples = (0..=2 * other.cells()).map(|k| on_line(0.5 * k as f64));
                if first.is_finite() && self.is_one_point(samples) {
                    poles.push(Pole {
                        axis,
                        at,
                        point: first,
                    });
                }
            }
        }
        poles
    }

    /// True when `points` are one point to rounding (within [`POLE_SPREAD`] of the surface's
    /// size of the first): a curve of them has no length worth reporting.
    pub(crate) fn is_one_point(&self, points: impl IntoIterator<Item = Point<D>>) -> bool {
        let mut points = points.into_iter();
        let Some(first) = points.next() else {
            return true;
        };
        let near = POLE_SPREAD * self.scale;
        points.all(|p| p.distance(first) <= near) // false for NaN
    }

    /// The pole whose line holds cell coordinates `s` (exactly), if any.
    pub(crate) fn pole_at(&self, s: [f64; 2]) -> Option<&Pole<D>> {
        self.poles.iter().find(|p| s[p.axis] == p.at)
    }

    /// Blocks along `u` and `v`.
    pub(crate) fn block_counts(&self) -> (usize, usize) {
        (
            self.u.cells().div_ceil(BLOCK),
            self.v.cells().div_ceil(BLOCK),
        )
    }

    /// The grid lines (vertices) along `axis` owned by block `k`: every vertex belongs to
    /// exactly one block, the last block taking the far border of an open direction.
    pub(crate) fn owned_vertices(axis: &Axis, k: usize) -> core::ops::Range<usize> {
        let blocks = axis.cells().div_ceil(BLOCK);
        let start = k * BLOCK;
        let end = if k + 1 == blocks {
            axis.vertices()
        } else {
            start + BLOCK
        };
        start..end
    }

    /// The cells along `axis` of block `k`.
    pub(crate) fn block_cells(axis: &Axis, k: usize) -> core::ops::Range<usize> {
        k * BLOCK..((k + 1) * BLOCK).min(axis.cells())
    }

    /// The bounding box of each block's samples, its far border lines included (so that it
    /// holds both ends of every edge the block owns).
    fn block_boxes(&self) -> Vec<BlockBox<D>> {
        let (bu, bv) = self.block_counts();
        let nv = self.v.vertices();
        let mut boxes = Vec::with_capacity(bu * bv);
        for bi in 0..bu {
            for bj in 0..bv {
                let mut lo = Point([f64::INFINITY; D]);
                let mut hi = Point([f64::NEG_INFINITY; D]);
                for da in 0..=BLOCK {
                    let Some(a) = self.u.vertex((bi * BLOCK + da) as i64) else {
                        continue;
                    };
                    for db in 0..=BLOCK {
                        let Some(b) = self.v.vertex((bj * BLOCK + db) as i64) else {
                            continue;
                        };
                        let p = self.points[a * nv + b];
                        for k in 0..D {
                            // NaN makes the box infinite: never skipped on a guess.
                            if p[k].is_nan() {
                                lo[k] = f64::NEG_INFINITY;
                                hi[k] = f64::INFINITY;
                            } else {
                                lo[k] = lo[k].min(p[k]);
                                hi[k] = hi[k].max(p[k]);
                            }
                        }
                    }
                }
                boxes.push(BlockBox { lo, hi });
            }
        }
        boxes
    }

    /// The surface parameters at cell coordinates `s`.
    pub(crate) fn params(&self, s: [f64; 2]) -> (f64, f64) {
        (self.u.param(s[0]), self.v.param(s[1]))
    }

    /// True when `s` lies in the domain.
    pub(crate) fn contains(&self, s: [f64; 2]) -> bool {
        self.u.contains(s[0]) && self.v.contains(s[1])
    }

    /// The axis of direction `k` (0 = u, 1 = v).
    pub(crate) fn axis(&self, k: usize) -> &Axis {
        if k == 0 {
            &self.u
        } else {
            &self.v
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cell_coordinates_map_to_the_domain() {
        let open = Axis::new(Interval::new(0.2, 0.8), 6, false);
        assert_eq!(open.param(0.0), 0.2);
        assert_eq!(open.param(6.0), 0.8);
        assert_eq!(open.param(7.0), 0.8);
        assert!((open.param(3.0) - 0.5).abs() < 1e-15);
        assert_eq!(open.vertex(7), None);
        assert_eq!(open.cell_index(6), None);
        let closed = Axis::new(Interval::new(0.2, 0.8), 6, true);
        assert_eq!(closed.param(6.0), 0.2);
        assert!((closed.param(-1.0) - 0.7).abs() < 1e-15);
        assert_eq!(closed.vertex(-1), Some(5));
        assert_eq!(closed.reduce(5.0), -1.0);
        assert_eq!(closed.vertices(), 6);
    }
}

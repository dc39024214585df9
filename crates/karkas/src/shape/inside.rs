//! The inside test of a [`FaceDomain`] with its loops' segments sorted into strips of `v`.
//!
//! [`FaceDomain::contains`] counts the crossings of a ray `+u` from `(u, v)` with every
//! segment of every loop: a face trimmed by many holes, each sampled finely, has tens of
//! thousands of segments, and inspecting points against it tests each of them for every
//! candidate foot. Only segments whose `v` range holds `v` can be crossed, so the segments are
//! kept in strips of equal height in `v` (a segment in every strip its range meets) and a point
//! tests those of its strip only, with the same arithmetic in the same direction: the answers
//! are those of [`FaceDomain::contains`], bit for bit. A plain bucket grid, not a general
//! spatial index crate, because the test needs every segment that meets one horizontal line,
//! which a grid over `v` gives directly.
//!
//! Most points need no segment at all: a grid of cells over the loops' box (`ParityGrid`)
//! marks every cell that the box of a segment, grown by a margin, meets; an unmarked cell
//! holds no point of any loop, so the even-odd count (the parity of the winding number) is
//! the same at all its points and is kept once, found at its centre. It is the same bit for
//! bit, not only in exact arithmetic: every segment is then to one side of the whole cell by
//! the margin, so whether it crosses the ray and lies beyond the point is decided alike for
//! every point of the cell, whatever the rounding of the crossing's `u` (a few ulps of the
//! coordinates, against a margin of `1e-9` of them). Points in marked cells, and outside
//! the grid, take the strips.

use super::FaceDomain;

/// Strips per segment (about eight segments a strip).
const SEGMENTS_PER_STRIP: usize = 8;
/// The most strips.
const MAX_STRIPS: usize = 4096;
/// The most strip entries per segment on average (long segments that span many strips).
const MAX_ENTRIES_PER_SEGMENT: usize = 32;

/// Grid cells per segment (about one cell in four holds a segment on a long loop).
const CELLS_PER_SEGMENT: usize = 16;
/// The most cells along one side of the grid.
const MAX_GRID_SIDE: usize = 1024;
/// The most cells the segments' boxes may mark, per segment on average (a long slanted
/// segment marks a large block); beyond it the face keeps the strips alone.
const MAX_MARKS_PER_SEGMENT: usize = 64;
/// The margin around a segment's box, relative to the largest magnitude of the coordinates:
/// far above the rounding of a crossing's `u`.
const GRID_MARGIN: f64 = 1e-9;

/// A segment of a loop, from `a` (vertex `i`) to `b` (vertex `i - 1`), as the crossing count
/// takes them.
type Segment = [[f64; 2]; 2];

/// [`FaceDomain::contains`] with the segments sorted into strips of `v`.
#[derive(Clone, Debug)]
pub(super) struct InsideIndex {
    u: (f64, f64),
    v: (f64, f64),
    margin: (f64, f64),
    whole: bool,
    /// The lowest `v` of the segments and the strips' count per unit of `v`.
    low: f64,
    scale: f64,
    strips: Vec<Vec<Segment>>,
    /// The answers of the cells no loop comes near (`None`: no grid).
    grid: Option<ParityGrid>,
}

/// What an unmarked cell of a [`ParityGrid`] answers.
#[derive(Clone, Copy, Debug, PartialEq)]
enum CellAnswer {
    Outside,
    Inside,
    /// A segment's box meets the cell: the strips decide.
    Near,
}

/// Cells over the loops' box, each with the even-odd answer of all its points where no
/// segment comes near it (module docs).
#[derive(Clone, Debug)]
struct ParityGrid {
    /// The lowest `u` and `v` of the segments.
    low: [f64; 2],
    /// Cells per unit of `u` and of `v`.
    scale: [f64; 2],
    /// Cells along `u` and along `v`.
    side: [usize; 2],
    /// Cell `(i, j)` at `i * side[1] + j`.
    answers: Vec<CellAnswer>,
}

impl ParityGrid {
    /// The grid over `segments` answered by `index`'s strips; `None` when the segments span no
    /// area or would mark too many cells.
    fn new(segments: &[Segment], index: &InsideIndex) -> Option<ParityGrid> {
        let mut low = [f64::INFINITY; 2];
        let mut high = [f64::NEG_INFINITY; 2];
        for p in segments.iter().flatten() {
            for a in 0..2 {
                low[a] = low[a].min(p[a]);
                high[a] = high[a].max(p[a]);
            }
        }
        let extent = [high[0] - low[0], high[1] - low[1]];
        let finite = segments.iter().flatten().flatten().all(|x| x.is_finite());
        if !(finite && extent[0] > 0.0 && extent[1] > 0.0 && extent.iter().all(|e| e.is_finite())) {
            return None;
        }
        let n = ((CELLS_PER_SEGMENT * segments.len()) as f64).sqrt().ceil() as usize;
        let side = [n.clamp(1, MAX_GRID_SIDE); 2];
        let margin = [0, 1].map(|a| GRID_MARGIN * (low[a].abs() + high[a].abs()));
        let mut grid = ParityGrid {
            low,
            scale: [0, 1].map(|a| side[a] as f64 / extent[a]),
            side,
            answers: vec![CellAnswer::Outside; side[0] * side[1]],
        };
        let mut marks = 0usize;
        for s in segments {
            let mut first = [0usize; 2];
            let mut last = [0usize; 2];
            for a in 0..2 {
                let (lo, hi) = (s[0][a].min(s[1][a]), s[0][a].max(s[1][a]));
                first[a] = grid.clamped(a, lo - margin[a]);
                last[a] = grid.clamped(a, hi + margin[a]);
            }
            marks += (last[0] - first[0] + 1) * (last[1] - first[1] + 1);
            if marks > MAX_MARKS_PER_SEGMENT * segments.len() {
                return None;
            }
            for i in first[0]..=last[0] {
                let row = &mut grid.answers[i * side[1]..(i + 1) * side[1]];
                row[first[1]..=last[1]].fill(CellAnswer::Near);
            }
        }
        grid.answer_free_cells(index);
        Some(grid)
    }

    /// Answers every unmarked cell at its centre (a cell whose centre rounds into another
    /// cell stays to the strips).
    fn answer_free_cells(&mut self, index: &InsideIndex) {
        for i in 0..self.side[0] {
            for j in 0..self.side[1] {
                let k = i * self.side[1] + j;
                if self.answers[k] == CellAnswer::Near {
                    continue;
                }
                let u = self.low[0] + (i as f64 + 0.5) / self.scale[0];
                let v = self.low[1] + (j as f64 + 0.5) / self.scale[1];
                self.answers[k] = if self.cell(0, u) != Some(i) || self.cell(1, v) != Some(j) {
                    CellAnswer::Near
                } else if index.crossings(u, v) {
                    CellAnswer::Inside
                } else {
                    CellAnswer::Outside
                };
            }
        }
    }

    /// The cell along axis `a` (0: `u`, 1: `v`) holding `x`, if the grid does (never for NaN).
    /// Monotone in `x`: a segment whose grown box ends in a lower cell lies below every point
    /// of a higher one.
    fn cell(&self, a: usize, x: f64) -> Option<usize> {
        let k = ((x - self.low[a]) * self.scale[a]).floor();
        (k >= 0.0 && k < self.side[a] as f64).then_some(k as usize)
    }

    /// [`ParityGrid::cell`] clamped to the grid.
    fn clamped(&self, a: usize, x: f64) -> usize {
        let k = ((x - self.low[a]) * self.scale[a]).floor();
        if k >= 0.0 {
            (k as usize).min(self.side[a] - 1)
        } else {
            0
        }
    }

    /// The answer of the cell holding `(u, v)`: `None` outside the grid and where a segment
    /// comes near.
    fn answer(&self, u: f64, v: f64) -> Option<bool> {
        let (i, j) = (self.cell(0, u)?, self.cell(1, v)?);
        match self.answers[i * self.side[1] + j] {
            CellAnswer::Outside => Some(false),
            CellAnswer::Inside => Some(true),
            CellAnswer::Near => None,
        }
    }
}

impl InsideIndex {
    /// The index of `domain`'s loops.
    pub(super) fn new(domain: &FaceDomain) -> InsideIndex {
        let mut segments: Vec<Segment> = Vec::new();
        for l in &domain.loops {
            let p = &l.points;
            let mut j = p.len().saturating_sub(1);
            for i in 0..p.len() {
                segments.push([p[i], p[j]]);
                j = i;
            }
        }
        let (low, high) = segments
            .iter()
            .flat_map(|s| [s[0][1], s[1][1]])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        let mut index = InsideIndex {
            u: (domain.u.start, domain.u.end),
            v: (domain.v.start, domain.v.end),
            margin: (1e-12 * domain.u.length(), 1e-12 * domain.v.length()),
            whole: domain.loops.is_empty(),
            low,
            scale: 0.0,
            strips: vec![Vec::new()],
            grid: None,
        };
        if segments.is_empty() || high <= low || !low.is_finite() || !high.is_finite() {
            index.strips[0] = segments;
            return index;
        }
        let mut count = (segments.len() / SEGMENTS_PER_STRIP).clamp(1, MAX_STRIPS);
        loop {
            index.scale = count as f64 / (high - low);
            let entries: usize = segments
                .iter()
                .map(|s| {
                    let (a, b) = index.span(s);
                    b - a + 1
                })
                .sum();
            if count == 1 || entries <= MAX_ENTRIES_PER_SEGMENT * segments.len() {
                break;
            }
            count /= 2;
        }
        index.strips = vec![Vec::new(); count];
        for s in &segments {
            let (a, b) = index.span(s);
            for strip in &mut index.strips[a..=b] {
                strip.push(*s);
            }
        }
        index.grid = ParityGrid::new(&segments, &index);
        index
    }

    /// The strip holding `v` (clamped to the strips).
    fn strip(&self, v: f64) -> usize {
        let k = ((v - self.low) * self.scale).floor();
        if k >= 0.0 {
            (k as usize).min(self.strips.len() - 1)
        } else {
            0
        }
    }

    /// The first and last strips a segment's `v` range meets.
    fn span(&self, s: &Segment) -> (usize, usize) {
        let (a, b) = (s[0][1].min(s[1][1]), s[0][1].max(s[1][1]));
        (self.strip(a), self.strip(b))
    }

    /// True when `(u, v)` lies in the face: [`FaceDomain::contains`].
    pub(super) fn contains(&self, u: f64, v: f64) -> bool {
        if u < self.u.0 - self.margin.0
            || u > self.u.1 + self.margin.0
            || v < self.v.0 - self.margin.1
            || v > self.v.1 + self.margin.1
        {
            return false;
        }
        if self.whole {
            return true;
        }
        if v.is_nan() {
            return false;
        }
        if let Some(answer) = self.grid.as_ref().and_then(|g| g.answer(u, v)) {
            return answer;
        }
        self.crossings(u, v)
    }

    /// The even-odd count of the crossings of the ray `+u` from `(u, v)` with the loops, from
    /// the segments of `v`'s strip (the rectangle not tested).
    fn crossings(&self, u: f64, v: f64) -> bool {
        let mut inside = false;
        for [a, b] in &self.strips[self.strip(v)] {
            if (a[1] > v) != (b[1] > v) {
                let x = a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if u < x {
                    inside = !inside;
                }
            }
        }
        inside
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Interval;
    use crate::shape::ParameterLoop;

    /// A square with many round holes, finely sampled, and a long thin zigzag.
    fn domain() -> FaceDomain {
        let mut loops = vec![ParameterLoop {
            points: vec![[0.0, 0.0], [10.0, 0.0], [10.0, 8.0], [0.0, 8.0]],
        }];
        for i in 0..5 {
            for j in 0..4 {
                let (cu, cv, r) = (
                    1.0 + 2.0 * i as f64,
                    1.0 + 2.0 * j as f64,
                    0.3 + 0.1 * j as f64,
                );
                let n = 200 + 37 * i;
                loops.push(ParameterLoop {
                    points: (0..n)
                        .map(|k| {
                            let t = -std::f64::consts::TAU * k as f64 / n as f64;
                            [cu + r * t.cos(), cv + r * t.sin()]
                        })
                        .collect(),
                });
            }
        }
        loops.push(ParameterLoop {
            points: (0..60)
                .map(|k| [0.05 + 0.15 * k as f64, if k % 2 == 0 { 0.01 } else { 7.9 }])
                .chain([[9.0, 7.95], [0.05, 7.95]])
                .collect(),
        });
        FaceDomain {
            u: Interval::new(0.0, 10.0),
            v: Interval::new(0.0, 8.0),
            loops,
        }
    }

    #[test]
    fn the_index_answers_as_the_domain_does() {
        let d = domain();
        let index = InsideIndex::new(&d);
        assert!(index.strips.len() > 1);
        let mut inside = 0;
        let mut state = 12345u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..200_000 {
            let (u, v) = (-0.5 + 11.0 * next(), -0.5 + 9.0 * next());
            assert_eq!(index.contains(u, v), d.contains(u, v), "({u}, {v})");
            inside += usize::from(d.contains(u, v));
        }
        // Vertices, their v exactly, and the rectangle's border.
        for l in &d.loops {
            for p in &l.points {
                for (u, v) in [(p[0], p[1]), (p[0] - 1e-3, p[1]), (0.0, p[1]), (10.0, p[1])] {
                    assert_eq!(index.contains(u, v), d.contains(u, v), "({u}, {v})");
                }
            }
        }
        assert!(inside > 1000 && inside < 199_000, "{inside}");
        // Without the zigzag (whose long slanted segments mark most cells), most of the
        // rectangle is answered by the grid of cells alone.
        let mut holes = d.clone();
        holes.loops.pop();
        let holes_index = InsideIndex::new(&holes);
        let grid = holes_index.grid.as_ref().expect("a grid over the loops");
        let free = grid
            .answers
            .iter()
            .filter(|&&a| a != CellAnswer::Near)
            .count();
        assert!(
            free * 2 > grid.answers.len(),
            "{free} of {}",
            grid.answers.len()
        );
        for _ in 0..20_000 {
            let (u, v) = (-0.5 + 11.0 * next(), -0.5 + 9.0 * next());
            assert_eq!(
                holes_index.contains(u, v),
                holes.contains(u, v),
                "({u}, {v})"
            );
        }
        let whole = FaceDomain { loops: vec![], ..d };
        let index = InsideIndex::new(&whole);
        assert!(index.contains(5.0, 5.0) && !index.contains(11.0, 5.0));
    }

    #[test]
    fn points_a_rounding_step_from_the_loops_and_the_cells_answer_as_the_domain_does() {
        for offset in [[0.0, 0.0], [1e6, -3e5], [-7.25, 1e-3]] {
            let mut d = domain();
            for l in &mut d.loops {
                for p in &mut l.points {
                    (p[0], p[1]) = (p[0] + offset[0], p[1] + offset[1]);
                }
            }
            d.u = Interval::new(d.u.start + offset[0], d.u.end + offset[0]);
            d.v = Interval::new(d.v.start + offset[1], d.v.end + offset[1]);
            let index = InsideIndex::new(&d);
            let grid = index.grid.as_ref().expect("a grid over the loops");
            let mut checked = 0;
            let mut check = |u: f64, v: f64| {
                assert_eq!(
                    index.contains(u, v),
                    d.contains(u, v),
                    "{offset:?}: ({u}, {v})"
                );
                checked += 1;
            };
            // Along every segment, and a few rounding steps and 1e-12 of the size off it.
            for l in &d.loops {
                let p = &l.points;
                for i in 0..p.len() {
                    let (a, b) = (p[i], p[(i + 1) % p.len()]);
                    for t in [0.0, 0.3, 0.5, 0.99] {
                        let (u, v) = (a[0] + t * (b[0] - a[0]), a[1] + t * (b[1] - a[1]));
                        for (du, dv) in [(0.0, 0.0), (1e-11, 0.0), (-1e-11, 0.0), (0.0, 1e-11)] {
                            check(u + du, v + dv);
                        }
                        check(u.next_up(), v);
                        check(u.next_down(), v.next_up());
                        check(u, v.next_down());
                    }
                }
            }
            // The cells' borders and corners, and a step either side of them.
            for i in 0..=grid.side[0] {
                for j in (0..=grid.side[1]).step_by(7) {
                    let u = grid.low[0] + i as f64 / grid.scale[0];
                    let v = grid.low[1] + j as f64 / grid.scale[1];
                    for (u, v) in [(u, v), (u.next_down(), v), (u, v.next_up()), (u, v + 0.01)] {
                        check(u, v);
                    }
                }
            }
            assert!(checked > 50_000, "{checked}");
        }
    }
}

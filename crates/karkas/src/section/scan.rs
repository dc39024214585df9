//! Finding every piece of a level set: start points on the edges of the coarse grid, and the
//! bookkeeping that traces each piece once.
//!
//! The level function is evaluated at every grid vertex (on the points sampled once). An edge
//! whose ends differ in sign is crossed by the level set; its crossing, found by the Illinois
//! variant of regula falsi, starts a trace unless a piece already traced passes through it.
//! "Passes through" is decided twice: every grid edge a traced chord crosses is marked, and
//! every chord is filed under the cells it spans, so that a start point within the tolerance of
//! a filed chord is recognised even when the chord cuts the corner of a different edge.
//!
//! A piece is found when it crosses at least one grid edge with a sign change: a closed loop
//! inside one cell, or a piece that leaves a cell through the edge it entered, is missed. The
//! grid must be finer than the smallest loop to be found (the `cells` option).

use super::chords::split_chords;
use super::lines::SHORTEST_CHORD;
use super::plane::LevelFunction;
use super::result::{SectionCurve, SectionWarning};
use super::sample_grid::SampleGrid;
use super::trace::{distance_to_segment, Ending, Node, Tracer};
use crate::core::Surface;
use crate::Point;
use std::collections::HashMap;

/// Iterations of the edge root search (it converges far sooner).
const ROOT_ITERATIONS: usize = 100;

/// How far from a pole on the level set (in cells along an edge) the level function is taken
/// in its place: at the pole it vanishes whichever way the curves leave it, while this close
/// to it its sign tells on which side of the curves the edge starts.
const POLE_OFFSET: f64 = 1e-6;

/// One grid edge: from vertex `(a, b)` one step along `u` (`along_v == false`) or `v`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Edge {
    a: usize,
    b: usize,
    along_v: bool,
}

/// A grid edge the level set crosses: between the fractions `t[0]` and `t[1]` of the edge
/// (0 and 1 but next to a pole) the level function goes from `g[0]` to `g[1]`, of opposite
/// signs.
#[derive(Clone, Copy, Debug)]
struct Crossing {
    edge: Edge,
    t: [f64; 2],
    g: [f64; 2],
}

/// Marks of traced pieces on the grid.
struct Visited<const D: usize> {
    /// One flag per edge: u-edges first (`a * v_vertices + b`), then v-edges.
    edges: Vec<bool>,
    /// Traced chords by cell `(a, b)`.
    cells: HashMap<(usize, usize), Vec<(Point<D>, Point<D>)>>,
}

/// Traces every piece of the level set of `tracer.level`.
///
/// The crossed edges are found block by block; a block whose bounding box the level function
/// cannot vanish in (when it can tell, [`LevelFunction::range_over_box`]) is skipped whole.
pub(crate) fn trace_all<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize>(
    tracer: &Tracer<'_, S, F, D>,
) -> (Vec<SectionCurve<D>>, Vec<SectionWarning>) {
    let grid = tracer.grid;
    let (nu, nv) = (grid.u.vertices(), grid.v.vertices());
    let u_edges = grid.u.cells() * nv;
    let mut visited = Visited {
        edges: vec![false; u_edges + nu * grid.v.cells()],
        cells: HashMap::new(),
    };
    let edge_index = |e: Edge| {
        if e.along_v {
            u_edges + e.a * grid.v.cells() + e.b
        } else {
            e.a * nv + e.b
        }
    };
    let near = 4.0 * tracer.tolerance + 1e-9 * grid.scale;
    let mut curves = Vec::new();
    let mut warnings = Vec::new();
    let mut pieces = Vec::new();
    let crossings = crossed_edges(tracer);
    for crossing in crossings {
        let edge = crossing.edge;
        if visited.edges[edge_index(edge)] {
            continue;
        }
        let s = edge_root(tracer, crossing);
        let Some((seed, _)) = tracer.correct(s, None) else {
            continue;
        };
        if grid.pole_at(seed.s).is_some() || visited.near(grid, seed.s, seed.point, near) {
            // A seed at a pole is the pole: the curves through it are found from their
            // crossings off the pole.
            visited.edges[edge_index(edge)] = true;
            continue;
        }
        let (nodes, closed, stops) = trace_piece(tracer, &seed);
        let nodes = split_far_chords(tracer, nodes, closed);
        warnings.extend(stops);
        visited.edges[edge_index(edge)] = true;
        visited.file(grid, &nodes, closed, &edge_index);
        pieces.push((nodes, closed));
    }
    join_at_poles(tracer, &mut pieces, &mut warnings);
    for (nodes, closed) in &pieces {
        if nodes.len() >= 2 && !grid.is_one_point(nodes.iter().map(|n| n.point)) {
            curves.push(to_curve(grid, nodes, *closed));
        }
    }
    (curves, warnings)
}

/// Splits the chords of a traced piece that stray farther than the tolerance from the section
/// (see `chords.rs`): the point between two nodes is their parameters' middle (or quarter)
/// brought onto the level set by Newton's method.
fn split_far_chords<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize>(
    tracer: &Tracer<'_, S, F, D>,
    nodes: Vec<Node<D>>,
    closed: bool,
) -> Vec<Node<D>> {
    let grid = tracer.grid;
    let on_arc = |a: &[f64; 2], b: &[f64; 2], t: f64| {
        let s = [
            a[0] + t * grid.u.reduce(b[0] - a[0]),
            a[1] + t * grid.v.reduce(b[1] - a[1]),
        ];
        let (probe, _) = tracer.correct(s, None)?;
        let inside = grid.contains(probe.s) && grid.pole_at(probe.s).is_none();
        inside.then_some((probe.s, probe.point))
    };
    let shortest = SHORTEST_CHORD * grid.scale;
    let nodes = nodes.into_iter().map(|n| (n.s, n.point)).collect();
    split_chords(nodes, closed, tracer.tolerance, shortest, &on_arc)
        .into_iter()
        .map(|(s, point)| Node { s, point })
        .collect()
}

/// Joins the pieces that end at the same pole (a collapsed border line, [`Pole`]): the
/// section of a body through its nose is one curve through the nose, which the parameter
/// plane splits into pieces ending on the pole line at different parameters. Two ends at a
/// pole are joined into one curve (a piece with both ends there is closed); more ends are
/// left apart (the curve crosses itself there). A pole on the level set that no piece
/// reaches is a point where the plane touches the surface, and is reported.
///
/// [`Pole`]: super::sample_grid::Pole
fn join_at_poles<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize>(
    tracer: &Tracer<'_, S, F, D>,
    pieces: &mut Vec<(Vec<Node<D>>, bool)>,
    warnings: &mut Vec<SectionWarning>,
) {
    let grid = tracer.grid;
    for pole in &grid.poles {
        let at_pole = |n: &Node<D>| n.s[pole.axis] == pole.at;
        let mut ends = Vec::new();
        for (k, (nodes, closed)) in pieces.iter().enumerate() {
            if *closed || nodes.len() < 2 {
                continue;
            }
            if at_pole(&nodes[0]) {
                ends.push((k, false));
            }
            if at_pole(&nodes[nodes.len() - 1]) {
                ends.push((k, true));
            }
        }
        match ends[..] {
            [] if tracer.level.value(pole.point).abs() <= tracer.acceptable => {
                let mut s = [0.0; 2];
                s[pole.axis] = pole.at;
                let (u, v) = grid.params(s);
                warnings.push(SectionWarning::SingularPoint { u, v });
            }
            [(k, _), (j, _)] if k == j => {
                let (nodes, closed) = &mut pieces[k];
                nodes.pop(); // the pole again
                *closed = true;
            }
            [(k, k_last), (j, j_last)] => {
                let mut first = core::mem::take(&mut pieces[k].0);
                let mut second = core::mem::take(&mut pieces[j].0);
                if !k_last {
                    first.reverse();
                }
                if j_last {
                    second.reverse();
                }
                first.extend(second.into_iter().skip(1)); // the pole once
                pieces[k].0 = first;
                pieces.remove(j);
            }
            _ => {}
        }
    }
}

/// The grid edges whose ends differ in sign (NaN is no sign change; zero counts as positive),
/// with the values at their ends.
///
/// An edge along a pole line (a collapsed border, one point) crosses nothing. An edge from a
/// pole on the level set takes the level function [`POLE_OFFSET`] off the pole instead of at
/// it (where it vanishes, with the sign of its rounding).
fn crossed_edges<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize>(
    tracer: &Tracer<'_, S, F, D>,
) -> Vec<Crossing> {
    let grid = tracer.grid;
    let level = tracer.level;
    let (nu, nv) = (grid.u.vertices(), grid.v.vertices());
    let value = |a: usize, b: usize| level.value(grid.points[a * nv + b]);
    let crossed = |g0: f64, g1: f64| g0.is_finite() && g1.is_finite() && (g0 < 0.0) != (g1 < 0.0);
    // Poles on the level set, by direction: `on_level[axis]` lists their lines.
    let mut on_level: [Vec<f64>; 2] = [Vec::new(), Vec::new()];
    for pole in &grid.poles {
        if level.value(pole.point).abs() <= tracer.acceptable {
            on_level[pole.axis].push(pole.at);
        }
    }
    let on_pole_line = |axis: usize, k: usize| {
        grid.poles
            .iter()
            .any(|p| p.axis == axis && p.at == k as f64)
    };
    // The crossing of an edge from vertex (a, b) to (a1, b1) along direction `axis`.
    let crossing = |edge: Edge, axis: usize, from: usize, ends: [(usize, usize); 2]| {
        let mut t = [0.0, 1.0];
        let mut g = [value(ends[0].0, ends[0].1), value(ends[1].0, ends[1].1)];
        for (end, offset) in [(0, POLE_OFFSET), (1, -POLE_OFFSET)] {
            let line = (from + end) as f64;
            if on_level[axis].contains(&line) {
                t[end] += offset;
                let mut s = [edge.a as f64, edge.b as f64];
                s[axis] += t[end];
                g[end] = tracer.value(s);
            }
        }
        crossed(g[0], g[1]).then_some(Crossing { edge, t, g })
    };
    let (blocks_u, blocks_v) = grid.block_counts();
    let mut crossings = Vec::new();
    for bi in 0..blocks_u {
        for bj in 0..blocks_v {
            let block = grid.blocks[bi * blocks_v + bj];
            if let Some((lowest, highest)) = level.range_over_box(block.lo, block.hi) {
                if lowest >= 0.0 || highest < 0.0 {
                    continue;
                }
            }
            let (cells_u, cells_v) = (
                SampleGrid::<D>::block_cells(&grid.u, bi),
                SampleGrid::<D>::block_cells(&grid.v, bj),
            );
            let (lines_u, lines_v) = (
                SampleGrid::<D>::owned_vertices(&grid.u, bi),
                SampleGrid::<D>::owned_vertices(&grid.v, bj),
            );
            // Edges along u start on the block's cells in u and its lines in v.
            for a in cells_u.clone() {
                let a1 = if a + 1 == nu { 0 } else { a + 1 };
                for b in lines_v.clone().filter(|&b| !on_pole_line(1, b)) {
                    let edge = Edge {
                        a,
                        b,
                        along_v: false,
                    };
                    crossings.extend(crossing(edge, 0, a, [(a, b), (a1, b)]));
                }
            }
            for a in lines_u.filter(|&a| !on_pole_line(0, a)) {
                for b in cells_v.clone() {
                    let b1 = if b + 1 == nv { 0 } else { b + 1 };
                    let edge = Edge {
                        a,
                        b,
                        along_v: true,
                    };
                    crossings.extend(crossing(edge, 1, b, [(a, b), (a, b1)]));
                }
            }
        }
    }
    crossings
}

/// Traces the piece through `seed` both ways: forward until it closes or ends, then backward.
fn trace_piece<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize>(
    tracer: &Tracer<'_, S, F, D>,
    seed: &super::trace::Probe<D>,
) -> (Vec<Node<D>>, bool, Vec<SectionWarning>) {
    let mut warnings = Vec::new();
    let mut forward = vec![seed.node()];
    let ending = tracer.trace(seed, 1.0, true, &mut forward, &mut warnings);
    if ending == Ending::Closed {
        return (forward, true, warnings);
    }
    if let Ending::Stopped(w) = ending {
        warnings.push(w);
    }
    let mut backward = vec![seed.node()];
    if let Ending::Stopped(w) = tracer.trace(seed, -1.0, false, &mut backward, &mut warnings) {
        warnings.push(w);
    }
    backward.reverse();
    backward.pop(); // the seed, first of `forward`
    backward.extend(forward);
    (backward, false, warnings)
}

/// The crossing of the level set on an edge, in cell coordinates.
fn edge_root<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize>(
    tracer: &Tracer<'_, S, F, D>,
    crossing: Crossing,
) -> [f64; 2] {
    let edge = crossing.edge;
    let at = |t: f64| {
        if edge.along_v {
            [edge.a as f64, edge.b as f64 + t]
        } else {
            [edge.a as f64 + t, edge.b as f64]
        }
    };
    // Illinois: regula falsi that halves the retained end's value when it is kept twice.
    let ([mut t0, mut t1], [mut f0, mut f1]) = (crossing.t, crossing.g);
    for _ in 0..ROOT_ITERATIONS {
        if f1.abs() <= tracer.converged || (t1 - t0).abs() <= 1e-15 {
            break;
        }
        let t = (t1 - f1 * (t1 - t0) / (f1 - f0)).clamp(t0.min(t1), t0.max(t1));
        let f = tracer.value(at(t));
        if !f.is_finite() {
            break;
        }
        if (f < 0.0) != (f1 < 0.0) {
            t0 = t1;
            f0 = f1;
        } else {
            f0 *= 0.5;
        }
        t1 = t;
        f1 = f;
    }
    at(t1)
}

/// A traced piece as the public curve type (wrapped parameters).
fn to_curve<const D: usize>(
    grid: &SampleGrid<D>,
    nodes: &[Node<D>],
    closed: bool,
) -> SectionCurve<D> {
    SectionCurve {
        params: nodes.iter().map(|n| grid.params(n.s)).collect(),
        points: nodes.iter().map(|n| n.point).collect(),
        closed,
    }
}

impl<const D: usize> Visited<D> {
    /// True when `point` (at cell coordinates `s`) lies within `near` of a filed chord.
    fn near(&self, grid: &SampleGrid<D>, s: [f64; 2], point: Point<D>, near: f64) -> bool {
        let (ca, cb) = (grid.u.cell_floor(s[0]), grid.v.cell_floor(s[1]));
        for da in -1..=1 {
            for db in -1..=1 {
                let (Some(a), Some(b)) = (grid.u.cell_index(ca + da), grid.v.cell_index(cb + db))
                else {
                    continue;
                };
                if let Some(chords) = self.cells.get(&(a, b)) {
                    if chords
                        .iter()
                        .any(|&(p, q)| distance_to_segment(point, p, q) <= near)
                    {
                        return true;
                    }
                }
            }
        }
        false
    }

    /// Files the chords of a traced piece under their cells and marks the edges they cross.
    fn file(
        &mut self,
        grid: &SampleGrid<D>,
        nodes: &[Node<D>],
        closed: bool,
        edge_index: &impl Fn(Edge) -> usize,
    ) {
        let closing = closed.then(|| (nodes[nodes.len() - 1], nodes[0]));
        let chords = nodes
            .windows(2)
            .map(|w| (w[0], w[1]))
            .chain(closing.map(|(a, b)| {
                // The closing chord in the unwrapped coordinates of its start.
                let s = [
                    a.s[0] + grid.u.reduce(b.s[0] - a.s[0]),
                    a.s[1] + grid.v.reduce(b.s[1] - a.s[1]),
                ];
                (a, Node { s, point: b.point })
            }));
        for (p, q) in chords {
            let lo = [p.s[0].min(q.s[0]), p.s[1].min(q.s[1])];
            let hi = [p.s[0].max(q.s[0]), p.s[1].max(q.s[1])];
            for ca in grid.u.cell_floor(lo[0])..=grid.u.cell_floor(hi[0]) {
                for cb in grid.v.cell_floor(lo[1])..=grid.v.cell_floor(hi[1]) {
                    if let (Some(a), Some(b)) = (grid.u.cell_index(ca), grid.v.cell_index(cb)) {
                        self.cells
                            .entry((a, b))
                            .or_default()
                            .push((p.point, q.point));
                    }
                }
            }
            self.mark_crossed_edges(grid, p.s, q.s, edge_index);
        }
    }

    /// Marks the grid edges crossed by the chord from `p` to `q` (cell coordinates).
    fn mark_crossed_edges(
        &mut self,
        grid: &SampleGrid<D>,
        p: [f64; 2],
        q: [f64; 2],
        edge_index: &impl Fn(Edge) -> usize,
    ) {
        for k in 0..2 {
            let (lo, hi) = (p[k].min(q[k]), p[k].max(q[k]));
            if hi - lo <= 0.0 {
                continue;
            }
            for line in lo.ceil() as i64..=hi.floor() as i64 {
                let t = (line as f64 - p[k]) / (q[k] - p[k]);
                let other = p[1 - k] + t * (q[1 - k] - p[1 - k]);
                // Grid line `line` of direction k is made of edges along the other direction.
                let (vertex, cell) = if k == 0 {
                    (
                        grid.u.vertex(line),
                        grid.v.cell_index(grid.v.cell_floor(other)),
                    )
                } else {
                    (
                        grid.v.vertex(line),
                        grid.u.cell_index(grid.u.cell_floor(other)),
                    )
                };
                let (Some(vertex), Some(cell)) = (vertex, cell) else {
                    continue;
                };
                let edge = if k == 0 {
                    Edge {
                        a: vertex,
                        b: cell,
                        along_v: true,
                    }
                } else {
                    Edge {
                        a: cell,
                        b: vertex,
                        along_v: false,
                    }
                };
                self.edges[edge_index(edge)] = true;
            }
        }
    }
}

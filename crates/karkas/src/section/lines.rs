//! The fast path of sections (Aulchenko et al., formula (21)): when the surface reports its level set
//! as whole parameter lines, each line is sampled into a polyline, finely enough that no chord
//! strays from the line by more than the tolerance.
//!
//! Sampling starts from the grid's vertices along the line and halves every interval whose
//! midpoint lies farther than the tolerance from its chord (at most [`MAX_DEPTH`] times), so a
//! line costs `O(cells + refinements)` evaluations; then every chord is measured against the
//! line at three points and split where it strays farther (see `chords.rs`).

use super::chords::split_chords;
use super::result::SectionCurve;
use super::sample_grid::{Axis, SampleGrid};
use crate::core::{ParameterLine, Surface};
use crate::Point;

/// Most halvings of one interval.
const MAX_DEPTH: usize = 24;

/// The polyline of one parameter line.
pub(crate) fn sample_line<S: Surface<D> + ?Sized, const D: usize>(
    surface: &S,
    grid: &SampleGrid<D>,
    line: ParameterLine,
    tolerance: f64,
) -> SectionCurve<D> {
    let (axis, fixed, along_u) = match line {
        ParameterLine::U(u) => (&grid.v, u, false),
        ParameterLine::V(v) => (&grid.u, v, true),
    };
    let eval = |t: f64| {
        if along_u {
            surface.eval(t, fixed)
        } else {
            surface.eval(fixed, t)
        }
    };
    let nodes = sample_params(axis, &eval, tolerance)
        .into_iter()
        .map(|s| (s, eval(axis.param(s))))
        .collect();
    let on_arc = |&a: &f64, &b: &f64, t: f64| {
        let s = a + t * axis.reduce(b - a);
        Some((s, eval(axis.param(s))))
    };
    let shortest = SHORTEST_CHORD * grid.scale;
    let nodes = split_chords(nodes, axis.closed(), tolerance, shortest, &on_arc);
    let params = nodes
        .iter()
        .map(|&(s, _)| {
            let t = axis.param(s);
            if along_u {
                (t, fixed)
            } else {
                (fixed, t)
            }
        })
        .collect();
    SectionCurve {
        params,
        points: nodes.into_iter().map(|(_, p)| p).collect(),
        closed: axis.closed(),
    }
}

/// Chords shorter than this (relative to the surface's size) are not split: they are at the
/// rounding of the points.
pub(crate) const SHORTEST_CHORD: f64 = 1e-12;

/// Cell coordinates along `axis`, refined until every chord's midpoint is within `tolerance`
/// of the curve.
fn sample_params<const D: usize>(
    axis: &Axis,
    eval: &impl Fn(f64) -> Point<D>,
    tolerance: f64,
) -> Vec<f64> {
    let coarse: Vec<f64> = (0..=axis.cells()).map(|k| k as f64).collect();
    let mut out = Vec::with_capacity(2 * coarse.len());
    let mut previous = (coarse[0], eval(axis.param(coarse[0])));
    out.push(previous.0);
    for &s in &coarse[1..] {
        let next = (s, eval(axis.param(s)));
        refine(axis, eval, previous, next, tolerance, MAX_DEPTH, &mut out);
        out.push(s);
        previous = next;
    }
    if axis.closed() {
        out.pop(); // s = cells is s = 0 again
    }
    out
}

/// Adds the cell coordinates strictly between `a` and `b` needed to follow the curve.
fn refine<const D: usize>(
    axis: &Axis,
    eval: &impl Fn(f64) -> Point<D>,
    a: (f64, Point<D>),
    b: (f64, Point<D>),
    tolerance: f64,
    depth: usize,
    out: &mut Vec<f64>,
) {
    let s = 0.5 * (a.0 + b.0);
    let m = (s, eval(axis.param(s)));
    let deviation = m.1.distance(a.1.lerp(b.1, 0.5));
    let too_far = deviation > tolerance; // false for NaN: nothing to refine
    if depth == 0 || !too_far {
        return;
    }
    refine(axis, eval, a, m, tolerance, depth - 1, out);
    out.push(s);
    refine(axis, eval, m, b, tolerance, depth - 1, out);
}

//! The chord error made a bound: after a section curve is traced (or sampled along a
//! parameter line, formula (21)), every chord is measured against the true section arc it
//! spans and halved until it is within the tolerance (Aulchenko et al., §1.4 of
//! docs/methods.md).
//!
//! The arc between two points of a polyline is found from their parameters: the parameter
//! point a fraction `t` of the way between them is brought onto the section (by the caller:
//! Newton's method onto the level set for a traced curve, nothing for a parameter line, which
//! is all section). The distance from the chord is measured at `t = k / 8`, `k = 1..7`: its
//! largest value `d`, plus what the arc can stray between two measured points, estimated from
//! the second differences `D` of the distances (a sub-arc deviates from its own chord by
//! `|D| / 8`, the parabola through three measurements; the ends count as distance 0), is the
//! chord error `d + max |D| / 8`. A chord whose error exceeds the tolerance is split at the
//! point of `t = 1/2` and both halves measured again. The step control of the trace already
//! aims at the tolerance, so few chords are split.

use super::trace::distance_to_segment;
use crate::Point;

/// Most halvings of one chord.
const MAX_DEPTH: usize = 24;

/// The measured points per chord: `t = k / (MEASURED + 1)`.
const MEASURED: usize = 7;

/// The order in which they are measured: the middle first (where the error usually peaks, and
/// where the chord is split), then the quarters, then the rest.
const ORDER: [usize; MEASURED] = [4, 2, 6, 1, 3, 5, 7];

/// Splits the chords of the polyline `nodes` (closed: the last joins the first) until each
/// lies within `tolerance` of the section arc it spans.
///
/// `on_arc(a, b, t)` is the point of the section between the nodes of parameters `a` and `b`
/// at the fraction `t` (its parameters and point), `None` where it cannot be found: a chord
/// whose arc points cannot be found, or lie farther from either end than the chord's length
/// (another branch of the section, not this arc), is left as it is; so is a chord shorter than
/// `shortest`.
pub(crate) fn split_chords<P: Copy, const D: usize>(
    nodes: Vec<(P, Point<D>)>,
    closed: bool,
    tolerance: f64,
    shortest: f64,
    on_arc: &impl Fn(&P, &P, f64) -> Option<(P, Point<D>)>,
) -> Vec<(P, Point<D>)> {
    if nodes.len() < 2 {
        return nodes;
    }
    let mut out = Vec::with_capacity(nodes.len() + nodes.len() / 8);
    let closing = closed.then(|| (nodes[nodes.len() - 1], nodes[0]));
    out.push(nodes[0]);
    for w in nodes.windows(2) {
        split(w[0], w[1], tolerance, shortest, on_arc, MAX_DEPTH, &mut out);
        out.push(w[1]);
    }
    if let Some((last, first)) = closing {
        split(
            last, first, tolerance, shortest, on_arc, MAX_DEPTH, &mut out,
        );
    }
    out
}

/// Adds the points strictly between `a` and `b` that bring their chords within `tolerance`.
fn split<P: Copy, const D: usize>(
    a: (P, Point<D>),
    b: (P, Point<D>),
    tolerance: f64,
    shortest: f64,
    on_arc: &impl Fn(&P, &P, f64) -> Option<(P, Point<D>)>,
    depth: usize,
    out: &mut Vec<(P, Point<D>)>,
) {
    let length = a.1.distance(b.1);
    let long_enough = length > shortest; // false for NaN
    if depth == 0 || !long_enough {
        return;
    }
    // distances[k] at t = k / 8; the ends are on the arc.
    let mut distances = [0.0f64; MEASURED + 2];
    let mut middle = None;
    for k in ORDER {
        let t = k as f64 / (MEASURED + 1) as f64;
        let Some(q) = on_arc(&a.0, &b.0, t) else {
            return;
        };
        let on_this_arc = q.1.distance(a.1) <= length && q.1.distance(b.1) <= length;
        if !on_this_arc {
            return;
        }
        distances[k] = distance_to_segment(q.1, a.1, b.1);
        if k == ORDER[0] {
            middle = Some(q);
        }
        if distances[k] > tolerance {
            break; // split at once
        }
    }
    let largest = distances.iter().fold(0.0f64, |m, &d| m.max(d));
    let between = distances
        .windows(3)
        .map(|w| (w[0] - 2.0 * w[1] + w[2]).abs() / 8.0)
        .fold(0.0f64, f64::max);
    let too_far = largest + between > tolerance; // false for NaN
    let Some(m) = middle.filter(|_| too_far) else {
        return;
    };
    split(a, m, tolerance, shortest, on_arc, depth - 1, out);
    out.push(m);
    split(m, b, tolerance, shortest, on_arc, depth - 1, out);
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point;

    /// The unit circle by angle: a chord between angles `a` and `b` deviates by
    /// `1 - cos((b - a) / 2)`; after splitting, every chord is within the tolerance.
    #[test]
    fn chords_of_a_circle_are_split_to_the_tolerance() {
        let on_circle = |t: f64| (t, Point([t.cos(), t.sin()]));
        let nodes: Vec<_> = (0..4).map(|k| on_circle(k as f64 * 1.5)).collect();
        let tolerance = 1e-4;
        let on_arc = |a: &f64, b: &f64, t: f64| Some(on_circle(a + t * (b - a)));
        let out = split_chords(nodes, false, tolerance, 0.0, &on_arc);
        for w in out.windows(2) {
            let deviation = 1.0 - (0.5 * (w[1].0 - w[0].0)).cos();
            assert!(deviation <= tolerance, "{deviation:e}");
            assert!(w[1].0 > w[0].0);
        }
        // No chord was split needlessly: each is more than a fifth of the tolerance off.
        assert!(out
            .windows(2)
            .all(|w| 1.0 - (0.5 * (w[1].0 - w[0].0)).cos() > 0.2 * tolerance));
    }
}

//! The curvature extrema the points demand, and the sign of `dκ/ds` between them
//! (docs/methods.md §8, "shape").
//!
//! The least-energy curve in the tolerance band touches the band's sides where the points
//! push it, and between touches its curvature may ripple: small extrema that no point
//! demands. After the energy is minimized, the extrema of the curvature (sign changes of
//! `dκ/ds` over the quadrature nodes) are simplified by persistence: an adjacent pair of
//! extrema, or an extremum and the open curve's end next to it, is dropped while the bump it
//! makes moves the curve by less than the tolerance, the cheapest first. The move of a bump of
//! height `Δκ` over a length `ℓ` is taken as `Δκ ℓ^2 / 8` (the sagitta of a turn of `Δκ ℓ`).
//! The extrema left are demanded by the points; between them `dκ/ds` must keep one sign,
//! which the solver then asks of every quadrature node (a penalty on the wrong sign) except
//! those of the spans next to a kept extremum, where the crossing may move.

use super::objective::NODES_PER_SPAN;

/// Nodes on each side of a kept extremum left free to carry its crossing.
const FREE_NODES: usize = NODES_PER_SPAN + 2;

/// One curvature extremum: its node (the first node after the sign change) and curvature.
#[derive(Clone, Copy, Debug)]
struct Extremum {
    node: usize,
    curvature: f64,
}

/// The sign `dκ/ds` must have at every node (`+1`, `-1`, or `0` where it is free), from the
/// samples of `κ`, `dκ/ds` (any positive multiple) and arc position `s` at the nodes, for the
/// tolerance `tolerance`; and the number of extrema kept. `None` when nothing is to change
/// (no extremum is dropped).
pub(crate) fn demanded_signs(
    curvature: &[f64],
    rate: &[f64],
    s: &[f64],
    length: f64,
    tolerance: f64,
    closed: bool,
) -> Option<(Vec<i8>, usize)> {
    let plot = Plot {
        curvature,
        s,
        length,
        closed,
        nodes: rate.len(),
    };
    let mut extrema = rate_sign_changes(curvature, rate, closed);
    let found = extrema.len();
    // Persistence: drop the cheapest pair (or end extremum) while it moves less than T.
    while let Some(drop) = plot.cheapest_drop(&extrema).filter(|d| d.cost < tolerance) {
        drop.apply(&mut extrema);
    }
    if extrema.len() == found || (closed && extrema.len() < 2) {
        // Nothing dropped, or a closed curve left without the two extrema it must have.
        return None;
    }
    extrema.sort_by_key(|e| e.node);
    Some((plot.signs(&extrema), extrema.len()))
}

/// The extrema of the curvature: the sign changes of the rate, skipping near-zero samples
/// (and, on a closed curve, the change across the seam, put first).
fn rate_sign_changes(curvature: &[f64], rate: &[f64], closed: bool) -> Vec<Extremum> {
    let n = rate.len();
    let scale = rate.iter().fold(0.0_f64, |a, r| a.max(r.abs()));
    let zero = 1e-9 * scale;
    let mut extrema = Vec::new();
    let mut previous: Option<(usize, f64)> = None;
    let mut first_sign = 0.0;
    for i in 0..n {
        let r = rate[i];
        if r.abs() <= zero {
            continue;
        }
        if first_sign == 0.0 {
            first_sign = r.signum();
        }
        if let Some((j, q)) = previous {
            if q.signum() != r.signum() {
                let c = if q > 0.0 {
                    curvature[j].max(curvature[i])
                } else {
                    curvature[j].min(curvature[i])
                };
                extrema.push(Extremum {
                    node: i,
                    curvature: c,
                });
            }
        }
        previous = Some((i, r));
    }
    let last_sign = previous.map_or(0.0, |p| p.1.signum());
    if closed && first_sign != 0.0 && first_sign != last_sign {
        // The change across the seam.
        let j = previous.map_or(0, |p| p.0);
        let i = (0..n).find(|&i| rate[i].abs() > zero).unwrap_or(0);
        let c = if last_sign > 0.0 {
            curvature[j].max(curvature[i])
        } else {
            curvature[j].min(curvature[i])
        };
        extrema.insert(
            0,
            Extremum {
                node: i,
                curvature: c,
            },
        );
    }
    extrema
}

/// The curvature plot the extrema lie on: `κ` and the arc position `s` at the nodes.
struct Plot<'a> {
    curvature: &'a [f64],
    s: &'a [f64],
    length: f64,
    closed: bool,
    /// The number of nodes (samples of the rate).
    nodes: usize,
}

/// The cheapest simplification of the extrema: an adjacent pair, or (open curve) an end
/// extremum alone.
struct Simplification {
    cost: f64,
    index: usize,
    single: bool,
}

impl Simplification {
    /// Removes the extremum or pair from `extrema` (a pair across a closed curve's seam is the
    /// last and the first).
    fn apply(&self, extrema: &mut Vec<Extremum>) {
        let (j, m) = (self.index, extrema.len());
        if self.single {
            extrema.remove(j);
        } else if j + 1 < m {
            extrema.drain(j..j + 2);
        } else {
            extrema.remove(j);
            extrema.remove(0);
        }
    }
}

impl Plot<'_> {
    /// The cheapest pair of adjacent extrema, or (open curve) extremum next to an end, to drop;
    /// the first of equal costs.
    fn cheapest_drop(&self, extrema: &[Extremum]) -> Option<Simplification> {
        let (curvature, closed, n) = (self.curvature, self.closed, self.nodes);
        let m = extrema.len();
        let mut best: Option<Simplification> = None;
        let mut consider = |cost: f64, index: usize, single: bool| {
            if best.as_ref().is_none_or(|x| cost < x.cost) {
                best = Some(Simplification {
                    cost,
                    index,
                    single,
                });
            }
        };
        let pairs = if closed { m } else { m.saturating_sub(1) };
        for j in 0..pairs {
            let (a, b) = (extrema[j], extrema[(j + 1) % m]);
            let c = self.bump_cost(closed, (a.node, a.curvature), (b.node, b.curvature));
            consider(c, j, false);
        }
        if !closed && m >= 1 {
            let (e0, e1) = (extrema[0], extrema[m - 1]);
            let c0 = self.bump_cost(false, (0, curvature[0]), (e0.node, e0.curvature));
            consider(c0, 0, true);
            let c1 = self.bump_cost(false, (e1.node, e1.curvature), (n - 1, curvature[n - 1]));
            consider(c1, m - 1, true);
        }
        best
    }

    /// The sign of `dκ/ds` at every node between the kept extrema (sorted by node), `0` near
    /// them: rising into a maximum, falling into a minimum.
    fn signs(&self, extrema: &[Extremum]) -> Vec<i8> {
        let (curvature, closed, n) = (self.curvature, self.closed, self.nodes);
        let mut signs = vec![0i8; n];
        let kept = extrema.len();
        let rising_first = if let Some(e) = extrema.first() {
            // A maximum when the curvature there is above its neighbours' mean.
            let before = curvature[e.node.saturating_sub(FREE_NODES)];
            let after = curvature[(e.node + FREE_NODES).min(n - 1)];
            e.curvature >= 0.5 * (before + after)
        } else {
            curvature[n - 1] >= curvature[0]
        };
        let mut sign: i8 = if rising_first { 1 } else { -1 };
        let mut next = 0;
        for (i, out) in signs.iter_mut().enumerate() {
            while next < kept && i >= extrema[next].node {
                sign = -sign;
                next += 1;
            }
            let near = extrema.iter().any(|e| {
                let d = e.node.abs_diff(i);
                d < FREE_NODES || (closed && n - d < FREE_NODES)
            });
            *out = if near { 0 } else { sign };
        }
        signs
    }

    /// How far the curve moves when the curvature between nodes `a` and `b` (an adjacent pair of
    /// extrema, or an end and its extremum; values `κ_a`, `κ_b`) is made monotone: `Δκ L^2 / 8`,
    /// `L` the length of the run around them where the curvature stays within `[κ_a, κ_b]` (the
    /// part of the plot the change flattens).
    fn bump_cost(&self, closed: bool, (a, ka): (usize, f64), (b, kb): (usize, f64)) -> f64 {
        let (curvature, s, length) = (self.curvature, self.s, self.length);
        let n = curvature.len();
        let (lo, hi) = (ka.min(kb), ka.max(kb));
        let inside = |i: usize| curvature[i] >= lo && curvature[i] <= hi;
        let step_back = |i: usize| {
            if i == 0 {
                if closed {
                    Some(n - 1)
                } else {
                    None
                }
            } else {
                Some(i - 1)
            }
        };
        let step_on = |i: usize| {
            if i + 1 == n {
                if closed {
                    Some(0)
                } else {
                    None
                }
            } else {
                Some(i + 1)
            }
        };
        // Walk out from a backwards and from b forwards while inside the band (at most once
        // around).
        let mut first = a;
        let mut steps = 0;
        while let Some(i) = step_back(first) {
            if !inside(i) || steps >= n {
                break;
            }
            first = i;
            steps += 1;
        }
        let mut last = b;
        steps = 0;
        while let Some(i) = step_on(last) {
            if !inside(i) || steps >= n {
                break;
            }
            last = i;
            steps += 1;
        }
        let mut span = s[last] - s[first];
        if span < 0.0 {
            span += length;
        }
        (hi - lo) * span * span / 8.0
    }
}

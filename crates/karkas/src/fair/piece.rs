//! One piece of a fair curve (the whole curve, or the part between two corners): its spline
//! space from the points, its kept ends, and the solve, with more spans when the start cannot
//! reach the tolerance on fewer.

use super::layout::{Control, Layout};
use super::options::POINTS_PER_SPAN;
use super::solver::Solve;
use super::space::Space;
use crate::{Error, Point, Result};

/// The weight `α` of `∫ |r'''|^2 dt` beside the energy (sizes of order one).
const ALPHA: f64 = 1e-3;

/// What one end of a piece keeps.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum End<const D: usize> {
    /// Nothing.
    Free,
    /// Its point.
    Point,
    /// Its point and the direction of its tangent (pointing into the piece).
    Tangent(Point<D>),
}

/// A faired piece: its space, controls and the parameters of its points.
pub(crate) struct Piece<const D: usize> {
    pub(crate) space: Space,
    pub(crate) controls: Vec<Point<D>>,
    pub(crate) params: Vec<f64>,
}

/// The chord-length parameters of `points` from `start` (closed: the last chord back to the
/// first point is the period's end, returned apart).
pub(crate) fn chord_parameters<const D: usize>(
    points: &[Point<D>],
    start: f64,
    closed: bool,
) -> (Vec<f64>, f64) {
    let mut u = Vec::with_capacity(points.len());
    let mut s = start;
    u.push(s);
    for w in points.windows(2) {
        s += w[0].distance(w[1]);
        u.push(s);
    }
    let end = if closed {
        s + points[points.len() - 1].distance(points[0])
    } else {
        s
    };
    (u, end)
}

/// Breaks for `spans` spans following the points: at the parameters of evenly spaced
/// fractional point indices (linearly interpolated), so that every span holds about the same
/// number of points.
fn breaks(params: &[f64], end: f64, spans: usize, closed: bool) -> Vec<f64> {
    let n = params.len();
    let last = if closed { n as f64 } else { (n - 1) as f64 };
    let at = |x: f64| -> f64 {
        let i = (x.floor() as usize).min(n - 1);
        let f = x - i as f64;
        let a = params[i];
        let b = if i + 1 < n { params[i + 1] } else { end };
        a + f * (b - a)
    };
    let mut out: Vec<f64> = (0..=spans)
        .map(|j| at(last * j as f64 / spans as f64))
        .collect();
    out[0] = params[0];
    out[spans] = end;
    out.dedup();
    out
}

/// Fairs `points` (scaled to size about one) within `tolerance` with the ends `ends`
/// (ignored when `closed`), parameters by chord length from `start`.
pub(crate) fn fair_piece<const D: usize>(
    points: &[Point<D>],
    tolerance: f64,
    ends: [End<D>; 2],
    closed: bool,
    start: f64,
) -> Result<Piece<D>> {
    let n = points.len();
    let (params, end) = chord_parameters(points, start, closed);
    let mut spans = ((n as f64 - 1.0) / POINTS_PER_SPAN)
        .round()
        .max(if closed { 4.0 } else { 1.0 }) as usize;
    // At most one span per chord: breaks at the points' own parameters, where the start
    // comes within the tolerance by (nearly) interpolating. More spans than chords would let
    // the start kink between the points, which the energy (dominated by the most curved
    // region) does not smooth out again.
    let most = if closed { n } else { n - 1 };
    loop {
        let b = breaks(&params, end, spans, closed);
        let space = Space::new(b, closed);
        let count = space.controls();
        let (kinds, pinned) = end_controls(points, ends, count, closed);
        let layout = Layout::new(kinds.clone(), closed);
        let controls = start_controls(&kinds, &space);
        let mut solve = Solve {
            space: &space,
            layout: &layout,
            points,
            tolerance,
            alpha: ALPHA,
            pinned: &pinned,
            params: params.clone(),
            basis: Vec::new(),
            controls,
            shape: None,
            slab: false,
        };
        solve.refresh_basis();
        if solve.start()? {
            solve.fair();
            let Solve {
                params, controls, ..
            } = solve;
            return Ok(Piece {
                space,
                controls,
                params,
            });
        }
        if spans >= most {
            return Err(Error::InvalidSetting {
                name: "tolerance",
                value: tolerance,
                reason: "no C^2 cubic spline with these ends comes within it of every point",
            });
        }
        spans = (2 * spans).min(most);
    }
}

/// The kinds of the controls (held or sliding at kept ends, free elsewhere) and which points
/// are pinned, for `count` controls of an open piece's `points` with the ends `ends` (all free
/// when `closed`).
fn end_controls<const D: usize>(
    points: &[Point<D>],
    ends: [End<D>; 2],
    count: usize,
    closed: bool,
) -> (Vec<Control<D>>, Vec<bool>) {
    let n = points.len();
    let mut kinds = vec![Control::Free; count];
    let mut pinned = vec![false; n];
    if !closed {
        for (side, &keep) in ends.iter().enumerate() {
            let (first, second, point) = if side == 0 {
                (0, 1, points[0])
            } else {
                (count - 1, count - 2, points[n - 1])
            };
            if keep != End::Free {
                kinds[first] = Control::Held(point);
                pinned[if side == 0 { 0 } else { n - 1 }] = true;
            }
            if let End::Tangent(direction) = keep {
                kinds[second] = Control::Along {
                    base: point,
                    direction,
                };
            }
        }
    }
    (kinds, pinned)
}

/// The controls the solver starts from: held ones at their point, free ones at zero, sliding
/// ones a third of the end span along their direction (a start away from zero).
fn start_controls<const D: usize>(kinds: &[Control<D>], space: &Space) -> Vec<Point<D>> {
    let mut controls: Vec<Point<D>> = kinds
        .iter()
        .map(|k| match k {
            Control::Held(p) => *p,
            Control::Along { base, .. } => *base,
            Control::Free => Point::ZERO,
        })
        .collect();
    for (j, k) in kinds.iter().enumerate() {
        if let Control::Along { base, direction } = k {
            let h = space.width(if j == 1 { 0 } else { space.spans() - 1 });
            controls[j] = base.add_scaled(h / 3.0 / direction.norm(), *direction);
        }
    }
    controls
}

//! The fitted curve as a dense polyline with its cumulative turning, for the shape guards
//! (docs/methods.md §4): samples placed adaptively by the turning of the tangent, so that a
//! loop or a hook inside one piece is resolved.

use super::super::hermite::HermiteSpline;
use crate::Point;

/// Uniform sub-intervals per piece before refinement.
const BASE_STEPS: usize = 16;
/// An interval is halved while its tangent turns more than this (radians).
const MAX_STEP_TURN: f64 = 0.2;
/// The most halvings of one base interval.
const MAX_DEPTH: u32 = 10;

/// Samples of a curve in increasing parameter, with the turning of the tangent from the
/// start of the curve to each sample.
pub(crate) struct Samples<const D: usize> {
    /// The parameters, increasing.
    pub t: Vec<f64>,
    /// The points of the curve.
    pub p: Vec<Point<D>>,
    /// The cumulative absolute turning of the tangent (radians), 0 at the first sample.
    pub turn: Vec<f64>,
}

impl<const D: usize> Samples<D> {
    /// Samples `spline` on every piece: [`BASE_STEPS`] uniform steps, each halved while the
    /// tangent turns more than [`MAX_STEP_TURN`] over it (judged at its midpoint).
    pub(crate) fn of(spline: &HermiteSpline<D>) -> Self {
        let knots = spline.knots();
        let mut raw: Vec<(f64, Point<D>, Point<D>)> = Vec::with_capacity(spline.pieces() * 20);
        let at = |piece: usize, s: f64| {
            let t = knots[piece] + s * (knots[piece + 1] - knots[piece]);
            (
                t,
                spline.deriv_on_piece(piece, s, 0),
                spline.deriv_on_piece(piece, s, 1),
            )
        };
        for piece in 0..spline.pieces() {
            let mut left = at(piece, 0.0);
            if piece == 0 {
                raw.push(left);
            }
            for step in 1..=BASE_STEPS {
                let right = at(piece, step as f64 / BASE_STEPS as f64);
                let s0 = (step - 1) as f64 / BASE_STEPS as f64;
                let s1 = step as f64 / BASE_STEPS as f64;
                refine(&at, piece, (s0, left), (s1, right), MAX_DEPTH, &mut raw);
                left = right;
            }
        }
        let mut turn = Vec::with_capacity(raw.len());
        let mut total = 0.0;
        let mut last: Option<Point<D>> = None;
        for &(_, _, tangent) in &raw {
            if tangent.0.iter().any(|&c| c != 0.0) {
                if let Some(previous) = last {
                    total += previous.angle_to(tangent);
                }
                last = Some(tangent);
            }
            turn.push(total);
        }
        Samples {
            t: raw.iter().map(|r| r.0).collect(),
            p: raw.iter().map(|r| r.1).collect(),
            turn,
        }
    }

    /// The cumulative turning at parameter `t` (linear between samples; clamped to the ends).
    pub fn turning_at(&self, t: f64) -> f64 {
        let k = self.t.partition_point(|&s| s < t);
        if k == 0 {
            return self.turn[0];
        }
        if k >= self.t.len() {
            return self.turn[self.turn.len() - 1];
        }
        let (t0, t1) = (self.t[k - 1], self.t[k]);
        let w = if t1 > t0 { (t - t0) / (t1 - t0) } else { 1.0 };
        self.turn[k - 1] + w * (self.turn[k] - self.turn[k - 1])
    }

    /// The total turning of the curve.
    pub fn total_turning(&self) -> f64 {
        self.turn[self.turn.len() - 1]
    }
}

/// Pushes the samples of `(s0, s1]` on `piece`, halving while the tangent turns too much.
fn refine<const D: usize>(
    at: &impl Fn(usize, f64) -> (f64, Point<D>, Point<D>),
    piece: usize,
    (s0, left): (f64, (f64, Point<D>, Point<D>)),
    (s1, right): (f64, (f64, Point<D>, Point<D>)),
    depth: u32,
    out: &mut Vec<(f64, Point<D>, Point<D>)>,
) {
    if depth > 0 {
        let sm = 0.5 * (s0 + s1);
        let middle = at(piece, sm);
        let turned = left.2.angle_to(middle.2) + middle.2.angle_to(right.2);
        if turned > MAX_STEP_TURN {
            refine(at, piece, (s0, left), (sm, middle), depth - 1, out);
            refine(at, piece, (sm, middle), (s1, right), depth - 1, out);
            return;
        }
    }
    out.push(right);
}

//! Foot points: the parameter of the point of the curve nearest to a data point.
//!
//! Minimizes `d(t) = |R(t) - r|^2 / 2` over `t in [0, 1]` from a starting parameter (the
//! previous foot point) by safeguarded Newton on `g(t) = (R - r) . R'`, with
//! `g'(t) = |R'|^2 + (R - r) . R''`:
//!
//! - the search starts in a window made of the start's piece and its two neighbours, widened
//!   by a piece whenever the iterate is pushed against an inner end of it;
//! - once a sign change of `g` is known (`g < 0` at `left`, `g > 0` at `right`, so a local
//!   minimum lies between), Newton steps that leave `(left, right)` are replaced by
//!   bisection;
//! - before that, every step must decrease `d` (halving it until it does), and Newton is
//!   used only where `g' > 0`.
//!
//! The search ends when Newton's step falls below the resolution of `t`, or, in the
//! quadratic regime, below `1e-10` of the window (the error left is then of the order of its
//! square). The result is a local minimizer: an inner `t` with `g = 0` and `g' >= 0` up to
//! rounding, or an end of `[0, 1]` where `d` increases inwards. The curve is evaluated from
//! its power form ([`PowerForm`]) with a piece hint per point; `O(1)` evaluations per point
//! in the usual case (three or four from the previous foot point).

use super::power::PowerForm;
use crate::Point;

/// The most Newton or bisection steps per projection (each at least halves a bracket or
/// converges quadratically; 100 is never reached in practice).
const MAX_STEPS: usize = 100;
/// A Newton step shorter than this times the search window (a few pieces) ends the search:
/// the error left is of the order of its square.
const NEWTON_SETTLED: f64 = 1e-10;

/// Value, slope and curvature of `d(t) = |R(t) - r|^2 / 2`.
#[derive(Clone, Copy, Debug)]
struct Jet {
    d: f64,
    g: f64,
    h: f64,
    /// `|R'|^2`.
    speed_sq: f64,
}

/// The jet at `t`; `piece` is a hint for the piece of `t` and is updated to it.
#[inline]
fn jet<const D: usize>(curve: &PowerForm<D>, r: Point<D>, t: f64, piece: &mut usize) -> Jet {
    *piece = curve.piece_near(t, *piece);
    let [p, d1, d2] = curve.jet(*piece, t);
    let e = p - r;
    Jet {
        d: 0.5 * e.norm_sq(),
        g: e.dot(d1),
        h: d1.norm_sq() + e.dot(d2),
        speed_sq: d1.norm_sq(),
    }
}

/// The foot point of `r` on `curve` over `[0, 1]` (the curve's domain), searched from
/// `start`; returns `(t, |R(t) - r|^2)`.
#[cfg(test)]
pub(crate) fn foot_point<const D: usize>(
    curve: &super::hermite::HermiteSpline<D>,
    r: Point<D>,
    start: f64,
) -> (f64, f64) {
    let mut piece = 0;
    foot_point_near(&PowerForm::new(curve), r, start, &mut piece)
}

/// [`foot_point`] with `piece`, a hint for the piece of `start`, updated to the piece of the
/// result (the fit keeps one per point, so that locating a parameter is `O(1)`).
pub(crate) fn foot_point_near<const D: usize>(
    curve: &PowerForm<D>,
    r: Point<D>,
    start: f64,
    piece: &mut usize,
) -> (f64, f64) {
    let knots = curve.knots();
    let (first, last) = (knots[0], knots[knots.len() - 1]);
    let mut t = if start.is_nan() {
        0.5 * (first + last)
    } else {
        start.clamp(first, last)
    };
    let mut cur = descend(curve, r, &mut t, piece);
    // A point where g vanishes but d bends down (a maximum, or a fold where two feet merge)
    // is no foot point: step off it to the lower side and descend again.
    for _ in 0..4 {
        let inner = t > first && t < last;
        if !(inner && cur.h < 0.0) {
            break;
        }
        let nudge = 1e-7 * (last - first);
        let below = (t - nudge).max(first);
        let above = (t + nudge).min(last);
        let (jb, ja) = (jet(curve, r, below, piece), jet(curve, r, above, piece));
        t = if jb.d <= ja.d { below } else { above };
        cur = descend(curve, r, &mut t, piece);
    }
    (t, 2.0 * cur.d)
}

/// Safeguarded Newton descent on `d` from `t` (updated in place); returns the jet there.
fn descend<const D: usize>(
    curve: &PowerForm<D>,
    r: Point<D>,
    t_io: &mut f64,
    piece: &mut usize,
) -> Jet {
    let knots = curve.knots();
    let (first, last) = (knots[0], knots[knots.len() - 1]);
    let mut t = *t_io;
    let mut cur = jet(curve, r, t, piece);
    let mut lo_knot = piece.saturating_sub(1);
    let mut hi_knot = (*piece + 2).min(knots.len() - 1);
    let (mut left, mut right) = (f64::NEG_INFINITY, f64::INFINITY);
    for _ in 0..MAX_STEPS {
        if cur.g < 0.0 {
            left = t;
        } else if cur.g > 0.0 {
            right = t;
        } else {
            break;
        }
        if left >= right {
            // Moved across a maximum of d: keep only the latest side.
            if cur.g < 0.0 {
                right = f64::INFINITY;
            } else {
                left = f64::NEG_INFINITY;
            }
        }
        if (t <= first && cur.g >= 0.0) || (t >= last && cur.g <= 0.0) {
            break; // a minimum at an end of the domain
        }
        if t <= knots[lo_knot] && cur.g > 0.0 && lo_knot > 0 {
            lo_knot -= 1;
        }
        if t >= knots[hi_knot] && cur.g < 0.0 && hi_knot + 1 < knots.len() {
            hi_knot += 1;
        }
        let a = knots[lo_knot].max(left);
        let b = knots[hi_knot].min(right);
        let bracketed = left.is_finite() && right.is_finite();
        let newton = if cur.h > 0.0 {
            let delta = cur.g / cur.h;
            if delta.abs() <= 4.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) {
                break; // the Newton step is below the resolution of t: converged
            }
            t - delta
        } else {
            f64::NAN
        };
        let mut next_t = if newton > a && newton < b {
            newton
        } else if newton >= b && b == last && t < last {
            last // Newton points past the end of the domain: try the end itself
        } else if newton <= a && a == first && t > first {
            first
        } else if cur.g > 0.0 {
            0.5 * (a + t)
        } else {
            0.5 * (t + b)
        };
        let mut next = jet(curve, r, next_t, piece);
        // A Newton step that moves the curve point by less than half the distance is in the
        // quadratic regime: there d changes below its own rounding, so it is not checked.
        let step = next_t - t;
        let small = next_t == newton && step * step * cur.speed_sq <= 0.5 * cur.d;
        if !bracketed && !small {
            let mut halvings = 0;
            // Rounding in d near the minimum must not veto a good Newton step.
            while next.d > cur.d * (1.0 + 8.0 * f64::EPSILON) && halvings < 60 {
                next_t = 0.5 * (t + next_t);
                next = jet(curve, r, next_t, piece);
                halvings += 1;
            }
        }
        let moved = (next_t - t).abs();
        t = next_t;
        cur = next;
        // Quadratic convergence: after a Newton step this short the next one would be below
        // the resolution of t.
        let converged = small && moved <= NEWTON_SETTLED * (knots[hi_knot] - knots[lo_knot]);
        if converged || moved <= 2.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) {
            break;
        }
    }
    *t_io = t;
    cur
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fit::HermiteSpline;

    #[test]
    fn foot_point_on_a_straight_line_is_the_orthogonal_projection() {
        // R(t) = (2t, 1) on [0, 1] with two pieces.
        let c = HermiteSpline::new(
            vec![0.0, 0.5, 1.0],
            vec![Point([0.0, 1.0]), Point([1.0, 1.0]), Point([2.0, 1.0])],
            vec![Point([2.0, 0.0]); 3],
        )
        .unwrap();
        let (t, d2) = foot_point(&c, Point([1.5, 3.0]), 0.1);
        assert!((t - 0.75).abs() < 1e-14 && (d2 - 4.0).abs() < 1e-12);
        // Beyond the end: the minimum is the end point.
        let (t, d2) = foot_point(&c, Point([3.0, 1.0]), 0.5);
        assert_eq!(t, 1.0);
        assert!((d2 - 1.0).abs() < 1e-14);
    }
}

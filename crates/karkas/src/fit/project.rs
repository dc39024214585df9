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
//! quadratic regime, when the step just computed is below `1e-10` of the window or leaves an
//! error (about `g'' step^2 / 2 g'`) below the resolution of `t`. That last step is taken
//! without evaluating the curve at its end: the quadratic model gives `d` there to rounding
//! (it falls by `g^2 / 2 g'`), which saves about one evaluation per point. The result is a
//! local minimizer: an inner `t` with `g = 0` and `g' >= 0` up to rounding, or an end of
//! `[0, 1]` where `d` increases inwards. The curve is evaluated from its power form
//! ([`PowerForm`]) with a piece hint per point; `O(1)` evaluations per point in the usual
//! case (two or three from the previous foot point).

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
    /// A bound on `|h'|`, the rate of change of `h` (see [`Descent::advance`]).
    bend: f64,
}

/// The jet at `t`; `piece` is a hint for the piece of `t` and is updated to it.
#[inline]
fn jet<const D: usize>(curve: &PowerForm<D>, r: Point<D>, t: f64, piece: &mut usize) -> Jet {
    *piece = curve.piece_near(t, *piece);
    let [p, d1, d2] = curve.jet(*piece, t);
    let e = p - r;
    let speed_sq = d1.norm_sq();
    Jet {
        d: 0.5 * e.norm_sq(),
        g: e.dot(d1),
        h: speed_sq + e.dot(d2),
        speed_sq,
        // h' = 3 R' . R'' + e . R'''.
        bend: 3.0 * d1.dot(d2).abs() + e.dot(curve.third(*piece)).abs(),
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

/// The foot point of `r` on `curve` over its domain, searched from `start`, with `piece` a
/// hint for the piece of `start`, updated to the piece of the result (the fit keeps one per
/// point, so that locating a parameter is `O(1)`); returns `(t, |R(t) - r|^2)`.
pub(crate) fn foot_point_near<const D: usize>(
    curve: &PowerForm<D>,
    r: Point<D>,
    start: f64,
    piece: &mut usize,
) -> (f64, f64) {
    let mut descent = Descent::start(curve, r, start, *piece);
    while descent.advance(curve) {}
    descent.finish(curve, piece)
}

/// [`foot_point_near`] of two points at once: their descents advance in turn, so that the
/// processor overlaps the two chains of dependent evaluations (each is bound by the latency
/// of its own). Each result is the one [`foot_point_near`] gives, to the bit.
pub(crate) fn foot_point_pair<const D: usize>(
    curve: &PowerForm<D>,
    r: [Point<D>; 2],
    start: [f64; 2],
    piece: [&mut usize; 2],
) -> [(f64, f64); 2] {
    let [piece_a, piece_b] = piece;
    let mut a = Descent::start(curve, r[0], start[0], *piece_a);
    let mut b = Descent::start(curve, r[1], start[1], *piece_b);
    let (mut going_a, mut going_b) = (true, true);
    while going_a && going_b {
        going_a = a.advance(curve);
        going_b = b.advance(curve);
    }
    while going_a {
        going_a = a.advance(curve);
    }
    while going_b {
        going_b = b.advance(curve);
    }
    [a.finish(curve, piece_a), b.finish(curve, piece_b)]
}

/// Safeguarded Newton descent on `d` (see the module docs), one step per [`Descent::advance`].
struct Descent<const D: usize> {
    r: Point<D>,
    t: f64,
    /// The jet at `t`.
    cur: Jet,
    /// The piece of `t`.
    piece: usize,
    /// The search window `[knots[lo_knot], knots[hi_knot]]`.
    lo_knot: usize,
    hi_knot: usize,
    /// Where `g < 0` and `g > 0` were last seen (a bracket once both are finite).
    left: f64,
    right: f64,
    steps: usize,
}

impl<const D: usize> Descent<D> {
    /// A descent from `start` (clamped to the domain; its middle if NaN), `piece` a hint for
    /// its piece.
    #[inline]
    fn start(curve: &PowerForm<D>, r: Point<D>, start: f64, piece: usize) -> Self {
        let knots = curve.knots();
        let (first, last) = (knots[0], knots[knots.len() - 1]);
        let t = if start.is_nan() {
            0.5 * (first + last)
        } else {
            start.clamp(first, last)
        };
        Self::at(curve, r, t, piece)
    }

    /// A descent from `t`, inside the domain.
    #[inline]
    fn at(curve: &PowerForm<D>, r: Point<D>, t: f64, mut piece: usize) -> Self {
        let cur = jet(curve, r, t, &mut piece);
        Descent {
            r,
            t,
            cur,
            piece,
            lo_knot: piece.saturating_sub(1),
            hi_knot: (piece + 2).min(curve.knots().len() - 1),
            left: f64::NEG_INFINITY,
            right: f64::INFINITY,
            steps: 0,
        }
    }

    /// Ends the search at a local minimizer: a point where `g` vanishes but `d` bends down
    /// (a maximum, or a fold where two feet merge) is no foot point, so the search steps off
    /// it to the lower side and descends again. Returns `(t, |R(t) - r|^2)` and sets `piece`.
    fn finish(mut self, curve: &PowerForm<D>, piece: &mut usize) -> (f64, f64) {
        let knots = curve.knots();
        let (first, last) = (knots[0], knots[knots.len() - 1]);
        for _ in 0..4 {
            let t = self.t;
            let inner = t > first && t < last;
            if !(inner && self.cur.h < 0.0) {
                break;
            }
            let nudge = 1e-7 * (last - first);
            let below = (t - nudge).max(first);
            let above = (t + nudge).min(last);
            let mut hint = self.piece;
            let (jb, ja) = (
                jet(curve, self.r, below, &mut hint),
                jet(curve, self.r, above, &mut hint),
            );
            let next = if jb.d <= ja.d { below } else { above };
            self = Self::at(curve, self.r, next, hint);
            while self.advance(curve) {}
        }
        *piece = self.piece;
        (self.t, 2.0 * self.cur.d)
    }

    /// Moves the bracket of the minimum and the window of knots by the sign of the slope at
    /// the current parameter; `false` when the descent ends there (no slope, or a minimum at
    /// an end of the domain).
    #[inline]
    fn narrow(&mut self, knots: &[f64]) -> bool {
        let (first, last) = (knots[0], knots[knots.len() - 1]);
        let (t, cur) = (self.t, self.cur);
        if cur.g < 0.0 {
            self.left = t;
        } else if cur.g > 0.0 {
            self.right = t;
        } else {
            return false;
        }
        if self.left >= self.right {
            // Moved across a maximum of d: keep only the latest side.
            if cur.g < 0.0 {
                self.right = f64::INFINITY;
            } else {
                self.left = f64::NEG_INFINITY;
            }
        }
        if (t <= first && cur.g >= 0.0) || (t >= last && cur.g <= 0.0) {
            return false; // a minimum at an end of the domain
        }
        if t <= knots[self.lo_knot] && cur.g > 0.0 && self.lo_knot > 0 {
            self.lo_knot -= 1;
        }
        if t >= knots[self.hi_knot] && cur.g < 0.0 && self.hi_knot + 1 < knots.len() {
            self.hi_knot += 1;
        }
        true
    }

    /// The Newton step's parameter (NaN when the model is not convex) and the parameter to
    /// try next: the Newton step inside the window and the bracket, an end of the domain it
    /// points past, else the middle towards the descent; `None` when the Newton step is below
    /// the resolution of `t`.
    #[inline]
    fn next_parameter(&self, knots: &[f64]) -> Option<(f64, f64)> {
        let (first, last) = (knots[0], knots[knots.len() - 1]);
        let (t, cur) = (self.t, self.cur);
        let a = knots[self.lo_knot].max(self.left);
        let b = knots[self.hi_knot].min(self.right);
        let newton = if cur.h > 0.0 {
            let delta = cur.g / cur.h;
            if delta.abs() <= 4.0 * f64::EPSILON * t.abs().max(f64::MIN_POSITIVE) {
                return None;
            }
            t - delta
        } else {
            f64::NAN
        };
        let next_t = if newton > a && newton < b {
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
        Some((newton, next_t))
    }

    /// One step of the descent; `false` once it has ended (then it changes nothing).
    #[inline]
    fn advance(&mut self, curve: &PowerForm<D>) -> bool {
        if self.steps >= MAX_STEPS {
            return false;
        }
        self.steps += 1;
        let knots = curve.knots();
        if !self.narrow(knots) {
            self.steps = MAX_STEPS;
            return false;
        }
        let (t, cur) = (self.t, self.cur);
        let bracketed = self.left.is_finite() && self.right.is_finite();
        let Some((newton, mut next_t)) = self.next_parameter(knots) else {
            self.steps = MAX_STEPS;
            return false; // the Newton step is below the resolution of t: converged
        };
        // A Newton step that moves the curve point by less than half the distance is in the
        // quadratic regime: there d changes below its own rounding, so it is not checked.
        let step = next_t - t;
        let small = next_t == newton && step * step * cur.speed_sq <= 0.5 * cur.d;
        // Quadratic convergence: the error left after a Newton step, about h' step^2 / 2h, is
        // below a quarter of the resolution of t (the next step would not be taken), or the
        // step is this short; the jet at its end is then the quadratic model's to rounding,
        // so it is not evaluated.
        let resolved = cur.bend * step * step <= 0.5 * f64::EPSILON * cur.h * next_t.abs();
        let window = knots[self.hi_knot] - knots[self.lo_knot];
        if small && (resolved || step.abs() <= NEWTON_SETTLED * window) {
            self.piece = curve.piece_near(next_t, self.piece);
            self.cur.d += 0.5 * cur.g * step;
            self.cur.g += cur.h * step;
            self.t = next_t;
            self.steps = MAX_STEPS;
            return false;
        }
        let mut next = jet(curve, self.r, next_t, &mut self.piece);
        if !bracketed && !small {
            let mut halvings = 0;
            // Rounding in d near the minimum must not veto a good Newton step.
            while next.d > cur.d * (1.0 + 8.0 * f64::EPSILON) && halvings < 60 {
                next_t = 0.5 * (t + next_t);
                next = jet(curve, self.r, next_t, &mut self.piece);
                halvings += 1;
            }
        }
        let moved = (next_t - t).abs();
        self.t = next_t;
        self.cur = next;
        if moved <= 2.0 * f64::EPSILON * next_t.abs().max(f64::MIN_POSITIVE) {
            self.steps = MAX_STEPS;
            return false;
        }
        true
    }
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

    /// Two points searched together give each the bits of its own search, whichever of the
    /// two ends first (including searches that cross pieces and end at the domain's ends).
    #[test]
    fn a_pair_of_foot_points_is_the_two_searched_alone() {
        let c = curved();
        let form = PowerForm::new(&c);
        for i in 0..300 {
            let u = i as f64 / 300.0;
            let r = |v: f64, off: f64| {
                let [q, d1, _] = form.jet(form.piece_near(v, 0), v);
                q + Point([-d1[1], d1[0]]) * (off / d1.norm())
            };
            let (ra, rb) = (
                r(u, 0.03 * (5.0 * u).sin()),
                r(1.0 - u, 0.3 * (3.0 * u).cos()),
            );
            let (sa, sb) = ((u + 0.1).min(1.0), (0.5 - u).abs());
            let (mut ka, mut kb) = (0, 3);
            let alone = [
                foot_point_near(&form, ra, sa, &mut ka),
                foot_point_near(&form, rb, sb, &mut kb),
            ];
            let (mut pa, mut pb) = (0, 3);
            let pair = foot_point_pair(&form, [ra, rb], [sa, sb], [&mut pa, &mut pb]);
            for (x, y) in alone.iter().zip(&pair) {
                assert_eq!(x.0.to_bits(), y.0.to_bits(), "{u}");
                assert_eq!(x.1.to_bits(), y.1.to_bits(), "{u}");
            }
            assert_eq!((ka, kb), (pa, pb));
        }
    }

    /// A spline that turns by more than a full circle over four pieces.
    fn curved() -> HermiteSpline<2> {
        HermiteSpline::new(
            vec![0.0, 0.2, 0.45, 0.7, 1.0],
            vec![
                Point([1.0, 0.0]),
                Point([0.3, 0.9]),
                Point([-0.8, 0.5]),
                Point([-0.6, -0.7]),
                Point([0.5, -0.8]),
            ],
            vec![
                Point([0.0, 4.0]),
                Point([-4.0, 2.5]),
                Point([-2.0, -4.0]),
                Point([3.0, -3.0]),
                Point([4.0, 1.5]),
            ],
        )
        .unwrap()
    }

    /// The parameter `t` of every foot point is a stationary point of the distance to the
    /// resolution of `t`, and the squared distance returned is the one at `t`, also where
    /// the last Newton step is taken without evaluating the curve.
    #[test]
    fn foot_points_on_a_curved_spline_are_stationary_with_their_distances() {
        let form = PowerForm::new(&curved());
        let mut piece = 0;
        let mut inner = 0;
        for i in 1..400 {
            let u = i as f64 / 400.0;
            // Points on both sides of the curve at up to 0.05, started off their feet.
            let offset = 0.05 * (7.3 * u).sin();
            let [q, d1, _] = form.jet(form.piece_near(u, 0), u);
            let normal = Point([-d1[1], d1[0]]) * (1.0 / d1.norm());
            let r = q + normal * offset;
            let start = (u + 0.02 * (11.0 * u).cos()).clamp(0.0, 1.0);
            let (t, d2) = foot_point_near(&form, r, start, &mut piece);
            let [p, d1, _] = form.jet(form.piece_near(t, 0), t);
            let e = p - r;
            // e = R - r carries the rounding of the coordinates, about eps |r|.
            let rounding = 8.0 * f64::EPSILON * (1.0 + r.norm()) * e.norm();
            assert!(
                (d2 - e.norm_sq()).abs() <= rounding,
                "{u}: {d2} {}",
                e.norm_sq()
            );
            if t > 0.0 && t < 1.0 {
                inner += 1;
                // g(t) = e . R' vanishes to the rounding of t (a change of t by a few ulps
                // changes g by about |R'|^2 times that).
                let g = e.dot(d1);
                assert!(
                    g.abs() <= 1e-13 * d1.norm_sq() + 1e-14 * e.norm() * d1.norm(),
                    "{u}"
                );
            }
        }
        assert!(inner > 350);
    }
}

//! Arc length `s(t0, t1) = ∫_{t0}^{t1} |P'(t)| dt` of a curve and its inverse.
//!
//! The integral is split at the curve's breakpoints (from
//! [`Curve::polynomial_pieces`]; shifted by whole periods on a closed curve), where `|P'|`
//! may have kinks, and each piece is integrated by adaptive 8-point Gauss–Legendre
//! quadrature (bisection until the rule and its two halves agree) with a share of the
//! accuracy proportional to its parameter length. A curve with no known pieces is split into
//! 16 parts per domain length instead. The inverse (the parameter at a given length from a
//! start) walks the pieces, then solves `s(a, t) = r` on the piece reached by Newton's method
//! (`ds/dt = |P'(t)|`) safeguarded by bisection.

use super::quadrature::integrate;
use crate::core::Curve;

/// Parts per domain length when the curve does not tell its pieces.
const DEFAULT_PARTS: f64 = 16.0;
/// Most parts an interval is split into before quadrature.
const MAX_PARTS: usize = 1 << 16;
/// Most Newton or bisection steps of the inverse on one piece.
const MAX_STEPS: usize = 200;

/// The parameters `t0 < .. < t1` splitting `[t0, t1]` (`t0 <= t1`) at the curve's breakpoints.
pub(crate) fn split_points<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    t0: f64,
    t1: f64,
) -> Vec<f64> {
    let domain = curve.domain();
    let len = domain.length();
    let mut points = vec![t0];
    if t1.partial_cmp(&t0) != Some(std::cmp::Ordering::Greater)
        || !t0.is_finite()
        || !t1.is_finite()
        || len.is_nan()
        || len <= 0.0
    {
        points.push(t1);
        return points;
    }
    let breaks: Vec<f64> = match curve.polynomial_pieces() {
        Some(p) => p.breaks,
        None => {
            let n = DEFAULT_PARTS as usize;
            (0..=n).map(|k| domain.uniform(k, n + 1)).collect()
        }
    };
    let mut inner: Vec<f64> = Vec::new();
    if curve.is_closed() {
        let first = ((t0 - domain.start) / len).floor() as i64;
        let last = ((t1 - domain.start) / len).floor() as i64;
        if (last - first) as usize * breaks.len() > MAX_PARTS {
            let n = MAX_PARTS;
            inner.extend((1..n).map(|k| t0 + (t1 - t0) * k as f64 / n as f64));
        } else {
            for period in first..=last {
                let shift = period as f64 * len;
                inner.extend(breaks.iter().map(|b| b + shift));
            }
        }
    } else {
        inner.extend(breaks.iter().copied());
    }
    let gap = 1e-14 * (t1 - t0).abs().max(len);
    inner.retain(|&b| b > t0 + gap && b < t1 - gap);
    inner.sort_by(f64::total_cmp);
    inner.dedup_by(|a, b| (*a - *b).abs() <= gap);
    points.extend(inner);
    points.push(t1);
    points
}

/// The speed `|P'(t)|`.
/// `(t0, t1)` clamped to the domain of an open curve (unchanged on a closed one).
fn within_domain<C: Curve<D> + ?Sized, const D: usize>(curve: &C, t0: f64, t1: f64) -> (f64, f64) {
    if curve.is_closed() {
        return (t0, t1);
    }
    let domain = curve.domain();
    (domain.clamp(t0), domain.clamp(t1))
}

fn speed<C: Curve<D> + ?Sized, const D: usize>(curve: &C, t: f64) -> f64 {
    curve.deriv(t, 1).norm()
}

/// `∫_a^b |P'|` to within `accuracy`, for `[a, b]` inside one polynomial piece (no
/// breakpoint inside, so no split): the parameters are used as given.
pub(crate) fn piece_length<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    a: f64,
    b: f64,
    accuracy: f64,
) -> f64 {
    integrate(&|t: f64| speed(curve, t), a, b, accuracy)
}

/// The length of `curve` from `t0` to `t1` (negative when `t1 < t0`), to within `accuracy`
/// (absolute, in the curve's length units; a non-positive accuracy asks for the best the
/// quadrature gives, about `1e-15` relative).
///
/// On an open curve the parameters are clamped to the domain (the length is measured along
/// the curve itself, never along an extension of its end pieces); on a closed curve they
/// wrap, so a whole period counts once per turn. NaN parameters give NaN.
///
/// ```
/// use karkas::geometry::arc_length;
/// use karkas::{ll::LlCurve, Curve, Point};
/// let pts = [Point([0.0, 0.0]), Point([1.0, 0.0]), Point([2.0, 0.0]), Point([3.0, 0.0])];
/// let line = LlCurve::new(&pts, 3, false).unwrap();
/// let d = line.domain();
/// assert!((arc_length(&line, d.start, d.end, 1e-12) - 3.0).abs() < 1e-12);
/// ```
pub fn arc_length<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    t0: f64,
    t1: f64,
    accuracy: f64,
) -> f64 {
    if t0.is_nan() || t1.is_nan() {
        return f64::NAN;
    }
    if t1 < t0 {
        return -arc_length(curve, t1, t0, accuracy);
    }
    // An open curve is measured within its domain: the parameters are clamped to it.
    let (t0, t1) = within_domain(curve, t0, t1);
    if t1 == t0 {
        return 0.0;
    }
    let points = split_points(curve, t0, t1);
    let total = t1 - t0;
    let f = |t: f64| speed(curve, t);
    points
        .windows(2)
        .map(|w| integrate(&f, w[0], w[1], accuracy * (w[1] - w[0]) / total))
        .sum()
}

/// The parameter `t` with `arc_length(t0, t) = length` to within `accuracy` (absolute): the
/// point reached after walking `length` along the curve from `t0` (backwards when `length`
/// is negative).
///
/// On an open curve the walk starts from `t0` clamped to the domain and stops at the domain
/// end (an end is returned when `length` exceeds what is left). On a closed curve it goes round by the period and the result is
/// wrapped into the domain. NaN input gives NaN.
pub fn inverse_arc_length<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    t0: f64,
    length: f64,
    accuracy: f64,
) -> f64 {
    if t0.is_nan() || length.is_nan() {
        return f64::NAN;
    }
    let domain = curve.domain();
    let closed = curve.is_closed() && domain.length() > 0.0;
    // An open curve is walked within its domain, from the start clamped to it.
    let t0 = if closed { t0 } else { domain.clamp(t0) };
    if length == 0.0 {
        return if closed { domain.wrap(t0) } else { t0 };
    }
    let accuracy = accuracy.max(0.0);
    let forward = length > 0.0;
    let mut remaining = length.abs();
    let limit = if closed {
        let perimeter = arc_length(curve, domain.start, domain.end, 0.25 * accuracy);
        if perimeter > 0.0 && remaining > perimeter {
            remaining %= perimeter;
        }
        if forward {
            t0 + domain.length()
        } else {
            t0 - domain.length()
        }
    } else if forward {
        domain.end.max(t0)
    } else {
        domain.start.min(t0)
    };
    let finish = |t: f64| if closed { domain.wrap(t) } else { t };
    let (lo, hi) = if forward { (t0, limit) } else { (limit, t0) };
    let mut points = split_points(curve, lo, hi);
    if !forward {
        points.reverse();
    }
    let piece_accuracy = 0.25 * accuracy / points.len() as f64;
    for w in points.windows(2) {
        let (a, b) = (w[0], w[1]);
        let piece = arc_length(curve, a, b, piece_accuracy).abs();
        if piece >= remaining {
            return finish(solve_on_piece(curve, a, b, piece, remaining, accuracy));
        }
        remaining -= piece;
    }
    finish(limit)
}

/// The `t` between `a` and `b` (either order) with `|arc_length(a, t)| = target`, where
/// `|arc_length(a, b)| = piece >= target`.
pub(crate) fn solve_on_piece<C: Curve<D> + ?Sized, const D: usize>(
    curve: &C,
    a: f64,
    b: f64,
    piece: f64,
    target: f64,
    accuracy: f64,
) -> f64 {
    if piece <= 0.0 {
        return a;
    }
    let sign = if b >= a { 1.0 } else { -1.0 };
    // Bracket [lo, hi] in "distance from a" units x = |t - a|.
    let (mut lo, mut hi) = (0.0, (b - a).abs());
    let mut x = hi * (target / piece);
    let inner = 0.5 * accuracy;
    for _ in 0..MAX_STEPS {
        let t = a + sign * x;
        let s = piece_length(curve, a, t, 0.25 * inner).abs();
        let f = s - target;
        if f.abs() <= inner {
            return t;
        }
        if f < 0.0 {
            lo = x;
        } else {
            hi = x;
        }
        if hi - lo <= f64::EPSILON * (a.abs() + hi) {
            return a + sign * x;
        }
        let v = speed(curve, t);
        let newton = x - f / v;
        x = if v > 0.0 && newton > lo && newton < hi {
            newton
        } else {
            0.5 * (lo + hi)
        };
    }
    a + sign * x
}

//! How fair a curve is: the figures a designer reads off a curvature plot ([`CurveFairness`]),
//! computed for any piecewise-polynomial curve ([`PiecewiseCurve`]).
//!
//! Curvature `κ` and its rate along the arc `dκ/ds` come in closed form from the first three
//! derivatives ([`curvature_rate`](fn@super::curvature_rate), the Frenet formulas of
//! docs/methods.md, differentiated): `κ` is signed in 2-D (positive for a counter-clockwise
//! turn) and `|κ|` in any other dimension.
//!
//! - **Curvature extrema**: the sign changes of `dκ/ds` along the curve, over dense samples
//!   of every polynomial piece (48 plus 4 per degree) that include both one-sided limits at
//!   every breakpoint, so that an extremum sitting on a knot (where `dκ/ds` jumps from one
//!   sign to the other) counts. Jumps of `κ` itself at the knots of a `C^1` curve are not
//!   sign changes of `dκ/ds` and do not count; their size is reported apart
//!   ([`CurveFairness::curvature_jump`]). Values with
//!   `|dκ/ds| <= 1e-8 (κ_max + 1/L) / L` (`L` the length) count as zero, so that rounding
//!   noise on a circle or a straight line is no extremum; closed curves are counted
//!   cyclically (the count is even).
//! - **Inflections**: in 2-D the sign changes of `κ` (zeros `|κ| <= 1e-8 (κ_max + 1/L)`
//!   skipped, so a curve starting with zero curvature has no inflection there); in 3-D,
//!   where `κ >= 0`, the runs of samples with `κ` below that threshold between samples above
//!   it (a space curve rarely has any).
//! - **Curvature range**: the smallest and largest sample of `κ`, each refined by
//!   golden-section search between its neighbours.
//! - **Fairness energy** `∫ (dκ/ds)^2 ds`: adaptive Gauss–Legendre quadrature of
//!   `(dκ/ds)^2 |P'(t)|` on every polynomial piece (to `1e-10` relative); the Dirac parts of
//!   `κ` jumps are not in it.
//! - **Length**: [`arc_length`](fn@super::arc_length) over the domain.
//! - **Largest distance to the polygon**: the largest distance of the curve from the polyline
//!   of the input points (closed for a closed curve), over the same samples, refined by
//!   golden-section search around the best sample of every piece that comes within half of
//!   the largest.
//!
//! Hand-written: no crate computes these figures on a user's piecewise-polynomial curve.

use super::arc_length::arc_length;
use super::curvature_rate::{curvature_rate, curvature_rate_on_side};
use super::polygon_distance::Polygon;
use super::quadrature::integrate;
use super::sign_changes::{interior_zero_runs, sign_changes};
use crate::core::{PiecewiseCurve, Side};
use crate::Point;

/// Samples of `dκ/ds` per polynomial piece (plus [`SAMPLES_PER_DEGREE`] per degree).
const SAMPLES_PER_PIECE: usize = 48;
/// Extra samples per degree of the pieces.
const SAMPLES_PER_DEGREE: usize = 4;
/// Values of `κ` and `dκ/ds` below this share of their scale count as zero.
const ZERO_THRESHOLD: f64 = 1e-8;
/// Relative accuracy of the fairness energy and the length.
const RELATIVE_ACCURACY: f64 = 1e-10;
/// Golden-section steps of a refinement (shrinks the bracket by `0.618^60 ~ 3e-13`).
const GOLDEN_STEPS: usize = 60;

/// The fairness figures of a curve (see the module documentation for how each is found).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurveFairness {
    /// The arc length over the domain.
    pub length: f64,
    /// The smallest curvature (signed in 2-D).
    pub curvature_min: f64,
    /// The largest curvature (signed in 2-D).
    pub curvature_max: f64,
    /// The number of curvature extrema (sign changes of `dκ/ds`, knots included).
    pub curvature_extrema: usize,
    /// The number of inflections (sign changes of `κ` in 2-D, zeros of `κ` otherwise).
    pub inflections: usize,
    /// The largest distance of the curve from the polygon of the input points (NaN when the
    /// points give no polygon: fewer than two distinct ones).
    pub max_distance_to_polygon: f64,
    /// `∫ (dκ/ds)^2 ds` over the curve. It scales as `1/size^3`: infinite for a curve so small
    /// (below about 1e-100 units for an airfoil-like shape) that it exceeds the floating-point
    /// range, and 0 for one so large that it falls below it.
    pub fairness_energy: f64,
    /// The number of polynomial pieces.
    pub pieces: usize,
    /// The largest jump of the curvature at a breakpoint (0 on a `C^2` curve).
    pub curvature_jump: f64,
}

/// One sample of the curvature along a curve.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CurvatureSample {
    /// The parameter.
    pub t: f64,
    /// The arc length from the start of the domain.
    pub s: f64,
    /// The curvature (signed in 2-D; a one-sided limit at a breakpoint).
    pub curvature: f64,
}

/// A sample of the curve for the fairness figures.
#[derive(Clone, Copy)]
struct Sample<const D: usize> {
    t: f64,
    point: Point<D>,
    speed: f64,
    k: f64,
    rate: f64,
}

/// The polynomial pieces `[a, b]` of `curve` (its breakpoints; the whole domain when it has
/// none) and the samples per piece.
fn pieces<C: PiecewiseCurve<D> + ?Sized, const D: usize>(curve: &C) -> (Vec<f64>, usize) {
    let mut breaks = curve.breakpoints();
    breaks.retain(|b| b.is_finite());
    if breaks.len() < 2 {
        let d = curve.domain();
        breaks = vec![d.start, d.end];
    }
    let degree = curve.polynomial_pieces().map_or(3, |p| p.degree);
    (breaks, SAMPLES_PER_PIECE + SAMPLES_PER_DEGREE * degree)
}

/// Samples of piece `[a, b]`: both ends as one-sided limits and `m - 1` inner points.
fn sample_piece<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    a: f64,
    b: f64,
    m: usize,
    out: &mut Vec<Sample<D>>,
) {
    for j in 0..=m {
        let t = if j == m {
            b
        } else {
            a + (b - a) * j as f64 / m as f64
        };
        let side = if j == 0 { Side::Above } else { Side::Below };
        let (d1, (k, rate)) = if j == 0 || j == m {
            (
                curve.deriv_on_side(t, 1, side),
                curvature_rate_on_side(curve, t, side),
            )
        } else {
            (curve.deriv(t, 1), curvature_rate(curve, t))
        };
        out.push(Sample {
            t,
            point: curve.eval(t),
            speed: d1.norm(),
            k,
            rate,
        });
    }
}

/// The `x` in `[lo, hi]` where `f` is largest (golden-section search, for a unimodal `f`),
/// and `f` there.
fn golden_max(f: impl Fn(f64) -> f64, lo: f64, hi: f64) -> (f64, f64) {
    const R: f64 = 0.618_033_988_749_894_9;
    let (mut a, mut b) = (lo, hi);
    let (mut x1, mut x2) = (b - R * (b - a), a + R * (b - a));
    let (mut f1, mut f2) = (f(x1), f(x2));
    for _ in 0..GOLDEN_STEPS {
        if f1 >= f2 {
            b = x2;
            (x2, f2) = (x1, f1);
            x1 = b - R * (b - a);
            f1 = f(x1);
        } else {
            a = x1;
            (x1, f1) = (x2, f2);
            x2 = a + R * (b - a);
            f2 = f(x2);
        }
    }
    if f1 >= f2 {
        (x1, f1)
    } else {
        (x2, f2)
    }
}

/// The fairness figures of `curve`, with the distance measured to the polygon of `points`
/// (closed when the curve is; an empty slice gives a NaN distance).
///
/// ```
/// use karkas::geometry::curve_fairness;
/// use karkas::{ll::LlCurve, Point};
/// let pts = [Point([0.0, 0.0]), Point([1.0, 0.0]), Point([2.0, 0.0]), Point([3.0, 0.0])];
/// let line = LlCurve::new(&pts, 3, false).unwrap();
/// let f = curve_fairness(&line, &pts);
/// assert!((f.length - 3.0).abs() < 1e-9);
/// assert_eq!((f.curvature_extrema, f.inflections), (0, 0));
/// assert!(f.fairness_energy < 1e-20 && f.max_distance_to_polygon < 1e-12);
/// ```
pub fn curve_fairness<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    points: &[Point<D>],
) -> CurveFairness {
    let (breaks, m) = pieces(curve);
    let closed = curve.is_closed();
    let mut samples: Vec<Sample<D>> = Vec::with_capacity((breaks.len() - 1) * (m + 1));
    for w in breaks.windows(2) {
        sample_piece(curve, w[0], w[1], m, &mut samples);
    }
    let (start, end) = (breaks[0], breaks[breaks.len() - 1]);
    let rough: f64 = samples
        .windows(2)
        .map(|w| w[0].point.distance(w[1].point))
        .sum();
    let length = arc_length(curve, start, end, RELATIVE_ACCURACY * rough);
    let k_max_abs = samples
        .iter()
        .map(|s| s.k.abs())
        .filter(|k| k.is_finite())
        .fold(0.0, f64::max);
    let inverse_length = if length > 0.0 { 1.0 / length } else { 0.0 };
    let k_threshold = ZERO_THRESHOLD * (k_max_abs + inverse_length);
    let rate_threshold = k_threshold * inverse_length;
    let curvature_extrema = sign_changes(samples.iter().map(|s| s.rate), rate_threshold, closed);
    let ks: Vec<f64> = samples.iter().map(|s| s.k).collect();
    let inflections = if D == 2 {
        sign_changes(ks.iter().copied(), k_threshold, closed)
    } else {
        interior_zero_runs(&ks, k_threshold, closed)
    };
    let (curvature_min, curvature_max) = curvature_range(curve, &samples, m);
    let fairness_energy = energy(
        curve,
        &breaks,
        &samples,
        m,
        (rate_threshold * length.sqrt()).powi(2),
    );
    let curvature_jump = samples
        .chunks(m + 1)
        .zip(samples.chunks(m + 1).skip(1))
        .map(|(left, right)| (left[m].k - right[0].k).abs())
        .chain(closed.then(|| (samples[samples.len() - 1].k - samples[0].k).abs()))
        .filter(|j| j.is_finite())
        .fold(0.0, f64::max);
    CurveFairness {
        length,
        curvature_min,
        curvature_max,
        curvature_extrema,
        inflections,
        max_distance_to_polygon: polygon_distance(curve, points, &samples, m),
        fairness_energy,
        pieces: breaks.len() - 1,
        curvature_jump,
    }
}

/// The smallest and largest curvature: the extreme samples refined between their neighbours
/// on their piece.
fn curvature_range<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    samples: &[Sample<D>],
    m: usize,
) -> (f64, f64) {
    let finite = |i: &usize| samples[*i].k.is_finite();
    let extreme = |sign: f64| -> f64 {
        let Some(best) = (0..samples.len())
            .filter(finite)
            .max_by(|&i, &j| (sign * samples[i].k).total_cmp(&(sign * samples[j].k)))
        else {
            return f64::NAN;
        };
        let j = best % (m + 1);
        let mut value = samples[best].k;
        if j > 0 && j < m {
            let (lo, hi) = (samples[best - 1].t, samples[best + 1].t);
            let (_, refined) = golden_max(|t| sign * curvature_rate(curve, t).0, lo, hi);
            if refined.is_finite() {
                value = sign * (sign * value).max(refined);
            }
        }
        value
    };
    (extreme(-1.0), extreme(1.0))
}

/// `∫ (dκ/ds)^2 ds` piece by piece, to [`RELATIVE_ACCURACY`] of an estimate from the samples
/// (or `floor`, the integral of the noise threshold squared, when that is larger).
///
/// Each piece is integrated over its own unit interval `τ`, `t = a + (b - a) τ`, with the
/// integrand `(κ_s sqrt(|P'| (b - a)))^2`: the factors stay near the energy's own scale
/// (`1/size^3`), where `κ_s^2 |P'|` alone leaves the floating-point range for curves
/// below about 1e-77 units long though their energy does not.
fn energy<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    breaks: &[f64],
    samples: &[Sample<D>],
    m: usize,
    floor: f64,
) -> f64 {
    let span = breaks[breaks.len() - 1] - breaks[0];
    if span.is_nan() || span <= 0.0 {
        return 0.0;
    }
    let estimate = sampled_energy(breaks, samples, m);
    let tolerance = (RELATIVE_ACCURACY * estimate).max(floor);
    breaks
        .windows(2)
        .map(|w| {
            let (a, width) = (w[0], w[1] - w[0]);
            let f = |tau: f64| {
                let t = a + width * tau;
                density(curvature_rate(curve, t).1, curve.deriv(t, 1).norm(), width)
            };
            integrate(&f, 0.0, 1.0, tolerance * width / span)
        })
        .sum()
}

/// `(rate sqrt(speed width))^2`, the energy density of a piece of parameter width `width`
/// per unit of its own interval.
fn density(rate: f64, speed: f64, width: f64) -> f64 {
    let value = (rate * (speed * width).sqrt()).powi(2);
    if value.is_finite() {
        value
    } else if rate.is_finite() && speed.is_finite() {
        // Finite factors whose product overflows: the energy of a curve so small that it
        // exceeds the floating-point range (it grows as 1/size^3).
        f64::INFINITY
    } else {
        0.0 // a singular point (a cusp's zero speed), of measure zero
    }
}

/// The energy `∫ (dκ/ds)^2 ds` estimated from the samples alone (their mean density on each
/// piece), without the adaptive quadrature.
fn sampled_energy<const D: usize>(breaks: &[f64], samples: &[Sample<D>], m: usize) -> f64 {
    samples
        .chunks(m + 1)
        .zip(breaks.windows(2))
        .map(|(piece, w)| {
            piece
                .iter()
                .map(|s| density(s.rate, s.speed, w[1] - w[0]))
                .filter(|x| x.is_finite())
                .sum::<f64>()
                / piece.len() as f64
        })
        .sum()
}

/// [`CurveFairness::fairness_energy`] estimated from the samples [`curve_fairness`] takes
/// (at most a few percent off on a smooth curve), at a fixed cost: the adaptive quadrature
/// of the exact figure can take seconds on a near-cusp, where this estimate is large
/// already (the samples about the cusp carry it).
pub(crate) fn sampled_fairness_energy<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
) -> f64 {
    let (breaks, m) = pieces(curve);
    let mut samples = Vec::with_capacity((breaks.len() - 1) * (m + 1));
    for w in breaks.windows(2) {
        sample_piece(curve, w[0], w[1], m, &mut samples);
    }
    sampled_energy(&breaks, &samples, m)
}

/// The largest distance of the curve from the polygon of `points`.
fn polygon_distance<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    points: &[Point<D>],
    samples: &[Sample<D>],
    m: usize,
) -> f64 {
    let single = points.iter().find(|p| p.is_finite());
    let Some(polygon) = Polygon::new(points, curve.is_closed()) else {
        return match single {
            Some(&p) => samples
                .iter()
                .map(|s| s.point.distance(p))
                .fold(0.0, f64::max),
            None => f64::NAN,
        };
    };
    let Some(projector) = polygon.projector() else {
        return f64::NAN;
    };
    let distance = |t: f64| projector.nearest(curve.eval(t)).distance;
    let sampled: Vec<f64> = samples
        .iter()
        .map(|s| projector.nearest(s.point).distance)
        .collect();
    let mut largest = sampled
        .iter()
        .copied()
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max);
    let cut = 0.5 * largest;
    for (ds, ss) in sampled.chunks(m + 1).zip(samples.chunks(m + 1)) {
        let Some((j, &d)) = ds
            .iter()
            .enumerate()
            .filter(|(_, d)| d.is_finite())
            .max_by(|a, b| a.1.total_cmp(b.1))
        else {
            continue;
        };
        if d < cut {
            continue;
        }
        let (lo, hi) = (ss[j.saturating_sub(1)].t, ss[(j + 1).min(m)].t);
        let (_, refined) = golden_max(distance, lo, hi);
        if refined.is_finite() {
            largest = largest.max(refined);
        }
    }
    largest
}

/// The curvature along `curve` at `per_piece` even steps of every polynomial piece, with both
/// one-sided limits at every breakpoint (so jumps show as two samples at one `t`), and the
/// arc length from the domain start.
pub fn curvature_profile<C: PiecewiseCurve<D> + ?Sized, const D: usize>(
    curve: &C,
    per_piece: usize,
) -> Vec<CurvatureSample> {
    let (breaks, _) = pieces(curve);
    let m = per_piece.max(1);
    let mut out = Vec::with_capacity((breaks.len() - 1) * (m + 1));
    let mut s = 0.0;
    let mut previous = breaks[0];
    for w in breaks.windows(2) {
        let (a, b) = (w[0], w[1]);
        let piece_accuracy = RELATIVE_ACCURACY * curve.eval(a).distance(curve.eval(b));
        for j in 0..=m {
            let t = if j == m {
                b
            } else {
                a + (b - a) * j as f64 / m as f64
            };
            let side = if j == 0 { Side::Above } else { Side::Below };
            s += arc_length(curve, previous, t, piece_accuracy / m as f64);
            previous = t;
            let curvature = if j == 0 || j == m {
                curvature_rate_on_side(curve, t, side).0
            } else {
                curvature_rate(curve, t).0
            };
            out.push(CurvatureSample { t, s, curvature });
        }
    }
    out
}

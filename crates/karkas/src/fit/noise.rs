//! The noise of measured points and the dimensionless weight of the bending term
//! (docs/methods.md §4, "noise-aware smoothing").
//!
//! The noise is estimated from the points alone, before any fit, by the residual ladder of
//! `super::noise_ladder`: around every point, windows of 3, 5, 7 and 9 points (orders 1 to
//! 4) compare the middle point with the polynomial through the others, each residual
//! measured against its own propagated noise. On exact points the residuals are the
//! interpolation error: they fall with the order where the points resolve the curve, and
//! stay or rise where they do not (a sparse nose, a corner), but they do not stand on a
//! floor that looks like noise (residuals flipping side at random from window to window,
//! spread as a `chi` variable, the next order no higher), so the estimate is 0. Noisy points
//! stand on such a floor, whose median is the noise; where the noise reaches the spacing,
//! wider strides make every window's gaps at least 5 times the noise first. Checked
//! (tests/karkas/fit_noise_exact.rs) on ellipses, NACA sections, spirals, a helix and shapes
//! with corners from 12 to 60 points: exact points read below `1e-6` of the size, so every
//! default of the fit is the paper's method. On eight curves the rules were not tuned on
//! (12 to 60 points) the same holds but for nine sparse cases (at most 30 points) that read
//! `7.6e-5` to `2.5e-2` of the size. Noise of `1e-4` to `1e-2` of the size reads within 30%
//! (the median over noise sets) wherever it stands above what the sampling leaves of the
//! curve's own shape: on the untuned curves from 100 points at `1e-4` of the size, 60 at
//! `3e-4` and `1e-3`, 40 at `3e-3` and `1e-2`; sparser, the estimate often reads 0 and the
//! fit is the paper's.
//!
//! The bending term `lambda int |R''(t)|^2 dt` is weighted
//! `lambda = (rho phi + s psi (sigma / L)^2) n tau`, with `n` the number of points, `L` the
//! diagonal of the points' bounding box, `rho` the fairness floor
//! ([`super::FitOptions::fairness`]), `phi = min(1, (8 / m)^2)` and `psi = min(1, (64 / m)^2)` the
//! shares kept when the pieces hold many points (`m = n / pieces` per piece),
//! `s` the smoothing ([`super::FitOptions::smoothing`]) and `tau = (2 pi / max(Theta,
//! 2 pi))^4`, where `Theta` is the total turning of the point polygon (taken through at most
//! 64 of the points, so that the noise does not count): the pull of the term on the shape is
//! about `lambda / n |R''''(t)|`, which grows as the fourth power of the turning, so `tau`
//! keeps it the same share of the size on a curve that winds three times as on one that
//! turns once. All three factors are invariant under scaling of the coordinates. The noise
//! part falls off towards the ends of the curve (see `problem::Taper`).

use super::noise_ladder::{rung, Rung, MAX_ORDER};
use crate::Point;
use std::f64::consts::PI;

/// Polygon vertices the turning is measured through, at most.
const TURNING_VERTICES: usize = 64;

/// What the points say about themselves before a fit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NoiseEstimate {
    /// The estimated standard deviation of the noise per coordinate (0 for fewer than 3
    /// points or exact points on straight lines).
    pub sigma: f64,
    /// The diagonal of the points' bounding box.
    pub size: f64,
    /// The total turning of the point polygon through at most 64 of its points, in radians.
    pub turning: f64,
}

impl NoiseEstimate {
    /// `tau = (2 pi / max(turning, 2 pi))^4`, the share of the bending weight kept on a
    /// curve that winds more than once.
    pub fn turning_factor(&self) -> f64 {
        (2.0 * PI / self.turning.max(2.0 * PI)).powi(4)
    }

    /// `lambda` for `n` points on `pieces` pieces with the fairness floor `rho` and the
    /// smoothing `s` (see the module documentation).
    pub fn bending_weight(&self, n: usize, pieces: usize, rho: f64, s: f64) -> f64 {
        let (fairness, smoothing) = self.bending_parts(n, pieces, rho, s);
        fairness + smoothing
    }

    /// The two parts of `lambda`: the fairness floor's and the noise's.
    pub fn bending_parts(&self, n: usize, pieces: usize, rho: f64, s: f64) -> (f64, f64) {
        let relative = if self.size > 0.0 {
            self.sigma / self.size
        } else {
            0.0
        };
        let per_piece = n as f64 / pieces.max(1) as f64;
        let floor = rho * (SPARSE_POINTS_PER_PIECE / per_piece).min(1.0).powi(2);
        let noise = s * (NOISY_POINTS_PER_PIECE / per_piece).min(1.0).powi(2) * relative * relative;
        let scale = n as f64 * self.turning_factor();
        (floor * scale, noise * scale)
    }
}

/// Points per piece up to which the fairness floor is kept whole: beyond, its share is
/// `(8 / (n / pieces))^2`. The floor keeps sparse points from sliding along the curve (a
/// piece with a handful of points can fold between them); with many points per piece the
/// points pin the parameterization themselves, and the floor would only pull the ends, which
/// a single point holds, inwards (by about `lambda |R''|` there, growing with `n`).
const SPARSE_POINTS_PER_PIECE: f64 = 8.0;
/// Points per piece up to which the noise term is kept whole: beyond, its share is
/// `(64 / (n / pieces))^2`. The noise left in a piece's coefficients falls as the square
/// root of its points, so dense pieces need less smoothing, and would only pay its bias and
/// its cost (the bending term is what the iteration converges slowest on).
const NOISY_POINTS_PER_PIECE: f64 = 64.0;

/// Estimates the noise, size and turning of `points` (see the module documentation).
pub fn estimate_noise<const D: usize>(points: &[Point<D>]) -> NoiseEstimate {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in points {
        for c in 0..D {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    // The diagonal, scaled by its largest side so that it neither overflows nor underflows.
    let sides: [f64; D] = std::array::from_fn(|c| (hi[c] - lo[c]).max(0.0));
    let largest = sides.iter().fold(0.0f64, |m, &s| m.max(s));
    let size = if largest > 0.0 && largest.is_finite() {
        largest
            * sides
                .iter()
                .map(|s| (s / largest).powi(2))
                .sum::<f64>()
                .sqrt()
    } else {
        0.0
    };
    let sigma = if largest > 0.0 && largest.is_finite() {
        noise_sigma(points, largest)
    } else {
        0.0
    };
    NoiseEstimate {
        sigma: if sigma.is_finite() { sigma } else { 0.0 },
        size,
        turning: turning(points),
    }
}

/// Window centres measured at most: beyond, runs of [`CENTRE_RUN`] consecutive points
/// spread evenly (the median of 16 384 residuals is within about 1% of its limit).
const MAX_CENTRES: usize = 16_384;
/// Consecutive centres per run when the centres are spread: neighbouring windows of a run
/// overlap, as the flips test expects.
const CENTRE_RUN: usize = 8;
/// The share of order-1 windows whose middle projects outside the chord from which the
/// noise is taken to exceed the spacing (the flips of such windows say nothing: their chords
/// point anywhere).
const NOISE_OUTSIDE: f64 = 0.05;
/// The share of flips at or above which the residuals of a rung read as noise.
const NOISE_FLIPS: f64 = 0.5;
/// Consecutive windows a rung must compare before its flips are believed.
const MIN_PAIRS: usize = 5;
/// The range of the quartile ratio (1 for noise) within which a rung reads as noise.
const NOISE_SPREAD: (f64, f64) = (0.5, 1.6);
/// The ladder stands on the first order whose next order does not fall below this share of
/// it: the noise floor, or the order past which the points no longer resolve the curve.
const FLOOR_FALL: f64 = 0.8;
/// On exact points the next order rises above this many times the floor (or falls on); on
/// noise it stays within it.
const FLAT_RISE: f64 = 1.5;
/// The stride of a noisy rung makes the gaps of its windows at least this many times
/// the noise: at a fifth of the spacing the noise leaves the windows graphs over their chords
/// and the first-order propagation exact.
const SPACING_PER_NOISE: f64 = 5.0;
/// Rounds of strides and estimates, at most.
const STRIDE_ROUNDS: usize = 4;

/// The noise `sigma` of `points` (0 when the residual ladder shows none), in the units of
/// the points; `unit` (the largest side of the bounding box) keeps the arithmetic in range.
fn noise_sigma<const D: usize>(points: &[Point<D>], unit: f64) -> f64 {
    let n = points.len();
    if n < 3 || D < 2 {
        return 0.0;
    }
    let centres = window_centres(n);
    let ones = vec![1; centres.len()];
    let Some(first) = rung(points, unit, &centres, &ones, 1) else {
        return 0.0;
    };
    let noisy_chords = first.flips >= NOISE_FLIPS && first.pairs >= MIN_PAIRS;
    if noisy_chords || first.outside >= NOISE_OUTSIDE {
        // The chord residuals are noise: strides make every window's gaps at least
        // SPACING_PER_NOISE times it (found again from the strided estimate, which the
        // noise does not bias low as it does the order-1 rung's where it exceeds the
        // spacing), then the ladder removes what bending is left.
        let mut sigma = first.sigma;
        let mut strides = ones;
        for _ in 0..STRIDE_ROUNDS {
            let wider: Vec<usize> = centres
                .iter()
                .zip(&strides)
                .map(|(&i, &m)| m.max(stride_for(points, unit, i, SPACING_PER_NOISE * sigma)))
                .collect();
            if wider == strides && sigma != first.sigma {
                break;
            }
            strides = wider;
            let ladder: Vec<Option<Rung>> = (1..=MAX_ORDER)
                .map(|k| rung(points, unit, &centres, &strides, k))
                .collect();
            sigma = floor_order(&ladder, centres.len())
                .and_then(|k| ladder[k - 1])
                .map_or(sigma, |r| r.sigma);
        }
        return sigma * unit;
    }
    // The chord residuals are the curve's bending: noise shows only if the ladder stands on
    // a floor of residuals that look like noise.
    let ladder: Vec<Option<Rung>> = std::iter::once(Some(first))
        .chain((2..=MAX_ORDER).map(|k| rung(points, unit, &centres, &ones, k)))
        .collect();
    let Some(floor) = floor_order(&ladder, centres.len()) else {
        return 0.0;
    };
    // The floor and the orders above it while the ladder stays flat: the first whose
    // residuals look like noise gives it.
    let rung_at = |k: usize| ladder.get(k - 1).copied().flatten();
    let mut k = floor;
    while let Some(here) = rung_at(k) {
        let next = rung_at(k + 1);
        // Flat into the next order; the highest order, flat from the one below it, whose
        // residuals flip side as noise does.
        let flat = match next {
            Some(next) => next.sigma <= FLAT_RISE * here.sigma,
            None => {
                k > floor
                    && rung_at(k - 1).is_some_and(|below| {
                        below.flips >= NOISE_FLIPS
                            && here.sigma >= FLOOR_FALL * below.sigma
                            && here.sigma <= FLAT_RISE * below.sigma
                    })
            }
        };
        if !flat {
            break;
        }
        let noisy = here.pairs >= MIN_PAIRS
            && here.flips >= NOISE_FLIPS
            && (NOISE_SPREAD.0..=NOISE_SPREAD.1).contains(&here.spread);
        if noisy {
            return here.sigma * unit;
        }
        match next {
            Some(next) if next.sigma >= FLOOR_FALL * here.sigma => k += 1,
            _ => break,
        }
    }
    0.0
}

/// The order (1-based) the ladder stands on: the first counted order whose next order is
/// not counted or does not fall below [`FLOOR_FALL`] of it; an order counts where at least
/// half the centres (and 5) gave a window.
fn floor_order(ladder: &[Option<Rung>], centres: usize) -> Option<usize> {
    let needed = (centres.saturating_sub(2) / 2).max(5);
    let counted = |k: usize| {
        ladder
            .get(k - 1)
            .copied()
            .flatten()
            .filter(|r| r.windows >= needed)
    };
    (1..=ladder.len()).find_map(|k| {
        let here = counted(k)?;
        match counted(k + 1) {
            Some(next) if next.sigma < FLOOR_FALL * here.sigma => None,
            _ => Some(k),
        }
    })
}

/// The centres of the windows: every point, or runs of consecutive points spread evenly
/// when there are more than [`MAX_CENTRES`].
fn window_centres(n: usize) -> Vec<usize> {
    if n <= MAX_CENTRES {
        return (0..n).collect();
    }
    let runs = MAX_CENTRES / CENTRE_RUN;
    let last_start = n - CENTRE_RUN;
    (0..runs)
        .flat_map(|r| {
            let start = r * last_start / (runs - 1);
            start..start + CENTRE_RUN
        })
        .collect()
}

/// The smallest stride `m` (a power of 2, at most `(n - 1) / (2 MAX_ORDER)`) at which the
/// chord `r_{i-m} r_{i+m}` around `i` (coordinates divided by `unit`) is at least `2 gap`
/// long, the window's gaps about `gap` each.
fn stride_for<const D: usize>(points: &[Point<D>], unit: f64, i: usize, gap: f64) -> usize {
    let n = points.len();
    let longest = ((n - 1) / (2 * MAX_ORDER)).max(1);
    let mut m = 1;
    while m < longest {
        let (a, b) = (i.saturating_sub(m), (i + m).min(n - 1));
        if (points[b] - points[a]).norm() / unit >= gap * (b - a) as f64 / m as f64 {
            break;
        }
        m = (2 * m).min(longest);
    }
    m
}

/// The total turning of the polygon through at most [`TURNING_VERTICES`] points spread
/// evenly by index.
fn turning<const D: usize>(points: &[Point<D>]) -> f64 {
    let n = points.len();
    if n < 3 {
        return 0.0;
    }
    let step = n.div_ceil(TURNING_VERTICES).max(1);
    let mut vertices: Vec<Point<D>> = points.iter().step_by(step).copied().collect();
    if !(n - 1).is_multiple_of(step) {
        vertices.push(points[n - 1]);
    }
    let edges: Vec<Point<D>> = vertices
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|e| e.0.iter().any(|&c| c != 0.0))
        .collect();
    edges.windows(2).map(|w| w[0].angle_to(w[1])).sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point2;

    /// A deterministic Gaussian sequence (Box–Muller on a linear congruential generator).
    fn gaussian(seed: u64, count: usize) -> Vec<f64> {
        let mut state = seed;
        let mut uniform = || {
            state = state
                .wrapping_mul(6_364_136_223_846_793_005)
                .wrapping_add(1_442_695_040_888_963_407);
            ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        (0..count)
            .map(|_| {
                let (u, v) = (uniform(), uniform());
                (-2.0 * u.ln()).sqrt() * (2.0 * PI * v).cos()
            })
            .collect()
    }

    fn circle(n: usize, sigma: f64, scale: f64) -> Vec<Point2> {
        let noise = gaussian(7, 2 * n);
        (0..n)
            .map(|i| {
                let a = 2.0 * PI * i as f64 / n as f64;
                Point2::new([
                    scale * (a.cos() + sigma * noise[2 * i]),
                    scale * (a.sin() + sigma * noise[2 * i + 1]),
                ])
            })
            .collect()
    }

    #[test]
    fn the_noise_of_a_circle_is_found() {
        // Spacing 1.6e-3: the noise a sixteenth of the spacing to six times it.
        for sigma in [1e-4, 1e-3, 1e-2] {
            let estimate = estimate_noise(&circle(4000, sigma, 1.0));
            assert!(
                (estimate.sigma / sigma - 1.0).abs() < 0.1,
                "sigma {sigma}: {estimate:?}"
            );
        }
    }

    #[test]
    fn exact_points_have_no_noise() {
        // From 12 points (30 degrees apart) to 4000: the residuals fall with the order.
        for n in [12, 13, 20, 40, 400, 4000] {
            let estimate = estimate_noise(&circle(n, 0.0, 1.0));
            assert_eq!(estimate.sigma, 0.0, "{n}: {estimate:?}");
        }
    }

    #[test]
    fn dense_points_are_measured_on_spread_centres() {
        // 10^5 points: runs of 8 centres spread evenly, the noise found all the same, and
        // exact points read as exact down to their rounding.
        let centres = window_centres(100_000);
        assert_eq!(centres.len(), MAX_CENTRES);
        assert!(centres.windows(2).all(|w| w[0] < w[1]));
        assert_eq!((centres[0], centres[MAX_CENTRES - 1]), (0, 99_999));
        let estimate = estimate_noise(&circle(100_000, 1e-5, 1.0));
        assert!((estimate.sigma / 1e-5 - 1.0).abs() < 0.1, "{estimate:?}");
        assert!(estimate_noise(&circle(100_000, 0.0, 1.0)).sigma < 1e-15);
    }

    #[test]
    fn the_estimate_scales_with_the_points() {
        let unit = estimate_noise(&circle(500, 1e-3, 1.0));
        for scale in [1e-150, 1e-3, 1e3, 1e150] {
            let scaled = estimate_noise(&circle(500, 1e-3, scale));
            assert!(
                (scaled.sigma / (scale * unit.sigma) - 1.0).abs() < 1e-9,
                "{scale}"
            );
            assert!(
                (scaled.size / (scale * unit.size) - 1.0).abs() < 1e-12,
                "{scale}"
            );
            assert!((scaled.turning - unit.turning).abs() < 1e-9, "{scale}");
            let (n, rho, s) = (500, 3e-11, 1.0);
            let ratio = scaled.bending_weight(n, 20, rho, s) / unit.bending_weight(n, 20, rho, s);
            assert!((ratio - 1.0).abs() < 1e-8, "{scale}: {ratio}");
        }
    }

    #[test]
    fn the_turning_counts_windings() {
        let spiral: Vec<Point2> = (0..100_000)
            .map(|i| {
                let s = i as f64 / 99_999.0;
                let a = 6.0 * PI * s;
                Point2::new([(1.0 + s) * a.cos(), (1.0 + s) * a.sin()])
            })
            .collect();
        // Through 64 vertices a polygon turns a little less than the curve (18.58 of 6 pi).
        let estimate = estimate_noise(&spiral);
        assert!((estimate.turning - 6.0 * PI).abs() < 0.5, "{estimate:?}");
        assert!((estimate.turning_factor() * 81.0 - 1.0).abs() < 0.15);
        let line: Vec<Point2> = (0..50).map(|i| Point2::new([i as f64, 0.0])).collect();
        let flat = estimate_noise(&line);
        assert_eq!(
            (flat.sigma, flat.turning, flat.turning_factor()),
            (0.0, 0.0, 1.0)
        );
    }
}

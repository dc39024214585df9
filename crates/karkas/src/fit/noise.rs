//! The noise of measured points and the dimensionless weight of the bending term
//! (docs/methods.md §4, "noise-aware smoothing").
//!
//! The noise is estimated from the points alone, before any fit: every inner point `r_i` is
//! compared with the chord of its neighbours, `e_i = r_i - (r_{i-1} + u (r_{i+1} - r_{i-1}))`
//! (`u` the projection of `r_i` on the chord). For independent noise of `sigma` per
//! coordinate the part of `e_i` across the chord has deviation `sigma sqrt(1 + u^2 +
//! (1 - u)^2)`; the median of `|e_i|` over that factor, divided by the median of a half-normal
//! (2-D) or a Rayleigh variable (3-D), estimates `sigma`, up to the chord's cut through the
//! bend (`|e_i|` about `h^2 kappa / 2` for spacing `h` and curvature `kappa`), which on sparse
//! exact points exceeds any noise. The same estimate over twice the stride (`r_{i-2}`,
//! `r_i`, `r_{i+2}`) sees four times that cut and the same noise, so
//! `sigma^2 = (16 s_1^2 - s_2^2) / 15` removes it (Richardson's extrapolation). The median
//! ignores the corners.
//!
//! The bending term `lambda int |R''(t)|^2 dt` is weighted
//! `lambda = (rho phi + s psi (sigma / L)^2) n tau`, with `n` the number of points, `L` the
//! diagonal of the points' bounding box, `rho` the fairness floor
//! ([`super::FitOptions::fairness`]), `phi = min(1, (8 / m)^2)` and
//! `psi = min(1, (64 / min(m, 2048))^2)` the shares kept when the pieces hold many points
//! (`m = n / pieces` per piece; `psi` falls no further past 2048, where small loops through
//! the noise band would start to pay),
//! `s` the smoothing ([`super::FitOptions::smoothing`]) and `tau = (2 pi / max(Theta,
//! 2 pi))^4`, where `Theta` is the total turning of the point polygon (taken through at most
//! 64 of the points, so that the noise does not count): the pull of the term on the shape is
//! about `lambda / n |R''''(t)|`, which grows as the fourth power of the turning, so `tau`
//! keeps it the same share of the size on a curve that winds three times as on one that
//! turns once. All three factors are invariant under scaling of the coordinates. The noise
//! part falls off towards the ends of the curve (see `problem::Taper`).

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
        let noise = s
            * (NOISY_POINTS_PER_PIECE / per_piece.min(DENSE_POINTS_PER_PIECE))
                .min(1.0)
                .powi(2)
            * relative
            * relative;
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
/// Points per piece beyond which the noise share falls no further: it stays
/// `(64 / 2048)^2`, so the noise part of `lambda` grows with `n` as the data term does. Were
/// it to keep falling (as `1 / n^2` against the data term), dense noisy points would make
/// small loops pay: a loop of a piece that passes through the noise band brings many points
/// closer and costs almost no bending. Measured on the upper half of an ellipse (sigma 1e-4
/// of the chord, 30 knots): loops appeared from about 10^4 points per piece (3 x 10^5
/// points), and the fit landed 10 times farther from the true curve at 10^6 points than at
/// 10^5; with the share held from 2048 points per piece the distance falls with `n`.
const DENSE_POINTS_PER_PIECE: f64 = 2048.0;

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
    // Richardson's extrapolation on the stride: the chord's cut through the bend grows as
    // the square of the spacing (16 times its square over twice the stride), the noise
    // does not.
    let (near, far) = (
        noise_sigma(points, largest, 1),
        noise_sigma(points, largest, 2),
    );
    let sigma = ((16.0 * near * near - far * far) / 15.0).max(0.0).sqrt();
    NoiseEstimate {
        sigma: if sigma.is_finite() { sigma } else { near },
        size,
        turning: turning(points),
    }
}

/// The median-based estimate of the noise from every point and its neighbours `stride`
/// before and after, working in coordinates divided by `scale`.
fn noise_sigma<const D: usize>(points: &[Point<D>], scale: f64, stride: usize) -> f64 {
    if points.len() < 2 * stride + 1 || !(scale > 0.0 && scale.is_finite()) {
        return 0.0;
    }
    let mut residuals: Vec<f64> = (stride..points.len() - stride)
        .filter_map(|i| {
            let w = [points[i - stride], points[i], points[i + stride]];
            let (a, b, c) = (
                w[0] * (1.0 / scale),
                w[1] * (1.0 / scale),
                w[2] * (1.0 / scale),
            );
            let chord = c - a;
            let length_sq = chord.norm_sq();
            if length_sq == 0.0 {
                return None;
            }
            let u = ((b - a).dot(chord) / length_sq).clamp(0.0, 1.0);
            let e = b - a.add_scaled(u, chord);
            let spread = (1.0 + u * u + (1.0 - u) * (1.0 - u)).sqrt();
            Some(e.norm() / spread)
        })
        .collect();
    if residuals.is_empty() {
        return 0.0;
    }
    let middle = residuals.len() / 2;
    let (_, median, _) = residuals.select_nth_unstable_by(middle, f64::total_cmp);
    // The median of |N(0, 1)| in 2-D (one component across the chord), of a Rayleigh
    // variable of unit scale in 3-D (two).
    let unit_median = if D <= 2 {
        0.674_489_750_196_081_7
    } else {
        1.177_410_022_515_474_7
    };
    *median / unit_median * scale
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
        // Spacing 1.6e-3: within 10% where the noise is below the spacing; up to 25% high
        // where it is six times the spacing and the chords point anywhere.
        for (sigma, within) in [(1e-4, 0.1), (1e-3, 0.1), (1e-2, 0.25)] {
            let estimate = estimate_noise(&circle(4000, sigma, 1.0));
            assert!(
                (estimate.sigma / sigma - 1.0).abs() < within,
                "sigma {sigma}: {estimate:?}"
            );
        }
    }

    #[test]
    fn exact_points_have_almost_no_noise() {
        // The chord of two neighbours passes h^2 / 2 inside the middle point (1.2e-2 on 40
        // points of a unit circle), read as a noise of that over 0.6745 sqrt(1.5); the
        // extrapolation leaves a tenth of it on 40 points, and a thousandth on 4000.
        for (n, share) in [(40, 0.15), (4000, 2e-3)] {
            let h = 2.0 * PI / n as f64;
            let cut = h * h / 2.0 / (0.6745 * 1.5f64.sqrt());
            let estimate = estimate_noise(&circle(n, 0.0, 1.0));
            assert!(
                estimate.sigma < share * cut,
                "{n}: {estimate:?} against {cut:e}"
            );
        }
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

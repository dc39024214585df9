//! The noise of measured points and the dimensionless weight of the bending term
//! (docs/methods.md §4, "noise-aware smoothing").
//!
//! The noise is estimated from the points alone, before any fit, by a ladder of differences
//! on the points' index (the leave-one-out residuals of local polynomials of rising degree on
//! index parameters). At order `k = 2..=8`, every window of `k + 1` neighbours gives the `k`-th
//! difference `e_j = sum_m (-1)^(k-m) C(k, m) r_(j+m) / sqrt(C(2k, k))`: the residual of
//! the polynomial of degree `k - 1` through the window's other points at its left-out point,
//! scaled so that independent noise of `sigma` per coordinate gives it deviation `sigma`. Its
//! part across the window's chord (`r_(j+k) - r_j`) leaves out the points' uneven spacing
//! along the curve. The scale `S_k` of order `k` is the root mean square of the smallest three
//! quarters of these parts, over its value for unit noise (a truncated chi-square with one
//! degree of freedom in 2-D, two in 3-D), so that the windows through a corner do not count.
//! On exact points of a smooth curve `S_k` keeps falling with `k` (a polynomial of degree
//! below `k` gives exactly 0), towards the rounding of the coordinates; on noisy points it
//! falls until the curve's part is below the noise and then stays at `sigma`. So the noise is
//! declared only where four successive orders agree within 20% (a plateau; their geometric
//! mean is `sigma`), and is 0 where none do: the ladder of exact points falls or jumps from
//! order to order, however sparse and curved the points (12 points of an ellipse, a spiral,
//! a NACA section with or without corners give 0), while on noise the orders' residuals are
//! sums of the same errors and agree. The guarantee: exact points of a polynomial curve of
//! degree below 8, and exact points whose scales fall by more than 20% over any four orders,
//! get `sigma = 0`, so that every default of the fit is Pavlov's method to round-off;
//! noise is found within 30% from about 30 points (fewer do not tell the curve from the
//! noise).
//!
//! Roughness within the precision the coordinates carry is not noise: `sigma` is 0 when it
//! is at most ten times the coordinates' resolution (the range of their last written digit),
//! the larger of 64 units in the last place of the largest coordinate and the finest of the
//! coordinates' lattice spacings. A coordinate is on a lattice of spacing `q` when every
//! point's difference from the first point's is a multiple of `q` (found from the values by
//! Euclid's algorithm, whatever the base: an airfoil file with five decimals has `10^-5`,
//! the same file multiplied by 7.57 has `7.57e-5`, so the rule is the same at every scale
//! and offset); rounding to it is noise of `q / sqrt 12`, and tabulated sections carry a
//! zigzag of a unit or two of the last decimal between neighbours. The finest coordinate
//! decides, so that stations on a coarse grid (every 0.025 of the chord) beside a finely
//! written coordinate do not hide noise.
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

/// Difference orders the ladder climbs through (the module documentation).
const ORDERS: std::ops::RangeInclusive<usize> = 2..=8;
/// Share of each order's windows, the smallest, its scale is taken over.
const KEPT_SHARE: f64 = 0.75;
/// Largest ratio between the scales of the orders of one plateau.
const PLATEAU_SPREAD: f64 = 1.2;
/// Orders a plateau spans at least.
const PLATEAU_ORDERS: usize = 4;
/// Units of the coordinates' resolution up to which roughness is not noise: the last written
/// digit's range. Tabulated airfoils carry a regular zigzag of one or two units of their
/// last decimal (AH 80-140: every other point 1.6e-5 off at five decimals), whose scale on
/// the ladder is 1.6 to 2.3 times its amplitude (5.9 units for AH 80-140).
const RESOLUTION_STEPS: f64 = 10.0;
/// Steps of its range a coordinate's lattice spacing spans at most: finer lattices are the
/// doubles' own rounding, not digits written.
const LATTICE_STEPS: f64 = 1e12;
/// Windows an order needs to be on the ladder.
const FEWEST_WINDOWS: usize = 3;

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
    let ladder = difference_ladder(points, largest);
    let sigma = plateau(&ladder) * largest;
    NoiseEstimate {
        sigma: if sigma.is_finite() && sigma > RESOLUTION_STEPS * resolution(points) {
            sigma
        } else {
            0.0
        },
        size,
        turning: turning(points),
    }
}

/// The scales `S_k` of the difference orders (module documentation), in coordinates divided
/// by `scale`, for the orders with at least [`FEWEST_WINDOWS`] windows.
fn difference_ladder<const D: usize>(points: &[Point<D>], scale: f64) -> Vec<f64> {
    if !(scale > 0.0 && scale.is_finite()) {
        return Vec::new();
    }
    // E[X; X <= a] / (nu P(X <= a)) for X chi-square with nu degrees of freedom and a its
    // quantile at KEPT_SHARE: nu = 1 across the chord in 2-D, 2 in 3-D.
    let (freedom, truncated) = if D <= 2 {
        (1.0, 0.368_524_050_983_562_5)
    } else {
        ((D - 1) as f64, 0.537_901_879_626_703)
    };
    let inverse = 1.0 / scale;
    let mut across: Vec<f64> = Vec::with_capacity(points.len());
    let mut ladder = Vec::new();
    for order in ORDERS {
        if points.len() < order + FEWEST_WINDOWS {
            break;
        }
        let weights = difference_weights(order);
        across.clear();
        across.extend(points.windows(order + 1).filter_map(|w| {
            let chord = (w[order] - w[0]) * inverse;
            let length_sq = chord.norm_sq();
            let e = w.iter().zip(&weights).fold(Point([0.0; D]), |e, (&p, &c)| {
                e.add_scaled(c * inverse, p - w[0])
            });
            (length_sq > 0.0).then(|| (e - chord * (e.dot(chord) / length_sq)).norm_sq())
        }));
        if across.len() < FEWEST_WINDOWS {
            break;
        }
        let kept = ((KEPT_SHARE * across.len() as f64).ceil() as usize).clamp(1, across.len());
        across.select_nth_unstable_by(kept - 1, f64::total_cmp);
        let mean = across[..kept].iter().sum::<f64>() / kept as f64;
        ladder.push((mean / (freedom * truncated)).sqrt());
    }
    ladder
}

/// `(-1)^(k-m) C(k, m) / sqrt(C(2k, k))`, `m = 0..=k`: the `k`-th difference scaled to unit
/// deviation under unit noise.
fn difference_weights(order: usize) -> Vec<f64> {
    let binomial =
        |n: usize, m: usize| (0..m).fold(1.0, |b, i| b * (n - i) as f64 / (i + 1) as f64);
    let norm = binomial(2 * order, order).sqrt();
    (0..=order)
        .map(|m| {
            let sign = if (order - m).is_multiple_of(2) {
                1.0
            } else {
                -1.0
            };
            sign * binomial(order, m) / norm
        })
        .collect()
}

/// The noise the ladder shows: the geometric mean of the first run of at least
/// [`PLATEAU_ORDERS`] successive scales within [`PLATEAU_SPREAD`] of each other; 0 when the
/// scales reach 0 first or no run is that long.
fn plateau(ladder: &[f64]) -> f64 {
    for (first, &scale) in ladder.iter().enumerate() {
        if scale.is_nan() || scale <= 0.0 {
            return 0.0;
        }
        let (mut low, mut high, mut last) = (scale, scale, first);
        for &next in &ladder[first + 1..] {
            let (l, h) = (low.min(next), high.max(next));
            if !(l > 0.0 && h <= PLATEAU_SPREAD * l) {
                break;
            }
            (low, high, last) = (l, h, last + 1);
        }
        if last + 1 - first >= PLATEAU_ORDERS {
            let run = &ladder[first..=last];
            return (run.iter().map(|s| s.ln()).sum::<f64>() / run.len() as f64).exp();
        }
    }
    0.0
}

/// The finest roughness the coordinates can show: the finest of their lattice spacings (see
/// [`lattice_spacing`]; none when some coordinate is not on a lattice) and 64 units in the
/// last place of the largest coordinate. Both scale with the points, so the rule is the same
/// at every scale and offset: five decimals multiplied by 7.57 are a lattice of `7.57e-5`.
fn resolution<const D: usize>(points: &[Point<D>]) -> f64 {
    let Some(first) = points.first() else {
        return 0.0;
    };
    let magnitude = points
        .iter()
        .flat_map(|p| p.0)
        .fold(0.0f64, |m, c| m.max(c.abs()));
    let rounding = 64.0 * f64::EPSILON * magnitude;
    let mut finest = f64::INFINITY;
    for c in 0..D {
        let differences = || points.iter().map(move |p| (p[c] - first[c]).abs());
        let range = differences().fold(0.0f64, f64::max);
        if range == 0.0 {
            continue;
        }
        match lattice_spacing(differences, range) {
            Some(q) => finest = finest.min(q),
            None => return rounding,
        }
    }
    if finest.is_finite() {
        finest.max(rounding)
    } else {
        rounding
    }
}

/// The spacing `q` of the coarsest lattice `{k q}` that holds every one of `differences` (to
/// a thousandth of `q`), whose largest is `range`: their approximate greatest common divisor
/// by Euclid's algorithm on remainders rounded to the nearest multiple, refined on the
/// largest difference after each. `None` when it falls below `range / LATTICE_STEPS` (values computed
/// in full precision), or is not finite.
fn lattice_spacing<I: Iterator<Item = f64>>(
    differences: impl Fn() -> I,
    range: f64,
) -> Option<f64> {
    let floor = range / LATTICE_STEPS;
    if !(floor > 0.0 && range.is_finite()) {
        return None;
    }
    let (mut spacing, mut largest) = (0.0f64, 0.0f64);
    for d in differences().filter(|&d| d > floor) {
        let (mut a, mut b) = (spacing.max(d), spacing.min(d));
        while b > floor {
            (a, b) = (b, (a - b * (a / b).round()).abs());
        }
        if a <= floor {
            return None;
        }
        // Refined on the largest difference, a multiple of the spacing, so that the rounding
        // of the remainders does not build up over the differences.
        largest = largest.max(d);
        spacing = largest / (largest / a).round();
    }
    differences()
        .all(|d| {
            let steps = d / spacing;
            (steps - steps.round()).abs() <= 1e-3
        })
        .then_some(spacing)
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

    /// `n` points of the ellipse with half-axes 2 and 1 from the angle 0.3, evenly by angle.
    fn ellipse(n: usize) -> Vec<Point2> {
        (0..n)
            .map(|i| {
                let a = 0.3 + 2.0 * PI * i as f64 / n as f64;
                Point2::new([2.0 * a.cos(), a.sin()])
            })
            .collect()
    }

    /// `n` points of the Archimedean spiral `r = 1 + a / 2`, two turns.
    fn spiral(n: usize) -> Vec<Point2> {
        (0..n)
            .map(|i| {
                let a = 4.0 * PI * i as f64 / (n - 1) as f64;
                Point2::new([(1.0 + 0.5 * a) * a.cos(), (1.0 + 0.5 * a) * a.sin()])
            })
            .collect()
    }

    /// NACA 0012 in cosine spacing from the trailing edge over the upper side and back: a
    /// corner at the leading edge for the index (the points crowd there).
    fn naca0012(n: usize) -> Vec<Point2> {
        (0..n)
            .map(|i| {
                let b = 2.0 * PI * i as f64 / (n - 1) as f64;
                let x = 0.5 * (1.0 + b.cos());
                let t = 0.6
                    * (0.2969 * x.sqrt() - 0.126 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                        - 0.1036 * x.powi(4));
                Point2::new([x, if b < PI { t } else { -t }])
            })
            .collect()
    }

    /// A D shape: a straight side, then a half circle back to the first point (corners at
    /// both joins).
    fn d_shape(n: usize) -> Vec<Point2> {
        let side = n / 3;
        let mut points: Vec<Point2> = (0..side)
            .map(|i| Point2::new([0.0, -1.0 + 2.0 * i as f64 / (side - 1) as f64]))
            .collect();
        let arc = n - side;
        points.extend((1..=arc).map(|i| {
            let a = 0.5 * PI - PI * i as f64 / arc as f64;
            Point2::new([a.cos(), a.sin()])
        }));
        points
    }

    #[test]
    fn exact_sparse_points_have_no_noise() {
        // The ladder of exact points falls or jumps from order to order: no plateau.
        for n in [12, 20, 30, 45, 60] {
            for (name, points) in [
                ("ellipse", ellipse(n)),
                ("spiral", spiral(n)),
                ("naca0012", naca0012(n)),
                ("d shape", d_shape(n)),
            ] {
                let estimate = estimate_noise(&points);
                assert_eq!(estimate.sigma, 0.0, "{name} on {n} points: {estimate:?}");
            }
        }
        // Points of a polynomial curve of degree 7 difference to 0 at order 8.
        let septic: Vec<Point2> = (0..40)
            .map(|i| {
                let t = i as f64 / 39.0 - 0.5;
                Point2::new([t, 3.0 * t.powi(7) - t.powi(4) + t])
            })
            .collect();
        assert_eq!(estimate_noise(&septic).sigma, 0.0);
    }

    #[test]
    fn the_noise_of_sparse_points_is_found() {
        // 60 points of the ellipse, Gaussian noise of 1e-4, 1e-3, 1e-2 of the size (sqrt 20):
        // the median over nine seeds within 30% of the true deviation.
        let size = 20f64.sqrt();
        for relative in [1e-4, 1e-3, 1e-2] {
            let sigma = relative * size;
            let mut ratios: Vec<f64> = (0..9)
                .map(|seed| {
                    let noise = gaussian(100 + seed, 120);
                    let points: Vec<Point2> = ellipse(60)
                        .iter()
                        .enumerate()
                        .map(|(i, p)| *p + Point2::new([noise[2 * i], noise[2 * i + 1]]) * sigma)
                        .collect();
                    estimate_noise(&points).sigma / sigma
                })
                .collect();
            ratios.sort_by(f64::total_cmp);
            assert!((ratios[4] - 1.0).abs() < 0.3, "{relative}: {ratios:?}");
        }
    }

    #[test]
    fn rounding_to_the_decimals_written_is_not_noise() {
        let rounded = |points: &[Point2], decimals: i32| -> Vec<Point2> {
            let q = 10f64.powi(decimals);
            points
                .iter()
                .map(|p| Point2::new([(p[0] * q).round() / q, (p[1] * q).round() / q]))
                .collect()
        };
        // Exact points of a dense ellipse written with 5 decimals: the rounding (2.9e-6 per
        // coordinate) makes a plateau, below the quantum 1e-5.
        let dense = rounded(&ellipse(400), 5);
        assert!((resolution(&dense) / 1e-5 - 1.0).abs() < 1e-9);
        assert_eq!(estimate_noise(&dense).sigma, 0.0);
        // Moved by an offset the quantum is the same.
        let moved: Vec<Point2> = dense
            .iter()
            .map(|p| *p + Point2::new([0.37, -12.5]))
            .collect();
        assert!((resolution(&moved) / 1e-5 - 1.0).abs() < 1e-9);
        // Noise of 1e-3 written with 5 decimals is found, within 10% on 400 points.
        let noise = gaussian(3, 800);
        let noisy: Vec<Point2> = ellipse(400)
            .iter()
            .enumerate()
            .map(|(i, p)| *p + Point2::new([noise[2 * i], noise[2 * i + 1]]) * 1e-3)
            .collect();
        let sigma = estimate_noise(&rounded(&noisy, 5)).sigma;
        assert!((sigma / 1e-3 - 1.0).abs() < 0.1, "{sigma}");
        // Coordinates not on a decimal grid have only the doubles' own resolution.
        assert!(resolution(&ellipse(400)) < 1e-13);
    }

    #[test]
    fn the_resolution_is_the_same_at_every_scale() {
        // Five decimals multiplied by a scale that is no power of ten or two are a lattice of
        // the scaled quantum; the noise found on them scales with them.
        let q = 1e5;
        let written: Vec<Point2> = ellipse(400)
            .iter()
            .map(|p| Point2::new([(p[0] * q).round() / q, (p[1] * q).round() / q]))
            .collect();
        let noise = gaussian(5, 800);
        let noisy: Vec<Point2> = written
            .iter()
            .enumerate()
            .map(|(i, p)| *p + Point2::new([noise[2 * i], noise[2 * i + 1]]) * 3e-4)
            .map(|p| Point2::new([(p[0] * q).round() / q, (p[1] * q).round() / q]))
            .collect();
        let unit = estimate_noise(&noisy).sigma;
        for scale in [7.57, 6.2e151 / 1e150, 1e-140, 3.3e140] {
            let scaled: Vec<Point2> = written.iter().map(|p| *p * scale).collect();
            let found = resolution(&scaled) / scale;
            assert!((found / 1e-5 - 1.0).abs() < 1e-9, "{scale}: {found}");
            assert_eq!(estimate_noise(&scaled).sigma, 0.0, "{scale}");
            let moved: Vec<Point2> = noisy
                .iter()
                .map(|p| (*p + Point2::new([1e3, -2e3])) * scale)
                .collect();
            let sigma = estimate_noise(&moved).sigma / scale;
            assert!(
                (sigma / unit - 1.0).abs() < 1e-6,
                "{scale}: {sigma} vs {unit}"
            );
        }
        // Stations on a coarse grid beside a finely written coordinate: the fine one decides.
        let stations: Vec<Point2> = (0..=40)
            .map(|k| Point2::new([0.025 * k as f64, ((0.3 * k as f64).sin() * q).round() / q]))
            .collect();
        assert!((resolution(&stations) / 1e-5 - 1.0).abs() < 1e-6);
    }
}

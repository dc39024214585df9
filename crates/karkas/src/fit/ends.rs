//! Where the open ends of a noisy fit lie along the curve (docs/methods.md §4, "Ends").
//!
//! A foot-point fit places an open end badly on noisy points. The points beyond the end
//! project onto the end itself, so their residuals pull it outward along the tangent, and
//! nothing pulls it back: the points inside project across the curve. On a dense cloud (a
//! trailing edge sampled in cosine spacing) the end runs out about one noise deviation past
//! the data. Across the curve the foot points place the end well.
//!
//! So each end is held on the fit's own tangent line, at the position along it that the run of
//! points towards that end says. That position comes from a quadratic in the point index,
//! fitted by least squares to the first `m` points and evaluated at index 0. The points are
//! measured in order, so their positions are a smooth function of the index near the end,
//! and a quadratic follows cosine as well as uniform spacing there. The windows run from 5
//! points, each half as long again as the last, to at most a quarter of the points; the
//! longest window is taken on which the cubic's value at index 0 agrees with the quadratic's
//! within `2` standard errors of their difference (from the noise estimate). Long windows
//! average the noise away, and the cubic shows where the quadratic's bias begins. Going
//! from the longest window down keeps a few outliers among the first points from choosing a
//! short window: in a long window their weight is small. (Lepski's rule, growing the window
//! until an estimate disagrees with a shorter window's, stops at once on such outliers.)
//!
//! Points that crowd towards the end with their spacing falling to zero there (cosine spacing
//! at a trailing edge) are even functions of the index about the end, and the even quadratic
//! `c0 + c2 i^2` gives the end with less than half the quadratic's variance on a window. It is
//! taken on the longest window where the quadratic agrees with it, when that window is at
//! least as long as the quadratic's own (see [`estimate_end`]). On NACA 4415 with 32 uniform
//! knots at noise 1e-3 (40 seeds) the end then lies 0.33 noise deviations from the true
//! trailing edge (RMS) at 1000 points and 0.15 at 5000, against 0.40 and 0.19 with the
//! quadratic alone.
//!
//! Where the two estimates agree within [`COINCIDENT`] standard errors of their difference,
//! the ends meet (a closed trailing edge: upper and lower surface end at one point) and each
//! run estimates the same point. Both ends are then held at the inverse-variance mean of the
//! two, along and across the curve: it has about `1/sqrt 2` of either estimate's error. With
//! the quadratic alone, NACA 4415 with 1000 points at noise 1e-3 ends 0.51 deviations from
//! the true trailing edge with each end held on its tangent line where its own estimate
//! projects (RMS over 40 noise seeds), 0.37 at the common point.
//!
//! The least-squares weights come from the normal equations of the powers of `i / m`,
//! solved with `nalgebra`. On 1000-5000 noisy points of NACA sections the quadratic's
//! estimate lies within 0.2-0.55 noise deviations of the true trailing edge (RMS, along the
//! chord), where a free foot-point end lies about one deviation out.

use super::hermite::HermiteSpline;
use crate::Point;
use nalgebra::{SMatrix, SVector};

/// The smallest window, in points.
const FIRST_WINDOW: usize = 5;
/// The largest window, as a share of the points.
const LARGEST_SHARE: f64 = 0.25;
/// How far the cubic's end may lie from the quadratic's on a window that is kept, in
/// standard errors of their difference.
const AGREEMENT: f64 = 2.0;
/// The largest standard error of an estimate that is used, for unit noise: an estimate
/// less than twice as precise as the first point alone is not worth holding the end at
/// (the quadratic has 0.94 on 5 points, 0.51 on 31 and 0.42 on 47, the first window length
/// tried that qualifies: so at least 188 points).
const USEFUL_SPREAD: f64 = 0.5;
/// Two end estimates closer than this many standard errors of their difference are taken
/// for one point (the ends of a contour that meet).
const COINCIDENT: f64 = 3.0;

/// The end pins of a fit of `points` whose free fit is `spline`, for points with noise
/// `sigma` per coordinate. Each pin lies on the spline's tangent line at that end, where the
/// estimate of the end from the points projects onto it; when the two estimates agree within
/// the noise (the ends meet), both pins are their common point. `None` when there is no noise
/// to correct for, too few points, or a degenerate end.
pub(crate) fn end_pins<const D: usize>(
    points: &[Point<D>],
    sigma: f64,
    spline: &HermiteSpline<D>,
) -> Option<[Point<D>; 2]> {
    if sigma.is_nan() || sigma <= 0.0 || points.len() < 4 * FIRST_WINDOW {
        return None;
    }
    let (values, derivatives) = (spline.values(), spline.derivatives());
    let last = values.len() - 1;
    let start = estimate_end(points.iter(), points.len(), sigma);
    let end = estimate_end(points.iter().rev(), points.len(), sigma);
    if start.is_none() && end.is_none() {
        return None;
    }
    if let (Some(a), Some(b)) = (start, end) {
        if let Some(common) = common_end(a, b, sigma) {
            // Ends that meet: both held at the common point, along and across alike.
            return Some([common, common]);
        }
    }
    // An end without an estimate is held where the free fit put it.
    Some([
        on_tangent(values[0], derivatives[0], start.map_or(values[0], |e| e.at))?,
        on_tangent(
            values[last],
            derivatives[last],
            end.map_or(values[last], |e| e.at),
        )?,
    ])
}

/// The common point of two end estimates that the noise does not tell apart (a contour whose
/// ends meet, the closed trailing edge of a section): their inverse-variance mean. `None` when
/// they lie more than [`COINCIDENT`] standard errors of their difference apart.
fn common_end<const D: usize>(
    a: EndEstimate<D>,
    b: EndEstimate<D>,
    sigma: f64,
) -> Option<Point<D>> {
    let (va, vb) = (a.spread * a.spread, b.spread * b.spread);
    let apart = (a.at - b.at).norm();
    if apart.is_nan() || apart > COINCIDENT * sigma * (va + vb).sqrt() {
        return None;
    }
    let at = a.at * (vb / (va + vb)) + b.at * (va / (va + vb));
    at.is_finite().then_some(at)
}

/// `estimate` projected onto the line through `end` along `tangent`.
fn on_tangent<const D: usize>(
    end: Point<D>,
    tangent: Point<D>,
    estimate: Point<D>,
) -> Option<Point<D>> {
    let norm_sq = tangent.dot(tangent);
    if !(norm_sq > 0.0 && norm_sq.is_finite()) {
        return None;
    }
    let along = (estimate - end).dot(tangent) / norm_sq;
    let pin = end + tangent * along;
    pin.is_finite().then_some(pin)
}

/// An estimate of where a run of points starts.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct EndEstimate<const D: usize> {
    /// The estimated end.
    pub(crate) at: Point<D>,
    /// Its standard error per coordinate, for unit noise (the norm of the weights).
    pub(crate) spread: f64,
    /// The points it was estimated from.
    pub(crate) window: usize,
}

/// The end of the ordered points `run` (`n` in all) at index 0 (`None` when no window gives
/// an estimate):
///
/// - the quadratic in the index on the longest window where the cubic agrees with it;
/// - or, where the even quadratic `c0 + c2 i^2` agrees with the quadratic on a window at
///   least as long, the even quadratic on the longest such window. Points that crowd towards
///   the end with their spacing falling to zero there (cosine spacing at a trailing edge)
///   are even functions of the index about the end, and two coefficients estimate the end
///   with less than half the quadratic's variance on a window. A shorter window is not
///   taken: there the test has too little power to see an odd term (points spaced evenly),
///   and the even model would carry its bias.
pub(crate) fn estimate_end<'a, const D: usize>(
    run: impl Iterator<Item = &'a Point<D>> + Clone,
    n: usize,
    sigma: f64,
) -> Option<EndEstimate<D>> {
    let general = longest_agreeing(run.clone(), n, sigma, [0, 1, 2], [0, 1, 2, 3])?;
    match longest_agreeing(run, n, sigma, [0, 2], [0, 1, 2]) {
        Some(even) if even.window >= general.window => Some(even),
        _ => Some(general),
    }
}

/// The end of `run` at index 0 from the polynomial in the index with the powers `model`, on
/// the longest window where the polynomial with the powers `check` agrees with it (`None`
/// when no window does, or none is long enough to be twice as precise as the first point).
fn longest_agreeing<'a, const D: usize, const K: usize, const L: usize>(
    run: impl Iterator<Item = &'a Point<D>> + Clone,
    n: usize,
    sigma: f64,
    model: [i32; K],
    check: [i32; L],
) -> Option<EndEstimate<D>> {
    let largest = ((n as f64 * LARGEST_SHARE) as usize).max(FIRST_WINDOW);
    let mut windows = vec![FIRST_WINDOW];
    while let Some(&m) = windows.last() {
        let next = m + m / 2 + 1;
        if next > largest {
            break;
        }
        windows.push(next);
    }
    windows.into_iter().rev().find_map(|m| {
        let fitted = start_weights(m, model)?;
        let wider = start_weights(m, check)?;
        let (mut at, mut at_check) = (Point::<D>::ZERO, Point::<D>::ZERO);
        let (mut own, mut spread) = (0.0, 0.0);
        for (i, p) in run.clone().take(m).enumerate() {
            let x = i as f64 / m as f64;
            let (w, w_check) = (polynomial(&fitted, model, x), polynomial(&wider, check, x));
            at = at.add_scaled(w, *p);
            at_check = at_check.add_scaled(w_check, *p);
            own += w * w;
            spread += (w_check - w) * (w_check - w);
        }
        let agree = (at_check - at).norm() <= AGREEMENT * sigma * spread.sqrt();
        let error = own.sqrt();
        let useful = agree && error <= USEFUL_SPREAD && at.is_finite();
        useful.then_some(EndEstimate {
            at,
            spread: error,
            window: m,
        })
    })
}

/// The coefficients `c` of the least-squares weights `w_i = sum_j c_j x_i^(p_j)` (`x_i = i /
/// m`, `i < m`, `p = powers`, the first 0) that give the polynomial with those powers fitted
/// to `m` values at `x = 0`: the first row of the inverse of the normal matrix.
fn start_weights<const K: usize>(m: usize, powers: [i32; K]) -> Option<SVector<f64, K>> {
    let mut normal = SMatrix::<f64, K, K>::zeros();
    for i in 0..m {
        let x = i as f64 / m as f64;
        let row = SVector::<f64, K>::from_fn(|r, _| x.powi(powers[r]));
        normal += row * row.transpose();
    }
    let inverse = normal.try_inverse()?;
    Some(inverse.row(0).transpose())
}

/// `sum_j c_j x^(p_j)`.
fn polynomial<const K: usize>(c: &SVector<f64, K>, powers: [i32; K], x: f64) -> f64 {
    c.iter().zip(powers).map(|(&cj, p)| cj * x.powi(p)).sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    type P2 = Point<2>;

    /// `n` points `(x^2, 3 + 2 x)`, `x = i / n`, with Gaussian noise of `sigma` per
    /// coordinate (Box-Muller on a xorshift generator seeded with `seed`).
    fn quadratic_run(n: usize, sigma: f64, seed: u64) -> Vec<P2> {
        let mut normal = gaussian(seed);
        (0..n)
            .map(|i| {
                let x = i as f64 / n as f64;
                P2::new([x * x + sigma * normal(), 3.0 + 2.0 * x + sigma * normal()])
            })
            .collect()
    }

    /// Standard normal deviates: Box-Muller on a xorshift generator seeded with `seed`.
    fn gaussian(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed.wrapping_mul(0x9E37_79B9_7F4A_7C15) | 1;
        let mut uniform = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            ((state >> 11) as f64 + 0.5) / (1u64 << 53) as f64
        };
        move || {
            let (a, b) = (uniform(), uniform());
            (-2.0 * a.ln()).sqrt() * (2.0 * std::f64::consts::PI * b).cos()
        }
    }

    /// `n` points round the ellipse `((1 + cos b) / 2, 0.1 sin b)`, `b` uniform over one turn
    /// (so both ends at `(1, 0)`), shifted by `gap` in `y` along the way (the last point
    /// `gap` above the first), with Gaussian noise of `sigma` per coordinate.
    fn closed_run(n: usize, sigma: f64, gap: f64, seed: u64) -> Vec<P2> {
        let mut normal = gaussian(seed);
        (0..n)
            .map(|i| {
                let s = i as f64 / (n - 1) as f64;
                let b = 2.0 * std::f64::consts::PI * s;
                let x = 0.5 * (1.0 + b.cos()) + sigma * normal();
                P2::new([x, 0.1 * b.sin() + gap * s + sigma * normal()])
            })
            .collect()
    }

    /// A spline from the first to the last of `run`, leaving along the run's ends.
    fn spline_along(run: &[P2]) -> HermiteSpline<2> {
        let (first, last) = (run[0], run[run.len() - 1]);
        let middle = run[run.len() / 2];
        let knots = vec![0.0, 0.5, 1.0];
        let values = vec![first, middle, last];
        let derivatives = vec![run[10] - first, last - first, last - run[run.len() - 11]];
        HermiteSpline::new(knots, values, derivatives).unwrap()
    }

    #[test]
    fn ends_that_meet_are_held_at_their_common_point() {
        // 1000 points round a closed contour at noise 1e-3, 100 seeds. Where both ends have
        // an estimate, both pins are one point (but for the odd seed whose two estimates
        // the noise puts 3 standard errors apart), about 1/sqrt(2) as far from the true end
        // as either end's own estimate.
        let (sigma, truth) = (1e-3, P2::new([1.0, 0.0]));
        let (mut own, mut pinned, mut both, mut met) = (0.0, 0.0, 0, 0);
        for seed in 0..100 {
            let run = closed_run(1000, sigma, 0.0, seed);
            let first = estimate_end(run.iter(), run.len(), sigma);
            let last = estimate_end(run.iter().rev(), run.len(), sigma);
            let (Some(first), Some(last)) = (first, last) else {
                continue;
            };
            let [start, end] = end_pins(&run, sigma, &spline_along(&run)).unwrap();
            both += 1;
            met += usize::from(start == end);
            own += (first.at - truth).norm_sq() + (last.at - truth).norm_sq();
            pinned += (start - truth).norm_sq() + (end - truth).norm_sq();
        }
        let (own, pinned) = (
            (own / 2.0 / both as f64).sqrt(),
            (pinned / 2.0 / both as f64).sqrt(),
        );
        eprintln!("{met} of {both} met; own estimates {own:e}, pins {pinned:e}");
        assert!(
            both >= 90 && met as f64 >= 0.95 * both as f64,
            "{met} of {both}"
        );
        assert!(pinned < 0.85 * own, "{pinned:e} against {own:e}");
    }

    #[test]
    fn ends_the_noise_tells_apart_keep_their_own_pins() {
        // The same contour with its ends 10 deviations apart: each pin stays by its end.
        let sigma = 1e-3;
        let run = closed_run(1000, sigma, 10.0 * sigma, 3);
        let [start, end] = end_pins(&run, sigma, &spline_along(&run)).unwrap();
        assert!(
            (start - P2::new([1.0, 0.0])).norm() < 2.0 * sigma,
            "{start:?}"
        );
        assert!(
            (end - P2::new([1.0, 10.0 * sigma])).norm() < 2.0 * sigma,
            "{end:?}"
        );
    }

    /// `n` points of the curve `(u, 0.3 u - 0.2 u^2)` crowding towards its start as cosine
    /// spacing does (`u = 1 - cos(pi i / (2 (n - 1)))`, so both coordinates are even in the
    /// index `i` about the start), with Gaussian noise of `sigma` per coordinate.
    fn crowded_run(n: usize, sigma: f64, seed: u64) -> Vec<P2> {
        let mut normal = gaussian(seed);
        (0..n)
            .map(|i| {
                let b = std::f64::consts::FRAC_PI_2 * i as f64 / (n - 1) as f64;
                let u = 1.0 - b.cos();
                P2::new([
                    u + sigma * normal(),
                    0.3 * u - 0.2 * u * u + sigma * normal(),
                ])
            })
            .collect()
    }

    #[test]
    fn points_that_crowd_towards_the_end_take_the_even_model() {
        // 200 noisy runs of 1000 points: the even quadratic brings the start closer to the
        // truth (RMS) than the quadratic alone (measured: 2.97e-4 against 3.41e-4).
        let sigma = 1e-3;
        let (mut chosen, mut general, mut counted) = (0.0, 0.0, 0);
        for seed in 0..200 {
            let run = crowded_run(1000, sigma, seed);
            let quadratic = longest_agreeing(run.iter(), run.len(), sigma, [0, 1, 2], [0, 1, 2, 3]);
            let (Some(end), Some(quadratic)) =
                (estimate_end(run.iter(), run.len(), sigma), quadratic)
            else {
                continue;
            };
            counted += 1;
            chosen += end.at.norm_sq();
            general += quadratic.at.norm_sq();
        }
        let (chosen, general) = (
            (chosen / counted as f64).sqrt(),
            (general / counted as f64).sqrt(),
        );
        eprintln!("{counted} runs: even where it agrees {chosen:e}, quadratic {general:e}");
        assert!(counted >= 180, "{counted}");
        assert!(chosen < 0.92 * general, "{chosen:e} against {general:e}");
    }

    #[test]
    fn evenly_spaced_points_keep_the_quadratic() {
        // Round the ellipse at even steps one coordinate is odd in the index about the end:
        // the even model is never taken.
        let sigma = 1e-3;
        for seed in 0..100 {
            let run = closed_run(1000, sigma, 0.0, seed);
            let quadratic = longest_agreeing(run.iter(), run.len(), sigma, [0, 1, 2], [0, 1, 2, 3]);
            assert_eq!(
                estimate_end(run.iter(), run.len(), sigma),
                quadratic,
                "seed {seed}"
            );
        }
    }

    #[test]
    fn exact_quadratic_gives_its_start() {
        let run = quadratic_run(400, 0.0, 1);
        let end = estimate_end(run.iter(), run.len(), 1e-3).unwrap().at;
        assert!((end - P2::new([0.0, 3.0])).norm() < 1e-12, "{end:?}");
    }

    #[test]
    fn long_windows_average_the_noise() {
        // Over 200 noisy runs of 2000 points the first point is sqrt(2) sigma from the true
        // start (RMS); windows of up to 500 points bring the estimate within a few tenths.
        let sigma = 1e-2;
        let (mut first, mut estimated) = (0.0, 0.0);
        for seed in 0..200 {
            let run = quadratic_run(2000, sigma, seed);
            let end = estimate_end(run.iter(), run.len(), sigma).unwrap().at;
            first += (run[0] - P2::new([0.0, 3.0])).norm_sq();
            estimated += (end - P2::new([0.0, 3.0])).norm_sq();
        }
        let (first, estimated) = ((first / 200.0).sqrt(), (estimated / 200.0).sqrt());
        eprintln!("first point {first:e}, estimate {estimated:e}");
        assert!(first > 1.2 * sigma, "{first:e}");
        assert!(estimated < 0.3 * sigma, "{estimated:e}");
    }

    #[test]
    fn outliers_at_the_start_do_not_shorten_the_window() {
        // The first two points 6 and 5 sigma off: a short window would follow them.
        let sigma = 1e-2;
        let mut worst: f64 = 0.0;
        for seed in 0..50 {
            let mut run = quadratic_run(2000, sigma, seed);
            run[0] += P2::new([-6.0 * sigma, 5.0 * sigma]);
            run[1] += P2::new([4.0 * sigma, -5.0 * sigma]);
            let end = estimate_end(run.iter(), run.len(), sigma).unwrap().at;
            worst = worst.max((end - P2::new([0.0, 3.0])).norm());
        }
        assert!(worst < 1.5 * sigma, "{worst:e}");
    }

    #[test]
    fn a_bend_beyond_the_quadratic_stops_the_window() {
        // Straight for 60 points, then turning sharply: the window must stop near the
        // turn, so the estimate stays at the straight run's start.
        let run: Vec<P2> = (0..400)
            .map(|i| {
                let x = i as f64 * 0.01;
                let y = if i < 60 {
                    0.0
                } else {
                    (x - 0.6).powi(4) * 50.0
                };
                P2::new([x, y])
            })
            .collect();
        let end = estimate_end(run.iter(), run.len(), 1e-6).unwrap().at;
        assert!(end.norm() < 1e-6, "{end:?}");
    }

    #[test]
    fn reversed_runs_estimate_the_other_end() {
        let run = quadratic_run(400, 0.0, 1);
        let end = estimate_end(run.iter().rev(), run.len(), 1e-3).unwrap().at;
        assert!((end - run[399]).norm() < 1e-12, "{end:?}");
    }

    #[test]
    fn pins_lie_on_the_tangent_lines() {
        let knots = vec![0.0, 0.5, 1.0];
        let values = vec![
            P2::new([0.0, 0.0]),
            P2::new([1.0, 0.5]),
            P2::new([2.0, 0.0]),
        ];
        let derivatives = vec![
            P2::new([2.0, 1.0]),
            P2::new([2.0, 0.0]),
            P2::new([2.0, -1.0]),
        ];
        let spline = HermiteSpline::new(knots, values, derivatives).unwrap();
        let run: Vec<P2> = (0..400)
            .map(|i| P2::new([0.3 + i as f64 * 0.0025, 1.0]))
            .collect();
        let [start, end] = end_pins(&run, 1e-3, &spline).unwrap();
        // Each pin differs from the spline's end along the end tangent only.
        let along = |pin: P2, end: P2, tangent: P2| {
            let d = pin - end;
            (d[0] * tangent[1] - d[1] * tangent[0]).abs()
        };
        assert!(along(start, P2::new([0.0, 0.0]), P2::new([2.0, 1.0])) < 1e-12);
        assert!(along(end, P2::new([2.0, 0.0]), P2::new([2.0, -1.0])) < 1e-12);
        // ... at the projection of the run's ends (0.3, 1) and (1.2975, 1).
        let t = (P2::new([0.3, 1.0]) - P2::new([0.0, 0.0])).dot(P2::new([2.0, 1.0])) / 5.0;
        assert!((start - P2::new([2.0, 1.0]) * t).norm() < 1e-9, "{start:?}");
        assert!(end_pins(&run, 0.0, &spline).is_none());
        assert!(end_pins(&run[..10], 1e-3, &spline).is_none());
        // 40 points: windows of at most 10, not twice as precise as the first point.
        assert!(end_pins(&run[..40], 1e-3, &spline).is_none());
    }
}

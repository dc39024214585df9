//! The noise estimate on exact and noisy points of analytic curves (docs/methods.md §4,
//! "The noise"): exact points, however sparse and curved, read as exact, so that every
//! default of the fit is the paper's method; noisy points read within 30% of their noise
//! wherever the noise stands above what the sampling leaves of the curve's own shape.

use crate::common::Rng;
use crate::fit_reference::naca;
use karkas::fit::{estimate_noise, fit_curve, fit_curve_adaptive, uniform_knots, FitOptions};
use karkas::{Point, Point2, Point3};
use std::f64::consts::PI;

/// One family of analytic curves, sampled at `n` points.
#[derive(Clone, Copy, Debug)]
enum Shape {
    /// A whole ellipse 2 x 0.7, uniform in angle (first and last points equal).
    Ellipse,
    /// Half the ellipse.
    EllipseArc,
    /// NACA 0012, 2412, 4415 (closed trailing edge) in cosine spacing from the trailing edge.
    Naca(f64, f64, f64),
    /// The same starting at the leading edge: the trailing edge is an inner corner.
    NacaFromNose(f64, f64, f64),
    /// Two turns of an Archimedean spiral.
    Spiral,
    /// Half the ellipse 1 x 0.6 closed by its major axis: two corners.
    Dome,
    /// Two turns of a helix (3-D).
    Helix,
}

const SHAPES: [Shape; 10] = [
    Shape::Ellipse,
    Shape::EllipseArc,
    Shape::Naca(0.0, 0.0, 0.12),
    Shape::Naca(0.02, 0.4, 0.12),
    Shape::Naca(0.04, 0.4, 0.15),
    Shape::NacaFromNose(0.0, 0.0, 0.12),
    Shape::NacaFromNose(0.04, 0.4, 0.15),
    Shape::Spiral,
    Shape::Dome,
    Shape::Helix,
];

/// The exact points of `shape`, in 3-D (z = 0 for the planar ones).
fn exact(shape: Shape, n: usize) -> Vec<Point3> {
    let s = |i: usize| i as f64 / (n - 1) as f64;
    let planar = |p: Point2| Point3::new([p[0], p[1], 0.0]);
    (0..n)
        .map(|i| match shape {
            Shape::Ellipse => {
                let a = 2.0 * PI * s(i);
                Point3::new([2.0 * a.cos(), 0.7 * a.sin(), 0.0])
            }
            Shape::EllipseArc => {
                let a = PI * s(i);
                Point3::new([2.0 * a.cos(), 0.7 * a.sin(), 0.0])
            }
            Shape::Naca(m, p, t) => planar(naca(m, p, t, 2.0 * PI * s(i))),
            Shape::NacaFromNose(m, p, t) => planar(naca(
                m,
                p,
                t,
                (PI * (1.0 + 2.0 * s(i))).rem_euclid(2.0 * PI),
            )),
            Shape::Spiral => {
                let a = 4.0 * PI * s(i) + 0.5;
                Point3::new([a * a.cos(), a * a.sin(), 0.0])
            }
            Shape::Dome => {
                let arc = n * 2 / 3;
                if i < arc {
                    let a = PI * i as f64 / (arc - 1) as f64;
                    Point3::new([a.cos(), 0.6 * a.sin(), 0.0])
                } else {
                    let rest = n - arc;
                    let x = -1.0 + 2.0 * (i - arc + 1) as f64 / rest as f64;
                    Point3::new([x, 0.0, 0.0])
                }
            }
            Shape::Helix => {
                let a = 4.0 * PI * s(i);
                Point3::new([a.cos(), a.sin(), 0.3 * a])
            }
        })
        .collect()
}

fn is_planar(shape: Shape) -> bool {
    !matches!(shape, Shape::Helix)
}

fn planar(points: &[Point3]) -> Vec<Point2> {
    points.iter().map(|p| Point2::new([p[0], p[1]])).collect()
}

fn size<const D: usize>(points: &[Point<D>]) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in points {
        for c in 0..D {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (0..D).map(|c| (hi[c] - lo[c]).powi(2)).sum::<f64>().sqrt()
}

/// `points` turned, scaled by `scale` and moved by `offset` times their size.
fn placed<const D: usize>(
    points: &[Point<D>],
    turn: f64,
    scale: f64,
    offset: f64,
) -> Vec<Point<D>> {
    let (c, s) = (turn.cos(), turn.sin());
    let shift = offset * size(points);
    points
        .iter()
        .map(|p| {
            let mut q = *p;
            q[0] = c * p[0] - s * p[1];
            q[1] = s * p[0] + c * p[1];
            for k in 0..D {
                q[k] = (q[k] + shift * (1.0 + k as f64)) * scale;
            }
            q
        })
        .collect()
}

/// The noise estimate of `points` (planar shapes in 2-D) over their size.
fn relative_noise(shape: Shape, points: &[Point3]) -> f64 {
    if is_planar(shape) {
        let p = planar(points);
        estimate_noise(&p).sigma / size(&p)
    } else {
        estimate_noise(points).sigma / size(points)
    }
}

fn noisy(points: &[Point3], sigma: f64, seed: u64, planar_only: bool) -> Vec<Point3> {
    let mut rng = Rng::new(seed);
    points
        .iter()
        .map(|p| {
            let z = if planar_only {
                0.0
            } else {
                sigma * rng.normal()
            };
            Point3::new([
                p[0] + sigma * rng.normal(),
                p[1] + sigma * rng.normal(),
                p[2] + z,
            ])
        })
        .collect()
}

/// The placements every exact case is tried in: turned, scaled and moved off the origin
/// (by a hundred times its size).
const PLACEMENTS: [(f64, f64, f64); 4] = [
    (0.0, 1.0, 0.0),
    (0.7, 1e-3, 100.0),
    (2.1, 1e3, -100.0),
    (4.0, 1e-150, 3.0),
];

#[test]
fn exact_points_read_as_exact_however_sparse() {
    // Every analytic curve of the list from 12 to 60 points, corners and all: the ladder's
    // residuals fall with the order (or rise where the points do not resolve the curve),
    // never stand on a floor that flips at random, so the noise reads 0.
    let mut worst = (0.0f64, String::new());
    for shape in SHAPES {
        for n in 12..=60 {
            for (turn, scale, offset) in PLACEMENTS {
                let points = placed(&exact(shape, n), turn, scale, offset);
                let relative = relative_noise(shape, &points);
                if relative >= worst.0 {
                    worst = (
                        relative,
                        format!("{shape:?} n {n} at {turn}, {scale}, {offset}"),
                    );
                }
            }
        }
    }
    assert!(
        worst.0 < 1e-6,
        "noise {:e} of the size: {}",
        worst.0,
        worst.1
    );
}

/// The spline of `fit`'s result: values and derivatives at its knots.
fn coefficients<const D: usize>(spline: &karkas::fit::HermiteSpline<D>) -> Vec<Point<D>> {
    spline
        .values()
        .iter()
        .chain(spline.derivatives())
        .copied()
        .collect()
}

fn largest_difference<const D: usize>(a: &[Point<D>], b: &[Point<D>]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter()
        .zip(b)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max)
}

/// The default fit and the paper's (`--smoothing 0`) of `points` on `knots` and in the
/// tolerance mode at `tolerance`: their largest differences over the size.
fn defaults_against_the_paper<const D: usize>(
    points: &[Point<D>],
    knots: &[f64],
    corners: Vec<f64>,
    tolerance: f64,
) -> (f64, f64) {
    let defaults = FitOptions {
        corners,
        ..Default::default()
    };
    let paper = FitOptions {
        smoothing: Some(0.0),
        ..defaults.clone()
    };
    let scale = size(points);
    let (a, b) = (
        fit_curve(points, knots, &defaults).unwrap(),
        fit_curve(points, knots, &paper).unwrap(),
    );
    assert!(a.noise.sigma < 1e-6 * scale, "{:?}", a.noise);
    let given = largest_difference(&coefficients(&a.spline), &coefficients(&b.spline)) / scale;
    let (a, b) = (
        fit_curve_adaptive(points, tolerance * scale, &defaults).unwrap(),
        fit_curve_adaptive(points, tolerance * scale, &paper).unwrap(),
    );
    assert_eq!(a.fit.spline.knots(), b.fit.spline.knots());
    let adaptive =
        largest_difference(&coefficients(&a.fit.spline), &coefficients(&b.fit.spline)) / scale;
    (given, adaptive)
}

#[test]
fn on_exact_points_every_default_is_the_papers_method() {
    // Given knots (a quarter as many as points, the corner of the D shape and the trailing
    // edge of the section started at its nose kept as corners) and the tolerance mode
    // (1e-3 of the size): the defaults equal `--smoothing 0` to 1e-9 of the size.
    for shape in SHAPES {
        for n in [12, 17, 24, 33, 47, 60] {
            let points = placed(&exact(shape, n), 0.3, 2.0, 5.0);
            let pieces = (n / 4).max(3);
            let mut knots = uniform_knots(pieces + 1);
            let mut corners = Vec::new();
            let corner_index = match shape {
                Shape::Dome => Some(n * 2 / 3 - 1),
                Shape::NacaFromNose(..) => Some((n - 1) / 2),
                _ => None,
            };
            if let Some(at) = corner_index {
                // The corner's chord-length parameter becomes a knot that stays a corner.
                let chords: Vec<f64> = points.windows(2).map(|w| w[0].distance(w[1])).collect();
                let total: f64 = chords.iter().sum();
                let t = chords[..at].iter().sum::<f64>() / total;
                knots.retain(|k| (k - t).abs() > 0.5 / pieces as f64);
                knots.push(t);
                knots.sort_by(f64::total_cmp);
                corners.push(t);
            }
            let (given, adaptive) = if is_planar(shape) {
                defaults_against_the_paper(&planar(&points), &knots, corners, 1e-3)
            } else {
                defaults_against_the_paper(&points, &knots, corners, 1e-3)
            };
            assert!(
                given <= 1e-9 && adaptive <= 1e-9,
                "{shape:?} n {n}: given knots {given:e}, tolerance mode {adaptive:e}"
            );
        }
    }
}

/// The ratio of the estimate to the true noise for every seed of `seeds` (Gaussian noise of
/// `relative` times the size per coordinate).
fn ratios(shape: Shape, n: usize, relative: f64, seeds: u64, place: (f64, f64, f64)) -> Vec<f64> {
    let points = exact(shape, n);
    let sigma = relative * size(&points);
    (0..seeds)
        .map(|seed| {
            let q = noisy(&points, sigma, 1 + seed, is_planar(shape));
            let q = placed(&q, place.0, place.1, place.2);
            relative_noise(shape, &q) * size(&q) / (sigma * place.1)
        })
        .collect()
}

#[test]
fn noisy_points_read_their_noise() {
    // Noise of 1e-3 and 1e-2 of the size (and 1e-4 from 200 points on), 60 to 1000 points,
    // turned, scaled and moved: the median of the estimates over the noise sets within 30% of
    // the true noise, and their RMS error within 30% from 200 points on. At 60 points the
    // median of about 50 residuals alone scatters by some 20%: single sets read within 30%
    // four times in five (the ellipse, 40 sets: RMS error 0.22-0.26), and the RMS error over
    // 25 sets reaches 0.32 on the D shape and NACA 4415, so it is held to 35% there.
    let mut report = Vec::new();
    for shape in SHAPES {
        for (n, seeds, levels) in [
            (60, 25, &[1e-3, 1e-2][..]),
            (200, 9, &[1e-4, 1e-3, 1e-2]),
            (1000, 9, &[1e-4, 1e-3, 1e-2]),
        ] {
            for &relative in levels {
                for place in [(0.0, 1.0, 0.0), (1.3, 1e4, 50.0)] {
                    let mut r = ratios(shape, n, relative, seeds, place);
                    r.sort_by(f64::total_cmp);
                    let median = r[r.len() / 2];
                    let rms =
                        (r.iter().map(|x| (x - 1.0).powi(2)).sum::<f64>() / r.len() as f64).sqrt();
                    let rms_limit = if n < 200 { 0.35 } else { 0.3 };
                    if (median - 1.0).abs() > 0.3 || rms > rms_limit {
                        report.push(format!(
                            "{shape:?} n {n} noise {relative:e} at {place:?}: median {median:.2}, RMS error {rms:.2}"
                        ));
                    }
                }
            }
        }
    }
    assert!(report.is_empty(), "{}", report.join("\n"));
}

#[test]
#[ignore = "prints, per shape, how many of 20 noise sets read noise, how many within 30%, and the median ratio"]
fn noise_tables() {
    for relative in [1e-4, 1e-3, 1e-2] {
        for n in [12, 20, 30, 40, 60, 200, 1000] {
            let line: Vec<String> = SHAPES
                .iter()
                .map(|&shape| {
                    let mut r = ratios(shape, n, relative, 20, (0.0, 1.0, 0.0));
                    let found = r.iter().filter(|&&x| x > 0.0).count();
                    r.sort_by(f64::total_cmp);
                    let within = r.iter().filter(|&&x| (x - 1.0).abs() <= 0.3).count();
                    format!("{found}/{within}/{:.2}", r[10])
                })
                .collect();
            eprintln!("noise {relative:e} n {n}: {}", line.join(" "));
        }
    }
}

/// Curves the estimator was not tuned on, sampled at `n` points (3-D; z = 0 for the planar
/// ones): a limaçon, a superellipse, NACA 6409, an S curve, a logarithmic spiral, an ellipse
/// with a third harmonic over three quarters of a turn, the wavy curve of the CLI's scale
/// tests, and a trefoil knot.
fn untuned(shape: usize, n: usize) -> Vec<Point3> {
    let s = |i: usize| i as f64 / (n - 1) as f64;
    (0..n)
        .map(|i| match shape {
            0 => {
                let a = 2.0 * PI * s(i);
                let r = 1.0 + 0.5 * a.cos();
                Point3::new([r * a.cos(), r * a.sin(), 0.0])
            }
            1 => {
                let a = 2.0 * PI * s(i);
                let f = |c: f64| c.signum() * c.abs().powf(0.8);
                Point3::new([1.5 * f(a.cos()), f(a.sin()), 0.0])
            }
            2 => {
                let p = naca(0.06, 0.4, 0.09, 2.0 * PI * s(i));
                Point3::new([p[0], p[1], 0.0])
            }
            3 => {
                let x = -1.0 + 2.0 * s(i);
                Point3::new([x, (3.0 * x).tanh(), 0.0])
            }
            4 => {
                let a = 3.0 * PI * s(i);
                let r = (0.15 * a).exp();
                Point3::new([r * a.cos(), r * a.sin(), 0.0])
            }
            5 => {
                let a = 1.5 * PI * s(i);
                Point3::new([1.3 * a.cos() + 0.2 * (3.0 * a).cos(), 0.8 * a.sin(), 0.0])
            }
            6 => {
                let t = 3.0 * s(i);
                Point3::new([
                    (3.0 * t).cos() * (1.0 + 0.3 * t),
                    (2.0 * t).sin() + 0.2 * t,
                    0.1 * t * t,
                ])
            }
            _ => {
                let a = 2.0 * PI * s(i);
                Point3::new([
                    a.sin() + 2.0 * (2.0 * a).sin(),
                    a.cos() - 2.0 * (2.0 * a).cos(),
                    -(3.0 * a).sin(),
                ])
            }
        })
        .collect()
}

const UNTUNED: usize = 8;

/// Whether the untuned `shape` is planar (the last two are not).
fn untuned_is_planar(shape: usize) -> bool {
    shape < 6
}

/// The relative noise estimate of untuned points, planar ones in 2-D.
fn untuned_relative(shape: usize, points: &[Point3]) -> f64 {
    if untuned_is_planar(shape) {
        let p = planar(points);
        estimate_noise(&p).sigma / size(&p)
    } else {
        estimate_noise(points).sigma / size(points)
    }
}

/// The (shape, n) of [`untuned`] whose exact points read as noisy, with the largest
/// estimate over the size in any placement: too sparse for what the residual ladder tells
/// apart (limaçon 17 points: 1.3e-3; superellipse 30: 3.4e-4; S curve 12, 15, 19: 1.2e-3,
/// 3.2e-4, 7.6e-5; ellipse with a third harmonic 13 to 15: 1.3e-2, 4.0e-3, 3.2e-3; the wavy
/// 3-D curve at 12: 2.5e-2).
const UNTUNED_MISREAD: [(usize, usize, f64); 9] = [
    (0, 17, 2e-3),
    (1, 30, 5e-4),
    (3, 12, 2e-3),
    (3, 15, 5e-4),
    (3, 19, 1e-4),
    (5, 13, 2e-2),
    (5, 14, 6e-3),
    (5, 15, 5e-3),
    (6, 12, 3e-2),
];

#[test]
fn exact_points_of_untuned_curves_read_as_exact() {
    // From 12 to 60 points, in six placements (turned, scaled 1e-150..1e3 and by decimal
    // factors, moved up to 100 sizes off the origin): below 1e-6 of the size but for the
    // listed sparse cases, which stay below their stated figures.
    let mut failures = Vec::new();
    for shape in 0..UNTUNED {
        for n in 12..=60 {
            for (turn, scale, offset) in [
                (0.0, 1.0, 0.0),
                (0.7, 1e-3, 100.0),
                (2.1, 1e3, -100.0),
                (4.0, 1e-150, 3.0),
                (1.1, 7.4, 0.3),
                (5.5, 3.7e-7, -20.0),
            ] {
                let points = placed(&untuned(shape, n), turn, scale, offset);
                let relative = untuned_relative(shape, &points);
                let bound = UNTUNED_MISREAD
                    .iter()
                    .find(|&&(s, m, _)| (s, m) == (shape, n))
                    .map_or(1e-6, |&(_, _, b)| b);
                if relative >= bound {
                    failures.push(format!(
                        "shape {shape} n {n} at {turn}, {scale}, {offset}: {relative:e}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The median over `seeds` noise sets of the estimate over the true noise (`relative` times
/// the size per coordinate) on `n` points of the untuned `shape`, turned, scaled and moved.
fn untuned_median(shape: usize, n: usize, relative: f64, seeds: u64) -> f64 {
    let points = untuned(shape, n);
    let sigma = relative * size(&points);
    let mut r: Vec<f64> = (0..seeds)
        .map(|seed| {
            let q = noisy(
                &points,
                sigma,
                9001 + 31 * seed + n as u64,
                untuned_is_planar(shape),
            );
            let q = placed(&q, 2.6, 0.05, -7.0);
            untuned_relative(shape, &q) * size(&q) / (sigma * 0.05)
        })
        .collect();
    r.sort_by(f64::total_cmp);
    r[r.len() / 2]
}

#[test]
fn noisy_points_of_untuned_curves_read_their_noise_where_it_shows() {
    // Noise of 1e-4 to 1e-2 of the size on 12 to 200 points: the median over 15 noise sets
    // within 30% of the true noise from 100 points at 1e-4, 60 at 3e-4 and 1e-3, 40 at 3e-3 and
    // 1e-2 of the size (the trefoil knot, which turns fastest, sets most of these). Sparser,
    // the residuals of the exact curve reach the noise: the estimate reads 0 (the fit is then
    // the paper's) or the noise plus some of the shape (`untuned_noise_tables`).
    let mut failures = Vec::new();
    for (relative, from) in [(1e-4, 100), (3e-4, 60), (1e-3, 60), (3e-3, 40), (1e-2, 40)] {
        for n in [12, 16, 20, 24, 30, 40, 60, 100, 200] {
            if n < from {
                continue;
            }
            for shape in 0..UNTUNED {
                let median = untuned_median(shape, n, relative, 15);
                if (median - 1.0).abs() > 0.3 {
                    failures.push(format!(
                        "shape {shape} n {n} noise {relative:e}: median {median:.2}"
                    ));
                }
            }
        }
    }
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
#[ignore = "prints, per untuned shape, the median ratio of the estimate to the true noise"]
fn untuned_noise_tables() {
    for relative in [1e-4, 3e-4, 1e-3, 3e-3, 1e-2] {
        for n in [12, 16, 20, 24, 30, 40, 60, 100, 200] {
            let line: Vec<String> = (0..UNTUNED)
                .map(|shape| format!("{:.2}", untuned_median(shape, n, relative, 15)))
                .collect();
            eprintln!("noise {relative:e} n {n}: {}", line.join(" "));
        }
    }
}

/// The 30 points of the CLI's shape-warning test: an arc of 2 rad whose radius ramps by a
/// sawtooth of up to 3e-3 (the noise of 1e-3 of the size the fit must smooth).
#[test]
fn a_sawtooth_on_thirty_points_reads_as_noise() {
    let points: Vec<Point2> = (0..30)
        .map(|i| {
            let a = 2.0 * i as f64 / 29.0;
            let wobble = 0.003 * ((i * 7919) % 13) as f64 / 13.0;
            Point2::new([(1.0 + wobble) * a.cos(), (1.0 + wobble) * a.sin()])
        })
        .collect();
    // The radius's deviation from its mean: 3e-3 times that of 0..12 / 13, about 8.6e-4.
    let values: Vec<f64> = (0..30)
        .map(|i| 0.003 * ((i * 7919) % 13) as f64 / 13.0)
        .collect();
    let mean = values.iter().sum::<f64>() / 30.0;
    let deviation = (values.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / 30.0).sqrt();
    let estimate = estimate_noise(&points).sigma;
    assert!(
        (estimate / deviation - 1.0).abs() < 0.3,
        "{estimate:e} against {deviation:e}"
    );
}

//! Translation: every mode of the fit (uniform knots, given knots with a corner, the jump
//! bound `eps`, pinned ends, free ends, the tolerance mode) in the plane and in space gives,
//! for points moved by offsets from 1e3 to 1e8, the curve of the unmoved points moved, to 64
//! units in the last place of the offset (docs/methods.md §4: the fit moves its points to the
//! origin by their bounding box's corner).
//!
//! The points lie on the grid of 2^-26, so that every moved point is exactly the point plus
//! the offset: the comparison is of the fit, not of the rounding of the input.

use crate::common::Rng;
use crate::fit_reference::naca;
use karkas::fit::{fit_curve, fit_curve_adaptive, uniform_knots, FitEnds, FitOptions};
use karkas::{Curve, Point};
use std::f64::consts::PI;

fn grid<const D: usize>(p: Point<D>) -> Point<D> {
    Point(p.0.map(|c| (c * 2f64.powi(26)).round() / 2f64.powi(26)))
}

/// The fit of `points` by every mode, as curves sampled at 1001 parameters.
fn every_mode<const D: usize>(points: &[Point<D>]) -> Vec<(&'static str, Vec<Point<D>>)> {
    let sample = |curve: &dyn Fn(f64) -> Point<D>| -> Vec<Point<D>> {
        (0..=1000).map(|k| curve(k as f64 / 1000.0)).collect()
    };
    let knots = uniform_knots(12);
    let mut out = Vec::new();
    let modes: [(&str, Vec<f64>, FitOptions); 5] = [
        ("uniform knots", knots.clone(), FitOptions::default()),
        (
            "a corner",
            knots.clone(),
            FitOptions {
                corners: vec![knots[6]],
                ..FitOptions::default()
            },
        ),
        (
            "eps",
            knots.clone(),
            FitOptions {
                eps: 1e-2,
                ..FitOptions::default()
            },
        ),
        (
            "pinned ends",
            knots.clone(),
            FitOptions {
                ends: FitEnds::Pinned,
                ..FitOptions::default()
            },
        ),
        (
            "free ends",
            knots.clone(),
            FitOptions {
                ends: FitEnds::Free,
                ..FitOptions::default()
            },
        ),
    ];
    for (name, knots, options) in modes {
        let fit = fit_curve(points, &knots, &options).unwrap();
        out.push((name, sample(&|t| fit.spline.eval(t))));
    }
    let adaptive = fit_curve_adaptive(points, 3e-4, &FitOptions::default()).unwrap();
    out.push(("tolerance", sample(&|t| adaptive.fit.spline.eval(t))));
    out
}

fn check<const D: usize>(what: &str, points: &[Point<D>], direction: Point<D>) {
    let base = every_mode(points);
    for offset in [1e3, 1e4, 1e5, 1e6, 1e7, 1e8] {
        let shift = direction * offset;
        let moved: Vec<Point<D>> = points.iter().map(|&p| p + shift).collect();
        assert!(moved.iter().zip(points).all(|(m, p)| *m - shift == *p));
        // The spacing of the doubles at the offset.
        let ulp = 2f64.powi(offset.log2().floor() as i32 - 52);
        for ((name, at_origin), (_, far)) in base.iter().zip(every_mode(&moved)) {
            let worst = at_origin
                .iter()
                .zip(&far)
                .map(|(a, b)| (*b - (*a + shift)).max_abs())
                .fold(0.0, f64::max);
            assert!(
                worst <= 64.0 * ulp,
                "{what}, {name}, offset {offset:e}: moved by {worst:.3e} ({:.1} units in the last place)",
                worst / ulp
            );
        }
    }
}

#[test]
fn every_fit_mode_moves_with_the_points() {
    let mut rng = Rng::new(11);
    let airfoil: Vec<Point<2>> = (0..101)
        .map(|i| {
            let p = naca(0.02, 0.4, 0.12, 2.0 * PI * i as f64 / 100.0);
            grid(Point([
                p[0] + 1e-4 * rng.normal(),
                p[1] + 1e-4 * rng.normal(),
            ]))
        })
        .collect();
    check("NACA 2412", &airfoil, Point([1.0, -0.5]));
    let helix: Vec<Point<3>> = (0..120)
        .map(|i| {
            let a = 4.0 * PI * i as f64 / 119.0;
            grid(Point([
                a.cos() + 1e-4 * rng.normal(),
                a.sin() + 1e-4 * rng.normal(),
                0.1 * a + 1e-4 * rng.normal(),
            ]))
        })
        .collect();
    check("helix", &helix, Point([0.5, 1.0, -1.0]));
}

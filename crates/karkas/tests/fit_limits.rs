//! The two limits of the fit (issue acceptance, METHODS.md §4): `eps -> 0` tends to the C^2
//! least-squares cubic spline on the same knots, a large `eps` is the unconstrained C^1 fit.
//! The references are dense least-squares solves written here (truncated-power C^2 basis,
//! Bezier-form Hermite basis).

mod fit_common;

use fit_common::{c2_basis, hermite_piece, least_squares, noisy_spiral};
use karkas::fit::{fit_curve, FitOptions, PenaltyRule};
use karkas::{Curve, Point2};

const KNOTS: [f64; 5] = [0.0, 0.2, 0.45, 0.7, 1.0];

/// The C^2 least-squares cubic spline on `KNOTS` for points at parameters `ts`, evaluated at
/// `at`.
fn c2_reference(points: &[Point2], ts: &[f64], at: &[f64]) -> Vec<Point2> {
    let rows: Vec<Vec<f64>> = ts.iter().map(|&t| c2_basis(&KNOTS, t)).collect();
    let coef: Vec<Vec<f64>> = (0..2)
        .map(|c| least_squares(&rows, &points.iter().map(|p| p[c]).collect::<Vec<_>>()))
        .collect();
    at.iter()
        .map(|&t| {
            let b = c2_basis(&KNOTS, t);
            let v = |c: usize| b.iter().zip(&coef[c]).map(|(x, y)| x * y).sum::<f64>();
            Point2::new([v(0), v(1)])
        })
        .collect()
}

fn samples() -> Vec<f64> {
    (0..=200).map(|k| k as f64 / 200.0).collect()
}

fn max_gap(a: &[Point2], b: &[Point2]) -> f64 {
    a.iter()
        .zip(b)
        .map(|(p, q)| p.distance(*q))
        .fold(0.0, f64::max)
}

#[test]
fn small_eps_tends_to_the_c2_least_squares_spline_with_parameters_held() {
    let points = noisy_spiral(30, 0.02, 3);
    let at = samples();
    let mut gaps = Vec::new();
    let mut reference = Vec::new();
    for eps in [1e-2, 1e-5, 1e-8] {
        let fit = fit_curve(
            &points,
            &KNOTS,
            &FitOptions {
                eps,
                foot_points: false,
                ..Default::default()
            },
        )
        .unwrap();
        assert!(fit.jump_sum <= eps);
        reference = c2_reference(&points, &fit.parameters, &at);
        let curve: Vec<Point2> = at.iter().map(|&t| fit.spline.eval(t)).collect();
        gaps.push(max_gap(&curve, &reference));
    }
    assert!(gaps[0] > gaps[1] && gaps[1] > gaps[2], "{gaps:?}");
    assert!(gaps[2] < 1e-4, "{gaps:?}");
    assert!(reference.iter().all(|p| p.is_finite()));
}

#[test]
fn small_eps_tends_to_the_c2_spline_with_foot_points() {
    // At the fit's own foot parameters, the nearly-C^2 fit is the C^2 least-squares spline,
    // and its H is no larger than that spline's H at those parameters (which is feasible).
    let points = noisy_spiral(30, 0.02, 3);
    let at = samples();
    let mut gaps = Vec::new();
    for eps in [1e-2, 1e-5, 1e-8] {
        let fit = fit_curve(
            &points,
            &KNOTS,
            &FitOptions {
                eps,
                ..Default::default()
            },
        )
        .unwrap();
        let reference = c2_reference(&points, &fit.parameters, &at);
        let curve: Vec<Point2> = at.iter().map(|&t| fit.spline.eval(t)).collect();
        gaps.push(max_gap(&curve, &reference));
        let at_points = c2_reference(&points, &fit.parameters, &fit.parameters);
        let h_ref: f64 = at_points
            .iter()
            .zip(&points)
            .map(|(a, b)| a.distance_sq(*b))
            .sum();
        assert!(fit.data_term <= h_ref * (1.0 + 1e-9));
    }
    assert!(gaps[0] > gaps[2] && gaps[2] < 1e-4, "{gaps:?}");
}

#[test]
fn large_eps_is_the_unconstrained_c1_fit() {
    let points = noisy_spiral(30, 0.02, 3);
    // With parameters held: the dense least squares in the Bezier-form Hermite basis.
    let fit = fit_curve(
        &points,
        &KNOTS,
        &FitOptions {
            eps: 1e30,
            foot_points: false,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(fit.penalty, 0.0);
    let n_knots = KNOTS.len();
    let basis = |t: f64| -> Vec<f64> {
        // Column j: the curve (first coordinate) of the unit coefficient j.
        (0..2 * n_knots)
            .map(|j| {
                let mut v = vec![Point2::ZERO; n_knots];
                let mut d = vec![Point2::ZERO; n_knots];
                if j % 2 == 0 {
                    v[j / 2] = Point2::new([1.0, 0.0]);
                } else {
                    d[j / 2] = Point2::new([1.0, 0.0]);
                }
                let k = (0..n_knots - 1).find(|&k| t <= KNOTS[k + 1]).unwrap();
                hermite_piece(KNOTS[k], KNOTS[k + 1], v[k], d[k], v[k + 1], d[k + 1], t)[0]
            })
            .collect()
    };
    let rows: Vec<Vec<f64>> = fit.parameters.iter().map(|&t| basis(t)).collect();
    for c in 0..2 {
        let coef = least_squares(&rows, &points.iter().map(|p| p[c]).collect::<Vec<_>>());
        for (l, (v, d)) in fit
            .spline
            .values()
            .iter()
            .zip(fit.spline.derivatives())
            .enumerate()
        {
            assert!((v[c] - coef[2 * l]).abs() < 1e-8, "value {l}");
            assert!(
                (d[c] - coef[2 * l + 1]).abs() < 1e-7 * (1.0 + coef[2 * l + 1].abs()),
                "derivative {l}"
            );
        }
    }
    // With foot points: a bound far above the unconstrained jumps changes nothing.
    let free = fit_curve(&points, &KNOTS, &FitOptions::default()).unwrap();
    let loose = fit_curve(
        &points,
        &KNOTS,
        &FitOptions {
            eps: 10.0 * free.jump_sum,
            penalty: PenaltyRule::SeedBound,
            ..Default::default()
        },
    )
    .unwrap();
    assert_eq!(loose.penalty, 0.0);
    assert_eq!(loose.data_term, free.data_term);
}

//! The two limits of the fit (issue acceptance, docs/methods.md §4): `eps -> 0` tends to the C^2
//! least-squares cubic spline on the same knots, a large `eps` is the unconstrained C^1 fit.
//! The references are dense least-squares solves written here (truncated-power C^2 basis,
//! Bezier-form Hermite basis).

use crate::common::dense_solve_vector;
use crate::fit_reference::{c2_basis, hermite_piece, least_squares, noisy_spiral};
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
                smoothing: Some(0.0),
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
                smoothing: Some(0.0),
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
    // With parameters held (and no bending term): the dense least squares in the Bezier-form
    // Hermite basis.
    let fit = fit_curve(
        &points,
        &KNOTS,
        &FitOptions {
            eps: 1e30,
            foot_points: false,
            fairness: 0.0,
            smoothing: Some(0.0),
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

/// The curve (first coordinate) of the unit coefficient `j` (`2 L` the value, `2 L + 1` the
/// derivative at knot `L`) on `knots`, as Bezier control points per piece.
fn unit_bezier(knots: &[f64], j: usize) -> Vec<[f64; 4]> {
    (0..knots.len() - 1)
        .map(|k| {
            let h = knots[k + 1] - knots[k];
            let at = |knot: usize, kind: usize| f64::from(j == 2 * knot + kind);
            let (r0, h0, r1, h1) = (at(k, 0), at(k, 1), at(k + 1, 0), at(k + 1, 1));
            [r0, r0 + h / 3.0 * h0, r1 - h / 3.0 * h1, r1]
        })
        .collect()
}

#[test]
fn the_bending_term_is_the_integral_of_the_squared_second_derivative() {
    // Parameters held: F = sum |A q - r|^2 + lambda q^T G q with G_jk = int B_j'' B_k'' dt,
    // built here from the Bezier form (R'' is linear on a piece: the integral of a product of
    // two linear functions a + (b - a) s over a piece of length h is h/6 (2 a a' + a b' + b a'
    // + 2 b b')), and solved densely.
    let points = noisy_spiral(30, 0.02, 3);
    let fit = fit_curve(
        &points,
        &KNOTS,
        &FitOptions {
            foot_points: false,
            fairness: 1e-4 / points.len() as f64,
            ..Default::default()
        },
    )
    .unwrap();
    // The weight's formula is tested with the noise estimate; here the term itself.
    let lambda = fit.bending_weight;
    assert!(lambda > 1e-6, "{lambda}");
    let unknowns = 2 * KNOTS.len();
    let bezier: Vec<Vec<[f64; 4]>> = (0..unknowns).map(|j| unit_bezier(&KNOTS, j)).collect();
    // Second derivatives at both ends of every piece.
    let ends = |c: &[f64; 4], h: f64| {
        let s = 6.0 / (h * h);
        (
            (c[0] - 2.0 * c[1] + c[2]) * s,
            (c[1] - 2.0 * c[2] + c[3]) * s,
        )
    };
    let mut gram = vec![vec![0.0; unknowns]; unknowns];
    for (j, row) in gram.iter_mut().enumerate() {
        for (k, entry) in row.iter_mut().enumerate() {
            for piece in 0..KNOTS.len() - 1 {
                let h = KNOTS[piece + 1] - KNOTS[piece];
                let (a, b) = ends(&bezier[j][piece], h);
                let (c, d) = ends(&bezier[k][piece], h);
                // Each piece weighted by its share of lambda, as the fit reports it.
                let share = fit.bending_shares[piece];
                *entry += share * h / 6.0 * (2.0 * a * c + a * d + b * c + 2.0 * b * d);
            }
        }
    }
    let basis = |t: f64| -> Vec<f64> {
        let piece = (0..KNOTS.len() - 1)
            .find(|&k| t <= KNOTS[k + 1])
            .unwrap_or(KNOTS.len() - 2);
        let s = (t - KNOTS[piece]) / (KNOTS[piece + 1] - KNOTS[piece]);
        let bernstein = [
            (1.0 - s).powi(3),
            3.0 * s * (1.0 - s).powi(2),
            3.0 * s * s * (1.0 - s),
            s.powi(3),
        ];
        (0..unknowns)
            .map(|j| (0..4).map(|i| bezier[j][piece][i] * bernstein[i]).sum())
            .collect()
    };
    let rows: Vec<Vec<f64>> = fit.parameters.iter().map(|&t| basis(t)).collect();
    let mut energy = 0.0;
    for c in 0..2 {
        let mut normal = gram
            .iter()
            .map(|r| r.iter().map(|g| lambda * g).collect::<Vec<_>>())
            .collect::<Vec<_>>();
        let mut rhs = vec![0.0; unknowns];
        for (row, p) in rows.iter().zip(&points) {
            for j in 0..unknowns {
                rhs[j] += row[j] * p[c];
                for k in 0..unknowns {
                    normal[j][k] += row[j] * row[k];
                }
            }
        }
        let coef = dense_solve_vector(normal, rhs);
        for l in 0..KNOTS.len() {
            let (v, d) = (fit.spline.values()[l][c], fit.spline.derivatives()[l][c]);
            assert!((v - coef[2 * l]).abs() < 1e-9, "value {l}, coordinate {c}");
            assert!(
                (d - coef[2 * l + 1]).abs() < 1e-8 * (1.0 + d.abs()),
                "derivative {l}"
            );
        }
        for j in 0..unknowns {
            for k in 0..unknowns {
                energy += coef[j] * gram[j][k] * coef[k];
            }
        }
    }
    // The energy the fit reports is the same integral.
    assert!(
        (fit.bending_energy - energy).abs() < 1e-9 * energy,
        "{} vs {energy}",
        fit.bending_energy
    );
    assert!(
        lambda * energy > 1e-2 * fit.data_term,
        "the bending term must matter here"
    );
}

#[test]
fn pinned_ends_pass_through_the_first_and_last_points() {
    let points = noisy_spiral(30, 0.02, 3);
    let (first, last) = (points[0], points[points.len() - 1]);
    for eps in [f64::INFINITY, 1e-3] {
        let free = fit_curve(
            &points,
            &KNOTS,
            &FitOptions {
                eps,
                smoothing: Some(0.0),
                ..Default::default()
            },
        )
        .unwrap();
        let pinned = fit_curve(
            &points,
            &KNOTS,
            &FitOptions {
                eps,
                ends: karkas::fit::FitEnds::Pinned,
                ..Default::default()
            },
        )
        .unwrap();
        // Without the pin the ends miss the points (so the check below can fail).
        assert!(free.spline.eval(0.0).distance(first) > 1e-4);
        assert_eq!(pinned.spline.eval(0.0), first);
        assert_eq!(pinned.spline.eval(1.0), last);
        assert_eq!(pinned.distances[0], 0.0);
        assert!(pinned.jump_sum <= eps);
        // Holding two more values cannot lower what the fit minimizes under the bound.
        let value =
            |f: &karkas::fit::CurveFit<2>| f.data_term + f.bending_weight * f.bending_energy;
        assert!(value(&pinned) >= value(&free) * (1.0 - 1e-9));
    }
}

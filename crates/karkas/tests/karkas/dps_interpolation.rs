//! Interpolation by discrete periodic splines (Malozemov et al.'s §2, problem (1); docs/methods.md §3): the
//! DFT formula against a direct solve of the circulant system, the nodes, the extremal
//! property, and convergence of order 2 to the periodic cubic interpolating spline.

use crate::common::{dense_solve_vector, max_abs, Rng};
use crate::dps_reference::{
    bspline_by_convolution, roughness, roughness_gradient, spline_by_definition,
};
use karkas::dps::{DiscreteSpline, InterpolationPlan};
use karkas::{Error, Point};
use proptest::prelude::*;
use std::f64::consts::PI;

/// Poles of the interpolation problem by Gaussian elimination on the circulant system
/// `sum_p a_p Q_r((l - p) n) = z(l)`, one coordinate at a time, with `Q_r` by definition.
fn poles_by_direct_solve<const D: usize>(nodes: &[Point<D>], r: usize, n: usize) -> Vec<Point<D>> {
    let m = nodes.len();
    let big_n = m * n;
    let q = bspline_by_convolution(m, n, r);
    let matrix: Vec<Vec<f64>> = (0..m)
        .map(|l| (0..m).map(|p| q[((l + m - p) % m) * n % big_n]).collect())
        .collect();
    let mut poles = vec![Point::ZERO; m];
    for c in 0..D {
        let x = dense_solve_vector(matrix.clone(), nodes.iter().map(|z| z[c]).collect());
        for (a, v) in poles.iter_mut().zip(x) {
            a[c] = v;
        }
    }
    poles
}

#[test]
fn dft_formula_agrees_with_a_direct_circulant_solve() {
    let mut rng = Rng::new(2024);
    for (m, n) in [(2, 2), (3, 5), (4, 4), (7, 3), (10, 6), (13, 4)] {
        for r in 1..=5 {
            let nodes: Vec<Point<3>> = rng.points(m);
            let fast = DiscreteSpline::interpolating(&nodes, r, n).unwrap();
            let slow = poles_by_direct_solve(&nodes, r, n);
            let scale = max_abs(&slow);
            for (p, (a, b)) in fast.poles().iter().zip(&slow).enumerate() {
                assert!(
                    a.distance(*b) < 1e-13 * scale,
                    "m={m} n={n} r={r} pole {p}: {a:?} vs {b:?}"
                );
            }
        }
    }
}

#[test]
fn symbol_is_the_spectrum_of_the_interpolation_matrix() {
    // T_r(k) = sum_l Q_r(l n) w^(-k l): the DFT of the matrix's first column (real, since Q_r
    // is symmetric), with Q_r by definition.
    for (m, n, r) in [(5, 3, 2), (8, 4, 3), (6, 2, 1), (9, 5, 4)] {
        let q = bspline_by_convolution(m, n, r);
        let plan = InterpolationPlan::new(m, n, r).unwrap();
        assert_eq!(plan.symbol().len(), m / 2 + 1);
        for (k, t) in plan.symbol().iter().enumerate() {
            let direct: f64 = (0..m)
                .map(|l| q[l * n] * (2.0 * PI * (k * l) as f64 / m as f64).cos())
                .sum();
            assert!(
                (t - direct).abs() < 1e-14,
                "m={m} n={n} r={r} k={k}: {t} vs {direct}"
            );
            assert!(*t > 0.0 && *t <= 1.0 + 1e-15);
        }
    }
}

#[test]
fn plan_rejects_wrong_counts() {
    let mut plan = InterpolationPlan::new(4, 3, 2).unwrap();
    let nodes = [Point([0.0]); 5];
    let mut poles = [Point([0.0]); 4];
    assert_eq!(
        plan.poles_into(&nodes, &mut poles),
        Err(Error::CountMismatch {
            what: "interpolation nodes",
            expected: 4,
            got: 5
        })
    );
    let mut short = [Point([0.0]); 3];
    assert!(plan.poles_into(&nodes[..4], &mut short).is_err());
    let bad = [
        Point([0.0]),
        Point([1.0]),
        Point([f64::INFINITY]),
        Point([0.0]),
    ];
    assert_eq!(
        plan.poles_into(&bad, &mut poles),
        Err(Error::NonFinitePoint { index: 2 })
    );
    assert!(InterpolationPlan::new(1, 3, 2).is_err());
    assert!(InterpolationPlan::new(4, 1, 2).is_err());
    assert!(InterpolationPlan::new(4, 3, 0).is_err());
}

#[test]
fn interpolant_is_the_least_rough_sequence_through_the_nodes() {
    // Extremal property: perturbing the interpolant anywhere but at the nodes never lowers
    // sum ||Delta^r x||^2.
    let mut rng = Rng::new(99);
    for (m, n, r) in [(5, 4, 1), (6, 5, 2), (4, 8, 3), (7, 3, 4), (3, 6, 2)] {
        let nodes: Vec<Point<2>> = rng.points(m);
        let x = DiscreteSpline::interpolating(&nodes, r, n)
            .unwrap()
            .to_values();
        let base = roughness(&x, r);
        for trial in 0..200 {
            let size = [1e-1, 1e-3, 1e-6][trial % 3];
            let mut y = x.clone();
            for (j, v) in y.iter_mut().enumerate() {
                if j % n != 0 {
                    *v = v.add_scaled(size, rng.point());
                }
            }
            let e = roughness(&y, r);
            assert!(
                e >= base * (1.0 - 1e-12),
                "m={m} n={n} r={r} trial {trial}: {e} < {base}"
            );
        }
    }
}

#[test]
fn interpolant_satisfies_the_first_order_optimality_condition() {
    // The gradient of sum ||Delta^r x||^2 vanishes at every free value (j not a multiple of n)
    // and not at the nodes, where the constraints hold it.
    let mut rng = Rng::new(7);
    for (m, n, r) in [(5, 4, 1), (6, 5, 2), (4, 8, 3), (9, 3, 4)] {
        let nodes: Vec<Point<3>> = rng.points(m);
        let x = DiscreteSpline::interpolating(&nodes, r, n)
            .unwrap()
            .to_values();
        let g = roughness_gradient(&x, r);
        let at_nodes = (0..m).map(|l| g[l * n].max_abs()).fold(0.0, f64::max);
        let free = (0..m * n)
            .filter(|j| j % n != 0)
            .map(|j| g[j].max_abs())
            .fold(0.0, f64::max);
        assert!(
            free < 1e-12 * at_nodes.max(1.0),
            "m={m} n={n} r={r}: {free:e} vs {at_nodes:e}"
        );
        assert!(at_nodes > 1e-6, "the test could not fail: {at_nodes:e}");
    }
}

/// The periodic cubic spline through `z(l)` at `t = l` (period `m`), evaluated at `t`:
/// second derivatives from the cyclic system `M_{l-1} + 4 M_l + M_{l+1} = 6 (z_{l+1} - 2 z_l +
/// z_{l-1})`, solved densely.
fn periodic_cubic(z: &[f64], t: f64) -> f64 {
    let m = z.len();
    let mut a = vec![vec![0.0; m]; m];
    let mut b = vec![0.0; m];
    for l in 0..m {
        a[l][l] += 4.0;
        a[l][(l + m - 1) % m] += 1.0;
        a[l][(l + 1) % m] += 1.0;
        b[l] = 6.0 * (z[(l + 1) % m] - 2.0 * z[l] + z[(l + m - 1) % m]);
    }
    let moments = dense_solve_vector(a, b);
    let l = (t.floor() as usize) % m;
    let u = t - t.floor();
    let next = (l + 1) % m;
    (1.0 - u) * z[l]
        + u * z[next]
        + ((1.0 - u).powi(3) - (1.0 - u)) * moments[l] / 6.0
        + (u.powi(3) - u) * moments[next] / 6.0
}

#[test]
fn order_two_converges_to_the_periodic_cubic_spline() {
    // Seven nodes of an irregular closed curve; S_2(j) against the cubic spline at t = j/n.
    let nodes: Vec<Point<2>> = [
        [0.0, 0.0],
        [2.0, -0.5],
        [3.5, 1.0],
        [2.5, 3.0],
        [1.0, 2.0],
        [-0.5, 3.5],
        [-1.5, 1.0],
    ]
    .map(Point)
    .to_vec();
    let m = nodes.len();
    let error = |n: usize| {
        let values = DiscreteSpline::interpolating(&nodes, 2, n)
            .unwrap()
            .to_values();
        let coords: [Vec<f64>; 2] = [0, 1].map(|c| nodes.iter().map(|p| p[c]).collect());
        values
            .iter()
            .enumerate()
            .map(|(j, v)| {
                let t = j as f64 / n as f64;
                let s = Point([periodic_cubic(&coords[0], t), periodic_cubic(&coords[1], t)]);
                v.distance(s)
            })
            .fold(0.0, f64::max)
    };
    let errors: Vec<f64> = [8, 16, 32, 64, 128].map(error).to_vec();
    for w in errors.windows(2) {
        let ratio = w[0] / w[1];
        assert!(
            (3.6..4.4).contains(&ratio),
            "second order in 1/n: {errors:?}, ratio {ratio}"
        );
    }
    assert!(errors[4] < 1e-3, "{errors:?}");
    assert_eq!(m, 7);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// S_r(l n) = z(l), and the interpolant's values equal the definition with its poles.
    #[test]
    fn interpolant_passes_through_its_nodes(m in 2usize..16, n in 2usize..10, r in 1usize..7, seed in 1u64..10_000) {
        let nodes: Vec<Point<3>> = Rng::new(seed).points(m);
        let spline = DiscreteSpline::interpolating(&nodes, r, n).unwrap();
        let values = spline.to_values();
        // The poles may be large for high orders (ill-conditioning); the nodes still match.
        let scale = max_abs(spline.poles());
        for (l, z) in nodes.iter().enumerate() {
            prop_assert!(values[l * n].distance(*z) < 1e-13 * scale, "l={l}");
        }
        if m * n <= 60 {
            let slow = spline_by_definition(&bspline_by_convolution(m, n, r), spline.poles(), n);
            for (a, b) in values.iter().zip(&slow) {
                prop_assert!(a.distance(*b) < 1e-13 * scale);
            }
        }
    }
}

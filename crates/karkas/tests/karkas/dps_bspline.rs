//! The discrete periodic B-spline `Q_r` and spline evaluation (Malozemov et al.'s §1; docs/methods.md §3):
//! the `O(r N)` moving-sum evaluation against the paper's convolution definition, partition of
//! unity, non-negativity, symmetry, the convex hull, periodicity, and the input errors.

use crate::common::Rng;
use crate::dps_reference::{bspline_by_convolution, hat, spline_by_definition};
use karkas::dps::{discrete_bspline, DiscreteSpline, MAX_ORDER};
use karkas::{Error, Point};
use proptest::prelude::*;

const SIZES: [(usize, usize); 7] = [(2, 2), (2, 5), (3, 2), (3, 7), (5, 4), (8, 3), (4, 16)];

#[test]
fn fast_bspline_matches_the_convolution_definition() {
    for (m, n) in SIZES {
        for r in 1..=5 {
            let fast = discrete_bspline(m, n, r).unwrap();
            let slow = bspline_by_convolution(m, n, r);
            assert_eq!(fast.len(), m * n);
            for (j, (a, b)) in fast.iter().zip(&slow).enumerate() {
                assert!((a - b).abs() < 1e-14, "m={m} n={n} r={r} j={j}: {a} vs {b}");
            }
        }
    }
}

#[test]
fn order_one_is_the_hat_of_the_seed() {
    for (m, n) in SIZES {
        let q = discrete_bspline(m, n, 1).unwrap();
        for (j, v) in q.iter().enumerate() {
            assert!((v - hat(m, n, j)).abs() < 1e-15, "m={m} n={n} j={j}");
        }
    }
}

#[test]
fn fast_spline_values_match_the_definition() {
    let mut rng = Rng::new(17);
    for (m, n) in SIZES {
        for r in 1..=4 {
            let poles: Vec<Point<3>> = rng.points(m);
            let fast = DiscreteSpline::from_poles(&poles, r, n)
                .unwrap()
                .to_values();
            let slow = spline_by_definition(&bspline_by_convolution(m, n, r), &poles, n);
            for (j, (a, b)) in fast.iter().zip(&slow).enumerate() {
                assert!(a.distance(*b) < 1e-14, "m={m} n={n} r={r} j={j}");
            }
        }
    }
}

#[test]
fn known_values_of_the_order_two_bspline() {
    // m = 2, n = 2 (N = 4): Q_1 = [1, 1/2, 0, 1/2] and
    // Q_2(j) = (1/2) sum_k Q_1(k) Q_1(j - k) = [3/4, 1/2, 1/4, 1/2].
    assert_eq!(discrete_bspline(2, 2, 2).unwrap(), [0.75, 0.5, 0.25, 0.5]);
}

#[test]
fn shifting_the_poles_shifts_the_values() {
    // Periodicity: the seam j = 0 is not special; rotating the poles by one rotates the curve
    // by n values.
    let mut rng = Rng::new(5);
    let (m, n, r) = (7, 5, 3);
    let poles: Vec<Point<2>> = rng.points(m);
    let mut rotated = poles.clone();
    rotated.rotate_left(1);
    let a = DiscreteSpline::from_poles(&poles, r, n)
        .unwrap()
        .to_values();
    let b = DiscreteSpline::from_poles(&rotated, r, n)
        .unwrap()
        .to_values();
    for j in 0..m * n {
        assert!(b[j].distance(a[(j + n) % (m * n)]) < 1e-14, "j={j}");
    }
}

#[test]
fn long_periods_keep_their_accuracy() {
    // The moving sums restart at every node, so rounding does not grow with N: constant
    // poles give the constant back to within a few ulps even for N = 10^6.
    let poles = vec![Point([1.0e3, -2.5]); 50_000];
    let spline = DiscreteSpline::from_poles(&poles, 4, 20).unwrap();
    let worst = spline
        .to_values()
        .iter()
        .map(|v| v.distance(poles[0]))
        .fold(0.0, f64::max);
    assert!(worst < 1e-11, "{worst}");
}

#[test]
fn bad_input_is_an_error() {
    let two = [Point([0.0, 0.0]), Point([1.0, 0.0])];
    assert!(matches!(
        DiscreteSpline::from_poles(&two[..1], 2, 4),
        Err(Error::TooFewPoints {
            needed: 2,
            got: 1,
            ..
        })
    ));
    assert_eq!(
        DiscreteSpline::from_poles(&two, 2, 1),
        Err(Error::InvalidStep { step: 1 })
    );
    assert!(matches!(
        DiscreteSpline::from_poles(&two, 0, 4),
        Err(Error::InvalidOrder { order: 0, .. })
    ));
    assert!(matches!(
        DiscreteSpline::from_poles(&two, MAX_ORDER + 1, 4),
        Err(Error::InvalidOrder { .. })
    ));
    assert!(DiscreteSpline::from_poles(&two, MAX_ORDER, 4).is_ok());
    let nan = [Point([0.0, 0.0]), Point([f64::NAN, 0.0])];
    assert_eq!(
        DiscreteSpline::from_poles(&nan, 2, 4),
        Err(Error::NonFinitePoint { index: 1 })
    );
    assert_eq!(
        DiscreteSpline::from_poles(&two, 2, usize::MAX),
        Err(Error::PeriodTooLarge {
            poles: 2,
            step: usize::MAX
        })
    );
    assert!(discrete_bspline(1, 4, 2).is_err());
    assert!(discrete_bspline(4, 0, 2).is_err());
    assert!(DiscreteSpline::interpolating(&nan, 2, 4).is_err());
    assert!(DiscreteSpline::interpolating(&two, 0, 4).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Q_r >= 0, sum_p Q_r(j - p n) = 1, Q_r(j) = Q_r(N - j); values lie in the poles'
    /// bounding box (they are convex combinations).
    #[test]
    fn partition_of_unity_and_non_negativity(m in 2usize..12, n in 2usize..12, r in 1usize..7) {
        let q = discrete_bspline(m, n, r).unwrap();
        let big_n = m * n;
        for j in 0..big_n {
            prop_assert!(q[j] >= 0.0, "Q({j}) = {:e}", q[j]);
            prop_assert!((q[j] - q[(big_n - j) % big_n]).abs() < 1e-15);
            let sum: f64 = (0..m).map(|p| q[(j + big_n - p * n) % big_n]).sum();
            prop_assert!((sum - 1.0).abs() < 1e-14, "j={j}: {sum}");
        }
    }

    #[test]
    fn values_lie_in_the_convex_hull(m in 2usize..10, n in 2usize..10, r in 1usize..6, seed in 1u64..1000) {
        let poles: Vec<Point<2>> = Rng::new(seed).points(m);
        let values = DiscreteSpline::from_poles(&poles, r, n).unwrap().to_values();
        for c in 0..2 {
            let lo = poles.iter().map(|p| p[c]).fold(f64::INFINITY, f64::min);
            let hi = poles.iter().map(|p| p[c]).fold(f64::NEG_INFINITY, f64::max);
            for v in &values {
                prop_assert!(v[c] >= lo - 1e-14 && v[c] <= hi + 1e-14);
            }
        }
    }
}

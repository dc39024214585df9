//! The surface variation method (docs/methods.md §1.5, Aulchenko et al.'s formulas (24)–(33)): sums met,
//! fixed entries kept, free entries moved by the least-squares minimum (checked against a
//! dense KKT solve written here), clear errors for sums that cannot be met, and the finite
//! penalty S tending to the exact solution.

use karkas::ll::{vary, FixedEntries, SumTargets, VariationOptions};
use karkas::{Error, Grid};
use nalgebra::{DMatrix, DVector};
use proptest::prelude::*;

use crate::common::Rng;

fn row_sums(g: &Grid<f64>) -> Vec<f64> {
    (0..g.rows()).map(|i| g.row(i).iter().sum()).collect()
}

fn column_sums(g: &Grid<f64>) -> Vec<f64> {
    (0..g.cols())
        .map(|j| (0..g.rows()).map(|i| *g.get(i, j)).sum())
        .collect()
}

/// The least-squares variation by brute force: unknowns are the movable entries `x`, with
/// weights `w` (1 free, 1/S penalized); minimize sum (x - r0)^2 / w subject to all row and
/// column sums, via the dense KKT system [[W^-1, A^T], [A, 0]] solved by SVD (least squares,
/// so redundant constraints do no harm).
fn kkt_reference(
    matrix: &Grid<f64>,
    fixed: &Grid<bool>,
    targets: &SumTargets,
    penalty: Option<f64>,
) -> Grid<f64> {
    let (n, m) = (matrix.rows(), matrix.cols());
    let cells: Vec<(usize, usize)> = (0..n)
        .flat_map(|i| (0..m).map(move |j| (i, j)))
        .filter(|&(i, j)| !*fixed.get(i, j) || penalty.is_some())
        .collect();
    let k = cells.len();
    let size = k + n + m;
    let mut a = DMatrix::<f64>::zeros(size, size);
    let mut b = DVector::<f64>::zeros(size);
    for (c, &(i, j)) in cells.iter().enumerate() {
        let cost = if *fixed.get(i, j) {
            penalty.unwrap()
        } else {
            1.0
        };
        a[(c, c)] = cost;
        b[c] = cost * matrix.get(i, j);
        a[(c, k + i)] = 1.0;
        a[(k + i, c)] = 1.0;
        a[(c, k + n + j)] = 1.0;
        a[(k + n + j, c)] = 1.0;
    }
    // Constraint right-hand sides: the target minus the entries that stay as they are.
    for i in 0..n {
        let kept: f64 = (0..m)
            .filter(|&j| *fixed.get(i, j) && penalty.is_none())
            .map(|j| matrix.get(i, j))
            .sum();
        b[k + i] = targets.rows[i] - kept;
    }
    for j in 0..m {
        let kept: f64 = (0..n)
            .filter(|&i| *fixed.get(i, j) && penalty.is_none())
            .map(|i| matrix.get(i, j))
            .sum();
        b[k + n + j] = targets.columns[j] - kept;
    }
    let x = a.svd(true, true).solve(&b, 1e-12).unwrap();
    let mut out = matrix.clone();
    for (c, &(i, j)) in cells.iter().enumerate() {
        *out.get_mut(i, j) = x[c];
    }
    out
}

/// A random matrix, mask (about `fixed_share` fixed) and reachable targets.
fn random_case(
    rng: &mut Rng,
    n: usize,
    m: usize,
    fixed_share: f64,
) -> (Grid<f64>, Grid<bool>, SumTargets) {
    let matrix = Grid::from_fn(n, m, |_, _| 10.0 * rng.uniform() - 3.0);
    let fixed = Grid::from_fn(n, m, |_, _| rng.uniform() < fixed_share);
    // Targets of a perturbed matrix whose fixed entries are unchanged: always reachable.
    let moved = Grid::from_fn(n, m, |i, j| {
        matrix.get(i, j)
            + if *fixed.get(i, j) {
                0.0
            } else {
                rng.uniform() - 0.5
            }
    });
    let targets = SumTargets {
        rows: row_sums(&moved),
        columns: column_sums(&moved),
    };
    (matrix, fixed, targets)
}

fn max_difference(a: &Grid<f64>, b: &Grid<f64>) -> f64 {
    a.as_slice()
        .iter()
        .zip(b.as_slice())
        .map(|(x, y)| (x - y).abs())
        .fold(0.0, f64::max)
}

#[test]
fn sums_are_met_fixed_entries_kept_and_the_change_is_least_squares() {
    let mut rng = Rng::new(0x5EED_0001);
    for (n, m, share) in [
        (5, 7, 0.3),
        (8, 4, 0.0),
        (6, 6, 0.5),
        (2, 9, 0.2),
        (12, 15, 0.25),
    ] {
        let (matrix, fixed, targets) = random_case(&mut rng, n, m, share);
        let varied = vary(&matrix, &fixed, &targets, &VariationOptions::default()).unwrap();
        for (got, want) in row_sums(&varied).iter().zip(&targets.rows) {
            assert!(
                (got - want).abs() <= 1e-12,
                "{n}x{m}: row sum {got} vs {want}"
            );
        }
        for (got, want) in column_sums(&varied).iter().zip(&targets.columns) {
            assert!(
                (got - want).abs() <= 1e-12,
                "{n}x{m}: column sum {got} vs {want}"
            );
        }
        for i in 0..n {
            for j in 0..m {
                if *fixed.get(i, j) {
                    assert_eq!(varied.get(i, j), matrix.get(i, j), "fixed ({i}, {j}) moved");
                }
            }
        }
        let reference = kkt_reference(&matrix, &fixed, &targets, None);
        let d = max_difference(&varied, &reference);
        assert!(d < 1e-10, "{n}x{m}: differs from the KKT solution by {d:e}");
    }
}

#[test]
fn unchanged_sums_change_nothing() {
    let mut rng = Rng::new(7);
    let (matrix, fixed, _) = random_case(&mut rng, 4, 5, 0.3);
    let targets = SumTargets {
        rows: row_sums(&matrix),
        columns: column_sums(&matrix),
    };
    let varied = vary(&matrix, &fixed, &targets, &VariationOptions::default()).unwrap();
    assert!(max_difference(&varied, &matrix) < 1e-14);
}

#[test]
fn uniform_change_of_a_free_matrix_is_spread_evenly() {
    // Closed form: with every entry free, raising every row sum by m*c and every column sum
    // by n*c adds c to each entry.
    let matrix = Grid::from_fn(3, 4, |i, j| (i * 4 + j) as f64);
    let fixed = Grid::from_fn(3, 4, |_, _| false);
    let c = 0.25;
    let targets = SumTargets {
        rows: row_sums(&matrix).iter().map(|s| s + 4.0 * c).collect(),
        columns: column_sums(&matrix).iter().map(|s| s + 3.0 * c).collect(),
    };
    let varied = vary(&matrix, &fixed, &targets, &VariationOptions::default()).unwrap();
    for (v, r) in varied.as_slice().iter().zip(matrix.as_slice()) {
        assert!((v - r - c).abs() < 1e-14);
    }
}

#[test]
fn the_papers_parameters_give_the_last_row_and_column_the_rest() {
    let t = SumTargets::with_total(&[1.0, 2.0], &[4.0], 10.0);
    assert_eq!(t.rows, [1.0, 2.0, 7.0]);
    assert_eq!(t.columns, [4.0, 6.0]);
}

#[test]
fn sums_that_cannot_be_met_are_errors() {
    let matrix = Grid::from_fn(3, 3, |i, j| (1 + i + j) as f64);
    let free = Grid::from_fn(3, 3, |_, _| false);
    let options = VariationOptions::default();
    // Rows add up to 16, columns to 15.
    let t = SumTargets {
        rows: vec![5.0, 5.0, 6.0],
        columns: vec![5.0, 5.0, 5.0],
    };
    assert!(matches!(
        vary(&matrix, &free, &t, &options),
        Err(Error::InconsistentTotals { .. })
    ));
    // Row 1 entirely fixed (sum 9), asked to become 10.
    let fixed = Grid::from_fn(3, 3, |i, _| i == 1);
    let t = SumTargets {
        rows: vec![7.0, 10.0, 13.0],
        columns: vec![10.0, 10.0, 10.0],
    };
    let e = vary(&matrix, &fixed, &t, &options).unwrap_err();
    assert_eq!(
        e,
        Error::FixedLineSum {
            kind: "row",
            index: 1,
            current: 9.0,
            wanted: 10.0
        }
    );
    assert_eq!(
        e.to_string(),
        "row 1 has every entry fixed: its sum 9 cannot become 10"
    );
    // A block: entries (0,0) and (1,1)... free only on the diagonal blocks {0}x{0} and
    // {1,2}x{1,2}; the first block's row must rise by 1 but its column by 2.
    let fixed = Grid::from_fn(3, 3, |i, j| (i == 0) != (j == 0));
    let t = SumTargets {
        rows: vec![7.0, 9.0, 13.0],
        columns: vec![8.0, 8.0, 13.0],
    };
    assert!(matches!(
        vary(&matrix, &fixed, &t, &options),
        Err(Error::InconsistentBlock { .. })
    ));
    // The same blocks with consistent changes are fine, and least squares.
    let t = SumTargets {
        rows: vec![7.0, 9.5, 12.5],
        columns: vec![7.0, 9.0, 13.0],
    };
    let varied = vary(&matrix, &fixed, &t, &options).unwrap();
    assert!(max_difference(&varied, &kkt_reference(&matrix, &fixed, &t, None)) < 1e-12);
    // Wrong sizes and bad penalties.
    let t = SumTargets {
        rows: vec![1.0],
        columns: vec![1.0],
    };
    assert!(vary(&matrix, &free, &t, &options).is_err());
    let t = SumTargets {
        rows: row_sums(&matrix),
        columns: column_sums(&matrix),
    };
    for s in [0.0, -1.0, f64::INFINITY, f64::NAN] {
        let options = VariationOptions {
            fixed_entries: FixedEntries::Penalty(s),
            ..VariationOptions::default()
        };
        assert!(vary(&matrix, &free, &t, &options).is_err(), "S = {s}");
    }
    let nan = Grid::from_fn(3, 3, |i, j| if i == 2 && j == 1 { f64::NAN } else { 1.0 });
    assert_eq!(
        vary(&nan, &free, &t, &options).unwrap_err(),
        Error::NonFiniteCell { row: 2, col: 1 }
    );
}

#[test]
fn a_finite_penalty_tends_to_the_exact_solution() {
    let mut rng = Rng::new(0xABCD);
    let (matrix, fixed, targets) = random_case(&mut rng, 6, 5, 0.4);
    let exact = vary(&matrix, &fixed, &targets, &VariationOptions::default()).unwrap();
    let mut previous = f64::INFINITY;
    for s in [1e1, 1e3, 1e5, 1e7] {
        let options = VariationOptions {
            fixed_entries: FixedEntries::Penalty(s),
            ..VariationOptions::default()
        };
        let soft = vary(&matrix, &fixed, &targets, &options).unwrap();
        // Sums are met at every S; the soft solution is the weighted least squares one.
        for (got, want) in row_sums(&soft).iter().zip(&targets.rows) {
            assert!((got - want).abs() <= 1e-11);
        }
        let reference = kkt_reference(&matrix, &fixed, &targets, Some(s));
        // Both solves lose accuracy like S (the condition number of either system).
        let d = max_difference(&soft, &reference);
        assert!(d < (1e-14 * s).max(1e-10), "S = {s}: {d:e}");
        let gap = max_difference(&soft, &exact);
        assert!(gap < previous, "S = {s}: {gap:e} did not shrink");
        assert!(gap * s < 100.0, "S = {s}: the gap {gap:e} is not O(1/S)");
        previous = gap;
    }
}

#[test]
fn scaling_with_the_total_is_the_papers_normalization() {
    let mut rng = Rng::new(99);
    let (matrix, fixed, targets) = random_case(&mut rng, 4, 6, 0.25);
    // Double the total: every target doubles.
    let doubled = SumTargets {
        rows: targets.rows.iter().map(|s| 2.0 * s).collect(),
        columns: targets.columns.iter().map(|s| 2.0 * s).collect(),
    };
    let options = VariationOptions {
        scale_with_total: true,
        ..VariationOptions::default()
    };
    let old_total: f64 = matrix.as_slice().iter().sum();
    let new_total: f64 = doubled.rows.iter().sum();
    let factor = new_total / old_total;
    let varied = vary(&matrix, &fixed, &doubled, &options).unwrap();
    // r / Q is varied: fixed entries keep their share, free ones the least-squares change of
    // the scaled matrix.
    let scaled = Grid::from_fn(4, 6, |i, j| matrix.get(i, j) * factor);
    for i in 0..4 {
        for j in 0..6 {
            if *fixed.get(i, j) {
                assert!(
                    (varied.get(i, j) / new_total - matrix.get(i, j) / old_total).abs() < 1e-15
                );
            }
        }
    }
    let reference = kkt_reference(&scaled, &fixed, &doubled, None);
    assert!(max_difference(&varied, &reference) < 1e-10);
    // A zero total cannot be scaled.
    let zero = Grid::from_fn(2, 2, |i, j| if i == j { 1.0 } else { -1.0 });
    let free = Grid::from_fn(2, 2, |_, _| false);
    let t = SumTargets {
        rows: vec![1.0, 1.0],
        columns: vec![1.0, 1.0],
    };
    assert!(vary(&zero, &free, &t, &options).is_err());
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// Reachable sums are met and fixed entries kept, for any shape and mask.
    #[test]
    fn reachable_sums_are_always_met(
        n in 1usize..7,
        m in 1usize..7,
        share in 0.0..0.8f64,
        seed in 1u64..u64::MAX,
    ) {
        let mut rng = Rng::new(seed);
        let (matrix, fixed, targets) = random_case(&mut rng, n, m, share);
        let varied = vary(&matrix, &fixed, &targets, &VariationOptions::default()).unwrap();
        for (got, want) in row_sums(&varied).iter().zip(&targets.rows) {
            prop_assert!((got - want).abs() <= 1e-12);
        }
        for (got, want) in column_sums(&varied).iter().zip(&targets.columns) {
            prop_assert!((got - want).abs() <= 1e-12);
        }
        for (k, f) in fixed.as_slice().iter().enumerate() {
            if *f {
                prop_assert_eq!(varied.as_slice()[k], matrix.as_slice()[k]);
            }
        }
    }
}

//! The surface variation method (Aulchenko et al., formulas (24)–(33); docs/methods.md §1.5).
//!
//! A surface is varied through a few numbers instead of all its grid points: for one
//! coordinate matrix `r_ij` (`n x m`, e.g. the `z` of every grid point) the user prescribes new
//! row sums `P_i`, column sums `R_j` (and so the total `Q`), and chooses which entries are
//! fixed. The varied matrix is the one closest to the original that meets the sums:
//!
//! ```text
//! minimize  1/2 sum_{free ij} (r_ij - r0_ij)^2
//! subject to  sum_j r_ij = P_i,  sum_i r_ij = R_j,  fixed entries unchanged.
//! ```
//!
//! Stationarity (27) gives `r_ij = r0_ij - alpha_i - beta_j` on the free entries, and the
//! multipliers solve the linear system (29)–(33): `m_i alpha_i + sum_{j free in row i} beta_j =
//! P0_i - P_i` for every row, and the same for every column. The paper fixes the gauge with
//! `alpha_n = beta_m = 0` and a separate `gamma`: `(n-1) + (m-1) + 1` unknowns. Here `gamma` is
//! folded into `alpha` (the same space), one column multiplier per block is the gauge, and the
//! symmetric positive definite system is solved by a dense Cholesky factorization (`nalgebra`):
//! it has `n + m - 1` unknowns, `O((n + m)^3)` work, small next to the grid.
//!
//! Fixed entries are kept exactly by default (the paper's `S -> infinity` limit, where fixed
//! entries are constants). [`FixedEntries::Penalty`] is the paper's finite penalty `S` of
//! (26), (28): a fixed entry then moves by `-(alpha_i + beta_j)/S`, and the result tends to the
//! exact one as `S` grows.
//!
//! The paper works with `r / Q` (shares of the total). That changes nothing while the total
//! stays as it was; when it changes, [`VariationOptions::scale_with_total`] reproduces the
//! paper exactly: the original matrix (fixed entries included) is first scaled by `Q / Q0`.
//!
//! Errors, before anything is solved: row sums and column sums that do not add up to the same
//! total; a row (column) whose entries are all fixed and whose sum would have to change; more
//! generally a block of rows and columns joined to the rest by fixed entries only whose row
//! sums and column sums would have to change by different amounts.

use crate::core::Grid;
use crate::{Error, Result};
use nalgebra::{DMatrix, DVector};

/// Relative size (of the sums involved) under which a mismatch of sums counts as rounding.
const SUM_TOLERANCE: f64 = 1e-12;

/// How the fixed entries are held.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum FixedEntries {
    /// Fixed entries do not move at all (the paper's `S -> infinity`).
    Exact,
    /// The paper's penalty `S > 0` of (26): fixed entries may move, at `S` times the cost.
    Penalty(f64),
}

/// The options of [`vary`].
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct VariationOptions {
    /// How fixed entries are held (default [`FixedEntries::Exact`]).
    pub fixed_entries: FixedEntries,
    /// Scale the original matrix by `Q / Q0` (new total over old) before varying it: the
    /// paper's normalization `r^ = r / Q`, under which fixed entries keep their share of the
    /// total rather than their value. Default `false`.
    pub scale_with_total: bool,
}

impl Default for VariationOptions {
    fn default() -> Self {
        VariationOptions {
            fixed_entries: FixedEntries::Exact,
            scale_with_total: false,
        }
    }
}

/// The prescribed sums: every row sum and every column sum (their totals must agree).
#[derive(Clone, Debug, PartialEq)]
pub struct SumTargets {
    /// The new sum of each row, `P_1..P_n`.
    pub rows: Vec<f64>,
    /// The new sum of each column, `R_1..R_m`.
    pub columns: Vec<f64>,
}

impl SumTargets {
    /// The paper's parameters: the first `n - 1` row sums, the first `m - 1` column sums and
    /// the total `Q`; the last row and column take the rest (`P_n = Q - sum P_i`, `R_m = Q -
    /// sum R_j`).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::ll::SumTargets;
    ///
    /// let targets = SumTargets::with_total(&[1.0, 2.0], &[4.0], 10.0);
    /// assert_eq!(targets.rows, vec![1.0, 2.0, 7.0]);
    /// assert_eq!(targets.columns, vec![4.0, 6.0]);
    /// ```
    pub fn with_total(rows_but_last: &[f64], columns_but_last: &[f64], total: f64) -> Self {
        let complete = |sums: &[f64]| {
            let mut all = sums.to_vec();
            all.push(total - sums.iter().sum::<f64>());
            all
        };
        SumTargets {
            rows: complete(rows_but_last),
            columns: complete(columns_but_last),
        }
    }
}

/// Why the sums given for one direction do not make a complete list ([`complete_sums`]).
#[derive(Clone, Debug, PartialEq)]
pub enum SumsProblem {
    /// One sum fewer than lines, and no total to give the last one.
    NoTotal {
        /// Sums given.
        given: usize,
        /// Lines of the grid in that direction.
        lines: usize,
    },
    /// Neither one sum a line nor one fewer.
    WrongCount {
        /// Sums given.
        given: usize,
        /// Lines of the grid in that direction.
        lines: usize,
    },
    /// A complete list whose sum is not the total (beyond `1e-12` of the magnitudes).
    TotalMismatch {
        /// Lines (and sums).
        lines: usize,
        /// The sum of the sums.
        sum: f64,
        /// The total given.
        total: f64,
    },
}

/// The complete list of `lines` sums of one direction from the sums `given` and the optional
/// new `total` `Q` (the rule of the command line's `vary --rows/--cols/--total` and Python's
/// `vary(..., total=)`): all `lines` sums (which must then add up to `total` when it is
/// given, to `1e-12` of their magnitudes), or the first `lines - 1` and `total`, the last
/// line taking the rest.
pub fn complete_sums(
    given: &[f64],
    lines: usize,
    total: Option<f64>,
) -> core::result::Result<Vec<f64>, SumsProblem> {
    let sum: f64 = given.iter().sum();
    if given.len() == lines {
        if let Some(q) = total {
            let magnitude = given.iter().map(|v| v.abs()).sum::<f64>() + q.abs();
            if (sum - q).abs() > 1e-12 * magnitude {
                return Err(SumsProblem::TotalMismatch {
                    lines,
                    sum,
                    total: q,
                });
            }
        }
        return Ok(given.to_vec());
    }
    if given.len() + 1 == lines {
        let Some(q) = total else {
            return Err(SumsProblem::NoTotal {
                given: given.len(),
                lines,
            });
        };
        let mut all = given.to_vec();
        all.push(q - sum);
        return Ok(all);
    }
    Err(SumsProblem::WrongCount {
        given: given.len(),
        lines,
    })
}

/// Varies `matrix` (`n x m`) so that its row and column sums become `targets`, changing the
/// entries not marked in `fixed` as little as possible (least squares). Returns the varied
/// matrix.
///
/// Errors: an empty matrix ([`Error::InvalidGridSize`]); `fixed` or `targets` of the wrong
/// size ([`Error::GridShape`], [`Error::CountMismatch`]); a non-finite entry or sum
/// ([`Error::NonFiniteCell`], [`Error::NonFiniteEntry`]); a penalty that is not positive and
/// finite ([`Error::InvalidSetting`]); sums that cannot be met ([`Error::InconsistentTotals`], [`Error::FixedLineSum`],
/// [`Error::InconsistentBlock`]); with `scale_with_total`, an original total of zero.
///
/// ```
/// use karkas::ll::{vary, SumTargets, VariationOptions};
/// use karkas::Grid;
/// let z = Grid::from_row_major(2, 2, vec![1.0, 2.0, 3.0, 4.0]).unwrap();
/// let fixed = Grid::from_fn(2, 2, |i, j| i == 0 && j == 0);
/// let targets = SumTargets { rows: vec![4.0, 8.0], columns: vec![5.0, 7.0] };
/// let varied = vary(&z, &fixed, &targets, &VariationOptions::default()).unwrap();
/// assert_eq!(*varied.get(0, 0), 1.0); // fixed
/// assert!((varied.get(0, 0) + varied.get(0, 1) - 4.0).abs() < 1e-12);
/// assert!((varied.get(0, 1) + varied.get(1, 1) - 7.0).abs() < 1e-12);
/// ```
pub fn vary(
    matrix: &Grid<f64>,
    fixed: &Grid<bool>,
    targets: &SumTargets,
    options: &VariationOptions,
) -> Result<Grid<f64>> {
    let (n, m) = (matrix.rows(), matrix.cols());
    check_input(matrix, fixed, targets, options)?;
    let (rows_total, tolerance) = consistent_totals(matrix, targets)?;
    let reference = reference_matrix(matrix, rows_total, options.scale_with_total)?;
    let weight = |i: usize, j: usize| match (*fixed.get(i, j), options.fixed_entries) {
        (false, _) => 1.0,
        (true, FixedEntries::Exact) => 0.0,
        (true, FixedEntries::Penalty(s)) => 1.0 / s,
    };
    // The change each row and column sum needs: sum_j w_ij (alpha_i + beta_j) = d_i.
    let row_change: Vec<f64> = (0..n)
        .map(|i| reference.row(i).iter().sum::<f64>() - targets.rows[i])
        .collect();
    let column_change: Vec<f64> = (0..m)
        .map(|j| (0..n).map(|i| *reference.get(i, j)).sum::<f64>() - targets.columns[j])
        .collect();

    let blocks = Blocks::new(n, m, |i, j| weight(i, j) > 0.0);
    blocks.check(&reference, targets, &row_change, &column_change, tolerance)?;

    let unknowns = Unknowns::new(&blocks, n, m);
    let multipliers = unknowns.solve(&weight, &row_change, &column_change)?;
    let alpha = |i: usize| unknowns.of_row[i].map_or(0.0, |a| multipliers[a]);
    let beta = |j: usize| unknowns.of_column[j].map_or(0.0, |b| multipliers[b]);
    Ok(Grid::from_fn(n, m, |i, j| {
        reference.get(i, j) - weight(i, j) * (alpha(i) + beta(j))
    }))
}

/// The total of the target sums (rows and columns agree within the tolerance returned,
/// relative to the data's magnitude).
fn consistent_totals(matrix: &Grid<f64>, targets: &SumTargets) -> Result<(f64, f64)> {
    let rows_total: f64 = targets.rows.iter().sum();
    let columns_total: f64 = targets.columns.iter().sum();
    let magnitude = matrix.as_slice().iter().map(|r| r.abs()).sum::<f64>()
        + targets.rows.iter().map(|r| r.abs()).sum::<f64>()
        + targets.columns.iter().map(|r| r.abs()).sum::<f64>();
    let tolerance = SUM_TOLERANCE * magnitude.max(f64::MIN_POSITIVE);
    if (rows_total - columns_total).abs() > tolerance {
        return Err(Error::InconsistentTotals {
            rows_total,
            columns_total,
        });
    }
    Ok((rows_total, tolerance))
}

/// The unknowns of the variation: `alpha_i` of every row and `beta_j` of every column in a
/// block with free entries, but for the gauge `beta_j = 0` of the last column of each block.
struct Unknowns {
    of_row: Vec<Option<usize>>,
    of_column: Vec<Option<usize>>,
    count: usize,
}

impl Unknowns {
    fn new(blocks: &Blocks, n: usize, m: usize) -> Self {
        let mut of_row = vec![None; n];
        let mut of_column = vec![None; m];
        let mut count = 0;
        for (i, slot) in of_row.iter_mut().enumerate() {
            if blocks.has_edges(i) {
                *slot = Some(count);
                count += 1;
            }
        }
        for (j, slot) in of_column.iter_mut().enumerate() {
            if blocks.has_edges(n + j) && !blocks.is_gauge_column(j) {
                *slot = Some(count);
                count += 1;
            }
        }
        Unknowns {
            of_row,
            of_column,
            count,
        }
    }

    /// The multipliers that give each row and column sum its change:
    /// `sum_j w_ij (alpha_i + beta_j) = d_i`, and likewise for the columns.
    fn solve(
        &self,
        weight: &dyn Fn(usize, usize) -> f64,
        row_change: &[f64],
        column_change: &[f64],
    ) -> Result<DVector<f64>> {
        let count = self.count;
        let mut system = DMatrix::<f64>::zeros(count, count);
        let mut rhs = DVector::<f64>::zeros(count);
        for (i, a) in self.of_row.iter().enumerate() {
            if let Some(a) = *a {
                rhs[a] = row_change[i];
            }
        }
        for (j, b) in self.of_column.iter().enumerate() {
            if let Some(b) = *b {
                rhs[b] = column_change[j];
            }
        }
        for (i, &a) in self.of_row.iter().enumerate() {
            for (j, &b) in self.of_column.iter().enumerate() {
                let w = weight(i, j);
                if w == 0.0 {
                    continue;
                }
                if let Some(a) = a {
                    system[(a, a)] += w;
                }
                if let Some(b) = b {
                    system[(b, b)] += w;
                }
                if let (Some(a), Some(b)) = (a, b) {
                    system[(a, b)] += w;
                    system[(b, a)] += w;
                }
            }
        }
        if count == 0 {
            return Ok(rhs);
        }
        let cholesky = system
            .cholesky()
            .ok_or(Error::SingularSystem { row: 0, pivot: 0.0 })?;
        Ok(cholesky.solve(&rhs))
    }
}

/// Validates sizes, finiteness and the penalty.
fn check_input(
    matrix: &Grid<f64>,
    fixed: &Grid<bool>,
    targets: &SumTargets,
    options: &VariationOptions,
) -> Result<()> {
    let (n, m) = (matrix.rows(), matrix.cols());
    if n == 0 || m == 0 {
        return Err(Error::InvalidGridSize {
            what: "matrix to vary",
            rows: n,
            cols: m,
            reason: "it has no entries",
        });
    }
    if (fixed.rows(), fixed.cols()) != (n, m) {
        return Err(Error::GridShape {
            rows: n,
            cols: m,
            len: fixed.rows() * fixed.cols(),
        });
    }
    Error::check_counts(&[
        ("row sums (one per row)", n, targets.rows.len()),
        ("column sums (one per column)", m, targets.columns.len()),
    ])?;
    if let Some(k) = matrix.as_slice().iter().position(|r| !r.is_finite()) {
        return Err(Error::NonFiniteCell {
            row: k / m,
            col: k % m,
        });
    }
    if let Some(k) = targets.rows.iter().position(|r| !r.is_finite()) {
        return Err(Error::NonFiniteEntry {
            what: "row sum",
            index: k,
        });
    }
    if let Some(k) = targets.columns.iter().position(|r| !r.is_finite()) {
        return Err(Error::NonFiniteEntry {
            what: "column sum",
            index: k,
        });
    }
    if let FixedEntries::Penalty(s) = options.fixed_entries {
        if !(s > 0.0 && s.is_finite()) {
            return Err(Error::InvalidSetting {
                name: "penalty",
                value: s,
                reason: "the penalty S must be positive and finite",
            });
        }
    }
    Ok(())
}

/// The matrix the variation starts from: the original, or with `scale_with_total` the
/// original scaled to the new total.
fn reference_matrix(matrix: &Grid<f64>, total: f64, scale_with_total: bool) -> Result<Grid<f64>> {
    if !scale_with_total {
        return Ok(matrix.clone());
    }
    let old_total: f64 = matrix.as_slice().iter().sum();
    let magnitude: f64 = matrix.as_slice().iter().map(|r| r.abs()).sum();
    if old_total.abs() <= SUM_TOLERANCE * magnitude || old_total == 0.0 {
        return Err(Error::InvalidSetting {
            name: "scale_with_total",
            value: old_total,
            reason: "the original total is zero, so there is no share of it to keep",
        });
    }
    let factor = total / old_total;
    let values = matrix.as_slice().iter().map(|r| r * factor).collect();
    Grid::from_row_major(matrix.rows(), matrix.cols(), values)
}

/// The connected blocks of the bipartite graph of rows (`0..n`) and columns (`n..n+m`)
/// joined by the entries that may move.
struct Blocks {
    n: usize,
    m: usize,
    /// The representative of each node.
    root: Vec<usize>,
    /// True for nodes with at least one movable entry.
    edges: Vec<bool>,
    /// The last column (0-based) of each block, by representative.
    last_column: Vec<Option<usize>>,
}

impl Blocks {
    fn new(n: usize, m: usize, movable: impl Fn(usize, usize) -> bool) -> Self {
        let mut parent: Vec<usize> = (0..n + m).collect();
        fn find(parent: &mut [usize], mut x: usize) -> usize {
            while parent[x] != x {
                parent[x] = parent[parent[x]];
                x = parent[x];
            }
            x
        }
        let mut edges = vec![false; n + m];
        for i in 0..n {
            for j in 0..m {
                if movable(i, j) {
                    edges[i] = true;
                    edges[n + j] = true;
                    let (a, b) = (find(&mut parent, i), find(&mut parent, n + j));
                    if a != b {
                        parent[a.max(b)] = a.min(b);
                    }
                }
            }
        }
        let root: Vec<usize> = (0..n + m).map(|x| find(&mut parent, x)).collect();
        let mut last_column = vec![None; n + m];
        for j in 0..m {
            last_column[root[n + j]] = Some(j);
        }
        Blocks {
            n,
            m,
            root,
            edges,
            last_column,
        }
    }

    fn has_edges(&self, node: usize) -> bool {
        self.edges[node]
    }

    fn is_gauge_column(&self, j: usize) -> bool {
        self.last_column[self.root[self.n + j]] == Some(j)
    }

    /// Every block's rows and columns must need the same total change.
    fn check(
        &self,
        reference: &Grid<f64>,
        targets: &SumTargets,
        row_change: &[f64],
        column_change: &[f64],
        tolerance: f64,
    ) -> Result<()> {
        let (n, m) = (self.n, self.m);
        for i in (0..n).filter(|&i| !self.edges[i]) {
            if row_change[i].abs() > tolerance {
                return Err(Error::FixedLineSum {
                    kind: "row",
                    index: i,
                    current: reference.row(i).iter().sum(),
                    wanted: targets.rows[i],
                });
            }
        }
        for j in (0..m).filter(|&j| !self.edges[n + j]) {
            if column_change[j].abs() > tolerance {
                return Err(Error::FixedLineSum {
                    kind: "column",
                    index: j,
                    current: (0..n).map(|i| *reference.get(i, j)).sum(),
                    wanted: targets.columns[j],
                });
            }
        }
        let mut block_roots: Vec<usize> = (0..n + m)
            .filter(|&x| self.edges[x])
            .map(|x| self.root[x])
            .collect();
        block_roots.sort_unstable();
        block_roots.dedup();
        if block_roots.len() < 2 {
            return Ok(()); // one block: the totals were checked already
        }
        for r in block_roots {
            let rows: Vec<usize> = (0..n).filter(|&i| self.root[i] == r).collect();
            let columns: Vec<usize> = (0..m).filter(|&j| self.root[n + j] == r).collect();
            let rows_change: f64 = rows.iter().map(|&i| row_change[i]).sum();
            let columns_change: f64 = columns.iter().map(|&j| column_change[j]).sum();
            if (rows_change - columns_change).abs() > tolerance {
                return Err(Error::InconsistentBlock {
                    rows,
                    columns,
                    // The change of the sums themselves (new minus old).
                    rows_change: -rows_change,
                    columns_change: -columns_change,
                });
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod sums_tests {
    use super::*;

    #[test]
    fn complete_sums_takes_all_or_all_but_the_last_with_the_total() {
        assert_eq!(complete_sums(&[1.0, 2.0], 2, None), Ok(vec![1.0, 2.0]));
        assert_eq!(complete_sums(&[1.0, 2.0], 2, Some(3.0)), Ok(vec![1.0, 2.0]));
        assert_eq!(complete_sums(&[1.0], 2, Some(5.0)), Ok(vec![1.0, 4.0]));
        assert_eq!(
            complete_sums(&[1.0], 2, None),
            Err(SumsProblem::NoTotal { given: 1, lines: 2 })
        );
        assert_eq!(
            complete_sums(&[1.0], 3, Some(1.0)),
            Err(SumsProblem::WrongCount { given: 1, lines: 3 })
        );
        assert!(matches!(
            complete_sums(&[1.0, 2.0], 2, Some(4.0)),
            Err(SumsProblem::TotalMismatch { lines: 2, .. })
        ));
    }
}

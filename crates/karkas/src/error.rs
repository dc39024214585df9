//! The one error type of the `karkas` library.

/// Everything that can go wrong when building or evaluating a curve or surface.
///
/// Each variant carries the data needed to point the user at the offending input: a point
/// index, a grid cell, an order. Indices are 0-based, as in the slices the caller passed.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum Error {
    /// A method needs more points than it was given
    /// (e.g. [`LlCurve::new`](crate::ll::LlCurve::new) with fewer than 3 points).
    #[error("{what} needs at least {needed} points, got {got}")]
    TooFewPoints {
        /// What was being built.
        what: &'static str,
        /// The minimum number of points.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// An input point has a NaN or infinite coordinate.
    #[error("point {index} has a non-finite coordinate")]
    NonFinitePoint {
        /// Index of the point in the input slice.
        index: usize,
    },
    /// A grid point has a NaN or infinite coordinate.
    #[error("grid point (i={row}, j={col}) has a non-finite coordinate")]
    NonFiniteCell {
        /// Row index.
        row: usize,
        /// Column index.
        col: usize,
    },
    /// A method order outside its allowed range (LL needs `L >= 1`).
    #[error("order {order} is not allowed: {reason}")]
    InvalidOrder {
        /// The order given.
        order: usize,
        /// Why it is not allowed.
        reason: &'static str,
    },
    /// Grid data whose length does not match `rows * cols`.
    #[error("a {rows} x {cols} grid needs {} values, got {len}", rows.saturating_mul(*cols))]
    GridShape {
        /// Rows asked for.
        rows: usize,
        /// Columns asked for.
        cols: usize,
        /// Values given.
        len: usize,
    },
    /// A linear system met a zero (or vanishing) pivot.
    #[error("singular linear system (pivot {pivot} vanished at row {row})")]
    SingularSystem {
        /// Row of the failing pivot.
        row: usize,
        /// Its value.
        pivot: f64,
    },
    /// Any other invalid argument, described in words.
    #[error("{0}")]
    InvalidInput(String),
    /// A plane that cannot be used: a zero or non-finite normal, or a non-finite offset
    /// ([`Plane::new`](crate::section::Plane::new)).
    #[error("invalid plane: {reason}")]
    InvalidPlane {
        /// What is wrong with it.
        reason: &'static str,
    },
    /// An option value outside its allowed range
    /// (e.g. [`Sectioner::new`](crate::section::Sectioner::new) with a negative tolerance).
    #[error("option {name} = {value}: {reason}")]
    InvalidOption {
        /// The option's name.
        name: &'static str,
        /// The value given.
        value: f64,
        /// What the option needs.
        reason: &'static str,
    },
    /// Prescribed row (or column) sums of a variation that the fixed entries make impossible:
    /// a line with every entry fixed whose sum would have to change
    /// ([`vary`](crate::ll::vary) with exact fixed entries).
    #[error("{kind} {index} has every entry fixed: its sum {current} cannot become {wanted}")]
    FixedLineSum {
        /// `"row"` or `"column"`.
        kind: &'static str,
        /// The 0-based index of the row or column.
        index: usize,
        /// Its sum now (fixed entries only).
        current: f64,
        /// The sum asked for.
        wanted: f64,
    },
    /// Prescribed sums of a variation that contradict each other: the row sums, the column
    /// sums and the total do not add up ([`vary`](crate::ll::vary)).
    #[error(
        "inconsistent sums: the row sums add up to {rows_total} and the column sums to \
         {columns_total}; they must be equal (the total)"
    )]
    InconsistentTotals {
        /// Sum of the prescribed row sums.
        rows_total: f64,
        /// Sum of the prescribed column sums.
        columns_total: f64,
    },
    /// Prescribed sums of a variation that the fixed entries make impossible: a block of rows
    /// and columns is linked to the rest of the matrix by fixed entries only, so its rows' sums
    /// and its columns' sums must change by the same amount ([`vary`](crate::ll::vary) with
    /// exact fixed entries).
    #[error(
        "rows {rows:?} and columns {columns:?} share their free entries only among themselves: \
         their sums must change by the same amount, but the rows change by {rows_change} and \
         the columns by {columns_change}"
    )]
    InconsistentBlock {
        /// The 0-based rows of the block.
        rows: Vec<usize>,
        /// The 0-based columns of the block.
        columns: Vec<usize>,
        /// How much the rows' sums change together.
        rows_change: f64,
        /// How much the columns' sums change together.
        columns_change: f64,
    },
}

/// `Result` with [`Error`].
pub type Result<T> = core::result::Result<T, Error>;

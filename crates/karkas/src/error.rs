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
    /// A knot that is not finite, out of order, too close to its neighbour or outside the
    /// allowed range ([`HermiteSpline::new`](crate::fit::HermiteSpline::new),
    /// [`FitOptions::knots`](crate::fit::FitOptions), [`fit_curve`](crate::fit::fit_curve)).
    #[error("knot {index} ({value}) is invalid: {reason}")]
    InvalidKnot {
        /// Index of the knot (0-based).
        index: usize,
        /// Its value.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A numeric setting outside its allowed range (e.g. a negative `eps` or tolerance in
    /// [`fit_curve`](crate::fit::fit_curve), a corner that is not an inner knot).
    #[error("{name} = {value} is not allowed: {reason}")]
    InvalidSetting {
        /// The setting.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Why it is not allowed.
        reason: &'static str,
    },
}

/// `Result` with [`Error`].
pub type Result<T> = core::result::Result<T, Error>;

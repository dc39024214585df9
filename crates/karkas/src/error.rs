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
    /// Boundary data of a Coons surface that violates the compatibility conditions (8) / (11)
    /// of seed 001: two curves, one of each family, disagree where they meet (a point, or a
    /// derivative there) by more than the tolerance. Produced by every constructor of
    /// [`CoonsSurface`](crate::coons::CoonsSurface) (e.g.
    /// [`CoonsSurface::gordon`](crate::coons::CoonsSurface::gordon)).
    #[error(
        "{first} and {second} disagree at (u={u}, v={v}): {condition} differ by {mismatch:.3e} \
         (tolerance {tolerance:.3e})"
    )]
    IncompatibleCurves {
        /// The curve of the family along `v` (a line `u = const` or its cross-derivative), named
        /// as the constructor's arguments name it, e.g. `"v-curve 2"`.
        first: String,
        /// The curve of the family along `u`, e.g. `"u-curve 1"`.
        second: String,
        /// The surface parameter `u` of the intersection.
        u: f64,
        /// The surface parameter `v` of the intersection.
        v: f64,
        /// The quantities compared, e.g. `"the points"` or `"d/du of u-curve 1 and the
        /// cross-derivative curve"`.
        condition: String,
        /// The size of the disagreement (Euclidean norm).
        mismatch: f64,
        /// The largest disagreement allowed.
        tolerance: f64,
    },
    /// A curve network given as point lists whose curves do not cross as a network must: a
    /// pair without a common point, a pair meeting twice, or crossings out of order. Produced
    /// by [`PointNetwork::new`](crate::coons::PointNetwork::new).
    #[error("v-curve {v_curve} and u-curve {u_curve}: {problem}")]
    NetworkCrossing {
        /// Index of the curve along `v` (a line `u = const`), 0-based.
        v_curve: usize,
        /// Index of the curve along `u` (a line `v = const`), 0-based.
        u_curve: usize,
        /// What is wrong.
        problem: String,
    },
}

/// `Result` with [`Error`].
pub type Result<T> = core::result::Result<T, Error>;

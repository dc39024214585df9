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
    /// Spline knots that are not finite and strictly increasing
    /// (e.g. [`CubicSpline::new`](crate::param::CubicSpline::new) with `knots[index] <=
    /// knots[index - 1]`).
    #[error("knot {index} is not finite and greater than the knot before it")]
    KnotsNotIncreasing {
        /// Index of the first offending knot.
        index: usize,
    },
    /// Two consecutive points coincide, so chord-length (or centripetal) parameters do not
    /// increase ([`curve_parameters`](crate::param::curve_parameters)).
    #[error("points {first} and {second} coincide: the parameters would not increase")]
    CoincidentPoints {
        /// Index of the first point.
        first: usize,
        /// Index of the second point.
        second: usize,
    },
    /// Two consecutive grid lines give a zero parameter step
    /// ([`grid_parameters`](crate::param::grid_parameters)): every chord between them used
    /// by the parameterization vanishes.
    #[error("grid lines {direction} = {index} and {direction} = {} coincide: the parameters would not increase", index + 1)]
    CoincidentGridLines {
        /// `"i"` (rows, parameter u) or `"j"` (columns, parameter v).
        direction: &'static str,
        /// Index of the first of the two lines.
        index: usize,
    },
    /// An expression of an implicit surface that does not parse
    /// ([`ExpressionSurface::parse`](crate::implicit::ExpressionSurface::parse)).
    #[error("expression: {message} (at character {position})")]
    ExpressionParse {
        /// 1-based character position in the expression where the problem was found.
        position: usize,
        /// What is wrong.
        message: String,
    },
    /// Newton's projection onto an implicit surface `F = 0` did not converge from a point
    /// ([`project_onto`](crate::implicit::project_onto), the start of
    /// [`trace_net`](crate::implicit::trace_net)).
    #[error("no surface F = 0 near ({}, {}, {}) (|F| = {residual:.3e} there)", point[0], point[1], point[2])]
    NoSurfaceNear {
        /// The point the search started from.
        point: [f64; 3],
        /// `|F|` at that point.
        residual: f64,
    },
    /// The gradient of an implicit surface vanishes (a singular point: no normal, no
    /// curvature) ([`SurfaceFrame::at`](crate::implicit::SurfaceFrame::at)).
    #[error("the gradient of F vanishes at ({}, {}, {}): a singular point of the surface", point[0], point[1], point[2])]
    SingularPoint {
        /// Where.
        point: [f64; 3],
    },
    /// The continuation along a line of a net failed
    /// ([`trace_net`](crate::implicit::trace_net)).
    #[error("tracing line {line} of the net failed at node {node}: {reason}")]
    ContinuationFailed {
        /// The line (0-based; the first traced line is the spine).
        line: usize,
        /// The node being reached.
        node: usize,
        /// What went wrong.
        reason: &'static str,
    },
}

/// `Result` with [`Error`].
pub type Result<T> = core::result::Result<T, Error>;

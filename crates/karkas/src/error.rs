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
    /// A grid size (rows x columns) outside what a method accepts
    /// (e.g. [`trace_net`](crate::implicit::trace_net) with fewer than 2 nodes in a
    /// direction, [`hausdorff_surface_implicit`](crate::measure::hausdorff_surface_implicit)
    /// with fewer than 2 samples, [`vary`](crate::ll::vary) with an empty matrix).
    #[error("a {rows} x {cols} {what} is not allowed: {reason}")]
    InvalidGridSize {
        /// What the grid is, e.g. `"net"`.
        what: &'static str,
        /// Rows asked for.
        rows: usize,
        /// Columns asked for.
        cols: usize,
        /// What the method needs.
        reason: &'static str,
    },
    /// A grid node that lies outside the grid
    /// ([`grid_parameters`](crate::param::grid_parameters) with a chord origin beyond the
    /// last row or column).
    #[error("{what} (i={row}, j={col}) is outside the {rows} x {cols} grid")]
    OutsideGrid {
        /// What the node is, e.g. `"the origin node"`.
        what: &'static str,
        /// Its row.
        row: usize,
        /// Its column.
        col: usize,
        /// Rows of the grid.
        rows: usize,
        /// Columns of the grid.
        cols: usize,
    },
    /// A single argument (a point, an angle, a vector) that is NaN or infinite
    /// (e.g. [`project_onto`](crate::implicit::project_onto) with a non-finite point,
    /// [`trace_net`](crate::implicit::trace_net) with a non-finite start or angle).
    #[error("{what} is not finite")]
    NonFiniteArgument {
        /// What the argument is, e.g. `"the point to project"`.
        what: &'static str,
    },
    /// An entry of a list of numbers that is NaN or infinite
    /// (e.g. [`vary`](crate::ll::vary) with a non-finite row sum).
    #[error("{what} {index} is not finite")]
    NonFiniteEntry {
        /// What the entries are, e.g. `"row sum"`.
        what: &'static str,
        /// Index of the entry (0-based).
        index: usize,
    },
    /// A parameter domain that is empty or not finite
    /// ([`Sectioner::new`](crate::section::Sectioner::new) of such a surface).
    #[error("the surface's parameter domain [{start}, {end}] is empty or not finite")]
    InvalidDomain {
        /// The start of the domain.
        start: f64,
        /// Its end.
        end: f64,
    },
    /// A fault inside the library that valid input cannot cause (a bug), e.g. an FFT of a
    /// size its own plan was made for failing
    /// ([`InterpolationPlan`](crate::dps::InterpolationPlan)).
    #[error("internal error: {what} (please report this as a bug)")]
    Internal {
        /// What failed.
        what: &'static str,
    },
    /// A discrete periodic spline with a step `n` below 2 between its nodes
    /// (e.g. [`DiscreteSpline::from_poles`](crate::dps::DiscreteSpline::from_poles) with
    /// `n = 1`; the paper asks for `n >= 2`).
    #[error("the step n between nodes must be at least 2, got {step}")]
    InvalidStep {
        /// The step given.
        step: usize,
    },
    /// A discrete period `N = m n` too large to index
    /// (e.g. [`DiscreteSpline::from_poles`](crate::dps::DiscreteSpline::from_poles) with
    /// `m n > usize::MAX`).
    #[error("the period m n = {poles} x {step} is too large")]
    PeriodTooLarge {
        /// The number of poles (or nodes) `m`.
        poles: usize,
        /// The step `n`.
        step: usize,
    },
    /// A family of skeleton curves of a tube with too few curves
    /// ([`TubeSurface::new`](crate::dps::TubeSurface::new) with fewer than 2 curves along or
    /// across).
    #[error("the {family} skeleton needs at least {needed} curves, got {got}")]
    TooFewCurves {
        /// `"along"` or `"across"`.
        family: &'static str,
        /// The minimum number of curves.
        needed: usize,
        /// The number given.
        got: usize,
    },
    /// Skeleton curves of a tube whose sample count does not match the other family
    /// ([`TubeSurface::new`](crate::dps::TubeSurface::new): every along curve needs
    /// `N2 = m2 n2` samples, every across curve `N1 = m1 n1`).
    #[error(
        "each {family} curve needs {expected} samples ({curves} {other} curves x step {step}), got {got}"
    )]
    SkeletonLength {
        /// `"along"` or `"across"`: the family whose curves have the wrong length.
        family: &'static str,
        /// The other family.
        other: &'static str,
        /// The number of curves of the other family (`m2` for along curves).
        curves: usize,
        /// The step of this family's direction (`n2` for along curves).
        step: usize,
        /// The number of samples needed.
        expected: usize,
        /// The number of samples given.
        got: usize,
    },
    /// A skeleton point with a NaN or infinite coordinate
    /// ([`TubeSurface::new`](crate::dps::TubeSurface::new)).
    #[error("{family} curve {curve}, sample {sample} has a non-finite coordinate")]
    NonFiniteSkeletonPoint {
        /// `"along"` or `"across"`.
        family: &'static str,
        /// The curve index (`i` along, `j` across).
        curve: usize,
        /// The sample index on the curve (`q` along, `p` across).
        sample: usize,
    },
    /// Two skeleton curves of a tube that do not meet where they must
    /// ([`TubeSurface::new`](crate::dps::TubeSurface::new): `f_i(j n2) = g_j(i n1)`).
    #[error(
        "along curve i={along} and across curve j={across} do not meet: f_i(j n2) and g_j(i n1) \
         are {distance:.3e} apart (tolerance {tolerance:.3e})"
    )]
    IncompatibleSkeleton {
        /// The along curve `i`.
        along: usize,
        /// The across curve `j`.
        across: usize,
        /// The distance between `f_i(j n2)` and `g_j(i n1)`.
        distance: f64,
        /// The largest distance accepted (relative to the size of the skeleton).
        tolerance: f64,
    },
    /// A list of the wrong length for what it is passed to
    /// (e.g. [`InterpolationPlan::poles_into`](crate::dps::InterpolationPlan::poles_into) with
    /// a number of nodes other than the plan's `m`).
    #[error("{what}: expected {expected}, got {got}")]
    CountMismatch {
        /// What was counted.
        what: &'static str,
        /// The length needed.
        expected: usize,
        /// The length given.
        got: usize,
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
    /// A plane that cannot be used: a zero or non-finite normal, or a non-finite offset
    /// ([`Plane::new`](crate::section::Plane::new)).
    #[error("invalid plane: {reason}")]
    InvalidPlane {
        /// What is wrong with it.
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
    /// Boundary data of a Coons surface that violates the compatibility conditions (8) / (11)
    /// of Chashnikov: two curves, one of each family, disagree where they meet (a point, or a
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
    /// Points that do not follow one curve in their order: many long chords turn back by more
    /// than 150 degrees, as in a shuffled list ([`points_out_of_order`](crate::geometry::points_out_of_order),
    /// checked by [`fair_curve`](crate::fair::fair_curve)).
    #[error(
        "points not in order ({reversals} long chords turn back; list the points along the curve)"
    )]
    PointsOutOfOrder {
        /// The number of long chords that turn back.
        reversals: usize,
    },
    /// A knot (or node, or parameter of a point) that is not finite, out of order, too close
    /// to its neighbour or outside the allowed range: the one error of the one knot validator
    /// [`check_knots`](crate::core::knots::check_knots), whichever method was given the knots
    /// (e.g. [`CubicSpline::new`](crate::param::CubicSpline::new),
    /// [`HermiteSpline::new`](crate::fit::HermiteSpline::new),
    /// [`fit_curve`](crate::fit::fit_curve),
    /// [`SplineBlending::new`](crate::coons::SplineBlending::new)).
    #[error("knot {index} ({}) is invalid: {reason}", Shown(*value))]
    InvalidKnot {
        /// Index of the knot (0-based).
        index: usize,
        /// Its value.
        value: f64,
        /// What is wrong with it.
        reason: &'static str,
    },
    /// A weight of a rational B-spline ([`NurbsCurve::new`](crate::bspline::NurbsCurve::new),
    /// [`NurbsSurface::new`](crate::bspline::NurbsSurface::new)) that is not a finite
    /// positive number.
    #[error("weight {index} ({}) is invalid: weights must be finite and positive", Shown(*value))]
    InvalidWeight {
        /// Index of the weight (0-based; row-major for a surface).
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A numeric setting or option outside its allowed range (e.g. a negative `eps` or
    /// tolerance in [`fit_curve`](crate::fit::fit_curve), a corner that is not an inner knot,
    /// a tolerance or cell count of [`Sectioner::new`](crate::section::Sectioner::new), the
    /// penalty of [`vary`](crate::ll::vary), node steps of
    /// [`trace_net`](crate::implicit::trace_net), the compatibility tolerance of a
    /// [`CoonsSurface`](crate::coons::CoonsSurface)).
    #[error("{name} = {} is not allowed: {reason}", Shown(*value))]
    InvalidSetting {
        /// The setting.
        name: &'static str,
        /// The value given.
        value: f64,
        /// Why it is not allowed.
        reason: &'static str,
    },
    /// A name that is not one of those accepted (a parameterization, a Coons surface kind),
    /// e.g. from [`GridParameterization::from_str`](crate::param::GridParameterization).
    #[error("unknown {what} '{name}' (expected one of: {})", expected.join(", "))]
    UnknownName {
        /// What the name names.
        what: &'static str,
        /// The name given.
        name: String,
        /// The names accepted.
        expected: &'static [&'static str],
    },
    /// A closed direction of a curve network whose period does not pass its last node
    /// ([`NetworkAxis::closed`](crate::coons::NetworkAxis::closed)).
    #[error(
        "a closed network direction needs its nodes within one period: the period {period} \
         from node 0 ({first}) does not pass the last node ({last})"
    )]
    InvalidPeriod {
        /// The period given.
        period: f64,
        /// The first node.
        first: f64,
        /// The last node.
        last: f64,
    },
    /// A curve of a network that is closed in an open direction or open in a closed one
    /// ([`CurveNetwork::new`](crate::coons::CurveNetwork::new)).
    #[error(
        "{family} {curve} is {} but its direction is {}",
        if *closed { "closed" } else { "open" },
        if *closed { "open" } else { "closed" }
    )]
    CurveClosure {
        /// `"v-curve"` or `"u-curve"`.
        family: &'static str,
        /// Index of the curve in its family (0-based).
        curve: usize,
        /// Whether that curve is closed.
        closed: bool,
    },
    /// A family of point lists of a network that mixes closed and open curves
    /// ([`PointNetwork::new`](crate::coons::PointNetwork::new); a closed curve repeats its
    /// first point last).
    #[error(
        "{family} {curve} is {} but {family} 0 is {}: the curves of a family must all be \
         closed (last point repeating the first) or all open",
        if *closed { "closed" } else { "open" },
        if *closed { "open" } else { "closed" }
    )]
    MixedClosure {
        /// `"v-curve"` or `"u-curve"`.
        family: &'static str,
        /// Index of the first curve that differs from curve 0.
        curve: usize,
        /// Whether that curve is closed.
        closed: bool,
    },
    /// A family of a curve network with too few curves
    /// ([`PointNetwork::new`](crate::coons::PointNetwork::new): at least 2, or 3 closed).
    #[error(
        "a curve network needs at least {needed} {family}s{}, got {got}",
        if *closed { " when they are closed" } else { "" }
    )]
    TooFewNetworkCurves {
        /// `"v-curve"` or `"u-curve"`.
        family: &'static str,
        /// The minimum number of curves.
        needed: usize,
        /// The number given.
        got: usize,
        /// Whether the family is closed.
        closed: bool,
    },
    /// A blending family with no functions
    /// ([`CoonsSurface::new`](crate::coons::CoonsSurface::new)).
    #[error(
        "a Coons surface needs at least one blending function in each direction; the \
         {direction} family has none"
    )]
    EmptyBlendingFamily {
        /// `"u"` or `"v"`.
        direction: &'static str,
    },
    /// A network that is not two open curves by two open curves, given to a surface that
    /// needs four sides ([`CoonsSurface::bilinear`](crate::coons::CoonsSurface::bilinear),
    /// [`CoonsSurface::bicubic`](crate::coons::CoonsSurface::bicubic)).
    #[error(
        "a {what} surface needs two open v-curves and two open u-curves, got {v_curves} and \
         {u_curves}{}",
        if *closed { " (closed)" } else { "" }
    )]
    NotFourSided {
        /// The surface, e.g. `"bilinear Coons"`.
        what: &'static str,
        /// The number of v-curves.
        v_curves: usize,
        /// The number of u-curves.
        u_curves: usize,
        /// Whether a direction is closed.
        closed: bool,
    },
    /// An error in one curve of a point network, naming the curve
    /// ([`PointNetwork::new`](crate::coons::PointNetwork::new) for a curve's points or its
    /// reparameterization, [`PointNetwork::cross_derivatives`](crate::coons::PointNetwork::cross_derivatives)
    /// for its cross-derivative vectors).
    #[error("{family} {curve}: {source}")]
    NetworkCurve {
        /// `"v-curve"`, `"u-curve"`, or `"the cross-derivative of v-curve"` (`u-curve`).
        family: &'static str,
        /// Index of the curve in its family (0-based).
        curve: usize,
        /// What is wrong with it.
        source: Box<Error>,
    },
    /// Crossings along a point-list curve spaced so unevenly, compared with the network's node
    /// values, that no increasing `C^2` reparameterization exists
    /// ([`PointNetwork::new`](crate::coons::PointNetwork::new), inside
    /// [`Error::NetworkCurve`]).
    #[error(
        "between crossings {piece} and {} the curve's spacing differs too much from the other \
         curves' for a smooth reparameterization",
        piece + 1
    )]
    UnevenCrossings {
        /// Index of the first crossing of the offending piece.
        piece: usize,
    },
    /// Cross-derivative vectors of a closed curve whose last vector does not repeat the first
    /// ([`PointNetwork::cross_derivatives`](crate::coons::PointNetwork::cross_derivatives)).
    #[error(
        "the cross-derivative of closed {family} {curve}: the last vector must repeat the \
         first, as the last point does"
    )]
    UnclosedCrossDerivative {
        /// `"v-curve"` or `"u-curve"`.
        family: &'static str,
        /// Index of the curve (0-based).
        curve: usize,
    },
    /// A curve or surface whose exact B-spline form cannot be built: data that are not known
    /// piecewise polynomials, or a degree too high to convert without losing digits
    /// ([`ToBSplineSurface::to_bspline`](crate::bspline::ToBSplineSurface) of a Coons surface).
    #[error("{what} has no exact B-spline form: {reason}")]
    NotExactlyConvertible {
        /// What was converted.
        what: &'static str,
        /// Why it cannot be.
        reason: String,
    },
    /// Periodic data whose last value (point, grid line) does not repeat the first (e.g.
    /// [`CubicSpline::new`](crate::param::CubicSpline::new) with periodic ends).
    #[error("{what} needs its last {item} to repeat the first")]
    OpenPeriodicData {
        /// What was being built.
        what: &'static str,
        /// What must repeat: `"value"`, `"point"`, `"grid line"`.
        item: &'static str,
    },
    /// End conditions a method does not support (e.g. clamped ends for
    /// [`SplineBlending`](crate::coons::SplineBlending), whose functions blend values only).
    #[error("{what} does not support {ends} ends")]
    UnsupportedEnds {
        /// What was being built.
        what: &'static str,
        /// The end conditions given.
        ends: &'static str,
    },
    /// A point where the principal curvatures (nearly) agree, so that no principal
    /// direction is defined: a plane, a sphere or an umbilic region
    /// ([`relay_grid`](crate::param::relay_grid), whose module documentation states the
    /// test).
    #[error(
        "the surface is umbilic near ({}, {}, {}) (principal curvatures {k1:.4e} and {k2:.4e} \
         nearly equal, as on a plane or a sphere): its lines of curvature are not defined",
        point[0], point[1], point[2]
    )]
    UmbilicRegion {
        /// Where.
        point: [f64; 3],
        /// The larger principal curvature there.
        k1: f64,
        /// The smaller.
        k2: f64,
    },
    /// A section of a loft that cannot be used ([`Loft::new`](crate::loft::Loft::new),
    /// [`Loft::wing`](crate::loft::Loft::wing)): too few points, not in unit chord, no leading
    /// edge between its ends, at the station of another, out of order, or without a
    /// correspondence with the others.
    #[error("section {section}: {reason}")]
    LoftSection {
        /// Index of the section (0-based, in span order).
        section: usize,
        /// What is wrong with it.
        reason: String,
    },
}

impl Error {
    /// Checks every `(what, expected, got)` count, failing with [`Error::CountMismatch`] on the
    /// first that differs.
    pub(crate) fn check_counts(counts: &[(&'static str, usize, usize)]) -> Result<()> {
        match counts.iter().find(|(_, expected, got)| got != expected) {
            Some(&(what, expected, got)) => Err(Error::CountMismatch {
                what,
                expected,
                got,
            }),
            None => Ok(()),
        }
    }
}

/// A float as the messages show it: as Rust prints it, but in exponent form where that
/// would run to many digits (below `1e-4` or from `1e16` in size: a knot of `4.45e-308`
/// would otherwise print 300 zeros).
struct Shown(f64);

impl core::fmt::Display for Shown {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        let size = self.0.abs();
        if size != 0.0 && size.is_finite() && !(1e-4..1e16).contains(&size) {
            write!(f, "{:e}", self.0)
        } else {
            write!(f, "{}", self.0)
        }
    }
}

/// `Result` with [`Error`].
pub type Result<T> = core::result::Result<T, Error>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn extreme_values_are_shown_with_an_exponent() {
        let knot = |value| Error::InvalidKnot {
            index: 1,
            value,
            reason: "r",
        };
        assert_eq!(
            knot(4.45e-308).to_string(),
            "knot 1 (4.45e-308) is invalid: r"
        );
        assert_eq!(knot(0.25).to_string(), "knot 1 (0.25) is invalid: r");
        assert_eq!(knot(0.0).to_string(), "knot 1 (0) is invalid: r");
        assert_eq!(knot(f64::NAN).to_string(), "knot 1 (NaN) is invalid: r");
        let setting = Error::InvalidSetting {
            name: "tolerance",
            value: -2e20,
            reason: "r",
        };
        assert_eq!(setting.to_string(), "tolerance = -2e20 is not allowed: r");
    }
}

//! The LL approximation (Aulchenko, Latypov, Nikulichev): the Python classes `LLCurve` and
//! `LLSurface`, and the surface variation method `vary`.
//!
//! Also `LLSurface.section`, with the command line's default cells (`karkas section --method ll`):
//! 2 per grid line in each direction, at least 16 ([`karkas::section::cells_for_grid`]),
//! instead of the fixed default of `Surface.section`.

use std::sync::Arc;

use karkas::ll::{
    complete_sums, vary as ll_vary, FixedEntries, LlCurve, LlSurface, SumTargets, SumsProblem,
    VariationOptions, DEFAULT_ORDER,
};
use karkas::Grid;
use numpy::{AllowTypeChange, PyArrayDyn, PyArrayLike2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::convert::{
    as_points, by_dim, count, creased, flatten, maybe_detach, py_bool, real_array, small_vector,
    variant, write_flat, FlatPoints, GridArray, PointsArray,
};
use crate::curve::PyCurve;
use crate::erased::{CurveImpl, SurfaceImpl, Wrapped, WrappedSurface};
use crate::errors::{library_error, OptionError, PointsError};
use crate::limits::{bytes_of, check_memory, shape_text, zeros};
use crate::surface::PySurface;

/// The LL approximation of a support polygon (Aulchenko, Latypov, Nikulichev): a C^L curve
/// that never oscillates more than its polygon.
///
/// Node ``i`` of the ``K`` polygon points sits at ``t = i/(K+1)``; the domain is
/// ``[1/(K+1), K/(K+1)]``. An open curve passes through its first and last points and
/// approximates the others; ``LLCurve.interpolate`` gives a curve through every point.
/// Calling the curve is described in ``Curve``.
///
/// Outside the domain (the rule of every curve class): a closed curve wraps the parameter by
/// its period; an open curve continues its end polynomial pieces when ``extrapolate`` is None
/// or True (SciPy's ``BSpline`` default; the values of ``BSpline(*c.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
///
/// Parameters
/// ----------
/// points : array_like
///     The support polygon, shape ``(n, d)``, ``d`` in {2, 3}; any real dtype, any layout.
/// order : int, optional
///     The order ``L >= 1``: the curve is C^L and its pieces have degree ``2L``.
/// closed : bool, optional
///     A closed curve through the polygon taken cyclically (the first point is not repeated
///     at the end).
/// interpolate : bool, optional
///     The interpolating variant (as ``LLCurve.interpolate``): a curve through every point.
/// within : float, optional
///     Pass within this distance (model units, Euclidean) of every point at its node, keeping
///     the order (as ``karkas curve ll --within``): each node's target is the point within
///     the distance nearest to the plain approximation's node, and the interpolating system
///     is solved once for the targets. A distance at or above the plain approximation's
///     largest node deviation gives the plain approximation; a tiny one tends to the
///     interpolating variant. Not with ``interpolate=True``.
///
/// Raises
/// ------
/// PointsError
///     Too few points, a non-finite coordinate, or an array that is not ``(n, 2)`` or
///     ``(n, 3)``.
/// OptionError
///     ``order`` is out of range, ``within`` is not positive and finite, or ``within`` is
///     given with ``interpolate=True``.
///
/// Examples
/// --------
/// >>> pts = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, 2.0], [4.0, 0.0]])
/// >>> c = karkas.LLCurve(pts, order=3)
/// >>> a, b = c.domain
/// >>> bool(np.isclose(a, 1 / 6)), bool(np.isclose(b, 5 / 6))
/// (True, True)
/// >>> bool(np.allclose(c(a), pts[0])), bool(np.allclose(c(b), pts[-1]))
/// (True, True)
/// >>> c.order, c.interpolating, c.control_points.shape
/// (3, False, (5, 2))
/// >>> near = karkas.LLCurve(pts, order=3, within=0.05)
/// >>> near.within, round(near.largest_deviation, 12)
/// (0.05, 0.05)
/// >>> bool(np.all(np.linalg.norm(near(np.arange(1, 6) / 6) - pts, axis=1) <= 0.05 + 1e-12))
/// True
#[pyclass(extends = PyCurve, module = "karkas", name = "LLCurve", frozen)]
pub struct PyLlCurve {
    /// The order L (the curve is C^L).
    #[pyo3(get)]
    pub(crate) order: usize,
    /// True for the interpolating variant.
    #[pyo3(get)]
    pub(crate) interpolating: bool,
    /// The distance given as ``within`` (None without it).
    #[pyo3(get)]
    pub(crate) within: Option<f64>,
    /// With ``within``: the largest distance from a point to the curve at its node (at most
    /// ``within`` up to round-off; the plain approximation's when that is smaller). None
    /// without ``within``.
    #[pyo3(get)]
    largest_deviation: Option<f64>,
    /// The control polygon r_1..r_K (closed curves repeat the first point at the end), (K, d).
    #[pyo3(get, name = "control_points")]
    control: FlatPoints,
    /// The points given (for pickling).
    pub(crate) points: FlatPoints,
    /// True for a closed curve (for pickling).
    pub(crate) closed: bool,
}

impl PyLlCurve {
    fn build(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        closed: bool,
        (interpolating, within): (bool, Option<f64>),
    ) -> PyResult<PyClassInitializer<Self>> {
        check_within(interpolating, within)?;
        let (pts, dim) = PointsArray::extract_checked(points, "points")?;
        let order = count(order, "order")?;
        let flat = pts.flat();
        let n = pts.len();
        let (inner, control, largest_deviation): (Arc<dyn CurveImpl>, FlatPoints, Option<f64>) = by_dim!(dim, D => {
            let p = as_points::<D>(&flat);
            let (curve, largest) = maybe_detach(py, n, || match within {
                Some(distance) => LlCurve::<D>::within(p, order, closed, distance)
                    .map(|fit| (fit.shape, Some(fit.largest_deviation))),
                None if interpolating => LlCurve::<D>::interpolating(p, order, closed).map(|c| (c, None)),
                None => LlCurve::<D>::new(p, order, closed).map(|c| (c, None)),
            })
            .map_err(library_error)?;
            let control = FlatPoints::of(curve.control_points());
            (Arc::new(Wrapped::<_, D>(curve)), control, largest)
        });
        let points = FlatPoints {
            coords: flat.into_owned(),
            dim,
        };
        let description = format!(
            "<karkas.LLCurve {}order={order}, closed={}{}, {n} points in {dim}-D",
            variant(interpolating),
            py_bool(closed),
            within_text(within)
        );
        Ok(
            PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(PyLlCurve {
                order,
                interpolating,
                within,
                largest_deviation,
                control,
                points,
                closed,
            }),
        )
    }
}

#[pymethods]
impl PyLlCurve {
    #[new]
    #[pyo3(signature = (points, order = DEFAULT_ORDER as i64, closed = false, interpolate = false, within = None))]
    #[pyo3(text_signature = "(points, order=3, closed=False, interpolate=False, within=None)")]
    fn py_new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        closed: bool,
        interpolate: bool,
        within: Option<f64>,
    ) -> PyResult<PyClassInitializer<Self>> {
        Self::build(py, points, order, closed, (interpolate, within))
    }

    /// The interpolating LL curve: through every point at its node ``t_i = i/(K+1)``.
    ///
    /// The control polygon is found by an O(K) banded solve, so that the LL curve of it passes
    /// through the given points.
    ///
    /// Parameters
    /// ----------
    /// points : array_like
    ///     The points to pass through, shape ``(n, d)``, ``d`` in {2, 3}.
    /// order : int, optional
    ///     The order ``L >= 1`` (the curve is C^L).
    /// closed : bool, optional
    ///     A closed curve through the points taken cyclically.
    ///
    /// Returns
    /// -------
    /// LLCurve
    ///     The curve, with ``interpolating`` True.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Too few points, a non-finite coordinate, or a wrong shape.
    /// OptionError
    ///     ``order`` is out of range.
    /// ConvergenceError
    ///     The linear system is singular.
    ///
    /// Examples
    /// --------
    /// >>> pts = np.array([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, 2.0], [4.0, 0.0]])
    /// >>> c = karkas.LLCurve.interpolate(pts, order=3)
    /// >>> bool(np.allclose(c(np.arange(1, 6) / 6), pts))
    /// True
    #[staticmethod]
    #[pyo3(signature = (points, order = DEFAULT_ORDER as i64, closed = false))]
    #[pyo3(text_signature = "(points, order=3, closed=False)")]
    fn interpolate(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        closed: bool,
    ) -> PyResult<Py<Self>> {
        Py::new(py, Self::build(py, points, order, closed, (true, None))?)
    }
}

/// The LL approximation of a grid of points: a C^L surface that never oscillates more than its
/// grid (the tensor product of LL curves, Aulchenko, Latypov, Nikulichev).
///
/// Node ``(i, j)`` sits at ``(i/(Ku+1), j/(Kv+1))``. ``LLSurface.interpolate`` gives a surface
/// through every grid point. Calling the surface is described in ``Surface``.
///
/// Outside the domain (the rule of every surface class, per direction): a closed direction
/// wraps the parameter by its period; an open one continues the end polynomial pieces when
/// ``extrapolate`` is None or True (the values of ``NdBSpline(*S.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
///
/// Parameters
/// ----------
/// grid : array_like
///     The grid, shape ``(nu, nv, d)``, ``d`` in {2, 3}; ``grid[i]`` is the ``i``-th row,
///     along ``v``.
/// order : int, optional
///     The order ``L >= 1`` (the surface is C^L).
/// closed_u, closed_v : bool, optional
///     Closed in ``u`` (the rows taken cyclically), in ``v`` (the columns taken cyclically).
/// interpolate : bool, optional
///     The interpolating variant (as ``LLSurface.interpolate``): through every grid point.
/// within : float, optional
///     Pass within this distance (model units, Euclidean) of every grid point at its node,
///     keeping the order (as ``karkas surface ll --within``; see ``LLCurve``). Not with
///     ``interpolate=True``.
/// crease_u, crease_v : bool, optional
///     Close the surface in ``u`` (``v``) with a crease, a ``C^0`` seam (a sharp trailing
///     edge stays sharp): the first row (column) is appended after the last unless the last
///     repeats it, and the direction is treated as an open one (``karkas surface ll
///     --crease-u/--crease-v``). Not with ``closed_u`` (``closed_v``): an ``OptionError``.
///
/// Raises
/// ------
/// PointsError
///     Too few grid points, a non-finite coordinate, or an array that is not
///     ``(nu, nv, 2)`` or ``(nu, nv, 3)``.
/// OptionError
///     ``order`` is out of range, ``within`` is not positive and finite, or ``within`` is
///     given with ``interpolate=True``.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, (i - 2) * (j - 2)] for j in range(5)] for i in range(5)], float)
/// >>> S = karkas.LLSurface(grid, order=3)
/// >>> a, b = S.domain_u
/// >>> bool(np.isclose(a, 1 / 6)), S.domain_v == S.domain_u
/// (True, True)
/// >>> bool(np.allclose(S(a, a), grid[0, 0]))
/// True
/// >>> S.sample(4, 6).shape
/// (4, 6, 3)
///
/// A ring of sharp-edged sections closed with a crease: the first column is repeated at the
/// end, so the surface meets itself at the edge, with a corner there.
///
/// >>> t = np.linspace(0, 2 * np.pi, 9)[:-1]
/// >>> lens = np.array([[[np.cos(a), 0.3 * np.sin(a) * abs(np.sin(a)), z] for a in t] for z in range(4)])
/// >>> W = karkas.LLSurface(lens, interpolate=True, crease_v=True)
/// >>> (a, b), (c, e) = W.domain_u, W.domain_v
/// >>> bool(np.allclose(W(a, c), W(a, e))), bool(np.allclose(W(a, c), lens[0, 0]))
/// (True, True)
#[pyclass(extends = PySurface, module = "karkas", name = "LLSurface", frozen)]
pub struct PyLlSurface {
    /// The order L (the surface is C^L).
    #[pyo3(get)]
    pub(crate) order: usize,
    /// True for the interpolating variant.
    #[pyo3(get)]
    pub(crate) interpolating: bool,
    /// The distance given as ``within`` (None without it).
    #[pyo3(get)]
    pub(crate) within: Option<f64>,
    /// With ``within``: the largest distance from a grid point to the surface at its node.
    /// None without ``within``.
    #[pyo3(get)]
    largest_deviation: Option<f64>,
    /// The grid given, row-major (for pickling and the default section cells).
    pub(crate) grid: FlatPoints,
    /// The grid's rows and columns.
    pub(crate) shape: (usize, usize),
    /// Closed in u, in v (for pickling).
    pub(crate) closed: (bool, bool),
}

impl PyLlSurface {
    fn build(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        order: i64,
        closed_u: bool,
        closed_v: bool,
        (interpolating, within): (bool, Option<f64>),
        crease: (bool, bool),
    ) -> PyResult<PyClassInitializer<Self>> {
        check_within(interpolating, within)?;
        let (g, dim) = GridArray::extract_checked(grid, "grid")?;
        let order = count(order, "order")?;
        let (rows, cols, inner, largest_deviation, coords): (
            usize,
            usize,
            Arc<dyn SurfaceImpl>,
            Option<f64>,
            Vec<f64>,
        ) = by_dim!(dim, D => {
            let grid = creased(g.grid::<D>()?, crease, (closed_u, closed_v))?;
            let (surface, largest) = maybe_detach(py, grid.rows() * grid.cols(), || match within {
                Some(distance) => LlSurface::<D>::within(&grid, order, closed_u, closed_v, distance)
                    .map(|fit| (fit.shape, Some(fit.largest_deviation))),
                None if interpolating => LlSurface::<D>::interpolating(&grid, order, closed_u, closed_v)
                    .map(|s| (s, None)),
                None => LlSurface::<D>::new(&grid, order, closed_u, closed_v).map(|s| (s, None)),
            })
            .map_err(library_error)?;
            let coords = flatten(grid.as_slice()).to_vec();
            (grid.rows(), grid.cols(), Arc::new(WrappedSurface::<_, D>(surface)), largest, coords)
        });
        // A creased grid is kept closed by its appended line: it rebuilds as an open one.
        let given = FlatPoints { coords, dim };
        let description = format!(
            "<karkas.LLSurface {}order={order}, closed_u={}, closed_v={}{}, {rows}x{cols} grid in {dim}-D",
            variant(interpolating),
            py_bool(closed_u),
            py_bool(closed_v),
            within_text(within)
        );
        Ok(
            PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(
                PyLlSurface {
                    order,
                    interpolating,
                    within,
                    largest_deviation,
                    grid: given,
                    shape: (rows, cols),
                    closed: (closed_u, closed_v),
                },
            ),
        )
    }
}

#[pymethods]
impl PyLlSurface {
    #[new]
    #[pyo3(signature = (grid, order = DEFAULT_ORDER as i64, closed_u = false, closed_v = false, interpolate = false, within = None, crease_u = false, crease_v = false))]
    #[pyo3(
        text_signature = "(grid, order=3, closed_u=False, closed_v=False, interpolate=False, within=None, crease_u=False, crease_v=False)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        order: i64,
        closed_u: bool,
        closed_v: bool,
        interpolate: bool,
        within: Option<f64>,
        crease_u: bool,
        crease_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let variant = (interpolate, within);
        Self::build(
            py,
            grid,
            order,
            closed_u,
            closed_v,
            variant,
            (crease_u, crease_v),
        )
    }

    /// The interpolating LL surface: through every grid point at its node.
    ///
    /// Parameters
    /// ----------
    /// grid : array_like
    ///     The grid, shape ``(nu, nv, d)``, ``d`` in {2, 3}.
    /// order : int, optional
    ///     The order ``L >= 1`` (the surface is C^L).
    /// closed_u, closed_v : bool, optional
    ///     Closed in ``u``, in ``v``.
    ///
    /// Returns
    /// -------
    /// LLSurface
    ///     The surface, with ``interpolating`` True.
    ///
    /// Raises
    /// ------
    /// PointsError
    ///     Too few grid points, a non-finite coordinate, or a wrong shape.
    /// OptionError
    ///     ``order`` is out of range.
    /// ConvergenceError
    ///     The linear system is singular.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, (i - 2) * (j - 2)] for j in range(5)] for i in range(5)], float)
    /// >>> S = karkas.LLSurface.interpolate(grid, order=3)
    /// >>> nodes = np.arange(1, 6) / 6
    /// >>> bool(np.allclose(S(nodes, nodes), grid))
    /// True
    #[staticmethod]
    #[pyo3(signature = (grid, order = DEFAULT_ORDER as i64, closed_u = false, closed_v = false))]
    #[pyo3(text_signature = "(grid, order=3, closed_u=False, closed_v=False)")]
    fn interpolate(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        order: i64,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<Py<Self>> {
        Py::new(
            py,
            Self::build(
                py,
                grid,
                order,
                closed_u,
                closed_v,
                (true, None),
                (false, false),
            )?,
        )
    }
}

/// Refuses ``within`` together with ``interpolate=True`` (the library refuses a distance that
/// is not positive and finite).
fn check_within(interpolating: bool, within: Option<f64>) -> PyResult<()> {
    if interpolating && within.is_some() {
        return Err(OptionError::new_err(
            "within and interpolate=True exclude each other: within already lies between the \
             approximation and the interpolation",
        ));
    }
    Ok(())
}

/// `", within=D"` for the `repr` of a curve or surface built with `within`.
fn within_text(within: Option<f64>) -> String {
    within.map_or_else(String::new, |d| format!(", within={d}"))
}

/// The LL paper's surface variation: the least change of a matrix that gives it prescribed row
/// and column sums.
///
/// Parameters
/// ----------
/// matrix : array_like
///     The matrix ``Z``, shape ``(n, m)``.
/// row_sums : sequence of float
///     The ``n`` row sums the result must have.
/// column_sums : sequence of float
///     The ``m`` column sums the result must have (they must add up to the same total as
///     ``row_sums``).
/// fixed : array_like of bool, optional
///     Shape ``(n, m)``: entries held (exactly, or at ``penalty`` times the cost of a change).
/// penalty : float, optional
///     None: fixed entries do not change; a number: changing them costs that many times more.
/// scale_with_total : bool, optional
///     Weigh each change by the entry's size relative to the total.
/// total : float, optional
///     The new sum of all entries: ``row_sums`` and ``column_sums`` may then leave out their
///     last sum, which takes the rest (as ``karkas vary --total``).
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(n, m)``: the varied matrix.
///
/// Raises
/// ------
/// IncompatibleDataError
///     The sums cannot all hold (different totals, or fixed entries that forbid them).
/// PointsError
///     Shapes that do not match.
///
/// Examples
/// --------
/// >>> z = np.ones((2, 3))
/// >>> w = karkas.vary(z, row_sums=[4.0, 2.0], column_sums=[2.0, 2.0, 2.0])
/// >>> w.sum(axis=1), w.sum(axis=0)
/// (array([4., 2.]), array([2., 2., 2.]))
#[pyfunction]
#[pyo3(signature = (matrix, row_sums, column_sums, fixed = None, penalty = None, scale_with_total = false, total = None))]
#[allow(clippy::too_many_arguments)]
pub fn vary<'py>(
    py: Python<'py>,
    matrix: &Bound<'py, PyAny>,
    row_sums: &Bound<'py, PyAny>,
    column_sums: &Bound<'py, PyAny>,
    fixed: Option<PyArrayLike2<'py, bool, AllowTypeChange>>,
    penalty: Option<f64>,
    scale_with_total: bool,
    total: Option<f64>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let row_sums = small_vector(row_sums, "row_sums")?;
    let column_sums = small_vector(column_sums, "column_sums")?;
    let matrix: PyArrayLike2<'py, f64, AllowTypeChange> =
        real_array(matrix, "matrix")?
            .extract()
            .map_err(|_| PointsError::new_err("matrix must be a 2-D float array"))?;
    let (n, m) = (matrix.shape()[0], matrix.shape()[1]);
    // The matrix, the fixed entries, the varied matrix and the solver's work (about as many
    // numbers again), before any copy.
    check_memory(
        py,
        &format!("vary of a {n} x {m} matrix"),
        bytes_of(&[n, m], 8 * 3 + 1),
    )?;
    let complete = |name: &str, given: &[f64], lines: usize| {
        complete_sums(given, lines, total).map_err(|problem| {
            OptionError::new_err(match problem {
                SumsProblem::TotalMismatch { lines, sum, total } => {
                    format!("{name}: the {lines} sums add up to {sum}, not to total {total}")
                }
                SumsProblem::NoTotal { given, lines } => format!(
                    "{name}: {given} sums given for {lines} lines; give all {lines}, or {} with total",
                    lines - 1
                ),
                SumsProblem::WrongCount { given, lines } => format!(
                    "{name}: {lines} sums are needed (or {} with total), got {given}",
                    lines.saturating_sub(1)
                ),
            })
        })
    };
    let row_sums = complete("row_sums", &row_sums, n)?;
    let column_sums = complete("column_sums", &column_sums, m)?;
    let values: Vec<f64> = matrix.as_array().iter().copied().collect();
    let z = Grid::from_row_major(n, m, values).map_err(library_error)?;
    let fixed = match fixed {
        Some(f) => {
            if f.shape() != [n, m] {
                return Err(PointsError::new_err(format!(
                    "fixed has shape {}, the matrix {}",
                    shape_text(f.shape()),
                    shape_text(&[n, m])
                )));
            }
            Grid::from_row_major(n, m, f.as_array().iter().copied().collect())
                .map_err(library_error)?
        }
        None => Grid::from_fn(n, m, |_, _| false),
    };
    let options = VariationOptions {
        fixed_entries: penalty.map_or(FixedEntries::Exact, FixedEntries::Penalty),
        scale_with_total,
    };
    let targets = SumTargets {
        rows: row_sums,
        columns: column_sums,
    };
    let varied = py
        .detach(|| ll_vary(&z, &fixed, &targets, &options))
        .map_err(library_error)?;
    let out = zeros(py, &[n, m])?;
    write_flat(&out, |flat| flat.copy_from_slice(varied.as_slice()))?;
    Ok(out)
}

#[pymethods]
impl PyLlSurface {
    /// Where the plane ``normal . x = offset`` cuts the surface, as polylines on it.
    ///
    /// As ``Surface.section``, with the command line's default search grid (``karkas section
    /// --method ll``): ``cells=None`` means 2 cells per grid line in each direction, at least 16.
    ///
    /// Parameters
    /// ----------
    /// normal : sequence of float
    ///     The plane's normal, ``d`` coordinates (need not be a unit vector).
    /// offset : float
    ///     The plane is ``normal . x = offset``.
    /// tolerance : float, optional
    ///     The largest chord error of the polylines; None: 1e-4 of the diagonal of the
    ///     surface's bounding box.
    /// cells : tuple of int, optional
    ///     The ``(nu, nv)`` cells of the search grid; None: the command line's default.
    ///
    /// Returns
    /// -------
    /// list of SectionCurve
    ///     The connected pieces of the section (empty when the plane misses the surface).
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     ``normal`` has the wrong number of coordinates or is zero, or ``tolerance`` or
    ///     ``cells`` is out of range.
    /// ConvergenceError
    ///     The continuation could not follow the section.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, i * j] for j in range(5)] for i in range(5)], float)
    /// >>> S = karkas.LLSurface(grid, order=3)
    /// >>> pieces = S.section([1.0, 0.0, 0.0], 2.0)
    /// >>> len(pieces)
    /// 1
    /// >>> bool(np.allclose(pieces[0].points[:, 0], 2.0))
    /// True
    #[pyo3(signature = (normal, offset, tolerance = None, cells = None))]
    fn section<'py>(
        slf: &Bound<'py, Self>,
        normal: &Bound<'py, PyAny>,
        offset: f64,
        tolerance: Option<f64>,
        cells: Option<(usize, usize)>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (rows, cols) = slf.get().shape;
        let cells = cells.unwrap_or_else(|| karkas::section::cells_for_grid(rows, cols));
        let base = slf.py().get_type::<PySurface>().getattr("section")?;
        base.call1((slf, normal, offset, tolerance, cells))
    }
}

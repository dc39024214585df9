//! The LL approximation (Aulchenko, Latypov, Nikulichev): the Python classes `LLCurve` and
//! `LLSurface`, and the surface variation method `vary`.

use std::sync::Arc;

use karkas::ll::{vary as ll_vary, FixedEntries, LlCurve, LlSurface, SumTargets, VariationOptions};
use karkas::Grid;
use numpy::{AllowTypeChange, PyArrayDyn, PyArrayLike2, PyUntypedArrayMethods};
use pyo3::prelude::*;

use crate::convert::{
    as_points, by_dim, count, maybe_detach, py_bool, real_array, small_vector, variant, write_flat,
    FlatPoints, GridArray, PointsArray,
};
use crate::curve::PyCurve;
use crate::errors::{library_error, PointsError};
use crate::limits::{bytes_of, check_memory, shape_text, zeros};
use crate::surface::PySurface;
use crate::wrapper::{CurveImpl, SurfaceImpl, Wrapped, WrappedSurface};

/// The LL approximation of a support polygon (Aulchenko, Latypov, Nikulichev): a C^L curve
/// that never oscillates more than its polygon.
///
/// LLCurve(points, order=5, closed=False): points (n, d), d in {2, 3}. Node i sits at
/// t = i/(K+1); the domain is [1/(K+1), K/(K+1)]. An open curve passes through its first and
/// last points; use LLCurve.interpolate for a curve through every point.
#[pyclass(extends = PyCurve, module = "karkas", name = "LLCurve", frozen)]
pub struct PyLlCurve {
    /// The order L (the curve is C^L).
    #[pyo3(get)]
    order: usize,
    /// True for the interpolating variant.
    #[pyo3(get)]
    interpolating: bool,
    /// The control polygon r_1..r_K (closed curves repeat the first point at the end), (K, d).
    #[pyo3(get, name = "control_points")]
    control: FlatPoints,
}

impl PyLlCurve {
    fn build(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        closed: bool,
        interpolating: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (pts, dim) = PointsArray::extract_checked(points, "points")?;
        let order = count(order, "order")?;
        let flat = pts.flat();
        let n = pts.len();
        let (inner, control): (Arc<dyn CurveImpl>, FlatPoints) = by_dim!(dim, D => {
            let p = as_points::<D>(&flat);
            let curve = maybe_detach(py, n, || {
                if interpolating {
                    LlCurve::<D>::interpolating(p, order, closed)
                } else {
                    LlCurve::<D>::new(p, order, closed)
                }
            })
            .map_err(library_error)?;
            let control = FlatPoints::of(curve.control_points());
            (Arc::new(Wrapped::<_, D>(curve)), control)
        });
        let description = format!(
            "<karkas.LLCurve {}order={order}, closed={}, {n} points in {dim}-D",
            variant(interpolating),
            py_bool(closed)
        );
        Ok(
            PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(PyLlCurve {
                order,
                interpolating,
                control,
            }),
        )
    }
}

#[pymethods]
impl PyLlCurve {
    #[new]
    #[pyo3(signature = (points, order = 5, closed = false))]
    fn py_new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        closed: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        Self::build(py, points, order, closed, false)
    }

    /// LLCurve.interpolate(points, order=5, closed=False): the interpolating LL curve, through
    /// every point at its node t_i = i/(K+1) (an O(K) banded solve).
    #[staticmethod]
    #[pyo3(signature = (points, order = 5, closed = false))]
    fn interpolate(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        order: i64,
        closed: bool,
    ) -> PyResult<Py<Self>> {
        Py::new(py, Self::build(py, points, order, closed, true)?)
    }
}

/// The LL approximation of a grid of points: a C^L surface that never oscillates more than its
/// grid (the tensor product of LL curves).
///
/// LLSurface(grid, order=5, closed_u=False, closed_v=False): grid (nu, nv, d), rows along u.
/// Node (i, j) sits at (i/(Ku+1), j/(Kv+1)). Use LLSurface.interpolate for a surface through
/// every grid point.
#[pyclass(extends = PySurface, module = "karkas", name = "LLSurface", frozen)]
pub struct PyLlSurface {
    /// The order L (the surface is C^L).
    #[pyo3(get)]
    order: usize,
    /// True for the interpolating variant.
    #[pyo3(get)]
    interpolating: bool,
}

impl PyLlSurface {
    fn build(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        order: i64,
        closed_u: bool,
        closed_v: bool,
        interpolating: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (g, dim) = GridArray::extract_checked(grid, "grid")?;
        let order = count(order, "order")?;
        let (rows, cols, inner): (usize, usize, Arc<dyn SurfaceImpl>) = by_dim!(dim, D => {
            let grid = g.grid::<D>()?;
            let surface = maybe_detach(py, grid.rows() * grid.cols(), || {
                if interpolating {
                    LlSurface::<D>::interpolating(&grid, order, closed_u, closed_v)
                } else {
                    LlSurface::<D>::new(&grid, order, closed_u, closed_v)
                }
            })
            .map_err(library_error)?;
            (grid.rows(), grid.cols(), Arc::new(WrappedSurface::<_, D>(surface)))
        });
        let description = format!(
            "<karkas.LLSurface {}order={order}, closed_u={}, closed_v={}, {rows}x{cols} grid in {dim}-D",
            variant(interpolating),
            py_bool(closed_u),
            py_bool(closed_v)
        );
        Ok(
            PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(
                PyLlSurface {
                    order,
                    interpolating,
                },
            ),
        )
    }
}

#[pymethods]
impl PyLlSurface {
    #[new]
    #[pyo3(signature = (grid, order = 5, closed_u = false, closed_v = false))]
    fn py_new(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        order: i64,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        Self::build(py, grid, order, closed_u, closed_v, false)
    }

    /// LLSurface.interpolate(grid, order=5, closed_u=False, closed_v=False): the interpolating
    /// LL surface, through every grid point at its node.
    #[staticmethod]
    #[pyo3(signature = (grid, order = 5, closed_u = false, closed_v = false))]
    fn interpolate(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        order: i64,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<Py<Self>> {
        Py::new(py, Self::build(py, grid, order, closed_u, closed_v, true)?)
    }
}

/// vary(matrix, row_sums, column_sums, fixed=None, penalty=None, scale_with_total=False) ->
/// (n, m): the LL paper's surface variation: the least change of matrix (n, m) whose row and
/// column sums become the given ones, entries where fixed (bool (n, m)) is true held exactly
/// (or at penalty times the cost).
#[pyfunction]
#[pyo3(signature = (matrix, row_sums, column_sums, fixed = None, penalty = None, scale_with_total = false))]
pub fn vary<'py>(
    py: Python<'py>,
    matrix: &Bound<'py, PyAny>,
    row_sums: &Bound<'py, PyAny>,
    column_sums: &Bound<'py, PyAny>,
    fixed: Option<PyArrayLike2<'py, bool, AllowTypeChange>>,
    penalty: Option<f64>,
    scale_with_total: bool,
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

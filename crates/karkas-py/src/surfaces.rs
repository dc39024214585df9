//! The surface classes built from grids: `LLSurface`, `BicubicSurface`.

use std::sync::Arc;

use karkas::ll::LlSurface;
use karkas::param::{BicubicSurface, GridParameterization};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{check_dim, extract_vector, invalid, maybe_detach, value_error, GridArray};
use crate::curves::{by_dim, count, py_bool};
use crate::surface::{PySurface, SurfaceImpl, WrappedSurface};

/// The LL approximation of a grid of points: a C^L surface that never oscillates more than its
/// grid (the tensor product of LL curves).
///
/// LLSurface(grid, order=5, closed_u=False, closed_v=False): grid (nu, nv, d), rows along u.
/// Node (i, j) sits at (i/(Ku+1), j/(Kv+1)). Use LLSurface.interpolate for a surface through
/// every grid point.
#[pyclass(extends = PySurface, module = "karkas", name = "LLSurface", frozen)]
pub struct PyLlSurface {
    order: usize,
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
        let g = GridArray::extract(grid, "grid")?;
        let dim = check_dim(g.dim(), "grid")?;
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
            .map_err(value_error)?;
            (grid.rows(), grid.cols(), Arc::new(WrappedSurface::<_, D>(surface)))
        });
        let kind = if interpolating { "interpolating " } else { "" };
        let description = format!(
            "<karkas.LLSurface {kind}order={order}, closed_u={}, closed_v={}, {rows}x{cols} grid in {dim}-D",
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

    /// The order L (the surface is C^L).
    #[getter]
    fn order(&self) -> usize {
        self.order
    }

    /// True for the interpolating variant.
    #[getter]
    fn interpolating(&self) -> bool {
        self.interpolating
    }
}

/// The grid parameterization named `name`.
pub fn parse_grid_parameterization(name: &str) -> PyResult<GridParameterization> {
    match name {
        "uniform" => Ok(GridParameterization::Uniform),
        "chord" => Ok(GridParameterization::default()),
        "averaged-chord" => Ok(GridParameterization::AveragedChord),
        "centripetal" => Ok(GridParameterization::Centripetal),
        _ => Err(invalid(format!(
            "unknown parameterization {name:?} (expected 'uniform', 'chord', 'averaged-chord' or 'centripetal')"
        ))),
    }
}

/// Bicubic interpolation of a grid of points (Kuznetsov, Filatov): a C^2 surface through every
/// grid point, on parameters computed from the grid.
///
/// BicubicSurface(grid, parameterization="chord", closed_u=False, closed_v=False): grid
/// (nu, nv, d). parameterization: 'uniform', 'chord' (chord lengths along the first row and
/// column), 'averaged-chord', 'centripetal'. BicubicSurface.from_knots(grid, knots_u, knots_v)
/// takes the parameters instead.
#[pyclass(extends = PySurface, module = "karkas", name = "BicubicSurface", frozen)]
pub struct PyBicubicSurface {
    knots_u: Vec<f64>,
    knots_v: Vec<f64>,
}

impl PyBicubicSurface {
    fn build(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        how: Result<&str, (Vec<f64>, Vec<f64>)>,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let g = GridArray::extract(grid, "grid")?;
        let dim = check_dim(g.dim(), "grid")?;
        let rule = match how {
            Ok(name) => Some(parse_grid_parameterization(name)?),
            Err(_) => None,
        };
        let (sub, inner, rows, cols): (Self, Arc<dyn SurfaceImpl>, usize, usize) = by_dim!(dim, D => {
            let grid = g.grid::<D>()?;
            let surface = maybe_detach(py, grid.rows() * grid.cols(), || match (&how, rule) {
                (Err((ku, kv)), _) => BicubicSurface::<D>::from_knots(&grid, ku, kv, closed_u, closed_v),
                (_, Some(rule)) => BicubicSurface::<D>::new(&grid, rule, closed_u, closed_v),
                (Ok(_), None) => Err(karkas::Error::Internal { what: "a parameterization without its rule" }),
            })
            .map_err(value_error)?;
            let sub = PyBicubicSurface {
                knots_u: surface.knots_u().to_vec(),
                knots_v: surface.knots_v().to_vec(),
            };
            (sub, Arc::new(WrappedSurface::<_, D>(surface)), grid.rows(), grid.cols())
        });
        let params = match how {
            Ok(name) => name.to_string(),
            Err(_) => "given knots".to_string(),
        };
        let description = format!(
            "<karkas.BicubicSurface parameterization='{params}', closed_u={}, closed_v={}, {rows}x{cols} grid in {dim}-D",
            py_bool(closed_u),
            py_bool(closed_v)
        );
        Ok(PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(sub))
    }
}

#[pymethods]
impl PyBicubicSurface {
    #[new]
    #[pyo3(signature = (grid, parameterization = "chord", closed_u = false, closed_v = false))]
    fn py_new(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        parameterization: &str,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        Self::build(py, grid, Ok(parameterization), closed_u, closed_v)
    }

    /// BicubicSurface.from_knots(grid, knots_u, knots_v, closed_u=False, closed_v=False): the
    /// bicubic interpolant on given parameters (knots_u (nu,), knots_v (nv,), increasing; a
    /// closed direction's last grid line must repeat its first).
    #[staticmethod]
    #[pyo3(signature = (grid, knots_u, knots_v, closed_u = false, closed_v = false))]
    fn from_knots(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        knots_u: &Bound<'_, PyAny>,
        knots_v: &Bound<'_, PyAny>,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<Py<Self>> {
        let ku = extract_vector(knots_u, "knots_u")?;
        let kv = extract_vector(knots_v, "knots_v")?;
        Py::new(
            py,
            Self::build(py, grid, Err((ku, kv)), closed_u, closed_v)?,
        )
    }

    /// The u parameters of the grid rows (a closed direction includes the closing step).
    #[getter]
    fn knots_u<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        crate::convert::vector_to_array(py, &self.knots_u)
    }

    /// The v parameters of the grid columns.
    #[getter]
    fn knots_v<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        crate::convert::vector_to_array(py, &self.knots_v)
    }
}

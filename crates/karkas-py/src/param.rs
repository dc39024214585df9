//! Interpolation on parameters (Kuznetsov, Filatov): the Python classes `CubicSpline` and
//! `BicubicSurface`, and the parameterizations of point lists and grids.

use std::sync::Arc;

use karkas::param::{
    curve_parameters as param_curve, grid_parameters as param_grid, BicubicSurface, CubicSpline,
    CurveParameterization, GridParameterization, SplineEnds,
};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points, by_dim, extract_vector, maybe_detach, py_bool, small_vector, vector_to_array,
    FlatPoints, GridArray, Numbers, PointsArray,
};
use crate::curve::PyCurve;
use crate::errors::{library_error, OptionError};
use crate::surface::PySurface;
use crate::wrapper::{CurveImpl, SurfaceImpl, Wrapped, WrappedSurface};

/// A float64 array returned to Python.
type Array<'py> = Bound<'py, PyArrayDyn<f64>>;

pub fn parse_parameterization(name: &str) -> PyResult<CurveParameterization> {
    match name {
        "uniform" => Ok(CurveParameterization::Uniform),
        "chord" | "chord-length" | "chordlength" => Ok(CurveParameterization::ChordLength),
        "centripetal" => Ok(CurveParameterization::Centripetal),
        _ => Err(OptionError::new_err(format!(
            "unknown parameterization {name:?} (expected 'uniform', 'chord' or 'centripetal')"
        ))),
    }
}

/// The end conditions named by `bc`.
fn parse_ends<const D: usize>(bc: &Bound<'_, PyAny>) -> PyResult<SplineEnds<D>> {
    if let Ok(name) = bc.extract::<String>() {
        return match name.as_str() {
            "not-a-knot" => Ok(SplineEnds::NotAKnot),
            "natural" => Ok(SplineEnds::Natural),
            "periodic" => Ok(SplineEnds::Periodic),
            _ => Err(OptionError::new_err(format!(
                "unknown bc {name:?} (expected 'not-a-knot', 'natural', 'periodic' or \
                 ('clamped', start_derivative, end_derivative))"
            ))),
        };
    }
    let (name, start, end): (String, Bound<'_, PyAny>, Bound<'_, PyAny>) =
        bc.extract().map_err(|_| {
            OptionError::new_err(
                "bc must be a name or ('clamped', start_derivative, end_derivative)",
            )
        })?;
    let start = small_vector(&start, "the start derivative of bc")?;
    let end = small_vector(&end, "the end derivative of bc")?;
    if name != "clamped" || start.len() != D || end.len() != D {
        return Err(OptionError::new_err(format!(
            "bc must be ('clamped', start, end) with {D} coordinates each"
        )));
    }
    let mut s = karkas::Point::<D>::ZERO;
    let mut e = karkas::Point::<D>::ZERO;
    s.0.copy_from_slice(&start);
    e.0.copy_from_slice(&end);
    Ok(SplineEnds::Clamped { start: s, end: e })
}

/// A cubic interpolating spline through points (C^2), as SciPy's CubicSpline but for
/// parametric curves.
///
/// CubicSpline(points, t=None, parameterization="chord", bc="not-a-knot"): points (n, d);
/// t (n,) strictly increasing parameters, or computed from the points by parameterization
/// ('uniform', 'chord', 'centripetal'; starting at 0). bc: 'not-a-knot', 'natural', 'periodic'
/// (closes the curve: the first point is appended unless the last repeats it) or
/// ('clamped', start_derivative, end_derivative).
#[pyclass(extends = PyCurve, module = "karkas", name = "CubicSpline", frozen)]
pub struct PyCubicSpline {
    /// The knots t_0 < ... < t_{n-1}.
    #[pyo3(get)]
    knots: Numbers,
    /// The interpolated values P(t_k), (n, d).
    #[pyo3(get)]
    values: FlatPoints,
    /// The node slopes P'(t_k), (n, d).
    #[pyo3(get)]
    slopes: FlatPoints,
}

#[pymethods]
impl PyCubicSpline {
    #[new]
    #[pyo3(signature = (points, t = None, parameterization = "chord", bc = None))]
    fn py_new(
        py: Python<'_>,
        points: &Bound<'_, PyAny>,
        t: Option<&Bound<'_, PyAny>>,
        parameterization: &str,
        bc: Option<&Bound<'_, PyAny>>,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (pts, dim) = PointsArray::extract_checked(points, "points")?;
        let rule = parse_parameterization(parameterization)?;
        let knots = t.map(|t| extract_vector(t, "t")).transpose()?;
        let flat = pts.flat();
        let n = pts.len();
        let (bc_name, built) = by_dim!(dim, D => {
            let ends: SplineEnds<D> = match bc {
                Some(bc) => parse_ends::<D>(bc)?,
                None => SplineEnds::NotAKnot,
            };
            let p = as_points::<D>(&flat);
            let spline = maybe_detach(py, n, || match &knots {
                Some(knots) => CubicSpline::<D>::new(knots, p, ends),
                None => CubicSpline::<D>::through(p, rule, ends),
            })
            .map_err(library_error)?;
            let name = match ends {
                SplineEnds::NotAKnot => "not-a-knot",
                SplineEnds::Natural => "natural",
                SplineEnds::Periodic => "periodic",
                SplineEnds::Clamped { .. } => "clamped",
            };
            let sub = PyCubicSpline {
                knots: Numbers(spline.knots().to_vec()),
                values: FlatPoints::of(spline.values()),
                slopes: FlatPoints::of(spline.slopes()),
            };
            let inner: Arc<dyn CurveImpl> = Arc::new(Wrapped::<_, D>(spline));
            (name, (inner, sub))
        });
        let (inner, sub) = built;
        let params = if knots.is_some() {
            "given t"
        } else {
            parameterization
        };
        let description = format!(
            "<karkas.CubicSpline bc='{bc_name}', parameterization='{params}', {} knots in {dim}-D",
            sub.knots.0.len()
        );
        Ok(PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(sub))
    }
}

/// The grid parameterization named `name`.
pub fn parse_grid_parameterization(name: &str) -> PyResult<GridParameterization> {
    match name {
        "uniform" => Ok(GridParameterization::Uniform),
        "chord" => Ok(GridParameterization::default()),
        "averaged-chord" => Ok(GridParameterization::AveragedChord),
        "centripetal" => Ok(GridParameterization::Centripetal),
        _ => Err(OptionError::new_err(format!(
            "unknown parameterization {name:?} (expected 'uniform', 'chord', 'averaged-chord' or 'centripetal')"
        ))),
    }
}

/// Where the parameters of a bicubic surface come from.
enum GridParameters {
    /// Computed from the grid.
    Rule(GridParameterization),
    /// Given: the u parameters of the rows, the v parameters of the columns.
    Knots(Vec<f64>, Vec<f64>),
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
    /// The u parameters of the grid rows (a closed direction includes the closing step).
    #[pyo3(get)]
    knots_u: Numbers,
    /// The v parameters of the grid columns.
    #[pyo3(get)]
    knots_v: Numbers,
}

impl PyBicubicSurface {
    fn build(
        py: Python<'_>,
        grid: &Bound<'_, PyAny>,
        how: Result<&str, (Vec<f64>, Vec<f64>)>,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (g, dim) = GridArray::extract_checked(grid, "grid")?;
        let (label, parameters) = match how {
            Ok(name) => (
                name.to_string(),
                GridParameters::Rule(parse_grid_parameterization(name)?),
            ),
            Err((ku, kv)) => ("given knots".to_string(), GridParameters::Knots(ku, kv)),
        };
        let (sub, inner, rows, cols): (Self, Arc<dyn SurfaceImpl>, usize, usize) = by_dim!(dim, D => {
            let grid = g.grid::<D>()?;
            let surface = maybe_detach(py, grid.rows() * grid.cols(), || match &parameters {
                GridParameters::Knots(ku, kv) => BicubicSurface::<D>::from_knots(&grid, ku, kv, closed_u, closed_v),
                GridParameters::Rule(rule) => BicubicSurface::<D>::new(&grid, *rule, closed_u, closed_v),
            })
            .map_err(library_error)?;
            let sub = PyBicubicSurface {
                knots_u: Numbers(surface.knots_u().to_vec()),
                knots_v: Numbers(surface.knots_v().to_vec()),
            };
            (sub, Arc::new(WrappedSurface::<_, D>(surface)), grid.rows(), grid.cols())
        });
        let description = format!(
            "<karkas.BicubicSurface parameterization='{label}', closed_u={}, closed_v={}, {rows}x{cols} grid in {dim}-D",
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
}

/// curve_parameters(points, parameterization="chord") -> (n,): the parameters of points
/// (n, d) starting at 0: 'uniform', 'chord' or 'centripetal'.
#[pyfunction]
#[pyo3(signature = (points, parameterization = "chord"))]
pub fn curve_parameters<'py>(
    py: Python<'py>,
    points: &Bound<'py, PyAny>,
    parameterization: &str,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let rule = parse_parameterization(parameterization)?;
    let (pts, dim) = PointsArray::extract_checked(points, "points")?;
    let flat = pts.flat();
    let t = by_dim!(dim, D => param_curve(as_points::<D>(&flat), rule)).map_err(library_error)?;
    vector_to_array(py, &t)
}

/// grid_parameters(grid, parameterization="chord") -> (u (nu,), v (nv,)): the parameters of
/// a grid (nu, nv, d): 'uniform', 'chord', 'averaged-chord' or 'centripetal'.
#[pyfunction]
#[pyo3(signature = (grid, parameterization = "chord"))]
pub fn grid_parameters<'py>(
    py: Python<'py>,
    grid: &Bound<'py, PyAny>,
    parameterization: &str,
) -> PyResult<(Array<'py>, Array<'py>)> {
    let rule = parse_grid_parameterization(parameterization)?;
    let (g, dim) = GridArray::extract_checked(grid, "grid")?;
    let (u, v) = by_dim!(dim, D => param_grid(&g.grid::<D>()?, rule)).map_err(library_error)?;
    Ok((vector_to_array(py, &u)?, vector_to_array(py, &v)?))
}

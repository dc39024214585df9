//! The classes `NurbsCurve` and `NurbsSurface`: the library's rational B-splines
//! ([`karkas::bspline::NurbsCurve`], [`karkas::bspline::NurbsSurface`]) as `Curve` and
//! `Surface` objects, built from their parts or read from CAD files (`read_cad`).

use std::sync::Arc;

use karkas::bspline::{NurbsCurve, NurbsSurface};
use karkas::{Curve, Grid, Point, Surface};
use numpy::PyArrayDyn;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::convert::{
    as_points, by_dim, extract_vector, py_bool, FlatPoints, GridArray, Numbers, PointsArray,
};
use crate::curve::PyCurve;
use crate::erased::{CurveImpl, SurfaceImpl, Wrapped, WrappedSurface};
use crate::errors::{library_error, OptionError};
use crate::surface::PySurface;

/// A rational B-spline (NURBS) curve in 2-D or 3-D: control points, weights, a knot vector
/// (clamped or not) and a degree; exact circles, ellipses and every B-spline.
///
/// ``C(t) = sum N_i(t) w_i P_i / sum N_i(t) w_i`` over the domain ``(knots[p], knots[n])``;
/// evaluation and derivatives of every order as for every ``Curve`` (the quotient rule of
/// The NURBS Book). Equal weights give the polynomial B-spline of the control points.
/// Outside the domain an open curve continues its end pieces (``extrapolate=False`` gives
/// NaN there). A rational curve has no polynomial B-spline form: ``to_bspline()`` raises
/// ``NoBSplineFormError`` for it.
///
/// Parameters
/// ----------
/// control_points : array_like
///     The control points, shape ``(n, d)``, ``d`` in {2, 3}.
/// knots : array_like
///     The knot vector, ``n + degree + 1`` nondecreasing values.
/// degree : int
///     The degree ``p`` (1 to 128).
/// weights : array_like, optional
///     One positive weight per control point (default: all 1).
/// closed : bool, optional
///     Mark the curve closed: parameters wrap by the domain's length (its ends must meet).
///
/// Raises
/// ------
/// PointsError
///     A control point that is not finite, a wrong shape, or counts that do not match.
/// KnotsError
///     Knots that decrease, are not finite, span an empty domain or repeat too often.
/// OptionError
///     A degree out of range; a weight that is not finite and positive.
///
/// Examples
/// --------
/// A quarter of the unit circle:
///
/// >>> w = np.sqrt(0.5)
/// >>> arc = karkas.NurbsCurve([[1, 0], [1, 1], [0, 1]], [0, 0, 0, 1, 1, 1], 2, [1, w, 1])
/// >>> p = arc(np.linspace(0, 1, 5))
/// >>> bool(np.allclose(np.hypot(p[:, 0], p[:, 1]), 1.0, atol=1e-15))
/// True
/// >>> arc.rational, arc.degree
/// (True, 2)
#[pyclass(extends = PyCurve, module = "karkas", name = "NurbsCurve", frozen)]
pub struct PyNurbsCurve {
    degree: usize,
    knots: Numbers,
    control: FlatPoints,
    weights: Numbers,
    closed: bool,
}

impl PyNurbsCurve {
    /// The Python object of a library curve of dimension `D`.
    pub fn initializer<const D: usize>(curve: NurbsCurve<D>) -> PyClassInitializer<Self> {
        let sub = PyNurbsCurve {
            degree: curve.degree(),
            knots: Numbers(curve.knots().to_vec()),
            control: FlatPoints::of(curve.control_points()),
            weights: Numbers(curve.weights().to_vec()),
            closed: curve.is_closed(),
        };
        let description = format!(
            "<karkas.NurbsCurve degree={}, {} control points, rational={}, closed={} in {D}-D",
            curve.degree(),
            curve.control_points().len(),
            py_bool(curve.is_rational()),
            py_bool(curve.is_closed())
        );
        let inner: Arc<dyn CurveImpl> = Arc::new(Wrapped::<_, D>(curve));
        PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(sub)
    }
}

#[pymethods]
impl PyNurbsCurve {
    #[new]
    #[pyo3(signature = (control_points, knots, degree, weights = None, closed = false))]
    #[pyo3(text_signature = "(control_points, knots, degree, weights=None, closed=False)")]
    fn py_new(
        control_points: &Bound<'_, PyAny>,
        knots: &Bound<'_, PyAny>,
        degree: i64,
        weights: Option<&Bound<'_, PyAny>>,
        closed: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (pts, dim) = PointsArray::extract_checked(control_points, "control_points")?;
        let knots = extract_vector(knots, "knots")?;
        let degree = usize::try_from(degree)
            .map_err(|_| OptionError::new_err(format!("degree must be positive, got {degree}")))?;
        let n = pts.len();
        let weights = match weights {
            Some(w) => extract_vector(w, "weights")?,
            None => vec![1.0; n],
        };
        let flat = pts.flat();
        Ok(by_dim!(dim, D => {
            let control: Vec<Point<D>> = as_points::<D>(&flat).to_vec();
            let curve = NurbsCurve::new(degree, knots, control, weights).map_err(library_error)?;
            Self::initializer(curve.with_closed(closed))
        }))
    }

    /// The degree ``p``.
    #[getter]
    fn degree(&self) -> usize {
        self.degree
    }

    /// The knot vector, float64 ``(n + p + 1,)``.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        (&self.knots).into_pyobject(py)
    }

    /// The control points, float64 ``(n, d)``.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.control.to_array(py)
    }

    /// The weights, float64 ``(n,)``.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        (&self.weights).into_pyobject(py)
    }

    /// True when the weights differ (the curve is not a polynomial B-spline).
    #[getter]
    fn rational(&self) -> bool {
        self.weights.0.iter().any(|&w| w != self.weights.0[0])
    }

    /// Pickling: the control points, knots, degree, weights and closedness.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let args = (
            self.control.to_array(py)?,
            (&self.knots).into_pyobject(py)?,
            self.degree,
            (&self.weights).into_pyobject(py)?,
            self.closed,
        )
            .into_pyobject(py)?;
        crate::pickle::reduce_call(py, "NurbsCurve", args)
    }
}

/// A rational tensor-product B-spline (NURBS) surface in 2-D or 3-D: a control grid, weights,
/// knot vectors in ``u`` and ``v`` (clamped or not) and degrees; exact cylinders, cones,
/// spheres, tori and every B-spline surface.
///
/// Evaluation and partial derivatives of every order as for every ``Surface``; outside the
/// domain an open direction continues its end pieces. A rational surface has no polynomial
/// B-spline form (``to_bspline()`` raises ``NoBSplineFormError``).
///
/// Parameters
/// ----------
/// control_points : array_like
///     The control grid, shape ``(nu, nv, d)``, ``d`` in {2, 3} (rows along ``u``).
/// knots_u, knots_v : array_like
///     The knot vectors, ``nu + degree_u + 1`` and ``nv + degree_v + 1`` nondecreasing values.
/// degree_u, degree_v : int
///     The degrees (1 to 128).
/// weights : array_like, optional
///     One positive weight per control point, shape ``(nu, nv)`` (default: all 1).
/// closed_u, closed_v : bool, optional
///     Mark a direction closed (periodic).
///
/// Raises
/// ------
/// PointsError
///     A control point that is not finite, a wrong shape, or counts that do not match.
/// KnotsError
///     Knots that decrease, are not finite, span an empty domain or repeat too often.
/// OptionError
///     A degree out of range; a weight that is not finite and positive.
///
/// Examples
/// --------
/// A quarter of the cylinder ``x^2 + y^2 = 1``, ``0 <= z <= 2``:
///
/// >>> w = np.sqrt(0.5)
/// >>> ring = [[1, 0], [1, 1], [0, 1]]
/// >>> grid = [[[x, y, 0], [x, y, 2]] for x, y in ring]
/// >>> S = karkas.NurbsSurface(grid, [0, 0, 0, 1, 1, 1], [0, 0, 1, 1], 2, 1,
/// ...                         [[1, 1], [w, w], [1, 1]])
/// >>> p = S(np.linspace(0, 1, 4), [1.0])[:, 0]
/// >>> bool(np.allclose(np.hypot(p[:, 0], p[:, 1]), 1.0, atol=1e-15))
/// True
#[pyclass(extends = PySurface, module = "karkas", name = "NurbsSurface", frozen)]
pub struct PyNurbsSurface {
    degrees: (usize, usize),
    knots_u: Numbers,
    knots_v: Numbers,
    control: FlatPoints,
    shape: (usize, usize),
    weights: Numbers,
    closed: (bool, bool),
}

impl PyNurbsSurface {
    /// The Python object of a library surface of dimension `D`.
    pub fn initializer<const D: usize>(surface: NurbsSurface<D>) -> PyClassInitializer<Self> {
        let grid = surface.control_points();
        let shape = (grid.rows(), grid.cols());
        let sub = PyNurbsSurface {
            degrees: (surface.degree_u(), surface.degree_v()),
            knots_u: Numbers(surface.knots_u().to_vec()),
            knots_v: Numbers(surface.knots_v().to_vec()),
            control: FlatPoints::of(grid.as_slice()),
            shape,
            weights: Numbers(surface.weights().as_slice().to_vec()),
            closed: (surface.is_closed_u(), surface.is_closed_v()),
        };
        let description = format!(
            "<karkas.NurbsSurface degrees=({}, {}), {}x{} control points, rational={} in {D}-D",
            surface.degree_u(),
            surface.degree_v(),
            shape.0,
            shape.1,
            py_bool(surface.is_rational())
        );
        let inner: Arc<dyn SurfaceImpl> = Arc::new(WrappedSurface::<_, D>(surface));
        PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(sub)
    }
}

#[pymethods]
impl PyNurbsSurface {
    #[new]
    #[pyo3(signature = (control_points, knots_u, knots_v, degree_u, degree_v, weights = None, closed_u = false, closed_v = false))]
    #[pyo3(
        text_signature = "(control_points, knots_u, knots_v, degree_u, degree_v, weights=None, closed_u=False, closed_v=False)"
    )]
    #[allow(clippy::too_many_arguments)]
    fn py_new(
        control_points: &Bound<'_, PyAny>,
        knots_u: &Bound<'_, PyAny>,
        knots_v: &Bound<'_, PyAny>,
        degree_u: i64,
        degree_v: i64,
        weights: Option<&Bound<'_, PyAny>>,
        closed_u: bool,
        closed_v: bool,
    ) -> PyResult<PyClassInitializer<Self>> {
        let (g, dim) = GridArray::extract_checked(control_points, "control_points")?;
        let (rows, cols) = g.rows_cols();
        let knots_u = extract_vector(knots_u, "knots_u")?;
        let knots_v = extract_vector(knots_v, "knots_v")?;
        let degree = |d: i64, name: &str| {
            usize::try_from(d)
                .map_err(|_| OptionError::new_err(format!("{name} must be positive, got {d}")))
        };
        let (du, dv) = (degree(degree_u, "degree_u")?, degree(degree_v, "degree_v")?);
        let weights = match weights {
            Some(w) => {
                let flat: Vec<f64> = w
                    .py()
                    .import("numpy")?
                    .call_method1("ravel", (w,))?
                    .call_method0("tolist")?
                    .extract()
                    .map_err(|_| OptionError::new_err("weights must be an array of numbers"))?;
                if flat.len() != rows * cols {
                    return Err(OptionError::new_err(format!(
                        "weights must have shape ({rows}, {cols}), got {} values",
                        flat.len()
                    )));
                }
                flat
            }
            None => vec![1.0; rows * cols],
        };
        let weights = Grid::from_row_major(rows, cols, weights).map_err(library_error)?;
        Ok(by_dim!(dim, D => {
            let grid = g.grid::<D>()?;
            let surface = NurbsSurface::new((du, knots_u), (dv, knots_v), grid, weights)
                .map_err(library_error)?;
            Self::initializer(surface.with_closed(closed_u, closed_v))
        }))
    }

    /// The degrees ``(p, q)`` in ``u`` and ``v``.
    #[getter]
    fn degrees(&self) -> (usize, usize) {
        self.degrees
    }

    /// The knot vector in ``u``, float64.
    #[getter]
    fn knots_u<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        (&self.knots_u).into_pyobject(py)
    }

    /// The knot vector in ``v``, float64.
    #[getter]
    fn knots_v<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        (&self.knots_v).into_pyobject(py)
    }

    /// The control grid, float64 ``(nu, nv, d)``.
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let (rows, cols) = self.shape;
        self.control
            .to_array(py)?
            .call_method1("reshape", ((rows, cols, self.control.dim),))
    }

    /// The weights, float64 ``(nu, nv)``.
    #[getter]
    fn weights<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        (&self.weights)
            .into_pyobject(py)?
            .call_method1("reshape", (self.shape,))
    }

    /// True when the weights differ (the surface is not a polynomial B-spline).
    #[getter]
    fn rational(&self) -> bool {
        self.weights.0.iter().any(|&w| w != self.weights.0[0])
    }

    /// Pickling: the control grid, knots, degrees, weights and closedness.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let me = slf.get();
        let py = slf.py();
        let args = (
            me.control_points(py)?,
            me.knots_u(py)?,
            me.knots_v(py)?,
            me.degrees.0,
            me.degrees.1,
            me.weights(py)?,
            me.closed.0,
            me.closed.1,
        )
            .into_pyobject(py)?;
        crate::pickle::reduce_call(py, "NurbsSurface", args)
    }
}

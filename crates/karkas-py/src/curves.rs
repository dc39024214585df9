//! The curve classes: `LLCurve`, `CubicSpline`, `HermiteSpline` (from `fit_curve`).

use std::sync::Arc;

use karkas::fit::{self, FitOptions, HermiteSpline};
use karkas::ll::LlCurve;
use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points, check_dim, extract_vector, flatten, invalid, maybe_detach, points_to_array,
    value_error, PointsArray,
};
use crate::curve::{CurveImpl, PyCurve, Wrapped};

/// Runs `$body` with `$D` bound to the constant dimension `$d` (2 or 3; checked before).
macro_rules! by_dim {
    ($d:expr, $D:ident => $body:expr) => {
        match $d {
            2 => {
                const $D: usize = 2;
                $body
            }
            _ => {
                const $D: usize = 3;
                $body
            }
        }
    };
}
pub(crate) use by_dim;

/// A non-negative Python integer as a count, or a `ValueError` naming it.
pub fn count(value: i64, name: &str) -> PyResult<usize> {
    usize::try_from(value)
        .map_err(|_| invalid(format!("{name} must be non-negative (got {value})")))
}

/// Flat coordinates and dimension kept for attributes such as `control_points`.
#[derive(Clone)]
pub struct FlatPoints {
    pub coords: Vec<f64>,
    pub dim: usize,
}

impl FlatPoints {
    /// The points of dimension `D`, flattened.
    pub fn of<const D: usize>(points: &[karkas::Point<D>]) -> Self {
        FlatPoints {
            coords: flatten(points).to_vec(),
            dim: D,
        }
    }

    /// A new `(n, d)` array.
    pub fn to_array<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        by_dim!(self.dim, D => points_to_array::<D>(py, as_points::<D>(&self.coords)))
    }
}

/// The LL approximation of a support polygon (Aulchenko, Latypov, Nikulichev): a C^L curve
/// that never oscillates more than its polygon.
///
/// LLCurve(points, order=5, closed=False): points (n, d), d in {2, 3}. Node i sits at
/// t = i/(K+1); the domain is [1/(K+1), K/(K+1)]. An open curve passes through its first and
/// last points; use LLCurve.interpolate for a curve through every point.
#[pyclass(extends = PyCurve, module = "karkas", name = "LLCurve", frozen)]
pub struct PyLlCurve {
    order: usize,
    interpolating: bool,
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
        let pts = PointsArray::extract(points, "points")?;
        let dim = check_dim(pts.dim(), "points")?;
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
            .map_err(value_error)?;
            let control = FlatPoints::of(curve.control_points());
            (Arc::new(Wrapped::<_, D>(curve)), control)
        });
        let kind = if interpolating { "interpolating " } else { "" };
        let description = format!(
            "<karkas.LLCurve {kind}order={order}, closed={}, {n} points in {dim}-D",
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

/// `True`/`False` as Python spells them.
pub fn py_bool(b: bool) -> &'static str {
    if b {
        "True"
    } else {
        "False"
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

    /// The order L (the curve is C^L).
    #[getter]
    fn order(&self) -> usize {
        self.order
    }

    /// True for the interpolating variant.
    #[getter]
    fn interpolating(&self) -> bool {
        self.interpolating
    }

    /// The control polygon r_1..r_K (closed curves repeat the first point at the end), (K, d).
    #[getter]
    fn control_points<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.control.to_array(py)
    }
}

pub fn parse_parameterization(name: &str) -> PyResult<CurveParameterization> {
    match name {
        "uniform" => Ok(CurveParameterization::Uniform),
        "chord" | "chord-length" | "chordlength" => Ok(CurveParameterization::ChordLength),
        "centripetal" => Ok(CurveParameterization::Centripetal),
        _ => Err(invalid(format!(
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
            _ => Err(invalid(format!(
                "unknown bc {name:?} (expected 'not-a-knot', 'natural', 'periodic' or \
                 ('clamped', start_derivative, end_derivative))"
            ))),
        };
    }
    let (name, start, end): (String, Vec<f64>, Vec<f64>) = bc.extract().map_err(|_| {
        invalid("bc must be a name or ('clamped', start_derivative, end_derivative)")
    })?;
    if name != "clamped" || start.len() != D || end.len() != D {
        return Err(invalid(format!(
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
    knots: Vec<f64>,
    values: FlatPoints,
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
        let pts = PointsArray::extract(points, "points")?;
        let dim = check_dim(pts.dim(), "points")?;
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
            .map_err(value_error)?;
            let name = match ends {
                SplineEnds::NotAKnot => "not-a-knot",
                SplineEnds::Natural => "natural",
                SplineEnds::Periodic => "periodic",
                SplineEnds::Clamped { .. } => "clamped",
            };
            let sub = PyCubicSpline {
                knots: spline.knots().to_vec(),
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
            sub.knots.len()
        );
        Ok(PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(sub))
    }

    /// The knots t_0 < ... < t_{n-1}.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        crate::convert::vector_to_array(py, &self.knots)
    }

    /// The interpolated values P(t_k), (n, d).
    #[getter]
    fn values<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.values.to_array(py)
    }

    /// The node slopes P'(t_k), (n, d).
    #[getter]
    fn slopes<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.slopes.to_array(py)
    }
}

/// A C^1 cubic Hermite spline (a cubic spline of defect 2) on [0, 1], as returned by
/// fit_curve: values and derivatives at its knots.
#[pyclass(extends = PyCurve, module = "karkas", name = "HermiteSpline", frozen)]
pub struct PyHermiteSpline {
    knots: Vec<f64>,
    values: FlatPoints,
    derivatives: FlatPoints,
    /// The largest distance of a fitted point from the curve.
    #[pyo3(get)]
    max_distance: f64,
    /// The root-mean-square distance of the fitted points from the curve.
    #[pyo3(get)]
    rms_distance: f64,
    /// f = sum delta_L |J_L|^2, the weighted sum of squared second-derivative jumps.
    #[pyo3(get)]
    jump_sum: f64,
    /// For a fit by tolerance: whether every point is within it (None otherwise).
    #[pyo3(get)]
    tolerance_met: Option<bool>,
    parameters: Vec<f64>,
    distances: Vec<f64>,
}

#[pymethods]
impl PyHermiteSpline {
    /// The knots 0 = T_1 < ... < T_N = 1.
    #[getter]
    fn knots<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        crate::convert::vector_to_array(py, &self.knots)
    }

    /// The values R_L at the knots, (N, d).
    #[getter]
    fn values<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.values.to_array(py)
    }

    /// The derivatives H_L at the knots, (N, d).
    #[getter]
    fn derivatives<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.derivatives.to_array(py)
    }

    /// The foot parameter of every fitted point, (n,).
    #[getter]
    fn parameters<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        crate::convert::vector_to_array(py, &self.parameters)
    }

    /// The distance of every fitted point from the curve, (n,).
    #[getter]
    fn distances<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        crate::convert::vector_to_array(py, &self.distances)
    }
}

/// fit_curve(points, knots=None, tolerance=None, eps=None, pin_ends=False, corners=None,
/// fairness=None) -> HermiteSpline
///
/// Fits measured points (n, d) with a C^1 cubic Hermite spline on [0, 1], minimizing the sum of
/// squared foot-point distances with the sum of squared second-derivative jumps bounded by eps
/// (None: no bound). knots: an int (that many uniform knots) or an increasing array from 0 to
/// 1; tolerance: knots are added until every point is within it. Give knots or tolerance.
#[pyfunction]
#[pyo3(signature = (points, knots = None, tolerance = None, eps = None, pin_ends = false, corners = None, fairness = None))]
#[allow(clippy::too_many_arguments)]
pub fn fit_curve(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    knots: Option<&Bound<'_, PyAny>>,
    tolerance: Option<f64>,
    eps: Option<f64>,
    pin_ends: bool,
    corners: Option<Vec<f64>>,
    fairness: Option<f64>,
) -> PyResult<Py<PyHermiteSpline>> {
    let pts = PointsArray::extract(points, "points")?;
    let dim = check_dim(pts.dim(), "points")?;
    let knots: Option<Vec<f64>> = match knots {
        None => None,
        Some(k) => match k.extract::<i64>() {
            Ok(n) => {
                let n = count(n, "knots")?;
                if n < 2 {
                    return Err(invalid(format!("knots must be at least 2 (got {n})")));
                }
                Some(fit::uniform_knots(n))
            }
            Err(_) => Some(extract_vector(k, "knots")?),
        },
    };
    if knots.is_some() && tolerance.is_some() {
        return Err(invalid("give knots or tolerance, not both"));
    }
    if knots.is_none() && tolerance.is_none() {
        return Err(invalid("give the knots or a tolerance"));
    }
    let mut options = FitOptions {
        pin_ends,
        corners: corners.unwrap_or_default(),
        ..FitOptions::default()
    };
    if let Some(eps) = eps {
        options.eps = eps;
    }
    if let Some(fairness) = fairness {
        options.fairness = fairness;
    }
    let flat = pts.flat();
    let (inner, sub): (Arc<dyn CurveImpl>, PyHermiteSpline) = by_dim!(dim, D => {
        let p = as_points::<D>(&flat);
        let (result, met) = py
            .detach(|| -> karkas::Result<(fit::CurveFit<D>, Option<bool>)> {
                match (&knots, tolerance) {
                    (Some(knots), _) => Ok((fit::fit_curve(p, knots, &options)?, None)),
                    (None, Some(tol)) => {
                        let a = fit::fit_curve_adaptive(p, tol, &options)?;
                        Ok((a.fit, Some(a.tolerance_met)))
                    }
                    (None, None) => Err(karkas::Error::Internal {
                        what: "neither knots nor a tolerance reached the fit",
                    }),
                }
            })
            .map_err(value_error)?;
        let spline: HermiteSpline<D> = result.spline.clone();
        let sub = PyHermiteSpline {
            knots: spline.knots().to_vec(),
            values: FlatPoints::of(spline.values()),
            derivatives: FlatPoints::of(spline.derivatives()),
            max_distance: result.max_distance(),
            rms_distance: result.rms_distance(),
            jump_sum: result.jump_sum,
            tolerance_met: met,
            parameters: result.parameters.clone(),
            distances: result.distances.clone(),
        };
        (Arc::new(Wrapped::<_, D>(spline)) as Arc<dyn CurveImpl>, sub)
    });
    let description = format!(
        "<karkas.HermiteSpline fit of {} points in {dim}-D, {} knots, max_distance={:.3e}, rms_distance={:.3e}",
        pts.len(),
        sub.knots.len(),
        sub.max_distance,
        sub.rms_distance
    );
    Py::new(
        py,
        PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(sub),
    )
}

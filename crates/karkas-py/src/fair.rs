//! The fairest curve within a tolerance (docs/methods.md §8): `fair_curve` and the Python
//! class `FairCurve` it returns.

use std::sync::Arc;

use karkas::bspline::BSplineCurve;
use karkas::fair::{
    fair_curve as fair_points, fair_existing_curve, FairCurve, FairEnds, FairOptions,
};
use karkas::geometry::CurveFairness;
use karkas::Curve;
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::{as_points, by_dim, extract_vector, FlatPoints, Numbers, PointsArray};
use crate::curve::PyCurve;
use crate::erased::CurveView;
use crate::erased::{CurveImpl, Wrapped};
use crate::errors::{library_error, OptionError};
use crate::geometry::fairness_dict;
use crate::limits::{bytes_of, check_memory};

/// Bytes the fairer works in per point (the spline, its banded systems, the report's
/// samples), in 3-D.
const BYTES_PER_POINT: u128 = 8 * 400;
/// Samples of a curve to fair: per polynomial piece, and at least.
const SAMPLES_PER_PIECE: usize = 20;
/// The least number of samples of a curve to fair.
const MIN_SAMPLES: usize = 200;

/// The fairest C^2 cubic B-spline within a tolerance of points: the result of ``fair_curve``,
/// with the points it was faired to, their parameters and distances, and its fairness report.
/// Calling the curve is described in ``Curve``; ``to_bspline()`` gives its knots and control
/// points.
///
/// Examples
/// --------
/// >>> x = np.linspace(0.0, 1.0, 60)
/// >>> f = karkas.fair_curve(np.column_stack([x, x * x + 1e-3 * np.sin(40 * x)]), 2e-3)
/// >>> bool(f.max_distance <= 2e-3), f.report()["after"]["curvature_extrema"]
/// (True, 0)
#[pyclass(extends = PyCurve, module = "karkas", name = "FairCurve", frozen)]
pub struct PyFairCurve {
    /// The clamped knot vector of the cubic B-spline, on [0, 1].
    #[pyo3(get)]
    knots: Numbers,
    /// The control points, (m, d).
    #[pyo3(get)]
    control_points: FlatPoints,
    /// The points the curve was faired to, (n, d) (samples of the curve given, for a curve).
    #[pyo3(get)]
    points: FlatPoints,
    /// The parameter of every point on the curve, (n,).
    #[pyo3(get)]
    parameters: Numbers,
    /// The distance of every point from the curve at its parameter (at most the tolerance).
    #[pyo3(get)]
    distances: Numbers,
    /// The tolerance asked.
    #[pyo3(get)]
    tolerance: f64,
    /// Whether the curve is closed.
    closed: bool,
    /// The fairness of the input: of the curve given, or of the cubic spline through the
    /// points (None when computed on demand).
    before: Option<CurveFairness>,
}

impl PyFairCurve {
    /// The object and its base from a library result of dimension `D`.
    fn from_library<const D: usize>(
        fair: FairCurve<D>,
        tolerance: f64,
        before: Option<CurveFairness>,
    ) -> PyClassInitializer<Self> {
        let dim = D;
        let description = format!(
            "<karkas.FairCurve of {} points in {dim}-D, {} control points, max_distance={:.3e}, tolerance={:.3e}",
            fair.points.len(),
            fair.curve.control_points().len(),
            fair.max_distance(),
            tolerance
        );
        let sub = PyFairCurve {
            knots: Numbers(fair.curve.knots().to_vec()),
            control_points: FlatPoints::of(fair.curve.control_points()),
            points: FlatPoints::of(&fair.points),
            parameters: Numbers(fair.parameters.clone()),
            distances: Numbers(fair.distances.clone()),
            tolerance,
            closed: fair.curve.is_closed(),
            before,
        };
        let inner = Arc::new(Wrapped::<_, D>(fair.curve)) as Arc<dyn CurveImpl>;
        PyClassInitializer::from(PyCurve::new(inner, description)).add_subclass(sub)
    }

    /// The library result again (for the report).
    fn library<const D: usize>(&self) -> PyResult<FairCurve<D>> {
        let control = as_points::<D>(&self.control_points.coords).to_vec();
        let closed = self.closed;
        let curve = if closed {
            BSplineCurve::new_closed(3, self.knots.0.clone(), control)
        } else {
            BSplineCurve::new(3, self.knots.0.clone(), control)
        }
        .map_err(library_error)?;
        Ok(FairCurve {
            curve,
            points: as_points::<D>(&self.points.coords).to_vec(),
            parameters: self.parameters.0.clone(),
            distances: self.distances.0.clone(),
        })
    }
}

/// The fairest C^2 cubic B-spline within ``tolerance`` of every point (or of a curve).
///
/// Minimizes the curvature-variation energy, the integral of (dk/ds)^2 over the arc length,
/// among cubic B-splines (one span per three points, the spans following the points) whose
/// distance from every point is at most ``tolerance`` (a hard bound, held by construction),
/// then asks dk/ds to keep its sign between the curvature extrema the points demand, so that
/// ripples no point needs are gone. As ``karkas curve fair``.
///
/// Parameters
/// ----------
/// points : array_like or Curve
///     The points in their order along the curve, shape ``(n, d)``, ``d`` in {2, 3}; or a
///     karkas curve, faired through samples of it (20 per piece, at least 200) with its own
///     end tangents for ``keep_tangents``.
/// tolerance : float
///     The largest distance allowed between a point and the curve (about 3 times the noise of
///     measured points).
/// keep_ends : bool, optional
///     Start at the first point and end at the last.
/// keep_tangents : bool, optional
///     Keep the ends and the directions of the end tangents (the first and last chords of
///     points, the curve's own of a curve).
/// corners : sequence of int, optional
///     Indices (0-based) of the points where the curve may turn a corner.
/// closed : bool, optional
///     The points go once around a closed curve (a curve given says so itself).
///
/// Returns
/// -------
/// FairCurve
///     The curve, with ``max_distance``, ``parameters``, ``distances`` and ``report()``.
///
/// Raises
/// ------
/// PointsError
///     Too few points, a non-finite coordinate, points not in order, or a wrong shape.
/// OptionError
///     A tolerance that is not positive or below what the coordinates resolve, corners that
///     are not inner points in increasing order.
///
/// Examples
/// --------
/// >>> t = np.linspace(0.0, 1.0, 40)
/// >>> f = karkas.fair_curve(np.column_stack([t, t * t]), 1e-4, keep_ends=True)
/// >>> f(np.array([0.0, 1.0]))
/// array([[0., 0.],
///        [1., 1.]])
#[pyfunction]
#[pyo3(signature = (points, tolerance, keep_ends = false, keep_tangents = false, corners = None, closed = false))]
#[pyo3(
    text_signature = "(points, tolerance, keep_ends=False, keep_tangents=False, corners=None, closed=False)"
)]
pub fn fair_curve(
    py: Python<'_>,
    points: &Bound<'_, PyAny>,
    tolerance: f64,
    keep_ends: bool,
    keep_tangents: bool,
    corners: Option<&Bound<'_, PyAny>>,
    closed: bool,
) -> PyResult<Py<PyFairCurve>> {
    let corners: Vec<usize> = match corners {
        None => Vec::new(),
        Some(c) => extract_vector(c, "corners")?
            .into_iter()
            .map(|v| {
                if v.fract() == 0.0 && v >= 0.0 && v < usize::MAX as f64 {
                    Ok(v as usize)
                } else {
                    Err(OptionError::new_err(format!(
                        "corners must be point indices, got {v}"
                    )))
                }
            })
            .collect::<PyResult<_>>()?,
    };
    let ends = if keep_tangents {
        FairEnds::KeptWithTangents
    } else if keep_ends {
        FairEnds::Kept
    } else {
        FairEnds::Free
    };
    let options = FairOptions {
        tolerance,
        ends,
        corners,
        closed,
    };
    if let Ok(curve) = points.cast::<PyCurve>() {
        let inner = curve.get().inner.clone();
        let dim = inner.dim();
        let samples =
            (SAMPLES_PER_PIECE * inner.breakpoints().len().saturating_sub(1)).max(MIN_SAMPLES);
        check_memory(
            py,
            &format!("fair_curve of a curve ({samples} samples)"),
            bytes_of(&[samples], BYTES_PER_POINT),
        )?;
        let init = by_dim!(dim, D => {
            let view = CurveView::<D>(inner.as_ref());
            let fair = py
                .detach(|| fair_existing_curve(&view, samples, &options))
                .map_err(library_error)?;
            let before = inner.fairness(crate::convert::flatten(&fair.points));
            PyFairCurve::from_library(fair, tolerance, Some(before))
        });
        return Py::new(py, init);
    }
    let (pts, dim) = PointsArray::extract_checked(points, "points")?;
    check_memory(
        py,
        &format!("fair_curve of {} points", pts.len()),
        bytes_of(&[pts.len()], BYTES_PER_POINT),
    )?;
    let flat = pts.flat();
    let init = by_dim!(dim, D => {
        let p = as_points::<D>(&flat);
        let fair = py.detach(|| fair_points(p, &options)).map_err(library_error)?;
        PyFairCurve::from_library(fair, tolerance, None)
    });
    Py::new(py, init)
}

#[pymethods]
impl PyFairCurve {
    /// The largest distance of a point from the curve.
    #[getter]
    fn max_distance(&self) -> f64 {
        self.distances.0.iter().fold(0.0, |a, &b| a.max(b))
    }

    /// The fairness before and after.
    ///
    /// Returns
    /// -------
    /// dict
    ///     ``{"before": {...}, "after": {...}}``, each with the keys of ``Curve.fairness``
    ///     (before: the curve given, or the cubic spline through the points with chord-length
    ///     parameters).
    ///
    /// Examples
    /// --------
    /// >>> x = np.linspace(0.0, 1.0, 60)
    /// >>> r = karkas.fair_curve(np.column_stack([x, x * x + 1e-3 * np.sin(40 * x)]), 2e-3).report()
    /// >>> r["before"]["curvature_extrema"], r["after"]["curvature_extrema"]
    /// (12, 0)
    fn report<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dim = self.points.dim;
        let (before, after) = by_dim!(dim, D => {
            let fair = self.library::<D>()?;
            py.detach(|| {
                let after = fair.fairness();
                (self.before.or_else(|| fair.fairness_before()).unwrap_or(after), after)
            })
        });
        let out = PyDict::new(py);
        out.set_item("before", fairness_dict(py, &before)?)?;
        out.set_item("after", fairness_dict(py, &after)?)?;
        Ok(out)
    }

    /// Pickling: the spline, the points with their parameters and distances, the tolerance.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, pyo3::types::PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let closed = this.closed;
        let args = (
            crate::convert::vector_to_array(py, &this.knots.0)?,
            this.control_points.to_array(py)?,
            closed,
            this.points.to_array(py)?,
            crate::convert::vector_to_array(py, &this.parameters.0)?,
            crate::convert::vector_to_array(py, &this.distances.0)?,
            this.tolerance,
        );
        crate::pickle::reduce(py, "FairCurve._from_state", args.into_pyobject(py)?, None)
    }

    /// The curve from its pickled state (``__reduce__``).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    fn _from_state(
        py: Python<'_>,
        knots: &Bound<'_, PyAny>,
        control_points: &Bound<'_, PyAny>,
        closed: bool,
        points: &Bound<'_, PyAny>,
        parameters: &Bound<'_, PyAny>,
        distances: &Bound<'_, PyAny>,
        tolerance: f64,
    ) -> PyResult<Py<PyFairCurve>> {
        let knots = extract_vector(knots, "knots")?;
        let (control, dim) = PointsArray::extract_checked(control_points, "control_points")?;
        let (pts, pdim) = PointsArray::extract_checked(points, "points")?;
        if pdim != dim {
            return Err(OptionError::new_err(
                "points and control points differ in dimension",
            ));
        }
        let (cf, pf) = (control.flat(), pts.flat());
        let parameters = extract_vector(parameters, "parameters")?;
        let distances = extract_vector(distances, "distances")?;
        let init = by_dim!(dim, D => {
            let control = as_points::<D>(&cf).to_vec();
            let curve = if closed {
                BSplineCurve::new_closed(3, knots.clone(), control)
            } else {
                BSplineCurve::new(3, knots.clone(), control)
            }
            .map_err(library_error)?;
            let fair = FairCurve { curve, points: as_points::<D>(&pf).to_vec(), parameters: parameters.clone(), distances: distances.clone() };
            PyFairCurve::from_library(fair, tolerance, None)
        });
        Py::new(py, init)
    }
}

//! Pickling and copying: `__reduce__` for every class, so that `pickle`, `copy.copy`,
//! `copy.deepcopy`, `multiprocessing` and `joblib` can ship karkas objects.
//!
//! The state is what the object was built from: the constructor's inputs (copied when the
//! object was built, so later changes to the caller's arrays do not leak in), or for a fitted
//! spline its coefficients and the fit's statistics. Unpickling calls [`restore`]
//! (`karkas._restore`) with the qualified name of the constructor and its arguments; every
//! construction is deterministic, so the copy evaluates bit-identically.

use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyTuple};

use crate::convert::{vector_to_array, FlatPoints};
use crate::coons::PyCoonsSurface;
use crate::dps::{PyDiscreteSpline, PyTubeSurface};
use crate::errors::OptionError;
use crate::fit::PyHermiteSpline;
use crate::implicit::PyImplicitSurface;
use crate::ll::{PyLlCurve, PyLlSurface};
use crate::param::{Ends, PyBicubicSurface, PyCubicSpline};
use crate::section::PySectionCurve;

/// The constructors `_restore` may call: the qualified names the `__reduce__` methods give.
const CONSTRUCTORS: [&str; 18] = [
    "LLCurve",
    "loft",
    "loft_windio",
    "LLSurface",
    "CubicSpline",
    "HermiteSpline._from_fit",
    "BicubicSurface",
    "BicubicSurface.from_knots",
    "DiscreteSpline",
    "DiscreteSpline.interpolate",
    "TubeSurface",
    "CoonsSurface",
    "SectionCurve._from_state",
    "ImplicitSurface",
    "HermiteSpline",
    "FairCurve._from_state",
    "NurbsCurve",
    "NurbsSurface",
];

/// _restore(name, args, kwargs=None): calls the karkas constructor `name` (e.g.
/// 'DiscreteSpline.interpolate') with the arguments; what `__reduce__` hands pickle.
#[pyfunction]
#[pyo3(name = "_restore", signature = (name, args, kwargs = None))]
pub fn restore<'py>(
    py: Python<'py>,
    name: &str,
    args: &Bound<'py, PyTuple>,
    kwargs: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    if !CONSTRUCTORS.contains(&name) {
        return Err(OptionError::new_err(format!(
            "{name:?} is not a karkas constructor"
        )));
    }
    let mut target = py.import("karkas")?.into_any();
    for part in name.split('.') {
        target = target.getattr(part)?;
    }
    target.call(args, kwargs)
}

#[pymethods]
impl crate::loft::PyLoftSurface {
    /// Pickling: `karkas.loft` of the profiles, placements, rule and tolerance (a dihedral
    /// not given is NaN), or `karkas.loft_windio` of the file's path (read again when
    /// unpickled).
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        reduce_loft(py, &self.input)
    }
}

/// What `LoftSurface.__reduce__` returns.
fn reduce_loft<'py>(
    py: Python<'py>,
    input: &crate::loft::LoftInput,
) -> PyResult<Bound<'py, PyTuple>> {
    use crate::convert::points_to_array;
    use crate::loft::LoftSource;
    let (profiles, placements) = match &input.source {
        LoftSource::Wing {
            profiles,
            placements,
        } => (profiles, placements),
        LoftSource::Windio { path } => {
            let args = (
                path.clone(),
                input.options.rule.name(),
                input.options.tolerance,
            );
            return reduce(py, "loft_windio", args.into_pyobject(py)?, None);
        }
    };
    let profiles = profiles
        .iter()
        .map(|p| points_to_array(py, p))
        .collect::<PyResult<Vec<_>>>()?;
    let les: Vec<karkas::Point3> = placements.iter().map(|p| p.leading_edge).collect();
    let numbers = |f: &dyn Fn(&karkas::loft::WingPlacement) -> f64| {
        vector_to_array(py, &placements.iter().map(f).collect::<Vec<f64>>())
    };
    let args = (
        profiles,
        points_to_array(py, &les)?,
        numbers(&|p| p.chord)?,
        numbers(&|p| p.twist)?,
        numbers(&|p| p.dihedral.unwrap_or(f64::NAN))?,
        input.options.rule.name(),
        input.options.tolerance,
    );
    reduce(py, "loft", args.into_pyobject(py)?, None)
}

/// What `__reduce__` returns: `(karkas._restore, (name, args[, kwargs]))`.
pub(crate) fn reduce<'py>(
    py: Python<'py>,
    name: &str,
    args: Bound<'py, PyTuple>,
    kwargs: Option<Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyTuple>> {
    let restore = py.import("karkas")?.getattr("_restore")?;
    let call_args = match kwargs {
        Some(k) => PyTuple::new(
            py,
            [
                name.into_pyobject(py)?.into_any(),
                args.into_any(),
                k.into_any(),
            ],
        )?,
        None => PyTuple::new(py, [name.into_pyobject(py)?.into_any(), args.into_any()])?,
    };
    PyTuple::new(py, [restore, call_args.into_any()])
}

/// What `__reduce__` returns for the constructor `name` called with `args` (no keywords).
pub(crate) fn reduce_call<'py>(
    py: Python<'py>,
    name: &str,
    args: Bound<'py, PyTuple>,
) -> PyResult<Bound<'py, PyTuple>> {
    reduce(py, name, args, None)
}

/// A grid `(rows, cols, d)` array of row-major points.
fn grid_array<'py>(
    py: Python<'py>,
    points: &FlatPoints,
    (rows, cols): (usize, usize),
) -> PyResult<Bound<'py, PyAny>> {
    use numpy::PyArrayMethods;
    points
        .to_array(py)?
        .reshape(vec![rows, cols, points.dim])
        .map(Bound::into_any)
}

/// A list of `(k, d)` arrays.
fn array_list<'py>(py: Python<'py>, lists: &[FlatPoints]) -> PyResult<Bound<'py, PyList>> {
    let arrays = lists
        .iter()
        .map(|p| p.to_array(py))
        .collect::<PyResult<Vec<_>>>()?;
    PyList::new(py, arrays)
}

#[pymethods]
impl PyLlCurve {
    /// Pickling: the points, order, closedness, variant and distance.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let args = (
            self.points.to_array(py)?,
            self.order,
            self.closed,
            self.interpolating,
            self.within,
        );
        reduce(py, "LLCurve", args.into_pyobject(py)?, None)
    }
}

#[pymethods]
impl PyLlSurface {
    /// Pickling: the grid, order, closedness, variant and distance.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let grid = grid_array(py, &self.grid, self.shape)?;
        let args = (
            grid,
            self.order,
            self.closed.0,
            self.closed.1,
            self.interpolating,
            self.within,
        );
        reduce(py, "LLSurface", args.into_pyobject(py)?, None)
    }
}

#[pymethods]
impl PyCubicSpline {
    /// Pickling: the points, parameters, parameterization and end conditions.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let (py, this) = (slf.py(), slf.get());
        let t = this
            .t
            .as_ref()
            .map(|t| vector_to_array(py, t))
            .transpose()?;
        let bc: Bound<'py, PyAny> = match &this.ends {
            Ends::Named(name) => name.into_pyobject(py)?.into_any(),
            Ends::Clamped(start, end) => ("clamped", start.clone(), end.clone())
                .into_pyobject(py)?
                .into_any(),
        };
        let args = (
            PyCubicSpline::points_given(slf)?.to_array(py)?,
            t,
            this.parameterization.as_str(),
            bc,
            slf.as_super().get().extrapolate.to_object(py)?,
        );
        reduce(py, "CubicSpline", args.into_pyobject(py)?, None)
    }
}

#[pymethods]
impl PyHermiteSpline {
    /// Pickling: the knots, values and derivatives, and the statistics of the fit.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let (knots, values, derivatives) = self.coefficients();
        let s = self.stats();
        let args = (
            vector_to_array(py, &knots.0)?,
            values.to_array(py)?,
            derivatives.to_array(py)?,
            s.max_distance,
            s.rms_distance,
            s.jump_sum,
            s.tolerance_met,
            vector_to_array(py, &s.parameters)?,
            vector_to_array(py, &s.distances)?,
            s.noise,
            s.warnings,
        );
        reduce(py, "HermiteSpline._from_fit", args.into_pyobject(py)?, None)
    }

    /// The spline of a fit from its coefficients and statistics (what unpickling calls).
    #[staticmethod]
    #[allow(clippy::too_many_arguments)]
    fn _from_fit(
        py: Python<'_>,
        knots: &Bound<'_, PyAny>,
        values: &Bound<'_, PyAny>,
        derivatives: &Bound<'_, PyAny>,
        max_distance: f64,
        rms_distance: f64,
        jump_sum: f64,
        tolerance_met: Option<bool>,
        parameters: Vec<f64>,
        distances: Vec<f64>,
        noise: f64,
        warnings: Vec<String>,
    ) -> PyResult<Py<Self>> {
        let stats = crate::fit::FitStats {
            max_distance,
            rms_distance,
            jump_sum,
            tolerance_met,
            parameters,
            distances,
            noise,
            warnings,
        };
        Py::new(py, Self::build(py, knots, values, derivatives, stats)?)
    }
}

#[pymethods]
impl PyBicubicSurface {
    /// Pickling: the grid, the parameterization or knots, and closedness.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let input = &slf.get().input;
        let grid = grid_array(py, &PyBicubicSurface::grid_given(slf)?, input.shape)?;
        let (cu, cv) = input.closed;
        match &input.how {
            Ok(name) => {
                let args = (grid, name.as_str(), cu, cv, input.origin);
                reduce(py, "BicubicSurface", args.into_pyobject(py)?, None)
            }
            Err((ku, kv)) => {
                let args = (
                    grid,
                    vector_to_array(py, ku)?,
                    vector_to_array(py, kv)?,
                    cu,
                    cv,
                );
                reduce(
                    py,
                    "BicubicSurface.from_knots",
                    args.into_pyobject(py)?,
                    None,
                )
            }
        }
    }
}

#[pymethods]
impl PyDiscreteSpline {
    /// Pickling: the poles (or nodes), order and step.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let (_, _, order, n) = self.parts();
        let args = (self.points.to_array(py)?, order, n);
        let name = if self.interpolating {
            "DiscreteSpline.interpolate"
        } else {
            "DiscreteSpline"
        };
        reduce(py, name, args.into_pyobject(py)?, None)
    }
}

#[pymethods]
impl PyTubeSurface {
    /// Pickling: the skeleton, steps and orders.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let [(a, ar, ac), (b, br, bc)] = &self.skeleton;
        let [n1, n2, r1, r2] = self.counts;
        let args = (
            grid_array(py, a, (*ar, *ac))?,
            grid_array(py, b, (*br, *bc))?,
            n1,
            n2,
            r1,
            r2,
        );
        reduce(py, "TubeSurface", args.into_pyobject(py)?, None)
    }
}

#[pymethods]
impl PyCoonsSurface {
    /// Pickling: the curves, kind, cross-derivatives, curve fit and tolerances.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let input = &this.input;
        let kwargs = PyDict::new(py);
        kwargs.set_item("u_curves", array_list(py, &input.curves.0)?)?;
        kwargs.set_item("v_curves", array_list(py, &input.curves.1)?)?;
        kwargs.set_item("kind", slf.getattr("kind")?)?;
        if let Some((du, dv)) = &input.derivs {
            kwargs.set_item("u_derivs", array_list(py, du)?)?;
            kwargs.set_item("v_derivs", array_list(py, dv)?)?;
        }
        match input.fit {
            karkas::coons::CurveFit::Ll(order) => kwargs.set_item("fit", ("ll", order))?,
            _ => kwargs.set_item("fit", "spline")?,
        }
        if let Some((rows, cols, points)) = &input.twists {
            let grid = points
                .to_array(py)?
                .call_method1("reshape", ((*rows, *cols, points.dim),))?;
            kwargs.set_item("twists", grid)?;
        }
        kwargs.set_item("crossing_tolerance", input.tolerances.0)?;
        kwargs.set_item("tolerance", input.tolerances.1)?;
        reduce(py, "CoonsSurface", PyTuple::empty(py), Some(kwargs))
    }
}

#[pymethods]
impl PySectionCurve {
    /// Pickling: the points, parameters, closedness and length.
    fn __reduce__<'py>(slf: &Bound<'py, Self>) -> PyResult<Bound<'py, PyTuple>> {
        let py = slf.py();
        let this = slf.get();
        let args = (
            slf.getattr("points")?,
            slf.getattr("params")?,
            this.closed,
            this.length,
        );
        reduce(
            py,
            "SectionCurve._from_state",
            args.into_pyobject(py)?,
            None,
        )
    }

    /// A piece of a section from its points (n, d), parameters (n, 2), closedness and length
    /// (what unpickling calls).
    #[staticmethod]
    fn _from_state(
        points: &Bound<'_, PyAny>,
        params: &Bound<'_, PyAny>,
        closed: bool,
        length: f64,
    ) -> PyResult<Self> {
        PySectionCurve::from_parts(points, params, closed, length)
    }
}

#[pymethods]
impl PyImplicitSurface {
    /// Pickling: the expression.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyTuple>> {
        let args = (self.surface.text(),);
        reduce(py, "ImplicitSurface", args.into_pyobject(py)?, None)
    }
}

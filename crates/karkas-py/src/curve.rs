//! The Python base class `Curve`: vectorized evaluation of any karkas curve in 2-D or 3-D.
//!
//! Every concrete curve class (`LLCurve`, `CubicSpline`, `HermiteSpline`, ...) extends it and
//! hands it a [`CurveImpl`].

use std::sync::{Arc, OnceLock};

use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::bspline_form::FlatBSpline;
use crate::convert::{maybe_detach, uniform, vector_to_array, write_flat, Size};
use crate::limits::{bytes_of, check_memory, zeros};
use crate::wrapper::CurveImpl;

/// Base class of every karkas curve: a parametric curve in 2-D or 3-D, called like SciPy's
/// splines.
///
/// Curves are made by the subclasses (``LLCurve``, ``CubicSpline``, ``fit_curve``'s
/// ``HermiteSpline``, ...); ``Curve`` itself has no constructor. ``isinstance(c,
/// karkas.Curve)`` tells any karkas curve.
///
/// Calling a curve, ``c(t, nu=0, out=None, extrapolate=None)``, evaluates it or its
/// ``nu``-th derivative with respect to the parameter.
///
/// Parameters
/// ----------
/// t : float or array_like
///     The parameters. A float gives an array of shape ``(d,)``, an array of any shape an
///     array of shape ``t.shape + (d,)``.
/// nu : int, optional
///     The order of the derivative (0: the points).
/// out : numpy.ndarray, optional
///     A C-contiguous float64 array of the result's shape, written without allocating and
///     returned.
/// extrapolate : bool, optional
///     Parameters outside the domain: a closed curve wraps them by its period; an open curve
///     continues its end polynomial pieces when ``extrapolate`` is None or True (SciPy's
///     rule) and gives NaN when it is False.
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``t.shape + (d,)`` (``out`` when given).
///
/// Raises
/// ------
/// TypeError
///     ``t`` is not a number or an array of numbers; ``out`` is not a C-contiguous float64
///     array.
/// ValueError
///     ``out`` has the wrong shape.
///
/// Examples
/// --------
/// >>> c = karkas.CubicSpline([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]],
/// ...                        parameterization="uniform")
/// >>> isinstance(c, karkas.Curve)
/// True
/// >>> c(1.0)
/// array([1., 1.])
/// >>> c(np.linspace(0.0, 3.0, 7)).shape
/// (7, 2)
/// >>> out = np.empty((4, 2))
/// >>> c(np.arange(4.0), out=out) is out
/// True
#[pyclass(subclass, module = "karkas", name = "Curve", frozen)]
pub struct PyCurve {
    pub inner: Arc<dyn CurveImpl>,
    /// What the object is, for `repr` (e.g. `LLCurve(order=5, closed=False, points=53, dim=2)`).
    pub description: String,
    /// The exact B-spline form, built on first use (by `to_bspline` or by an evaluation
    /// outside the domain).
    pub bspline: OnceLock<karkas::Result<Arc<FlatBSpline>>>,
    /// What a call with `extrapolate=None` does outside the domain (SciPy's `extrapolate` of
    /// a constructor).
    pub extrapolate: Extrapolate,
}

/// What an open curve gives outside its domain when a call does not say
/// (`extrapolate=None`): SciPy's `extrapolate` of `CubicSpline` and `BSpline`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Extrapolate {
    /// The end pieces continued (`None` or `True`).
    #[default]
    Continue,
    /// NaN (`False`).
    Nan,
    /// The parameter wrapped into the domain by its length (`'periodic'`).
    Periodic,
}

impl Extrapolate {
    /// `extrapolate=` of a constructor: None, a bool, or ``'periodic'``.
    pub fn extract(value: Option<&Bound<'_, PyAny>>) -> PyResult<Extrapolate> {
        let Some(value) = value.filter(|v| !v.is_none()) else {
            return Ok(Extrapolate::Continue);
        };
        if let Ok(flag) = value.extract::<bool>() {
            return Ok(if flag {
                Extrapolate::Continue
            } else {
                Extrapolate::Nan
            });
        }
        match value.extract::<String>() {
            Ok(name) if name == "periodic" => Ok(Extrapolate::Periodic),
            _ => Err(crate::errors::OptionError::new_err(format!(
                "extrapolate must be None, True, False or 'periodic', got {}",
                value.repr()?
            ))),
        }
    }

    /// The value `extrapolate=` gave, for pickling (None for the default).
    pub fn to_object<'py>(self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        Ok(match self {
            Extrapolate::Continue => py.None().into_bound(py),
            Extrapolate::Nan => false.into_pyobject(py)?.to_owned().into_any(),
            Extrapolate::Periodic => "periodic".into_pyobject(py)?.into_any(),
        })
    }
}

impl PyCurve {
    /// The base part of a curve object.
    pub fn new(inner: Arc<dyn CurveImpl>, description: String) -> Self {
        PyCurve {
            inner,
            description,
            bspline: OnceLock::new(),
            extrapolate: Extrapolate::Continue,
        }
    }

    /// The curve with `extrapolate` as what a call with `extrapolate=None` does.
    pub fn with_extrapolate(mut self, extrapolate: Extrapolate) -> Self {
        self.extrapolate = extrapolate;
        self
    }

    /// The exact B-spline form (built once).
    pub fn bspline(&self) -> karkas::Result<Arc<FlatBSpline>> {
        self.bspline
            .get_or_init(|| self.inner.to_bspline().map(Arc::new))
            .clone()
    }
}

#[pymethods]
impl PyCurve {
    /// ``n`` points at uniformly spaced parameters over the domain, ends included.
    ///
    /// Parameters
    /// ----------
    /// n : int
    ///     The number of points.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(n, d)``: the curve at ``np.linspace(a, b, n)``, ``(a, b) =
    ///     c.domain``.
    ///
    /// Raises
    /// ------
    /// OverflowError
    ///     ``n`` is negative.
    /// MemoryError
    ///     The result does not fit in memory.
    ///
    /// Examples
    /// --------
    /// >>> c = karkas.LLCurve([[0.0, 0.0], [1.0, 2.0], [2.0, 0.0], [3.0, 2.0]], order=3)
    /// >>> p = c.sample(5)
    /// >>> p.shape
    /// (5, 2)
    /// >>> bool(np.allclose(p, c(np.linspace(*c.domain, 5))))
    /// True
    fn sample<'py>(&self, py: Python<'py>, n: Size) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let n = n.0;
        let d = self.inner.dim();
        // The parameters and the points.
        check_memory(py, &format!("Curve.sample({n})"), bytes_of(&[n, d + 1], 8))?;
        let ts = uniform(self.inner.domain(), n);
        let array = zeros(py, &[n, d])?;
        let inner = &self.inner;
        write_flat(&array, |flat| {
            maybe_detach(py, n, || inner.eval_flat(&ts, 0, flat))
        })?;
        Ok(array)
    }

    /// The parameter domain ``(a, b)``: where the curve is defined by its pieces.
    #[getter]
    fn domain(&self) -> (f64, f64) {
        self.inner.domain()
    }

    /// The dimension ``d`` of the points (2 or 3).
    #[getter]
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    /// True when the curve is closed (parameters wrap by the period ``b - a``).
    #[getter]
    fn closed(&self) -> bool {
        self.inner.closed()
    }

    /// The parameters where the polynomial pieces meet, ends included, float64 ``(m,)``.
    #[getter]
    fn breakpoints<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        vector_to_array(py, &self.inner.breakpoints())
    }

    /// The order of continuity ``k`` at the breakpoints (the curve is C^k).
    #[getter]
    fn continuity(&self) -> usize {
        self.inner.continuity()
    }

    fn __repr__(&self) -> String {
        let (a, b) = self.inner.domain();
        format!("{}, domain=({a}, {b})>", self.description)
    }
}

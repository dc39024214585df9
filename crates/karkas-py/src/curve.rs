//! The Python base class `Curve`: vectorized evaluation of any karkas curve in 2-D or 3-D.
//!
//! Every concrete curve class (`LLCurve`, `CubicSpline`, `HermiteSpline`, ...) extends it and
//! hands it a [`CurveImpl`].

use std::sync::{Arc, OnceLock};

use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::bspline_form::FlatBSpline;
use crate::convert::{maybe_detach, uniform, vector_to_array, write_flat};
use crate::wrapper::CurveImpl;

/// Base class of every karkas curve.
///
/// Calling a curve evaluates it, as SciPy's ``BSpline``: ``c(t, nu=0, out=None,
/// extrapolate=None)`` with a float ``t`` gives an array of shape ``(d,)``, with an array of any
/// shape an array of shape ``t.shape + (d,)``; ``nu`` is the order of the derivative with
/// respect to the parameter. ``out=`` takes a preallocated C-contiguous float64 array of that
/// shape and writes into it without allocating (it is returned). ``c.derivative(nu)`` is the
/// derivative as a curve object, ``c.to_bspline()`` the exact B-spline form ``(t, c, k)``.
///
/// Parameters outside the domain (the same rule for every curve class): a closed curve wraps
/// them by its period; an open curve continues its end polynomial pieces when
/// ``extrapolate`` is None or True (SciPy's ``BSpline`` rule, the values of
/// ``scipy.interpolate.BSpline(*c.to_bspline())``) and gives NaN when ``extrapolate=False``.
#[pyclass(subclass, module = "karkas", name = "Curve", frozen)]
pub struct PyCurve {
    pub inner: Arc<dyn CurveImpl>,
    /// What the object is, for `repr` (e.g. `LLCurve(order=5, closed=False, points=53, dim=2)`).
    pub description: String,
    /// The exact B-spline form, built on first use (by `to_bspline` or by an evaluation
    /// outside the domain).
    pub bspline: OnceLock<karkas::Result<Arc<FlatBSpline>>>,
}

impl PyCurve {
    /// The base part of a curve object.
    pub fn new(inner: Arc<dyn CurveImpl>, description: String) -> Self {
        PyCurve {
            inner,
            description,
            bspline: OnceLock::new(),
        }
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
    /// c.sample(n): `n` points at uniformly spaced parameters over the domain, shape (n, d).
    fn sample<'py>(&self, py: Python<'py>, n: usize) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let ts = uniform(self.inner.domain(), n);
        let array = PyArrayDyn::<f64>::zeros(py, &[n, self.inner.dim()][..], false);
        let inner = &self.inner;
        write_flat(&array, |flat| {
            maybe_detach(py, n, || inner.eval_flat(&ts, 0, flat))
        })?;
        Ok(array)
    }

    /// The parameter domain (a, b).
    #[getter]
    fn domain(&self) -> (f64, f64) {
        self.inner.domain()
    }

    /// The dimension d (2 or 3).
    #[getter]
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    /// True when the curve is closed (evaluation wraps by the period).
    #[getter]
    fn closed(&self) -> bool {
        self.inner.closed()
    }

    /// The parameters where the polynomial pieces meet, ends included.
    #[getter]
    fn breakpoints<'py>(&self, py: Python<'py>) -> Bound<'py, PyArrayDyn<f64>> {
        vector_to_array(py, &self.inner.breakpoints())
    }

    /// The order of continuity at the breakpoints (C^k).
    #[getter]
    fn continuity(&self) -> usize {
        self.inner.continuity()
    }

    fn __repr__(&self) -> String {
        let (a, b) = self.inner.domain();
        format!("{}, domain=({a}, {b})>", self.description)
    }
}

//! The Python base class `Curve`: vectorized evaluation of any karkas curve in 2-D or 3-D.
//!
//! Every concrete curve class (`LLCurve`, `CubicSpline`, `HermiteSpline`, ...) extends it and
//! hands it a [`CurveImpl`].

use std::sync::Arc;

use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    maybe_detach, output_array, uniform, vector_to_array, write_flat, Params, Size,
};
use crate::limits::{bytes_of, check_memory, zeros};
use crate::wrapper::CurveImpl;

/// Base class of every karkas curve.
///
/// Calling a curve evaluates it: `c(t)` with a float `t` gives an array of shape `(d,)`, with an
/// array of any shape an array of shape `t.shape + (d,)`. `out=` takes a preallocated
/// C-contiguous float64 array of that shape and writes into it without allocating (it is
/// returned). Parameters outside the domain are clamped (open curves, except cubic splines,
/// which extend their end pieces) or wrapped (closed curves).
#[pyclass(subclass, module = "karkas", name = "Curve", frozen)]
pub struct PyCurve {
    pub inner: Arc<dyn CurveImpl>,
    /// What the object is, for `repr` (e.g. `LLCurve(order=5, closed=False, points=53, dim=2)`).
    pub description: String,
}

impl PyCurve {
    /// The base part of a curve object.
    pub fn new(inner: Arc<dyn CurveImpl>, description: String) -> Self {
        PyCurve { inner, description }
    }
}

#[pymethods]
impl PyCurve {
    /// c(t, out=None): the curve at `t` (float -> (d,), array -> t.shape + (d,)).
    #[pyo3(signature = (t, out = None))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        out: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.derivative(py, t, 0, out)
    }

    /// c.derivative(t, k=1, out=None): the k-th derivative with respect to the parameter.
    #[pyo3(signature = (t, k = 1, out = None))]
    fn derivative<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        k: usize,
        out: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let params = Params::extract(t, "t")?;
        let mut shape = params.shape();
        shape.push(self.inner.dim());
        let array = output_array(py, out, &shape)?;
        let ts = params.flat();
        let inner = &self.inner;
        write_flat(&array, |flat| {
            maybe_detach(py, ts.len(), || inner.eval_flat(&ts, k, flat))
        })?;
        Ok(array)
    }

    /// c.sample(n): `n` points at uniformly spaced parameters over the domain, shape (n, d).
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
    fn breakpoints<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
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

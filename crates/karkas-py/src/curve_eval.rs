//! SciPy's conventions on the base class `Curve`: `c(t, nu=0, out=None, extrapolate=None)`,
//! `c.derivative(nu=1)` as a curve object (the class `CurveDerivative`) and
//! `c.to_bspline() -> (t, c, k)` for `scipy.interpolate.BSpline`.
//!
//! Inside the domain the library evaluates as before (one batch call, no per-point work but a
//! range check); the parameters of an open curve outside the domain are then rewritten with
//! the exact B-spline form's end pieces continued ([`crate::bspline_form`]), or NaN.

use std::sync::Arc;

use numpy::{PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;

use crate::bspline_form::FlatBSpline;
use crate::convert::{count, maybe_detach, output_array, vector_to_array, write_flat, Params};
use crate::curve::{Extrapolate, PyCurve};
use crate::errors::library_error;
use crate::wrapper::CurveImpl;

/// Rewrites the values at the parameters of `ts` outside `[a, b]` in `flat` (`dim` values
/// each): NaN when `extrapolate` is false, else the `nu`-th derivative of the end pieces of
/// `form` continued.
pub fn extend_outside(
    ts: &[f64],
    (a, b): (f64, f64),
    nu: usize,
    extrapolate: bool,
    dim: usize,
    flat: &mut [f64],
    form: impl FnOnce() -> karkas::Result<Arc<FlatBSpline>>,
) -> karkas::Result<()> {
    if !any_outside(ts, (a, b)) {
        return Ok(());
    }
    let mut outside = ts
        .iter()
        .enumerate()
        .filter(|(_, &t)| t < a || t > b)
        .map(|(i, _)| i)
        .peekable();
    if outside.peek().is_none() {
        return Ok(());
    }
    if !extrapolate {
        for i in outside {
            flat[i * dim..(i + 1) * dim].fill(f64::NAN);
        }
        return Ok(());
    }
    let spline = form()?.derivative(nu);
    for i in outside {
        spline.eval_into(ts[i], &mut flat[i * dim..(i + 1) * dim]);
    }
    Ok(())
}

/// True when a parameter of `ts` lies outside `[a, b]` (NaN does not): one branch-free pass
/// per block of parameters, which the compiler vectorizes, stopping at the first block with
/// one (a search by index, with its branch per parameter, took a third of the time of the
/// evaluation it follows).
fn any_outside(ts: &[f64], (a, b): (f64, f64)) -> bool {
    ts.chunks(1024).any(|block| {
        block
            .iter()
            .fold(false, |found, &t| found | (t < a) | (t > b))
    })
}

/// The `nu`-th derivative of a curve, as a curve.
pub(crate) struct DerivativeCurve {
    pub(crate) parent: Arc<dyn CurveImpl>,
    pub(crate) nu: usize,
}

impl CurveImpl for DerivativeCurve {
    fn dim(&self) -> usize {
        self.parent.dim()
    }
    fn domain(&self) -> (f64, f64) {
        self.parent.domain()
    }
    fn closed(&self) -> bool {
        self.parent.closed()
    }
    fn breakpoints(&self) -> Vec<f64> {
        self.parent.breakpoints()
    }
    fn continuity(&self) -> usize {
        self.parent.continuity().saturating_sub(self.nu)
    }
    fn eval_flat(&self, ts: &[f64], k: usize, out: &mut [f64]) {
        self.parent.eval_flat(ts, k + self.nu, out);
    }
    fn to_bspline(&self) -> karkas::Result<FlatBSpline> {
        Ok(self.parent.to_bspline()?.derivative(self.nu))
    }
}

/// The derivative of a curve as a curve object, as returned by ``Curve.derivative``.
///
/// ``d = c.derivative(nu)`` evaluates ``d(t, k) == c(t, nu + k)``; its domain, closed flag
/// and breakpoints are the curve's, its continuity ``max(c.continuity - nu, 0)``;
/// ``d.to_bspline()`` is the derivative of the curve's B-spline form (degree reduced by
/// ``nu``, down to 0). Parameters outside the domain follow the rule of ``Curve``: a closed
/// curve wraps them by its period; an open curve continues its end polynomial pieces when
/// ``extrapolate`` is None or True and gives NaN when ``extrapolate=False``. It pickles as
/// ``parent.derivative(nu)``.
///
/// Examples
/// --------
/// >>> import numpy as np, karkas
/// >>> c = karkas.CubicSpline(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]]))
/// >>> d = c.derivative()
/// >>> bool(np.allclose(d(0.4), c(0.4, 1)))
/// True
#[pyclass(extends = PyCurve, module = "karkas", name = "CurveDerivative", frozen)]
pub struct PyCurveDerivative {
    /// The curve this is a derivative of.
    #[pyo3(get)]
    parent: Py<PyCurve>,
    /// The order of the derivative.
    #[pyo3(get)]
    nu: usize,
}

#[pymethods]
impl PyCurveDerivative {
    /// Pickles as ``(parent.derivative, (nu,))``.
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (usize,))> {
        Ok((self.parent.bind(py).getattr("derivative")?, (self.nu,)))
    }
}

#[pymethods]
impl PyCurve {
    /// The curve or its derivative at ``t``.
    ///
    /// Parameters
    /// ----------
    /// t : float or array_like
    ///     Parameters, any shape.
    /// nu : int, optional
    ///     The order of the derivative with respect to the parameter (0: the points).
    /// out : numpy.ndarray, optional
    ///     A C-contiguous float64 array of shape ``t.shape + (d,)`` to write into.
    /// extrapolate : bool, optional
    ///     For an open curve, parameters outside the domain continue the end polynomial
    ///     pieces when None (the default) or True, and give NaN when False. A closed curve
    ///     always wraps them by its period.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     Shape ``t.shape + (d,)`` (``(d,)`` for a float); ``out`` when given.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     A negative ``nu``.
    /// KarkasError
    ///     An ``out`` that is not a C-contiguous writeable float64 array of the right shape.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> c = karkas.CubicSpline(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]))
    /// >>> c(0.5, 1).shape
    /// (2,)
    /// >>> bool(np.isnan(c(-1.0, extrapolate=False)).all())
    /// True
    #[pyo3(signature = (t, nu = 0, out = None, extrapolate = None))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        t: &Bound<'py, PyAny>,
        nu: i64,
        out: Option<Bound<'py, PyAny>>,
        extrapolate: Option<bool>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let nu = count(nu, "nu")?;
        let params = Params::extract(t, "t")?;
        let dim = self.inner.dim();
        let mut shape = params.shape();
        shape.push(dim);
        let array = output_array(py, out, &shape)?;
        let inner = &self.inner;
        let closed = inner.closed();
        let domain = inner.domain();
        let rule = match extrapolate {
            Some(true) => Extrapolate::Continue,
            Some(false) => Extrapolate::Nan,
            None => self.extrapolate,
        };
        let mut ts = params.flat();
        if rule == Extrapolate::Periodic && !closed {
            // SciPy's rule: every parameter wrapped, the domain's end to its start.
            let (a, b) = domain;
            let wrap = karkas::Interval::new(a, b);
            ts = std::borrow::Cow::Owned(ts.iter().map(|&t| wrap.wrap(t)).collect());
        }
        write_flat(&array, |flat| {
            maybe_detach(py, ts.len(), || {
                inner.eval_flat(&ts, nu, flat);
                if closed {
                    return Ok(());
                }
                let extrapolate = rule != Extrapolate::Nan;
                if extrapolate && inner.extrapolates() {
                    return Ok(());
                }
                extend_outside(&ts, domain, nu, extrapolate, dim, flat, || self.bspline())
            })
        })?
        .map_err(library_error)?;
        Ok(array)
    }

    /// The ``nu``-th derivative as a curve object (SciPy's ``BSpline.derivative``).
    ///
    /// Parameters
    /// ----------
    /// nu : int, optional
    ///     The order of the derivative (default 1).
    ///
    /// Returns
    /// -------
    /// CurveDerivative
    ///     A curve whose value at ``t`` is ``self(t, nu)``.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     A negative ``nu``.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> c = karkas.CubicSpline(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0]]))
    /// >>> d2 = c.derivative(2)
    /// >>> bool(np.allclose(d2(0.3), c(0.3, 2)))
    /// True
    #[pyo3(signature = (nu = 1))]
    fn derivative(slf: &Bound<'_, Self>, nu: i64) -> PyResult<Py<PyCurveDerivative>> {
        let nu = count(nu, "nu")?;
        let base = slf.get();
        let inner: Arc<dyn CurveImpl> = Arc::new(DerivativeCurve {
            parent: base.inner.clone(),
            nu,
        });
        let of = base
            .description
            .strip_prefix("<karkas.")
            .unwrap_or(&base.description);
        let description = format!("<karkas.CurveDerivative nu={nu} of {of}");
        Py::new(
            slf.py(),
            PyClassInitializer::from(
                PyCurve::new(inner, description).with_extrapolate(base.extrapolate),
            )
            .add_subclass(PyCurveDerivative {
                parent: slf.clone().unbind(),
                nu,
            }),
        )
    }

    /// The exact B-spline form ``(t, c, k)`` in the curve's own parameter.
    ///
    /// ``scipy.interpolate.BSpline(*c.to_bspline())`` equals the curve on its domain to
    /// rounding (and continues it as the curve does outside an open curve's domain). A
    /// closed curve is given over one period as a clamped B-spline whose ends coincide.
    ///
    /// Returns
    /// -------
    /// t : numpy.ndarray
    ///     The clamped knot vector, shape ``(n + k + 1,)``.
    /// c : numpy.ndarray
    ///     The coefficients (control points), shape ``(n, d)``.
    /// k : int
    ///     The degree.
    ///
    /// Raises
    /// ------
    /// NoBSplineFormError
    ///     A curve that is not a piecewise polynomial of its parameter.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> from scipy.interpolate import BSpline
    /// >>> c = karkas.CubicSpline(np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 2.0]]))
    /// >>> t, coefs, k = c.to_bspline()
    /// >>> k
    /// 3
    /// >>> bool(np.allclose(BSpline(t, coefs, k)(0.7), c(0.7), atol=1e-12))
    /// True
    #[allow(clippy::type_complexity)]
    fn to_bspline<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(
        Bound<'py, PyArrayDyn<f64>>,
        Bound<'py, PyArrayDyn<f64>>,
        usize,
    )> {
        let form = self.bspline().map_err(library_error)?;
        let knots = vector_to_array(py, &form.knots)?;
        let coefs = vector_to_array(py, &form.coefs)?.reshape(vec![form.count(), form.dim])?;
        Ok((knots, coefs, form.degree))
    }
}

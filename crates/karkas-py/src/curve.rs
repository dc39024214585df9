//! The Python base class `Curve`: vectorized evaluation of any karkas curve in 2-D or 3-D.
//!
//! Every concrete curve class (`LLCurve`, `CubicSpline`, `HermiteSpline`, ...) extends it and
//! hands it a [`CurveImpl`].
//!
//! SciPy's conventions on the base class `Curve`: `c(t, nu=0, out=None, extrapolate=None)`,
//! `c.derivative(nu=1)` as a curve object (the class `CurveDerivative`) and
//! `c.to_bspline() -> (t, c, k)` for `scipy.interpolate.BSpline`.
//!
//! Inside the domain the library evaluates as before (one batch call, no per-point work but a
//! range check); the parameters of an open curve outside the domain are then rewritten with
//! the exact B-spline form's end pieces continued ([`crate::bspline`]), or NaN.

use std::sync::{Arc, OnceLock};

use numpy::{PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;

use crate::bspline::FlatBSpline;
use crate::convert::{
    count, maybe_detach, output_array, uniform, vector_to_array, write_flat, Params, Size,
};
use crate::erased::CurveImpl;
use crate::errors::library_error;
use crate::limits::{bytes_of, check_memory, zeros};

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

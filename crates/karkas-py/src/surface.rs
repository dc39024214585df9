//! The Python base class `Surface`: grid and pointwise evaluation of any karkas surface.
//!
//! Every concrete surface class (`LLSurface`, `BicubicSurface`, `CoonsSurface`) extends it and
//! hands it a [`SurfaceImpl`].
//!
//! SciPy's conventions on the base class `Surface`: `S(u, v, du=0, dv=0, grid=True, out=None,
//! extrapolate=None)` (`RectBivariateSpline`'s names), `S.derivative(du=1, dv=0)` as a surface
//! object (the class `SurfaceDerivative`) and `S.to_bspline() -> ((tu, tv), c, (ku, kv))` for
//! `scipy.interpolate.NdBSpline`.
//!
//! Inside the domain the library evaluates as before; the parameters outside it in an open
//! direction are then rewritten with the exact B-spline form's end pieces continued
//! ([`crate::bspline`]), or NaN; a closed direction wraps by its period.

use std::sync::{Arc, OnceLock};

use karkas::implicit::ExpressionSurface;
use karkas::measure::Hausdorff;
use karkas::section::SectionOptions;
use karkas::{Interval, Point3};
use numpy::{PyArrayDyn, PyArrayMethods};
use pyo3::prelude::*;

use crate::bspline::FlatBSplineSurface;
use crate::convert::{
    count, maybe_detach, output_array, small_vector, uniform, vector_to_array, write_flat, Params,
    Size,
};
use crate::erased::SurfaceImpl;
use crate::errors::{library_error, KarkasError, OptionError};
use crate::limits::{bytes_of, check_memory, zeros};
use crate::section::PySectionCurve;

/// Base class of every karkas surface: a parametric surface in 2-D or 3-D, called like SciPy's
/// RectBivariateSpline.
///
/// Surfaces are made by the subclasses (``LLSurface``, ``BicubicSurface``,
/// ``CoonsSurface``); ``Surface`` itself has no constructor.
///
/// Calling a surface, ``S(u, v, du=0, dv=0, grid=True, out=None, extrapolate=None)``,
/// evaluates it or its partial derivative ``d^(du+dv) S / du^du dv^dv``.
///
/// Parameters
/// ----------
/// u, v : float or array_like
///     The parameters. With ``grid=True``, floats or 1-D arrays ``(mu,)`` and ``(mv,)``: the
///     grid ``u x v``, ``u`` outer; with ``grid=False``, arrays of one shape: the pairs
///     ``(u[i], v[i])``.
/// du, dv : int, optional
///     The orders of the partial derivative in ``u`` and ``v`` (0, 0: the points).
/// grid : bool, optional
///     Evaluate on the grid ``u x v`` (True) or at the pairs (False).
/// out : numpy.ndarray, optional
///     A C-contiguous float64 array of the result's shape, written without allocating and
///     returned.
/// extrapolate : bool, optional
///     Parameters outside a direction's domain: a closed direction wraps them by its period;
///     an open one continues its end pieces when ``extrapolate`` is None or True and gives
///     NaN when it is False.
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(mu, mv, d)`` with ``grid=True`` (a float counts as no axis),
///     ``u.shape + (d,)`` with ``grid=False``.
///
/// Raises
/// ------
/// TypeError
///     ``u`` or ``v`` is not a number or an array of numbers; ``out`` is not a C-contiguous
///     float64 array.
/// ValueError
///     ``u`` and ``v`` of different shapes with ``grid=False``, arrays of more than one axis
///     with ``grid=True``, or ``out`` of the wrong shape.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, i * j] for j in range(4)] for i in range(3)], float)
/// >>> S = karkas.BicubicSurface(grid, parameterization="uniform")
/// >>> isinstance(S, karkas.Surface)
/// True
/// >>> S(1.0, 2.0)
/// array([1., 2., 2.])
/// >>> S(np.linspace(0, 2, 5), np.linspace(0, 3, 7)).shape
/// (5, 7, 3)
/// >>> S([0.0, 2.0], [0.0, 3.0], grid=False)
/// array([[0., 0., 0.],
///        [2., 3., 6.]])
#[pyclass(subclass, module = "karkas", name = "Surface", frozen)]
pub struct PySurface {
    pub inner: Arc<dyn SurfaceImpl>,
    /// What the object is, for `repr`.
    pub description: String,
    /// The exact B-spline form, built on first use (by `to_bspline` or by an evaluation
    /// outside the domain).
    pub bspline: OnceLock<karkas::Result<Arc<FlatBSplineSurface>>>,
}

impl PySurface {
    /// The base part of a surface object.
    pub fn new(inner: Arc<dyn SurfaceImpl>, description: String) -> Self {
        PySurface {
            inner,
            description,
            bspline: OnceLock::new(),
        }
    }

    /// The exact B-spline form (built once).
    pub fn bspline(&self) -> karkas::Result<Arc<FlatBSplineSurface>> {
        self.bspline
            .get_or_init(|| self.inner.to_bspline().map(Arc::new))
            .clone()
    }
}

#[pymethods]
impl PySurface {
    /// The points at ``nu x nv`` uniformly spaced parameters over the domain, ends included.
    ///
    /// Parameters
    /// ----------
    /// nu, nv : int
    ///     The numbers of parameters in ``u`` and in ``v``.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     float64, shape ``(nu, nv, d)``: the surface on ``np.linspace(*S.domain_u, nu) x
    ///     np.linspace(*S.domain_v, nv)``.
    ///
    /// Raises
    /// ------
    /// OverflowError
    ///     ``nu`` or ``nv`` is negative.
    /// MemoryError
    ///     The result does not fit in memory.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, i * j] for j in range(4)] for i in range(3)], float)
    /// >>> S = karkas.BicubicSurface(grid, parameterization="uniform")
    /// >>> S.sample(3, 4).shape
    /// (3, 4, 3)
    /// >>> bool(np.allclose(S.sample(3, 4), grid))
    /// True
    fn sample<'py>(
        &self,
        py: Python<'py>,
        nu: Size,
        nv: Size,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (nu, nv) = (nu.0, nv.0);
        let d = self.inner.dim();
        // The parameters and the points.
        let bytes = bytes_of(&[nu, nv, d], 8).saturating_add(bytes_of(&[nu.saturating_add(nv)], 8));
        check_memory(py, &format!("Surface.sample({nu}, {nv})"), bytes)?;
        let us = uniform(self.inner.domain_u(), nu);
        let vs = uniform(self.inner.domain_v(), nv);
        let array = zeros(py, &[nu, nv, d])?;
        let inner = &self.inner;
        write_flat(&array, |flat| {
            maybe_detach(py, nu * nv, || inner.grid_flat(&us, &vs, 0, 0, flat))
        })?;
        Ok(array)
    }

    /// Where the plane ``normal . x = offset`` cuts the surface, as polylines on it.
    ///
    /// The cut is found on a ``cells`` grid of the parameter domain and traced by a
    /// predictor-corrector continuation; pieces smaller than a cell may be missed.
    ///
    /// Parameters
    /// ----------
    /// normal : sequence of float
    ///     The plane's normal, ``d`` coordinates (need not be a unit vector).
    /// offset : float
    ///     The plane is ``normal . x = offset``.
    /// tolerance : float, optional
    ///     The largest chord error of the polylines; None: 1e-4 of the diagonal of the
    ///     surface's bounding box.
    /// cells : tuple of int, optional
    ///     The ``(nu, nv)`` cells of the search grid (64 x 64 when not given).
    ///
    /// Returns
    /// -------
    /// list of SectionCurve
    ///     The connected pieces of the section (empty when the plane misses the surface).
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     ``normal`` has the wrong number of coordinates or is zero, or ``tolerance`` or
    ///     ``cells`` is out of range.
    /// ConvergenceError
    ///     The continuation could not follow the section.
    ///
    /// Examples
    /// --------
    /// >>> grid = np.array([[[i, j, i * j] for j in range(4)] for i in range(3)], float)
    /// >>> S = karkas.BicubicSurface(grid, parameterization="uniform")
    /// >>> pieces = S.section([1.0, 0.0, 0.0], 1.0)
    /// >>> len(pieces)
    /// 1
    /// >>> bool(np.allclose(pieces[0].points[:, 0], 1.0))
    /// True
    /// >>> round(pieces[0].length, 6)
    /// 4.242641
    #[pyo3(signature = (normal, offset, tolerance = None, cells = (64, 64)))]
    #[pyo3(text_signature = "($self, normal, offset, tolerance=None, cells=(64, 64))")]
    fn section(
        &self,
        py: Python<'_>,
        normal: &Bound<'_, PyAny>,
        offset: f64,
        tolerance: Option<f64>,
        cells: (usize, usize),
    ) -> PyResult<Vec<PySectionCurve>> {
        let d = self.inner.dim();
        let normal = small_vector(normal, "normal")?;
        if normal.len() != d {
            return Err(OptionError::new_err(format!(
                "normal must have {d} coordinates (got {})",
                normal.len()
            )));
        }
        // The coarse grid of samples (points and plane values) and the traced polylines.
        let grid = [cells.0.saturating_add(1), cells.1.saturating_add(1), d + 1];
        check_memory(
            py,
            &format!("Surface.section(cells=({}, {}))", cells.0, cells.1),
            bytes_of(&grid, 16),
        )?;
        let options = SectionOptions {
            tolerance,
            cells,
            ..SectionOptions::default()
        };
        let inner = &self.inner;
        py.detach(|| inner.section(&normal, offset, &options))
            .map_err(library_error)
    }

    /// The ``u`` domain ``(a, b)``.
    #[getter]
    fn domain_u(&self) -> (f64, f64) {
        self.inner.domain_u()
    }

    /// The ``v`` domain ``(a, b)``.
    #[getter]
    fn domain_v(&self) -> (f64, f64) {
        self.inner.domain_v()
    }

    /// The dimension ``d`` of the points (2 or 3).
    #[getter]
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    /// True when the surface is closed in ``u`` (``u`` wraps by its period).
    #[getter]
    fn closed_u(&self) -> bool {
        self.inner.closed().0
    }

    /// True when the surface is closed in ``v`` (``v`` wraps by its period).
    #[getter]
    fn closed_v(&self) -> bool {
        self.inner.closed().1
    }

    fn __repr__(&self) -> String {
        let (a, b) = self.inner.domain_u();
        let (c, d) = self.inner.domain_v();
        format!(
            "{}, domain_u=({a}, {b}), domain_v=({c}, {d})>",
            self.description
        )
    }
}

/// Where a surface is evaluated and how values outside its domain are made.
struct Outside {
    domain_u: Interval,
    domain_v: Interval,
    closed: (bool, bool),
    derivative: (usize, usize),
    extrapolate: bool,
    dim: usize,
}

impl Outside {
    /// True when `u` lies outside an open u direction.
    fn out_u(&self, u: f64) -> bool {
        !self.closed.0 && (u < self.domain_u.start || u > self.domain_u.end)
    }

    /// True when `v` lies outside an open v direction.
    fn out_v(&self, v: f64) -> bool {
        !self.closed.1 && (v < self.domain_v.start || v > self.domain_v.end)
    }

    /// Rewrites the values of `flat` whose parameters lie outside an open direction: NaN or
    /// the end pieces of `form` continued (closed directions wrapped).
    fn extend(
        &self,
        us: &[f64],
        vs: &[f64],
        grid: bool,
        flat: &mut [f64],
        form: impl FnOnce() -> karkas::Result<Arc<FlatBSplineSurface>>,
    ) -> karkas::Result<()> {
        let any_u = us.iter().any(|&u| self.out_u(u));
        let any_v = vs.iter().any(|&v| self.out_v(v));
        if !any_u && !any_v {
            return Ok(());
        }
        let outside: Vec<(usize, f64, f64)> = if grid {
            let mv = vs.len();
            us.iter()
                .enumerate()
                .flat_map(|(i, &u)| vs.iter().enumerate().map(move |(j, &v)| (i * mv + j, u, v)))
                .filter(|&(_, u, v)| self.out_u(u) || self.out_v(v))
                .collect()
        } else {
            us.iter()
                .zip(vs)
                .enumerate()
                .map(|(k, (&u, &v))| (k, u, v))
                .filter(|&(_, u, v)| self.out_u(u) || self.out_v(v))
                .collect()
        };
        let d = self.dim;
        if !self.extrapolate {
            for (k, _, _) in outside {
                flat[k * d..(k + 1) * d].fill(f64::NAN);
            }
            return Ok(());
        }
        let spline = form()?.derivative(self.derivative.0, self.derivative.1);
        for (k, u, v) in outside {
            let u = if self.closed.0 {
                self.domain_u.wrap(u)
            } else {
                u
            };
            let v = if self.closed.1 {
                self.domain_v.wrap(v)
            } else {
                v
            };
            spline.eval_into(u, v, &mut flat[k * d..(k + 1) * d]);
        }
        Ok(())
    }
}

/// The partial derivative of a surface, as a surface.
pub(crate) struct DerivativeSurface {
    pub(crate) parent: Arc<dyn SurfaceImpl>,
    pub(crate) du: usize,
    pub(crate) dv: usize,
}

/// The error of what a derivative surface does not do.
fn not_for_derivatives() -> karkas::Error {
    karkas::Error::InvalidSetting {
        name: "derivative surface",
        value: f64::NAN,
        reason: "sections and distances are computed on surfaces, not on their derivatives",
    }
}

impl SurfaceImpl for DerivativeSurface {
    fn dim(&self) -> usize {
        self.parent.dim()
    }
    fn domain_u(&self) -> (f64, f64) {
        self.parent.domain_u()
    }
    fn domain_v(&self) -> (f64, f64) {
        self.parent.domain_v()
    }
    fn closed(&self) -> (bool, bool) {
        self.parent.closed()
    }
    fn grid_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]) {
        self.parent
            .grid_flat(us, vs, ku + self.du, kv + self.dv, out);
    }
    fn points_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]) {
        self.parent
            .points_flat(us, vs, ku + self.du, kv + self.dv, out);
    }
    fn to_bspline(&self) -> karkas::Result<FlatBSplineSurface> {
        Ok(self.parent.to_bspline()?.derivative(self.du, self.dv))
    }
    fn section(
        &self,
        _normal: &[f64],
        _offset: f64,
        _options: &SectionOptions,
    ) -> karkas::Result<Vec<PySectionCurve>> {
        Err(not_for_derivatives())
    }
    fn hausdorff_implicit(
        &self,
        _implicit: &ExpressionSurface,
        _patch: &[Point3],
        _samples: (usize, usize),
    ) -> karkas::Result<Hausdorff> {
        Err(not_for_derivatives())
    }
}

/// A partial derivative of a surface as a surface object, as returned by
/// ``Surface.derivative``.
///
/// ``D = S.derivative(du, dv)`` evaluates ``D(u, v, a, b) == S(u, v, du + a, dv + b)``; its
/// domains and closed flags are the surface's; ``D.to_bspline()`` is the derivative of the
/// surface's B-spline form. Parameters outside the domain follow the rule of ``Surface``
/// per direction (closed: wrapped; open: end pieces continued when ``extrapolate`` is None
/// or True, NaN when False). It pickles as ``parent.derivative(du, dv)``.
///
/// Examples
/// --------
/// >>> import numpy as np, karkas
/// >>> g = np.array([[[i, j, i * j] for j in range(4)] for i in range(4)], float)
/// >>> S = karkas.BicubicSurface(g)
/// >>> D = S.derivative(1, 1)
/// >>> bool(np.allclose(D(0.3, 0.6), S(0.3, 0.6, 1, 1)))
/// True
#[pyclass(extends = PySurface, module = "karkas", name = "SurfaceDerivative", frozen)]
pub struct PySurfaceDerivative {
    /// The surface this is a derivative of.
    #[pyo3(get)]
    parent: Py<PySurface>,
    /// The order of the derivative in u.
    #[pyo3(get)]
    du: usize,
    /// The order of the derivative in v.
    #[pyo3(get)]
    dv: usize,
}

#[pymethods]
impl PySurfaceDerivative {
    /// Pickles as ``(parent.derivative, (du, dv))``.
    #[allow(clippy::type_complexity)]
    fn __reduce__<'py>(&self, py: Python<'py>) -> PyResult<(Bound<'py, PyAny>, (usize, usize))> {
        Ok((
            self.parent.bind(py).getattr("derivative")?,
            (self.du, self.dv),
        ))
    }
}

/// The shape of `S(u, v, grid=...)`'s result.
fn result_shape(su: Vec<usize>, sv: Vec<usize>, grid: bool, d: usize) -> PyResult<Vec<usize>> {
    if grid {
        if su.len() > 1 || sv.len() > 1 {
            return Err(KarkasError::new_err(
                "with grid=True, u and v must be floats or 1-D arrays",
            ));
        }
        let mut s = su;
        s.extend(&sv);
        s.push(d);
        Ok(s)
    } else {
        if su != sv {
            return Err(KarkasError::new_err(format!(
                "with grid=False, u and v must have one shape (got {su:?} and {sv:?})"
            )));
        }
        let mut s = su;
        s.push(d);
        Ok(s)
    }
}

/// The orders `(du, dv)`, or `RectBivariateSpline`'s `dx`, `dy` in their place (one name of
/// each); an `OptionError` for both names or a negative order.
fn scipy_orders(
    (du, dv): (i64, i64),
    (dx, dy): (Option<i64>, Option<i64>),
) -> PyResult<(usize, usize)> {
    let pick = |ours: i64, theirs: Option<i64>, names: &str| match theirs {
        Some(_) if ours != 0 => Err(crate::errors::OptionError::new_err(format!(
            "{names}: give the order once (du and dx, dv and dy are the same order)"
        ))),
        Some(order) => Ok(order),
        None => Ok(ours),
    };
    let du = pick(du, dx, "du, dx")?;
    let dv = pick(dv, dy, "dv, dy")?;
    Ok((count(du, "du")?, count(dv, "dv")?))
}

#[pymethods]
impl PySurface {
    /// The surface or a partial derivative at parameters ``(u, v)``.
    ///
    /// Parameters
    /// ----------
    /// u, v : float or array_like
    ///     Parameters: 1-D arrays (or floats) with ``grid=True``, arrays of one shape with
    ///     ``grid=False``.
    /// du, dv : int, optional
    ///     The orders of the partial derivative ``d^(du+dv) S / du^du dv^dv`` (0, 0: points).
    /// dx, dy : int, optional
    ///     ``RectBivariateSpline``'s names of ``du`` and ``dv`` (keywords; give one name of
    ///     each).
    /// grid : bool, optional
    ///     True: the grid ``u x v`` (u outer), shape ``(mu, mv, d)``; False: the pairs
    ///     ``(u[i], v[i])``, shape ``u.shape + (d,)``.
    /// out : numpy.ndarray, optional
    ///     A C-contiguous float64 array of the result's shape to write into.
    /// extrapolate : bool, optional
    ///     In an open direction, parameters outside the domain continue the end polynomial
    ///     pieces when None (the default) or True, and give NaN when False. A closed
    ///     direction always wraps them by its period.
    ///
    /// Returns
    /// -------
    /// numpy.ndarray
    ///     The values; ``out`` when given.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     A negative ``du`` or ``dv``, or ``du`` and ``dx`` (``dv`` and ``dy``) both given.
    /// KarkasError
    ///     Parameters of the wrong shapes, or a bad ``out``.
    /// NoBSplineFormError
    ///     Parameters outside the domain of a surface with no polynomial form, with
    ///     ``extrapolate`` None or True.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> g = np.array([[[i, j, i * j] for j in range(4)] for i in range(4)], float)
    /// >>> S = karkas.BicubicSurface(g)
    /// >>> S([0.2, 0.5], [0.1, 0.4, 0.9]).shape
    /// (2, 3, 3)
    /// >>> S(0.5, 0.5, du=1, grid=False).shape
    /// (3,)
    /// >>> bool(np.array_equal(S(0.5, 0.5, dx=1, dy=1), S(0.5, 0.5, du=1, dv=1)))
    /// True
    #[pyo3(signature = (u, v, du = 0, dv = 0, grid = true, out = None, extrapolate = None, *, dx = None, dy = None))]
    #[allow(clippy::too_many_arguments)]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        du: i64,
        dv: i64,
        grid: bool,
        out: Option<Bound<'py, PyAny>>,
        extrapolate: Option<bool>,
        dx: Option<i64>,
        dy: Option<i64>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let (du, dv) = scipy_orders((du, dv), (dx, dy))?;
        let pu = Params::extract(u, "u")?;
        let pv = Params::extract(v, "v")?;
        let d = self.inner.dim();
        let shape = result_shape(pu.shape(), pv.shape(), grid, d)?;
        let array = output_array(py, out, &shape)?;
        let (us, vs) = (pu.flat(), pv.flat());
        let inner = &self.inner;
        let (a, b) = inner.domain_u();
        let (c, e) = inner.domain_v();
        let rule = Outside {
            domain_u: Interval::new(a, b),
            domain_v: Interval::new(c, e),
            closed: inner.closed(),
            derivative: (du, dv),
            extrapolate: extrapolate.unwrap_or(true),
            dim: d,
        };
        let work = if grid { us.len() * vs.len() } else { us.len() };
        write_flat(&array, |flat| {
            maybe_detach(py, work, || {
                if grid {
                    inner.grid_flat(&us, &vs, du, dv, flat)
                } else {
                    inner.points_flat(&us, &vs, du, dv, flat)
                }
                if rule.extrapolate && inner.extrapolates() {
                    return Ok(());
                }
                rule.extend(&us, &vs, grid, flat, || self.bspline())
            })
        })?
        .map_err(library_error)?;
        Ok(array)
    }

    /// The partial derivative ``d^(du+dv) S / du^du dv^dv`` as a surface object.
    ///
    /// Parameters
    /// ----------
    /// du, dv : int, optional
    ///     The orders of the derivative in u (default 1) and v (default 0).
    /// dx, dy : int, optional
    ///     ``RectBivariateSpline``'s names of ``du`` and ``dv`` (keywords).
    ///
    /// Returns
    /// -------
    /// SurfaceDerivative
    ///     A surface whose value at ``(u, v)`` is ``self(u, v, du, dv)``.
    ///
    /// Raises
    /// ------
    /// OptionError
    ///     A negative order.
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> g = np.array([[[i, j, i * j] for j in range(4)] for i in range(4)], float)
    /// >>> S = karkas.BicubicSurface(g)
    /// >>> Su = S.derivative()
    /// >>> bool(np.allclose(Su(0.2, 0.7), S(0.2, 0.7, du=1)))
    /// True
    #[pyo3(signature = (du = None, dv = None, *, dx = None, dy = None))]
    fn derivative(
        slf: &Bound<'_, Self>,
        du: Option<i64>,
        dv: Option<i64>,
        dx: Option<i64>,
        dy: Option<i64>,
    ) -> PyResult<Py<PySurfaceDerivative>> {
        let or_default = |ours: Option<i64>, theirs: Option<i64>, default: i64| match theirs {
            Some(_) => ours.unwrap_or(0),
            None => ours.unwrap_or(default),
        };
        let (du, dv) = (or_default(du, dx, 1), or_default(dv, dy, 0));
        let (du, dv) = scipy_orders((du, dv), (dx, dy))?;
        let base = slf.get();
        let inner: Arc<dyn SurfaceImpl> = Arc::new(DerivativeSurface {
            parent: base.inner.clone(),
            du,
            dv,
        });
        let of = base
            .description
            .strip_prefix("<karkas.")
            .unwrap_or(&base.description);
        let description = format!("<karkas.SurfaceDerivative du={du}, dv={dv} of {of}");
        Py::new(
            slf.py(),
            PyClassInitializer::from(PySurface::new(inner, description)).add_subclass(
                PySurfaceDerivative {
                    parent: slf.clone().unbind(),
                    du,
                    dv,
                },
            ),
        )
    }

    /// The exact B-spline form ``((tu, tv), c, (ku, kv))`` in the surface's own parameters.
    ///
    /// ``scipy.interpolate.NdBSpline(*S.to_bspline())`` equals the surface on its domain to
    /// rounding; ``c`` has shape ``(nu, nv, d)`` (NdBSpline's layout for vector values). A
    /// closed direction is given over one period, clamped.
    ///
    /// Returns
    /// -------
    /// (tu, tv) : tuple of numpy.ndarray
    ///     The clamped knot vectors.
    /// c : numpy.ndarray
    ///     The coefficients, shape ``(nu, nv, d)``.
    /// (ku, kv) : tuple of int
    ///     The degrees.
    ///
    /// Raises
    /// ------
    /// NoBSplineFormError
    ///     A surface that is not a piecewise polynomial of its parameters (e.g. a Coons
    ///     surface over data that are not).
    ///
    /// Examples
    /// --------
    /// >>> import numpy as np, karkas
    /// >>> from scipy.interpolate import NdBSpline
    /// >>> g = np.array([[[i, j, i * j] for j in range(4)] for i in range(4)], float)
    /// >>> S = karkas.BicubicSurface(g)
    /// >>> b = NdBSpline(*S.to_bspline())
    /// >>> bool(np.allclose(b([[0.3, 0.6]])[0], S(0.3, 0.6), atol=1e-12))
    /// True
    #[allow(clippy::type_complexity)]
    fn to_bspline<'py>(
        &self,
        py: Python<'py>,
    ) -> PyResult<(
        (Bound<'py, PyArrayDyn<f64>>, Bound<'py, PyArrayDyn<f64>>),
        Bound<'py, PyArrayDyn<f64>>,
        (usize, usize),
    )> {
        let form = self.bspline().map_err(library_error)?;
        let tu = vector_to_array(py, &form.knots.0)?;
        let tv = vector_to_array(py, &form.knots.1)?;
        let (nu, nv) = form.counts;
        let coefs = vector_to_array(py, &form.coefs)?.reshape(vec![nu, nv, form.dim])?;
        Ok(((tu, tv), coefs, form.degrees))
    }
}

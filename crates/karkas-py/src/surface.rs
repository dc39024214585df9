//! The Python base class `Surface`: grid and pointwise evaluation of any karkas surface.
//!
//! Every concrete surface class (`LLSurface`, `BicubicSurface`, `CoonsSurface`) extends it and
//! hands it a [`SurfaceImpl`].

use std::sync::{Arc, OnceLock};

use karkas::section::SectionOptions;
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::bspline_form::FlatBSplineSurface;
use crate::convert::{maybe_detach, small_vector, uniform, write_flat, Size};
use crate::errors::{library_error, OptionError};
use crate::limits::{bytes_of, check_memory, zeros};
use crate::section::PySectionCurve;
use crate::wrapper::SurfaceImpl;

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

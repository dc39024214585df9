//! The Python base class `Surface`: grid and pointwise evaluation of any karkas surface.
//!
//! Every concrete surface class (`LLSurface`, `BicubicSurface`, `CoonsSurface`) extends it and
//! hands it a [`SurfaceImpl`].

use std::sync::{Arc, OnceLock};

use karkas::section::SectionOptions;
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::bspline_form::FlatBSplineSurface;
use crate::convert::{maybe_detach, uniform, write_flat};
use crate::errors::{library_error, OptionError};
use crate::section::PySectionCurve;
use crate::wrapper::SurfaceImpl;

/// Base class of every karkas surface.
///
/// ``S(u, v, du=0, dv=0, grid=True, out=None, extrapolate=None)`` (SciPy's
/// ``RectBivariateSpline`` names, ``dx``/``dy`` as ``du``/``dv``): with grid=True, u (mu,) and
/// v (mv,) give the partial derivative ``d^(du+dv) S / du^du dv^dv`` (``(0, 0)``: the points)
/// on the grid u x v, shape (mu, mv, d) (u outer); with grid=False, u and v of one shape give
/// it at the pairs (u[i], v[i]), shape u.shape + (d,). Floats work too. out= takes a
/// preallocated C-contiguous float64 array of the result's shape. ``S.derivative(du, dv)`` is
/// the derivative as a surface object, ``S.to_bspline()`` the exact B-spline form
/// ``((tu, tv), c, (ku, kv))`` for ``scipy.interpolate.NdBSpline``.
///
/// Parameters outside the domain, per direction (the same rule for every surface class): a
/// closed direction wraps by its period; an open one continues the end polynomial pieces when
/// ``extrapolate`` is None or True (the values of ``NdBSpline(*S.to_bspline())``) and gives
/// NaN when ``extrapolate=False``.
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
    /// S.sample(nu, nv): the points at nu x nv uniformly spaced parameters, (nu, nv, d).
    fn sample<'py>(
        &self,
        py: Python<'py>,
        nu: usize,
        nv: usize,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let us = uniform(self.inner.domain_u(), nu);
        let vs = uniform(self.inner.domain_v(), nv);
        let array = PyArrayDyn::<f64>::zeros(py, &[nu, nv, self.inner.dim()][..], false);
        let inner = &self.inner;
        write_flat(&array, |flat| {
            maybe_detach(py, nu * nv, || inner.grid_flat(&us, &vs, 0, 0, flat))
        })?;
        Ok(array)
    }

    /// S.section(normal, offset, tolerance=None, cells=(64, 64)) -> list[SectionCurve]: where
    /// the plane normal . x = offset cuts the surface, as polylines on it (chord error at most
    /// tolerance; default 1e-4 of the bounding box diagonal). Pieces smaller than a cell of the
    /// cells grid may be missed.
    #[pyo3(signature = (normal, offset, tolerance = None, cells = (64, 64)))]
    fn section(
        &self,
        py: Python<'_>,
        normal: Vec<f64>,
        offset: f64,
        tolerance: Option<f64>,
        cells: (usize, usize),
    ) -> PyResult<Vec<PySectionCurve>> {
        let d = self.inner.dim();
        if normal.len() != d {
            return Err(OptionError::new_err(format!(
                "normal must have {d} coordinates (got {})",
                normal.len()
            )));
        }
        let options = SectionOptions {
            tolerance,
            cells,
            ..SectionOptions::default()
        };
        let inner = &self.inner;
        py.detach(|| inner.section(&normal, offset, &options))
            .map_err(library_error)
    }

    /// The u domain (a, b).
    #[getter]
    fn domain_u(&self) -> (f64, f64) {
        self.inner.domain_u()
    }

    /// The v domain (a, b).
    #[getter]
    fn domain_v(&self) -> (f64, f64) {
        self.inner.domain_v()
    }

    /// The dimension d (2 or 3).
    #[getter]
    fn dim(&self) -> usize {
        self.inner.dim()
    }

    /// True when closed in u.
    #[getter]
    fn closed_u(&self) -> bool {
        self.inner.closed().0
    }

    /// True when closed in v.
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

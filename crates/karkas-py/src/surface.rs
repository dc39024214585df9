//! The Python base class `Surface`: grid and pointwise evaluation of any karkas surface.
//!
//! Every concrete surface class (`LLSurface`, `BicubicSurface`, `CoonsSurface`) extends it and
//! hands it a [`SurfaceImpl`].

use std::sync::Arc;

use karkas::section::SectionOptions;
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{maybe_detach, output_array, small_vector, uniform, write_flat, Params, Size};
use crate::errors::{library_error, KarkasError, OptionError};
use crate::limits::{bytes_of, check_memory, zeros};
use crate::section::PySectionCurve;
use crate::wrapper::SurfaceImpl;

/// Base class of every karkas surface.
///
/// S(u, v, grid=True, out=None): with grid=True, u (mu,) and v (mv,) give the points of the
/// grid u x v, shape (mu, mv, d) (u outer, as SciPy's RectBivariateSpline); with grid=False,
/// u and v of one shape give the points (u[i], v[i]), shape u.shape + (d,). Floats work too.
/// out= takes a preallocated C-contiguous float64 array of the result's shape.
#[pyclass(subclass, module = "karkas", name = "Surface", frozen)]
pub struct PySurface {
    pub inner: Arc<dyn SurfaceImpl>,
    /// What the object is, for `repr`.
    pub description: String,
}

impl PySurface {
    /// The base part of a surface object.
    pub fn new(inner: Arc<dyn SurfaceImpl>, description: String) -> Self {
        PySurface { inner, description }
    }
}

#[pymethods]
impl PySurface {
    /// S(u, v, grid=True, out=None): points of the surface.
    #[pyo3(signature = (u, v, grid = true, out = None))]
    fn __call__<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        grid: bool,
        out: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        self.derivative(py, u, v, 0, 0, grid, out)
    }

    /// S.derivative(u, v, ku=1, kv=0, grid=True, out=None): the partial derivative
    /// d^(ku+kv) S / du^ku dv^kv.
    #[pyo3(signature = (u, v, ku = 1, kv = 0, grid = true, out = None))]
    #[allow(clippy::too_many_arguments)]
    fn derivative<'py>(
        &self,
        py: Python<'py>,
        u: &Bound<'py, PyAny>,
        v: &Bound<'py, PyAny>,
        ku: usize,
        kv: usize,
        grid: bool,
        out: Option<Bound<'py, PyAny>>,
    ) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
        let pu = Params::extract(u, "u")?;
        let pv = Params::extract(v, "v")?;
        let (su, sv) = (pu.shape(), pv.shape());
        let d = self.inner.dim();
        let shape: Vec<usize> = if grid {
            if su.len() > 1 || sv.len() > 1 {
                return Err(KarkasError::new_err(
                    "with grid=True, u and v must be floats or 1-D arrays",
                ));
            }
            let mut s = su.clone();
            s.extend(&sv);
            s.push(d);
            s
        } else {
            if su != sv {
                return Err(KarkasError::new_err(format!(
                    "with grid=False, u and v must have one shape (got {su:?} and {sv:?})"
                )));
            }
            let mut s = su.clone();
            s.push(d);
            s
        };
        let array = output_array(py, out, &shape)?;
        let (us, vs) = (pu.flat(), pv.flat());
        let inner = &self.inner;
        let work = if grid { us.len() * vs.len() } else { us.len() };
        write_flat(&array, |flat| {
            maybe_detach(py, work, || {
                if grid {
                    inner.grid_flat(&us, &vs, ku, kv, flat)
                } else {
                    inner.points_flat(&us, &vs, ku, kv, flat)
                }
            })
        })?;
        Ok(array)
    }

    /// S.sample(nu, nv): the points at nu x nv uniformly spaced parameters, (nu, nv, d).
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

    /// S.section(normal, offset, tolerance=None, cells=(64, 64)) -> list[SectionCurve]: where
    /// the plane normal . x = offset cuts the surface, as polylines on it (chord error at most
    /// tolerance; default 1e-4 of the bounding box diagonal). Pieces smaller than a cell of the
    /// cells grid may be missed.
    #[pyo3(signature = (normal, offset, tolerance = None, cells = (64, 64)))]
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

//! The Python base class `Surface`: grid and pointwise evaluation of any karkas surface.

use std::sync::Arc;

use karkas::implicit::ExpressionSurface;
use karkas::measure::{hausdorff_surface_implicit, Hausdorff};
use karkas::section::{plane_section, Plane, SectionOptions};
use karkas::{Point, Point3, Surface};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{
    as_points_mut, flatten, invalid, maybe_detach, output_array, write_flat, Params,
};

/// A karkas surface of either dimension, evaluated on flat buffers.
pub trait SurfaceImpl: Send + Sync {
    /// The dimension `d` (2 or 3).
    fn dim(&self) -> usize;
    /// The `u` domain.
    fn domain_u(&self) -> (f64, f64);
    /// The `v` domain.
    fn domain_v(&self) -> (f64, f64);
    /// Closed in `u`, in `v`.
    fn closed(&self) -> (bool, bool);
    /// The derivative `(ku, kv)` ((0, 0): the point) on the grid `us x vs`, row-major with `u`
    /// outer, into `out`.
    fn grid_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]);
    /// The derivative `(ku, kv)` at the pairs `(us[i], vs[i])` into `out`.
    fn points_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]);
    /// The section by the plane `normal . x = offset` (`normal.len() == dim`).
    fn section(
        &self,
        normal: &[f64],
        offset: f64,
        options: &SectionOptions,
    ) -> karkas::Result<FlatSection>;
    /// The two-sided Hausdorff distance to the patch of an implicit surface (3-D only).
    fn hausdorff_implicit(
        &self,
        implicit: &ExpressionSurface,
        patch: &[Point3],
        samples: (usize, usize),
    ) -> karkas::Result<Hausdorff>;
}

/// One piece of a section with dimension-free coordinates.
pub struct FlatCurve {
    /// The points, `dim` numbers each.
    pub points: Vec<f64>,
    /// The surface parameters `(u, v)` of the points, flat.
    pub params: Vec<f64>,
    /// True when the last point joins the first.
    pub closed: bool,
    /// The polyline's length (the closing chord included when closed).
    pub length: f64,
}

/// A section with dimension-free coordinates.
pub struct FlatSection {
    /// The pieces.
    pub curves: Vec<FlatCurve>,
    /// The library's warnings, as text.
    pub warnings: Vec<String>,
}

/// A surface of dimension `D` seen as one in 3-D (used only when `D == 3`: the coordinates
/// are copied, missing ones are zero).
struct Lift<'a, S, const D: usize>(&'a S);

fn lift<const D: usize>(p: Point<D>) -> Point3 {
    let mut q = Point3::ZERO;
    for (a, b) in q.0.iter_mut().zip(p.0) {
        *a = b;
    }
    q
}

impl<S: Surface<D>, const D: usize> Surface<3> for Lift<'_, S, D> {
    fn domain_u(&self) -> karkas::Interval {
        self.0.domain_u()
    }
    fn domain_v(&self) -> karkas::Interval {
        self.0.domain_v()
    }
    fn is_closed_u(&self) -> bool {
        self.0.is_closed_u()
    }
    fn is_closed_v(&self) -> bool {
        self.0.is_closed_v()
    }
    fn eval(&self, u: f64, v: f64) -> Point3 {
        lift(self.0.eval(u, v))
    }
    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        lift(self.0.deriv(u, v, ku, kv))
    }
}

/// A karkas surface of dimension `D` behind [`SurfaceImpl`].
pub struct WrappedSurface<S, const D: usize>(pub S);

impl<S, const D: usize> SurfaceImpl for WrappedSurface<S, D>
where
    S: Surface<D> + Send + Sync,
{
    fn dim(&self) -> usize {
        D
    }
    fn domain_u(&self) -> (f64, f64) {
        let d = self.0.domain_u();
        (d.start, d.end)
    }
    fn domain_v(&self) -> (f64, f64) {
        let d = self.0.domain_v();
        (d.start, d.end)
    }
    fn closed(&self) -> (bool, bool) {
        (self.0.is_closed_u(), self.0.is_closed_v())
    }
    fn grid_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]) {
        let out: &mut [Point<D>] = as_points_mut(out);
        if ku == 0 && kv == 0 {
            self.0.eval_grid_into(us, vs, out);
            return;
        }
        for (row, &u) in out.chunks_exact_mut(vs.len().max(1)).zip(us) {
            for (p, &v) in row.iter_mut().zip(vs) {
                *p = self.0.deriv(u, v, ku, kv);
            }
        }
    }
    fn section(
        &self,
        normal: &[f64],
        offset: f64,
        options: &SectionOptions,
    ) -> karkas::Result<FlatSection> {
        let mut n = Point::<D>::ZERO;
        n.0.copy_from_slice(normal);
        let section = plane_section(&self.0, &Plane::new(n, offset)?, options)?;
        Ok(FlatSection {
            curves: section
                .curves
                .iter()
                .map(|c| FlatCurve {
                    points: flatten(&c.points).to_vec(),
                    params: c.params.iter().flat_map(|&(u, v)| [u, v]).collect(),
                    closed: c.closed,
                    length: c.length(),
                })
                .collect(),
            warnings: section.warnings.iter().map(|w| format!("{w:?}")).collect(),
        })
    }
    fn hausdorff_implicit(
        &self,
        implicit: &ExpressionSurface,
        patch: &[Point3],
        samples: (usize, usize),
    ) -> karkas::Result<Hausdorff> {
        hausdorff_surface_implicit(&Lift(&self.0), implicit, patch, samples)
    }
    fn points_flat(&self, us: &[f64], vs: &[f64], ku: usize, kv: usize, out: &mut [f64]) {
        let out: &mut [Point<D>] = as_points_mut(out);
        for ((p, &u), &v) in out.iter_mut().zip(us).zip(vs) {
            *p = if ku == 0 && kv == 0 {
                self.0.eval(u, v)
            } else {
                self.0.deriv(u, v, ku, kv)
            };
        }
    }
}

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

    #[allow(clippy::too_many_arguments)]
    fn evaluate<'py>(
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
                return Err(invalid(
                    "with grid=True, u and v must be floats or 1-D arrays",
                ));
            }
            let mut s = su.clone();
            s.extend(&sv);
            s.push(d);
            s
        } else {
            if su != sv {
                return Err(invalid(format!(
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
        self.evaluate(py, u, v, 0, 0, grid, out)
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
        self.evaluate(py, u, v, ku, kv, grid, out)
    }

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
    ) -> PyResult<Vec<crate::extras::PySectionCurve>> {
        let d = self.inner.dim();
        if normal.len() != d {
            return Err(invalid(format!(
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
        let section = py
            .detach(|| inner.section(&normal, offset, &options))
            .map_err(crate::convert::value_error)?;
        Ok(crate::extras::section_curves(section, d))
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

/// `n` uniformly spaced parameters over `(a, b)`, ends included.
pub fn uniform((a, b): (f64, f64), n: usize) -> Vec<f64> {
    (0..n)
        .map(|i| {
            if n == 1 {
                a
            } else {
                a + (b - a) * i as f64 / (n - 1) as f64
            }
        })
        .collect()
}

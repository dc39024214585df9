//! Hausdorff distances between point sets, and between a surface and an implicit surface.

use karkas::implicit::ExpressionSurface;
use karkas::measure::{hausdorff_points_implicit, hausdorff_sets, DirectedDistance, Hausdorff};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::points3;
use crate::errors::{library_error, OptionError, PointsError};
use crate::implicit::PyImplicitSurface;
use crate::surface::PySurface;

/// A Hausdorff result as a dict: distance, and each direction's distance and the points
/// where it is attained.
fn hausdorff_dict<'py>(py: Python<'py>, h: &Hausdorff) -> PyResult<Bound<'py, PyDict>> {
    let side = |d: &DirectedDistance| -> PyResult<Bound<'py, PyDict>> {
        let s = PyDict::new(py);
        s.set_item("distance", d.distance)?;
        s.set_item("from", d.from.0.to_vec())?;
        s.set_item("to", d.to.0.to_vec())?;
        Ok(s)
    };
    let out = PyDict::new(py);
    out.set_item("distance", h.distance)?;
    out.set_item("forward", side(&h.forward)?)?;
    out.set_item("backward", side(&h.backward)?)?;
    Ok(out)
}

/// hausdorff(a, b=None, expr=None) -> dict: the two-sided Hausdorff distance between point
/// sets a (n, 3) and b (m, 3) (k-d tree, O((n + m) log)), or with expr instead of b between a
/// and the patch of the implicit surface F(x, y, z) = expr = 0 that a covers (as karkas
/// hausdorff A --expr EXPR); with where each one-sided distance is attained.
#[pyfunction]
#[pyo3(signature = (a, b = None, expr = None))]
pub fn hausdorff<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: Option<&Bound<'py, PyAny>>,
    expr: Option<&str>,
) -> PyResult<Bound<'py, PyDict>> {
    let a = points3(a, "a")?;
    let h = match (b, expr) {
        (Some(b), None) => {
            let b = points3(b, "b")?;
            py.detach(|| hausdorff_sets(&a, &b))
        }
        (None, Some(expr)) => {
            let surface = ExpressionSurface::parse(expr).map_err(library_error)?;
            py.detach(|| hausdorff_points_implicit(&a, &surface))
        }
        _ => return Err(OptionError::new_err("give b or expr, not both")),
    }
    .map_err(library_error)?;
    hausdorff_dict(py, &h)
}

/// hausdorff_to_implicit(surface, implicit, patch, samples=(50, 50)) -> dict: the two-sided
/// Hausdorff distance between a 3-D surface (sampled on samples) and the patch of an implicit
/// surface given by points on it (patch (n, 3)).
#[pyfunction]
#[pyo3(signature = (surface, implicit, patch, samples = (50, 50)))]
pub fn hausdorff_to_implicit<'py>(
    py: Python<'py>,
    surface: &Bound<'py, PySurface>,
    implicit: &Bound<'py, PyImplicitSurface>,
    patch: &Bound<'py, PyAny>,
    samples: (usize, usize),
) -> PyResult<Bound<'py, PyDict>> {
    let s = surface.get();
    if s.inner.dim() != 3 {
        return Err(PointsError::new_err("the surface must be 3-D"));
    }
    let patch = points3(patch, "patch")?;
    let inner = &s.inner;
    let expr = &implicit.get().surface;
    let h = py
        .detach(|| inner.hausdorff_implicit(expr, &patch, samples))
        .map_err(library_error)?;
    hausdorff_dict(py, &h)
}

//! Hausdorff distances between point sets, and between a surface and an implicit surface.

use karkas::measure::{hausdorff_sets, DirectedDistance, Hausdorff};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::points3;
use crate::errors::{library_error, PointsError};
use crate::implicit::PyImplicitSurface;
use crate::limits::{bytes_of, check_memory};
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

/// hausdorff(a, b) -> dict: the two-sided Hausdorff distance between point sets a (n, 3) and
/// b (m, 3) (k-d tree, O((n + m) log)), with where each one-sided distance is attained.
#[pyfunction]
pub fn hausdorff<'py>(
    py: Python<'py>,
    a: &Bound<'py, PyAny>,
    b: &Bound<'py, PyAny>,
) -> PyResult<Bound<'py, PyDict>> {
    let (a, b) = (points3(a, "a")?, points3(b, "b")?);
    let h = py
        .detach(|| hausdorff_sets(&a, &b))
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
    // The surface's samples, their distances and the k-d tree over them.
    check_memory(
        py,
        &format!(
            "hausdorff_to_implicit(samples=({}, {}))",
            samples.0, samples.1
        ),
        bytes_of(&[samples.0, samples.1, 3], 32),
    )?;
    let patch = points3(patch, "patch")?;
    let inner = &s.inner;
    let expr = &implicit.get().surface;
    let h = py
        .detach(|| inner.hausdorff_implicit(expr, &patch, samples))
        .map_err(library_error)?;
    hausdorff_dict(py, &h)
}

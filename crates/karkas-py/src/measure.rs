//! Hausdorff distances between point sets, and between a surface and an implicit surface.

use karkas::implicit::ExpressionSurface;
use karkas::measure::{hausdorff_points_implicit, hausdorff_sets, DirectedDistance, Hausdorff};
use pyo3::prelude::*;
use pyo3::types::PyDict;

use crate::convert::points3;
use crate::errors::{library_error, OptionError, PointsError};
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

/// The two-sided Hausdorff distance between two point sets, and where it is attained.
///
/// Nearest neighbours by a k-d tree, O((n + m) log(n + m)). With ``expr`` instead of ``b``:
/// the distance between ``a`` and the patch of the implicit surface ``expr = 0`` that ``a``
/// covers (its part inside the bounding box of ``a``, sampled on a lattice of 64 steps along
/// the box's largest side, and the closest points of ``a`` on it), as
/// ``karkas hausdorff A --expr EXPR``.
///
/// Parameters
/// ----------
/// a : array_like
///     The first set, shape ``(n, 3)``.
/// b : array_like, optional
///     The second set, shape ``(m, 3)``.
/// expr : str, optional
///     Instead of ``b``: an implicit surface ``F(x, y, z) = 0``, written as for
///     ``ImplicitSurface``.
///
/// Returns
/// -------
/// dict
///     ``distance`` (the larger of the two one-sided distances), ``forward`` (from ``a`` to
///     ``b``) and ``backward`` (from ``b`` to ``a``), each a dict with its ``distance`` and the
///     points ``from`` and ``to`` where it is attained.
///
/// Raises
/// ------
/// PointsError
///     An empty set, a non-finite coordinate, or not an ``(n, 3)`` array.
///
/// Examples
/// --------
/// >>> a = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0]]
/// >>> b = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [1.0, 2.0, 0.0]]
/// >>> h = karkas.hausdorff(a, b)
/// >>> h["distance"], h["forward"]["distance"], h["backward"]["distance"]
/// (2.0, 0.0, 2.0)
/// >>> h["backward"]["from"], h["backward"]["to"]
/// ([1.0, 2.0, 0.0], [1.0, 0.0, 0.0])
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

/// The two-sided Hausdorff distance between a 3-D surface and a patch of an implicit surface.
///
/// Parameters
/// ----------
/// surface : Surface
///     A 3-D karkas surface, sampled on a ``samples`` grid.
/// implicit : ImplicitSurface
///     The implicit surface.
/// patch : array_like
///     Points on the implicit surface, ``(n, 3)``, that delimit the patch compared.
/// samples : tuple of int, optional
///     The ``(nu, nv)`` samples of ``surface``.
///
/// Returns
/// -------
/// dict
///     As ``hausdorff``: ``distance``, ``forward`` (surface to implicit) and ``backward``,
///     each with its ``distance``, ``from`` and ``to``.
///
/// Raises
/// ------
/// PointsError
///     The surface is not 3-D, or ``patch`` is not an ``(n, 3)`` array of finite numbers.
/// ConvergenceError
///     A projection onto the implicit surface did not converge.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 1.0] for j in range(3)] for i in range(3)])
/// >>> S = karkas.BicubicSurface(grid, parameterization="uniform")
/// >>> plane = karkas.ImplicitSurface("z")
/// >>> patch = grid.reshape(-1, 3) * [1, 1, 0]
/// >>> h = karkas.hausdorff_to_implicit(S, plane, patch, samples=(5, 5))
/// >>> round(h["distance"], 6)
/// 1.0
#[pyfunction]
#[pyo3(signature = (surface, implicit, patch, samples = (50, 50)))]
#[pyo3(text_signature = "(surface, implicit, patch, samples=(50, 50))")]
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

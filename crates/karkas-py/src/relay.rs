//! `karkas.relay_grid`: a grid re-laid along the lines of curvature of its own bicubic
//! interpolant (Kuznetsov and Filatov, Theorem 2.1; docs/methods.md §5), as
//! `karkas surface relay` does.

use karkas::param::{relay_grid as relay, RelayOptions};
use numpy::PyArrayDyn;
use pyo3::prelude::*;

use crate::convert::{grid_to_array, GridArray};
use crate::errors::{library_error, PointsError};

/// Re-lays a grid of 3-D points along the lines of curvature of its bicubic interpolant.
///
/// The interpolant (chord-length parameters, not-a-knot ends) is built, the two families of
/// lines of curvature are traced through the start node, spaced by arc length, and node
/// ``(i, j)`` of the new grid is the crossing of the ``i``-th ``v`` line with the ``j``-th
/// ``u`` line (Kuznetsov and Filatov: arc lengths along lines of curvature are the best
/// parameters). The new nodes lie on the input's interpolant, so they are only as accurate
/// as it is.
///
/// Parameters
/// ----------
/// grid : array_like
///     ``(nu, nv, 3)`` points.
/// size : tuple of int, optional
///     Rows and columns ``(M, N)`` of the new grid, each at least 2; default the input's.
/// start : tuple of int, optional
///     The start node ``(i, j)`` of the input; default its centre.
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(M, N, 3)``, the re-laid nodes.
///
/// Raises
/// ------
/// PointsError
///     A grid that is not ``(nu, nv, 3)``, too small or with coinciding nodes, a size below
///     2, a start outside the grid, or an umbilic region (a plane or a sphere: the principal
///     directions are undefined).
/// ConvergenceError
///     A singular point, or a net that does not fit the interpolant's domain.
///
/// Examples
/// --------
/// A grid on the unit cylinder along helices turned by 30 degrees comes back to circles
/// ``z = const`` (its rows or its columns):
///
/// >>> a = np.radians(30.0)
/// >>> s, t = np.meshgrid(np.linspace(-0.6, 0.6, 9), np.linspace(-0.9, 0.9, 13), indexing="ij")
/// >>> z, angle = np.cos(a) * s - np.sin(a) * t, np.sin(a) * s + np.cos(a) * t
/// >>> grid = np.stack([np.cos(angle), np.sin(angle), z], axis=-1)
/// >>> relaid = karkas.relay_grid(grid, size=(5, 7))
/// >>> relaid.shape
/// (5, 7, 3)
/// >>> bool(min(np.ptp(relaid[..., 2], axis=1).max(), np.ptp(relaid[..., 2], axis=0).max()) < 1e-3)
/// True
#[pyfunction]
#[pyo3(signature = (grid, size = None, start = None))]
pub fn relay_grid<'py>(
    py: Python<'py>,
    grid: &Bound<'py, PyAny>,
    size: Option<(usize, usize)>,
    start: Option<(usize, usize)>,
) -> PyResult<Bound<'py, PyArrayDyn<f64>>> {
    let (g, dim) = GridArray::extract_checked(grid, "grid")?;
    if dim != 3 {
        return Err(PointsError::new_err(format!(
            "grid: relay_grid needs 3-D points, got {dim}-D"
        )));
    }
    let nodes = g.grid::<3>()?;
    let options = RelayOptions {
        size,
        start,
        ..RelayOptions::default()
    };
    let relaid = relay(&nodes, &options).map_err(library_error)?;
    grid_to_array(py, &relaid.nodes)
}

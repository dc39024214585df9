//! Exports through karkas-io: OBJ and binary STL meshes of sampled surfaces, CSV of curve and
//! surface samples. Files are written atomically (nothing is left behind on failure); a file
//! that cannot be written raises `OSError`.

use std::path::PathBuf;

use karkas::Point3;
use karkas_io::obj::write_surface_obj;
use karkas_io::stl::write_surface_stl;
use karkas_io::write::{write_curve_csv, write_surface_csv};
use pyo3::prelude::*;

use crate::convert::{as_points, by_dim, check_dim3, extract_vector, GridArray, PointsArray};
use crate::export_format::write_error;

/// A (nu, nv, 3) grid of points.
fn grid3(grid: &Bound<'_, PyAny>) -> PyResult<(usize, usize, Vec<Point3>)> {
    let g = GridArray::extract(grid, "grid")?;
    check_dim3(g.dim(), "grid")?;
    let grid = g.grid::<3>()?;
    Ok((grid.rows(), grid.cols(), grid.into_vec()))
}

/// Writes a sampled surface as an OBJ triangle mesh (two triangles a grid cell).
///
/// The file is written atomically: nothing is left behind on failure.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file to write.
/// grid : array_like
///     The surface's points, shape ``(nu, nv, 3)``, e.g. ``S.sample(nu, nv)``.
///
/// Returns
/// -------
/// None
///
/// Raises
/// ------
/// PointsError
///     ``grid`` is not a ``(nu, nv, 3)`` array of finite numbers.
/// OSError
///     The file cannot be written.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 0.0] for j in range(3)] for i in range(2)])
/// >>> karkas.export_obj("patch.obj", grid)
/// >>> text = open("patch.obj").read()
/// >>> text.count("\nv "), text.count("\nf ")
/// (6, 4)
#[pyfunction]
pub fn export_obj(py: Python<'_>, path: PathBuf, grid: &Bound<'_, PyAny>) -> PyResult<()> {
    let (nu, nv, points) = grid3(grid)?;
    py.detach(|| write_surface_obj(&path, nu, nv, &points))
        .map_err(write_error)
}

/// Writes a sampled surface as a binary STL mesh (two triangles a grid cell).
///
/// The file is written atomically: nothing is left behind on failure.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file to write.
/// grid : array_like
///     The surface's points, shape ``(nu, nv, 3)``.
///
/// Returns
/// -------
/// None
///
/// Raises
/// ------
/// PointsError
///     ``grid`` is not a ``(nu, nv, 3)`` array of finite numbers.
/// OSError
///     The file cannot be written.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 0.0] for j in range(3)] for i in range(2)])
/// >>> karkas.export_stl("patch.stl", grid)
/// >>> import os
/// >>> os.path.getsize("patch.stl") == 84 + 50 * 4
/// True
#[pyfunction]
pub fn export_stl(py: Python<'_>, path: PathBuf, grid: &Bound<'_, PyAny>) -> PyResult<()> {
    let (nu, nv, points) = grid3(grid)?;
    py.detach(|| write_surface_stl(&path, nu, nv, &points))
        .map_err(write_error)
}

/// Writes curve samples as CSV with the header ``t,x,y`` or ``t,x,y,z``.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file to write.
/// t : array_like
///     The parameters, ``(n,)``.
/// points : array_like
///     The points at ``t``, ``(n, d)``, ``d`` in {2, 3}.
///
/// Returns
/// -------
/// None
///
/// Raises
/// ------
/// PointsError
///     ``points`` is not an ``(n, 2)`` or ``(n, 3)`` array, or not one point per parameter.
/// OSError
///     The file cannot be written.
///
/// Examples
/// --------
/// >>> karkas.export_curve_csv("c.csv", [0.0, 1.0], [[0.0, 0.0], [1.0, 2.0]])
/// >>> print(open("c.csv").read().splitlines()[0])
/// t,x,y
/// >>> bool(np.allclose(np.loadtxt("c.csv", delimiter=",", skiprows=1), [[0, 0, 0], [1, 1, 2]]))
/// True
#[pyfunction]
pub fn export_curve_csv(
    py: Python<'_>,
    path: PathBuf,
    t: &Bound<'_, PyAny>,
    points: &Bound<'_, PyAny>,
) -> PyResult<()> {
    let ts = extract_vector(t, "t")?;
    let (pts, dim) = PointsArray::extract_checked(points, "points")?;
    let flat = pts.flat();
    by_dim!(dim, D => {
        let p = as_points::<D>(&flat);
        py.detach(|| write_curve_csv(&path, &ts, p)).map_err(write_error)
    })
}

/// Writes surface samples as CSV with the header ``u,v,x,y,z``, one row a grid point.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file to write.
/// u, v : array_like
///     The parameters of the rows ``(nu,)`` and of the columns ``(nv,)``.
/// grid : array_like
///     The points, ``(nu, nv, 3)``, e.g. ``S(u, v)``.
///
/// Returns
/// -------
/// None
///
/// Raises
/// ------
/// PointsError
///     ``grid`` is not a ``(len(u), len(v), 3)`` array of finite numbers.
/// OSError
///     The file cannot be written.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 0.0] for j in range(3)] for i in range(2)])
/// >>> karkas.export_surface_csv("s.csv", [0.0, 1.0], [0.0, 0.5, 1.0], grid)
/// >>> rows = open("s.csv").read().splitlines()
/// >>> rows[0], len(rows)
/// ('u,v,x,y,z', 7)
#[pyfunction]
pub fn export_surface_csv(
    py: Python<'_>,
    path: PathBuf,
    u: &Bound<'_, PyAny>,
    v: &Bound<'_, PyAny>,
    grid: &Bound<'_, PyAny>,
) -> PyResult<()> {
    let (us, vs) = (extract_vector(u, "u")?, extract_vector(v, "v")?);
    let (_, _, points) = grid3(grid)?;
    py.detach(|| write_surface_csv(&path, &us, &vs, &points))
        .map_err(write_error)
}

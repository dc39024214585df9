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
use crate::errors::file_error;

/// A (nu, nv, 3) grid of points.
fn grid3(grid: &Bound<'_, PyAny>) -> PyResult<(usize, usize, Vec<Point3>)> {
    let g = GridArray::extract(grid, "grid")?;
    check_dim3(g.dim(), "grid")?;
    let grid = g.grid::<3>()?;
    Ok((grid.rows(), grid.cols(), grid.into_vec()))
}

/// export_obj(path, grid): writes a sampled surface (nu, nv, 3), e.g. S.sample(nu, nv), as an
/// OBJ mesh of quads.
#[pyfunction]
pub fn export_obj(py: Python<'_>, path: PathBuf, grid: &Bound<'_, PyAny>) -> PyResult<()> {
    let (nu, nv, points) = grid3(grid)?;
    py.detach(|| write_surface_obj(&path, nu, nv, &points))
        .map_err(file_error)
}

/// export_stl(path, grid): writes a sampled surface (nu, nv, 3) as a binary STL mesh.
#[pyfunction]
pub fn export_stl(py: Python<'_>, path: PathBuf, grid: &Bound<'_, PyAny>) -> PyResult<()> {
    let (nu, nv, points) = grid3(grid)?;
    py.detach(|| write_surface_stl(&path, nu, nv, &points))
        .map_err(file_error)
}

/// export_curve_csv(path, t, points): writes curve samples as CSV with header t,x,y or
/// t,x,y,z (points (n, d) at parameters t (n,)).
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
        py.detach(|| write_curve_csv(&path, &ts, p)).map_err(file_error)
    })
}

/// export_surface_csv(path, u, v, grid): writes surface samples as CSV with header u,v,x,y,z
/// (grid (len(u), len(v), 3), e.g. S(u, v)).
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
        .map_err(file_error)
}

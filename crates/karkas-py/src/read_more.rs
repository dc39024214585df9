//! The readers of karkas-io the command line uses besides those of [`crate::read`]: the
//! skeleton curves of a tube (`surface dps-tube --along/--across`), point sets (`hausdorff`),
//! sampled surfaces `u,v,x,y,z` (`convert`) and cell masks (`vary --fixed`). Files are read
//! with the GIL released; errors as in [`crate::read`].

use std::path::PathBuf;

use numpy::{PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::prelude::*;

use crate::limits::{bytes_of, check_memory};
use crate::read::{file_path, flat_points, points_array, read_error};

/// Reads the skeleton curves of a tube along or across it.
///
/// CSV rows ``i,q,x,y,z`` (`across=False`: curve ``i`` along the tube, sample ``q``) or
/// ``j,p,x,y,z`` (`across=True`), every (curve, sample) once, rows in any order, as
/// ``karkas surface dps-tube`` reads ``--along`` and ``--across``.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The CSV file.
/// across : bool, default False
///     Read the curves across the tube (header ``j,p``) instead of along it (``i,q``).
///
/// Returns
/// -------
/// numpy.ndarray
///     ``(m, N, 3)`` float64: curve ``k`` is ``out[k]``, as `TubeSurface` takes them.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened.
/// karkas.FileFormatError
///     Its content cannot be read (the message names the line or the curve and sample).
///
/// Examples
/// --------
/// >>> import os, tempfile, karkas
/// >>> p = os.path.join(tempfile.mkdtemp(), "f.csv")
/// >>> _ = open(p, "w").write("i,q,x,y,z\n0,0,1,0,0\n0,1,0,1,0\n")
/// >>> karkas.read_skeleton(p).shape
/// (1, 2, 3)
#[pyfunction]
#[pyo3(signature = (path, across = false))]
#[pyo3(text_signature = "(path, across=False)")]
pub fn read_skeleton(
    py: Python<'_>,
    path: PathBuf,
    across: bool,
) -> PyResult<Bound<'_, PyArray3<f64>>> {
    let path = file_path(path)?;
    let grid = py
        .detach(|| {
            if across {
                karkas_io::skeleton::read_across_curves(&path)
            } else {
                karkas_io::skeleton::read_along_curves(&path)
            }
        })
        .map_err(read_error)?;
    let (rows, cols) = (grid.rows(), grid.cols());
    PyArray1::from_vec(py, flat_points(grid.into_vec())).reshape([rows, cols, 3])
}

/// Reads a point set: the vertices of an OBJ file, or the ``x,y,z`` columns of a CSV file.
///
/// As ``karkas hausdorff`` reads its inputs: ``.obj`` by its ``v`` lines, anything else as
/// CSV or whitespace columns with ``x``, ``y``, ``z`` (a grid ``i,j,x,y,z``, samples
/// ``u,v,x,y,z`` or plain points).
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
///
/// Returns
/// -------
/// numpy.ndarray
///     ``(n, 3)`` float64.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened.
/// karkas.FileFormatError
///     Its content cannot be read.
///
/// Examples
/// --------
/// >>> import os, tempfile, karkas
/// >>> p = os.path.join(tempfile.mkdtemp(), "p.csv")
/// >>> _ = open(p, "w").write("x,y,z\n0,0,0\n1,2,3\n")
/// >>> karkas.read_point_set(p).tolist()
/// [[0.0, 0.0, 0.0], [1.0, 2.0, 3.0]]
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_point_set(py: Python<'_>, path: PathBuf) -> PyResult<Bound<'_, PyArray2<f64>>> {
    let path = file_path(path)?;
    let points = py
        .detach(|| karkas_io::pointset::read_point_set(&path))
        .map_err(read_error)?;
    points_array(py, points)
}

/// Reads the samples of a surface: CSV rows ``u,v,x,y,z`` on a full grid of parameters.
///
/// The file ``export(surface, "s.csv")`` and the ``surface`` commands write, as
/// ``karkas convert`` reads it: the ``u`` values are the rows, the ``v`` values the columns.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The CSV file.
///
/// Returns
/// -------
/// numpy.ndarray
///     ``(nu, nv, 3)`` float64, ``out[i, j]`` the point at the ``i``-th ``u`` and the ``j``-th
///     ``v``.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened.
/// karkas.FileFormatError
///     Its content cannot be read.
///
/// Examples
/// --------
/// >>> import os, tempfile, karkas
/// >>> p = os.path.join(tempfile.mkdtemp(), "s.csv")
/// >>> _ = open(p, "w").write("u,v,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,0,1,0,0\n1,1,1,1,1\n")
/// >>> karkas.read_surface_samples(p).shape
/// (2, 2, 3)
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_surface_samples(py: Python<'_>, path: PathBuf) -> PyResult<Bound<'_, PyArray3<f64>>> {
    let path = file_path(path)?;
    let grid = py
        .detach(|| karkas_io::samples::read_surface_samples(&path))
        .map_err(read_error)?;
    let (rows, cols) = (grid.rows(), grid.cols());
    PyArray1::from_vec(py, flat_points(grid.into_vec())).reshape([rows, cols, 3])
}

/// Reads a cell mask: CSV rows ``i,j`` naming the marked cells of a ``rows x cols`` grid.
///
/// As ``karkas vary --fixed`` reads it; cells not listed are unmarked.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The CSV file.
/// rows, cols : int
///     The shape of the grid.
///
/// Returns
/// -------
/// numpy.ndarray
///     ``(rows, cols)`` bool, True for every listed cell.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened.
/// karkas.FileFormatError
///     A cell outside the grid or listed twice, or content that cannot be read.
///
/// Examples
/// --------
/// >>> import os, tempfile, karkas
/// >>> p = os.path.join(tempfile.mkdtemp(), "m.csv")
/// >>> _ = open(p, "w").write("i,j\n1,0\n")
/// >>> karkas.read_mask(p, 2, 2).tolist()
/// [[False, False], [True, False]]
#[pyfunction]
#[pyo3(text_signature = "(path, rows, cols)")]
pub fn read_mask(
    py: Python<'_>,
    path: PathBuf,
    rows: usize,
    cols: usize,
) -> PyResult<Bound<'_, PyArray2<bool>>> {
    let path = file_path(path)?;
    check_memory(
        py,
        &format!("read_mask of {rows} x {cols} cells"),
        bytes_of(&[rows, cols], 1),
    )?;
    let mask = py
        .detach(|| karkas_io::mask::read_cell_mask(&path, rows, cols))
        .map_err(read_error)?;
    PyArray1::from_vec(py, mask.into_vec()).reshape([rows, cols])
}

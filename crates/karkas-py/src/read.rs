//! The readers of karkas-io as Python functions returning NumPy arrays: curve points, airfoils,
//! surface frames, curve networks and triangle meshes, read as the command line reads them.
//!
//! - Arrays are built from the readers' own vectors without a copy (a `Vec<f64>` becomes the
//!   array's memory; `Vec<Point3>` is reinterpreted as `Vec<f64>` by `bytemuck`), so a read
//!   holds the points once. Mesh faces are converted from `u32` to `int64`, one copy.
//! - Files are read with the GIL released.
//! - A path is a path: `-` is a file named `-` here, not standard input as on the command line
//!   (a Python caller has `sys.stdin` for that).
//! - Errors: a file that cannot be opened or read raises the `OSError` subclass of the
//!   operating system's error (`FileNotFoundError`, `PermissionError`, `IsADirectoryError`)
//!   with `errno`, `strerror` and `filename` set, as Python's `open` does; content that cannot
//!   be read raises `karkas.FileFormatError` with exactly the command line's message (file,
//!   line, what is wrong).
//! - What a read keeps is bounded by karkas-io's process-wide cap ([`set_max_input_bytes`],
//!   2 GiB by default), as the command line's `--max-memory`.
//!
//! Besides these, the readers the command line uses for the skeleton curves of a tube
//! (`surface dps-tube --along/--across`), point sets (`hausdorff`), sampled surfaces
//! `u,v,x,y,z` (`convert`) and cell masks (`vary --fixed`), with the same rules.

use std::path::{Path, PathBuf};

use karkas::Point;
use karkas_io::IoError;
use numpy::{PyArray1, PyArray2, PyArray3, PyArrayMethods};
use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;

use crate::errors::{FileFormatError, OptionError};
use crate::limits::{bytes_of, check_memory};

/// Reads the ordered points of a curve file, as the command line's ``curve`` commands do.
///
/// CSV (an optional header naming ``x``, ``y`` and optionally ``z``), whitespace-separated
/// columns, or an airfoil .dat (Selig or Lednicer). Files as spreadsheets write them are read
/// too: fields separated by ``;`` or tabs, decimal commas (``0,5``) where the comma does not
/// separate the fields, quoted fields, units in brackets in the header (``x [mm]``); a header
/// of two or three columns that names none of ``x``, ``y``, ``z`` is read in order.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file (``-`` is a file named ``-``, not standard input).
/// columns : sequence of int or str, optional
///     The x, y (and z) columns by header name or by position counted from 1, as the command
///     line's ``--columns``: ``(2, 3)``, ``("Абсцисса", "Ордината")``.
/// decimal_comma : bool, optional
///     The numbers are written with a decimal comma: the comma never separates fields (as
///     ``--decimal-comma``; detected without it in files separated by ``;``, tabs or spaces).
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(n, d)``, ``d`` 2 or 3 as the file says.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened or read (``FileNotFoundError``, ``PermissionError``,
///     ``IsADirectoryError``, ...), with ``errno``, ``strerror`` and ``filename`` set.
/// FileFormatError
///     The content cannot be read (the command line's message, ``file:line: ...``).
/// OptionError
///     ``columns`` is not two or three names or positions.
///
/// Warns
/// -----
/// KarkasWarning
///     A first column that counts the rows (``0, 1, 2, ...``: row numbers read as x), points
///     far out of their order along the curve, or a header read in order.
///
/// Examples
/// --------
/// >>> _ = open("c.csv", "w").write("x,y\n0,0\n1,2\n2,1\n")
/// >>> karkas.read_curve("c.csv")
/// array([[0., 0.],
///        [1., 2.],
///        [2., 1.]])
/// >>> _ = open("excel.csv", "w").write("x [mm];y [mm]\n0,5;1\n1,5;2,25\n2;0\n")
/// >>> karkas.read_curve("excel.csv")
/// array([[0.5 , 1.  ],
///        [1.5 , 2.25],
///        [2.  , 0.  ]])
/// >>> _ = open("i.csv", "w").write("n,a,b\n1,0,0\n2,1,2\n3,2,1\n")
/// >>> karkas.read_curve("i.csv", columns=("a", "b"))
/// array([[0., 0.],
///        [1., 2.],
///        [2., 1.]])
#[pyfunction]
#[pyo3(signature = (path, *, columns = None, decimal_comma = false))]
#[pyo3(text_signature = "(path, *, columns=None, decimal_comma=False)")]
pub fn read_curve<'py>(
    py: Python<'py>,
    path: PathBuf,
    columns: Option<Vec<ColumnArg>>,
    decimal_comma: bool,
) -> PyResult<Bound<'py, PyArray2<f64>>> {
    let path = file_path(path)?;
    let options = karkas_io::points::ReadOptions {
        columns: column_choice(columns)?,
        decimal_comma,
    };
    let read = py
        .detach(|| karkas_io::points::read_curve_coordinates_with(&path, &options))
        .map_err(read_error)?;
    crate::errors::warn_all(py, &path, &read.warnings)?;
    let (flat, dim) = read.points;
    let rows = flat.len() / dim.max(1);
    PyArray1::from_vec(py, flat).reshape([rows, dim])
}

/// One column of ``columns=``: a position counted from 1 or a header name.
#[derive(FromPyObject)]
pub enum ColumnArg {
    /// A position counted from 1.
    Position(i64),
    /// A header name.
    Name(String),
}

/// The library's column choice of ``columns=``, or an ``OptionError`` naming what is wrong.
fn column_choice(
    columns: Option<Vec<ColumnArg>>,
) -> PyResult<Option<karkas_io::points::ColumnChoice>> {
    use karkas_io::points::{ColumnChoice, ColumnRef};
    let Some(columns) = columns else {
        return Ok(None);
    };
    let refs = columns
        .into_iter()
        .map(|c| match c {
            ColumnArg::Position(k) if k >= 1 => Ok(ColumnRef::Position(k as usize)),
            ColumnArg::Position(k) => Err(OptionError::new_err(format!(
                "columns: positions count from 1, got {k}"
            ))),
            ColumnArg::Name(name) => Ok(ColumnRef::Name(name)),
        })
        .collect::<PyResult<Vec<_>>>()?;
    let count = refs.len();
    ColumnChoice::new(refs).map(Some).ok_or_else(|| {
        OptionError::new_err(format!(
            "columns: give two or three columns (x, y and z; names or positions from 1), got \
             {count}"
        ))
    })
}

/// Reads an airfoil .dat file, Selig or Lednicer layout.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
///
/// Returns
/// -------
/// name : str
///     The name line, trimmed.
/// points : numpy.ndarray
///     float64, shape ``(n, 2)``: the contour in Selig order (trailing edge, upper surface,
///     leading edge, lower surface, trailing edge).
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened or read (``FileNotFoundError``, ``PermissionError``,
///     ``IsADirectoryError``, ...), with ``errno``, ``strerror`` and ``filename`` set.
/// FileFormatError
///     The content is not an airfoil.
///
/// Examples
/// --------
/// >>> _ = open("wing.dat", "w").write("WING\n1 0\n0.5 0.1\n0 0\n0.5 -0.1\n1 0\n")
/// >>> name, points = karkas.read_airfoil("wing.dat")
/// >>> name, points.shape
/// ('WING', (5, 2))
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_airfoil(py: Python<'_>, path: PathBuf) -> PyResult<(String, Bound<'_, PyArray2<f64>>)> {
    let path = file_path(path)?;
    let airfoil = py
        .detach(|| {
            let text = karkas_io::input::read_text(&path)?;
            karkas_io::airfoil::parse_airfoil(&text, &path)
        })
        .map_err(read_error)?;
    let points = points_array(py, airfoil.points)?;
    Ok((airfoil.name, points))
}

/// Reads a surface frame, CSV rows ``i,j,x,y,z``, as the command line's ``surface`` commands
/// do.
///
/// A header names the columns; rows may come in any order; every cell of the ``m x n`` grid
/// is given once.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
///
/// Returns
/// -------
/// numpy.ndarray
///     float64, shape ``(m, n, 3)``; ``grid[i, j]`` is the point of cell ``(i, j)``.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened or read (``FileNotFoundError``, ``PermissionError``,
///     ``IsADirectoryError``, ...), with ``errno``, ``strerror`` and ``filename`` set.
/// FileFormatError
///     The content cannot be read (the message names the line or the grid cell).
///
/// Examples
/// --------
/// >>> rows = ["i,j,x,y,z"] + [f"{i},{j},{i},{j},{i * j}" for i in range(2) for j in range(3)]
/// >>> _ = open("grid.csv", "w").write("\n".join(rows) + "\n")
/// >>> g = karkas.read_grid("grid.csv")
/// >>> g.shape, g[1, 2]
/// ((2, 3, 3), array([1., 2., 2.]))
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_grid(py: Python<'_>, path: PathBuf) -> PyResult<Bound<'_, PyArray3<f64>>> {
    let path = file_path(path)?;
    let grid = py
        .detach(|| karkas_io::grid::read_grid(&path))
        .map_err(read_error)?;
    let (rows, cols) = (grid.rows(), grid.cols());
    PyArray1::from_vec(py, flat_points(grid.into_vec())).reshape([rows, cols, 3])
}

/// Reads one family of curves of a curve network, CSV rows ``curve,x,y,z``, as ``surface
/// coons`` does.
///
/// A header names the columns; curves are numbered from 0 without gaps, each curve's points
/// together, in their order along the curve.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
///
/// Returns
/// -------
/// list of numpy.ndarray
///     Item ``c`` is curve ``c``, float64 ``(k, 3)``.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened or read (``FileNotFoundError``, ``PermissionError``,
///     ``IsADirectoryError``, ...), with ``errno``, ``strerror`` and ``filename`` set.
/// FileFormatError
///     The content cannot be read.
///
/// Examples
/// --------
/// >>> text = "curve,x,y,z\n0,0,0,0\n0,0,1,0\n1,1,0,0\n1,1,1,0\n1,1,2,0\n"
/// >>> _ = open("v.csv", "w").write(text)
/// >>> [c.shape for c in karkas.read_network("v.csv")]
/// [(2, 3), (3, 3)]
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_network(py: Python<'_>, path: PathBuf) -> PyResult<Vec<Bound<'_, PyArray2<f64>>>> {
    let path = file_path(path)?;
    let family = py
        .detach(|| karkas_io::network::read_curve_family(&path))
        .map_err(read_error)?;
    family
        .curves
        .into_iter()
        .map(|curve| points_array(py, curve))
        .collect()
}

/// Reads a triangle mesh: .obj, .stl (binary or ASCII) or .ply by the file's extension, as
/// ``convert`` does.
///
/// Parameters
/// ----------
/// path : str or os.PathLike
///     The file.
///
/// Returns
/// -------
/// vertices : numpy.ndarray
///     float64, shape ``(n, 3)``.
/// faces : numpy.ndarray
///     int64, shape ``(m, 3)``, indexing ``vertices`` from 0.
///
/// Raises
/// ------
/// OSError
///     The file cannot be opened or read (``FileNotFoundError``, ``PermissionError``,
///     ``IsADirectoryError``, ...), with ``errno``, ``strerror`` and ``filename`` set.
/// FileFormatError
///     The content cannot be read, or the mesh has no faces.
///
/// Examples
/// --------
/// >>> grid = np.array([[[i, j, 0.0] for j in range(3)] for i in range(2)])
/// >>> karkas.export_obj("patch.obj", grid)
/// >>> vertices, faces = karkas.read_mesh("patch.obj")
/// >>> vertices.shape, faces.shape, faces.dtype
/// ((6, 3), (4, 3), dtype('int64'))
#[pyfunction]
#[pyo3(text_signature = "(path)")]
pub fn read_mesh(py: Python<'_>, path: PathBuf) -> PyResult<MeshArrays<'_>> {
    let path = file_path(path)?;
    let mesh = py
        .detach(|| karkas_io::mesh::read_mesh(&path))
        .map_err(read_error)?;
    let faces: Vec<i64> = mesh
        .triangles
        .iter()
        .flat_map(|t| t.map(i64::from))
        .collect();
    let m = mesh.triangles.len();
    let vertices = points_array(py, mesh.positions)?;
    let faces = PyArray1::from_vec(py, faces).reshape([m, 3])?;
    Ok((vertices, faces))
}

/// The vertices `(n, 3)` and faces `(m, 3)` of a mesh.
type MeshArrays<'py> = (Bound<'py, PyArray2<f64>>, Bound<'py, PyArray2<i64>>);

/// Sets the most memory one read may keep, in bytes, for every reader of the process.
///
/// What a read keeps is the points it returns, or the text of a file read whole. The default
/// is 2 GiB, as the command line's ``--max-memory``. A larger input raises
/// ``FileFormatError`` instead of exhausting the machine.
///
/// Parameters
/// ----------
/// nbytes : int
///     The cap, positive and below 2^64.
///
/// Returns
/// -------
/// None
///
/// Raises
/// ------
/// OptionError
///     ``nbytes`` is not positive or too large.
///
/// Examples
/// --------
/// >>> old = karkas.max_input_bytes()
/// >>> karkas.set_max_input_bytes(10)
/// >>> _ = open("c.csv", "w").write("x,y\n0,0\n1,2\n2,1\n")
/// >>> karkas.read_curve("c.csv")
/// Traceback (most recent call last):
/// ...
/// karkas.FileFormatError: ...
/// >>> karkas.set_max_input_bytes(old)
#[pyfunction]
#[pyo3(text_signature = "(nbytes)")]
pub fn set_max_input_bytes(nbytes: i128) -> PyResult<()> {
    let bytes = u64::try_from(nbytes)
        .ok()
        .filter(|&b| b > 0)
        .ok_or_else(|| {
            OptionError::new_err(format!(
                "nbytes must be a positive number of bytes below 2^64 (got {nbytes})"
            ))
        })?;
    karkas_io::input::set_max_input_bytes(bytes);
    Ok(())
}

/// The most memory one read may keep, in bytes (see ``set_max_input_bytes``).
///
/// Returns
/// -------
/// int
///     The cap in bytes (2 GiB unless set).
///
/// Examples
/// --------
/// >>> karkas.max_input_bytes() >= 1
/// True
#[pyfunction]
#[pyo3(text_signature = "()")]
pub fn max_input_bytes() -> u64 {
    karkas_io::input::max_input_bytes()
}

/// The path to read: `-` names the file `./-` (the readers would take it for standard
/// input). A directory is refused here as `IsADirectoryError`, the error Python's `open`
/// gives, before any reader sees it.
pub(crate) fn file_path(path: PathBuf) -> PyResult<PathBuf> {
    let path = if karkas_io::input::is_stdin(&path) {
        Path::new(".").join(&path)
    } else {
        path
    };
    if std::fs::metadata(&path).is_ok_and(|m| m.is_dir()) {
        return Err(PyOSError::new_err((
            EISDIR,
            "Is a directory",
            os_name(&path),
        )));
    }
    Ok(path)
}

/// The error number Python maps to `IsADirectoryError` (`errno.EISDIR`, 21 on every platform
/// Python supports).
const EISDIR: i32 = 21;

/// `path` as Python's `filename` attribute takes it (`str`, undecodable bytes escaped).
fn os_name(path: &Path) -> std::ffi::OsString {
    path.as_os_str().to_os_string()
}

/// A read error as the Python exception of its kind: an open or read failure of the operating
/// system as `OSError` (see [`os_error`]), anything else as `karkas.FileFormatError` with the
/// command line's one-line message.
pub(crate) fn read_error(e: IoError) -> PyErr {
    match &e {
        IoError::Open { path, source } => os_error(path, source),
        _ => FileFormatError::new_err(error_line(&e)),
    }
}

/// `OSError(errno, strerror, filename)`, which Python turns into the subclass of the error
/// number (`FileNotFoundError`, `PermissionError`, ...), as its own `open` raises; an error
/// without a number keeps its kind's subclass and carries karkas-io's message.
fn os_error(path: &Path, source: &std::io::Error) -> PyErr {
    match source.raw_os_error() {
        Some(errno) => {
            let text = source.to_string();
            let suffix = format!(" (os error {errno})");
            let strerror = text.strip_suffix(&suffix).unwrap_or(&text).to_owned();
            PyOSError::new_err((errno, strerror, os_name(path)))
        }
        None => PyErr::from(std::io::Error::new(
            source.kind(),
            format!("cannot read {}: {source}", path.display()),
        )),
    }
}

/// The message of `error` as the command line prints it (after `karkas: error: `): its text,
/// then each cause whose text is not already in the line, joined by `": "`.
fn error_line(error: &(dyn std::error::Error + 'static)) -> String {
    let mut line = String::new();
    let mut cause = Some(error);
    while let Some(e) = cause {
        let text = e.to_string();
        if !text.is_empty() && !line.contains(&text) {
            if !line.is_empty() {
                line.push_str(": ");
            }
            line.push_str(&text);
        }
        cause = e.source();
    }
    line
}

/// Points as a flat coordinate vector: the same memory reinterpreted (a `Point<D>` is
/// `[f64; D]`, so the cast cannot fail; were it refused, the coordinates are copied).
pub(crate) fn flat_points<const D: usize>(points: Vec<Point<D>>) -> Vec<f64> {
    bytemuck::allocation::try_cast_vec(points)
        .unwrap_or_else(|(_, points)| points.iter().flat_map(|p| p.0).collect())
}

/// An `(n, D)` float64 array owning the memory of `points` (no copy).
pub(crate) fn points_array<const D: usize>(
    py: Python<'_>,
    points: Vec<Point<D>>,
) -> PyResult<Bound<'_, PyArray2<f64>>> {
    let n = points.len();
    PyArray1::from_vec(py, flat_points(points)).reshape([n, D])
}

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

//! Exports through karkas-io's writers.
//!
//! - `export_obj`, `export_stl`, `export_curve_csv`, `export_surface_csv`: OBJ and binary STL
//!   meshes of sampled surfaces, CSV of curve and surface samples. Files are written atomically
//!   (nothing is left behind on failure); a file that cannot be written raises `OSError`.
//! - What `karkas.export` shares between its writers: its options, the choice of the output
//!   format (by `format=` or the extension, as the command line chooses), the Python exception
//!   of a write error, and arrays read as float64 NumPy arrays and lifted into space.
//! - `karkas.export(obj, path, ...)`: any curve, surface, discrete periodic spline or tube,
//!   point list, grid or triangle mesh written in every format the command line writes for that
//!   kind of result, the format chosen by the extension as the command line chooses it (or by
//!   `format=`). The writing itself is karkas-io's ([`karkas_io::export`]), the command line's
//!   own, so that the files are the same byte for byte; every file is written atomically (an
//!   error leaves an existing file as it was).
//! - The exact B-spline forms [`export`] writes as STEP or IGES: a curve's or a surface's
//!   `to_bspline()` (SciPy's `(t, c, k)` and `((tu, tv), c, (ku, kv))`), and SciPy's own
//!   `BSpline` and `NdBSpline` objects.

use std::path::{Path, PathBuf};

use karkas::bspline::{BSplineCurve, BSplineSurface};
use karkas::geometry::mesh_parameters::DEFAULT_RELATIVE_TOLERANCE;
use karkas::geometry::{mesh_parameters, surface_size};
use karkas::{Grid, Point, Point3};
use karkas_io::cad::CadShell;
use karkas_io::export::cad::{
    write_cad_curve, write_cad_curve_with_points, write_cad_shell, write_cad_surface, CadUnits,
    NO_EXACT_FORM,
};
use karkas_io::export::curve::{
    write_curve, write_curve_figure, write_discrete_curve, CurveDrawing, DiscreteTitles,
};
use karkas_io::export::formats::{
    CURVE_FORMATS, EXACT_CURVE_FORMATS, EXACT_SURFACE_FORMATS, MESH_FORMATS, POINTS_FORMATS,
    SURFACE_FORMATS,
};
use karkas_io::export::mesh::write_triangle_mesh;
use karkas_io::export::samples::{
    default_curve_samples, default_surface_samples, sample_surface, MAX_SAMPLES,
};
use karkas_io::export::surface::{
    write_sampled_surface, write_surface, write_surface_at, SurfaceDrawing,
};
use karkas_io::mesh::{body_mesh, write_mesh_as, MeshOptions, TriangleMesh};
use karkas_io::obj::write_surface_obj;
use karkas_io::stl::write_surface_stl;
use karkas_io::svg::CurveOverlay;
use karkas_io::write::{write_curve_csv, write_indexed_grid_csv, write_surface_csv};
use karkas_io::{IoError, OutputFormat};
use numpy::PyReadonlyArray2;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::convert::{
    as_points, by_dim, check_dim, check_dim3, extract_vector, GridArray, PointsArray,
};
use crate::curve::PyCurve;
use crate::dps::{PyDiscreteSpline, PyTubeSurface};
use crate::erased::{CurveView, SurfaceView};
use crate::errors::{
    file_error, library_error, IncompatibleDataError, KarkasError, OptionError, PointsError,
};
use crate::surface::PySurface;

/// A (nu, nv, 3) grid of points (3-D only), as its shape and points.
fn space_grid(grid: &Bound<'_, PyAny>) -> PyResult<(usize, usize, Vec<Point3>)> {
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
    let (nu, nv, points) = space_grid(grid)?;
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
    let (nu, nv, points) = space_grid(grid)?;
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
    let (_, _, points) = space_grid(grid)?;
    py.detach(|| write_surface_csv(&path, &us, &vs, &points))
        .map_err(write_error)
}

/// What the options of `karkas.export` say about a drawing and a mesh.
pub struct Options {
    pub(crate) format: Option<String>,
    pub(crate) samples: Option<(usize, usize)>,
    pub(crate) title: Option<String>,
    pub(crate) points: Option<(Vec<f64>, usize)>,
    pub(crate) closed_points: bool,
    pub(crate) net: Option<Grid<Point3>>,
    pub(crate) comb: bool,
    pub(crate) mesh: MeshOptions,
    /// `mesh_tolerance=`: meshes of surfaces within it (None: the default).
    pub(crate) mesh_tolerance: Option<f64>,
}

/// The format of `path` among `allowed`: `options.format` by name, else the extension; STEP,
/// IGES and DXF asked of a kind without them are refused with `no_exact` (DXF of a kind with
/// STEP, a surface, as curves only), and a mesh of a kind without one (a curve) says so.
pub fn choose(
    path: &Path,
    options: &Options,
    allowed: &[OutputFormat],
    no_exact: &str,
) -> PyResult<OutputFormat> {
    let what = if allowed.contains(&OutputFormat::Dxf) {
        "a curve"
    } else {
        "this object"
    };
    let format = match &options.format {
        Some(name) => named(name)?,
        None => {
            let all = OutputFormat::ALL;
            OutputFormat::from_path(path, &all).map_err(|e| OptionError::new_err(e.to_string()))?
        }
    };
    if format == OutputFormat::Dxf
        && allowed.contains(&OutputFormat::Step)
        && !allowed.contains(&format)
    {
        return Err(OptionError::new_err(format!(
            "{}: DXF is written for curves only (write .step or .iges)",
            path.display()
        )));
    }
    if OutputFormat::MESHES.contains(&format)
        && !allowed.iter().any(|f| OutputFormat::MESHES.contains(f))
    {
        let names: Vec<String> = allowed
            .iter()
            .map(|f| format!(".{}", f.extension()))
            .collect();
        return Err(OptionError::new_err(format!(
            "{}: {what} has no mesh form (.{} is a mesh, made of surfaces, grids and triangle \
             meshes): write {}",
            path.display(),
            format.extension(),
            names.join(", ")
        )));
    }
    if format.is_cad() && !allowed.contains(&format) {
        return Err(OptionError::new_err(format!(
            "{}: {no_exact}",
            path.display()
        )));
    }
    let format = format
        .allowed_for(path, allowed)
        .map_err(|e| OptionError::new_err(e.to_string()))?;
    if options.mesh.flip_normals && !OutputFormat::MESHES.contains(&format) {
        return Err(OptionError::new_err(format!(
            "flip_normals: only meshes (.obj .stl .ply .vtk .vts .glb) have normals to flip, \
             not .{}",
            format.extension()
        )));
    }
    Ok(format)
}

/// The format named `name` (an extension, with or without its dot, or its alias).
fn named(name: &str) -> PyResult<OutputFormat> {
    let name = name.trim_start_matches('.');
    OutputFormat::ALL
        .into_iter()
        .find(|f| {
            name.eq_ignore_ascii_case(f.extension())
                || f.alias().is_some_and(|a| name.eq_ignore_ascii_case(a))
        })
        .ok_or_else(|| {
            let names: Vec<&str> = OutputFormat::ALL.iter().map(|f| f.extension()).collect();
            OptionError::new_err(format!(
                "format {name:?}: unknown (one of {})",
                names.join(", ")
            ))
        })
}

/// A write error of karkas-io as the Python exception of its kind: `OSError` when the
/// operating system refused the file, a `KarkasError` subclass (a `ValueError`) when the data
/// cannot be written: parameters and points of different counts `IncompatibleDataError`, a
/// mesh that fails its checks `PointsError`, an unknown extension `OptionError`.
pub fn write_error(e: IoError) -> PyErr {
    match e {
        IoError::Write { .. } | IoError::Open { .. } => file_error(e),
        IoError::UnknownExtension { .. } => OptionError::new_err(e.to_string()),
        IoError::Geometry(g) => library_error(g.source),
        IoError::LengthMismatch { .. } => IncompatibleDataError::new_err(e.to_string()),
        IoError::InvalidMesh { .. } => PointsError::new_err(e.to_string()),
        other => KarkasError::new_err(other.to_string()),
    }
}

/// `obj` as a float64 NumPy array (lists, tuples and other arrays converted).
pub fn numpy_array<'py>(obj: &Bound<'py, PyAny>) -> PyResult<Bound<'py, PyAny>> {
    obj.py()
        .import("numpy")?
        .call_method1("ascontiguousarray", (obj, "float64"))
}

/// A `(nu, nv, 3)` grid (a 2-D grid in `z = 0`).
pub fn grid3(obj: &Bound<'_, PyAny>) -> PyResult<Grid<Point3>> {
    let array = numpy_array(obj)?;
    let (g, dim) = GridArray::extract_checked(&array, "grid")?;
    by_dim!(dim, D => Ok(lift_grid(&g.grid::<D>()?)))
}

/// Points of any dimension in space (`z = 0` for planar ones).
pub fn lift<const D: usize>(p: &Point<D>) -> Point3 {
    let mut q = Point3::ZERO;
    q.0[..D].copy_from_slice(&p.0);
    q
}

/// A grid of any dimension in space.
pub fn lift_grid<const D: usize>(g: &Grid<Point<D>>) -> Grid<Point3> {
    Grid::from_fn(g.rows(), g.cols(), |i, j| lift(g.get(i, j)))
}

/// Writes `obj` to `path` in the format of its extension (or `format`), as the command line
/// writes the same result.
///
/// Parameters
/// ----------
/// obj : Curve, Surface, DiscreteSpline, TubeSurface, array_like or tuple
///     A curve (any `Curve`: CSV ``t,x,y[,z]``, SVG, PNG, HTML, STEP, IGES, DXF), a surface (any
///     `Surface`: CSV ``u,v,x,y,z``, OBJ, STL, PLY, VTK, VTS, GLB, SVG, PNG, HTML, STEP,
///     IGES), a `DiscreteSpline` (its values: CSV, SVG, PNG, HTML), a `TubeSurface` (CSV of
///     its values, meshes, pictures, HTML), a point list ``(n, d)`` (SVG, PNG, HTML), a grid
///     ``(nu, nv, 3)`` (CSV ``i,j,x,y,z``, meshes, pictures, HTML) or a triangle mesh
///     ``(vertices (n, 3), faces (m, 3))`` as `read_mesh` returns it (OBJ, STL, PLY, VTK, GLB,
///     HTML).
/// path : str or os.PathLike
///     The file to write; its extension names the format (``.stp``, ``.igs`` too).
/// format : str, optional
///     The format by name (``"csv"``, ``"step"``, ...), whatever the extension.
/// samples : int or (int, int), optional
///     Samples of a curve (default 10 per point of `points`, else per piece, at least 200)
///     or of a surface per direction (default 4 per line of `net`, at least 50).
/// title : str, optional
///     The caption of pictures and of the viewer page (default: the object's repr).
/// points : array_like, optional
///     Input points ``(n, d)`` drawn over a curve in pictures and on the page, and written
///     as POINT entities on layer ``POINTS`` of a DXF.
/// closed_points : bool, default False
///     Draw `points` as a closed polygon.
/// net : array_like, optional
///     An input grid or control net ``(nu, nv, 3)`` shown on the viewer page of a surface.
/// comb : bool, default False
///     Draw the curvature comb in curve pictures (the command line's ``--comb``).
/// ascii : bool, default False
///     Write STL and PLY as text instead of binary.
/// flip_normals : bool, default False
///     Turn meshes over (reverse the triangles' winding and the normals).
/// mesh_tolerance : float, optional
///     Meshes of a surface (OBJ, STL, PLY, VTK, VTS, GLB) without ``samples``: sampled
///     densely where the surface bends and sparsely where it does not, so that the mesh lies
///     within this distance of it (model units; the command line's ``--mesh-tolerance``).
///     Default: ``1e-4`` of the surface's size (the diagonal of its bounding box).
/// cap : bool, default False
///     A surface in STEP, IGES or a triangle mesh (OBJ, STL, PLY, GLB): close every open
///     boundary loop that lies in a plane (a wing's root and tip, a tube's ends) with a planar
///     face, as the command line's ``--cap``. STEP then holds a closed solid
///     (``MANIFOLD_SOLID_BREP``), IGES the faces and the caps (trimmed planes), meshes are
///     closed and turned outwards, sampled uniformly (``samples``). A body closed by its poles
///     and seams is written as a solid without it.
///
/// Returns
/// -------
/// pathlib.Path
///     The path written.
///
/// Raises
/// ------
/// karkas.OptionError
///     The extension or `format` is not one the object can be written in; STEP, IGES or DXF
///     for an object without an exact piecewise polynomial form (discrete periodic splines,
///     point lists, grids, meshes); DXF for a surface; `flip_normals` for a format that is not
///     a mesh; `points` of another dimension than a curve's; `cap` for an object that is not a
///     surface, a format that holds no body, with `mesh_tolerance`, or a surface whose open
///     boundary is not a planar loop (or that has none).
/// TypeError
///     `obj` is none of the kinds above.
/// OSError
///     The file cannot be written (an existing file is left as it was).
///
/// Examples
/// --------
/// >>> import os, tempfile, numpy as np, karkas
/// >>> c = karkas.LLCurve(np.array([[0., 0.], [1., 1.], [2., 0.], [3., 1.]]))
/// >>> d = tempfile.mkdtemp()
/// >>> karkas.export(c, os.path.join(d, "c.csv"), samples=5).name
/// 'c.csv'
/// >>> open(os.path.join(d, "c.csv")).readline().strip()
/// 't,x,y'
///
/// A surface meshed within a tolerance: rows dense where it bends, sparse elsewhere.
///
/// >>> u, v = np.meshgrid(np.linspace(0, np.pi, 9), np.linspace(0, 2, 5), indexing="ij")
/// >>> S = karkas.BicubicSurface(np.stack([np.cos(u), np.sin(u), v], axis=-1))
/// >>> _ = karkas.export(S, os.path.join(d, "s.stl"), mesh_tolerance=1e-3)
/// >>> try:
/// ...     karkas.export(c, os.path.join(d, "c.stl"))
/// ... except karkas.OptionError as e:
/// ...     print(str(e).split(": ", 1)[1])
/// a curve has no mesh form (.stl is a mesh, made of surfaces, grids and triangle meshes): write .csv, .svg, .png, .html, .step, .iges, .dxf
///
/// A tube capped at both ends: a closed solid in STEP, a closed mesh in STL.
///
/// >>> t = np.linspace(0, 2 * np.pi, 13)[:-1]
/// >>> rings = np.array([[[np.cos(a), np.sin(a), z] for a in t] for z in (0.0, 1.0, 2.0)])
/// >>> tube = karkas.BicubicSurface(rings, closed_v=True)
/// >>> _ = karkas.export(tube, os.path.join(d, "tube.step"), cap=True)
/// >>> "MANIFOLD_SOLID_BREP" in open(os.path.join(d, "tube.step")).read()
/// True
/// >>> _ = karkas.export(tube, os.path.join(d, "tube.stl"), cap=True, samples=(20, 60))
#[pyfunction]
#[pyo3(signature = (obj, path, *, format = None, samples = None, title = None, points = None, closed_points = false, net = None, comb = false, ascii = false, flip_normals = false, mesh_tolerance = None, cap = false))]
#[pyo3(
    text_signature = "(obj, path, *, format=None, samples=None, title=None, points=None, closed_points=False, net=None, comb=False, ascii=False, flip_normals=False, mesh_tolerance=None, cap=False)"
)]
#[allow(clippy::too_many_arguments)]
pub fn export(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    path: PathBuf,
    format: Option<String>,
    samples: Option<&Bound<'_, PyAny>>,
    title: Option<String>,
    points: Option<&Bound<'_, PyAny>>,
    closed_points: bool,
    net: Option<&Bound<'_, PyAny>>,
    comb: bool,
    ascii: bool,
    flip_normals: bool,
    mesh_tolerance: Option<f64>,
    cap: bool,
) -> PyResult<PathBuf> {
    if let Some(t) = mesh_tolerance {
        if !(t > 0.0 && t.is_finite()) {
            return Err(OptionError::new_err(format!(
                "mesh_tolerance must be positive and finite (model units), got {t}"
            )));
        }
    }
    let options = Options {
        mesh_tolerance,
        format,
        samples: samples.map(sample_counts).transpose()?,
        title,
        points: points.map(flat_points).transpose()?,
        closed_points,
        net: net.map(grid3).transpose()?,
        comb,
        mesh: MeshOptions {
            ascii,
            flip_normals,
        },
    };
    let request = Request(py, obj, &path, &options);
    if cap {
        let Ok(surface) = obj.cast::<PySurface>() else {
            return Err(OptionError::new_err(
                "cap: only surfaces have boundary loops to cap",
            ));
        };
        request.capped(surface.get())?;
    } else if let Ok(curve) = obj.cast::<PyCurve>() {
        request.curve(curve.get())?;
    } else if let Ok(surface) = obj.cast::<PySurface>() {
        request.surface(surface.get())?;
    } else if obj.cast::<PyDiscreteSpline>().is_ok() {
        request.discrete()?;
    } else if obj.cast::<PyTubeSurface>().is_ok() {
        request.tube()?;
    } else if ["t", "c", "k"]
        .iter()
        .all(|a| obj.hasattr(*a).unwrap_or(false))
    {
        request.scipy_spline()?;
    } else if let Ok(tuple) = obj.cast::<PyTuple>() {
        request.mesh(tuple)?;
    } else {
        request.array()?;
    }
    Ok(path)
}

/// The caption: `options.title`, else what is drawn: the object as its repr describes it
/// (without the angle brackets, the module and the domain) and the input points drawn over
/// it, e.g. `LLCurve order=3, closed=False, 12 points in 2-D; its 12 input points in red`.
fn title_of(obj: &Bound<'_, PyAny>, options: &Options) -> PyResult<String> {
    if let Some(t) = &options.title {
        return Ok(t.clone());
    }
    let repr = obj.repr()?.to_string();
    let what = repr
        .trim_start_matches('<')
        .trim_end_matches('>')
        .trim_start_matches("karkas.");
    let what = what.split(", domain=").next().unwrap_or(what);
    Ok(match &options.points {
        Some((flat, dim)) if *dim > 0 => {
            format!("{what}; its {} input points in red", flat.len() / dim)
        }
        _ => what.to_owned(),
    })
}

/// `samples=`: a count, or a pair of counts (a single count for both directions of a
/// surface), each from 2 to [`MAX_SAMPLES`] (a surface checks `nu * nv` too).
fn sample_counts(obj: &Bound<'_, PyAny>) -> PyResult<(usize, usize)> {
    let (a, b) = match obj.extract::<usize>() {
        Ok(n) => (n, n),
        Err(_) => obj.extract::<(usize, usize)>().map_err(|_| {
            OptionError::new_err("samples must be a positive count or a pair of counts")
        })?,
    };
    if a < 2 || b < 2 {
        return Err(OptionError::new_err(format!(
            "samples must be at least 2, got {a}, {b}"
        )));
    }
    if a > MAX_SAMPLES || b > MAX_SAMPLES {
        return Err(OptionError::new_err(format!(
            "samples: at most {MAX_SAMPLES} samples can be written"
        )));
    }
    Ok((a, b))
}

/// `points=`: the flat coordinates and the dimension.
fn flat_points(obj: &Bound<'_, PyAny>) -> PyResult<(Vec<f64>, usize)> {
    let array = numpy_array(obj)?;
    let (pts, dim) = PointsArray::extract_checked(&array, "points")?;
    Ok((pts.flat().into_owned(), dim))
}

/// The flat coordinates of `points=` (none: empty), refused unless of dimension `dim`, that
/// of `what` they are drawn over.
fn input_points(options: &Options, dim: usize, what: &str) -> PyResult<Vec<f64>> {
    match &options.points {
        Some((_, d)) if *d != dim => Err(OptionError::new_err(format!(
            "points have {d} coordinates, {what} {dim}"
        ))),
        Some((flat, _)) => Ok(flat.clone()),
        None => Ok(Vec::new()),
    }
}

/// The sample counts of a surface: `samples=`, else the default for `net=`'s lines (or for
/// none), refused when `nu * nv` exceeds [`MAX_SAMPLES`].
fn surface_counts(options: &Options) -> PyResult<(usize, usize)> {
    let (nu, nv) = options.samples.unwrap_or_else(|| match &options.net {
        Some(net) => (
            default_surface_samples(net.rows()),
            default_surface_samples(net.cols()),
        ),
        None => (default_surface_samples(0), default_surface_samples(0)),
    });
    if nu.saturating_mul(nv) > MAX_SAMPLES {
        return Err(OptionError::new_err(format!(
            "samples: at most {MAX_SAMPLES} samples can be written"
        )));
    }
    Ok((nu, nv))
}

/// What `karkas.export` was asked, with the interpreter's token: the object to write, the
/// file and the options.
#[derive(Clone, Copy)]
struct Request<'a, 'py>(Python<'py>, &'a Bound<'py, PyAny>, &'a Path, &'a Options);

impl Request<'_, '_> {
    /// A curve: sampled (CSV, pictures, page) or its exact B-spline form (STEP, IGES).
    fn curve(&self, curve: &PyCurve) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let no_exact = "this curve has no exact piecewise polynomial form";
        let format = choose(path, options, &EXACT_CURVE_FORMATS, no_exact)?;
        let dim = curve.inner.dim();
        if format.is_cad() {
            let (knots, control, degree, cdim) = bspline_curve(obj, no_exact)?;
            let input = input_points(options, cdim, "the curve")?;
            return by_dim!(cdim, D => {
                let b = BSplineCurve::<D>::new(degree, knots, as_points::<D>(&control).to_vec())
                    .map_err(library_error)?;
                let input = as_points::<D>(&input);
                py.detach(|| {
                    write_cad_curve_with_points(&b, input, format, path, path).map(|_| ())
                })
                .map_err(write_error)
            });
        }
        let title = title_of(obj, options)?;
        let input = input_points(options, dim, "the curve")?;
        let n = match options.samples {
            Some((n, _)) => n,
            None => default_curve_samples(if input.is_empty() {
                curve.inner.breakpoints().len().saturating_sub(1)
            } else {
                input.len() / dim
            }),
        };
        let inner = &*curve.inner;
        by_dim!(dim, D => {
            let drawing = CurveDrawing {
                title: &title,
                input: as_points::<D>(&input),
                closed_input: options.closed_points,
                comb: options.comb,
            };
            py.detach(|| write_curve(&CurveView::<D>(inner), n, format, path, &drawing))
                .map_err(write_error)
        })
    }

    /// A surface: sampled (CSV, meshes, pictures, page) or its exact B-spline form.
    fn surface(&self, surface: &PySurface) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let (format, exact) = surface_format(obj, path, options)?;
        if let Some(b) = exact {
            return py
                .detach(|| write_cad_surface(&b, format, path))
                .map_err(write_error);
        }
        let counts = surface_counts(options)?;
        let title = title_of(obj, options)?;
        let view = SurfaceView(&*surface.inner);
        if OutputFormat::MESHES.contains(&format) && options.samples.is_none() {
            return export_mesh_within(py, &view, format, path, &title, options);
        }
        let drawing = SurfaceDrawing {
            title: &title,
            net: options.net.as_ref(),
            mesh: options.mesh,
        };
        py.detach(|| write_sampled_surface(&view, counts, format, path, &drawing))
            .map_err(write_error)
    }

    /// A surface with its open planar boundary loops capped (`cap=True`, the command line's
    /// `--cap`): STEP or IGES as a shell of its B-spline face and planar caps (a solid when it
    /// closes, turned outwards), or a closed triangle mesh sampled uniformly
    /// ([`body_mesh`]). Other formats, `mesh_tolerance`, and loops that are not planar (or none)
    /// are refused naming `cap`.
    fn capped(&self, surface: &PySurface) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let (format, exact) = surface_format(obj, path, options)?;
        let refuse = |why: String| OptionError::new_err(format!("cap: {why}"));
        if let Some(b) = exact {
            return py.detach(|| {
                let mut shell = CadShell::of_surfaces(std::slice::from_ref(&b));
                shell.cap_free_loops().map_err(|e| refuse(e.to_string()))?;
                if shell.is_closed() {
                    shell.orient_outward();
                }
                let unit = CadUnits::default().cad_unit();
                write_cad_shell(&shell, format, path, unit).map_err(write_error)
            });
        }
        if !matches!(
            format,
            OutputFormat::Obj | OutputFormat::Stl | OutputFormat::Ply | OutputFormat::Glb
        ) {
            return Err(refuse(format!(
                "only STEP, IGES and the triangle meshes (.step .iges .obj .stl .ply .glb) hold \
             caps, not .{}",
                format.extension()
            )));
        }
        if options.mesh_tolerance.is_some() {
            return Err(refuse(
                "capped meshes are sampled uniformly (samples), not to mesh_tolerance".to_string(),
            ));
        }
        let (nu, nv) = surface_counts(options)?;
        let view = SurfaceView(&*surface.inner);
        py.detach(|| {
            let (_, _, samples) = sample_surface(&view, nu, nv);
            let grid = Grid::from_row_major(nu, nv, samples).map_err(library_error)?;
            let (body, _) = body_mesh(&grid, true).map_err(|e| refuse(e.to_string()))?;
            write_mesh_as(format, path, &body, &options.mesh).map_err(write_error)
        })
    }

    /// A discrete periodic spline: its values as CSV, a picture or the page; no exact form.
    fn discrete(&self) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let format = choose(path, options, &CURVE_FORMATS, NO_EXACT_FORM)?;
        let values = numpy_array(&obj.call_method0("values")?)?;
        let (pts, dim) = PointsArray::extract_checked(&values, "values")?;
        let flat = pts.flat().into_owned();
        let title = title_of(obj, options)?;
        let input = input_points(options, dim, "the spline")?;
        let titles = DiscreteTitles {
            picture: &title,
            page: &title,
        };
        by_dim!(dim, D => py
        .detach(|| write_discrete_curve(path, format, as_points::<D>(&flat), as_points::<D>(&input), &titles))
        .map_err(write_error))
    }

    /// A discrete periodic tube: the CSV of its values `p,q,x,y,z`, or its closed grid as a mesh,
    /// picture or page; no exact form.
    fn tube(&self) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let format = choose(path, options, &SURFACE_FORMATS, NO_EXACT_FORM)?;
        let title = title_of(obj, options)?;
        if format == OutputFormat::Csv {
            let values = grid3(&obj.call_method0("values")?)?;
            return py
                .detach(|| write_indexed_grid_csv(path, ["p", "q"], &values))
                .map_err(write_error);
        }
        let grid = grid3(&obj.call_method0("closed_grid")?)?;
        let drawing = SurfaceDrawing {
            title: &title,
            net: None,
            mesh: options.mesh,
        };
        py.detach(|| write_surface(path, format, &grid, &drawing))
            .map_err(write_error)
    }

    /// A point list `(n, d)` (drawn as a curve) or a grid `(nu, nv, 3)` (a frame: the page shows
    /// it as the net), as `karkas convert` writes them.
    fn array(&self) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let not_polynomial = "points and grids have no exact B-spline form";
        let array = numpy_array(obj).map_err(|_| not_exportable(obj))?;
        let ndim: usize = array.getattr("ndim")?.extract()?;
        let title = options.title.clone().unwrap_or_default();
        match ndim {
            2 => {
                let format = choose(path, options, &POINTS_FORMATS, not_polynomial)?;
                let (pts, dim) = PointsArray::extract_checked(&array, "points")?;
                let flat = pts.flat().into_owned();
                let overlay = CurveOverlay::default();
                by_dim!(dim, D => py
                .detach(|| write_curve_figure(path, format, &title, as_points::<D>(&flat), &[], false, &overlay))
                .map_err(write_error))
            }
            3 => {
                let format = choose(path, options, &SURFACE_FORMATS, not_polynomial)?;
                let grid = grid3(&array)?;
                let drawing = SurfaceDrawing {
                    title: &title,
                    net: Some(options.net.as_ref().unwrap_or(&grid)),
                    mesh: options.mesh,
                };
                py.detach(|| write_surface(path, format, &grid, &drawing))
                    .map_err(write_error)
            }
            _ => Err(not_exportable(obj)),
        }
    }

    /// A triangle mesh `(vertices (n, 3), faces (m, 3))`, as `read_mesh` returns it.
    fn mesh(&self, tuple: &Bound<'_, PyTuple>) -> PyResult<()> {
        let Request(py, _, path, options) = *self;
        if tuple.len() != 2 {
            return Err(not_exportable(tuple.as_any()));
        }
        let format = choose(
            path,
            options,
            &MESH_FORMATS,
            "meshes have no exact B-spline form",
        )?;
        let vertices = numpy_array(&tuple.get_item(0)?)?;
        let (pts, dim) = PointsArray::extract_checked(&vertices, "vertices")?;
        check_dim(dim, "vertices")?;
        let flat = pts.flat().into_owned();
        let positions: Vec<Point3> =
            by_dim!(dim, D => as_points::<D>(&flat).iter().map(lift).collect());
        let faces = py
            .import("numpy")?
            .call_method1("ascontiguousarray", (tuple.get_item(1)?, "int64"))?;
        let faces: PyReadonlyArray2<'_, i64> = faces
            .extract()
            .map_err(|_| PyTypeError::new_err("faces must be an (m, 3) integer array"))?;
        let faces = faces.as_array();
        if faces.ncols() != 3 {
            return Err(PyTypeError::new_err(
                "faces must be an (m, 3) integer array",
            ));
        }
        let n = positions.len().min(u32::MAX as usize) as i64;
        let mut triangles = Vec::with_capacity(faces.nrows());
        for (k, f) in faces.rows().into_iter().enumerate() {
            if f.iter().any(|&i| !(0..n).contains(&i)) {
                return Err(OptionError::new_err(format!(
                    "faces[{k}] = {f}: vertex indices from 0 to {} expected",
                    n - 1
                )));
            }
            triangles.push([f[0] as u32, f[1] as u32, f[2] as u32]);
        }
        let mesh = TriangleMesh {
            positions,
            normals: Vec::new(),
            triangles,
            grid: None,
        };
        let title = options.title.clone().unwrap_or_default();
        py.detach(|| write_triangle_mesh(path, format, mesh, &options.mesh, &title))
            .map_err(write_error)
    }

    /// A SciPy B-spline: `scipy.interpolate.BSpline` (coefficients `(n, d)`, `d` in {2, 3}) or
    /// `NdBSpline` of two variables (coefficients `(nu, nv, 3)`), written exactly as STEP or IGES
    /// (a curve also as DXF, without input points).
    fn scipy_spline(&self) -> PyResult<()> {
        let Request(py, obj, path, options) = *self;
        let only = "a SciPy B-spline is written as STEP, IGES or (a curve) DXF only";
        let format = choose(path, options, &OutputFormat::CURVE_CAD, only)?;
        let (t, c, k) = (obj.getattr("t")?, obj.getattr("c")?, obj.getattr("k")?);
        if let Ok((tu, tv)) = t.extract::<(Bound<'_, PyAny>, Bound<'_, PyAny>)>() {
            if format == OutputFormat::Dxf {
                return Err(OptionError::new_err(format!(
                    "{}: DXF is written for curves only (write .step or .iges)",
                    path.display()
                )));
            }
            let (ku, kv): (usize, usize) = k.extract()?;
            let b = surface_form((&tu, &tv), &c, (ku, kv))?;
            return py
                .detach(|| write_cad_surface(&b, format, path))
                .map_err(write_error);
        }
        let (knots, control, degree, dim) = curve_form(&t, &c, k.extract()?)?;
        by_dim!(dim, D => {
            let b = BSplineCurve::<D>::new(degree, knots, as_points::<D>(&control).to_vec())
                .map_err(library_error)?;
            py.detach(|| write_cad_curve(&b, format, path, path).map(|_| ()))
                .map_err(write_error)
        })
    }
}

/// The format of a surface's export and, for STEP and IGES, the surface's exact B-spline
/// form (refused for a surface without one).
fn surface_format(
    obj: &Bound<'_, PyAny>,
    path: &Path,
    options: &Options,
) -> PyResult<(OutputFormat, Option<BSplineSurface<3>>)> {
    let no_exact = "this surface has no exact piecewise polynomial form";
    let format = choose(path, options, &EXACT_SURFACE_FORMATS, no_exact)?;
    let exact = if format.is_cad() {
        Some(bspline_surface(obj, no_exact)?)
    } else {
        None
    };
    Ok((format, exact))
}

/// A surface as a mesh within `options.mesh_tolerance` (default
/// [`DEFAULT_RELATIVE_TOLERANCE`] of its size), sampled where it bends
/// ([`mesh_parameters`]), within `karkas.max_memory`.
fn export_mesh_within(
    py: Python<'_>,
    view: &SurfaceView<'_>,
    format: OutputFormat,
    path: &Path,
    title: &str,
    options: &Options,
) -> PyResult<()> {
    // A sample of a mesh: its point, normal, two triangles and the writer's arrays.
    const BYTES_PER_SAMPLE: u128 = 24 + 130;
    let budget = match crate::limits::current_cap(py)? {
        Some(cap) => usize::try_from(cap / BYTES_PER_SAMPLE).unwrap_or(usize::MAX),
        None => usize::MAX,
    }
    .min(MAX_SAMPLES);
    let drawing = SurfaceDrawing {
        title,
        net: options.net.as_ref(),
        mesh: options.mesh,
    };
    py.detach(|| {
        let tolerance = options
            .mesh_tolerance
            .unwrap_or_else(|| DEFAULT_RELATIVE_TOLERANCE * surface_size(view));
        let found = mesh_parameters(view, tolerance, budget);
        write_surface_at(view, (&found.us, &found.vs), format, path, &drawing)
    })
    .map_err(write_error)
}

/// The `TypeError` for an object [`export`] cannot write.
fn not_exportable(obj: &Bound<'_, PyAny>) -> PyErr {
    let kind = obj
        .get_type()
        .name()
        .map_or_else(|_| "?".to_owned(), |n| n.to_string());
    PyTypeError::new_err(format!(
        "export: cannot write a {kind} (a Curve, Surface, DiscreteSpline, TubeSurface, points \
         (n, d), grid (nu, nv, 3) or mesh (vertices, faces) is expected)"
    ))
}

/// The exact B-spline form `(t, c, k)` of `obj` by its `to_bspline()`, the control points
/// flat; objects without one are refused with `no_exact`.
pub fn bspline_curve(
    obj: &Bound<'_, PyAny>,
    no_exact: &str,
) -> PyResult<(Vec<f64>, Vec<f64>, usize, usize)> {
    if !obj.hasattr("to_bspline")? {
        return Err(OptionError::new_err(format!("STEP/IGES: {no_exact}")));
    }
    let (t, c, k): (Bound<'_, PyAny>, Bound<'_, PyAny>, usize) =
        obj.call_method0("to_bspline")?.extract()?;
    curve_form(&t, &c, k)
}

/// The knots, the flat control points (`len(t) - k - 1` of them: SciPy's convention allows
/// trailing unused coefficients), the degree and the dimension of the B-spline `(t, c, k)`.
fn curve_form(
    t: &Bound<'_, PyAny>,
    c: &Bound<'_, PyAny>,
    k: usize,
) -> PyResult<(Vec<f64>, Vec<f64>, usize, usize)> {
    let knots: Vec<f64> = numpy_array(t)?.call_method0("tolist")?.extract()?;
    let c = numpy_array(c)?;
    let (pts, dim) = PointsArray::extract_checked(&c, "control points")?;
    let mut control = pts.flat().into_owned();
    let count = knots.len().saturating_sub(k + 1);
    control.truncate(count * dim);
    Ok((knots, control, k, dim))
}

/// The exact B-spline surface of `obj` by its `to_bspline()`: `((tu, tv), c, (ku, kv))`.
pub fn bspline_surface(obj: &Bound<'_, PyAny>, no_exact: &str) -> PyResult<BSplineSurface<3>> {
    if !obj.hasattr("to_bspline")? {
        return Err(OptionError::new_err(format!("STEP/IGES: {no_exact}")));
    }
    type Form<'py> = (
        (Bound<'py, PyAny>, Bound<'py, PyAny>),
        Bound<'py, PyAny>,
        (usize, usize),
    );
    let ((tu, tv), c, k): Form<'_> = obj.call_method0("to_bspline")?.extract()?;
    surface_form((&tu, &tv), &c, k)
}

/// The B-spline surface of knots `(tu, tv)`, coefficients `c` `(nu, nv, 3)` (trailing unused
/// ones dropped) and degrees `(ku, kv)`.
fn surface_form(
    (tu, tv): (&Bound<'_, PyAny>, &Bound<'_, PyAny>),
    c: &Bound<'_, PyAny>,
    (ku, kv): (usize, usize),
) -> PyResult<BSplineSurface<3>> {
    let tu: Vec<f64> = numpy_array(tu)?.call_method0("tolist")?.extract()?;
    let tv: Vec<f64> = numpy_array(tv)?.call_method0("tolist")?.extract()?;
    let (nu, nv) = (
        tu.len().saturating_sub(ku + 1),
        tv.len().saturating_sub(kv + 1),
    );
    let c = numpy_array(c)?;
    let sliced = c.get_item((
        pyo3::types::PySlice::new(c.py(), 0, nu as isize, 1),
        pyo3::types::PySlice::new(c.py(), 0, nv as isize, 1),
    ))?;
    let control = grid3(&sliced)?;
    BSplineSurface::new((ku, tu), (kv, tv), control).map_err(library_error)
}

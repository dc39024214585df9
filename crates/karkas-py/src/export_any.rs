//! `karkas.export(obj, path, ...)`: any curve, surface, discrete periodic spline or tube, point
//! list, grid or triangle mesh written in every format the command line writes for that kind
//! of result, the format chosen by the extension as the command line chooses it (or by
//! `format=`). The writing itself is karkas-io's ([`karkas_io::export`]), the command line's
//! own, so that the files are the same byte for byte; every file is written atomically (an
//! error leaves an existing file as it was).

use std::path::{Path, PathBuf};

use karkas::bspline::BSplineCurve;
use karkas::geometry::mesh_parameters::DEFAULT_RELATIVE_TOLERANCE;
use karkas::geometry::{mesh_parameters, surface_size};
use karkas::{Grid, Point3};
use karkas_io::cad::CadShell;
use karkas_io::export::cad::{
    write_cad_curve_with_points, write_cad_shell, write_cad_surface, CadUnits, NO_EXACT_FORM,
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
use karkas_io::svg::CurveOverlay;
use karkas_io::write::write_indexed_grid_csv;
use karkas_io::OutputFormat;
use numpy::PyReadonlyArray2;
use pyo3::exceptions::PyTypeError;
use pyo3::prelude::*;
use pyo3::types::PyTuple;

use crate::adapters::{CurveView, SurfaceView};
use crate::convert::{as_points, by_dim, check_dim, PointsArray};
use crate::curve::PyCurve;
use crate::dps::{PyDiscreteSpline, PyTubeSurface};
use crate::errors::{library_error, OptionError};
use crate::export_cad::{bspline_curve, bspline_surface, export_scipy_spline};
use crate::export_format::{choose, grid3, lift, numpy_array, write_error, Options};
use crate::surface::PySurface;

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
    if cap {
        let Ok(surface) = obj.cast::<PySurface>() else {
            return Err(OptionError::new_err(
                "cap: only surfaces have boundary loops to cap",
            ));
        };
        export_capped(py, obj, surface.get(), &path, &options)?;
    } else if let Ok(curve) = obj.cast::<PyCurve>() {
        export_curve(py, obj, curve.get(), &path, &options)?;
    } else if let Ok(surface) = obj.cast::<PySurface>() {
        export_surface(py, obj, surface.get(), &path, &options)?;
    } else if obj.cast::<PyDiscreteSpline>().is_ok() {
        export_discrete(py, obj, &path, &options)?;
    } else if obj.cast::<PyTubeSurface>().is_ok() {
        export_tube(py, obj, &path, &options)?;
    } else if ["t", "c", "k"]
        .iter()
        .all(|a| obj.hasattr(*a).unwrap_or(false))
    {
        export_scipy_spline(py, obj, &path, &options)?;
    } else if let Ok(tuple) = obj.cast::<PyTuple>() {
        export_mesh(py, tuple, &path, &options)?;
    } else {
        export_array(py, obj, &path, &options)?;
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

/// A curve: sampled (CSV, pictures, page) or its exact B-spline form (STEP, IGES).
fn export_curve(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    curve: &PyCurve,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
    let no_exact = "this curve has no exact piecewise polynomial form";
    let format = choose(path, options, &EXACT_CURVE_FORMATS, no_exact)?;
    let dim = curve.inner.dim();
    if format.is_cad() {
        let (knots, control, degree, cdim) = bspline_curve(obj, no_exact)?;
        let input = match &options.points {
            Some((_, d)) if *d != cdim => {
                return Err(OptionError::new_err(format!(
                    "points have {d} coordinates, the curve {cdim}"
                )))
            }
            Some((flat, _)) => flat.clone(),
            None => Vec::new(),
        };
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
    let input = match &options.points {
        Some((flat, d)) if *d != dim => {
            return Err(OptionError::new_err(format!(
                "points have {d} coordinates, the curve {dim}"
            )))
        }
        Some((flat, _)) => flat.clone(),
        None => Vec::new(),
    };
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
fn export_surface(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    surface: &PySurface,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
    let no_exact = "this surface has no exact piecewise polynomial form";
    let format = choose(path, options, &EXACT_SURFACE_FORMATS, no_exact)?;
    if format.is_cad() {
        let b = bspline_surface(obj, no_exact)?;
        return py
            .detach(|| write_cad_surface(&b, format, path))
            .map_err(write_error);
    }
    if options
        .samples
        .is_some_and(|(nu, nv)| nu.saturating_mul(nv) > MAX_SAMPLES)
    {
        return Err(OptionError::new_err(format!(
            "samples: at most {MAX_SAMPLES} samples can be written"
        )));
    }
    let title = title_of(obj, options)?;
    let view = SurfaceView(&*surface.inner);
    if OutputFormat::MESHES.contains(&format) && options.samples.is_none() {
        return export_mesh_within(py, &view, format, path, &title, options);
    }
    let counts = options.samples.unwrap_or_else(|| match &options.net {
        Some(net) => (
            default_surface_samples(net.rows()),
            default_surface_samples(net.cols()),
        ),
        None => (default_surface_samples(0), default_surface_samples(0)),
    });
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
fn export_capped(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    surface: &PySurface,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
    let no_exact = "this surface has no exact piecewise polynomial form";
    let format = choose(path, options, &EXACT_SURFACE_FORMATS, no_exact)?;
    let refuse = |why: String| OptionError::new_err(format!("cap: {why}"));
    if format.is_cad() {
        let b = bspline_surface(obj, no_exact)?;
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
    let view = SurfaceView(&*surface.inner);
    py.detach(|| {
        let (_, _, samples) = sample_surface(&view, nu, nv);
        let grid = Grid::from_row_major(nu, nv, samples).map_err(library_error)?;
        let (body, _) = body_mesh(&grid, true).map_err(|e| refuse(e.to_string()))?;
        write_mesh_as(format, path, &body, &options.mesh).map_err(write_error)
    })
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

/// A discrete periodic spline: its values as CSV, a picture or the page; no exact form.
fn export_discrete(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
    let format = choose(path, options, &CURVE_FORMATS, NO_EXACT_FORM)?;
    let values = numpy_array(&obj.call_method0("values")?)?;
    let (pts, dim) = PointsArray::extract_checked(&values, "values")?;
    let flat = pts.flat().into_owned();
    let title = title_of(obj, options)?;
    let input = match &options.points {
        Some((p, d)) if *d == dim => p.clone(),
        Some((_, d)) => {
            return Err(OptionError::new_err(format!(
                "points have {d} coordinates, the spline {dim}"
            )))
        }
        None => Vec::new(),
    };
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
fn export_tube(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
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
fn export_array(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
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
fn export_mesh(
    py: Python<'_>,
    tuple: &Bound<'_, PyTuple>,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
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

//! What `karkas.export` shares between its writers: its options, the choice of the output
//! format (by `format=` or the extension, as the command line chooses), the Python exception of
//! a write error, and arrays read as float64 NumPy arrays and lifted into space.

use std::path::Path;

use karkas::{Grid, Point, Point3};
use karkas_io::mesh::MeshOptions;
use karkas_io::{IoError, OutputFormat};
use pyo3::prelude::*;

use crate::convert::{by_dim, GridArray};
use crate::errors::{
    file_error, library_error, IncompatibleDataError, KarkasError, OptionError, PointsError,
};

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

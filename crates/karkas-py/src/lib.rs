//! `karkas` for Python: the karkas library's curves and surfaces on NumPy arrays.
//!
//! Built by maturin into the Python module `karkas` (see `pyproject.toml`). Points are float64
//! arrays of shape `(n, d)`, grids `(nu, nv, d)`, `d` in {2, 3}. Evaluation writes straight
//! into the output array (`out=`) with the GIL released for large batches; construction with
//! the GIL released too. Bad input raises `karkas.KarkasError` (a `ValueError`) or one of its
//! typed subclasses, with the library's message (see `errors`).
//!
//! One file per library module (`ll`, `param`, `fit`, `fair`, `dps`, `coons`, `implicit`,
//! `section`, `measure`, `loft`, `nurbs`) plus `export`, `read` and
//! `cad` (karkas-io's writers and readers), `batch` (the command line's batch jobs), `geometry`
//! (arc length, curvature, normals, projection and fairness on the base classes), `pickle` and
//! `repr_html` (Python's protocols); the memory cap `karkas.max_memory` and checked array
//! allocation in `limits`; the base classes `Curve` and `Surface` in `curve` and `surface` over
//! the dimension-erased layer `erased`; the B-spline form on flat buffers in `bspline`; arrays
//! in `convert`; exceptions in `errors`.

mod batch;
mod bspline;
mod cad;
mod convert;
mod coons;
mod curve;
mod dps;
mod erased;
mod errors;
mod export;
mod fair;
mod fit;
mod geometry;
mod implicit;
mod limits;
mod ll;
mod loft;
mod measure;
mod nurbs;
mod param;
mod pickle;
mod read;
mod repr_html;
mod section;
mod surface;

use pyo3::prelude::*;

/// mimalloc keeps freed memory for the next allocation instead of returning it to the
/// kernel: large results (10^6 points and more) then skip the first-touch page faults that
/// cost more than the computation itself (BENCHMARKS.md, "Memory").
#[global_allocator]
static ALLOCATOR: mimalloc::MiMalloc = mimalloc::MiMalloc;

/// karkas: smooth parametric curves and surfaces from point frames.
///
/// Curves (``LLCurve``, ``CubicSpline``, ``HermiteSpline`` from ``fit_curve``, ...) are
/// ``Curve`` objects, called like SciPy's splines: ``c(t, nu=0, out=None,
/// extrapolate=None)``; surfaces (``LLSurface``, ``BicubicSurface``, ``CoonsSurface``) are
/// ``Surface`` objects, ``S(u, v, grid=True)``. Arrays are float64: points ``(n, d)``, grids
/// ``(nu, nv, d)``, ``d`` in {2, 3}; any real dtype and any memory layout is accepted. Bad
/// input raises ``KarkasError`` (a ``ValueError``) or one of its typed subclasses.
///
/// Examples
/// --------
/// >>> pts = np.array([[0.0, 0.0], [1.0, 1.0], [2.0, 0.0], [3.0, 1.0]])
/// >>> c = karkas.CubicSpline(pts, parameterization="uniform")
/// >>> c(np.array([0.0, 3.0]))
/// array([[0., 0.],
///        [3., 1.]])
/// >>> issubclass(karkas.KarkasError, ValueError)
/// True
///
/// ``karkas.max_memory`` (bytes, or None for no cap; default ``KARKAS_MAX_MEMORY`` or 2 GiB, as
/// the command line's ``--max-memory``) bounds every request whose size the caller gives:
/// larger ones raise ``MemoryError`` before anything is allocated.
#[pymodule(name = "karkas")]
fn karkas_module(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("__version__", env!("CARGO_PKG_VERSION"))?;
    m.add("max_memory", limits::initial_max_memory()?)?;
    errors::register(m)?;
    m.add_class::<curve::PyCurve>()?;
    m.add_class::<curve::PyCurveDerivative>()?;
    m.add_class::<ll::PyLlCurve>()?;
    m.add_class::<param::PyCubicSpline>()?;
    m.add_class::<fit::PyHermiteSpline>()?;
    m.add_function(wrap_pyfunction!(fit::fit_curve, m)?)?;
    m.add_class::<fair::PyFairCurve>()?;
    m.add_function(wrap_pyfunction!(fair::fair_curve, m)?)?;
    m.add_class::<surface::PySurface>()?;
    m.add_class::<surface::PySurfaceDerivative>()?;
    m.add_class::<ll::PyLlSurface>()?;
    m.add_class::<param::PyBicubicSurface>()?;
    m.add_class::<loft::PyLoftSurface>()?;
    m.add_function(wrap_pyfunction!(loft::loft, m)?)?;
    m.add_function(wrap_pyfunction!(loft::loft_windio, m)?)?;
    m.add_class::<dps::PyDiscreteSpline>()?;
    m.add_class::<dps::PyTubeSurface>()?;
    m.add_class::<coons::PyCoonsSurface>()?;
    m.add_class::<section::PySectionCurve>()?;
    m.add_class::<nurbs::PyNurbsCurve>()?;
    m.add_class::<nurbs::PyNurbsSurface>()?;
    m.add_class::<cad::PyCadModel>()?;
    m.add_class::<cad::PyCadFace>()?;
    m.add_function(wrap_pyfunction!(cad::read_cad, m)?)?;
    m.add_class::<implicit::PyImplicitSurface>()?;
    m.add_function(wrap_pyfunction!(measure::hausdorff, m)?)?;
    m.add_function(wrap_pyfunction!(measure::hausdorff_to_implicit, m)?)?;
    m.add_function(wrap_pyfunction!(ll::vary, m)?)?;
    m.add_function(wrap_pyfunction!(param::curve_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(param::grid_parameters, m)?)?;
    m.add_function(wrap_pyfunction!(param::relay_grid, m)?)?;
    m.add_function(wrap_pyfunction!(export::export, m)?)?;
    m.add_function(wrap_pyfunction!(export::export_obj, m)?)?;
    m.add_function(wrap_pyfunction!(export::export_stl, m)?)?;
    m.add_function(wrap_pyfunction!(export::export_curve_csv, m)?)?;
    m.add_function(wrap_pyfunction!(export::export_surface_csv, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_curve, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_airfoil, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_grid, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_network, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_mesh, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_skeleton, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_point_set, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_surface_samples, m)?)?;
    m.add_function(wrap_pyfunction!(read::read_mask, m)?)?;
    m.add_function(wrap_pyfunction!(read::set_max_input_bytes, m)?)?;
    m.add_function(wrap_pyfunction!(read::max_input_bytes, m)?)?;
    m.add_function(wrap_pyfunction!(pickle::restore, m)?)?;
    m.add_function(wrap_pyfunction!(batch::batch, m)?)?;
    m.add_function(wrap_pyfunction!(batch::batch_inputs, m)?)?;
    let names: Vec<String> = m
        .dict()
        .keys()
        .iter()
        .filter_map(|k| k.extract::<String>().ok())
        .filter(|k| !k.starts_with('_') || k == "__version__" || k == "_restore")
        .collect();
    m.add("__all__", names)?;
    Ok(())
}

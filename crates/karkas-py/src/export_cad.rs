//! The exact B-spline forms [`crate::export_any::export`] writes as STEP or IGES: a curve's or
//! a surface's `to_bspline()` (SciPy's `(t, c, k)` and `((tu, tv), c, (ku, kv))`), and SciPy's
//! own `BSpline` and `NdBSpline` objects.

use std::path::Path;

use karkas::bspline::{BSplineCurve, BSplineSurface};
use karkas_io::export::cad::{write_cad_curve, write_cad_surface};
use karkas_io::OutputFormat;
use pyo3::prelude::*;

use crate::convert::{as_points, by_dim, PointsArray};
use crate::errors::{library_error, OptionError};
use crate::export_format::{choose, grid3, numpy_array, write_error, Options};

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

/// A SciPy B-spline: `scipy.interpolate.BSpline` (coefficients `(n, d)`, `d` in {2, 3}) or
/// `NdBSpline` of two variables (coefficients `(nu, nv, 3)`), written exactly as STEP or IGES
/// (a curve also as DXF, without input points).
pub fn export_scipy_spline(
    py: Python<'_>,
    obj: &Bound<'_, PyAny>,
    path: &Path,
    options: &Options,
) -> PyResult<()> {
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

//! The exact B-spline forms of curves and surfaces as STEP or IGES, and of curves as DXF
//! (with their input points).

use crate::cad::dxf::{write_dxf, DxfCurve};
use crate::cad::{curve_in_space, CadEntity, CadError};
use crate::iges::write_iges;
use crate::step::write_step;
use crate::{GeometryError, IoError, OutputFormat};
use karkas::bspline::{BSplineCurve, BSplineSurface};
use karkas::{Curve, Point, Point3};
use std::path::Path;

/// Writes the B-spline curve `bspline` (planar curves in `z = 0`) at `output` as STEP, IGES or
/// DXF (by `format`, one of [`OutputFormat::CURVE_CAD`]; a DXF without input points); returns
/// it in space. `what` names the input in errors.
pub fn write_cad_curve<const D: usize>(
    bspline: &BSplineCurve<D>,
    format: OutputFormat,
    output: &Path,
    what: &Path,
) -> Result<BSplineCurve<3>, IoError> {
    write_cad_curve_with_points(bspline, &[], format, output, what)
}

/// [`write_cad_curve`] with the input points `points` of the curve, which a DXF holds as POINT
/// entities on their own layer (STEP and IGES leave them out).
pub fn write_cad_curve_with_points<const D: usize>(
    bspline: &BSplineCurve<D>,
    points: &[Point<D>],
    format: OutputFormat,
    output: &Path,
    what: &Path,
) -> Result<BSplineCurve<3>, IoError> {
    let format = format.allowed_for(output, &OutputFormat::CURVE_CAD)?;
    let spatial = curve_in_space(bspline).map_err(|e| match e {
        CadError::Geometry(source) => geometry(what, source),
        other => crate::error::data_error(what, other.to_string()),
    })?;
    if format == OutputFormat::Dxf {
        let points: Vec<Point3> = points.iter().map(in_space).collect();
        let drawing = DxfCurve {
            spline: &spatial,
            closed: bspline.is_closed() || ends_meet(&spatial),
            planar: D < 3,
            points: &points,
        };
        write_dxf(output, &drawing)?;
    } else {
        write_cad(&[CadEntity::Curve(&spatial)], format, output)?;
    }
    Ok(spatial)
}

/// `p` in space (missing coordinates 0, as [`curve_in_space`] places a curve).
fn in_space<const D: usize>(p: &Point<D>) -> Point3 {
    Point3::new(core::array::from_fn(|c| if c < D { p[c] } else { 0.0 }))
}

/// True when the ends of the clamped curve `spline` (its first and last control points)
/// coincide to 1e-12 of the control polygon's size: a closed curve whose closure flag was lost
/// (a SciPy `(t, c, k)` or a form handed over from Python).
fn ends_meet(spline: &BSplineCurve<3>) -> bool {
    let control = spline.control_points();
    let (Some(first), Some(last)) = (control.first(), control.last()) else {
        return false;
    };
    let size = control
        .iter()
        .map(|p| (*p - *first).norm())
        .fold(0.0, f64::max);
    (*last - *first).norm() <= 1e-12 * size
}

/// Writes the B-spline surface `bspline` at `output` as STEP or IGES (by `format`).
pub fn write_cad_surface(
    bspline: &BSplineSurface<3>,
    format: OutputFormat,
    output: &Path,
) -> Result<(), IoError> {
    let format = format.allowed_for(output, &OutputFormat::CAD)?;
    write_cad(&[CadEntity::Surface(bspline)], format, output)
}

/// The library's error `source` about the input `what`.
pub fn geometry(what: &Path, source: karkas::Error) -> IoError {
    IoError::Geometry(Box::new(GeometryError {
        path: what.to_path_buf(),
        source,
    }))
}

fn write_cad(
    entities: &[CadEntity<'_>],
    format: OutputFormat,
    output: &Path,
) -> Result<(), IoError> {
    match format {
        OutputFormat::Iges => write_iges(output, entities),
        _ => write_step(output, entities),
    }
}

/// The message refusing STEP, IGES and DXF for the discrete periodic splines: they are point
/// sets (docs/methods.md §3, §6), with no exact piecewise polynomial form to export.
pub const NO_EXACT_FORM: &str = "discrete periodic splines are point sets, not piecewise \
     polynomials: they have no exact STEP/IGES/DXF form (write .csv, .obj or .stl and convert \
     the points)";

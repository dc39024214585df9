//! The exact B-spline forms of curves and surfaces as STEP or IGES.

use crate::cad::{curve_in_space, CadEntity, CadError};
use crate::iges::write_iges;
use crate::step::write_step;
use crate::{GeometryError, IoError, OutputFormat};
use karkas::bspline::{BSplineCurve, BSplineSurface};
use std::path::Path;

/// Writes the B-spline curve `bspline` (planar curves in `z = 0`) at `output` as STEP or IGES
/// (by `format`, one of [`OutputFormat::CAD`]); returns it in space. `what` names the input in
/// errors.
pub fn write_cad_curve<const D: usize>(
    bspline: &BSplineCurve<D>,
    format: OutputFormat,
    output: &Path,
    what: &Path,
) -> Result<BSplineCurve<3>, IoError> {
    let format = format.allowed_for(output, &OutputFormat::CAD)?;
    let spatial = curve_in_space(bspline).map_err(|e| match e {
        CadError::Geometry(source) => geometry(what, source),
        other => crate::error::data_error(what, other.to_string()),
    })?;
    write_cad(&[CadEntity::Curve(&spatial)], format, output)?;
    Ok(spatial)
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

/// The message refusing STEP and IGES for the discrete periodic splines: they are point sets
/// (docs/methods.md §3, §6), with no exact piecewise polynomial form to export.
pub const NO_EXACT_FORM: &str = "discrete periodic splines are point sets, not piecewise \
     polynomials: they have no exact STEP/IGES form (write .csv, .obj or .stl and convert the \
     points)";

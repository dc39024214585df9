//! The exact B-spline forms of curves and surfaces as STEP or IGES, and of curves as DXF
//! (with their input points).

use crate::cad::dxf::{dxf_text_in, DxfCurve};
pub use crate::cad::units::{CadUnits, LengthUnit};
use crate::cad::{
    curve_closed, curve_in_space, CadEntity, CadError, CadShell, FaceSurface, MAX_CAD_DEGREE,
};
use crate::iges::iges_text_in;
use crate::step::step_text_in;
use crate::write::write_atomic;
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
    write_cad_curve_in(bspline, points, format, output, what, &CadUnits::default())
}

/// [`write_cad_curve_with_points`] stating the length unit and scaling the coordinates as
/// `units` says ([`crate::cad::units`]).
pub fn write_cad_curve_in<const D: usize>(
    bspline: &BSplineCurve<D>,
    points: &[Point<D>],
    format: OutputFormat,
    output: &Path,
    what: &Path,
    units: &CadUnits,
) -> Result<BSplineCurve<3>, IoError> {
    let format = format.allowed_for(output, &OutputFormat::CURVE_CAD)?;
    if format != OutputFormat::Dxf {
        check_degree(bspline.degree(), format, output)?;
    }
    let (text, spatial) =
        cad_curve_text_in(bspline, points, format, file_name(output), what, units)?;
    write_atomic(output, |out| out.write_all(text.as_bytes()))?;
    Ok(spatial)
}

/// The text of the file [`write_cad_curve_with_points`] writes for a file whose stem is
/// `name` (STEP and IGES name the product after it), and the curve in space: what a page or a
/// program holding no files exports, byte for byte the command line's file. `format` is STEP,
/// IGES or DXF. A STEP or IGES curve of a degree above [`MAX_CAD_DEGREE`] is refused, naming
/// the file `name`.ext.
pub fn cad_curve_text<const D: usize>(
    bspline: &BSplineCurve<D>,
    points: &[Point<D>],
    format: OutputFormat,
    name: &str,
    what: &Path,
) -> Result<(String, BSplineCurve<3>), IoError> {
    cad_curve_text_in(bspline, points, format, name, what, &CadUnits::default())
}

/// [`cad_curve_text`] stating the length unit and scaling the coordinates as `units` says.
pub fn cad_curve_text_in<const D: usize>(
    bspline: &BSplineCurve<D>,
    points: &[Point<D>],
    format: OutputFormat,
    name: &str,
    what: &Path,
    units: &CadUnits,
) -> Result<(String, BSplineCurve<3>), IoError> {
    let spatial = curve_in_space(bspline).map_err(|e| match e {
        CadError::Geometry(source) => geometry(what, source),
        other => crate::error::data_error(what, other.to_string()),
    })?;
    let spatial = scaled_curve(spatial, units.scale).map_err(|e| geometry(what, e))?;
    if format != OutputFormat::Dxf {
        let target = format!("{name}.{}", format.extension());
        check_degree(spatial.degree(), format, Path::new(&target))?;
    }
    let entities = [CadEntity::Curve(&spatial)];
    let text = match format {
        OutputFormat::Dxf => {
            let points: Vec<Point3> = points.iter().map(|p| in_space(p) * units.scale).collect();
            let curve = DxfCurve {
                spline: &spatial,
                closed: bspline.is_closed() || curve_closed(&spatial),
                planar: D < 3,
                points: &points,
            };
            dxf_text_in(&curve, units.unit)
        }
        OutputFormat::Iges => iges_text_in(&entities, name, units.cad_unit()),
        _ => step_text_in(&entities, name, units.cad_unit()),
    };
    Ok((text, spatial))
}

/// The text of the STEP or IGES file (by `format`) of the B-spline surface `bspline`, the
/// product named `name`: byte for byte what [`write_cad_surface`] writes to a file of that
/// stem.
///
/// Errors: a degree above [`MAX_CAD_DEGREE`] ([`IoError::Data`] naming the file `name`.ext).
pub fn cad_surface_text(
    bspline: &BSplineSurface<3>,
    format: OutputFormat,
    name: &str,
) -> Result<String, IoError> {
    cad_surface_text_in(bspline, format, name, &CadUnits::default())
}

/// [`cad_surface_text`] stating the length unit and scaling the coordinates as `units` says.
pub fn cad_surface_text_in(
    bspline: &BSplineSurface<3>,
    format: OutputFormat,
    name: &str,
    units: &CadUnits,
) -> Result<String, IoError> {
    let target = format!("{name}.{}", format.extension());
    check_degree(
        bspline.degree_u().max(bspline.degree_v()),
        format,
        Path::new(&target),
    )?;
    let scaled;
    let bspline = if units.scale == 1.0 {
        bspline
    } else {
        scaled =
            scaled_surface(bspline, units.scale).map_err(|e| geometry(Path::new(&target), e))?;
        &scaled
    };
    let entities = [CadEntity::Surface(bspline)];
    Ok(match format {
        OutputFormat::Iges => iges_text_in(&entities, name, units.cad_unit()),
        _ => step_text_in(&entities, name, units.cad_unit()),
    })
}

/// The text of the STEP or IGES file (by `format`) of the shell `shell` (a solid in STEP when
/// it is closed), the product named `name`, its coordinates stated in `unit` (as they are:
/// scale the faces before building the shell, [`scaled_surface`]): byte for byte what
/// [`write_cad_shell`] writes to a file of that stem.
///
/// Errors: a face of a degree above [`MAX_CAD_DEGREE`] ([`IoError::Data`] naming the file
/// `name`.ext).
pub fn cad_shell_text(
    shell: &CadShell,
    format: OutputFormat,
    name: &str,
    unit: LengthUnit,
) -> Result<String, IoError> {
    let target = format!("{name}.{}", format.extension());
    let degree = shell
        .faces()
        .iter()
        .map(|f| match &f.surface {
            FaceSurface::BSpline(s) => s.degree_u().max(s.degree_v()),
            FaceSurface::Plane(_) => 1,
        })
        .max()
        .unwrap_or(1);
    check_degree(degree, format, Path::new(&target))?;
    let entities = [CadEntity::Shell(shell)];
    Ok(match format {
        OutputFormat::Iges => iges_text_in(&entities, name, unit),
        _ => step_text_in(&entities, name, unit),
    })
}

/// Writes the shell `shell` at `output` as STEP (a solid when it is closed) or IGES (its
/// faces), by `format`, its coordinates stated in `unit`.
pub fn write_cad_shell(
    shell: &CadShell,
    format: OutputFormat,
    output: &Path,
    unit: LengthUnit,
) -> Result<(), IoError> {
    let format = format.allowed_for(output, &OutputFormat::CAD)?;
    let text = cad_shell_text(shell, format, file_name(output), unit)?;
    write_atomic(output, |out| out.write_all(text.as_bytes()))
}

/// `surface` with its control points multiplied by `scale` (a copy of `surface` for 1).
pub fn scaled_surface(
    surface: &BSplineSurface<3>,
    scale: f64,
) -> Result<BSplineSurface<3>, karkas::Error> {
    let mut grid = surface.control_points().clone();
    if scale != 1.0 {
        for p in grid.as_mut_slice() {
            *p *= scale;
        }
    }
    BSplineSurface::new(
        (surface.degree_u(), surface.knots_u().to_vec()),
        (surface.degree_v(), surface.knots_v().to_vec()),
        grid,
    )
}

/// `curve` with its control points multiplied by `scale` (`curve` itself for 1).
fn scaled_curve(curve: BSplineCurve<3>, scale: f64) -> Result<BSplineCurve<3>, karkas::Error> {
    if scale == 1.0 {
        return Ok(curve);
    }
    let control = curve.control_points().iter().map(|&p| p * scale).collect();
    BSplineCurve::new(curve.degree(), curve.knots().to_vec(), control)
}

/// Refuses a B-spline of a degree above [`MAX_CAD_DEGREE`] for STEP and IGES.
fn check_degree(degree: usize, format: OutputFormat, what: &Path) -> Result<(), IoError> {
    if degree > MAX_CAD_DEGREE {
        let name = if format == OutputFormat::Iges {
            "IGES"
        } else {
            "STEP"
        };
        return Err(crate::error::data_error(
            what,
            format!(
                "the exact B-spline has degree {degree}, above {MAX_CAD_DEGREE}, the highest \
                 that CAD programs read from {name} (Open CASCADE reads it as an empty shape): \
                 choose an LL order of at most {} (degree 2L), or write .csv, .obj or .stl",
                MAX_CAD_DEGREE / 2
            ),
        ));
    }
    Ok(())
}

/// The stem of `path` as STEP and IGES name their product ("karkas" when it has none).
fn file_name(path: &Path) -> &str {
    path.file_stem()
        .and_then(|s| s.to_str())
        .unwrap_or("karkas")
}

/// `p` in space (missing coordinates 0, as [`curve_in_space`] places a curve).
fn in_space<const D: usize>(p: &Point<D>) -> Point3 {
    Point3::new(core::array::from_fn(|c| if c < D { p[c] } else { 0.0 }))
}

/// Writes the B-spline surface `bspline` at `output` as STEP or IGES (by `format`).
pub fn write_cad_surface(
    bspline: &BSplineSurface<3>,
    format: OutputFormat,
    output: &Path,
) -> Result<(), IoError> {
    write_cad_surface_in(bspline, format, output, &CadUnits::default())
}

/// [`write_cad_surface`] stating the length unit and scaling the coordinates as `units` says.
pub fn write_cad_surface_in(
    bspline: &BSplineSurface<3>,
    format: OutputFormat,
    output: &Path,
    units: &CadUnits,
) -> Result<(), IoError> {
    let format = format.allowed_for(output, &OutputFormat::CAD)?;
    check_degree(bspline.degree_u().max(bspline.degree_v()), format, output)?;
    let text = cad_surface_text_in(bspline, format, file_name(output), units)?;
    write_atomic(output, |out| out.write_all(text.as_bytes()))
}

/// The library's error `source` about the input `what`.
pub fn geometry(what: &Path, source: karkas::Error) -> IoError {
    IoError::Geometry(Box::new(GeometryError {
        path: what.to_path_buf(),
        source,
    }))
}

/// The message refusing STEP, IGES and DXF for the discrete periodic splines: they are point
/// sets (docs/methods.md §3, §6), with no exact piecewise polynomial form to export.
pub const NO_EXACT_FORM: &str = "discrete periodic splines are point sets, not piecewise \
     polynomials: they have no exact STEP/IGES/DXF form (write .csv, .obj or .stl and convert \
     the points)";

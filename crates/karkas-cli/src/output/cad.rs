//! The exact B-spline forms as STEP, IGES or DXF (curves), and the refusal of those formats
//! for the discrete periodic splines, which have none.

use super::console::note;
use crate::args::CadOptions;
use anyhow::{anyhow, bail, Context, Result};
use karkas::bspline::{BSplineSurface, ToBSplineCurve, ToBSplineSurface};
use karkas::Point;
use karkas_io::cad::CadShell;
use karkas_io::export::cad::{scaled_surface, write_cad_curve_in, NO_EXACT_FORM};
use karkas_io::OutputFormat;
use std::path::Path;

/// Writes the exact B-spline form of `curve` as STEP, IGES or DXF (by `format`, one of
/// [`OutputFormat::CURVE_CAD`]) with the input `points` the curve was made from, which a DXF
/// holds as POINT entities on layer `POINTS` (STEP and IGES leave them out), in the unit and
/// at the scale of `cad`; with `close`, the curve closed by the straight segment from its end
/// to its start ([`karkas::bspline::BSplineCurve::closed_by_segment`], `--close-te`); `what` names the input
/// for errors.
pub fn write_cad_curve<const D: usize>(
    curve: &impl ToBSplineCurve<D>,
    points: &[Point<D>],
    format: OutputFormat,
    output: &Path,
    (cad, close): (&CadOptions, bool),
    what: impl std::fmt::Display,
) -> Result<()> {
    let what = what.to_string();
    let mut bspline = curve.to_bspline().with_context(|| what.clone())?;
    if close {
        bspline = bspline
            .closed_by_segment()
            .with_context(|| format!("{what}: --close-te"))?;
    }
    let units = cad.units();
    let spatial = write_cad_curve_in(&bspline, points, format, output, Path::new(&what), &units)?;
    let shown_points = if format == OutputFormat::Dxf {
        format!(", {} input points", points.len())
    } else {
        String::new()
    };
    super::console::record("degree", spatial.degree());
    super::console::record("control_points", spatial.control_points().len());
    let closed = if close {
        ", closed by the trailing-edge segment"
    } else {
        ""
    };
    note(format!(
        "karkas: wrote {} (B-spline curve of degree {}, {} control points{shown_points}{closed})",
        super::target::shown(output).display(),
        spatial.degree(),
        spatial.control_points().len()
    ));
    Ok(())
}

/// Writes the exact B-spline form of `surface` as STEP or IGES (by `format`), in the unit
/// and at the scale of `cad`: one face, with no edge at its poles and one seam edge for a
/// closed direction; with `cap`, every open boundary loop closed by a planar face (an error
/// naming `--cap` when a loop is not planar or there is none). A closed result is a solid in
/// STEP, its faces turned outwards, and its volume (in the file's coordinates) is reported.
pub fn write_cad_surface(
    surface: &impl ToBSplineSurface<3>,
    format: OutputFormat,
    output: &Path,
    cad: &CadOptions,
    what: impl std::fmt::Display,
    cap: bool,
) -> Result<()> {
    let bspline = surface.to_bspline().with_context(|| what.to_string())?;
    write_cad_faces(&bspline, &[], format, output, cad, what, cap)
}

/// Writes `bspline` with the further faces `more` (sharing its edges, e.g. a blunt trailing
/// edge's strip) as one shell, as [`write_cad_surface`] writes one surface; the summary line
/// describes `bspline`.
pub fn write_cad_faces(
    bspline: &BSplineSurface<3>,
    more: &[BSplineSurface<3>],
    format: OutputFormat,
    output: &Path,
    cad: &CadOptions,
    what: impl std::fmt::Display,
    cap: bool,
) -> Result<()> {
    let units = cad.units();
    let scaled = std::iter::once(bspline)
        .chain(more)
        .map(|s| scaled_surface(s, units.scale).with_context(|| what.to_string()))
        .collect::<Result<Vec<_>>>()?;
    let mut shell = CadShell::of_surfaces(&scaled);
    let caps = if cap {
        shell.cap_free_loops().map_err(|e| anyhow!("--cap: {e}"))?
    } else {
        Vec::new()
    };
    let volume = shell.is_closed().then(|| shell.orient_outward());
    karkas_io::export::cad::write_cad_shell(&shell, format, output, units.cad_unit())?;
    let grid = bspline.control_points();
    super::console::record("control_points", vec![grid.rows(), grid.cols()]);
    let mut body = String::new();
    if !caps.is_empty() {
        super::console::record("caps", caps.len());
        body.push_str(&format!(
            ", {} planar cap{}",
            caps.len(),
            if caps.len() == 1 { "" } else { "s" }
        ));
    }
    if let Some(volume) = volume {
        super::console::record("volume", volume);
        let kind = if format == OutputFormat::Iges {
            "closed faces"
        } else {
            "closed solid"
        };
        body.push_str(&format!(", {kind}, enclosed volume {volume:.9e}"));
    }
    note(format!(
        "karkas: wrote {} (B-spline surface of degree {}x{}, {}x{} control points{body})",
        super::target::shown(output).display(),
        bspline.degree_u(),
        bspline.degree_v(),
        grid.rows(),
        grid.cols()
    ));
    Ok(())
}

/// Refuses the exact formats `exact` (STEP and IGES, [`OutputFormat::CAD`], for surfaces; and
/// DXF, [`OutputFormat::CURVE_CAD`], for curves) for the discrete periodic splines: they are
/// point sets (docs/methods.md §3, §6), with no exact piecewise polynomial form to export.
pub fn refuse_cad_for_discrete(output: &Path, exact: &[OutputFormat]) -> Result<()> {
    let cad = match super::target::requested_format() {
        Some(format) => exact.contains(&format),
        None => OutputFormat::from_path(output, exact).is_ok(),
    };
    if cad {
        bail!(
            "{}: {NO_EXACT_FORM}",
            super::target::shown(output).display()
        );
    }
    Ok(())
}

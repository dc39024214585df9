//! What every command that writes an output file shares: the input-overwrite check and the
//! writing of a sampled surface.

use anyhow::{anyhow, bail, Result};
use karkas::bspline::{ToBSplineCurve, ToBSplineSurface};
use karkas::{Grid, Point3, Surface};
use karkas_io::cad::{curve_in_space, CadEntity};
use karkas_io::iges::write_iges;
use karkas_io::obj::write_surface_obj;
use karkas_io::step::write_step;
use karkas_io::write::write_surface_csv;
use karkas_io::OutputFormat;
use std::path::Path;

/// Refuses an output path that names the input file: the atomic rename would replace the
/// user's data with the result.
pub fn ensure_distinct(input: &Path, output: &Path) -> Result<()> {
    let same = match (input.canonicalize(), output.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => false,
    };
    if same {
        bail!(
            "{}: the output would overwrite the input file; choose another output name",
            output.display()
        );
    }
    Ok(())
}

/// Samples `surface` on a uniform `nu x nv` grid over its whole domain and writes the samples
/// to `output` as a `u,v,x,y,z` CSV or any mesh, picture or page format of
/// [`super::export::EXACT_SURFACE_FORMATS`],
/// by `format`; then reports what was written.
pub fn write_sampled_surface(
    surface: &impl Surface<3>,
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
) -> Result<()> {
    write_sampled_surface_with_net(surface, (nu, nv), format, output, "karkas surface", None)
}

/// [`write_sampled_surface`] with a caption for pictures and the page, and the input grid
/// `net` shown on the page.
pub fn write_sampled_surface_with_net(
    surface: &impl Surface<3>,
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
    title: &str,
    net: Option<&Grid<Point3>>,
) -> Result<()> {
    super::guard::check_memory(
        &format!("{}: {nu} x {nv} samples", output.display()),
        (nu as u128) * (nv as u128) * 24 + (nu as u128 + nv as u128) * 8,
    )?;
    let mut us = vec![0.0; nu];
    let mut vs = vec![0.0; nv];
    let mut samples = vec![Point3::ZERO; nu * nv];
    surface.sample_grid_into(&mut us, &mut vs, &mut samples);
    match format {
        OutputFormat::Obj => write_surface_obj(output, nu, nv, &samples)?,
        OutputFormat::Csv => write_surface_csv(output, &us, &vs, &samples)?,
        _ => {
            let grid = Grid::from_row_major(nu, nv, samples)?;
            super::export::write_surface(output, format, &grid, title, net)?;
        }
    }
    super::curve_ll::report(output, nu * nv);
    Ok(())
}

/// Writes the exact B-spline form of `curve` as STEP or IGES (by `format`, one of
/// [`OutputFormat::CAD`]); `what` names the input for errors.
pub fn write_cad_curve<const D: usize>(
    curve: &impl ToBSplineCurve<D>,
    format: OutputFormat,
    output: &Path,
    what: &str,
) -> Result<()> {
    let bspline = curve.to_bspline().map_err(|e| anyhow!("{what}: {e}"))?;
    let spatial = curve_in_space(&bspline).map_err(|e| anyhow!("{what}: {e}"))?;
    write_cad(&[CadEntity::Curve(&spatial)], format, output)?;
    eprintln!(
        "karkas: wrote {} (B-spline curve of degree {}, {} control points)",
        output.display(),
        spatial.degree(),
        spatial.control_points().len()
    );
    Ok(())
}

/// Writes the exact B-spline form of `surface` as STEP or IGES (by `format`).
pub fn write_cad_surface(
    surface: &impl ToBSplineSurface<3>,
    format: OutputFormat,
    output: &Path,
    what: &str,
) -> Result<()> {
    let bspline = surface.to_bspline().map_err(|e| anyhow!("{what}: {e}"))?;
    write_cad(&[CadEntity::Surface(&bspline)], format, output)?;
    let grid = bspline.control_points();
    eprintln!(
        "karkas: wrote {} (B-spline surface of degree {}x{}, {}x{} control points)",
        output.display(),
        bspline.degree_u(),
        bspline.degree_v(),
        grid.rows(),
        grid.cols()
    );
    Ok(())
}

fn write_cad(entities: &[CadEntity<'_>], format: OutputFormat, output: &Path) -> Result<()> {
    match format {
        OutputFormat::Iges => write_iges(output, entities)?,
        _ => write_step(output, entities)?,
    }
    Ok(())
}

/// Refuses STEP and IGES for the discrete periodic splines: they are point sets (METHODS.md
/// §3, §6), with no exact piecewise polynomial form to export.
pub fn refuse_cad_for_discrete(output: &Path) -> Result<()> {
    if OutputFormat::from_path(output, &OutputFormat::CAD).is_ok() {
        bail!(
            "{}: discrete periodic splines are point sets, not piecewise polynomials: they have no \
             exact STEP/IGES form (write .csv, .obj or .stl and convert the points)",
            output.display()
        );
    }
    Ok(())
}

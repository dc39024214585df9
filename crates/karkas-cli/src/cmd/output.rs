//! What every command that writes an output file shares: the input-overwrite check and the
//! writing of a sampled surface.

use anyhow::{bail, Result};
use karkas::{Grid, Point3, Surface};
use karkas_io::obj::write_surface_obj;
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
/// to `output` as a `u,v,x,y,z` CSV or any other format of [`super::export::SURFACE_FORMATS`],
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

//! What every command that writes an output file shares: the input-overwrite check and the
//! writing of a sampled surface.

use anyhow::{bail, Result};
use karkas::{Point3, Surface};
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
/// to `output` as a `.obj` mesh or a `u,v,x,y,z` CSV, by `format`; then reports what was written.
pub fn write_sampled_surface(
    surface: &impl Surface<3>,
    (nu, nv): (usize, usize),
    format: OutputFormat,
    output: &Path,
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
        _ => write_surface_csv(output, &us, &vs, &samples)?,
    }
    super::curve_ll::report(output, nu * nv);
    Ok(())
}

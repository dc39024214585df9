//! `karkas surface dps-tube`: a closed tube through a skeleton of curves along and across it,
//! by formula (3) of Malozemov et al. (docs/methods.md §3).

use crate::args::{check_dps_order, check_dps_step, MeshOutput};
use crate::input::one_standard_input;
use crate::output::cad::refuse_cad_for_discrete;
use crate::output::formats::SURFACE_FORMATS;
use crate::output::memory::{check_memory, surface_output_bytes};
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::{report_samples, MAX_SAMPLES};
use crate::output::surface::write_surface;
use crate::output::target::output_format;
use anyhow::{bail, Result};
use clap::Args;
use karkas::dps::{TubeSurface, DEFAULT_TUBE_ORDER};
use karkas::Error;
use karkas_io::skeleton::{read_across_curves, read_along_curves};
use karkas_io::write::write_indexed_grid_csv;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// Arguments of `karkas surface dps-tube`.
#[derive(Debug, Args)]
pub struct SurfaceDpsTubeArgs {
    /// Curves along the tube, f_i(q): CSV with header i,q,x,y,z (m1 curves of N2 = m2 n2
    /// samples).
    #[arg(long, value_name = "F.csv")]
    along: PathBuf,
    /// Curves across the tube, g_j(p): CSV with header j,p,x,y,z (m2 curves of N1 = m1 n1
    /// samples).
    #[arg(long, value_name = "G.csv")]
    across: PathBuf,
    /// Values between neighbouring along curves, around the tube (p direction).
    #[arg(long = "n1", value_name = "N1")]
    n1: usize,
    /// Values between neighbouring across curves, along the tube (q direction).
    #[arg(long = "n2", value_name = "N2")]
    n2: usize,
    /// Spline order around the tube (in p).
    #[arg(long = "r1", value_name = "R1", default_value_t = DEFAULT_TUBE_ORDER)]
    r1: usize,
    /// Spline order along the tube (in q).
    #[arg(long = "r2", value_name = "R2", default_value_t = DEFAULT_TUBE_ORDER)]
    r2: usize,
    #[command(flatten)]
    mesh: MeshOutput,
    /// Output file: .csv (p,q,x,y,z), a closed mesh (.obj .stl .ply .vtk .vts .glb), a
    /// picture (.svg .png) or a 3-D viewer page (.html).
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas surface dps-tube`.
pub fn run(args: &SurfaceDpsTubeArgs) -> Result<()> {
    refuse_cad_for_discrete(&args.output, &OutputFormat::CAD)?;
    let format = output_format(&args.output, &SURFACE_FORMATS)?;
    args.mesh.check(format)?;
    check_dps_order("--r1", args.r1)?;
    check_dps_order("--r2", args.r2)?;
    check_dps_step("--n1", args.n1)?;
    check_dps_step("--n2", args.n2)?;
    one_standard_input(&[("--along", &args.along), ("--across", &args.across)])?;
    ensure_distinct(&args.along, &args.output)?;
    ensure_distinct(&args.across, &args.output)?;
    let along = read_along_curves(&args.along)?;
    let across = read_across_curves(&args.across)?;
    let (big_n1, big_n2) = (
        along.rows().saturating_mul(args.n1),
        across.rows().saturating_mul(args.n2),
    );
    if big_n1.saturating_mul(big_n2) > MAX_SAMPLES {
        bail!(
            "--n1, --n2: {big_n1} x {big_n2} values, more than the {MAX_SAMPLES} that can be written"
        );
    }
    // The tube's values and their output.
    check_memory(
        &format!("surface dps-tube: {big_n1} x {big_n2} values"),
        surface_output_bytes(format, big_n1, big_n2) + big_n1 as u128 * big_n2 as u128 * 24,
    )?;
    let (f, g) = (args.along.display(), args.across.display());
    let tube =
        TubeSurface::new(&along, &across, args.n1, args.n2, args.r1, args.r2).map_err(|e| {
            let at = match &e {
                Error::TooFewCurves {
                    family: "along", ..
                }
                | Error::SkeletonLength {
                    family: "along", ..
                } => f.to_string(),
                Error::TooFewCurves { .. } | Error::SkeletonLength { .. } => g.to_string(),
                _ => format!("{f}, {g}"),
            };
            anyhow::Error::new(e).context(at)
        })?;
    match format {
        OutputFormat::Csv => write_indexed_grid_csv(&args.output, ["p", "q"], tube.values())?,
        _ => {
            let title = format!(
                "discrete periodic tube, {big_n1} x {big_n2} values, orders {} and {}",
                args.r1, args.r2
            );
            let mesh = args.mesh.options(false);
            write_surface(
                &args.output,
                format,
                &tube.closed_grid(),
                &title,
                None,
                &mesh,
            )?;
        }
    }
    report_samples(&args.output, big_n1 * big_n2);
    Ok(())
}

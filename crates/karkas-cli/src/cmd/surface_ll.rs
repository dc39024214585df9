//! `karkas surface ll`: the LL surface of a grid of points (seed 000, METHODS.md §1.3).

use super::curve_ll::MAX_SAMPLES;
use super::output::{ensure_distinct, write_cad_surface, write_sampled_surface_with_net};
use crate::samples::{default_surface_samples, parse_pair};
use anyhow::{anyhow, bail, Result};
use clap::Args;
use karkas::ll::{LlKernel, LlSurface};
use karkas_io::grid::read_grid;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// Arguments of `karkas surface ll`.
#[derive(Debug, Args)]
pub struct SurfaceLlArgs {
    /// LL order L (at least 1): the surface is C^L in each variable.
    #[arg(long, default_value_t = 3)]
    order: usize,
    /// Close the surface in u (across rows, index i).
    #[arg(long)]
    closed_u: bool,
    /// Close the surface in v (along rows, index j).
    #[arg(long)]
    closed_v: bool,
    /// Pass through every grid point instead of approximating the grid.
    #[arg(long)]
    interpolate: bool,
    /// Samples NU,NV, uniform over the domain, ends included
    /// [default: 4 per grid line in each direction, at least 50].
    #[arg(long, value_parser = parse_pair)]
    samples: Option<(usize, usize)>,
    /// Input grid: CSV with header i,j,x,y,z (indices from 0, rows in any order).
    input: PathBuf,
    /// Output file: .csv (u,v,x,y,z), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs.
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas surface ll`.
pub fn run(args: &SurfaceLlArgs) -> Result<()> {
    let format = OutputFormat::from_path(&args.output, &super::export::EXACT_SURFACE_FORMATS)?;
    LlKernel::new(args.order).map_err(|e| anyhow!("--order: {e}"))?;
    if args
        .samples
        .is_some_and(|(nu, nv)| nu.saturating_mul(nv) > MAX_SAMPLES)
    {
        bail!("--samples: at most {MAX_SAMPLES} samples can be written");
    }
    ensure_distinct(&args.input, &args.output)?;
    let grid = read_grid(&args.input)?;
    super::guard::grid_points(&args.input, grid.as_slice())?;
    let build = if args.interpolate {
        LlSurface::interpolating
    } else {
        LlSurface::new
    };
    let surface = build(&grid, args.order, args.closed_u, args.closed_v)
        .map_err(|e| anyhow!("{}: {e}", args.input.display()))?;
    if format.is_cad() {
        let what = args.input.display().to_string();
        return write_cad_surface(&surface, format, &args.output, &what);
    }
    let (nu, nv) = args.samples.unwrap_or_else(|| {
        (
            default_surface_samples(grid.rows()),
            default_surface_samples(grid.cols()),
        )
    });
    let title = format!(
        "LL surface, L = {}, {} x {} grid",
        args.order,
        grid.rows(),
        grid.cols()
    );
    write_sampled_surface_with_net(
        &surface,
        (nu, nv),
        format,
        &args.output,
        &title,
        Some(&grid),
    )
}

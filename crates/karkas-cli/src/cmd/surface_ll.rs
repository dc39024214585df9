//! `karkas surface ll`: the LL surface of a grid of points (Aulchenko et al., docs/methods.md §1.3).

use crate::args::{GridInput, GridSamples, LlSurfaceOptions};
use crate::input::grid_points;
use crate::output::cad::write_cad_surface;
use crate::output::formats::EXACT_SURFACE_FORMATS;
use crate::output::overwrite::ensure_distinct;
use crate::output::surface::write_sampled_surface;
use anyhow::Result;
use clap::Args;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// Arguments of `karkas surface ll`.
#[derive(Debug, Args)]
pub struct SurfaceLlArgs {
    #[command(flatten)]
    ll: LlSurfaceOptions,
    #[command(flatten)]
    samples: GridSamples,
    #[command(flatten)]
    grid: GridInput,
    /// Output file: .csv (u,v,x,y,z), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs.
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas surface ll`.
pub fn run(args: &SurfaceLlArgs) -> Result<()> {
    let format = OutputFormat::from_path(&args.output, &EXACT_SURFACE_FORMATS)?;
    args.ll.check()?;
    args.samples.check()?;
    ensure_distinct(&args.grid.input, &args.output)?;
    let grid = args.grid.read()?;
    grid_points(&args.grid.input, grid.as_slice())?;
    let surface = args.ll.build(&grid, &args.grid.input)?;
    if format.is_cad() {
        return write_cad_surface(&surface, format, &args.output, args.grid.input.display());
    }
    let (nu, nv) = args.samples.or_else(|| GridInput::default_samples(&grid));
    let title = format!(
        "LL surface, L = {}, {} x {} grid",
        args.ll.order,
        grid.rows(),
        grid.cols()
    );
    write_sampled_surface(
        &surface,
        (nu, nv),
        format,
        &args.output,
        &title,
        Some(&grid),
    )
}

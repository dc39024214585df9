//! `karkas surface ll`: the LL surface of a grid of points (Aulchenko et al., docs/methods.md §1.3).

use crate::args::{GridInput, GridSamples, LlSurfaceOptions, MeshOutput};
use crate::input::grid_points;
use crate::output::formats::EXACT_SURFACE_FORMATS;
use crate::output::surface::write_grid_surface;
use crate::output::target::output_format;
use anyhow::Result;
use clap::Args;
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
    #[command(flatten)]
    mesh: MeshOutput,
    /// Output file: .csv (u,v,x,y,z), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs.
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas surface ll`.
pub fn run(args: &SurfaceLlArgs) -> Result<()> {
    let format = output_format(&args.output, &EXACT_SURFACE_FORMATS)?;
    args.ll.check()?;
    args.samples.check()?;
    args.mesh.check(format)?;
    let grid = args.grid.read_for(&args.output)?;
    grid_points(&args.grid.input, grid.as_slice())?;
    let surface = args.ll.build(&grid, &args.grid.input)?;
    let title = format!(
        "LL surface, L = {}, {} x {} grid",
        args.ll.order(),
        grid.rows(),
        grid.cols()
    );
    let input = (args.grid.input.as_path(), &grid);
    write_grid_surface(
        &surface,
        format,
        &args.output,
        input,
        args.samples.samples,
        &title,
        &args.mesh.options(false),
    )
}

//! `karkas surface bicubic`: the bicubic interpolant of a grid of points with chosen
//! parameters (Kuznetsov and Filatov, docs/methods.md §5).

use crate::args::{ClosedUv, GridInput, GridParamOption, GridSamples, MeshOutput};
use crate::input::grid_points;
use crate::output::formats::EXACT_SURFACE_FORMATS;
use crate::output::surface::write_grid_surface;
use crate::output::target::output_format;
use anyhow::{Context, Result};
use clap::Args;
use karkas::param::BicubicSurface;
use std::path::PathBuf;

/// Arguments of `karkas surface bicubic`.
#[derive(Debug, Args)]
#[command(mut_arg("samples", |a| a.value_name("NU,NV").help(
    "Samples NU,NV, uniform in the parameters over the domain, ends included [default: 4 per \
     grid line in each direction, at least 50]"
)))]
pub struct SurfaceBicubicArgs {
    #[command(flatten)]
    param: GridParamOption,
    #[command(flatten)]
    closed: ClosedUv,
    #[command(flatten)]
    samples: GridSamples,
    #[command(flatten)]
    grid: GridInput,
    #[command(flatten)]
    mesh: MeshOutput,
    /// Output file: .csv (u,v,x,y,z in the chosen parameters), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs.
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas surface bicubic`.
pub fn run(args: &SurfaceBicubicArgs) -> Result<()> {
    let format = output_format(&args.output, &EXACT_SURFACE_FORMATS)?;
    args.samples.check()?;
    args.mesh.check(format)?;
    let grid = args.grid.read_for(&args.output)?;
    grid_points(&args.grid.input, grid.as_slice())?;
    let (closed_u, closed_v) = (args.closed.closed_u, args.closed.closed_v);
    let surface = BicubicSurface::new(&grid, args.param.kind().to_library(), closed_u, closed_v)
        .with_context(|| args.grid.input.display().to_string())?;
    let title = format!("bicubic surface, {} x {} grid", grid.rows(), grid.cols());
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

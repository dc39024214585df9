//! `karkas surface ll`: the LL surface of a grid of points (Aulchenko et al., docs/methods.md §1.3).

use super::curve_ll::{check_within, report_within};
use crate::args::{
    CadOptions, CapOption, CreaseUv, GridInput, GridSamples, LlSurfaceOptions, MeshOutput,
    MeshTolerance,
};
use crate::input::grid_points;
use crate::output::formats::STREAMED_SURFACE_FORMATS;
use crate::output::surface::{write_grid_surface, SurfaceWriting};
use crate::output::target::output_formats;
use anyhow::{Context, Result};
use clap::Args;
use karkas::ll::LlSurface;
use std::path::PathBuf;

/// Arguments of `karkas surface ll`.
#[derive(Debug, Args)]
pub struct SurfaceLlArgs {
    #[command(flatten)]
    ll: LlSurfaceOptions,
    /// Pass within distance D (model units) of every grid point at its node, keeping the
    /// order L: between the approximation and --interpolate (the separable system (6) solved
    /// for targets pulled to distance D). D at or above the approximation's largest deviation
    /// gives the approximation itself.
    #[arg(
        long,
        value_name = "D",
        conflicts_with = "interpolate",
        allow_hyphen_values = true
    )]
    within: Option<f64>,
    #[command(flatten)]
    samples: GridSamples,
    #[command(flatten)]
    grid: GridInput,
    #[command(flatten)]
    mesh: MeshOutput,
    #[command(flatten)]
    cap: CapOption,
    #[command(flatten)]
    crease: CreaseUv,
    #[command(flatten)]
    tolerance: MeshTolerance,
    /// Output file: .csv (u,v,x,y,z), .npy (the samples' points, an (nu, nv, 3) float64
    /// array), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs. Repeat -o for several outputs of
    /// one surface.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
    #[command(flatten)]
    cad: CadOptions,
}

/// Runs `karkas surface ll`.
pub fn run(args: &SurfaceLlArgs) -> Result<()> {
    let formats = output_formats(&args.output, &STREAMED_SURFACE_FORMATS)?;
    args.ll.check()?;
    check_within(args.within)?;
    let options = (&args.samples, &args.mesh, &args.tolerance);
    let writing = SurfaceWriting::checked(&formats, options, &args.cap, &args.cad)?;
    let grid = args.crease.apply(args.grid.read_for_all(&args.output)?)?;
    grid_points(&args.grid.input, grid.as_slice())?;
    let surface = match args.within {
        Some(distance) => {
            let closed = &args.ll.closed;
            let fit = LlSurface::within(
                &grid,
                args.ll.order(),
                closed.closed_u,
                closed.closed_v,
                distance,
            )
            .with_context(|| args.grid.input.display().to_string())?;
            report_within(&fit, distance, "surface ll");
            fit.shape
        }
        None => args.ll.build(&grid, &args.grid.input)?,
    };
    let variant = args
        .within
        .map(|d| format!("within {d} "))
        .unwrap_or_default();
    let title = format!(
        "{variant}LL surface, L = {}, {} x {} grid",
        args.ll.order(),
        grid.rows(),
        grid.cols()
    );
    let input = (args.grid.input.as_path(), &grid);
    for (output, &format) in args.output.iter().zip(&formats) {
        write_grid_surface(&surface, format, output, input, &writing, &title)?;
    }
    Ok(())
}

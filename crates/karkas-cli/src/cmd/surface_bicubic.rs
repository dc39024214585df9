//! `karkas surface bicubic`: the bicubic interpolant of a grid of points with chosen
//! parameters (seed 004, METHODS.md §5).

use super::curve_ll::MAX_SAMPLES;
use super::output::{ensure_distinct, write_cad_surface, write_sampled_surface_with_net};
use crate::samples::{default_surface_samples, parse_pair};
use anyhow::{anyhow, bail, Result};
use clap::{Args, ValueEnum};
use karkas::param::{BicubicSurface, GridParameterization};
use karkas_io::grid::read_grid;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// The parameterizations of `--param`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum ParamKind {
    /// u_i = i, v_j = j.
    Uniform,
    /// Chord lengths along the row and the column through node (0, 0) (the seed's rule).
    Chord,
    /// Chord lengths averaged over all rows and columns.
    Averaged,
    /// Square roots of chord lengths averaged over all rows and columns.
    Centripetal,
}

impl ParamKind {
    /// The library's parameterization.
    pub fn to_library(self) -> GridParameterization {
        match self {
            ParamKind::Uniform => GridParameterization::Uniform,
            ParamKind::Chord => GridParameterization::default(),
            ParamKind::Averaged => GridParameterization::AveragedChord,
            ParamKind::Centripetal => GridParameterization::Centripetal,
        }
    }
}

/// Arguments of `karkas surface bicubic`.
#[derive(Debug, Args)]
pub struct SurfaceBicubicArgs {
    /// Parameters of the grid nodes.
    #[arg(long, value_enum, default_value_t = ParamKind::Chord)]
    param: ParamKind,
    /// Close the surface in u (across rows, index i): periodic ends.
    #[arg(long)]
    closed_u: bool,
    /// Close the surface in v (along rows, index j): periodic ends.
    #[arg(long)]
    closed_v: bool,
    /// Samples NU,NV, uniform in the parameters over the domain, ends included
    /// [default: 4 per grid line in each direction, at least 50].
    #[arg(long, value_name = "NU,NV", value_parser = parse_pair)]
    samples: Option<(usize, usize)>,
    /// Input grid: CSV with header i,j,x,y,z (indices from 0, rows in any order).
    input: PathBuf,
    /// Output file: .csv (u,v,x,y,z in the chosen parameters), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs.
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas surface bicubic`.
pub fn run(args: &SurfaceBicubicArgs) -> Result<()> {
    let format = OutputFormat::from_path(&args.output, &super::export::EXACT_SURFACE_FORMATS)?;
    if args
        .samples
        .is_some_and(|(nu, nv)| nu.saturating_mul(nv) > MAX_SAMPLES)
    {
        bail!("--samples: at most {MAX_SAMPLES} samples can be written");
    }
    ensure_distinct(&args.input, &args.output)?;
    let grid = read_grid(&args.input)?;
    super::guard::grid_points(&args.input, grid.as_slice())?;
    let surface = BicubicSurface::new(&grid, args.param.to_library(), args.closed_u, args.closed_v)
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
    let title = format!("bicubic surface, {} x {} grid", grid.rows(), grid.cols());
    write_sampled_surface_with_net(
        &surface,
        (nu, nv),
        format,
        &args.output,
        &title,
        Some(&grid),
    )
}

//! `karkas surface bicubic`: the bicubic interpolant of a grid of points with chosen
//! parameters (Kuznetsov and Filatov, docs/methods.md §5).

use crate::args::{
    parse_whole, CadOptions, CapOption, ClosedUv, CreaseUv, GridInput, GridParamOption,
    GridSamples, MeshOutput, MeshTolerance, ParamKind,
};
use crate::input::grid_points;
use crate::output::formats::EXACT_SURFACE_FORMATS;
use crate::output::surface::{write_grid_surface, SurfaceWriting};
use crate::output::target::output_formats;
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::param::{BicubicSurface, ConditionSummary, GridParameterization};
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
    /// The origin node I,J of --param chord (Kuznetsov and Filatov's (i*, j*)): u is the chord
    /// length along column J, v along row I, both zero at the node [default: 0,0].
    #[arg(long, value_name = "I,J", value_parser = parse_origin)]
    origin: Option<(usize, usize)>,
    #[command(flatten)]
    closed: ClosedUv,
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
    /// Print to standard error how well the parameters condition the continuation system
    /// (Kuznetsov and Filatov's measure (2.4), 1 for arc lengths along orthogonal lines): the
    /// smallest and mean measure over the nodes and the worst node, then the same for the
    /// paper's |D| itself (the sine of the angle between the parameter lines, blind to
    /// stretched parameters).
    #[arg(long)]
    report: bool,
    #[command(flatten)]
    tolerance: MeshTolerance,
    /// Output file: .csv (u,v,x,y,z in the chosen parameters), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs. Repeat -o for several outputs of
    /// one surface.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
    #[command(flatten)]
    cad: CadOptions,
}

/// Runs `karkas surface bicubic`.
pub fn run(args: &SurfaceBicubicArgs) -> Result<()> {
    let formats = output_formats(&args.output, &EXACT_SURFACE_FORMATS)?;
    let options = (&args.samples, &args.mesh, &args.tolerance);
    let writing = SurfaceWriting::checked(&formats, options, &args.cap, &args.cad)?;
    let grid = args.crease.apply(args.grid.read_for_all(&args.output)?)?;
    grid_points(&args.grid.input, grid.as_slice())?;
    let (closed_u, closed_v) = (args.closed.closed_u, args.closed.closed_v);
    let rule = parameterization(args.param.kind(), args.origin, (grid.rows(), grid.cols()))?;
    let surface = BicubicSurface::new(&grid, rule, closed_u, closed_v)
        .with_context(|| args.grid.input.display().to_string())?;
    if args.report {
        eprintln!("karkas: {}", condition_report(&surface.condition_summary()));
        eprintln!(
            "karkas: {}",
            paper_report(&surface.paper_condition_summary())
        );
    }
    let title = format!("bicubic surface, {} x {} grid", grid.rows(), grid.cols());
    let input = (args.grid.input.as_path(), &grid);
    for (output, &format) in args.output.iter().zip(&formats) {
        write_grid_surface(&surface, format, output, input, &writing, &title)?;
    }
    Ok(())
}

/// The rule of `--param` with the origin node of `--origin` (`--param chord` only, inside the
/// `rows x cols` grid).
fn parameterization(
    kind: ParamKind,
    origin: Option<(usize, usize)>,
    (rows, cols): (usize, usize),
) -> Result<GridParameterization> {
    let Some((i, j)) = origin else {
        return Ok(kind.to_library());
    };
    if kind != ParamKind::Chord {
        bail!(
            "--origin: the origin node belongs to --param chord, not --param {}",
            kind.to_library().name()
        );
    }
    if i >= rows || j >= cols {
        bail!(
            "--origin: node ({i}, {j}) is outside the {rows} x {cols} grid (I below {rows}, J \
             below {cols})"
        );
    }
    Ok(GridParameterization::Chord {
        origin_row: i,
        origin_col: j,
    })
}

/// Parses `I,J` (two whole numbers).
fn parse_origin(text: &str) -> Result<(usize, usize), String> {
    let (i, j) = text.split_once(',').ok_or_else(|| {
        format!("expected I,J (row and column of a node, separated by a comma), got '{text}'")
    })?;
    Ok((parse_whole(i.trim())?, parse_whole(j.trim())?))
}

/// The line of `--report`: `condition measure of the parameters: min M at node (i=I, j=J),
/// mean A over N nodes (1 = arc lengths along orthogonal lines)`.
fn condition_report(summary: &ConditionSummary) -> String {
    let (i, j) = summary.worst;
    format!(
        "condition measure of the parameters: min {:.6} at node (i={i}, j={j}), mean {:.6} over \
         {} nodes (1 = arc lengths along orthogonal lines)",
        summary.min, summary.mean, summary.nodes
    )
}

/// The second line of `--report`: `the paper's |D| (2.4) of the parameters: min M at node
/// (i=I, j=J), mean A over N nodes (the sine of the angle between the parameter lines)`.
fn paper_report(summary: &ConditionSummary) -> String {
    let (i, j) = summary.worst;
    format!(
        "the paper's |D| (2.4) of the parameters: min {:.6} at node (i={i}, j={j}), mean {:.6} \
         over {} nodes (the sine of the angle between the parameter lines; blind to stretch)",
        summary.min, summary.mean, summary.nodes
    )
}

//! `karkas surface implicit`: a grid of nodes on an implicit surface, traced along its lines
//! of curvature (or a net turned by an angle) by continuation (Kuznetsov and Filatov, docs/methods.md §5).

use crate::args::{parse_finite_list, parse_pair_with, parse_steps, parse_whole};
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::implicit::{trace_net, ExpressionSurface, NetDirections, NetSpec};
use karkas::Point3;
use karkas_io::write::write_grid_csv;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// The largest grid the command traces.
const MAX_NODES: usize = 1_000_000;

/// Arguments of `karkas surface implicit`.
#[derive(Debug, Args)]
pub struct SurfaceImplicitArgs {
    /// The surface F(x, y, z) = 0 as an expression in x, y, z, e.g. "x^2+y^2-1"
    /// (+ - * / ^, numbers, pi, e, sin cos tan asin acos atan sinh cosh tanh exp ln log log2
    /// log10 sqrt).
    #[arg(long, value_name = "EXPR")]
    expr: String,
    /// A point X,Y,Z on or near the surface (within one step): the node (0, 0).
    #[arg(long, value_name = "X,Y,Z", value_parser = parse_point)]
    start: Point3,
    /// Nodes NU,NV: NU along the u lines (first principal direction), NV along every v line.
    #[arg(long, value_name = "NU,NV", value_parser = parse_nodes)]
    nodes: (usize, usize),
    /// Arc length between nodes: H for both directions, or HU,HV.
    #[arg(long, value_name = "H", value_parser = parse_steps)]
    step: (f64, f64),
    /// Turn both families of lines by DEG degrees about the normal: a net at a constant angle
    /// to the lines of curvature (0: the lines of curvature themselves).
    #[arg(
        long,
        value_name = "DEG",
        default_value_t = 0.0,
        allow_negative_numbers = true
    )]
    turn: f64,
    /// Turn only the u family (the spine and every column) by DEG degrees about the normal;
    /// the v lines stay lines of curvature (a net that is not orthogonal, the paper's frames
    /// with one axis turned).
    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        conflicts_with_all = ["turn", "turn_v"]
    )]
    turn_u: Option<f64>,
    /// Turn only the v family (every row) by DEG degrees about the normal; the u lines stay
    /// lines of curvature.
    #[arg(
        long,
        value_name = "DEG",
        allow_negative_numbers = true,
        conflicts_with = "turn"
    )]
    turn_v: Option<f64>,
    /// The v lines are closed: spread their NV nodes evenly over one turn (the last node
    /// repeats the first); the v step is then only the tracing step while measuring a turn.
    #[arg(long)]
    closed_v: bool,
    /// Output grid: .csv with header i,j,x,y,z (input of `surface bicubic`, `surface ll`).
    #[arg(short, long, value_name = "GRID.csv")]
    output: PathBuf,
}

/// Runs `karkas surface implicit`.
pub fn run(args: &SurfaceImplicitArgs) -> Result<()> {
    output_format(&args.output, &[OutputFormat::Csv])?;
    let (nu, nv) = args.nodes;
    if nu.saturating_mul(nv) > MAX_NODES {
        bail!("--nodes: at most {MAX_NODES} nodes can be traced");
    }
    let directions = directions(args)?;
    let surface = ExpressionSurface::parse(&args.expr).context("--expr")?;
    let mut spec = NetSpec::new(args.start, directions, args.nodes, args.step);
    spec.closed_v = args.closed_v;
    let grid = trace_net(&surface, &spec).map_err(|e| match e {
        karkas::Error::NoSurfaceNear { .. } | karkas::Error::SingularPoint { .. } => {
            anyhow::Error::new(e).context("--start")
        }
        _ => anyhow::Error::new(e),
    })?;
    write_grid_csv(&args.output, &grid)?;
    eprintln!(
        "karkas: wrote {} ({nu} x {nv} nodes)",
        shown(&args.output).display()
    );
    Ok(())
}

/// The direction fields of `--turn`, `--turn-u` or `--turn-v` (at most one given; a zero
/// angle is the lines of curvature).
fn directions(args: &SurfaceImplicitArgs) -> Result<NetDirections> {
    let (option, degrees) = match (args.turn_u, args.turn_v) {
        (Some(a), _) => ("--turn-u", a),
        (_, Some(a)) => ("--turn-v", a),
        _ => ("--turn", args.turn),
    };
    if !degrees.is_finite() {
        bail!("{option}: the angle must be finite");
    }
    let angle = degrees.to_radians();
    Ok(match option {
        _ if degrees == 0.0 => NetDirections::Principal,
        "--turn-u" => NetDirections::TurnedU { angle },
        "--turn-v" => NetDirections::TurnedV { angle },
        _ => NetDirections::Turned { angle },
    })
}

/// Parses `X,Y,Z`.
fn parse_point(text: &str) -> Result<Point3, String> {
    parse_finite_list(text, "X,Y,Z (three numbers separated by commas)").map(Point3::new)
}

/// Parses `NU,NV` (each at least 2).
fn parse_nodes(text: &str) -> Result<(usize, usize), String> {
    parse_pair_with(text, |s| match parse_whole(s)? {
        n if n >= 2 => Ok(n),
        n => Err(format!("at least 2 nodes are needed, got {n}")),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn option_values() {
        assert_eq!(parse_point("1, 0,-2.5"), Ok(Point3::new([1.0, 0.0, -2.5])));
        assert!(parse_point("1,0").is_err());
        assert!(parse_point("1,0,inf").is_err());
        assert_eq!(parse_nodes("5,9"), Ok((5, 9)));
        assert!(parse_nodes("1,9").is_err());
        assert_eq!(parse_steps("0.5"), Ok((0.5, 0.5)));
        assert_eq!(parse_steps("0.5,0.25"), Ok((0.5, 0.25)));
        assert!(parse_steps("-1").is_err());
    }
}

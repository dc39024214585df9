//! `karkas surface relay`: a grid re-laid along the lines of curvature of its own bicubic
//! interpolant, spaced by arc length (Kuznetsov and Filatov, Theorem 2.1; docs/methods.md §5).

use crate::args::{parse_pair_with, parse_steps, parse_whole, ClosedUv, GridInput};
use crate::input::grid_points;
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::param::{relay_grid, RelayOptions};
use karkas_io::write::write_grid_csv;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// The largest grid the command lays.
const MAX_NODES: usize = 1_000_000;

/// What `--umbilic` does where the principal directions are undefined.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum UmbilicAction {
    /// Fail (exit status 2) naming the point.
    Error,
    /// Warn and write the input grid unchanged (its own directions).
    Keep,
}

/// Arguments of `karkas surface relay`.
#[derive(Debug, Args)]
pub struct SurfaceRelayArgs {
    #[command(flatten)]
    grid: GridInput,
    /// Rows and columns M,N of the new grid [default: the input's].
    #[arg(long, value_name = "M,N", value_parser = parse_size)]
    size: Option<(usize, usize)>,
    /// The start node I,J of the input grid, through which both lines of curvature are
    /// traced [default: the grid's centre].
    #[arg(long, value_name = "I,J", value_parser = parse_node)]
    start: Option<(usize, usize)>,
    /// Arc length between nodes HU,HV (or H for both) [default: the largest that keeps the
    /// lines through the start inside the input].
    #[arg(long, value_name = "HU,HV", value_parser = parse_steps)]
    step: Option<(f64, f64)>,
    #[command(flatten)]
    closed: ClosedUv,
    /// Where the principal curvatures are (nearly) equal (a plane, a sphere): fail, or keep
    /// the input grid with a warning.
    #[arg(long, value_enum, default_value_t = UmbilicAction::Error)]
    umbilic: UmbilicAction,
    /// Output grid: .csv with header i,j,x,y,z.
    #[arg(short, long, value_name = "OUT.csv")]
    output: PathBuf,
}

/// Runs `karkas surface relay`.
pub fn run(args: &SurfaceRelayArgs) -> Result<()> {
    output_format(&args.output, &[OutputFormat::Csv])?;
    if let Some((m, n)) = args.size {
        if m.saturating_mul(n) > MAX_NODES {
            bail!("--size: at most {MAX_NODES} nodes can be laid");
        }
    }
    let grid = args.grid.read_for(&args.output)?;
    grid_points(&args.grid.input, grid.as_slice())?;
    if let Some((i, j)) = args.start {
        if i >= grid.rows() || j >= grid.cols() {
            bail!(
                "--start: node ({i}, {j}) is outside the {} x {} grid of {}",
                grid.rows(),
                grid.cols(),
                args.grid.input.display()
            );
        }
    }
    let options = RelayOptions {
        size: args.size,
        start: args.start,
        steps: args.step,
        closed: (args.closed.closed_u, args.closed.closed_v),
        ..RelayOptions::default()
    };
    let nodes = match relay_grid(&grid, &options) {
        Ok(relaid) => relaid.nodes,
        Err(e @ karkas::Error::UmbilicRegion { .. }) if args.umbilic == UmbilicAction::Keep => {
            eprintln!(
                "karkas: warning: {}: {e}; the input grid is written unchanged",
                args.grid.input.display()
            );
            grid
        }
        Err(e) => {
            return Err(anyhow::Error::new(e))
                .with_context(|| args.grid.input.display().to_string())
        }
    };
    write_grid_csv(&args.output, &nodes)?;
    eprintln!(
        "karkas: wrote {} ({} x {} nodes)",
        shown(&args.output).display(),
        nodes.rows(),
        nodes.cols()
    );
    Ok(())
}

/// Parses `M,N` (each at least 2).
fn parse_size(text: &str) -> Result<(usize, usize), String> {
    parse_pair_with(text, |s| match parse_whole(s)? {
        n if n >= 2 => Ok(n),
        n => Err(format!("at least 2 nodes are needed, got {n}")),
    })
}

/// Parses `I,J`.
fn parse_node(text: &str) -> Result<(usize, usize), String> {
    parse_pair_with(text, parse_whole)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn option_values() {
        assert_eq!(parse_size("7,11"), Ok((7, 11)));
        assert!(parse_size("1,11").is_err());
        assert!(parse_size("7").is_err());
        assert_eq!(parse_node("0, 3"), Ok((0, 3)));
        assert!(parse_node("-1,3").is_err());
        assert_eq!(parse_steps("0.5"), Ok((0.5, 0.5)));
        assert!(parse_steps("0,1").is_err());
    }
}

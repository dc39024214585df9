//! `karkas vary`: the surface variation method (Aulchenko et al., formulas (24)–(33); docs/methods.md §1.5).
//!
//! One coordinate of a grid is varied through new row sums, column sums and total, with the
//! cells listed in a mask file kept fixed; the other coordinates are copied.

use crate::args::GridInput;
use crate::output::overwrite::ensure_distinct;
use crate::output::target::output_format;
use anyhow::{anyhow, bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::ll::{complete_sums, vary, FixedEntries, SumTargets, SumsProblem, VariationOptions};
use karkas::{Grid, Point3};
use karkas_io::mask::read_cell_mask;
use karkas_io::write::write_grid_csv;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};

/// A coordinate of the grid points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Coordinate {
    /// The x coordinate.
    X,
    /// The y coordinate.
    Y,
    /// The z coordinate.
    Z,
}

/// Arguments of `karkas vary`.
#[derive(Debug, Args)]
pub struct VaryArgs {
    #[command(flatten)]
    grid: GridInput,
    /// The coordinate to vary.
    #[arg(long, value_enum)]
    coord: Coordinate,
    /// New row sums P1,P2,... of the coordinate (row i: the cells with that i): all n of them,
    /// or the first n-1 with --total (the last row takes the rest).
    #[arg(
        long,
        value_name = "P1,P2,...",
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    rows: Vec<f64>,
    /// New column sums R1,R2,... (column j: the cells with that j): all m, or the first m-1
    /// with --total.
    #[arg(
        long,
        value_name = "R1,R2,...",
        value_delimiter = ',',
        allow_hyphen_values = true,
        required = true
    )]
    cols: Vec<f64>,
    /// The new total Q (must equal the sum of the row sums and of the column sums when those
    /// are complete).
    #[arg(long, allow_hyphen_values = true)]
    total: Option<f64>,
    /// Cells kept fixed: CSV with header i,j and one line per fixed cell (indices from 0, as in
    /// the grid file) [default: every cell may move].
    #[arg(long, value_name = "MASK.csv")]
    fixed: Option<PathBuf>,
    /// Keep fixed cells by the paper's finite penalty S (they may then move a little) instead
    /// of exactly.
    #[arg(long, value_name = "S", allow_hyphen_values = true)]
    penalty: Option<f64>,
    /// Vary the coordinate's shares of the total (the paper's r/Q): the original is first
    /// scaled to the new total, fixed cells included.
    #[arg(long)]
    scale_with_total: bool,
    /// Output grid: .csv with header i,j,x,y,z.
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas vary`.
pub fn run(args: &VaryArgs) -> Result<()> {
    output_format(&args.output, &[OutputFormat::Csv])?;
    if let Some(s) = args.penalty {
        if !(s.is_finite() && s > 0.0) {
            bail!("--penalty: the penalty S must be a positive number, got {s}");
        }
    }
    if let Some(q) = args.total {
        if !q.is_finite() {
            bail!("--total: not a finite number");
        }
    }
    for (name, values) in [("--rows", &args.rows), ("--cols", &args.cols)] {
        if let Some(v) = values.iter().find(|v| !v.is_finite()) {
            bail!("{name}: '{v}' is not a finite number");
        }
    }
    if let Some(mask) = &args.fixed {
        // The same message as for the grid, which names only the output.
        ensure_distinct(mask, &args.output)?;
    }
    let grid = args.grid.read_for(&args.output)?;
    let (n, m) = (grid.rows(), grid.cols());
    let axis = args.coord as usize;
    let matrix = Grid::from_fn(n, m, |i, j| grid.get(i, j)[axis]);
    let fixed = match &args.fixed {
        Some(path) => read_cell_mask(path, n, m)?,
        None => Grid::from_fn(n, m, |_, _| false),
    };
    let targets = targets(args, n, m)?;
    let options = VariationOptions {
        fixed_entries: args
            .penalty
            .map_or(FixedEntries::Exact, FixedEntries::Penalty),
        scale_with_total: args.scale_with_total,
    };
    let varied = vary(&matrix, &fixed, &targets, &options)
        .with_context(|| args.grid.input.display().to_string())?;
    let out = Grid::from_fn(n, m, |i, j| {
        let mut p: Point3 = *grid.get(i, j);
        p[axis] = *varied.get(i, j);
        p
    });
    write_grid_csv(&args.output, &out)?;
    let largest = varied
        .as_slice()
        .iter()
        .zip(matrix.as_slice())
        .map(|(a, b)| (a - b).abs())
        .fold(0.0, f64::max);
    report(&args.output, n, m, args.coord, largest);
    Ok(())
}

/// The complete row and column sums from the command line.
fn targets(args: &VaryArgs, n: usize, m: usize) -> Result<SumTargets> {
    let complete = |name: &str, given: &[f64], count: usize| -> Result<Vec<f64>> {
        complete_sums(given, count, args.total).map_err(|problem| match problem {
            SumsProblem::TotalMismatch { lines, sum, total } => {
                anyhow!("{name}: the {lines} sums add up to {sum}, not to --total {total}")
            }
            SumsProblem::NoTotal { given, lines } => anyhow!(
                "{name}: {given} sums given for {lines} lines; give all {lines}, or {} with --total",
                lines - 1
            ),
            SumsProblem::WrongCount { given, lines } => anyhow!(
                "{name}: the grid has {lines} of them: give {lines} sums (or {} with --total), got {given}",
                lines.saturating_sub(1)
            ),
        })
    };
    Ok(SumTargets {
        rows: complete("--rows", &args.rows, n)?,
        columns: complete("--cols", &args.cols, m)?,
    })
}

/// Prints what was written.
fn report(output: &Path, n: usize, m: usize, coord: Coordinate, largest: f64) {
    let name = match coord {
        Coordinate::X => "x",
        Coordinate::Y => "y",
        Coordinate::Z => "z",
    };
    eprintln!(
        "karkas: wrote {} ({name} of the {n} x {m} grid varied; largest change {largest:.6e})",
        crate::output::target::shown(output).display()
    );
}

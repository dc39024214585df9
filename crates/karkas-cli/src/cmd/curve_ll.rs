//! `karkas curve ll`: the LL curve of an ordered point list (seed 000, METHODS.md §1.2).

use super::output::ensure_distinct;
use crate::samples::{default_curve_samples, parse_count};
use anyhow::{anyhow, bail, Result};
use clap::Args;
use karkas::ll::{LlCurve, LlKernel};
use karkas::{Curve, Point, Point2};
use karkas_io::points::{read_curve_points, CurvePoints};
use karkas_io::svg::{write_curve_svg, CurvePlot};
use karkas_io::write::write_curve_csv;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};

/// The largest number of samples one command writes (a guard against a mistyped count
/// exhausting memory).
pub const MAX_SAMPLES: usize = 50_000_000;

/// Arguments of `karkas curve ll`.
#[derive(Debug, Args)]
pub struct CurveLlArgs {
    /// LL order L (at least 1): the curve is C^L, made of polynomial pieces of degree 2L.
    #[arg(long, default_value_t = 3)]
    order: usize,
    /// Close the curve (the last point is joined to the first unless it repeats it).
    #[arg(long)]
    closed: bool,
    /// Pass through every input point instead of approximating the polygon.
    #[arg(long)]
    interpolate: bool,
    /// Number of samples, uniform in t over the curve's domain, ends included
    /// [default: 10 per input point, at least 200].
    #[arg(long, value_parser = parse_count)]
    samples: Option<usize>,
    /// Input points: CSV or whitespace columns x,y[,z], or an airfoil .dat (Selig or Lednicer).
    input: PathBuf,
    /// Output file: .csv (t,x,y[,z]) or .svg (picture of the curve over its points).
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas curve ll`.
pub fn run(args: &CurveLlArgs) -> Result<()> {
    let format = OutputFormat::from_path(&args.output, &[OutputFormat::Csv, OutputFormat::Svg])?;
    LlKernel::new(args.order).map_err(|e| anyhow!("--order: {e}"))?;
    if args.samples.is_some_and(|n| n > MAX_SAMPLES) {
        bail!("--samples: at most {MAX_SAMPLES} samples can be written");
    }
    ensure_distinct(&args.input, &args.output)?;
    match read_curve_points(&args.input)? {
        CurvePoints::Planar(points) => build_and_write(args, format, &points),
        CurvePoints::Spatial(points) => build_and_write(args, format, &points),
    }
}

fn build_and_write<const D: usize>(
    args: &CurveLlArgs,
    format: OutputFormat,
    points: &[Point<D>],
) -> Result<()> {
    let build = if args.interpolate {
        LlCurve::interpolating
    } else {
        LlCurve::new
    };
    super::guard::curve_points(&args.input, points)?;
    let n = args
        .samples
        .unwrap_or_else(|| default_curve_samples(points.len()).min(MAX_SAMPLES));
    super::guard::check_memory(
        &format!("curve ll: {n} samples"),
        (n as u128) * (8 + 8 * D as u128),
    )?;
    let curve = build(points, args.order, args.closed)
        .map_err(|e| anyhow!("{}: {e}", args.input.display()))?;
    let mut ts = vec![0.0; n];
    let mut samples = vec![Point::ZERO; n];
    curve.sample_into(&mut ts, &mut samples);
    match format {
        OutputFormat::Svg => {
            let variant = if args.interpolate {
                "interpolating "
            } else {
                ""
            };
            let title = format!(
                "{variant}LL curve, L = {}, {} points{}",
                args.order,
                points.len(),
                if D > 2 { " (x-y projection)" } else { "" }
            );
            let plot = CurvePlot {
                title: &title,
                curve: &project(&samples),
                input: &project(points),
                closed_input: args.closed,
            };
            write_curve_svg(&args.output, &plot)?;
        }
        _ => write_curve_csv(&args.output, &ts, &samples)?,
    }
    report(&args.output, n);
    Ok(())
}

/// The x-y projection of points of any dimension.
fn project<const D: usize>(points: &[Point<D>]) -> Vec<Point2> {
    points.iter().map(|p| Point2::new([p[0], p[1]])).collect()
}

/// Prints what was written.
pub fn report(output: &Path, samples: usize) {
    eprintln!("karkas: wrote {} ({samples} samples)", output.display());
}

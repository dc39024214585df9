//! `karkas curve dps`: a closed discrete curve, the discrete periodic spline through (or with
//! poles at) the input points (seed 002, METHODS.md §3).

use super::curve_ll::{report, MAX_SAMPLES};
use super::export::{to_space, write_curve_html};
use super::output::ensure_distinct;
use anyhow::{anyhow, bail, Result};
use clap::Args;
use karkas::dps::{DiscreteSpline, MAX_ORDER};
use karkas::{Error, Point, Point2};
use karkas_io::png::write_svg_as_png;
use karkas_io::points::{read_curve_points, CurvePoints};
use karkas_io::svg::{render_discrete_curve_svg, write_discrete_curve_svg, DiscreteCurvePlot};
use karkas_io::write::write_discrete_curve_csv;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// Arguments of `karkas curve dps`.
#[derive(Debug, Args)]
pub struct CurveDpsArgs {
    /// Spline order r (1 to 64): r = 1 is the closed polygon, r = 2 behaves like a cubic.
    #[arg(long)]
    order: usize,
    /// Values per input point (at least 2): the curve has N = m n values, j = 0..N-1.
    #[arg(long = "n", value_name = "N")]
    step: usize,
    /// Use the input points as poles (the curve stays in their convex hull) instead of
    /// passing through them at j = l n.
    #[arg(long)]
    poles: bool,
    /// Input points (m of them, at least 2): CSV or whitespace columns x,y[,z], or an airfoil
    /// .dat.
    input: PathBuf,
    /// Output file: .csv (j,x,y[,z]), a picture of the closed curve over its points (.svg,
    /// .png) or a 3-D viewer page (.html).
    #[arg(short, long)]
    output: PathBuf,
}

/// Runs `karkas curve dps`.
pub fn run(args: &CurveDpsArgs) -> Result<()> {
    super::output::refuse_cad_for_discrete(&args.output)?;
    let format = OutputFormat::from_path(&args.output, &super::export::CURVE_FORMATS)?;
    check_order("--order", args.order)?;
    check_step("--n", args.step)?;
    ensure_distinct(&args.input, &args.output)?;
    match read_curve_points(&args.input)? {
        CurvePoints::Planar(points) => build_and_write(args, format, &points),
        CurvePoints::Spatial(points) => build_and_write(args, format, &points),
    }
}

/// Refuses an order outside `1..=MAX_ORDER`, naming the option.
pub fn check_order(option: &str, order: usize) -> Result<()> {
    if order == 0 || order > MAX_ORDER {
        bail!("{option}: the order must be between 1 and {MAX_ORDER}, got {order}");
    }
    Ok(())
}

/// Refuses a step below 2, naming the option.
pub fn check_step(option: &str, step: usize) -> Result<()> {
    if step < 2 {
        bail!("{option}: the number of values per point must be at least 2, got {step}");
    }
    Ok(())
}

fn build_and_write<const D: usize>(
    args: &CurveDpsArgs,
    format: OutputFormat,
    points: &[Point<D>],
) -> Result<()> {
    super::guard::curve_points(&args.input, points)?;
    let m = points.len();
    let period = m.saturating_mul(args.step);
    if period > MAX_SAMPLES {
        bail!(
            "--n: {m} points x {} = {period} values, more than the {MAX_SAMPLES} that can be written",
            args.step
        );
    }
    let build = if args.poles {
        DiscreteSpline::from_poles
    } else {
        DiscreteSpline::interpolating
    };
    let spline = build(points, args.order, args.step).map_err(|e| match e {
        Error::InvalidOrder { .. } => anyhow!("--order: {e}"),
        Error::InvalidStep { .. } | Error::PeriodTooLarge { .. } => anyhow!("--n: {e}"),
        _ => anyhow!("{}: {e}", args.input.display()),
    })?;
    let mut values = vec![Point::ZERO; period];
    spline.values(&mut values);
    match format {
        OutputFormat::Svg | OutputFormat::Png => {
            let title = format!(
                "discrete periodic spline, order {}, {m} {}, n = {} ({period} values){}",
                args.order,
                if args.poles { "poles" } else { "nodes" },
                args.step,
                if D > 2 { ", x-y projection" } else { "" }
            );
            let plot = DiscreteCurvePlot {
                title: &title,
                values: &project(&values),
                dots: false,
                input: &project(points),
            };
            if format == OutputFormat::Png {
                let svg = render_discrete_curve_svg(&plot).map_err(|e| anyhow!("{e}"))?;
                write_svg_as_png(&args.output, &svg)?;
            } else {
                write_discrete_curve_svg(&args.output, &plot)?;
            }
        }
        OutputFormat::Html => {
            let title = format!(
                "discrete periodic spline, order {}, n = {} ({period} values)",
                args.order, args.step
            );
            let mut closed = to_space(&values);
            closed.extend(closed.first().copied());
            write_curve_html(&args.output, &title, &closed, &to_space(points))?;
        }
        _ => write_discrete_curve_csv(&args.output, &values)?,
    }
    report(&args.output, period);
    Ok(())
}

/// The x-y projection of points of any dimension.
fn project<const D: usize>(points: &[Point<D>]) -> Vec<Point2> {
    points.iter().map(|p| Point2::new([p[0], p[1]])).collect()
}

//! `karkas curve dps`: a closed discrete curve, the discrete periodic spline through (or with
//! poles at) the input points (Malozemov et al., docs/methods.md §3).

use crate::args::{check_dps_order, check_dps_step, CurveInputOptions};
use crate::input::{curve_points, run_on_curve_points, CurveCommand, CurveJob};
use crate::output::cad::refuse_cad_for_discrete;
use crate::output::curve::curve_output_bytes;
use crate::output::formats::CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::{report_samples, MAX_SAMPLES};
use crate::output::target::output_formats;
use anyhow::{bail, Result};
use clap::Args;
use karkas::dps::DiscreteSpline;
use karkas::{Error, Point};
use karkas_io::export::curve::{write_discrete_curve, DiscreteTitles};
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
    #[command(flatten)]
    read: CurveInputOptions,
    /// Output file: .csv (j,x,y[,z]), a picture of the closed curve over its points (.svg,
    /// .png) or a 3-D viewer page (.html). Repeat -o for several outputs of one curve.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
}

/// Runs `karkas curve dps`.
pub fn run(args: &CurveDpsArgs) -> Result<()> {
    for output in &args.output {
        refuse_cad_for_discrete(output, &OutputFormat::CURVE_CAD)?;
    }
    let formats = output_formats(&args.output, &CURVE_FORMATS)?;
    check_dps_order("--order", args.order)?;
    check_dps_step("--n", args.step)?;
    for output in &args.output {
        ensure_distinct(&args.input, output)?;
    }
    run_on_curve_points(&args.input, &args.read, &CurveCommand::new(args, &formats))
}

impl CurveJob for CurveCommand<'_, CurveDpsArgs> {
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let Self { args, formats } = *self;
        curve_points(&args.input, points)?;
        let m = points.len();
        let period = m.saturating_mul(args.step);
        if period > MAX_SAMPLES {
            bail!(
                "--n: {m} points x {} = {period} values, more than the {MAX_SAMPLES} that can be written",
                args.step
            );
        }
        // The values, and as much again for the spline's work.
        for &format in formats {
            check_memory(
                &format!("curve dps: {period} values"),
                curve_output_bytes::<D>(format, period + m) + period as u128 * 8 * D as u128,
            )?;
        }
        let build = if args.poles {
            DiscreteSpline::from_poles
        } else {
            DiscreteSpline::interpolating
        };
        let spline = build(points, args.order, args.step).map_err(|e| {
            let at = match e {
                Error::InvalidOrder { .. } => "--order".to_owned(),
                Error::InvalidStep { .. } | Error::PeriodTooLarge { .. } => "--n".to_owned(),
                _ => args.input.display().to_string(),
            };
            anyhow::Error::new(e).context(at)
        })?;
        let mut values = vec![Point::ZERO; period];
        spline.values(&mut values);
        let picture = format!(
            "discrete periodic spline, order {}, {m} {}, n = {} ({period} values){}",
            args.order,
            if args.poles { "poles" } else { "nodes" },
            args.step,
            if D > 2 { ", x-y projection" } else { "" }
        );
        let page = format!(
            "discrete periodic spline, order {}, n = {} ({period} values)",
            args.order, args.step
        );
        let titles = DiscreteTitles {
            picture: &picture,
            page: &page,
        };
        for (output, &format) in args.output.iter().zip(formats) {
            write_discrete_curve(output, format, &values, points, &titles)?;
            report_samples(output, period);
        }
        Ok(())
    }
}

//! `karkas curve ll`: the LL curve of an ordered point list (Aulchenko et al., docs/methods.md §1.2).

use crate::args::{check_ll_order, CombOption, CurveSamples};
use crate::input::{curve_points, run_on_curve_points, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::curve::{curve_output_bytes, write_sampled_curve};
use crate::output::formats::EXACT_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::sample_curve;
use crate::output::samples::{default_curve_samples, report_samples, MAX_SAMPLES};
use crate::output::target::output_format;
use anyhow::{Context, Result};
use clap::Args;
use karkas::ll::LlCurve;
use karkas::{Curve, Point, Point2};
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// Arguments of `karkas curve ll`.
#[derive(Debug, Args)]
pub struct CurveLlArgs {
    /// LL order L (at least 1): the curve is C^L, made of polynomial pieces of degree 2L.
    #[arg(long, default_value_t = karkas::ll::DEFAULT_ORDER)]
    order: usize,
    /// Close the curve (the last point is joined to the first unless it repeats it).
    #[arg(long)]
    closed: bool,
    /// Pass through every input point instead of approximating the polygon.
    #[arg(long)]
    interpolate: bool,
    #[command(flatten)]
    samples: CurveSamples,
    /// Input points: CSV or whitespace columns x,y[,z], or an airfoil .dat (Selig or Lednicer).
    input: PathBuf,
    /// Output file: .csv (t,x,y[,z]), a picture of the curve over its points (.svg, .png;
    /// x-y projection) a 3-D viewer page (.html), or
    /// the exact B-spline curve as .step/.stp, .iges/.igs or .dxf (a SPLINE with the input
    /// points; planar curves in z = 0).
    #[arg(short, long)]
    output: PathBuf,
    #[command(flatten)]
    comb: CombOption,
    /// Pictures: draw a whisker from every input point to the curve at its node.
    #[arg(long)]
    whiskers: bool,
}

/// Runs `karkas curve ll`.
pub fn run(args: &CurveLlArgs) -> Result<()> {
    let format = output_format(&args.output, &EXACT_CURVE_FORMATS)?;
    check_ll_order(args.order)?;
    args.samples.check()?;
    ensure_distinct(&args.input, &args.output)?;
    run_on_curve_points(&args.input, &(args, format))
}

impl CurveJob for (&CurveLlArgs, OutputFormat) {
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let (args, format) = *self;
        curve_points(&args.input, points)?;
        let curve = build_ll(
            points,
            args.order,
            args.closed,
            args.interpolate,
            &args.input,
        )?;
        if format.is_cad() {
            return write_cad_curve(&curve, points, format, &args.output, args.input.display());
        }
        let n = args
            .samples
            .or_else(|| default_curve_samples(points.len()).min(MAX_SAMPLES));
        check_memory(
            &format!("curve ll: {n} samples"),
            curve_output_bytes::<D>(format, n + points.len()),
        )?;
        let (ts, samples) = sample_curve(&curve, n);
        let variant = if args.interpolate {
            "interpolating "
        } else {
            ""
        };
        let title = format!(
            "{variant}LL curve, L = {}, {} points",
            args.order,
            points.len()
        );
        let comb = args.comb.teeth(&curve, &ts);
        let whiskers = if args.whiskers {
            node_whiskers(&curve, points)
        } else {
            Vec::new()
        };
        let (output, overlay) = (&args.output, (&comb[..], &whiskers[..]));
        let samples = (&ts[..], &samples[..]);
        write_sampled_curve(
            output,
            format,
            &title,
            samples,
            points,
            args.closed,
            overlay,
        )?;
        report_samples(&args.output, n);
        Ok(())
    }
}

/// The LL curve of `points` (approximating, or interpolating when `interpolate`), errors
/// naming `input`.
pub(super) fn build_ll<const D: usize>(
    points: &[Point<D>],
    order: usize,
    closed: bool,
    interpolate: bool,
    input: &std::path::Path,
) -> Result<LlCurve<D>> {
    let build = if interpolate {
        LlCurve::interpolating
    } else {
        LlCurve::new
    };
    build(points, order, closed).with_context(|| input.display().to_string())
}

/// Whiskers from every input point (x-y projection) to the curve at its node: point `i`
/// (1-based) of `K` at `t = i / (K + 1)` (a closed curve's nodes are spread the same way over
/// its domain).
fn node_whiskers<const D: usize>(curve: &LlCurve<D>, points: &[Point<D>]) -> Vec<[Point2; 2]> {
    let (axis, domain) = (curve.axis(), curve.domain());
    points
        .iter()
        .enumerate()
        .map(|(k, p)| (p, axis.node(k + 1)))
        .filter(|(_, t)| domain.contains(*t))
        .map(|(p, t)| {
            let q = curve.eval(t);
            [Point2::new([p[0], p[1]]), Point2::new([q[0], q[1]])]
        })
        .collect()
}

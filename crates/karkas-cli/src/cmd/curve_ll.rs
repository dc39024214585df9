//! `karkas curve ll`: the LL curve of an ordered point list (Aulchenko et al., docs/methods.md §1.2).

use crate::args::{
    check_ll_order, CadOptions, CloseTeOption, CombOption, CurveInputOptions, CurveSamples,
};
use crate::input::{curve_points, run_on_curve_points, CurveCommand, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::console::{note, record};
use crate::output::curve::{curve_output_bytes, whiskers, write_curve_samples};
use crate::output::formats::STREAMED_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::report_samples;
use crate::output::self_crossing::warn_self_crossing;
use crate::output::target::output_formats;
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::ll::{LlCurve, WithinFit};
use karkas::{Curve, Point, Point2};
use karkas_io::export::curve::CurveDrawing;
use karkas_io::export::stream;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};

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
    /// Pass within distance D (model units) of every input point at its node, keeping the
    /// order L: between the approximation and --interpolate (system (6) solved for targets
    /// pulled to distance D). D at or above the approximation's largest deviation gives the
    /// approximation itself.
    #[arg(
        long,
        value_name = "D",
        conflicts_with = "interpolate",
        allow_hyphen_values = true
    )]
    within: Option<f64>,
    #[command(flatten)]
    samples: CurveSamples,
    /// Input points: CSV or whitespace columns x,y[,z], or an airfoil .dat (Selig or Lednicer).
    /// A first and last point within 1e-6 of the diagonal of the points' bounding box are one
    /// point (a sharp trailing edge; the rule of curve fit): the curve's ends meet there, at
    /// their midpoint (not with --closed).
    input: PathBuf,
    #[command(flatten)]
    read: CurveInputOptions,
    /// Output file: .csv (t,x,y[,z]), .npy (the samples' points, an (n, dim) float64 array),
    /// a picture of the curve over its points (.svg, .png; x-y projection) a 3-D viewer page
    /// (.html), or
    /// the exact B-spline curve as .step/.stp, .iges/.igs or .dxf (a SPLINE with the input
    /// points; planar curves in z = 0). Repeat -o for several outputs of one curve.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
    #[command(flatten)]
    cad: CadOptions,
    #[command(flatten)]
    close: CloseTeOption,
    #[command(flatten)]
    comb: CombOption,
    /// Pictures: draw a whisker from every input point to the curve at its node.
    #[arg(long)]
    whiskers: bool,
}

/// Runs `karkas curve ll`.
pub fn run(args: &CurveLlArgs) -> Result<()> {
    let formats = output_formats(&args.output, &STREAMED_CURVE_FORMATS)?;
    check_ll_order(args.order)?;
    check_within(args.within)?;
    args.samples.check()?;
    args.cad.check(&formats)?;
    args.close
        .check(&formats, args.closed.then_some("--closed"))?;
    for output in &args.output {
        ensure_distinct(&args.input, output)?;
    }
    run_on_curve_points(&args.input, &args.read, &CurveCommand::new(args, &formats))
}

impl CurveJob for CurveCommand<'_, CurveLlArgs> {
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let Self { args, formats } = *self;
        curve_points(&args.input, points)?;
        args.close.check_points(points, &args.input)?;
        if args.closed {
            crate::output::console::warn_near_miss("--closed", points);
        }
        // Ends that coincide by the shared-end rule meet exactly (the library's rule; the
        // written input points say the same).
        let shared;
        let points = if args.closed {
            points
        } else {
            shared = karkas::core::with_shared_end(points);
            &shared
        };
        let curve = match args.within {
            Some(distance) => {
                build_ll_within(points, args.order, args.closed, distance, &args.input)?
            }
            None => build_ll(
                points,
                args.order,
                args.closed,
                args.interpolate,
                &args.input,
            )?,
        };
        let remedy = if args.interpolate {
            "the interpolating LL curve takes its points at evenly spaced parameters and \
             overshoots where they lie very unevenly apart (less at a higher --order, whose \
             control points move less): the approximating LL curve (without --interpolate), \
             curve spline or curve fit follow them"
        } else {
            "look at the points there (out of order, or a sharp turn)"
        };
        warn_self_crossing(&curve, points, &args.input, remedy);
        for (output, &format) in args.output.iter().zip(formats) {
            write_ll(args, &curve, points, output, format)?;
        }
        Ok(())
    }
}

/// Writes the LL `curve` of `points` to `output` in `format`.
fn write_ll<const D: usize>(
    args: &CurveLlArgs,
    curve: &LlCurve<D>,
    points: &[Point<D>],
    output: &Path,
    format: OutputFormat,
) -> Result<()> {
    if format.is_cad() {
        let what = args.input.display();
        let cad = (&args.cad, args.close.close_te);
        return write_cad_curve(curve, points, format, output, cad, what);
    }
    let n = args.samples.resolve(points.len());
    // The cap is checked against the samples held, as before CSV and .npy were written
    // block by block (they take one block now): the same requests pass as before.
    check_memory(
        &format!("curve ll: {n} samples"),
        curve_output_bytes::<D>(format, n + points.len()),
    )?;
    if stream::streams(format) {
        stream::write_curve_samples(curve, n, format, output)?;
        report_samples(output, n);
        return Ok(());
    }
    let variant = match (args.interpolate, args.within) {
        (true, _) => "interpolating ".to_owned(),
        (false, Some(d)) => format!("within {d} "),
        (false, None) => String::new(),
    };
    let title = format!(
        "{variant}LL curve, L = {}, {} points",
        args.order,
        points.len()
    );
    let whiskers = match args.whiskers {
        true => node_whiskers(curve, points),
        false => Vec::new(),
    };
    let drawing = CurveDrawing {
        title: &title,
        input: points,
        closed_input: args.closed,
        comb: args.comb.comb,
    };
    write_curve_samples(output, format, (curve, n), &drawing, &whiskers)?;
    report_samples(output, n);
    Ok(())
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

/// Refuses a `--within` distance that is not positive and finite.
pub(super) fn check_within(within: Option<f64>) -> Result<()> {
    match within {
        Some(d) if !(d > 0.0 && d.is_finite()) => {
            bail!("--within: the distance must be positive and finite (model units), got {d}")
        }
        _ => Ok(()),
    }
}

/// Reports on standard error (and in a batch record) what `--within` achieved.
pub(super) fn report_within<T>(fit: &WithinFit<T>, distance: f64, what: &str) {
    let how = if fit.pulled_nodes == 0 {
        "the approximation is already within it, nothing solved".to_owned()
    } else {
        format!(
            "{} of {} nodes pulled in, system (6) solved once (direct, no iterations)",
            fit.pulled_nodes, fit.nodes
        )
    };
    note(format!(
        "karkas: {what} within {distance}: largest node deviation {:.6e} (approximation \
         {:.6e}); {how}",
        fit.largest_deviation, fit.plain_deviation
    ));
    record("within", distance);
    record("largest_deviation", fit.largest_deviation);
    record("plain_deviation", fit.plain_deviation);
    record("pulled_nodes", fit.pulled_nodes);
    record("solves", usize::from(fit.pulled_nodes > 0));
}

/// The LL curve of `points` within `distance` of them (reported on standard error), errors
/// naming `input`.
fn build_ll_within<const D: usize>(
    points: &[Point<D>],
    order: usize,
    closed: bool,
    distance: f64,
    input: &std::path::Path,
) -> Result<LlCurve<D>> {
    let fit = LlCurve::within(points, order, closed, distance)
        .with_context(|| input.display().to_string())?;
    report_within(&fit, distance, "curve ll");
    Ok(fit.shape)
}

/// Whiskers from every input point (x-y projection) to the curve at its node: point `i`
/// (1-based) of `K` at `t = i / (K + 1)` (a closed curve's nodes are spread the same way over
/// its domain).
fn node_whiskers<const D: usize>(curve: &LlCurve<D>, points: &[Point<D>]) -> Vec<[Point2; 2]> {
    let (axis, domain) = (curve.axis(), curve.domain());
    let nodes = points
        .iter()
        .enumerate()
        .map(|(k, p)| (p, axis.node(k + 1)));
    whiskers(curve, nodes.filter(|(_, t)| domain.contains(*t)))
}

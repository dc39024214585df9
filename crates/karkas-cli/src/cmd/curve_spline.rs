//! `karkas curve spline`: the cubic interpolating spline through ordered points, with chosen
//! end conditions and point parameters (Kuznetsov and Filatov's spline, its not-a-knot ends
//! (3.10)–(3.12); docs/methods.md §5). The options are [`SplineOptions`], shared with the
//! commands that offer the spline as a method.

use crate::args::{CadOptions, CloseTeOption, CombOption, CurveInputOptions, CurveSamples};
use crate::cmd::spline_options::{EndsKind, SplineOptions};
use crate::input::{curve_points, run_on_curve_points, CurveCommand, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::curve::{curve_output_bytes, whiskers, write_curve_samples};
use crate::output::formats::EXACT_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::report_samples;
use crate::output::self_crossing::warn_self_crossing;
use crate::output::target::output_formats;
use anyhow::Result;
use clap::Args;
use karkas::param::CubicSpline;
use karkas::{Curve, Point};
use karkas_io::export::curve::CurveDrawing;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};

/// Arguments of `karkas curve spline`.
#[derive(Debug, Args)]
pub struct CurveSplineArgs {
    #[command(flatten)]
    spline: SplineOptions,
    #[command(flatten)]
    samples: CurveSamples,
    /// Input points: CSV or whitespace columns x,y[,z], or an airfoil .dat (Selig or Lednicer).
    /// A first and last point within 1e-6 of the diagonal of the points' bounding box are one
    /// point (a sharp trailing edge; the rule of curve fit): the curve's ends meet there, at
    /// their midpoint, in a corner with natural ends unless --ends says otherwise (not with
    /// --ends periodic).
    input: PathBuf,
    #[command(flatten)]
    read: CurveInputOptions,
    /// Output file: .csv (t,x,y[,z] in the spline's parameter), a picture of the curve over
    /// its points (.svg, .png; x-y projection), a 3-D viewer page (.html), or the exact
    /// B-spline curve as .step/.stp, .iges/.igs or .dxf (a SPLINE with the input points on
    /// their own layer; planar curves in z = 0). Repeat -o for several outputs of one spline.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
    #[command(flatten)]
    cad: CadOptions,
    #[command(flatten)]
    close: CloseTeOption,
    #[command(flatten)]
    comb: CombOption,
    /// Pictures: draw a whisker from every input point to the curve at its knot (of zero
    /// length up to rounding: the spline passes through its points).
    #[arg(long)]
    whiskers: bool,
}

/// Runs `karkas curve spline`.
pub fn run(args: &CurveSplineArgs) -> Result<()> {
    let formats = output_formats(&args.output, &EXACT_CURVE_FORMATS)?;
    args.spline.check()?;
    args.samples.check()?;
    args.cad.check(&formats)?;
    let periodic = (args.spline.kind() == EndsKind::Periodic).then_some("--ends periodic");
    args.close.check(&formats, periodic)?;
    for output in &args.output {
        ensure_distinct(&args.input, output)?;
    }
    run_on_curve_points(&args.input, &args.read, &CurveCommand::new(args, &formats))
}

impl CurveJob for CurveCommand<'_, CurveSplineArgs> {
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let Self { args, formats } = *self;
        curve_points(&args.input, points)?;
        args.close.check_points(points, &args.input)?;
        let curve = args.spline.build(points, &args.input)?;
        // The points the spline interpolates, written and checked: with open ends the
        // library's (ends that coincide by the shared-end rule made one point); periodic ends
        // keep the input's (the library appends the seam point).
        let points = match args.spline.kind() {
            EndsKind::Periodic => points,
            _ => curve.values(),
        };
        let remedy = "look at the points there (out of order, or very unevenly apart: curve fit \
                      follows such points)";
        warn_self_crossing(&curve, points, &args.input, remedy);
        for (output, &format) in args.output.iter().zip(formats) {
            write_spline(args, &curve, points, output, format)?;
        }
        Ok(())
    }
}

/// Writes the spline `curve` through `points` to `output` in `format`.
fn write_spline<const D: usize>(
    args: &CurveSplineArgs,
    curve: &CubicSpline<D>,
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
    check_memory(
        &format!("curve spline: {n} samples"),
        curve_output_bytes::<D>(format, n + points.len()),
    )?;
    let title = format!(
        "cubic spline, {}, {} points",
        args.spline.describe(points),
        points.len()
    );
    let feet = curve.values().iter().zip(curve.knots().iter().copied());
    let whiskers = match args.whiskers {
        true => whiskers(curve, feet),
        false => Vec::new(),
    };
    let drawing = CurveDrawing {
        title: &title,
        input: points,
        closed_input: curve.is_closed(),
        comb: args.comb.comb,
    };
    write_curve_samples(output, format, (curve, n), &drawing, &whiskers)?;
    report_samples(output, n);
    Ok(())
}

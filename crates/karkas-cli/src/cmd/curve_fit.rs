//! `karkas curve fit`: a C^1 cubic Hermite spline fitted to measured points with bounded
//! second-derivative jumps (Pavlov, docs/methods.md §4).

use super::fit_options::FitCurveOptions;
use super::fit_summary::FitSummary;
use crate::args::{CadOptions, CloseTeOption, CombOption, CurveInputOptions, CurveSamples};
use crate::input::{run_on_curve_points, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::console::{note, warn_open_near_miss};
use crate::output::curve::{curve_output_bytes, whiskers, write_sampled_curve};
use crate::output::formats::EXACT_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::sample_curve;
use crate::output::target::{output_formats, shown};
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::fit::{closed_bspline, CurveFit};
use karkas::Point;
use karkas_io::write::write_atomic;
use karkas_io::OutputFormat;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `karkas curve fit`.
#[derive(Debug, Args)]
#[command(mut_arg("samples", |a| a.value_name("N").help(
    "Number of samples of the fitted curve, uniform in t, ends included [default: 20 per \
     piece, at least 200]"
)))]
#[command(mut_arg("comb", |a| a.help("Pictures: draw the curvature comb of the fitted curve")))]
pub struct CurveFitArgs {
    /// Input points, in order along the curve: CSV or whitespace columns x,y[,z], or an
    /// airfoil .dat.
    input: PathBuf,
    #[command(flatten)]
    fit: FitCurveOptions,
    /// Fit a closed contour (a frame, a section of a fuselage or hull): one periodic spline,
    /// C^1 across the seam (a cubic of defect 2 is C^1 at every knot; its second derivative
    /// jumps by what --eps allows), the seam at the first point (t = 0, held there), the
    /// period's parameters started by closed chord length. --knots gives the knots of one
    /// period (0 = T1 < ... < TN = 1; --corner 0 makes the seam a corner); --tolerance
    /// inserts knots in every piece, the seam's included. A last point that repeats the first
    /// is dropped. STEP, IGES and DXF get one closed B-spline; CSV and pictures the closed
    /// curve. Needs at least 3 points and a point per piece.
    #[arg(long, conflicts_with_all = ["pin_ends", "free_ends", "close_te"])]
    closed: bool,
    /// Also print the summary as one JSON object on standard output (keys input, points,
    /// knots, closed, max_deviation, rms_deviation, f, p, noise, bending_weight, tolerance,
    /// tolerance_met, warnings, seconds).
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    samples: CurveSamples,
    #[command(flatten)]
    read: CurveInputOptions,
    /// Output: .csv (t,x,y[,z] samples of the curve), a picture .svg or .png (points, curve,
    /// deviation whiskers; x-y projection) a 3-D viewer page (.html), or
    /// the exact B-spline curve as .step/.stp, .iges/.igs or .dxf (a SPLINE with the input
    /// points; planar curves in z = 0). Repeat -o for several outputs of one fit.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
    #[command(flatten)]
    cad: CadOptions,
    #[command(flatten)]
    close: CloseTeOption,
    #[command(flatten)]
    comb: CombOption,
    /// Per-point deviations as CSV: point,t,distance.
    #[arg(long, value_name = "DEV.csv")]
    report: Option<PathBuf>,
}

/// Runs `karkas curve fit`.
pub fn run(args: &CurveFitArgs) -> Result<()> {
    let formats = output_formats(&args.output, &EXACT_CURVE_FORMATS)?;
    let knots = args.fit.check()?;
    args.samples.check()?;
    args.cad.check(&formats)?;
    args.close.check(&formats, None)?;
    if args.fit.knots.is_none() && args.fit.tolerance.is_none() {
        bail!("give the knots (--knots T1,...,TN) or a tolerance (--tolerance TOL)");
    }
    for output in &args.output {
        ensure_distinct(&args.input, output)?;
    }
    if let Some(report) = &args.report {
        ensure_distinct(&args.input, report)?;
        if args.output.contains(report) {
            bail!("--report: must differ from the output file");
        }
    }
    let job = FitJob {
        args,
        formats,
        knots,
    };
    run_on_curve_points(&args.input, &args.read, &job)
}

/// `curve fit` on the points of its input: the arguments, the format of each output and the
/// knots given (none: the tolerance picks them).
struct FitJob<'a> {
    args: &'a CurveFitArgs,
    formats: Vec<OutputFormat>,
    knots: Option<Vec<f64>>,
}

impl CurveJob for FitJob<'_> {
    fn refuses_disorder(&self) -> bool {
        true
    }

    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let (args, formats, knots) = (self.args, &self.formats, &self.knots);
        let input = || args.input.display().to_string();
        args.close.check_points(points, &args.input)?;
        if !(args.fit.free_ends || args.close.close_te || args.closed) {
            warn_open_near_miss(
                points,
                "--close-te closes it with the straight segment between them in STEP, IGES and \
                 DXF (repeat the first point exactly as the last to close it at that point)",
            );
        }
        let started = Instant::now();
        let fit: CurveFit<D> = if args.closed {
            args.fit.fit_closed(points, knots.as_deref(), &input())?
        } else {
            args.fit.fit(points, knots.as_deref(), None, &input())?
        };
        let fit_time = started.elapsed();
        let mut summary = FitSummary::new(input(), &fit, args.fit.tolerance, fit_time);
        summary.closed = args.closed;
        for warning in &fit.warnings {
            note(format!("karkas: warning: {warning}"));
        }
        let n = args.samples.resolve(2 * fit.spline.pieces());
        for &format in formats {
            check_memory(
                &format!("curve fit: {n} samples"),
                curve_output_bytes::<D>(format, n + points.len()),
            )?;
        }
        let (ts, samples) = sample_curve(&fit.spline, n);
        if let Some(report) = &args.report {
            write_atomic(report, |w| {
                writeln!(w, "point,t,distance")?;
                for (i, (t, d)) in fit.parameters.iter().zip(&fit.distances).enumerate() {
                    writeln!(w, "{},{t},{d}", i + 1)?;
                }
                Ok(())
            })?;
        }
        for (output, &format) in args.output.iter().zip(formats) {
            if format.is_cad() {
                let what = args.input.display();
                let cad = (&args.cad, args.close.close_te);
                if args.closed {
                    let closed = closed_bspline(&fit.spline).context("--closed")?;
                    write_cad_curve(&closed, points, format, output, cad, what)?;
                } else {
                    write_cad_curve(&fit.spline, points, format, output, cad, what)?;
                }
            } else {
                let samples = (&ts[..], &samples[..]);
                write_fit_picture_or_samples(args, output, format, points, &fit, samples)?;
            }
            let what = if format.is_cad() {
                "the exact B-spline".to_string()
            } else {
                format!("{n} samples")
            };
            note(format!(
                "karkas: wrote {} ({what}); {}",
                shown(output).display(),
                summary.line()
            ));
        }
        crate::output::console::record_all(serde_json::to_value(&summary)?);
        if args.json && !crate::output::console::is_capturing() {
            println!("{}", serde_json::to_string(&summary)?);
        }
        Ok(())
    }
}

/// Writes the samples of a fit as CSV, a picture or a page (with the points, the deviation
/// whiskers and the comb).
fn write_fit_picture_or_samples<const D: usize>(
    args: &CurveFitArgs,
    output: &Path,
    format: OutputFormat,
    points: &[Point<D>],
    fit: &CurveFit<D>,
    (ts, samples): (&[f64], &[Point<D>]),
) -> Result<()> {
    // The whiskers are drawn, not written: a CSV of samples needs none (two points per
    // input point would double the memory of a large fit).
    let whiskers = if format == OutputFormat::Csv {
        Vec::new()
    } else {
        whiskers(
            &fit.spline,
            points.iter().zip(fit.parameters.iter().copied()),
        )
    };
    let comb = args.comb.teeth(&fit.spline, ts);
    let title = format!(
        "{}defect-2 cubic spline fit, {} knots, {} points, max deviation {:.3e}",
        if args.closed { "closed " } else { "" },
        fit.spline.knots().len(),
        points.len(),
        fit.max_distance()
    );
    let overlay = (&comb[..], &whiskers[..]);
    let samples = (ts, samples);
    write_sampled_curve(
        output,
        format,
        &title,
        samples,
        points,
        args.closed,
        overlay,
    )?;
    Ok(())
}

//! `karkas curve fair`: the fairest C^2 cubic B-spline within a tolerance of every input point
//! (least ∫ (dκ/ds)^2 ds; docs/methods.md §8), with its fairness before and after.

use crate::args::{CadOptions, CombOption, CurveInputOptions, CurveSamples};
use crate::input::{curve_points, run_on_curve_points, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::console::{note, record_all};
use crate::output::curve::{curve_output_bytes, whiskers, write_curve_samples};
use crate::output::formats::EXACT_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::fair::{fair_curve, FairCurve, FairEnds, FairOptions};
use karkas::geometry::CurveFairness;
use karkas::Point;
use karkas_io::export::curve::CurveDrawing;
use karkas_io::write::write_atomic;
use karkas_io::OutputFormat;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Bytes the fairer works in per point (the spline, its banded systems and the report's
/// samples), in 3-D.
const FAIR_BYTES_PER_POINT: u128 = 8 * 400;

/// Arguments of `karkas curve fair`.
#[derive(Debug, Args)]
#[command(mut_arg("samples", |a| a.value_name("N").help(
    "Number of samples of the faired curve, uniform in t, ends included [default: 20 per \
     piece, at least 200]"
)))]
#[command(mut_arg("comb", |a| a.help("Pictures: draw the curvature comb of the faired curve")))]
pub struct CurveFairArgs {
    /// Input points, in order along the curve: CSV or whitespace columns x,y[,z], or an
    /// airfoil .dat.
    input: PathBuf,
    /// The largest distance T allowed between any input point and the curve (a hard bound;
    /// about 3 times the noise of measured points).
    #[arg(long, value_name = "T")]
    tolerance: f64,
    /// A point (1-based, as in --report) where the curve may turn a corner: it passes through
    /// it and is faired on each side apart; repeat for several.
    #[arg(long = "corner", value_name = "I")]
    corners: Vec<usize>,
    /// Start at the first point and end at the last.
    #[arg(long)]
    keep_ends: bool,
    /// Keep the ends and the directions of the first and last chords as end tangents.
    #[arg(long)]
    keep_tangents: bool,
    /// The points go once around a closed curve (a last point equal to the first is dropped).
    #[arg(long)]
    closed: bool,
    /// Also print the summary as one JSON object on standard output (keys input, points,
    /// pieces, tolerance, max_deviation, before, after (each with fairness_energy,
    /// curvature_extrema, inflections, max_distance_to_polygon, ...), seconds).
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    samples: CurveSamples,
    #[command(flatten)]
    read: CurveInputOptions,
    #[command(flatten)]
    cad: CadOptions,
    /// Output: .csv (t,x,y[,z] samples of the curve), a picture .svg or .png (points, curve,
    /// deviation whiskers; x-y projection), a 3-D viewer page (.html), or the exact B-spline
    /// curve as .step/.stp, .iges/.igs or .dxf.
    #[arg(short, long)]
    output: PathBuf,
    #[command(flatten)]
    comb: CombOption,
    /// Per-point deviations as CSV: point,t,distance.
    #[arg(long, value_name = "DEV.csv")]
    report: Option<PathBuf>,
}

/// The fairness figures of one curve in the summary.
#[derive(Debug, Serialize)]
struct Figures {
    fairness_energy: f64,
    curvature_extrema: usize,
    inflections: usize,
    max_deviation: f64,
    curvature_min: f64,
    curvature_max: f64,
    length: f64,
}

impl Figures {
    fn new(f: &CurveFairness, max_deviation: f64) -> Self {
        Figures {
            fairness_energy: f.fairness_energy,
            curvature_extrema: f.curvature_extrema,
            inflections: f.inflections,
            max_deviation,
            curvature_min: f.curvature_min,
            curvature_max: f.curvature_max,
            length: f.length,
        }
    }

    fn line(&self) -> String {
        format!(
            "energy {:.4e}, {} curvature extrema, {} inflections, max deviation {:.3e}",
            self.fairness_energy, self.curvature_extrema, self.inflections, self.max_deviation
        )
    }
}

/// The summary of a fairing.
#[derive(Debug, Serialize)]
struct FairSummary {
    input: String,
    points: usize,
    pieces: usize,
    tolerance: f64,
    max_deviation: f64,
    before: Figures,
    after: Figures,
    seconds: f64,
}

/// Runs `karkas curve fair`.
pub fn run(args: &CurveFairArgs) -> Result<()> {
    let format = output_format(&args.output, &EXACT_CURVE_FORMATS)?;
    args.samples.check()?;
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        bail!(
            "--tolerance: must be a positive number, got {}",
            args.tolerance
        );
    }
    if let Some(&bad) = args.corners.iter().find(|&&c| c == 0) {
        bail!("--corner: points are numbered from 1, got {bad}");
    }
    ensure_distinct(&args.input, &args.output)?;
    if let Some(report) = &args.report {
        ensure_distinct(&args.input, report)?;
        if report == &args.output {
            bail!("--report: must differ from the output file");
        }
    }
    args.cad.check(&[format])?;
    run_on_curve_points(&args.input, &args.read, &FairJob { args, format })
}

/// `curve fair` on the points of its input: the arguments and the output's format.
struct FairJob<'a> {
    args: &'a CurveFairArgs,
    format: OutputFormat,
}

impl CurveJob for FairJob<'_> {
    fn refuses_disorder(&self) -> bool {
        true
    }

    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let Self { args, format } = *self;
        let input = args.input.display().to_string();
        curve_points(&args.input, points)?;
        check_memory(
            &format!("curve fair of {} points", points.len()),
            (points.len() as u128).saturating_mul(FAIR_BYTES_PER_POINT),
        )?;
        let options = fair_options(args);
        let started = Instant::now();
        let fair: FairCurve<D> = fair_curve(points, &options).with_context(|| input.clone())?;
        let seconds = started.elapsed().as_secs_f64();
        let after = fair.fairness();
        let before = fair.fairness_before().unwrap_or(after);
        let summary = FairSummary {
            input: input.clone(),
            points: points.len(),
            pieces: after.pieces,
            tolerance: args.tolerance,
            max_deviation: fair.max_distance(),
            before: Figures::new(&before, 0.0),
            after: Figures::new(&after, fair.max_distance()),
            seconds,
        };
        let n = args.samples.resolve(2 * after.pieces);
        check_memory(
            &format!("curve fair: {n} samples"),
            curve_output_bytes::<D>(format, n + points.len()),
        )?;
        if let Some(report) = &args.report {
            write_report(report, &fair)?;
        }
        let what = write_fair_curve(args, format, &fair, points, (n, after.pieces))?;
        note(format!(
            "karkas: wrote {} ({what}); before: {}; after: {}; faired in {:.1} ms",
            shown(&args.output).display(),
            summary.before.line(),
            summary.after.line(),
            seconds * 1e3
        ));
        record_all(serde_json::to_value(&summary)?);
        if args.json && !crate::output::console::is_capturing() {
            println!("{}", serde_json::to_string(&summary)?);
        }
        Ok(())
    }
}

/// The library's options of `curve fair` from its arguments.
fn fair_options(args: &CurveFairArgs) -> FairOptions {
    let ends = if args.keep_tangents {
        FairEnds::KeptWithTangents
    } else if args.keep_ends {
        FairEnds::Kept
    } else {
        FairEnds::Free
    };
    FairOptions {
        tolerance: args.tolerance,
        ends,
        corners: args.corners.iter().map(|c| c - 1).collect(),
        closed: args.closed,
    }
}

/// Writes `--report`: every point's parameter and distance to the fair curve.
fn write_report<const D: usize>(report: &Path, fair: &FairCurve<D>) -> Result<()> {
    Ok(write_atomic(report, |w| {
        writeln!(w, "point,t,distance")?;
        for (i, (t, d)) in fair.parameters.iter().zip(&fair.distances).enumerate() {
            writeln!(w, "{},{t},{d}", i + 1)?;
        }
        Ok(())
    })?)
}

/// Writes the fair curve of `points` (of `pieces` pieces) to the output in `format` (`n`
/// samples, or the exact B-spline in a CAD format), and says what was written.
fn write_fair_curve<const D: usize>(
    args: &CurveFairArgs,
    format: OutputFormat,
    fair: &FairCurve<D>,
    points: &[Point<D>],
    (n, pieces): (usize, usize),
) -> Result<String> {
    let input = args.input.display().to_string();
    Ok(if format.is_cad() {
        write_cad_curve(
            &fair.curve,
            points,
            format,
            &args.output,
            (&args.cad, false),
            &input,
        )?;
        "the exact B-spline".to_string()
    } else {
        let whiskers = whiskers(
            &fair.curve,
            points.iter().zip(fair.parameters.iter().copied()),
        );
        let title = format!(
            "fair C2 cubic, {} pieces, {} points, max deviation {:.3e} (T {:.3e})",
            pieces,
            points.len(),
            fair.max_distance(),
            args.tolerance
        );
        let drawing = CurveDrawing {
            title: &title,
            input: points,
            closed_input: args.closed,
            comb: args.comb.comb,
        };
        write_curve_samples(&args.output, format, (&fair.curve, n), &drawing, &whiskers)?;
        format!("{n} samples")
    })
}

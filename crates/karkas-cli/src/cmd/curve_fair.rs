//! `karkas curve fair`: the fairest C^2 cubic B-spline within a tolerance of every input point
//! (least ∫ (dκ/ds)^2 ds; docs/methods.md §8), with its fairness before and after.

use crate::args::{CadOptions, CombOption, CurveInputOptions, CurveSamples};
use crate::input::{curve_points, run_on_curve_points, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::console::{note, record_all};
use crate::output::curve::{curve_output_bytes, write_sampled_curve};
use crate::output::formats::EXACT_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::sample_curve;
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::fair::{fair_curve, FairCurve, FairEnds, FairOptions};
use karkas::geometry::CurveFairness;
use karkas::{Point, Point2};
use karkas_io::write::write_atomic;
use karkas_io::OutputFormat;
use serde::Serialize;
use std::path::PathBuf;
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
    run_on_curve_points(&args.input, &args.read, &(args, format))
}

impl CurveJob for (&CurveFairArgs, OutputFormat) {
    fn refuses_disorder(&self) -> bool {
        true
    }

    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let (args, format) = (self.0, self.1);
        let input = args.input.display().to_string();
        curve_points(&args.input, points)?;
        check_memory(
            &format!("curve fair of {} points", points.len()),
            (points.len() as u128).saturating_mul(FAIR_BYTES_PER_POINT),
        )?;
        let ends = if args.keep_tangents {
            FairEnds::KeptWithTangents
        } else if args.keep_ends {
            FairEnds::Kept
        } else {
            FairEnds::Free
        };
        let options = FairOptions {
            tolerance: args.tolerance,
            ends,
            corners: args.corners.iter().map(|c| c - 1).collect(),
            closed: args.closed,
        };
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
            write_atomic(report, |w| {
                writeln!(w, "point,t,distance")?;
                for (i, (t, d)) in fair.parameters.iter().zip(&fair.distances).enumerate() {
                    writeln!(w, "{},{t},{d}", i + 1)?;
                }
                Ok(())
            })?;
        }
        let what = if format.is_cad() {
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
            let (ts, samples) = sample_curve(&fair.curve, n);
            let whiskers: Vec<[Point2; 2]> = fair
                .parameters
                .iter()
                .zip(points)
                .map(|(&t, p)| {
                    let f = karkas::Curve::eval(&fair.curve, t);
                    [Point2::new([p[0], p[1]]), Point2::new([f[0], f[1]])]
                })
                .collect();
            let comb = args.comb.teeth(&fair.curve, &ts);
            let title = format!(
                "fair C2 cubic, {} pieces, {} points, max deviation {:.3e} (T {:.3e})",
                after.pieces,
                points.len(),
                fair.max_distance(),
                args.tolerance
            );
            write_sampled_curve(
                &args.output,
                format,
                &title,
                (&ts, &samples),
                points,
                args.closed,
                (&comb, &whiskers),
            )?;
            format!("{n} samples")
        };
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

//! `karkas curve fit`: a C^1 cubic Hermite spline fitted to measured points with bounded
//! second-derivative jumps (Pavlov, docs/methods.md §4).

use super::fit_summary::FitSummary;
use crate::args::{CombOption, CurveSamples};
use crate::input::{run_on_curve_points, CurveJob};
use crate::output::cad::write_cad_curve;
use crate::output::curve::{curve_output_bytes, write_sampled_curve};
use crate::output::formats::EXACT_CURVE_FORMATS;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::default_curve_samples;
use crate::output::samples::sample_curve;
use crate::output::target::{output_format, shown};
use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::fit::{
    fit_curve, fit_curve_adaptive, knots_from_list, CurveFit, FitOptions, DEFAULT_FAIRNESS,
    DEFAULT_SMOOTHING,
};
use karkas::{Curve, Point, Point2};
use karkas_io::write::write_atomic;
use karkas_io::OutputFormat;
use std::path::PathBuf;
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
    /// The knots 0 = T1 < T2 < ... < TN = 1, comma-separated; or one whole number N: N
    /// uniformly spaced knots.
    #[arg(
        long,
        value_delimiter = ',',
        conflicts_with = "tolerance",
        value_name = "T1,...,TN|N"
    )]
    knots: Option<Vec<f64>>,
    /// Place knots automatically until every point is within TOL of the curve.
    #[arg(long, value_name = "TOL")]
    tolerance: Option<f64>,
    /// Bound on the sum of squared second-derivative jumps (Pavlov's J_L) at the inner
    /// knots [default: none, the unconstrained C^1 fit].
    #[arg(long, value_name = "E")]
    eps: Option<f64>,
    /// An inner knot whose jump is left free (a corner); repeat for several.
    #[arg(long = "corner", value_name = "T")]
    corners: Vec<f64>,
    /// Weight rho of the bending energy that keeps the parameterization even (lambda = rho n
    /// for n points on pieces with at most 8 points each, less on denser pieces; 0 for
    /// none).
    #[arg(long, value_name = "RHO", default_value_t = DEFAULT_FAIRNESS)]
    fairness: f64,
    /// Smoothing s: the bending weight grows with the noise estimated from the points,
    /// lambda = (rho + s (sigma / L)^2) n tau (sigma the noise, L the size of the points;
    /// 0 for none).
    #[arg(long, value_name = "S", default_value_t = DEFAULT_SMOOTHING)]
    smoothing: f64,
    /// Also print the summary as one JSON object on standard output (keys input, points,
    /// knots, max_deviation, rms_deviation, f, p, noise, bending_weight, tolerance,
    /// tolerance_met, warnings, seconds).
    #[arg(long)]
    json: bool,
    #[command(flatten)]
    samples: CurveSamples,
    /// Pin the ends of the curve to the first and last points (e.g. a profile closed at a
    /// known trailing edge).
    #[arg(long)]
    pin_ends: bool,
    /// Output: .csv (t,x,y[,z] samples of the curve), a picture .svg or .png (points, curve,
    /// deviation whiskers; x-y projection) a 3-D viewer page (.html), or
    /// the exact B-spline curve as .step/.stp, .iges/.igs or .dxf (a SPLINE with the input
    /// points; planar curves in z = 0).
    #[arg(short, long)]
    output: PathBuf,
    #[command(flatten)]
    comb: CombOption,
    /// Per-point deviations as CSV: point,t,distance.
    #[arg(long, value_name = "DEV.csv")]
    report: Option<PathBuf>,
}

/// The bytes a fit works in per knot, in 3-D (the most): the knot and its spline values and
/// derivatives, the Newton solver's per-piece blocks, its vectors and the banded normal
/// equations (`8 (32 + 48 d^2 + 2 d (16 + 8 d))` with `d = 3`).
const FIT_BYTES_PER_KNOT: u128 = 8 * (32 + 48 * 9 + 6 * (16 + 24));

/// Runs `karkas curve fit`.
pub fn run(args: &CurveFitArgs) -> Result<()> {
    let format = output_format(&args.output, &EXACT_CURVE_FORMATS)?;
    if let [count] = args.knots.as_deref().unwrap_or_default() {
        // A count of uniform knots is checked before the knots and the fit's work arrays are
        // made: per knot the spline, the per-piece blocks of the Newton solver and the band
        // of the normal equations, in 3-D.
        if count.fract() == 0.0 && *count >= 2.0 {
            check_memory(
                &format!("--knots {count}"),
                (*count as u128).saturating_mul(FIT_BYTES_PER_KNOT),
            )?;
        }
    }
    let knots = match &args.knots {
        Some(given) => Some(knots_from_list(given).context("--knots")?),
        None => None,
    };
    if !(args.fairness.is_finite() && args.fairness >= 0.0) {
        bail!("--fairness: must be a number >= 0, got {}", args.fairness);
    }
    if !(args.smoothing.is_finite() && args.smoothing >= 0.0) {
        bail!("--smoothing: must be a number >= 0, got {}", args.smoothing);
    }
    if let Some(tol) = args.tolerance {
        if !(tol.is_finite() && tol > 0.0) {
            bail!("--tolerance: must be a positive number, got {tol}");
        }
    }
    args.samples.check()?;
    if args.knots.is_none() && args.tolerance.is_none() {
        bail!("give the knots (--knots T1,...,TN) or a tolerance (--tolerance TOL)");
    }
    if let Some(eps) = args.eps {
        if eps.is_nan() || eps <= 0.0 {
            bail!("--eps: must be a positive number, got {eps}");
        }
    }
    ensure_distinct(&args.input, &args.output)?;
    if let Some(report) = &args.report {
        ensure_distinct(&args.input, report)?;
        if report == &args.output {
            bail!("--report: must differ from the output file");
        }
    }
    run_on_curve_points(&args.input, &(args, format, knots))
}

impl CurveJob for (&CurveFitArgs, OutputFormat, Option<Vec<f64>>) {
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let (args, format, knots) = (self.0, self.1, &self.2);
        let options = FitOptions {
            eps: args.eps.unwrap_or(f64::INFINITY),
            corners: args.corners.clone(),
            pin_ends: args.pin_ends,
            fairness: args.fairness,
            smoothing: args.smoothing,
            ..Default::default()
        };
        let input = || args.input.display().to_string();
        let started = Instant::now();
        let fit: CurveFit<D> = match (knots, args.tolerance) {
            (Some(knots), _) => fit_curve(points, knots, &options).with_context(input)?,
            (None, Some(tol)) => {
                fit_curve_adaptive(points, tol, &options)
                    .with_context(input)?
                    .fit
            }
            (None, None) => bail!("give --knots or --tolerance"),
        };
        let fit_time = started.elapsed();
        let summary = FitSummary::new(input(), &fit, args.tolerance, fit_time);
        for warning in &fit.warnings {
            eprintln!("karkas: warning: {warning}");
        }
        let n = args
            .samples
            .or_else(|| default_curve_samples(2 * fit.spline.pieces()));
        check_memory(
            &format!("curve fit: {n} samples"),
            curve_output_bytes::<D>(format, n + points.len()),
        )?;
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
        if format.is_cad() {
            write_cad_curve(
                &fit.spline,
                points,
                format,
                &args.output,
                args.input.display(),
            )?;
        } else {
            write_fit_picture_or_samples(args, format, points, &fit, (&ts, &samples))?;
        }
        let what = if format.is_cad() {
            "the exact B-spline".to_string()
        } else {
            format!("{n} samples")
        };
        eprintln!(
            "karkas: wrote {} ({what}); {}",
            shown(&args.output).display(),
            summary.line()
        );
        if args.json {
            println!("{}", serde_json::to_string(&summary)?);
        }
        Ok(())
    }
}

/// Writes the samples of a fit as CSV, a picture or a page (with the points, the deviation
/// whiskers and the comb).
fn write_fit_picture_or_samples<const D: usize>(
    args: &CurveFitArgs,
    format: OutputFormat,
    points: &[Point<D>],
    fit: &CurveFit<D>,
    (ts, samples): (&[f64], &[Point<D>]),
) -> Result<()> {
    let whiskers: Vec<[Point2; 2]> = fit
        .parameters
        .iter()
        .zip(points)
        .map(|(&t, p)| {
            let f = fit.spline.eval(t);
            [Point2::new([p[0], p[1]]), Point2::new([f[0], f[1]])]
        })
        .collect();
    let comb = args.comb.teeth(&fit.spline, ts);
    let title = format!(
        "defect-2 cubic spline fit, {} knots, {} points, max deviation {:.3e}",
        fit.spline.knots().len(),
        points.len(),
        fit.max_distance()
    );
    let (output, overlay) = (&args.output, (&comb[..], &whiskers[..]));
    let samples = (ts, samples);
    write_sampled_curve(output, format, &title, samples, points, false, overlay)?;
    Ok(())
}

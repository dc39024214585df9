//! `karkas curve analyze`: how fair the curves of the LL approximation (Aulchenko et al.,
//! docs/methods.md §1.2), the cubic spline (§5) and the constrained fit (§4) are on the same
//! points: length, curvature range, curvature extrema and inflections, the largest distance
//! from the point polygon and `∫ (dκ/ds)^2 ds` ([`karkas::geometry::curve_fairness`]).

use super::curve_ll::build_ll;
use super::fairness_report::{write_profiles, MethodReport};
use super::fit_options::FitCurveOptions;
use super::spline_options::{EndsKind, SplineOptions};
use crate::args::{check_ll_order, CurveInputOptions};
use crate::input::{curve_points, run_on_curve_points, CurveJob};
use crate::output::console::note;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::target::output_format;
use anyhow::{bail, Result};
use clap::{Args, ValueEnum};
use karkas::geometry::{curvature_profile, curve_fairness};
use karkas::{PiecewiseCurve, Point};
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// A way to make a curve from the points.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Method {
    /// The LL curve (`curve ll`): shape-preserving, no overshoot, rippling curvature.
    Ll,
    /// The cubic interpolating spline (`curve spline`): fair curvature, may overshoot.
    Spline,
    /// The constrained cubic fit (`curve fit`): for measured points with noise.
    Fit,
}

impl Method {
    /// The method's name, as on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Method::Ll => "ll",
            Method::Spline => "spline",
            Method::Fit => "fit",
        }
    }
}

/// The formats `-o` writes.
const PROFILE_FORMATS: [OutputFormat; 3] =
    [OutputFormat::Csv, OutputFormat::Svg, OutputFormat::Png];
/// Share of the points' size the fit is held to when neither --knots nor --tolerance is given.
const DEFAULT_FIT_TOLERANCE: f64 = 1e-4;
/// Samples of the fairness figures per piece, at most (with its working set per sample).
const SAMPLES_PER_PIECE: u128 = 80;
/// Samples per piece of the curvature plot or CSV.
const PROFILE_PER_PIECE: usize = 16;

/// Arguments of `karkas curve analyze`.
#[derive(Debug, Args)]
pub struct CurveAnalyzeArgs {
    /// Input points: CSV or whitespace columns x,y[,z], or an airfoil .dat (Selig or Lednicer).
    input: PathBuf,
    /// The method that makes the curve (spline: the fair interpolant a designer starts from).
    #[arg(long, value_enum, default_value_t = Method::Spline, conflicts_with = "compare")]
    method: Method,
    /// Several methods side by side on the same points, comma-separated (e.g. ll,spline,fit).
    #[arg(long, value_enum, value_delimiter = ',', value_name = "M1,M2,...")]
    compare: Option<Vec<Method>>,
    /// Close the curve, for every method (ll --closed, spline with periodic ends; the fit
    /// makes open curves only). --ends periodic says the same.
    #[arg(long)]
    closed: bool,
    /// LL: the order L (at least 1): pieces of degree 2L.
    #[arg(long, default_value_t = karkas::ll::DEFAULT_ORDER)]
    order: usize,
    /// LL: pass through every input point instead of approximating the polygon.
    #[arg(long)]
    interpolate: bool,
    #[command(flatten)]
    spline: SplineOptions,
    #[command(flatten)]
    fit: FitCurveOptions,
    #[command(flatten)]
    read: CurveInputOptions,
    /// The curvature against the arc length of every method: .csv (method,t,s,curvature;
    /// both one-sided values at a knot) or a plot (.svg, .png).
    #[arg(short, long)]
    output: Option<PathBuf>,
    /// Print the figures as one JSON object keyed by method (keys length, curvature_min,
    /// curvature_max, curvature_extrema, inflections, max_distance_to_polygon,
    /// fairness_energy, pieces, curvature_jump, points) instead of the table.
    #[arg(long)]
    json: bool,
}

/// What the job needs besides the points.
struct Job<'a> {
    args: &'a CurveAnalyzeArgs,
    methods: Vec<Method>,
    spline: SplineOptions,
    knots: Option<Vec<f64>>,
    format: Option<OutputFormat>,
    /// `--closed`, or `--ends periodic`.
    closed: bool,
}

/// Runs `karkas curve analyze`.
pub fn run(args: &CurveAnalyzeArgs) -> Result<()> {
    let mut methods = args.compare.clone().unwrap_or_else(|| vec![args.method]);
    let mut seen = Vec::new();
    methods.retain(|m| {
        let new = !seen.contains(m);
        seen.push(*m);
        new
    });
    let format = match &args.output {
        Some(output) => {
            ensure_distinct(&args.input, output)?;
            Some(output_format(output, &PROFILE_FORMATS)?)
        }
        None => None,
    };
    check_ll_order(args.order)?;
    if args.json
        && args
            .output
            .as_deref()
            .is_some_and(karkas_io::write::is_stdout)
    {
        bail!("-o -: standard output carries the JSON of --json; write the curvature to a file");
    }
    let knots = args.fit.check()?;
    let spline = spline_options(args)?;
    check_unused(args, &methods)?;
    // Periodic ends say that the curve is closed, as --closed does.
    let closed = args.closed || spline.kind() == EndsKind::Periodic;
    if closed && methods.contains(&Method::Fit) {
        let option = if args.closed {
            "--closed"
        } else {
            "--ends periodic"
        };
        bail!("{option}: the fit makes open curves only; leave fit out of --method/--compare");
    }
    let job = Job {
        args,
        methods,
        spline,
        knots,
        format,
        closed,
    };
    run_on_curve_points(&args.input, &args.read, &job)
}

/// The spline's options with `--closed` applied (periodic ends).
fn spline_options(args: &CurveAnalyzeArgs) -> Result<SplineOptions> {
    let mut spline = args.spline.clone();
    spline.check()?;
    match (args.closed, spline.kind()) {
        (true, EndsKind::NotAKnot) => spline.ends = Some(EndsKind::Periodic),
        // The analysis keeps the documented not-a-knot ends at a shared end too: natural ends
        // (curve spline's there) bring the curvature to 0 at the corner, an extremum the
        // section does not have.
        (false, _) if spline.ends.is_none() => spline.ends = Some(EndsKind::NotAKnot),
        (_, EndsKind::Periodic) | (false, _) => {}
        (true, ends) => bail!(
            "--closed: a closed spline has periodic ends, not --ends {}",
            ends.name()
        ),
    }
    Ok(spline)
}

/// Refuses options of a method that is not analyzed.
fn check_unused(args: &CurveAnalyzeArgs, methods: &[Method]) -> Result<()> {
    let given = |method: Method, options: &[(&str, bool)]| -> Result<()> {
        if methods.contains(&method) {
            return Ok(());
        }
        if let Some((name, _)) = options.iter().find(|(_, given)| *given) {
            bail!(
                "{name}: an option of the {} method, which is not among --method/--compare",
                method.name()
            );
        }
        Ok(())
    };
    given(Method::Ll, &[("--interpolate", args.interpolate)])?;
    let s = &args.spline;
    given(
        Method::Spline,
        &[
            ("--ends", s.kind() != EndsKind::NotAKnot),
            ("--start-tangent", s.start_tangent.is_some()),
            ("--end-tangent", s.end_tangent.is_some()),
        ],
    )?;
    let f = &args.fit;
    given(
        Method::Fit,
        &[
            ("--knots", f.knots.is_some()),
            ("--tolerance", f.tolerance.is_some()),
            ("--eps", f.eps.is_some()),
            ("--corner", !f.corners.is_empty()),
            ("--pin-ends", f.pin_ends),
            (
                "--penalty",
                f.penalty != super::fit_options::Penalty::Active,
            ),
        ],
    )
}

/// The fit's tolerance when neither knots nor a tolerance are given: a share of the
/// diagonal of the points' bounding box.
fn default_tolerance<const D: usize>(points: &[Point<D>]) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in points {
        for c in 0..D {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let diagonal = (0..D).map(|c| (hi[c] - lo[c]).powi(2)).sum::<f64>().sqrt();
    DEFAULT_FIT_TOLERANCE * diagonal
}

impl Job<'_> {
    /// The figures (and the curvature profile, when written) of `curve`.
    fn analyze<C: PiecewiseCurve<D>, const D: usize>(
        &self,
        method: Method,
        curve: &C,
        points: &[Point<D>],
    ) -> Result<MethodReport> {
        let pieces = curve.breakpoints().len() as u128;
        let per_sample = (8 * D as u128 + 40) * SAMPLES_PER_PIECE;
        check_memory(
            &format!("curve analyze ({}): {pieces} pieces", method.name()),
            pieces.saturating_mul(per_sample),
        )?;
        let fairness = curve_fairness(curve, points);
        let profile = match self.format {
            Some(_) => curvature_profile(curve, PROFILE_PER_PIECE),
            None => Vec::new(),
        };
        Ok(MethodReport {
            method: method.name(),
            fairness,
            points: points.len(),
            profile,
        })
    }
}

impl CurveJob for Job<'_> {
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()> {
        let args = self.args;
        curve_points(&args.input, points)?;
        let input = args.input.display().to_string();
        let mut reports = Vec::new();
        for &method in &self.methods {
            let report = match method {
                Method::Ll => {
                    let curve = build_ll(
                        points,
                        args.order,
                        self.closed,
                        args.interpolate,
                        &args.input,
                    )?;
                    self.analyze(method, &curve, points)?
                }
                Method::Spline => {
                    let curve = self.spline.build(points, &args.input)?;
                    self.analyze(method, &curve, points)?
                }
                Method::Fit => {
                    let fallback = (self.knots.is_none() && args.fit.tolerance.is_none())
                        .then(|| default_tolerance(points));
                    if let Some(tol) = fallback {
                        note(format!(
                            "karkas: fit to the tolerance {tol:.3e} ({DEFAULT_FIT_TOLERANCE:e} of \
                             the points' size; set --knots or --tolerance)"
                        ));
                    }
                    let fit = args
                        .fit
                        .fit(points, self.knots.as_deref(), fallback, &input)?;
                    for warning in &fit.warnings {
                        note(format!("karkas: warning: fit: {warning}"));
                    }
                    self.analyze(method, &fit.spline, points)?
                }
            };
            reports.push(report);
        }
        if let (Some(output), Some(format)) = (&args.output, self.format) {
            write_profiles(output, format, &input, &reports)?;
        }
        let stdout_taken = args
            .output
            .as_deref()
            .is_some_and(karkas_io::write::is_stdout);
        super::fairness_report::print(&reports, args.json, stdout_taken)
    }
}

//! The options of the constrained C^1 cubic fit to measured points (`curve fit`, and any
//! command that offers the fit as one of its methods): knots or a tolerance, the bound on the
//! second-derivative jumps, corners, fairness and smoothing (Pavlov, docs/methods.md §4).
//!
//! The group is flattened into a command's arguments (`#[command(flatten)]`);
//! [`FitCurveOptions::check`] refuses bad values naming the option, and
//! [`FitCurveOptions::fit`] makes the fit.

use crate::output::memory::check_memory;
use anyhow::{bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::fair::RESOLUTION_ULPS;
use karkas::fit::{
    fit_closed_curve, fit_closed_curve_adaptive, fit_curve, fit_curve_adaptive, knots_from_list,
    work_bytes_per_knot, CurveFit, FitEnds, FitOptions, PenaltyRule, DEFAULT_FAIRNESS,
};
use karkas::geometry::points_out_of_order;
use karkas::Point;

/// The options of a constrained cubic fit.
#[derive(Clone, Debug, Args)]
pub struct FitCurveOptions {
    /// The knots 0 = T1 < T2 < ... < TN = 1, comma-separated; or one whole number N: N
    /// uniformly spaced knots.
    #[arg(
        long,
        value_delimiter = ',',
        conflicts_with = "tolerance",
        value_name = "T1,...,TN|N"
    )]
    pub knots: Option<Vec<f64>>,
    /// Place knots automatically until every point is within TOL of the curve.
    #[arg(long, value_name = "TOL")]
    pub tolerance: Option<f64>,
    /// Bound on the sum of squared second-derivative jumps (Pavlov's J_L) at the inner
    /// knots [default: none, the unconstrained C^1 fit].
    #[arg(long, value_name = "E")]
    pub eps: Option<f64>,
    /// An inner knot whose jump is left free (a corner); repeat for several.
    #[arg(long = "corner", value_name = "T")]
    pub corners: Vec<f64>,
    /// Weight rho of the bending energy that keeps the parameterization even (lambda = rho n
    /// for n points on pieces with at most 8 points each, less on denser pieces; 0 for
    /// none).
    #[arg(long, value_name = "RHO", default_value_t = DEFAULT_FAIRNESS)]
    pub fairness: f64,
    /// Smoothing s: the bending weight grows with the noise estimated from the points,
    /// lambda = (rho + s (sigma / L)^2) n tau (sigma the noise, L the size of the points;
    /// 0 for none), its noise part falling off near the ends of the curve. Default 0.1 on given knots (--knots), 0.3 with --tolerance.
    #[arg(long, value_name = "S")]
    pub smoothing: Option<f64>,
    /// Pin the ends of the curve to the first and last points (e.g. a profile closed at a
    /// known trailing edge).
    #[arg(long)]
    pub pin_ends: bool,
    /// Leave the ends where the foot points put them. By default a first and last point that
    /// coincide (within 1e-6 of the points' size: a closed profile, a sharp trailing edge)
    /// pin both ends at that point, so the curve closes there with a corner; on given knots
    /// each other end of a noisy fit is held on its tangent line where the points towards it
    /// say it lies (noisy points beyond an end pull it outward), and ends that the noise does
    /// not tell apart (a closed trailing edge) at their common point.
    #[arg(long, conflicts_with = "pin_ends")]
    pub free_ends: bool,
    /// How the penalty p is chosen when --eps bounds the jumps: `active` lowers p until the
    /// bound holds with equality (the constrained optimum); `paper` is Pavlov's rule
    /// p = H(q*) / eps, times 10 until the bound holds.
    #[arg(long, value_enum, default_value_t = Penalty::Active)]
    pub penalty: Penalty,
    /// Solve Pavlov's system from N starting parameterizations on the given knots (1: the
    /// paper's chord length; then cumulative chords to the powers 0.5, 0, 0.75, 0.25, 1.5,
    /// 0.875, 0.625) and keep the fit with the smallest sum of squared distances among those
    /// that do not cross themselves or turn beyond their points; 1 to 8 (open fits on given
    /// knots).
    #[arg(
        long,
        value_name = "N",
        default_value_t = 1,
        conflicts_with = "tolerance"
    )]
    pub starts: usize,
}

/// The rule for the penalty `p` (`--penalty`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Penalty {
    /// Lower p until the bound is active.
    Active,
    /// The paper's p = H(q*) / eps, raised tenfold until the bound holds.
    Paper,
}

impl Penalty {
    /// The library's rule.
    pub fn to_library(self) -> PenaltyRule {
        match self {
            Penalty::Active => PenaltyRule::ActiveBound,
            Penalty::Paper => PenaltyRule::SeedBound,
        }
    }
}

impl FitCurveOptions {
    /// Checks the values (memory of a knot count, knots, fairness, smoothing, tolerance, eps)
    /// and returns the knots when given.
    pub fn check(&self) -> Result<Option<Vec<f64>>> {
        if let [count] = self.knots.as_deref().unwrap_or_default() {
            // A count of uniform knots is checked before the knots and the fit's work arrays
            // are made: per knot the spline, the per-piece blocks of the Newton solver and
            // the band of the normal equations, in 3-D.
            if count.fract() == 0.0 && *count >= 2.0 {
                check_memory(
                    &format!("--knots {count}"),
                    // In 3-D, the most.
                    (*count as u128).saturating_mul(work_bytes_per_knot(3)),
                )?;
            }
        }
        let knots = match &self.knots {
            Some(given) => Some(knots_from_list(given).context("--knots")?),
            None => None,
        };
        if !(self.fairness.is_finite() && self.fairness >= 0.0) {
            bail!("--fairness: must be a number >= 0, got {}", self.fairness);
        }
        if let Some(s) = self.smoothing.filter(|s| !(s.is_finite() && *s >= 0.0)) {
            bail!("--smoothing: must be a number >= 0, got {s}");
        }
        if !(1..=8).contains(&self.starts) {
            bail!("--starts: must be 1 to 8, got {}", self.starts);
        }
        if let Some(tol) = self.tolerance {
            if !(tol.is_finite() && tol > 0.0) {
                bail!("--tolerance: must be a positive number, got {tol}");
            }
        }
        if let Some(eps) = self.eps {
            if eps.is_nan() || eps <= 0.0 {
                bail!("--eps: must be a positive number, got {eps}");
            }
        }
        Ok(knots)
    }

    /// The library's options of the fit.
    pub fn options(&self) -> FitOptions {
        FitOptions {
            eps: self.eps.unwrap_or(f64::INFINITY),
            corners: self.corners.clone(),
            ends: if self.pin_ends {
                FitEnds::Pinned
            } else if self.free_ends {
                FitEnds::Free
            } else {
                FitEnds::Auto
            },
            fairness: self.fairness,
            smoothing: self.smoothing,
            penalty: self.penalty.to_library(),
            starts: self.starts,
            ..Default::default()
        }
    }

    /// The fit of `points` on `knots` (from [`check`](Self::check)) or, without them, to
    /// `tolerance` (the option's, else the one given); `input` names the points in errors.
    pub fn fit<const D: usize>(
        &self,
        points: &[Point<D>],
        knots: Option<&[f64]>,
        tolerance: Option<f64>,
        input: &str,
    ) -> Result<CurveFit<D>> {
        let options = self.options();
        // A shuffled list gives a page of warnings about empty knot spans: say once what is
        // wrong instead.
        if let Some(reversals) = points_out_of_order(points) {
            return Err(karkas::Error::PointsOutOfOrder { reversals }).context(input.to_owned());
        }
        let tolerance = self.tolerance.or(tolerance);
        self.check_resolution(points, tolerance, input)?;
        Ok(match (knots, tolerance) {
            (Some(knots), _) => fit_curve(points, knots, &options).context(input.to_owned())?,
            (None, Some(tol)) => {
                fit_curve_adaptive(points, tol, &options)
                    .context(input.to_owned())?
                    .fit
            }
            (None, None) => {
                bail!("give the knots (--knots T1,...,TN) or a tolerance (--tolerance TOL)")
            }
        })
    }

    /// The closed (periodic) fit of `points` (`--closed`, docs/methods.md §4 "Closed
    /// curves"): on `knots` of one period, or to the tolerance; errors name `--closed`.
    pub fn fit_closed<const D: usize>(
        &self,
        points: &[Point<D>],
        knots: Option<&[f64]>,
        input: &str,
    ) -> Result<CurveFit<D>> {
        let options = self.options();
        self.check_resolution(points, self.tolerance, input)?;
        let context = || format!("{input}: --closed");
        Ok(match (knots, self.tolerance) {
            (Some(knots), _) => fit_closed_curve(points, knots, &options).with_context(context)?,
            (None, Some(tol)) => {
                fit_closed_curve_adaptive(points, tol, &options)
                    .with_context(context)?
                    .fit
            }
            (None, None) => {
                bail!("give the knots (--knots T1,...,TN) or a tolerance (--tolerance TOL)")
            }
        })
    }

    /// Refuses a tolerance below what the coordinates of `points` resolve.
    fn check_resolution<const D: usize>(
        &self,
        points: &[Point<D>],
        tolerance: Option<f64>,
        input: &str,
    ) -> Result<()> {
        if let Some(tol) = tolerance {
            // The same bound as `curve fair`'s: no fit can be asked closer than the
            // coordinates resolve.
            let largest = points.iter().fold(0.0_f64, |a, p| a.max(p.max_abs()));
            if tol < RESOLUTION_ULPS * f64::EPSILON * largest {
                bail!(
                    "{input}: --tolerance {tol:e} is below what the coordinates can resolve \
                     ({RESOLUTION_ULPS} units in the last place of the largest coordinate, {:.3e})",
                    RESOLUTION_ULPS * f64::EPSILON * largest
                );
            }
        }
        Ok(())
    }
}

//! The options of the cubic interpolating spline through ordered points (`curve spline`, and
//! any command that offers the spline as one of its methods): its end conditions, the
//! parameters of the points, and the end tangents of a clamped spline (Kuznetsov and
//! Filatov's spline, docs/methods.md §5; the library's [`CubicSpline`]).
//!
//! The group is flattened into a command's arguments (`#[command(flatten)]`);
//! [`SplineOptions::build`] makes the spline and refuses what does not fit the points: tangents
//! with a count of components other than the points' dimension, tangents without clamped
//! ends, clamped ends without both tangents.

use anyhow::{anyhow, bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use karkas::Point;
use karkas_io::input::display_name;
use std::path::Path;

/// The end conditions of `--ends`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum EndsKind {
    /// The third derivative is continuous at the second and the second-to-last points (SciPy's
    /// default; the default here unless the first and last points are one point).
    NotAKnot,
    /// Zero second derivative at both ends (the default where the first and last points are
    /// one point, a sharp trailing edge: there not-a-knot ends overshoot across the other
    /// branch where the last points are sparse).
    Natural,
    /// Given first derivatives at the ends: --start-tangent and --end-tangent.
    Clamped,
    /// A closed curve, C^2 across the seam; the first point is appended when the last does
    /// not repeat it.
    Periodic,
}

impl EndsKind {
    /// The name of the option's value (`not-a-knot`, `natural`, `clamped`, `periodic`).
    pub fn name(self) -> &'static str {
        match self {
            EndsKind::NotAKnot => "not-a-knot",
            EndsKind::Natural => "natural",
            EndsKind::Clamped => "clamped",
            EndsKind::Periodic => "periodic",
        }
    }
}

/// An end tangent as given on the command line: 2 or 3 finite components.
#[derive(Clone, Debug, PartialEq)]
pub struct Tangent(pub Vec<f64>);

/// The options of a cubic interpolating spline through ordered points.
#[derive(Clone, Debug, Args)]
pub struct SplineOptions {
    /// End conditions [default: not-a-knot, but natural when the first and last points are one
    /// point by the shared-end rule (a sharp trailing edge: the curve has a corner there)].
    /// periodic closes the curve: if the last point does not repeat the first, the first is
    /// appended (as `curve ll --closed` joins its ends).
    #[arg(long, value_enum)]
    pub ends: Option<EndsKind>,
    /// Parameters of the points: uniform (t_k = k), chord (cumulative chord length) or
    /// centripetal (cumulative square root of the chord length).
    #[arg(long, value_name = "RULE", default_value = "chord", value_parser = parse_param)]
    pub param: CurveParameterization,
    /// The first derivative dP/dt at the first point, in the chosen parameter (with --ends
    /// clamped; as many components as the points have).
    #[arg(long, value_name = "X,Y[,Z]", value_parser = parse_tangent, allow_hyphen_values = true)]
    pub start_tangent: Option<Tangent>,
    /// The first derivative dP/dt at the last point, in the chosen parameter (with --ends
    /// clamped; as many components as the points have).
    #[arg(long, value_name = "X,Y[,Z]", value_parser = parse_tangent, allow_hyphen_values = true)]
    pub end_tangent: Option<Tangent>,
}

impl SplineOptions {
    /// Refuses tangents without clamped ends and clamped ends without both tangents (the
    /// checks that need no points; [`build`](Self::build) makes them too).
    pub fn check(&self) -> Result<()> {
        let given: Vec<&str> = [
            ("--start-tangent", self.start_tangent.is_some()),
            ("--end-tangent", self.end_tangent.is_some()),
        ]
        .into_iter()
        .filter(|(_, given)| *given)
        .map(|(option, _)| option)
        .collect();
        if self.kind() != EndsKind::Clamped {
            if !given.is_empty() {
                bail!(
                    "{}: end tangents are given only with --ends clamped, not {}",
                    given.join(" and "),
                    self.kind().name()
                );
            }
        } else if self.start_tangent.is_none() {
            bail!("--ends clamped: --start-tangent X,Y[,Z] is needed too");
        } else if self.end_tangent.is_none() {
            bail!("--ends clamped: --end-tangent X,Y[,Z] is needed too");
        }
        Ok(())
    }

    /// The kind of ends asked (not-a-knot when none are: see [`resolved`](Self::resolved)).
    pub fn kind(&self) -> EndsKind {
        self.ends.unwrap_or(EndsKind::NotAKnot)
    }

    /// The kind of ends of the spline through `points`: the asked ones, else the library's
    /// default for them ([`SplineEnds::default_for`]: natural at a shared end, not-a-knot
    /// otherwise).
    pub fn resolved<const D: usize>(&self, points: &[Point<D>]) -> EndsKind {
        self.ends.unwrap_or(match SplineEnds::default_for(points) {
            SplineEnds::Natural => EndsKind::Natural,
            _ => EndsKind::NotAKnot,
        })
    }

    /// The spline's end conditions through `points` (of dimension `D`).
    pub fn ends<const D: usize>(&self, points: &[Point<D>]) -> Result<SplineEnds<D>> {
        self.check()?;
        Ok(match self.resolved(points) {
            EndsKind::NotAKnot => SplineEnds::NotAKnot,
            EndsKind::Natural => SplineEnds::Natural,
            EndsKind::Periodic => SplineEnds::Periodic,
            EndsKind::Clamped => match (&self.start_tangent, &self.end_tangent) {
                (Some(start), Some(end)) => SplineEnds::Clamped {
                    start: tangent_point::<D>("--start-tangent", start)?,
                    end: tangent_point::<D>("--end-tangent", end)?,
                },
                _ => bail!("--ends clamped: --start-tangent and --end-tangent are needed"),
            },
        })
    }

    /// The cubic spline through `points` (read from `what`, which errors name). With
    /// periodic ends the curve is closed: the first point is appended unless the last repeats
    /// it; a closed curve needs 3 distinct points.
    pub fn build<const D: usize>(
        &self,
        points: &[Point<D>],
        what: &Path,
    ) -> Result<CubicSpline<D>> {
        let ends = self.ends(points)?;
        let name = display_name(what);
        if points.len() < 2 {
            bail!(
                "{}: a cubic spline needs at least 2 points, got {}",
                name.display(),
                points.len()
            );
        }
        if ends.is_periodic() {
            let scale = points.iter().fold(0.0f64, |m, p| m.max(p.max_abs()));
            let repeats = (points[points.len() - 1] - points[0]).max_abs() <= 1e-12 * scale;
            let distinct = points.len() - usize::from(repeats);
            if distinct < 3 {
                bail!(
                    "{}: a closed (periodic) spline needs at least 3 points besides a repeated \
                     first one, got {distinct}",
                    name.display()
                );
            }
            crate::output::console::warn_near_miss("--ends periodic", points);
        }
        let spline = CubicSpline::through(points, self.param, ends).map_err(|e| match e {
            karkas::Error::CoincidentPoints { first, second } => anyhow!(
                "points {} and {} (counting from 1) coincide: {} parameters need distinct \
                 consecutive points (--param uniform does not)",
                first + 1,
                second + 1,
                self.param.name()
            ),
            e => anyhow::Error::new(e),
        });
        spline.with_context(|| {
            format!(
                "{}: cubic spline ({} ends, {} parameters)",
                name.display(),
                self.resolved(points).name(),
                self.param.name()
            )
        })
    }

    /// A short description for titles and reports of the spline through `points`, e.g.
    /// `not-a-knot ends, chord parameters`.
    pub fn describe<const D: usize>(&self, points: &[Point<D>]) -> String {
        format!(
            "{} ends, {} parameters",
            self.resolved(points).name(),
            self.param.name()
        )
    }
}

/// The tangent as a point of dimension `D`, or an error of `option` naming the counts.
fn tangent_point<const D: usize>(option: &str, tangent: &Tangent) -> Result<Point<D>> {
    let got = tangent.0.len();
    if got != D {
        bail!(
            "{option}: the tangent has {got} components but the points have {D} coordinates \
             (give {})",
            if D == 2 { "X,Y" } else { "X,Y,Z" }
        );
    }
    let mut p = Point::ZERO;
    for (c, &v) in tangent.0.iter().enumerate() {
        p[c] = v;
    }
    Ok(p)
}

/// Parses a parameterization by the library's names (the ones Python's `parameterization=`
/// accepts).
fn parse_param(text: &str) -> Result<CurveParameterization, String> {
    text.trim()
        .parse()
        .map_err(|e: karkas::Error| e.to_string())
}

/// Parses `X,Y` or `X,Y,Z`: 2 or 3 finite numbers separated by commas.
fn parse_tangent(text: &str) -> Result<Tangent, String> {
    let fields: Vec<&str> = text.split(',').collect();
    if !(2..=3).contains(&fields.len()) {
        return Err(format!(
            "expected X,Y or X,Y,Z (2 or 3 numbers separated by commas), got '{text}'"
        ));
    }
    let values = fields
        .into_iter()
        .map(crate::args::parse_finite)
        .collect::<Result<Vec<f64>, String>>()?;
    Ok(Tangent(values))
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::Parser;
    use karkas::Point2;

    #[derive(Debug, Parser)]
    struct Cli {
        #[command(flatten)]
        spline: SplineOptions,
    }

    fn parse(args: &[&str]) -> Result<SplineOptions, clap::Error> {
        let mut all = vec!["karkas"];
        all.extend_from_slice(args);
        Cli::try_parse_from(all).map(|c| c.spline)
    }

    /// Every name of `--ends` is the name the group reports, and every name the library
    /// accepts for the parameters parses to the same rule.
    #[test]
    fn names_agree() {
        for kind in EndsKind::value_variants() {
            let name = kind.to_possible_value().map(|v| v.get_name().to_owned());
            assert_eq!(name.as_deref(), Some(kind.name()));
        }
        for name in CurveParameterization::NAMES {
            let o = parse(&["--param", name]).unwrap();
            assert_eq!(Ok(o.param), name.parse::<CurveParameterization>());
        }
        assert!(parse(&["--param", "arc"]).is_err());
        let o = parse(&[]).unwrap();
        assert_eq!(o.ends, None);
        assert_eq!(o.kind(), EndsKind::NotAKnot);
        assert_eq!(o.param, CurveParameterization::ChordLength);
    }

    #[test]
    fn tangents_are_checked() {
        let pts = [
            Point2::new([0.0, 0.0]),
            Point2::new([1.0, 1.0]),
            Point2::new([2.0, 0.0]),
        ];
        let input = Path::new("in.csv");
        let o = parse(&["--ends", "clamped", "--start-tangent", "1,0"]).unwrap();
        let e = o.build(&pts, input).unwrap_err().to_string();
        assert!(e.contains("--end-tangent"), "{e}");
        let o = parse(&[
            "--ends",
            "clamped",
            "--start-tangent",
            "-1,0,0",
            "--end-tangent",
            "1,0,0",
        ])
        .unwrap();
        let e = o.build(&pts, input).unwrap_err().to_string();
        assert!(
            e.contains("--start-tangent") && e.contains("3 components"),
            "{e}"
        );
        let o = parse(&["--start-tangent", "1,0", "--end-tangent", "1,0"]).unwrap();
        assert!(o.build(&pts, input).is_err());
        assert!(parse(&["--ends", "clamped", "--start-tangent", "1,inf"]).is_err());
        assert!(parse(&["--start-tangent", "1"]).is_err());
        let o = parse(&[
            "--ends",
            "clamped",
            "--start-tangent=-1,2",
            "--end-tangent",
            "3,-4",
        ])
        .unwrap();
        let s = o.build(&pts, input).unwrap();
        assert_eq!(s.slopes()[0], Point2::new([-1.0, 2.0]));
        assert_eq!(s.slopes()[2], Point2::new([3.0, -4.0]));
    }

    #[test]
    fn periodic_closes_and_needs_three_points() {
        let pts = [
            Point2::new([1.0, 0.0]),
            Point2::new([0.0, 1.0]),
            Point2::new([-1.0, 0.0]),
        ];
        let o = parse(&["--ends", "periodic"]).unwrap();
        let s = o.build(&pts, Path::new("in.csv")).unwrap();
        assert_eq!(s.values().len(), 4);
        assert_eq!(s.values()[3], pts[0]);
        let e = o.build(&pts[..2], Path::new("in.csv")).unwrap_err();
        assert!(e.to_string().contains("at least 3 points"), "{e}");
    }
}

//! The commands of the `karkas` binary, one file each.

pub mod convert;
mod curve_analyze;
mod curve_dps;
mod curve_fair;
mod curve_fit;
mod curve_ll;
mod curve_spline;
mod fairness_report;
mod fit_options;
mod fit_summary;
pub mod hausdorff;
pub mod inspect;
pub mod loft;
pub mod section;
mod section_model;
pub mod spline_options;
mod surface_bicubic;
mod surface_coons;
mod surface_dps_tube;
mod surface_implicit;
mod surface_ll;
mod surface_relay;
pub mod vary;

use clap::Subcommand;

/// `karkas curve ...`
#[derive(Debug, Subcommand)]
pub enum CurveCommand {
    /// LL-approximation (or interpolation) of an ordered point list.
    Ll(curve_ll::CurveLlArgs),
    /// Discrete periodic spline: a closed discrete curve through (or with poles at) the points.
    Dps(curve_dps::CurveDpsArgs),
    /// Fit a C^1 cubic spline with bounded second-derivative jumps to measured points.
    Fit(curve_fit::CurveFitArgs),
    /// The fairest C^2 cubic within a tolerance of every point (least integral of
    /// (dk/ds)^2), with its fairness before and after.
    Fair(curve_fair::CurveFairArgs),
    /// Cubic interpolating spline through ordered points (not-a-knot, natural, clamped or
    /// periodic ends; uniform, chord or centripetal parameters).
    Spline(curve_spline::CurveSplineArgs),
    /// Fairness of the curves of one or more methods on the same points: length, curvature
    /// range, curvature extrema, inflections, distance from the points, energy.
    Analyze(curve_analyze::CurveAnalyzeArgs),
}

impl CurveCommand {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            CurveCommand::Ll(args) => curve_ll::run(&args),
            CurveCommand::Dps(args) => curve_dps::run(&args),
            CurveCommand::Fit(args) => curve_fit::run(&args),
            CurveCommand::Fair(args) => curve_fair::run(&args),
            CurveCommand::Analyze(args) => curve_analyze::run(&args),
            CurveCommand::Spline(args) => curve_spline::run(&args),
        }
    }
}

/// `karkas surface ...`
#[derive(Debug, Subcommand)]
pub enum SurfaceCommand {
    /// LL-approximation (or interpolation) of a grid of points.
    Ll(surface_ll::SurfaceLlArgs),
    /// Closed tube through curves along and across it (discrete periodic splines).
    DpsTube(surface_dps_tube::SurfaceDpsTubeArgs),
    /// Bicubic interpolation of a grid of points with chosen parameters.
    Bicubic(surface_bicubic::SurfaceBicubicArgs),
    /// A grid of nodes on an implicit surface along its lines of curvature.
    Implicit(surface_implicit::SurfaceImplicitArgs),
    /// Coons, Gordon or composite Coons surface through a network of curves.
    Coons(surface_coons::SurfaceCoonsArgs),
    /// A grid re-laid along the lines of curvature of its own bicubic interpolant.
    Relay(surface_relay::SurfaceRelayArgs),
}

impl SurfaceCommand {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            SurfaceCommand::Ll(args) => surface_ll::run(&args),
            SurfaceCommand::DpsTube(args) => surface_dps_tube::run(&args),
            SurfaceCommand::Bicubic(args) => surface_bicubic::run(&args),
            SurfaceCommand::Implicit(args) => surface_implicit::run(&args),
            SurfaceCommand::Coons(args) => surface_coons::run(&args),
            SurfaceCommand::Relay(args) => surface_relay::run(&args),
        }
    }
}

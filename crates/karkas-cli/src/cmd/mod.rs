//! The commands of the `karkas` binary, one file each.

mod curve_fit;
mod curve_ll;
mod output;
mod surface_ll;

use clap::Subcommand;

/// `karkas curve ...`
#[derive(Debug, Subcommand)]
pub enum CurveCommand {
    /// LL-approximation (or interpolation) of an ordered point list.
    Ll(curve_ll::CurveLlArgs),
    /// Fit a C^1 cubic spline with bounded second-derivative jumps to measured points.
    Fit(curve_fit::CurveFitArgs),
}

impl CurveCommand {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            CurveCommand::Ll(args) => curve_ll::run(&args),
            CurveCommand::Fit(args) => curve_fit::run(&args),
        }
    }
}

/// `karkas surface ...`
#[derive(Debug, Subcommand)]
pub enum SurfaceCommand {
    /// LL-approximation (or interpolation) of a grid of points.
    Ll(surface_ll::SurfaceLlArgs),
}

impl SurfaceCommand {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            SurfaceCommand::Ll(args) => surface_ll::run(&args),
        }
    }
}

//! The commands of the `karkas` binary, one file each.

mod curve_ll;
mod output;
pub mod section;
mod surface_ll;
pub mod vary;

use clap::Subcommand;

/// `karkas curve ...`
#[derive(Debug, Subcommand)]
pub enum CurveCommand {
    /// LL-approximation (or interpolation) of an ordered point list.
    Ll(curve_ll::CurveLlArgs),
}

impl CurveCommand {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            CurveCommand::Ll(args) => curve_ll::run(&args),
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

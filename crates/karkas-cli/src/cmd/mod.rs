//! The commands of the `karkas` binary, one file each.

mod curve_ll;
mod output;
mod surface_coons;
mod surface_ll;

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
    /// Coons, Gordon or composite Coons surface through a network of curves.
    Coons(surface_coons::SurfaceCoonsArgs),
}

impl SurfaceCommand {
    /// Runs the command.
    pub fn run(self) -> anyhow::Result<()> {
        match self {
            SurfaceCommand::Ll(args) => surface_ll::run(&args),
            SurfaceCommand::Coons(args) => surface_coons::run(&args),
        }
    }
}

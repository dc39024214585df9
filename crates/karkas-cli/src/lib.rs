//! `karkas`: smooth curves and surfaces from point frames, on the command line.
//!
//! A thin layer over the `karkas` and `karkas-io` crates: one file per command in `cmd/`, the
//! option groups they share in `args`, the checks of input frames in `input`, and every way a
//! result leaves the program (files, reports, the error line) in `output/`.
//! Exit codes: 0 on success (also when the reader of standard output closes it early), 2 on
//! any error (bad arguments, bad or unreadable input, an
//! output that cannot be written); the message is one line on standard error naming the file
//! and the line or grid cell at fault. No output file is created or changed on error.

mod args;
pub mod batch;
mod cmd;
mod demo;
mod input;
mod output;
mod reference;

use clap::error::ErrorKind;
use clap::{CommandFactory, Parser, Subcommand};
use std::ffi::OsString;
use std::process::ExitCode;

/// Smooth parametric curves and surfaces from point frames.
#[derive(Debug, Parser)]
#[command(name = "karkas", version, about, long_about = None)]
struct Cli {
    #[command(subcommand)]
    command: Command,
    /// The most memory one request's output may take, like 512M or 4G (default 2G, or the
    /// environment variable KARKAS_MAX_MEMORY); larger requests fail before any work.
    #[arg(long, global = true, value_name = "SIZE", value_parser = output::memory::parse_size)]
    max_memory: Option<u64>,
    /// The format of the output: csv, svg, obj, stl, png, step, iges, ply, vtk, vts, glb, html,
    /// dxf (each command writes some). Needed for another format than CSV on standard output
    /// (-o -); wins over the output file's extension.
    #[arg(long, global = true, value_name = "FORMAT", value_parser = args::parse_format)]
    format: Option<karkas_io::OutputFormat>,
}

#[derive(Debug, Subcommand)]
enum Command {
    /// Build a curve from ordered points.
    #[command(subcommand)]
    Curve(cmd::CurveCommand),
    /// Build a surface from a grid of points or a skeleton of curves.
    #[command(subcommand)]
    Surface(cmd::SurfaceCommand),
    /// Two-sided Hausdorff distance between point sets or a point set and F(x, y, z) = 0.
    Hausdorff(cmd::hausdorff::HausdorffArgs),
    /// Distances of measured points to a CAD model's faces (STEP or IGES): summary, worst
    /// points, CSV report.
    ///
    /// Each point's distance to the nearest face, signed where the face bounds a solid
    /// (positive outside). Standard output: `points N`, `max`, `rms`, `mean`, the percentiles
    /// `p50 p90 p95 p99 p99.9` of the distance (nearest rank), `signed ...` (when signed) and
    /// one `worst K point I distance D [signed S] at x,y,z face F foot x,y,z` line per
    /// farthest point. Exit 2 on a bad model or points file, naming the file and line.
    Inspect(cmd::inspect::InspectArgs),
    /// Loft a surface through sections placed along a span (a wing from its sections table).
    Loft(cmd::loft::LoftArgs),
    /// Cut a surface (of a grid or of a curve network) by planes: sections and isolines.
    Section(cmd::section::SectionArgs),
    /// Vary one coordinate of a grid through new row sums, column sums and total.
    Vary(cmd::vary::VaryArgs),
    /// Reproduce the examples of the papers on built-in data.
    Demo(demo::DemoArgs),
    /// Convert a mesh, grid or curve file into another format (by the output extension).
    ///
    /// A mesh (.obj .stl .ply) converts to .obj .stl .ply .vtk .glb .html; a grid CSV
    /// (i,j,x,y,z or u,v,x,y,z) to those and .vts .svg .png .csv (i,j,x,y,z); curve points
    /// (CSV x,y[,z], airfoil .dat) to .svg .png .html.
    Convert(cmd::convert::ConvertArgs),
    /// Run one command on many inputs in parallel: `karkas batch curve fit --inputs DIR --out
    /// DIR --tolerance 1e-4`, each output OUT/<input stem>.<format>, a record per input in
    /// OUT/results.jsonl, --resume to finish a run that stopped.
    Batch(batch::BatchArgs),
}

/// Runs the command line `args` (the program's name first, as `std::env::args_os` gives it)
/// and returns the exit status: 0 on success, 1 when a batch finished with failed inputs, 2
/// on any error.
pub fn run(args: impl IntoIterator<Item = OsString>) -> ExitCode {
    let args: Vec<OsString> = args.into_iter().collect();
    // `karkas --markdown-help`: the book's command-line reference (hidden; see `reference`).
    if args.len() == 2 && args[1] == "--markdown-help" {
        let text = reference::markdown(&Cli::command());
        return match std::io::Write::write_all(&mut std::io::stdout(), text.as_bytes()) {
            Ok(()) => ExitCode::SUCCESS,
            Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => ExitCode::SUCCESS,
            Err(e) => {
                eprintln!("karkas: error: standard output: {e}");
                ExitCode::from(2)
            }
        };
    }
    let cli = match Cli::try_parse_from(args) {
        Ok(cli) => cli,
        // --help, --version, and a command given without its subcommand: clap's own output.
        Err(e)
            if !e.use_stderr()
                || e.kind() == ErrorKind::DisplayHelpOnMissingArgumentOrSubcommand =>
        {
            e.exit()
        }
        Err(e) => {
            eprintln!(
                "karkas: error: {} (see karkas --help)",
                output::message::clap_line(&e)
            );
            return ExitCode::from(2);
        }
    };
    let max_memory = match &cli.command {
        Command::Batch(args) => args.max_memory().map(|m| m.or(cli.max_memory)),
        _ => Ok(cli.max_memory),
    };
    if let Err(e) = max_memory.and_then(output::memory::set_max_memory) {
        eprintln!("karkas: error: {}", output::message::error_line(&e));
        return ExitCode::from(2);
    }
    if cli.format.is_some() && matches!(cli.command, Command::Hausdorff(_) | Command::Demo(_)) {
        eprintln!("karkas: error: --format: this command writes no output file");
        return ExitCode::from(2);
    }
    output::target::set_requested_format(cli.format);
    let result = match cli.command {
        Command::Curve(c) => c.run(),
        Command::Surface(c) => c.run(),
        Command::Hausdorff(args) => cmd::hausdorff::run(&args),
        Command::Inspect(args) => cmd::inspect::run(&args),
        Command::Section(args) => cmd::section::run(&args),
        Command::Loft(args) => cmd::loft::run(&args),
        Command::Vary(args) => cmd::vary::run(&args),
        Command::Demo(args) => demo::run(&args),
        Command::Convert(args) => cmd::convert::run(&args),
        Command::Batch(args) => match batch::cli_run(&args, cli.format) {
            Ok(true) => Ok(()),
            Ok(false) => return ExitCode::from(1),
            Err(e) => Err(e),
        },
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        // The reader of standard output went away (`karkas ... -o - | head`): what it wanted
        // was written, like a tool killed by SIGPIPE but without a message.
        Err(e) if output::message::is_broken_pipe(&e) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("karkas: error: {}", output::message::error_line(&e));
            ExitCode::from(2)
        }
    }
}

#[cfg(test)]
mod tests {
    use clap::CommandFactory;

    /// The committed command-line reference equals what the binary generates; after changing
    /// a help text or adding an option, regenerate it with
    /// `cargo run --release -- --markdown-help > docs/reference/command-line.md`.
    #[test]
    fn committed_reference_is_current() {
        let path = concat!(
            env!("CARGO_MANIFEST_DIR"),
            "/../../docs/reference/command-line.md"
        );
        let committed = std::fs::read_to_string(path).unwrap_or_default();
        let generated = super::reference::markdown(&super::Cli::command());
        assert!(
            committed == generated,
            "docs/reference/command-line.md is stale: regenerate it with \
             `cargo run --release -- --markdown-help > docs/reference/command-line.md`"
        );
    }
}

//! `karkas demo`: the examples of the papers, reproduced on built-in data, written to a folder
//! with pictures, meshes and the data itself, and a summary table on the terminal.

mod coons;
mod coons_data;
mod data;
mod dps;
mod fit;
mod ll;
mod param;

use anyhow::{Context, Result};
use clap::Args;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `karkas demo`.
#[derive(Debug, Args)]
pub struct DemoArgs {
    /// Folder for the pictures, meshes and data (created if missing; files of the same names
    /// inside it are replaced).
    #[arg(long, default_value = "karkas-demo")]
    out: PathBuf,
}

/// One line of the summary: what was checked, the figure found and the paper's figure.
pub struct Finding {
    /// The example.
    pub example: String,
    /// What the figure measures.
    pub measure: String,
    /// The figure.
    pub value: f64,
    /// The paper's figure for the same measure, where it gives one.
    pub paper: Option<f64>,
}

/// Runs every example and prints the summary.
pub fn run(args: &DemoArgs) -> Result<()> {
    let started = Instant::now();
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("cannot create the folder {}", args.out.display()))?;
    let mut findings = ll::run(&args.out)?;
    findings.extend(dps::run(&args.out)?);
    findings.extend(param::run(&args.out)?);
    findings.extend(coons::run(&args.out)?);
    findings.extend(fit::run(&args.out)?);
    print_summary(&findings, &args.out, started.elapsed().as_secs_f64());
    Ok(())
}

fn print_summary(findings: &[Finding], out: &Path, seconds: f64) {
    println!(
        "{:<40} {:<44} {:>12} {:>8}",
        "example", "measure", "value", "paper"
    );
    for f in findings {
        let paper = f.paper.map_or_else(String::new, |p| p.to_string());
        println!(
            "{:<40} {:<44} {:>12.3e} {:>8}",
            f.example, f.measure, f.value, paper
        );
    }
    println!("wrote {} in {seconds:.2} s", out.display());
}

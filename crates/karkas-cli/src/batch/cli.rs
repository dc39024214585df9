//! The arguments of `karkas batch`, which may stand before the command or among its options
//! (`karkas batch curve fit --inputs foils --out fits --tolerance 1e-4`), and its summary.

use super::{run, Batch};
use crate::args::parse_format;
use crate::output::memory::parse_size;
use anyhow::{bail, Result};
use clap::Args;
use karkas_io::OutputFormat;
use std::path::PathBuf;

/// Arguments of `karkas batch`.
#[derive(Debug, Args)]
#[command(
    after_help = "Examples:\n  karkas batch curve fit --inputs foils/ --out fits --tolerance 1e-4\n  \
     karkas batch curve ll --inputs 'scans/*.csv' --out svg --format svg --order 3\n  \
     karkas batch convert --inputs meshes.txt --out obj --format obj --resume\n\n\
     Each input writes OUT/<input stem>.<format>, and one JSON line in OUT/results.jsonl \
     (input, outputs, status, error, summary, seconds). Exit status 0 when every input is ok, \
     1 when some failed, 2 on bad usage."
)]
pub struct BatchArgs {
    /// Inputs: a folder (its files), a glob pattern (quote it: 'scans/*.dat') or a .txt list
    /// of paths, one a line; may be repeated.
    #[arg(long, value_name = "DIR|GLOB|LIST.txt")]
    inputs: Vec<String>,
    /// The output folder (made when missing).
    #[arg(long, value_name = "DIR")]
    out: Option<PathBuf>,
    /// Name each output after the input's path below this folder (OUT/a/b/x.csv for
    /// DIR/a/b/x.dat), so that files of one name in different folders do not collide
    /// [default: after the input's stem alone, OUT/x.csv].
    #[arg(long, value_name = "DIR")]
    tree: Option<PathBuf>,
    /// Inputs processed at once [default: one per core].
    #[arg(long, value_name = "N")]
    jobs: Option<usize>,
    /// Skip the inputs recorded ok in OUT/results.jsonl whose outputs exist, and run the others
    /// (the failed ones again).
    #[arg(long)]
    resume: bool,
    /// The command (curve ll, curve fit, curve spline, curve dps, curve analyze, surface ll,
    /// surface bicubic, section, vary, convert) and its options, without input and -o
    /// (curve fit's --report takes no file: `OUT/<stem>.deviations.csv`).
    #[arg(
        trailing_var_arg = true,
        allow_hyphen_values = true,
        required = true,
        value_name = "COMMAND [OPTIONS]"
    )]
    command: Vec<String>,
}

/// The batch's own options taken out of the command's: those clap could not see after the
/// command's first word.
#[derive(Debug, Default)]
struct Split {
    job: Vec<String>,
    inputs: Vec<String>,
    out: Option<PathBuf>,
    tree: Option<PathBuf>,
    jobs: Option<usize>,
    resume: bool,
    format: Option<OutputFormat>,
    max_memory: Option<u64>,
}

impl BatchArgs {
    /// `--max-memory` when it stands among the command's options (before the command, the
    /// global option has it).
    pub fn max_memory(&self) -> Result<Option<u64>> {
        Ok(self.split()?.max_memory)
    }

    fn split(&self) -> Result<Split> {
        let mut split = Split {
            inputs: self.inputs.clone(),
            out: self.out.clone(),
            tree: self.tree.clone(),
            jobs: self.jobs,
            resume: self.resume,
            ..Split::default()
        };
        let mut words = self.command.iter();
        while let Some(word) = words.next() {
            let (name, inline) = match word.split_once('=') {
                Some((name, value)) if name.starts_with("--") => (name, Some(value.to_owned())),
                _ => (word.as_str(), None),
            };
            let known = [
                "--inputs",
                "--out",
                "--tree",
                "--jobs",
                "--format",
                "--max-memory",
            ];
            if name == "--resume" {
                split.resume = true;
                continue;
            }
            if !known.contains(&name) {
                split.job.push(word.clone());
                continue;
            }
            let Some(value) = inline.or_else(|| words.next().cloned()) else {
                bail!("{name}: a value is needed");
            };
            match name {
                "--inputs" => {
                    split.inputs.push(value);
                    // The files of a pattern the shell expanded: the command's options all
                    // start with '-', and it takes no other argument.
                    while let Some(more) = words.clone().next().filter(|w| !w.starts_with('-')) {
                        split.inputs.push(more.clone());
                        words.next();
                    }
                }
                "--out" => split.out = Some(PathBuf::from(value)),
                "--tree" => split.tree = Some(PathBuf::from(value)),
                "--jobs" => {
                    split.jobs = Some(
                        value
                            .parse()
                            .map_err(|_| anyhow::anyhow!("--jobs {value}: not a count"))?,
                    );
                }
                "--format" => {
                    split.format = Some(parse_format(&value).map_err(anyhow::Error::msg)?);
                }
                _ => split.max_memory = Some(parse_size(&value).map_err(anyhow::Error::msg)?),
            }
        }
        Ok(split)
    }
}

/// Runs `karkas batch` (`format`: the global `--format`, when given before the command):
/// true when every input ended ok.
pub fn run_cli(args: &BatchArgs, format: Option<OutputFormat>) -> Result<bool> {
    let split = args.split()?;
    let Some(out) = &split.out else {
        bail!("batch: --out DIR is needed (the outputs and results.jsonl go there)");
    };
    let format = split.format.or(format);
    let tree = split.tree.as_deref();
    let mut batch = Batch::new(&split.job, format, &split.inputs, out, tree)?;
    batch.jobs = split.jobs;
    batch.resume = split.resume;
    batch.progress = true;
    let outcome = run(&batch)?;
    let ok = outcome.records.len() - outcome.failed;
    let rate = outcome.ran as f64 / outcome.seconds.max(1e-9);
    let skipped = if outcome.skipped > 0 {
        format!(" ({} done before)", outcome.skipped)
    } else {
        String::new()
    };
    eprintln!(
        "karkas: batch {}: {} inputs, {ok} ok{skipped}, {} failed; {} run in {:.2} s ({rate:.1} \
         inputs/s); records in {}",
        batch.job.name(),
        outcome.records.len(),
        outcome.failed,
        outcome.ran,
        outcome.seconds,
        batch.results_path().display()
    );
    Ok(outcome.failed == 0)
}

//! `karkas batch`: one command run on many inputs, every core busy, bad files recorded rather
//! than fatal, and a run that resumes where a killed one stopped.
//!
//! Each input runs its command in this process on a worker of a rayon pool (`--jobs`), with
//! the command's lines and figures captured for its record (`output::console`); the
//! records go to `OUT/results.jsonl` as they finish (`results`). The Python package's
//! `karkas.batch` calls [`run`] with the same arguments.

mod cli;
mod inputs;
mod job;
mod results;

pub use crate::args::parse_format;
pub use crate::output::memory::set_output_cap;
pub use cli::{run_cli as cli_run, BatchArgs};
pub use inputs::expand as expand_inputs;
pub use job::Job;
pub use results::{Record, Status, RESULTS_FILE};

use anyhow::{Context, Result};
use indicatif::{ProgressBar, ProgressStyle};
use rayon::prelude::*;
use std::collections::HashMap;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// A batch: the job, its inputs and where the outputs go.
#[derive(Clone, Debug)]
pub struct Batch {
    /// The command run on every input.
    pub job: Job,
    /// The input files.
    inputs: Vec<PathBuf>,
    /// The name of each input's outputs, without extension (see [`Job::outputs`]).
    bases: Vec<PathBuf>,
    /// The output folder (made when missing).
    out: PathBuf,
    /// Inputs processed at once (default: one per core).
    pub jobs: Option<usize>,
    /// Skip the inputs recorded ok whose outputs (those this job writes) exist; run the
    /// others.
    pub resume: bool,
    /// Keep `OUT/results.jsonl` (false: records returned only).
    pub results_file: bool,
    /// Report on standard error: a progress bar (rate, time left) when it is a terminal, and
    /// the error line of every input that fails.
    pub progress: bool,
}

/// What a batch did.
#[derive(Debug)]
pub struct Outcome {
    /// One record per input, in the order of the inputs.
    pub records: Vec<Record>,
    /// Inputs run now.
    pub ran: usize,
    /// Inputs skipped by `--resume` (recorded ok before).
    pub skipped: usize,
    /// Inputs whose record is an error.
    pub failed: usize,
    /// The wall time of the batch, in seconds.
    pub seconds: f64,
}

impl Batch {
    /// A batch of `job` (the command's words and options, as [`Job::new`] takes them) on the
    /// files `inputs` names (see [`expand_inputs`]), writing into the folder `out` outputs
    /// named after each input's stem, or with `tree` after its path below that folder (see
    /// `inputs::output_bases`); with the defaults: as many inputs at once as cores, no
    /// resume, the results file kept, no progress bar.
    pub fn new(
        job: &[String],
        format: Option<karkas_io::OutputFormat>,
        inputs: &[String],
        out: &Path,
        tree: Option<&Path>,
    ) -> Result<Batch> {
        let job = Job::new(job, format)?;
        let inputs = expand_inputs(inputs)?;
        let bases = inputs::output_bases(&inputs, out, tree)?;
        Ok(Batch {
            job,
            inputs,
            bases,
            out: out.to_path_buf(),
            jobs: None,
            resume: false,
            results_file: true,
            progress: false,
        })
    }

    /// The path of the results file.
    pub fn results_path(&self) -> PathBuf {
        self.out.join(RESULTS_FILE)
    }
}

/// Runs `batch`. Errors are about the batch itself (the output folder cannot be made, the
/// pool cannot start); an input's failure is its record.
pub fn run(batch: &Batch) -> Result<Outcome> {
    let started = Instant::now();
    if let Some(0) = batch.jobs {
        anyhow::bail!("--jobs: at least 1");
    }
    std::fs::create_dir_all(&batch.out)
        .with_context(|| format!("--out: cannot create the folder {}", batch.out.display()))?;
    let path = batch.results_path();
    let before = if batch.resume && batch.results_file {
        results::read(&path)?
    } else {
        Vec::new()
    };
    let earlier: HashMap<&str, &Record> = before.iter().map(|r| (r.input.as_str(), r)).collect();
    let done = already_done(batch, &earlier);
    let todo: Vec<(&PathBuf, &PathBuf)> = batch
        .inputs
        .iter()
        .zip(&batch.bases)
        .zip(&done)
        .filter(|(_, earlier)| earlier.is_none())
        .map(|(pair, _)| pair)
        .collect();
    let journal = results::Journal::open(&path, batch.resume, batch.results_file)?;
    let bar = progress_bar(batch, todo.len())?;
    let fresh = run_inputs(batch, &todo, &journal, &bar)?;
    bar.finish_and_clear();
    // The fresh records come in the order of `todo`, the inputs not done.
    let mut fresh = fresh.into_iter();
    let records: Vec<Record> = done
        .iter()
        .filter_map(|earlier| earlier.cloned().or_else(|| fresh.next()))
        .collect();
    // Records of inputs not in this batch stay in the file, after this batch's.
    let mine: std::collections::HashSet<&str> = records.iter().map(|r| r.input.as_str()).collect();
    let others: Vec<Record> = before
        .iter()
        .filter(|r| !mine.contains(r.input.as_str()))
        .cloned()
        .collect();
    journal.finish(&[&records[..], &others[..]].concat())?;
    let failed = records.iter().filter(|r| r.status == Status::Error).count();
    Ok(Outcome {
        ran: todo.len(),
        skipped: batch.inputs.len() - todo.len(),
        failed,
        records,
        seconds: started.elapsed().as_secs_f64(),
    })
}

/// Each input's earlier record in `earlier` when it needs no new run: recorded ok, with the
/// very outputs this job writes (another --format or --report runs again), all present.
fn already_done<'a>(batch: &Batch, earlier: &HashMap<&str, &'a Record>) -> Vec<Option<&'a Record>> {
    batch
        .inputs
        .iter()
        .zip(&batch.bases)
        .map(|(input, base)| {
            let outputs: Vec<String> = batch
                .job
                .outputs(base)
                .iter()
                .map(|o| o.display().to_string())
                .collect();
            earlier
                .get(input.display().to_string().as_str())
                .filter(|r| r.is_done() && r.outputs == outputs)
                .copied()
        })
        .collect()
}

/// Runs the inputs `todo` on the batch's worker threads, each record appended to `journal`
/// as it comes; the records in the order of `todo`.
fn run_inputs(
    batch: &Batch,
    todo: &[(&PathBuf, &PathBuf)],
    journal: &results::Journal,
    bar: &ProgressBar,
) -> Result<Vec<Record>> {
    let mut builder = rayon::ThreadPoolBuilder::new();
    if let Some(jobs) = batch.jobs {
        builder = builder.num_threads(jobs);
    }
    let pool = builder.build().context("cannot start the worker threads")?;
    pool.install(|| {
        todo.par_iter()
            .with_max_len(1)
            .map(|(input, base)| {
                let record = batch.job.run(input, base);
                if let (Some(error), true) = (&record.error, batch.progress) {
                    bar.suspend(|| eprintln!("karkas: error: {error}"));
                }
                let appended = journal.append(&record);
                bar.inc(1);
                appended.map(|()| record)
            })
            .collect::<Result<Vec<Record>>>()
    })
}

/// The progress bar of `todo` inputs: rate and time left, on standard error when it is a
/// terminal and the batch asks for one.
fn progress_bar(batch: &Batch, todo: usize) -> Result<ProgressBar> {
    if !batch.progress {
        return Ok(ProgressBar::hidden());
    }
    let bar = ProgressBar::new(todo as u64);
    bar.set_style(
        ProgressStyle::with_template(
            "{prefix} [{bar:30}] {pos}/{len} {rate} inputs/s, ETA {eta} ({elapsed})",
        )
        .context("progress bar template")?
        .with_key(
            "rate",
            |state: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
                let _ = write!(w, "{:.1}", state.per_sec());
            },
        )
        .progress_chars("=> "),
    );
    bar.set_prefix(format!("batch {}", batch.job.name()));
    Ok(bar)
}

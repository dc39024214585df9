//! The command a batch runs on every input: which commands qualify, their options checked
//! once before the first input, the command line of one input, and its record.

use super::results::{Record, Status};
use crate::cmd::{self, CurveCommand, SurfaceCommand};
use crate::output::console;
use crate::output::message::{clap_line, error_line};
use anyhow::{bail, Result};
use clap::{Parser, Subcommand};
use karkas_io::OutputFormat;
use serde_json::Value;
use std::ffi::OsString;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// The commands a batch runs: those that read one input and write one output.
const JOBS: [&str; 10] = [
    "curve ll",
    "curve fit",
    "curve spline",
    "curve dps",
    "curve analyze",
    "surface ll",
    "surface bicubic",
    "section",
    "vary",
    "convert",
];

/// The command line of one input, parsed as the `karkas` binary parses it.
#[derive(Debug, Parser)]
#[command(name = "karkas")]
struct JobLine {
    #[command(subcommand)]
    command: JobCommand,
}

/// The commands of [`JOBS`].
#[derive(Debug, Subcommand)]
enum JobCommand {
    #[command(subcommand)]
    Curve(CurveCommand),
    #[command(subcommand)]
    Surface(SurfaceCommand),
    Section(cmd::section::SectionArgs),
    Vary(cmd::vary::VaryArgs),
    Convert(cmd::convert::ConvertArgs),
}

impl JobCommand {
    fn run(self) -> Result<()> {
        match self {
            JobCommand::Curve(c) => c.run(),
            JobCommand::Surface(c) => c.run(),
            JobCommand::Section(args) => cmd::section::run(&args),
            JobCommand::Vary(args) => cmd::vary::run(&args),
            JobCommand::Convert(args) => cmd::convert::run(&args),
        }
    }
}

/// A command of `JOBS` with its options, run on every input of a batch.
#[derive(Clone, Debug)]
pub struct Job {
    /// The command's words: `curve fit`.
    words: Vec<String>,
    /// Its options, as on the command line.
    options: Vec<String>,
    /// `curve fit --report`: the deviations go to `OUT/<stem>.deviations.csv`.
    report: bool,
    /// The extension of the outputs.
    extension: &'static str,
}

impl Job {
    /// The job of `line` (the command's words, then its options; no input, no `-o`), writing
    /// `format` (default CSV). Refuses a command that is not one of `JOBS` and options the
    /// command would refuse, before any input is read.
    pub fn new(line: &[String], format: Option<OutputFormat>) -> Result<Job> {
        let words = command_words(line)?;
        let mut options = Vec::new();
        let mut report = false;
        let mut rest = line[words.len()..].iter().peekable();
        while let Some(option) = rest.next() {
            let name = option.split('=').next().unwrap_or(option);
            if matches!(name, "-o" | "--output") || (option.starts_with("-o") && option.len() > 2) {
                bail!(
                    "batch: each output is named OUT/<input stem>.<format> (choose the format \
                     with --format); leave out {name}"
                );
            }
            if option == "--report" && words[..] == ["curve", "fit"] {
                if rest.peek().is_some_and(|next| !next.starts_with('-')) {
                    bail!(
                        "batch: --report takes no file name in a batch (each input's deviations \
                         go to OUT/<input stem>.deviations.csv)"
                    );
                }
                report = true;
                continue;
            }
            options.push(option.clone());
        }
        let extension = match format {
            Some(format) => format.extension(),
            None if words[0] == "convert" => {
                bail!("batch convert: give the output format with --format (obj, stl, ply, ...)")
            }
            None => OutputFormat::Csv.extension(),
        };
        let job = Job {
            words,
            options,
            report,
            extension,
        };
        let example = Path::new("input.csv");
        job.parse(example, &job.outputs(Path::new("out/input")))?;
        let given = |name: &str| {
            job.options
                .iter()
                .any(|o| o == name || o.starts_with(&format!("{name}=")))
        };
        if job.words[..] == ["curve", "fit"] && !given("--knots") && !given("--tolerance") {
            bail!(
                "batch curve fit: give the knots (--knots T1,...,TN or N) or a tolerance \
                 (--tolerance TOL)"
            );
        }
        Ok(job)
    }

    /// The command's name: `curve fit`.
    pub fn name(&self) -> String {
        self.words.join(" ")
    }

    /// The files the job writes for an input whose outputs are named `base` (their folder and
    /// name without extension, `OUT/naca`): `OUT/naca.<ext>`, and `OUT/naca.deviations.csv`
    /// with `--report`.
    pub fn outputs(&self, base: &Path) -> Vec<PathBuf> {
        let named = |suffix: &str| {
            let mut name = base.as_os_str().to_os_string();
            name.push(suffix);
            PathBuf::from(name)
        };
        let mut outputs = vec![named(&format!(".{}", self.extension))];
        if self.report {
            outputs.push(named(".deviations.csv"));
        }
        outputs
    }

    /// The command line of `input` writing `outputs`, parsed.
    fn parse(&self, input: &Path, outputs: &[PathBuf]) -> Result<JobCommand> {
        // A relative name starting with '-' would read as an option.
        let input = if input.to_string_lossy().starts_with('-') {
            Path::new(".").join(input)
        } else {
            input.to_path_buf()
        };
        let mut line: Vec<OsString> = vec!["karkas".into()];
        line.extend(self.words.iter().map(OsString::from));
        line.push(input.into_os_string());
        if self.words[0] == "convert" {
            line.push(outputs[0].clone().into_os_string());
        } else {
            line.push("-o".into());
            line.push(outputs[0].clone().into_os_string());
        }
        if let Some(report) = outputs.get(1) {
            line.push("--report".into());
            line.push(report.clone().into_os_string());
        }
        line.extend(self.options.iter().map(OsString::from));
        match JobLine::try_parse_from(line) {
            Ok(parsed) => Ok(parsed.command),
            Err(e) => bail!("batch {}: {}", self.name(), clap_line(&e)),
        }
    }

    /// Runs the job on `input`, its outputs named `base` (see [`Job::outputs`]; the folder is
    /// made when missing), and returns its record; a failure (a panic too) is the record's
    /// error.
    pub fn run(&self, input: &Path, base: &Path) -> Record {
        let started = Instant::now();
        let outputs = self.outputs(base);
        let (result, captured) = console::capture(|| {
            std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| {
                if let Some(folder) = base.parent().filter(|f| !f.as_os_str().is_empty()) {
                    std::fs::create_dir_all(folder).map_err(|e| {
                        anyhow::anyhow!("{}: cannot create the folder: {e}", folder.display())
                    })?;
                }
                self.parse(input, &outputs)?.run()
            }))
        });
        let error = match result {
            Ok(Ok(())) => None,
            Ok(Err(e)) => Some(error_line(&e)),
            Err(panic) => Some(format!(
                "{}: internal error: {}",
                input.display(),
                panic
                    .downcast_ref::<&str>()
                    .map(|s| s.to_string())
                    .or_else(|| panic.downcast_ref::<String>().cloned())
                    .unwrap_or_default()
            )),
        };
        let mut summary = captured.figures;
        summary.insert("messages".to_owned(), Value::from(captured.messages));
        Record {
            input: input.display().to_string(),
            outputs: match error {
                None => outputs.iter().map(|o| o.display().to_string()).collect(),
                Some(_) => Vec::new(),
            },
            status: if error.is_none() {
                Status::Ok
            } else {
                Status::Error
            },
            error,
            summary: Value::Object(summary),
            seconds: started.elapsed().as_secs_f64(),
        }
    }
}

/// The leading words of `line` that name the command (`curve fit`, `convert`), checked.
fn command_words(line: &[String]) -> Result<Vec<String>> {
    let known = JOBS.join(", ");
    let Some(first) = line.first().filter(|w| !w.starts_with('-')) else {
        bail!("batch: name the command to run first ({known})");
    };
    let words: Vec<String> = match first.as_str() {
        "curve" | "surface" => match line.get(1).filter(|w| !w.starts_with('-')) {
            Some(second) => vec![first.clone(), second.clone()],
            None => bail!("batch: {first} what? ({known})"),
        },
        _ => vec![first.clone()],
    };
    let name = words.join(" ");
    if Path::new(first).exists() && !JOBS.contains(&name.as_str()) {
        bail!(
            "batch: {first} is a file, not a command (quote a pattern given to --inputs, \
             'foils/*.dat', so that the shell does not expand it)"
        );
    }
    if !JOBS.contains(&name.as_str()) {
        let why = if matches!(
            name.as_str(),
            "surface coons" | "surface dps-tube" | "surface implicit" | "hausdorff"
        ) {
            "it reads several inputs or none"
        } else {
            "no such command"
        };
        bail!("batch: cannot run {name} on each input ({why}); the commands are {known}");
    }
    Ok(words)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn line(text: &str) -> Vec<String> {
        text.split_whitespace().map(str::to_owned).collect()
    }

    #[test]
    fn jobs_are_checked_before_any_input() {
        let fit = Job::new(&line("curve fit --tolerance 1e-4 --report"), None).unwrap();
        assert_eq!(fit.name(), "curve fit");
        let outputs = fit.outputs(Path::new("out/naca"));
        assert_eq!(
            outputs,
            [
                PathBuf::from("out/naca.csv"),
                PathBuf::from("out/naca.deviations.csv")
            ]
        );
        let svg = Job::new(&line("curve ll --order 3"), Some(OutputFormat::Svg)).unwrap();
        assert_eq!(svg.outputs(Path::new("o/a")), [PathBuf::from("o/a.svg")]);
        for (bad, says) in [
            ("curve fit --tolerance 1e-4 -o x.csv", "leave out -o"),
            ("curve fit --report dev.csv --knots 5", "takes no file name"),
            (
                "curve fit --no-such-option",
                "batch curve fit: unexpected argument",
            ),
            ("surface coons --kind bilinear", "reads several inputs"),
            ("curve", "curve what?"),
            ("--tolerance 1e-4", "name the command"),
            ("convert", "--format"),
            ("curve fit --pin-ends", "give the knots"),
            ("Cargo.toml curve fit", "not a command (quote a pattern"),
        ] {
            let error = Job::new(&line(bad), None).unwrap_err().to_string();
            assert!(error.contains(says), "{bad}: {error}");
        }
    }
}

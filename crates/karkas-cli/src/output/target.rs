//! Where a result goes and in which format: the output path's extension, or `--format`, and
//! `-` for standard output.
//!
//! `-o -` writes to standard output, CSV unless `--format` names another format. `--format`
//! also wins over the extension of a file output (`-o result.txt --format csv`). Every format
//! a command writes may go to standard output, binary ones too (a pipe carries bytes), except
//! to a terminal, where a binary format is refused.

use anyhow::{bail, Result};
use karkas_io::write::{is_stdout, output_name};
use karkas_io::OutputFormat;
use std::io::IsTerminal;
use std::path::{Path, PathBuf};
use std::sync::OnceLock;

/// The format of `--format`, set once from the command line.
static REQUESTED: OnceLock<Option<OutputFormat>> = OnceLock::new();

/// Sets the format asked for with `--format` (none: by the output's extension).
pub fn set_requested_format(format: Option<OutputFormat>) {
    let _ = REQUESTED.set(format);
}

/// The format asked for with `--format`, if any.
pub fn requested_format() -> Option<OutputFormat> {
    REQUESTED.get().copied().flatten()
}

/// The format `output` is written in, one of `allowed`: `--format` if given, else CSV for
/// standard output (`-`), else by the extension. Refuses a format the command cannot write,
/// and a binary format to a terminal.
pub fn output_format(output: &Path, allowed: &[OutputFormat]) -> Result<OutputFormat> {
    let format = match requested_format() {
        Some(format) if allowed.contains(&format) => format,
        Some(format) => bail!(
            "--format {}: this command writes {}",
            format.extension(),
            names(allowed)
        ),
        None if is_stdout(output) => {
            if !allowed.contains(&OutputFormat::Csv) {
                bail!(
                    "-o -: standard output needs --format (one of {})",
                    names(allowed)
                );
            }
            OutputFormat::Csv
        }
        None => OutputFormat::from_path(output, allowed)?,
    };
    if !is_stdout(output) {
        ensure_place(output)?;
    }
    if is_stdout(output) && is_binary(format) && std::io::stdout().is_terminal() {
        bail!(
            "{}: {} is binary and standard output is a terminal (redirect it to a file or a pipe)",
            output_name(output).display(),
            format.extension()
        );
    }
    Ok(format)
}

/// Refuses, before any work, an output that cannot be written where it is: a folder, or a
/// file in a folder that does not exist (the write would fail only after the computation).
fn ensure_place(output: &Path) -> Result<()> {
    if output.is_dir() {
        bail!(
            "cannot write {}: it is a folder",
            output_name(output).display()
        );
    }
    match output.parent().map(std::fs::metadata) {
        // The message the write would give.
        Some(Err(e)) if output.parent().is_some_and(|f| !f.as_os_str().is_empty()) => {
            bail!("cannot write {}: {e}", output_name(output).display())
        }
        _ => Ok(()),
    }
}

/// The formats of a command's outputs (`-o`, repeatable: one computation, every output),
/// each one of `allowed`, as [`output_format`] gives them, with two rules for several
/// outputs: `--format` names the format of standard output (`-o -`) only, each file taking
/// its extension's; and no output may be given twice, standard output included.
pub fn output_formats(outputs: &[PathBuf], allowed: &[OutputFormat]) -> Result<Vec<OutputFormat>> {
    if outputs.len() < 2 {
        return outputs.iter().map(|o| output_format(o, allowed)).collect();
    }
    for (k, a) in outputs.iter().enumerate() {
        if outputs[..k].iter().any(|b| same_output(a, b)) {
            bail!(
                "-o {}: given twice (each output is written once)",
                output_name(a).display()
            );
        }
    }
    outputs
        .iter()
        .map(|o| {
            if is_stdout(o) {
                output_format(o, allowed)
            } else {
                Ok(OutputFormat::from_path(o, allowed)?)
            }
        })
        .collect()
}

/// True when the outputs `a` and `b` are one: both standard output, or one path.
fn same_output(a: &Path, b: &Path) -> bool {
    match (is_stdout(a), is_stdout(b)) {
        (true, true) => true,
        (false, false) => {
            a == b
                || std::path::absolute(a)
                    .ok()
                    .zip(std::path::absolute(b).ok())
                    .is_some_and(|(x, y)| x == y)
        }
        _ => false,
    }
}

/// True for the formats written as bytes rather than text (STL and PLY by default).
fn is_binary(format: OutputFormat) -> bool {
    matches!(
        format,
        OutputFormat::Png
            | OutputFormat::Stl
            | OutputFormat::Ply
            | OutputFormat::Glb
            | OutputFormat::Npy
    )
}

/// The names of `formats` for messages: `csv, svg, png`.
fn names(formats: &[OutputFormat]) -> String {
    let names: Vec<&str> = formats.iter().map(|f| f.extension()).collect();
    names.join(", ")
}

/// The name of `output` in the lines that report what was written: the path, or `<stdout>`.
pub fn shown(output: &Path) -> std::path::PathBuf {
    output_name(output)
}

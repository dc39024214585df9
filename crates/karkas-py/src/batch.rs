//! `karkas.batch`: the command line's `karkas batch` (the same jobs, options, outputs, records
//! and resume) from Python, with the GIL released while the inputs run.

use crate::errors::OptionError;
use pyo3::exceptions::PyOSError;
use pyo3::prelude::*;
use pyo3::types::{PyDict, PyList, PyString, PyTuple};
use std::path::PathBuf;

/// Runs one command of the command line on many input files in parallel.
///
/// The Python form of ``karkas batch``: every input runs the command with the same options,
/// writes ``out/<input stem>.<format>``, and gets a record; a bad file is a record with status
/// ``"error"``, never an exception. The records also go to ``out/results.jsonl``, one JSON
/// line per input, as the command line writes them. Each input's output is capped by
/// ``karkas.max_memory`` and what its reader keeps by ``set_max_input_bytes``; ``jobs``
/// inputs run at once.
///
/// Parameters
/// ----------
/// job : str, or list or tuple of str
///     The command and, optionally, its options as on the command line:
///     ``"curve fit"``, ``"curve ll --order 3"``, ``["curve", "fit", "--knots", "8"]``. One of
///     curve ll, curve fit, curve spline, curve dps, curve analyze, surface ll, surface
///     bicubic, section, vary, convert.
/// inputs : str, os.PathLike or a list or tuple of them
///     A folder (its files), a glob pattern, a ``.txt`` list of paths, or files.
/// out : str or os.PathLike
///     The output folder (made when missing).
/// options : list or tuple of str, optional
///     More options of the command, as on the command line (``["--tolerance", "1e-4"]``).
/// format : str, optional
///     The output format (``"csv"``, the default; ``"svg"``, ``"step"``, ...).
/// tree : str or os.PathLike, optional
///     Name each output after the input's path below this folder (``out/a/b/x.csv`` for
///     ``tree/a/b/x.dat``) rather than after its stem alone (``out/x.csv``), so that files of
///     one name in different folders do not collide.
/// jobs : int, optional
///     Inputs processed at once (default: one per core).
/// resume : bool
///     Skip the inputs recorded ok in ``out/results.jsonl`` whose outputs exist; run the rest.
/// results_file : bool
///     Write ``out/results.jsonl`` (False: only return the records).
/// as_frame : bool, optional
///     Return a pandas DataFrame (default: when pandas is installed) instead of a list.
/// progress : bool
///     Show a progress bar on a terminal and print the error line of every failed input.
/// job_options : keyword arguments
///     The command's options by name: ``tolerance=1e-4`` is ``--tolerance 1e-4``,
///     ``pin_ends=True`` is ``--pin-ends``, ``knots=[0, 0.5, 1]`` (a list or tuple) is
///     ``--knots 0,0.5,1``;
///     False and None leave the option out.
///
/// Returns
/// -------
/// list of dict or pandas.DataFrame
///     One record per input, in the order of the inputs: ``input``, ``outputs`` (list),
///     ``status`` (``"ok"`` or ``"error"``), ``error`` (str or None), ``summary`` (the
///     command's figures, e.g. ``knots`` and ``max_deviation`` of a fit, and ``messages``)
///     and ``seconds``.
///
/// Raises
/// ------
/// OptionError
///     The command is not one a batch runs, its options are not the command's, the inputs
///     name nothing, an input is outside ``tree``, or two inputs would write outputs of the
///     same name.
/// OSError
///     The output folder or the results file cannot be written.
///
/// Examples
/// --------
/// >>> import os
/// >>> os.makedirs("foils", exist_ok=True)
/// >>> t = np.linspace(0, 2 * np.pi, 60)
/// >>> np.savetxt("foils/a.csv", np.c_[np.cos(t), 0.1 * np.sin(t)], delimiter=",")
/// >>> _ = open("foils/b.csv", "w").write("1,2\n")
/// >>> records = karkas.batch("curve fit", "foils", "fits", knots=6, as_frame=False)
/// >>> [(r["input"][-5:], r["status"], r["summary"].get("knots")) for r in records]
/// [('a.csv', 'ok', 6), ('b.csv', 'error', None)]
/// >>> records[0]["outputs"]
/// ['fits/a.csv']
#[pyfunction]
#[pyo3(
    signature = (job, inputs, out, options=None, format=None, tree=None, jobs=None, resume=false, results_file=true, as_frame=None, progress=false, **job_options),
    text_signature = "(job, inputs, out, options=None, format=None, tree=None, jobs=None, resume=False, results_file=True, as_frame=None, progress=False, **job_options)"
)]
#[allow(clippy::too_many_arguments)]
pub fn batch<'py>(
    py: Python<'py>,
    job: &Bound<'py, PyAny>,
    inputs: &Bound<'py, PyAny>,
    out: PathBuf,
    options: Option<&Bound<'py, PyAny>>,
    format: Option<String>,
    tree: Option<PathBuf>,
    jobs: Option<usize>,
    resume: bool,
    results_file: bool,
    as_frame: Option<bool>,
    progress: bool,
    job_options: Option<&Bound<'py, PyDict>>,
) -> PyResult<Bound<'py, PyAny>> {
    let mut line = words(job)?;
    if let Some(options) = options {
        line.extend(items(options, "options: a list of strings")?);
    }
    if let Some(named) = job_options {
        line.extend(named_options(named)?);
    }
    let format = format
        .map(|f| karkas_cli::batch::parse_format(&f).map_err(OptionError::new_err))
        .transpose()?;
    if jobs == Some(0) {
        return Err(OptionError::new_err("jobs: at least 1"));
    }
    let specs = paths(inputs)?;
    let mut batch = karkas_cli::batch::Batch::new(&line, format, &specs, &out, tree.as_deref())
        .map_err(|e| OptionError::new_err(error_text(&e)))?;
    batch.jobs = jobs;
    batch.resume = resume;
    batch.results_file = results_file;
    batch.progress = progress;
    // Each input's request is capped by karkas.max_memory, as every call of the package is.
    let cap =
        crate::limits::current_cap(py)?.map_or(u64::MAX, |c| c.min(u128::from(u64::MAX)) as u64);
    karkas_cli::batch::set_output_cap(cap);
    let outcome = py
        .detach(|| karkas_cli::batch::run(&batch))
        .map_err(|e| PyOSError::new_err(error_text(&e)))?;
    let text =
        serde_json::to_string(&outcome.records).map_err(|e| PyOSError::new_err(e.to_string()))?;
    let records = py.import("json")?.call_method1("loads", (text,))?;
    let frame = match as_frame {
        Some(false) => None,
        Some(true) => Some(py.import("pandas")?),
        None => py.import("pandas").ok(),
    };
    match frame {
        Some(pandas) => pandas.call_method1("DataFrame", (records,)),
        None => Ok(records),
    }
}

/// The input files a batch of ``inputs`` would run, in order.
///
/// As ``batch`` and the command line's ``--inputs`` expand them: a folder gives its files
/// (not sub-folders, nor names starting with a dot) sorted by name, a glob pattern its
/// matching files, a ``.txt`` file the paths on its lines, another file itself.
///
/// Parameters
/// ----------
/// inputs : str, os.PathLike or a list or tuple of them
///     Folders, patterns, lists or files.
///
/// Returns
/// -------
/// list of str
///     The files, each once.
///
/// Raises
/// ------
/// OptionError
///     A name that is no file, folder or matching pattern, or no files at all.
///
/// Examples
/// --------
/// >>> import os
/// >>> os.makedirs("some", exist_ok=True)
/// >>> for name in ["b.dat", "a.dat"]:
/// ...     _ = open(os.path.join("some", name), "w").write("0 0\n1 1\n")
/// >>> karkas.batch_inputs("some/*.dat")
/// ['some/a.dat', 'some/b.dat']
#[pyfunction]
#[pyo3(text_signature = "(inputs)")]
pub fn batch_inputs(inputs: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    let specs = paths(inputs)?;
    let files = karkas_cli::batch::expand_inputs(&specs)
        .map_err(|e| OptionError::new_err(error_text(&e)))?;
    Ok(files.iter().map(|f| f.display().to_string()).collect())
}

/// The error line of `e`, its causes joined as the command line joins them.
fn error_text(e: &anyhow::Error) -> String {
    format!("{e:#}")
}

/// The words of `job`: a string split at white space, or a list or tuple of strings.
fn words(job: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    if let Ok(text) = job.cast::<PyString>() {
        return Ok(text
            .to_cow()?
            .split_whitespace()
            .map(str::to_owned)
            .collect());
    }
    items(job, "job: a string like 'curve fit' or a list of words")
}

/// One path or several (a list or tuple), as strings.
fn paths(value: &Bound<'_, PyAny>) -> PyResult<Vec<String>> {
    let what = "inputs: a path, a pattern, or a list of them";
    if value.cast::<PyList>().is_err() && value.cast::<PyTuple>().is_err() {
        let one: PathBuf = value.extract().map_err(|_| OptionError::new_err(what))?;
        return Ok(vec![one.to_string_lossy().into_owned()]);
    }
    items(value, what)
}

/// The items of a list or tuple of strings or paths (nothing else, so that a huge array is
/// refused before it is walked).
fn items(value: &Bound<'_, PyAny>, what: &str) -> PyResult<Vec<String>> {
    let list: Vec<Bound<'_, PyAny>> = if let Ok(list) = value.cast::<PyList>() {
        list.iter().collect()
    } else if let Ok(tuple) = value.cast::<PyTuple>() {
        tuple.iter().collect()
    } else {
        return Err(OptionError::new_err(what.to_owned()));
    };
    list.iter()
        .map(|item| {
            let path: PathBuf = item
                .extract()
                .map_err(|_| OptionError::new_err(what.to_owned()))?;
            Ok(path.to_string_lossy().into_owned())
        })
        .collect()
}

/// `name=value` keywords as command-line options.
fn named_options(named: &Bound<'_, PyDict>) -> PyResult<Vec<String>> {
    let mut line = Vec::new();
    for (name, value) in named.iter() {
        let flag = format!("--{}", name.extract::<String>()?.replace('_', "-"));
        if value.is_none() || value.extract::<bool>().is_ok_and(|b| !b) {
            continue;
        }
        if value.extract::<bool>().is_ok_and(|b| b) {
            line.push(flag);
            continue;
        }
        let listed: Option<Vec<Bound<'_, PyAny>>> = if let Ok(list) = value.cast::<PyList>() {
            Some(list.iter().collect())
        } else if let Ok(tuple) = value.cast::<PyTuple>() {
            Some(tuple.iter().collect())
        } else {
            None
        };
        let text = match listed {
            Some(items) => {
                let parts: PyResult<Vec<String>> =
                    items.iter().map(|v| v.str()?.extract::<String>()).collect();
                parts?.join(",")
            }
            None => value.str()?.extract::<String>()?,
        };
        line.push(flag);
        line.push(text);
    }
    Ok(line)
}

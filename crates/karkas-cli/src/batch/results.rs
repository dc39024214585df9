//! `OUT/results.jsonl`: one JSON object per input (`input`, `outputs`, `status`, `error`,
//! `summary`, `seconds`), appended as each input finishes (so that a batch killed half-way
//! keeps what it did) and rewritten at the end with one line per input.

use anyhow::{Context, Result};
use serde::{Deserialize, Serialize};
use serde_json::Value;
use std::collections::HashMap;
use std::fs::{File, OpenOptions};
use std::io::{BufRead, BufReader, Read, Write};
use std::path::{Path, PathBuf};
use std::sync::Mutex;

/// The name of the results file in the output folder.
pub const RESULTS_FILE: &str = "results.jsonl";

/// The longest results file read back by `--resume`: 1 GiB.
const MAX_RESULTS_BYTES: u64 = 1 << 30;

/// How an input ended.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum Status {
    /// The command succeeded and wrote its outputs.
    Ok,
    /// The command failed; `error` says why.
    Error,
}

/// The record of one input.
#[derive(Clone, Debug, PartialEq, Serialize, Deserialize)]
pub struct Record {
    /// The input file, as the batch named it.
    pub input: String,
    /// The files written (none on error).
    pub outputs: Vec<String>,
    /// `ok` or `error`.
    pub status: Status,
    /// The error line, or null.
    pub error: Option<String>,
    /// The command's figures (e.g. `knots`, `max_deviation` of a fit) and `messages`, the
    /// lines it printed.
    pub summary: Value,
    /// The wall time of the input, in seconds.
    pub seconds: f64,
}

impl Record {
    /// True when the input needs no new run: it ended ok and its outputs are all there.
    pub fn is_done(&self) -> bool {
        self.status == Status::Ok && self.outputs.iter().all(|o| Path::new(o).is_file())
    }
}

/// The records of `path` by input, the last one of each input winning, in the order of
/// their first appearance; none when the file does not exist. Lines that are not records
/// (the last line of a batch killed while writing it) are skipped.
pub fn read(path: &Path) -> Result<Vec<Record>> {
    let file = match File::open(path) {
        Ok(file) => file,
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => return Ok(Vec::new()),
        Err(e) => return Err(e).with_context(|| format!("cannot read {}", path.display())),
    };
    let mut order: Vec<String> = Vec::new();
    let mut last: HashMap<String, Record> = HashMap::new();
    let reader = BufReader::new(file.take(MAX_RESULTS_BYTES));
    for line in reader.split(b'\n') {
        let line = line.with_context(|| format!("cannot read {}", path.display()))?;
        let Ok(record) = serde_json::from_slice::<Record>(&line) else {
            continue;
        };
        if !last.contains_key(&record.input) {
            order.push(record.input.clone());
        }
        last.insert(record.input.clone(), record);
    }
    Ok(order
        .into_iter()
        .filter_map(|input| last.remove(&input))
        .collect())
}

/// The results file while a batch runs: records appended one whole line at a time.
#[derive(Debug)]
pub struct Journal {
    file: Option<Mutex<File>>,
    path: PathBuf,
}

impl Journal {
    /// Opens `path` to append to (`resume`) or anew; `keep == false` keeps no file at all.
    pub fn open(path: &Path, resume: bool, keep: bool) -> Result<Self> {
        let file = if keep {
            let file = OpenOptions::new()
                .create(true)
                .append(resume)
                .write(true)
                .truncate(!resume)
                .open(path)
                .with_context(|| format!("cannot write {}", path.display()))?;
            Some(Mutex::new(file))
        } else {
            None
        };
        Ok(Journal {
            file,
            path: path.to_path_buf(),
        })
    }

    /// Appends `record` as one line.
    pub fn append(&self, record: &Record) -> Result<()> {
        let Some(file) = &self.file else {
            return Ok(());
        };
        let mut line = serde_json::to_vec(record)?;
        line.push(b'\n');
        let mut file = file.lock().unwrap_or_else(|e| e.into_inner());
        file.write_all(&line)
            .with_context(|| format!("cannot write {}", self.path.display()))
    }

    /// Replaces the file by `records`, one line each (atomically).
    pub fn finish(self, records: &[Record]) -> Result<()> {
        if self.file.is_none() {
            return Ok(());
        }
        drop(self.file);
        karkas_io::write::write_atomic(&self.path, |w| {
            for record in records {
                serde_json::to_writer(&mut *w, record)?;
                w.write_all(b"\n")?;
            }
            Ok(())
        })?;
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn record(input: &str, status: Status) -> Record {
        Record {
            input: input.to_owned(),
            outputs: Vec::new(),
            status,
            error: (status == Status::Error).then(|| "bad".to_owned()),
            summary: serde_json::json!({"knots": 5}),
            seconds: 0.5,
        }
    }

    #[test]
    fn the_last_record_of_an_input_wins_and_torn_lines_are_skipped() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join(RESULTS_FILE);
        let journal = Journal::open(&path, false, true).unwrap();
        journal.append(&record("a", Status::Error)).unwrap();
        journal.append(&record("b", Status::Ok)).unwrap();
        journal.append(&record("a", Status::Ok)).unwrap();
        drop(journal);
        let mut text = std::fs::read_to_string(&path).unwrap();
        text.push_str("{\"input\":\"c\",\"outp");
        std::fs::write(&path, text).unwrap();
        let records = read(&path).unwrap();
        assert_eq!(records, [record("a", Status::Ok), record("b", Status::Ok)]);
        let line = serde_json::to_string(&record("b", Status::Error)).unwrap();
        assert!(line.contains("\"status\":\"error\""), "{line}");
        assert!(read(&dir.path().join("none.jsonl")).unwrap().is_empty());
    }
}

//! Line handling shared by the readers: comments, rows of fields with their line numbers,
//! number fields.
//!
//! All text formats of this crate share one convention: `#` starts a comment that runs to the
//! end of the line, blank lines are skipped, and errors name the 1-based physical line.

use std::path::Path;

use crate::error::{IoError, Location};
use crate::input::{not_utf8_message, read_line_bytes};

/// One non-blank line of a file, split into fields.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Row {
    /// 1-based physical line number in the file.
    pub line: usize,
    /// The fields, trimmed.
    pub fields: Vec<String>,
}

/// Reads a whole text file (`-`: standard input) with the bounds of [`crate::input`]: lines
/// at most 1 MiB, no NUL bytes, UTF-8, the size within the memory cap.
pub(crate) fn read_text(path: &Path) -> Result<String, IoError> {
    crate::input::read_text(path)
}

/// `text` without a leading byte-order mark (spreadsheets like to write one).
pub(crate) fn strip_bom(text: &str) -> &str {
    text.strip_prefix('\u{feff}').unwrap_or(text)
}

/// `line` without its `#` comment.
pub(crate) fn strip_comment(line: &str) -> &str {
    match line.find('#') {
        Some(k) => &line[..k],
        None => line,
    }
}

/// True when `field` reads as a floating-point number (NaN and infinities included: those are
/// numbers, rejected later with a better message than "not a number").
pub(crate) fn is_number(field: &str) -> bool {
    field.trim().parse::<f64>().is_ok()
}

/// The first line that is neither blank nor only a comment, with its 1-based number and the
/// comment stripped.
pub(crate) fn first_content_line(text: &str) -> Option<(usize, &str)> {
    text.lines()
        .enumerate()
        .map(|(k, l)| (k + 1, strip_comment(l).trim()))
        .find(|(_, l)| !l.is_empty())
}

/// Non-blank lines split at whitespace, comments stripped.
pub(crate) fn whitespace_rows(text: &str) -> Vec<Row> {
    text.lines()
        .enumerate()
        .filter_map(|(k, l)| {
            let fields: Vec<String> = strip_comment(l)
                .split_whitespace()
                .map(str::to_owned)
                .collect();
            (!fields.is_empty()).then_some(Row {
                line: k + 1,
                fields,
            })
        })
        .collect()
}

/// Non-blank lines read as comma-separated records with the `csv` crate, comments stripped,
/// fields trimmed, rows allowed to differ in length (the callers report ragged rows themselves,
/// with a clearer message).
pub(crate) fn csv_rows(text: &str, path: &Path) -> Result<Vec<Row>, IoError> {
    // `csv` only knows comments that fill a whole line; cut trailing comments here, keeping
    // every line break so that record positions are still physical line numbers.
    let mut cleaned = String::with_capacity(text.len());
    for line in text.lines() {
        cleaned.push_str(strip_comment(line));
        cleaned.push('\n');
    }
    // Where each line starts, to turn record offsets into line numbers: `csv` skips blank lines
    // without counting them in its line positions, so the record's byte offset is used instead.
    let line_starts: Vec<usize> = std::iter::once(0)
        .chain(cleaned.match_indices('\n').map(|(k, _)| k + 1))
        .collect();
    let line_at = |offset: usize| {
        let bytes = cleaned.as_bytes();
        let start = (offset.min(bytes.len())..bytes.len())
            .find(|&k| !bytes[k].is_ascii_whitespace())
            .unwrap_or(bytes.len());
        line_starts.partition_point(|&s| s <= start)
    };
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .trim(csv::Trim::All)
        .comment(Some(b'#'))
        .from_reader(cleaned.as_bytes());
    let mut rows = Vec::new();
    for record in reader.records() {
        let record = record.map_err(|e| {
            let line = e.position().map_or(1, |p| line_at(p.byte() as usize));
            Location::new(path, line).error(format!("malformed CSV: {e}"))
        })?;
        if record.iter().all(str::is_empty) {
            continue;
        }
        let line = record.position().map_or(0, |p| line_at(p.byte() as usize));
        rows.push(Row {
            line,
            fields: record.iter().map(str::to_owned).collect(),
        });
    }
    Ok(rows)
}

/// A streaming reader of rows: one line at a time into a reused buffer, so a file of any
/// length is read in memory proportional to its longest line (plus what the caller keeps).
///
/// Lines follow the shared conventions: `#` comments stripped, blank lines skipped, a
/// byte-order mark at the start ignored, 1-based physical line numbers. Fields are split at
/// whitespace, or at commas (trimmed; a line with a double quote is read with the `csv`
/// crate, so quoted fields work as in [`csv_rows`]).
pub(crate) struct RowReader<'p, R> {
    reader: R,
    path: &'p Path,
    bytes: Vec<u8>,
    buf: String,
    line: usize,
    fields: Vec<String>,
}

impl<'p, R: std::io::BufRead> RowReader<'p, R> {
    /// Rows of `reader`; `path` names the file in errors.
    pub fn new(reader: R, path: &'p Path) -> Self {
        RowReader {
            reader,
            path,
            bytes: Vec::new(),
            buf: String::new(),
            line: 0,
            fields: Vec::new(),
        }
    }

    /// The next line that is neither blank nor only a comment: its 1-based number and its
    /// content, comment stripped and trimmed; `None` at the end of the input.
    pub fn next_content_line(&mut self) -> Result<Option<(usize, &str)>, IoError> {
        Ok(self
            .advance()?
            .map(|(line, range)| (line, &self.buf[range])))
    }

    /// Reads up to the next content line; its number and where its content is in `buf`.
    fn advance(&mut self) -> Result<Option<(usize, std::ops::Range<usize>)>, IoError> {
        loop {
            self.buf.clear();
            if !read_line_bytes(&mut self.reader, self.path, &mut self.bytes, self.line + 1)? {
                return Ok(None);
            }
            self.line += 1;
            match std::str::from_utf8(&self.bytes) {
                Ok(text) => self.buf.push_str(text),
                Err(_) => return Err(Location::new(self.path, self.line).error(not_utf8_message())),
            }
            let skip = if self.line == 1 {
                self.buf.len() - strip_bom(&self.buf).len()
            } else {
                0
            };
            let content = strip_comment(&self.buf[skip..]).trim();
            if !content.is_empty() {
                let start = content.as_ptr() as usize - self.buf.as_ptr() as usize;
                return Ok(Some((self.line, start..start + content.len())));
            }
        }
    }

    /// The next non-empty row of fields, split at commas (`csv`) or whitespace.
    pub fn next_row(&mut self, csv: bool) -> Result<Option<(usize, &[String])>, IoError> {
        loop {
            let path = self.path;
            let Some((line, range)) = self.advance()? else {
                return Ok(None);
            };
            let content = &self.buf[range];
            let fields = &mut self.fields;
            fields.clear();
            if !csv {
                fields.extend(content.split_whitespace().map(str::to_owned));
            } else if content.contains('"') {
                let mut reader = csv::ReaderBuilder::new()
                    .has_headers(false)
                    .flexible(true)
                    .trim(csv::Trim::All)
                    .from_reader(content.as_bytes());
                let mut record = csv::StringRecord::new();
                reader
                    .read_record(&mut record)
                    .map_err(|e| Location::new(path, line).error(format!("malformed CSV: {e}")))?;
                fields.extend(record.iter().map(str::to_owned));
            } else {
                fields.extend(content.split(',').map(|f| f.trim().to_owned()));
            }
            if self.fields.iter().any(|f| !f.is_empty()) {
                return Ok(Some((line, &self.fields)));
            }
        }
    }
}

/// Opens `path` (`-`: standard input) for one buffered pass, as [`IoError::Open`] on failure.
pub(crate) fn open_buffered(path: &Path) -> Result<crate::input::Input, IoError> {
    crate::input::Input::open(path)
}

/// The 0-based positions of the columns `names` in the header row `header` of `path` (names
/// matched case-insensitively, other columns ignored); `expected` lists the columns for the
/// messages. Errors: a header of numbers only (no header), a column missing, a column named
/// twice.
pub(crate) fn header_columns<const N: usize>(
    header: &Row,
    path: &Path,
    names: [&str; N],
    expected: &str,
) -> Result<[usize; N], IoError> {
    let at = Location::new(path, header.line);
    if header.fields.iter().all(|f| is_number(f)) {
        return Err(at.error(format!("missing header: expected the columns {expected}")));
    }
    let mut index = [0; N];
    for (slot, name) in index.iter_mut().zip(names) {
        let mut found = header
            .fields
            .iter()
            .enumerate()
            .filter(|(_, f)| f.eq_ignore_ascii_case(name))
            .map(|(k, _)| k);
        *slot = found.next().ok_or_else(|| {
            at.error(format!(
                "the header has no column '{name}' (expected {expected})"
            ))
        })?;
        if found.next().is_some() {
            return Err(at.error(format!("the header names column '{name}' twice")));
        }
    }
    Ok(index)
}

/// The location of `row` in `path`, or a parse error there when the row has not `width`
/// fields (as many as the header).
pub(crate) fn row_location<'a>(
    row: &Row,
    path: &'a Path,
    width: usize,
) -> Result<Location<'a>, IoError> {
    let at = Location::new(path, row.line);
    if row.fields.len() != width {
        return Err(at.error(format!(
            "expected {width} fields, found {}",
            row.fields.len()
        )));
    }
    Ok(at)
}

/// A finite coordinate from `field` of column `column` (1-based), or a parse error at `at`.
pub(crate) fn parse_coordinate(
    field: &str,
    column: usize,
    at: Location<'_>,
) -> Result<f64, IoError> {
    match field.trim().parse::<f64>() {
        Ok(v) if v.is_finite() => Ok(v),
        Ok(_) => Err(at.error(format!("non-finite value '{field}' in column {column}"))),
        Err(_) => Err(at.error(format!("'{field}' is not a number (column {column})"))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_keep_physical_line_numbers() {
        let text = "# c\n\n1 2 # x\n  \n3\t4\n";
        let rows = whitespace_rows(text);
        assert_eq!(rows.len(), 2);
        assert_eq!((rows[0].line, rows[1].line), (3, 5));
        assert_eq!(rows[1].fields, ["3", "4"]);
        let rows = csv_rows("# c\n\nx, y # names\n , \n1,2\n", Path::new("a")).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!((rows[0].line, rows[1].line), (3, 5));
        assert_eq!(rows[0].fields, ["x", "y"]);
        assert_eq!(first_content_line(text), Some((3, "1 2")));
    }

    #[test]
    fn coordinates_must_be_finite_numbers() {
        let at = Location::new(Path::new("f"), 2);
        assert_eq!(parse_coordinate(" 1.5", 1, at).unwrap(), 1.5);
        let e = parse_coordinate("nan", 2, at).unwrap_err().to_string();
        assert_eq!(e, "f:2: non-finite value 'nan' in column 2");
        let e = parse_coordinate("abc", 1, at).unwrap_err().to_string();
        assert_eq!(e, "f:2: 'abc' is not a number (column 1)");
    }
}

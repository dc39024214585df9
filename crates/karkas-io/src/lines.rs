//! Line handling shared by the readers: comments, rows of fields with their line numbers,
//! number fields.
//!
//! All text formats of this crate share one convention: `#` starts a comment that runs to the
//! end of the line, blank lines are skipped, and errors name the 1-based physical line.

use std::path::Path;

pub(crate) use crate::dialect::split_fields;
use crate::dialect::{column_name, parse_number};
use crate::error::{IoError, Location};
use crate::input::{excerpt, not_utf8_message, read_line_bytes, MAX_LINE_BYTES};

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
            Location::new(path, line).error(format!("malformed CSV: {}", excerpt(&e.to_string())))
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

/// A reader of the lines of one input in one pass, with the bounds of [`crate::input`] (at
/// most 1 MiB, no NUL byte, UTF-8): memory is one line, whatever the length of the input.
///
/// Lines are returned without their end of line (`\n` or `\r\n`), a byte-order mark at the
/// start of the first line removed, with their 1-based physical number.
///
/// Speed: a line that lies whole in the reader's buffer is handed out in place
/// ([`LineReader::next_raw`]), found with `memchr`, not copied; a reader that can check its
/// bytes itself (a number parser accepts only ASCII) skips the NUL and UTF-8 checks for the
/// lines it accepts and calls [`check_line`] on the others. Other lines (across the
/// buffer's end) are read with [`read_line_bytes`].
pub(crate) struct LineReader<'p, R> {
    reader: R,
    name: &'p Path,
    bytes: Vec<u8>,
    line: usize,
    consumed: u64,
    /// Bytes of the current line still to be consumed from `reader` (a line handed out in
    /// place).
    pending: usize,
    /// The start of a line after the last block ([`LineReader::read_block`]).
    carry: Vec<u8>,
}

impl<'p, R: std::io::BufRead> LineReader<'p, R> {
    /// The lines of `reader`; `name` names the input in errors.
    pub(crate) fn new(reader: R, name: &'p Path) -> Self {
        LineReader {
            reader,
            name,
            bytes: Vec::new(),
            line: 0,
            consumed: 0,
            pending: 0,
            carry: Vec::new(),
        }
    }

    /// The name of the input in errors.
    pub fn name(&self) -> &'p Path {
        self.name
    }

    /// The number of the last line read (0 before the first).
    pub fn line(&self) -> usize {
        self.line
    }

    /// Reads whole lines into `block[..len]`: at least `target` bytes of lines when the
    /// input has that many; [`Block::Lines`]`(0)` at the end of the input, [`Block::TooLong`]
    /// when `target` bytes hold no line break. The bytes after the last line break wait for
    /// the next call, except at the end of the input. `block` is kept `target` bytes long
    /// between calls, so it is zeroed once, not per block. The reader counts no lines from
    /// here on: the caller does (and checks what [`LineReader::next_raw`] checks).
    pub fn read_block(&mut self, block: &mut Vec<u8>, target: usize) -> Result<Block, IoError> {
        if self.pending > 0 {
            self.reader.consume(self.pending);
            self.pending = 0;
        }
        if block.len() < target {
            block.resize(target, 0);
        }
        let mut len = self.carry.len();
        block[..len].copy_from_slice(&self.carry);
        self.carry.clear();
        let mut end = false;
        while len < target {
            let read = loop {
                match self.reader.read(&mut block[len..target]) {
                    Ok(n) => break n,
                    Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                    Err(e) => return Err(IoError::open(self.name)(e)),
                }
            };
            if read == 0 {
                end = true;
                break;
            }
            len += read;
            self.consumed += read as u64;
        }
        if !end {
            let Some(k) = memchr::memrchr(b'\n', &block[..len]) else {
                return Ok(Block::TooLong);
            };
            self.carry.extend_from_slice(&block[k + 1..len]);
            len = k + 1;
        }
        Ok(Block::Lines(len))
    }

    /// How many bytes have been read so far.
    pub fn consumed(&self) -> u64 {
        self.consumed
    }

    /// The next line as bytes, end of line included, NUL bytes and UTF-8 not yet checked
    /// (see [`check_line`]), and its 1-based number; `None` at the end of the input.
    pub fn next_raw(&mut self) -> Result<Option<(usize, &[u8])>, IoError> {
        if self.pending > 0 {
            self.reader.consume(self.pending);
            self.pending = 0;
        }
        let line = self.line + 1;
        let in_place = loop {
            match self.reader.fill_buf() {
                Ok(buf) => break memchr::memchr(b'\n', buf).map(|k| k + 1),
                Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
                Err(e) => return Err(IoError::open(self.name)(e)),
            }
        };
        if let Some(len) = in_place {
            self.line = line;
            self.consumed += len as u64;
            self.pending = len;
            let buf = self.reader.fill_buf().map_err(IoError::open(self.name))?;
            return Ok(Some((line, &buf[..len])));
        }
        if !read_line_bytes(&mut self.reader, self.name, &mut self.bytes, line)? {
            return Ok(None);
        }
        self.line = line;
        self.consumed += self.bytes.len() as u64;
        Ok(Some((line, &self.bytes)))
    }

    /// The next line and its 1-based number; `None` at the end of the input.
    pub fn next_line(&mut self) -> Result<Option<(usize, &str)>, IoError> {
        let name = self.name;
        let Some((line, bytes)) = self.next_raw()? else {
            return Ok(None);
        };
        Ok(Some((line, check_line(name, line, bytes)?)))
    }
}

/// Line `line`'s `bytes` (from [`LineReader::next_raw`]) of the input `name` as text without
/// its end of line, or the error of a line holding a NUL byte or not UTF-8. The byte-order
/// mark of line 1 is removed.
pub(crate) fn check_line<'b>(
    name: &Path,
    line: usize,
    bytes: &'b [u8],
) -> Result<&'b str, IoError> {
    let at = Location::new(name, line);
    if memchr::memchr(0, bytes).is_some() {
        return Err(at.error("binary data (a NUL byte): expected a text file, one line per record"));
    }
    let Ok(text) = std::str::from_utf8(bytes) else {
        return Err(at.error(not_utf8_message()));
    };
    let text = text.strip_suffix('\n').unwrap_or(text);
    let text = text.strip_suffix('\r').unwrap_or(text);
    Ok(if line == 1 { strip_bom(text) } else { text })
}

/// [`crate::input::check_held`] for a reader at line `line` of `name`: the cap's error names
/// the line where the input outgrew it.
pub(crate) fn check_held_at(name: &Path, line: usize, bytes: u128) -> Result<(), IoError> {
    crate::input::check_held(name, bytes).map_err(|e| match e {
        IoError::Data { message, .. } => Location::new(name, line).error(message),
        other => other,
    })
}

/// What [`LineReader::read_block`] read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Block {
    /// Whole lines, this many bytes of them (0: the end of the input).
    Lines(usize),
    /// A line longer than a block.
    TooLong,
}

/// The error of line `line` of `name` when it is longer than [`MAX_LINE_BYTES`].
pub(crate) fn too_long(name: &Path, line: usize) -> IoError {
    Location::new(name, line).error(format!(
        "line longer than {} MiB: not a text file of records, or a file without line breaks",
        MAX_LINE_BYTES >> 20
    ))
}

/// The first field of `content` split at whitespace, commas or semicolons, without a quote
/// before it: what tells a row (damaged or not) from text.
pub(crate) fn first_token(content: &str) -> Option<&str> {
    content
        .split(|c: char| c == ',' || c == ';' || c.is_whitespace())
        .map(|f| f.trim_start_matches('"'))
        .find(|f| !f.is_empty())
}

/// True when `field` is a number or looks like one meant to be: only digits, signs, points,
/// exponent letters and parentheses, with a digit or a point (`0.5`, `......`, `(0.0022)`).
/// A line starting with such a field is a data row, damaged or not, never a note.
pub(crate) fn looks_numeric(field: &str) -> bool {
    is_number(field)
        || (field.bytes().any(|b| b.is_ascii_digit() || b == b'.')
            && field
                .bytes()
                .all(|b| b.is_ascii_digit() || b"+-.eE()".contains(&b)))
}

/// The 0-based positions of the columns `names` in the header row `header` of `path` (names
/// matched as [`column_name`] compares them: case, quotes and units aside; other columns
/// ignored); `expected` lists the columns for the
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
            .filter(|(_, f)| column_name(f) == name)
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
    parse_coordinate_with(field, column, at, false)
}

/// [`parse_coordinate`], a decimal comma read too when `decimal_comma` ([`parse_number`]).
pub(crate) fn parse_coordinate_with(
    field: &str,
    column: usize,
    at: Location<'_>,
    decimal_comma: bool,
) -> Result<f64, IoError> {
    match parse_number(field, decimal_comma) {
        Some(v) if v.is_finite() => Ok(v),
        Some(_) => Err(at.error(format!(
            "non-finite value '{}' in column {column}",
            excerpt(field)
        ))),
        None => Err(at.error(format!(
            "'{}' is not a number (column {column})",
            excerpt(field)
        ))),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn rows_keep_physical_line_numbers() {
        let rows = csv_rows("# c\n\nx, y # names\n , \n1,2\n", Path::new("a")).unwrap();
        assert_eq!(rows.len(), 2);
        assert_eq!((rows[0].line, rows[1].line), (3, 5));
        assert_eq!(rows[0].fields, ["x", "y"]);
    }

    #[test]
    fn lines_come_without_their_ends_and_the_mark() {
        let mut lines = LineReader::new(&b"\xef\xbb\xbfa b\r\n\n3 4"[..], Path::new("f"));
        assert_eq!(lines.next_line().unwrap(), Some((1, "a b")));
        assert_eq!(lines.next_line().unwrap(), Some((2, "")));
        assert_eq!(lines.next_line().unwrap(), Some((3, "3 4")));
        assert_eq!(lines.next_line().unwrap(), None);
        assert_eq!(lines.consumed(), 12);
    }

    #[test]
    fn numbers_and_placeholders_look_numeric() {
        for f in ["0.5", "-1e-3", "......", "(0.0022)", "nan", "1.2.3"] {
            assert!(looks_numeric(f), "{f}");
        }
        for f in ["ZZ", "Thickness:", "7.99%", "http://x", "e", "-"] {
            assert!(!looks_numeric(f), "{f}");
        }
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

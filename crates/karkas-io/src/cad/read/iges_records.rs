//! The records of an IGES 5.3 file: fixed 80-column lines in the Start (`S`), Global (`G`),
//! Directory Entry (`D`, two lines per entity) and Parameter Data (`P`) sections and the
//! Terminate line (`T`), read in one pass.
//!
//! The global section gives the delimiters and the unit; each directory entry its type,
//! parameter pointer and line count, transformation matrix, status and form; the parameter
//! lines (columns 1–64, with the entry's pointer in 66–72) are joined per entity and split
//! into free-format fields (numbers with `E` or `D` exponents, Hollerith strings `nH...`,
//! empty fields). Only the parameters of the entity types the caller wants are kept, charged
//! to the memory cap. Errors name the line, and the directory entry when inside one.
//!
//! Hand-written: no maintained Rust crate reads IGES.

use std::collections::BTreeMap;
use std::io::BufRead;
use std::path::Path;

use crate::error::{IoError, Location};
use crate::input::{read_line_bytes, MAX_LINE_BYTES};
use crate::lines::check_held_at;

/// One field of an entity's parameters.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Field {
    /// A number (integers too).
    Number(f64),
    /// A Hollerith string.
    Text(String),
    /// An empty field (the default value).
    Empty,
}

/// A directory entry, with its parameters when its type is wanted.
#[derive(Clone, Debug)]
pub(crate) struct Entry {
    /// The entity type number.
    pub kind: i64,
    /// The form number.
    pub form: i64,
    /// The directory pointer of its transformation matrix (0: none).
    pub transform: i64,
    /// The subordinate entity switch (status digits 3-4): 0 when independent.
    pub subordinate: i64,
    /// The line of its first directory record.
    pub line: usize,
    /// Its parameters (type number first), when kept.
    pub params: Option<Vec<Field>>,
    /// The line of its first parameter record.
    pub param_line: usize,
}

/// The parts of an IGES file the geometry needs.
#[derive(Debug, Default)]
pub(crate) struct IgesFile {
    /// The unit flag (global parameter 14) and name (15).
    pub unit_flag: i64,
    pub unit_name: String,
    /// The model space scale (global parameter 13).
    pub scale: f64,
    /// The directory entries by their pointer (the sequence number of their first line:
    /// 1, 3, 5, ...).
    pub entries: BTreeMap<i64, Entry>,
    /// The count of entities of each type whose parameters were not kept.
    pub others: BTreeMap<i64, usize>,
}

/// Reads the records of an IGES file, keeping the parameters of entity types `wanted`
/// accepts.
pub(crate) fn read_records(
    path: &Path,
    reader: &mut dyn BufRead,
    wanted: &dyn Fn(i64) -> bool,
) -> Result<IgesFile, IoError> {
    let mut records = Records {
        path,
        wanted,
        file: IgesFile {
            scale: 1.0,
            unit_flag: 2,
            ..Default::default()
        },
        global: String::new(),
        global_line: 0,
        pending_d: None,
        current: None,
        held: 0,
    };
    let mut line_no = 0usize;
    let mut buf = Vec::new();
    let mut terminated = false;
    loop {
        if !read_line_bytes(reader, path, &mut buf, line_no + 1)? {
            break;
        }
        line_no += 1;
        let Some(text) = record_text(path, &mut buf, line_no)? else {
            continue;
        };
        if records.record(&text, line_no)? {
            terminated = true;
            break;
        }
    }
    records.finish(terminated, line_no)
}

/// The text of the 80-column record just read into `buf` (its line end dropped), `None`
/// when blank; refused when not ASCII or shorter than the section letter's column.
fn record_text(path: &Path, buf: &mut Vec<u8>, line_no: usize) -> Result<Option<String>, IoError> {
    while buf.last().is_some_and(|b| *b == b'\n' || *b == b'\r') {
        buf.pop();
    }
    if buf.is_empty() {
        return Ok(None);
    }
    if buf.iter().any(|&b| b == 0 || b >= 0x80) {
        return Err(Location::new(path, line_no)
            .error("a byte that is not ASCII text: not an IGES file (binary IGES is not read)"));
    }
    if buf.len() < 73 {
        return Err(Location::new(path, line_no).error(format!(
            "a record of {} columns: IGES records have 80 (the section letter in column 73)",
            buf.len()
        )));
    }
    Ok(Some(String::from_utf8_lossy(buf).into_owned()))
}

/// The sections read so far, and the records not yet complete.
struct Records<'a> {
    path: &'a Path,
    wanted: &'a dyn Fn(i64) -> bool,
    file: IgesFile,
    global: String,
    global_line: usize,
    /// The first record of a directory entry, waiting for its second.
    pending_d: Option<(String, usize)>,
    /// The entity whose parameter lines are being joined: (pointer, text, first line).
    current: Option<(i64, String, usize)>,
    /// Bytes kept, charged to the memory cap.
    held: u128,
}

impl Records<'_> {
    /// Takes one record by its section letter (column 73); `true` at the Terminate record.
    fn record(&mut self, text: &str, line_no: usize) -> Result<bool, IoError> {
        let path = self.path;
        match text.as_bytes()[72] as char {
            'S' => {}
            'G' => {
                if self.global.is_empty() {
                    self.global_line = line_no;
                }
                self.global.push_str(&text[..72]);
                if self.global.len() > MAX_LINE_BYTES {
                    return Err(Location::new(path, line_no).error("a global section longer than 1 MiB"));
                }
            }
            'D' => self.directory(text, line_no)?,
            'P' => self.parameters(text, line_no)?,
            'T' => return Ok(true),
            other => {
                return Err(Location::new(path, line_no).error(format!(
                    "column 73 holds '{other}', not a section letter (S, G, D, P, T): not an IGES file?"
                )))
            }
        }
        Ok(false)
    }

    /// A directory record: the first of an entry waits for the second.
    fn directory(&mut self, text: &str, line_no: usize) -> Result<(), IoError> {
        match self.pending_d.take() {
            None => self.pending_d = Some((text.to_owned(), line_no)),
            Some((first, first_line)) => {
                let entry = directory_entry(self.path, &first, text, first_line)?;
                let pointer = (self.file.entries.len() * 2 + 1) as i64;
                self.held += 160;
                check_held_at(self.path, line_no, self.held)?;
                self.file.entries.insert(pointer, entry);
            }
        }
        Ok(())
    }

    /// A parameter record: joined to its entity's, or the start of the next entity's.
    fn parameters(&mut self, text: &str, line_no: usize) -> Result<(), IoError> {
        let path = self.path;
        if self.pending_d.is_some() {
            return Err(Location::new(path, line_no)
                .error("the directory section ends in the middle of an entry"));
        }
        let data = &text[..64.min(text.len())];
        let pointer: i64 = text
            .get(64..72)
            .map(str::trim)
            .and_then(|s| s.parse().ok())
            .ok_or_else(|| {
                Location::new(path, line_no).error(
                    "columns 65-72 of a parameter record must hold its directory entry's number",
                )
            })?;
        match &mut self.current {
            Some((p, joined, _)) if *p == pointer => {
                joined.push_str(data);
                if joined.len() > MAX_LINE_BYTES * 64 {
                    return Err(Location::new(path, line_no)
                        .error("an entity's parameters longer than 64 MiB"));
                }
            }
            _ => {
                self.store_current()?;
                self.current = Some((pointer, data.to_owned(), line_no));
            }
        }
        Ok(())
    }

    /// Keeps the parameters of the entity whose lines were being joined.
    fn store_current(&mut self) -> Result<(), IoError> {
        if let Some((p, joined, first)) = self.current.take() {
            self.held += store_params(self.path, &mut self.file, p, &joined, first, self.wanted)?;
            check_held_at(self.path, first, self.held)?;
        }
        Ok(())
    }

    /// The file, once the last entity's parameters are kept, the Terminate record and the
    /// global section met, and every wanted entity has its parameters.
    fn finish(mut self, terminated: bool, line_no: usize) -> Result<IgesFile, IoError> {
        let path = self.path;
        self.store_current()?;
        if !terminated {
            return Err(Location::new(path, line_no.max(1))
                .error("the file ends before its Terminate record (truncated?)"));
        }
        if self.global.is_empty() {
            return Err(Location::new(path, 1).error("no global section: not an IGES file"));
        }
        let mut file = self.file;
        read_global(path, &self.global, self.global_line, &mut file)?;
        for (pointer, e) in &file.entries {
            if (self.wanted)(e.kind) && e.params.is_none() {
                return Err(Location::new(path, e.line).error(format!(
                    "directory entry {pointer} (type {}): its parameter lines are missing (truncated?)",
                    e.kind
                )));
            }
        }
        Ok(file)
    }
}

/// The directory entry of the two records `a` (at line `line`) and `b`.
fn directory_entry(path: &Path, a: &str, b: &str, line: usize) -> Result<Entry, IoError> {
    let field = |s: &str, k: usize, at: usize| -> Result<i64, IoError> {
        let f = s.get(8 * k..8 * k + 8).unwrap_or("").trim();
        if f.is_empty() {
            return Ok(0);
        }
        f.parse::<i64>().map_err(|_| {
            let number = k + 1 + if at == line { 0 } else { 9 };
            Location::new(path, at)
                .error(format!("directory field {number} is '{f}', not an integer"))
        })
    };
    let kind = field(a, 0, line)?;
    let transform = field(a, 6, line)?;
    let status = a.get(64..72).unwrap_or("").trim();
    let subordinate = status
        .get(2..4)
        .and_then(|s| s.trim().parse().ok())
        .unwrap_or(0);
    let kind2 = field(b, 0, line + 1)?;
    if kind2 != kind {
        return Err(Location::new(path, line + 1).error(format!(
            "the directory entry's second record has type {kind2}, the first {kind}"
        )));
    }
    let form = field(b, 4, line + 1)?;
    Ok(Entry {
        kind,
        form,
        transform,
        subordinate,
        line,
        params: None,
        param_line: 0,
    })
}

/// Splits and keeps the joined parameter text of entity `pointer`; the bytes kept.
fn store_params(
    path: &Path,
    file: &mut IgesFile,
    pointer: i64,
    text: &str,
    line: usize,
    wanted: &dyn Fn(i64) -> bool,
) -> Result<u128, IoError> {
    let Some(entry) = file.entries.get_mut(&pointer) else {
        return Err(Location::new(path, line).error(format!(
            "parameter records point to directory entry {pointer}, which the file does not have"
        )));
    };
    if !wanted(entry.kind) {
        *file.others.entry(entry.kind).or_insert(0) += 1;
        return Ok(0);
    }
    let fields = split_fields(text, ',', ';').map_err(|m| {
        Location::new(path, line).error(format!(
            "directory entry {pointer} (type {}): {m}",
            entry.kind
        ))
    })?;
    let bytes = (fields.len() * std::mem::size_of::<Field>()) as u128 + 64;
    entry.params = Some(fields);
    entry.param_line = line;
    Ok(bytes)
}

/// Splits free-format parameter text into fields up to the record delimiter.
pub(crate) fn split_fields(
    text: &str,
    delimiter: char,
    record: char,
) -> Result<Vec<Field>, String> {
    let mut out = Vec::new();
    let bytes = text.as_bytes();
    let mut i = 0;
    let mut token = String::new();
    let mut ended = false;
    while i < bytes.len() {
        let c = bytes[i] as char;
        if c == delimiter || c == record {
            out.push(field_of(&token)?);
            token.clear();
            i += 1;
            if c == record {
                ended = true;
                break;
            }
            continue;
        }
        if (c == 'H' || c == 'h')
            && !token.trim().is_empty()
            && token.trim().bytes().all(|b| b.is_ascii_digit())
        {
            let n: usize = token
                .trim()
                .parse()
                .map_err(|_| "a bad Hollerith count".to_string())?;
            let start = i + 1;
            let end = start + n;
            if end > bytes.len() {
                return Err(format!(
                    "a Hollerith string of {n} characters runs past the end of the parameters"
                ));
            }
            out.push(Field::Text(text[start..end].to_owned()));
            token.clear();
            i = end;
            // Skip to the next delimiter.
            while i < bytes.len() && bytes[i] == b' ' {
                i += 1;
            }
            if i < bytes.len() {
                let d = bytes[i] as char;
                if d == record {
                    ended = true;
                    break;
                }
                if d != delimiter {
                    return Err(format!(
                        "'{d}' after a Hollerith string where a delimiter was expected"
                    ));
                }
                i += 1;
            }
            continue;
        }
        token.push(c);
        i += 1;
    }
    if !ended {
        return Err("the parameters do not end with the record delimiter (truncated?)".into());
    }
    Ok(out)
}

/// A field's value.
fn field_of(token: &str) -> Result<Field, String> {
    let t = token.trim();
    if t.is_empty() {
        return Ok(Field::Empty);
    }
    let normalized: String = t
        .chars()
        .map(|c| if c == 'D' || c == 'd' { 'E' } else { c })
        .collect();
    normalized
        .parse::<f64>()
        .ok()
        .filter(|x| {
            x.is_finite()
                && !normalized.contains(|c: char| c.is_ascii_alphabetic() && c != 'E' && c != 'e')
        })
        .map(Field::Number)
        .ok_or_else(|| format!("'{}' is not a number", crate::input::excerpt(t)))
}

/// Reads the delimiters, the unit and the scale from the global section.
fn read_global(path: &Path, text: &str, line: usize, file: &mut IgesFile) -> Result<(), IoError> {
    // The delimiters come first, each as `1Hx` or an empty field (',' and ';').
    let take = |rest: &str, default: char| -> (char, usize) {
        let b = rest.as_bytes();
        if b.len() >= 3 && b[0] == b'1' && (b[1] == b'H' || b[1] == b'h') {
            (b[2] as char, 3)
        } else {
            (default, 0)
        }
    };
    let (delimiter, used) = take(text, ',');
    let rest = &text[used..];
    let rest = rest.strip_prefix(delimiter).unwrap_or(rest);
    let (record, used) = take(rest, ';');
    let rest = &rest[used..];
    let rest = rest.strip_prefix(delimiter).unwrap_or(rest);
    let fields = split_fields(rest, delimiter, record)
        .map_err(|m| Location::new(path, line).error(format!("the global section: {m}")))?;
    // Field k of the standard (1-based) is at index k - 3 here.
    let number = |k: usize| match fields.get(k - 3) {
        Some(Field::Number(x)) => Some(*x),
        _ => None,
    };
    file.scale = number(13).filter(|x| *x > 0.0).unwrap_or(1.0);
    file.unit_flag = number(14).map_or(2, |x| x as i64);
    file.unit_name = match fields.get(15 - 3) {
        Some(Field::Text(t)) => t.trim().to_owned(),
        _ => String::new(),
    };
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fields_numbers_strings_and_defaults() {
        let f = split_fields("126,1,2.5D-1,,3HA,B, -4.E2;", ',', ';').unwrap();
        assert_eq!(
            f,
            vec![
                Field::Number(126.0),
                Field::Number(1.0),
                Field::Number(0.25),
                Field::Empty,
                Field::Text("A,B".into()),
                Field::Number(-400.0)
            ]
        );
        assert!(split_fields("126,1,2", ',', ';')
            .unwrap_err()
            .contains("truncated"));
        assert!(split_fields("126,x1;", ',', ';')
            .unwrap_err()
            .contains("not a number"));
        assert!(split_fields("1,9Habc;", ',', ';')
            .unwrap_err()
            .contains("Hollerith"));
    }
}

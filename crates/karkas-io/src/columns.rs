//! Column files of curve points (CSV or whitespace-separated), read in one streaming pass.
//!
//! The first content line decides the layout: its separator and decimal mark
//! ([`crate::dialect`]: commas, semicolons, tabs or spaces; decimal commas where the comma
//! does not separate), and whether it is a header (any field not a number) or the first data
//! row. A header gives the columns by name (`x`, `y` and, for points in space, `z`; units in
//! brackets and quotes aside), by `--columns` ([`ReadOptions::columns`]), or, when it names
//! none of `x`, `y`, `z` and has two or three columns (names in another language), in order,
//! with a warning. Without a header two columns are planar points and three spatial ones,
//! unless `--columns` chooses. Then every line is one of:
//!
//! - blank or a `#` comment: skipped;
//! - a data row: as many fields as the first row, the coordinate columns numbers;
//! - a damaged row, refused naming its line: its first field is or looks like a number
//!   ([`looks_numeric`]: `0.5`, `......`, `(0.0022)`), or it has the data's number of fields
//!   with a number among them;
//! - otherwise a note: the data end there, and the rest of the file is notes (a source URL,
//!   a table of properties), ignored, except that a data row after the notes is refused.
//!
//! Speed: the input is read in blocks of whole lines (1 MiB per thread), the next block read
//! on a thread of its own while the current one is parsed; a block of plain rows (no comment,
//! nothing but the data's fields, numbers maybe in double quotes) is split in pieces parsed in parallel,
//! each walked once, row after row, and each coordinate parsed where it starts: a plain
//! decimal by [`crate::plain_decimal`] (with the file's decimal mark), any other number by
//! `fast-float2` (both correctly
//! rounded, as `str::parse`; tests compare the fast and careful paths on random rows), with no
//! allocation per row or field. Any other block is read line by line, each line tried the same way and
//! otherwise split into owned fields to be classified or reported, so line numbers and
//! messages are those of a line-by-line read. Memory: the points themselves
//! ([`crate::store`]), two blocks and one block's points, and nothing per skipped line except
//! its bytes counted against the memory cap (so an endless stream of comments or notes ends
//! too).

use std::io::BufRead;
use std::path::Path;

use crate::dialect::{column_name, join_units, parse_number, ReadOptions, Separator};
use crate::error::{data_error, IoError, Location};
use crate::input::{excerpt, MAX_LINE_BYTES};
use crate::lines::{
    check_held_at, check_line, first_token, looks_numeric, parse_coordinate_with, split_fields,
    strip_comment, too_long, Block, LineReader,
};
use crate::plain_decimal;
use crate::store::{Growth, Store};

/// Which fields of a row hold x, y and (for spatial points) z, 0-based.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Columns {
    /// The field of x.
    pub x: usize,
    /// The field of y.
    pub y: usize,
    /// The field of z, for spatial points.
    pub z: Option<usize>,
}

impl Columns {
    /// The columns named `x`, `y` and optionally `z` in a header (compared as
    /// [`column_name`] compares: case, quotes and units aside); `None` unless both `x` and `y`
    /// are there.
    pub(crate) fn from_header(fields: &[String]) -> Option<Columns> {
        let names: Vec<String> = fields.iter().map(|f| column_name(f)).collect();
        let find = |name: &str| names.iter().position(|f| f == name);
        Some(Columns {
            x: find("x")?,
            y: find("y")?,
            z: find("z"),
        })
    }

    /// The columns of the 0-based `fields` chosen, x first.
    fn from_fields(fields: &[usize]) -> Columns {
        Columns {
            x: fields[0],
            y: fields[1],
            z: fields.get(2).copied(),
        }
    }
}

/// The points of a column file, planar or spatial, in the stores `A` and `B`.
pub(crate) enum Either<A, B> {
    /// Two coordinates per point.
    Planar(A),
    /// Three coordinates per point.
    Spatial(B),
}

/// How the columns were found: what the warnings about the columns need to know.
#[derive(Clone, Debug, PartialEq, Eq)]
pub(crate) enum Found {
    /// By the header's names `x`, `y`, `z`.
    ByName,
    /// By `--columns`.
    Chosen,
    /// The first two or three fields of rows without a header.
    NoHeader,
    /// In order, the header (quoted) naming none of `x`, `y`, `z`.
    InOrder(String),
}

/// How the rows of a column file are laid out, as its first content line says.
pub(crate) struct Layout {
    /// What separates the fields.
    pub sep: Separator,
    /// The decimal mark the fast path reads (`b'.'` or `b','`); the careful path reads
    /// either where the separator allows a decimal comma.
    pub point: u8,
    /// True until the decimal mark is known (a header, before the first row).
    pub point_open: bool,
    /// A comma in a number field is a decimal comma: the separator is not a comma, or
    /// `--decimal-comma` says so (then quoted fields may hold them in a comma-separated file).
    pub comma_decimals: bool,
    /// The number of fields of every data row.
    pub width: usize,
    /// Where the coordinates are.
    pub columns: Columns,
    /// How they were found.
    pub found: Found,
    /// The first data row (its line and content), when the first line was not a header.
    pub first_row: Option<(usize, String)>,
    /// The header's line and text, when there is one.
    pub header: Option<(usize, String)>,
}

impl Layout {
    /// The layout given by the first content line `content` (line `line`) of `name`, read with
    /// the user's `options`.
    pub(crate) fn from_first_line(
        content: &str,
        line: usize,
        name: &Path,
        options: &ReadOptions,
    ) -> Result<Layout, IoError> {
        let at = Location::new(name, line);
        let sep = Separator::of_line(content, options.decimal_comma);
        let fields = split_fields(content, sep, at)?;
        let comma = sep.allows_decimal_comma() || options.decimal_comma;
        if !fields.iter().all(|f| parse_number(f, comma).is_some()) {
            let fields = if sep == Separator::Whitespace {
                join_units(fields)
            } else {
                fields
            };
            return Layout::from_header(fields, sep, line, name, options);
        }
        let width = fields.len();
        let (columns, found) = match &options.columns {
            Some(choice) => {
                let chosen = choice.resolve(None, width).map_err(|m| at.error(m))?;
                (Columns::from_fields(&chosen), Found::Chosen)
            }
            None => match width {
                2 | 3 => (Columns::from_fields(&[0, 1, 2][..width]), Found::NoHeader),
                n => {
                    let hint = if options.decimal_comma && content.matches(',').count() > 1 {
                        " (with --decimal-comma the comma is a decimal mark: separate the \
                         fields by ';', tabs or spaces)"
                    } else {
                        ": choose them with --columns A,B[,C] (positions counted from 1)"
                    };
                    return Err(at.error(format!(
                        "expected 2 columns (x y) or 3 columns (x y z), found {n}{hint}"
                    )));
                }
            },
        };
        Ok(Layout {
            sep,
            point: decimal_mark(sep, &fields),
            point_open: false,
            comma_decimals: comma,
            width,
            columns,
            found,
            first_row: Some((line, content.to_owned())),
            header: None,
        })
    }

    /// The layout of a file whose header (line `line`, split at `sep`) is `fields`.
    pub(crate) fn from_header(
        fields: Vec<String>,
        sep: Separator,
        line: usize,
        name: &Path,
        options: &ReadOptions,
    ) -> Result<Layout, IoError> {
        let at = Location::new(name, line);
        let width = fields.len();
        let text = excerpt(&fields.join(&sep_text(sep)));
        let (columns, found) = match &options.columns {
            Some(choice) => {
                let chosen = choice
                    .resolve(Some(&fields), width)
                    .map_err(|m| at.error(m))?;
                (Columns::from_fields(&chosen), Found::Chosen)
            }
            None => {
                let names: Vec<String> = fields.iter().map(|f| column_name(f)).collect();
                if let Some(name) = duplicated_name(&names) {
                    return Err(at.error(format!("the header names column '{name}' twice")));
                }
                let named = names.iter().any(|n| ["x", "y", "z"].contains(&n.as_str()));
                match Columns::from_header(&fields) {
                    Some(columns) => (columns, Found::ByName),
                    None if !named && (2..=3).contains(&width) => (
                        Columns::from_fields(&[0, 1, 2][..width]),
                        Found::InOrder(text.clone()),
                    ),
                    None => {
                        return Err(at.error(format!(
                            "the header '{text}' names no 'x' and 'y' columns: choose them with \
                             --columns A,B[,C]"
                        )))
                    }
                }
            }
        };
        Ok(Layout {
            sep,
            point: b'.',
            point_open: sep.allows_decimal_comma(),
            comma_decimals: sep.allows_decimal_comma() || options.decimal_comma,
            width,
            columns,
            found,
            first_row: None,
            header: Some((line, text)),
        })
    }
}

/// How a header's fields are joined again in messages.
fn sep_text(sep: Separator) -> String {
    match sep {
        Separator::Comma => ",".to_owned(),
        Separator::Semicolon => ";".to_owned(),
        Separator::Tab | Separator::Whitespace => " ".to_owned(),
    }
}

/// The decimal mark of a file separated by `sep` whose first data row has `fields`: a comma
/// when the separator allows decimal commas and a field holds one.
fn decimal_mark(sep: Separator, fields: &[String]) -> u8 {
    if sep.allows_decimal_comma() && fields.iter().any(|f| f.contains(',')) {
        b','
    } else {
        b'.'
    }
}

/// Reads the rest of a column file in `layout` from `lines` into the store for its
/// dimension; `size` is the input's size when known (see [`Growth`]).
pub(crate) fn read_columns<R: BufRead + Send, A: Store<2>, B: Store<3>>(
    lines: &mut LineReader<'_, R>,
    layout: Layout,
    size: Option<u64>,
) -> Result<Either<A, B>, IoError> {
    let mut layout = layout;
    let Columns { x, y, z } = layout.columns;
    Ok(match z {
        None => Either::Planar(collect(lines, &mut layout, [x, y], size)?),
        Some(z) => Either::Spatial(collect(lines, &mut layout, [x, y, z], size)?),
    })
}

/// What a line that is not a plain data row turned out to be.
enum Slow<const D: usize> {
    /// Nothing (all fields empty): skipped.
    Blank,
    /// A data row after all.
    Point([f64; D]),
    /// The first note.
    Note,
}

/// The points of the data rows, coordinate `k` from field `columns[k]`.
fn collect<R: BufRead + Send, const D: usize, S: Store<D>>(
    lines: &mut LineReader<'_, R>,
    layout: &mut Layout,
    columns: [usize; D],
    size: Option<u64>,
) -> Result<S, IoError> {
    let mut rows = Rows::<D, S>::new(lines.name(), Growth { size }, layout.width, columns);
    if let Some((line, content)) = &layout.first_row {
        if let Slow::Point(p) = slow_row(content, *line, &*layout, &rows.slot, rows.name)? {
            rows.push(p, lines.consumed(), *line)?;
        }
    }
    rows.line = lines.line();
    let mut after = lines.consumed();
    // Two blocks: one parsed while the next is read on another thread.
    let mut blocks = [Vec::new(), Vec::new()];
    // 1 MiB of whole lines per thread parsing them.
    let block_bytes = rayon::current_num_threads().clamp(1, MAX_PIECES) << 20;
    let mut next = lines.read_block(&mut blocks[0], block_bytes)?;
    let mut current = 0;
    loop {
        let len = match next {
            Block::TooLong => return Err(too_long(rows.name, rows.line + 1)),
            Block::Lines(0) => break,
            Block::Lines(len) => len,
        };
        let [first, second] = &mut blocks;
        let (block, spare) = if current == 0 {
            (&first[..len], second)
        } else {
            (&second[..len], first)
        };
        current = 1 - current;
        after += len as u64;
        if layout.point_open {
            settle_decimal_mark(layout, block);
        }
        let layout = &*layout;
        let try_fast = rows.notes.is_none();
        let slot = &rows.slot;
        let parse = || {
            if try_fast {
                fast_block::<D>(block, layout, slot)
            } else {
                None
            }
        };
        let (fast, read) = if cfg!(target_family = "wasm") {
            // No threads in a browser: parse, then read the next block.
            (parse(), Ok(lines.read_block(spare, block_bytes)))
        } else {
            std::thread::scope(|scope| {
                let reader = scope.spawn(|| lines.read_block(spare, block_bytes));
                (parse(), reader.join())
            })
        };
        next = match read {
            Ok(read) => read?,
            Err(panic) => std::panic::resume_unwind(panic),
        };
        match fast {
            Some(pieces) => rows.take_pieces(&pieces, after)?,
            None => rows.read_carefully(block, after, layout)?,
        }
    }
    rows.finish(layout)
}

/// The data rows read so far: the points, the line reached, and the first note met (after
/// which every row must be a note).
struct Rows<'p, const D: usize, S> {
    name: &'p Path,
    growth: Growth,
    /// `slot[k]`: which coordinate field `k` holds, or `D` for none.
    slot: Vec<usize>,
    store: S,
    line: usize,
    /// Bytes of blank lines and notes passed over.
    skipped: u128,
    notes: Option<(usize, String)>,
}

impl<'p, const D: usize, S: Store<D>> Rows<'p, D, S> {
    fn new(name: &'p Path, growth: Growth, width: usize, columns: [usize; D]) -> Self {
        let mut slot = vec![D; width];
        for (c, &k) in columns.iter().enumerate() {
            slot[k] = c;
        }
        Rows {
            name,
            growth,
            slot,
            store: S::default(),
            line: 0,
            skipped: 0,
            notes: None,
        }
    }

    /// Adds the point of `line`, the points up to it taking the first `consumed` bytes.
    fn push(&mut self, p: [f64; D], consumed: u64, line: usize) -> Result<(), IoError> {
        if self.store.len() == self.store.capacity() {
            let at = Location::new(self.name, line);
            self.growth.grow(&mut self.store, 1, consumed, at)?;
        }
        self.store.push(p);
        Ok(())
    }

    /// Adds a block's points parsed on the fast path, the block ending at byte `after`.
    fn take_pieces(&mut self, pieces: &[Vec<[f64; D]>], after: u64) -> Result<(), IoError> {
        let count = pieces.iter().map(Vec::len).sum();
        if self.store.capacity() - self.store.len() < count {
            let at = Location::new(self.name, self.line + count);
            self.growth.grow(&mut self.store, count, after, at)?;
        }
        for piece in pieces {
            self.store.extend_from(piece);
        }
        self.line += count;
        Ok(())
    }

    /// Reads a block line by line (the block ending at byte `after`): plain rows on the fast
    /// path, the others (blank, quoted, notes) on the careful one.
    fn read_carefully(&mut self, block: &[u8], after: u64, layout: &Layout) -> Result<(), IoError> {
        let name = self.name;
        let mut consumed = after - block.len() as u64;
        for bytes in block.split_inclusive(|&b| b == b'\n') {
            self.line += 1;
            let line = self.line;
            consumed += bytes.len() as u64;
            if bytes.len() > MAX_LINE_BYTES + 1 {
                return Err(too_long(name, line));
            }
            if self.notes.is_none() {
                if let Some(p) = fast_row(bytes, layout, &self.slot) {
                    self.push(p, consumed, line)?;
                    continue;
                }
            }
            let text = check_line(name, line, bytes)?;
            let content = strip_comment(text).trim();
            if content.is_empty() {
                self.skipped += text.len() as u128 + 1;
                if self.skipped > 1 << 16 {
                    self.check_held()?;
                }
                continue;
            }
            match (
                &self.notes,
                slow_row(content, line, layout, &self.slot, name)?,
            ) {
                (_, Slow::Blank) => {}
                (None, Slow::Point(p)) => self.push(p, consumed, line)?,
                (None, Slow::Note) => self.notes = Some((line, excerpt(content))),
                (Some((first, note)), Slow::Point(_)) => {
                    return Err(Location::new(name, line).error(format!(
                        "a data row after the notes that begin on line {first} ('{note}'): notes \
                         may only follow the data (remove them or start them with '#')"
                    )))
                }
                (Some(_), Slow::Note) => {
                    self.skipped += text.len() as u128 + 1;
                    self.check_held()?;
                }
            }
        }
        Ok(())
    }

    /// Fails when the points and the bytes passed over exceed the memory cap.
    fn check_held(&self) -> Result<(), IoError> {
        check_held_at(
            self.name,
            self.line,
            self.skipped + held_bytes::<D, S>(&self.store),
        )
    }

    /// The points, refused when there are none.
    fn finish(self, layout: &Layout) -> Result<S, IoError> {
        if self.store.len() == 0 {
            return Err(data_error(
                self.name,
                nothing_read(layout, self.notes.as_ref()),
            ));
        }
        Ok(self.store)
    }
}

/// Settles the decimal mark of a file with a header from the first row of `block` that is
/// not blank nor a comment: a comma when that row holds one (the separator allows it).
fn settle_decimal_mark(layout: &mut Layout, block: &[u8]) {
    let row = block
        .split(|&b| b == b'\n')
        .map(|l| l.split(|&b| b == b'#').next().unwrap_or(l))
        .find(|l| l.iter().any(|b| !b.is_ascii_whitespace()));
    if let Some(row) = row {
        if row.contains(&b',') {
            layout.point = b',';
        }
        layout.point_open = false;
    }
}

/// What "no points found" says of a column file in `layout` that gave none: the header
/// alone, or the line where the data ended (the first `note`).
fn nothing_read(layout: &Layout, note: Option<&(usize, String)>) -> String {
    let header = match &layout.header {
        Some((line, text)) => format!("the header '{text}' (line {line})"),
        None => "the first line".to_owned(),
    };
    match note {
        Some((line, text)) => format!(
            "no points found: after {header}, line {line} ('{text}') is not a row of {} \
             numbers separated by {}, and the data end there",
            layout.width,
            layout.sep.name()
        ),
        None => format!("no points found: {header} and no data rows after it"),
    }
}

/// The most pieces a block is parsed in, in parallel.
const MAX_PIECES: usize = 16;

/// The points of a block of lines that are all plain data rows (see [`fast_row`]), parsed in
/// as many pieces as there are threads, in parallel; `None` when any line is not (the caller
/// then reads the block line by line).
fn fast_block<const D: usize>(
    block: &[u8],
    layout: &Layout,
    slot: &[usize],
) -> Option<Vec<Vec<[f64; D]>>> {
    use rayon::prelude::*;
    let pieces = rayon::current_num_threads().clamp(1, MAX_PIECES);
    let mut bounds = vec![0];
    for k in 1..pieces {
        let from = (block.len() * k / pieces).max(*bounds.last()?);
        let cut = memchr::memchr(b'\n', &block[from..]).map_or(block.len(), |e| from + e + 1);
        bounds.push(cut);
    }
    bounds.push(block.len());
    bounds
        .par_windows(2)
        .map(|w| fast_lines(&block[w[0]..w[1]], layout, slot))
        .collect()
}

/// The points of `bytes`, lines that are all plain data rows; `None` when one is not. One
/// walk over the bytes: each row is parsed from where the previous one ended.
fn fast_lines<const D: usize>(
    bytes: &[u8],
    layout: &Layout,
    slot: &[usize],
) -> Option<Vec<[f64; D]>> {
    let mut points = Vec::with_capacity(bytes.len() / (8 * D + 1) + 1);
    let mut start = 0;
    while start < bytes.len() {
        let (p, len) = fast_row_at(&bytes[start..], layout, slot)?;
        if len > MAX_LINE_BYTES {
            return None;
        }
        points.push(p);
        start += len;
    }
    Some(points)
}

/// The bytes the points of `store` take.
fn held_bytes<const D: usize, S: Store<D>>(store: &S) -> u128 {
    (store.len() * D * std::mem::size_of::<f64>()) as u128
}

/// The point of a plain data row: `layout.width` fields split at the layout's separator, its
/// coordinate fields finite numbers (maybe in double quotes) with the layout's decimal mark;
/// `None` for anything else (a comment, another double quote, a field that is not a number),
/// which [`slow_row`] then reads.
#[inline]
fn fast_row<const D: usize>(line: &[u8], layout: &Layout, slot: &[usize]) -> Option<[f64; D]> {
    fast_row_at(line, layout, slot)
        .filter(|&(_, len)| len == line.len())
        .map(|(p, _)| p)
}

/// The point of the plain data row (see [`fast_row`]) that `bytes` start with, and the length
/// of that row with its end of line; the row's parser is chosen for the layout's separator
/// and decimal mark ([`row_at`]).
#[inline]
fn fast_row_at<const D: usize>(
    bytes: &[u8],
    layout: &Layout,
    slot: &[usize],
) -> Option<([f64; D], usize)> {
    let width = layout.width;
    match (layout.sep.byte(), layout.point) {
        (Some(b','), _) => row_at::<D, b',', b'.'>(bytes, width, slot),
        (Some(b';'), b',') => row_at::<D, b';', b','>(bytes, width, slot),
        (Some(b';'), _) => row_at::<D, b';', b'.'>(bytes, width, slot),
        (Some(b'\t'), b',') => row_at::<D, b'\t', b','>(bytes, width, slot),
        (Some(b'\t'), _) => row_at::<D, b'\t', b'.'>(bytes, width, slot),
        (_, b',') => row_at::<D, 0, b','>(bytes, width, slot),
        _ => row_at::<D, 0, b'.'>(bytes, width, slot),
    }
}

/// [`fast_row_at`] for the separator `SEP` (0: runs of whitespace) and the decimal mark
/// `POINT`. One scan of the bytes finds the fields; a coordinate is parsed where it starts
/// (the parser finds its end, and never reads past the end of its line), and the byte after
/// it (after its closing quote, if it opened with one) must end the field.
#[inline]
fn row_at<const D: usize, const SEP: u8, const POINT: u8>(
    bytes: &[u8],
    width: usize,
    slot: &[usize],
) -> Option<([f64; D], usize)> {
    let mut p = [0.0; D];
    let n = bytes.len();
    let csv = SEP != 0;
    let blank = |b: u8| matches!(b, b' ' | b'\t' | b'\r') && b != SEP;
    // The end of a field: its separator or the end of the line.
    let end_of_field = |b: u8| b == b'\n' || if csv { b == SEP } else { blank(b) };
    let skip_blanks = |mut k: usize| {
        while k < n && blank(bytes[k]) {
            k += 1;
        }
        k
    };
    let mut k = 0;
    let mut count = 0;
    loop {
        k = skip_blanks(k);
        if (k == n || bytes[k] == b'\n') && (!csv || count > 0) {
            break;
        }
        let s = *slot.get(count)?;
        count += 1;
        if s < D {
            let quoted = bytes.get(k) == Some(&b'"');
            k += usize::from(quoted);
            let rest = &bytes[k..];
            let (v, used): (f64, usize) = match plain_decimal::parse_with::<POINT>(rest) {
                Some(plain) => plain,
                None => fast_float2::parse_partial(rest).ok()?,
            };
            if used == 0 || !v.is_finite() {
                return None;
            }
            p[s] = v;
            k += used;
            if quoted {
                if bytes.get(k) != Some(&b'"') {
                    return None;
                }
                k += 1;
            }
            if csv {
                k = skip_blanks(k);
            }
            if k < n && !end_of_field(bytes[k]) {
                return None;
            }
        } else {
            while k < n && !end_of_field(bytes[k]) {
                if matches!(bytes[k], b'#' | b'"') {
                    return None;
                }
                k += 1;
            }
        }
        if csv {
            if k == n || bytes[k] == b'\n' {
                break;
            }
            k = skip_blanks(k + 1);
            if k == n || bytes[k] == b'\n' {
                // A separator at the end: one more (empty) field.
                return None;
            }
        }
    }
    // Here `k` is at the end of the line: its `\n` or the end of `bytes`.
    (count == width).then_some((p, (k + 1).min(n)))
}

/// Classifies a line that is not a plain data row (see the [module docs](self)): a point, a
/// note, nothing, or the error of a damaged row.
fn slow_row<const D: usize>(
    content: &str,
    line: usize,
    layout: &Layout,
    slot: &[usize],
    name: &Path,
) -> Result<Slow<D>, IoError> {
    let at = Location::new(name, line);
    let fields = split_fields(content, layout.sep, at)?;
    if fields.iter().all(String::is_empty) {
        return Ok(Slow::Blank);
    }
    let comma = layout.comma_decimals;
    let is_number = |f: &String| parse_number(f, comma).is_some();
    let width = layout.width;
    let shaped = fields.len() == width;
    let numeric_first = first_token(content).is_some_and(looks_numeric);
    let note = !(numeric_first || (shaped && fields.iter().any(is_number)));
    let is_row = shaped
        && fields
            .iter()
            .zip(slot)
            .all(|(f, &s)| s == D || is_number(f));
    if note && !is_row {
        return Ok(Slow::Note);
    }
    if !shaped {
        return Err(at.error(format!("expected {width} fields, found {}", fields.len())));
    }
    let mut p = [0.0; D];
    for (k, (field, &s)) in fields.iter().zip(slot).enumerate() {
        if s < D {
            p[s] = parse_coordinate_with(field, k + 1, at, comma)?;
        }
    }
    Ok(Slow::Point(p))
}

/// A coordinate column name (`x`, `y`, `z`) that a header's `names` (as [`column_name`]
/// gives them) hold twice, if any.
fn duplicated_name(names: &[String]) -> Option<&'static str> {
    ["x", "y", "z"]
        .into_iter()
        .find(|name| names.iter().filter(|f| f == name).count() > 1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A layout of `width` columns, `x` and `y` at `columns`, read by name with decimal points.
    fn layout_of(sep: Separator, width: usize, (x, y): (usize, usize)) -> Layout {
        Layout {
            sep,
            point: b'.',
            point_open: false,
            comma_decimals: false,
            found: Found::ByName,
            header: None,
            width,
            columns: Columns { x, y, z: None },
            first_row: None,
        }
    }

    /// Marsaglia's xorshift64 generator from `state` (nonzero).
    fn xorshift(mut state: u64) -> impl FnMut() -> u64 {
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        }
    }

    /// Commas or whitespace.
    fn sep_of(csv: bool) -> Separator {
        if csv {
            Separator::Comma
        } else {
            Separator::Whitespace
        }
    }

    #[test]
    fn header_columns_are_found_by_name() {
        let h = |s: &str| s.split(',').map(str::to_owned).collect::<Vec<_>>();
        assert_eq!(
            Columns::from_header(&h("t,X,y")),
            Some(Columns {
                x: 1,
                y: 2,
                z: None
            })
        );
        assert_eq!(
            Columns::from_header(&h("z,y,x")),
            Some(Columns {
                x: 2,
                y: 1,
                z: Some(0)
            })
        );
        assert_eq!(Columns::from_header(&h("a,b")), None);
        assert_eq!(duplicated_name(&h("x,y,x")), Some("x"));
        assert_eq!(
            Columns::from_header(&h("x [mm],\"Y (mm)\"")),
            Some(Columns {
                x: 0,
                y: 1,
                z: None
            })
        );
    }

    #[test]
    fn plain_rows_take_the_fast_path() {
        let layout = layout_of(Separator::Comma, 3, (1, 2));
        let slot = [2, 0, 1];
        assert_eq!(
            fast_row::<2>(b"7, 1.5 ,-2e3", &layout, &slot),
            Some([1.5, -2e3])
        );
        assert_eq!(fast_row::<2>(b"a,1,2", &layout, &slot), Some([1.0, 2.0]));
        assert_eq!(fast_row::<2>(b"1,2", &layout, &slot), None);
        assert_eq!(fast_row::<2>(b"1,2,3,4", &layout, &slot), None);
        assert_eq!(fast_row::<2>(b"1,nan,3", &layout, &slot), None);
        assert_eq!(fast_row::<2>(b"\"1\",2,3", &layout, &slot), None);
        assert_eq!(fast_row::<2>(b"1,2,3 # c", &layout, &slot), None);
        assert_eq!(fast_row::<2>(b"", &layout, &slot), None);
        let layout = layout_of(Separator::Whitespace, 2, (0, 1));
        let slot = [0, 1];
        assert_eq!(fast_row::<2>(b" 1\t2 \r", &layout, &slot), Some([1.0, 2.0]));
        assert_eq!(fast_row::<2>(b"1 2#c", &layout, &slot), None);
        assert_eq!(fast_row::<2>(b"   ", &layout, &slot), None);
    }

    #[test]
    fn the_fast_parser_accepts_what_the_standard_one_does() {
        let fields = [
            "1",
            "-1.5",
            "+2",
            "1e5",
            "1E-5",
            ".5",
            "5.",
            "1e",
            "e5",
            "--1",
            "+-1",
            "1.2.3",
            "0x10",
            "1_0",
            " 1",
            "1 ",
            "",
            ".",
            "-",
            "1e+",
            "1e400",
            "1e-400",
            "00012",
            "1d5",
            "١",
            "0.30000000000000004",
            "123456789012345678901234567890",
            "inf",
            "NaN",
            "1,5",
        ];
        for f in fields {
            let std = f.parse::<f64>().ok().filter(|v| v.is_finite());
            let fast = fast_float2::parse::<f64, _>(f.as_bytes())
                .ok()
                .filter(|v| v.is_finite());
            assert_eq!(std, fast, "{f:?}");
        }
    }

    #[test]
    fn the_fast_path_agrees_with_the_careful_one() {
        const ALPHABET: &[u8] = b"0123456789.,-+e #\t\r\"xnaif ";
        let mut next = xorshift(0x9e37_79b9_7f4a_7c15);
        let mut agreed = 0;
        for k in 0..40_000 {
            let csv = k % 2 == 0;
            let len = (next() % 24) as usize;
            let line: String = (0..len)
                .map(|_| ALPHABET[(next() % ALPHABET.len() as u64) as usize] as char)
                .collect();
            let line = format!("{line}\n");
            let layout = layout_of(sep_of(csv), 2, (0, 1));
            let Some(fast) = fast_row::<2>(line.as_bytes(), &layout, &[0, 1]) else {
                continue;
            };
            let content = strip_comment(&line).trim();
            let at = Location::new(Path::new("r"), 1);
            let fields = split_fields(content, sep_of(csv), at).unwrap();
            assert_eq!(fields.len(), 2, "{line:?}");
            let careful =
                [0, 1].map(|c| parse_coordinate_with(&fields[c], c + 1, at, false).unwrap());
            assert_eq!(fast, careful, "{line:?}");
            agreed += 1;
        }
        assert!(agreed > 100, "{agreed}");
    }

    #[test]
    fn semicolons_tabs_and_decimal_commas_agree_with_the_careful_path() {
        const ALPHABET: &[u8] = b"0123456789012345678901234567890123456789.,;-+e #\t\"x ";
        let mut next = xorshift(0x2545_f491_4f6c_dd1d);
        let mut agreed = 0;
        for k in 0..40_000 {
            let (sep, sep_text) = if k % 2 == 0 {
                (Separator::Semicolon, ";")
            } else {
                (Separator::Tab, "\t")
            };
            let len = (next() % 40) as usize;
            let mut line: String = (0..len)
                .map(|_| ALPHABET[(next() % ALPHABET.len() as u64) as usize] as char)
                .collect();
            if k % 4 < 2 {
                let mut number = || {
                    let digits = 1 + (next() % 20) as usize;
                    let mut text: String = (0..digits)
                        .map(|_| char::from(b'0' + (next() % 10) as u8))
                        .collect();
                    let point = (next() % (digits as u64 + 2)) as usize;
                    if point <= digits {
                        text.insert(point, if next().is_multiple_of(3) { '.' } else { ',' });
                    }
                    match next() % 4 {
                        0 => format!("-{text}"),
                        1 => format!("\"{text}\""),
                        _ => text,
                    }
                };
                line = format!("{}{sep_text}{}", number(), number());
            }
            let block = format!("{line}\n1{sep_text}2\n");
            for point in [b'.', b','] {
                let layout = Layout {
                    point,
                    comma_decimals: true,
                    found: Found::NoHeader,
                    ..layout_of(sep, 2, (0, 1))
                };
                let Some(points) = fast_lines::<2>(block.as_bytes(), &layout, &[0, 1]) else {
                    continue;
                };
                assert_eq!(points[1], [1.0, 2.0], "{line:?}");
                let content = strip_comment(&line).trim();
                let at = Location::new(Path::new("r"), 1);
                let fields = split_fields(content, sep, at).unwrap();
                assert_eq!(fields.len(), 2, "{line:?}");
                let careful = [0, 1].map(|c| parse_coordinate_with(&fields[c], c + 1, at, true));
                let careful = careful.map(|v| v.unwrap().to_bits());
                assert_eq!(points[0].map(f64::to_bits), careful, "{line:?}");
                agreed += 1;
            }
        }
        assert!(agreed > 10_000, "{agreed}");
    }

    #[test]
    fn rows_within_a_block_agree_with_the_careful_path() {
        // Rows of long numbers, followed by another row: the parser sees the bytes after
        // each number, as it does inside a block.
        const ALPHABET: &[u8] = b"0123456789012345678901234567890123456789.,-+e #\t\"x ";
        let mut next = xorshift(0x853c_49e6_748f_ea9b);
        let mut agreed = 0;
        for k in 0..40_000 {
            let csv = k % 2 == 0;
            let len = (next() % 60) as usize;
            let mut line: String = (0..len)
                .map(|_| ALPHABET[(next() % ALPHABET.len() as u64) as usize] as char)
                .collect();
            if k % 4 < 2 {
                // Two numbers of up to 22 digits, a sign and a point or not.
                let mut number = || {
                    let digits = 1 + (next() % 22) as usize;
                    let mut text: String = (0..digits)
                        .map(|_| char::from(b'0' + (next() % 10) as u8))
                        .collect();
                    let point = (next() % (digits as u64 + 2)) as usize;
                    if point <= digits {
                        text.insert(point, '.');
                    }
                    match next() % 3 {
                        0 => format!("-{text}"),
                        1 => format!(" {text}"),
                        _ => text,
                    }
                };
                let (a, b) = (number(), number());
                line = if csv {
                    format!("{a},{b}")
                } else {
                    format!("{a} {b}")
                };
            }
            let block = format!("{line}\n{}\n", if csv { "1,2" } else { "1 2" });
            let layout = layout_of(sep_of(csv), 2, (0, 1));
            let Some(points) = fast_lines::<2>(block.as_bytes(), &layout, &[0, 1]) else {
                continue;
            };
            assert_eq!(points.len(), 2, "{line:?}");
            assert_eq!(points[1], [1.0, 2.0], "{line:?}");
            let content = strip_comment(&line).trim();
            let at = Location::new(Path::new("r"), 1);
            let fields = split_fields(content, sep_of(csv), at).unwrap();
            assert_eq!(fields.len(), 2, "{line:?}");
            let careful =
                [0, 1].map(|c| parse_coordinate_with(&fields[c], c + 1, at, false).unwrap());
            assert_eq!(
                points[0].map(f64::to_bits),
                careful.map(f64::to_bits),
                "{line:?}"
            );
            agreed += 1;
        }
        assert!(agreed > 10_000, "{agreed}");
    }
}

//! Column files of curve points (CSV or whitespace-separated), read in one streaming pass.
//!
//! The first content line decides the layout: a header (any field not a number; it must name
//! `x` and `y`, and `z` makes the points spatial) or the first data row (two columns are
//! planar points, three spatial ones). Then every line is one of:
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
//! no double quote, nothing but the data's fields) is split in pieces parsed in parallel,
//! each walked once, row after row, and each coordinate parsed where it starts: a plain
//! decimal by [`crate::plain_decimal`], any other number by `fast-float2` (both correctly
//! rounded, as `str::parse`; tests compare the fast and careful paths on random rows), with no
//! allocation per row or field. Any other block is read line by line, each line tried the same way and
//! otherwise split into owned fields to be classified or reported, so line numbers and
//! messages are those of a line-by-line read. Memory: the points themselves
//! ([`crate::store`]), two blocks and one block's points, and nothing per skipped line except
//! its bytes counted against the memory cap (so an endless stream of comments or notes ends
//! too).

use std::io::BufRead;
use std::path::Path;

use crate::error::{data_error, IoError, Location};
use crate::input::{excerpt, MAX_LINE_BYTES};
use crate::lines::{
    check_held_at, check_line, first_token, is_number, looks_numeric, parse_coordinate,
    split_fields, strip_comment, too_long, Block, LineReader,
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
    /// The columns named `x`, `y` and optionally `z` (case-insensitive) in a header; `None`
    /// unless both `x` and `y` are there.
    pub fn from_header(fields: &[String]) -> Option<Columns> {
        let find = |name: &str| fields.iter().position(|f| f.eq_ignore_ascii_case(name));
        Some(Columns {
            x: find("x")?,
            y: find("y")?,
            z: find("z"),
        })
    }
}

/// The points of a column file, planar or spatial, in the stores `A` and `B`.
pub(crate) enum Either<A, B> {
    /// Two coordinates per point.
    Planar(A),
    /// Three coordinates per point.
    Spatial(B),
}

/// How the rows of a column file are laid out, as its first content line says.
pub(crate) struct Layout {
    /// Fields split at commas (else at whitespace).
    pub csv: bool,
    /// The number of fields of every data row.
    pub width: usize,
    /// Where the coordinates are.
    pub columns: Columns,
    /// The first data row (its line and content), when the first line was not a header.
    pub first_row: Option<(usize, String)>,
}

impl Layout {
    /// The layout given by the first content line `content` (line `line`) of `name`.
    pub fn from_first_line(content: &str, line: usize, name: &Path) -> Result<Layout, IoError> {
        let at = Location::new(name, line);
        let csv = content.contains(',');
        let fields = split_fields(content, csv, at)?;
        let width = fields.len();
        if !fields.iter().all(|f| is_number(f)) {
            let columns = Columns::from_header(&fields).ok_or_else(|| {
                at.error(format!(
                    "the header '{}' names no 'x' and 'y' columns",
                    excerpt(&fields.join(","))
                ))
            })?;
            if let Some(name) = duplicated_name(&fields) {
                return Err(at.error(format!("the header names column '{name}' twice")));
            }
            return Ok(Layout {
                csv,
                width,
                columns,
                first_row: None,
            });
        }
        let z = match width {
            2 => None,
            3 => Some(2),
            n => {
                return Err(at.error(format!(
                    "expected 2 columns (x y) or 3 columns (x y z), found {n}"
                )))
            }
        };
        Ok(Layout {
            csv,
            width,
            columns: Columns { x: 0, y: 1, z },
            first_row: Some((line, content.to_owned())),
        })
    }
}

/// Reads the rest of a column file in `layout` from `lines` into the store for its
/// dimension; `size` is the input's size when known (see [`Growth`]).
pub(crate) fn read_columns<R: BufRead + Send, A: Store<2>, B: Store<3>>(
    lines: &mut LineReader<'_, R>,
    layout: Layout,
    size: Option<u64>,
) -> Result<Either<A, B>, IoError> {
    let Columns { x, y, z } = layout.columns;
    Ok(match z {
        None => Either::Planar(collect(lines, &layout, [x, y], size)?),
        Some(z) => Either::Spatial(collect(lines, &layout, [x, y, z], size)?),
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
    layout: &Layout,
    columns: [usize; D],
    size: Option<u64>,
) -> Result<S, IoError> {
    let name = lines.name();
    let growth = Growth { size };
    // slot[k]: which coordinate field k holds, or D for none.
    let mut slot = vec![D; layout.width];
    for (c, &k) in columns.iter().enumerate() {
        slot[k] = c;
    }
    let mut store = S::default();
    let push = |store: &mut S, p: [f64; D], consumed: u64, line: usize| -> Result<(), IoError> {
        if store.len() == store.capacity() {
            growth.grow(store, 1, consumed, Location::new(name, line))?;
        }
        store.push(p);
        Ok(())
    };
    if let Some((line, content)) = &layout.first_row {
        let p = slow_row(content, *line, layout, &slot, name)?;
        if let Slow::Point(p) = p {
            push(&mut store, p, lines.consumed(), *line)?;
        }
    }
    let mut skipped: u128 = 0;
    let mut notes: Option<(usize, String)> = None;
    let mut line = lines.line();
    let mut after = lines.consumed();
    // Two blocks: one parsed while the next is read on another thread.
    let mut blocks = [Vec::new(), Vec::new()];
    // 1 MiB of whole lines per thread parsing them.
    let block_bytes = rayon::current_num_threads().clamp(1, MAX_PIECES) << 20;
    let mut next = lines.read_block(&mut blocks[0], block_bytes)?;
    let mut current = 0;
    loop {
        let len = match next {
            Block::TooLong => return Err(too_long(name, line + 1)),
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
        let try_fast = notes.is_none();
        let parse = || {
            if try_fast {
                fast_block::<D>(block, layout, &slot)
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
        if let Some(pieces) = fast {
            let count = pieces.iter().map(Vec::len).sum();
            if store.capacity() - store.len() < count {
                let at = Location::new(name, line + count);
                growth.grow(&mut store, count, after, at)?;
            }
            for piece in &pieces {
                store.extend_from(piece);
            }
            line += count;
            continue;
        }
        let mut consumed = after - block.len() as u64;
        for bytes in block.split_inclusive(|&b| b == b'\n') {
            line += 1;
            consumed += bytes.len() as u64;
            if bytes.len() > MAX_LINE_BYTES + 1 {
                return Err(too_long(name, line));
            }
            if notes.is_none() {
                if let Some(p) = fast_row(bytes, layout, &slot) {
                    push(&mut store, p, consumed, line)?;
                    continue;
                }
            }
            let text = check_line(name, line, bytes)?;
            let content = strip_comment(text).trim();
            if content.is_empty() {
                skipped += text.len() as u128 + 1;
                if skipped > 1 << 16 {
                    check_held_at(name, line, skipped + held_bytes::<D, S>(&store))?;
                }
                continue;
            }
            let at = Location::new(name, line);
            match (&notes, slow_row(content, line, layout, &slot, name)?) {
                (_, Slow::Blank) => {}
                (None, Slow::Point(p)) => push(&mut store, p, consumed, line)?,
                (None, Slow::Note) => notes = Some((line, excerpt(content))),
                (Some((first, note)), Slow::Point(_)) => {
                    return Err(at.error(format!(
                        "a data row after the notes that begin on line {first} ('{note}'): notes \
                         may only follow the data (remove them or start them with '#')"
                    )))
                }
                (Some(_), Slow::Note) => {
                    skipped += text.len() as u128 + 1;
                    check_held_at(name, line, skipped + held_bytes::<D, S>(&store))?;
                }
            }
        }
    }
    if store.len() == 0 {
        return Err(data_error(name, "no points found"));
    }
    Ok(store)
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

/// The point of a plain data row: `layout.width` fields split at commas or whitespace, its
/// coordinate fields finite numbers; `None` for anything else (a comment, a double quote, a
/// field that is not a number), which [`slow_row`] then reads.
#[inline]
fn fast_row<const D: usize>(line: &[u8], layout: &Layout, slot: &[usize]) -> Option<[f64; D]> {
    fast_row_at(line, layout, slot)
        .filter(|&(_, len)| len == line.len())
        .map(|(p, _)| p)
}

/// The point of the plain data row (see [`fast_row`]) that `bytes` start with, and the length
/// of that row with its end of line (`\n`, or the end of `bytes`). One scan of the bytes finds
/// the fields; a coordinate is parsed where it starts (the parser finds its end, and never
/// reads past the end of its line), and the byte after it must end the field.
#[inline]
fn fast_row_at<const D: usize>(
    bytes: &[u8],
    layout: &Layout,
    slot: &[usize],
) -> Option<([f64; D], usize)> {
    let mut p = [0.0; D];
    let n = bytes.len();
    let csv = layout.csv;
    let blank = |b: u8| matches!(b, b' ' | b'\t' | b'\r');
    // The end of a field: its separator or the end of the line.
    let end_of_field = |b: u8| b == b'\n' || if csv { b == b',' } else { blank(b) };
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
            let rest = &bytes[k..];
            let (v, used): (f64, usize) = match plain_decimal::parse(rest) {
                Some(plain) => plain,
                None => fast_float2::parse_partial(rest).ok()?,
            };
            if used == 0 || !v.is_finite() {
                return None;
            }
            p[s] = v;
            k += used;
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
                // A comma at the end: one more (empty) field.
                return None;
            }
        }
    }
    // Here `k` is at the end of the line: its `\n` or the end of `bytes`.
    (count == layout.width).then_some((p, (k + 1).min(n)))
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
    let fields = split_fields(content, layout.csv, at)?;
    if fields.iter().all(String::is_empty) {
        return Ok(Slow::Blank);
    }
    let width = layout.width;
    let shaped = fields.len() == width;
    let numeric_first = first_token(content).is_some_and(looks_numeric);
    let note = !(numeric_first || (shaped && fields.iter().any(|f| is_number(f))));
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
            p[s] = parse_coordinate(field, k + 1, at)?;
        }
    }
    Ok(Slow::Point(p))
}

/// A coordinate column name (`x`, `y`, `z`) that a header gives twice, if any.
fn duplicated_name(fields: &[String]) -> Option<&'static str> {
    ["x", "y", "z"].into_iter().find(|name| {
        fields
            .iter()
            .filter(|f| f.eq_ignore_ascii_case(name))
            .count()
            > 1
    })
}

#[cfg(test)]
mod tests {
    use super::*;

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
    }

    #[test]
    fn plain_rows_take_the_fast_path() {
        let layout = Layout {
            csv: true,
            width: 3,
            columns: Columns {
                x: 1,
                y: 2,
                z: None,
            },
            first_row: None,
        };
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
        let layout = Layout {
            csv: false,
            width: 2,
            columns: Columns {
                x: 0,
                y: 1,
                z: None,
            },
            first_row: None,
        };
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
        let mut state: u64 = 0x9e37_79b9_7f4a_7c15;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
        let mut agreed = 0;
        for k in 0..40_000 {
            let csv = k % 2 == 0;
            let len = (next() % 24) as usize;
            let line: String = (0..len)
                .map(|_| ALPHABET[(next() % ALPHABET.len() as u64) as usize] as char)
                .collect();
            let line = format!("{line}\n");
            let layout = Layout {
                csv,
                width: 2,
                columns: Columns {
                    x: 0,
                    y: 1,
                    z: None,
                },
                first_row: None,
            };
            let Some(fast) = fast_row::<2>(line.as_bytes(), &layout, &[0, 1]) else {
                continue;
            };
            let content = strip_comment(&line).trim();
            let at = Location::new(Path::new("r"), 1);
            let fields = split_fields(content, csv, at).unwrap();
            assert_eq!(fields.len(), 2, "{line:?}");
            let careful = [0, 1].map(|c| parse_coordinate(&fields[c], c + 1, at).unwrap());
            assert_eq!(fast, careful, "{line:?}");
            agreed += 1;
        }
        assert!(agreed > 100, "{agreed}");
    }

    #[test]
    fn rows_within_a_block_agree_with_the_careful_path() {
        // Rows of long numbers, followed by another row: the parser sees the bytes after
        // each number, as it does inside a block.
        const ALPHABET: &[u8] = b"0123456789012345678901234567890123456789.,-+e #\t\"x ";
        let mut state: u64 = 0x853c_49e6_748f_ea9b;
        let mut next = move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            state
        };
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
            let layout = Layout {
                csv,
                width: 2,
                columns: Columns {
                    x: 0,
                    y: 1,
                    z: None,
                },
                first_row: None,
            };
            let Some(points) = fast_lines::<2>(block.as_bytes(), &layout, &[0, 1]) else {
                continue;
            };
            assert_eq!(points.len(), 2, "{line:?}");
            assert_eq!(points[1], [1.0, 2.0], "{line:?}");
            let content = strip_comment(&line).trim();
            let at = Location::new(Path::new("r"), 1);
            let fields = split_fields(content, csv, at).unwrap();
            assert_eq!(fields.len(), 2, "{line:?}");
            let careful = [0, 1].map(|c| parse_coordinate(&fields[c], c + 1, at).unwrap());
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

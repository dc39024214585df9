//! Surface frames: a grid of spatial points as CSV rows `i,j,x,y,z`.
//!
//! One row per grid cell, indices from 0, rows in any order: a frame is often assembled by a
//! script section by section, and an explicit index is easier to check than an implied layout.
//! The header is required; its columns are found by name (any order, any case) and extra
//! columns are ignored. The result is a [`Grid`] with `max i + 1` rows and `max j + 1` columns,
//! every cell given exactly once. `#` comments and blank lines are skipped as in the other
//! formats; quoted fields are read with the `csv` crate, plain lines split at commas without
//! it (no allocation per field, no map of cells: a million-cell grid reads in a fraction of a
//! second). Cells in row-major order, as programs write them, go straight into the grid, and
//! a large text of them is read in pieces in parallel (`parse_in_order`).
//!
//! The same layout with other index names holds the skeleton curves of a tube
//! (the `skeleton` module); the parser here serves both.

use std::collections::HashMap;

use rayon::prelude::*;
use std::path::Path;

use karkas::{Grid, Point, Point3};

use crate::error::{data_error, IoError, Location};
use crate::input::display_name;
use crate::input::excerpt;
use crate::lines::{
    csv_rows, header_columns, parse_coordinate, read_text, strip_bom, strip_comment, Row,
};
use crate::range::check_coordinate_range;

/// The names of a file of indexed points `a,b,x,y,z`, and how its errors name a cell.
pub(crate) struct IndexedLayout {
    /// The five column names: two indices, then `x`, `y`, `z`.
    pub names: [&'static str; 5],
    /// The header as the messages quote it, like `"i,j,x,y,z"`.
    pub header: &'static str,
    /// What the points are, for "no ... found".
    pub what: &'static str,
    /// The error about cell `(a, b)` of `path`.
    pub cell_error: fn(&Path, usize, usize, String) -> IoError,
}

/// The layout of a surface frame.
const GRID: IndexedLayout = IndexedLayout {
    names: ["i", "j", "x", "y", "z"],
    header: "i,j,x,y,z",
    what: "grid points",
    cell_error: |path, i, j, message| IoError::Cell {
        path: path.to_path_buf(),
        i,
        j,
        message,
    },
};

/// Reads the surface frame of the grid CSV file at `path` (`-`: standard input).
pub fn read_grid(path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_grid(&read_text(path)?, &display_name(path))
}

/// Reads a surface frame from grid CSV `text` already in memory; `path` names the file in
/// error messages.
pub fn parse_grid(text: &str, path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_indexed(text, path, &GRID)
}

/// Reads a grid of points from `text` in the `layout` (header names, error wording).
///
/// Text without double quotes or bare carriage returns (what programs write) is split at
/// commas by hand, each field a slice of `text`; any other is read with the `csv` crate
/// ([`csv_rows`]). Both hand the same rows, with the same line numbers, to one
/// [`IndexedRows`], so the grid and every error are the same either way.
pub(crate) fn parse_indexed(
    text: &str,
    path: &Path,
    layout: &IndexedLayout,
) -> Result<Grid<Point3>, IoError> {
    let text = crate::dialect::normalized_csv(strip_bom(text));
    let text = text.as_ref();
    let plain = is_plain(text);
    if plain {
        if let Some(grid) = parse_in_order(text, path, layout) {
            return grid;
        }
    }
    parse_any_order(text, plain, path, layout)
}

/// [`parse_indexed`] for cells in any order: each cell is kept with its indices and line
/// until the grid is complete.
fn parse_any_order(
    text: &str,
    plain: bool,
    path: &Path,
    layout: &IndexedLayout,
) -> Result<Grid<Point3>, IoError> {
    let mut rows = IndexedRows::new(path, layout);
    // At most one cell a line: reserved once (capacity not used is never touched).
    rows.cells
        .reserve(memchr::memchr_iter(b'\n', text.as_bytes()).count() + 1);
    if plain {
        let mut fields: Vec<&str> = Vec::new();
        for (k, line) in text.lines().enumerate() {
            split_row(line, &mut fields);
            rows.row(k + 1, &fields)?;
        }
    } else {
        for row in csv_rows(text, path)? {
            let fields: Vec<&str> = row.fields.iter().map(String::as_str).collect();
            rows.row(row.line, &fields)?;
        }
    }
    rows.finish()
}

/// The grid of plain `text` whose cells come in row-major order, each once (what programs
/// write): the points go straight into the grid, with no record of each cell's indices and
/// line, and a large text is read in pieces in parallel. `None` as soon as a cell comes out
/// of that order or a row does not read; the general reader then reads the text again and
/// reports what it finds, so the grid and every error are the same either way.
fn parse_in_order(
    text: &str,
    path: &Path,
    layout: &IndexedLayout,
) -> Option<Result<Grid<Point3>, IoError>> {
    let (columns, body) = header_and_body(text, path, layout)?;
    let pieces = if body.len() < PARALLEL_BYTES {
        1
    } else {
        rayon::current_num_threads().clamp(1, MAX_PIECES)
    };
    let mut bounds = vec![0];
    for k in 1..pieces {
        let from = (body.len() * k / pieces).max(bounds[k - 1]);
        let cut =
            memchr::memchr(b'\n', &body.as_bytes()[from..]).map_or(body.len(), |e| from + e + 1);
        bounds.push(cut);
    }
    bounds.push(body.len());
    let runs: Vec<Option<Run>> = bounds
        .par_windows(2)
        .map(|w| Run::of(&body[w[0]..w[1]], &columns, path))
        .collect();
    let runs: Vec<Run> = runs.into_iter().collect::<Option<Vec<Run>>>()?;
    // The runs joined: each must go on where the previous one ended.
    let mut cols: Option<usize> = None;
    let mut last: Option<(usize, usize)> = None;
    for run in runs.iter().filter(|r| !r.points.is_empty()) {
        match last {
            None if run.first != (0, 0) => return None,
            None => {}
            Some(end) => follow(end, run.first, &mut cols)?,
        }
        if let Some(c) = run.cols {
            if *cols.get_or_insert(c) != c {
                return None;
            }
        }
        last = Some(run.last);
    }
    let (i, j) = last?;
    let (rows, cols) = match (cols, i.checked_add(1)?, j.checked_add(1)?) {
        (None, _, length) => (1, length),
        (Some(cols), rows, length) if length == cols => (rows, cols),
        _ => return None,
    };
    // The first run's points are the start of the grid's: the others are appended to them.
    let rest: usize = runs.iter().skip(1).map(|r| r.points.len()).sum();
    let mut runs = runs.into_iter();
    let mut points = runs.next()?.points;
    points.reserve_exact(rest);
    for run in runs {
        points.extend_from_slice(&run.points);
    }
    Some(
        check_coordinate_range(points.iter().flat_map(|p| p.0), path).and_then(|()| {
            Grid::from_row_major(rows, cols, points)
                .map_err(|source| IoError::geometry(path, source))
        }),
    )
}

/// Texts shorter than this are read in one piece.
const PARALLEL_BYTES: usize = 1 << 20;
/// The most pieces a text is read in.
const MAX_PIECES: usize = 16;

/// The columns named by the header (the first line with content) of `text`, and the text
/// after it; `None` when there is no header or it does not name the columns.
fn header_and_body<'t>(
    text: &'t str,
    path: &Path,
    layout: &IndexedLayout,
) -> Option<(GridColumns, &'t str)> {
    let mut rest = text;
    let mut line = 0;
    while !rest.is_empty() {
        line += 1;
        let end = memchr::memchr(b'\n', rest.as_bytes()).map_or(rest.len(), |e| e + 1);
        let (content, after) = rest.split_at(end);
        rest = after;
        let mut fields = Vec::new();
        split_row(content.lines().next().unwrap_or(""), &mut fields);
        if fields.iter().all(|f| f.is_empty()) {
            continue;
        }
        let header = Row {
            line,
            fields: fields.iter().map(|f| (*f).to_owned()).collect(),
        };
        let columns = GridColumns::from_header(&header, path, layout).ok()?;
        return Some((columns, rest));
    }
    None
}

/// The trimmed fields of a plain line, its comment cut, into `fields` (cleared first).
fn split_row<'t>(line: &'t str, fields: &mut Vec<&'t str>) {
    fields.clear();
    fields.extend(strip_comment(line).split(',').map(str::trim));
}

/// Consecutive cells of a grid in row-major order: the first and the last, the row length
/// when a row ended among them, and their points.
struct Run {
    first: (usize, usize),
    last: (usize, usize),
    cols: Option<usize>,
    points: Vec<Point3>,
}

impl Run {
    /// The cells of the lines of `piece`; `None` when a row does not read or a cell does not
    /// follow the one before it.
    fn of(piece: &str, columns: &GridColumns, path: &Path) -> Option<Run> {
        let mut run = Run {
            first: (0, 0),
            last: (0, 0),
            cols: None,
            points: Vec::with_capacity(memchr::memchr_iter(b'\n', piece.as_bytes()).count() + 1),
        };
        let mut fields: Vec<&str> = Vec::new();
        for line in piece.lines() {
            split_row(line, &mut fields);
            if fields.iter().all(|f| f.is_empty()) {
                continue;
            }
            // The line only names errors, and an error sends the text to the general reader.
            let (i, j, point) = columns.read(&fields, 0, path).ok()?;
            if run.points.is_empty() {
                run.first = (i, j);
            } else {
                follow(run.last, (i, j), &mut run.cols)?;
            }
            run.last = (i, j);
            run.points.push(point);
        }
        Some(run)
    }
}

/// Whether cell `next` follows cell `last` in row-major order: the next in the row, or the
/// first of the next row, which makes the row `last.1 + 1` long (recorded in `cols`, and
/// checked against a length already recorded).
/// (Indices at `usize::MAX` have no successor here: the general reader takes them.)
fn follow(last: (usize, usize), next: (usize, usize), cols: &mut Option<usize>) -> Option<()> {
    let length = last.1.checked_add(1)?;
    if next == (last.0, length) {
        return Some(());
    }
    if next != (last.0.checked_add(1)?, 0) {
        return None;
    }
    (*cols.get_or_insert(length) == length).then_some(())
}

/// True when `text` has no double quote (no quoted field) and no carriage return but before a
/// line feed: then its records are its lines split at commas, as `csv` reads them.
fn is_plain(text: &str) -> bool {
    let bytes = text.as_bytes();
    memchr::memchr(b'"', bytes).is_none()
        && memchr::memchr_iter(b'\r', bytes).all(|k| bytes.get(k + 1) == Some(&b'\n'))
}

/// One cell as read: its indices, its line and its point.
#[derive(Clone, Copy, Debug)]
struct Cell {
    i: usize,
    j: usize,
    line: usize,
    point: Point3,
}

/// The rows of a file of indexed points, read one at a time: the header, then the cells in
/// file order. Errors come in file order, as the rows are read: a cell given twice before a
/// row that does not read is reported first.
struct IndexedRows<'a> {
    path: &'a Path,
    layout: &'a IndexedLayout,
    columns: Option<GridColumns>,
    cells: Vec<Cell>,
}

impl<'a> IndexedRows<'a> {
    fn new(path: &'a Path, layout: &'a IndexedLayout) -> Self {
        IndexedRows {
            path,
            layout,
            columns: None,
            cells: Vec::new(),
        }
    }

    /// Reads the row of `fields` (trimmed) on line `line`; rows of empty fields are skipped.
    fn row(&mut self, line: usize, fields: &[&str]) -> Result<(), IoError> {
        if fields.iter().all(|f| f.is_empty()) {
            return Ok(());
        }
        let Some(columns) = &self.columns else {
            let header = Row {
                line,
                fields: fields.iter().map(|f| (*f).to_owned()).collect(),
            };
            self.columns = Some(GridColumns::from_header(&header, self.path, self.layout)?);
            return Ok(());
        };
        match columns.read(fields, line, self.path) {
            Ok((i, j, point)) => {
                self.cells.push(Cell { i, j, line, point });
                Ok(())
            }
            Err(e) => Err(self.first_duplicate().unwrap_or(e)),
        }
    }

    /// The grid of the cells read, or the error of the first cell given twice (in file order)
    /// or of the first missing cell (in row-major order).
    fn finish(self) -> Result<Grid<Point3>, IoError> {
        let none_found = || data_error(self.path, format!("no {} found", self.layout.what));
        if self.columns.is_none() || self.cells.is_empty() {
            return Err(none_found());
        }
        let max_i = self.cells.iter().map(|c| c.i).max().unwrap_or(0);
        let max_j = self.cells.iter().map(|c| c.j).max().unwrap_or(0);
        // Cell counts in u128, so absurd indices cannot overflow (only both at usize::MAX
        // would saturate, and then the count of missing cells is off by one in 2^128).
        let expected = (max_i as u128 + 1).saturating_mul(max_j as u128 + 1);
        if expected != self.cells.len() as u128 {
            if let Some(e) = self.first_duplicate() {
                return Err(e);
            }
            let cells: HashMap<(usize, usize), (usize, Point3)> = self
                .cells
                .iter()
                .map(|c| ((c.i, c.j), (c.line, c.point)))
                .collect();
            let cols = max_j as u128 + 1;
            return Err(first_missing_cell(
                &cells,
                cols,
                expected,
                self.path,
                self.layout,
            ));
        }
        // As many cells as the grid has: each in its place, unless one is given twice.
        let (rows, cols) = (max_i + 1, max_j + 1);
        let mut points = vec![Point::ZERO; self.cells.len()];
        let mut lines = vec![0usize; self.cells.len()];
        for cell in &self.cells {
            let k = cell.i * cols + cell.j;
            if lines[k] != 0 {
                return Err(self.twice(cell, lines[k]));
            }
            lines[k] = cell.line;
            points[k] = cell.point;
        }
        check_coordinate_range(points.iter().flat_map(|p| p.0), self.path)?;
        Grid::from_row_major(rows, cols, points)
            .map_err(|source| IoError::geometry(self.path, source))
    }

    /// The error of the first cell read so far that repeats an earlier one, if any.
    fn first_duplicate(&self) -> Option<IoError> {
        let mut seen: HashMap<(usize, usize), usize> = HashMap::new();
        self.cells.iter().find_map(|cell| {
            let first = *seen.entry((cell.i, cell.j)).or_insert(cell.line);
            (first != cell.line).then(|| self.twice(cell, first))
        })
    }

    /// The error of `cell` given again after line `first_line`.
    fn twice(&self, cell: &Cell, first_line: usize) -> IoError {
        let message = format!("given twice, on lines {first_line} and {}", cell.line);
        (self.layout.cell_error)(self.path, cell.i, cell.j, message)
    }
}

/// The error for the first cell missing in row-major order of a grid with `cols` columns and
/// `expected` cells, of which only `cells.len()` are given.
///
/// Among the first `cells.len() + 1` cells at least one is missing, so the search stops early
/// and never allocates, however large the indices.
fn first_missing_cell(
    cells: &HashMap<(usize, usize), (usize, Point3)>,
    cols: u128,
    expected: u128,
    path: &Path,
    layout: &IndexedLayout,
) -> IoError {
    let first = (0..=cells.len())
        .map(|k| {
            let k = k as u128;
            // Both quotient and remainder are at most k, which is a usize.
            ((k / cols) as usize, (k % cols) as usize)
        })
        .find(|cell| !cells.contains_key(cell))
        .unwrap_or((0, 0));
    let more = expected - cells.len() as u128 - 1;
    let message = match more {
        0 => "missing".to_owned(),
        1 => "missing (and 1 more cell)".to_owned(),
        n => format!("missing (and {n} more cells)"),
    };
    (layout.cell_error)(path, first.0, first.1, message)
}

/// Where the five named columns are in the rows of a grid file (0-based field indices).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct GridColumns {
    /// Field indices of the two indices and `x`, `y`, `z`.
    index: [usize; 5],
    /// The column names, in the same order.
    names: [&'static str; 5],
    /// Number of fields every row has.
    width: usize,
}

impl GridColumns {
    /// Finds the columns in the header row.
    fn from_header(
        header: &Row,
        path: &Path,
        layout: &IndexedLayout,
    ) -> Result<GridColumns, IoError> {
        let index = header_columns(header, path, layout.names, layout.header)?;
        Ok(GridColumns {
            index,
            names: layout.names,
            width: header.fields.len(),
        })
    }

    /// The cell and point of the data row of `fields` (trimmed) on line `line`.
    fn read(
        &self,
        fields: &[&str],
        line: usize,
        path: &Path,
    ) -> Result<(usize, usize, Point3), IoError> {
        let at = Location::new(path, line);
        if fields.len() != self.width {
            return Err(at.error(format!(
                "expected {} fields, found {}",
                self.width,
                fields.len()
            )));
        }
        let field = |k: usize| fields[self.index[k]];
        let grid_index = |k: usize| {
            parse_index(field(k)).ok_or_else(|| {
                at.error(format!(
                    "'{}' is not a non-negative integer (column {}, '{}')",
                    excerpt(field(k)),
                    self.index[k] + 1,
                    self.names[k]
                ))
            })
        };
        // The fast parser agrees with `str::parse` on every finite value (tested in
        // `columns`); anything else goes to the careful one for its message.
        let coordinate = |k: usize| match fast_float2::parse::<f64, _>(field(k).as_bytes()) {
            Ok(v) if v.is_finite() => Ok(v),
            _ => parse_coordinate(field(k), self.index[k] + 1, at),
        };
        Ok((
            grid_index(0)?,
            grid_index(1)?,
            Point([coordinate(2)?, coordinate(3)?, coordinate(4)?]),
        ))
    }
}

/// `field` as a `usize`, as `str::parse` reads it; plain digits (at most 19, which cannot
/// overflow) without its generality.
fn parse_index(field: &str) -> Option<usize> {
    let bytes = field.as_bytes();
    if (1..=19).contains(&bytes.len()) && bytes.iter().all(u8::is_ascii_digit) {
        return Some(
            bytes
                .iter()
                .fold(0usize, |v, &b| v * 10 + usize::from(b - b'0')),
        );
    }
    field.parse().ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn indices_read_as_str_parse_reads_them() {
        for text in [
            "0",
            "7",
            "0042",
            "+5",
            "-1",
            "",
            " 1",
            "1.0",
            "1e3",
            "x",
            "18446744073709551615",
            "18446744073709551616",
            "9999999999999999999",
            "00000000000000000001",
        ] {
            assert_eq!(parse_index(text), text.parse::<usize>().ok(), "{text:?}");
        }
    }

    #[test]
    fn cells_in_order_read_as_the_general_reader_reads_them() {
        let header = "i,j,x,y,z\n";
        let row = |i: usize, j: usize| format!("{i},{j},{}.5,{j},-{i}e-3\n", i + j);
        let ordered = |rows: usize, cols: usize| -> Vec<String> {
            (0..rows)
                .flat_map(|i| (0..cols).map(move |j| row(i, j)))
                .collect()
        };
        let joined = |lines: &[String]| format!("{header}{}", lines.concat());
        let mut texts = Vec::new();
        for (rows, cols) in [(1, 1), (1, 4), (4, 1), (3, 5)] {
            texts.push(joined(&ordered(rows, cols)));
        }
        let full = ordered(3, 4);
        let mut swapped = full.clone();
        swapped.swap(5, 6);
        let mut repeated = full.clone();
        repeated[7] = row(1, 2);
        let mut short = full.clone();
        short.pop();
        let mut bad = full.clone();
        bad[9] = "2,1,x,0,0\n".to_owned();
        let mut extra_row = full.clone();
        extra_row.push(row(3, 0));
        let mut wide = full.clone();
        wide.insert(4, row(0, 4));
        let mut huge = full.clone();
        huge[11] = "2,3,1e308,0,0\n".to_owned();
        for lines in [swapped, repeated, short, bad, extra_row, wide, huge] {
            texts.push(joined(&lines));
        }
        texts.push(format!(
            "# comment\n\n{}",
            joined(&full).replace("1,0,", "\n1,0,")
        ));
        texts.push(header.to_owned());
        // Indices at the end of usize: no successor, so the general reader takes them.
        let max = usize::MAX;
        texts.push(format!("{header}0,0,1,1,1\n0,{max},1,1,1\n0,0,2,2,2\n"));
        texts.push(format!("{header}0,{max},1,1,1\n1,0,1,1,1\n"));
        texts.push(format!("{header}{max},0,1,1,1\n0,0,1,1,1\n"));
        for text in &texts {
            let path = Path::new("g.csv");
            let general = parse_any_order(text, true, path, &GRID).map_err(|e| e.to_string());
            let read = parse_grid(text, path).map_err(|e| e.to_string());
            assert_eq!(read, general, "{text}");
        }
        // Texts long enough to be read in pieces: in order, one pair swapped at each place,
        // a row one cell short, the last row one cell long.
        let big = ordered(400, 300);
        assert!(joined(&big).len() > 2 * PARALLEL_BYTES);
        let mut big_texts = vec![joined(&big)];
        for at in [1, 299, 300, 59_999, 60_000, 119_998] {
            let mut lines = big.clone();
            lines.swap(at, at + 1);
            big_texts.push(joined(&lines));
        }
        let mut lines = big.clone();
        lines.remove(60_299);
        big_texts.push(joined(&lines));
        let mut lines = big.clone();
        lines.push(row(399, 300));
        big_texts.push(joined(&lines));
        for text in &big_texts {
            let path = Path::new("g.csv");
            let general = parse_any_order(text, true, path, &GRID).map_err(|e| e.to_string());
            assert_eq!(parse_grid(text, path).map_err(|e| e.to_string()), general);
        }
        assert!(parse_grid(&big_texts[0], Path::new("g.csv")).is_ok());
        // The ordered ones took the direct path.
        assert!(parse_in_order(&texts[3], Path::new("g.csv"), &GRID).is_some());
        assert!(parse_in_order(&texts[4], Path::new("g.csv"), &GRID).is_none());
    }

    #[test]
    fn missing_count_is_exact_for_huge_indices() {
        let text = "i,j,x,y,z\n0,0,0,0,0\n1000000000000,0,1,1,1\n";
        let e = parse_grid(text, Path::new("g.csv"))
            .unwrap_err()
            .to_string();
        assert_eq!(
            e,
            "g.csv: grid cell (i=1, j=0): missing (and 999999999998 more cells)"
        );
        let text = "i,j,x,y,z\n0,0,0,0,0\n0,1,0,0,0\n1,1,0,0,0\n";
        let e = parse_grid(text, Path::new("g.csv"))
            .unwrap_err()
            .to_string();
        assert_eq!(e, "g.csv: grid cell (i=1, j=0): missing");
    }
}

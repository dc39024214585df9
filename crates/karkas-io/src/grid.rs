//! Surface frames: a grid of spatial points as CSV rows `i,j,x,y,z`.
//!
//! One row per grid cell, indices from 0, rows in any order: a frame is often assembled by a
//! script section by section, and an explicit index is easier to check than an implied layout.
//! The header is required; its columns are found by name (any order, any case) and extra
//! columns are ignored. The result is a [`Grid`] with `max i + 1` rows and `max j + 1` columns,
//! every cell given exactly once. `#` comments and blank lines are skipped as in the other
//! formats; quoted fields are read with the `csv` crate, plain lines split at commas without
//! it (no allocation per field, no map of cells: a million-cell grid reads in a fraction of a
//! second).
//!
//! The same layout with other index names holds the skeleton curves of a tube
//! (the `skeleton` module); the parser here serves both.

use std::collections::HashMap;
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
    let text = strip_bom(text);
    let mut rows = IndexedRows::new(path, layout);
    // At most one cell a line: reserved once (capacity not used is never touched).
    rows.cells
        .reserve(memchr::memchr_iter(b'\n', text.as_bytes()).count() + 1);
    if is_plain(text) {
        let mut fields: Vec<&str> = Vec::new();
        for (k, line) in text.lines().enumerate() {
            fields.clear();
            fields.extend(strip_comment(line).split(',').map(str::trim));
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
            field(k).parse::<usize>().map_err(|_| {
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

#[cfg(test)]
mod tests {
    use super::*;

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

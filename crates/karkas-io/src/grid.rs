//! Surface frames: a grid of spatial points as CSV rows `i,j,x,y,z`.
//!
//! One row per grid cell, indices from 0, rows in any order: a frame is often assembled by a
//! script section by section, and an explicit index is easier to check than an implied layout.
//! The header is required; its columns are found by name (any order, any case) and extra
//! columns are ignored. The result is a [`Grid`] with `max i + 1` rows and `max j + 1` columns,
//! every cell given exactly once. Read with the `csv` crate (`#` comments and blank lines are
//! skipped as in the other formats).
//!
//! The same layout with other index names holds the skeleton curves of a tube
//! (the `skeleton` module); the parser here serves both.

use std::collections::HashMap;
use std::path::Path;

use karkas::{Grid, Point, Point3};

use crate::error::{data_error, IoError};
use crate::input::display_name;
use crate::input::excerpt;
use crate::lines::{
    csv_rows, header_columns, parse_coordinate, read_text, row_location, strip_bom, Row,
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
pub(crate) fn parse_indexed(
    text: &str,
    path: &Path,
    layout: &IndexedLayout,
) -> Result<Grid<Point3>, IoError> {
    let text = strip_bom(text);
    let rows = csv_rows(text, path)?;
    let none_found = || data_error(path, format!("no {} found", layout.what));
    let Some((header, data)) = rows.split_first() else {
        return Err(none_found());
    };
    let columns = GridColumns::from_header(header, path, layout)?;
    if data.is_empty() {
        return Err(none_found());
    }

    // Cell -> (line, point); duplicates are caught here.
    let mut cells: HashMap<(usize, usize), (usize, Point3)> = HashMap::with_capacity(data.len());
    let (mut max_i, mut max_j) = (0, 0);
    for row in data {
        let (i, j, p) = columns.read(row, path)?;
        if let Some(&(first_line, _)) = cells.get(&(i, j)) {
            let message = format!("given twice, on lines {first_line} and {}", row.line);
            return Err((layout.cell_error)(path, i, j, message));
        }
        cells.insert((i, j), (row.line, p));
        max_i = max_i.max(i);
        max_j = max_j.max(j);
    }

    // Cell counts in u128, so absurd indices cannot overflow (only both at usize::MAX would
    // saturate, and then the count of missing cells is off by one in 2^128).
    let expected = (max_i as u128 + 1).saturating_mul(max_j as u128 + 1);
    if expected != cells.len() as u128 {
        return Err(first_missing_cell(
            &cells,
            max_j as u128 + 1,
            expected,
            path,
            layout,
        ));
    }
    let (rows, cols) = (max_i + 1, max_j + 1);
    let mut points = vec![Point::ZERO; cells.len()];
    for ((i, j), (_, p)) in cells {
        points[i * cols + j] = p;
    }
    check_coordinate_range(points.iter().flat_map(|p| p.0), path)?;
    Grid::from_row_major(rows, cols, points).map_err(|source| IoError::geometry(path, source))
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

    /// The cell and point of a data row.
    fn read(&self, row: &Row, path: &Path) -> Result<(usize, usize, Point3), IoError> {
        let at = row_location(row, path, self.width)?;
        let field = |k: usize| row.fields[self.index[k]].as_str();
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
        let coordinate = |k: usize| parse_coordinate(field(k), self.index[k] + 1, at);
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

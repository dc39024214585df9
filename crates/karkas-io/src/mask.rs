//! Cell masks: which cells of a grid are marked (e.g. the entries a surface variation keeps
//! fixed), as CSV.
//!
//! Format: a header line `i,j` (columns found by name, any order, any case; other columns are
//! ignored), then one line per marked cell with its 0-based row `i` and column `j`, as in grid
//! files. Cells not listed are unmarked; a header with no lines marks nothing. `#` comments
//! and blank lines are skipped. A cell outside the grid or listed twice is an error naming
//! the line.

use std::path::Path;

use karkas::Grid;

use crate::error::{data_error, IoError};
use crate::input::display_name;
use crate::input::excerpt;
use crate::lines::{csv_rows, header_columns, read_text, row_location, strip_bom};

/// Reads the mask file at `path` (`-`: standard input) for a `rows x cols` grid: `true` for
/// every listed cell.
pub fn read_cell_mask(path: &Path, rows: usize, cols: usize) -> Result<Grid<bool>, IoError> {
    parse_cell_mask(&read_text(path)?, &display_name(path), rows, cols)
}

/// Reads a cell mask from `text` already in memory; `path` names the file in messages.
pub fn parse_cell_mask(
    text: &str,
    path: &Path,
    rows: usize,
    cols: usize,
) -> Result<Grid<bool>, IoError> {
    let records = csv_rows(&crate::dialect::normalized_csv(strip_bom(text)), path)?;
    let Some((header, data)) = records.split_first() else {
        return Err(data_error(
            path,
            "empty mask file: expected a header line i,j",
        ));
    };
    let [ci, cj] = header_columns(header, path, ["i", "j"], "i,j")?;
    let mut mask = Grid::from_fn(rows, cols, |_, _| false);
    let mut first_line = Grid::from_fn(rows, cols, |_, _| 0usize);
    for row in data {
        let at = row_location(row, path, header.fields.len())?;
        let index = |k: usize, name: &str, limit: usize| {
            let field = &row.fields[k];
            let value: usize = field.parse().map_err(|_| {
                at.error(format!(
                    "'{}' is not a non-negative integer (column {}, '{name}')",
                    excerpt(field),
                    k + 1
                ))
            })?;
            if value >= limit {
                return Err(at.error(format!(
                    "{name} = {value} is outside the grid ({name} < {limit})"
                )));
            }
            Ok(value)
        };
        let (i, j) = (index(ci, "i", rows)?, index(cj, "j", cols)?);
        if *mask.get(i, j) {
            return Err(at.error(format!(
                "cell (i={i}, j={j}) is listed twice (first on line {})",
                first_line.get(i, j)
            )));
        }
        *mask.get_mut(i, j) = true;
        *first_line.get_mut(i, j) = row.line;
    }
    Ok(mask)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cells_are_marked_and_errors_name_the_line() {
        let p = Path::new("m.csv");
        let mask = parse_cell_mask("j,i\n1,0\n# none\n2, 1\n", p, 2, 3).unwrap();
        assert_eq!(mask.as_slice(), &[false, true, false, false, false, true]);
        let none = parse_cell_mask("i,j\n", p, 2, 2).unwrap();
        assert!(none.as_slice().iter().all(|m| !m));
        let e = |text: &str| parse_cell_mask(text, p, 2, 3).unwrap_err().to_string();
        assert_eq!(
            e("i,j\n0,0\n2,0\n"),
            "m.csv:3: i = 2 is outside the grid (i < 2)"
        );
        assert_eq!(
            e("i,j\n0,1\n0,1\n"),
            "m.csv:3: cell (i=0, j=1) is listed twice (first on line 2)"
        );
        assert_eq!(
            e("i,j\n0,-1\n"),
            "m.csv:2: '-1' is not a non-negative integer (column 2, 'j')"
        );
        assert_eq!(
            e("0,1\n"),
            "m.csv:1: missing header: expected the columns i,j"
        );
        assert_eq!(
            e("i,k\n"),
            "m.csv:1: the header has no column 'j' (expected i,j)"
        );
        assert_eq!(e("i,j\n1\n"), "m.csv:2: expected 2 fields, found 1");
        assert_eq!(e(""), "m.csv: empty mask file: expected a header line i,j");
    }
}

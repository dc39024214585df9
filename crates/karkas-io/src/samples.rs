//! Sampled surfaces read back: a CSV `u,v,x,y,z` (as the surface commands write it, `u` outer)
//! into the grid of its samples.
//!
//! The first run of rows with equal `u` is one grid row; every later run must be as long and
//! carry its own `u`. Columns are found by name in the header (any order, any case).

use std::path::Path;

use karkas::{Grid, Point3};

use crate::error::{data_error, IoError, Location};
use crate::input::display_name;
use crate::lines::{csv_rows, parse_coordinate, read_text, strip_bom};

/// Reads a sampled surface CSV file (`-`: standard input; header `u,v,x,y,z`, `u` outer, as
/// the surface commands write it) back into its grid: the rows of one `u` value form one grid
/// row.
pub fn read_surface_samples(path: &Path) -> Result<Grid<Point3>, IoError> {
    parse_surface_samples(&read_text(path)?, &display_name(path))
}

/// Reads a sampled surface from CSV `text` (see [`read_surface_samples`]).
pub fn parse_surface_samples(text: &str, path: &Path) -> Result<Grid<Point3>, IoError> {
    let rows = csv_rows(&crate::dialect::normalized_csv(strip_bom(text)), path)?;
    let Some((header, data)) = rows.split_first() else {
        return Err(data_error(path, "no surface samples found"));
    };
    let names = ["u", "v", "x", "y", "z"];
    let mut columns = [0usize; 5];
    for (c, name) in names.iter().enumerate() {
        columns[c] = header
            .fields
            .iter()
            .position(|f| f.eq_ignore_ascii_case(name))
            .ok_or_else(|| {
                Location::new(path, header.line).error(format!(
                    "the header has no column '{name}' (expected u,v,x,y,z)"
                ))
            })?;
    }
    let mut us = Vec::with_capacity(data.len());
    let mut points = Vec::with_capacity(data.len());
    for row in data {
        let at = Location::new(path, row.line);
        let mut values = [0.0; 5];
        for c in 0..5 {
            let field = row
                .fields
                .get(columns[c])
                .ok_or_else(|| at.error(format!("missing column {}", columns[c] + 1)))?;
            values[c] = parse_coordinate(field, columns[c] + 1, at)?;
        }
        us.push(values[0]);
        points.push(Point3::new([values[2], values[3], values[4]]));
    }
    let Some(&first_u) = us.first() else {
        return Err(data_error(path, "no surface samples found"));
    };
    // The first run of equal u is one grid row; every later row must be as long.
    let nv = us.iter().take_while(|&&u| u == first_u).count();
    let nu = points.len() / nv;
    for (k, row) in data.iter().enumerate() {
        let start = us[k - k % nv];
        let fresh = k % nv == 0 && k > 0 && us[k] == us[k - 1];
        if us[k] != start || fresh || k >= nu * nv {
            return Err(Location::new(path, row.line).error(format!(
                "not a grid of rows of {nv} samples with equal u (u is the outer index)"
            )));
        }
    }
    Grid::from_row_major(nu, nv, points).map_err(|source| IoError::geometry(path, source))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn surface_samples_read_back_into_their_grid() {
        let text = "u,v,x,y,z\n0,0,1,2,3\n0,1,4,5,6\n0,2,7,8,9\n1,0,1,1,1\n1,1,2,2,2\n1,2,3,3,3\n";
        let grid = parse_surface_samples(text, Path::new("s.csv")).unwrap();
        assert_eq!((grid.rows(), grid.cols()), (2, 3));
        assert_eq!(*grid.get(1, 2), Point3::new([3.0, 3.0, 3.0]));
        let ragged = "u,v,x,y,z\n0,0,1,2,3\n0,1,4,5,6\n1,0,1,1,1\n2,1,2,2,2\n";
        let e = parse_surface_samples(ragged, Path::new("s.csv")).unwrap_err();
        assert_eq!(
            e.to_string(),
            "s.csv:5: not a grid of rows of 2 samples with equal u (u is the outer index)"
        );
        let long = "u,v,x,y,z\n0,0,1,2,3\n0,1,4,5,6\n0,2,1,1,1\n1,1,2,2,2\n";
        assert!(parse_surface_samples(long, Path::new("s.csv")).is_err());
        let wrong =
            parse_surface_samples("i,j,x,y,z\n0,0,1,2,3\n", Path::new("g.csv")).unwrap_err();
        assert!(wrong.to_string().contains("no column 'u'"));
    }
}

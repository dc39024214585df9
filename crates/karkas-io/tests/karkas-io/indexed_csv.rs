//! CSV of discrete curves (`j,x,y[,z]`) and of indexed grids (`p,q,x,y,z`, `i,q,x,y,z`, ...):
//! golden text, and a round trip through the skeleton reader.

use std::path::Path;

use karkas::{Grid, Point};
use karkas_io::skeleton::read_along_curves;
use karkas_io::write::{write_discrete_curve_csv, write_indexed_grid_csv};

use crate::util::scratch;

#[test]
fn discrete_curve_csv_is_indexed_from_zero() {
    let (_dir, path) = scratch("c.csv");
    write_discrete_curve_csv(&path, &[Point([0.5, -1.0]), Point([0.1, 2.0])]).unwrap();
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        "j,x,y\n0,0.5,-1\n1,0.1,2\n"
    );
    write_discrete_curve_csv(&path, &[Point([1.0, 2.0, 3.0])]).unwrap();
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        "j,x,y,z\n0,1,2,3\n"
    );
}

#[test]
fn indexed_grid_csv_is_row_major_and_reads_back() {
    let (_dir, path) = scratch("f.csv");
    let grid = Grid::from_fn(2, 3, |i, q| Point([i as f64, q as f64, 1.0 / 3.0]));
    write_indexed_grid_csv(&path, ["p", "q"], &grid).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines[0], "p,q,x,y,z");
    assert_eq!(lines[1], "0,0,0,0,0.3333333333333333");
    assert_eq!(lines[6], "1,2,1,2,0.3333333333333333");
    assert_eq!(lines.len(), 7);
    write_indexed_grid_csv(&path, ["i", "q"], &grid).unwrap();
    assert_eq!(read_along_curves(Path::new(&path)).unwrap(), grid);
}

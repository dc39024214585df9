//! Reading surface frames from grid CSV.

use std::path::Path;

use karkas::{Grid, Point};
use karkas_io::grid::{parse_grid, read_grid};
use karkas_io::IoError;

use crate::util::scratch;

/// A 2 x 3 frame in row-major order, point (i, j) = (i, j, i + 10 j).
const ORDERED: &str = "i,j,x,y,z
0,0,0,0,0
0,1,0,1,10
0,2,0,2,20
1,0,1,0,1
1,1,1,1,11
1,2,1,2,21
";

fn cell_error(text: &str) -> IoError {
    parse_grid(text, Path::new("g.csv")).unwrap_err()
}

#[test]
fn ordered_grid() {
    let g = parse_grid(ORDERED, Path::new("g.csv")).unwrap();
    assert_eq!((g.rows(), g.cols()), (2, 3));
    for i in 0..2 {
        for j in 0..3 {
            let (x, y) = (i as f64, j as f64);
            assert_eq!(*g.get(i, j), Point([x, y, x + 10.0 * y]));
        }
    }
}

#[test]
fn shuffled_rows_and_columns_give_the_same_grid() {
    let ordered = parse_grid(ORDERED, Path::new("g.csv")).unwrap();
    let shuffled = "# a frame\nZ, y, J, extra, x, I
21,2,2,foo,1,1
0,0,0,foo,0,0

11,1,1,foo,1,1
10,1,1,foo,0,0
1,0,0,foo,1,1
20,2,2,foo,0,0
";
    let (_dir, path) = scratch("shuffled.csv");
    std::fs::write(&path, shuffled).unwrap();
    assert_eq!(read_grid(&path).unwrap(), ordered);
}

#[test]
fn missing_cell_is_named() {
    let text = ORDERED.replace("0,2,0,2,20\n", "");
    let e = cell_error(&text);
    assert!(matches!(e, IoError::Cell { i: 0, j: 2, .. }), "{e:?}");
    assert_eq!(e.to_string(), "g.csv: grid cell (i=0, j=2): missing");

    let text = "i,j,x,y,z\n0,0,0,0,0\n2,2,1,1,1\n";
    assert_eq!(
        cell_error(text).to_string(),
        "g.csv: grid cell (i=0, j=1): missing (and 6 more cells)"
    );
}

#[test]
fn absurd_index_is_a_missing_cell_not_an_allocation() {
    let text = "i,j,x,y,z\n0,0,0,0,0\n0,1,0,0,0\n1000000000000,1000000,0,0,0\n";
    let e = cell_error(text);
    assert!(matches!(e, IoError::Cell { i: 0, j: 2, .. }), "{e:?}");
}

#[test]
fn duplicate_cell_names_both_lines() {
    let text = ORDERED.replace("1,2,1,2,21", "0,1,5,5,5");
    assert_eq!(
        cell_error(&text).to_string(),
        "g.csv: grid cell (i=0, j=1): given twice, on lines 3 and 7"
    );
}

#[test]
fn bad_index_names_the_line() {
    for bad in ["-1", "1.5", "one"] {
        let text = ORDERED.replace("1,1,1,1,11", &format!("{bad},1,1,1,11"));
        let e = cell_error(&text);
        assert!(matches!(e, IoError::Parse { line: 6, .. }), "{e:?}");
        assert!(
            e.to_string().contains("is not a non-negative integer"),
            "{e}"
        );
    }
}

#[test]
fn bad_coordinate_names_the_line() {
    let text = ORDERED.replace("1,1,1,1,11", "1,1,1,1,NaN");
    assert_eq!(
        cell_error(&text).to_string(),
        "g.csv:6: non-finite value 'NaN' in column 5"
    );
}

#[test]
fn missing_column_or_header() {
    let text = ORDERED.replace("i,j,x,y,z", "i,j,x,y,w");
    let e = cell_error(&text);
    assert!(matches!(e, IoError::Parse { line: 1, .. }), "{e:?}");
    assert!(e.to_string().contains("no column 'z'"), "{e}");

    let text = ORDERED.replace("i,j,x,y,z\n", "");
    let e = cell_error(&text);
    assert!(matches!(e, IoError::Parse { line: 1, .. }), "{e:?}");
    assert!(e.to_string().contains("missing header"), "{e}");
}

#[test]
fn empty_grid_is_a_data_error() {
    for text in ["", "i,j,x,y,z\n", "# nothing\n"] {
        assert!(matches!(cell_error(text), IoError::Data { .. }));
    }
}

#[test]
fn written_grids_read_back_exactly() {
    let (_dir, path) = scratch("g.csv");
    let grid = Grid::from_fn(2, 3, |i, j| {
        Point([0.1 * i as f64, 1.0 / 3.0 + j as f64, -2e-17])
    });
    karkas_io::write::write_grid_csv(&path, &grid).unwrap();
    assert_eq!(read_grid(&path).unwrap(), grid);
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with("i,j,x,y,z\n0,0,0,0.3333333333333333,-0.00000000000000002\n"));
}

/// Grid text read by hand (plain lines) and with the `csv` crate (a quote anywhere sends the
/// text there): the same grid, the same error.
#[test]
fn plain_and_quoted_readings_agree() {
    let texts = [
        ORDERED.to_owned(),
        // Comments, blank lines, spaces, extra columns, rows shuffled, CRLF.
        "# frame\r\n\r\nI , J,x,y,z,note\r\n1,2,1,2,21,a # c\r\n0,0,0,0,0,\r\n , \r\n0,1,0,1,10,b\r\n0,2,0,2,20,c\r\n1,0,1,0,1,d\r\n1,1,1,1,11,e\r\n".to_owned(),
        // Errors: a bad number, a cell twice before a bad number, a missing cell, a ragged
        // row, a negative index, a non-finite value, no header, no data.
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,x1,0\n".to_owned(),
        "i,j,x,y,z\n0,0,0,0,0\n0,0,1,1,1\n0,1,0,x1,0\n".to_owned(),
        "i,j,x,y,z\n0,0,0,0,0\n1,1,0,0,0\n".to_owned(),
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,0\n".to_owned(),
        "i,j,x,y,z\n0,-1,0,0,0\n".to_owned(),
        "i,j,x,y,z\n0,0,0,inf,0\n".to_owned(),
        "0,0,0,0,0\n".to_owned(),
        "i,j,x,y,z\n# nothing\n".to_owned(),
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,0,0\n0,1,2,2,2\n1,0,0,0,0\n".to_owned(),
    ];
    for text in texts {
        let quoted = format!("{text}\n# \"quoted\"\n");
        let (a, b) = (
            parse_grid(&text, Path::new("g.csv")),
            parse_grid(&quoted, Path::new("g.csv")),
        );
        match (a, b) {
            (Ok(a), Ok(b)) => assert_eq!(a, b, "{text}"),
            (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{text}"),
            (a, b) => panic!("{text}: {a:?} vs {b:?}"),
        }
    }
}

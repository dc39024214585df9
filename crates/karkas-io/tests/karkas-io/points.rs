//! Reading curve points: CSV, whitespace columns, airfoil files, and the error messages.

use std::path::Path;

use karkas::{Point, Point2, Point3};
use karkas_io::airfoil::parse_airfoil;
use karkas_io::points::{
    parse_curve_points, parse_curve_points_with, read_curve_points, CurvePoints, ReadOptions,
};
use karkas_io::IoError;

use crate::util::scratch;

fn planar(text: &str, name: &str) -> Vec<Point2> {
    match parse_curve_points(text, Path::new(name)) {
        Ok(CurvePoints::Planar(p)) => p,
        other => panic!("expected planar points, got {other:?}"),
    }
}

fn spatial(text: &str, name: &str) -> Vec<Point3> {
    match parse_curve_points(text, Path::new(name)) {
        Ok(CurvePoints::Spatial(p)) => p,
        other => panic!("expected spatial points, got {other:?}"),
    }
}

fn error(text: &str, name: &str) -> String {
    match parse_curve_points(text, Path::new(name)) {
        Err(e) => e.to_string(),
        Ok(p) => panic!("expected an error, got {p:?}"),
    }
}

const SQUARE: [Point2; 4] = [
    Point([0.0, 0.0]),
    Point([1.0, 0.0]),
    Point([1.0, 1.0]),
    Point([0.0, 1.0]),
];

#[test]
fn csv_with_and_without_header() {
    assert_eq!(planar("x,y\n0,0\n1,0\n1,1\n0,1\n", "a.csv"), SQUARE);
    assert_eq!(planar("0,0\n1,0\n1,1\n0,1\n", "a.csv"), SQUARE);
    assert_eq!(planar("Y , X\n0,0\n0,1\n1,1\n1,0\n", "a.csv"), SQUARE);
    // CRLF line ends and a byte-order mark, as spreadsheets write them.
    assert_eq!(
        planar("\u{feff}x,y\r\n0,0\r\n1,0\r\n1,1\r\n0,1\r\n", "a.csv"),
        SQUARE
    );
}

#[test]
fn comments_and_blank_lines_are_skipped() {
    let text =
        "# a square\n\nx, y  # header\n0, 0\n\n# the far side\n1, 0\n1, 1   # corner\n   \n0, 1\n";
    assert_eq!(planar(text, "a.csv"), SQUARE);
    let text = "# a square\n\n0 0\n1 0 # corner\n\n1 1\n0 1\n";
    assert_eq!(planar(text, "a.txt"), SQUARE);
}

#[test]
fn spatial_header_is_read_by_name() {
    let text = "t,x,y,z\n0,1,2,3\n0.5,4,5,6\n1,7,8,9\n";
    assert_eq!(
        spatial(text, "c.csv"),
        [
            Point([1.0, 2.0, 3.0]),
            Point([4.0, 5.0, 6.0]),
            Point([7.0, 8.0, 9.0])
        ]
    );
    // Without z the same columns are planar.
    assert_eq!(
        planar("t,x,y\n0,1,2\n1,3,4\n", "c.csv"),
        [Point([1.0, 2.0]), Point([3.0, 4.0])]
    );
}

#[test]
fn whitespace_columns() {
    assert_eq!(planar("0 0\n1\t0\n  1   1\n0 1\n", "a.txt"), SQUARE);
    assert_eq!(
        spatial("1 2 3\n4 5 6\n", "a.xyz"),
        [Point([1.0, 2.0, 3.0]), Point([4.0, 5.0, 6.0])]
    );
    assert_eq!(planar("x y\n0 0\n1 0\n1 1\n0 1\n", "a.txt"), SQUARE);
    // A .dat whose first line is numeric is plain columns.
    assert_eq!(planar("0 0\n1 0\n1 1\n0 1\n", "a.dat"), SQUARE);
}

const SELIG: &str = "\
MADE-UP 9 POINT FOIL
1.0000  0.0000
0.7500  0.0600
0.5000  0.0800
0.2500  0.0700
0.0000  0.0000
0.2500 -0.0400
0.5000 -0.0400
0.7500 -0.0200
1.0000  0.0000
";

const LEDNICER: &str = "\
MADE-UP 9 POINT FOIL
       5.       5.

0.0000  0.0000
0.2500  0.0700
0.5000  0.0800
0.7500  0.0600
1.0000  0.0000

0.0000  0.0000
0.2500 -0.0400
0.5000 -0.0400
0.7500 -0.0200
1.0000  0.0000
";

#[test]
fn selig_and_lednicer_give_the_same_points() {
    let dir = tempfile::tempdir().unwrap();
    let read = |name: &str, text: &str| {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        match read_curve_points(&path).unwrap() {
            CurvePoints::Planar(p) => p,
            other => panic!("expected planar points, got {other:?}"),
        }
    };
    let selig = read("selig.dat", SELIG);
    let lednicer = read("lednicer.dat", LEDNICER);
    assert_eq!(selig.len(), 9);
    assert_eq!(selig, lednicer);
    assert_eq!(selig[0], Point([1.0, 0.0]));
    assert_eq!(selig[1], Point([0.75, 0.06]));
    assert_eq!(selig[4], Point([0.0, 0.0]));
    assert_eq!(selig[8], Point([1.0, 0.0]));

    let foil = parse_airfoil(LEDNICER, Path::new("l.dat")).unwrap();
    assert_eq!(foil.name, "MADE-UP 9 POINT FOIL");
    // Recognised by content, whatever the extension, when there is no comma.
    assert_eq!(planar(SELIG, "foil.txt"), selig);
    // Blank lines between the blocks are not needed: the counts are used.
    let packed: String = LEDNICER
        .lines()
        .filter(|l| !l.trim().is_empty())
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(planar(&packed, "foil.dat"), selig);
}

#[test]
fn airfoil_errors_name_the_line() {
    let text = SELIG.replace("0.5000 -0.0400", "0.5000 x");
    assert_eq!(
        parse_airfoil(&text, Path::new("f.dat"))
            .unwrap_err()
            .to_string(),
        "f.dat:8: 'x' is not a number (column 2)"
    );
    let text = LEDNICER.replace("0.7500 -0.0200\n", "");
    let e = error(&text, "f.dat");
    assert!(e.contains("line 2") && e.contains("only 9 follow"), "{e}");
}

#[test]
fn ragged_row_names_its_line() {
    assert_eq!(
        error("x,y\n0,0\n\n# c\n1,0,5\n1,1\n", "r.csv"),
        "r.csv:5: expected 2 fields, found 3"
    );
    assert_eq!(
        error("0 0 0\n1 0 0\n1 1\n", "r.txt"),
        "r.txt:3: expected 3 fields, found 2"
    );
}

#[test]
fn non_finite_values_are_named() {
    assert_eq!(
        error("0,0\n1,nan\n", "n.csv"),
        "n.csv:2: non-finite value 'nan' in column 2"
    );
    assert_eq!(
        error("x y\n0 0\ninf 1\n", "n.txt"),
        "n.txt:3: non-finite value 'inf' in column 1"
    );
}

#[test]
fn text_in_a_numeric_column() {
    assert_eq!(
        error("x,y\n0,0\nabc,1\n", "t.csv"),
        "t.csv:3: 'abc' is not a number (column 1)"
    );
}

#[test]
fn empty_files_have_no_points() {
    for text in ["", "\n\n", "# only a comment\n", "x,y\n"] {
        let e = parse_curve_points(text, Path::new("e.csv")).unwrap_err();
        assert!(matches!(e, IoError::Data { .. }), "{e:?}");
        assert!(e.to_string().starts_with("e.csv: no points found: "), "{e}");
    }
}

#[test]
fn one_column_is_an_error() {
    assert_eq!(
        error("1\n2\n3\n", "one.txt"),
        "one.txt:1: expected 2 columns (x y) or 3 columns (x y z), found 1: choose them with \
         --columns A,B[,C] (positions counted from 1)"
    );
}

#[test]
fn header_without_x_and_y_is_an_error() {
    // Two or three columns named otherwise are read in order, with a warning.
    let options = ReadOptions::default();
    let read =
        parse_curve_points_with("# c\na,b\n0,0\n1,1\n", Path::new("h.csv"), &options).unwrap();
    assert_eq!(read.points.len(), 2);
    assert!(
        read.warnings[0].contains("read in order as x, y"),
        "{read:?}"
    );
    // More columns, or a header naming y but no x: refused, naming --columns.
    for text in ["# c\na,b,c,d\n0,0,0,0\n", "# c\nt,y\n0,0\n"] {
        let e = parse_curve_points(text, Path::new("h.csv")).unwrap_err();
        assert!(matches!(e, IoError::Parse { line: 2, .. }), "{e:?}");
        let e = e.to_string();
        assert!(
            e.contains("names no 'x' and 'y'") && e.contains("--columns"),
            "{e}"
        );
    }
}

#[test]
fn missing_file_is_an_open_error() {
    let (_dir, path) = scratch("absent.csv");
    let e = read_curve_points(&path).unwrap_err();
    assert!(matches!(e, IoError::Open { .. }), "{e:?}");
    assert!(e.to_string().starts_with("cannot read "), "{e}");
}

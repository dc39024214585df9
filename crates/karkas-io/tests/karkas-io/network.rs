//! Reading curve families of a curve network from CSV `curve,x,y,z`.

use std::path::Path;

use karkas::Point;
use karkas_io::network::{parse_curve_family, read_curve_family};

fn error(text: &str) -> String {
    parse_curve_family(text, Path::new("u.csv"))
        .unwrap_err()
        .to_string()
}

#[test]
fn curves_in_file_order_numbered_by_the_curve_column() {
    let text =
        "# two curves\ncurve,x,y,z\n0,0,0,0\n0,1,0,0.5\n0,2,0,1\n\n1,0,1,0\n1,1,1,1e-1\n1,2,1,0\n";
    let f = parse_curve_family(text, Path::new("u.csv")).unwrap();
    assert_eq!(f.curves.len(), 2);
    assert_eq!(f.first_lines, [3, 7]);
    assert_eq!(
        f.curves[0],
        [
            Point([0.0, 0.0, 0.0]),
            Point([1.0, 0.0, 0.5]),
            Point([2.0, 0.0, 1.0])
        ]
    );
    assert_eq!(f.curves[1][1], Point([1.0, 1.0, 0.1]));
}

#[test]
fn columns_by_name_and_blocks_in_any_order() {
    let text = "Z, x, note, CURVE, y\n5,1,a,1,2\n6,3,b,1,4\n0,0,c,0,0\n1,1,d,0,1\n";
    let f = parse_curve_family(text, Path::new("u.csv")).unwrap();
    assert_eq!(
        f.curves[0],
        [Point([0.0, 0.0, 0.0]), Point([1.0, 1.0, 1.0])]
    );
    assert_eq!(
        f.curves[1],
        [Point([1.0, 2.0, 5.0]), Point([3.0, 4.0, 6.0])]
    );
    assert_eq!(f.first_lines, [4, 2]);
}

#[test]
fn malformed_files_name_the_file_and_line() {
    assert_eq!(
        error("0,1,2,3\n"),
        "u.csv:1: missing header: expected the columns curve,x,y,z"
    );
    assert_eq!(
        error("curve,x,y\n0,1,2\n"),
        "u.csv:1: the header has no column 'z' (expected curve,x,y,z)"
    );
    assert_eq!(
        error("curve,x,y,z\n0,1,2,3\n0,1,nan,3\n"),
        "u.csv:3: non-finite value 'nan' in column 3"
    );
    assert_eq!(
        error("curve,x,y,z\n0,1,2,3\n-1,1,2,3\n"),
        "u.csv:3: '-1' is not a curve number (a non-negative integer, column 1)"
    );
    assert_eq!(
        error("curve,x,y,z\n0,1,2,3\n0,1,2\n"),
        "u.csv:3: expected 4 fields, found 3"
    );
    assert_eq!(
        error("curve,x,y,z\n0,1,2,3\n1,1,2,3\n0,4,5,6\n"),
        "u.csv:4: curve 0 resumes here, but its points began on line 2 and another curve came \
         in between (give each curve's points together)"
    );
    assert_eq!(
        error("curve,x,y,z\n0,1,2,3\n2,1,2,3\n2,4,5,6\n"),
        "u.csv: curve 1 is missing (curves are numbered from 0 without gaps)"
    );
    assert_eq!(
        error("curve,x,y,z\n0,1,2,3\n99999999999999,1,2,3\n"),
        "u.csv:3: curve 99999999999999: curves must be numbered from 0 without gaps, and there \
         are only 2 points"
    );
    assert_eq!(error("curve,x,y,z\n"), "u.csv: no curve points found");
    assert_eq!(error(""), "u.csv: no curve points found");
    assert!(read_curve_family(Path::new("/nonexistent/u.csv"))
        .unwrap_err()
        .to_string()
        .starts_with("cannot read /nonexistent/u.csv"));
}

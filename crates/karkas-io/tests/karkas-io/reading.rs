//! Reading curve files as they are found: airfoils with notes, names with commas, text and
//! domain lines before the data; column files with notes; one pass over large files; hostile
//! bytes refused naming the line.

use std::path::Path;

use karkas::{Point, Point2};
use karkas_io::airfoil::{parse_airfoil, read_airfoil};
use karkas_io::points::CurvePoints;
use karkas_io::points::{
    parse_curve_points, parse_curve_points_with, read_curve_coordinates, read_curve_points,
    ReadOptions,
};

use crate::util::scratch;

/// A made-up five-point contour in Selig order, as `x y` lines.
const PAIRS: &str = "1 0\n0.5 0.05\n0 0\n0.5 -0.05\n1 0\n";

fn contour() -> Vec<Point2> {
    vec![
        Point([1.0, 0.0]),
        Point([0.5, 0.05]),
        Point([0.0, 0.0]),
        Point([0.5, -0.05]),
        Point([1.0, 0.0]),
    ]
}

fn planar(text: &str, name: &str) -> Vec<Point2> {
    match parse_curve_points(text, Path::new(name)) {
        Ok(CurvePoints::Planar(p)) => p,
        other => panic!("expected planar points from {name}, got {other:?}"),
    }
}

fn error(text: &str, name: &str) -> String {
    match parse_curve_points(text, Path::new(name)) {
        Err(e) => e.to_string(),
        Ok(p) => panic!("expected an error, got {p:?}"),
    }
}

#[test]
fn notes_after_the_coordinates_are_ignored() {
    for notes in [
        "\nsource: http://example.org/foils/x.dat\n",
        "Thickness: 7.99%\nCamber: 2%\n",
        "ZZ\n",
        "\n  alpha    CL      CD\n  0.0   0.250  0.0061\n  2.0   0.470  0.0064\n",
        "\n\n# comment\nRe = 100000 Mach = 0\n",
    ] {
        let text = format!("MY FOIL\n{PAIRS}{notes}");
        assert_eq!(planar(&text, "a.dat"), contour(), "{notes:?}");
        assert_eq!(planar(&text, "a.txt"), contour(), "{notes:?}");
    }
}

#[test]
fn the_name_is_the_whole_first_line_whatever_the_extension() {
    let text = format!("NACA 63,3-418 # modified\n{PAIRS}");
    for name in ["f.dat", "f.csv", "f.txt", "f"] {
        assert_eq!(planar(&text, name), contour(), "{name}");
    }
    let foil = parse_airfoil(&text, Path::new("f.csv")).unwrap();
    assert_eq!(foil.name, "NACA 63,3-418 # modified");
    // Comma-separated rows after a first line without x and y: a CSV header, its two
    // columns read in order.
    let read = parse_curve_points_with(
        "NACA 63,3-418\n1,0\n0,0\n1,1\n",
        Path::new("f.csv"),
        &ReadOptions::default(),
    )
    .unwrap();
    let expected = vec![Point([1.0, 0.0]), Point([0.0, 0.0]), Point([1.0, 1.0])];
    assert_eq!(read.points, CurvePoints::Planar(expected));
    assert!(read.warnings[0].contains("'NACA 63,3-418'"), "{read:?}");
}

#[test]
fn text_and_a_domain_line_before_the_data_are_skipped() {
    let text = format!("FOIL\nOrnithopter airfoil\n\n{PAIRS}");
    assert_eq!(planar(&text, "o.dat"), contour());
    let text = format!("FOIL\n -2.0  3.0  -2.5  2.5\n{PAIRS}");
    assert_eq!(planar(&text, "m.dat"), contour());
    let text = format!("FOIL\nfrom a thesis\n-2 3 -2.5 2.5\n{PAIRS}");
    assert_eq!(planar(&text, "m.txt"), contour());
    // Only one domain line: a second line of four numbers is a damaged pair.
    let text = format!("FOIL\n-2 3 -2 2\n-2 3 -2 2\n{PAIRS}");
    assert_eq!(
        error(&text, "m.dat"),
        "m.dat:3: expected 2 fields (x y), found 4"
    );
}

#[test]
fn pairs_may_be_separated_by_blank_lines() {
    let text = "FOIL\n\n1 0\n0.5 0.05\n\n0 0\n\n\n0.5 -0.05\n1 0\n\n";
    assert_eq!(planar(text, "b.dat"), contour());
}

#[test]
fn damaged_pairs_are_refused_naming_the_line() {
    let damaged = |line: &str| format!("FOIL\n1 0\n0.5 0.05\n{line}\n0.5 -0.05\n1 0\n");
    assert_eq!(
        error(&damaged("0.0 ......"), "d.dat"),
        "d.dat:4: '......' is not a number (column 2)"
    );
    assert_eq!(
        error(&damaged("......"), "d.dat"),
        "d.dat:4: expected 2 fields (x y), found 1"
    );
    assert_eq!(
        error(&damaged("0.0 (0.0022)"), "d.dat"),
        "d.dat:4: '(0.0022)' is not a number (column 2)"
    );
    assert_eq!(
        error(&damaged("0.5 abc"), "d.dat"),
        "d.dat:4: 'abc' is not a number (column 2)"
    );
    assert_eq!(
        error(&damaged("abc 0.5"), "d.dat"),
        "d.dat:4: 'abc' is not a number (column 1)"
    );
    assert_eq!(
        error(&damaged("0 0 0"), "d.dat"),
        "d.dat:4: expected 2 fields (x y), found 3"
    );
    assert_eq!(
        error(&damaged("0 nan"), "d.dat"),
        "d.dat:4: non-finite value 'nan' in column 2"
    );
}

#[test]
fn pairs_after_the_notes_are_refused() {
    let text = format!("FOIL\n{PAIRS}\nsource: a book\n0.2 0.1\n");
    assert_eq!(
        error(&text, "n.dat"),
        "n.dat:9: a point after the notes that begin on line 8 ('source: a book'): notes may \
         only follow the coordinates (remove them or start them with '#')"
    );
}

#[test]
fn lednicer_files_with_notes() {
    let text = "LEDNICER FOIL\n3. 3.\n\n0 0\n0.5 0.05\n1 0\n\n0 0\n0.5 -0.05\n1 0\n\nZZ\n";
    let points = planar(text, "l.dat");
    assert_eq!(points.len(), 5);
    assert_eq!(points[0], Point([1.0, 0.0]));
    assert_eq!(points[2], Point([0.0, 0.0]));
    assert_eq!(points[4], Point([1.0, 0.0]));
}

#[test]
fn column_files_end_at_their_notes() {
    let csv = "x,y\n0,0\n1,0\n\n1,1\n0,1\nmeasured by hand on a Tuesday\n";
    assert_eq!(planar(csv, "c.csv").len(), 4);
    let columns = "0 0\n1 0\n\n1 1\n0 1\nsource: http://example.org\nZZ\n";
    assert_eq!(planar(columns, "c.txt").len(), 4);
    assert_eq!(
        error("x,y\n0,0\n1,0\nsee below\n1,1\n", "c.csv"),
        "c.csv:5: a data row after the notes that begin on line 4 ('see below'): notes may only \
         follow the data (remove them or start them with '#')"
    );
    // A row of the data's shape with a number in it is damaged, not a note.
    assert_eq!(
        error("x,y\n0,0\n1,0\nabc,1\n", "c.csv"),
        "c.csv:4: 'abc' is not a number (column 1)"
    );
}

#[test]
fn one_pass_over_a_large_file_gives_both_layouts() {
    let (_dir, path) = scratch("large.csv");
    let mut text = String::from("# made-up helix\nx,y,z\n");
    for k in 0..150_000 {
        let t = f64::from(k) * 1e-3;
        text.push_str(&format!("{},{},{}\n", t.cos(), t.sin(), t * 0.1));
    }
    std::fs::write(&path, &text).unwrap();
    let CurvePoints::Spatial(points) = read_curve_points(&path).unwrap() else {
        panic!("expected spatial points");
    };
    let (flat, dim) = read_curve_coordinates(&path).unwrap();
    assert_eq!((points.len(), dim), (150_000, 3));
    let again: Vec<f64> = points.iter().flat_map(|p| p.0).collect();
    assert_eq!(flat, again);
    assert_eq!(points[149_999][2], 149_999.0 * 1e-3 * 0.1);
    // The airfoil path gives the same flat layout.
    let (_dir2, foil) = scratch("foil.dat");
    std::fs::write(&foil, format!("FOIL\n{PAIRS}ZZ\n")).unwrap();
    let (flat, dim) = read_curve_coordinates(&foil).unwrap();
    assert_eq!(dim, 2);
    assert_eq!(flat, [1.0, 0.0, 0.5, 0.05, 0.0, 0.0, 0.5, -0.05, 1.0, 0.0]);
    assert_eq!(read_airfoil(&foil).unwrap().name, "FOIL");
}

#[test]
fn hostile_bytes_are_refused_with_their_line() {
    let (_dir, path) = scratch("bad.csv");
    let read = |bytes: &[u8]| {
        std::fs::write(&path, bytes).unwrap();
        read_curve_points(&path).unwrap_err().to_string()
    };
    let name = path.display().to_string();
    let e = read(b"x,y\n1,2\n3,4\x005\n");
    assert_eq!(
        e,
        format!("{name}:3: binary data (a NUL byte): expected a text file, one line per record")
    );
    let e = read(b"x,y\n1,2\n3,\xff\xfe\n");
    assert!(e.starts_with(&format!("{name}:3: not UTF-8 text")), "{e}");
    let mut long = b"x,y\n1,2\n".to_vec();
    long.extend(std::iter::repeat_n(b'7', 2 << 20));
    let e = read(&long);
    assert!(
        e.starts_with(&format!("{name}:3: line longer than 1 MiB")),
        "{e}"
    );
    // A field is quoted in at most 100 characters.
    let e = read(format!("x,y\n1,2\n3,{}\n", "a".repeat(5000)).as_bytes());
    assert!(e.starts_with(&format!("{name}:3: 'aaaa")), "{e}");
    assert!(e.len() < name.len() + 160, "{e}");
    let e = read(format!("{},y\n1,2\n", "b".repeat(5000)).as_bytes());
    assert!(
        e.contains("names no 'x' and 'y'") && e.len() < name.len() + 200,
        "{e}"
    );
}

#[test]
fn line_numbers_hold_across_large_blocks() {
    let (_dir, path) = scratch("numbers.txt");
    let mut text = String::from("x y\n");
    for k in 0..300_000 {
        text.push_str(&format!("{k} {}\n", k % 7));
        if k == 200_000 {
            text.push_str("# a comment\n\n");
        }
    }
    // Line 1 is the header, rows start on line 2, two extra lines after row 200 000.
    text.push_str("1 x\n");
    std::fs::write(&path, &text).unwrap();
    let e = read_curve_points(&path).unwrap_err().to_string();
    let name = path.display().to_string();
    assert_eq!(e, format!("{name}:300004: 'x' is not a number (column 2)"));
    // A line longer than 1 MiB among the data, even one of blanks, is refused.
    let long = format!("x y\n0 0\n1{}2\n", " ".repeat(2 << 20));
    std::fs::write(&path, long).unwrap();
    let e = read_curve_points(&path).unwrap_err().to_string();
    assert!(
        e.starts_with(&format!("{name}:3: line longer than 1 MiB")),
        "{e}"
    );
}

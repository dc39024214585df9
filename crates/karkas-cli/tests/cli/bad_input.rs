//! The bad-input table (docs/reference/bad-input.md), one test per row: the command, the input, the exact one-line
//! error (naming the file and line or cell) and exit status 2; an output file that existed
//! before is left byte for byte as it was, and nothing panics. The huge- and tiny-coordinate
//! rows are the cases that work: the methods are linear in the coordinates.

use crate::common::{grid_csv, karkas_in, read_csv, stderr, temp_dir, write};
use std::path::Path;
use std::process::Output;

/// What the output file holds before each refused run.
const EXISTING: &str = "existing output, must survive\n";

/// Runs `karkas args` in a fresh folder holding `files` and an existing `out.csv`.
fn run(files: &[(&str, &str)], args: &[&str]) -> (Output, String, tempfile::TempDir) {
    let dir = temp_dir();
    for (name, text) in files {
        write(dir.path(), name, text);
    }
    write(dir.path(), "out.csv", EXISTING);
    let output = karkas_in(dir.path(), args);
    let stderr = stderr(&output);
    (output, stderr, dir)
}

/// Asserts that `karkas args` on `files` fails with exactly `message` (one line after
/// `karkas: error: `), exit status 2, and `out.csv` untouched.
fn refused(files: &[(&str, &str)], args: &[&str], message: &str) {
    let (output, stderr, dir) = run(files, args);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    assert_eq!(output.status.code(), Some(2), "{stderr}");
    assert_eq!(stderr, format!("karkas: error: {message}\n"));
    let kept = std::fs::read_to_string(dir.path().join("out.csv")).unwrap();
    assert_eq!(kept, EXISTING, "the existing output was changed");
}

/// Asserts that `karkas args` on `files` succeeds and returns the numbers of `out.csv`.
fn works(files: &[(&str, &str)], args: &[&str]) -> Vec<Vec<f64>> {
    let (output, stderr, dir) = run(files, args);
    assert!(!stderr.contains("panicked"), "panic: {stderr}");
    assert_eq!(output.status.code(), Some(0), "{stderr}");
    read_rows(&dir.path().join("out.csv"))
}

/// The data rows of a CSV the CLI wrote, every value finite.
fn read_rows(path: &Path) -> Vec<Vec<f64>> {
    let (_, rows) = read_csv(path);
    assert!(!rows.is_empty());
    assert!(
        rows.iter().flatten().all(|v| v.is_finite()),
        "non-finite output"
    );
    rows
}

/// A grid CSV `i,j,x,y,z` of `f(i, j)`.
fn grid(rows: usize, cols: usize, f: impl Fn(f64, f64) -> [f64; 3]) -> String {
    grid_csv(rows, cols, |i, j| f(i as f64, j as f64))
}

/// A wavy grid: not flat, not on a line.
fn wavy(i: f64, j: f64) -> [f64; 3] {
    [i, j, (i * j * 0.7).sin()]
}

#[test]
fn empty_file() {
    refused(
        &[("pts.csv", "")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv: no points found: the input is empty",
    );
}

#[test]
fn header_only() {
    refused(
        &[("pts.csv", "x,y\n")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv: no points found: the header 'x,y' (line 1) and no data rows after it",
    );
}

#[test]
fn one_point() {
    refused(
        &[("pts.csv", "x,y\n1,2\n")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv: an LL curve needs at least 3 points, got 1",
    );
}

#[test]
fn two_points_for_a_fit() {
    refused(
        &[("pts.csv", "x,y\n1,2\n3,4\n")],
        &[
            "curve",
            "fit",
            "pts.csv",
            "--tolerance",
            "0.1",
            "-o",
            "out.csv",
        ],
        "pts.csv: a fit needs at least 3 points, got 2",
    );
}

#[test]
fn three_points_of_a_closed_fit_one_repeated() {
    // The last point repeats the first and is dropped: the message says so.
    for text in ["x,y\n1,2\n1,2\n1,2\n", "x,y\n1,2\n3,4\n1,2\n"] {
        refused(
            &[("pts.csv", text)],
            &[
                "curve", "fit", "pts.csv", "--closed", "--knots", "5", "-o", "out.csv",
            ],
            "pts.csv: --closed: a closed fit (after dropping its last point, which repeats the \
             first) needs at least 3 points, got 2",
        );
    }
}

#[test]
fn nan_coordinate() {
    refused(
        &[("pts.csv", "x,y\n0,0\n1,nan\n2,0\n")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv:3: non-finite value 'nan' in column 2",
    );
}

#[test]
fn infinite_coordinate_in_a_grid() {
    let text = "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,inf\n1,0,1,0,0\n1,1,1,1,0\n";
    refused(
        &[("g.csv", text)],
        &["surface", "ll", "g.csv", "-o", "out.csv"],
        "g.csv:3: non-finite value 'inf' in column 5",
    );
}

#[test]
fn text_in_a_numeric_column() {
    refused(
        &[("pts.csv", "x,y\n0,0\n1,abc\n2,0\n")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv:3: 'abc' is not a number (column 2)",
    );
}

#[test]
fn text_in_a_grid_index() {
    refused(
        &[("g.csv", "i,j,x,y,z\n0,0,0,0,0\nzero,1,0,1,0\n")],
        &["surface", "ll", "g.csv", "-o", "out.csv"],
        "g.csv:3: 'zero' is not a non-negative integer (column 1, 'i')",
    );
}

#[test]
fn zero_chord_length_in_a_grid() {
    // Rows 1 and 2 repeat each other: chord-length parameters would not increase.
    let text = grid(4, 4, |i, j| {
        let i = if i >= 2.0 { i - 1.0 } else { i };
        wavy(i, j)
    });
    refused(
        &[("g.csv", &text)],
        &["surface", "bicubic", "g.csv", "-o", "out.csv"],
        "g.csv: grid lines i = 1 and i = 2 coincide: the parameters would not increase",
    );
}

#[test]
fn zero_chord_length_along_a_curve_is_fine_for_ll() {
    // LL parameters are uniform, not chordal: a repeated point is a legal polygon vertex.
    let rows = works(
        &[("pts.csv", "x,y\n0,0\n1,1\n1,1\n2,0\n")],
        &["curve", "ll", "--samples", "11", "pts.csv", "-o", "out.csv"],
    );
    assert_eq!(rows.len(), 11);
    assert_eq!((rows[0][1], rows[0][2]), (0.0, 0.0));
    assert!((rows[10][1] - 2.0).abs() < 1e-12 && rows[10][2].abs() < 1e-12);
}

#[test]
fn all_points_identical_curve() {
    refused(
        &[("pts.csv", "x,y\n1,1\n1,1\n1,1\n1,1\n")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv: all 4 points coincide (at 1,1): there is no curve to build",
    );
}

#[test]
fn all_points_identical_fit() {
    refused(
        &[("pts.csv", "x,y\n1,1\n1,1\n1,1\n1,1\n")],
        &[
            "curve",
            "fit",
            "pts.csv",
            "--tolerance",
            "0.1",
            "-o",
            "out.csv",
        ],
        "pts.csv: a fit (distinct points) needs at least 2 points, got 1",
    );
}

#[test]
fn all_grid_points_identical() {
    let text = grid(4, 4, |_, _| [1.0, 2.0, 3.0]);
    refused(
        &[("g.csv", &text)],
        &["surface", "ll", "g.csv", "-o", "out.csv"],
        "g.csv: all 16 grid points coincide (at 1,2,3): there is no surface to build",
    );
}

#[test]
fn collinear_grid_for_a_surface() {
    let text = grid(4, 4, |i, j| [i + 4.0 * j, 2.0 * (i + 4.0 * j), 0.0]);
    refused(
        &[("g.csv", &text)],
        &["surface", "bicubic", "g.csv", "-o", "out.csv"],
        "g.csv: all 16 grid points lie on one straight line: there is no surface to build",
    );
}

#[test]
fn ragged_grid_row() {
    let text = "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1\n1,0,1,0,0\n1,1,1,1,0\n";
    refused(
        &[("g.csv", text)],
        &["surface", "ll", "g.csv", "-o", "out.csv"],
        "g.csv:3: expected 5 fields, found 4",
    );
}

#[test]
fn ragged_curve_row() {
    refused(
        &[("pts.csv", "1 2\n3 4 5\n6 7\n")],
        &["curve", "ll", "pts.csv", "-o", "out.csv"],
        "pts.csv:2: expected 2 fields, found 3",
    );
}

#[test]
fn missing_grid_cell() {
    let text = "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,0,1,0,0\n";
    refused(
        &[("g.csv", text)],
        &["surface", "ll", "g.csv", "-o", "out.csv"],
        "g.csv: grid cell (i=1, j=1): missing",
    );
}

#[test]
fn duplicate_grid_cell() {
    let text = "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,0,1,0,0\n1,1,1,1,0\n0,1,0,1,0\n";
    refused(
        &[("g.csv", text)],
        &["surface", "ll", "g.csv", "-o", "out.csv"],
        "g.csv: grid cell (i=0, j=1): given twice, on lines 3 and 6",
    );
}

/// A zigzag of `n` points scaled by `s`, as CSV.
fn zigzag(n: usize, s: f64) -> String {
    let mut text = String::from("x,y\n");
    for k in 0..n {
        text.push_str(&format!("{:e},{:e}\n", k as f64 * s, (k % 2) as f64 * s));
    }
    text
}

/// The LL curve of the zigzag scaled by `s` is the unit one scaled by `s`.
fn scaled_curve_matches(s: f64) {
    let args = ["curve", "ll", "--samples", "21", "pts.csv", "-o", "out.csv"];
    let unit = works(&[("pts.csv", &zigzag(6, 1.0))], &args);
    let scaled = works(&[("pts.csv", &zigzag(6, s))], &args);
    for (a, b) in unit.iter().zip(&scaled) {
        assert_eq!(a[0], b[0]);
        for k in 1..3 {
            assert!((b[k] / s - a[k]).abs() <= 1e-12, "{} vs {}", b[k] / s, a[k]);
        }
    }
}

#[test]
fn huge_coordinates_work() {
    scaled_curve_matches(1e150);
}

#[test]
fn tiny_coordinates_work() {
    scaled_curve_matches(1e-150);
}

#[test]
fn huge_and_tiny_grids_work() {
    for s in [1e150, 1e-150] {
        let text = grid(4, 5, |i, j| {
            let p = wavy(i, j);
            [p[0] * s, p[1] * s, p[2] * s]
        });
        for method in ["ll", "bicubic"] {
            let rows = works(
                &[("g.csv", &text)],
                &[
                    "surface",
                    method,
                    "--samples",
                    "5,5",
                    "g.csv",
                    "-o",
                    "out.csv",
                ],
            );
            // The corner sample is the corner grid point (0, 0, 0) for both methods.
            assert_eq!(rows.len(), 25);
            assert!(rows[0][2..].iter().all(|v| v.abs() <= 1e-12 * s));
            let far = rows[24][2] / s;
            assert!((far - 3.0).abs() < 1e-9, "{method} at scale {s}: {far}");
        }
    }
}

#[test]
fn knots_out_of_order() {
    refused(
        &[("pts.csv", &zigzag(8, 1.0))],
        &["curve", "fit", "pts.csv", "--knots", "0,0.6,0.4,1", "-o", "out.csv"],
        "--knots: knot 2 (0.4) is invalid: not greater than the knot before it (knots must increase)",
    );
}

#[test]
fn knots_too_close() {
    refused(
        &[("pts.csv", &zigzag(8, 1.0))],
        &[
            "curve",
            "fit",
            "pts.csv",
            "--knots",
            "0,0.5,0.5000001,1",
            "-o",
            "out.csv",
        ],
        "--knots: knot 2 (0.5000001) is invalid: closer than 1e-6 to the knot before it",
    );
}

#[test]
fn one_point_for_a_discrete_spline() {
    refused(
        &[("pts.csv", "x,y\n1,2\n")],
        &[
            "curve", "dps", "--order", "2", "--n", "4", "pts.csv", "-o", "out.csv",
        ],
        "pts.csv: a discrete periodic spline needs at least 2 points, got 1",
    );
}

#[test]
fn n_one_for_a_discrete_spline() {
    refused(
        &[("pts.csv", &zigzag(4, 1.0))],
        &[
            "curve", "dps", "--order", "2", "--n", "1", "pts.csv", "-o", "out.csv",
        ],
        "--n: the number of values per point must be at least 2, got 1",
    );
}

#[test]
fn incompatible_curve_network() {
    let u = "curve,x,y,z\n0,0,0,0\n0,1,0,0\n0,2,0,0\n1,0,2,0\n1,1,2,0\n1,2,2,0\n";
    // The second v-curve runs at x = 5, beyond the end of the u-curves.
    let v = "curve,x,y,z\n0,0,0,0\n0,0,1,0\n0,0,2,0\n1,5,0,0\n1,5,1,0\n1,5,2,0\n";
    refused(
        &[("U.csv", u), ("V.csv", v)],
        &[
            "surface",
            "coons",
            "--kind",
            "bilinear",
            "--u-curves",
            "U.csv",
            "--v-curves",
            "V.csv",
            "-o",
            "out.csv",
        ],
        "V.csv:5 (v-curve 1) and U.csv:2 (u-curve 0): no common point: every crossing must be \
         a point of both curves (to within 5.385e-6)",
    );
}

#[test]
fn expression_that_does_not_parse() {
    refused(
        &[],
        &[
            "surface", "implicit", "--expr", "x^2+*y", "--start", "1,0,0", "--nodes", "3,3",
            "--step", "0.1", "-o", "out.csv",
        ],
        "--expr: expression: expected a number, a variable, a function or '(', found '*' (at \
         character 5)",
    );
}

#[test]
fn no_surface_near_the_start() {
    refused(
        &[],
        &[
            "surface",
            "implicit",
            "--expr",
            "x^2+y^2+z^2-1",
            "--start",
            "5,5,5",
            "--nodes",
            "3,3",
            "--step",
            "0.1",
            "-o",
            "out.csv",
        ],
        "--start: no surface F = 0 near (5, 5, 5) (|F| = 7.400e1 there)",
    );
}

#[test]
fn output_beyond_the_memory_cap() {
    refused(
        &[("pts.csv", &zigzag(6, 1.0))],
        &[
            "--max-memory",
            "1M",
            "curve",
            "ll",
            "--samples",
            "100000",
            "pts.csv",
            "-o",
            "out.csv",
        ],
        "curve ll: 100000 samples would need 2.3 MiB of memory, above the cap of 1.0 MiB \
         (raise it with --max-memory or KARKAS_MAX_MEMORY, or ask for fewer samples)",
    );
}

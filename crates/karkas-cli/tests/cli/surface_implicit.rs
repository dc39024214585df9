//! The CLI contract of `karkas surface implicit` (grid CSV out, expression errors naming the
//! character, no surface near the start).

use crate::common::{karkas, read_csv, s, stderr, temp_dir};
use std::path::Path;

/// The rows `i,j,x,y,z` of a grid file.
fn read_grid(path: &Path) -> Vec<[f64; 5]> {
    let (header, rows) = read_csv(path);
    assert_eq!(header.join(","), "i,j,x,y,z");
    rows.iter()
        .map(|v| [v[0], v[1], v[2], v[3], v[4]])
        .collect()
}

#[test]
fn cylinder_lines_of_curvature_feed_the_bicubic_command() {
    let dir = temp_dir();
    let grid = dir.path().join("g.csv");
    let o = karkas(&[
        "surface",
        "implicit",
        "--expr",
        "x^2 + y^2 - 1",
        "--start",
        "1,0,0",
        "--nodes",
        "5,9",
        "--step",
        "0.5,0.7853981633974483",
        "-o",
        s(&grid),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = read_grid(&grid);
    assert_eq!(rows.len(), 45);
    for r in &rows {
        let (i, j) = (r[0], r[1]);
        let a = std::f64::consts::TAU * j / 8.0;
        let expected = [a.cos(), a.sin(), 0.5 * i];
        for c in 0..3 {
            assert!(
                (r[2 + c] - expected[c]).abs() < 1e-7,
                "node ({i}, {j}): {r:?}"
            );
        }
    }
    let surface = dir.path().join("s.csv");
    let o = karkas(&["surface", "bicubic", s(&grid), "-o", s(&surface)]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn turned_and_closed_nets() {
    let dir = temp_dir();
    let grid = dir.path().join("g.csv");
    let o = karkas(&[
        "surface",
        "implicit",
        "--expr",
        "x^2+y^2-z^2-1",
        "--start",
        "1.2,0,-0.6",
        "--nodes",
        "3,7",
        "--step",
        "0.3,0.5",
        "--closed-v",
        "-o",
        s(&grid),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = read_grid(&grid);
    for i in 0..3 {
        assert_eq!(rows[7 * i][2..], rows[7 * i + 6][2..], "row {i} closes");
    }
    // The start (1.2, 0, -0.6) is projected onto the hyperboloid first.
    let p = rows[0];
    assert!((p[2] * p[2] + p[3] * p[3] - p[4] * p[4] - 1.0).abs() < 1e-12);
    let o = karkas(&[
        "surface",
        "implicit",
        "--expr",
        "x^2+y^2-1",
        "--start",
        "1,0,0",
        "--nodes",
        "3,3",
        "--step",
        "0.4",
        "--turn",
        "30",
        "-o",
        s(&grid),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = read_grid(&grid);
    // Turned lines are helices: the first v line climbs (z grows) as it goes round.
    assert!(rows[1][4] > 0.1 && rows[2][4] > rows[1][4]);
    for r in &rows {
        assert!((r[2] * r[2] + r[3] * r[3] - 1.0).abs() < 1e-12);
    }
}

#[test]
fn expression_errors_name_the_character() {
    let dir = temp_dir();
    let grid = dir.path().join("g.csv");
    for (expr, at) in [
        ("x^2+*y", "character 5"),
        ("x^2 + w^2", "character 7"),
        ("sin(x", "character 4"),
    ] {
        let o = karkas(&[
            "surface",
            "implicit",
            "--expr",
            expr,
            "--start",
            "1,0,0",
            "--nodes",
            "5,9",
            "--step",
            "0.5",
            "-o",
            s(&grid),
        ]);
        assert_eq!(o.status.code(), Some(2));
        let err = stderr(&o);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("--expr") && err.contains(at), "{expr}: {err}");
    }
    assert!(!grid.exists());
}

#[test]
fn no_surface_near_the_start_is_a_clear_error() {
    let dir = temp_dir();
    let grid = dir.path().join("g.csv");
    for (expr, start) in [("x^2+y^2+z^2+1", "1,0,0"), ("x^2+y^2-1", "5,5,0")] {
        let o = karkas(&[
            "surface",
            "implicit",
            "--expr",
            expr,
            "--start",
            start,
            "--nodes",
            "5,9",
            "--step",
            "0.5",
            "-o",
            s(&grid),
        ]);
        assert_eq!(o.status.code(), Some(2));
        let err = stderr(&o);
        assert!(err.contains("--start: no surface F = 0 near"), "{err}");
    }
    let o = karkas(&[
        "surface",
        "implicit",
        "--expr",
        "x^2+y^2-1",
        "--start",
        "1,0",
        "--nodes",
        "5,9",
        "--step",
        "0.5",
        "-o",
        s(&grid),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!grid.exists());
}

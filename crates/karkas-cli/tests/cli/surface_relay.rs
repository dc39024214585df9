//! The CLI contract of `karkas surface relay` (a grid re-laid along lines of curvature; the
//! umbilic refusal and its fallback; bad input exits 2).

use crate::common::{karkas, read_csv, s, stderr, temp_dir};
use std::f64::consts::{PI, TAU};
use std::path::Path;

/// The rows `i,j,x,y,z` of a grid file.
fn read_grid(path: &Path) -> Vec<[f64; 5]> {
    let (header, rows) = read_csv(path);
    assert_eq!(header.join(","), "i,j,x,y,z");
    rows.iter()
        .map(|v| [v[0], v[1], v[2], v[3], v[4]])
        .collect()
}

/// Writes a grid file `i,j,x,y,z` of `f(i, j)`.
fn write_grid(path: &Path, rows: usize, cols: usize, f: impl Fn(usize, usize) -> [f64; 3]) {
    let mut text = String::from("i,j,x,y,z\n");
    for i in 0..rows {
        for j in 0..cols {
            let p = f(i, j);
            text.push_str(&format!("{i},{j},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    std::fs::write(path, text).unwrap();
}

#[test]
fn a_turned_hyperboloid_frame_is_relaid_along_meridians_and_circles() {
    let dir = temp_dir();
    let (turned, relaid) = (dir.path().join("t.csv"), dir.path().join("r.csv"));
    let o = karkas(&[
        "surface",
        "implicit",
        "--expr",
        "x^2 + y^2 - z^2 - 1",
        "--start",
        "1.118033988749895,0,-0.5",
        "--nodes",
        "5,9",
        "--step",
        "0.2714,0.7853981633974483",
        "--turn",
        "30",
        "-o",
        s(&turned),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let o = karkas(&["surface", "relay", s(&turned), "-o", s(&relaid)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = read_grid(&relaid);
    assert_eq!(rows.len(), 45);
    // One family of lines keeps its height (circles), the other its angle (meridians).
    let node = |i: usize, j: usize| rows[i * 9 + j];
    let spread = |line: &dyn Fn(usize) -> [f64; 5], count: usize, f: &dyn Fn([f64; 5]) -> f64| {
        let values: Vec<f64> = (0..count).map(|k| f(line(k))).collect();
        let lo = values.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = values.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        hi - lo
    };
    let height = |r: [f64; 5]| r[4];
    let angle = |r: [f64; 5]| {
        let a = r[3].atan2(r[2]);
        a - TAU * ((a + PI) / TAU).floor()
    };
    let (mut rows_h, mut cols_a, mut rows_a, mut cols_h) = (0.0f64, 0.0f64, 0.0f64, 0.0f64);
    for i in 0..5 {
        rows_h = rows_h.max(spread(&|j| node(i, j), 9, &height));
        rows_a = rows_a.max(spread(&|j| node(i, j), 9, &angle));
    }
    for j in 0..9 {
        cols_a = cols_a.max(spread(&|i| node(i, j), 5, &angle));
        cols_h = cols_h.max(spread(&|i| node(i, j), 5, &height));
    }
    let principal = (rows_h < 2.5e-2 && cols_a < 2.5e-2) || (cols_h < 2.5e-2 && rows_a < 2.5e-2);
    assert!(principal, "{rows_h} {cols_a} / {cols_h} {rows_a}");
    // --size and --start are honoured.
    let o = karkas(&[
        "surface",
        "relay",
        s(&turned),
        "-o",
        s(&relaid),
        "--size",
        "7,5",
        "--start",
        "1,3",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(read_grid(&relaid).len(), 35);
}

#[test]
fn a_plane_is_refused_as_umbilic_or_kept_with_a_warning() {
    let dir = temp_dir();
    let (plane, out) = (dir.path().join("p.csv"), dir.path().join("o.csv"));
    write_grid(&plane, 5, 6, |i, j| {
        let (x, y) = (0.3 * i as f64, 0.2 * j as f64);
        [x, y, 1.0 + 0.5 * x - 0.25 * y]
    });
    let o = karkas(&["surface", "relay", s(&plane), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("umbilic"), "{}", stderr(&o));
    assert!(!out.exists());
    let o = karkas(&[
        "surface",
        "relay",
        s(&plane),
        "-o",
        s(&out),
        "--umbilic",
        "keep",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(stderr(&o).contains("warning"), "{}", stderr(&o));
    assert_eq!(read_grid(&out), read_grid(&plane));
}

#[test]
fn bad_input_exits_2() {
    let dir = temp_dir();
    let (grid, out) = (dir.path().join("g.csv"), dir.path().join("o.csv"));
    write_grid(&grid, 5, 9, |i, j| {
        let a = TAU * j as f64 / 8.0;
        [a.cos(), a.sin(), 0.5 * i as f64]
    });
    let missing = dir.path().join("missing.csv");
    for args in [
        vec!["surface", "relay", s(&missing), "-o", s(&out)],
        vec![
            "surface",
            "relay",
            s(&grid),
            "-o",
            s(&out),
            "--start",
            "5,0",
        ],
        vec!["surface", "relay", s(&grid), "-o", s(&out), "--size", "1,9"],
        vec!["surface", "relay", s(&grid), "-o", s(&out), "--step", "-1"],
        vec!["surface", "relay", s(&grid), "-o", s(&out), "--step", "9,9"],
        vec!["surface", "relay", s(&grid), "-o", "out.svg"],
    ] {
        let o = karkas(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
    }
    assert!(!out.exists());
}

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

/// Runs `surface implicit` on the unit cylinder from (1, 0, 0) with `extra` options.
fn cylinder_net(dir: &Path, extra: &[&str]) -> std::process::Output {
    let grid = dir.join("g.csv");
    let mut args = vec![
        "surface",
        "implicit",
        "--expr",
        "x^2+y^2-1",
        "--start",
        "1,0,0",
        "-o",
        s(&grid),
    ];
    args.extend_from_slice(extra);
    karkas(&args)
}

/// `--turn-u` turns the generators only (the spine is the helix at the angle to them, the rows
/// stay circles); `--turn-v` turns the circles only (the spine is a generator, the rows are
/// helices at the angle to the circles). Closed forms on the unit cylinder.
#[test]
fn one_family_turned_nets() {
    let dir = temp_dir();
    let grid = dir.path().join("g.csv");
    let (sin30, cos30) = 30f64.to_radians().sin_cos();
    let eighth = std::f64::consts::TAU / 8.0;
    let o = cylinder_net(
        dir.path(),
        &[
            "--nodes",
            "3,9",
            "--step",
            "0.5",
            "--closed-v",
            "--turn-u",
            "30",
        ],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = read_grid(&grid);
    assert_eq!(rows.len(), 27);
    for r in &rows {
        let (i, j) = (r[0], r[1]);
        // The spine node i is 0.5 i along the helix: height 0.5 i cos 30, turned 0.5 i sin 30.
        assert!((r[4].abs() - 0.5 * i * cos30).abs() < 1e-7, "{r:?}");
        let start = rows[(9.0 * i) as usize];
        assert!(
            (start[3].atan2(start[2]).abs() - 0.5 * i * sin30).abs() < 1e-7,
            "{start:?}"
        );
        // Row i: the circle through it, 9 nodes a turn, 8 steps of 45 degrees.
        let turned = (r[2] * start[2] + r[3] * start[3]).clamp(-1.0, 1.0).acos();
        let expected = (eighth * j).min(std::f64::consts::TAU - eighth * j);
        assert!((turned - expected).abs() < 1e-6, "{r:?}");
    }
    let o = cylinder_net(
        dir.path(),
        &["--nodes", "3,5", "--step", "0.5", "--turn-v", "30"],
    );
    assert!(o.status.success(), "{}", stderr(&o));
    let rows = read_grid(&grid);
    for r in &rows {
        let (i, j) = (r[0], r[1]);
        let start = rows[(5.0 * i) as usize];
        // The spine is the generator through (1, 0, 0): nodes 0.5 apart.
        assert!(
            start[2] == 1.0 || (start[2] - 1.0).abs() < 1e-9,
            "{start:?}"
        );
        assert!((start[4].abs() - 0.5 * i).abs() < 1e-7, "{start:?}");
        // Row i: the helix at 30 degrees to the circle, 0.5 j along it.
        let turned = r[3].atan2(r[2]) - start[3].atan2(start[2]);
        assert!((turned.abs() - 0.5 * j * cos30).abs() < 1e-7, "{r:?}");
        assert!(
            ((r[4] - start[4]).abs() - 0.5 * j * sin30).abs() < 1e-7,
            "{r:?}"
        );
    }
    // One turn at a time.
    let o = cylinder_net(
        dir.path(),
        &[
            "--nodes", "3,5", "--step", "0.5", "--turn", "10", "--turn-u", "30",
        ],
    );
    assert_eq!(o.status.code(), Some(2));
    let o = cylinder_net(
        dir.path(),
        &[
            "--nodes", "3,5", "--step", "0.5", "--turn-u", "10", "--turn-v", "30",
        ],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--turn-v") || stderr(&o).contains("--turn-u"));
}

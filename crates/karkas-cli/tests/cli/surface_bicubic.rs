//! The CLI contract of `karkas surface bicubic` (options, CSV header, parameters, exit code 2
//! and no output on bad input).

use crate::common::{grid_csv, karkas, read_csv, s, stderr, temp_dir, write};

/// A 4 x 5 grid whose rows are 1, 3, 2 apart (x) and columns 1 apart (y), with a bump in z.
fn grid_text() -> String {
    let xs = [0.0, 1.0, 4.0, 6.0];
    grid_csv(4, 5, |i, j| [xs[i], j as f64, 0.1 * (i * j) as f64])
}

#[test]
fn uniform_parameters_reproduce_every_node() {
    let dir = temp_dir();
    let input = write(dir.path(), "g.csv", &grid_text());
    let out = dir.path().join("s.csv");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--param",
        "uniform",
        "--samples",
        "4,5",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["u", "v", "x", "y", "z"]);
    assert_eq!(rows.len(), 20);
    let xs = [0.0, 1.0, 4.0, 6.0];
    for (k, row) in rows.iter().enumerate() {
        let (i, j) = (k / 5, k % 5);
        assert_eq!((row[0], row[1]), (i as f64, j as f64));
        let expected = [xs[i], j as f64, 0.1 * (i * j) as f64];
        for c in 0..3 {
            assert!(
                (row[2 + c] - expected[c]).abs() < 1e-12,
                "node ({i}, {j}): {row:?}"
            );
        }
    }
}

#[test]
fn chord_parameters_are_the_default_and_averaged_ones_differ() {
    let dir = temp_dir();
    let input = write(dir.path(), "g.csv", &grid_text());
    let out = dir.path().join("s.csv");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--samples",
        "3,2",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    // Chords along the column j = 0 (z = 0): 1 + 3 + 2 = 6; along the row i = 0: 4.
    assert_eq!(rows.last().unwrap()[..2], [6.0, 4.0]);
    let o = karkas(&[
        "surface",
        "bicubic",
        "--param",
        "averaged",
        "--samples",
        "3,2",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    assert!(
        rows.last().unwrap()[1] > 4.0,
        "averaged v chords include the tilted rows"
    );
}

#[test]
fn closed_direction_and_obj_output() {
    let dir = temp_dir();
    let mut text = String::from("i,j,x,y,z\n");
    for i in 0..3 {
        for j in 0..6 {
            let a = std::f64::consts::TAU * j as f64 / 6.0;
            text.push_str(&format!("{i},{j},{},{},{i}\n", a.cos(), a.sin()));
        }
    }
    let input = write(dir.path(), "ring.csv", &text);
    let out = dir.path().join("ring-out.csv");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--closed-v",
        "--samples",
        "3,13",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    for i in 0..3 {
        let (first, last) = (&rows[13 * i], &rows[13 * i + 12]);
        for c in 2..5 {
            assert!((first[c] - last[c]).abs() < 1e-12, "the seam is closed");
        }
    }
    let mesh = dir.path().join("ring.obj");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--closed-v",
        s(&input),
        "-o",
        s(&mesh),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let obj = std::fs::read_to_string(&mesh).unwrap();
    assert!(obj.lines().any(|l| l.starts_with("v ")) && obj.lines().any(|l| l.starts_with("f ")));
}

#[test]
fn bad_input_exits_2_with_one_line_and_no_output() {
    let dir = temp_dir();
    let out = dir.path().join("s.csv");
    let missing = write(
        dir.path(),
        "m.csv",
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,1,1,1,0\n",
    );
    let o = karkas(&["surface", "bicubic", s(&missing), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("m.csv") && err.contains("(i=1, j=0)"), "{err}");
    let twice = write(
        dir.path(),
        "t.csv",
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n0,2,1,2,0\n1,0,0,0,0\n1,1,0,1,0\n1,2,1,2,0\n",
    );
    let o = karkas(&["surface", "bicubic", s(&twice), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(
        stderr(&o).contains("t.csv") && stderr(&o).contains("coincide"),
        "{}",
        stderr(&o)
    );
    let good = write(dir.path(), "g.csv", &grid_text());
    let o = karkas(&[
        "surface",
        "bicubic",
        "--param",
        "arc",
        s(&good),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!out.exists());
}

/// `--parameterization` is `--param` by Python's name, and `averaged-chord` (Python's
/// spelling) is `averaged`.
#[test]
fn python_spellings_of_the_parameterization() {
    let dir = temp_dir();
    let input = write(dir.path(), "g.csv", &grid_text());
    let (a, b) = (dir.path().join("a.csv"), dir.path().join("b.csv"));
    let run = |option: &str, value: &str, out: &std::path::Path| {
        karkas(&["surface", "bicubic", option, value, s(&input), "-o", s(out)])
    };
    assert!(run("--param", "averaged", &a).status.success());
    let o = run("--parameterization", "averaged-chord", &b);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        std::fs::read_to_string(&a).unwrap(),
        std::fs::read_to_string(&b).unwrap()
    );
}

/// The number after `key ` in the `--report` line of `err`.
fn reported(err: &str, key: &str) -> f64 {
    reported_on(err, "condition measure", key)
}

/// The number after `key ` in the line of `err` that contains `line_key`.
fn reported_on(err: &str, line_key: &str, key: &str) -> f64 {
    let line = err
        .lines()
        .find(|l| l.contains(line_key))
        .unwrap_or_else(|| panic!("no report in {err}"));
    let rest = line.split(&format!("{key} ")).nth(1).unwrap();
    rest.split([' ', ',']).next().unwrap().parse().unwrap()
}

/// `--report`: the condition measure (2.4) of the parameters on stderr; the closed forms of a
/// grid of unit steps along orthogonal lines (1) and along lines at 60 degrees (tan 30).
#[test]
fn report_gives_the_condition_measure_of_the_parameters() {
    let dir = temp_dir();
    let out = dir.path().join("s.csv");
    let steps = [0.0, 0.5, 1.5, 2.0];
    for (deg, expected) in [(90.0f64, 1.0), (60.0, 30f64.to_radians().tan())] {
        let (c, s_) = (deg.to_radians().cos(), deg.to_radians().sin());
        let text = grid_csv(4, 5, |i, j| {
            let y = 0.7 * j as f64;
            [steps[i] + c * y, s_ * y, 1.0]
        });
        let input = write(dir.path(), "g.csv", &text);
        let o = karkas(&["surface", "bicubic", "--report", s(&input), "-o", s(&out)]);
        assert!(o.status.success(), "{}", stderr(&o));
        let err = stderr(&o);
        assert!((reported(&err, "min") - expected).abs() < 2e-6, "{err}");
        assert!((reported(&err, "mean") - expected).abs() < 2e-6, "{err}");
        assert!(err.contains("over 20 nodes"), "{err}");
        // The paper's |D| (2.4): the sine of the angle between the lines, 1 and sin 60.
        let paper = reported_on(&err, "the paper's |D|", "min");
        assert!((paper - deg.to_radians().sin()).abs() < 2e-6, "{err}");
    }
    // Uniform parameters on rows 2 apart: the u tangents are stretched to 2, measure 1/2; the
    // worst node is named.
    let text = grid_csv(3, 3, |i, j| [2.0 * i as f64, j as f64, 0.0]);
    let input = write(dir.path(), "u.csv", &text);
    let o = karkas(&[
        "surface",
        "bicubic",
        "--param",
        "uniform",
        "--report",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    assert!((reported(&err, "min") - 0.5).abs() < 2e-6, "{err}");
    assert!(err.contains("at node (i="), "{err}");
    // The paper's |D| does not see the stretch: the lines stay orthogonal.
    assert!(
        (reported_on(&err, "the paper's |D|", "min") - 1.0).abs() < 2e-6,
        "{err}"
    );
    // Without --report nothing is said about it.
    let o = karkas(&["surface", "bicubic", s(&input), "-o", s(&out)]);
    assert!(!stderr(&o).contains("condition measure"));
    // The sine of an angle does not depend on the grid's scale: lines at 60 degrees scaled by
    // 1e+-150 still give sin 60 with uniform parameters (E G would overflow or underflow).
    for scale in [1e-150, 1e150] {
        let (c, s_) = (60f64.to_radians().cos(), 60f64.to_radians().sin());
        let text = grid_csv(4, 5, |i, j| {
            let y = 0.7 * j as f64;
            [scale * (i as f64 + c * y), scale * s_ * y, scale]
        });
        let input = write(dir.path(), "scaled.csv", &text);
        let o = karkas(&[
            "surface",
            "bicubic",
            "--param",
            "uniform",
            "--report",
            s(&input),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let err = stderr(&o);
        let paper = reported_on(&err, "the paper's |D|", "min");
        assert!((paper - s_).abs() < 2e-6, "scale {scale}: {err}");
    }
}

/// `--origin I,J`: the paper's origin node (i*, j*) of the chord parameters. On the grid of
/// [`grid_text`] with the origin (2, 1), `u` is the chord length along column 1 (points
/// `(x_i, 1, 0.1 i)`) and `v` along row 2 (points `(4, j, 0.2 j)`), both zero at the node.
#[test]
fn origin_moves_the_zero_of_the_chord_parameters() {
    let dir = temp_dir();
    let input = write(dir.path(), "g.csv", &grid_text());
    let out = dir.path().join("s.csv");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--origin",
        "2,1",
        "--samples",
        "2,2",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    let xs: [f64; 4] = [0.0, 1.0, 4.0, 6.0];
    let chord = |i: usize| ((xs[i + 1] - xs[i]).powi(2) + 0.01f64).sqrt();
    let (u0, u3) = (-(chord(0) + chord(1)), chord(2));
    let step_v = 1.04f64.sqrt();
    let (v0, v4) = (-step_v, 3.0 * step_v);
    let corners = [(u0, v0), (u0, v4), (u3, v0), (u3, v4)];
    for (row, (u, v)) in rows.iter().zip(corners) {
        assert!(
            (row[0] - u).abs() < 1e-12 && (row[1] - v).abs() < 1e-12,
            "{row:?}"
        );
    }
    // The corners are still the corner nodes.
    assert!(
        rows[0][2..].iter().all(|c| c.abs() < 1e-12),
        "{:?}",
        rows[0]
    );
    assert!((rows[3][2] - 6.0).abs() < 1e-12 && (rows[3][3] - 4.0).abs() < 1e-12);
    // The origin (0, 0) written out is the default.
    let a = dir.path().join("a.csv");
    let b = dir.path().join("b.csv");
    assert!(karkas(&["surface", "bicubic", s(&input), "-o", s(&a)])
        .status
        .success());
    let o = karkas(&[
        "surface",
        "bicubic",
        "--origin",
        "0,0",
        s(&input),
        "-o",
        s(&b),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read(&a).unwrap(), std::fs::read(&b).unwrap());
}

#[test]
fn origin_outside_the_grid_or_without_chord_exits_2() {
    let dir = temp_dir();
    let input = write(dir.path(), "g.csv", &grid_text());
    let out = dir.path().join("s.csv");
    for (origin, param) in [
        ("4,0", "chord"),
        ("0,5", "chord"),
        ("1,1", "uniform"),
        ("1", "chord"),
    ] {
        let o = karkas(&[
            "surface",
            "bicubic",
            "--param",
            param,
            "--origin",
            origin,
            s(&input),
            "-o",
            s(&out),
        ]);
        assert_eq!(o.status.code(), Some(2), "{origin} {param}");
        let err = stderr(&o);
        assert!(
            err.contains("--origin") && err.lines().count() == 1,
            "{err}"
        );
        assert!(!out.exists());
    }
    let o = karkas(&[
        "surface",
        "bicubic",
        "--origin",
        "4,0",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(
        stderr(&o).contains("outside the 4 x 5 grid"),
        "{}",
        stderr(&o)
    );
}

//! The CLI contract of `karkas curve fair`: outputs, the summary line and JSON (before and
//! after), kept ends, corners, closed curves, and exit code 2 with one line naming the cause
//! on bad input.

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, stdout, temp_dir, write};

/// A noisy arc of `n` points (deterministic wobble of about 1e-3).
fn arc(n: usize) -> String {
    let mut text = String::from("x,y\n");
    for i in 0..n {
        let a = 2.0 * i as f64 / (n - 1) as f64;
        let wobble = 0.002 * (((i * 7919) % 13) as f64 / 13.0 - 0.5);
        text.push_str(&format!(
            "{},{}\n",
            (1.0 + wobble) * a.cos(),
            (1.0 + wobble) * a.sin()
        ));
    }
    text
}

#[test]
fn samples_report_and_json_before_and_after() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc(60));
    let out = dir.path().join("fair.csv");
    let dev = dir.path().join("dev.csv");
    let o = karkas(&[
        "curve",
        "fair",
        s(&input),
        "--tolerance",
        "3e-3",
        "-o",
        s(&out),
        "--report",
        s(&dev),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["t", "x", "y"]);
    assert_eq!((rows[0][0], rows[rows.len() - 1][0]), (0.0, 1.0));
    let (header, rows) = read_csv(&dev);
    assert_eq!(header, ["point", "t", "distance"]);
    assert_eq!(rows.len(), 60);
    assert!(rows.iter().all(|r| r[2] <= 3e-3));
    let json: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    let (before, after) = (&json["before"], &json["after"]);
    assert!(
        after["fairness_energy"].as_f64().unwrap() < before["fairness_energy"].as_f64().unwrap()
    );
    assert!(
        after["curvature_extrema"].as_u64().unwrap()
            < before["curvature_extrema"].as_u64().unwrap()
    );
    assert!(json["max_deviation"].as_f64().unwrap() <= 3e-3);
    let line = stderr(&o);
    assert!(
        line.contains("before: energy") && line.contains("after: energy"),
        "{line}"
    );
}

#[test]
fn kept_ends_corners_closed_and_cad_output() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc(60));
    let out = dir.path().join("fair.csv");
    let o = karkas(&[
        "curve",
        "fair",
        s(&input),
        "--tolerance",
        "3e-3",
        "--keep-ends",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    let (first, last) = (&rows[0], &rows[rows.len() - 1]);
    assert!(
        (first[1] - 0.999).abs() < 1e-12 && first[2].abs() < 1e-12,
        "{first:?}"
    );
    assert!(last[1] < -0.4 && last[2] > 0.9, "{last:?}");
    let step = dir.path().join("fair.step");
    let o = karkas(&[
        "curve",
        "fair",
        s(&input),
        "--tolerance",
        "3e-3",
        "--corner",
        "30",
        "-o",
        s(&step),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read_to_string(&step)
        .unwrap()
        .contains("B_SPLINE_CURVE_WITH_KNOTS"));
    let mut ring = String::from("x,y\n");
    for i in 0..40 {
        let a = std::f64::consts::TAU * i as f64 / 40.0;
        ring.push_str(&format!(
            "{},{}\n",
            2.0 * a.cos(),
            a.sin() + 1e-3 * ((i * 37 % 7) as f64 - 3.0)
        ));
    }
    let ring = write(dir.path(), "ring.csv", &ring);
    let o = karkas(&[
        "curve",
        "fair",
        s(&ring),
        "--tolerance",
        "5e-3",
        "--closed",
        "-o",
        s(&out),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    let (a, b) = (&rows[0], &rows[rows.len() - 1]);
    assert!((a[1] - b[1]).abs() < 1e-12 && (a[2] - b[2]).abs() < 1e-12);
}

#[test]
fn bad_input_exits_2_naming_the_cause() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc(40));
    let out = dir.path().join("fair.csv");
    for (tol, needle) in [
        ("0", "--tolerance"),
        ("-1", "--tolerance"),
        ("nan", "--tolerance"),
        ("1e-18", "resolve"),
    ] {
        let option = format!("--tolerance={tol}");
        assert_rejected(
            &["curve", "fair", s(&input), &option, "-o", s(&out)],
            needle,
            &out,
            None,
        );
    }
    let mut shuffled = String::from("x,y\n");
    let text = arc(40);
    let lines: Vec<&str> = text.lines().skip(1).collect();
    for i in 0..40 {
        shuffled.push_str(lines[(i * 17) % 40]);
        shuffled.push('\n');
    }
    let shuffled = write(dir.path(), "shuffled.csv", &shuffled);
    let o = karkas(&[
        "curve",
        "fair",
        s(&shuffled),
        "--tolerance",
        "1e-3",
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    assert!(err.contains("points not in order"), "{err}");
    let few = write(dir.path(), "few.csv", "x,y\n0,0\n1,0\n2,1\n");
    assert_rejected(
        &[
            "curve",
            "fair",
            s(&few),
            "--tolerance",
            "1e-3",
            "-o",
            s(&out),
        ],
        "at least 4",
        &out,
        None,
    );
    let nan = write(dir.path(), "nan.csv", "x,y\n0,0\n1,0\nnan,1\n3,2\n4,4\n");
    let o = karkas(&[
        "curve",
        "fair",
        s(&nan),
        "--tolerance",
        "1e-3",
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert_rejected(
        &[
            "curve",
            "fair",
            s(&input),
            "--tolerance",
            "1e-3",
            "--corner",
            "40",
            "-o",
            s(&out),
        ],
        "corner",
        &out,
        None,
    );
}

/// `curve fit` (every mode) on a shuffled list: one line "points not in order" and exit 2, not
/// a page of warnings about empty knot spans; a tolerance below what the coordinates resolve:
/// one line naming it and exit 2; the same points in order are fitted.
#[test]
fn curve_fit_refuses_shuffled_points_and_unresolvable_tolerances_in_one_line() {
    let dir = temp_dir();
    let text = arc(41);
    let lines: Vec<&str> = text.lines().skip(1).collect();
    let mut shuffled = String::from("x,y\n");
    for i in 0..41 {
        shuffled.push_str(lines[(i * 17) % 41]);
        shuffled.push('\n');
    }
    let shuffled = write(dir.path(), "shuffled.csv", &shuffled);
    let ordered = write(dir.path(), "arc.csv", &text);
    let out = dir.path().join("fit.csv");
    for mode in [["--tolerance", "1e-3"], ["--knots", "8"]] {
        let args = [
            "curve",
            "fit",
            s(&shuffled),
            mode[0],
            mode[1],
            "-o",
            s(&out),
        ];
        assert_rejected(
            &args,
            &["points not in order", "shuffled.csv"][..],
            &out,
            None,
        );
    }
    assert_rejected(
        &[
            "curve",
            "fit",
            s(&ordered),
            "--tolerance",
            "1e-20",
            "-o",
            s(&out),
        ],
        &["--tolerance", "resolve"][..],
        &out,
        None,
    );
    let o = karkas(&[
        "curve",
        "fit",
        s(&ordered),
        "--tolerance",
        "1e-3",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

//! The CLI contract of `karkas loft`: the shipped wing, its summary and JSON, sections at span
//! stations, and bad sections tables refused naming the row and the file (exit 2, nothing
//! written).

use crate::common::{assert_rejected, karkas, read_csv, s, stdout, temp_dir, write};
use std::path::{Path, PathBuf};

/// The shipped demo wing's folder.
fn wing_dir() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/loft-wing")
}

/// Copies the shipped wing's profiles into `dir` and writes `table` there as wing.csv.
fn wing_with_table(dir: &Path, table: &str) -> PathBuf {
    for name in ["naca4415.dat", "naca2412.dat", "naca0009.dat"] {
        std::fs::copy(wing_dir().join(name), dir.join(name)).unwrap();
    }
    write(dir, "wing.csv", table)
}

const HEADER: &str = "file,x,y,z,chord,twist,dihedral\n";

#[test]
fn the_shipped_wing_lofts_within_the_tolerance_and_reports_in_json() {
    let dir = temp_dir();
    let out = dir.path().join("wing.step");
    let table = wing_dir().join("wing.csv");
    let o = karkas(&["loft", s(&table), "-o", s(&out), "--json"]);
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    let json: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(json["sections"], 3);
    assert_eq!(json["span"], "monotone");
    assert_eq!(json["tolerance_met"], true);
    assert!(json["max_relative_deviation"].as_f64().unwrap() <= 1e-5);
    let counts = json["control_points"].as_array().unwrap();
    assert_eq!(counts[0], 6); // two per station, C^1
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.contains("B_SPLINE_SURFACE_WITH_KNOTS"));
    // The summary line on standard error names the figures.
    assert!(crate::common::stderr(&o).contains("largest section deviation"));
}

#[test]
fn sections_at_span_stations_pass_through_the_placed_leading_edges() {
    let dir = temp_dir();
    let table = wing_with_table(
        dir.path(),
        &format!(
            "{HEADER}naca4415.dat,0,0,0,1.6,2,\nnaca2412.dat,0.35,3,0,1.2,0,\nnaca0009.dat,0.9,6,0,0.6,-3,\n"
        ),
    );
    let (out, cuts) = (dir.path().join("w.obj"), dir.path().join("cuts.csv"));
    let o = karkas(&[
        "loft",
        s(&table),
        "-o",
        s(&out),
        "--span",
        "linear",
        "--sections-at",
        "0,1.5,3",
        "--sections-out",
        s(&cuts),
    ]);
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    let (header, rows) = read_csv(&cuts);
    assert_eq!(header.join(","), "curve,x,y,z");
    assert_eq!(rows.len(), 600);
    // The flat wing's span station is y; the linear rule puts the leading edge at 1.5 half
    // way between the root's and the middle section's.
    let min_x = |k: f64| {
        rows.iter()
            .filter(|r| r[0] == k)
            .map(|r| r[1])
            .fold(f64::INFINITY, f64::min)
    };
    assert!(min_x(0.0).abs() < 1e-3, "{}", min_x(0.0));
    assert!((min_x(1.0) - 0.175).abs() < 1e-3, "{}", min_x(1.0));
    assert!(rows
        .iter()
        .filter(|r| r[0] == 2.0)
        .all(|r| (r[2] - 3.0).abs() < 1e-9));
}

#[test]
fn bad_tables_exit_2_naming_the_row_and_the_file_and_write_nothing() {
    let dir = temp_dir();
    let d = dir.path();
    let out = d.join("out.step");
    let row = |file: &str, y: f64| format!("{file},0,{y},0,1,0,\n");
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            format!(
                "{HEADER}{}{}",
                row("naca4415.dat", 0.0),
                row("missing.dat", 2.0)
            ),
            vec!["wing.csv: row 3 (missing.dat)"],
        ),
        (
            format!(
                "{HEADER}{}{}",
                row("naca4415.dat", 0.0),
                row("naca2412.dat", 0.0)
            ),
            vec!["row 3 (naca2412.dat)", "span station of section 0"],
        ),
        (
            format!(
                "{HEADER}{}{}{}",
                row("naca4415.dat", 0.0),
                row("naca2412.dat", 3.0),
                row("naca0009.dat", 1.0)
            ),
            vec!["row 4 (naca0009.dat)", "out of order"],
        ),
        (
            format!(
                "{HEADER}{}{}",
                row("naca4415.dat", 0.0),
                row("few.dat", 2.0)
            ),
            vec!["row 3 (few.dat)", "at least 5 points"],
        ),
        (
            format!(
                "{HEADER}{}{}",
                row("naca4415.dat", 0.0),
                row("percent.dat", 2.0)
            ),
            vec!["row 3 (percent.dat)", "not in unit chord"],
        ),
        (
            format!(
                "{HEADER}{}{}",
                row("naca4415.dat", 0.0),
                row("noedge.dat", 2.0)
            ),
            vec!["row 3 (noedge.dat)", "no leading edge"],
        ),
        (
            format!(
                "{HEADER}{}{}",
                row("naca4415.dat", 0.0),
                row("garbage.dat", 2.0)
            ),
            vec!["row 3 (garbage.dat)"],
        ),
        (
            format!("{HEADER}naca4415.dat,0,0,0,-1,0,\n"),
            vec!["wing.csv:2", "chord"],
        ),
    ];
    wing_with_table(d, HEADER);
    write(d, "few.dat", "1 0\n0.5 0.05\n0 0\n0.5 -0.05\n");
    let percent: String = std::fs::read_to_string(d.join("naca2412.dat"))
        .unwrap()
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split_whitespace().map(|x| x.parse().unwrap()).collect();
            format!("{} {}\n", 100.0 * v[0], 100.0 * v[1])
        })
        .collect();
    write(d, "percent.dat", &percent);
    write(
        d,
        "noedge.dat",
        "0 0\n0.3 0.05\n0.6 0.06\n1 0\n0.6 -0.03\n0.3 -0.02\n",
    );
    write(d, "garbage.dat", "1 0\n0.5 abc\n");
    for (table, needles) in cases {
        let path = write(d, "wing.csv", &table);
        assert_rejected(&["loft", s(&path), "-o", s(&out)], &needles[..], &out, None);
    }
    // An existing output is left as it was.
    std::fs::write(&out, "before").unwrap();
    let path = write(
        d,
        "wing.csv",
        &format!(
            "{HEADER}{}{}",
            row("naca4415.dat", 0.0),
            row("missing.dat", 2.0)
        ),
    );
    assert_rejected(
        &["loft", s(&path), "-o", s(&out)],
        &["missing.dat"][..],
        &out,
        Some("before"),
    );
}

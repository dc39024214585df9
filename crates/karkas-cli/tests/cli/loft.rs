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

/// The shipped wing's trailing edges are blunt: `--cap` adds the flat trailing-edge face
/// between them and closes root and tip, a closed solid (four faces) whose volume the mesh
/// of the same command agrees with; Open CASCADE's verdict is `tests/cad/check_bodies.py`'s.
#[test]
fn a_blunt_edged_wing_caps_into_a_closed_solid_with_its_trailing_edge_face() {
    let dir = temp_dir();
    let table = wing_dir().join("wing.csv");
    let volume = |name: &str| {
        let out = dir.path().join(name);
        let o = karkas(&["loft", "--cap", s(&table), "-o", s(&out)]);
        let err = crate::common::stderr(&o);
        assert!(o.status.success(), "{err}");
        let at = err.find("enclosed volume ").expect("a volume") + "enclosed volume ".len();
        let figure = err[at..]
            .split(|c: char| c == ')' || c.is_whitespace())
            .next()
            .unwrap();
        (err.clone(), figure.parse::<f64>().unwrap(), out)
    };
    let (err, solid, step) = volume("wing.step");
    assert!(err.contains("2 planar caps, closed solid"), "{err}");
    let text = std::fs::read_to_string(step).unwrap();
    assert!(text.contains("MANIFOLD_SOLID_BREP"));
    assert_eq!(text.matches("ADVANCED_FACE(").count(), 4); // wing, trailing edge, two caps
    let (err, meshed, _) = volume("wing.stl");
    assert!(err.contains("closed mesh"), "{err}");
    assert!(
        (meshed - solid).abs() <= 1e-3 * solid,
        "mesh {meshed}, solid {solid}"
    );
    // A sharp tip on a blunt root cannot be capped by planar faces: one line naming --cap.
    let mixed = temp_dir();
    let tip = std::fs::read_to_string(wing_dir().join("naca0009.dat")).unwrap();
    let first = tip.lines().nth(1).unwrap().to_string();
    std::fs::write(mixed.path().join("sharp.dat"), format!("{tip}{first}\n")).unwrap();
    let table = wing_with_table(
        mixed.path(),
        &format!("{HEADER}naca4415.dat,0,0,0,1.6,2,\nsharp.dat,0.9,6,0.45,0.6,-3,\n"),
    );
    let out = mixed.path().join("mixed.step");
    let o = karkas(&["loft", "--cap", s(&table), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(crate::common::stderr(&o).contains("--cap: the trailing edge is blunt at some"));
    assert!(!out.exists());
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

/// A small windIO blade: a prebent reference axis, three airfoils (a NACA 0012 and a
/// thicker NACA 0021, 41 points each) at `positions`.
fn windio_blade(positions: [f64; 3]) -> String {
    let foil = |t: f64| {
        let (mut xs, mut ys) = (Vec::new(), Vec::new());
        for k in 0..41 {
            let a = std::f64::consts::PI * k as f64 / 20.0;
            let x = 0.5 * (1.0 + a.cos());
            let h = 5.0
                * t
                * (0.2969 * x.sqrt() - 0.126 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                    - 0.1036 * x.powi(4));
            xs.push(format!("{x}"));
            ys.push(format!("{}", if k <= 20 { h } else { -h }));
        }
        format!("{{x: [{}], y: [{}]}}", xs.join(", "), ys.join(", "))
    };
    format!(
        "windIO_version: '2.0'\nname: test blade\ncomponents:\n  blade:\n    reference_axis:\n      \
         x: {{grid: &g [0.0, 0.5, 1.0], values: [0.0, -0.2, -1.0]}}\n      \
         y: {{grid: [0.0, 1.0], values: [0.0, 0.0]}}\n      \
         z: {{grid: *g, values: [0.0, 10.0, 20.0]}}\n    outer_shape:\n      \
         chord: {{grid: *g, values: [2.0, 2.4, 0.8]}}\n      \
         twist: {{grid: *g, values: [12.0, 4.0, -1.0]}}\n      \
         section_offset_y: {{grid: *g, values: [1.0, 0.7, 0.2]}}\n      airfoils:\n        \
         - {{name: thick, spanwise_position: {}}}\n        \
         - {{name: thin, spanwise_position: {}}}\n        \
         - {{name: thin, spanwise_position: {}}}\nairfoils:\n  \
         - {{name: thick, coordinates: {}}}\n  - {{name: thin, coordinates: {}}}\n",
        positions[0],
        positions[1],
        positions[2],
        foil(0.21),
        foil(0.12)
    )
}

#[test]
fn a_windio_blade_lofts_through_its_airfoils_at_their_positions() {
    let dir = temp_dir();
    let yaml = write(dir.path(), "blade.yaml", &windio_blade([0.0, 0.4, 1.0]));
    let out = dir.path().join("blade.step");
    let o = karkas(&["loft", "--windio", s(&yaml), "-o", s(&out), "--json"]);
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    let json: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    // The three airfoils and the grid position 0.5 between the second and the third.
    assert_eq!(json["sections"], 4);
    assert_eq!(json["tolerance_met"], true);
    // Stations: the positions times the axis length (a little over 20 for the prebent axis).
    let stations: Vec<f64> = json["airfoil_stations"]
        .as_array()
        .unwrap()
        .iter()
        .map(|v| v.as_f64().unwrap())
        .collect();
    assert_eq!(stations[0], 0.0);
    assert!(stations[2] > 20.0 && stations[2] < 20.2, "{stations:?}");
    assert!(
        (stations[1] - 0.4 * stations[2]).abs() < 1e-12,
        "{stations:?}"
    );
    assert!(std::fs::read_to_string(&out)
        .unwrap()
        .contains("B_SPLINE_SURFACE_WITH_KNOTS"));
    // The root section at the surface's first row: leading edge 1 upstream of the axis,
    // turned by the 12 degrees twist into the wind (-x).
    let cuts = dir.path().join("root.csv");
    let o = karkas(&[
        "loft",
        "--windio",
        s(&yaml),
        "-o",
        s(&dir.path().join("b.obj")),
        "--sections-at",
        "0",
        "--sections-out",
        s(&cuts),
    ]);
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    let (_, rows) = read_csv(&cuts);
    let (sin, cos) = 12f64.to_radians().sin_cos();
    let expected = [-sin, -cos, 0.0];
    let nearest = rows
        .iter()
        .map(|r| {
            (0..3)
                .map(|k| (r[k + 1] - expected[k]).powi(2))
                .sum::<f64>()
                .sqrt()
        })
        .fold(f64::INFINITY, f64::min);
    assert!(nearest < 0.015, "{nearest}");
}

#[test]
fn bad_windio_files_exit_2_naming_the_file_and_write_nothing() {
    let dir = temp_dir();
    let d = dir.path();
    let out = d.join("out.step");
    let good = windio_blade([0.0, 0.4, 1.0]);
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            good.replace("name: thick, spanwise", "name: gone, spanwise"),
            vec!["blade.yaml", "'gone'"],
        ),
        (
            windio_blade([0.0, 0.4, 0.4]),
            vec!["blade.yaml", "airfoil 3 ('thin' at spanwise_position 0.4)"],
        ),
        (
            windio_blade([0.0, 0.6, 0.4]),
            vec!["blade.yaml", "airfoil 3", "not after"],
        ),
        (
            windio_blade([0.0, 0.4, 1.5]),
            vec!["blade.yaml", "outside [0, 1]"],
        ),
        (
            good.replace("values: [2.0, 2.4, 0.8]", "values: [2.0, 2.4]"),
            vec!["blade.yaml", "outer_shape.chord"],
        ),
        (
            good.replace("outer_shape:", "outer_shape_bem:"),
            vec!["blade.yaml", "windIO 1"],
        ),
        (
            good.replace("airfoils:\n  -", "airfoils: [\n  -"),
            vec!["blade.yaml:"],
        ),
        ("name: [1, 2".to_owned(), vec!["blade.yaml"]),
    ];
    for (text, needles) in cases {
        let path = write(d, "blade.yaml", &text);
        assert_rejected(
            &["loft", "--windio", s(&path), "-o", s(&out)],
            &needles[..],
            &out,
            None,
        );
    }
    let path = write(d, "blade.yaml", &good);
    assert_rejected(
        &[
            "loft",
            "--windio",
            s(&d.join("missing.yaml")),
            "-o",
            s(&out),
        ],
        &["missing.yaml"][..],
        &out,
        None,
    );
    // A table and --windio at once: refused.
    let o = karkas(&["loft", s(&path), "--windio", s(&path), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!out.exists());
}

/// The Wigley hull (length 1, beam 0.1, draught 0.0625) as a table of offsets of
/// `stations` x `waterlines`, midship at `x0`.
fn wigley_offsets(stations: usize, waterlines: usize, x0: f64) -> String {
    let mut text = String::from("station,waterline,half_breadth\n");
    for i in 0..stations {
        let x = -0.5 + i as f64 / (stations - 1) as f64;
        for j in 0..waterlines {
            let z = -0.0625 + 0.0625 * j as f64 / (waterlines - 1) as f64;
            let hb = wigley(x, z);
            text.push_str(&format!("{},{z},{hb}\n", x0 + x));
        }
    }
    text
}

/// The Wigley hull's half-breadth.
fn wigley(x: f64, z: f64) -> f64 {
    0.05 * (1.0 - 4.0 * x * x) * (1.0 - (z / 0.0625).powi(2))
}

#[test]
fn a_table_of_offsets_lofts_a_hull_near_the_analytic_one() {
    let dir = temp_dir();
    let x0 = 250.0;
    let table = write(dir.path(), "wigley.csv", &wigley_offsets(21, 11, x0));
    {
        let out = dir.path().join("hull.step");
        let cuts = dir.path().join("cuts.csv");
        let args = vec![
            "loft",
            "--offsets",
            s(&table),
            "-o",
            s(&out),
            "--json",
            "--sections-at",
            "249.525,249.8,250.125,250.46",
            "--sections-out",
            s(&cuts),
        ];
        let o = karkas(&args);
        assert!(o.status.success(), "{}", crate::common::stderr(&o));
        let json: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        assert_eq!(json["sections"], 21);
        assert_eq!(json["tolerance_met"], true);
        // Between the stations, the surface's sections against the analytic hull: the
        // half-breadth at the section's height within 2e-3 of the beam (the table's own
        // spacing; the loft's offsets themselves are within 1e-5 of the beam).
        let (_, rows) = read_csv(&cuts);
        assert_eq!(rows.len(), 800);
        let mut worst = 0.0f64;
        for r in &rows {
            let (x, y, z) = (r[1] - x0, r[2], r[3]);
            assert!((-0.0625 - 1e-9..=1e-9).contains(&z), "{r:?}");
            assert!(y >= -1e-9, "{r:?}");
            worst = worst.max((y - wigley(x, z)).abs());
        }
        assert!(worst < 2e-4, "{worst}");
    }
}

#[test]
fn a_mirrored_table_of_offsets_lofts_the_whole_hull_with_its_keel_corner() {
    let dir = temp_dir();
    let x0 = 250.0;
    let table = write(dir.path(), "wigley.csv", &wigley_offsets(21, 11, x0));
    let out = dir.path().join("hull.step");
    let cuts = dir.path().join("cuts.csv");
    let o = karkas(&[
        "loft",
        "--offsets",
        s(&table),
        "--mirror",
        "-o",
        s(&out),
        "--json",
        "--sections-at",
        "249.525,249.8,250.125,250.46",
        "--sections-out",
        s(&cuts),
    ]);
    assert!(o.status.success(), "{}", crate::common::stderr(&o));
    let json: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
    assert_eq!(json["sections"], 21);
    assert_eq!(json["tolerance_met"], true);
    assert!(std::fs::read_to_string(&out)
        .unwrap()
        .contains("B_SPLINE_SURFACE_WITH_KNOTS"));
    // Each cut: 200 points uniform in v, port (y <= 0) then starboard (y >= 0), the whole
    // section within 2e-3 of the beam of the analytic |y| on both sides (the keel corner kept:
    // one smooth knot vector through it is off by 1.7e-3 absolute), mirror images to 1e-12.
    let (_, rows) = read_csv(&cuts);
    assert_eq!(rows.len(), 800);
    let mut worst = 0.0f64;
    for cut in rows.chunks(200) {
        for (k, r) in cut.iter().enumerate() {
            let (x, y, z) = (r[1] - x0, r[2], r[3]);
            assert!((-0.0625 - 1e-9..=1e-9).contains(&z), "{r:?}");
            assert!(if k < 100 { y <= 1e-12 } else { y >= -1e-12 }, "{k} {r:?}");
            worst = worst.max((y.abs() - wigley(x, z)).abs());
            let m = &cut[199 - k];
            assert!((m[1] - r[1]).abs() < 1e-12, "{r:?} {m:?}");
            assert!((m[2] + r[2]).abs() < 1e-12, "{r:?} {m:?}");
            assert!((m[3] - r[3]).abs() < 1e-12, "{r:?} {m:?}");
        }
    }
    assert!(worst < 2e-4, "{worst}");
    // --mirror needs --offsets.
    let o = karkas(&[
        "loft",
        s(&table),
        "--mirror",
        "-o",
        s(&dir.path().join("w.step")),
    ]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn bad_tables_of_offsets_exit_2_naming_the_station_and_write_nothing() {
    let dir = temp_dir();
    let d = dir.path();
    let out = d.join("hull.step");
    let good = wigley_offsets(5, 6, 0.0);
    let cases: Vec<(String, Vec<&str>)> = vec![
        (
            good.replace("-0.25,", "-0.6,"),
            vec!["o.csv:", "out of order"],
        ),
        (
            good.replacen("-0.5,-0.05,", "-0.5,-0.0625,", 1),
            vec!["o.csv:", "not above"],
        ),
        (good.replacen(",0\n", ",-1\n", 1), vec!["o.csv:", "negative"]),
        (
            "station,waterline,half_breadth\n0,0,0.1\n0,1,0.2\n0,2,0.2\n1,0,0.1\n1,1,0.1\n1,2,0.1\n"
                .to_owned(),
            vec!["o.csv: station 0 (line 2)", "at least 5 points"],
        ),
        ("station,waterline\n0,0\n".to_owned(), vec!["half_breadth"]),
    ];
    for (text, needles) in cases {
        let path = write(d, "o.csv", &text);
        assert_rejected(
            &["loft", "--offsets", s(&path), "-o", s(&out)],
            &needles[..],
            &out,
            None,
        );
    }
    assert_rejected(
        &["loft", "--offsets", s(&d.join("none.csv")), "-o", s(&out)],
        &["none.csv"][..],
        &out,
        None,
    );
    // A pointed hull cannot be capped: the message speaks of its deck, not of a trailing edge.
    let path = write(d, "o.csv", &good);
    assert_rejected(
        &[
            "loft",
            "--offsets",
            s(&path),
            "--mirror",
            "--cap",
            "-o",
            s(&out),
        ],
        &["--cap", "deck edges meet at some stations"][..],
        &out,
        None,
    );
}

//! The CLI contract of the exact CAD outputs: `.step`/`.stp` and `.iges`/`.igs` for every
//! command whose result is a piecewise polynomial (docs/reference/contract.md); a clear error for
//! the discrete periodic splines and for Coons networks without an exact form.

use crate::common::{grid_csv, karkas, s, stderr, temp_dir, write};
use std::path::{Path, PathBuf};

/// The STEP entity instances of a given type, as their argument text.
fn step_items(text: &str, entity: &str) -> Vec<String> {
    let prefix = format!("={entity}(");
    text.lines()
        .filter_map(|l| l.find(&prefix).map(|k| l[k + prefix.len()..].to_owned()))
        .collect()
}

/// The parameters of the first entity in an IGES file's parameter section.
fn iges_first_entity(text: &str) -> Vec<String> {
    let data: String = text
        .lines()
        .filter(|l| l.len() == 80 && &l[72..73] == "P" && l[65..72].trim() == "1")
        .map(|l| l[..64].trim_end())
        .collect();
    data.trim_end_matches(';')
        .split(',')
        .map(str::to_owned)
        .collect()
}

fn wavy_grid(rows: usize, cols: usize) -> String {
    grid_csv(rows, cols, |i, j| {
        let (x, y) = (i as f64, j as f64 * 0.5);
        [x, y, (x * 0.7).sin() * (1.0 + y * y)]
    })
}

const POINTS: &str = "x,y\n0,0\n1,2\n2,1\n3,3\n4,0\n";

#[test]
fn ll_curve_step_and_iges_hold_the_exact_b_spline() {
    let dir = temp_dir();
    let input = write(dir.path(), "pts.csv", POINTS);
    for name in ["c.step", "c.STP"] {
        let out = dir.path().join(name);
        let o = karkas(&["curve", "ll", "--order", "3", s(&input), "-o", s(&out)]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(
            stderr(&o).contains("B-spline curve of degree 6"),
            "{}",
            stderr(&o)
        );
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.starts_with("ISO-10303-21;"));
        let curves = step_items(&text, "B_SPLINE_CURVE_WITH_KNOTS");
        assert_eq!(curves.len(), 1);
        // Degree 2L = 6; knot multiplicities 7, then L = 3 at the 4 inner borders, then 7.
        assert!(curves[0].contains(",6,(#"), "{}", curves[0]);
        assert!(curves[0].contains(",(7,3,3,3,3,7),("), "{}", curves[0]);
        // A planar curve lies in z = 0; an open LL curve starts at its first point.
        let points = step_items(&text, "CARTESIAN_POINT");
        assert!(points
            .iter()
            .all(|p| p.ends_with(",0.0000000000000000E0));")));
    }
    for name in ["c.iges", "c.igs"] {
        let out = dir.path().join(name);
        let o = karkas(&["curve", "ll", "--order", "2", s(&input), "-o", s(&out)]);
        assert!(o.status.success(), "{}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        assert!(text.lines().all(|l| l.len() == 80));
        let f = iges_first_entity(&text);
        // Entity 126: L (K + 1) + 1 = 13 control points (index 12), degree 2L = 4, planar.
        assert_eq!(f[0], "126");
        assert_eq!(f[1], "12");
        assert_eq!(f[2], "4");
        assert_eq!(f[3], "1");
        let n: usize = f[1].parse::<usize>().unwrap() + 1;
        // Knots: n + p + 1 of them; the first control point is the first input point.
        let first_point = 7 + (n + 5) + n;
        let x: f64 = f[first_point].parse().unwrap();
        let y: f64 = f[first_point + 1].parse().unwrap();
        assert_eq!((x, y), (0.0, 0.0));
    }
}

#[test]
fn surfaces_write_step_faces_and_iges_128() {
    let dir = temp_dir();
    let grid = write(dir.path(), "g.csv", &wavy_grid(5, 4));
    let out = dir.path().join("s.iges");
    let o = karkas(&["surface", "ll", "--order", "2", s(&grid), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    // L (K + 1) + 1 control points per direction: 13 x 11 for L = 2, K = 5 x 4; degree 4.
    let f = iges_first_entity(&std::fs::read_to_string(&out).unwrap());
    assert_eq!(
        &f[..10],
        ["128", "12", "10", "4", "4", "0", "0", "1", "0", "0"]
    );

    let out = dir.path().join("b.step");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--param",
        "uniform",
        s(&grid),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let surfaces = step_items(&text, "B_SPLINE_SURFACE_WITH_KNOTS");
    assert_eq!(surfaces.len(), 1);
    // Degrees 3 x 3; uniform parameters 0..4 and 0..3 with simple inner knots.
    assert!(surfaces[0].starts_with("'b_0',3,3,((#"), "{}", surfaces[0]);
    assert!(
        surfaces[0].contains(",(4,1,1,1,4),(4,1,1,4),"),
        "{}",
        surfaces[0]
    );
    assert_eq!(step_items(&text, "ADVANCED_FACE").len(), 1);
    assert_eq!(step_items(&text, "OPEN_SHELL").len(), 1);
}

/// A network whose curves cross at equal point indices (exact) or not (warped).
fn network(dir: &Path, warped: bool) -> (PathBuf, PathBuf) {
    let surface = |u: f64, v: f64| [2.0 * u, 2.0 * v, u * v + 0.1 * u * u];
    let mut u_text = String::from("curve,x,y,z\n");
    for (c, v) in [0.0, 0.5, 1.0].iter().enumerate() {
        for k in 0..=6 {
            let p = surface(k as f64 / 6.0, *v);
            u_text.push_str(&format!("{c},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    let mut v_text = String::from("curve,x,y,z\n");
    for (c, u) in [0.0, 0.5, 1.0].iter().enumerate() {
        let params: Vec<f64> = if warped && c == 1 {
            vec![0.0, 0.1, 0.2, 0.5, 0.9, 1.0]
        } else {
            vec![0.0, 0.25, 0.5, 0.75, 1.0]
        };
        for v in params {
            let p = surface(*u, v);
            v_text.push_str(&format!("{c},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    (write(dir, "u.csv", &u_text), write(dir, "v.csv", &v_text))
}

#[test]
fn coons_surfaces_are_exported_exactly_or_refused() {
    let dir = temp_dir();
    let (u, v) = network(dir.path(), false);
    for kind in ["composite", "gordon-spline", "bilinear"] {
        let out = dir.path().join(format!("{kind}.stp"));
        let o = karkas(&[
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(&u),
            "--v-curves",
            s(&v),
            "-o",
            s(&out),
        ]);
        if kind == "bilinear" {
            // Three curves per family: bilinear needs two; refused before any export.
            assert_eq!(o.status.code(), Some(2));
            continue;
        }
        assert!(o.status.success(), "{kind}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        assert_eq!(step_items(&text, "B_SPLINE_SURFACE_WITH_KNOTS").len(), 1);
    }
    let warped = temp_dir();
    let (u, v) = network(warped.path(), true);
    let out = warped.path().join("w.step");
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "composite",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let e = stderr(&o);
    assert!(
        e.contains("has no exact B-spline form")
            && e.contains("same point numbers")
            && e.contains("resample")
            && !e.contains("warp"),
        "{e}"
    );
    assert_eq!(e.lines().count(), 1);
    assert!(!out.exists());
}

#[test]
fn fitted_curves_export_defect_two_cubics() {
    let dir = temp_dir();
    let mut text = String::from("x,y\n");
    for k in 0..=20 {
        let t = k as f64 / 20.0;
        text.push_str(&format!("{},{}\n", t * 4.0, (3.0 * t).sin()));
    }
    let input = write(dir.path(), "p.csv", &text);
    let out = dir.path().join("f.step");
    let o = karkas(&[
        "curve",
        "fit",
        "--knots",
        "0,0.5,1",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let curves = step_items(
        &std::fs::read_to_string(&out).unwrap(),
        "B_SPLINE_CURVE_WITH_KNOTS",
    );
    assert!(
        curves[0].contains(",3,(#") && curves[0].contains(",(4,2,4),("),
        "{}",
        curves[0]
    );
}

#[test]
fn discrete_splines_and_bad_input_give_one_line_errors_and_no_file() {
    let dir = temp_dir();
    let input = write(dir.path(), "pts.csv", POINTS);
    for name in ["d.step", "d.igs"] {
        let out = dir.path().join(name);
        let o = karkas(&[
            "curve",
            "dps",
            "--order",
            "2",
            "--n",
            "4",
            s(&input),
            "-o",
            s(&out),
        ]);
        assert_eq!(o.status.code(), Some(2));
        let e = stderr(&o);
        assert!(
            e.contains("discrete periodic splines are point sets"),
            "{e}"
        );
        assert_eq!(e.lines().count(), 1);
        assert!(!out.exists());
    }
    let bad = write(dir.path(), "bad.csv", "x,y\n0,0\n1,nan\n2,1\n");
    let out = dir.path().join("bad.step");
    let o = karkas(&["curve", "ll", s(&bad), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.csv"), "{}", stderr(&o));
    assert!(!out.exists());
}

/// The global parameters of an IGES file (the `G` section) split at the delimiter `,`, the
/// first (`1H,`, the delimiter itself) taken whole: field `k` (1-based) at index `k - 1`.
fn iges_global(text: &str) -> Vec<String> {
    let data: String = text
        .lines()
        .filter(|l| l.len() == 80 && &l[72..73] == "G")
        .map(|l| &l[..72])
        .collect();
    let rest = data.strip_prefix("1H,,").expect("the delimiter field");
    std::iter::once("1H,".to_owned())
        .chain(
            rest.trim_end()
                .trim_end_matches(';')
                .split(',')
                .map(|f| f.trim().to_owned()),
        )
        .collect()
}

#[test]
fn closed_curves_and_surfaces_carry_their_closed_flags() {
    let dir = temp_dir();
    let input = write(dir.path(), "pts.csv", POINTS);
    for (closed, flag, iges) in [(false, ".F.", "0"), (true, ".T.", "1")] {
        let mut args = vec!["curve", "ll", "--order", "2"];
        if closed {
            args.push("--closed");
        }
        let step = dir.path().join(format!("c{closed}.step"));
        let o = karkas(&[&args[..], &[s(&input), "-o", s(&step)]].concat());
        assert!(o.status.success(), "{}", stderr(&o));
        let curve = &step_items(
            &std::fs::read_to_string(&step).unwrap(),
            "B_SPLINE_CURVE_WITH_KNOTS",
        )[0];
        assert!(
            curve.contains(&format!(",.UNSPECIFIED.,{flag},.F.,(")),
            "{curve}"
        );
        let igs = dir.path().join(format!("c{closed}.igs"));
        let o = karkas(&[&args[..], &[s(&input), "-o", s(&igs)]].concat());
        assert!(o.status.success(), "{}", stderr(&o));
        // Entity 126: PROP2 (the fifth field) is 1 for a closed curve.
        assert_eq!(
            iges_first_entity(&std::fs::read_to_string(&igs).unwrap())[4],
            iges
        );
    }
    // A grid closed in v: the STEP surface is closed in v only, so is the IGES surface.
    let grid = write(
        dir.path(),
        "tube.csv",
        &grid_csv(5, 8, |i, j| {
            let th = std::f64::consts::TAU * j as f64 / 8.0;
            [i as f64, th.cos(), th.sin()]
        }),
    );
    let tube = |ext: &str| {
        let out = dir.path().join(format!("tube.{ext}"));
        let o = karkas(&[
            "surface",
            "ll",
            "--order",
            "2",
            "--closed-v",
            s(&grid),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        std::fs::read_to_string(&out).unwrap()
    };
    let surface = &step_items(&tube("step"), "B_SPLINE_SURFACE_WITH_KNOTS")[0];
    assert!(
        surface.contains(",.UNSPECIFIED.,.F.,.T.,.F.,("),
        "{surface}"
    );
    let f = iges_first_entity(&tube("igs"));
    assert_eq!((f[5].as_str(), f[6].as_str()), ("0", "1"));
}

/// The STEP `FILE_NAME` time stamp (its second field) and the IGES global dates (fields 18
/// and 25) of a curve written with `SOURCE_DATE_EPOCH` set to `fixed`, or unset.
fn written_time_stamps(fixed: Option<&str>) -> (String, String, String) {
    let dir = temp_dir();
    let input = write(dir.path(), "p.csv", "x,y\n0,0\n1,2\n2,-1\n3,0\n");
    let mut stamps = Vec::new();
    for ext in ["step", "igs"] {
        let out = dir.path().join(format!("p.{ext}"));
        let mut command = std::process::Command::new(env!("CARGO_BIN_EXE_karkas"));
        command.args(["curve", "ll", "--order", "2", s(&input), "-o", s(&out)]);
        match fixed {
            Some(value) => command.env("SOURCE_DATE_EPOCH", value),
            None => command.env_remove("SOURCE_DATE_EPOCH"),
        };
        let o = command.output().unwrap();
        assert!(o.status.success(), "{}", stderr(&o));
        stamps.push(std::fs::read_to_string(&out).unwrap());
    }
    let file_name = stamps[0]
        .lines()
        .find(|l| l.starts_with("FILE_NAME("))
        .unwrap()
        .to_owned();
    let step_stamp = file_name.split('\'').nth(3).unwrap().to_owned();
    let g = iges_global(&stamps[1]);
    (step_stamp, g[17].clone(), g[24].clone())
}

#[test]
fn step_and_iges_carry_the_moment_they_were_written() {
    // SOURCE_DATE_EPOCH = 10^9 s is 2001-09-09 01:46:40 UTC (reproducible output).
    let (step, iges_made, iges_changed) = written_time_stamps(Some("1000000000"));
    assert_eq!(step, "2001-09-09T01:46:40");
    assert_eq!(iges_made, "15H20010909.014640");
    assert_eq!(iges_changed, iges_made);
    // Without it, the clock: moments after this code was written, in each format's spelling.
    let (step, iges_made, _) = written_time_stamps(None);
    assert_eq!(step.len(), 19, "{step}");
    assert!(step.as_str() > "2026-01-01T00:00:00", "{step}");
    assert_eq!(iges_made.len(), 18, "{iges_made}");
    assert!(iges_made.as_str() > "15H20260101.000000", "{iges_made}");
}

#[test]
fn iges_states_the_largest_coordinate() {
    let dir = temp_dir();
    let input = write(
        dir.path(),
        "far.csv",
        "x,y\n0,0\n1000,2\n2000,-3500\n3000,3\n4000,0\n",
    );
    let out = dir.path().join("far.iges");
    let o = karkas(&["curve", "ll", "--order", "2", s(&input), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    // Global parameter 20, the maximum coordinate value: the largest control point coordinate.
    let g = iges_global(&text);
    let largest: f64 = g[19].parse().unwrap();
    let f = iges_first_entity(&text);
    let n: usize = f[1].parse::<usize>().unwrap() + 1;
    let first = 7 + (n + 5) + n;
    let control: f64 = (0..3 * n)
        .map(|k| f[first + k].parse::<f64>().unwrap().abs())
        .fold(0.0, f64::max);
    assert_eq!(largest, control);
    assert!(largest >= 4000.0);
}

#[test]
fn b_splines_above_degree_25_are_refused_for_step_and_iges() {
    let dir = temp_dir();
    let input = write(dir.path(), "pts.csv", POINTS);
    let grid = write(dir.path(), "g.csv", &wavy_grid(5, 4));
    for (command, source, name) in [
        ("curve", &input, "c.step"),
        ("curve", &input, "c.iges"),
        ("surface", &grid, "s.step"),
        ("surface", &grid, "s.igs"),
    ] {
        let out = dir.path().join(name);
        let o = karkas(&[command, "ll", "--order", "13", s(source), "-o", s(&out)]);
        assert_eq!(o.status.code(), Some(2), "{name}: {}", stderr(&o));
        let e = stderr(&o);
        assert!(e.contains("degree 26, above 25"), "{e}");
        assert!(e.contains("an LL order of at most 12"), "{e}");
        assert_eq!(e.lines().count(), 1);
        assert!(!out.exists());
        // Order 12 (degree 24) is written.
        let o = karkas(&[command, "ll", "--order", "12", s(source), "-o", s(&out)]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
    }
    // DXF has no such limit in the readers that take it: written.
    let out = dir.path().join("c.dxf");
    let o = karkas(&["curve", "ll", "--order", "13", s(&input), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
}

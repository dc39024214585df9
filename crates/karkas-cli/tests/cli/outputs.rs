//! Everyday output options: `-o` repeated (one computation, every output, the same bytes as
//! separate runs), `--units` and `--scale` of STEP, IGES and DXF, the bound of the default
//! sample counts, meshes to a tolerance, and pictures whose input dots leave the curve in
//! sight.

use crate::common::{grid_csv, karkas_in, read_csv, stderr, temp_dir, write};
use std::path::Path;

/// A noisy airfoil-like contour of `n` points, `x,y`.
fn foil(n: usize) -> String {
    let mut text = String::from("x,y\n");
    for k in 0..n {
        let t = std::f64::consts::TAU * k as f64 / (n - 1) as f64;
        let x = 0.5 + 0.5 * t.cos();
        let y = 0.12 * t.sin() * (1.0 - x).sqrt() + 1e-4 * (7.3 * k as f64).sin();
        text.push_str(&format!("{x},{y}\n"));
    }
    text
}

/// Runs karkas in `dir` with `SOURCE_DATE_EPOCH` fixed (STEP and IGES stamp the time);
/// asserts success and returns standard error.
fn run(dir: &Path, args: &[&str]) -> String {
    let o = std::process::Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args(args)
        .current_dir(dir)
        .env_remove("KARKAS_MAX_MEMORY")
        .env("SOURCE_DATE_EPOCH", "1700000000")
        .output()
        .unwrap();
    let err = stderr(&o);
    assert_eq!(o.status.code(), Some(0), "{args:?}: {err}");
    err
}

#[test]
fn one_fit_writes_every_output_byte_for_byte_as_separate_runs() {
    let dir = temp_dir();
    write(dir.path(), "foil.csv", &foil(121));
    let fit = ["curve", "fit", "foil.csv", "--tolerance", "1e-3"];
    let outputs = ["f.step", "f.dxf", "f.svg", "f.csv", "f.iges"];
    let mut args = fit.to_vec();
    for o in &outputs {
        args.extend_from_slice(&["-o", o]);
    }
    let err = run(dir.path(), &args);
    // One fit: its summary line once per output written.
    for o in outputs {
        let summaries = err
            .lines()
            .filter(|l| l.starts_with(&format!("karkas: wrote {o} (")) && l.contains("knots"));
        assert_eq!(summaries.count(), 1, "{o}: {err}");
    }
    // Each output alone, by its own run in a folder of its own (STEP and IGES name the
    // product after the file's name, which is the same).
    for o in outputs {
        let together = std::fs::read(dir.path().join(o)).unwrap();
        let alone = dir.path().join(format!("alone-{o}"));
        std::fs::create_dir(&alone).unwrap();
        let mut args = vec!["curve", "fit", "../foil.csv", "--tolerance", "1e-3"];
        args.extend_from_slice(&["-o", o]);
        run(&alone, &args);
        let separate = std::fs::read(alone.join(o)).unwrap();
        assert!(together == separate, "{o} differs from a separate run");
    }
}

#[test]
fn several_outputs_of_every_builder_and_their_refusals() {
    let dir = temp_dir();
    write(dir.path(), "foil.csv", &foil(41));
    let grid = grid_csv(6, 5, |i, j| {
        let (x, y) = (i as f64 * 0.2, j as f64 * 0.25);
        [x, y, (2.0 * x).sin() * y]
    });
    write(dir.path(), "g.csv", &grid);
    for args in [
        &[
            "curve", "ll", "foil.csv", "-o", "a.csv", "-o", "a.svg", "-o", "a.step",
        ][..],
        &["curve", "spline", "foil.csv", "-o", "b.dxf", "-o", "b.png"],
        &[
            "curve", "dps", "--order", "2", "--n", "4", "foil.csv", "-o", "c.csv", "-o", "c.svg",
        ],
        &[
            "surface", "ll", "g.csv", "-o", "d.obj", "-o", "d.step", "-o", "d.csv",
        ],
        &["surface", "bicubic", "g.csv", "-o", "e.stl", "-o", "e.iges"],
    ] {
        run(dir.path(), args);
        for o in args.iter().skip_while(|a| **a != "-o").skip(1).step_by(2) {
            assert!(dir.path().join(o).exists(), "{o} of {args:?}");
        }
    }
    // An output given twice, and an input among the outputs: refused before any work.
    for (args, needle) in [
        (
            &["curve", "ll", "foil.csv", "-o", "x.csv", "-o", "./x.csv"][..],
            "given twice",
        ),
        (
            &["curve", "ll", "foil.csv", "-o", "y.csv", "-o", "foil.csv"],
            "would overwrite the input",
        ),
    ] {
        let o = karkas_in(dir.path(), args);
        assert_eq!(o.status.code(), Some(2), "{args:?}");
        assert!(stderr(&o).contains(needle), "{}", stderr(&o));
        assert!(!dir.path().join("x.csv").exists() && !dir.path().join("y.csv").exists());
    }
}

#[test]
fn units_and_scale_are_stated_in_step_iges_and_dxf() {
    let dir = temp_dir();
    write(dir.path(), "foil.csv", &foil(41));
    let ll = |out: &str, extra: &[&str]| {
        let mut args = vec!["curve", "ll", "foil.csv", "-o", out];
        args.extend_from_slice(extra);
        run(dir.path(), &args);
        std::fs::read_to_string(dir.path().join(out)).unwrap()
    };
    let mm = ll("mm.step", &[]);
    assert!(mm.contains("SI_UNIT(.MILLI.,.METRE.)"));
    let m = ll("m.step", &["--units", "m"]);
    assert!(m.contains("SI_UNIT($,.METRE.)") && !m.contains(".MILLI."));
    let inch = ll("in.step", &["--units", "in"]);
    assert!(inch.contains("CONVERSION_BASED_UNIT('INCH'") && inch.contains("LENGTH_MEASURE(25.4)"));
    let cm = ll("cm.igs", &["--units", "cm"]);
    let global: String = cm
        .lines()
        .filter(|l| l.len() == 80 && &l[72..73] == "G")
        .map(|l| &l[..72])
        .collect::<Vec<_>>()
        .concat();
    // Split at the delimiter; the first parameter, `1H,`, names the delimiter itself and
    // takes two pieces, so parameter k (from 1) is piece k.
    let params: Vec<&str> = global.split(',').collect();
    // Global parameters 14 and 15: the units flag (10: centimetres) and name.
    assert_eq!(
        (params[14].trim(), params[15].trim()),
        ("10", "2HCM"),
        "{global}"
    );
    let dxf = ll("m.dxf", &["--units", "m"]);
    assert!(dxf.contains("$INSUNITS\n 70\n6\n"), "{dxf}");
    let plain = ll("plain.dxf", &[]);
    assert!(plain.contains("$INSUNITS\n 70\n0\n"));
    // --scale multiplies every coordinate: the control points of the scaled file are the
    // unit file's times the factor.
    let scaled = ll("scaled.step", &["--units", "mm", "--scale", "1000"]);
    let points = |text: &str| -> Vec<f64> {
        text.lines()
            .filter(|l| l.contains("CARTESIAN_POINT"))
            .flat_map(|l| {
                let inner = &l[l.find(",(").unwrap() + 2..l.rfind("))").unwrap()];
                inner
                    .split(',')
                    .map(|v| v.parse::<f64>().unwrap())
                    .collect::<Vec<_>>()
            })
            .collect()
    };
    let (a, b) = (points(&mm), points(&scaled));
    assert_eq!(a.len(), b.len());
    assert!(a.len() > 30);
    for (x, y) in a.iter().zip(&b) {
        assert!((x * 1000.0 - y).abs() <= 1e-9 * y.abs().max(1.0), "{x} {y}");
    }
    // The options of an output without units: refused.
    for (extra, needle) in [
        (&["--units", "m"][..], "--units: only STEP, IGES and DXF"),
        (
            &["--scale", "-2", "-o", "s.step"],
            "--scale: the factor must be positive",
        ),
        (
            &["--units", "ft", "-o", "s.step"],
            "'ft' is not a length unit",
        ),
    ] {
        let mut args = vec!["curve", "ll", "foil.csv", "-o", "s.csv"];
        args.extend_from_slice(extra);
        let o = karkas_in(dir.path(), &args);
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
        assert!(stderr(&o).contains(needle), "{}", stderr(&o));
    }
}

#[test]
fn the_default_sample_count_is_bounded_and_says_so() {
    let dir = temp_dir();
    // 20 000 points: 10 a point would be 200 000 samples, above the bound of 100 000.
    let mut text = String::from("x,y\n");
    for k in 0..20_000 {
        let t = k as f64 * 1e-3;
        text.push_str(&format!(
            "{},{}\n",
            t.cos() * (1.0 + t),
            t.sin() * (1.0 + t)
        ));
    }
    write(dir.path(), "dense.csv", &text);
    let err = run(dir.path(), &["curve", "ll", "dense.csv", "-o", "d.csv"]);
    let (_, rows) = read_csv(&dir.path().join("d.csv"));
    assert_eq!(rows.len(), 100_000);
    assert!(
        err.contains("karkas: note: 100000 samples, the default's bound (10 a point would be 200000); --samples N writes N"),
        "{err}"
    );
    // Asked for, more are written and nothing is said.
    let err = run(
        dir.path(),
        &[
            "curve",
            "ll",
            "dense.csv",
            "-o",
            "e.csv",
            "--samples",
            "200000",
        ],
    );
    let (_, rows) = read_csv(&dir.path().join("e.csv"));
    assert_eq!(rows.len(), 200_000);
    assert!(!err.contains("note"), "{err}");
}

#[test]
fn a_mesh_to_a_tolerance_reports_its_deviation() {
    let dir = temp_dir();
    // A wing-like grid: an ellipse-nosed section swept along the span.
    let grid = grid_csv(9, 33, |i, j| {
        let t = std::f64::consts::TAU * j as f64 / 32.0;
        let x = 0.5 + 0.5 * t.cos();
        [x, 0.12 * t.sin() * (1.0 - x).sqrt(), i as f64 * 0.5]
    });
    write(dir.path(), "wing.csv", &grid);
    let err = run(
        dir.path(),
        &[
            "surface",
            "bicubic",
            "wing.csv",
            "--closed-v",
            "--mesh-tolerance",
            "1e-4",
            "-o",
            "w.obj",
            "-o",
            "w.csv",
        ],
    );
    let line = err
        .lines()
        .find(|l| l.contains("w.obj"))
        .unwrap_or_else(|| panic!("{err}"));
    let deviation: f64 = line
        .split("largest deviation ")
        .nth(1)
        .and_then(|r| r.split(' ').next())
        .and_then(|v| v.parse().ok())
        .unwrap_or_else(|| panic!("{line}"));
    assert!(deviation <= 1e-4, "{line}");
    // The CSV keeps the uniform default samples.
    assert!(err.contains("w.csv (6600 samples)"), "{err}");
    for (args, needle) in [
        (
            &["--mesh-tolerance", "1e-4", "-o", "x.csv"][..],
            "--mesh-tolerance: only meshes",
        ),
        (
            &["--mesh-tolerance", "0", "-o", "x.obj"],
            "must be positive",
        ),
    ] {
        let mut all = vec!["surface", "bicubic", "wing.csv"];
        all.extend_from_slice(args);
        let o = karkas_in(dir.path(), &all);
        assert_eq!(o.status.code(), Some(2));
        assert!(stderr(&o).contains(needle), "{}", stderr(&o));
    }
}

#[test]
fn dense_input_dots_leave_the_curve_in_sight() {
    let dir = temp_dir();
    write(dir.path(), "foil.csv", &foil(301));
    run(dir.path(), &["curve", "spline", "foil.csv", "-o", "f.svg"]);
    let svg = std::fs::read_to_string(dir.path().join("f.svg")).unwrap();
    // The curve is drawn after (over) the dots.
    let dots = svg.find("class=\"input\"").unwrap();
    let curve = svg.find("class=\"curve\"").unwrap();
    assert!(dots < curve, "the dots are drawn over the curve");
    // Every dot is smaller than the gap to its neighbour: the curve shows between them.
    let group = &svg[dots..];
    let group = &group[..group.find("</g>").unwrap()];
    let circles: Vec<(f64, f64, f64)> = group
        .split("<circle ")
        .skip(1)
        .map(|c| {
            let attr = |name: &str| -> f64 {
                let at = c.find(&format!("{name}=\"")).unwrap() + name.len() + 2;
                c[at..at + c[at..].find('"').unwrap()].parse().unwrap()
            };
            (attr("cx"), attr("cy"), attr("r"))
        })
        .collect();
    assert_eq!(circles.len(), 301);
    let mut gaps: Vec<f64> = circles
        .windows(2)
        .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
        .filter(|g| *g > 0.0)
        .collect();
    gaps.sort_by(f64::total_cmp);
    let median = gaps[gaps.len() / 2];
    let r = circles[0].2;
    assert!(
        2.0 * r < median,
        "dots of radius {r} over a median gap of {median}"
    );
    // The title says what is drawn.
    assert!(svg.contains("cubic spline, not-a-knot ends"), "title");
}

//! The CLI contract of `karkas curve fit` (issue 12): options, CSV headers, and exit code 2
//! with no output on bad knots.

use crate::common::{karkas, s, stderr, temp_dir, write};

/// A noisy arc of 30 points.
fn arc() -> String {
    let mut text = String::from("x,y\n");
    for i in 0..30 {
        let a = 2.0 * i as f64 / 29.0;
        let wobble = 0.003 * ((i * 7919) % 13) as f64 / 13.0;
        text.push_str(&format!(
            "{},{}\n",
            (1.0 + wobble) * a.cos(),
            (1.0 + wobble) * a.sin()
        ));
    }
    text
}

#[test]
fn csv_output_and_deviation_report() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let out = dir.path().join("fit.csv");
    let dev = dir.path().join("dev.csv");
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--knots",
        "0,0.3,0.7,1",
        "--eps",
        "0.01",
        "-o",
        s(&out),
        "--report",
        s(&dev),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("t,x,y\n"));
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows[0][0], 0.0);
    assert_eq!(rows[rows.len() - 1][0], 1.0);
    let report = std::fs::read_to_string(&dev).unwrap();
    let mut lines = report.lines();
    assert_eq!(lines.next(), Some("point,t,distance"));
    let dev: Vec<Vec<f64>> = lines
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    assert_eq!(dev.len(), 30);
    assert_eq!(dev[0][0], 1.0);
    assert!(dev
        .iter()
        .all(|r| r[2] >= 0.0 && r[2] < 0.01 && (0.0..=1.0).contains(&r[1])));
}

#[test]
fn pinned_ends_start_and_end_at_the_first_and_last_points() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let first: Vec<f64> = arc()
        .lines()
        .nth(1)
        .unwrap()
        .split(',')
        .map(|f| f.parse().unwrap())
        .collect();
    let last: Vec<f64> = arc()
        .lines()
        .last()
        .unwrap()
        .split(',')
        .map(|f| f.parse().unwrap())
        .collect();
    let out = dir.path().join("fit.csv");
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--knots",
        "0,0.5,1",
        "--pin-ends",
        "--samples",
        "7",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    let rows: Vec<Vec<f64>> = text
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(|f| f.parse().unwrap()).collect())
        .collect();
    assert_eq!(rows.len(), 7);
    let (start, end) = (&rows[0], &rows[rows.len() - 1]);
    assert_eq!((start[0], end[0]), (0.0, 1.0));
    for c in 0..2 {
        assert!(
            (start[c + 1] - first[c]).abs() < 1e-12,
            "{start:?} vs {first:?}"
        );
        assert!((end[c + 1] - last[c]).abs() < 1e-12, "{end:?} vs {last:?}");
    }
}

#[test]
fn svg_output_with_tolerance() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let out = dir.path().join("fit.svg");
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--tolerance",
        "0.005",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(svg.starts_with("<svg") && svg.contains("polyline"));
}

#[test]
fn bad_knots_are_one_line_errors_with_exit_2_and_no_output() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let out = dir.path().join("fit.csv");
    for knots in [
        "0,0.6,0.4,1",
        "0,0.5,0.5000000001,1",
        "0,0.5,1.5",
        "0.1,0.5,1",
    ] {
        let o = karkas(&["curve", "fit", s(&input), "--knots", knots, "-o", s(&out)]);
        assert_eq!(o.status.code(), Some(2), "{knots}");
        let err = stderr(&o);
        assert_eq!(err.trim_end().lines().count(), 1, "{err}");
        assert!(err.contains("knot"), "{err}");
        assert!(!out.exists());
    }
    // Too few samples.
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--knots",
        "0,1",
        "--samples",
        "1",
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!out.exists());
    // A corner that is not a knot.
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--knots",
        "0,0.5,1",
        "--eps",
        "1",
        "--corner",
        "0.3",
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!out.exists());
}

/// `--knots N` (one whole number) is N uniform knots, as Python's `fit_curve(knots=N)`; a
/// count below 2 or a fraction is refused.
#[test]
fn one_number_of_knots_is_a_count() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let (by_count, by_list) = (dir.path().join("n.csv"), dir.path().join("l.csv"));
    for (knots, out) in [("5", &by_count), ("0,0.25,0.5,0.75,1", &by_list)] {
        let o = karkas(&["curve", "fit", s(&input), "--knots", knots, "-o", s(out)]);
        assert!(o.status.success(), "{knots}: {}", stderr(&o));
    }
    let (a, b) = (
        std::fs::read_to_string(&by_count).unwrap(),
        std::fs::read_to_string(&by_list).unwrap(),
    );
    assert_eq!(a, b);
    for bad in ["1", "2.5", "0"] {
        let out = dir.path().join("bad.csv");
        let o = karkas(&["curve", "fit", s(&input), "--knots", bad, "-o", s(&out)]);
        assert_eq!(o.status.code(), Some(2), "{bad}");
        assert!(stderr(&o).contains("--knots"), "{}", stderr(&o));
        assert!(!out.exists());
    }
}

/// `--fairness` is passed to the fit: 0 and the default give different curves, and a
/// negative weight is refused.
#[test]
fn fairness_option() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let (default, none) = (dir.path().join("d.csv"), dir.path().join("z.csv"));
    let run = |extra: &[&str], out: &std::path::Path| {
        let mut argv = vec!["curve", "fit", s(&input), "--knots", "6"];
        argv.extend_from_slice(extra);
        argv.extend(["-o", s(out)]);
        karkas(&argv)
    };
    assert!(run(&[], &default).status.success());
    assert!(run(&["--fairness", "0"], &none).status.success());
    assert_ne!(
        std::fs::read_to_string(&default).unwrap(),
        std::fs::read_to_string(&none).unwrap()
    );
    let o = run(&["--fairness", "-1"], &dir.path().join("bad.csv"));
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn a_huge_knot_count_is_refused_before_anything_is_allocated() {
    // `--knots N` is a count of uniform knots; a billion of them is refused by the memory
    // cap (exit 2, one line), not attempted (it aborted on the allocation).
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let out = dir.path().join("fit.csv");
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--knots",
        "1000000000",
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    let err = stderr(&o);
    assert_eq!(err.trim_end().lines().count(), 1, "{err}");
    assert!(
        err.contains("--knots 1000000000") && err.contains("memory"),
        "{err}"
    );
    assert!(!out.exists());
    // A modest count works.
    let o = karkas(&["curve", "fit", s(&input), "--knots", "6", "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(0), "{}", stderr(&o));
    assert!(out.exists());
}

#[test]
fn shape_warnings_are_printed_with_their_place() {
    // 30 points on an arc; the knots 0.5 and 0.5001 leave a span with no point in it.
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let out = dir.path().join("fit.csv");
    let o = karkas(&[
        "curve",
        "fit",
        s(&input),
        "--knots",
        "0,0.25,0.5,0.5001,0.75,1",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let line = err
        .lines()
        .find(|l| l.starts_with("karkas: warning: the knot span 3 holds no point"))
        .unwrap_or_else(|| panic!("{err}"));
    assert!(line.contains("t = 0.5..0.5001"), "{line}");
    assert!(
        !err.contains("crosses itself") && !err.contains(" rad"),
        "{err}"
    );
}

/// The figure after `name = ` in the fit's summary line.
fn summary_figure(text: &str, name: &str) -> f64 {
    let at = text.find(&format!("{name} = ")).expect(name) + name.len() + 3;
    text[at..]
        .split([',', ' '])
        .next()
        .unwrap()
        .parse()
        .unwrap()
}

#[test]
fn penalty_rules_meet_the_bound_actively_or_by_the_paper() {
    let dir = temp_dir();
    let input = write(dir.path(), "arc.csv", &arc());
    let out = dir.path().join("f.csv");
    let eps = 1e-4;
    let fit = |rule: &str| {
        let o = karkas(&[
            "curve",
            "fit",
            "--knots",
            "0,0.3,0.5,0.7,1",
            "--eps",
            "1e-4",
            "--penalty",
            rule,
            s(&input),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{rule}: {}", stderr(&o));
        (
            summary_figure(&stderr(&o), "f"),
            summary_figure(&stderr(&o), "p"),
        )
    };
    // The active bound: f within 1e-3 of eps (the constrained optimum).
    let (f_active, p_active) = fit("active");
    assert!(
        f_active <= eps && f_active >= (1.0 - 1e-3) * eps,
        "{f_active}"
    );
    // The paper's rule: p = H(q*) / eps, raised tenfold until f <= eps: a larger p, and f
    // below the bound.
    let (f_paper, p_paper) = fit("paper");
    assert!(f_paper <= eps, "{f_paper}");
    assert!(p_paper > p_active, "{p_paper} vs {p_active}");
    assert!(f_paper < f_active, "{f_paper} vs {f_active}");
    let o = karkas(&[
        "curve",
        "fit",
        "--knots",
        "5",
        "--penalty",
        "soft",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--penalty"), "{}", stderr(&o));
}

/// `curve fit --json` of the paper's hydrofoil on its knots with `extra` options.
fn hydrofoil_fit(extra: &[&str]) -> std::process::Output {
    let input = concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../data/hydrofoil-profile.csv"
    );
    let dir = temp_dir();
    let out = dir.path().join("f.csv");
    let mut args = vec![
        "curve",
        "fit",
        "--knots",
        "0,0.445,0.449,0.587,1",
        "--eps",
        "0.01",
        "--penalty",
        "paper",
        "--json",
        input,
        "-o",
        s(&out),
    ];
    args.extend_from_slice(extra);
    karkas(&args)
}

#[test]
fn more_starts_keep_a_sound_fit_no_worse_than_chord_length() {
    let figures = |extra: &[&str]| {
        let o = hydrofoil_fit(extra);
        assert!(o.status.success(), "{extra:?}: {}", stderr(&o));
        let v: serde_json::Value =
            serde_json::from_str(&String::from_utf8_lossy(&o.stdout)).unwrap();
        let crossing = v["warnings"]
            .as_array()
            .unwrap()
            .iter()
            .any(|w| w.to_string().contains("cross"));
        (v["rms_deviation"].as_f64().unwrap(), crossing)
    };
    let (one, _) = figures(&[]);
    let (explicit_one, _) = figures(&["--starts", "1"]);
    assert_eq!(one.to_bits(), explicit_one.to_bits());
    let (eight, crossing) = figures(&["--starts", "8"]);
    assert!(eight <= one * (1.0 + 1e-12), "{eight} vs {one}");
    assert!(!crossing);
}

#[test]
fn a_bad_number_of_starts_is_refused_naming_the_option() {
    for extra in [
        &["--starts", "0"][..],
        &["--starts", "9"][..],
        &["--starts", "x"][..],
    ] {
        let o = hydrofoil_fit(extra);
        assert_eq!(o.status.code(), Some(2), "{extra:?}");
        assert!(stderr(&o).contains("--starts"), "{extra:?}: {}", stderr(&o));
    }
}

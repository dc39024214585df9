//! `karkas curve analyze`: the JSON keys, the order of the curvature extrema counts of the
//! three methods on an analytic section (NACA 0012), the methods side by side on the
//! repository's hydrofoil profile, the curvature CSV and plot, and bad input refused with
//! exit code 2.

use crate::common::{karkas, s, stderr, stdout, temp_dir, write};
use serde_json::Value;
use std::f64::consts::PI;

/// The seven figures every method reports.
const KEYS: [&str; 7] = [
    "length",
    "curvature_min",
    "curvature_max",
    "curvature_extrema",
    "inflections",
    "max_distance_to_polygon",
    "fairness_energy",
];

/// NACA 0012 (closed trailing-edge coefficient form), `n` cosine-spaced stations per
/// surface: from the trailing edge over the upper surface round the nose and back below.
fn naca0012(n: usize) -> String {
    let thickness = |x: f64| {
        5.0 * 0.12
            * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                - 0.1036 * x.powi(4))
    };
    let xs: Vec<f64> = (0..n)
        .map(|i| 0.5 * (1.0 - (PI * i as f64 / (n - 1) as f64).cos()))
        .collect();
    let mut text = String::from("x,y\n");
    for &x in xs.iter().rev() {
        text += &format!("{x},{}\n", thickness(x));
    }
    for &x in &xs[1..] {
        text += &format!("{x},{}\n", -thickness(x));
    }
    text
}

/// The JSON object printed by `args`, which must succeed.
fn analyze_json(args: &[&str]) -> Value {
    let mut all = vec!["curve", "analyze", "--json"];
    all.extend_from_slice(args);
    let o = karkas(&all);
    assert!(o.status.success(), "{}", stderr(&o));
    serde_json::from_str(&stdout(&o)).unwrap()
}

/// The curvature extrema count of `method` in `json`.
fn extrema(json: &Value, method: &str) -> u64 {
    json[method]["curvature_extrema"].as_u64().unwrap()
}

#[test]
fn json_has_one_object_per_method_with_the_seven_keys() {
    let dir = temp_dir();
    let input = write(dir.path(), "naca.csv", &naca0012(40));
    let json = analyze_json(&[s(&input)]);
    let object = json.as_object().unwrap();
    assert_eq!(
        object.keys().collect::<Vec<_>>(),
        ["spline"],
        "spline by default"
    );
    let json = analyze_json(&[s(&input), "--compare", "ll,fit", "--knots", "6"]);
    for method in ["ll", "fit"] {
        for key in KEYS {
            assert!(json[method][key].is_number(), "{method}.{key}: {json}");
        }
        assert_eq!(json[method]["points"], 79);
    }
    assert!(json.get("spline").is_none());
    // The polygon's length is a lower bound of every curve near it.
    let polygon: f64 = {
        let text = naca0012(40);
        let pts: Vec<[f64; 2]> = text
            .lines()
            .skip(1)
            .map(|l| {
                let mut f = l.split(',').map(|v| v.parse::<f64>().unwrap());
                [f.next().unwrap(), f.next().unwrap()]
            })
            .collect();
        pts.windows(2)
            .map(|w| (w[1][0] - w[0][0]).hypot(w[1][1] - w[0][1]))
            .sum()
    };
    let length = json["fit"]["length"].as_f64().unwrap();
    assert!(
        length > polygon && length < polygon * 1.01,
        "{length} {polygon}"
    );
}

#[test]
fn extrema_order_fit_spline_ll_on_naca_0012() {
    let dir = temp_dir();
    let input = write(dir.path(), "naca.csv", &naca0012(40));
    let json = analyze_json(&[s(&input), "--compare", "ll,spline,fit", "--knots", "6"]);
    let (ll, spline, fit) = (
        extrema(&json, "ll"),
        extrema(&json, "spline"),
        extrema(&json, "fit"),
    );
    assert!(
        fit <= spline && spline < ll,
        "fit {fit}, spline {spline}, ll {ll}"
    );
    // The exact section's curvature has its maximum at the nose and one minimum on each
    // surface (at x = 0.775, from the closed form); a dip of the exact curve within 4.5e-5
    // chord of the nose is far below the points' spacing (4e-4 there).
    assert_eq!(spline, 3, "{json}");
    // A symmetric convex section: no inflection, curvature peak at the nose near 1 / r_LE
    // (r_LE = 1.1019 t^2 = 0.01587 chord).
    for method in ["spline", "fit"] {
        assert_eq!(json[method]["inflections"], 0, "{method}");
        let k = json[method]["curvature_max"].as_f64().unwrap();
        assert!((k * 1.1019 * 0.0144 - 1.0).abs() < 0.1, "{method}: {k}");
    }
}

#[test]
fn compare_on_the_repository_hydrofoil() {
    // The hydrofoil of Pavlov's paper as the repository ships it (x, y; the paper's deviation
    // column left out), fitted on the paper's knots and bound.
    let shipped = std::fs::read_to_string(concat!(
        env!("CARGO_MANIFEST_DIR"),
        "/../../data/hydrofoil-profile.csv"
    ))
    .unwrap();
    let xy: String = shipped
        .lines()
        .filter(|l| !l.starts_with('#'))
        .map(|l| l.split(',').take(2).collect::<Vec<_>>().join(",") + "\n")
        .collect();
    let dir = temp_dir();
    let input = write(dir.path(), "hydrofoil.csv", &xy);
    let args = [
        "curve",
        "analyze",
        s(&input),
        "--compare",
        "ll,spline,fit",
        "--knots",
        "0,0.445,0.449,0.587,1",
        "--eps",
        "0.01",
    ];
    let o = karkas(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let table = stdout(&o);
    let rows: Vec<&str> = table.lines().collect();
    assert_eq!(rows.len(), 4, "{table}");
    assert!(rows[0].contains("extrema") && rows[0].contains("inflections"));
    for (row, method) in rows[1..].iter().zip(["ll", "spline", "fit"]) {
        assert!(row.starts_with(method), "{table}");
    }
    let json = analyze_json(&args[2..]);
    let (ll, spline, fit) = (
        extrema(&json, "ll"),
        extrema(&json, "spline"),
        extrema(&json, "fit"),
    );
    assert!(
        fit <= spline && spline < ll,
        "fit {fit}, spline {spline}, ll {ll}"
    );
}

#[test]
fn a_closed_circle_has_the_circle_s_curvature() {
    let (r, n) = (2.0f64, 24);
    let mut text = String::from("x,y\n");
    for i in 0..n {
        let a = 2.0 * PI * i as f64 / n as f64;
        text += &format!("{},{}\n", 1.0 + r * a.cos(), r * a.sin());
    }
    let dir = temp_dir();
    let input = write(dir.path(), "circle.csv", &text);
    let json = analyze_json(&[
        s(&input),
        "--closed",
        "--compare",
        "spline,ll",
        "--interpolate",
    ]);
    for method in ["spline", "ll"] {
        let f = &json[method];
        let length = f["length"].as_f64().unwrap();
        // Within the chord polygon's shortfall (1 - cos(pi / n) ~ 0.86%) of the circle.
        assert!(
            (length / (2.0 * PI * r) - 1.0).abs() < 3e-3,
            "{method}: {length}"
        );
        assert_eq!(f["inflections"], 0, "{method}");
        let (lo, hi) = (
            f["curvature_min"].as_f64().unwrap(),
            f["curvature_max"].as_f64().unwrap(),
        );
        if method == "spline" {
            assert!(lo > 0.99 / r && hi < 1.01 / r, "{method}: {lo} {hi}");
        } else {
            // The LL curve's curvature swings between 0 at the vertices and about twice the
            // circle's between them.
            assert!(
                lo > -1e-9 / r && lo < 0.1 / r && hi > 1.5 / r && hi < 2.1 / r,
                "{lo} {hi}"
            );
        }
        // Every vertex lies on the curve: the spline bulges out of the chords by about the
        // circle's sagitta, the LL curve (straighter near the vertices) by less.
        let sagitta = r * (1.0 - (PI / n as f64).cos());
        let d = f["max_distance_to_polygon"].as_f64().unwrap();
        if method == "spline" {
            assert!((d / sagitta - 1.0).abs() < 0.02, "{method}: {d} {sagitta}");
        } else {
            assert!(d > 0.3 * sagitta && d < sagitta, "{method}: {d} {sagitta}");
        }
        // Closed: the extrema go round, so they come in pairs.
        assert_eq!(f["curvature_extrema"].as_u64().unwrap() % 2, 0, "{method}");
    }
}

#[test]
fn curvature_csv_and_plots() {
    let dir = temp_dir();
    let input = write(dir.path(), "naca.csv", &naca0012(30));
    let csv = dir.path().join("k.csv");
    let o = karkas(&[
        "curve",
        "analyze",
        s(&input),
        "--compare",
        "ll,spline",
        "-o",
        s(&csv),
        "--json",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let json: Value = serde_json::from_str(&stdout(&o)).unwrap();
    let text = std::fs::read_to_string(&csv).unwrap();
    assert_eq!(text.lines().next(), Some("method,t,s,curvature"));
    for method in ["ll", "spline"] {
        let rows: Vec<Vec<f64>> = text
            .lines()
            .skip(1)
            .filter(|l| l.starts_with(&format!("{method},")))
            .map(|l| l.split(',').skip(1).map(|v| v.parse().unwrap()).collect())
            .collect();
        assert!(rows.len() > 100, "{method}");
        assert_eq!(rows[0][1], 0.0);
        assert!(rows
            .windows(2)
            .all(|w| w[1][0] >= w[0][0] && w[1][1] >= w[0][1]));
        let length = json[method]["length"].as_f64().unwrap();
        let last = rows[rows.len() - 1][1];
        assert!(
            (last - length).abs() < 1e-8 * length,
            "{method}: {last} {length}"
        );
        let k_max = rows.iter().map(|r| r[2]).fold(f64::MIN, f64::max);
        let reported = json[method]["curvature_max"].as_f64().unwrap();
        assert!(
            k_max <= reported * (1.0 + 1e-9) && k_max > 0.9 * reported,
            "{method}"
        );
    }
    let svg = dir.path().join("k.svg");
    let o = karkas(&[
        "curve",
        "analyze",
        s(&input),
        "--compare",
        "ll,spline",
        "-o",
        s(&svg),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let picture = std::fs::read_to_string(&svg).unwrap();
    assert!(picture.contains("ll (") && picture.contains("spline ("));
    assert!(picture.contains("arc length"));
    let png = dir.path().join("k.png");
    let o = karkas(&["curve", "analyze", s(&input), "-o", s(&png)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
}

#[test]
fn bad_input_exits_2_naming_the_problem() {
    let dir = temp_dir();
    let input = write(dir.path(), "naca.csv", &naca0012(20));
    let missing = dir.path().join("missing.csv");
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (vec![s(&missing)], "missing.csv"),
        (vec![s(&input), "--compare", "ll,bezier"], "bezier"),
        (
            vec![s(&input), "--closed", "--compare", "ll,fit"],
            "--closed",
        ),
        (
            vec![s(&input), "--method", "spline", "--knots", "5"],
            "--knots",
        ),
        (
            vec![s(&input), "--method", "ll", "--ends", "natural"],
            "--ends",
        ),
        (vec![s(&input), "--order", "0", "--method", "ll"], "--order"),
        (
            vec![s(&input), "--method", "fit", "--knots", "0,0.5,0.4,1"],
            "--knots",
        ),
        (
            vec![s(&input), "--compare", "spline,fit", "--ends", "periodic"],
            "--ends periodic: the fit makes open curves only",
        ),
        (vec![s(&input), "-o", "k.txt"], "txt"),
        (vec![s(&input), "-o", s(&input)], "naca.csv"),
        (
            vec![s(&input), "--method", "ll", "--compare", "ll"],
            "--compare",
        ),
    ];
    for (args, needle) in cases {
        let mut all = vec!["curve", "analyze"];
        all.extend_from_slice(&args);
        let o = karkas(&all);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", stderr(&o));
        assert!(stderr(&o).contains(needle), "{args:?}: {}", stderr(&o));
        assert!(!stderr(&o).contains("panicked"), "{args:?}");
    }
    assert!(!dir.path().join("k.txt").exists());
    // Periodic ends say the curve is closed: the same figures as --closed.
    let periodic = karkas(&[
        "curve",
        "analyze",
        s(&input),
        "--ends",
        "periodic",
        "--json",
    ]);
    let closed = karkas(&["curve", "analyze", s(&input), "--closed", "--json"]);
    assert_eq!(periodic.status.code(), Some(0), "{}", stderr(&periodic));
    let figures = |o: &std::process::Output| {
        let v: serde_json::Value = serde_json::from_slice(&o.stdout).unwrap();
        v["spline"].clone()
    };
    assert_eq!(figures(&periodic), figures(&closed));
    let one = write(dir.path(), "one.csv", "x,y\n1,2\n");
    let o = karkas(&["curve", "analyze", s(&one)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
}

//! The CLI contract of `karkas curve spline`, against figures found without the program:
//! cubic polynomials the not-a-knot and clamped splines reproduce, the natural spline's closed
//! form on three points, the parameter formulas, a circle closed C^2 by periodic ends, the
//! STEP file's knot vector, and exit code 2 with no output on bad input. (SciPy's
//! `CubicSpline` checks the natural and clamped ends on more points in
//! crates/karkas-py/tests/test_cli_spline_scipy.py.)

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::Path;

/// Runs `karkas curve spline` with `options` on `input`, writing `out`; its CSV rows.
fn spline_csv(input: &Path, out: &Path, options: &[&str]) -> (Vec<String>, Vec<Vec<f64>>) {
    let mut args = vec!["curve", "spline", s(input), "-o", s(out)];
    args.extend_from_slice(options);
    let o = karkas(&args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    read_csv(out)
}

/// The points `f(t)` at `ts` as a CSV text with header x,y or x,y,z.
fn points_csv<const D: usize>(ts: &[f64], f: impl Fn(f64) -> [f64; D]) -> String {
    let mut text = String::from(if D == 2 { "x,y\n" } else { "x,y,z\n" });
    for &t in ts {
        let p = f(t);
        let fields: Vec<String> = p.iter().map(|v| format!("{v:e}")).collect();
        text.push_str(&fields.join(","));
        text.push('\n');
    }
    text
}

/// Asserts every CSV row `t,x,y[,z]` lies on `f(t)` within `tol` times the largest value.
fn assert_rows_on<const D: usize>(rows: &[Vec<f64>], f: impl Fn(f64) -> [f64; D], tol: f64) {
    let scale = rows
        .iter()
        .flat_map(|r| r[1..].iter())
        .fold(1.0f64, |m, v| m.max(v.abs()));
    for row in rows {
        assert_eq!(row.len(), D + 1, "{row:?}");
        let p = f(row[0]);
        for c in 0..D {
            assert!(
                (row[1 + c] - p[c]).abs() <= tol * scale,
                "t = {}: {row:?} against {p:?}",
                row[0]
            );
        }
    }
}

/// A planar cubic and its derivative.
fn cubic(t: f64) -> [f64; 2] {
    [
        1.0 + 2.0 * t - t * t + 0.5 * t * t * t,
        -1.0 - 3.0 * t + t * t * t,
    ]
}

fn cubic_slope(t: f64) -> [f64; 2] {
    [2.0 - 2.0 * t + 1.5 * t * t, -3.0 + 3.0 * t * t]
}

/// A spatial cubic.
fn cubic3(t: f64) -> [f64; 3] {
    let [x, y] = cubic(t);
    [x, y, 0.25 * t * t * t - t]
}

#[test]
fn not_a_knot_reproduces_a_cubic_sampled_at_uniform_parameters() {
    let dir = temp_dir();
    let ts: Vec<f64> = (0..7).map(f64::from).collect();
    let input = write(dir.path(), "p.csv", &points_csv(&ts, cubic));
    let out = dir.path().join("s.csv");
    let (header, rows) = spline_csv(&input, &out, &["--param", "uniform", "--samples", "61"]);
    assert_eq!(header, ["t", "x", "y"]);
    assert_eq!(rows.len(), 61);
    assert_eq!((rows[0][0], rows[60][0]), (0.0, 6.0));
    assert_rows_on(&rows, cubic, 1e-12);
    // The default end conditions are not-a-knot.
    let (_, explicit) = spline_csv(
        &input,
        &out,
        &[
            "--param",
            "uniform",
            "--samples",
            "61",
            "--ends",
            "not-a-knot",
        ],
    );
    assert_eq!(explicit, rows);

    let input = write(dir.path(), "p3.csv", &points_csv(&ts, cubic3));
    let (header, rows) = spline_csv(&input, &out, &["--param", "uniform", "--samples", "37"]);
    assert_eq!(header, ["t", "x", "y", "z"]);
    assert_rows_on(&rows, cubic3, 1e-12);
}

#[test]
fn clamped_with_the_cubics_end_slopes_reproduces_it() {
    let dir = temp_dir();
    let ts: Vec<f64> = (0..5).map(f64::from).collect();
    let input = write(dir.path(), "p.csv", &points_csv(&ts, cubic));
    let out = dir.path().join("s.csv");
    let [a, b] = cubic_slope(0.0);
    let [c, d] = cubic_slope(4.0);
    let (start, end) = (format!("{a},{b}"), format!("{c},{d}"));
    let options = [
        "--param",
        "uniform",
        "--ends",
        "clamped",
        "--start-tangent",
        &start,
        "--end-tangent",
        &end,
        "--samples",
        "41",
    ];
    let (_, rows) = spline_csv(&input, &out, &options);
    assert_rows_on(&rows, cubic, 1e-12);
    // Other end slopes give another curve: the check above can fail.
    let (_, other) = spline_csv(
        &input,
        &out,
        &[
            "--param",
            "uniform",
            "--ends",
            "clamped",
            "--start-tangent=-5,0",
            "--end-tangent",
            &end,
        ],
    );
    let [x, _] = cubic(0.5);
    let near = other.iter().find(|r| (r[0] - 0.5).abs() < 0.01).unwrap();
    assert!((near[1] - x).abs() > 1e-3, "{near:?}");
}

/// Through (0, y0), (1, y1), (2, y2) at t = 0, 1, 2 the natural spline has second derivative
/// M = 3/2 (y0 - 2 y1 + y2) at t = 1 and 0 at the ends: on [0, 1] it is
/// y0 (1 - t) + y1 t + M / 6 (t^3 - t), on [1, 2] the mirror image.
#[test]
fn natural_matches_its_closed_form_on_three_points() {
    let dir = temp_dir();
    let ys = [[0.0, 1.0], [2.0, -1.0], [3.0, 4.0]];
    let ts = [0.0, 1.0, 2.0];
    let input = write(dir.path(), "p.csv", &points_csv(&ts, |t| ys[t as usize]));
    let out = dir.path().join("s.csv");
    let options = ["--param", "uniform", "--ends", "natural", "--samples", "21"];
    let (_, rows) = spline_csv(&input, &out, &options);
    let closed_form = |t: f64| {
        let mut p = [0.0; 2];
        for (c, slot) in p.iter_mut().enumerate() {
            let (y0, y1, y2) = (ys[0][c], ys[1][c], ys[2][c]);
            let m = 1.5 * (y0 - 2.0 * y1 + y2);
            *slot = if t <= 1.0 {
                y0 * (1.0 - t) + y1 * t + m / 6.0 * (t * t * t - t)
            } else {
                let u = 2.0 - t;
                y2 * (1.0 - u) + y1 * u + m / 6.0 * (u * u * u - u)
            };
        }
        p
    };
    assert_rows_on(&rows, closed_form, 1e-13);
}

/// Chord lengths 1, 4, 9, 16: chord parameters 0, 1, 5, 14, 30 and centripetal ones 0, 1, 3,
/// 6, 10, so that the samples at whole t fall on the knots.
#[test]
fn chord_and_centripetal_parameters_follow_their_formulas() {
    let dir = temp_dir();
    let pts = [
        [0.0, 0.0],
        [1.0, 0.0],
        [1.0, 4.0],
        [10.0, 4.0],
        [10.0, -12.0],
    ];
    let text = points_csv(&[0.0, 1.0, 2.0, 3.0, 4.0], |t| pts[t as usize]);
    let input = write(dir.path(), "p.csv", &text);
    let out = dir.path().join("s.csv");
    for (param, knots) in [
        ("chord", [0.0, 1.0, 5.0, 14.0, 30.0]),
        ("centripetal", [0.0, 1.0, 3.0, 6.0, 10.0]),
        ("uniform", [0.0, 1.0, 2.0, 3.0, 4.0]),
    ] {
        let n = knots[4] as usize + 1;
        let samples = n.to_string();
        let mut options = vec!["--samples", &samples];
        if param != "chord" {
            // Chord parameters are the default.
            options.extend_from_slice(&["--param", param]);
        }
        let (_, rows) = spline_csv(&input, &out, &options);
        assert_eq!(rows.len(), n);
        for (k, &t) in knots.iter().enumerate() {
            let row = &rows[t as usize];
            assert!((row[0] - t).abs() < 1e-12, "{param}: {row:?}");
            for c in 0..2 {
                assert!(
                    (row[1 + c] - pts[k][c]).abs() < 1e-12,
                    "{param}: knot {k}: {row:?}"
                );
            }
        }
    }
}

/// The second derivative of coordinate `c` by one-sided differences of second order at the
/// first (`forward`) or the last of `rows`, spaced `h` apart.
fn one_sided_second(rows: &[Vec<f64>], h: f64, c: usize, forward: bool) -> f64 {
    let at = |k: usize| {
        if forward {
            rows[k][1 + c]
        } else {
            rows[rows.len() - 1 - k][1 + c]
        }
    };
    (2.0 * at(0) - 5.0 * at(1) + 4.0 * at(2) - at(3)) / (h * h)
}

/// The first derivative likewise.
fn one_sided_first(rows: &[Vec<f64>], h: f64, c: usize, forward: bool) -> f64 {
    let at = |k: usize| {
        if forward {
            rows[k][1 + c]
        } else {
            rows[rows.len() - 1 - k][1 + c]
        }
    };
    let d = (-3.0 * at(0) + 4.0 * at(1) - at(2)) / (2.0 * h);
    if forward {
        d
    } else {
        -d
    }
}

#[test]
fn periodic_closes_a_circle_c2_across_the_seam() {
    let dir = temp_dir();
    let k = 12;
    let angles: Vec<f64> = (0..k)
        .map(|i| std::f64::consts::TAU * f64::from(i) / f64::from(k))
        .collect();
    let ring = |a: f64| [2.0 * a.cos(), 2.0 * a.sin()];
    let open = write(dir.path(), "ring.csv", &points_csv(&angles, ring));
    let mut repeated = angles.clone();
    repeated.push(0.0);
    let closed = write(dir.path(), "closed.csv", &points_csv(&repeated, ring));
    let out = dir.path().join("s.csv");
    let n = 20001;
    let samples = n.to_string();
    let (_, rows) = spline_csv(&open, &out, &["--ends", "periodic", "--samples", &samples]);
    // The first point is appended: the same curve as from the points with it repeated.
    let (_, same) = spline_csv(
        &closed,
        &out,
        &["--ends", "periodic", "--samples", &samples],
    );
    assert_eq!(rows, same);
    let last = &rows[n - 1];
    assert!((last[1] - rows[0][1]).abs() < 1e-12 && (last[2] - rows[0][2]).abs() < 1e-12);
    // The period: 12 chords of the circle of radius 2.
    let chord = 2.0 * 2.0 * (std::f64::consts::PI / f64::from(k)).sin();
    assert!((last[0] - 12.0 * chord).abs() < 1e-12, "{last:?}");
    let h = last[0] / (n - 1) as f64;
    for c in 0..2 {
        let (d1_start, d1_end) = (
            one_sided_first(&rows, h, c, true),
            one_sided_first(&rows, h, c, false),
        );
        assert!((d1_start - d1_end).abs() < 1e-6, "P' {d1_start} {d1_end}");
        let (d2_start, d2_end) = (
            one_sided_second(&rows, h, c, true),
            one_sided_second(&rows, h, c, false),
        );
        assert!((d2_start - d2_end).abs() < 1e-4, "P'' {d2_start} {d2_end}");
    }
    // Near the circle everywhere; the second derivative near the circle's 1/2 (chord
    // parameters close to arc length).
    assert!(rows.iter().all(|r| (r[1].hypot(r[2]) - 2.0).abs() < 2e-3));
    let d2 = one_sided_second(&rows, h, 0, true);
    assert!((d2 + 0.5).abs() < 0.05, "{d2}");

    // Natural ends on the same closed data have zero second derivative at the ends (the
    // measure above tells the two apart).
    let (_, natural) = spline_csv(&closed, &out, &["--ends", "natural", "--samples", &samples]);
    let d2 = one_sided_second(&natural, h, 0, true);
    assert!(d2.abs() < 1e-3, "{d2}");
}

#[test]
fn step_and_iges_hold_the_c2_cubic_b_spline() {
    let dir = temp_dir();
    let input = write(dir.path(), "p.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n4,0\n");
    let out = dir.path().join("c.step");
    let o = karkas(&["curve", "spline", s(&input), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("degree 3, 7 control points"),
        "{}",
        stderr(&o)
    );
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.starts_with("ISO-10303-21;"));
    let curve = text
        .lines()
        .find(|l| l.contains("=B_SPLINE_CURVE_WITH_KNOTS("))
        .unwrap();
    // Degree 3, C^2: end knots of multiplicity 4 and the 3 inner knots simple.
    assert!(curve.contains(",3,(#"), "{curve}");
    assert!(curve.contains(",(4,1,1,1,4),("), "{curve}");
    let out = dir.path().join("c.igs");
    let o = karkas(&[
        "curve",
        "spline",
        s(&input),
        "-o",
        s(&out),
        "--ends",
        "natural",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert!(text.lines().all(|l| l.len() == 80));
    assert!(text.lines().any(|l| l.starts_with("126,6,3,")), "{text}");
}

#[test]
fn pictures_and_viewer_page_are_written() {
    let dir = temp_dir();
    let input = write(dir.path(), "p.csv", "x,y,z\n0,0,0\n1,2,1\n2,1,0\n3,3,2\n");
    for name in ["c.svg", "c.png", "c.html"] {
        let out = dir.path().join(name);
        let o = karkas(&[
            "curve",
            "spline",
            s(&input),
            "-o",
            s(&out),
            "--comb",
            "--whiskers",
            "--ends",
            "periodic",
        ]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert!(std::fs::metadata(&out).unwrap().len() > 100, "{name}");
    }
}

#[test]
fn bad_input_is_refused_naming_the_problem() {
    let dir = temp_dir();
    let input = write(dir.path(), "p.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n");
    let out = dir.path().join("s.csv");
    let run = |extra: &[&str], needles: &[&str]| {
        let mut args = vec!["curve", "spline", s(&input), "-o", s(&out)];
        args.extend_from_slice(extra);
        assert_rejected(&args, needles, &out, None);
    };
    run(&["--ends", "clamped"], &["--start-tangent"]);
    run(
        &["--ends", "clamped", "--start-tangent", "1,0"],
        &["--end-tangent"],
    );
    run(
        &[
            "--ends",
            "clamped",
            "--start-tangent",
            "1,0,0",
            "--end-tangent",
            "1,0,0",
        ],
        &["--start-tangent", "3 components", "2 coordinates"],
    );
    run(
        &[
            "--ends",
            "clamped",
            "--start-tangent",
            "1,nan",
            "--end-tangent",
            "1,0",
        ],
        &["--start-tangent", "nan"],
    );
    run(
        &["--start-tangent", "1,0"],
        &["--start-tangent", "--ends clamped"],
    );
    run(&["--ends", "closed"], &["--ends", "closed"]);
    run(&["--param", "arc"], &["--param", "arc"]);

    let dup = write(dir.path(), "dup.csv", "x,y\n0,0\n1,2\n1,2\n3,3\n");
    let args = ["curve", "spline", s(&dup), "-o", s(&out)];
    assert_rejected(
        &args,
        &["dup.csv", "points 2 and 3", "coincide"][..],
        &out,
        None,
    );
    let centripetal = [
        "curve",
        "spline",
        s(&dup),
        "-o",
        s(&out),
        "--param",
        "centripetal",
    ];
    assert_rejected(&centripetal, &["points 2 and 3"][..], &out, None);
    // Uniform parameters take repeated points.
    let o = karkas(&[
        "curve",
        "spline",
        s(&dup),
        "-o",
        s(&out),
        "--param",
        "uniform",
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    std::fs::remove_file(&out).unwrap();

    let one = write(dir.path(), "one.csv", "x,y\n0,0\n");
    let args = ["curve", "spline", s(&one), "-o", s(&out)];
    assert_rejected(
        &args,
        &["one.csv", "a cubic spline needs at least 2 points, got 1"][..],
        &out,
        None,
    );
    let two = write(dir.path(), "two.csv", "x,y\n0,0\n1,1\n");
    let args = [
        "curve",
        "spline",
        s(&two),
        "-o",
        s(&out),
        "--ends",
        "periodic",
    ];
    assert_rejected(&args, &["two.csv", "at least 3 points"][..], &out, None);
    let nan = write(dir.path(), "nan.csv", "x,y\n0,0\n1,nan\n2,0\n");
    let args = ["curve", "spline", s(&nan), "-o", s(&out)];
    assert_rejected(&args, &["nan.csv:3"][..], &out, None);

    // The input is never the output.
    let before = std::fs::read_to_string(&input).unwrap();
    let args = ["curve", "spline", s(&input), "-o", s(&input)];
    assert_rejected(&args, "overwrite", &input, Some(&before));
}

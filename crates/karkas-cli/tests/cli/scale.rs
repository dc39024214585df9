//! Every command at every scale (docs/reference/bad-input.md, "Scale"): data multiplied by `s` anywhere in
//! 1e-150..1e150 give the unit result times `s` (lengths), `s^0` (parameters of uniform
//! rules, counts), or another power (curvature `1/s`), to 1e-12 relative; coordinates past
//! the limits (largest magnitude above 1e152 or below 1e-152) are refused with exit 2 and a
//! message saying they are out of range.
//!
//! `curve fit` is compared exactly at power-of-two scales, where the scaled input is exact.
//! At other scales the rounding of the scaled input moves every point by up to an ulp, and
//! the fit moves with it by more than 1e-12: its iteration stops once no point's distance
//! moves by more than a millionth of the RMS distance (so on exact points, where the
//! distances are small, the shape is settled to about 1e-10 of the size), and the tolerance
//! mode decides to add and remove knots (its result moves by about 2e-11 when the unit points
//! move by one ulp). Given knots are held to [`SETTLED_FIT`] at those scales.

use crate::common::{karkas, s, stderr, stdout, temp_dir, write};
use proptest::prelude::*;
use std::path::{Path, PathBuf};

/// A wavy 3-D curve of 15 points.
fn curve_rows() -> Vec<Vec<f64>> {
    (0..15)
        .map(|k| {
            let t = 0.2 * k as f64;
            vec![
                (3.0 * t).cos() * (1.0 + 0.3 * t),
                (2.0 * t).sin() + 0.2 * t,
                0.1 * t * t,
            ]
        })
        .collect()
}

/// A 7 x 9 grid `i,j,x,y,z` of a wavy sheet.
fn grid_rows() -> Vec<Vec<f64>> {
    let mut rows = Vec::new();
    for i in 0..7 {
        for j in 0..9 {
            let (u, v) = (i as f64, j as f64);
            rows.push(vec![
                u,
                v,
                0.3 * u,
                0.2 * v + 0.01 * u * u,
                (0.4 * u).sin() * (0.3 * v).cos(),
            ]);
        }
    }
    rows
}

/// A Gordon network `curve,x,y,z`: three u-curves and three v-curves of a saddle.
fn network_rows() -> (Vec<Vec<f64>>, Vec<Vec<f64>>) {
    let f = |u: f64, v: f64| [2.0 * u, 2.0 * v, u * v + 0.1 * u * u];
    let mut u_rows = Vec::new();
    let mut v_rows = Vec::new();
    for (c, w) in [0.0, 0.5, 1.0].into_iter().enumerate() {
        for k in 0..7 {
            let p = f(k as f64 / 6.0, w);
            u_rows.push(vec![c as f64, p[0], p[1], p[2]]);
        }
        for k in 0..5 {
            let p = f(w, k as f64 / 4.0);
            v_rows.push(vec![c as f64, p[0], p[1], p[2]]);
        }
    }
    (u_rows, v_rows)
}

/// Writes `rows` under `header`, the columns from `skip` on multiplied by `scale`; the index
/// columns before `skip` are written as integers.
fn write_scaled(
    dir: &Path,
    name: &str,
    header: &str,
    rows: &[Vec<f64>],
    skip: usize,
    scale: f64,
) -> PathBuf {
    let mut text = format!("{header}\n");
    for row in rows {
        let fields: Vec<String> = row
            .iter()
            .enumerate()
            .map(|(k, v)| {
                if k < skip {
                    format!("{}", *v as usize)
                } else {
                    format!("{:e}", v * scale)
                }
            })
            .collect();
        text.push_str(&fields.join(","));
        text.push('\n');
    }
    write(dir, name, &text)
}

/// What a command run gave: numeric fields in order, and the text fields.
#[derive(Debug)]
struct Output {
    numbers: Vec<Vec<f64>>,
    texts: Vec<String>,
}

/// The fields of a CSV file (header left out), or of `key value` lines and JSON numbers.
fn parse_fields(text: &str, has_header: bool) -> Output {
    let mut numbers = Vec::new();
    let mut texts = Vec::new();
    for line in text.lines().skip(usize::from(has_header)) {
        let mut row = Vec::new();
        for field in line.split([',', ' ', ':', '{', '}']) {
            let field = field.trim().trim_matches('"');
            if field.is_empty() {
                continue;
            }
            match field.parse::<f64>() {
                Ok(v) => row.push(v),
                Err(_) => texts.push(field.to_owned()),
            }
        }
        numbers.push(row);
    }
    Output { numbers, texts }
}

/// The largest relative difference between `scaled` and `unit` times `scale^power`, per
/// column, the power (-3..=1) that fits each column best; `None` when the shapes differ.
fn scaled_difference(unit: &Output, scaled: &Output, scale: f64) -> Option<f64> {
    if unit.texts != scaled.texts || unit.numbers.len() != scaled.numbers.len() {
        return None;
    }
    if unit
        .numbers
        .iter()
        .zip(&scaled.numbers)
        .any(|(a, b)| a.len() != b.len())
    {
        return None;
    }
    let columns = unit.numbers.iter().map(Vec::len).max().unwrap_or(0);
    let mut worst = 0.0f64;
    for c in 0..columns {
        let pairs: Vec<(f64, f64)> = unit
            .numbers
            .iter()
            .zip(&scaled.numbers)
            .filter(|(a, _)| a.len() > c)
            .map(|(a, b)| (a[c], b[c]))
            .collect();
        let size = pairs.iter().fold(0.0f64, |m, (a, _)| m.max(a.abs()));
        // Figures that are zero but for round-off (dimensionless) are compared as they are.
        let size = if size < 1e-12 { 1.0 } else { size };
        let best = (-3..=1)
            .map(|power| {
                let factor = scale.powi(power);
                pairs
                    .iter()
                    .map(|(a, b)| (b / factor - a).abs() / size)
                    .fold(0.0f64, f64::max)
            })
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(best);
    }
    Some(worst)
}

/// One command of the table: how to run it on data at `scale` in `dir`, and what it gives.
/// The relative difference `curve fit --knots` and `loft` (whose sections are fitted and
/// projected the same way) are held to at scales that are not powers of two (see the module
/// documentation): a thousand times the shape's settling on exact points.
const SETTLED_FIT: f64 = 1e-9;

/// The tolerance of `job` at a scale that rounds its input, for a command otherwise held to
/// `tolerance`.
fn rounded_input_tolerance(job: &Job, tolerance: f64) -> f64 {
    if job.name == "curve fit --knots" || job.name == "loft" {
        tolerance.max(SETTLED_FIT)
    } else {
        tolerance
    }
}

struct Job {
    name: &'static str,
    run: fn(&Path, f64) -> Result<Output, String>,
}

/// Runs `args` and reads the output file `out` (CSV) or, when `out` is `None`, standard output.
fn output_of(args: &[&str], out: Option<&Path>) -> Result<Output, String> {
    let o = karkas(args);
    if !o.status.success() {
        return Err(stderr(&o));
    }
    Ok(match out {
        Some(path) => parse_fields(
            &std::fs::read_to_string(path).map_err(|e| e.to_string())?,
            true,
        ),
        None => parse_fields(&stdout(&o), false),
    })
}

fn curve_job(dir: &Path, scale: f64, command: &[&str]) -> Result<Output, String> {
    let input = write_scaled(dir, "c.csv", "x,y,z", &curve_rows(), 0, scale);
    let out = dir.join("o.csv");
    let mut args: Vec<&str> = command.to_vec();
    args.extend([s(&input), "-o", s(&out)]);
    output_of(&args, Some(&out))
}

fn grid_job(dir: &Path, scale: f64, command: &[&str], extra: &[String]) -> Result<Output, String> {
    let input = write_scaled(dir, "g.csv", "i,j,x,y,z", &grid_rows(), 2, scale);
    let out = dir.join("o.csv");
    let mut args: Vec<&str> = command.to_vec();
    args.push(s(&input));
    args.extend(extra.iter().map(String::as_str));
    args.extend(["-o", s(&out)]);
    output_of(&args, Some(&out))
}

/// `surface coons --kind gordon` over the networks `u` and `v`, written to `out`.
fn gordon_args<'a>(u: &'a Path, v: &'a Path, out: &'a Path) -> [&'a str; 10] {
    [
        "surface",
        "coons",
        "--kind",
        "gordon",
        "--u-curves",
        s(u),
        "--v-curves",
        s(v),
        "-o",
        s(out),
    ]
}

/// `curve analyze --compare ll,spline --json`: a row of figures per method, keys in order.
/// The curvature jump (zero on these `C^2` curves but for round-off) is taken relative to the
/// largest curvature; the fairness energy, which scales as `1/s^3` and leaves the
/// floating-point range within 1e-150..1e150, is checked on its own
/// ([`fairness_energy_scales_as_the_inverse_cube`]).
fn analyze_job(dir: &Path, scale: f64) -> Result<Output, String> {
    let input = write_scaled(dir, "c.csv", "x,y,z", &curve_rows(), 0, scale);
    let figures = analyze_json(&input)?;
    let mut numbers = Vec::new();
    let mut texts = Vec::new();
    for (method, values) in figures.as_object().ok_or("not an object")? {
        texts.push(method.clone());
        let mut row = Vec::new();
        let get = |key: &str| {
            values[key]
                .as_f64()
                .ok_or(format!("{method}.{key}: {}", values[key]))
        };
        for (key, value) in values.as_object().ok_or("not an object")? {
            texts.push(key.clone());
            match key.as_str() {
                "curvature_jump" => row.push(get(key)? / get("curvature_max")?),
                "fairness_energy" => {}
                _ => row.push(value.as_f64().ok_or(format!("{method}.{key}: {value}"))?),
            }
        }
        numbers.push(row);
    }
    Ok(Output { numbers, texts })
}

/// The JSON figures of `curve analyze --compare ll,spline` on `input`.
fn analyze_json(input: &Path) -> Result<serde_json::Value, String> {
    let o = karkas(&[
        "curve",
        "analyze",
        "--compare",
        "ll,spline",
        "--json",
        s(input),
    ]);
    if !o.status.success() {
        return Err(stderr(&o));
    }
    serde_json::from_str(&stdout(&o)).map_err(|e| e.to_string())
}

/// `loft` of the shipped wing's table with its positions and chords scaled (the airfoil
/// files, in unit chord, copied beside it).
fn loft_job(dir: &Path, scale: f64) -> Result<Output, String> {
    let wing = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/loft-wing");
    let mut table = String::from("file,x,y,z,chord,twist,dihedral\n");
    for row in std::fs::read_to_string(wing.join("wing.csv"))
        .map_err(|e| e.to_string())?
        .lines()
        .skip(1)
    {
        let fields: Vec<&str> = row.split(',').collect();
        std::fs::copy(wing.join(fields[0]), dir.join(fields[0])).map_err(|e| e.to_string())?;
        let scaled: Vec<String> = fields[1..5]
            .iter()
            .map(|v| format!("{:e}", v.parse::<f64>().unwrap_or(f64::NAN) * scale))
            .collect();
        table.push_str(&format!(
            "{},{},{}\n",
            fields[0],
            scaled.join(","),
            fields[5..].join(",")
        ));
    }
    let input = write(dir, "wing.csv", &table);
    let out = dir.join("o.csv");
    output_of(&["loft", s(&input), "-o", s(&out)], Some(&out))
}

const JOBS: &[Job] = &[
    Job {
        name: "curve ll",
        run: |d, k| curve_job(d, k, &["curve", "ll"]),
    },
    Job {
        name: "curve ll --interpolate",
        run: |d, k| curve_job(d, k, &["curve", "ll", "--interpolate"]),
    },
    Job {
        name: "curve dps",
        run: |d, k| curve_job(d, k, &["curve", "dps", "--order", "2", "--n", "4"]),
    },
    Job {
        name: "curve spline",
        run: |d, k| curve_job(d, k, &["curve", "spline"]),
    },
    Job {
        name: "curve fit --knots",
        run: |d, k| curve_job(d, k, &["curve", "fit", "--knots", "5"]),
    },
    Job {
        name: "curve analyze --json",
        run: analyze_job,
    },
    Job {
        name: "surface ll",
        run: |d, k| grid_job(d, k, &["surface", "ll"], &[]),
    },
    Job {
        name: "surface bicubic",
        run: |d, k| grid_job(d, k, &["surface", "bicubic"], &[]),
    },
    Job {
        name: "surface bicubic --closed-v",
        run: |d, k| grid_job(d, k, &["surface", "bicubic", "--closed-v"], &[]),
    },
    Job {
        name: "surface ll --closed-v",
        run: |d, k| grid_job(d, k, &["surface", "ll", "--closed-v"], &[]),
    },
    Job {
        name: "loft",
        run: loft_job,
    },
    Job {
        name: "surface coons --kind gordon",
        run: |d, k| {
            let (u, v) = network_rows();
            let u = write_scaled(d, "u.csv", "curve,x,y,z", &u, 1, k);
            let v = write_scaled(d, "v.csv", "curve,x,y,z", &v, 1, k);
            let out = d.join("o.csv");
            output_of(&gordon_args(&u, &v, &out), Some(&out))
        },
    },
    Job {
        name: "section",
        run: |d, k| {
            grid_job(
                d,
                k,
                &["section", "--method", "ll"],
                &["--x".into(), format!("{:e}", 0.9 * k)],
            )
        },
    },
    Job {
        name: "vary",
        run: |d, k| {
            let rows: Vec<String> = (0..6)
                .map(|r| format!("{:e}", 0.1 * k * r as f64))
                .collect();
            let cols: Vec<String> = (0..8)
                .map(|c| format!("{:e}", 0.05 * k * c as f64))
                .collect();
            let extra = [
                "--coord".into(),
                "z".into(),
                "--rows".into(),
                rows.join(","),
                "--cols".into(),
                cols.join(","),
                "--total".into(),
                format!("{:e}", 2.0 * k),
            ];
            grid_job(d, k, &["vary"], &extra)
        },
    },
    Job {
        name: "hausdorff",
        run: |d, k| {
            let a = write_scaled(d, "a.csv", "x,y,z", &curve_rows(), 0, k);
            // Shifted by different amounts, so that one point is farthest (no ties).
            let shifted: Vec<Vec<f64>> = curve_rows()
                .into_iter()
                .enumerate()
                .map(|(k, p)| vec![p[0] + 0.01 + 1e-3 * k as f64, p[1], p[2] - 0.02])
                .collect();
            let b = write_scaled(d, "b.csv", "x,y,z", &shifted, 0, k);
            output_of(&["hausdorff", s(&a), s(&b)], None)
        },
    },
];

/// Runs every job at unit scale and at `scale`; each must agree to `tolerance`.
fn check_every_job(scale: f64, tolerance: f64) -> Result<(), TestCaseError> {
    for job in JOBS {
        let (unit_dir, scaled_dir) = (temp_dir(), temp_dir());
        let unit = (job.run)(unit_dir.path(), 1.0)
            .map_err(|e| TestCaseError::fail(format!("{}: {e}", job.name)))?;
        let scaled = (job.run)(scaled_dir.path(), scale)
            .map_err(|e| TestCaseError::fail(format!("{} at {scale:e}: {e}", job.name)))?;
        let difference = scaled_difference(&unit, &scaled, scale);
        let tolerance = rounded_input_tolerance(job, tolerance);
        prop_assert!(
            difference.is_some_and(|d| d <= tolerance),
            "{} at scale {scale:e}: relative difference {difference:?} (unit {unit:?}, scaled {scaled:?})",
            job.name
        );
    }
    Ok(())
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 6, ..ProptestConfig::default() })]

    #[test]
    fn every_command_is_scale_equivariant_from_1e_150_to_1e150(exponent in -150i32..=150, mantissa in 1.0f64..10.0) {
        let scale = mantissa * 10f64.powi(exponent);
        prop_assume!((1e-150..=1e150).contains(&scale));
        check_every_job(scale, 1e-12)?;
    }

    #[test]
    fn the_fit_is_exactly_equivariant_at_powers_of_two(exponent in -498i32..=498) {
        let scale = 2f64.powi(exponent);
        let tolerance_mode = |d: &Path, k: f64| curve_job(d, k, &["curve", "fit", "--tolerance", &format!("{:e}", 1e-3 * k)]);
        let knots_mode = |d: &Path, k: f64| curve_job(d, k, &["curve", "fit", "--knots", "5"]);
        let fair = |d: &Path, k: f64| curve_job(d, k, &["curve", "fair", "--tolerance", &format!("{:e}", 1e-3 * k)]);
        for (name, job) in [("tolerance", &tolerance_mode as &dyn Fn(&Path, f64) -> Result<Output, String>), ("knots", &knots_mode), ("fair", &fair)] {
            let (unit_dir, scaled_dir) = (temp_dir(), temp_dir());
            let unit = job(unit_dir.path(), 1.0).map_err(TestCaseError::fail)?;
            let scaled = job(scaled_dir.path(), scale).map_err(TestCaseError::fail)?;
            let difference = scaled_difference(&unit, &scaled, scale);
            prop_assert!(difference.is_some_and(|d| d <= 1e-12), "{name} at 2^{exponent}: {difference:?}");
        }
    }
}

#[test]
fn the_extreme_scales_of_the_range_hold_too() {
    for scale in [1e-150, 1e150] {
        check_every_job(scale, 1e-12).unwrap();
    }
}

#[test]
fn coordinates_at_the_limits_work_and_past_them_are_refused() {
    // Scaled to just within 1e152 and 1e-152, and then past them.
    // The largest coordinate is 1.577 in the curve and 1.6 in its shifted copy (hausdorff).
    let within_high = 0.999e152 / 1.6;
    let within_low = 1.001e-152 / 1.5;
    for job in JOBS
        .iter()
        .filter(|j| j.name.starts_with("curve") || j.name == "hausdorff")
    {
        for scale in [within_high, within_low] {
            let (unit_dir, scaled_dir) = (temp_dir(), temp_dir());
            let unit = (job.run)(unit_dir.path(), 1.0).unwrap();
            let scaled = (job.run)(scaled_dir.path(), scale)
                .unwrap_or_else(|e| panic!("{} at {scale:e}: {e}", job.name));
            let difference = scaled_difference(&unit, &scaled, scale);
            let tolerance = rounded_input_tolerance(job, 1e-12);
            assert!(
                difference.is_some_and(|d| d <= tolerance),
                "{} at {scale:e}: {difference:?}",
                job.name
            );
        }
    }
    for job in JOBS {
        for (scale, words) in [
            (2e152, "above 1e152"),
            (1e-153, "below 1e-152"),
            (1e300, "above 1e152"),
            (1e-300, "below 1e-152"),
        ] {
            let dir = temp_dir();
            let e = (job.run)(dir.path(), scale).expect_err(job.name);
            assert!(
                e.contains("coordinates out of range")
                    && e.contains(words)
                    && e.contains("rescale"),
                "{} at {scale:e}: {e}",
                job.name
            );
            assert!(
                !dir.path().join("o.csv").exists(),
                "{}: an output was written",
                job.name
            );
        }
    }
}

#[test]
fn a_refusal_out_of_range_exits_2_and_names_the_file() {
    let dir = temp_dir();
    let input = write(dir.path(), "far.csv", "x,y\n0,0\n1,2e160\n2,0\n");
    let out = dir.path().join("o.csv");
    let o = karkas(&["curve", "ll", s(&input), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("far.csv: coordinates out of range: the largest magnitude is 2e160"),
        "{e}"
    );
    assert!(!out.exists());
}

#[test]
fn fairness_energy_scales_as_the_inverse_cube() {
    let dir = temp_dir();
    let energies = |scale: f64| {
        let input = write_scaled(dir.path(), "c.csv", "x,y,z", &curve_rows(), 0, scale);
        let figures = analyze_json(&input).unwrap();
        ["ll", "spline"].map(|m| figures[m]["fairness_energy"].as_f64().unwrap())
    };
    let unit = energies(1.0);
    for scale in [3.7e-95, 1e-20, 2.2e33, 6e95] {
        for (u, e) in unit.iter().zip(energies(scale)) {
            let expected = u / scale / scale / scale;
            assert!(
                (e / expected - 1.0).abs() < 1e-12,
                "{scale:e}: {e:e} against {expected:e}"
            );
        }
    }
}

#[test]
fn fairness_energy_leaves_the_range_as_ieee_says() {
    // About 6.4e4 at unit size, the energy is 6.4e454 for the curve times 1e-150 (infinite:
    // JSON null) and 6.4e-446 for the curve times 1e150 (0).
    let dir = temp_dir();
    for (scale, expected) in [
        (1e-150, serde_json::Value::Null),
        (1e150, serde_json::json!(0.0)),
    ] {
        let input = write_scaled(dir.path(), "c.csv", "x,y,z", &curve_rows(), 0, scale);
        let figures = analyze_json(&input).unwrap();
        for method in ["ll", "spline"] {
            assert_eq!(
                figures[method]["fairness_energy"], expected,
                "{method} at {scale:e}"
            );
        }
    }
}

#[test]
fn one_stray_value_is_named_instead_of_a_line_or_a_double_crossing() {
    // Without the check, the stray z = 1e15 set the model's size: the grid was refused as
    // "all 16 grid points lie on one straight line" and the network as curves that "meet more
    // than once".
    let dir = temp_dir();
    let mut grid = String::from("i,j,x,y,z\n");
    for i in 0..4 {
        for j in 0..4 {
            let z = if (i, j) == (2, 2) {
                1e15
            } else {
                0.1 * (i * j) as f64
            };
            grid.push_str(&format!("{i},{j},{i},{j},{z}\n"));
        }
    }
    let grid = write(dir.path(), "g.csv", &grid);
    let out = dir.path().join("o.csv");
    for command in [["surface", "bicubic"], ["surface", "ll"]] {
        let o = karkas(&[command[0], command[1], s(&grid), "-o", s(&out)]);
        assert_eq!(o.status.code(), Some(2), "{command:?}");
        let e = stderr(&o);
        assert!(e.contains("g.csv: the point at (2,2,1000000000000000) lies 5.0e14 times farther from the others"), "{e}");
        assert!(!e.contains("straight line"), "{e}");
    }
    let (mut u_rows, v_rows) = network_rows();
    u_rows[3][3] = 1e15;
    let u = write_scaled(dir.path(), "u.csv", "curve,x,y,z", &u_rows, 1, 1.0);
    let v = write_scaled(dir.path(), "v.csv", "curve,x,y,z", &v_rows, 1, 1.0);
    let o = karkas(&gordon_args(&u, &v, &out));
    assert_eq!(o.status.code(), Some(2));
    let e = stderr(&o);
    assert!(
        e.contains("u.csv: the point at (1,0,1000000000000000) lies 1.0e15 times farther"),
        "{e}"
    );
    assert!(!out.exists());
}

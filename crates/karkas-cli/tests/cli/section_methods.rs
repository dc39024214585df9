//! `karkas section --method bicubic` and `--method coons`: sections of the bicubic interpolant
//! of a grid and of the Coons / Gordon surface of a curve network, against the closed-form
//! sections of the sphere they are sampled from; and the options each method refuses.

use crate::common::{assert_rejected, grid_csv, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::{Path, PathBuf};

/// The unit sphere's point at latitude `lat` and longitude `lon` (degrees).
fn sphere_point(lat: f64, lon: f64) -> [f64; 3] {
    let (lat, lon) = (lat.to_radians(), lon.to_radians());
    [lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin()]
}

/// A sphere grid: the latitudes `lats` (rows) by 18 longitudes 20 degrees apart (columns).
fn sphere_grid(dir: &Path, name: &str, lats: &[f64]) -> PathBuf {
    let text = grid_csv(lats.len(), 18, |i, j| {
        sphere_point(lats[i], 20.0 * j as f64)
    });
    write(dir, name, &text)
}

/// The largest distance of the section points in `out` from the circle in which the plane
/// `n . p = c` cuts the unit sphere, after checking that every point lies on the plane; and the
/// number of points.
fn off_circle(out: &Path, n: [f64; 3], c: f64) -> (f64, usize) {
    let (header, rows) = read_csv(out);
    assert_eq!(header, ["section", "t", "x", "y", "z"]);
    let norm = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    let centre = n.map(|a| a * c / (norm * norm));
    let radius = (1.0 - (c / norm).powi(2)).sqrt();
    let mut worst: f64 = 0.0;
    for r in &rows {
        let p = [r[2], r[3], r[4]];
        let level = n[0] * p[0] + n[1] * p[1] + n[2] * p[2];
        assert!((level - c).abs() < 1e-9, "{p:?} is off the plane");
        let d = [p[0] - centre[0], p[1] - centre[1], p[2] - centre[2]];
        let rho = (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]).sqrt();
        worst = worst.max((rho - radius).abs());
    }
    (worst, rows.len())
}

/// Runs `karkas section` with `args` then `-o out`, expecting success.
fn section(args: &[&str], out: &Path) {
    let mut all = vec!["section"];
    all.extend_from_slice(args);
    all.extend_from_slice(&["-o", s(out)]);
    let o = karkas(&all);
    assert!(o.status.success(), "{all:?}: {}", stderr(&o));
}

/// Cubic spline interpolation of `f` at spacing `h` errs by at most `5/384 h^4 max|f''''|`
/// (Hall's bound); on the unit sphere in angle parameters `|f''''| <= 1`, and chord parameters
/// are proportional to the angles here (equal angles, equal chords).
fn spline_bound(h_degrees: f64) -> f64 {
    5.0 / 384.0 * h_degrees.to_radians().powi(4)
}

#[test]
fn bicubic_section_of_a_sphere_grid_is_its_circle_to_the_interpolation_error() {
    let dir = temp_dir();
    // 17 latitudes -80..80 every 10 degrees, 18 longitudes every 20 degrees (closed in v).
    let lats: Vec<f64> = (0..17).map(|i| -80.0 + 10.0 * i as f64).collect();
    let input = sphere_grid(dir.path(), "sphere.csv", &lats);
    // The surface errs by at most the sum of the two directions' spline errors, 5/384 (h_u^4 +
    // h_v^4) = 2.05e-4; a point of the surface that far from the sphere lies that far divided
    // by the sine of the angle between plane and sphere (the circle's radius r, >= 0.85 here)
    // from the circle in the plane.
    let surface_bound = spline_bound(10.0) + spline_bound(20.0);
    for (n, c) in [([0.0, 0.0, 1.0], 0.45), ([0.3, 0.2, 1.0], 0.4)] {
        let out = dir.path().join("bicubic.csv");
        let plane = format!("{},{},{},{c}", n[0], n[1], n[2]);
        section(
            &[
                s(&input),
                "--method",
                "bicubic",
                "--closed-v",
                "--plane",
                &plane,
            ],
            &out,
        );
        let (worst, points) = off_circle(&out, n, c);
        let norm = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let radius = (1.0 - (c / norm).powi(2)).sqrt();
        eprintln!("bicubic plane {plane}: {points} points, {worst:.3e} off the circle");
        assert!(points > 30);
        assert!(
            worst < surface_bound / radius,
            "plane {plane}: {worst:e} off the circle, bound {:e}",
            surface_bound / radius
        );
    }
}

#[test]
fn param_uniform_changes_the_bicubic_section_of_an_uneven_grid() {
    let dir = temp_dir();
    // Latitudes alternately 6 and 14 degrees apart: -80, -74, -60, -54, ..., 80.
    let lats: Vec<f64> = (0..17)
        .map(|i| -80.0 + 20.0 * (i / 2) as f64 + if i % 2 == 1 { 6.0 } else { 0.0 })
        .collect();
    let input = sphere_grid(dir.path(), "uneven.csv", &lats);
    let (n, c) = ([0.3, 0.2, 1.0], 0.4);
    let mut errors = Vec::new();
    for param in [None, Some("chord"), Some("uniform")] {
        let out = dir.path().join("s.csv");
        let mut args = vec![
            s(&input),
            "--method",
            "bicubic",
            "--closed-v",
            "--plane",
            "0.3,0.2,1,0.4",
        ];
        if let Some(p) = param {
            args.extend_from_slice(&["--param", p]);
        }
        section(&args, &out);
        let (worst, _) = off_circle(&out, n, c);
        eprintln!("--param {param:?}: {worst:.3e} off the circle");
        errors.push(worst);
    }
    // The default is chord; uniform parameters on uneven spacing bend the meridians between the
    // nodes, which chord lengths (here the arc lengths to 1e-3) do not.
    assert_eq!(errors[0], errors[1]);
    assert!(
        errors[2] > 10.0 * errors[1],
        "uniform {:e} vs chord {:e}",
        errors[2],
        errors[1]
    );
}

/// The network of the unit sphere between latitudes -60 and 60: u-curves the 7 latitude
/// circles 20 degrees apart (closed, a point every 15 degrees of longitude), v-curves the 12
/// meridians 30 degrees apart (a point every 10 degrees of latitude).
fn sphere_network(dir: &Path) -> (PathBuf, PathBuf) {
    let mut u = String::from("curve,x,y,z\n");
    for k in 0..7 {
        for q in 0..=24 {
            let p = sphere_point(-60.0 + 20.0 * k as f64, 15.0 * (q % 24) as f64);
            u.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    let mut v = String::from("curve,x,y,z\n");
    for k in 0..12 {
        for q in 0..=12 {
            let p = sphere_point(-60.0 + 10.0 * q as f64, 30.0 * k as f64);
            v.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    (write(dir, "u.csv", &u), write(dir, "v.csv", &v))
}

#[test]
fn coons_section_of_a_sphere_network_is_its_circle_to_the_interpolation_error() {
    let dir = temp_dir();
    let (u, v) = sphere_network(dir.path());
    // The gordon-spline surface interpolates every curve, and its error is that of the curves
    // (cubic splines through points 15 and 10 degrees apart in angle, 5/384 h^4 = 6.1e-5 and
    // 1.2e-5) plus the product of the two blending errors, far smaller: 7.3e-5 in all, divided
    // by the circle's radius (>= 0.9 here) in the plane.
    let surface_bound = spline_bound(15.0) + spline_bound(10.0);
    for (n, c) in [([0.0, 0.0, 1.0], 0.3), ([0.3, 0.2, 1.0], -0.2)] {
        let out = dir.path().join("coons.csv");
        let plane = format!("{},{},{},{c}", n[0], n[1], n[2]);
        section(
            &[
                "--method",
                "coons",
                "--kind",
                "gordon-spline",
                "--u-curves",
                s(&u),
                "--v-curves",
                s(&v),
                "--plane",
                &plane,
            ],
            &out,
        );
        let (worst, points) = off_circle(&out, n, c);
        let norm = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
        let radius = (1.0 - (c / norm).powi(2)).sqrt();
        eprintln!("coons plane {plane}: {points} points, {worst:.3e} off the circle");
        assert!(points > 30);
        assert!(
            worst < surface_bound / radius,
            "plane {plane}: {worst:e} off the circle, bound {:e}",
            surface_bound / radius
        );
    }
}

#[test]
fn options_of_another_method_exit_2_naming_them_and_write_nothing() {
    let dir = temp_dir();
    let lats: Vec<f64> = (0..17).map(|i| -80.0 + 10.0 * i as f64).collect();
    let grid = sphere_grid(dir.path(), "sphere.csv", &lats);
    let (u, v) = sphere_network(dir.path());
    let out = dir.path().join("out.csv");
    let (grid, u, v) = (s(&grid), s(&u), s(&v));
    let net = ["--kind", "gordon", "--u-curves", u, "--v-curves", v];
    let cases: Vec<(Vec<&str>, &str)> =
        vec![
        (
            vec![grid, "--method", "ll", "--u-curves", u],
            "--u-curves is used only by --method coons, not --method ll",
        ),
        (
            [&[grid, "--method", "bicubic"][..], &net[..]].concat(),
            "--kind, --u-curves, --v-curves are used only by --method coons, not --method bicubic",
        ),
        (
            vec![grid, "--method", "ll", "--param", "uniform"],
            "--param is used only by --method bicubic, not --method ll",
        ),
        (
            vec![grid, "--method", "bicubic", "--order", "3"],
            "--order is used only by --method ll, not --method bicubic",
        ),
        (
            [&["--method", "coons", "--interpolate"][..], &net[..]].concat(),
            "--interpolate is used only by --method ll, not --method coons",
        ),
        (
            [&["--method", "coons", "--parameterization", "chord"][..], &net[..]].concat(),
            "--param is used only by --method bicubic, not --method coons",
        ),
        (
            [&["--method", "coons", "--closed-u"][..], &net[..]].concat(),
            "--closed-u / --closed-v are not used by --method coons",
        ),
        (
            [&[grid, "--method", "coons"][..], &net[..]].concat(),
            "--method coons takes no INPUT_GRID",
        ),
        (
            vec!["--method", "coons", "--kind", "gordon", "--u-curves", u],
            "--method coons needs --kind, --u-curves U.csv and --v-curves V.csv",
        ),
        (
            vec!["--method", "bicubic", "--closed-v"],
            "--method bicubic needs INPUT_GRID",
        ),
        (vec!["--method", "ll"], "--method ll needs INPUT_GRID"),
    ];
    for (args, needle) in cases {
        let mut all = vec!["section"];
        all.extend_from_slice(&args);
        all.extend_from_slice(&["--z", "0", "-o", s(&out)]);
        assert_rejected(&all, needle, &out, None);
    }
    // A network error names the file, as `surface coons` names it.
    let bad = write(dir.path(), "bad.csv", "curve,x,y,z\n0,0,0,0\n");
    assert_rejected(
        &[
            "section",
            "--method",
            "coons",
            "--kind",
            "gordon",
            "--u-curves",
            s(&bad),
            "--v-curves",
            v,
            "--z",
            "0",
            "-o",
            s(&out),
        ],
        "bad.csv:2: curve 0 has 1 point; at least 2 are needed",
        &out,
        None,
    );
}

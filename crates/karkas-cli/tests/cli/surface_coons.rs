//! The CLI contract of `karkas surface coons`: options, the `curve,x,y,z` inputs, the `u,v`
//! parameters of the output, and exit code 2 with one line naming the file (and line) and no
//! output on bad input.

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, temp_dir};
use std::path::{Path, PathBuf};

/// The sheet `(x, y, 0.3 sin x cos y)`.
fn sheet(x: f64, y: f64) -> [f64; 3] {
    [x, y, 0.3 * x.sin() * y.cos()]
}

/// A curve family as `curve,x,y,z` text: curve `k` is `f(k, t)` at `t = 0, 0.1, .., 2`.
fn family(count: usize, f: impl Fn(usize, f64) -> [f64; 3]) -> String {
    let mut text = String::from("curve,x,y,z\n");
    for k in 0..count {
        for q in 0..=20 {
            let p = f(k, q as f64 / 10.0);
            text.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    text
}

/// The network of the sheet: u-curves at y = 0, 1, 2 (along x), v-curves at x = 0, 1, 2
/// (`spacing` = 1), or just the borders (`spacing` = 2).
fn sheet_files(dir: &Path, spacing: usize) -> (PathBuf, PathBuf) {
    let count = 2 / spacing + 1;
    let at = |k: usize| (k * spacing) as f64;
    let u = dir.join("u.csv");
    let v = dir.join("v.csv");
    std::fs::write(&u, family(count, |k, t| sheet(t, at(k)))).unwrap();
    std::fs::write(&v, family(count, |k, t| sheet(at(k), t))).unwrap();
    (u, v)
}

#[test]
fn every_kind_writes_a_surface_through_the_network() {
    let dir = temp_dir();
    let (u3, v3) = sheet_files(dir.path(), 1);
    let sub = dir.path().join("borders");
    std::fs::create_dir(&sub).unwrap();
    let (u2, v2) = sheet_files(&sub, 2);
    for (kind, u, v) in [
        ("bilinear", &u2, &v2),
        ("bicubic", &u2, &v2),
        ("gordon", &u3, &v3),
        ("gordon-spline", &u3, &v3),
        ("composite", &u3, &v3),
    ] {
        let out = dir.path().join(format!("{kind}.csv"));
        let o = karkas(&[
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(u),
            "--v-curves",
            s(v),
            "--samples",
            "21,11",
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{kind}: {}", stderr(&o));
        let (header, rows) = read_csv(&out);
        assert_eq!(header, ["u", "v", "x", "y", "z"]);
        assert_eq!(rows.len(), 21 * 11);
        // u outer, v inner, both over [0, 1]: the curves' point index, normalised.
        assert_eq!(&rows[0][..2], &[0.0, 0.0]);
        assert_eq!(&rows[1][..2], &[0.0, 0.1]);
        assert_eq!(&rows[11][..2], &[0.05, 0.0]);
        assert_eq!(&rows[230][..2], &[1.0, 1.0]);
        // The borders are the input curves: v = 0 is u-curve 0 (y = 0), u = 1 is the last
        // v-curve (x = 2), at their points (every other sample).
        for a in (0..21).step_by(2) {
            let row = &rows[a * 11];
            let want = sheet(a as f64 / 10.0, 0.0);
            for c in 0..3 {
                assert!((row[2 + c] - want[c]).abs() < 1e-12, "{kind}: {row:?}");
            }
        }
        for b in 0..11 {
            let row = &rows[20 * 11 + b];
            let want = sheet(2.0, b as f64 / 5.0);
            for c in 0..3 {
                assert!((row[2 + c] - want[c]).abs() < 1e-12, "{kind}: {row:?}");
            }
        }
    }
}

#[test]
fn bicubic_without_derivative_files_warns() {
    // Two curves per family: the cross-boundary derivatives are invented unless given.
    let dir = temp_dir();
    let (u, v) = sheet_files(dir.path(), 2);
    let run = |extra: &[&str]| {
        let out = dir.path().join("b.csv");
        let mut args = vec![
            "surface",
            "coons",
            "--kind",
            "bicubic",
            "--u-curves",
            s(&u),
            "--v-curves",
            s(&v),
            "-o",
            s(&out),
        ];
        args.extend_from_slice(extra);
        let o = karkas(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        stderr(&o)
    };
    let warned = run(&[]);
    assert!(
        warned.contains("warning: --kind bicubic without --u-derivs and --v-derivs"),
        "{warned}"
    );
    // With the derivatives given (those of the sheet, per unit of the parameters over 0..2):
    // no warning.
    let du = dir.path().join("du.csv");
    let dv = dir.path().join("dv.csv");
    std::fs::write(
        &du,
        family(2, |k, t| {
            [0.0, 2.0, -0.6 * t.sin() * (2.0 * k as f64).sin()]
        }),
    )
    .unwrap();
    std::fs::write(
        &dv,
        family(2, |k, t| [2.0, 0.0, 0.6 * (2.0 * k as f64).cos() * t.cos()]),
    )
    .unwrap();
    let quiet = run(&["--u-derivs", s(&du), "--v-derivs", s(&dv)]);
    assert!(!quiet.contains("warning"), "{quiet}");
    // Composite and bilinear surfaces do not warn.
    assert!(!stderr(&karkas(&[
        "surface",
        "coons",
        "--kind",
        "bilinear",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "-o",
        s(&dir.path().join("l.csv")),
    ]))
    .contains("warning"));
}

#[test]
fn obj_output_and_cross_derivative_files() {
    let dir = temp_dir();
    let (u, v) = sheet_files(dir.path(), 1);
    // dS/dv along the u-curves and dS/du along the v-curves, per unit of the surface's
    // parameters (which run over 0..2 in y and x: a factor 2).
    let du = dir.path().join("du.csv");
    let dv = dir.path().join("dv.csv");
    std::fs::write(
        &du,
        family(3, |k, t| [0.0, 2.0, -0.6 * t.sin() * (k as f64).sin()]),
    )
    .unwrap();
    std::fs::write(
        &dv,
        family(3, |k, t| [2.0, 0.0, 0.6 * (k as f64).cos() * t.cos()]),
    )
    .unwrap();
    let out = dir.path().join("c.obj");
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "composite",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "--u-derivs",
        s(&du),
        "--v-derivs",
        s(&dv),
        "--samples",
        "9,7",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mesh = std::fs::read_to_string(&out).unwrap();
    assert_eq!(mesh.lines().filter(|l| l.starts_with("v ")).count(), 63);
    assert_eq!(
        mesh.lines().filter(|l| l.starts_with("f ")).count(),
        2 * 8 * 6
    );
}

#[test]
fn closed_curves_make_a_closed_surface() {
    // A tube: 3 closed frames (v-curves, last point repeating the first), 4 stringers.
    let dir = temp_dir();
    let tau = std::f64::consts::TAU;
    let ring = |x: f64, a: f64| [x, (1.0 + 0.1 * x) * a.cos(), (1.0 + 0.1 * x) * a.sin()];
    let mut frames = String::from("curve,x,y,z\n");
    for k in 0..3 {
        for q in 0..=16 {
            let p = ring(k as f64, tau * (q % 16) as f64 / 16.0);
            frames.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    let mut stringers = String::from("curve,x,y,z\n");
    for j in 0..4 {
        for q in 0..=10 {
            let p = ring(q as f64 / 5.0, tau * j as f64 / 4.0);
            stringers.push_str(&format!("{j},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    let u = dir.path().join("stringers.csv");
    let v = dir.path().join("frames.csv");
    std::fs::write(&u, stringers).unwrap();
    std::fs::write(&v, frames).unwrap();
    let out = dir.path().join("tube.csv");
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "gordon-spline",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "--samples",
        "5,9",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(&out);
    // v runs over one period [0, 1]: the last sample of each u line is the first again.
    for a in 0..5 {
        let (first, last) = (&rows[a * 9], &rows[a * 9 + 8]);
        assert_eq!((first[1], last[1]), (0.0, 1.0));
        for c in 2..5 {
            assert!((first[c] - last[c]).abs() < 1e-12);
        }
    }
    // Bilinear Coons surfaces need open curves.
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "bilinear",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
}

#[test]
fn bad_input_exits_2_naming_the_file_and_writes_nothing() {
    let dir = temp_dir();
    let (u, v) = sheet_files(dir.path(), 1);
    let out = dir.path().join("out.csv");
    std::fs::write(&out, "keep me").unwrap();
    let run = |kind: &str, u: &Path, v: &Path, extra: &[&str], needles: &[&str]| {
        let mut args = vec![
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(u),
            "--v-curves",
            s(v),
            "-o",
            s(&out),
        ];
        args.extend_from_slice(extra);
        assert_rejected(&args, needles, &out, Some("keep me"));
    };
    let bad = |name: &str, text: &str| {
        let p = dir.path().join(name);
        std::fs::write(&p, text).unwrap();
        p
    };
    // A malformed file: named with its line.
    let header = bad("header.csv", "curve,x,y\n0,1,2\n");
    run(
        "gordon",
        &header,
        &v,
        &[],
        &["header.csv:1:", "no column 'z'"],
    );
    let nan = bad("nan.csv", "curve,x,y,z\n0,0,0,0\n0,1,nan,0\n0,2,0,0\n");
    run("gordon", &u, &nan, &[], &["nan.csv:3:", "non-finite"]);
    // A curve of one point (two make a straight edge): named by its first line.
    let short = bad(
        "short.csv",
        &(family(2, |k, t| sheet(t, k as f64)) + "2,0,2,0\n"),
    );
    run(
        "gordon",
        &short,
        &v,
        &[],
        &[
            "short.csv:44:",
            "curve 2 has 1 point; at least 2 are needed",
        ],
    );
    // u-curve 1 lifted off the network: the pair is named with both files and lines.
    let lifted = bad(
        "lifted.csv",
        &family(3, |k, t| {
            let mut p = sheet(t, k as f64);
            if k == 1 {
                p[2] += 0.01;
            }
            p
        }),
    );
    run(
        "gordon",
        &lifted,
        &v,
        &[],
        &[
            "v.csv:2 (v-curve 0) and ",
            "lifted.csv:23 (u-curve 1): no common point",
        ],
    );
    // Bilinear needs two curves per direction.
    run(
        "bilinear",
        &u,
        &v,
        &[],
        &["two open v-curves and two open u-curves"],
    );
    // Cross-derivatives: only for bicubic and composite, both files together, and they
    // must agree with the curves' own tangents.
    let zeros = bad("zeros.csv", &family(3, |_, _| [0.0, 0.0, 0.0]));
    run(
        "gordon",
        &u,
        &v,
        &["--u-derivs", s(&zeros), "--v-derivs", s(&zeros)],
        &["only by --kind bicubic and composite"],
    );
    run(
        "composite",
        &u,
        &v,
        &["--u-derivs", s(&zeros)],
        &["--u-derivs and --v-derivs go together"],
    );
    run(
        "composite",
        &u,
        &v,
        &["--u-derivs", s(&zeros), "--v-derivs", s(&zeros)],
        &[
            "u.csv, ",
            "v.csv: ",
            "disagree at",
            "cross-derivative curve",
        ],
    );
    // Unknown kind, unknown extension, output equal to an input.
    run("coons", &u, &v, &[], &["invalid value 'coons'"]);
    let svg = dir.path().join("out.dxf");
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "gordon",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "-o",
        s(&svg),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("unknown output extension"));
    assert!(!svg.exists());
    let before = std::fs::read_to_string(&u).unwrap();
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "gordon",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "-o",
        s(&u),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("overwrite the input"));
    assert_eq!(std::fs::read_to_string(&u).unwrap(), before);
}

#[test]
fn straight_edges_of_two_points_make_the_bilinear_patch() {
    let dir = temp_dir();
    // Two u-curves and two v-curves, each a straight edge between two corners.
    let corners = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.5],
        [1.0, 1.0, 0.0],
    ];
    let edge = |k: usize, a: [f64; 3], b: [f64; 3]| {
        format!(
            "{k},{},{},{}\n{k},{},{},{}\n",
            a[0], a[1], a[2], b[0], b[1], b[2]
        )
    };
    let u = dir.path().join("u.csv");
    let v = dir.path().join("v.csv");
    std::fs::write(
        &u,
        format!(
            "curve,x,y,z\n{}{}",
            edge(0, corners[0], corners[1]),
            edge(1, corners[2], corners[3])
        ),
    )
    .unwrap();
    std::fs::write(
        &v,
        format!(
            "curve,x,y,z\n{}{}",
            edge(0, corners[0], corners[2]),
            edge(1, corners[1], corners[3])
        ),
    )
    .unwrap();
    for kind in ["bilinear", "gordon", "gordon-spline"] {
        let out = dir.path().join(format!("{kind}.csv"));
        let o = karkas(&[
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(&u),
            "--v-curves",
            s(&v),
            "--samples",
            "5,5",
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{kind}: {}", stderr(&o));
        // The bilinear patch through the corners: x = u, y = v, z = 0.5 v (1 - u).
        let (_, rows) = read_csv(&out);
        assert_eq!(rows.len(), 25);
        for r in rows {
            let (uu, vv) = (r[0], r[1]);
            let expected = [uu, vv, 0.5 * vv * (1.0 - uu)];
            for c in 0..3 {
                assert!((r[2 + c] - expected[c]).abs() < 1e-14, "{kind} {r:?}");
            }
        }
    }
}

/// The network of the wave `(x, y, a sin wx cos wy)` with `per_span` point steps between
/// crossings (u-curves at y = 0, 1, 2, v-curves at x = 0, 1, 2), and its exact
/// cross-derivatives per unit of the surface's parameters (which run over 0..2 in x and y: a
/// factor 2), dS/dv along the u-curves shifted by `shift`.
fn sheet_with_derivs(
    dir: &Path,
    per_span: usize,
    (a, w): (f64, f64),
    shift: [f64; 3],
) -> [PathBuf; 4] {
    let steps = 2 * per_span;
    let sheet = |x: f64, y: f64| [x, y, a * (w * x).sin() * (w * y).cos()];
    let write = |name: &str, f: &dyn Fn(usize, f64) -> [f64; 3]| {
        let mut text = String::from("curve,x,y,z\n");
        for k in 0..3 {
            for q in 0..=steps {
                let p = f(k, 2.0 * q as f64 / steps as f64);
                text.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
            }
        }
        let path = dir.join(name);
        std::fs::write(&path, text).unwrap();
        path
    };
    let u = write("u.csv", &|k, t| sheet(t, k as f64));
    let v = write("v.csv", &|k, t| sheet(k as f64, t));
    let du = write("du.csv", &|k, t| {
        let y = k as f64;
        let dz = -2.0 * a * w * (w * t).sin() * (w * y).sin();
        [shift[0], 2.0 + shift[1], dz + shift[2]]
    });
    let dv = write("dv.csv", &|k, t| {
        let x = k as f64;
        [2.0, 0.0, 2.0 * a * w * (w * x).cos() * (w * t).cos()]
    });
    [u, v, du, dv]
}

/// `surface coons --kind composite` of the four files, with `extra` options.
fn composite(files: &[PathBuf; 4], out: &Path, extra: &[&str]) -> std::process::Output {
    let mut args = vec![
        "surface",
        "coons",
        "--kind",
        "composite",
        "--u-curves",
        s(&files[0]),
        "--v-curves",
        s(&files[1]),
        "--u-derivs",
        s(&files[2]),
        "--v-derivs",
        s(&files[3]),
        "--samples",
        "9,33",
        "-o",
        s(out),
    ];
    args.extend_from_slice(extra);
    karkas(&args)
}

#[test]
fn tolerance_option_accepts_what_the_default_refuses() {
    // Exact derivatives, but 8 point steps per span of a wave: the interpolated curves'
    // tangents differ from them by more than the default 1e-4 of the model size.
    let dir = temp_dir();
    let files = sheet_with_derivs(dir.path(), 8, (0.5, 2.0), [0.0; 3]);
    let out = dir.path().join("out.csv");
    let o = composite(&files, &out, &[]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let message = stderr(&o);
    assert!(
        message.contains("differ by 1.344e-3 (tolerance 5.967e-4)"),
        "{message}"
    );
    assert!(!out.exists());
    let o = composite(&files, &out, &["--tolerance", "3e-3"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(read_csv(&out).1.len(), 9 * 33);
    // A tolerance that is no tolerance, and --tolerance with --repair.
    for bad in [&["--tolerance=-1"][..], &["--tolerance", "nan"]] {
        let o = composite(&files, &dir.path().join("bad.csv"), bad);
        assert_eq!(o.status.code(), Some(2));
        assert!(stderr(&o).contains("--tolerance must be a finite number >= 0"));
    }
    let o = composite(
        &files,
        &dir.path().join("bad.csv"),
        &["--tolerance", "1e-3", "--repair"],
    );
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot be used with"), "{}", stderr(&o));
}

#[test]
fn repair_reports_half_the_perturbation_and_keeps_the_curves() {
    // dS/dv along the u-curves lifted by 0.01 in z: it disagrees with the v-curves' own
    // tangents by 0.01 at every crossing; the mean moves each side by 0.005.
    let lift = 0.01;
    let dir = temp_dir();
    let files = sheet_with_derivs(dir.path(), 10, (0.3, 1.0), [0.0, 0.0, lift]);
    let out = dir.path().join("out.csv");
    let o = composite(&files, &out, &[]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("disagree at"), "{}", stderr(&o));
    let o = composite(&files, &out, &["--repair"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let message = stderr(&o);
    let reported: f64 = message
        .split("largest correction ")
        .nth(1)
        .and_then(|rest| rest.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .unwrap_or_else(|| panic!("no correction in {message:?}"));
    assert!(
        (reported - lift / 2.0).abs() < 0.05 * lift,
        "{reported} vs {lift} / 2: {message}"
    );
    assert!(message.contains("d/dv"), "{message}");
    // Proposition 1 for the repaired curves: the u-curves are still the given curves (their
    // crossings and tangents agreed with the v-curves and their cross-derivatives), and the
    // surface's dS/dv along v = 0 is the mean of the lifted data and the v-curves' tangents.
    let (_, rows) = read_csv(&out);
    for a in 0..9 {
        let row = &rows[a * 33];
        let want = sheet(2.0 * row[0], 0.0);
        for c in 0..3 {
            assert!((row[2 + c] - want[c]).abs() < 1e-4, "{row:?}");
        }
    }
    // At the crossing (u, v) = (0.5, 0): one-sided differences of the samples (h = 1/32)
    // against dS/dv = (0, 2, 0) + 0.005 z, to the sampling error.
    let (p0, p1, p2) = (&rows[4 * 33], &rows[4 * 33 + 1], &rows[4 * 33 + 2]);
    let h = 1.0 / 32.0;
    let dz = (-3.0 * p0[4] + 4.0 * p1[4] - p2[4]) / (2.0 * h);
    assert!((dz - lift / 2.0).abs() < 5e-4, "{dz}");
}

#[test]
fn lagrange_gordon_of_closed_curves_warns_of_its_seam() {
    let dir = temp_dir();
    let tau = std::f64::consts::TAU;
    let ring = |x: f64, a: f64| [x, a.cos(), a.sin()];
    let mut frames = String::from("curve,x,y,z\n");
    for k in 0..3 {
        for q in 0..=12 {
            let p = ring(k as f64, tau * (q % 12) as f64 / 12.0);
            frames.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    let mut stringers = String::from("curve,x,y,z\n");
    for j in 0..4 {
        for q in 0..=6 {
            let p = ring(q as f64 / 3.0, tau * j as f64 / 4.0);
            stringers.push_str(&format!("{j},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    let u = dir.path().join("stringers.csv");
    let v = dir.path().join("frames.csv");
    std::fs::write(&u, stringers).unwrap();
    std::fs::write(&v, frames).unwrap();
    let (u3, v3) = sheet_files(dir.path(), 1);
    let out = dir.path().join("out.csv");
    let run = |kind: &str, u: &Path, v: &Path| {
        let o = karkas(&[
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(u),
            "--v-curves",
            s(v),
            "--samples",
            "5,5",
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{kind}: {}", stderr(&o));
        stderr(&o)
    };
    let warned = run("gordon", &u, &v);
    assert!(
        warned.contains("warning") && warned.contains("closes in v with a C^0 seam"),
        "{warned}"
    );
    for (kind, u, v) in [
        ("gordon-spline", &u, &v),
        ("composite", &u, &v),
        ("gordon", &u3, &v3),
    ] {
        let quiet = run(kind, u, v);
        assert!(!quiet.contains("seam"), "{kind}: {quiet}");
    }
}

#[test]
fn twists_file_gives_the_surface_its_twists_and_brings_it_closer() {
    // z = sin x cos y over [0, 2]^2, curves at x, y = 0, 1, 2; the surface parameters run
    // over [0, 1] (a factor 2 per derivative), so the exact twists are
    // 4 d2z/dxdy = -4 cos x sin y at the crossings.
    let dir = temp_dir();
    let files = sheet_with_derivs(dir.path(), 10, (1.0, 1.0), [0.0; 3]);
    let twists = dir.path().join("twists.csv");
    let mut text = String::from("i,j,x,y,z\n");
    for (i, j) in [
        (2, 1),
        (0, 0),
        (1, 2),
        (0, 1),
        (2, 0),
        (1, 0),
        (0, 2),
        (1, 1),
        (2, 2),
    ] {
        let (x, y) = (i as f64, j as f64);
        text.push_str(&format!("{i},{j},0,0,{}\n", -4.0 * x.cos() * y.sin()));
    }
    std::fs::write(&twists, text).unwrap();
    let run = |name: &str, kind: &str, extra: &[&str]| {
        let out = dir.path().join(name);
        let mut args = vec![
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(&files[0]),
            "--v-curves",
            s(&files[1]),
            "--samples",
            "33,33",
            "-o",
            s(&out),
        ];
        args.extend_from_slice(extra);
        let o = karkas(&args);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        read_csv(&out).1
    };
    let with = run("with.csv", "composite", &["--twists", s(&twists)]);
    let without = run("without.csv", "composite", &[]);
    let gordon = run("gordon.csv", "gordon-spline", &[]);
    let z = |x: f64, y: f64| x.sin() * y.cos();
    let error = |rows: &[Vec<f64>]| {
        rows.iter()
            .map(|r| (r[4] - z(2.0 * r[0], 2.0 * r[1])).abs())
            .fold(0.0, f64::max)
    };
    let (e_with, e_without, e_gordon) = (error(&with), error(&without), error(&gordon));
    assert!(
        e_with < 0.8 * e_without && e_with < 0.8 * e_gordon,
        "twists {e_with:e}, derived {e_without:e}, gordon-spline {e_gordon:e}"
    );
    // The twist at the inner crossing (u, v) = (0.5, 0.5), sample (16, 16), by the central
    // difference of the samples (h = 1/32), against -4 cos 1 sin 1.
    let twist = |rows: &[Vec<f64>]| {
        let at = |a: usize, b: usize| rows[a * 33 + b][4];
        (at(17, 17) - at(17, 15) - at(15, 17) + at(15, 15)) * (32.0 * 32.0 / 4.0)
    };
    let exact = -4.0 * 1f64.cos() * 1f64.sin();
    assert!(
        (twist(&with) - exact).abs() < 1e-2,
        "{} vs {exact}",
        twist(&with)
    );
    // Twists go with bicubic and composite only, not with derivative files, and must cover
    // the crossings.
    let out = dir.path().join("bad.csv");
    let reject = |kind: &str, extra: &[&str], needles: &[&str]| {
        let mut args = vec![
            "surface",
            "coons",
            "--kind",
            kind,
            "--u-curves",
            s(&files[0]),
            "--v-curves",
            s(&files[1]),
            "-o",
            s(&out),
        ];
        args.extend_from_slice(extra);
        assert_rejected(&args, needles, &out, None);
    };
    reject(
        "gordon",
        &["--twists", s(&twists)],
        &["--twists is used only by --kind bicubic and composite"],
    );
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "composite",
        "--u-curves",
        s(&files[0]),
        "--v-curves",
        s(&files[1]),
        "--twists",
        s(&twists),
        "--u-derivs",
        s(&files[2]),
        "--v-derivs",
        s(&files[3]),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cannot be used with"), "{}", stderr(&o));
    let small = dir.path().join("small.csv");
    std::fs::write(
        &small,
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,0,0\n1,0,0,0,0\n1,1,0,0,0\n",
    )
    .unwrap();
    reject(
        "composite",
        &["--twists", s(&small)],
        &[
            "small.csv: 3 v-curves x 3 u-curves",
            "rows of twists (one per v-curve)",
        ],
    );
}

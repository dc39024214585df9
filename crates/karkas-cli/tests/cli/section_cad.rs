//! `karkas section MODEL.step|.igs`: a CAD model's faces cut by planes. A surface exported to
//! STEP and IGES cuts as the same surface built from its grid does; options that build a
//! surface, pictures and bad tolerances are refused with exit 2 and nothing written. Trimmed
//! solids are checked against Open CASCADE's own sections by tests/cad/check_section.py.

use crate::common::{
    assert_rejected, grid_csv, karkas, read_csv, s, square_model, stderr, temp_dir, write,
};
use std::path::Path;

/// The pieces of a sections CSV, as point lists.
fn pieces(path: &Path) -> Vec<Vec<[f64; 3]>> {
    let (header, rows) = read_csv(path);
    assert_eq!(header, ["section", "t", "x", "y", "z"]);
    let mut out: Vec<Vec<[f64; 3]>> = Vec::new();
    for r in rows {
        let k = r[0] as usize;
        if k == out.len() {
            out.push(Vec::new());
        }
        out[k].push([r[2], r[3], r[4]]);
    }
    out
}

/// The distance from `p` to the polylines `lines`.
fn to_lines(p: [f64; 3], lines: &[Vec<[f64; 3]>]) -> f64 {
    let mut best = f64::INFINITY;
    for line in lines {
        for w in line.windows(2) {
            let d: Vec<f64> = (0..3).map(|c| w[1][c] - w[0][c]).collect();
            let q: Vec<f64> = (0..3).map(|c| p[c] - w[0][c]).collect();
            let dd: f64 = d.iter().map(|x| x * x).sum();
            let s = if dd > 0.0 {
                ((0..3).map(|c| q[c] * d[c]).sum::<f64>() / dd).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let e: f64 = (0..3).map(|c| (q[c] - s * d[c]).powi(2)).sum();
            best = best.min(e.sqrt());
        }
    }
    best
}

#[test]
fn a_flat_square_from_step_and_iges_cuts_into_its_exact_segment() {
    let dir = temp_dir();
    let origin = [1e3, -2e3, 5.0];
    for name in ["square.step", "square.igs"] {
        let model = square_model(dir.path(), name, origin);
        let out = dir.path().join(format!("{name}.csv"));
        let o = karkas(&["section", s(&model), "--x", "1001.25", "-o", s(&out)]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("1 open piece over 1 faces"),
            "{}",
            stderr(&o)
        );
        let cut = pieces(&out);
        assert_eq!(cut.len(), 1, "{name}");
        let (first, last) = (cut[0][0], cut[0][cut[0].len() - 1]);
        let mut ys = [first[1], last[1]];
        ys.sort_by(f64::total_cmp);
        assert!(
            (ys[0] + 2e3).abs() < 1e-9 && (ys[1] + 1997.0).abs() < 1e-9,
            "{ys:?}"
        );
        for p in &cut[0] {
            assert!(
                (p[0] - 1001.25).abs() < 1e-9 && (p[2] - 5.0).abs() < 1e-12,
                "{p:?}"
            );
        }
    }
}

#[test]
fn a_closed_body_exported_to_step_cuts_as_the_surface_of_its_grid() {
    let dir = temp_dir();
    // A body of revolution about z with a wavy radius, closed around (v), away from the origin.
    let text = grid_csv(12, 16, |i, j| {
        let (z, a) = (i as f64 * 0.4, j as f64 * std::f64::consts::TAU / 16.0);
        let r = 1.0 + 0.3 * (0.7 * z).sin();
        [50.0 + r * a.cos(), -20.0 + r * a.sin(), 7.0 + z]
    });
    let grid = write(dir.path(), "body.csv", &text);
    let model = dir.path().join("body.step");
    let o = karkas(&[
        "surface",
        "bicubic",
        s(&grid),
        "--closed-v",
        "-o",
        s(&model),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let planes = [
        "--z",
        "8.1,10.3",
        "--plane",
        "1,0.3,0.2,52",
        "--tolerance",
        "1e-5",
    ];
    let from_model = dir.path().join("model.csv");
    let from_grid = dir.path().join("grid.csv");
    let mut args = vec!["section", s(&model), "-o", s(&from_model)];
    args.extend(planes);
    let o = karkas(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let mut args = vec!["section", s(&grid), "--method", "bicubic", "--closed-v"];
    args.extend(["-o", s(&from_grid)]);
    args.extend(planes);
    let o = karkas(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let (a, b) = (pieces(&from_model), pieces(&from_grid));
    assert_eq!(a.len(), b.len(), "{a:?}\n{b:?}");
    // Two polylines within T of one curve are within 2 T of each other, both ways.
    for (x, y) in [(&a, &b), (&b, &a)] {
        for line in x.iter() {
            for &p in line {
                let d = to_lines(p, y);
                assert!(d <= 2e-5, "{p:?} is {d:e} from the other's sections");
            }
        }
    }
    // The rings at z = 8.1 and 10.3 are closed: the last point repeats the first.
    for line in &a[..2] {
        assert_eq!(line[0], line[line.len() - 1]);
    }
}

#[test]
fn a_model_named_by_no_cad_extension_is_cut_when_no_method_is_given() {
    // A pipe (`<(cat m.step)`), /dev/stdin or a file named otherwise: STEP and IGES told by
    // their first bytes, cut as the file named .step/.igs is; with --method it is a grid.
    let dir = temp_dir();
    for name in ["square.step", "square.igs"] {
        let model = square_model(dir.path(), name, [0.0; 3]);
        let direct = dir.path().join(format!("{name}.csv"));
        let o = karkas(&["section", s(&model), "--x", "1.25", "-o", s(&direct)]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let renamed = dir.path().join(format!("{name}.txt"));
        std::fs::copy(&model, &renamed).unwrap();
        let out = dir.path().join(format!("{name}.renamed.csv"));
        let o = karkas(&["section", s(&renamed), "--x", "1.25", "-o", s(&out)]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert_eq!(pieces(&out), pieces(&direct), "{name}");
        let piped = dir.path().join(format!("{name}.piped.csv"));
        let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_karkas"))
            .args(["section", "/dev/stdin", "--x", "1.25", "-o", s(&piped)])
            .stdin(std::process::Stdio::piped())
            .stderr(std::process::Stdio::piped())
            .spawn()
            .unwrap();
        use std::io::Write as _;
        let text = std::fs::read(&model).unwrap();
        child.stdin.take().unwrap().write_all(&text).unwrap();
        let o = child.wait_with_output().unwrap();
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        assert_eq!(pieces(&piped), pieces(&direct), "{name}");
    }
    // Text that is neither STEP nor IGES, without --method: the message names the input.
    let out = dir.path().join("none.csv");
    let points = write(dir.path(), "points.txt", "x,y\n0,0\n1,1\n");
    assert_rejected(
        &["section", s(&points), "--x", "0.5", "-o", s(&out)],
        "points.txt is neither",
        &out,
        None,
    );
}

#[test]
fn options_that_build_a_surface_pictures_and_bad_tolerances_are_refused_for_a_model() {
    let dir = temp_dir();
    let model = square_model(dir.path(), "square.step", [0.0; 3]);
    let out = dir.path().join("out.csv");
    let m = s(&model);
    for (extra, needle) in [
        (vec!["--method", "ll"], "--method"),
        (vec!["--order", "2"], "--order"),
        (vec!["--cells", "8,8"], "--cells"),
        (vec!["--closed-u"], "--closed-u"),
        (vec!["--tolerance", "0"], "tolerance"),
        (vec!["--tolerance", "1e-20"], "tolerance"),
    ] {
        let mut args = vec!["section", m, "--x", "0.5", "-o", s(&out)];
        args.extend(extra);
        assert_rejected(&args, needle, &out, None);
    }
    let svg = dir.path().join("out.svg");
    assert_rejected(
        &["section", m, "--x", "0.5", "-o", s(&svg)],
        "CSV",
        &svg,
        None,
    );
    // A grid without --method names what is needed.
    let grid = write(
        dir.path(),
        "g.csv",
        &grid_csv(4, 4, |i, j| [i as f64, j as f64, 0.0]),
    );
    assert_rejected(
        &["section", s(&grid), "--x", "0.5", "-o", s(&out)],
        "--method",
        &out,
        None,
    );
}

//! Reading back the CAD files karkas writes: every STEP and IGES file of the curve and surface
//! commands (LL, spline, fit, bicubic, composite Coons) reads back to the same degrees,
//! knots, weights and control points, bit for bit. The check: the file written again from
//! what was read is the same text (every real is written with 17 significant digits, so equal
//! text means equal numbers), header time stamps aside.

use crate::common::{karkas, s, stderr, temp_dir};
use karkas_io::cad::read::{read_cad, CadModel};
use karkas_io::cad::CadEntity;
use karkas_io::{iges, step};
use std::path::{Path, PathBuf};

fn data(name: &str) -> String {
    format!("{}/../../data/{name}", env!("CARGO_MANIFEST_DIR"))
}

/// A curve network sampled from a smooth surface (as tests/cad/check_cad.py builds it).
fn network(dir: &Path) -> (PathBuf, PathBuf) {
    let surface = |u: f64, v: f64| {
        [
            3.0 * u,
            2.0 * v + 0.3 * (3.0 * u).sin(),
            (2.0 * u).sin() * (1.0 + v * v),
        ]
    };
    let (m, n, per) = (4usize, 3usize, 5usize);
    let mut paths = Vec::new();
    for (name, count, steps, along_u) in [
        ("u", n, (m - 1) * per, true),
        ("v", m, (n - 1) * per, false),
    ] {
        let mut text = String::from("curve,x,y,z\n");
        for c in 0..count {
            for k in 0..=steps {
                let t = k as f64 / steps as f64;
                let p = if along_u {
                    surface(t, c as f64 / (n - 1) as f64)
                } else {
                    surface(c as f64 / (m - 1) as f64, t)
                };
                text.push_str(&format!("{c},{:?},{:?},{:?}\n", p[0], p[1], p[2]));
            }
        }
        let path = dir.join(format!("net-{name}.csv"));
        std::fs::write(&path, text).unwrap();
        paths.push(path);
    }
    (paths[0].clone(), paths[1].clone())
}

/// The lines of a file that carry geometry: STEP's data section, IGES's directory and
/// parameter sections (the header and global section hold the time stamp).
fn geometry_lines(text: &str) -> Vec<String> {
    if text.starts_with("ISO-10303-21") {
        let data = text.split("DATA;\n").nth(1).unwrap_or("");
        data.lines().map(str::to_owned).collect()
    } else {
        text.lines()
            .filter(|l| l.len() == 80 && matches!(&l[72..73], "D" | "P"))
            .map(str::to_owned)
            .collect()
    }
}

/// The file written again from `model`, by the writer of `path`'s format.
fn rewrite(model: &CadModel, path: &Path) -> String {
    let name = path.file_stem().unwrap().to_str().unwrap();
    let curves: Vec<_> = model
        .shape
        .curves
        .iter()
        .map(|c| c.to_bspline().expect("a polynomial curve"))
        .collect();
    let surfaces: Vec<_> = model
        .shape
        .faces
        .iter()
        .map(|f| f.surface.to_bspline().expect("a polynomial surface"))
        .collect();
    let mut entities: Vec<CadEntity<'_>> = curves.iter().map(CadEntity::Curve).collect();
    entities.extend(surfaces.iter().map(CadEntity::Surface));
    if path.extension().is_some_and(|e| e == "step") {
        step::step_text(&entities, name)
    } else {
        iges::iges_text(&entities, name)
    }
}

#[test]
fn every_step_and_iges_file_karkas_writes_reads_back_bit_for_bit() {
    let dir = temp_dir();
    let (u_net, v_net) = network(dir.path());
    let cases: Vec<(&str, bool, Vec<String>)> = vec![
        (
            "ll-curve",
            true,
            vec![
                "curve".into(),
                "ll".into(),
                "--order".into(),
                "5".into(),
                "--closed".into(),
                data("contour-53.csv"),
            ],
        ),
        (
            "spline-curve",
            true,
            vec![
                "curve".into(),
                "spline".into(),
                "--ends".into(),
                "periodic".into(),
                "--param".into(),
                "centripetal".into(),
                data("contour-53.csv"),
            ],
        ),
        (
            "fit-curve",
            true,
            vec![
                "curve".into(),
                "fit".into(),
                "--knots".into(),
                "0,0.3,0.5,0.7,1".into(),
                data("hydrofoil-profile.csv"),
            ],
        ),
        (
            "ll-surface",
            false,
            vec![
                "surface".into(),
                "ll".into(),
                "--order".into(),
                "3".into(),
                data("aircraft-15x31.csv"),
            ],
        ),
        (
            "ll-surface-closed",
            false,
            vec![
                "surface".into(),
                "ll".into(),
                "--order".into(),
                "3".into(),
                "--closed-v".into(),
                data("aircraft-15x31.csv"),
            ],
        ),
        (
            "bicubic-surface",
            false,
            vec![
                "surface".into(),
                "bicubic".into(),
                "--param".into(),
                "chord".into(),
                data("aircraft-15x31.csv"),
            ],
        ),
        (
            "composite-coons",
            false,
            vec![
                "surface".into(),
                "coons".into(),
                "--kind".into(),
                "composite".into(),
                "--u-curves".into(),
                s(&u_net).into(),
                "--v-curves".into(),
                s(&v_net).into(),
            ],
        ),
    ];
    for (name, is_curve, args) in &cases {
        for ext in ["step", "igs"] {
            let out = dir.path().join(format!("{name}.{ext}"));
            let mut argv: Vec<&str> = args.iter().map(String::as_str).collect();
            argv.extend(["-o", s(&out)]);
            let o = karkas(&argv);
            assert!(o.status.success(), "{name}.{ext}: {}", stderr(&o));
            let written = std::fs::read_to_string(&out).unwrap();
            let model = read_cad(&out).unwrap_or_else(|e| panic!("{name}.{ext}: {e}"));
            assert!(
                model.warning().is_none(),
                "{name}.{ext}: {:?}",
                model.warning()
            );
            let (faces, curves) = (model.shape.faces.len(), model.shape.curves.len());
            assert_eq!(
                (faces, curves),
                if *is_curve { (0, 1) } else { (1, 0) },
                "{name}.{ext}"
            );
            let again = rewrite(&model, &out);
            let (a, b) = (geometry_lines(&written), geometry_lines(&again));
            assert!(!a.is_empty());
            assert_eq!(a.len(), b.len(), "{name}.{ext}: line counts");
            for (k, (x, y)) in a.iter().zip(&b).enumerate() {
                assert_eq!(
                    x, y,
                    "{name}.{ext}: geometry line {k} differs after reading back"
                );
            }
            for f in &model.shape.faces {
                assert!(f.surface.weights().as_slice().iter().all(|&w| w == 1.0));
                assert_eq!(f.loops.len(), usize::from(ext == "step"));
            }
        }
    }
}

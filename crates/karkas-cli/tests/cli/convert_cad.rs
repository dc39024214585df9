//! `karkas convert MODEL.step OUT.obj --tolerance T`: a CAD model's faces meshed to a chordal
//! tolerance (a flat square read back from STEP and IGES covers its area exactly), and bad
//! input refused with exit 2 and nothing written. Curved and trimmed solids are checked
//! against Open CASCADE and trimesh by tests/cad/check_convert.py.

use crate::common::{grid_csv, karkas, s, stderr, temp_dir, write};
use std::path::{Path, PathBuf};

/// The square [x0, x0 + 3] x [y0, y0 + 3] at z = z0 as a bicubic surface written to `name`.
fn square(dir: &Path, name: &str, origin: [f64; 3]) -> PathBuf {
    let grid = write(
        dir,
        "square.csv",
        &grid_csv(4, 5, |i, j| {
            [origin[0] + i as f64, origin[1] + 0.75 * j as f64, origin[2]]
        }),
    );
    let out = dir.join(name);
    let o = karkas(&["surface", "bicubic", s(&grid), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    out
}

/// The vertices and triangles of an OBJ file.
fn read_obj(path: &Path) -> (Vec<[f64; 3]>, Vec<[usize; 3]>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut vertices = Vec::new();
    let mut triangles = Vec::new();
    for line in text.lines() {
        let mut words = line.split_whitespace();
        match words.next() {
            Some("v") => {
                let v: Vec<f64> = words.take(3).map(|w| w.parse().unwrap()).collect();
                vertices.push([v[0], v[1], v[2]]);
            }
            Some("f") => {
                let f: Vec<usize> = words
                    .map(|w| w.split('/').next().unwrap().parse::<usize>().unwrap() - 1)
                    .collect();
                triangles.push([f[0], f[1], f[2]]);
            }
            _ => {}
        }
    }
    (vertices, triangles)
}

#[test]
fn a_flat_square_from_step_and_iges_meshes_to_its_exact_area() {
    let dir = temp_dir();
    let origin = [1e3, -2e3, 5.0];
    for name in ["square.step", "square.igs"] {
        let model = square(dir.path(), name, origin);
        let out = dir.path().join(format!("{name}.obj"));
        let o = karkas(&["convert", s(&model), s(&out), "--tolerance", "1e-3"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let (v, t) = read_obj(&out);
        assert!(!t.is_empty(), "{name}: no triangles");
        let mut area = 0.0;
        for tri in &t {
            let [a, b, c] = tri.map(|k| v[k]);
            let (e, f) = (
                [b[0] - a[0], b[1] - a[1], b[2] - a[2]],
                [c[0] - a[0], c[1] - a[1], c[2] - a[2]],
            );
            // The square lies in z = z0 and the triangles turn counter-clockwise seen from +z
            // (the surface's own normal).
            area += 0.5 * (e[0] * f[1] - e[1] * f[0]);
        }
        assert!((area - 9.0).abs() < 1e-9, "{name}: area {area}");
        for p in &v {
            assert!((p[2] - origin[2]).abs() < 1e-12, "{name}: {p:?}");
            assert!(
                (origin[0] - 1e-9..=origin[0] + 3.0 + 1e-9).contains(&p[0]),
                "{p:?}"
            );
        }
    }
}

#[test]
fn bad_tolerances_and_inputs_exit_2_and_write_nothing() {
    let dir = temp_dir();
    let model = square(dir.path(), "square.step", [0.0; 3]);
    let out = dir.path().join("out.stl");
    for t in ["0", "-1", "nan", "inf"] {
        let option = format!("--tolerance={t}");
        let o = karkas(&["convert", s(&model), s(&out), &option]);
        assert_eq!(o.status.code(), Some(2), "{t}: {}", stderr(&o));
        assert!(stderr(&o).contains("tolerance"), "{t}: {}", stderr(&o));
        assert!(!out.exists(), "{t}");
    }
    // --tolerance is for CAD models only.
    let points = write(dir.path(), "points.csv", "x,y\n0,0\n1,1\n2,0\n");
    let svg = dir.path().join("points.svg");
    let o = karkas(&["convert", s(&points), s(&svg), "--tolerance", "1e-3"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("--tolerance"), "{}", stderr(&o));
    assert!(!svg.exists());
    // A model cut short, and a CAD model to a format that is not a mesh.
    let text = std::fs::read_to_string(&model).unwrap();
    let cut = write(dir.path(), "cut.step", &text[..text.len() / 2]);
    let o = karkas(&["convert", s(&cut), s(&out)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cut.step"), "{}", stderr(&o));
    let csv = dir.path().join("model.csv");
    let o = karkas(&["convert", s(&model), s(&csv)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!csv.exists());
}

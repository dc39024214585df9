//! `karkas convert MODEL.step OUT.obj --tolerance T`: a CAD model's faces meshed to a chordal
//! tolerance (a flat square read back from STEP and IGES covers its area exactly), and bad
//! input refused with exit 2 and nothing written. Curved and trimmed solids are checked
//! against Open CASCADE and trimesh by tests/cad/check_convert.py.

use crate::common::{
    assert_rejected, grid_csv, karkas, read_obj, s, square_model, stderr, temp_dir, write,
};
use std::path::{Path, PathBuf};

#[test]
fn a_flat_square_from_step_and_iges_meshes_to_its_exact_area() {
    let dir = temp_dir();
    let origin = [1e3, -2e3, 5.0];
    for name in ["square.step", "square.igs"] {
        let model = square_model(dir.path(), name, origin);
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
    let model = square_model(dir.path(), "square.step", [0.0; 3]);
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

/// The header of the STEP file `model` (up to its DATA section) with `entities` as its data.
fn step_with(model: &Path, entities: &str) -> String {
    let text = std::fs::read_to_string(model).unwrap();
    let head = &text[..text.find("DATA;\n").unwrap() + "DATA;\n".len()];
    format!("{head}{entities}ENDSEC;\nEND-ISO-10303-21;\n")
}

#[test]
fn a_model_without_faces_is_refused_as_such_before_the_tolerance() {
    let dir = temp_dir();
    let model = square_model(dir.path(), "square.step", [0.0; 3]);
    let empty = write(dir.path(), "empty.step", &step_with(&model, ""));
    let point = "#1=CARTESIAN_POINT('',(1.,2.,3.));\n";
    let point = write(dir.path(), "point.step", &step_with(&model, point));
    let points = write(dir.path(), "line.csv", "x,y\n0,0\n1,1\n2,0\n3,1\n");
    let curve = dir.path().join("curve.step");
    let o = karkas(&["curve", "spline", s(&points), "-o", s(&curve)]);
    assert!(o.status.success(), "{}", stderr(&o));
    // An existing output is kept.
    let out = write(dir.path(), "out.stl", "kept");
    for (m, curves) in [(&empty, 0), (&point, 0), (&curve, 1)] {
        let name = m.file_name().unwrap().to_str().unwrap();
        let message = format!("cannot mesh {}: the model has no faces to mesh", s(m));
        let count = format!("({curves} curves)");
        let needles: &[&str] = &[&message, &count, name];
        assert_rejected(&["convert", s(m), s(&out)], needles, &out, Some("kept"));
        let o = karkas(&["convert", s(m), s(&out)]);
        assert!(!stderr(&o).contains("tolerance"), "{}", stderr(&o));
    }
}

/// A bicubic grid of 4 x 5 nodes `(i, 0.75 j, bulge i (3 - i)) * scale` written as `name`.
fn scaled_model(dir: &Path, name: &str, scale: f64, bulge: f64) -> PathBuf {
    let text = grid_csv(4, 5, |i, j| {
        let (x, y) = (i as f64, 0.75 * j as f64);
        [x * scale, y * scale, bulge * x * (3.0 - x) * scale]
    });
    let grid = write(dir, &format!("{name}.csv"), &text);
    let out = dir.join(name);
    let o = karkas(&["surface", "bicubic", s(&grid), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    out
}

#[test]
fn models_at_the_ends_of_the_coordinate_range() {
    let dir = temp_dir();
    // 1e150, within the range: the square meshes to its area (spade's triangulation takes
    // coordinates up to about 3e60 only, so parameters are scaled into its range).
    let far = scaled_model(dir.path(), "far.step", 1e150, 0.0);
    let out = dir.path().join("far.obj");
    let o = karkas(&["convert", s(&far), s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (v, t) = read_obj(&out);
    assert!(v.len() >= 4, "{} vertices", v.len());
    let area: f64 = t
        .iter()
        .map(|tri| {
            let [a, b, c] = tri.map(|k| v[k]);
            0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        })
        .sum();
    assert!((area / 9e300 - 1.0).abs() < 1e-9, "area {area:e}");
    // 1e307, out of range: both commands refuse the model (inspect used to panic).
    let text = std::fs::read_to_string(&far)
        .unwrap()
        .replace("E150", "E307");
    let beyond = write(dir.path(), "beyond.step", &text);
    let points = write(dir.path(), "points.csv", "x,y,z\n1,2,3\n");
    let report = dir.path().join("report.csv");
    let needles: &[&str] = &["beyond.step", "coordinates out of range", "3e307"];
    let stl = dir.path().join("beyond.stl");
    assert_rejected(&["convert", s(&beyond), s(&stl)], needles, &stl, None);
    let args = [
        "inspect",
        s(&beyond),
        "--points",
        s(&points),
        "-o",
        s(&report),
    ];
    assert_rejected(&args, needles, &report, None);
}

#[test]
fn a_tolerance_far_below_the_model_is_refused_by_the_vertex_limit() {
    let dir = temp_dir();
    let model = scaled_model(dir.path(), "bulge.step", 1.0, 0.1);
    let out = write(dir.path(), "out.stl", "kept");
    let start = std::time::Instant::now();
    let needles: &[&str] = &["bulge.step", "vertices", "give a larger tolerance"];
    let args = ["convert", s(&model), s(&out), "--tolerance", "1e-300"];
    assert_rejected(&args, needles, &out, Some("kept"));
    assert!(
        start.elapsed().as_secs_f64() < 60.0,
        "{:?}",
        start.elapsed()
    );
    // A tolerance far above the model's size gives a coarse mesh, not an error.
    let coarse = dir.path().join("coarse.obj");
    let o = karkas(&["convert", s(&model), s(&coarse), "--tolerance", "1e300"]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!read_obj(&coarse).1.is_empty());
}

#[test]
fn a_model_on_standard_input_is_meshed() {
    let dir = temp_dir();
    let model = square_model(dir.path(), "square.step", [0.0; 3]);
    let text = std::fs::read_to_string(&model).unwrap();
    let out = dir.path().join("piped.obj");
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args(["convert", "-", s(&out), "--tolerance", "1e-3"])
        .stdin(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write as _;
    child
        .stdin
        .take()
        .unwrap()
        .write_all(text.as_bytes())
        .unwrap();
    let o = child.wait_with_output().unwrap();
    assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr));
    // The same mesh as from the file itself.
    let direct = dir.path().join("direct.obj");
    let o = karkas(&["convert", s(&model), s(&direct), "--tolerance", "1e-3"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (piped, file) = (read_obj(&out), read_obj(&direct));
    assert!(!piped.1.is_empty());
    assert_eq!(piped, file);
}

/// The signed distance of `p` from the box `[lo, hi]` with every edge rounded to radius `r`:
/// the distance from the box shrunk by `r`, less `r`.
fn rounded_box_distance(p: [f64; 3], lo: [f64; 3], hi: [f64; 3], r: f64) -> f64 {
    let q: [f64; 3] = std::array::from_fn(|i| {
        let (centre, half) = (0.5 * (lo[i] + hi[i]), 0.5 * (hi[i] - lo[i]) - r);
        (p[i] - centre).abs() - half
    });
    let outside = q.iter().map(|x| x.max(0.0).powi(2)).sum::<f64>().sqrt();
    let inside = q.iter().fold(f64::NEG_INFINITY, |m, &x| m.max(x)).min(0.0);
    outside + inside - r
}

#[test]
fn a_filleted_box_meshes_closed_on_its_surface_with_its_exact_volume() {
    // Open CASCADE's box with every edge filleted (data/cad/README.md): three blends meet at
    // each corner on a sphere's pole, and the fillets' cylinders end on its arcs. As IGES its
    // flat sides are planes (entity 108) and its faces say nothing of their outside: the
    // blends' surfaces run the other way round from the planes.
    for name in ["filleted-box.step", "filleted-box.igs"] {
        let model = format!("{}/../../data/cad/{name}", env!("CARGO_MANIFEST_DIR"));
        filleted_box_meshes(&model);
    }
}

/// The checks of [`a_filleted_box_meshes_closed_on_its_surface_with_its_exact_volume`] on
/// the model file `model`.
fn filleted_box_meshes(model: &str) {
    let (lo, hi, r) = ([-20.0, 5.0, 7.0], [-8.0, 13.0, 12.0], 1.5);
    let (a, b, c) = (12.0 - 2.0 * r, 8.0 - 2.0 * r, 5.0 - 2.0 * r);
    let pi = std::f64::consts::PI;
    let volume = a * b * c
        + 2.0 * r * (a * b + b * c + a * c)
        + pi * r * r * (a + b + c)
        + 4.0 / 3.0 * pi * r.powi(3);
    let area = 2.0 * (a * b + b * c + a * c) + 2.0 * pi * r * (a + b + c) + 4.0 * pi * r * r;
    let dir = temp_dir();
    for tolerance in [0.15, 0.05, 0.015, 0.005] {
        let out = dir.path().join(format!("box-{tolerance}.obj"));
        let o = karkas(&[
            "convert",
            model,
            s(&out),
            "--tolerance",
            &tolerance.to_string(),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let (v, t) = read_obj(&out);
        // Closed and oriented: each side used once in each direction.
        let mut sides = std::collections::BTreeMap::new();
        for tri in &t {
            for k in 0..3 {
                *sides.entry((tri[k], tri[(k + 1) % 3])).or_insert(0) += 1;
            }
        }
        for (&(p, q), &n) in &sides {
            assert_eq!(
                n, 1,
                "{model} T {tolerance}: side {p}-{q} used {n} times one way"
            );
            assert_eq!(
                sides.get(&(q, p)),
                Some(&1),
                "{model} T {tolerance}: side {p}-{q} open"
            );
        }
        for p in &v {
            let d = rounded_box_distance(*p, lo, hi, r);
            assert!(
                d.abs() < 1e-9,
                "{model} T {tolerance}: vertex {p:?} {d:e} off the surface"
            );
        }
        let mut enclosed = 0.0;
        for tri in &t {
            let [p, q, w] = tri.map(|k| v[k]);
            let mid: [f64; 3] = std::array::from_fn(|i| 0.5 * (p[i] + q[i]));
            let d = rounded_box_distance(mid, lo, hi, r);
            assert!(
                d.abs() <= tolerance,
                "{model} T {tolerance}: side {p:?}-{q:?} {d:e} off"
            );
            enclosed += (p[0] * (q[1] * w[2] - q[2] * w[1]) - p[1] * (q[0] * w[2] - q[2] * w[0])
                + p[2] * (q[0] * w[1] - q[1] * w[0]))
                / 6.0;
        }
        // Outward winding, and no more volume missing than a layer of the tolerance.
        assert!(enclosed > 0.0, "{model} T {tolerance}: volume {enclosed}");
        assert!(
            (volume - enclosed).abs() <= tolerance * area,
            "{model} T {tolerance}: volume {enclosed} against {volume}"
        );
    }
}

/// Runs `karkas ARGS` with `input` on standard input.
fn karkas_fed(args: &[&str], input: &[u8]) -> std::process::Output {
    let mut child = std::process::Command::new(env!("CARGO_BIN_EXE_karkas"))
        .args(args)
        .stdin(std::process::Stdio::piped())
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    use std::io::Write as _;
    // The command may refuse before reading all of it: a broken pipe is its answer.
    let _ = child.stdin.take().unwrap().write_all(input);
    child.wait_with_output().unwrap()
}

#[test]
fn a_model_or_mesh_named_by_no_known_extension_is_told_by_its_content() {
    // A pipe (`<(cat m.step)` is /dev/fd/63), /dev/stdin, or a file named otherwise: STEP and
    // IGES by their first bytes, as `-` is; the same mesh as from the file named .step/.igs.
    let dir = temp_dir();
    for name in ["square.step", "square.igs"] {
        let model = square_model(dir.path(), name, [2.0, -1.0, 0.5]);
        let direct = dir.path().join(format!("{name}.direct.obj"));
        let o = karkas(&["convert", s(&model), s(&direct), "--tolerance", "1e-3"]);
        assert!(o.status.success(), "{}", stderr(&o));
        let renamed = dir.path().join(format!("{name}.model"));
        std::fs::copy(&model, &renamed).unwrap();
        let by_name = dir.path().join(format!("{name}.renamed.obj"));
        let o = karkas(&["convert", s(&renamed), s(&by_name), "--tolerance", "1e-3"]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let piped = dir.path().join(format!("{name}.piped.obj"));
        let text = std::fs::read(&model).unwrap();
        let args = ["convert", "/dev/stdin", s(&piped), "--tolerance", "1e-3"];
        let o = karkas_fed(&args, &text);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let expected = read_obj(&direct);
        assert!(!expected.1.is_empty());
        assert_eq!(read_obj(&by_name), expected, "{name}");
        assert_eq!(read_obj(&piped), expected, "{name}");
    }
    // A binary STL through a pipe is a mesh (it was read as curve points before).
    let model = square_model(dir.path(), "square.step", [0.0; 3]);
    let stl = dir.path().join("square.stl");
    let o = karkas(&["convert", s(&model), s(&stl)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let from_pipe = dir.path().join("from-pipe.obj");
    let o = karkas_fed(
        &["convert", "/dev/stdin", s(&from_pipe)],
        &std::fs::read(&stl).unwrap(),
    );
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(
        read_obj(&from_pipe).1.len(),
        read_obj(&model_mesh(&model, dir.path())).1.len()
    );
    // --tolerance on points through a pipe, and on a mesh, is refused naming the option.
    let svg = dir.path().join("points.svg");
    let args = ["convert", "/dev/stdin", s(&svg), "--tolerance", "1e-3"];
    let o = karkas_fed(&args, b"x,y\n0,0\n1,1\n2,0\n");
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(stderr(&o).contains("--tolerance") && stderr(&o).contains("/dev/stdin"));
    assert!(!svg.exists());
    let obj = dir.path().join("again.obj");
    let o = karkas(&["convert", s(&stl), s(&obj), "--tolerance", "1e-3"]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(!obj.exists());
}

/// The OBJ mesh of `model` at its default tolerance, written into `dir`.
fn model_mesh(model: &Path, dir: &Path) -> PathBuf {
    let out = dir.join("model-default.obj");
    let o = karkas(&["convert", s(model), s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    out
}

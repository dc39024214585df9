//! Bodies as CAD takes them: a pole is a vertex (no edge), a closed direction one seam edge
//! used twice, `--cap` closes planar open boundary loops, and a closed shell is a STEP solid
//! whose volume the command reports (docs/reference/contract.md, `--cap`). Open CASCADE's reading
//! of the same files (BRepCheck, areas, volumes) is checked by tests/cad/check_bodies.py.

use crate::common::{grid_csv, karkas, s, stderr, temp_dir, write};
use std::f64::consts::PI;

/// The STEP entity instances of a given type.
fn count(text: &str, entity: &str) -> usize {
    text.matches(&format!("={entity}(")).count()
}

/// An ellipsoid with semi-axes (a, b, c) as a grid of `rows` meridian stations from pole to
/// pole (the first and last rows one repeated point) and `cols` points around.
fn ellipsoid(rows: usize, cols: usize, (a, b, c): (f64, f64, f64)) -> String {
    grid_csv(rows, cols, |i, j| {
        let theta = PI * i as f64 / (rows - 1) as f64;
        let phi = 2.0 * PI * j as f64 / cols as f64;
        let r = if i == 0 || i == rows - 1 {
            0.0
        } else {
            theta.sin()
        };
        [a * theta.cos(), b * r * phi.cos(), c * r * phi.sin()]
    })
}

/// A tube along x whose sections are ellipses, open at both ends.
fn tube(rows: usize, cols: usize) -> String {
    grid_csv(rows, cols, |i, j| {
        let phi = 2.0 * PI * j as f64 / cols as f64;
        let r = 1.0 + 0.2 * (i as f64 / 3.0).sin();
        [0.3 * i as f64, r * phi.cos(), 0.6 * r * phi.sin()]
    })
}

/// The enclosed volume the command reports on standard error.
fn reported_volume(err: &str) -> f64 {
    let at = err.find("enclosed volume ").expect(err) + "enclosed volume ".len();
    err[at..]
        .split(|c: char| c == ')' || c.is_whitespace())
        .next()
        .unwrap()
        .parse()
        .unwrap()
}

#[test]
fn a_body_closed_by_poles_is_a_solid_with_one_seam_and_no_pole_edges() {
    let dir = temp_dir();
    let (a, b, c) = (2.0, 1.0, 0.7);
    // LL interpolation converges slowly at the poles: 49 x 96 nodes keep it within 1e-3.
    let input = write(dir.path(), "e.csv", &ellipsoid(49, 96, (a, b, c)));
    let exact = 4.0 / 3.0 * PI * a * b * c;
    for method in [
        vec!["surface", "bicubic", "--closed-v"],
        vec!["surface", "ll", "--closed-v", "--interpolate"],
    ] {
        let out = dir.path().join("e.step");
        let mut args = method.clone();
        args.extend([s(&input), "-o", s(&out)]);
        let o = karkas(&args);
        assert!(o.status.success(), "{method:?}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        // The seam (one edge, twice in the loop) and the two poles (vertices only).
        assert_eq!(count(&text, "EDGE_CURVE"), 1, "{method:?}");
        assert_eq!(count(&text, "ORIENTED_EDGE"), 2, "{method:?}");
        assert_eq!(count(&text, "VERTEX_POINT"), 2, "{method:?}");
        assert_eq!(count(&text, "CLOSED_SHELL"), 1, "{method:?}");
        assert_eq!(count(&text, "MANIFOLD_SOLID_BREP"), 1, "{method:?}");
        let volume = reported_volume(&stderr(&o));
        assert!(
            (volume - exact).abs() < 1e-3 * exact,
            "{method:?}: {volume} against {exact}"
        );
    }
}

#[test]
fn caps_close_a_tube_into_a_solid() {
    let dir = temp_dir();
    let input = write(dir.path(), "t.csv", &tube(13, 24));
    for ext in ["step", "iges"] {
        let out = dir.path().join(format!("t.{ext}"));
        let o = karkas(&[
            "surface",
            "bicubic",
            "--closed-v",
            "--cap",
            s(&input),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(stderr(&o).contains("2 planar caps"), "{}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        if ext == "step" {
            assert_eq!(count(&text, "PLANE"), 2);
            assert_eq!(count(&text, "ADVANCED_FACE"), 3);
            assert_eq!(count(&text, "EDGE_CURVE"), 3);
            assert_eq!(count(&text, "MANIFOLD_SOLID_BREP"), 1);
        } else {
            // Two trimmed planes beside the B-spline face.
            let kinds: Vec<&str> = text
                .lines()
                .filter(|l| l.len() == 80 && &l[72..73] == "D")
                .step_by(2)
                .map(|l| l[..8].trim())
                .collect();
            assert_eq!(
                kinds.iter().filter(|k| **k == "144").count(),
                2,
                "{kinds:?}"
            );
        }
    }
    // Without --cap the tube is an open shell with no volume.
    let out = dir.path().join("open.step");
    let o = karkas(&["surface", "bicubic", "--closed-v", s(&input), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(!stderr(&o).contains("volume"), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(count(&text, "OPEN_SHELL"), 1);
}

#[test]
fn a_cap_on_a_boundary_that_cannot_take_one_exits_2() {
    let dir = temp_dir();
    // Open in both directions and not flat: the one boundary loop is not planar.
    let input = write(
        dir.path(),
        "g.csv",
        &grid_csv(5, 6, |i, j| {
            let (x, y) = (i as f64, j as f64);
            [x, y, (0.5 * x).sin() * (0.3 * y).cos()]
        }),
    );
    let out = dir.path().join("g.step");
    let o = karkas(&["surface", "bicubic", "--cap", s(&input), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--cap: the open boundary loop"),
        "{}",
        stderr(&o)
    );
    assert!(
        stderr(&o).contains("is not planar: it strays"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists());
    // A body closed by its poles has nothing to cap.
    let input = write(dir.path(), "e.csv", &ellipsoid(9, 12, (1.0, 1.0, 1.0)));
    let o = karkas(&[
        "surface",
        "bicubic",
        "--closed-v",
        "--cap",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--cap: the surface has no open boundary"),
        "{}",
        stderr(&o)
    );
    // --cap is for STEP, IGES and the triangle meshes.
    for ext in ["csv", "vts"] {
        let o = karkas(&[
            "surface",
            "bicubic",
            "--cap",
            s(&input),
            "-o",
            s(&dir.path().join(format!("e.{ext}"))),
        ]);
        assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
        assert!(stderr(&o).contains("--cap: only"), "{}", stderr(&o));
    }
    // A closed body's mesh has nothing to cap either.
    let o = karkas(&[
        "surface",
        "bicubic",
        "--closed-v",
        "--cap",
        s(&input),
        "-o",
        s(&dir.path().join("e.stl")),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--cap: the surface has no open boundary"),
        "{}",
        stderr(&o)
    );
}

/// A tapered wing of sharp-trailing-edge sections, each in Selig order with the edge first and
/// last (when `repeat`) or first only.
fn wing(rows: usize, cols: usize, repeat: bool) -> String {
    let half = (cols - 1) / 2;
    let all = grid_csv(rows, cols, |i, j| {
        let span = 4.0 * i as f64 / (rows - 1) as f64;
        let chord = 2.0 - 0.25 * span;
        let k = (j as i64 - half as i64).unsigned_abs() as f64;
        let x = 0.5 * (1.0 - (PI * k / half as f64).cos());
        let t = if k as usize == half {
            0.0
        } else {
            0.6 * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                - 0.1036 * x.powi(4))
        };
        let y = if j < half { t } else { -t };
        [0.3 * span + chord * x, chord * y, span]
    });
    if repeat {
        return all;
    }
    // Leave out the last column (the repeated trailing edge).
    all.lines()
        .filter(|l| {
            l.split(',')
                .nth(1)
                .is_none_or(|j| j != (cols - 1).to_string())
        })
        .map(|l| format!("{l}\n"))
        .collect()
}

#[test]
fn a_creased_capped_wing_is_a_solid_with_a_sharp_trailing_edge() {
    let dir = temp_dir();
    for (name, repeat) in [("repeated", true), ("appended", false)] {
        let input = write(dir.path(), &format!("{name}.csv"), &wing(9, 41, repeat));
        let out = dir.path().join(format!("{name}.step"));
        let o = karkas(&[
            "surface",
            "bicubic",
            "--crease-v",
            "--cap",
            s(&input),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{name}: {}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        assert_eq!(count(&text, "MANIFOLD_SOLID_BREP"), 1, "{name}");
        assert_eq!(count(&text, "PLANE"), 2, "{name}");
        // The trailing edge is the seam (one edge, used by the face twice), the root and tip
        // loops the two others.
        assert_eq!(count(&text, "EDGE_CURVE"), 3, "{name}");
        let volume = reported_volume(&stderr(&o));
        assert!(volume > 0.1 && volume < 1.0, "{name}: {volume}");
        // The tangents on the two sides of the trailing edge differ: a crease.
        let samples = dir.path().join(format!("{name}-s.csv"));
        let o = karkas(&[
            "surface",
            "bicubic",
            "--crease-v",
            "--samples",
            "5,201",
            s(&input),
            "-o",
            s(&samples),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let (_, rows) = crate::common::read_csv(&samples);
        let row: Vec<[f64; 3]> = rows[2 * 201..3 * 201]
            .iter()
            .map(|r| [r[2], r[3], r[4]])
            .collect();
        let along = |a: [f64; 3], b: [f64; 3]| [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
        let (start, end) = (along(row[0], row[1]), along(row[199], row[200]));
        let dot: f64 = (0..3).map(|c| start[c] * end[c]).sum();
        let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
        let angle = (dot / norm(start) / norm(end))
            .clamp(-1.0, 1.0)
            .acos()
            .to_degrees();
        assert!(angle > 10.0, "{name}: tangents {angle} degrees apart");
        assert_eq!(row[0], row[200], "{name}");
    }
    // A crease and a periodic closure of the same direction, or too few columns, exit 2.
    let input = write(dir.path(), "w.csv", &wing(3, 11, true));
    let out = dir.path().join("w.step");
    let o = karkas(&[
        "surface",
        "bicubic",
        "--crease-v",
        "--closed-v",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let narrow = write(
        dir.path(),
        "n.csv",
        &grid_csv(3, 2, |i, j| [i as f64, j as f64, 0.0]),
    );
    let o = karkas(&["surface", "ll", "--crease-v", s(&narrow), "-o", s(&out)]);
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--crease-v: a closed direction needs at least 3 columns"),
        "{}",
        stderr(&o)
    );
}

/// The triangles of the mesh file `path` as corner coordinates.
fn mesh_triangles(path: &std::path::Path) -> Vec<[[f64; 3]; 3]> {
    let mesh = karkas_io::mesh::read_mesh(path).unwrap();
    mesh.triangles
        .iter()
        .map(|t| t.map(|k| mesh.positions[k as usize].0))
        .collect()
}

/// True when every edge of `triangles` (corners keyed by their f32 coordinates, as STL holds
/// them) is used exactly once in each direction: watertight, the winding consistent.
fn watertight(triangles: &[[[f64; 3]; 3]]) -> bool {
    use std::collections::HashMap;
    let key = |p: [f64; 3]| p.map(|x| (x as f32).to_bits());
    let mut edges: HashMap<_, usize> = HashMap::new();
    for t in triangles {
        for e in 0..3 {
            *edges.entry((key(t[e]), key(t[(e + 1) % 3]))).or_default() += 1;
        }
    }
    edges
        .iter()
        .all(|(&(a, b), &n)| n == 1 && edges.get(&(b, a)) == Some(&1))
}

/// The signed volume of `triangles`, `sum a . (b x c) / 6`, and their smallest area.
fn volume_and_smallest_area(triangles: &[[[f64; 3]; 3]]) -> (f64, f64) {
    let sub = |p: [f64; 3], q: [f64; 3]| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    let cross = |p: [f64; 3], q: [f64; 3]| {
        [
            p[1] * q[2] - p[2] * q[1],
            p[2] * q[0] - p[0] * q[2],
            p[0] * q[1] - p[1] * q[0],
        ]
    };
    let dot = |p: [f64; 3], q: [f64; 3]| p[0] * q[0] + p[1] * q[1] + p[2] * q[2];
    let mut volume = 0.0;
    let mut smallest = f64::INFINITY;
    for &[a, b, c] in triangles {
        volume += dot(a, cross(b, c)) / 6.0;
        let n = cross(sub(b, a), sub(c, a));
        smallest = smallest.min(0.5 * dot(n, n).sqrt());
    }
    (volume, smallest)
}

#[test]
fn pole_closed_and_capped_meshes_are_watertight_with_the_solids_volume() {
    let dir = temp_dir();
    let ellipsoid = write(dir.path(), "e.csv", &ellipsoid(25, 48, (2.0, 1.0, 0.7)));
    let tube = write(dir.path(), "t.csv", &tube(13, 24));
    for (input, cap) in [(&ellipsoid, false), (&tube, true)] {
        let mut command = vec!["surface", "bicubic", "--closed-v"];
        if cap {
            command.push("--cap");
        }
        let step = dir.path().join("b.step");
        let mut args = command.clone();
        args.extend([s(input), "-o", s(&step)]);
        let o = karkas(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        let solid = reported_volume(&stderr(&o));
        for ext in ["stl", "obj", "ply"] {
            let out = dir.path().join(format!("b.{ext}"));
            let mut args = command.clone();
            args.extend(["--samples", "200,400", s(input), "-o", s(&out)]);
            let o = karkas(&args);
            assert!(o.status.success(), "{ext}: {}", stderr(&o));
            let triangles = mesh_triangles(&out);
            assert!(watertight(&triangles), "{ext} (cap {cap}): not watertight");
            let (volume, smallest) = volume_and_smallest_area(&triangles);
            // Outward normals: a positive volume.
            assert!(
                (volume - solid).abs() < 1e-3 * solid,
                "{ext} (cap {cap}): mesh volume {volume}, solid {solid}"
            );
            assert!(
                smallest > 1e-9,
                "{ext} (cap {cap}): a triangle of area {smallest}"
            );
            if cap {
                assert!(stderr(&o).contains("2 planar caps"), "{}", stderr(&o));
                let meshed = reported_volume(&stderr(&o));
                assert!((meshed - volume).abs() < 1e-6 * volume, "{meshed} {volume}");
            }
        }
    }
}

/// The wing of [`wing`] (`rows` sections of `cols` points, the trailing edge repeated) as a
/// curve network: v-curves its closed sections, u-curves the spanwise lines through each
/// distinct section point. Returns the (u-curves, v-curves) CSV texts.
fn wing_network(rows: usize, cols: usize) -> (String, String) {
    let grid: Vec<Vec<String>> = wing(rows, cols, true)
        .lines()
        .skip(1)
        .map(|l| l.split(',').map(str::to_owned).collect())
        .collect();
    let at = |i: usize, j: usize| grid[i * cols + j][2..].join(",");
    let mut u = String::from("curve,x,y,z\n");
    for j in 0..cols - 1 {
        for i in 0..rows {
            u.push_str(&format!("{j},{}\n", at(i, j)));
        }
    }
    let mut v = String::from("curve,x,y,z\n");
    for i in 0..rows {
        for j in 0..cols {
            v.push_str(&format!("{i},{}\n", at(i, j)));
        }
    }
    (u, v)
}

#[test]
fn a_creased_capped_coons_wing_is_a_solid_with_a_sharp_trailing_edge() {
    let dir = temp_dir();
    let (u, v) = wing_network(7, 41);
    let (u, v) = (
        write(dir.path(), "u.csv", &u),
        write(dir.path(), "v.csv", &v),
    );
    let network = ["--u-curves", s(&u), "--v-curves", s(&v)];
    let out = dir.path().join("wing.step");
    let mut args = vec!["surface", "coons", "--kind", "gordon-spline", "--crease-v"];
    args.extend(network);
    let o = karkas(&[&args[..], &["--cap", "-o", s(&out)]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&out).unwrap();
    assert_eq!(count(&text, "MANIFOLD_SOLID_BREP"), 1);
    assert_eq!(count(&text, "PLANE"), 2);
    let volume = reported_volume(&stderr(&o));
    assert!(volume > 0.1 && volume < 1.0, "{volume}");
    // The trailing edge is sharp: the tangents along v on its two sides differ.
    let samples = dir.path().join("s.csv");
    let o = karkas(&[&args[..], &["--samples", "5,201", "-o", s(&samples)]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = crate::common::read_csv(&samples);
    let row: Vec<[f64; 3]> = rows[2 * 201..3 * 201]
        .iter()
        .map(|r| [r[2], r[3], r[4]])
        .collect();
    let along = |a: [f64; 3], b: [f64; 3]| [b[0] - a[0], b[1] - a[1], b[2] - a[2]];
    let (start, end) = (along(row[0], row[1]), along(row[199], row[200]));
    let dot: f64 = (0..3).map(|c| start[c] * end[c]).sum();
    let norm = |v: [f64; 3]| (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    let angle = (dot / norm(start) / norm(end))
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees();
    assert!(angle > 10.0, "tangents {angle} degrees apart");
    assert!(
        (0..3).all(|c| (row[0][c] - row[200][c]).abs() < 1e-12),
        "{:?} {:?}",
        row[0],
        row[200]
    );
    // Without the crease the closed direction is periodic and C^2: the one-sided tangents
    // agree (measured 5e-5 either side of the seam: the spline turns round the sharp edge
    // within one point's spacing of it).
    let mut smooth = vec!["surface", "coons", "--kind", "gordon-spline"];
    smooth.extend(network);
    let o = karkas(&[&smooth[..], &["--samples", "5,20001", "-o", s(&samples)]].concat());
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = crate::common::read_csv(&samples);
    let row: Vec<[f64; 3]> = rows[2 * 20001..3 * 20001]
        .iter()
        .map(|r| [r[2], r[3], r[4]])
        .collect();
    let (start, end) = (along(row[0], row[1]), along(row[19999], row[20000]));
    let dot: f64 = (0..3).map(|c| start[c] * end[c]).sum();
    let smooth_angle = (dot / norm(start) / norm(end))
        .clamp(-1.0, 1.0)
        .acos()
        .to_degrees();
    assert!(
        smooth_angle < 5.0,
        "periodic: tangents {smooth_angle} degrees apart"
    );
}

#[test]
fn a_coons_crease_on_an_open_direction_or_with_derivatives_exits_2() {
    let dir = temp_dir();
    let (u, v) = wing_network(5, 21);
    let (u, v) = (
        write(dir.path(), "u.csv", &u),
        write(dir.path(), "v.csv", &v),
    );
    let out = dir.path().join("w.step");
    let base = [
        "surface",
        "coons",
        "--kind",
        "gordon-spline",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "-o",
        s(&out),
    ];
    // The u-curves (spanwise lines) are open: u cannot take a crease.
    let o = karkas(&[&base[..], &["--crease-u"]].concat());
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    let err = stderr(&o);
    assert!(
        err.contains("--crease-u: ") && err.contains("u.csv:2 (u-curve 0) is open"),
        "{err}"
    );
    assert_eq!(err.trim().lines().count(), 1, "{err}");
    // Cross-derivative data cannot give both sides of a crease.
    let twists = write(dir.path(), "t.csv", "i,j,x,y,z\n0,0,0,0,0\n");
    let mut args = base.to_vec();
    args[3] = "composite";
    let o = karkas(&[&args[..], &["--crease-v", "--twists", s(&twists)]].concat());
    assert_eq!(o.status.code(), Some(2), "{}", stderr(&o));
    assert!(
        stderr(&o).contains("--crease-v: not with --twists"),
        "{}",
        stderr(&o)
    );
    assert!(!out.exists());
}

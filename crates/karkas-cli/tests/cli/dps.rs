//! The CLI contract of `karkas curve dps` and `karkas surface dps-tube`: options, CSV headers,
//! indices, meshes, and exit code 2 with no output on bad input.

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::{Path, PathBuf};

const SQUARE: &str = "x,y\n0,0\n2,0\n2,1\n0,1\n";

#[test]
fn curve_through_nodes_has_j_from_zero_and_passes_through_them() {
    let dir = temp_dir();
    let input = write(dir.path(), "sq.csv", SQUARE);
    let out = dir.path().join("c.csv");
    let o = karkas(&[
        "curve",
        "dps",
        "--order",
        "2",
        "--n",
        "5",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["j", "x", "y"]);
    assert_eq!(rows.len(), 20);
    let nodes = [[0.0, 0.0], [2.0, 0.0], [2.0, 1.0], [0.0, 1.0]];
    for (j, row) in rows.iter().enumerate() {
        assert_eq!(row[0], j as f64);
        if j % 5 == 0 {
            let z = nodes[j / 5];
            assert!(
                (row[1] - z[0]).abs() < 1e-13 && (row[2] - z[1]).abs() < 1e-13,
                "{row:?}"
            );
        }
    }
}

#[test]
fn curve_from_poles_stays_in_their_hull_and_svg_works() {
    let dir = temp_dir();
    let input = write(dir.path(), "ring.txt", "1 0 0\n0 1 1\n-1 0 0\n0 -1 1\n");
    let out = dir.path().join("c.csv");
    let o = karkas(&[
        "curve",
        "dps",
        "--order",
        "3",
        "--n",
        "4",
        "--poles",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["j", "x", "y", "z"]);
    assert_eq!(rows.len(), 16);
    for row in &rows {
        assert!(row[1].abs() < 1.0 && row[2].abs() < 1.0 && row[3] > 0.0 && row[3] < 1.0);
    }
    // Symmetric poles: opposite values are opposite in x and y.
    for j in 0..8 {
        assert!((rows[j][1] + rows[j + 8][1]).abs() < 1e-14);
    }
    let svg = dir.path().join("c.svg");
    let o = karkas(&[
        "curve",
        "dps",
        "--order",
        "2",
        "--n",
        "8",
        "--poles",
        s(&input),
        "-o",
        s(&svg),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("polyline"));
}

#[test]
fn bad_curve_input_exits_2_and_writes_nothing() {
    let dir = temp_dir();
    let out = dir.path().join("out.csv");
    let good = write(dir.path(), "good.csv", SQUARE);
    let one = write(dir.path(), "one.csv", "x,y\n1,2\n");
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "2",
            "--n",
            "4",
            s(&one),
            "-o",
            s(&out),
        ],
        "one.csv: a discrete periodic spline needs at least 2 points, got 1",
        &out,
        None,
    );
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "0",
            "--n",
            "4",
            s(&good),
            "-o",
            s(&out),
        ],
        "--order",
        &out,
        None,
    );
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "65",
            "--n",
            "4",
            s(&good),
            "-o",
            s(&out),
        ],
        "--order",
        &out,
        None,
    );
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "2",
            "--n",
            "1",
            s(&good),
            "-o",
            s(&out),
        ],
        "--n",
        &out,
        None,
    );
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "2",
            "--n",
            "100000000",
            s(&good),
            "-o",
            s(&out),
        ],
        "--n",
        &out,
        None,
    );
    assert_rejected(
        &["curve", "dps", "--n", "4", s(&good), "-o", s(&out)],
        "--order",
        &out,
        None,
    );
    let nan = write(dir.path(), "nan.csv", "x,y\n0,0\n1,inf\n2,0\n");
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "2",
            "--n",
            "4",
            s(&nan),
            "-o",
            s(&out),
        ],
        "nan.csv:3",
        &out,
        None,
    );
    let obj = dir.path().join("out.obj");
    assert_rejected(
        &[
            "curve",
            "dps",
            "--order",
            "2",
            "--n",
            "4",
            s(&good),
            "-o",
            s(&obj),
        ],
        "unknown output extension",
        &obj,
        None,
    );
}

/// A torus skeleton: `m1` curves along of `m2 n2` samples and `m2` rings of `m1 n1` samples.
fn torus_files(dir: &Path, (m1, n1, m2, n2): (usize, usize, usize, usize)) -> (PathBuf, PathBuf) {
    let (big_n1, big_n2) = (m1 * n1, m2 * n2);
    let at = |p: usize, q: usize| {
        let u = std::f64::consts::TAU * p as f64 / big_n1 as f64;
        let v = std::f64::consts::TAU * q as f64 / big_n2 as f64;
        let r = 3.0 + u.cos();
        [r * v.cos(), r * v.sin(), u.sin()]
    };
    let mut along = String::from("i,q,x,y,z\n");
    for i in 0..m1 {
        for q in 0..big_n2 {
            let [x, y, z] = at(i * n1, q);
            along.push_str(&format!("{i},{q},{x},{y},{z}\n"));
        }
    }
    let mut across = String::from("j,p,x,y,z\n");
    for j in 0..m2 {
        for p in 0..big_n1 {
            let [x, y, z] = at(p, j * n2);
            across.push_str(&format!("{j},{p},{x},{y},{z}\n"));
        }
    }
    (write(dir, "f.csv", &along), write(dir, "g.csv", &across))
}

#[test]
fn tube_csv_obj_and_stl() {
    let dir = temp_dir();
    let (f, g) = torus_files(dir.path(), (3, 4, 4, 5));
    let out = dir.path().join("t.csv");
    let o = karkas(&[
        "surface",
        "dps-tube",
        "--along",
        s(&f),
        "--across",
        s(&g),
        "--n1",
        "4",
        "--n2",
        "5",
        "--r1",
        "3",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["p", "q", "x", "y", "z"]);
    assert_eq!(rows.len(), 12 * 20);
    // p outer, q inner; c(i n1, q) = f_i(q): row (p = 4, q = 7) is f_1(7).
    let row = &rows[4 * 20 + 7];
    assert_eq!(&row[..2], &[4.0, 7.0]);
    let (text, _) = (std::fs::read_to_string(&f).unwrap(), ());
    let f17: Vec<f64> = text
        .lines()
        .find(|l| l.starts_with("1,7,"))
        .unwrap()
        .split(',')
        .skip(2)
        .map(|v| v.parse().unwrap())
        .collect();
    for c in 0..3 {
        assert!((row[2 + c] - f17[c]).abs() < 1e-12, "{row:?} vs {f17:?}");
    }

    let obj = dir.path().join("t.obj");
    let o = karkas(&[
        "surface",
        "dps-tube",
        "--along",
        s(&f),
        "--across",
        s(&g),
        "--n1",
        "4",
        "--n2",
        "5",
        "-o",
        s(&obj),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mesh = std::fs::read_to_string(&obj).unwrap();
    // The closed grid, (N1 + 1) x (N2 + 1) samples, with both seams welded: N1 x N2
    // vertices, 2 N1 N2 triangles.
    assert_eq!(
        mesh.lines().filter(|l| l.starts_with("v ")).count(),
        12 * 20
    );
    assert_eq!(
        mesh.lines().filter(|l| l.starts_with("f ")).count(),
        2 * 12 * 20
    );

    let stl = dir.path().join("t.stl");
    let o = karkas(&[
        "surface",
        "dps-tube",
        "--along",
        s(&f),
        "--across",
        s(&g),
        "--n1",
        "4",
        "--n2",
        "5",
        "-o",
        s(&stl),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let bytes = std::fs::read(&stl).unwrap();
    assert_eq!(
        u32::from_le_bytes(bytes[80..84].try_into().unwrap()),
        2 * 12 * 20
    );
    assert_eq!(bytes.len(), 84 + 50 * 2 * 12 * 20);

    // The other mesh formats and the viewer page, by extension.
    for ext in ["ply", "html"] {
        let path = dir.path().join(format!("t.{ext}"));
        let o = karkas(&[
            "surface",
            "dps-tube",
            "--along",
            s(&f),
            "--across",
            s(&g),
            "--n1",
            "4",
            "--n2",
            "5",
            "-o",
            s(&path),
        ]);
        assert!(o.status.success(), "{ext}: {}", stderr(&o));
        let bytes = std::fs::read(&path).unwrap();
        let head = String::from_utf8_lossy(&bytes[..bytes.len().min(4096)]).into_owned();
        if ext == "ply" {
            // Both seams welded: 12 x 20 vertices.
            assert!(head.contains("element vertex 240\n"), "{head}");
            assert!(head.contains("element face 480\n"), "{head}");
        } else {
            assert!(head.starts_with("<!DOCTYPE html>"), "{head}");
        }
    }
}

#[test]
fn bad_tube_input_exits_2_and_writes_nothing() {
    let dir = temp_dir();
    let (f, g) = torus_files(dir.path(), (2, 5, 3, 4));
    let out = dir.path().join("t.obj");
    let run = |extra: &[&str], needle: &str, out: &Path| {
        let mut args = vec!["surface", "dps-tube", "--along", s(&f), "--across", s(&g)];
        args.extend_from_slice(extra);
        args.extend_from_slice(&["-o", s(out)]);
        assert_rejected(&args, needle, out, None);
    };
    run(
        &["--n1", "5", "--n2", "5"],
        "f.csv: each along curve needs 15 samples",
        &out,
    );
    run(
        &["--n1", "4", "--n2", "4"],
        "g.csv: each across curve needs 8 samples",
        &out,
    );
    run(&["--n1", "1", "--n2", "4"], "--n1", &out);
    run(&["--n1", "5", "--n2", "4", "--r2", "0"], "--r2", &out);
    run(&["--n1", "5", "--n2", "4", "--r1", "99"], "--r1", &out);
    let unknown = dir.path().join("t.dxf");
    run(
        &["--n1", "5", "--n2", "4"],
        "unknown output extension",
        &unknown,
    );

    // f_1 moved where it must meet g_2 (q = 2 n2 = 8).
    let text = std::fs::read_to_string(&f).unwrap();
    let moved: String = text
        .lines()
        .map(|l| {
            if l.starts_with("1,8,") {
                "1,8,0,0,0\n".to_owned()
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    let bad = write(dir.path(), "bad.csv", &moved);
    assert_rejected(
        &[
            "surface",
            "dps-tube",
            "--along",
            s(&bad),
            "--across",
            s(&g),
            "--n1",
            "5",
            "--n2",
            "4",
            "-o",
            s(&out),
        ],
        "along curve i=1 and across curve j=2 do not meet",
        &out,
        None,
    );
    let holey = write(dir.path(), "holey.csv", &text.replace("0,3,", "0,33,"));
    assert_rejected(
        &[
            "surface",
            "dps-tube",
            "--along",
            s(&holey),
            "--across",
            s(&g),
            "--n1",
            "5",
            "--n2",
            "4",
            "-o",
            s(&out),
        ],
        "holey.csv: i=0, q=3: missing",
        &out,
        None,
    );
}

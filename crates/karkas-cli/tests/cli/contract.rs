//! The CLI contract of `karkas curve ll` and `karkas surface ll` (docs/reference/contract.md):
//! options, CSV headers, parameters, and exit code 2 with no output on bad input.

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, temp_dir, write};

#[test]
fn open_curve_csv_has_the_papers_parameters_and_ends() {
    let dir = temp_dir();
    let input = write(dir.path(), "pts.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n4,0\n");
    let out = dir.path().join("out.csv");
    let o = karkas(&[
        "curve",
        "ll",
        "--order",
        "4",
        "--samples",
        "9",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["t", "x", "y"]);
    assert_eq!(rows.len(), 9);
    // K = 5: domain [1/6, 5/6]; an open LL curve passes through its first and last points.
    assert!((rows[0][0] - 1.0 / 6.0).abs() < 1e-15 && (rows[8][0] - 5.0 / 6.0).abs() < 1e-15);
    assert_eq!(&rows[0][1..], &[0.0, 0.0]);
    assert!((rows[8][1] - 4.0).abs() < 1e-14 && rows[8][2].abs() < 1e-14);
}

#[test]
fn interpolating_closed_spatial_curve_passes_through_its_points() {
    let dir = temp_dir();
    let pts = [
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.5],
        [-1.0, 0.0, 1.0],
        [0.0, -1.0, 0.5],
    ];
    let text: String = pts
        .iter()
        .map(|p| format!("{} {} {}\n", p[0], p[1], p[2]))
        .collect();
    let input = write(dir.path(), "ring.txt", &format!("# a ring\n{text}"));
    let out = dir.path().join("ring.csv");
    // K = 5 (the first point is repeated); 4 intervals of samples per node step.
    let o = karkas(&[
        "curve",
        "ll",
        "--closed",
        "--interpolate",
        "--samples",
        "17",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["t", "x", "y", "z"]);
    for (k, p) in pts.iter().chain([&pts[0]]).enumerate() {
        let row = &rows[4 * k];
        assert!((row[0] - (k + 1) as f64 / 6.0).abs() < 1e-14);
        for c in 0..3 {
            assert!(
                (row[1 + c] - p[c]).abs() < 1e-12,
                "node {k}: {row:?} vs {p:?}"
            );
        }
    }
}

#[test]
fn airfoil_dat_and_svg_output() {
    let dir = temp_dir();
    let dat = "TEST AIRFOIL\n1.0 0.0\n0.5 0.06\n0.1 0.04\n0.0 0.0\n0.1 -0.03\n0.5 -0.04\n1.0 0.0\n";
    let input = write(dir.path(), "foil.dat", dat);
    let out = dir.path().join("foil.svg");
    let o = karkas(&["curve", "ll", "--closed", s(&input), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(
        svg.starts_with("<svg") && svg.contains("polyline"),
        "not an SVG plot"
    );
}

#[test]
fn surface_csv_and_obj() {
    let dir = temp_dir();
    let mut text = String::from("i,j,x,y,z\n");
    // Rows in reverse order: the reader must place them by index.
    for i in (0..4).rev() {
        for j in 0..5 {
            text.push_str(&format!("{i},{j},{i},{j},{}\n", (i * j) as f64 * 0.1));
        }
    }
    let input = write(dir.path(), "grid.csv", &text);
    let out = dir.path().join("s.csv");
    let o = karkas(&[
        "surface",
        "ll",
        "--order",
        "2",
        "--samples",
        "3,4",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["u", "v", "x", "y", "z"]);
    assert_eq!(rows.len(), 12);
    // Corners of the grid are interpolated; u outer, v inner; u in [1/5, 4/5], v in [1/6, 5/6].
    assert_eq!(rows[0], [0.2, 1.0 / 6.0, 0.0, 0.0, 0.0]);
    let last = &rows[11];
    assert!((last[0] - 0.8).abs() < 1e-15 && (last[1] - 5.0 / 6.0).abs() < 1e-15);
    assert!(
        (last[2] - 3.0).abs() < 1e-14
            && (last[3] - 4.0).abs() < 1e-14
            && (last[4] - 1.2).abs() < 1e-14
    );
    let obj = dir.path().join("s.obj");
    let o = karkas(&[
        "surface",
        "ll",
        "--closed-v",
        "--samples",
        "6,7",
        s(&input),
        "-o",
        s(&obj),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let mesh = std::fs::read_to_string(&obj).unwrap();
    // 6 x 7 samples, closed in v: the seam column is welded, 6 x 6 vertices.
    assert_eq!(mesh.lines().filter(|l| l.starts_with("v ")).count(), 36);
    assert_eq!(
        mesh.lines().filter(|l| l.starts_with("f ")).count(),
        2 * 5 * 6
    );
}

#[test]
fn bad_curve_input_exits_2_and_writes_nothing() {
    let dir = temp_dir();
    let out = dir.path().join("out.csv");
    let two = write(dir.path(), "two.csv", "x,y\n0,0\n1,1\n");
    assert_rejected(
        &["curve", "ll", s(&two), "-o", s(&out)],
        "two.csv: an LL curve needs at least 3 points, got 2",
        &out,
        None,
    );
    let nan = write(dir.path(), "nan.csv", "x,y\n0,0\n1,nan\n2,0\n");
    assert_rejected(
        &["curve", "ll", s(&nan), "-o", s(&out)],
        "nan.csv:3",
        &out,
        None,
    );
    let ragged = write(dir.path(), "ragged.csv", "0,0\n1,1,1\n2,0\n");
    assert_rejected(
        &["curve", "ll", s(&ragged), "-o", s(&out)],
        "ragged.csv:2",
        &out,
        None,
    );
    let good = write(dir.path(), "good.csv", "0,0\n1,1\n2,0\n");
    assert_rejected(
        &["curve", "ll", "--order", "0", s(&good), "-o", s(&out)],
        "--order",
        &out,
        None,
    );
    let obj = dir.path().join("out.obj");
    assert_rejected(
        &["curve", "ll", s(&good), "-o", s(&obj)],
        "unknown output extension",
        &obj,
        None,
    );
    let missing = dir.path().join("missing.csv");
    assert_rejected(
        &["curve", "ll", s(&missing), "-o", s(&out)],
        "missing.csv",
        &out,
        None,
    );
    // An existing output survives a failed run byte for byte.
    std::fs::write(&out, "precious\n").unwrap();
    assert_rejected(
        &["curve", "ll", s(&two), "-o", s(&out)],
        "two.csv",
        &out,
        Some("precious\n"),
    );
    // The output may not replace the input.
    assert_rejected(
        &["curve", "ll", s(&good), "-o", s(&good)],
        "overwrite the input",
        &good,
        Some("0,0\n1,1\n2,0\n"),
    );
}

#[test]
fn bad_grid_input_names_the_cell() {
    let dir = temp_dir();
    let out = dir.path().join("out.obj");
    let mut text = String::from("i,j,x,y,z\n");
    for i in 0..3 {
        for j in 0..3 {
            if (i, j) != (1, 2) {
                text.push_str(&format!("{i},{j},{i},{j},0\n"));
            }
        }
    }
    let holey = write(dir.path(), "holey.csv", &text);
    assert_rejected(
        &["surface", "ll", s(&holey), "-o", s(&out)],
        "(i=1, j=2)",
        &out,
        None,
    );
    let small = write(
        dir.path(),
        "small.csv",
        "i,j,x,y,z\n0,0,0,0,0\n0,1,0,1,0\n1,0,1,0,0\n1,1,1,1,0\n",
    );
    assert_rejected(
        &["surface", "ll", s(&small), "-o", s(&out)],
        "small.csv",
        &out,
        None,
    );
    assert_rejected(
        &["surface", "ll", "--samples", "5", s(&small), "-o", s(&out)],
        "NU,NV",
        &out,
        None,
    );
}

//! The CLI contract of `karkas section` (docs/reference/contract.md): options, the CSV header
//! `section,t,x,y,z`, section numbering, pictures, and exit code 2 with no output on bad input.

use crate::common::{assert_rejected, grid_csv, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::Path;

/// A sphere-like grid: 17 latitudes (-80..80 degrees, rows) by 18 longitudes (columns).
fn sphere(dir: &Path) -> std::path::PathBuf {
    let text = grid_csv(17, 18, |i, j| {
        let lat = (-80.0 + 10.0 * i as f64).to_radians();
        let lon = (20.0 * j as f64).to_radians();
        [lat.cos() * lon.cos(), lat.cos() * lon.sin(), lat.sin()]
    });
    write(dir, "sphere.csv", &text)
}

/// The rows of each section block, by section number.
fn blocks(rows: &[Vec<f64>]) -> Vec<Vec<Vec<f64>>> {
    let mut out: Vec<Vec<Vec<f64>>> = Vec::new();
    for r in rows {
        let k = r[0] as usize;
        if k == out.len() {
            out.push(Vec::new());
        }
        assert_eq!(
            k + 1,
            out.len(),
            "sections are numbered in order, one block each"
        );
        out[k].push(r.clone());
    }
    out
}

#[test]
fn csv_has_one_block_per_piece_in_plane_order() {
    let dir = temp_dir();
    let input = sphere(dir.path());
    let out = dir.path().join("s.csv");
    let o = karkas(&[
        "section",
        s(&input),
        "--method",
        "ll",
        "--closed-v",
        "--interpolate",
        "--x",
        "0.3",
        "--plane",
        "0,0,2,0.6",
        "--z=-0.5,0.5",
        "--x",
        "5",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (header, rows) = read_csv(&out);
    assert_eq!(header, ["section", "t", "x", "y", "z"]);
    let blocks = blocks(&rows);
    // Order: --plane (z = 0.3), then --x 0.3 (x = 5 misses), then z = -0.5, z = 0.5.
    assert_eq!(blocks.len(), 4);
    let on_plane: [(usize, f64); 4] = [(2, 0.3), (0, 0.3), (2, -0.5), (2, 0.5)];
    for (block, (axis, value)) in blocks.iter().zip(on_plane) {
        for r in block {
            assert!(
                (r[2 + axis] - value).abs() < 1e-9,
                "{r:?} not on {axis} = {value}"
            );
        }
        // Every piece here is closed: the last row repeats the first point, and t is the
        // length along the polyline.
        let (first, last) = (&block[0], &block[block.len() - 1]);
        assert_eq!(first[1], 0.0);
        assert_eq!(&first[2..], &last[2..]);
        for w in block.windows(2) {
            let d = ((w[1][2] - w[0][2]).powi(2)
                + (w[1][3] - w[0][3]).powi(2)
                + (w[1][4] - w[0][4]).powi(2))
            .sqrt();
            assert!((w[1][1] - w[0][1] - d).abs() < 1e-12);
        }
    }
    let err = stderr(&o);
    assert!(
        err.contains("plane 1 (0x + 0y + 2z = 0.6): 1 closed piece, section 0"),
        "{err}"
    );
    assert!(err.contains("plane 3 (x = 5): no section"), "{err}");
}

#[test]
fn a_plane_that_misses_writes_only_the_header() {
    let dir = temp_dir();
    let input = sphere(dir.path());
    let out = dir.path().join("none.csv");
    let o = karkas(&[
        "section",
        s(&input),
        "--method",
        "ll",
        "--y",
        "3",
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert_eq!(std::fs::read_to_string(&out).unwrap(), "section,t,x,y,z\n");
}

#[test]
fn pictures_in_svg_and_png() {
    let dir = temp_dir();
    let input = sphere(dir.path());
    for (name, check) in [
        (
            "s.svg",
            (|b: &[u8]| b.starts_with(b"<svg")) as fn(&[u8]) -> bool,
        ),
        ("s.png", |b: &[u8]| b.starts_with(b"\x89PNG\r\n\x1a\n")),
    ] {
        let out = dir.path().join(name);
        let o = karkas(&[
            "section",
            s(&input),
            "--method",
            "ll",
            "--closed-v",
            "--z",
            "0,0.5",
            "--plane",
            "1,1,0,0.2",
            "--view",
            "-30,20",
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        assert!(
            check(&std::fs::read(&out).unwrap()),
            "{name} is not a picture"
        );
    }
    let svg = std::fs::read_to_string(dir.path().join("s.svg")).unwrap();
    assert!(svg.contains("<polygon") && svg.contains("<polyline"));
    assert!(svg.contains("z = const (2 pieces)"));
}

#[test]
fn bad_section_input_exits_2_and_writes_nothing() {
    let dir = temp_dir();
    let input = sphere(dir.path());
    let out = dir.path().join("out.csv");
    let base = ["section", s(&input), "--method", "ll"];
    let run = |extra: &[&str], needle: &str| {
        let mut args = base.to_vec();
        args.extend_from_slice(extra);
        args.extend_from_slice(&["-o", s(&out)]);
        assert_rejected(&args, needle, &out, None);
    };
    run(&[], "no plane given");
    run(&["--plane", "0,0,0,1"], "--plane 0,0,0,1: invalid plane");
    run(&["--plane", "0,0,1"], "NX,NY,NZ,C");
    run(&["--x", "nan"], "--x NaN");
    run(&["--z", "0", "--tolerance", "-1"], "--tolerance");
    // A chord error below floating-point resolution: refused, not 22 pieces where 1 is right.
    run(
        &["--z", "0", "--tolerance", "1e-300"],
        "--tolerance: 1e-300 is below what floating point resolves on this surface (1e-12 of its size)",
    );
    run(&["--z", "0", "--cells", "2,50"], "cells must be 3 to 4096");
    run(&["--z", "0", "--order", "0"], "--order");
    assert_rejected(
        &["section", s(&input), "--z", "0", "-o", s(&out)],
        "--method",
        &out,
        None,
    );
    let obj = dir.path().join("out.obj");
    assert_rejected(
        &[
            "section",
            s(&input),
            "--method",
            "ll",
            "--z",
            "0",
            "-o",
            s(&obj),
        ],
        "unknown output extension (use one of: .csv, .svg, .png)",
        &obj,
        None,
    );
    // Every grid point at one place: refused as `surface ll` refuses it, not an empty result.
    let same: String = (0..16)
        .map(|k| format!("{},{},1,2,3\n", k / 4, k % 4))
        .collect();
    let same = write(dir.path(), "same.csv", &format!("i,j,x,y,z\n{same}"));
    assert_rejected(
        &[
            "section",
            s(&same),
            "--method",
            "ll",
            "--z",
            "0",
            "-o",
            s(&out),
        ],
        "all 16 grid points coincide (at 1,2,3): there is no surface to build",
        &out,
        None,
    );
    let holey = write(dir.path(), "holey.csv", "i,j,x,y,z\n0,0,0,0,0\n1,1,1,1,1\n");
    assert_rejected(
        &[
            "section",
            s(&holey),
            "--method",
            "ll",
            "--z",
            "0",
            "-o",
            s(&out),
        ],
        "holey.csv: grid cell (i=0, j=1)",
        &out,
        None,
    );
    // An existing output survives a failed run, and the input may not be overwritten.
    std::fs::write(&out, "precious\n").unwrap();
    assert_rejected(
        &[
            "section",
            s(&holey),
            "--method",
            "ll",
            "--z",
            "0",
            "-o",
            s(&out),
        ],
        "holey.csv",
        &out,
        Some("precious\n"),
    );
    let text = std::fs::read_to_string(&input).unwrap();
    assert_rejected(
        &[
            "section",
            s(&input),
            "--method",
            "ll",
            "--z",
            "0",
            "-o",
            s(&input),
        ],
        "overwrite the input",
        &input,
        Some(&text),
    );
}

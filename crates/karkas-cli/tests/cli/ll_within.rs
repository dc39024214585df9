//! `curve ll --within D` and `surface ll --within D`: every node within D of its point, the
//! plain approximation when D allows it, close to `--interpolate` for a tiny D, and D refused
//! unless positive and finite.
//!
//! With as many samples as points, the samples of an LL curve (surface) fall on its nodes
//! (`t_i = i/(K+1)`, uniform over the domain `[1/(K+1), K/(K+1)]`), so the written CSV holds
//! the node values.

use crate::common::{assert_rejected, grid_csv, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::Path;

const K: usize = 14;

/// A noisy open polygon: a sine with deterministic noise.
fn noisy_points() -> (String, Vec<[f64; 2]>) {
    let pts: Vec<[f64; 2]> = (0..K)
        .map(|i| {
            let x = 0.5 * i as f64;
            [x, x.sin() + 0.4 * (7.3 * i as f64).sin()]
        })
        .collect();
    let mut text = String::from("x,y\n");
    for p in &pts {
        text.push_str(&format!("{},{}\n", p[0], p[1]));
    }
    (text, pts)
}

/// Runs `curve ll` with `extra` options and `K` samples; returns the node values and stderr.
fn curve_nodes(input: &Path, out: &Path, extra: &[&str]) -> (Vec<[f64; 2]>, String) {
    let samples = K.to_string();
    let mut args = vec!["curve", "ll", "--samples", &samples];
    args.extend(extra);
    args.extend([s(input), "-o", s(out)]);
    let o = karkas(&args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    let (header, rows) = read_csv(out);
    assert_eq!(header, ["t", "x", "y"]);
    assert_eq!(rows.len(), K);
    (rows.iter().map(|r| [r[1], r[2]]).collect(), stderr(&o))
}

fn distances(nodes: &[[f64; 2]], pts: &[[f64; 2]]) -> Vec<f64> {
    nodes
        .iter()
        .zip(pts)
        .map(|(a, b)| (a[0] - b[0]).hypot(a[1] - b[1]))
        .collect()
}

fn largest(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}

#[test]
fn curve_ll_within_keeps_every_node_within_the_distance() {
    let dir = temp_dir();
    let (text, pts) = noisy_points();
    let input = write(dir.path(), "p.csv", &text);
    let out = dir.path().join("c.csv");
    let (plain, _) = curve_nodes(&input, &out, &[]);
    let top = largest(&distances(&plain, &pts));
    assert!(top > 0.02, "the noisy points should bend: {top}");
    for f in [0.9, 0.5, 0.2, 0.05, 0.01] {
        let d = f * top;
        let within = format!("{d}");
        let (nodes, err) = curve_nodes(&input, &out, &["--within", &within]);
        let dev = distances(&nodes, &pts);
        for (i, e) in dev.iter().enumerate() {
            assert!(*e <= d + 1e-12, "D = {d}: node {} at {e}", i + 1);
        }
        // The farthest nodes are pulled to the distance, not further.
        assert!(
            largest(&dev) >= d * (1.0 - 1e-9),
            "D = {d}: {}",
            largest(&dev)
        );
        assert!(err.contains("largest node deviation"), "{err}");
        assert!(err.contains("pulled in, system (6) solved once"), "{err}");
    }
}

#[test]
fn curve_ll_within_above_the_deviation_is_the_approximation() {
    let dir = temp_dir();
    let (text, pts) = noisy_points();
    let input = write(dir.path(), "p.csv", &text);
    let plain_out = dir.path().join("plain.csv");
    let within_out = dir.path().join("within.csv");
    let (plain, _) = curve_nodes(&input, &plain_out, &["--order", "4"]);
    let top = largest(&distances(&plain, &pts));
    for d in [top * (1.0 + 1e-9), 10.0 * top] {
        let within = format!("{d}");
        let (_, err) = curve_nodes(&input, &within_out, &["--order", "4", "--within", &within]);
        assert_eq!(
            std::fs::read(&plain_out).unwrap(),
            std::fs::read(&within_out).unwrap()
        );
        assert!(err.contains("already within it, nothing solved"), "{err}");
    }
}

#[test]
fn curve_ll_tiny_within_approaches_interpolate() {
    let dir = temp_dir();
    let (text, _) = noisy_points();
    let input = write(dir.path(), "p.csv", &text);
    let a = dir.path().join("a.csv");
    let b = dir.path().join("b.csv");
    for closed in [false, true] {
        let mut extra = vec!["--samples", "300"];
        if closed {
            extra.push("--closed");
        }
        let mut with_interp = extra.clone();
        with_interp.push("--interpolate");
        let mut with_within = extra.clone();
        with_within.extend(["--within", "1e-9"]);
        for (args, out) in [(&with_interp, &a), (&with_within, &b)] {
            let mut full = vec!["curve", "ll"];
            full.extend(args.iter());
            full.extend([s(&input), "-o", s(out)]);
            let o = karkas(&full);
            assert!(o.status.success(), "{}", stderr(&o));
        }
        let (_, ra) = read_csv(&a);
        let (_, rb) = read_csv(&b);
        assert_eq!(ra.len(), rb.len());
        let gap = ra
            .iter()
            .zip(&rb)
            .map(|(p, q)| (p[1] - q[1]).hypot(p[2] - q[2]))
            .fold(0.0, f64::max);
        // Each sample is a convex combination of controls within 2 D of the interpolating ones.
        assert!(gap <= 2e-9 * (1.0 + 1e-6), "closed {closed}: {gap:e}");
    }
}

#[test]
fn within_must_be_positive_finite_and_not_with_interpolate() {
    let dir = temp_dir();
    let (text, _) = noisy_points();
    let input = write(dir.path(), "p.csv", &text);
    let grid = write(
        dir.path(),
        "g.csv",
        &grid_csv(4, 5, |i, j| [i as f64, j as f64, ((i * j) % 3) as f64]),
    );
    let out = dir.path().join("o.csv");
    for (command, file) in [("curve", &input), ("surface", &grid)] {
        for d in ["0", "-0.5", "nan", "inf", "-inf"] {
            assert_rejected(
                &[command, "ll", "--within", d, s(file), "-o", s(&out)],
                &["--within", "positive and finite"][..],
                &out,
                None,
            );
        }
        assert_rejected(
            &[
                command,
                "ll",
                "--within",
                "0.1",
                "--interpolate",
                s(file),
                "-o",
                s(&out),
            ],
            &["--within", "--interpolate"][..],
            &out,
            None,
        );
    }
}

/// The noisy 6 x 7 test grid, row-major.
fn noisy_grid() -> Vec<[f64; 3]> {
    (0..6 * 7)
        .map(|k| {
            let (i, j) = ((k / 7) as f64, (k % 7) as f64);
            [
                i + 0.1 * (3.1 * j).sin(),
                j,
                (0.5 * i).sin() * (0.4 * j).cos() + 0.2 * (5.7 * k as f64).sin(),
            ]
        })
        .collect()
}

/// Runs `surface ll` with `extra` options on 6 x 7 samples (the nodes); the node values.
fn surface_nodes(input: &Path, out: &Path, extra: &[&str]) -> (Vec<[f64; 3]>, String) {
    let mut args = vec!["surface", "ll", "--samples", "6,7"];
    args.extend(extra);
    args.extend([s(input), "-o", s(out)]);
    let o = karkas(&args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    let (header, rows) = read_csv(out);
    assert_eq!(header, ["u", "v", "x", "y", "z"]);
    (
        rows.iter().map(|r| [r[2], r[3], r[4]]).collect(),
        stderr(&o),
    )
}

#[test]
fn surface_ll_within_keeps_every_node_within_the_distance() {
    let dir = temp_dir();
    let pts = noisy_grid();
    let input = write(dir.path(), "g.csv", &grid_csv(6, 7, |i, j| pts[i * 7 + j]));
    let out = dir.path().join("s.csv");
    let dist = |nodes: &[[f64; 3]]| -> Vec<f64> {
        nodes
            .iter()
            .zip(&pts)
            .map(|(a, b)| {
                ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
            })
            .collect()
    };
    let (plain, _) = surface_nodes(&input, &out, &[]);
    let top = largest(&dist(&plain));
    assert!(top > 0.05, "the noisy grid should bend: {top}");
    for f in [0.9, 0.4, 0.1, 0.01] {
        let d = f * top;
        let within = format!("{d}");
        let (nodes, err) = surface_nodes(&input, &out, &["--within", &within]);
        let dev = dist(&nodes);
        for (k, e) in dev.iter().enumerate() {
            assert!(*e <= d + 1e-12, "D = {d}: node {k} at {e}");
        }
        assert!(
            largest(&dev) >= d * (1.0 - 1e-9),
            "D = {d}: {}",
            largest(&dev)
        );
        assert!(err.contains("surface ll within"), "{err}");
    }
    let plain_out = dir.path().join("plain.csv");
    surface_nodes(&input, &plain_out, &[]);
    let within = format!("{}", 2.0 * top);
    let (_, err) = surface_nodes(&input, &out, &["--within", &within]);
    assert_eq!(
        std::fs::read(&plain_out).unwrap(),
        std::fs::read(&out).unwrap()
    );
    assert!(err.contains("nothing solved"), "{err}");
}

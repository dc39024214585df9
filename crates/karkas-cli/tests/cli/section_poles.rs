//! `karkas section` through the pole rows of a body (a grid row that is one repeated point,
//! the nose or tail): one curve through each pole, no zero-length pieces, no warnings.

use crate::common::{grid_csv, karkas, read_csv, s, stderr, temp_dir, write};
use std::f64::consts::{PI, TAU};
use std::path::Path;

/// The spheroid `(2 cos(theta), sin(theta) cos(phi), sin(theta) sin(phi))` on `rows` rows of
/// `theta` from `first` to `last` and 9 columns of `phi` over a turn (the last repeating the
/// first): a pole row at `theta = 0` and at `theta = pi`.
fn spheroid(dir: &Path, name: &str, rows: usize, first: f64, last: f64) -> std::path::PathBuf {
    let text = grid_csv(rows, 9, |i, j| {
        let theta = first + (last - first) * i as f64 / (rows - 1) as f64;
        let phi = TAU * (j % 8) as f64 / 8.0;
        [
            2.0 * theta.cos(),
            theta.sin() * phi.cos(),
            theta.sin() * phi.sin(),
        ]
    });
    write(dir, name, &text)
}

/// The pieces of a section CSV: the points of each block.
fn pieces(rows: &[Vec<f64>]) -> Vec<Vec<[f64; 3]>> {
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

fn section(input: &Path, out: &Path, plane: &[&str]) -> (Vec<Vec<[f64; 3]>>, String) {
    let mut args = vec!["section", s(input), "--method", "ll", "--closed-v"];
    args.extend_from_slice(plane);
    args.extend_from_slice(&["-o", s(out)]);
    let o = karkas(&args);
    assert!(o.status.success(), "{}", stderr(&o));
    let (_, rows) = read_csv(out);
    (pieces(&rows), stderr(&o))
}

fn near(p: [f64; 3], q: [f64; 3]) -> bool {
    (0..3).all(|k| (p[k] - q[k]).abs() < 1e-12)
}

#[test]
fn a_plane_through_the_pole_rows_cuts_one_curve() {
    let dir = temp_dir();
    let out = dir.path().join("out.csv");
    let (nose, tail) = ([2.0, 0.0, 0.0], [-2.0, 0.0, 0.0]);
    // Both poles: the side profile is one closed loop through the nose and the tail.
    let both = spheroid(dir.path(), "both.csv", 7, 0.0, PI);
    for plane in [&["--z", "0"][..], &["--y", "0"], &["--plane", "0,0.3,1,0"]] {
        let (pieces, err) = section(&both, &out, plane);
        assert!(!err.contains("warning"), "{plane:?}: {err}");
        assert!(err.contains("1 closed piece"), "{plane:?}: {err}");
        assert_eq!(pieces.len(), 1, "{plane:?}");
        let loop_ = &pieces[0];
        assert!(near(loop_[0], loop_[loop_.len() - 1]), "closed");
        let body = &loop_[..loop_.len() - 1];
        assert_eq!(body.iter().filter(|&&p| near(p, nose)).count(), 1);
        assert_eq!(body.iter().filter(|&&p| near(p, tail)).count(), 1);
        assert!(
            body.windows(2).all(|w| !near(w[0], w[1])),
            "a zero-length chord"
        );
    }
    // One pole (the first row, then the last): one open curve through it.
    for (name, first, last, pole) in [
        ("nose.csv", 0.0, 2.0 * PI / 3.0, nose),
        ("tail.csv", PI / 3.0, PI, tail),
    ] {
        let input = spheroid(dir.path(), name, 5, first, last);
        let (pieces, err) = section(&input, &out, &["--z", "0"]);
        assert!(!err.contains("warning"), "{name}: {err}");
        assert!(err.contains("1 open piece"), "{name}: {err}");
        assert_eq!(pieces[0].iter().filter(|&&p| near(p, pole)).count(), 1);
        assert!(pieces[0].windows(2).all(|w| !near(w[0], w[1])));
    }
    // A plane through neither pole: one closed loop, as ever.
    let (pieces, err) = section(&both, &out, &["--plane", "0.3,0,1,0.2"]);
    assert!(
        !err.contains("warning") && err.contains("1 closed piece"),
        "{err}"
    );
    assert_eq!(pieces.len(), 1);
}

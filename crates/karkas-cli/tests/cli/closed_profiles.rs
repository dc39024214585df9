//! Closed profiles: a first and last point that coincide (a sharp trailing edge) close every
//! curve method's curve at that point; `--free-ends` keeps a fit's ends free; an option that
//! closes a curve whose ends miss each other by a little warns with the distance
//! (docs/reference/contract.md, "curve fit", "Closed profiles").

use crate::common::{karkas, read_csv, s, stderr, temp_dir, write};

/// A NACA 00xx-like section with a sharp trailing edge, `n` points per surface in Selig order
/// (upper surface from the trailing edge to the nose, then the lower one back).
fn sharp_foil(n: usize) -> String {
    // The trailing edge (x = 1) is written as exactly 0 on both surfaces.
    let thickness = |x: f64| {
        if x == 1.0 {
            return 0.0;
        }
        0.6 * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
            - 0.1036 * x.powi(4))
    };
    let mut text = String::from("x,y\n");
    let xs: Vec<f64> = (0..=n)
        .map(|k| 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / n as f64).cos()))
        .collect();
    for &x in xs.iter().rev() {
        text.push_str(&format!("{x},{}\n", thickness(x)));
    }
    for &x in &xs[1..] {
        text.push_str(&format!("{x},{}\n", -thickness(x)));
    }
    text
}

/// The first and last samples of a curve CSV (`t,x,y`).
fn ends(path: &std::path::Path) -> ([f64; 2], [f64; 2]) {
    let (_, rows) = read_csv(path);
    let (a, b) = (&rows[0], &rows[rows.len() - 1]);
    ([a[1], a[2]], [b[1], b[2]])
}

#[test]
fn every_curve_method_closes_a_sharp_trailing_edge_at_its_point() {
    let dir = temp_dir();
    let input = write(dir.path(), "foil.csv", &sharp_foil(40));
    let out = dir.path().join("c.csv");
    for method in [
        vec!["curve", "fit", "--tolerance", "1e-4"],
        vec!["curve", "fit", "--knots", "12"],
        vec!["curve", "spline"],
        vec!["curve", "ll", "--interpolate"],
        vec!["curve", "ll"],
        vec!["curve", "ll", "--within", "1e-4"],
    ] {
        let mut args = method.clone();
        args.extend([s(&input), "-o", s(&out)]);
        let o = karkas(&args);
        assert!(o.status.success(), "{method:?}: {}", stderr(&o));
        let (first, last) = ends(&out);
        // The fit's ends are pinned at the point; an interpolant ends there to rounding.
        let gap = (first[0] - last[0]).hypot(first[1] - last[1]);
        assert!(gap <= 1e-15, "{method:?}: {first:?} {last:?}");
        assert!(
            (first[0] - 1.0).abs() < 1e-12 && first[1].abs() < 1e-12,
            "{method:?}: {first:?}"
        );
    }
    // --free-ends leaves the fit's ends where its foot points put them: apart.
    let o = karkas(&[
        "curve",
        "fit",
        "--tolerance",
        "1e-4",
        "--free-ends",
        s(&input),
        "-o",
        s(&out),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (first, last) = ends(&out);
    assert_ne!(first, last);
}

#[test]
fn a_closing_option_warns_of_ends_that_nearly_meet() {
    let dir = temp_dir();
    let mut text = String::from("x,y\n");
    for k in 0..12 {
        let t = 2.0 * std::f64::consts::PI * k as f64 / 12.0;
        text.push_str(&format!("{},{}\n", t.cos(), t.sin()));
    }
    text.push_str("1.002,0\n");
    let input = write(dir.path(), "ring.csv", &text);
    let out = dir.path().join("r.csv");
    for (args, option) in [
        (vec!["curve", "ll", "--closed"], "--closed"),
        (
            vec!["curve", "spline", "--ends", "periodic"],
            "--ends periodic",
        ),
    ] {
        let mut all = args.clone();
        all.extend([s(&input), "-o", s(&out)]);
        let o = karkas(&all);
        assert!(o.status.success(), "{}", stderr(&o));
        let warning = format!(
            "karkas: warning: {option}: the last point is 2.0e-3 from the first (7.1e-4 of the size)"
        );
        assert!(stderr(&o).contains(&warning), "{}", stderr(&o));
    }
    // A last point that repeats the first says nothing.
    let input = write(dir.path(), "closed.csv", &text.replace("1.002,0", "1,0"));
    let o = karkas(&["curve", "ll", "--closed", s(&input), "-o", s(&out)]);
    assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
}

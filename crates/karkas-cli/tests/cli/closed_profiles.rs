//! Closed profiles: a first and last point that coincide (a sharp trailing edge) close every
//! curve method's curve at that point; `--free-ends` keeps a fit's ends free; an option that
//! closes a curve whose ends miss each other by a little warns with the distance
//! (docs/reference/contract.md, "curve fit", "Closed profiles").

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, temp_dir, write};

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

/// `sharp_foil(n)` with its first and last points pushed apart across the edge (in y) to
/// `share` of the diagonal of the points' bounding box (the shared-end rule's measure).
fn foil_with_gap(n: usize, share: f64) -> String {
    let text = sharp_foil(n);
    let mut rows: Vec<[f64; 2]> = text
        .lines()
        .skip(1)
        .map(|l| {
            let mut v = l.split(',').map(|c| c.parse::<f64>().unwrap());
            [v.next().unwrap(), v.next().unwrap()]
        })
        .collect();
    let (lo, hi) = rows
        .iter()
        .fold(([f64::MAX; 2], [f64::MIN; 2]), |(lo, hi), p| {
            (
                [lo[0].min(p[0]), lo[1].min(p[1])],
                [hi[0].max(p[0]), hi[1].max(p[1])],
            )
        });
    let diagonal = (hi[0] - lo[0]).hypot(hi[1] - lo[1]);
    let last = rows.len() - 1;
    rows[0][1] = 0.5 * share * diagonal;
    rows[last][1] = -0.5 * share * diagonal;
    let mut out = String::from("x,y\n");
    for p in rows {
        out.push_str(&format!("{:e},{:e}\n", p[0], p[1]));
    }
    out
}

#[test]
fn every_curve_method_closes_ends_within_the_shared_end_rule_and_none_beyond_it() {
    // sg6041.dat's ends are 9.95e-7 of its size apart: the fit closed them, the spline and
    // the LL curve did not. 0.99e-6 closes in every method, 1.01e-6 in none.
    let dir = temp_dir();
    let out = dir.path().join("c.csv");
    for (share, closes) in [(0.99e-6, true), (1.01e-6, false)] {
        let input = write(dir.path(), "gap.csv", &foil_with_gap(40, share));
        for method in [
            vec!["curve", "fit", "--tolerance", "1e-4"],
            vec!["curve", "fit", "--knots", "12"],
            vec!["curve", "spline"],
            vec!["curve", "spline", "--ends", "natural"],
            vec!["curve", "ll", "--interpolate"],
            vec!["curve", "ll"],
            vec!["curve", "ll", "--within", "1e-4"],
        ] {
            let mut args = method.clone();
            args.extend([s(&input), "-o", s(&out)]);
            let o = karkas(&args);
            assert!(o.status.success(), "{method:?}: {}", stderr(&o));
            let (first, last) = ends(&out);
            let gap = (first[0] - last[0]).hypot(first[1] - last[1]);
            if closes {
                assert!(gap <= 1e-15, "{share:e} {method:?}: ends {gap:e} apart");
            } else {
                assert!(gap > 1e-7, "{share:e} {method:?}: ends {gap:e} apart");
            }
        }
    }
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

/// [`sharp_foil`] with a blunt trailing edge: the upper surface raised and the lower one
/// lowered by `half` times x, so the edge at x = 1 is `2 half` thick.
fn blunt_foil(n: usize, half: f64) -> String {
    let mut text = String::from("x,y\n");
    // Rows 0..=n are the upper surface, the rest the lower one.
    for (k, row) in sharp_foil(n).lines().skip(1).enumerate() {
        let (x, y) = row.split_once(',').unwrap();
        let (x, y): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
        let sign = if k <= n { 1.0 } else { -1.0 };
        text.push_str(&format!("{x},{}\n", y + sign * half * x));
    }
    text
}

#[test]
fn the_default_fit_warns_of_ends_that_nearly_meet() {
    let dir = temp_dir();
    let out = dir.path().join("c.csv");
    let fit = |input: &std::path::Path, extra: &[&str]| {
        let mut args = vec!["curve", "fit", "--tolerance", "1e-4"];
        args.extend_from_slice(extra);
        args.extend([s(input), "-o", s(&out)]);
        let o = karkas(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        stderr(&o)
    };
    // A blunt edge 2e-3 thick on a unit chord (diagonal sqrt(1 + 0.122^2) ~ 1.0075).
    let blunt = write(dir.path(), "blunt.csv", &blunt_foil(40, 1e-3));
    let err = fit(&blunt, &[]);
    let line = err
        .lines()
        .find(|l| l.contains("warning: the last point is"))
        .unwrap_or_else(|| panic!("no warning: {err}"));
    assert!(
        line.contains("the last point is 2.0e-3 from the first (2.0e-3 of the size)"),
        "{line}"
    );
    assert!(line.contains("--close-te"), "{line}");
    // --pin-ends keeps the ends apart too: the same warning.
    assert!(fit(&blunt, &["--pin-ends"]).contains("warning: the last point is 2.0e-3"));
    // Asked to stay free, or closed by the segment: nothing to say.
    assert!(!fit(&blunt, &["--free-ends"]).contains("the last point is"));
    // A sharp edge given with a small error (1e-5 apart, above the 1e-6 rule) warns too.
    let almost = write(dir.path(), "almost.csv", &blunt_foil(40, 5e-6));
    assert!(
        fit(&almost, &[]).contains("warning: the last point is 1.0e-5 from the first"),
        "{}",
        fit(&almost, &[])
    );
    // Ends that coincide (the rule) or lie far apart (above 1e-2 of the size) say nothing.
    let sharp = write(dir.path(), "sharp.csv", &sharp_foil(40));
    assert!(!fit(&sharp, &[]).contains("the last point is"));
    let open = write(dir.path(), "open.csv", &blunt_foil(40, 1e-2));
    assert!(!fit(&open, &[]).contains("the last point is"));
}

/// The numbers of a STEP entity's argument list, flattened in order.
fn step_numbers(text: &str) -> Vec<f64> {
    text.split(|c: char| !(c.is_ascii_digit() || "+-.E".contains(c)))
        .filter_map(|t| t.parse().ok())
        .collect()
}

#[test]
fn close_te_writes_a_blunt_trailing_edge_as_one_closed_curve() {
    let dir = temp_dir();
    let input = write(dir.path(), "blunt.csv", &blunt_foil(40, 1e-3));
    for method in [
        vec!["curve", "fit", "--tolerance", "1e-4"],
        vec!["curve", "spline"],
        vec!["curve", "ll", "--interpolate"],
    ] {
        let step = dir.path().join("c.step");
        let dxf = dir.path().join("c.dxf");
        let iges = dir.path().join("c.iges");
        let mut args = method.clone();
        args.extend([
            "--close-te",
            s(&input),
            "-o",
            s(&step),
            "-o",
            s(&dxf),
            "-o",
            s(&iges),
        ]);
        let o = karkas(&args);
        assert!(o.status.success(), "{method:?}: {}", stderr(&o));
        assert!(
            stderr(&o).contains("closed by the trailing-edge segment"),
            "{}",
            stderr(&o)
        );
        assert!(!stderr(&o).contains("warning"), "{}", stderr(&o));
        let text = std::fs::read_to_string(&step).unwrap();
        // One curve, flagged closed, with a corner (multiplicity = degree) where the
        // segment starts.
        let prefix = "=B_SPLINE_CURVE_WITH_KNOTS(";
        let curves: Vec<&str> = text.lines().filter(|l| l.contains(prefix)).collect();
        assert_eq!(curves.len(), 1, "{method:?}");
        assert!(curves[0].contains(",.T.,.F.,"), "{}", curves[0]);
        let degree: usize = curves[0].split(',').nth(1).unwrap().parse().unwrap();
        let counts = curves[0].split(".T.,.F.,(").nth(1).unwrap();
        let counts: Vec<usize> = counts[..counts.find(')').unwrap()]
            .split(',')
            .map(|c| c.parse().unwrap())
            .collect();
        assert_eq!(counts.last(), Some(&(degree + 1)));
        assert_eq!(counts[counts.len() - 2], degree, "{counts:?}");
        // The control points, by the references in the curve's list: the last degree + 1
        // run along the edge segment (collinear, inside |y| <= 1e-3 + the fit's deviation),
        // and the first and last are the same point.
        let coordinates = |id: &str| -> [f64; 2] {
            let line = text
                .lines()
                .find(|l| l.starts_with(&format!("{id}=CARTESIAN_POINT(")))
                .unwrap();
            let v = step_numbers(&line[line.find(",(").unwrap()..]);
            [v[0], v[1]]
        };
        let list = &curves[0][curves[0].find("(#").unwrap() + 1..];
        let list = &list[..list.find(')').unwrap()];
        let points: Vec<[f64; 2]> = list.split(',').map(coordinates).collect();
        let n = points.len();
        assert_eq!(points[0], points[n - 1]);
        let (a, b) = (points[n - degree - 1], points[n - 1]);
        assert!(
            (a[0] - 1.0).abs() < 1e-4 && (a[1] + 1e-3).abs() < 1e-4,
            "{a:?}"
        );
        assert!(
            (b[0] - 1.0).abs() < 1e-4 && (b[1] - 1e-3).abs() < 1e-4,
            "{b:?}"
        );
        for p in &points[n - degree - 1..] {
            let cross = (p[0] - a[0]) * (b[1] - a[1]) - (p[1] - a[1]) * (b[0] - a[0]);
            assert!(cross.abs() < 1e-15, "{method:?}: {p:?} off the segment");
        }
        // The DXF: one SPLINE, its closed flag (70: bit 1) set.
        let dxf_text = std::fs::read_to_string(&dxf).unwrap();
        let lines: Vec<&str> = dxf_text.lines().map(str::trim).collect();
        let splines = lines.iter().filter(|l| **l == "SPLINE").count();
        assert_eq!(splines, 1);
        let at = lines.iter().position(|l| *l == "SPLINE").unwrap();
        let flag = lines[at..]
            .windows(2)
            .find(|w| w[0] == "70")
            .map(|w| w[1].parse::<u32>().unwrap())
            .unwrap();
        assert_eq!(flag & 1, 1, "DXF flag {flag}");
        // The IGES: one entity 126, flagged closed (PROP2 = 1).
        let iges_text = std::fs::read_to_string(&iges).unwrap();
        let entity: String = iges_text
            .lines()
            .filter(|l| l.len() == 80 && &l[72..73] == "P" && l[65..72].trim() == "1")
            .map(|l| l[..64].trim_end())
            .collect();
        let fields: Vec<&str> = entity.split(',').collect();
        assert_eq!(fields[0], "126");
        assert_eq!(fields[4], "1", "closed flag: {entity}");
    }
}

#[test]
fn close_te_refuses_where_it_cannot_apply() {
    let dir = temp_dir();
    let blunt = write(dir.path(), "blunt.csv", &blunt_foil(20, 1e-3));
    let sharp = write(dir.path(), "sharp.csv", &sharp_foil(20));
    let step = dir.path().join("c.step");
    let csv = dir.path().join("c.csv");
    // The segment exists only in CAD outputs.
    assert_rejected(
        &[
            "curve",
            "fit",
            "--tolerance",
            "1e-4",
            "--close-te",
            s(&blunt),
            "-o",
            s(&csv),
        ],
        &["--close-te", "STEP, IGES and DXF"][..],
        &csv,
        None,
    );
    // A curve closed otherwise.
    assert_rejected(
        &[
            "curve",
            "ll",
            "--closed",
            "--close-te",
            s(&blunt),
            "-o",
            s(&step),
        ],
        &["--close-te", "--closed"][..],
        &step,
        None,
    );
    assert_rejected(
        &[
            "curve",
            "spline",
            "--ends",
            "periodic",
            "--close-te",
            s(&blunt),
            "-o",
            s(&step),
        ],
        &["--close-te", "--ends periodic"][..],
        &step,
        None,
    );
    // A sharp edge: nothing to close.
    for method in [
        vec!["curve", "fit", "--tolerance", "1e-4"],
        vec!["curve", "spline"],
        vec!["curve", "ll"],
    ] {
        let mut args = method.clone();
        args.extend(["--close-te", s(&sharp), "-o", s(&step)]);
        assert_rejected(
            &args,
            &["--close-te", "coincide", "sharp.csv"][..],
            &step,
            None,
        );
    }
}

/// Whether the polyline through `p` crosses itself (two segments that are not neighbours
/// cross properly), by trying every pair: the test's own check, independent of karkas's sweep.
fn polyline_crosses(p: &[[f64; 2]]) -> bool {
    let orient = |o: [f64; 2], a: [f64; 2], b: [f64; 2]| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    (0..p.len() - 1).any(|i| {
        (i + 2..p.len() - 1).any(|j| {
            let (a, b, c, d) = (p[i], p[i + 1], p[j], p[j + 1]);
            orient(a, b, c) * orient(a, b, d) < 0.0 && orient(c, d, a) * orient(c, d, b) < 0.0
        })
    })
}

#[test]
fn a_curve_that_loops_where_the_points_do_not_is_named_in_one_warning() {
    let dir = temp_dir();
    // A sharp foil with one more point 3.8e-4 from the nose, its neighbours 1e-2 away (as in
    // the corpus's s4022.dat): evenly spaced node parameters overshoot into a loop there.
    let plain = sharp_foil(15);
    let looping: String = plain
        .lines()
        .flat_map(|l| {
            let extra = (l == "0,0").then_some("0.00001,0.00038");
            extra.into_iter().chain([l])
        })
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(looping.lines().count(), plain.lines().count() + 1);
    let input = write(dir.path(), "loop.csv", &looping);
    let samples = dir.path().join("s.csv");
    let o = karkas(&[
        "curve",
        "ll",
        "--interpolate",
        s(&input),
        "--samples",
        "4000",
        "-o",
        s(&samples),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let err = stderr(&o);
    let warnings: Vec<&str> = err.lines().filter(|l| l.contains("warning")).collect();
    assert_eq!(warnings.len(), 1, "{err}");
    assert!(
        warnings[0].contains("loop.csv: the curve crosses itself 1 time where the points do not")
            && warnings[0].contains("without --interpolate"),
        "{err}"
    );
    let (_, rows) = read_csv(&samples);
    let curve: Vec<[f64; 2]> = rows.iter().map(|r| [r[1], r[2]]).collect();
    assert!(polyline_crosses(&curve), "the samples do not cross: {err}");
    // The same foil without the extra point, and the approximating LL curve and the spline
    // through it, do not loop: no warning, and their samples do not cross.
    let clean = write(dir.path(), "clean.csv", &plain);
    let runs: [(&[&str], &std::path::Path); 3] = [
        (&["curve", "ll", "--interpolate"], &clean),
        (&["curve", "ll"], &input),
        (&["curve", "spline"], &input),
    ];
    for (command, file) in runs {
        let args = [command, &[s(file), "--samples", "4000", "-o", s(&samples)]].concat();
        let o = karkas(&args);
        assert!(o.status.success(), "{command:?}: {}", stderr(&o));
        assert!(
            !stderr(&o).contains("crosses itself"),
            "{command:?}: {}",
            stderr(&o)
        );
        let (_, rows) = read_csv(&samples);
        let curve: Vec<[f64; 2]> = rows.iter().map(|r| [r[1], r[2]]).collect();
        assert!(!polyline_crosses(&curve), "{command:?} crosses");
    }
}

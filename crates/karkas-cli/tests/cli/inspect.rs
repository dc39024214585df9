//! `karkas inspect`: distances of points to a CAD model's faces against closed-form
//! distances (a plane square read from STEP and IGES), the report's header (a contract) and
//! the refusal of bad input with exit 2 naming the file and line.

use crate::common::{karkas, s, square_model, stderr, stdout, temp_dir, write};
use std::path::Path;

/// The report's header and rows (an empty field read as NaN).
fn read_report(path: &Path) -> (String, Vec<Vec<f64>>) {
    let text = std::fs::read_to_string(path).unwrap();
    let mut lines = text.lines();
    let header = lines.next().unwrap().to_owned();
    let rows = lines
        .map(|l| {
            l.split(',')
                .map(|f| {
                    if f.is_empty() {
                        f64::NAN
                    } else {
                        f.parse().unwrap()
                    }
                })
                .collect()
        })
        .collect();
    (header, rows)
}

/// Points above, below and beside the square, with their exact distances.
fn probes(origin: [f64; 3]) -> (String, Vec<f64>) {
    let mut text = String::from("x,y,z\n");
    let mut exact = Vec::new();
    for k in 0..40 {
        let t = k as f64 / 40.0;
        let h = 0.05 + 0.9 * t * t - if k % 2 == 0 { 0.0 } else { 0.6 };
        // Over the square: the distance is |h|.
        let (x, y) = (0.1 + 2.8 * t, 2.9 - 2.7 * t);
        text.push_str(&format!(
            "{:?},{:?},{:?}\n",
            origin[0] + x,
            origin[1] + y,
            origin[2] + h
        ));
        exact.push(h.abs());
        // Beyond the edge x = 3 by a: the distance to the edge.
        let a = 0.2 + 1.3 * t;
        text.push_str(&format!(
            "{:?},{:?},{:?}\n",
            origin[0] + 3.0 + a,
            origin[1] + y,
            origin[2] + h
        ));
        exact.push((a * a + h * h).sqrt());
        // Beyond the corner (0, 0).
        text.push_str(&format!(
            "{:?},{:?},{:?}\n",
            origin[0] - a,
            origin[1] - 0.5 * a,
            origin[2] + h
        ));
        exact.push((1.25 * a * a + h * h).sqrt());
    }
    (text, exact)
}

#[test]
fn distances_to_a_square_equal_the_closed_form_from_step_and_iges() {
    let dir = temp_dir();
    for origin in [[0.0, 0.0, 0.0], [1.0e3, -250.0, 40.0]] {
        for name in ["square.step", "square.igs"] {
            let model = square_model(dir.path(), name, origin);
            let (text, exact) = probes(origin);
            let points = write(dir.path(), "scan.csv", &text);
            let report = dir.path().join("report.csv");
            let o = karkas(&[
                "inspect",
                s(&model),
                "--points",
                s(&points),
                "-o",
                s(&report),
                "--worst",
                "3",
            ]);
            assert!(o.status.success(), "{name}: {}", stderr(&o));
            let (header, rows) = read_report(&report);
            assert_eq!(
                header,
                "point,x,y,z,distance,signed_distance,face,u,v,foot_x,foot_y,foot_z,on_edge"
            );
            assert_eq!(rows.len(), exact.len());
            let scale = 1.0 + origin.iter().fold(0.0f64, |m, c| m.max(c.abs()));
            for (row, d) in rows.iter().zip(&exact) {
                assert!(
                    (row[4] - d).abs() <= 1e-11 * scale,
                    "{name} {origin:?}: point {} distance {} exact {d}",
                    row[0],
                    row[4]
                );
                // The foot is at the reported distance from the point.
                let foot = ((row[1] - row[9]).powi(2)
                    + (row[2] - row[10]).powi(2)
                    + (row[3] - row[11]).powi(2))
                .sqrt();
                assert!((foot - row[4]).abs() <= 1e-11 * scale);
            }
            // One face, no solid: unsigned (the column empty).
            assert!(rows.iter().all(|r| r[5].is_nan() && r[6] == 0.0));
            let worst = exact.iter().copied().fold(0.0, f64::max);
            let out = stdout(&o);
            let max: f64 = out
                .lines()
                .find_map(|l| l.strip_prefix("max "))
                .unwrap()
                .parse()
                .unwrap();
            assert!((max - worst).abs() <= 1e-11 * scale, "{out}");
            assert_eq!(out.lines().filter(|l| l.starts_with("worst ")).count(), 3);
            assert!(out.contains(&format!("points {}", exact.len())), "{out}");
            assert!(!out.contains("signed"), "{out}");
        }
    }
}

#[test]
fn bad_points_and_bad_models_exit_2_naming_file_and_line() {
    let dir = temp_dir();
    let model = square_model(dir.path(), "square.step", [0.0; 3]);
    let points = write(dir.path(), "scan.csv", "x,y,z\n1,2,3\n1,2,oops\n");
    let o = karkas(&["inspect", s(&model), "--points", s(&points)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("scan.csv:3"), "{}", stderr(&o));
    let good = write(dir.path(), "good.csv", "x,y,z\n1,2,3\n");
    // A model cut short in its data section.
    let text = std::fs::read_to_string(&model).unwrap();
    let cut = write(dir.path(), "cut.step", &text[..text.len() * 2 / 3]);
    let o = karkas(&["inspect", s(&cut), "--points", s(&good)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("cut.step:"), "{}", stderr(&o));
    // A file that is not CAD at all.
    let o = karkas(&["inspect", s(&good), "--points", s(&good)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("good.csv"), "{}", stderr(&o));
    // A report that would replace an input, and a report that is not CSV.
    let o = karkas(&["inspect", s(&model), "--points", s(&good), "-o", s(&good)]);
    assert_eq!(o.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&good).unwrap(), "x,y,z\n1,2,3\n");
    let png = dir.path().join("r.png");
    let o = karkas(&["inspect", s(&model), "--points", s(&good), "-o", s(&png)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(!png.exists());
    // A report in a folder that does not exist, or onto a folder: refused before the model
    // is read and the points projected (no timing note), with the message the write gives.
    let nowhere = dir.path().join("missing").join("r.csv");
    let folder = dir.path().join("folder.csv");
    std::fs::create_dir(&folder).unwrap();
    for (report, says) in [
        (&nowhere, "No such file or directory (os error 2)"),
        (&folder, "it is a folder"),
    ] {
        let o = karkas(&["inspect", s(&model), "--points", s(&good), "-o", s(report)]);
        assert_eq!(o.status.code(), Some(2));
        let err = stderr(&o);
        assert_eq!(
            err,
            format!("karkas: error: cannot write {}: {says}\n", report.display())
        );
    }
}

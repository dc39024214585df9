//! The CLI contract of `.dxf` output: the exact SPLINE on layer CURVE and the input points as
//! POINT entities on layer POINTS for `curve ll` and `curve fit`, checked against the input
//! and, through a de Boor evaluation written here, against the command's own CSV samples; the
//! refusal for the discrete periodic splines; the input never overwritten.

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, temp_dir, write};
use std::path::Path;

/// One DXF entity: its kind and its group codes with their values.
struct Entity {
    kind: String,
    pairs: Vec<(u32, String)>,
}

impl Entity {
    /// The values of group `code`.
    fn values(&self, code: u32) -> Vec<&str> {
        self.pairs
            .iter()
            .filter(|p| p.0 == code)
            .map(|p| p.1.as_str())
            .collect()
    }

    /// The values of group `code` as numbers.
    fn reals(&self, code: u32) -> Vec<f64> {
        self.values(code)
            .iter()
            .map(|v| v.trim().parse().unwrap())
            .collect()
    }

    /// The single value of group `code` as an integer.
    fn int(&self, code: u32) -> i64 {
        let v = self.values(code);
        assert_eq!(v.len(), 1, "group {code} of {}", self.kind);
        v[0].trim().parse().unwrap()
    }
}

/// The entities of the ENTITIES section of the DXF text `text`, checking the file's frame
/// (R2000 header, sections, EOF) on the way.
fn entities(text: &str) -> Vec<Entity> {
    let lines: Vec<&str> = text.lines().collect();
    assert_eq!(lines.len() % 2, 0, "group codes and values come in pairs");
    let pairs: Vec<(u32, &str)> = lines
        .chunks(2)
        .map(|c| (c[0].trim().parse().unwrap(), c[1]))
        .collect();
    assert_eq!(
        pairs[..4],
        [
            (0, "SECTION"),
            (2, "HEADER"),
            (9, "$ACADVER"),
            (1, "AC1015")
        ]
    );
    assert_eq!(pairs.last(), Some(&(0, "EOF")));
    for section in [
        "HEADER", "CLASSES", "TABLES", "BLOCKS", "ENTITIES", "OBJECTS",
    ] {
        assert!(pairs.contains(&(2, section)), "no {section} section");
    }
    let start = pairs.iter().position(|p| *p == (2, "ENTITIES")).unwrap() + 1;
    let mut found: Vec<Entity> = Vec::new();
    for &(code, value) in &pairs[start..] {
        if code == 0 {
            if value == "ENDSEC" {
                break;
            }
            found.push(Entity {
                kind: value.to_owned(),
                pairs: Vec::new(),
            });
        } else if let Some(e) = found.last_mut() {
            e.pairs.push((code, value.to_owned()));
        }
    }
    found
}

/// The entities of the DXF file at `path`.
fn read_entities(path: &Path) -> Vec<Entity> {
    entities(&std::fs::read_to_string(path).unwrap())
}

/// A B-spline curve read from a SPLINE entity.
struct Spline {
    degree: usize,
    knots: Vec<f64>,
    control: Vec<[f64; 3]>,
}

impl Spline {
    fn from(e: &Entity) -> Spline {
        assert_eq!(e.kind, "SPLINE");
        let degree = e.int(71) as usize;
        let knots = e.reals(40);
        let (x, y, z) = (e.reals(10), e.reals(20), e.reals(30));
        assert_eq!(e.int(72) as usize, knots.len());
        assert_eq!(e.int(73) as usize, x.len());
        assert_eq!(knots.len(), x.len() + degree + 1);
        let control = (0..x.len()).map(|k| [x[k], y[k], z[k]]).collect();
        Spline {
            degree,
            knots,
            control,
        }
    }

    /// The point at `t` by de Boor's algorithm (Piegl and Tiller, The NURBS Book, A3.1).
    fn eval(&self, t: f64) -> [f64; 3] {
        let (p, n) = (self.degree, self.control.len());
        let mut span = p;
        while span + 1 < n && self.knots[span + 1] <= t {
            span += 1;
        }
        let mut d: Vec<[f64; 3]> = (0..=p).map(|j| self.control[span - p + j]).collect();
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = span - p + j;
                let denominator = self.knots[i + p + 1 - r] - self.knots[i];
                let a = if denominator > 0.0 {
                    (t - self.knots[i]) / denominator
                } else {
                    0.0
                };
                let previous = d[j - 1];
                for (value, before) in d[j].iter_mut().zip(previous) {
                    *value = (1.0 - a) * before + a * *value;
                }
            }
        }
        d[p]
    }
}

const WAVE: &str = "x,y\n0,0\n0.5,0.8\n1.2,1.1\n2,0.7\n2.6,-0.2\n3.5,-0.6\n4.4,0.1\n5,0.9\n";

/// Runs karkas and asserts success.
fn run(args: &[&str]) -> String {
    let o = karkas(args);
    assert!(o.status.success(), "{args:?}: {}", stderr(&o));
    stderr(&o)
}

/// The DXF of `dxf` agrees with the CSV samples `csv` of the same curve to 1e-12 of its size.
fn assert_same_curve(dxf: &Spline, csv: &Path) {
    let (header, rows) = read_csv(csv);
    assert_eq!(header[0], "t");
    let dim = header.len() - 1;
    let size = dxf
        .control
        .iter()
        .flat_map(|p| p.iter().map(|c| c.abs()))
        .fold(0.0, f64::max);
    for row in &rows {
        let q = dxf.eval(row[0]);
        for c in 0..dim {
            assert!(
                (q[c] - row[1 + c]).abs() <= 1e-12 * size,
                "t = {}: {q:?} against {row:?}",
                row[0]
            );
        }
    }
}

#[test]
fn ll_curve_dxf_holds_the_spline_and_the_input_points() {
    let dir = temp_dir();
    let input = write(dir.path(), "wave.csv", WAVE);
    let out = dir.path().join("wave.dxf");
    let e = run(&["curve", "ll", "--order", "3", s(&input), "-o", s(&out)]);
    assert!(e.contains("8 input points"), "{e}");
    let found = read_entities(&out);
    let splines: Vec<&Entity> = found.iter().filter(|e| e.kind == "SPLINE").collect();
    let points: Vec<&Entity> = found.iter().filter(|e| e.kind == "POINT").collect();
    assert_eq!((splines.len(), points.len(), found.len()), (1, 8, 9));
    let spline = splines[0];
    assert_eq!(spline.values(8), ["CURVE"]);
    // Planar (8), open, not rational, not periodic.
    assert_eq!(spline.int(70), 8);
    let curve = Spline::from(spline);
    assert_eq!(curve.degree, 6);
    assert!(curve.control.iter().all(|p| p[2] == 0.0));
    // An open LL curve starts at the first input point and ends at the last.
    let near = |p: [f64; 3], q: [f64; 3]| (0..3).all(|c| (p[c] - q[c]).abs() <= 1e-12 * 5.0);
    assert!(near(curve.control[0], [0.0, 0.0, 0.0]));
    assert!(near(
        curve.control[curve.control.len() - 1],
        [5.0, 0.9, 0.0]
    ));
    let input_points: Vec<[f64; 2]> = WAVE
        .lines()
        .skip(1)
        .map(|l| {
            let v: Vec<f64> = l.split(',').map(|f| f.parse().unwrap()).collect();
            [v[0], v[1]]
        })
        .collect();
    for (p, q) in points.iter().zip(&input_points) {
        assert_eq!(p.values(8), ["POINTS"]);
        assert_eq!(
            [p.reals(10)[0], p.reals(20)[0], p.reals(30)[0]],
            [q[0], q[1], 0.0]
        );
    }
    let csv = dir.path().join("wave.csv.out.csv");
    run(&[
        "curve",
        "ll",
        "--order",
        "3",
        "--samples",
        "97",
        s(&input),
        "-o",
        s(&csv),
    ]);
    assert_same_curve(&curve, &csv);
}

#[test]
fn closed_and_spatial_curves_set_their_flags() {
    let dir = temp_dir();
    let ring: String = std::iter::once("x,y,z".to_owned())
        .chain((0..12).map(|k| {
            let a = k as f64 * std::f64::consts::TAU / 12.0;
            format!(
                "{},{},{}",
                3.0 * a.cos(),
                2.0 * a.sin(),
                0.25 * (2.0 * a).sin()
            )
        }))
        .collect::<Vec<_>>()
        .join("\n");
    let input = write(dir.path(), "ring.csv", &ring);
    let out = dir.path().join("ring.dxf");
    run(&["curve", "ll", "--closed", s(&input), "-o", s(&out)]);
    let found = read_entities(&out);
    let spline = found.iter().find(|e| e.kind == "SPLINE").unwrap();
    // Closed (1), not planar: a curve in space keeps z.
    assert_eq!(spline.int(70), 1);
    assert!(spline.values(210).is_empty());
    let curve = Spline::from(spline);
    let (first, last) = (curve.control[0], curve.control[curve.control.len() - 1]);
    for c in 0..3 {
        assert!(
            (first[c] - last[c]).abs() <= 1e-12 * 3.0,
            "{first:?} {last:?}"
        );
    }
    let points: Vec<&Entity> = found.iter().filter(|e| e.kind == "POINT").collect();
    assert_eq!(points.len(), 12);
    let z: Vec<f64> = points.iter().map(|p| p.reals(30)[0]).collect();
    assert!(z.iter().any(|&z| z.abs() > 0.2));
    let csv = dir.path().join("ring.out.csv");
    run(&["curve", "ll", "--closed", s(&input), "-o", s(&csv)]);
    assert_same_curve(&curve, &csv);
}

#[test]
fn fit_dxf_matches_the_fit_samples() {
    let dir = temp_dir();
    let input = write(dir.path(), "wave.csv", WAVE);
    let out = dir.path().join("fit.DXF");
    run(&["curve", "fit", "--knots", "4", s(&input), "-o", s(&out)]);
    let found = read_entities(&out);
    let spline = found.iter().find(|e| e.kind == "SPLINE").unwrap();
    let curve = Spline::from(spline);
    assert_eq!(curve.degree, 3);
    assert_eq!(found.iter().filter(|e| e.kind == "POINT").count(), 8);
    let csv = dir.path().join("fit.csv");
    run(&["curve", "fit", "--knots", "4", s(&input), "-o", s(&csv)]);
    assert_same_curve(&curve, &csv);
}

#[test]
fn dps_refuses_dxf_and_the_input_is_never_overwritten() {
    let dir = temp_dir();
    let input = write(dir.path(), "wave.csv", WAVE);
    let out = dir.path().join("d.dxf");
    let dps = [
        "curve",
        "dps",
        "--order",
        "2",
        "--n",
        "4",
        s(&input),
        "-o",
        s(&out),
    ];
    assert_rejected(&dps, "discrete periodic splines are point sets", &out, None);
    let csv_out = dir.path().join("d.csv");
    let by_name = [
        "curve",
        "dps",
        "--order",
        "2",
        "--n",
        "4",
        "--format",
        "dxf",
        s(&input),
        "-o",
        s(&csv_out),
    ];
    assert_rejected(&by_name, "no exact STEP/IGES/DXF form", &csv_out, None);
    let named_dxf = write(dir.path(), "pts.dxf", WAVE);
    let same = ["curve", "ll", s(&named_dxf), "-o", s(&named_dxf)];
    assert_rejected(&same, "overwrite the input", &named_dxf, Some(WAVE));
}

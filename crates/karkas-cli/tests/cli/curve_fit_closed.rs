//! `curve fit --closed`: a periodic fit of a closed contour (docs/methods.md §4, "Closed
//! curves"), written as one closed B-spline; judged by Open CASCADE where `OCP` is present.

use crate::common::{assert_rejected, karkas, read_csv, s, stderr, stdout, temp_dir, write};
use std::f64::consts::TAU;
use std::process::Command;

/// A fuselage-like frame `|x / 1.8|^2.5 + |(y - 0.3) / 2.1|^2.5 = 1` around `(cx, cy)`,
/// `n` points from the top, optionally with the first point repeated at the end.
fn frame(n: usize, (cx, cy): (f64, f64), repeat: bool) -> String {
    let mut text = String::from("x,y\n");
    for i in 0..n + usize::from(repeat) {
        let u = TAU * (i % n) as f64 / n as f64 + TAU / 4.0;
        let (c, s) = (u.cos(), u.sin());
        let x = cx + 1.8 * c.signum() * c.abs().powf(0.8);
        let y = cy + 0.3 + 2.1 * s.signum() * s.abs().powf(0.8);
        text.push_str(&format!("{x},{y}\n"));
    }
    text
}

#[test]
fn a_frame_fitted_closed_meets_its_tolerance_and_closes() {
    let dir = temp_dir();
    for centre in [(0.0, 0.0), (1e3, -5e2)] {
        let input = write(dir.path(), "frame.csv", &frame(90, centre, false));
        let out = dir.path().join("c.csv");
        let o = karkas(&[
            "curve",
            "fit",
            "--closed",
            "--tolerance",
            "1e-4",
            s(&input),
            "-o",
            s(&out),
            "--json",
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let json: serde_json::Value = serde_json::from_str(stdout(&o).trim()).unwrap();
        assert_eq!(json["closed"], true);
        assert_eq!(json["tolerance_met"], true);
        assert!(json["max_deviation"].as_f64().unwrap() <= 1e-4);
        let (_, rows) = read_csv(&out);
        let (a, b) = (&rows[0], &rows[rows.len() - 1]);
        assert!(
            (a[1] - b[1]).abs() <= 1e-9 && (a[2] - b[2]).abs() <= 1e-9,
            "{a:?} {b:?}"
        );
    }
}

#[test]
fn a_repeated_first_point_gives_the_same_curve() {
    // The same file names in two folders, so that the STEP entity names agree too.
    let (a, b) = (temp_dir(), temp_dir());
    let mut outputs = Vec::new();
    for (dir, repeat) in [(&a, false), (&b, true)] {
        let input = write(dir.path(), "frame.csv", &frame(60, (3.0, 1.0), repeat));
        let out = dir.path().join("frame.step");
        let o = karkas(&[
            "curve",
            "fit",
            "--closed",
            "--knots",
            "17",
            s(&input),
            "-o",
            s(&out),
        ]);
        assert!(o.status.success(), "{}", stderr(&o));
        let text = std::fs::read_to_string(&out).unwrap();
        let start = text.find("DATA;").unwrap();
        outputs.push(text[start..].to_string());
    }
    assert!(outputs[0].contains("CARTESIAN_POINT"));
    assert_eq!(outputs[0], outputs[1]);
}

#[test]
fn bad_input_names_closed() {
    let dir = temp_dir();
    let input = write(dir.path(), "few.csv", &frame(6, (0.0, 0.0), false));
    let out = dir.path().join("c.step");
    assert_rejected(
        &[
            "curve",
            "fit",
            "--closed",
            "--knots",
            "12",
            s(&input),
            "-o",
            s(&out),
        ],
        "--closed",
        &out,
        None,
    );
    let two = write(dir.path(), "two.csv", "x,y\n0,0\n1,0\n");
    assert_rejected(
        &[
            "curve",
            "fit",
            "--closed",
            "--knots",
            "3",
            s(&two),
            "-o",
            s(&out),
        ],
        "--closed",
        &out,
        None,
    );
    let good = write(dir.path(), "frame.csv", &frame(40, (0.0, 0.0), false));
    for other in ["--pin-ends", "--free-ends", "--close-te"] {
        let o = karkas(&[
            "curve",
            "fit",
            "--closed",
            other,
            "--knots",
            "9",
            s(&good),
            "-o",
            s(&out),
        ]);
        assert_eq!(o.status.code(), Some(2), "{other}");
        assert!(stderr(&o).contains("--closed"), "{other}: {}", stderr(&o));
        assert!(!out.exists());
    }
}

/// Open CASCADE reads the closed fit's STEP, IGES and DXF... (STEP here) as one closed
/// edge and makes a valid planar face of it whose area is that of the frame's polygon.
#[test]
fn open_cascade_makes_a_valid_face_of_the_closed_step() {
    let probe = Command::new("python3").args(["-c", "import OCP"]).output();
    if !probe.is_ok_and(|o| o.status.success()) {
        eprintln!("skipped: python3 with OCP is not available");
        return;
    }
    let dir = temp_dir();
    let input = write(dir.path(), "frame.csv", &frame(90, (40.0, -7.0), false));
    let step = dir.path().join("frame.step");
    let o = karkas(&[
        "curve",
        "fit",
        "--closed",
        "--tolerance",
        "1e-4",
        s(&input),
        "-o",
        s(&step),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    // The shoelace area of a dense polygon of the exact frame.
    let m = 200_000;
    let area: f64 = (0..m)
        .map(|i| {
            let p = |k: usize| {
                let u = TAU * k as f64 / m as f64;
                let (c, s) = (u.cos(), u.sin());
                (
                    1.8 * c.signum() * c.abs().powf(0.8),
                    2.1 * s.signum() * s.abs().powf(0.8),
                )
            };
            let (a, b) = (p(i), p((i + 1) % m));
            0.5 * (a.0 * b.1 - a.1 * b.0)
        })
        .sum();
    let script = format!(
        r#"
import sys
from OCP.STEPControl import STEPControl_Reader
from OCP.TopAbs import TopAbs_EDGE
from OCP.TopExp import TopExp_Explorer
from OCP.TopoDS import TopoDS
from OCP.BRep import BRep_Tool
from OCP.BRepBuilderAPI import BRepBuilderAPI_MakeWire, BRepBuilderAPI_MakeFace
from OCP.BRepCheck import BRepCheck_Analyzer
from OCP.GProp import GProp_GProps
from OCP.BRepGProp import BRepGProp
r = STEPControl_Reader()
assert r.ReadFile(sys.argv[1]) == 1
r.TransferRoots()
shape = r.OneShape()
edges = []
ex = TopExp_Explorer(shape, TopAbs_EDGE)
while ex.More():
    edges.append((getattr(TopoDS, "Edge_s", None) or TopoDS.Edge)(ex.Current()))
    ex.Next()
assert len(edges) == 1, len(edges)
assert BRep_Tool.IsClosed_s(edges[0]), "edge not closed"
wire = BRepBuilderAPI_MakeWire(edges[0]).Wire()
assert wire.Closed(), "wire not closed"
maker = BRepBuilderAPI_MakeFace(wire, True)
assert maker.IsDone(), "no face"
face = maker.Face()
assert BRepCheck_Analyzer(face).IsValid(), "invalid face"
props = GProp_GProps()
BRepGProp.SurfaceProperties_s(face, props, 1e-9)
area = abs(props.Mass())
assert abs(area - {area}) <= 1e-3 * {area}, (area, {area})
print("ok", area)
"#
    );
    let o = Command::new("python3")
        .args(["-c", &script, s(&step)])
        .output()
        .unwrap();
    assert!(
        o.status.success() && String::from_utf8_lossy(&o.stdout).starts_with("ok"),
        "{}{}",
        String::from_utf8_lossy(&o.stdout),
        String::from_utf8_lossy(&o.stderr)
    );
}

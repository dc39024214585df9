//! `karkas demo`: the report lists every example of the five papers and the loft of the
//! shipped wing, the cylinder row of Kuznetsov and Filatov's table lands where the paper's
//! figure is, the wing's rows meet the loft's acceptance, and every file the report names
//! exists.

use crate::common::{karkas, s, stderr, temp_dir};
use serde_json::Value;

/// The examples the demo promises (issue contract: scripts read report.json by these ids).
const EXAMPLES: [&str; 12] = [
    "ll-contour",
    "ll-aircraft",
    "coons-fig3",
    "coons-fuselage",
    "dps-five-petal",
    "dps-knotted-tube",
    "fit-hydrofoil",
    "fit-hydrofoil-clean",
    "param-cylinder-hyperboloid",
    "param-angle-sweep",
    "param-relay",
    "loft-wing",
];

#[test]
fn demo_writes_a_complete_report() {
    let dir = temp_dir();
    let out = dir.path().join("demo");
    let run = karkas(&["demo", "--out", s(&out)]);
    assert!(run.status.success(), "demo failed: {}", stderr(&run));

    let report: Value =
        serde_json::from_str(&std::fs::read_to_string(out.join("report.json")).unwrap()).unwrap();
    let examples = report["examples"].as_array().unwrap();
    let ids: Vec<&str> = examples.iter().map(|e| e["id"].as_str().unwrap()).collect();
    assert_eq!(ids, EXAMPLES);

    for e in examples {
        assert!(
            !e["rows"].as_array().unwrap().is_empty(),
            "{} has no rows",
            e["id"]
        );
        for kind in ["pictures", "viewers", "data"] {
            for f in e[kind].as_array().unwrap() {
                let name = f.as_str().unwrap();
                let len = std::fs::metadata(out.join(name)).map(|m| m.len());
                assert!(matches!(len, Ok(n) if n > 0), "{name} missing or empty");
            }
        }
        assert!(
            !e["pictures"].as_array().unwrap().is_empty(),
            "{} has no picture",
            e["id"]
        );
    }

    // Kuznetsov and Filatov's table: the cylinder frame along the lines of curvature, paper 0.011.
    let cylinder = examples
        .iter()
        .flat_map(|e| e["rows"].as_array().unwrap())
        .find(|r| r["example"].as_str() == Some("004 cylinder, lines of curvature"))
        .expect("the cylinder row");
    let value = cylinder["karkas"].as_f64().unwrap();
    assert!((0.008..=0.013).contains(&value), "cylinder {value}");
    assert_eq!(cylinder["paper"].as_f64(), Some(0.011));
    let ratio = cylinder["ratio"].as_f64().unwrap();
    assert!((ratio - value / 0.011).abs() < 1e-12);

    // Every paper's figure is in a row with its ratio.
    let paper_rows = examples
        .iter()
        .flat_map(|e| e["rows"].as_array().unwrap())
        .filter(|r| r["paper"].is_number())
        .count();
    // Kuznetsov and Filatov: 7 table entries, the same 7 frames with natural ends and the 7
    // printed points of the angle sweep; Pavlov: 20 per-point deviations and their maximum,
    // and the largest deviation beside the clean hydrofoil's.
    assert_eq!(paper_rows, 7 + 7 + 7 + 21 + 1);
    crate::demo_hydrofoil::check_clean_hydrofoil(&out, examples);
    check_angle_sweep(examples);

    check_relaid_frames(examples);
    check_loft_wing(&out, examples);

    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    for seed in ["000", "001", "002", "003", "004"] {
        assert!(html.contains(&format!("id=\"seed-{seed}\"")), "seed {seed}");
    }
    assert!(html.contains("report.json"));

    // The browser workbench: the page web/build.py built, with its WebAssembly inlined.
    let workbench = std::fs::read_to_string(out.join("karkas-workbench.html")).unwrap();
    let built = include_str!("../../../../web/dist/karkas-workbench.html");
    assert_eq!(workbench, built);
    assert!(workbench.contains(r#"<meta name="karkas-sources" content=""#));
    let wasm = workbench
        .split(r#"<script id="karkas-wasm" type="application/octet-stream">"#)
        .nth(1)
        .and_then(|rest| rest.split("</script>").next())
        .unwrap();
    // Base64 of a WebAssembly module starts with its magic number, "\0asm".
    assert!(
        wasm.starts_with("AGFzbQ"),
        "{}",
        &wasm[..20.min(wasm.len())]
    );
}

/// The angle sweep of Kuznetsov and Filatov's figures 3.2 and 3.3: a row for every angle of
/// every series, each naming its angle as `N deg`, the paper's printed points beside the frames
/// it measured, and for each surface the frame along the lines of curvature (0 deg) the best.
fn check_angle_sweep(examples: &[Value]) {
    let sweep = examples
        .iter()
        .find(|e| e["id"] == "param-angle-sweep")
        .expect("the angle sweep");
    let rows: Vec<(&str, f64, Option<f64>)> = sweep["rows"]
        .as_array()
        .unwrap()
        .iter()
        .map(|r| {
            (
                r["example"].as_str().unwrap(),
                r["karkas"].as_f64().unwrap(),
                r["paper"].as_f64(),
            )
        })
        .collect();
    let row = |name: &str| {
        rows.iter()
            .find(|r| r.0 == format!("004 sweep: {name}"))
            .unwrap_or_else(|| panic!("no row {name} in {rows:?}"))
    };
    for surface in ["cylinder", "hyperboloid"] {
        let principal = row(&format!("{surface}, 0 deg (lines of curvature)"));
        let one = if surface == "cylinder" {
            "generator"
        } else {
            "meridian"
        };
        let mut series = Vec::new();
        for deg in [15, 30, 45, 60, 75] {
            series.push(row(&format!("{surface}, {one} turned {deg} deg")));
            if surface == "cylinder" || deg < 45 {
                series.push(row(&format!("{surface}, both families turned {deg} deg")));
            }
        }
        // Turning one family can leave the worst point where it was (at the seam of the first
        // circle, which every frame shares), so small turns of one family may tie with 0 deg;
        // none is better, and turning both families is always worse.
        for r in &series {
            assert!(r.1 >= principal.1, "{r:?} vs 0 deg {principal:?}");
            if r.0.contains("both families") || r.0.contains("75 deg") {
                assert!(r.1 > principal.1, "{r:?} vs 0 deg {principal:?}");
            }
        }
        let all = rows.iter().filter(|r| r.0.contains(surface)).count();
        assert_eq!(
            all,
            series.len() + 1 + usize::from(surface == "hyperboloid")
        );
    }
    assert_eq!(row("cylinder, 0 deg (lines of curvature)").2, Some(0.011));
    assert_eq!(row("cylinder, both families turned 30 deg").2, Some(0.089));
    assert_eq!(row("cylinder, both families turned 45 deg").2, Some(0.267));
    assert_eq!(row("cylinder, generator turned 30 deg").2, Some(0.086));
    assert_eq!(row("cylinder, generator turned 45 deg").2, Some(0.09));
    assert_eq!(row("hyperboloid, 0 deg (lines of curvature)").2, Some(0.03));
    assert_eq!(row("hyperboloid, meridian turned 68 deg").2, Some(0.078));
    // The 0 deg frames are the table's frames along the lines of curvature.
    let table = examples
        .iter()
        .flat_map(|e| e["rows"].as_array().unwrap())
        .find(|r| r["example"] == "004 cylinder, lines of curvature")
        .unwrap();
    assert_eq!(
        table["karkas"].as_f64(),
        Some(row("cylinder, 0 deg (lines of curvature)").1)
    );
}

#[test]
fn demo_into_a_file_is_an_error() {
    let dir = temp_dir();
    let file = dir.path().join("taken");
    std::fs::write(&file, "keep").unwrap();
    let run = karkas(&["demo", "--out", s(&file)]);
    assert_eq!(run.status.code(), Some(2));
    assert_eq!(std::fs::read_to_string(&file).unwrap(), "keep");
    assert!(stderr(&run).contains("taken"), "{}", stderr(&run));
}

/// The re-laid frames: for the cylinder and the hyperboloid at 30 and 45 degrees, the turned,
/// re-laid and principal frames' errors; the hyperboloid's re-laid frames land within twice
/// the principal frame's error.
fn check_relaid_frames(examples: &[Value]) {
    let relay = examples
        .iter()
        .find(|e| e["id"] == "param-relay")
        .expect("the param-relay example");
    let rows = relay["rows"].as_array().unwrap();
    let value = |example: &str, measure: &str| {
        rows.iter()
            .find(|r| {
                r["example"].as_str() == Some(example)
                    && r["measure"]
                        .as_str()
                        .is_some_and(|m| m.starts_with(measure))
            })
            .and_then(|r| r["karkas"].as_f64())
            .unwrap_or_else(|| panic!("{example}: no {measure} row"))
    };
    for surface in ["cylinder", "hyperboloid"] {
        for degrees in [30, 45] {
            let example = format!("004 {surface}, both axes turned {degrees} deg");
            let turned = value(&example, "turned frame");
            let relaid = value(&example, "re-laid");
            let principal = value(&example, "principal frame");
            assert!(turned > 0.0 && relaid > 0.0 && principal > 0.0, "{example}");
            if surface == "hyperboloid" {
                assert!(
                    relaid <= 2.0 * principal,
                    "{example}: {relaid} vs {principal}"
                );
            }
            // Re-laid from a denser turned frame: the error falls to the principal frame's of
            // the same region (cylinder) and to the dense input's own (hyperboloid), far below
            // the coarse turned frame's.
            let dense = rows
                .iter()
                .filter_map(|r| r["example"].as_str())
                .find(|e| e.starts_with(&format!("{example}, re-laid from ")))
                .unwrap_or_else(|| panic!("{example}: no dense row"))
                .to_string();
            let dense_turned = value(&dense, "turned frame");
            let dense_input = value(&dense, "dense turned input frame");
            let dense_relaid = value(&dense, "re-laid");
            let dense_principal = value(&dense, "principal frame");
            assert_eq!(dense_turned, turned, "{dense}");
            assert!(
                dense_relaid < 0.5 * turned,
                "{dense}: {dense_relaid} vs {turned}"
            );
            if surface == "cylinder" {
                assert!(
                    dense_relaid <= 1.5 * dense_principal && dense_relaid <= 1.5 * principal,
                    "{dense}: {dense_relaid} vs {dense_principal}, {principal}"
                );
                assert!(
                    dense_principal > 0.5 * principal,
                    "{dense}: {dense_principal}"
                );
            } else {
                assert!(
                    dense_relaid <= 1.5 * dense_input,
                    "{dense}: {dense_relaid} vs {dense_input}"
                );
            }
        }
    }
}

/// The shipped wing's loft: 3 sections; every input point within 1e-5 of the chord of the
/// surface at its station (none beyond); the leading and trailing edges through the placed
/// sections; on 1000 spanwise lines no chord, twist or leading edge outside its neighbours'
/// range and no crossing trailing edges; the control points of a cubic across the span
/// (2 x 3 - 2 rows with double knots at the inner station) and of a fit along the sections.
fn check_loft_wing(out: &std::path::Path, examples: &[Value]) {
    let wing = examples
        .iter()
        .find(|e| e["id"] == "loft-wing")
        .expect("the loft-wing example");
    assert_eq!(wing["seed"], "loft");
    let rows = wing["rows"].as_array().unwrap();
    let value = |start: &str| {
        let row = rows
            .iter()
            .find(|r| r["measure"].as_str().unwrap().starts_with(start))
            .unwrap_or_else(|| panic!("no row {start} in {rows:?}"));
        assert_eq!(row["example"], "loft: shipped wing, 3 sections");
        row["karkas"].as_f64().unwrap()
    };
    assert_eq!(value("sections"), 3.0);
    let (along_span, along_sections) = (
        value("control points along the span"),
        value("control points along the sections"),
    );
    assert!((4.0..=10.0).contains(&along_span), "{along_span}");
    assert!((10.0..=200.0).contains(&along_sections), "{along_sections}");
    let worst = value("largest distance of an input point");
    assert!(worst > 0.0 && worst <= 1e-5, "{worst}");
    assert_eq!(value("input points farther than the tolerance"), 0.0);
    assert!(value("leading-edge line off") < 1e-12);
    assert!(value("trailing-edge lines off") < 1e-12);
    assert_eq!(
        value("1000 spanwise lines with chord, twist or leading edge"),
        0.0
    );
    assert_eq!(
        value("1000 spanwise lines whose trailing-edge branches cross"),
        0.0
    );
    // The shipped files are written beside the report, as data/loft-wing has them.
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/loft-wing");
    for (written, shipped) in [
        ("loft-wing.csv", "wing.csv"),
        ("loft-wing-naca4415.dat", "naca4415.dat"),
        ("loft-wing-naca2412.dat", "naca2412.dat"),
        ("loft-wing-naca0009.dat", "naca0009.dat"),
    ] {
        assert_eq!(
            std::fs::read(out.join(written)).unwrap(),
            std::fs::read(root.join(shipped)).unwrap(),
            "{written}"
        );
    }
    let html = std::fs::read_to_string(out.join("index.html")).unwrap();
    assert!(html.contains("id=\"seed-loft\""));
}

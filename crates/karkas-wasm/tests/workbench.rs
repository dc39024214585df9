//! The workbench's curves and surfaces against the command line's files: the same points and
//! options give the same STEP, IGES and DXF bytes as `karkas_io`'s writers, which the command
//! line calls; and errors name the input as the command line's do.

use std::path::Path;

use karkas::bspline::ToBSplineCurve;
use karkas::{Grid, Point, Point2, Point3};
use karkas_io::export::cad::{write_cad_curve_with_points, write_cad_surface};
use karkas_io::OutputFormat;
use karkas_wasm::curves::{build_curve, CurveRequest};
use karkas_wasm::surfaces::grid_surface;

fn request(method: &str) -> CurveRequest {
    CurveRequest {
        method: method.into(),
        order: 3,
        closed: false,
        ends: "not-a-knot".into(),
        param: "chord".into(),
        tolerance: 1e-3,
        eps: f64::INFINITY,
        corners: Vec::new(),
        knots: Vec::new(),
        start: Vec::new(),
    }
}

/// A NACA 0012 section through 61 points, trailing edge to trailing edge over the top.
fn section() -> Vec<Point2> {
    (0..61)
        .map(|k| {
            let th = std::f64::consts::TAU * k as f64 / 60.0;
            let x = 0.5 * (1.0 + th.cos());
            let y = 0.6
                * (0.2969 * x.sqrt() - 0.126 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                    - 0.1036 * x.powi(4));
            Point([x, if k <= 30 { y } else { -y }])
        })
        .collect()
}

#[test]
fn curve_exports_equal_the_command_line_files() {
    let points = section();
    let dir = std::env::temp_dir().join(format!("karkas-wasm-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    // What `karkas curve ll --order 3 foil.dat -o foil.EXT` writes.
    let ll = karkas::ll::LlCurve::new(&points, 3, false).unwrap();
    let bspline = ToBSplineCurve::to_bspline(&ll).unwrap();
    let built = build_curve(&points, &request("ll"), "foil.dat").unwrap();
    for (format, ext) in [
        (OutputFormat::Step, "step"),
        (OutputFormat::Iges, "iges"),
        (OutputFormat::Dxf, "dxf"),
    ] {
        let path = dir.join(format!("foil.{ext}"));
        write_cad_curve_with_points(&bspline, &points, format, &path, Path::new("foil.dat"))
            .unwrap();
        let text = built.cad(format, "foil", "foil.dat").unwrap();
        assert_eq!(text, std::fs::read_to_string(&path).unwrap(), "{ext}");
    }
    // `-o foil.csv`: the default samples, 10 per point.
    let (ts, samples) = karkas_io::export::samples::sample_curve(&ll, 10 * points.len());
    let path = dir.join("foil.csv");
    karkas_io::write::write_curve_csv(&path, &ts, &samples).unwrap();
    assert_eq!(built.csv(), std::fs::read_to_string(&path).unwrap());
    assert!(built.svg("LL").unwrap().contains("<svg"));
    std::fs::remove_dir_all(&dir).ok();
    for method in ["ll", "ll-interpolate", "spline", "fit"] {
        let built = build_curve(&points, &request(method), "foil.dat").unwrap();
        let (degree, poles) = built.bspline_size();
        assert!(degree >= 3 && poles >= 4, "{method}: {degree}, {poles}");
        assert!(built
            .cad(OutputFormat::Step, "foil", "foil.dat")
            .unwrap()
            .starts_with("ISO-10303-21;"));
        // Samples: 9 numbers each, arc length increasing; the profile finite.
        let s = built.samples(50);
        assert_eq!(s.len(), 9 * 50);
        assert!(s
            .chunks(9)
            .zip(s.chunks(9).skip(1))
            .all(|(a, b)| b[8] > a[8]));
        let profile = built.profile(4);
        assert_eq!(profile.len() % 3, 0);
        assert!(profile.iter().all(|x| x.is_finite()), "{method}");
    }
}

#[test]
fn surface_step_equals_the_command_line_file() {
    let grid = Grid::from_fn(6, 7, |i, j| {
        let (u, v) = (i as f64 / 5.0, j as f64 / 6.0);
        Point3::new([u, v, (u * 3.0).sin() * (v * 2.0).cos()])
    });
    let built = grid_surface(&grid, "ll", 3, "sheet.csv").unwrap();
    let text = built.cad(OutputFormat::Step, "sheet", "sheet.csv").unwrap();
    let path = std::env::temp_dir().join(format!("karkas-wasm-sheet-{}.step", std::process::id()));
    let surface = karkas::ll::LlSurface::new(&grid, 3, false, false).unwrap();
    let bspline = karkas::bspline::ToBSplineSurface::to_bspline(&surface).unwrap();
    write_cad_surface(&bspline, OutputFormat::Step, &path).unwrap();
    let written = std::fs::read_to_string(&path).unwrap();
    std::fs::remove_file(&path).ok();
    // The product is named after the file's stem.
    assert_eq!(
        text.replace("'sheet", "'x"),
        written.replace(&format!("'karkas-wasm-sheet-{}", std::process::id()), "'x")
    );
    assert_eq!(built.samples(4, 5).len(), 3 * 20);
    // `-o sheet.obj`: the default samples, 4 per grid line, at least 50.
    let (_, _, samples) = karkas_io::export::samples::sample_surface(&surface, 50, 50);
    let obj = std::env::temp_dir().join(format!("karkas-wasm-sheet-{}.obj", std::process::id()));
    karkas_io::obj::write_surface_obj(&obj, 50, 50, &samples).unwrap();
    assert_eq!(
        built.mesh("obj").unwrap(),
        std::fs::read_to_string(&obj).unwrap()
    );
    std::fs::remove_file(&obj).ok();
    assert!(built.mesh("stl").unwrap().starts_with("solid"));
    assert!(built.mesh("ply").is_err());
    let section = built.section([1.0, 0.0, 0.0], 0.5).unwrap();
    assert!(section.len() > 3 * 5 && section.chunks(3).last().unwrap()[0].is_nan());
    assert!(grid_surface(&grid, "nurbs", 3, "sheet.csv").is_err());
}

#[test]
fn errors_name_the_input() {
    let two = [Point([0.0, 0.0]), Point([1.0, 0.0])];
    let e = build_curve(&two, &request("ll"), "two.csv").err().unwrap();
    assert!(e.starts_with("two.csv: "), "{e}");
    let e = build_curve(&section(), &request("bezier"), "foil.dat")
        .err()
        .unwrap();
    assert_eq!(e, "unknown method 'bezier'");
}

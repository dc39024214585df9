//! Seed 000 (LL-approximation): the 53-point contour with L = 5 and the aircraft-like surface
//! with its sections (METHODS.md §1.6).

use super::data::{aircraft_15x31, contour_53, contour_csv, grid_csv};
use super::Finding;
use anyhow::Result;
use karkas::ll::{LlCurve, LlSurface};
use karkas::{Curve, Point, Point2, Point3, Surface};
use karkas_io::obj::write_surface_obj;
use karkas_io::svg::{write_curve_svg, write_lines_svg, CurvePlot, LineGroup, LinesPlot};
use karkas_io::write::{write_atomic, write_curve_csv};
use std::path::Path;

const ORDER: usize = 5;

/// Runs both examples into `out`.
pub fn run(out: &Path) -> Result<Vec<Finding>> {
    let mut findings = contour(out)?;
    findings.extend(aircraft(out)?);
    Ok(findings)
}

fn write_text(path: &Path, text: &str) -> Result<()> {
    write_atomic(path, |w| w.write_all(text.as_bytes()))?;
    Ok(())
}

fn sample<const D: usize>(curve: &LlCurve<D>, n: usize) -> (Vec<f64>, Vec<Point<D>>) {
    let mut ts = vec![0.0; n];
    let mut pts = vec![Point::ZERO; n];
    curve.sample_into(&mut ts, &mut pts);
    (ts, pts)
}

fn contour(out: &Path) -> Result<Vec<Finding>> {
    let points = contour_53();
    write_text(&out.join("contour-53.csv"), &contour_csv(&points))?;
    let approx = LlCurve::new(&points, ORDER, true)?;
    let interp = LlCurve::interpolating(&points, ORDER, true)?;
    let (ts, samples) = sample(&approx, 2000);
    write_curve_csv(&out.join("contour-ll5.csv"), &ts, &samples)?;
    write_curve_svg(
        &out.join("contour-ll5.svg"),
        &CurvePlot {
            title: "Seed 000: LL curve, L = 5, through a 53-point contour",
            curve: &samples,
            input: &points,
            closed_input: true,
        },
    )?;
    let (_, interp_samples) = sample(&interp, 2000);
    write_curve_svg(
        &out.join("contour-ll5-interpolating.svg"),
        &CurvePlot {
            title: "Seed 000: interpolating LL curve, L = 5",
            curve: &interp_samples,
            input: &points,
            closed_input: true,
        },
    )?;

    // Formula (5): P(t_i) - r_i = d_L D_i at every node.
    let axis = approx.axis();
    let k = axis.nodes();
    let d_l = approx.kernel().d_l();
    let node_error = (1..k)
        .map(|i| {
            let prev = points[if i == 1 { k - 2 } else { i - 2 }];
            let second = prev + points[i] - points[i - 1] * 2.0;
            approx
                .eval(axis.node(i))
                .distance(points[i - 1] + second * d_l)
        })
        .fold(0.0, f64::max);
    let interp_error = (1..=k)
        .map(|i| interp.eval(axis.node(i)).distance(points[i - 1]))
        .fold(0.0, f64::max);
    // The flat bottom is y = 0: the approximating curve never dips below it (convex hull of
    // consecutive triples); the interpolating one overshoots at the corners.
    let dip = |s: &[Point2]| s.iter().map(|p| -p[1]).fold(0.0, f64::max);
    Ok(vec![
        Finding {
            example: "000 contour, 53 points, L = 5".into(),
            measure: "max |P(t_i) - r_i - d_L D_i| (formula 5)".into(),
            value: node_error,
            paper: None,
        },
        Finding {
            example: "000 contour, 53 points, L = 5".into(),
            measure: "dip below the flat bottom, approximating".into(),
            value: dip(&samples),
            paper: None,
        },
        Finding {
            example: "000 contour, interpolating".into(),
            measure: "max |P(t_i) - p_i|".into(),
            value: interp_error,
            paper: None,
        },
        Finding {
            example: "000 contour, interpolating".into(),
            measure: "dip below the flat bottom, interpolating".into(),
            value: dip(&interp_samples),
            paper: None,
        },
    ])
}

/// An axonometric view of a 3-D point: the camera on the side of +y, a little ahead of the
/// nose (azimuth 15 degrees) and above (elevation 35 degrees).
fn view(p: Point3) -> Point2 {
    let (az, el) = (15f64.to_radians(), 35f64.to_radians());
    let right = p[0] * az.cos() + p[1] * az.sin();
    let up = (p[0] * az.sin() - p[1] * az.cos()) * el.sin() + p[2] * el.cos();
    Point2::new([right, up])
}

fn aircraft(out: &Path) -> Result<Vec<Finding>> {
    let grid = aircraft_15x31();
    write_text(&out.join("aircraft-15x31.csv"), &grid_csv(&grid))?;
    let surface = LlSurface::new(&grid, ORDER, false, false)?;
    let (au, av) = (surface.axis_u(), surface.axis_v());

    // The 15 sections x = const through the nodes, and 11 lines v = const along the body.
    let sections: Vec<Vec<Point3>> = (1..=au.nodes())
        .map(|i| sample(&surface.curve_at_u(au.node(i)), 200).1)
        .collect();
    let v_lines: Vec<Vec<Point3>> = (0..11)
        .map(|k| sample(&surface.curve_at_v(surface.domain_v().uniform(k, 11)), 200).1)
        .collect();
    let to_view = |lines: &[Vec<Point3>]| -> Vec<Vec<Point2>> {
        lines
            .iter()
            .map(|l| l.iter().map(|&p| view(p)).collect())
            .collect()
    };
    let frame_lines = to_view(&v_lines);
    let section_lines = to_view(&sections);
    write_lines_svg(
        &out.join("aircraft-ll5-view.svg"),
        &LinesPlot {
            title: "Seed 000: LL surface, L = 5, 15 sections x = const and 11 lines v = const",
            axes: ("view x", "view y"),
            groups: &[
                LineGroup {
                    lines: &frame_lines,
                    rgb: (160, 160, 160),
                    width: 1,
                },
                LineGroup {
                    lines: &section_lines,
                    rgb: (20, 60, 200),
                    width: 2,
                },
            ],
        },
    )?;
    let body_plan: Vec<Vec<Point2>> = sections
        .iter()
        .map(|s| s.iter().map(|p| Point2::new([p[1], p[2]])).collect())
        .collect();
    write_lines_svg(
        &out.join("aircraft-ll5-sections.svg"),
        &LinesPlot {
            title: "Seed 000: the 15 sections x = const (body plan, y-z)",
            axes: ("y", "z"),
            groups: &[LineGroup {
                lines: &body_plan,
                rgb: (20, 60, 200),
                width: 1,
            }],
        },
    )?;
    let (nu, nv) = (141, 121);
    let mut us = vec![0.0; nu];
    let mut vs = vec![0.0; nv];
    let mut mesh = vec![Point3::ZERO; nu * nv];
    surface.sample_grid_into(&mut us, &mut vs, &mut mesh);
    write_surface_obj(&out.join("aircraft-ll5.obj"), nu, nv, &mesh)?;

    let corner_error = [(0, 0), (0, 30), (14, 0), (14, 30)]
        .iter()
        .map(|&(i, j)| {
            surface
                .eval(au.node(i + 1), av.node(j + 1))
                .distance(*grid.get(i, j))
        })
        .fold(0.0, f64::max);
    let plane_error = sections
        .iter()
        .enumerate()
        .flat_map(|(i, s)| s.iter().map(move |p| (p[0] - i as f64).abs()))
        .fold(0.0, f64::max);
    Ok(vec![
        Finding {
            example: "000 aircraft 15 x 31, L = 5".into(),
            measure: "max corner error (corners interpolated)".into(),
            value: corner_error,
            paper: None,
        },
        Finding {
            example: "000 aircraft 15 x 31, L = 5".into(),
            measure: "max |x - x_i| on the node sections".into(),
            value: plane_error,
            paper: None,
        },
    ])
}

//! Aulchenko et al. (LL-approximation): the 53-point contour with L = 5 and the aircraft-like surface
//! with 15 sections x = const and 11 sections y = const, hidden lines removed (docs/methods.md
//! §1.4, §1.6).

use super::common::{write_text, write_viewer, Finding, Output};
use super::data::{aircraft_15x31, contour_53, contour_csv, grid_csv};
use crate::output::samples::{sample_curve, sample_surface};
use anyhow::Result;
use karkas::ll::{LlCurve, LlSurface};
use karkas::section::{Plane, Section, SectionOptions, Sectioner};
use karkas::{Curve, Grid, Point2, Point3, Surface};
use karkas_io::obj::write_surface_obj;
use karkas_io::scene::{write_scene_png, write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::svg::{write_curve_svg, write_lines_svg, CurvePlot, LineGroup, LinesPlot};
use karkas_io::write::write_curve_csv;

const ORDER: usize = 5;

pub fn contour(out: &Output) -> Result<Vec<Finding>> {
    let points = contour_53();
    write_text(&out.file("contour-53.csv"), &contour_csv(&points))?;
    let approx = LlCurve::new(&points, ORDER, true)?;
    let interp = LlCurve::interpolating(&points, ORDER, true)?;
    let (ts, samples) = sample_curve(&approx, 2000);
    write_curve_csv(&out.file("contour-ll5.csv"), &ts, &samples)?;
    write_curve_svg(
        &out.file("contour-ll5.svg"),
        &CurvePlot {
            title: "Aulchenko et al.: LL curve, L = 5, through a 53-point contour",
            curve: &samples,
            input: &points,
            closed_input: true,
        },
    )?;
    let (_, interp_samples) = sample_curve(&interp, 2000);
    write_curve_svg(
        &out.file("contour-ll5-interpolating.svg"),
        &CurvePlot {
            title: "Aulchenko et al.: interpolating LL curve, L = 5",
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
        Finding::new(
            "000 contour, 53 points, L = 5",
            "max |P(t_i) - r_i - d_L D_i| (formula 5)",
            node_error,
        ),
        Finding::new(
            "000 contour, 53 points, L = 5",
            "dip below the flat bottom, approximating",
            dip(&samples),
        ),
        Finding::new(
            "000 contour, interpolating",
            "max |P(t_i) - p_i|",
            interp_error,
        ),
        Finding::new(
            "000 contour, interpolating",
            "dip below the flat bottom, interpolating",
            dip(&interp_samples),
        ),
    ])
}

/// The camera of the aircraft picture: on the side of the wing (+y), ahead of the nose and
/// above it.
const AIRCRAFT_VIEW: View = View {
    azimuth: 118.0,
    elevation: 28.0,
};

/// The stations of the paper's picture: 15 sections x = const through the grid's rows.
const STATIONS: usize = 15;
/// And 11 sections y = const, from beside the keel line to near the wing tip.
fn buttock_lines() -> Vec<f64> {
    (0..11).map(|k| 0.25 + 0.5 * k as f64).collect()
}

/// The polylines of a section, closed ones closed again.
fn polylines(section: &Section<3>) -> Vec<Vec<Point3>> {
    section
        .curves
        .iter()
        .map(|c| {
            let mut line = c.points.clone();
            if c.closed {
                line.push(c.points[0]);
            }
            line
        })
        .collect()
}

pub fn aircraft(out: &Output) -> Result<Vec<Finding>> {
    let grid = aircraft_15x31();
    write_text(&out.file("aircraft-15x31.csv"), &grid_csv(&grid))?;
    let surface = LlSurface::new(&grid, ORDER, false, false)?;
    let sections = AircraftSections::cut(&surface, &grid)?;
    sections.write_views(out, &surface, &grid)?;
    sections.write_body_plan(out)?;
    let (au, av) = (surface.axis_u(), surface.axis_v());
    let corner_error = [(0, 0), (0, 30), (14, 0), (14, 30)]
        .iter()
        .map(|&(i, j)| {
            surface
                .eval(au.node(i + 1), av.node(j + 1))
                .distance(*grid.get(i, j))
        })
        .fold(0.0, f64::max);
    Ok(vec![
        Finding::new(
            "000 aircraft 15 x 31, L = 5",
            "max corner error (corners interpolated)",
            corner_error,
        ),
        Finding::new(
            "000 aircraft sections",
            "max distance of section points from their plane",
            sections.plane_error,
        ),
        Finding::new(
            "000 aircraft sections",
            "pieces: x = const (all by the fast path (21))",
            if sections.all_fast {
                sections.stations.len() as f64
            } else {
                f64::NAN
            },
        ),
        Finding::new(
            "000 aircraft sections",
            "pieces: y = const (traced)",
            sections.buttocks.len() as f64,
        ),
    ])
}

/// The aircraft's sections by true planes: x = const (the paper's fast path, formula (21))
/// and y = const (traced).
struct AircraftSections {
    stations: Vec<Vec<Point3>>,
    buttocks: Vec<Vec<Point3>>,
    /// The largest distance of a section point from its plane.
    plane_error: f64,
    /// Whether every x = const section took the fast path.
    all_fast: bool,
}

impl AircraftSections {
    /// Cuts at the grid's stations and the buttock lines, two cells per LL segment for the
    /// start points.
    fn cut(surface: &LlSurface<3>, grid: &Grid<Point3>) -> Result<Self> {
        let options = SectionOptions {
            cells: (2 * grid.rows(), 2 * grid.cols()),
            ..SectionOptions::default()
        };
        let sectioner = Sectioner::new(surface, &options)?;
        let mut plane_error = 0.0f64;
        let mut all_fast = true;
        let mut cut = |axis: usize, value: f64| -> Result<Vec<Vec<Point3>>> {
            let plane = Plane::coordinate(axis, value)?;
            let section = sectioner.plane(&plane);
            all_fast &= axis != 0 || section.fast_path;
            for p in section.curves.iter().flat_map(|c| &c.points) {
                plane_error = plane_error.max((p[axis] - value).abs());
            }
            Ok(polylines(&section))
        };
        let mut stations = Vec::new();
        for i in 0..STATIONS {
            stations.extend(cut(0, grid.get(i, 0)[0])?);
        }
        let mut buttocks = Vec::new();
        for y in buttock_lines() {
            buttocks.extend(cut(1, y)?);
        }
        Ok(AircraftSections {
            stations,
            buttocks,
            plane_error,
            all_fast,
        })
    }

    /// The surface with its sections: mesh, picture, viewer.
    fn write_views(&self, out: &Output, surface: &LlSurface<3>, grid: &Grid<Point3>) -> Result<()> {
        let (nu, nv) = (141, 121);
        let (_, _, mesh) = sample_surface(surface, nu, nv);
        write_surface_obj(&out.file("aircraft-ll5.obj"), nu, nv, &mesh)?;
        let scene = Scene {
            title: "Aulchenko et al.: LL surface, L = 5, of the aircraft-like body (right half): \
                    15 sections x = const, 11 sections y = const",
            mesh: SceneMesh {
                rows: nu,
                cols: nv,
                points: &mesh,
            },
            curves: &[
                SceneCurves {
                    label: "x = 0, 1, ..., 14",
                    lines: &self.stations,
                    rgb: (20, 60, 200),
                    width: 1.6,
                },
                SceneCurves {
                    label: "y = 0.25, 0.75, ..., 5.25",
                    lines: &self.buttocks,
                    rgb: (200, 40, 30),
                    width: 1.6,
                },
            ],
            view: AIRCRAFT_VIEW,
        };
        write_scene_svg(&out.file("aircraft-ll5-view.svg"), &scene)?;
        write_viewer(
            out,
            "aircraft-ll5.html",
            "Aulchenko et al.: LL surface, L = 5, of the aircraft-like body, with its sections",
            (nu, nv),
            &mesh,
            Some(grid.clone()),
            vec![
                ("sections x = const", self.stations.clone()),
                ("sections y = const", self.buttocks.clone()),
            ],
        )?;
        write_scene_png(&out.file("aircraft-ll5-view.png"), &scene)?;
        Ok(())
    }

    /// The body plan: the x = const sections seen along x.
    fn write_body_plan(&self, out: &Output) -> Result<()> {
        let body_plan: Vec<Vec<Point2>> = self
            .stations
            .iter()
            .map(|s| s.iter().map(|p| Point2::new([p[1], p[2]])).collect())
            .collect();
        write_lines_svg(
            &out.file("aircraft-ll5-sections.svg"),
            &LinesPlot {
                title: "Aulchenko et al.: the 15 sections x = const (body plan, y-z)",
                axes: ("y", "z"),
                groups: &[LineGroup {
                    lines: &body_plan,
                    rgb: (20, 60, 200),
                    width: 1,
                }],
            },
        )?;
        Ok(())
    }
}

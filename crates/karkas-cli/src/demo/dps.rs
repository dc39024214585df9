//! Malozemov et al. (discrete periodic splines): the five-petal curve (s = 2, r = 2, m = 20, n = 16)
//! and the knotted tube (m1 = 2, n1 = 5, m2 = 3, n2 = 40), docs/methods.md §3.
//!
//! The paper prints only pictures, so the data are made here: the poles of the five-petal
//! curve are 20 samples of the (2, 5) torus-knot diagram (radius `1 + 0.7 cos 5t` at angle
//! `2t`: it winds twice around and crosses itself five times), and the tube's skeleton is cut
//! from a tube of radius 0.4 around a trefoil knot: the two curves along it run on either side
//! (offset horizontally, perpendicular to the knot), and the three rings across it are circles
//! through those two curves at `q = 0, 40, 80`.

use super::common::{write_viewer, Finding, Output};
use anyhow::Result;
use karkas::dps::{compatibility_residual, discrete_bspline, DiscreteSpline, TubeSurface};
use karkas::{Grid, Point2, Point3};
use karkas_io::obj::write_surface_obj;
use karkas_io::scene::{write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::svg::{write_discrete_curve_svg, write_lines_svg, DiscreteCurvePlot};
use karkas_io::svg::{LineGroup, LinesPlot};
use karkas_io::write::{write_atomic, write_discrete_curve_csv, write_indexed_grid_csv};
use std::f64::consts::TAU;

/// The five-petal curve: order, values per pole.
const PETAL_ORDER: usize = 2;
const PETAL_STEP: usize = 16;

/// The tube: curves along (m1) and across (m2), steps, orders.
const TUBE_M1: usize = 2;
const TUBE_N1: usize = 5;
const TUBE_M2: usize = 3;
const TUBE_N2: usize = 40;
const TUBE_ORDERS: (usize, usize) = (2, 2);
/// The radius of the tube the skeleton is cut from.
const TUBE_RADIUS: f64 = 0.4;

/// The 20 poles of the five-petal curve: the (2, 5) torus-knot diagram
/// `(1 + 0.7 cos 5t) (cos 2t, sin 2t)` at `t = 2 pi (l + 1/2) / 20` (the half step keeps the 20
/// poles distinct: at `t = 2 pi l / 20` the two windings would share five points).
pub fn five_petal_poles() -> Vec<Point2> {
    (0..20)
        .map(|l| {
            let t = TAU * (l as f64 + 0.5) / 20.0;
            let r = 1.0 + 0.7 * (5.0 * t).cos();
            Point2::new([r * (2.0 * t).cos(), r * (2.0 * t).sin()])
        })
        .collect()
}

/// The trefoil knot `(sin t + 2 sin 2t, cos t - 2 cos 2t, -sin 3t)` and its unit horizontal
/// normal `e_z x tangent / |e_z x tangent|`.
fn trefoil(t: f64) -> (Point3, Point3) {
    let point = Point3::new([
        t.sin() + 2.0 * (2.0 * t).sin(),
        t.cos() - 2.0 * (2.0 * t).cos(),
        -(3.0 * t).sin(),
    ]);
    let (dx, dy) = (
        t.cos() + 4.0 * (2.0 * t).cos(),
        -t.sin() + 4.0 * (2.0 * t).sin(),
    );
    let len = dx.hypot(dy);
    (point, Point3::new([-dy / len, dx / len, 0.0]))
}

/// The tube the skeleton is cut from, at `p` in `0..N1` around and `q` in `0..N2` along:
/// a circle of radius [`TUBE_RADIUS`] in the plane of the horizontal normal and the vertical.
fn knot_tube(p: usize, q: usize) -> Point3 {
    let (big_n1, big_n2) = (TUBE_M1 * TUBE_N1, TUBE_M2 * TUBE_N2);
    let (centre, normal) = trefoil(TAU * q as f64 / big_n2 as f64);
    let theta = TAU * p as f64 / big_n1 as f64;
    centre
        .add_scaled(TUBE_RADIUS * theta.cos(), normal)
        .add_scaled(TUBE_RADIUS * theta.sin(), Point3::new([0.0, 0.0, 1.0]))
}

/// The knotted tube's skeleton: `f_i(q)` (2 curves along, 120 samples) and `g_j(p)` (3 rings
/// across, 10 samples), compatible by construction.
pub fn knot_skeleton() -> (Grid<Point3>, Grid<Point3>) {
    let (big_n1, big_n2) = (TUBE_M1 * TUBE_N1, TUBE_M2 * TUBE_N2);
    let along = Grid::from_fn(TUBE_M1, big_n2, |i, q| knot_tube(i * TUBE_N1, q));
    let across = Grid::from_fn(TUBE_M2, big_n1, |j, p| knot_tube(p, j * TUBE_N2));
    (along, across)
}

pub fn five_petals(out: &Output) -> Result<Vec<Finding>> {
    let poles = five_petal_poles();
    let text: String = std::iter::once("x,y\n".to_owned())
        .chain(poles.iter().map(|p| format!("{},{}\n", p[0], p[1])))
        .collect();
    write_atomic(&out.file("five-petal-poles.csv"), |w| {
        w.write_all(text.as_bytes())
    })?;
    let spline = DiscreteSpline::from_poles(&poles, PETAL_ORDER, PETAL_STEP)?;
    let values = spline.to_values();
    write_discrete_curve_csv(&out.file("five-petal-r2.csv"), &values)?;
    let title =
        "Malozemov et al.'s fig. 1: 20 poles and the 320 values of the order-2 spline (n = 16)";
    write_discrete_curve_svg(
        &out.file("five-petal-poles.svg"),
        &DiscreteCurvePlot {
            title,
            values: &values,
            dots: true,
            input: &poles,
        },
    )?;
    write_discrete_curve_svg(
        &out.file("five-petal-r2.svg"),
        &DiscreteCurvePlot {
            title: "Malozemov et al.'s fig. 2: the five-petal curve (neighbouring values joined)",
            values: &values,
            dots: false,
            input: &poles,
        },
    )?;

    // The same 20 points as nodes: the interpolating spline passes through them.
    let through = DiscreteSpline::interpolating(&poles, PETAL_ORDER, PETAL_STEP)?;
    let through_values = through.to_values();
    write_discrete_curve_svg(
        &out.file("five-petal-interpolating.svg"),
        &DiscreteCurvePlot {
            title: "Malozemov et al.: the order-2 spline through the same 20 points (nodes)",
            values: &through_values,
            dots: false,
            input: &poles,
        },
    )?;
    let node_error = poles
        .iter()
        .enumerate()
        .map(|(l, z)| through_values[l * PETAL_STEP].distance(*z))
        .fold(0.0, f64::max);
    let q = discrete_bspline(poles.len(), PETAL_STEP, PETAL_ORDER)?;
    let big_n = q.len();
    let unity = (0..big_n)
        .map(|j| {
            let sum: f64 = (0..poles.len())
                .map(|p| q[(j + big_n - p * PETAL_STEP) % big_n])
                .sum();
            (sum - 1.0).abs()
        })
        .fold(0.0, f64::max);
    Ok(vec![
        Finding::new(
            "002 five-petal, 20 poles, r = 2",
            "self-intersections of the closed polyline",
            self_intersections(&values) as f64,
        ),
        Finding::new(
            "002 five-petal, 20 poles, r = 2",
            "max |sum_p Q_2(j - p n) - 1| (partition of unity)",
            unity,
        ),
        Finding::new(
            "002 five-petal, interpolating",
            "max |S_2(l n) - z(l)| at the 20 nodes",
            node_error,
        ),
    ])
}

/// The number of crossings of non-neighbouring edges of the closed polygon `points`.
fn self_intersections(points: &[Point2]) -> usize {
    let n = points.len();
    let edge = |k: usize| (points[k], points[(k + 1) % n]);
    let cross = |o: Point2, a: Point2, b: Point2| {
        (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0])
    };
    let mut count = 0;
    for a in 0..n {
        for b in a + 2..n {
            if a == 0 && b == n - 1 {
                continue; // neighbours across the seam
            }
            let ((p, q), (r, s)) = (edge(a), edge(b));
            let d1 = cross(p, q, r);
            let d2 = cross(p, q, s);
            let d3 = cross(r, s, p);
            let d4 = cross(r, s, q);
            if d1 * d2 < 0.0 && d3 * d4 < 0.0 {
                count += 1;
            }
        }
    }
    count
}

/// An axonometric camera: looking down at `ELEVATION` degrees from the azimuth `AZIMUTH`.
/// The same view as [`View`] with these angles, for the wireframe pictures.
struct Camera {
    right: Point3,
    up: Point3,
}

const AZIMUTH: f64 = -75.0;
const ELEVATION: f64 = 62.0;

impl Camera {
    fn new() -> Camera {
        let (az, el) = (AZIMUTH.to_radians(), ELEVATION.to_radians());
        let towards = Point3::new([az.cos(), az.sin(), 0.0]);
        let right = Point3::new([-az.sin(), az.cos(), 0.0]);
        let vertical = Point3::new([0.0, 0.0, 1.0]);
        Camera {
            right,
            up: vertical * el.cos() - towards * el.sin(),
        }
    }

    fn project(&self, p: Point3) -> Point2 {
        Point2::new([p.dot(self.right), p.dot(self.up)])
    }
}

pub fn knot(out: &Output) -> Result<Vec<Finding>> {
    let (along, across) = knot_skeleton();
    write_indexed_grid_csv(&out.file("knot-along.csv"), ["i", "q"], &along)?;
    write_indexed_grid_csv(&out.file("knot-across.csv"), ["j", "p"], &across)?;
    let (r1, r2) = TUBE_ORDERS;
    let tube = TubeSurface::new(&along, &across, TUBE_N1, TUBE_N2, r1, r2)?;
    let closed = tube.closed_grid();
    write_surface_obj(
        &out.file("knot-tube.obj"),
        closed.rows(),
        closed.cols(),
        closed.as_slice(),
    )?;
    write_viewer(
        out,
        "knot-tube.html",
        "Malozemov et al.: the knotted tube, 2 x 5 curves along, 3 x 40 rings across",
        (closed.rows(), closed.cols()),
        closed.as_slice(),
        None,
        Vec::new(),
    )?;
    let pictures = KnotPictures::new(&along, &across);
    pictures.skeleton(out)?;
    pictures.wireframe(out, &tube)?;
    pictures.scene(out, &closed)?;
    knot_findings(&tube, &along, &across)
}

/// A closed polyline through `points`: the first point again at the end.
fn closed_line(points: &[Point3]) -> Vec<Point3> {
    points.iter().chain(points.first()).copied().collect()
}

const RED: (u8, u8, u8) = (200, 30, 30);
const BLUE: (u8, u8, u8) = (20, 60, 200);

/// The knot's skeleton as closed lines in space and seen by the pictures' camera.
struct KnotPictures {
    camera: Camera,
    along_3d: Vec<Vec<Point3>>,
    across_3d: Vec<Vec<Point3>>,
    along_lines: Vec<Vec<Point2>>,
    across_lines: Vec<Vec<Point2>>,
    axes: (String, String),
}

impl KnotPictures {
    fn new(along: &Grid<Point3>, across: &Grid<Point3>) -> Self {
        let camera = Camera::new();
        let along_3d: Vec<Vec<Point3>> = (0..along.rows())
            .map(|i| closed_line(along.row(i)))
            .collect();
        let across_3d: Vec<Vec<Point3>> = (0..across.rows())
            .map(|j| closed_line(across.row(j)))
            .collect();
        let (along_lines, across_lines) = (
            project_lines(&camera, &along_3d),
            project_lines(&camera, &across_3d),
        );
        let axes = View {
            azimuth: AZIMUTH,
            elevation: ELEVATION,
        }
        .axis_names();
        KnotPictures {
            camera,
            along_3d,
            across_3d,
            along_lines,
            across_lines,
            axes,
        }
    }

    fn skeleton_groups(&self, width: u32) -> [LineGroup<'_>; 2] {
        [
            LineGroup {
                lines: &self.along_lines,
                rgb: RED,
                width,
            },
            LineGroup {
                lines: &self.across_lines,
                rgb: BLUE,
                width,
            },
        ]
    }

    fn skeleton(&self, out: &Output) -> Result<()> {
        write_lines_svg(
            &out.file("knot-skeleton.svg"),
            &LinesPlot {
                title:
                    "Malozemov et al.'s fig. 3: the skeleton, 2 curves along (red) and 3 across (blue)",
                axes: (&self.axes.0, &self.axes.1),
                groups: &self.skeleton_groups(2),
            },
        )?;
        Ok(())
    }

    /// The tube's lines of constant `p` and `q` behind the skeleton in bold.
    fn wireframe(&self, out: &Output, tube: &TubeSurface<3>) -> Result<()> {
        let (big_n1, big_n2) = tube.periods();
        let values = tube.values();
        let p_lines: Vec<Vec<Point3>> = (0..big_n1).map(|p| closed_line(values.row(p))).collect();
        let q_lines: Vec<Vec<Point3>> = (0..big_n2)
            .map(|q| {
                let ring: Vec<Point3> = (0..big_n1).map(|p| *values.get(p, q)).collect();
                closed_line(&ring)
            })
            .collect();
        let [bold_along, bold_across] = self.skeleton_groups(3);
        write_lines_svg(
            &out.file("knot-tube-wireframe.svg"),
            &LinesPlot {
                title:
                    "Malozemov et al.: the knotted tube by formula (3), wireframe, skeleton in bold",
                axes: (&self.axes.0, &self.axes.1),
                groups: &[
                    LineGroup {
                        lines: &project_lines(&self.camera, &q_lines),
                        rgb: (170, 170, 170),
                        width: 1,
                    },
                    LineGroup {
                        lines: &project_lines(&self.camera, &p_lines),
                        rgb: (110, 110, 110),
                        width: 1,
                    },
                    bold_along,
                    bold_across,
                ],
            },
        )?;
        Ok(())
    }

    fn scene(&self, out: &Output, closed: &Grid<Point3>) -> Result<()> {
        let skeleton = [
            SceneCurves {
                label: "curves along",
                lines: &self.along_3d,
                rgb: RED,
                width: 3.0,
            },
            SceneCurves {
                label: "curves across",
                lines: &self.across_3d,
                rgb: BLUE,
                width: 3.0,
            },
        ];
        write_scene_svg(
            &out.file("knot-tube.svg"),
            &Scene {
                title:
                    "Malozemov et al.'s fig. 4: the knotted tube by formula (3), skeleton in bold",
                mesh: SceneMesh {
                    rows: closed.rows(),
                    cols: closed.cols(),
                    points: closed.as_slice(),
                },
                curves: &skeleton,
                view: View {
                    azimuth: AZIMUTH,
                    elevation: ELEVATION,
                },
            },
        )?;
        Ok(())
    }
}

fn project_lines(camera: &Camera, lines: &[Vec<Point3>]) -> Vec<Vec<Point2>> {
    lines
        .iter()
        .map(|l| l.iter().map(|&p| camera.project(p)).collect())
        .collect()
}

/// The skeleton's compatibility and how closely the tube passes through its curves
/// (condition 2).
fn knot_findings(
    tube: &TubeSurface<3>,
    along: &Grid<Point3>,
    across: &Grid<Point3>,
) -> Result<Vec<Finding>> {
    let (big_n1, big_n2) = tube.periods();
    let along_error = (0..TUBE_M1)
        .flat_map(|i| (0..big_n2).map(move |q| (i, q)))
        .map(|(i, q)| tube.value(i * TUBE_N1, q).distance(*along.get(i, q)))
        .fold(0.0, f64::max);
    let across_error = (0..TUBE_M2)
        .flat_map(|j| (0..big_n1).map(move |p| (j, p)))
        .map(|(j, p)| tube.value(p, j * TUBE_N2).distance(*across.get(j, p)))
        .fold(0.0, f64::max);
    Ok(vec![
        Finding::new(
            "002 knotted tube, 2 x 5 by 3 x 40",
            "skeleton max |f_i(j n2) - g_j(i n1)|",
            compatibility_residual(along, across, TUBE_N1, TUBE_N2)?,
        ),
        Finding::new(
            "002 knotted tube, 2 x 5 by 3 x 40",
            "max |c(i n1, q) - f_i(q)| (condition 2)",
            along_error,
        ),
        Finding::new(
            "002 knotted tube, 2 x 5 by 3 x 40",
            "max |c(p, j n2) - g_j(p)| (condition 2)",
            across_error,
        ),
    ])
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Point;

    #[test]
    fn five_petal_poles_are_distinct_and_symmetric() {
        let poles = five_petal_poles();
        assert_eq!(poles.len(), 20);
        for (a, p) in poles.iter().enumerate() {
            assert!(poles[..a].iter().all(|q| q.distance(*p) > 0.1));
        }
        // Four poles on: rotated by 144 degrees (the curve's five-fold symmetry).
        let (c, s) = (144f64.to_radians().cos(), 144f64.to_radians().sin());
        for l in 0..20 {
            let p = poles[l];
            let rotated = Point([c * p[0] - s * p[1], s * p[0] + c * p[1]]);
            assert!(rotated.distance(poles[(l + 4) % 20]) < 1e-12);
        }
    }

    #[test]
    fn knot_skeleton_is_compatible() {
        let (along, across) = knot_skeleton();
        assert_eq!((along.rows(), along.cols()), (2, 120));
        assert_eq!((across.rows(), across.cols()), (3, 10));
        assert_eq!(compatibility_residual(&along, &across, 5, 40).unwrap(), 0.0);
    }

    #[test]
    fn polygon_crossings_are_counted() {
        // A bow tie crosses itself once; a square never.
        let bow = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]].map(Point);
        assert_eq!(self_intersections(&bow), 1);
        let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]].map(Point);
        assert_eq!(self_intersections(&square), 0);
    }
}

//! Re-laying grids along lines of curvature (Kuznetsov and Filatov, Theorem 2.1): frames of a
//! cylinder and a hyperboloid turned away from the lines of curvature come back to them, and
//! their interpolants' errors against the exact surfaces fall to those of the principal
//! frames; planes and spheres are refused as umbilic.

use karkas::implicit::{trace_net, Cylinder, Hyperboloid, ImplicitSurface, NetDirections, NetSpec};
use karkas::measure::hausdorff_surface_implicit;
use karkas::param::{relay_grid, BicubicSurface, GridParameterization, RelayOptions};
use karkas::{Error, Grid, Point3};
use std::f64::consts::{PI, TAU};

/// The surfaces of revolution about `z` of the paper: `rho(z)` is the radius at height `z`.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Revolution {
    /// `x^2 + y^2 = 1`.
    Cylinder,
    /// `x^2 + y^2 - z^2 = 1`.
    Hyperboloid,
}

impl Revolution {
    fn rho(self, z: f64) -> f64 {
        match self {
            Revolution::Cylinder => 1.0,
            Revolution::Hyperboloid => (1.0 + z * z).sqrt(),
        }
    }

    fn frame(self, directions: NetDirections, closed: bool) -> Grid<Point3> {
        self.frame_and_error(directions, closed).0
    }

    /// A 5 x 9 frame traced on the exact surface (the demo's layout) and the Hausdorff error
    /// of its interpolant against the exact patch it covers (the same net traced 4 times
    /// denser), as the demo measures it.
    fn frame_and_error(self, directions: NetDirections, closed: bool) -> (Grid<Point3>, f64) {
        self.frame_sized(directions, closed, 1)
    }

    /// As [`frame_and_error`] with `refine` times as many node steps each way (4 `refine` + 1
    /// by 8 `refine` + 1 nodes, steps divided by `refine`).
    fn frame_sized(
        self,
        directions: NetDirections,
        closed: bool,
        refine: usize,
    ) -> (Grid<Point3>, f64) {
        let (start, u_step) = match self {
            Revolution::Cylinder => (Point3::new([1.0, 0.0, 0.0]), 0.5),
            Revolution::Hyperboloid => (Point3::new([1.25f64.sqrt(), 0.0, -0.5]), 0.2714),
        };
        let r = refine as f64;
        let mut spec = NetSpec::new(
            start,
            directions,
            (4 * refine + 1, 8 * refine + 1),
            (u_step / r, TAU / 8.0 / r),
        );
        spec.closed_v = closed;
        let mut dense = spec;
        dense.nodes = (16 * refine + 1, 32 * refine + 1);
        dense.steps = (spec.steps.0 / 4.0, spec.steps.1 / 4.0);
        let nodes = match self {
            Revolution::Cylinder => trace_net(&Cylinder { radius: 1.0 }, &spec),
            Revolution::Hyperboloid => trace_net(&Hyperboloid { neck_radius: 1.0 }, &spec),
        }
        .unwrap();
        let surface =
            BicubicSurface::new(&nodes, GridParameterization::default(), false, false).unwrap();
        let error = match self {
            Revolution::Cylinder => {
                let c = Cylinder { radius: 1.0 };
                let patch = trace_net(&c, &dense).unwrap();
                hausdorff_surface_implicit(&surface, &c, patch.as_slice(), (64, 160))
            }
            Revolution::Hyperboloid => {
                let h = Hyperboloid { neck_radius: 1.0 };
                let patch = trace_net(&h, &dense).unwrap();
                hausdorff_surface_implicit(&surface, &h, patch.as_slice(), (64, 160))
            }
        };
        (nodes, error.unwrap().distance)
    }

    /// The two-sided Hausdorff error of the bicubic interpolant (the paper's chord
    /// parameters through node (0, 0)) of `nodes` against the exact patch between the node
    /// grid's first and last rows and columns: the angles and heights of the rows (circles)
    /// and columns (meridians) of a principal grid, sampled in closed form.
    fn error(self, relaid: &Grid<Point3>) -> f64 {
        let surface =
            BicubicSurface::new(relaid, GridParameterization::default(), false, false).unwrap();
        // The rows are the circles when they keep their heights better than the columns.
        let height_spread = |g: &Grid<Point3>| {
            (0..g.rows())
                .map(|i| {
                    let zs = g.row(i).iter().map(|p| p[2]);
                    let (lo, hi) = zs.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), z| {
                        (lo.min(z), hi.max(z))
                    });
                    hi - lo
                })
                .fold(0.0, f64::max)
        };
        let transposed = relaid.transposed();
        let nodes = if height_spread(relaid) <= height_spread(&transposed) {
            relaid
        } else {
            &transposed
        };
        let (m, n) = (nodes.rows(), nodes.cols());
        let base = nodes.get(m / 2, n / 2);
        let base_angle = base[1].atan2(base[0]);
        let angle = |p: &Point3| {
            let a = p[1].atan2(p[0]) - base_angle;
            a - TAU * ((a + PI) / TAU).floor()
        };
        let column_angle =
            |j: usize| (0..m).map(|i| angle(nodes.get(i, j))).sum::<f64>() / m as f64;
        let row_height = |i: usize| (0..n).map(|j| nodes.get(i, j)[2]).sum::<f64>() / n as f64;
        let (a0, a1) = (column_angle(0), column_angle(n - 1));
        let (z0, z1) = (row_height(0), row_height(m - 1));
        let (pu, pv) = (4 * (m - 1) + 1, 4 * (n - 1) + 1);
        let mut patch = Vec::with_capacity(pu * pv);
        for a in 0..pu {
            let z = z0 + (z1 - z0) * a as f64 / (pu - 1) as f64;
            for b in 0..pv {
                let t = base_angle + a0 + (a1 - a0) * b as f64 / (pv - 1) as f64;
                let r = self.rho(z);
                patch.push(Point3::new([r * t.cos(), r * t.sin(), z]));
            }
        }
        let h = match self {
            Revolution::Cylinder => {
                hausdorff_surface_implicit(&surface, &Cylinder { radius: 1.0 }, &patch, (64, 160))
            }
            Revolution::Hyperboloid => hausdorff_surface_implicit(
                &surface,
                &Hyperboloid { neck_radius: 1.0 },
                &patch,
                (64, 160),
            ),
        };
        h.unwrap().distance
    }

    fn implicit_value(self, p: Point3) -> f64 {
        match self {
            Revolution::Cylinder => Cylinder { radius: 1.0 }.value(p),
            Revolution::Hyperboloid => Hyperboloid { neck_radius: 1.0 }.value(p),
        }
    }
}

/// The frame of plane sections turned by `degrees` (the demo's turned cylinder frames:
/// ellipses in planes normal to `(0, -sin a, cos a)` and their orthogonal trajectories).
fn plane_sections(degrees: f64) -> NetDirections {
    let a = degrees.to_radians();
    NetDirections::PlaneSections {
        plane_normal: Point3::new([0.0, -a.sin(), a.cos()]),
    }
}

/// How far the rows of `nodes` are from circles `z = const` about the axis and the columns
/// from meridians `angle = const` (or the other way round, whichever fits better): the
/// largest spread of a line's heights and of the other lines' angles (times the radius).
fn spread_from_principal(nodes: &Grid<Point3>) -> (f64, f64) {
    let (a, b) = spread_rows_circles(nodes);
    let (c, d) = spread_rows_circles(&nodes.transposed());
    if a.max(b) <= c.max(d) {
        (a, b)
    } else {
        (c, d)
    }
}

fn spread_rows_circles(nodes: &Grid<Point3>) -> (f64, f64) {
    let (m, n) = (nodes.rows(), nodes.cols());
    let mut rows: f64 = 0.0;
    for i in 0..m {
        let zs: Vec<f64> = (0..n).map(|j| nodes.get(i, j)[2]).collect();
        let lo = zs.iter().cloned().fold(f64::INFINITY, f64::min);
        let hi = zs.iter().cloned().fold(f64::NEG_INFINITY, f64::max);
        rows = rows.max(hi - lo);
    }
    let mut cols: f64 = 0.0;
    for j in 0..n {
        let base = nodes.get(0, j);
        let a0 = base[1].atan2(base[0]);
        for i in 1..m {
            let p = nodes.get(i, j);
            let r = p[0].hypot(p[1]);
            let mut d = p[1].atan2(p[0]) - a0;
            d -= TAU * ((d + PI) / TAU).floor();
            cols = cols.max((d * r).abs());
        }
    }
    (rows, cols)
}

#[test]
fn turned_cylinder_frames_come_back_to_axial_lines_and_circles() {
    let principal =
        Revolution::Cylinder.error(&Revolution::Cylinder.frame(NetDirections::Principal, true));
    for degrees in [30.0, 45.0] {
        let (turned, turned_error) =
            Revolution::Cylinder.frame_and_error(plane_sections(degrees), true);
        // The frame's ellipses are closed (the 9th node repeats the first).
        let options = RelayOptions {
            closed: (false, true),
            ..RelayOptions::default()
        };
        let relaid = relay_grid(&turned, &options).unwrap();
        assert_eq!((relaid.nodes.rows(), relaid.nodes.cols()), (5, 9));
        let (rows, cols) = spread_from_principal(&relaid.nodes);
        let error = Revolution::Cylinder.error(&relaid.nodes);
        eprintln!(
            "cylinder {degrees}: turned {turned_error:.4}, relaid {error:.4}, principal {principal:.4}, spreads {rows:.2e} {cols:.2e}, steps {:?}",
            relaid.steps
        );
        // The turned frame's rows are ellipses climbing tan(a) >= 0.57 over a half turn; the
        // re-laid rows are circles and the columns axial lines to the accuracy of the 5 x 9
        // interpolant's curvature (its nodes are on the interpolant, which is off the cylinder by
        // up to 0.02 there): its error stays that of the turned frame's interpolant.
        assert!(
            rows < 0.1 && cols < 0.15,
            "{degrees} deg: rows {rows:e}, columns {cols:e}"
        );
        assert!(
            error <= 1.2 * turned_error,
            "{degrees} deg: {error} vs {turned_error}"
        );
    }
}

#[test]
fn turned_hyperboloid_frames_come_back_to_meridians_and_circles() {
    let h = Revolution::Hyperboloid;
    let principal = h.error(&h.frame(NetDirections::Principal, true));
    for degrees in [30.0f64, 45.0] {
        let (turned, turned_error) = h.frame_and_error(
            NetDirections::Turned {
                angle: degrees.to_radians(),
            },
            false,
        );
        let relaid = relay_grid(&turned, &RelayOptions::default()).unwrap();
        let (rows, cols) = spread_from_principal(&relaid.nodes);
        let error = h.error(&relaid.nodes);
        let off = relaid
            .nodes
            .as_slice()
            .iter()
            .map(|&p| h.implicit_value(p).abs())
            .fold(0.0, f64::max);
        eprintln!(
            "hyperboloid {degrees}: turned {turned_error:.4}, relaid {error:.4}, principal {principal:.4}, spreads {rows:.2e} {cols:.2e}, off {off:.2e}, steps {:?}",
            relaid.steps
        );
        assert!(
            off < 1e-2,
            "{degrees} deg: a node is {off:e} off the hyperboloid"
        );
        assert!(
            rows < 2.5e-2 && cols < 2.5e-2,
            "{degrees} deg: rows {rows:e}, columns {cols:e}"
        );
        // The re-laid frame's error stays within twice the principal frame's (1.6 times at 30
        // degrees): its nodes lie on the turned frame's interpolant.
        assert!(
            error <= 2.0 * principal,
            "{degrees} deg: {error} vs {principal}"
        );
    }
}

#[test]
fn dense_turned_cylinder_frames_are_relaid_along_axial_lines_and_circles() {
    let c = Revolution::Cylinder;
    let (_, principal) = c.frame_sized(NetDirections::Principal, true, 3);
    for degrees in [30.0, 45.0] {
        let (turned, turned_error) = c.frame_sized(plane_sections(degrees), true, 3);
        let options = RelayOptions {
            closed: (false, true),
            ..RelayOptions::default()
        };
        let relaid = relay_grid(&turned, &options).unwrap();
        let (rows, cols) = spread_from_principal(&relaid.nodes);
        let error = c.error(&relaid.nodes);
        eprintln!(
            "dense cylinder {degrees}: turned {turned_error:.2e}, relaid {error:.2e}, principal {principal:.2e}, spreads {rows:.2e} {cols:.2e}, steps {:?}",
            relaid.steps
        );
        // To the accuracy of the interpolant's curvature: lines of the exact cylinder.
        assert!(
            rows < 3e-3 && cols < 3e-3,
            "{degrees} deg: rows {rows:e}, columns {cols:e}"
        );
        assert!(
            error <= 2.0 * turned_error,
            "{degrees} deg: {error} vs {turned_error}"
        );
    }
}

#[test]
fn planes_and_spheres_are_refused_as_umbilic() {
    let plane = Grid::from_fn(5, 7, |i, j| {
        let (x, y) = (i as f64 * 0.3, j as f64 * 0.2);
        Point3::new([x, y, 0.5 * x - 0.25 * y + 1.0])
    });
    let sphere = Grid::from_fn(7, 9, |i, j| {
        let (lat, lon) = (-0.6 + 0.2 * i as f64, -0.8 + 0.2 * j as f64);
        Point3::new([
            2.0 * lat.cos() * lon.cos(),
            2.0 * lat.cos() * lon.sin(),
            2.0 * lat.sin(),
        ])
    });
    for (name, grid) in [("plane", plane), ("sphere", sphere)] {
        match relay_grid(&grid, &RelayOptions::default()) {
            Err(Error::UmbilicRegion { k1, k2, .. }) => {
                assert!(
                    (k1 - k2).abs() <= 0.1 * k1.abs().max(k2.abs()).max(0.1),
                    "{name}"
                );
            }
            other => panic!("{name}: {other:?}"),
        }
    }
}

#[test]
fn bad_options_are_refused() {
    let frame = Revolution::Hyperboloid.frame(NetDirections::Principal, false);
    let outside = RelayOptions {
        start: Some((5, 0)),
        ..RelayOptions::default()
    };
    assert!(matches!(
        relay_grid(&frame, &outside),
        Err(Error::OutsideGrid { row: 5, .. })
    ));
    let tiny = RelayOptions {
        size: Some((1, 9)),
        ..RelayOptions::default()
    };
    assert!(matches!(
        relay_grid(&frame, &tiny),
        Err(Error::InvalidGridSize { rows: 1, .. })
    ));
    // A size that would not fit in memory is refused before any allocation.
    let huge = RelayOptions {
        size: Some((usize::MAX / 2, 3)),
        ..RelayOptions::default()
    };
    assert!(matches!(
        relay_grid(&frame, &huge),
        Err(Error::InvalidSetting { name: "size", .. })
    ));
    let negative = RelayOptions {
        steps: Some((-0.1, 0.1)),
        ..RelayOptions::default()
    };
    assert!(matches!(
        relay_grid(&frame, &negative),
        Err(Error::InvalidSetting { .. })
    ));
    // Steps too long for the patch: the net does not fit and says where.
    let long = RelayOptions {
        steps: Some((5.0, 5.0)),
        ..RelayOptions::default()
    };
    assert!(matches!(
        relay_grid(&frame, &long),
        Err(Error::ContinuationFailed { .. })
    ));
}

#[test]
fn a_principal_frame_is_relaid_onto_itself() {
    // The cylinder's closed frame of generators and circles: re-laid from its centre, the
    // circles closed, the nodes come back to the input's (to the interpolant's accuracy).
    let frame = Revolution::Cylinder.frame(NetDirections::Principal, true);
    let options = RelayOptions {
        closed: (false, true),
        ..RelayOptions::default()
    };
    let relaid = relay_grid(&frame, &options).unwrap();
    let nodes = &relaid.nodes;
    assert_eq!((nodes.rows(), nodes.cols()), (5, 9));
    let worst = nodes
        .as_slice()
        .iter()
        .zip(frame.as_slice())
        .map(|(a, b)| a.distance(*b))
        .fold(0.0, f64::max);
    assert!(worst < 1e-3, "worst node moved by {worst}");
    assert!((relaid.steps.0 - 0.5).abs() < 1e-3 && (relaid.steps.1 - TAU / 8.0).abs() < 1e-3);
}

/// Kuznetsov and Filatov's claim (Theorem 2.1) on a surface known densely: a turned cylinder
/// frame twice as dense and three times as long along `u` as the demo's (25 x 17 nodes,
/// closed ellipses) re-laid onto 5 x 9 nodes with the principal frame's steps (0.5, pi/4),
/// shrunk until the net fits, interpolates the cylinder as well as the principal 5 x 9 frame
/// of the same steps (nodes in closed form), while the 5 x 9 turned frame stays 3 to 7 times
/// worse.
#[test]
fn a_dense_turned_cylinder_frame_relaid_onto_5_by_9_matches_the_principal_frame() {
    let c = Revolution::Cylinder;
    let principal_5x9 = c.error(&c.frame(NetDirections::Principal, true));
    for degrees in [30.0, 45.0] {
        let (_, turned_error) = c.frame_and_error(plane_sections(degrees), true);
        let mut spec = NetSpec::new(
            Point3::new([1.0, 0.0, 0.0]),
            plane_sections(degrees),
            (25, 17),
            (0.25, TAU / 16.0),
        );
        spec.closed_v = true;
        let dense = trace_net(&Cylinder { radius: 1.0 }, &spec).unwrap();
        let relaid = [1.0, 0.95, 0.9, 0.8]
            .iter()
            .find_map(|f| {
                let options = RelayOptions {
                    size: Some((5, 9)),
                    steps: Some((0.5 * f, TAU / 8.0 * f)),
                    closed: (false, true),
                    ..RelayOptions::default()
                };
                relay_grid(&dense, &options).ok()
            })
            .expect("a net of the principal frame's size fits the dense frame");
        let (hu, hv) = relaid.steps;
        let principal = Grid::from_fn(5, 9, |i, j| {
            let t = j as f64 * hv;
            Point3::new([t.cos(), t.sin(), i as f64 * hu])
        });
        let principal_error = c.error(&principal);
        let error = c.error(&relaid.nodes);
        eprintln!(
            "dense cylinder {degrees} to 5 x 9: turned {turned_error:.4}, relaid {error:.4}, principal of the same steps {principal_error:.4}, principal {principal_5x9:.4}, steps {:?}",
            relaid.steps
        );
        assert!(hu >= 0.4 && hv >= 0.6, "{degrees} deg: steps {hu} {hv}");
        assert!(
            error <= 1.5 * principal_error && error <= 1.5 * principal_5x9,
            "{degrees} deg: {error} vs {principal_error}, {principal_5x9}"
        );
        assert!(
            error < 0.5 * turned_error,
            "{degrees} deg: {error} vs {turned_error}"
        );
    }
}

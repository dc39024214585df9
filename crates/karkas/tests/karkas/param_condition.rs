//! The condition measure of a parameterization (Kuznetsov and Filatov, (2.3)–(2.4) and
//! Theorem 2.1, extended to tangents of any length): closed forms on planes and the paper's
//! cylinder frames.

use karkas::implicit::{trace_net, Cylinder, NetDirections, NetSpec};
use karkas::param::{condition_measure, BicubicSurface, ConditionSummary, GridParameterization};
use karkas::{Grid, Point3};
use std::f64::consts::TAU;

/// A unit vector of the plane spanned by `a`, `b` (orthonormal) at `angle` from `a`.
fn turned(a: Point3, b: Point3, angle: f64) -> Point3 {
    a * angle.cos() + b * angle.sin()
}

/// An orthonormal pair spanning a tilted plane (neither axis a coordinate axis).
fn tilted_plane() -> (Point3, Point3) {
    let a = Point3::new([2.0, 1.0, 2.0]) * (1.0 / 3.0);
    let b = Point3::new([-1.0, 2.0, 0.0]) * (1.0 / 5f64.sqrt());
    (a, b)
}

/// The grid `origin + x_i a + y_j b` with uneven steps.
fn plane_grid(a: Point3, b: Point3) -> Grid<Point3> {
    let xs = [0.0, 0.7, 1.1, 2.0, 2.6];
    let ys = [0.0, 0.4, 1.3, 1.7, 2.9, 3.2];
    let origin = Point3::new([0.3, -1.0, 2.0]);
    Grid::from_fn(xs.len(), ys.len(), |i, j| origin + a * xs[i] + b * ys[j])
}

#[test]
fn arc_length_along_orthogonal_lines_gives_one() {
    // Theorem 2.1: chord lengths along straight orthogonal grid lines are arc lengths, so every
    // node has W_u, W_v orthonormal and the best conditioning.
    let (a, b) = tilted_plane();
    let s = BicubicSurface::new(
        &plane_grid(a, b),
        GridParameterization::default(),
        false,
        false,
    )
    .unwrap();
    let m = s.condition_measures();
    assert_eq!((m.rows(), m.cols()), (5, 6));
    for &x in m.as_slice() {
        assert!((x - 1.0).abs() < 1e-13, "{x}");
    }
    let summary = s.condition_summary();
    assert_eq!(summary.nodes, 30);
    assert!((summary.min - 1.0).abs() < 1e-13 && (summary.mean - 1.0).abs() < 1e-13);
}

#[test]
fn a_skewed_grid_gives_tan_of_half_the_angle() {
    // Unit tangents at an angle theta: the first fundamental form [[1, c], [c, 1]] has
    // eigenvalues 1 +- cos(theta), so the measure is sqrt((1 - c) / (1 + c)) = tan(theta / 2).
    let (a, b) = tilted_plane();
    for deg in [30.0f64, 45.0, 60.0, 75.0] {
        let theta = deg.to_radians();
        let grid = plane_grid(a, turned(a, b, theta));
        let s = BicubicSurface::new(&grid, GridParameterization::default(), false, false).unwrap();
        let expected = (theta / 2.0).tan();
        for &x in s.condition_measures().as_slice() {
            assert!((x - expected).abs() < 1e-13, "{deg} deg: {x} vs {expected}");
        }
        assert!(s.condition_summary().min < 1.0);
    }
}

#[test]
fn a_stretched_parameter_gives_the_ratio_of_lengths() {
    // Uniform parameters on rows 2.5 apart and columns 0.8 apart: W_u = 2.5 a, W_v = 0.8 b,
    // singular values 2.5 and 0.8, measure min(1, 0.8) / max(1, 2.5) = 0.32.
    let (a, b) = tilted_plane();
    let grid = Grid::from_fn(4, 5, |i, j| a * (2.5 * i as f64) + b * (0.8 * j as f64));
    let s = BicubicSurface::new(&grid, GridParameterization::Uniform, false, false).unwrap();
    for &x in s.condition_measures().as_slice() {
        assert!((x - 0.32).abs() < 1e-13, "{x}");
    }
    // The same node values through the free function.
    assert!((condition_measure(a * 2.5, b * 0.8) - 0.32).abs() < 1e-15);
    // Chord parameters undo the stretch.
    let s = BicubicSurface::new(&grid, GridParameterization::default(), false, false).unwrap();
    assert!((s.condition_summary().min - 1.0).abs() < 1e-13);
}

#[test]
fn the_worst_node_is_found_and_a_closed_seam_counts_once() {
    // Rows at x = 0, 1, 2, 5 with uniform parameters: the not-a-knot spline of x is the cubic
    // x(t) = t + t (t - 1) (t - 2) / 3, x'(t) = 5/3, 2/3, 5/3, 14/3 at the nodes; columns 1
    // apart give W_v = e_y. Measures min(1, s_2) / max(1, s_1): 3/5, 2/3, 3/5, 3/14.
    let xs = [0.0, 1.0, 2.0, 5.0];
    let grid = Grid::from_fn(4, 3, |i, j| Point3::new([xs[i], j as f64, 0.0]));
    let s = BicubicSurface::new(&grid, GridParameterization::Uniform, false, false).unwrap();
    let summary = s.condition_summary();
    assert_eq!(summary.worst, (3, 0), "{summary:?}");
    assert!((summary.min - 3.0 / 14.0).abs() < 1e-14, "{summary:?}");
    let mean = (0.6 + 2.0 / 3.0 + 0.6 + 3.0 / 14.0) / 4.0;
    assert!((summary.mean - mean).abs() < 1e-14, "{summary:?}");
    // A ring of 8 points per row, closed in v: 8 distinct columns, not 9.
    let ring = Grid::from_fn(3, 8, |i, j| {
        let t = TAU * j as f64 / 8.0;
        Point3::new([t.cos(), t.sin(), 0.5 * i as f64])
    });
    let s = BicubicSurface::new(&ring, GridParameterization::default(), false, true).unwrap();
    assert_eq!(s.condition_measures().cols(), 9);
    assert_eq!(s.condition_summary().nodes, 24);
}

/// The summary of the cylinder's 5 x 9 frame along `directions` (the paper's example 3.1:
/// chord parameters through node (0, 0), open not-a-knot ends, the 9th node on the first).
fn cylinder_frame(directions: NetDirections, u_step: f64) -> ConditionSummary {
    let mut spec = NetSpec::new(
        Point3::new([1.0, 0.0, 0.0]),
        directions,
        (5, 9),
        (u_step, TAU / 8.0),
    );
    spec.closed_v = true;
    let nodes = trace_net(&Cylinder { radius: 1.0 }, &spec).unwrap();
    BicubicSurface::new(&nodes, GridParameterization::default(), false, false)
        .unwrap()
        .condition_summary()
}

#[test]
fn the_principal_cylinder_frame_scores_better_than_turned_ones() {
    let principal = cylinder_frame(NetDirections::Principal, 0.5);
    // Generators and circles: orthogonal; |W_u| = 1 and |W_v| = arc / chord of 45 degrees,
    // (pi / 8) / sin(pi / 8) at every node, up to the spline's slope error.
    let chord_ratio = (TAU / 16.0) / (TAU / 16.0).sin();
    assert!(
        (principal.mean - 1.0 / chord_ratio).abs() < 0.02 && principal.min > 0.9,
        "{principal:?}"
    );
    for deg in [30.0f64, 45.0] {
        let a = deg.to_radians();
        let both = cylinder_frame(
            NetDirections::PlaneSections {
                plane_normal: Point3::new([0.0, -a.sin(), a.cos()]),
            },
            0.5,
        );
        let one = cylinder_frame(NetDirections::TurnedU { angle: a }, 0.5 / a.cos());
        for (what, turned) in [("both families", both), ("the generator", one)] {
            assert!(
                turned.min < principal.min && turned.mean < principal.mean,
                "{what} turned {deg} deg: {turned:?} vs principal {principal:?}"
            );
        }
        // One family turned by a: the tangents meet at 90 - a degrees, so the measure is
        // about tan((90 - a) / 2) (the circles' chord stretch aside).
        let skew = ((90.0 - deg).to_radians() / 2.0).tan();
        assert!(one.mean < skew * 1.01 && one.mean > skew * 0.9, "{one:?}");
    }
}

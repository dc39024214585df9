//! Grids of nodes on nets of lines traced over an implicit surface by continuation (Kuznetsov and Filatov,
//! section 2 and the experiments of section 3; docs/methods.md §5).
//!
//! By Theorem 2.1 the best parameters of `F = 0` are arc lengths along two orthogonal
//! directions, and the paper takes the principal directions: the node grid is then a net of
//! lines of curvature spaced by arc length. A line is traced from a node as the solution of
//! `dx/ds = d(x)` for a unit tangent field `d` (a principal direction, or one turned by an
//! angle): each node step of arc length `h` is split into [`NetSpec::substeps`] classical
//! Runge–Kutta steps (the predictor), each followed by Newton's projection back onto
//! `F = 0` (the corrector). The field's sign and, at crossings of the two families or at
//! umbilics, its branch are chosen to continue the previous direction.
//!
//! The net: the spine is the `u` line from the start point (`nu` nodes, `r_{i,0}`); from
//! every spine node the `v` line is traced (`nv` nodes, row `i` of the grid). A `v` line can
//! be closed ([`NetSpec::closed_v`]): its length is measured by tracing it once around, and
//! its `nv` nodes are spaced evenly with the last equal to the first. Cost:
//! `O(nu nv substeps)` frame evaluations.

use super::frame::{cross, project_onto, SurfaceFrame};
use super::surface::ImplicitSurface;
use crate::core::Grid;
use crate::{Error, Point3, Result};

/// Which two tangent direction fields the net follows.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum NetDirections {
    /// Lines of curvature: `u` lines along the first principal direction (curvature `k_1`),
    /// `v` lines along the second.
    Principal,
    /// Both families turned by `angle` (radians) about the normal: an orthogonal net at a
    /// constant angle to the lines of curvature.
    Turned {
        /// The angle, radians.
        angle: f64,
    },
    /// Only the `u` family turned by `angle` (radians); the `v` lines stay lines of
    /// curvature (a net that is not orthogonal).
    TurnedU {
        /// The angle, radians.
        angle: f64,
    },
    /// Only the `v` family turned by `angle` (radians); the `u` lines (the spine) stay lines
    /// of curvature (a net that is not orthogonal).
    TurnedV {
        /// The angle, radians.
        angle: f64,
    },
    /// `v` lines are the sections of the surface by the planes normal to `plane_normal`, `u`
    /// lines their orthogonal trajectories.
    PlaneSections {
        /// The common normal of the cutting planes.
        plane_normal: Point3,
    },
}

/// What net to trace: where, along which fields, how many nodes, how far apart.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NetSpec {
    /// A point on or near the surface; it is projected onto `F = 0` first.
    pub start: Point3,
    /// The two direction fields.
    pub directions: NetDirections,
    /// Nodes along `u` (the spine) and along `v` (every row), each at least 2.
    pub nodes: (usize, usize),
    /// Arc length between consecutive nodes along `u` and along `v` (the `v` step is ignored
    /// for closed `v` lines, except as the tracing step while measuring them).
    pub steps: (f64, f64),
    /// Close every `v` line: spread its `nv` nodes evenly over one turn, last = first.
    pub closed_v: bool,
    /// Runge–Kutta steps per node step (default 32).
    pub substeps: usize,
}

impl NetSpec {
    /// A spec with 32 substeps and open `v` lines.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::implicit::{trace_net, Cylinder, NetDirections, NetSpec};
    /// use karkas::Point;
    ///
    /// let spec = NetSpec::new(Point([1.0, 0.0, 0.0]), NetDirections::Principal, (4, 3), (0.1, 0.1));
    /// assert_eq!((spec.substeps, spec.closed_v), (32, false));
    /// // On a cylinder of radius 1 the lines of curvature are circles and generators: every node
    /// // stays on the cylinder.
    /// let net = trace_net(&Cylinder { radius: 1.0 }, &spec)?;
    /// assert_eq!((net.rows(), net.cols()), (4, 3));
    /// assert!(net.as_slice().iter().all(|p| (p.0[0].hypot(p.0[1]) - 1.0).abs() < 1e-9));
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        start: Point3,
        directions: NetDirections,
        nodes: (usize, usize),
        steps: (f64, f64),
    ) -> Self {
        NetSpec {
            start,
            directions,
            nodes,
            steps,
            closed_v: false,
            substeps: 32,
        }
    }
}

/// The family of a line: `u` or `v`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Family {
    U,
    V,
}

/// The unit tangent of `family` at `x`, continuing `previous` (sign and branch).
fn direction<S: ImplicitSurface + ?Sized>(
    surface: &S,
    directions: &NetDirections,
    family: Family,
    x: Point3,
    previous: Point3,
) -> Result<Point3> {
    let frame = SurfaceFrame::at(surface, x)?;
    let n = frame.normal;
    let in_plane = |d: Point3| {
        let t = d - n * n.dot(d);
        let len = t.norm();
        if len > 1e-300 {
            Ok(t * (1.0 / len))
        } else {
            Err(Error::ContinuationFailed {
                line: 0,
                node: 0,
                reason: "the line turned normal to the surface",
            })
        }
    };
    let (angle, principal) = match (*directions, family) {
        (NetDirections::Principal, _) => (0.0, true),
        (NetDirections::Turned { angle }, _) => (angle, true),
        (NetDirections::TurnedU { angle }, Family::U) => (angle, true),
        (NetDirections::TurnedU { .. }, Family::V) => (0.0, true),
        (NetDirections::TurnedV { angle }, Family::V) => (angle, true),
        (NetDirections::TurnedV { .. }, Family::U) => (0.0, true),
        (NetDirections::PlaneSections { plane_normal }, fam) => {
            let section = in_plane(cross(plane_normal, n))?;
            let d = match fam {
                Family::V => section,
                Family::U => cross(n, section),
            };
            return Ok(if d.dot(previous) < 0.0 { -d } else { d });
        }
    };
    debug_assert!(principal);
    // Undo the turn on the previous direction, pick the principal branch closest to it,
    // then turn again.
    let unturned = frame.turn(previous, -angle);
    let d = if frame.is_umbilic() {
        in_plane(unturned)?
    } else {
        let (a, b) = (frame.first_direction, frame.second_direction);
        if a.dot(unturned).abs() >= b.dot(unturned).abs() {
            a
        } else {
            b
        }
    };
    let d = if d.dot(unturned) < 0.0 { -d } else { d };
    Ok(frame.turn(d, angle))
}

/// The initial direction of `family` at `x`: the principal direction with its largest
/// coordinate positive (the first tangent-basis vector at an umbilic), turned as the net
/// asks.
fn initial_direction<S: ImplicitSurface + ?Sized>(
    surface: &S,
    directions: &NetDirections,
    family: Family,
    x: Point3,
) -> Result<Point3> {
    let frame = SurfaceFrame::at(surface, x)?;
    let canonical = |d: Point3| {
        let k = (0..3)
            .max_by(|&a, &b| d[a].abs().total_cmp(&d[b].abs()))
            .unwrap_or(0);
        if d[k] < 0.0 {
            -d
        } else {
            d
        }
    };
    let base = match family {
        Family::U => canonical(frame.first_direction),
        Family::V => canonical(frame.second_direction),
    };
    let seed = match *directions {
        NetDirections::PlaneSections { plane_normal } => {
            let section = cross(plane_normal, frame.normal);
            let d = match family {
                Family::V => section,
                Family::U => cross(frame.normal, section),
            };
            canonical(d)
        }
        NetDirections::Turned { angle } => frame.turn(base, angle),
        NetDirections::TurnedU { angle } if family == Family::U => frame.turn(base, angle),
        NetDirections::TurnedV { angle } if family == Family::V => frame.turn(base, angle),
        _ => base,
    };
    direction(surface, directions, family, x, seed)
}

/// One predictor-corrector step of arc length `h` from `x` (on the surface) with current
/// direction `d`: classical Runge–Kutta on `dx/ds = d(x)`, then Newton onto `F = 0`.
fn step<S: ImplicitSurface + ?Sized>(
    surface: &S,
    directions: &NetDirections,
    family: Family,
    x: Point3,
    d: Point3,
    h: f64,
) -> Result<(Point3, Point3)> {
    let field = |p: Point3, prev: Point3| direction(surface, directions, family, p, prev);
    let k1 = field(x, d)?;
    let k2 = field(x.add_scaled(0.5 * h, k1), k1)?;
    let k3 = field(x.add_scaled(0.5 * h, k2), k2)?;
    let k4 = field(x.add_scaled(h, k3), k3)?;
    let predicted = x.add_scaled(h / 6.0, k1 + k2 * 2.0 + k3 * 2.0 + k4);
    let corrected = project_onto(surface, predicted)?;
    let d_new = field(corrected, k4)?;
    Ok((corrected, d_new))
}

/// Traces `count` node steps of arc length `h` (each in `substeps` steps) from `x`, writing
/// the nodes after `x` into `out`. Returns the final direction.
#[allow(clippy::too_many_arguments)]
fn trace_line<S: ImplicitSurface + ?Sized>(
    surface: &S,
    spec: &NetSpec,
    family: Family,
    line: usize,
    mut x: Point3,
    mut d: Point3,
    h: f64,
    out: &mut [Point3],
) -> Result<Point3> {
    let sub = spec.substeps.max(1);
    let small = h / sub as f64;
    for (node, slot) in out.iter_mut().enumerate() {
        for _ in 0..sub {
            (x, d) = step(surface, &spec.directions, family, x, d, small).map_err(|e| match e {
                Error::ContinuationFailed { reason, .. } => Error::ContinuationFailed {
                    line,
                    node: node + 1,
                    reason,
                },
                Error::SingularPoint { .. } => Error::ContinuationFailed {
                    line,
                    node: node + 1,
                    reason: "the line met a singular point of the surface",
                },
                _ => Error::ContinuationFailed {
                    line,
                    node: node + 1,
                    reason: "the corrector did not return to the surface",
                },
            })?;
        }
        *slot = x;
    }
    Ok(d)
}

/// The length of the closed line through `x` with initial direction `d`, found by tracing
/// it in steps of `h` until it comes back to `x` (the closest approach, refined by a
/// parabola through three samples of the squared distance).
fn loop_length<S: ImplicitSurface + ?Sized>(
    surface: &S,
    spec: &NetSpec,
    line: usize,
    start: Point3,
    d: Point3,
    h: f64,
) -> Result<f64> {
    const MAX_STEPS: usize = 200_000;
    let failed = |_| Error::ContinuationFailed {
        line,
        node: 0,
        reason: "the corrector did not return to the surface while closing the line",
    };
    let (mut x, mut dir) = (start, d);
    // The last three samples (point, direction) and their squared distances to the start.
    let mut states = [(start, d); 3];
    let mut history = [f64::INFINITY; 3];
    let mut left = false;
    for k in 1..=MAX_STEPS {
        (x, dir) = step(surface, &spec.directions, Family::V, x, dir, h).map_err(failed)?;
        states = [states[1], states[2], (x, dir)];
        history = [history[1], history[2], x.distance_sq(start)];
        if history[2] > 9.0 * h * h {
            left = true;
        }
        if left && history[1] <= history[0] && history[1] <= history[2] && history[1] < 4.0 * h * h
        {
            // Minimum of the parabola through (-h, d0), (0, d1), (h, d2), relative to s - h.
            let (a, b, c) = (history[0], history[1], history[2]);
            let curvature = a - 2.0 * b + c;
            let offset = if curvature > 0.0 {
                0.5 * h * (a - c) / curvature
            } else {
                0.0
            };
            let mut length = (k - 1) as f64 * h + offset;
            // Refine: trace from the sample at s - 2h to the estimate and remove the
            // remaining offset along the line (two secant-free corrections suffice).
            let (from, from_dir) = states[0];
            let s0 = (k - 2) as f64 * h;
            for _ in 0..2 {
                let rest = length - s0;
                let (mut p, mut pd) = (from, from_dir);
                for _ in 0..4 {
                    (p, pd) = step(surface, &spec.directions, Family::V, p, pd, rest / 4.0)
                        .map_err(failed)?;
                }
                length -= (p - start).dot(pd);
            }
            return Ok(length);
        }
    }
    Err(Error::ContinuationFailed {
        line,
        node: 0,
        reason: "the v line does not close",
    })
}

/// Traces the node grid described by `spec` on `surface`: `nu x nv` nodes, row `i` the `v`
/// line from spine node `i`.
///
/// Errors: [`Error::InvalidGridSize`] for fewer than 2 nodes in a direction (or more than
/// `10^8` in all), [`Error::InvalidSetting`] for non-positive or non-finite steps or a zero
/// or non-finite plane normal, [`Error::NonFiniteArgument`] for a non-finite start or angle; [`Error::NoSurfaceNear`] when the start
/// point is farther than one node step from the surface (or no surface is found);
/// [`Error::SingularPoint`] at the start; [`Error::ContinuationFailed`] when a line cannot
/// be continued.
pub fn trace_net<S: ImplicitSurface + ?Sized>(surface: &S, spec: &NetSpec) -> Result<Grid<Point3>> {
    check_spec(spec)?;
    let (nu, nv) = spec.nodes;
    let (hu, hv) = spec.steps;
    let start = project_onto(surface, spec.start)?;
    if start.distance(spec.start) > hu.max(hv) {
        return Err(Error::NoSurfaceNear {
            point: spec.start.0,
            residual: surface.value(spec.start).abs(),
        });
    }
    let mut grid = Grid::from_fn(nu, nv, |_, _| Point3::ZERO);
    let (spine, spine_tangents) = trace_spine(surface, spec, start)?;
    let mut dv_prev = initial_direction(surface, &spec.directions, Family::V, start)?;
    let side = |node: Point3, du: Point3, dv: Point3| -> Result<f64> {
        Ok(SurfaceFrame::at(surface, node)?.normal.dot(cross(du, dv)))
    };
    let start_side = side(start, spine_tangents[0], dv_prev)?;
    let mut row = vec![Point3::ZERO; nv - 1];
    for (i, &node) in spine.iter().enumerate() {
        let mut dv = direction(surface, &spec.directions, Family::V, node, dv_prev)?;
        // The v direction by continuity alone flips when the spine turns by more than a
        // right angle around the surface between two nodes (a steep helix on a cylinder).
        if side(node, spine_tangents[i], dv)? * start_side < 0.0 {
            dv = -dv;
        }
        dv_prev = dv;
        let h = if spec.closed_v {
            loop_length(
                surface,
                spec,
                i + 1,
                node,
                dv,
                hv / spec.substeps.max(1) as f64,
            )? / (nv - 1) as f64
        } else {
            hv
        };
        trace_line(surface, spec, Family::V, i + 1, node, dv, h, &mut row)?;
        if spec.closed_v {
            row[nv - 2] = node;
        }
        *grid.get_mut(i, 0) = node;
        for (j, p) in row.iter().enumerate() {
            *grid.get_mut(i, j + 1) = *p;
        }
    }
    Ok(grid)
}

/// Refuses a net smaller than `2 x 2` or larger than `10^8` nodes, steps that are not
/// positive and finite, a non-finite angle or plane normal, and a non-finite start.
fn check_spec(spec: &NetSpec) -> Result<()> {
    let (nu, nv) = spec.nodes;
    let (hu, hv) = spec.steps;
    if nu < 2 || nv < 2 || nu.saturating_mul(nv) > 100_000_000 {
        return Err(Error::InvalidGridSize {
            what: "net",
            rows: nu,
            cols: nv,
            reason: "a net needs at least 2 nodes in each direction and at most 10^8 in all",
        });
    }
    for (name, h) in [("step_u", hu), ("step_v", hv)] {
        if !(h > 0.0 && h.is_finite()) {
            return Err(Error::InvalidSetting {
                name,
                value: h,
                reason: "the node steps must be positive and finite",
            });
        }
    }
    match spec.directions {
        NetDirections::Principal => {}
        NetDirections::Turned { angle }
        | NetDirections::TurnedU { angle }
        | NetDirections::TurnedV { angle } => {
            if !angle.is_finite() {
                return Err(Error::NonFiniteArgument { what: "the angle" });
            }
        }
        NetDirections::PlaneSections { plane_normal } => {
            let length = plane_normal.norm();
            if !(plane_normal.is_finite() && length > 0.0) {
                return Err(Error::InvalidSetting {
                    name: "|plane_normal|",
                    value: length,
                    reason: "the plane normal must be finite and non-zero",
                });
            }
        }
    }
    if !spec.start.is_finite() {
        return Err(Error::NonFiniteArgument {
            what: "the start point",
        });
    }
    Ok(())
}

/// The spine, node by node, with its tangent at every node (carried continuously by the
/// tracing): every row starts on the same side of the spine as the first, whatever the
/// spine turns between two nodes.
fn trace_spine<S: ImplicitSurface + ?Sized>(
    surface: &S,
    spec: &NetSpec,
    start: Point3,
) -> Result<(Vec<Point3>, Vec<Point3>)> {
    let nu = spec.nodes.0;
    let hu = spec.steps.0;
    let mut spine = vec![start; nu];
    let mut spine_tangents = vec![Point3::ZERO; nu];
    spine_tangents[0] = initial_direction(surface, &spec.directions, Family::U, start)?;
    for i in 1..nu {
        let (x, d) = (spine[i - 1], spine_tangents[i - 1]);
        spine_tangents[i] = trace_line(surface, spec, Family::U, 0, x, d, hu, &mut spine[i..=i])
            .map_err(|e| match e {
                Error::ContinuationFailed { line, reason, .. } => Error::ContinuationFailed {
                    line,
                    node: i,
                    reason,
                },
                other => other,
            })?;
    }
    Ok((spine, spine_tangents))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::implicit::{Cylinder, Hyperboloid, Sphere};
    use core::f64::consts::{PI, TAU};

    #[test]
    fn cylinder_principal_net_is_circles_and_generators() {
        let c = Cylinder { radius: 1.0 };
        let spec = NetSpec::new(
            Point3::new([1.0, 0.0, 0.0]),
            NetDirections::Principal,
            (5, 9),
            (0.5, TAU / 8.0),
        );
        let g = trace_net(&c, &spec).unwrap();
        for i in 0..5 {
            for j in 0..9 {
                let a = TAU * j as f64 / 8.0;
                let expected = Point3::new([a.cos(), a.sin(), 0.5 * i as f64]);
                assert!(g.get(i, j).distance(expected) < 1e-8, "node ({i}, {j})");
            }
        }
    }

    #[test]
    fn every_row_runs_the_same_way_however_steep_the_spine() {
        // The generator turned by 75 degrees into a helix, its step stretched to
        // 0.5 / cos 75 = 1.93 so that its nodes stay on the circles z = 0.5 i: consecutive
        // spine nodes are 107 degrees apart around the axis, yet every closed circle starts
        // at its spine node and runs counter-clockwise like the first, as in closed form.
        for (degrees, closed) in [(75.0f64, true), (60.0, true), (75.0, false)] {
            let a = degrees.to_radians();
            let c = Cylinder { radius: 1.0 };
            let mut spec = NetSpec::new(
                Point3::new([1.0, 0.0, 0.0]),
                NetDirections::TurnedU { angle: a },
                (5, 9),
                (0.5 / a.cos(), TAU / 8.0),
            );
            spec.closed_v = closed;
            let g = trace_net(&c, &spec).unwrap();
            let sign = g.get(0, 1)[1].signum();
            for i in 0..5 {
                for j in 0..9 {
                    let phi = sign * (TAU * j as f64 / 8.0 - 0.5 * i as f64 * a.tan());
                    let expected = Point3::new([phi.cos(), phi.sin(), 0.5 * i as f64]);
                    assert!(
                        g.get(i, j).distance(expected) < 1e-6,
                        "{degrees} deg, node ({i}, {j}): {:?}",
                        g.get(i, j)
                    );
                }
            }
        }
    }

    #[test]
    fn turned_net_on_a_cylinder_is_a_helix_lattice() {
        // Unrolled, a net at 30 degrees to the lines of curvature is a turned square lattice.
        let c = Cylinder { radius: 1.0 };
        let t = 30f64.to_radians();
        let spec = NetSpec::new(
            Point3::new([1.0, 0.0, 0.0]),
            NetDirections::Turned { angle: t },
            (3, 4),
            (0.5, 0.4),
        );
        let g = trace_net(&c, &spec).unwrap();
        for i in 0..3 {
            for j in 0..4 {
                // u: the generator (0, 1) turned by t towards -s; v: the circle (1, 0) turned up.
                let (ui, vj) = (0.5 * i as f64, 0.4 * j as f64);
                let s = -ui * t.sin() + vj * t.cos();
                let z = ui * t.cos() + vj * t.sin();
                let expected = Point3::new([s.cos(), s.sin(), z]);
                assert!(g.get(i, j).distance(expected) < 1e-8, "node ({i}, {j})");
            }
        }
    }

    #[test]
    fn closed_rows_on_a_hyperboloid_close_exactly() {
        let h = Hyperboloid { neck_radius: 1.0 };
        let mut spec = NetSpec::new(
            Point3::new([1.25f64.sqrt(), 0.0, -0.5]),
            NetDirections::Principal,
            (5, 9),
            (0.25, 0.8),
        );
        spec.closed_v = true;
        let g = trace_net(&h, &spec).unwrap();
        for i in 0..5 {
            let z = g.get(i, 0)[2];
            let r = (1.0 + z * z).sqrt();
            assert_eq!(g.get(i, 8), g.get(i, 0));
            for j in 0..8 {
                let a = TAU * j as f64 / 8.0;
                let expected = Point3::new([r * a.cos(), r * a.sin(), z]);
                assert!(
                    g.get(i, j).distance(expected) < 1e-7,
                    "node ({i}, {j}): {}",
                    g.get(i, j).distance(expected)
                );
            }
        }
        // The spine follows the meridian upwards.
        assert!(g.get(4, 0)[2] > 0.4);
    }

    #[test]
    fn sphere_umbilics_and_bad_starts_are_handled() {
        let s = Sphere { radius: 1.0 };
        let spec = NetSpec::new(
            Point3::new([1.0, 0.0, 0.0]),
            NetDirections::Principal,
            (3, 3),
            (PI / 8.0, PI / 8.0),
        );
        let g = trace_net(&s, &spec).unwrap();
        assert!(g.as_slice().iter().all(|p| (p.norm() - 1.0).abs() < 1e-12));
        let far = NetSpec::new(
            Point3::new([9.0, 0.0, 0.0]),
            NetDirections::Principal,
            (3, 3),
            (0.1, 0.1),
        );
        assert!(matches!(
            trace_net(&s, &far),
            Err(Error::NoSurfaceNear { .. })
        ));
        let bad = NetSpec::new(
            Point3::new([1.0, 0.0, 0.0]),
            NetDirections::Principal,
            (1, 3),
            (0.1, 0.1),
        );
        assert!(trace_net(&s, &bad).is_err());
    }
}

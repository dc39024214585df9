//! Re-laying a grid of points along the lines of curvature of its own bicubic interpolant
//! (Kuznetsov and Filatov, Theorem 2.1 and section 2; docs/methods.md §5).
//!
//! By Theorem 2.1 the best parameters of a surface are arc lengths along two orthogonal
//! directions, and the paper takes the principal directions. A surface known only by a grid
//! of points laid along other lines (turned by an angle, plane sections) can be re-laid: the
//! grid's bicubic interpolant `W(u, v)` ([`BicubicSurface`], chord-length parameters through
//! node `(0, 0)`, not-a-knot ends) is built, and on it the two families of lines of curvature
//! are traced through a start node, spaced by arc length:
//!
//! - a line of curvature is the solution of `dx/ds = t(x)` for a unit principal direction
//!   `t` (from the fundamental forms, [`principal_curvatures`]); it is integrated in the
//!   parameter plane, `d(u, v)/ds = I^{-1} (t . W_u, t . W_v)` with the first form
//!   `I = [[E, F], [F, G]]`, by classical Runge–Kutta steps (the predictor); working in
//!   `(u, v)` keeps every point exactly on `W` (the corrector of the implicit tracer is not
//!   needed). The branch and sign of `t` continue the previous step;
//! - the `u` family is the principal direction closer to `W_u` at the start node, the `v`
//!   family the other;
//! - the spine (the `u` line through the start) and the rib (the `v` line through it) carry
//!   nodes at arc-length steps `h_u`, `h_v`; node `(i, j)` of the new grid is the crossing of
//!   the `v` line through spine node `i` with the `u` line through rib node `j` (found on the
//!   traced polylines in the parameter plane), so every row and every column of the new grid
//!   lies on one line of curvature;
//! - unless given, the steps are the largest that keep the spine and the rib inside the
//!   interpolant's domain (in a closed direction: within half a period each way from the
//!   start, so that a closed line is re-laid closed, its last node on its first); when a crossing falls outside it the steps are shrunk by
//!   0.85 and the net traced again, at most 24 times.
//!
//! Umbilics (principal curvatures equal, e.g. every point of a plane or sphere) have no
//! principal directions: the relay refuses them with [`Error::UmbilicRegion`] at the first
//! point met where `|k1 - k2| <= 0.1 max(|k1|, |k2|, 1 / L)` (`L` the grid's
//! diameter). Every line is traced in a bounded number of steps.
//!
//! Cost: `O(N M)` for the interpolant, `O((M + N) substeps max(M, N))` frame evaluations for
//! the lines and `O(M N (substeps max(M, N))^2)` segment tests for the crossings.

use super::bicubic::BicubicSurface;
use super::parameterization::GridParameterization;
use crate::core::{Grid, Surface};
use crate::geometry::surface_frame::{normal, principal_curvatures};
use crate::{Error, Point3, Result};

/// Runge–Kutta steps per node step (the default of [`RelayOptions::substeps`]).
pub const DEFAULT_SUBSTEPS: usize = 32;

/// The relative spread of the principal curvatures under which a point is an umbilic.
const UMBILIC_RATIO: f64 = 0.1;

/// The factor the automatic steps are shrunk by when a crossing falls outside the domain.
const SHRINK: f64 = 0.85;

/// The largest number of times the automatic steps are shrunk.
const SHRINK_ROUNDS: usize = 24;

/// How far (relative to the domain's span) the lines that are crossed to find the nodes run
/// on beyond the domain (the interpolant continues its end patches): a line along an edge of
/// the domain drifts across it.
const LINE_SLACK: f64 = 0.25;

/// How far (relative to the domain's span) a crossing may lie outside the domain.
const NODE_SLACK: f64 = 0.02;

/// The largest number of Runge–Kutta steps of one traced line.
const MAX_LINE_STEPS: usize = 200_000;

/// How far (relative to the domain's span) a node may land outside the domain: the lengths
/// to the boundary are measured on a polyline.
const DOMAIN_SLACK: f64 = 1e-3;

/// How to re-lay a grid.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RelayOptions {
    /// Rows and columns `(M, N)` of the new grid (each at least 2); `None`: the input's.
    pub size: Option<(usize, usize)>,
    /// The start node `(i, j)` of the input grid; `None`: its centre
    /// `((rows - 1) / 2, (cols - 1) / 2)`. In the new grid it becomes node
    /// `(round(i (M - 1) / (rows - 1)), round(j (N - 1) / (cols - 1)))`.
    pub start: Option<(usize, usize)>,
    /// Arc-length steps `(h_u, h_v)` between nodes; `None`: the largest that keep the spine
    /// and the rib inside the interpolant's domain.
    pub steps: Option<(f64, f64)>,
    /// Runge–Kutta steps per node step (at least 1; default [`DEFAULT_SUBSTEPS`]).
    pub substeps: usize,
    /// Interpolate the input closed (periodic) in `u` and in `v`, as
    /// [`BicubicSurface::new`] does; a line of curvature then runs at most half a period of
    /// that parameter each way from the start, so that a closed grid is re-laid closed.
    pub closed: (bool, bool),
}

impl Default for RelayOptions {
    fn default() -> Self {
        RelayOptions {
            size: None,
            start: None,
            steps: None,
            substeps: DEFAULT_SUBSTEPS,
            closed: (false, false),
        }
    }
}

/// A grid re-laid along lines of curvature.
#[derive(Clone, Debug, PartialEq)]
pub struct RelaidGrid {
    /// The nodes: row `i` lies on one `v` line of curvature, column `j` on one `u` line.
    pub nodes: Grid<Point3>,
    /// The parameters `(u, v)` of every node on the input's interpolant.
    pub parameters: Grid<[f64; 2]>,
    /// The arc-length steps `(h_u, h_v)` along the spine and the rib.
    pub steps: (f64, f64),
    /// The start node in the new grid.
    pub start: (usize, usize),
}

/// The most nodes [`relay_grid`] lays (as `karkas surface relay --size` allows).
const MAX_RELAY_NODES: usize = 1_000_000;

/// Re-lays `grid` along the lines of curvature of its bicubic interpolant (chord-length
/// parameters through node `(0, 0)`, not-a-knot ends or periodic in a closed direction), as
/// the module docs describe.
///
/// Errors: those of [`BicubicSurface::new`]; a size below 2 ([`Error::InvalidGridSize`]); a
/// start node outside the grid ([`Error::OutsideGrid`]); non-positive or non-finite steps, or
/// more than `MAX_RELAY_NODES` (10^6) nodes ([`Error::InvalidSetting`]); an umbilic met ([`Error::UmbilicRegion`]); a singular point
/// or a net that does not fit the domain ([`Error::ContinuationFailed`]).
pub fn relay_grid(grid: &Grid<Point3>, options: &RelayOptions) -> Result<RelaidGrid> {
    let (rows, cols) = (grid.rows(), grid.cols());
    let (si, sj) = options.start.unwrap_or(((rows - 1) / 2, (cols - 1) / 2));
    let (closed_u, closed_v) = options.closed;
    let surface = BicubicSurface::new(grid, GridParameterization::default(), closed_u, closed_v)?;
    if si >= rows || sj >= cols {
        return Err(Error::OutsideGrid {
            what: "the start node",
            row: si,
            col: sj,
            rows,
            cols,
        });
    }
    let (m, n) = options.size.unwrap_or((rows, cols));
    if m.saturating_mul(n) > MAX_RELAY_NODES {
        return Err(Error::InvalidSetting {
            name: "size",
            value: m as f64 * n as f64,
            reason: "at most 1e6 nodes can be re-laid (each is the crossing of two traced lines)",
        });
    }
    let start_uv = (surface.knots_u()[si], surface.knots_v()[sj]);
    let scaled = |k: usize, from: usize, to: usize| {
        ((k as f64) * (to - 1) as f64 / (from - 1) as f64).round() as usize
    };
    let start_index = if m >= 2 && n >= 2 {
        (scaled(si, rows, m), scaled(sj, cols, n))
    } else {
        (0, 0)
    };
    let diameter = grid_diameter(grid);
    relay_surface(
        &surface,
        start_uv,
        (m, n),
        start_index,
        options.steps,
        options.substeps,
        diameter,
    )
}

/// Lays an `M x N` grid of nodes along the lines of curvature of `surface` through the point
/// `start_uv`, which becomes node `start_index`; `steps` as [`RelayOptions::steps`];
/// `size_scale` is the length `L` of the umbilic test (the surface's diameter).
///
/// Errors: as [`relay_grid`] (a start outside the domain is [`Error::InvalidSetting`]).
pub fn relay_surface<S: Surface<3> + ?Sized>(
    surface: &S,
    start_uv: (f64, f64),
    size: (usize, usize),
    start_index: (usize, usize),
    steps: Option<(f64, f64)>,
    substeps: usize,
    size_scale: f64,
) -> Result<RelaidGrid> {
    check_request(size, start_index, steps)?;
    let p0 = [start_uv.0, start_uv.1];
    let domain = start_domain(surface, p0);
    if !domain.contains(p0, 0.0) {
        return Err(Error::InvalidSetting {
            name: "the start parameter u",
            value: start_uv.0,
            reason: "the start must lie in the surface's domain",
        });
    }
    let field = Field {
        surface,
        inverse_size: if size_scale.is_finite() && size_scale > 0.0 {
            1.0 / size_scale
        } else {
            0.0
        },
        domain,
    };
    let (dir_u, dir_v, sign) = field.start_directions(p0)?;
    let mut net = NetLayout {
        field: &field,
        start: p0,
        dir_u,
        dir_v,
        sign,
        size,
        start_index,
        steps: (0.0, 0.0),
        substeps: substeps.max(1),
    };
    net.steps = match steps {
        Some(h) => h,
        None => net.probed_steps()?,
    };
    let rounds = if steps.is_some() { 1 } else { SHRINK_ROUNDS };
    net.relay(rounds)
}

/// Refuses a grid smaller than `2 x 2`, a start node outside it and steps that are not
/// positive and finite.
fn check_request(
    (m, n): (usize, usize),
    start_index: (usize, usize),
    steps: Option<(f64, f64)>,
) -> Result<()> {
    if m < 2 || n < 2 {
        return Err(Error::InvalidGridSize {
            what: "re-laid grid",
            rows: m,
            cols: n,
            reason: "at least 2 nodes are needed in each direction",
        });
    }
    if start_index.0 >= m || start_index.1 >= n {
        return Err(Error::OutsideGrid {
            what: "the start node",
            row: start_index.0,
            col: start_index.1,
            rows: m,
            cols: n,
        });
    }
    if let Some((hu, hv)) = steps {
        for (name, h) in [("the u step", hu), ("the v step", hv)] {
            if !(h.is_finite() && h > 0.0) {
                return Err(Error::InvalidSetting {
                    name,
                    value: h,
                    reason: "an arc-length step must be positive and finite",
                });
            }
        }
    }
    Ok(())
}

/// The surface's domain as the net sees it: a closed direction spans half a period each way
/// from the start `p0` (the surface wraps).
fn start_domain<S: Surface<3> + ?Sized>(surface: &S, p0: [f64; 2]) -> Domain {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let range = |closed: bool, start: f64, end: f64, at: f64| {
        if closed {
            let half = 0.5 * (end - start);
            (at - half, at + half)
        } else {
            (start, end)
        }
    };
    Domain {
        u: range(surface.is_closed_u(), du.start, du.end, p0[0]),
        v: range(surface.is_closed_v(), dv.start, dv.end, p0[1]),
    }
}

/// The largest distance between two corners of the grid's bounding box.
fn grid_diameter(grid: &Grid<Point3>) -> f64 {
    let mut lo = [f64::INFINITY; 3];
    let mut hi = [f64::NEG_INFINITY; 3];
    for p in grid.as_slice() {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    Point3::new(hi).distance(Point3::new(lo))
}

/// `a x b`.
fn cross(a: Point3, b: Point3) -> Point3 {
    Point3::new([
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ])
}

/// The parameter rectangle of the surface.
#[derive(Clone, Copy, Debug)]
struct Domain {
    u: (f64, f64),
    v: (f64, f64),
}

impl Domain {
    /// Whether `p` lies in the rectangle widened by `slack` times its spans.
    fn contains(&self, p: [f64; 2], slack: f64) -> bool {
        let (su, sv) = (slack * (self.u.1 - self.u.0), slack * (self.v.1 - self.v.0));
        p[0] >= self.u.0 - su
            && p[0] <= self.u.1 + su
            && p[1] >= self.v.0 - sv
            && p[1] <= self.v.1 + sv
    }

    /// The fraction `t` in `[0, 1]` of the segment `a -> b` (`a` inside) where it leaves.
    fn exit_fraction(&self, a: [f64; 2], b: [f64; 2]) -> f64 {
        let mut t: f64 = 1.0;
        for (k, (lo, hi)) in [(0, self.u), (1, self.v)] {
            let d = b[k] - a[k];
            if b[k] > hi && d > 0.0 {
                t = t.min((hi - a[k]) / d);
            }
            if b[k] < lo && d < 0.0 {
                t = t.min((lo - a[k]) / d);
            }
        }
        t.clamp(0.0, 1.0)
    }

    /// The rectangle widened by `slack` times its spans on every side.
    fn widened(&self, slack: f64) -> Domain {
        let (su, sv) = (slack * (self.u.1 - self.u.0), slack * (self.v.1 - self.v.0));
        Domain {
            u: (self.u.0 - su, self.u.1 + su),
            v: (self.v.0 - sv, self.v.1 + sv),
        }
    }

    fn diagonal(&self) -> f64 {
        (self.u.1 - self.u.0).hypot(self.v.1 - self.v.0)
    }
}

/// The principal direction fields of a surface in its parameter plane.
struct Field<'a, S: ?Sized> {
    surface: &'a S,
    /// `1 / L`: the curvature under which both principal curvatures count as zero.
    inverse_size: f64,
    domain: Domain,
}

/// A traced line: its points in the parameter plane and its arc length.
struct Polyline {
    points: Vec<[f64; 2]>,
    length: f64,
}

/// What went wrong on a line, before it is named by its line and node.
fn failed(reason: &'static str) -> Error {
    Error::ContinuationFailed {
        line: 0,
        node: 0,
        reason,
    }
}

impl<S: Surface<3> + ?Sized> Field<'_, S> {
    /// The two unit principal directions and the unit normal at `p`.
    ///
    /// Errors: a singular point, an umbilic.
    fn principal_pair(&self, p: [f64; 2]) -> Result<(Point3, Point3, Point3)> {
        let pc = principal_curvatures(self.surface, p[0], p[1]);
        if !(pc.k1.is_finite() && pc.k2.is_finite() && pc.dir1.is_finite()) {
            return Err(failed(
                "the surface is singular there (W_u x W_v = 0 or not finite)",
            ));
        }
        let scale = pc.k1.abs().max(pc.k2.abs()).max(self.inverse_size);
        if pc.k1 - pc.k2 <= UMBILIC_RATIO * scale {
            return Err(Error::UmbilicRegion {
                point: self.surface.eval(p[0], p[1]).0,
                k1: pc.k1,
                k2: pc.k2,
            });
        }
        Ok((pc.dir1, pc.dir2, pc.normal))
    }

    /// The two families at the start `p0`: `u` the principal direction closer to `W_u`,
    /// each turned along its parameter, and the sign with `dir_v = sign n x dir_u`.
    fn start_directions(&self, p0: [f64; 2]) -> Result<(Point3, Point3, f64)> {
        let (d1, d2, normal) = self.principal_pair(p0)?;
        let su = self.surface.deriv(p0[0], p0[1], 1, 0);
        let sv = self.surface.deriv(p0[0], p0[1], 0, 1);
        let (mut dir_u, mut dir_v) = if d1.dot(su).abs() >= d2.dot(su).abs() {
            (d1, d2)
        } else {
            (d2, d1)
        };
        if dir_u.dot(su) < 0.0 {
            dir_u = -dir_u;
        }
        if dir_v.dot(sv) < 0.0 {
            dir_v = -dir_v;
        }
        // v = sign n x u; then u = -sign n x v.
        let sign = if dir_v.dot(cross(normal, dir_u)) >= 0.0 {
            1.0
        } else {
            -1.0
        };
        Ok((dir_u, dir_v, sign))
    }

    /// The principal direction continuing `previous` at `p`, and its parameter velocity
    /// `d(u, v)/ds`.
    fn direction(&self, p: [f64; 2], previous: Point3) -> Result<(Point3, [f64; 2])> {
        let (d1, d2, _) = self.principal_pair(p)?;
        let d = if d1.dot(previous).abs() >= d2.dot(previous).abs() {
            d1
        } else {
            d2
        };
        let d = if d.dot(previous) < 0.0 { -d } else { d };
        let su = self.surface.deriv(p[0], p[1], 1, 0);
        let sv = self.surface.deriv(p[0], p[1], 0, 1);
        let (e, f, g) = (su.dot(su), su.dot(sv), sv.dot(sv));
        let det = e * g - f * f;
        if !(det.is_finite() && det > 0.0) {
            return Err(failed("the surface is singular there (E G - F^2 = 0)"));
        }
        let (a, b) = (d.dot(su), d.dot(sv));
        Ok((d, [(g * a - f * b) / det, (e * b - f * a) / det]))
    }

    /// One Runge–Kutta step of arc length `h` from `p` with direction `d`.
    fn step(&self, p: [f64; 2], d: Point3, h: f64) -> Result<([f64; 2], Point3)> {
        let at = |q: [f64; 2], k: [f64; 2], s: f64| [q[0] + s * k[0], q[1] + s * k[1]];
        let (t1, k1) = self.direction(p, d)?;
        let (t2, k2) = self.direction(at(p, k1, 0.5 * h), t1)?;
        let (t3, k3) = self.direction(at(p, k2, 0.5 * h), t2)?;
        let (t4, k4) = self.direction(at(p, k3, h), t3)?;
        let next = [
            p[0] + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]),
            p[1] + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]),
        ];
        if !(next[0].is_finite() && next[1].is_finite()) {
            return Err(failed("the traced line left the finite numbers"));
        }
        Ok((next, t4))
    }

    /// The line from `p` with direction `d` in steps of `h`, until it has length `max_length`
    /// or leaves the domain widened by `slack` times its spans (its last point then on the
    /// boundary).
    fn polyline(
        &self,
        p: [f64; 2],
        d: Point3,
        h: f64,
        max_length: f64,
        slack: f64,
    ) -> Result<Polyline> {
        let domain = self.domain.widened(slack);
        let mut points = vec![p];
        let (mut p, mut d, mut length) = (p, d, 0.0);
        for _ in 0..MAX_LINE_STEPS {
            if length >= max_length {
                break;
            }
            let h = h.min(max_length - length);
            let (next, d_next) = match self.step(p, d, h) {
                Ok(stepped) => stepped,
                // Beyond the domain the interpolant is only continued: the line ends there.
                Err(_) if !self.domain.contains(p, 0.0) => break,
                Err(e) => return Err(e),
            };
            if !domain.contains(next, 0.0) {
                let t = domain.exit_fraction(p, next);
                points.push([p[0] + t * (next[0] - p[0]), p[1] + t * (next[1] - p[1])]);
                length += t * h;
                break;
            }
            points.push(next);
            length += h;
            (p, d) = (next, d_next);
        }
        Ok(Polyline { points, length })
    }

    /// `count` nodes at arc-length steps `h` from `p` along `d` (each in `substeps` steps),
    /// with the direction at every node.
    fn nodes(
        &self,
        p: [f64; 2],
        d: Point3,
        h: f64,
        count: usize,
        substeps: usize,
    ) -> Result<Vec<([f64; 2], Point3)>> {
        let small = h / substeps as f64;
        let (mut p, mut d) = (p, d);
        let mut out = Vec::with_capacity(count);
        for _ in 0..count {
            for _ in 0..substeps {
                (p, d) = self.step(p, d, small)?;
                if !self.domain.contains(p, DOMAIN_SLACK) {
                    return Err(failed(
                        "the line of curvature left the input surface's domain",
                    ));
                }
            }
            out.push((p, d));
        }
        Ok(out)
    }
}

/// One attempt at the net with given steps.
struct NetLayout<'a, 'b, S: ?Sized> {
    field: &'a Field<'b, S>,
    start: [f64; 2],
    dir_u: Point3,
    dir_v: Point3,
    /// `dir_v = sign n x dir_u` at the start.
    sign: f64,
    size: (usize, usize),
    start_index: (usize, usize),
    steps: (f64, f64),
    substeps: usize,
}

impl<S: Surface<3> + ?Sized> NetLayout<'_, '_, S> {
    /// The steps that fit the grid's nodes on the lines through the start, probed in small
    /// steps to where each line ends.
    fn probed_steps(&self) -> Result<(f64, f64)> {
        let (m, n) = self.size;
        let (i0, j0) = self.start_index;
        let probe = self.field.domain.diagonal() / 400.0;
        let along = |d: Point3, count: usize| -> Result<f64> {
            if count == 0 {
                return Ok(f64::INFINITY);
            }
            let line = self
                .field
                .polyline(self.start, d, probe, f64::INFINITY, 0.0)?;
            Ok(line.length / count as f64)
        };
        let hu = along(self.dir_u, m - 1 - i0)?.min(along(-self.dir_u, i0)?);
        let hv = along(self.dir_v, n - 1 - j0)?.min(along(-self.dir_v, j0)?);
        Ok((hu, hv))
    }

    /// The net in at most `rounds` attempts, the steps shrunk after each that fails to
    /// continue a line.
    fn relay(mut self, rounds: usize) -> Result<RelaidGrid> {
        let (m, n) = self.size;
        let mut last_error = None;
        for _ in 0..rounds {
            match self.lay() {
                Ok(parameters) => {
                    let nodes = Grid::from_fn(m, n, |i, j| {
                        let [u, v] = *parameters.get(i, j);
                        self.field.surface.eval(u, v)
                    });
                    return Ok(RelaidGrid {
                        nodes,
                        parameters,
                        steps: self.steps,
                        start: self.start_index,
                    });
                }
                Err(e @ Error::ContinuationFailed { .. }) => {
                    last_error = Some(e);
                    self.steps.0 *= SHRINK;
                    self.steps.1 *= SHRINK;
                }
                Err(e) => return Err(e),
            }
        }
        Err(last_error.unwrap_or(Error::Internal {
            what: "the relay made no attempt",
        }))
    }

    /// The parameters of every node. Errors: [`Error::ContinuationFailed`] naming the row
    /// (`line`) and column (`node`) that could not be placed, or the umbilic met.
    fn lay(&self) -> Result<Grid<[f64; 2]>> {
        let (m, n) = self.size;
        let (i0, j0) = self.start_index;
        let (hu, hv) = self.steps;
        // Spine (u line through the start) and rib (v line through it), with directions.
        let spine = self
            .line_nodes(self.dir_u, hu, i0, m)
            .map_err(at_node(i0, j0))?;
        let rib = self
            .line_nodes(self.dir_v, hv, j0, n)
            .map_err(at_node(i0, j0))?;
        let mut params = Grid::from_fn(m, n, |_, _| [f64::NAN; 2]);
        for (i, &(p, _)) in spine.iter().enumerate() {
            *params.get_mut(i, j0) = p;
        }
        for (j, &(p, _)) in rib.iter().enumerate() {
            *params.get_mut(i0, j) = p;
        }
        let u_lines = self.u_lines(&rib)?;
        for (i, &(p, d_u)) in spine.iter().enumerate() {
            if i == i0 {
                continue;
            }
            let normal = normal(self.field.surface, p[0], p[1]);
            let d_v = cross(normal, d_u) * self.sign;
            for (dir, js) in [
                (d_v, (j0 + 1..n).collect::<Vec<_>>()),
                (-d_v, (0..j0).rev().collect::<Vec<_>>()),
            ] {
                if !js.is_empty() {
                    self.place_on_v_line(i, (p, dir), &js, &u_lines, &mut params)?;
                }
            }
        }
        Ok(params)
    }

    /// The u lines through the rib nodes, towards smaller and larger `i` (none through the
    /// start, whose u line is the spine).
    fn u_lines(&self, rib: &[([f64; 2], Point3)]) -> Result<Vec<UnderAndOver>> {
        let (m, _) = self.size;
        let (i0, j0) = self.start_index;
        let hu = self.steps.0;
        let f = self.field;
        let sub_u = hu / self.substeps as f64;
        let reach_u = 2.0 * hu * (m as f64) + hu;
        let mut u_lines = Vec::with_capacity(rib.len());
        for (j, &(p, d_v)) in rib.iter().enumerate() {
            if j == j0 {
                u_lines.push((None, None));
                continue;
            }
            let normal = normal(f.surface, p[0], p[1]);
            let d_u = cross(normal, d_v) * (-self.sign);
            let up = (i0 + 1 < m)
                .then(|| f.polyline(p, d_u, sub_u, reach_u, LINE_SLACK))
                .transpose()
                .map_err(at_node(i0, j))?;
            let down = (i0 > 0)
                .then(|| f.polyline(p, -d_u, sub_u, reach_u, LINE_SLACK))
                .transpose()
                .map_err(at_node(i0, j))?;
            u_lines.push((down, up));
        }
        Ok(u_lines)
    }

    /// Places the nodes `js` of row `i`: the v line from the spine node `(p, dir)` traced,
    /// and each node where it first meets the u line of its column.
    fn place_on_v_line(
        &self,
        i: usize,
        (p, dir): ([f64; 2], Point3),
        js: &[usize],
        u_lines: &[UnderAndOver],
        params: &mut Grid<[f64; 2]>,
    ) -> Result<()> {
        let (_, n) = self.size;
        let (i0, j0) = self.start_index;
        let hv = self.steps.1;
        let f = self.field;
        let reach_v = 2.0 * hv * (n as f64) + hv;
        let line = f
            .polyline(p, dir, hv / self.substeps as f64, reach_v, LINE_SLACK)
            .map_err(at_node(i, j0))?;
        let mut from = 0;
        for &j in js {
            let crossing_line = if i > i0 {
                u_lines[j].1.as_ref()
            } else {
                u_lines[j].0.as_ref()
            };
            let Some(other) = crossing_line else {
                return Err(Error::Internal {
                    what: "a u line of the re-laid net was not traced",
                });
            };
            let found = first_crossing(&line.points[from..], &other.points)
                .filter(|(_, q)| f.domain.contains(*q, NODE_SLACK));
            let Some((k, point)) = found else {
                return Err(Error::ContinuationFailed {
                    line: i,
                    node: j,
                    reason: "the lines of curvature through the node do not meet \
                             inside the input surface's domain",
                });
            };
            from += k;
            *params.get_mut(i, j) = point;
        }
        Ok(())
    }

    /// The `count` nodes of the line through the start along `d` with step `h`, the start at
    /// index `at`; each with its direction pointing towards larger indices.
    fn line_nodes(
        &self,
        d: Point3,
        h: f64,
        at: usize,
        count: usize,
    ) -> Result<Vec<([f64; 2], Point3)>> {
        let f = self.field;
        let mut before = f.nodes(self.start, -d, h, at, self.substeps)?;
        before.reverse();
        let mut out: Vec<([f64; 2], Point3)> = before.into_iter().map(|(p, t)| (p, -t)).collect();
        out.push((self.start, d));
        out.extend(f.nodes(self.start, d, h, count - 1 - at, self.substeps)?);
        Ok(out)
    }
}

/// A u line through a rib node: its parts towards smaller and larger `i`.
type UnderAndOver = (Option<Polyline>, Option<Polyline>);

/// Names a continuation failure by the row (`line`) and column (`node`) it happened at.
fn at_node(line: usize, node: usize) -> impl Fn(Error) -> Error {
    move |e: Error| match e {
        Error::ContinuationFailed { reason, .. } => {
            Error::ContinuationFailed { line, node, reason }
        }
        other => other,
    }
}

/// The first crossing of the polyline `a` (walked from its start) with the polyline `b`: the
/// index of the segment of `a` and the point.
fn first_crossing(a: &[[f64; 2]], b: &[[f64; 2]]) -> Option<(usize, [f64; 2])> {
    for (k, sa) in a.windows(2).enumerate() {
        let (lo_u, hi_u) = (sa[0][0].min(sa[1][0]), sa[0][0].max(sa[1][0]));
        let (lo_v, hi_v) = (sa[0][1].min(sa[1][1]), sa[0][1].max(sa[1][1]));
        for sb in b.windows(2) {
            if sb[0][0].max(sb[1][0]) < lo_u
                || sb[0][0].min(sb[1][0]) > hi_u
                || sb[0][1].max(sb[1][1]) < lo_v
                || sb[0][1].min(sb[1][1]) > hi_v
            {
                continue;
            }
            if let Some(p) = segment_crossing(sa[0], sa[1], sb[0], sb[1]) {
                return Some((k, p));
            }
        }
    }
    None
}

/// The crossing of the segments `p0 p1` and `q0 q1` in the plane, ends included.
fn segment_crossing(p0: [f64; 2], p1: [f64; 2], q0: [f64; 2], q1: [f64; 2]) -> Option<[f64; 2]> {
    let r = [p1[0] - p0[0], p1[1] - p0[1]];
    let s = [q1[0] - q0[0], q1[1] - q0[1]];
    let denom = r[0] * s[1] - r[1] * s[0];
    if denom == 0.0 || !denom.is_finite() {
        return None;
    }
    let w = [q0[0] - p0[0], q0[1] - p0[1]];
    let t = (w[0] * s[1] - w[1] * s[0]) / denom;
    let u = (w[0] * r[1] - w[1] * r[0]) / denom;
    const EDGE: f64 = 1e-12;
    if (-EDGE..=1.0 + EDGE).contains(&t) && (-EDGE..=1.0 + EDGE).contains(&u) {
        Some([p0[0] + t * r[0], p0[1] + t * r[1]])
    } else {
        None
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segments_cross_where_they_should() {
        let p = segment_crossing([0.0, 0.0], [2.0, 2.0], [0.0, 2.0], [2.0, 0.0]);
        assert_eq!(p, Some([1.0, 1.0]));
        assert_eq!(
            segment_crossing([0.0, 0.0], [1.0, 0.0], [0.0, 1.0], [1.0, 1.0]),
            None
        );
        assert_eq!(
            segment_crossing([0.0, 0.0], [1.0, 1.0], [3.0, 0.0], [2.0, 1.0]),
            None
        );
    }
}

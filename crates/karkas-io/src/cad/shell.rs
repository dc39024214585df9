//! Shells and solids for STEP and IGES: B-spline faces and planar caps joined by shared
//! edges ([`CadShell`]).
//!
//! A B-spline patch is bounded by its parameter rectangle, whose four sides become edges
//! with these rules, which CAD kernels need to read the face as valid with its true area:
//!
//! - a side whose control points all coincide (a pole: the nose or tail of a body, the apex
//!   of a cone) is no edge: its corners are one vertex, and the loop passes through it (the
//!   reader adds the degenerate edge in the parameter plane; Open CASCADE does);
//! - two sides that are one curve (a closed direction: the first and last control lines
//!   coincide) are one edge, the seam, used twice in the loop in opposite senses;
//! - two faces that share a side (the same B-spline curve, in either direction) share the
//!   edge, as a closed shell needs;
//! - each use of an edge by a B-spline face records the side of the parameter rectangle it
//!   is ([`ParameterSegment`]), which STEP writes as the edge's curve on that face.
//!
//! Vertices coincide within the shell's tolerance (by default `1e-9` of the control points'
//! extent). The loop of a patch runs counter-clockwise in `(u, v)`, so the face's normal is
//! `S_u x S_v`.
//!
//! [`CadShell::cap_free_loops`] closes every loop of free edges (edges used once) by a planar
//! face when the loop lies in a plane ([`karkas::geometry::polygon_plane`] of its control polygon:
//! a B-spline curve lies in a plane exactly when its control points do); [`CadShell::is_closed`] tells a closed shell (every
//! edge used once in each sense), which STEP writes as a solid; [`CadShell::orient_outward`]
//! turns every face so that the normals point out of the enclosed volume
//! ([`karkas::geometry::flux_volume`], docs/methods.md §6, "Closed bodies") and returns the
//! volume.

use karkas::bspline::{BSplineCurve, BSplineSurface};
use karkas::geometry::{area_vector, flux_volume, polygon_plane, Plane};
use karkas::{Point3, Surface};

/// The tolerance of a shell relative to the extent of its control points: vertices this
/// close are one vertex, a side whose control points all lie this close is a pole.
const SHELL_RELATIVE_TOLERANCE: f64 = 1e-9;

/// The largest distance of a loop's control points from its best plane, relative to the
/// shell's extent, for [`CadShell::cap_free_loops`] to cap it with a planar face.
pub(crate) const CAP_RELATIVE_FLATNESS: f64 = 1e-6;

/// An edge of a shell: a B-spline curve from one vertex to another (the same vertex for a
/// closed curve).
#[derive(Clone, Debug)]
pub struct ShellEdge {
    /// The vertex at the curve's start.
    pub start: usize,
    /// The vertex at the curve's end.
    pub end: usize,
    /// The edge's geometry.
    pub curve: BSplineCurve<3>,
}

/// An edge used by a loop, along its curve (`forward`) or against it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct OrientedEdge {
    /// The index of the edge in [`CadShell::edges`].
    pub edge: usize,
    /// True when the loop runs along the edge's curve.
    pub forward: bool,
    /// Where the edge lies in the parameter plane of a B-spline face (a side of its
    /// parameter rectangle); `None` on a plane.
    pub on_face: Option<ParameterSegment>,
}

/// A straight segment of a B-spline face's parameter plane that an edge runs along: the
/// surface at `start` is the edge's curve at its first parameter, at `end` at its last,
/// and the parameters between map linearly (the edge is a side of the face's parameter
/// rectangle). A STEP file carries it as the edge's curve on the face (`PCURVE`), so that a
/// reader need not find it by projection, which folds where a side runs back along itself.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ParameterSegment {
    /// `(u, v)` at the edge curve's first parameter.
    pub start: [f64; 2],
    /// `(u, v)` at the edge curve's last parameter.
    pub end: [f64; 2],
}

impl ParameterSegment {
    /// The segment run the other way.
    fn reversed(self) -> ParameterSegment {
        ParameterSegment {
            start: self.end,
            end: self.start,
        }
    }
}

/// The surface a face lies on.
#[derive(Clone, Debug)]
pub enum FaceSurface {
    /// A B-spline patch bounded by its parameter rectangle.
    BSpline(BSplineSurface<3>),
    /// A plane (a cap), bounded by a loop of the other faces' edges.
    Plane(Plane),
}

/// A face: its surface and its one bounding loop.
#[derive(Clone, Debug)]
pub struct ShellFace {
    /// The surface.
    pub surface: FaceSurface,
    /// The loop, counter-clockwise about the face's normal.
    pub bound: Vec<OrientedEdge>,
    /// True when the face's normal is the surface's (`S_u x S_v`, or the plane's normal).
    pub same_sense: bool,
}

/// A planar cap that [`CadShell::cap_free_loops`] added.
#[derive(Clone, Copy, Debug)]
pub struct Cap {
    /// The index of the cap in [`CadShell::faces`].
    pub face: usize,
    /// Its plane.
    pub plane: Plane,
    /// The area it closes.
    pub area: f64,
}

/// Why a shell's free loops cannot be capped.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CapError {
    /// The shell has no free edge: nothing to cap.
    #[error("the surface has no open boundary to cap: it is closed already")]
    NothingToCap,
    /// The free edges do not form closed loops (a vertex where more or fewer than two meet).
    #[error("the open boundary does not form closed loops (it branches at {at:?})")]
    NotALoop {
        /// Where the loops branch or end.
        at: [f64; 3],
    },
    /// A loop does not lie in a plane.
    #[error(
        "the open boundary loop through {at:?} is not planar: it strays {deviation:.3e} from its \
         best plane ({relative:.1e} of the model size; a cap needs at most {limit:.0e})"
    )]
    NotPlanar {
        /// A point of the loop.
        at: [f64; 3],
        /// The largest distance of its control points from their best plane.
        deviation: f64,
        /// The same relative to the shell's extent.
        relative: f64,
        /// `CAP_RELATIVE_FLATNESS` (1e-6).
        limit: f64,
    },
}

/// A shell of faces joined by shared edges (see the module docs).
#[derive(Clone, Debug, Default)]
pub struct CadShell {
    vertices: Vec<Point3>,
    edges: Vec<ShellEdge>,
    faces: Vec<ShellFace>,
    tolerance: f64,
}

impl CadShell {
    /// An empty shell whose vertices coincide within `tolerance` (model units).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::cad::CadShell;
    ///
    /// let shell = CadShell::new(1e-6);
    /// assert_eq!(shell.tolerance(), 1e-6);
    /// assert!(shell.faces().is_empty() && shell.vertices().is_empty());
    /// ```
    pub fn new(tolerance: f64) -> CadShell {
        CadShell {
            tolerance: tolerance.max(0.0),
            ..CadShell::default()
        }
    }

    /// The shell of the patches `surfaces`, with the tolerance `SHELL_RELATIVE_TOLERANCE` (1e-9)
    /// of their control points' extent.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::BSplineSurface;
    /// use karkas::{Grid, Point};
    /// use karkas_io::cad::CadShell;
    ///
    /// // One square patch: one face, four corners, four edges, an open shell.
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let shell = CadShell::of_surfaces(&[BSplineSurface::new(linear.clone(), linear, control)?]);
    /// assert_eq!((shell.faces().len(), shell.vertices().len(), shell.edges().len()), (1, 4, 4));
    /// assert!(!shell.is_closed());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn of_surfaces(surfaces: &[BSplineSurface<3>]) -> CadShell {
        let points = surfaces
            .iter()
            .flat_map(|s| s.control_points().as_slice().iter().copied());
        let mut shell = CadShell::new(SHELL_RELATIVE_TOLERANCE * extent(points));
        for s in surfaces {
            shell.add_surface(s.clone());
        }
        shell
    }

    /// The vertices.
    pub fn vertices(&self) -> &[Point3] {
        &self.vertices
    }

    /// The edges.
    pub fn edges(&self) -> &[ShellEdge] {
        &self.edges
    }

    /// The faces.
    pub fn faces(&self) -> &[ShellFace] {
        &self.faces
    }

    /// The tolerance within which vertices coincide.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// Adds the patch `surface` bounded by its parameter rectangle (poles, seams and shared
    /// edges as the module docs say); returns its face index.
    pub fn add_surface(&mut self, surface: BSplineSurface<3>) -> usize {
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        let (u0, u1, v0, v1) = (du.start, du.end, dv.start, dv.end);
        // Counter-clockwise in (u, v): v = v0 forward, u = u1 forward, v = v1 back, u = u0 back;
        // each side's curve runs from the segment's start to its end.
        let sides = [
            (surface.curve_at_v(v0), [u0, v0], [u1, v0], true),
            (surface.curve_at_u(u1), [u1, v0], [u1, v1], true),
            (surface.curve_at_v(v1), [u0, v1], [u1, v1], false),
            (surface.curve_at_u(u0), [u0, v0], [u0, v1], false),
        ];
        let mut bound = Vec::new();
        for (curve, start, end, forward) in sides {
            if self.is_point(curve.control_points()) {
                continue;
            }
            let (edge, along) = self.edge_for(curve);
            let segment = ParameterSegment { start, end };
            bound.push(OrientedEdge {
                edge,
                forward: forward == along,
                on_face: Some(if along { segment } else { segment.reversed() }),
            });
        }
        self.faces.push(ShellFace {
            surface: FaceSurface::BSpline(surface),
            bound,
            same_sense: true,
        });
        self.faces.len() - 1
    }

    /// True when every edge is used twice, once in each sense (a closed shell: a solid's
    /// boundary).
    pub fn is_closed(&self) -> bool {
        !self.faces.is_empty()
            && self
                .uses()
                .iter()
                .all(|&(forward, backward)| forward == 1 && backward == 1)
    }

    /// Closes every loop of free edges by a planar face (see the module docs); returns the
    /// caps added, in the order of their loops.
    ///
    /// Errors: no free edge ([`CapError::NothingToCap`]); free edges that branch
    /// ([`CapError::NotALoop`]); a loop whose control points stray more than
    /// `CAP_RELATIVE_FLATNESS` (1e-6) of the shell's extent from their best plane
    /// ([`CapError::NotPlanar`]). Nothing is added on an error.
    pub fn cap_free_loops(&mut self) -> Result<Vec<Cap>, CapError> {
        let loops = self.free_loops()?;
        if loops.is_empty() {
            return Err(CapError::NothingToCap);
        }
        let size = extent(
            self.edges
                .iter()
                .flat_map(|e| e.curve.control_points().iter().copied()),
        );
        let mut planned = Vec::new();
        for bound in loops {
            // The loop's control polygon, in order (each edge's last point is the next's first).
            let points: Vec<Point3> = bound
                .iter()
                .flat_map(|o| {
                    let c = self.edges[o.edge].curve.control_points();
                    let along: Vec<Point3> = if o.forward {
                        c[..c.len() - 1].to_vec()
                    } else {
                        c[1..].iter().rev().copied().collect()
                    };
                    along
                })
                .collect();
            let at = points[0].0;
            let (plane, deviation) = polygon_plane(&points).ok_or(CapError::NotPlanar {
                at,
                deviation: f64::INFINITY,
                relative: f64::INFINITY,
                limit: CAP_RELATIVE_FLATNESS,
            })?;
            let relative = deviation / size.max(f64::MIN_POSITIVE);
            if relative > CAP_RELATIVE_FLATNESS {
                return Err(CapError::NotPlanar {
                    at,
                    deviation,
                    relative,
                    limit: CAP_RELATIVE_FLATNESS,
                });
            }
            let area = self.loop_area_vector(&bound);
            let length = area.norm();
            // The normal about which the loop runs counter-clockwise.
            let normal = if length > 0.0 && area.dot(plane.normal) < 0.0 {
                -plane.normal
            } else {
                plane.normal
            };
            planned.push((bound, Plane { normal, ..plane }, length));
        }
        let mut caps = Vec::new();
        for (bound, plane, area) in planned {
            self.faces.push(ShellFace {
                surface: FaceSurface::Plane(plane),
                bound,
                same_sense: true,
            });
            caps.push(Cap {
                face: self.faces.len() - 1,
                plane,
                area,
            });
        }
        Ok(caps)
    }

    /// The volume enclosed by the faces with their normals as they are (positive when they
    /// point outwards); meaningful for a closed shell.
    pub fn signed_volume(&self) -> f64 {
        self.faces
            .iter()
            .map(|face| {
                let sign = if face.same_sense { 1.0 } else { -1.0 };
                sign * match &face.surface {
                    FaceSurface::BSpline(s) => patch_flux(s),
                    FaceSurface::Plane(plane) => {
                        let oriented = if face.same_sense {
                            face.bound.clone()
                        } else {
                            reversed(&face.bound)
                        };
                        plane.origin.dot(self.loop_area_vector(&oriented)) / 3.0
                    }
                }
            })
            .sum()
    }

    /// Turns every face over when the normals point into the enclosed volume, so that they
    /// point out; returns the volume (positive). For a closed shell.
    pub fn orient_outward(&mut self) -> f64 {
        let volume = self.signed_volume();
        if volume < 0.0 {
            for face in &mut self.faces {
                face.same_sense = !face.same_sense;
                face.bound = reversed(&face.bound);
            }
        }
        volume.abs()
    }

    /// The uses of each edge by the faces' loops: (forward, backward).
    fn uses(&self) -> Vec<(usize, usize)> {
        let mut uses = vec![(0, 0); self.edges.len()];
        for o in self.faces.iter().flat_map(|f| &f.bound) {
            if o.forward {
                uses[o.edge].0 += 1;
            } else {
                uses[o.edge].1 += 1;
            }
        }
        uses
    }

    /// The loops of free edges, each oriented against the one use of its edges (as a face
    /// closing them runs).
    fn free_loops(&self) -> Result<Vec<Vec<OrientedEdge>>, CapError> {
        let uses = self.uses();
        let mut open: Vec<OrientedEdge> = uses
            .iter()
            .enumerate()
            .filter(|(_, &(f, b))| f + b == 1)
            .map(|(edge, &(f, _))| OrientedEdge {
                edge,
                forward: f == 0,
                on_face: None,
            })
            .collect();
        let ends = |o: &OrientedEdge| {
            let e = &self.edges[o.edge];
            if o.forward {
                (e.start, e.end)
            } else {
                (e.end, e.start)
            }
        };
        let mut loops = Vec::new();
        while let Some(first) = open.pop() {
            let (start, mut at) = ends(&first);
            let mut bound = vec![first];
            while at != start {
                let next: Vec<usize> = (0..open.len())
                    .filter(|&k| ends(&open[k]).0 == at)
                    .collect();
                if next.len() != 1 {
                    return Err(CapError::NotALoop {
                        at: self.vertices[at].0,
                    });
                }
                let o = open.swap_remove(next[0]);
                at = ends(&o).1;
                bound.push(o);
            }
            loops.push(bound);
        }
        Ok(loops)
    }

    /// `1/2 ∮ C × C'` along the loop `bound`.
    fn loop_area_vector(&self, bound: &[OrientedEdge]) -> Point3 {
        bound.iter().fold(Point3::ZERO, |sum, o| {
            let curve = &self.edges[o.edge].curve;
            let breaks: Vec<f64> = curve.distinct_knots().iter().map(|k| k.0).collect();
            let pieces = curve.degree().div_ceil(7).max(1);
            let a = area_vector(curve, &breaks, pieces);
            if o.forward {
                sum + a
            } else {
                sum - a
            }
        })
    }

    /// True when all `points` lie within the tolerance of the first.
    fn is_point(&self, points: &[Point3]) -> bool {
        points
            .iter()
            .all(|p| p.distance(points[0]) <= self.tolerance)
    }

    /// The vertex at `p`: an existing one within the tolerance, or a new one.
    fn vertex_for(&mut self, p: Point3) -> usize {
        match self
            .vertices
            .iter()
            .position(|q| q.distance(p) <= self.tolerance)
        {
            Some(k) => k,
            None => {
                self.vertices.push(p);
                self.vertices.len() - 1
            }
        }
    }

    /// The edge whose curve is `curve` (an existing one, in either direction, or a new one),
    /// and whether it runs along `curve`.
    fn edge_for(&mut self, curve: BSplineCurve<3>) -> (usize, bool) {
        let points = curve.control_points();
        let (Some(&first), Some(&last)) = (points.first(), points.last()) else {
            return (self.add_edge(0, 0, curve), true);
        };
        let (start, end) = (self.vertex_for(first), self.vertex_for(last));
        let same = |a: &[Point3], b: &mut dyn Iterator<Item = Point3>| {
            a.iter()
                .zip(b)
                .all(|(p, q)| p.distance(q) <= self.tolerance)
        };
        for (k, e) in self.edges.iter().enumerate() {
            let other = e.curve.control_points();
            if other.len() != points.len() {
                continue;
            }
            if e.start == start && e.end == end && same(other, &mut points.iter().copied()) {
                return (k, true);
            }
            if e.start == end && e.end == start && same(other, &mut points.iter().rev().copied()) {
                return (k, false);
            }
        }
        (self.add_edge(start, end, curve), true)
    }

    fn add_edge(&mut self, start: usize, end: usize, curve: BSplineCurve<3>) -> usize {
        self.edges.push(ShellEdge { start, end, curve });
        self.edges.len() - 1
    }
}

/// The loop run the other way.
fn reversed(bound: &[OrientedEdge]) -> Vec<OrientedEdge> {
    bound
        .iter()
        .rev()
        .map(|o| OrientedEdge {
            forward: !o.forward,
            ..*o
        })
        .collect()
}

/// `1/3 ∫∫ S · (S_u × S_v)` of a B-spline patch, on its knot cells.
fn patch_flux(s: &BSplineSurface<3>) -> f64 {
    let (su, sv) = (s.derivative_surface(1, 0), s.derivative_surface(0, 1));
    let breaks_u: Vec<f64> = s.distinct_knots_u().iter().map(|k| k.0).collect();
    let breaks_v: Vec<f64> = s.distinct_knots_v().iter().map(|k| k.0).collect();
    // The integrand has degree 3p - 1 in u (3q - 1 in v); the 8-point rule is exact to 15.
    let pieces = (3 * s.degree_u().max(s.degree_v())).div_ceil(16).max(1);
    flux_volume(
        |u, v| [s.eval(u, v), su.eval(u, v), sv.eval(u, v)],
        &breaks_u,
        &breaks_v,
        pieces,
    )
}

/// The diagonal of the bounding box of `points` (1 for none).
fn extent(points: impl Iterator<Item = Point3>) -> f64 {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for p in points {
        for c in 0..3 {
            low[c] = low[c].min(p[c]);
            high[c] = high[c].max(p[c]);
        }
    }
    let d = (0..3)
        .map(|c| (high[c] - low[c]).powi(2))
        .sum::<f64>()
        .sqrt();
    if d.is_finite() && d > 0.0 {
        d
    } else {
        1.0
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::{Curve, Grid, Point};
    use std::f64::consts::PI;

    /// A bilinear-in-u, closed-in-v ruled tube around z between radii `r0` and `r1` at
    /// heights 0 and `h` (its v direction: a degree-1 polygon of `n` sides, closed), or a
    /// cone with a pole when `r1 == 0`.
    fn tube(r0: f64, r1: f64, h: f64, n: usize) -> BSplineSurface<3> {
        let grid = Grid::from_fn(2, n + 1, |i, j| {
            let (r, z) = if i == 0 { (r0, 0.0) } else { (r1, h) };
            let phi = 2.0 * PI * (j % n) as f64 / n as f64;
            Point([r * phi.cos(), r * phi.sin(), z])
        });
        let mut kv = vec![0.0];
        kv.extend((0..=n).map(|j| j as f64 / n as f64));
        kv.push(1.0);
        BSplineSurface::new((1, vec![0.0, 0.0, 1.0, 1.0]), (1, kv), grid).unwrap()
    }

    /// The area of a regular `n`-gon of circumradius `r`.
    fn polygon_area(r: f64, n: usize) -> f64 {
        0.5 * n as f64 * r * r * (2.0 * PI / n as f64).sin()
    }

    #[test]
    fn a_closed_direction_has_one_seam_used_twice() {
        let shell = CadShell::of_surfaces(&[tube(1.0, 1.0, 2.0, 8)]);
        let face = &shell.faces()[0];
        // Seam, top circle, seam back, bottom circle: 3 edges, 4 uses.
        assert_eq!(shell.edges().len(), 3);
        assert_eq!(face.bound.len(), 4);
        assert_eq!(face.bound[0].edge, face.bound[2].edge);
        assert_ne!(face.bound[0].forward, face.bound[2].forward);
        assert_eq!(shell.vertices().len(), 2);
        assert!(!shell.is_closed());
    }

    #[test]
    fn a_pole_is_a_vertex_and_caps_close_a_solid() {
        // A cone: a pole at the top; the base circle is the one free loop.
        let (r, h, n) = (1.5, 2.0, 12);
        let mut shell = CadShell::of_surfaces(&[tube(r, 0.0, h, n)]);
        assert_eq!(shell.faces()[0].bound.len(), 3); // base, seam, seam back
        let caps = shell.cap_free_loops().unwrap();
        assert_eq!(caps.len(), 1);
        assert!((caps[0].area - polygon_area(r, n)).abs() < 1e-12);
        assert!(shell.is_closed());
        let volume = shell.orient_outward();
        let exact = polygon_area(r, n) * h / 3.0;
        assert!((volume - exact).abs() < 1e-12 * exact, "{volume} {exact}");
        assert!(shell.signed_volume() > 0.0);
        assert_eq!(shell.cap_free_loops().unwrap_err(), CapError::NothingToCap);
    }

    #[test]
    fn a_tube_gets_two_caps_and_encloses_its_prism() {
        let (r, h, n) = (0.7, 3.0, 9);
        let mut shell = CadShell::of_surfaces(&[tube(r, r, h, n)]);
        let caps = shell.cap_free_loops().unwrap();
        assert_eq!(caps.len(), 2);
        assert!(shell.is_closed());
        let volume = shell.orient_outward();
        let exact = polygon_area(r, n) * h;
        assert!((volume - exact).abs() < 1e-12 * exact, "{volume} {exact}");
        // The caps' normals point out: down at z = 0, up at z = h.
        for face in shell.faces() {
            if let FaceSurface::Plane(p) = face.surface {
                let outward = if p.origin[2] < 1.0 { -1.0 } else { 1.0 };
                let sign = if face.same_sense { 1.0 } else { -1.0 };
                assert!(sign * p.normal[2] * outward > 0.99, "{p:?}");
            }
        }
    }

    #[test]
    fn a_bent_boundary_is_not_capped() {
        let mut s = tube(1.0, 1.0, 2.0, 8);
        let mut grid = s.control_points().clone();
        grid.get_mut(1, 2).0[2] += 0.1;
        s = BSplineSurface::new((1, s.knots_u().to_vec()), (1, s.knots_v().to_vec()), grid)
            .unwrap();
        let mut shell = CadShell::of_surfaces(&[s]);
        let error = shell.cap_free_loops().unwrap_err();
        assert!(matches!(error, CapError::NotPlanar { deviation, .. } if deviation > 0.01));
        assert_eq!(shell.faces().len(), 1);
    }

    #[test]
    fn an_open_sheet_is_one_free_loop_of_four_edges() {
        let grid = Grid::from_fn(3, 3, |i, j| Point([i as f64, j as f64, 0.0]));
        let k = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let s = BSplineSurface::new((2, k.clone()), (2, k), grid).unwrap();
        let mut shell = CadShell::of_surfaces(&[s]);
        assert_eq!(shell.edges().len(), 4);
        let caps = shell.cap_free_loops().unwrap();
        assert!((caps[0].area - 4.0).abs() < 1e-12);
        // A flat sheet and its cap: closed, enclosing nothing.
        assert!(shell.is_closed());
        assert!(shell.signed_volume().abs() < 1e-12);
    }

    /// Every use of an edge by a B-spline face: the surface along its parameter segment is
    /// the edge's curve, parameter for parameter (at both ends and in between).
    fn assert_segments_follow_their_edges(shell: &CadShell) {
        for face in shell.faces() {
            let FaceSurface::BSpline(s) = &face.surface else {
                assert!(face.bound.iter().all(|o| o.on_face.is_none()));
                continue;
            };
            for o in &face.bound {
                let curve = &shell.edges()[o.edge].curve;
                let segment = o.on_face.expect("a B-spline face's edge has its segment");
                let d = curve.domain();
                for f in [0.0, 0.3, 0.5, 1.0] {
                    let t = d.start + f * (d.end - d.start);
                    let uv =
                        [0, 1].map(|c| segment.start[c] + f * (segment.end[c] - segment.start[c]));
                    let gap = s.eval(uv[0], uv[1]).distance(curve.eval(t));
                    assert!(gap < 1e-12, "{gap} at {f} of {o:?}");
                }
            }
        }
    }

    #[test]
    fn each_side_knows_its_line_in_the_parameter_plane() {
        // A seam used twice, a pole left out, a cap with none.
        let mut cone = CadShell::of_surfaces(&[tube(1.5, 0.0, 2.0, 12)]);
        assert_segments_follow_their_edges(&cone);
        cone.cap_free_loops().unwrap();
        cone.orient_outward();
        assert_segments_follow_their_edges(&cone);
        // Two sheets sharing a side that runs the other way on the second: its segment on
        // the second face runs backwards, over the second's own parameters.
        let first = Grid::from_fn(2, 3, |i, j| Point([i as f64, j as f64, 0.0]));
        let second = Grid::from_fn(2, 3, |i, j| {
            Point([1.0 + i as f64, 2.0 - j as f64, 0.5 * i as f64])
        });
        let k1 = vec![0.0, 0.0, 1.0, 1.0];
        let a = BSplineSurface::new(
            (1, k1.clone()),
            (2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
            first,
        );
        let b = BSplineSurface::new((1, k1), (2, vec![3.0, 3.0, 3.0, 7.0, 7.0, 7.0]), second);
        let shell = CadShell::of_surfaces(&[a.unwrap(), b.unwrap()]);
        assert_eq!(shell.edges().len(), 7);
        let shared = shell.faces()[1].bound[3];
        assert_eq!(shared.edge, shell.faces()[0].bound[1].edge);
        let segment = shared.on_face.unwrap();
        assert_eq!((segment.start, segment.end), ([0.0, 7.0], [0.0, 3.0]));
        assert_segments_follow_their_edges(&shell);
    }
}

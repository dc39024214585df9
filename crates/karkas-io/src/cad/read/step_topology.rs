//! STEP topology (ISO 10303-42) to a karkas [`Shape`]: the faces of shells and solids with
//! their loops of edges, free surfaces and free curves.
//!
//! Every `ADVANCED_FACE` and `FACE_SURFACE` becomes a [`Face`]: its surface a NURBS (an
//! analytic surface over the rectangle its loops span), its `EDGE_LOOP`s loops of [`Edge`]s
//! whose curves run between their vertices (`POLY_LOOP`s loops of segments; a `VERTEX_LOOP`
//! bounds nothing). Faces of closed shells bound a solid; an `ORIENTED_CLOSED_SHELL` or
//! `ORIENTED_FACE` with orientation `.F.` turns its faces over. Curves and surfaces that no
//! other entity uses (wireframes, curve and surface sets) are read as free curves and whole
//! faces. A face or curve on an entity type karkas does not read is skipped and counted.

use std::collections::{BTreeMap, HashMap, HashSet};
use std::path::Path;

use karkas::bspline::conic::line_segment;
use karkas::shape::{Edge, EdgeLoop, Face, Shape};
use karkas::{Curve, Point3};

use super::analytic::{BasisCurve, BasisSurface, SampledEdge};
use super::step_args::Args;
use super::step_cycles::push_refs;
use super::step_geometry::{read, Geometry, Outcome, Unread, CURVE_TYPES, SURFACE_TYPES};
use super::step_syntax::Exchange;
use crate::error::IoError;

/// The topology entity types read.
pub(crate) const TOPOLOGY_TYPES: &[&str] = &[
    "ADVANCED_FACE",
    "FACE_SURFACE",
    "ORIENTED_FACE",
    "FACE_BOUND",
    "FACE_OUTER_BOUND",
    "EDGE_LOOP",
    "VERTEX_LOOP",
    "POLY_LOOP",
    "ORIENTED_EDGE",
    "EDGE_CURVE",
    "VERTEX_POINT",
    "CLOSED_SHELL",
    "OPEN_SHELL",
    "ORIENTED_CLOSED_SHELL",
    "ORIENTED_OPEN_SHELL",
    "MANIFOLD_SOLID_BREP",
    "BREP_WITH_VOIDS",
    "SHELL_BASED_SURFACE_MODEL",
    "GEOMETRIC_CURVE_SET",
    "GEOMETRIC_SET",
    "COMPOSITE_CURVE",
    "COMPOSITE_CURVE_SEGMENT",
    "DEFINITIONAL_REPRESENTATION",
    "PCURVE",
    "CARTESIAN_POINT",
    "DIRECTION",
    "VECTOR",
    "AXIS1_PLACEMENT",
    "AXIS2_PLACEMENT_2D",
    "AXIS2_PLACEMENT_3D",
    "RATIONAL_B_SPLINE_CURVE",
    "RATIONAL_B_SPLINE_SURFACE",
];

/// Containers whose references do not make a curve or surface part of something else.
const SETS: &[&str] = &["GEOMETRIC_CURVE_SET", "GEOMETRIC_SET"];

/// How a face sits in its shell: whether it bounds a solid, and whether it is turned over.
#[derive(Clone, Copy, Debug, Default)]
struct Placement {
    solid: bool,
    flipped: bool,
}

/// Builds the shape of a STEP data section.
pub(crate) struct Topology<'a> {
    geometry: Geometry<'a>,
    path: &'a Path,
    exchange: &'a Exchange,
    /// Items not read, by their entity type and reason.
    pub unread: BTreeMap<Unread, usize>,
}

impl<'a> Topology<'a> {
    /// A builder over `exchange` whose angles are in units of `radians`.
    pub(crate) fn new(path: &'a Path, exchange: &'a Exchange, radians: f64) -> Self {
        Topology {
            geometry: Geometry::new(path, exchange, radians),
            path,
            exchange,
            unread: BTreeMap::new(),
        }
    }

    fn skip(&mut self, u: Unread) {
        *self.unread.entry(u).or_insert(0) += 1;
    }

    /// The instances whose (first) type is one of `names`, by increasing number.
    fn all(&self, names: &[&str]) -> Vec<u64> {
        let mut ids: Vec<u64> = self
            .exchange
            .instances
            .iter()
            .filter(|(_, i)| i.parts.iter().any(|p| names.contains(&&*p.name)))
            .map(|(&id, _)| id)
            .collect();
        ids.sort_unstable();
        ids
    }

    /// The arguments of the part named one of `names` of instance `id` (known to exist).
    fn args(&self, id: u64, names: &[&str]) -> Option<Args<'a>> {
        let instance = self.exchange.instances.get(&id)?;
        let part = instance.parts.iter().find(|p| names.contains(&&*p.name))?;
        Some(Args::of(self.path, id, instance, part))
    }

    /// The whole shape.
    pub fn shape(&mut self) -> Result<Shape, IoError> {
        let placements = self.placements()?;
        let mut shape = Shape::default();
        for id in self.all(&["ADVANCED_FACE", "FACE_SURFACE"]) {
            let place = placements.get(&id).copied().unwrap_or_default();
            match self.face(id, place)? {
                Outcome::Read(face) => shape.faces.push(face),
                Outcome::Skip(u) => self.skip(u),
            }
        }
        self.free_items(&mut shape)?;
        Ok(shape)
    }

    /// Which faces bound solids and which are turned over, from the shells.
    fn placements(&mut self) -> Result<HashMap<u64, Placement>, IoError> {
        let mut out: HashMap<u64, Placement> = HashMap::new();
        // Oriented shells first: the shell they turn over, and whether it is closed.
        let mut turned: HashMap<u64, bool> = HashMap::new();
        for id in self.all(&["ORIENTED_CLOSED_SHELL", "ORIENTED_OPEN_SHELL"]) {
            let Some(a) = self.args(id, &["ORIENTED_CLOSED_SHELL", "ORIENTED_OPEN_SHELL"]) else {
                continue;
            };
            a.count(4)?;
            let element = a.reference(2)?;
            if !a.logical(3, true)? {
                turned.insert(element, true);
            }
        }
        for id in self.all(&["CLOSED_SHELL", "OPEN_SHELL"]) {
            let Some(a) = self.args(id, &["CLOSED_SHELL", "OPEN_SHELL"]) else {
                continue;
            };
            a.count(2)?;
            let solid = a.name == "CLOSED_SHELL";
            let shell_flip = turned.contains_key(&id);
            for face in a.references(1)? {
                // A face may be an ORIENTED_FACE around the face itself.
                let (target, flip) = match self.args(face, &["ORIENTED_FACE"]) {
                    Some(o) => {
                        o.count(4)?;
                        (o.reference(2)?, !o.logical(3, true)?)
                    }
                    None => (face, false),
                };
                out.insert(
                    target,
                    Placement {
                        solid,
                        flipped: flip != shell_flip,
                    },
                );
            }
        }
        Ok(out)
    }

    /// The face `id` (an ADVANCED_FACE or FACE_SURFACE).
    fn face(&mut self, id: u64, place: Placement) -> Result<Outcome<Face>, IoError> {
        let Some(a) = self.args(id, &["ADVANCED_FACE", "FACE_SURFACE"]) else {
            return Ok(Outcome::Skip(Unread {
                entity: "ADVANCED_FACE".into(),
                reason: "missing",
            }));
        };
        a.count(4)?;
        let mut loops = Vec::new();
        for bound in a.references(1)? {
            let b = self
                .geometry
                .expect(bound, &a, &["FACE_BOUND", "FACE_OUTER_BOUND"])?;
            b.count(3)?;
            let outer = b.name == "FACE_OUTER_BOUND";
            let orientation = b.logical(2, true)?;
            let edges = read!(self.edge_loop(b.reference(1)?, &b));
            if !edges.is_empty() {
                let l = EdgeLoop::new(edges, outer);
                loops.push(if orientation { l } else { l.reversed() });
            }
        }
        let surface_id = a.reference(2)?;
        let basis = match self.geometry.surface(surface_id, &a)? {
            Outcome::Read(s) => s,
            Outcome::Skip(u) => {
                return Ok(Outcome::Skip(Unread {
                    entity: format!("faces on {}", u.entity),
                    reason: u.reason,
                }));
            }
        };
        let surface = {
            let sampled: Vec<Vec<SampledEdge<'_>>> = loops
                .iter()
                .map(|l| {
                    l.edges
                        .iter()
                        .map(|e| SampledEdge::new(Box::new(move |s| e.point_along(s))))
                        .collect()
                })
                .collect();
            match &basis {
                BasisSurface::Nurbs(s) => s.clone(),
                other => other.bounded(&sampled).map_err(|e| a.error(e))?,
            }
        };
        let mut face = Face {
            surface,
            loops,
            same_sense: a.logical(3, true)?,
            bounds_solid: place.solid,
        };
        if place.flipped {
            face.same_sense = !face.same_sense;
            face.loops = face.loops.into_iter().map(EdgeLoop::reversed).collect();
        }
        Ok(Outcome::Read(face))
    }

    /// The edges of a loop, in loop order.
    fn edge_loop(&mut self, id: u64, from: &Args<'_>) -> Result<Outcome<Vec<Edge>>, IoError> {
        let l = self
            .geometry
            .expect(id, from, &["EDGE_LOOP", "VERTEX_LOOP", "POLY_LOOP"])?;
        match l.name {
            "VERTEX_LOOP" => {
                l.count(2)?;
                Ok(Outcome::Read(Vec::new()))
            }
            "POLY_LOOP" => {
                l.count(2)?;
                let points = l
                    .references(1)?
                    .iter()
                    .map(|&p| self.geometry.point(p, &l))
                    .collect::<Result<Vec<_>, _>>()?;
                let mut edges = Vec::new();
                for k in 0..points.len() {
                    let (p, q) = (points[k], points[(k + 1) % points.len()]);
                    let length = p.distance(q);
                    if length > 0.0 {
                        let curve = line_segment(p, q, (0.0, length))
                            .map_err(|e| l.error(e.to_string()))?;
                        edges.push(Edge {
                            curve,
                            forward: true,
                        });
                    }
                }
                Ok(Outcome::Read(edges))
            }
            _ => {
                l.count(2)?;
                let mut edges = Vec::new();
                for oriented in l.references(1)? {
                    if let Some(e) = read!(self.oriented_edge(oriented, &l, 0)) {
                        edges.push(e);
                    }
                }
                Ok(Outcome::Read(edges))
            }
        }
    }

    /// An ORIENTED_EDGE (or a bare EDGE_CURVE): its curve between its vertices and the way
    /// the loop runs along it; `None` for an edge of zero length.
    fn oriented_edge(
        &mut self,
        id: u64,
        from: &Args<'_>,
        depth: usize,
    ) -> Result<Outcome<Option<Edge>>, IoError> {
        let e = self
            .geometry
            .expect(id, from, &["ORIENTED_EDGE", "EDGE_CURVE"])?;
        if e.name == "ORIENTED_EDGE" {
            e.count(5)?;
            if depth > 4 {
                return Err(e.error("oriented edges nest too deep"));
            }
            let orientation = e.logical(4, true)?;
            self.geometry.enter(id, from)?;
            let inner = self.oriented_edge(e.reference(3)?, &e, depth + 1);
            self.geometry.leave(id);
            let edge = read!(inner);
            return Ok(Outcome::Read(edge.map(|mut edge| {
                if !orientation {
                    edge.forward = !edge.forward;
                }
                edge
            })));
        }
        e.count(5)?;
        let vertex = |g: &Geometry<'_>, i: usize| -> Result<Point3, IoError> {
            let v = g.expect(e.reference(i)?, &e, &["VERTEX_POINT"])?;
            v.count(2)?;
            g.point(v.reference(1)?, &v)
        };
        let start = vertex(&self.geometry, 1)?;
        let end = vertex(&self.geometry, 2)?;
        let same_sense = e.logical(4, true)?;
        let curve = match self.geometry.curve(e.reference(3)?, &e)? {
            Outcome::Read(c) => c.basis,
            Outcome::Skip(u) => {
                return Ok(Outcome::Skip(Unread {
                    entity: format!("faces with edges on {}", u.entity),
                    reason: u.reason,
                }));
            }
        };
        let bounded = edge_curve(&curve, start, end, same_sense).map_err(|m| e.error(m))?;
        Ok(Outcome::Read(bounded.map(|(curve, along)| Edge {
            curve,
            forward: along,
        })))
    }

    /// Curves and surfaces no other entity uses, read as free curves and whole faces.
    fn free_items(&mut self, shape: &mut Shape) -> Result<(), IoError> {
        let mut used: HashSet<u64> = HashSet::new();
        for instance in self.exchange.instances.values() {
            if instance.parts.iter().any(|p| SETS.contains(&&*p.name)) {
                continue;
            }
            let mut refs = Vec::new();
            for p in &instance.parts {
                push_refs(&p.params, &mut refs);
            }
            used.extend(refs);
        }
        let mut names: Vec<&str> = CURVE_TYPES.to_vec();
        names.push("COMPOSITE_CURVE");
        for id in self.all(&names) {
            if used.contains(&id) {
                continue;
            }
            if let Some(c) = self.args(id, &["COMPOSITE_CURVE"]) {
                c.count(3)?;
                for segment in c.references(1)? {
                    let s = self.geometry.expect(
                        segment,
                        &c,
                        &[
                            "COMPOSITE_CURVE_SEGMENT",
                            "REPARAMETRISED_COMPOSITE_CURVE_SEGMENT",
                        ],
                    )?;
                    if s.params.len() < 3 {
                        s.count(3)?;
                    }
                    let sense = s.logical(1, true)?;
                    if let Some(curve) = self.free_curve(s.reference(2)?, &s)? {
                        shape
                            .curves
                            .push(if sense { curve } else { curve.reversed() });
                    }
                }
                continue;
            }
            let Some(instance) = self.exchange.instances.get(&id) else {
                continue;
            };
            let part = &instance.parts[0];
            let from = Args::of(self.path, id, instance, part);
            if let Some(curve) = self.free_curve(id, &from)? {
                shape.curves.push(curve);
            }
        }
        for id in self.all(SURFACE_TYPES) {
            if used.contains(&id) {
                continue;
            }
            let Some(instance) = self.exchange.instances.get(&id) else {
                continue;
            };
            let from = Args::of(self.path, id, instance, &instance.parts[0]);
            match self.geometry.surface(id, &from)? {
                Outcome::Read(BasisSurface::Nurbs(s)) => shape.faces.push(Face::whole(s)),
                Outcome::Read(other) => match other.bounded(&[]) {
                    Ok(s) => shape.faces.push(Face::whole(s)),
                    Err(_) => self.skip(Unread {
                        entity: from.name.to_owned(),
                        reason: "unbounded surface outside any face",
                    }),
                },
                Outcome::Skip(u) => self.skip(u),
            }
        }
        Ok(())
    }

    /// A curve read on its own: its natural stretch (a line has none and is skipped).
    fn free_curve(
        &mut self,
        id: u64,
        from: &Args<'_>,
    ) -> Result<Option<karkas::bspline::NurbsCurve<3>>, IoError> {
        match self.geometry.curve(id, from)? {
            Outcome::Read(c) => match c.basis.natural_range() {
                Some((a, b)) => Ok(Some(c.basis.bounded(a, b).map_err(|m| from.error(m))?)),
                None => {
                    self.skip(Unread {
                        entity: "LINE".into(),
                        reason: "unbounded line outside any edge",
                    });
                    Ok(None)
                }
            },
            Outcome::Skip(u) => {
                self.skip(u);
                Ok(None)
            }
        }
    }
}

/// The stretch of `curve` between the vertices `start` and `end` of an EDGE_CURVE (which
/// runs along the curve's parameter when `same_sense`): the bounded curve and whether the
/// edge runs along its parameter; `None` for an open curve's empty stretch.
fn edge_curve(
    curve: &BasisCurve,
    start: Point3,
    end: Point3,
    same_sense: bool,
) -> Result<Option<(karkas::bspline::NurbsCurve<3>, bool)>, String> {
    let ta = curve.parameter_of(start)?;
    let tb = curve.parameter_of(end)?;
    let (mut lo, mut hi) = if same_sense { (ta, tb) } else { (tb, ta) };
    let mut along = same_sense;
    let size = start.distance(end);
    match curve.period() {
        Some(p) => {
            // Same vertex (or the same point): the whole turn from it. Two vertices whose
            // stretch passes the curve's parameter 0 (from 300 to 30 degrees): on past a turn.
            let span = curve.point(lo).distance(curve.point(lo + 0.5 * p));
            if hi.to_bits() == lo.to_bits() || (size <= 1e-9 * span && (hi - lo).abs() < 1e-6 * p) {
                hi = lo + p;
            } else if hi <= lo + 1e-12 * p {
                hi += p;
            }
            // More than a turn by more than rounding: `lo + p - lo` exceeds `p` by an ulp when
            // `lo` lies just below a turn (a full circle whose vertex is at angle -6e-16).
            while hi - lo > p * (1.0 + 1e-12) {
                hi -= p;
            }
            if let BasisCurve::Nurbs(c) = curve {
                // Snap to the domain ends (the stretch is then the curve itself).
                let d = c.domain();
                if (lo - d.start).abs() <= 1e-12 * p && (hi - d.end).abs() <= 1e-12 * p {
                    (lo, hi) = (d.start, d.end);
                }
            }
        }
        None => {
            if hi < lo {
                std::mem::swap(&mut lo, &mut hi);
                along = !along;
            }
            if let BasisCurve::Nurbs(c) = curve {
                let d = c.domain();
                let tol = 1e-9 * d.length();
                if (lo - d.start).abs() <= tol {
                    lo = d.start;
                }
                if (hi - d.end).abs() <= tol {
                    hi = d.end;
                }
            }
            if hi.is_nan() || hi <= lo {
                return Ok(None);
            }
        }
    }
    Ok(Some((curve.bounded(lo, hi)?, along)))
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::bspline::sweep::Frame;

    #[test]
    fn an_arc_across_the_circles_parameter_zero_is_the_short_way_round() {
        // From 300 to 30 degrees (90 degrees through 0), and the same arc's vertex just below
        // a turn (an angle of -4e-6 rad, as Open CASCADE writes a revolved profile's circle).
        let frame = Frame::new(
            Point3::new([1.0, -2.0, 0.5]),
            Point3::new([0.1, 0.05, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap();
        let circle = BasisCurve::Conic {
            frame,
            a: 2.0,
            b: 2.0,
        };
        for (from, to, length) in [(300.0f64, 30.0f64, 90.0f64), (-0.00023, 249.99977, 250.0)] {
            let (a, b) = (
                circle.point(from.to_radians()),
                circle.point(to.to_radians()),
            );
            for same_sense in [true, false] {
                let (start, end) = if same_sense { (a, b) } else { (b, a) };
                let (curve, along) = edge_curve(&circle, start, end, same_sense)
                    .unwrap()
                    .unwrap();
                let d = curve.domain();
                assert!(
                    (d.length() - length.to_radians()).abs() < 1e-9,
                    "{from} to {to}: {d:?}"
                );
                assert_eq!(along, same_sense);
                let ends = [curve.eval(d.start), curve.eval(d.end)];
                assert!(ends[0].distance(a) < 1e-12 && ends[1].distance(b) < 1e-12);
            }
        }
    }

    #[test]
    fn a_full_circle_on_one_vertex_just_below_a_turn_is_the_whole_circle() {
        // The vertex's angle is -6.1e-16 (rem_euclid: just below 2 pi), so lo + 2 pi - lo
        // rounds one ulp above 2 pi.
        let z = Point3::new([-1.898746e-16, 3.798993e-17, -1.0]);
        let x = Point3::new([-1.0, 6.106227e-16, 1.898746e-16]);
        let centre = Point3::new([-4.423929967573, 2.553033135614, 2.24866721196]);
        let frame = Frame::new(centre, z, x).unwrap();
        let circle = BasisCurve::Conic {
            frame,
            a: 0.5,
            b: 0.5,
        };
        let vertex = Point3::new([-4.923929967573, 2.553033135614, 2.24866721196]);
        for same_sense in [true, false] {
            let (curve, _) = edge_curve(&circle, vertex, vertex, same_sense)
                .unwrap()
                .unwrap();
            let d = curve.domain();
            assert!((d.length() - std::f64::consts::TAU).abs() < 1e-12, "{d:?}");
            let opposite = curve.eval(d.start + 0.5 * d.length());
            assert!((opposite.distance(vertex) - 1.0).abs() < 1e-12);
        }
    }
}

//! Triangle meshes of a CAD shape's trimmed faces to a chordal tolerance (`karkas convert
//! PART.step OUT.stl`).
//!
//! Each face is meshed in its surface's parameters (its [`FaceDomain`]: the rectangle and
//! the trimming loops as polygons in `(u, v)`):
//! - **Parameter lines.** Every knot span of the surface is cut into `n` equal steps with
//!   `n = ceil(h sqrt(M / (4 T)))`, `h` the span's length, `M` the largest second derivative
//!   across it (`|S_uu|` for `u`, `|S_vv|` for `v`, sampled at the span's ends and middle
//!   against every span of the other direction) and `T` the tolerance: a linear piece of
//!   length `h / n` leaves a curve of second derivative `M` by at most `M (h / n)^2 / 8 <= T / 2`,
//!   the other half left for the cross term. Spans of degree one (planes, ruled directions)
//!   stay one step.
//! - **Triangulation.** The nodes of those lines inside the face, the loops' vertices and the
//!   loops' segments as constraints (each loop thinned to the vertices that keep it within
//!   half the tolerance on the surface, its corners and the ends of a pole kept:
//!   [`super::face_loops`]) go into a constrained Delaunay triangulation (the `spade`
//!   crate, built for it) in parameters scaled by the surface's mean speed in each direction,
//!   so that triangles are well shaped on the surface (and by a power of two that keeps any
//!   model's parameters within the range `spade` takes); nodes within a third of a step of a
//!   loop are left out (no slivers along the trim). The nodes are bulk loaded (near linear
//!   time), the loops inserted after them. A triangle is kept when its centroid lies inside
//!   the thinned loops and it is not flat in the parameters; it is wound counter-clockwise
//!   seen from the face's outside ([`Face::same_sense`]).
//! - **Refinement.** A side whose chord passes farther than the tolerance from the surface at
//!   its middle is split there, round by round ([`refine`]): the parameter lines bound the
//!   sides along them, not a side across them, which a face trimmed by a curve can have
//!   (a fillet's cylinder cut by a mitre, whose straight direction has lines at its ends).
//! - **Bounded size.** A mesh of more than `MAX_VERTICES` (2^22, about 4.2 million) vertices,
//!   counted from each face's parameter lines before it is triangulated, is refused with a
//!   message asking for a larger tolerance: a tolerance far below the model's size costs an
//!   error, not unbounded memory or time.
//! - **One surface of all faces.** Vertices of all faces within `1e-9` of the model's size are
//!   merged (shared corners, seams, poles), triangles that collapse are dropped, boundary
//!   vertices of two faces within a hundredth of the tolerance are merged (one edge sampled
//!   at the same places on two surfaces, apart by the model's gap), and where two
//!   faces sampled a shared edge at different points, each boundary vertex is inserted into
//!   the nearest boundary segment of every other face that passes within the tolerance of it
//!   and runs along one of its own boundary sides (the T-junctions closed,
//!   [`super::shape_seams`]), so that a closed shell comes out watertight.
//! - **One winding.** Faces that run a shared side the same way (an IGES solid, whose faces
//!   do not say their outside) are turned to agree, and a closed part outward
//!   ([`super::face_orientation`]).
//!
//! Written here rather than taken from a crate: no maintained Rust crate meshes trimmed NURBS
//! faces; the triangulation itself is `spade`'s.

use karkas::bspline::NurbsSurface;
use karkas::core::Surface;
use karkas::shape::{Face, FaceDomain, ParameterLoop, Shape};
use karkas::Point3;
use spade::{
    mitigate_underflow, validate_vertex, ConstrainedDelaunayTriangulation, HasPosition, Point2,
    Triangulation,
};

use crate::mesh::face_loops::{nodes_near_loops, simplified};
use crate::mesh::face_orientation::orient_faces;
use crate::mesh::shape_seams::{Soup, Tri};
use crate::mesh::TriangleMesh;

/// The most vertices one mesh may have before it is refused (about twice as many triangles):
/// this bounds the memory (a few hundred bytes a vertex while a face is triangulated) and the
/// time of a tolerance far below the model's size.
const MAX_VERTICES: usize = 1 << 22;

/// A triangle whose doubled area in the parameter plane is at most this share of its longest
/// side squared is flat there (see [`flat_in_parameters`]).
const FLAT: f64 = 1e-9;

/// Boundary vertices of two faces closer than this share of the tolerance are one vertex.
const SNAP: f64 = 1e-2;

/// The most rounds of [`refine`]: each halves the sides it splits, and a side's distance
/// from the surface falls with the square of its length.
const REFINE_ROUNDS: usize = 24;

/// What can stop a shape from being meshed.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ShapeMeshError {
    /// The chordal tolerance is not a positive finite number.
    #[error("the chordal tolerance must be a positive number, got {0}")]
    Tolerance(f64),
    /// The shape has no faces.
    #[error("the model has no faces to mesh")]
    NoFaces,
    /// The mesh would take more vertices than the limit.
    #[error(
        "meshing face {face} to the tolerance takes more than {limit} vertices (the most a mesh \
         may have, about twice as many triangles); give a larger tolerance"
    )]
    TooManyVertices {
        /// The face (from 0) at which the limit was passed.
        face: usize,
        /// The limit.
        limit: usize,
    },
    /// A face's points could not be triangulated.
    #[error("face {face}: its parameter points cannot be triangulated ({reason})")]
    Triangulation {
        /// The face, from 0.
        face: usize,
        /// Why, as the triangulation says it.
        reason: String,
    },
    /// A face's trimming loops could not be placed on its surface.
    #[error("face {face}: {source}")]
    Domain {
        /// The face, from 0.
        face: usize,
        /// Why.
        source: karkas::Error,
    },
}

/// The triangle mesh of `shape`'s faces within `tolerance` of them (see the module docs).
///
/// # Examples
///
/// ```
/// use karkas::bspline::{BSplineSurface, NurbsSurface};
/// use karkas::shape::{Face, Shape};
/// use karkas::{Grid, Point};
/// use karkas_io::mesh::shape_mesh;
///
/// // A flat unit square: two triangles, whatever the tolerance.
/// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
/// let knots = vec![0.0, 0.0, 1.0, 1.0];
/// let square = BSplineSurface::new((1, knots.clone()), (1, knots), control)?;
/// let shape = Shape { faces: vec![Face::whole(NurbsSurface::from_bspline(&square))], curves: vec![] };
/// let mesh = shape_mesh(&shape, 1e-3).expect("a square meshes");
/// assert_eq!((mesh.positions.len(), mesh.triangles.len()), (4, 2));
/// # Ok::<(), karkas::Error>(())
/// ```
pub fn shape_mesh(shape: &Shape, tolerance: f64) -> Result<TriangleMesh, ShapeMeshError> {
    if shape.faces.is_empty() {
        return Err(ShapeMeshError::NoFaces);
    }
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(ShapeMeshError::Tolerance(tolerance));
    }
    let mut soup = Soup::default();
    for (k, face) in shape.faces.iter().enumerate() {
        let domain =
            FaceDomain::of(face).map_err(|source| ShapeMeshError::Domain { face: k, source })?;
        face_triangles(face, &domain, tolerance, k, &mut soup)?;
    }
    let weld = 1e-9 * shape.size().max(f64::MIN_POSITIVE);
    soup.weld(weld);
    soup.snap_boundaries((SNAP * tolerance).max(weld));
    soup.close_t_junctions(tolerance.max(weld));
    orient_faces(&soup.positions, &mut soup.triangles);
    Ok(TriangleMesh {
        positions: soup.positions,
        normals: Vec::new(),
        triangles: soup.triangles.iter().map(|t| t.corners).collect(),
        grid: None,
    })
}

/// The parameter lines of one direction of `s` (see the module docs): `along_u` for `u`.
fn parameter_lines(s: &NurbsSurface<3>, along_u: bool, tolerance: f64) -> Vec<f64> {
    let (mine, other) = if along_u {
        (
            breaks(s.knots_u(), s.domain_u()),
            breaks(s.knots_v(), s.domain_v()),
        )
    } else {
        (
            breaks(s.knots_v(), s.domain_v()),
            breaks(s.knots_u(), s.domain_u()),
        )
    };
    let degree = if along_u { s.degree_u() } else { s.degree_v() };
    let mut lines = vec![mine[0]];
    for w in mine.windows(2) {
        // Past the vertex limit the face is refused (see `face_triangles`): stop counting.
        if lines.len() > MAX_VERTICES {
            break;
        }
        let (a, b) = (w[0], w[1]);
        let steps = if degree < 2 && !s.is_rational() {
            1
        } else {
            let m = largest_second_derivative(s, along_u, (a, b), &other);
            let n = ((b - a) * (m / (4.0 * tolerance)).sqrt()).ceil();
            if n.is_finite() {
                (n as usize).clamp(1, MAX_VERTICES)
            } else {
                MAX_VERTICES
            }
        };
        lines.extend((1..=steps).map(|k| {
            if k == steps {
                b
            } else {
                a + (b - a) * k as f64 / steps as f64
            }
        }));
    }
    lines
}

/// The distinct knots of `knots` inside `domain`, its ends included.
fn breaks(knots: &[f64], domain: karkas::core::Interval) -> Vec<f64> {
    let mut out = vec![domain.start];
    for &k in knots {
        if k > *out.last().unwrap_or(&domain.start) && k < domain.end {
            out.push(k);
        }
    }
    out.push(domain.end);
    out
}

/// The largest `|S_uu|` (`along_u`) or `|S_vv|` over the span `span` of that direction,
/// sampled at the span's ends and middle against the other direction's breaks and midpoints.
fn largest_second_derivative(
    s: &NurbsSurface<3>,
    along_u: bool,
    span: (f64, f64),
    other: &[f64],
) -> f64 {
    let mut across: Vec<f64> = other.to_vec();
    across.extend(other.windows(2).map(|w| 0.5 * (w[0] + w[1])));
    let mut m = 0.0f64;
    for t in [span.0, 0.5 * (span.0 + span.1), span.1] {
        for &o in &across {
            let (u, v) = if along_u { (t, o) } else { (o, t) };
            let d = s.second_order(u, v);
            let second = if along_u { d[3] } else { d[5] };
            m = m.max(second.norm());
        }
    }
    m
}

/// The mean speeds `(|S_u|, |S_v|)` over the nodes: the scales that make parameter
/// distances surface distances on average (1 where a direction does not move).
fn speeds(s: &NurbsSurface<3>, us: &[f64], vs: &[f64]) -> (f64, f64) {
    let (mut su, mut sv, mut n) = (0.0, 0.0, 0.0);
    let step = |len: usize| (len / 16).max(1);
    for &u in us.iter().step_by(step(us.len())) {
        for &v in vs.iter().step_by(step(vs.len())) {
            let d = s.second_order(u, v);
            su += d[1].norm();
            sv += d[2].norm();
            n += 1.0;
        }
    }
    let mean = |x: f64| {
        if x > 0.0 && (x / n).is_finite() {
            x / n
        } else {
            1.0
        }
    };
    (mean(su), mean(sv))
}

/// A point of a face's triangulation: where it lies in the scaled parameter plane, and its
/// surface parameters.
#[derive(Clone, Copy)]
struct Node {
    at: Point2<f64>,
    uv: [f64; 2],
}

impl HasPosition for Node {
    type Scalar = f64;

    fn position(&self) -> Point2<f64> {
        self.at
    }
}

/// Places surface parameters in the triangulation's plane: `u` and `v` times the mean speeds,
/// the whole scaled by the power of two that brings the domain's farthest corner near 1, so
/// that models of any size stay within the range `spade` accepts (a power of two changes no
/// rounding, hence no triangle).
struct ParameterPlane {
    scale: (f64, f64),
}

impl ParameterPlane {
    fn new(s: &NurbsSurface<3>, speeds: (f64, f64)) -> ParameterPlane {
        let (du, dv) = (s.domain_u(), s.domain_v());
        let far = (du.start.abs().max(du.end.abs()) * speeds.0)
            .max(dv.start.abs().max(dv.end.abs()) * speeds.1);
        let power = if far > 0.0 && far.is_finite() {
            (-far.log2().ceil()).clamp(-1000.0, 1000.0) as i32
        } else {
            0
        };
        let unit = 2f64.powi(power);
        ParameterPlane {
            scale: (speeds.0 * unit, speeds.1 * unit),
        }
    }

    /// The node of `uv`; `None` where the triangulation cannot take it (not finite).
    fn node(&self, uv: [f64; 2]) -> Option<Node> {
        let at = mitigate_underflow(Point2::new(uv[0] * self.scale.0, uv[1] * self.scale.1));
        validate_vertex(&at).ok().map(|()| Node { at, uv })
    }
}

/// Meshes one face into `soup` (see the module docs): the grid's nodes are loaded at once
/// (`spade`'s bulk loading, near linear in their number), the loops' vertices and sides added
/// to them.
fn face_triangles(
    face: &Face,
    domain: &FaceDomain,
    tolerance: f64,
    index: usize,
    soup: &mut Soup,
) -> Result<(), ShapeMeshError> {
    let s = &face.surface;
    let us = parameter_lines(s, true, tolerance);
    let vs = parameter_lines(s, false, tolerance);
    if us
        .len()
        .saturating_mul(vs.len())
        .saturating_add(soup.positions.len())
        > MAX_VERTICES
    {
        return Err(ShapeMeshError::TooManyVertices {
            face: index,
            limit: MAX_VERTICES,
        });
    }
    let scale = speeds(s, &us, &vs);
    let plane = ParameterPlane::new(s, scale);
    let near_loops = nodes_near_loops(domain, &us, &vs, scale);
    let polygon = mesh_polygon(s, domain, tolerance);
    let mut nodes = Vec::new();
    for (i, &u) in us.iter().enumerate() {
        for (j, &v) in vs.iter().enumerate() {
            if !near_loops[i * vs.len() + j] && polygon.contains(u, v) {
                nodes.extend(plane.node([u, v]));
            }
        }
    }
    let mut cdt = ConstrainedDelaunayTriangulation::<Node>::bulk_load(nodes).map_err(|e| {
        ShapeMeshError::Triangulation {
            face: index,
            reason: e.to_string(),
        }
    })?;
    for l in &polygon.loops {
        let handles: Vec<_> = l
            .points
            .iter()
            .filter_map(|&p| cdt.insert(plane.node(p)?).ok())
            .collect();
        for k in 0..handles.len() {
            let (a, b) = (handles[k], handles[(k + 1) % handles.len()]);
            if a != b && cdt.can_add_constraint(a, b) {
                cdt.add_constraint(a, b);
            }
        }
    }
    refine(
        &mut cdt,
        s,
        &plane,
        &polygon,
        tolerance,
        index,
        soup.positions.len(),
    )?;
    emit(face, &cdt, &polygon, index, soup);
    Ok(())
}

/// The face as its mesh bounds it: the loops thinned to the vertices that go into the
/// triangulation ([`simplified`]). Nodes and triangles are kept inside these, not inside the
/// loops as sampled, or those between a side and the stretch of loop it stands for overlap
/// the ones inside the side.
fn mesh_polygon(s: &NurbsSurface<3>, domain: &FaceDomain, tolerance: f64) -> FaceDomain {
    FaceDomain {
        u: domain.u,
        v: domain.v,
        loops: domain
            .loops
            .iter()
            .map(|l| ParameterLoop {
                points: simplified(s, &l.points, tolerance / 2.0),
            })
            .collect(),
    }
}

/// Adds the triangles of `cdt` inside `polygon` to `soup`, wound counter-clockwise seen
/// from the face's outside; those flat in the parameters are left out (corners on one line
/// there, to round-off: a flap of three loop vertices along an iso-parameter line, which is
/// a real triangle on the surface).
fn emit(
    face: &Face,
    cdt: &ConstrainedDelaunayTriangulation<Node>,
    polygon: &FaceDomain,
    index: usize,
    soup: &mut Soup,
) {
    let s = &face.surface;
    let base = soup.positions.len();
    soup.positions.extend(
        cdt.vertices()
            .map(|n| s.eval(n.data().uv[0], n.data().uv[1])),
    );
    for f in cdt.inner_faces() {
        let v = f.vertices();
        let c = v.map(|h| h.data().uv);
        let centre = [
            (c[0][0] + c[1][0] + c[2][0]) / 3.0,
            (c[0][1] + c[1][1] + c[2][1]) / 3.0,
        ];
        if !polygon.contains(centre[0], centre[1]) || flat_in_parameters(v.map(|h| h.data().at)) {
            continue;
        }
        let mut t = v.map(|h| (base + h.fix().index()) as u32);
        if !face.same_sense {
            t.swap(1, 2);
        }
        soup.triangles.push(Tri {
            corners: t,
            face: index,
        });
    }
}

/// Splits the sides of the face's triangles whose chord passes farther than the tolerance
/// from the surface at its middle ([`off_surface`]), round by round, the loops' sides left as they are. The parameter
/// lines bound the sides along the lines, not a side across them: a ruled face trimmed by
/// a curve, whose straight direction has lines at its two ends only, was fanned from one
/// corner by chords through the body. A side no longer than the tolerance is left: its
/// middle is within half its length of its ends, on the surface.
fn refine(
    cdt: &mut ConstrainedDelaunayTriangulation<Node>,
    s: &NurbsSurface<3>,
    plane: &ParameterPlane,
    domain: &FaceDomain,
    tolerance: f64,
    index: usize,
    base: usize,
) -> Result<(), ShapeMeshError> {
    for _ in 0..REFINE_ROUNDS {
        let at: Vec<Point3> = cdt
            .vertices()
            .map(|n| s.eval(n.data().uv[0], n.data().uv[1]))
            .collect();
        let mut seen = std::collections::HashSet::new();
        let mut splits = Vec::new();
        for f in cdt.inner_faces() {
            let c = f.vertices().map(|h| h.data().uv);
            let centre = [
                (c[0][0] + c[1][0] + c[2][0]) / 3.0,
                (c[0][1] + c[1][1] + c[2][1]) / 3.0,
            ];
            if !domain.contains(centre[0], centre[1]) {
                continue;
            }
            for e in f.adjacent_edges() {
                if e.is_constraint_edge() || !seen.insert(e.fix().as_undirected()) {
                    continue;
                }
                let [a, b] = e.vertices();
                let (ua, ub) = (a.data().uv, b.data().uv);
                let mid = [0.5 * (ua[0] + ub[0]), 0.5 * (ua[1] + ub[1])];
                let (pa, pb) = (at[a.fix().index()], at[b.fix().index()]);
                if pa.distance(pb) > tolerance
                    && off_surface(s, mid, (pa + pb) * 0.5) > tolerance
                    && domain.contains(mid[0], mid[1])
                {
                    splits.extend(plane.node(mid));
                }
            }
        }
        if splits.is_empty() {
            return Ok(());
        }
        if base + cdt.num_vertices() + splits.len() > MAX_VERTICES {
            return Err(ShapeMeshError::TooManyVertices {
                face: index,
                limit: MAX_VERTICES,
            });
        }
        for node in splits {
            let _ = cdt.insert(node);
        }
    }
    Ok(())
}

/// How far the chord's middle `chord` lies off the surface at the side's middle parameters
/// `uv`: along the surface's normal there, since near a pole those parameters may land
/// beside the chord's middle rather than under it. 0 where the normal is not defined.
fn off_surface(s: &NurbsSurface<3>, uv: [f64; 2], chord: Point3) -> f64 {
    let n = karkas::geometry::surface_frame::normal(s, uv[0], uv[1]);
    let d = (chord - s.eval(uv[0], uv[1])).dot(n).abs();
    if d.is_nan() {
        0.0
    } else {
        d
    }
}

/// True when the triangle `at` (in the scaled parameter plane) has no area to speak of: its
/// corners lie on one line to within round-off of their coordinates.
fn flat_in_parameters(at: [Point2<f64>; 3]) -> bool {
    let (a, b) = (
        [at[1].x - at[0].x, at[1].y - at[0].y],
        [at[2].x - at[0].x, at[2].y - at[0].y],
    );
    let c = [at[2].x - at[1].x, at[2].y - at[1].y];
    let longest = [a, b, c]
        .iter()
        .map(|d| d[0] * d[0] + d[1] * d[1])
        .fold(0.0f64, f64::max);
    (a[0] * b[1] - a[1] * b[0]).abs() <= FLAT * longest
}

#[cfg(test)]
mod tests {
    use super::flat_in_parameters;
    use spade::Point2;

    #[test]
    fn three_points_of_one_line_to_round_off_are_flat_and_a_thin_triangle_is_not() {
        let at = |y: f64| {
            [
                Point2::new(0.0, 0.0),
                Point2::new(0.5, y),
                Point2::new(1.0, 0.0),
            ]
        };
        assert!(flat_in_parameters(at(1e-16)));
        assert!(flat_in_parameters(at(-1e-17)));
        assert!(!flat_in_parameters(at(1e-3)));
    }
}

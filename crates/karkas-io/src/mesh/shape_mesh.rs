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
//!   half the tolerance on the surface) go into a constrained Delaunay triangulation (the `spade`
//!   crate, built for it) in parameters scaled by the surface's mean speed in each direction,
//!   so that triangles are well shaped on the surface (and by a power of two that keeps any
//!   model's parameters within the range `spade` takes); nodes within a third of a step of a
//!   loop are left out (no slivers along the trim). The nodes are bulk loaded (near linear
//!   time), the loops inserted after them. A triangle is kept when its centroid lies
//!   in the face; it is wound counter-clockwise seen from the face's outside
//!   ([`Face::same_sense`]).
//! - **Bounded size.** A mesh of more than `MAX_VERTICES` (2^22, about 4.2 million) vertices,
//!   counted from each face's parameter lines before it is triangulated, is refused with a
//!   message asking for a larger tolerance: a tolerance far below the model's size costs an
//!   error, not unbounded memory or time.
//! - **One surface of all faces.** Vertices of all faces within `1e-9` of the model's size are
//!   merged (shared corners, seams, poles), triangles that collapse are dropped, and where two
//!   faces sampled a shared edge at different points, each boundary vertex is inserted into
//!   the nearest boundary segment of every other face that passes within the tolerance of it
//!   (the T-junctions closed), so that a closed shell comes out watertight.
//!
//! Written here rather than taken from a crate: no maintained Rust crate meshes trimmed NURBS
//! faces; the triangulation itself is `spade`'s.

use std::collections::{BTreeMap, HashMap};

use karkas::bspline::NurbsSurface;
use karkas::core::Surface;
use karkas::shape::{Face, FaceDomain, Shape};
use karkas::Point3;
use spade::{
    mitigate_underflow, validate_vertex, ConstrainedDelaunayTriangulation, HasPosition, Point2,
    Triangulation,
};

use crate::mesh::TriangleMesh;

/// The most vertices one mesh may have before it is refused (about twice as many triangles):
/// this bounds the memory (a few hundred bytes a vertex while a face is triangulated) and the
/// time of a tolerance far below the model's size.
const MAX_VERTICES: usize = 1 << 22;

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
    soup.close_t_junctions(tolerance.max(weld));
    Ok(TriangleMesh {
        positions: soup.positions,
        normals: Vec::new(),
        triangles: soup.triangles.iter().map(|t| t.corners).collect(),
        grid: None,
    })
}

/// Triangles of many faces before they are joined.
#[derive(Default)]
struct Soup {
    positions: Vec<Point3>,
    triangles: Vec<Tri>,
}

/// A triangle and the face it came from.
#[derive(Clone, Copy)]
struct Tri {
    corners: [u32; 3],
    face: usize,
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
    let mut nodes = Vec::new();
    for (i, &u) in us.iter().enumerate() {
        for (j, &v) in vs.iter().enumerate() {
            if !near_loops[i * vs.len() + j] && domain.contains(u, v) {
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
    for l in &domain.loops {
        let kept = simplified(s, &l.points, tolerance / 2.0);
        let handles: Vec<_> = kept
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
        if !domain.contains(centre[0], centre[1]) {
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
    Ok(())
}

/// The vertices of the closed loop `points` (in `s`'s parameters) that keep its image on the
/// surface within `tolerance` of the loop's (Douglas and Peucker's rule on the surface points,
/// the loop cut at its first vertex and the one farthest from it).
fn simplified(s: &NurbsSurface<3>, points: &[[f64; 2]], tolerance: f64) -> Vec<[f64; 2]> {
    let n = points.len();
    if n < 4 {
        return points.to_vec();
    }
    let at: Vec<Point3> = points.iter().map(|p| s.eval(p[0], p[1])).collect();
    let far = (1..n)
        .max_by(|&a, &b| at[a].distance(at[0]).total_cmp(&at[b].distance(at[0])))
        .unwrap_or(n / 2);
    let mut keep = vec![false; n + 1];
    keep[0] = true;
    keep[far] = true;
    keep[n] = true;
    let mut stack = vec![(0, far), (far, n)];
    while let Some((a, b)) = stack.pop() {
        let (pa, pb) = (at[a % n], at[b % n]);
        let worst = (a + 1..b)
            .map(|k| (k, along(at[k], pa, pb)))
            .map(|(k, (t, d))| {
                (
                    k,
                    if (0.0..=1.0).contains(&t) {
                        d
                    } else {
                        at[k].distance(pa).min(at[k].distance(pb))
                    },
                )
            })
            .max_by(|x, y| x.1.total_cmp(&y.1));
        if let Some((k, d)) = worst {
            if d > tolerance {
                keep[k] = true;
                stack.push((a, k));
                stack.push((k, b));
            }
        }
    }
    (0..n).filter(|&k| keep[k]).map(|k| points[k]).collect()
}

/// For each node `(us[i], vs[j])` (row-major), whether it lies within a third of the
/// smaller adjacent step of a loop segment, in scaled parameters.
fn nodes_near_loops(domain: &FaceDomain, us: &[f64], vs: &[f64], scale: (f64, f64)) -> Vec<bool> {
    let mut near = vec![false; us.len() * vs.len()];
    let gap = |lines: &[f64], i: usize| {
        let before = if i > 0 {
            lines[i] - lines[i - 1]
        } else {
            f64::INFINITY
        };
        let after = if i + 1 < lines.len() {
            lines[i + 1] - lines[i]
        } else {
            f64::INFINITY
        };
        before.min(after)
    };
    let widest = |lines: &[f64]| lines.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    let (reach_u, reach_v) = (widest(us) / 3.0, widest(vs) / 3.0);
    for l in &domain.loops {
        for k in 0..l.points.len() {
            let (p, q) = (l.points[k], l.points[(k + 1) % l.points.len()]);
            let i0 = us.partition_point(|&u| u < p[0].min(q[0]) - reach_u);
            let i1 = us.partition_point(|&u| u <= p[0].max(q[0]) + reach_u);
            let j0 = vs.partition_point(|&v| v < p[1].min(q[1]) - reach_v);
            let j1 = vs.partition_point(|&v| v <= p[1].max(q[1]) + reach_v);
            for i in i0..i1 {
                for j in j0..j1 {
                    let limit = (gap(us, i) * scale.0).min(gap(vs, j) * scale.1) / 3.0;
                    let d = segment_distance([us[i], vs[j]], p, q, scale);
                    if d < limit {
                        near[i * vs.len() + j] = true;
                    }
                }
            }
        }
    }
    near
}

/// The distance of `x` from the segment `p q`, in parameters scaled by `scale`.
fn segment_distance(x: [f64; 2], p: [f64; 2], q: [f64; 2], scale: (f64, f64)) -> f64 {
    let s = |a: [f64; 2]| [a[0] * scale.0, a[1] * scale.1];
    let (x, p, q) = (s(x), s(p), s(q));
    let d = [q[0] - p[0], q[1] - p[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((x[0] - p[0]) * d[0] + (x[1] - p[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let e = [x[0] - p[0] - t * d[0], x[1] - p[1] - t * d[1]];
    (e[0] * e[0] + e[1] * e[1]).sqrt()
}

impl Soup {
    /// Merges vertices within `eps` of each other and drops the triangles that collapse.
    fn weld(&mut self, eps: f64) {
        let cell = |p: Point3| [0, 1, 2].map(|c| (p[c] / eps).floor() as i64);
        let mut buckets: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let mut map = vec![0u32; self.positions.len()];
        let mut kept: Vec<Point3> = Vec::new();
        for (i, &p) in self.positions.iter().enumerate() {
            let c = cell(p);
            let mut found = None;
            'search: for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        let key = [c[0] + dx, c[1] + dy, c[2] + dz];
                        if let Some(list) = buckets.get(&key) {
                            if let Some(&k) =
                                list.iter().find(|&&k| kept[k as usize].distance(p) <= eps)
                            {
                                found = Some(k);
                                break 'search;
                            }
                        }
                    }
                }
            }
            map[i] = found.unwrap_or_else(|| {
                kept.push(p);
                let k = (kept.len() - 1) as u32;
                buckets.entry(c).or_default().push(k);
                k
            });
        }
        self.positions = kept;
        for t in &mut self.triangles {
            t.corners = t.corners.map(|c| map[c as usize]);
        }
        self.triangles.retain(|t| {
            let [a, b, c] = t.corners;
            a != b && b != c && a != c
        });
    }

    /// Splits each boundary segment (a side of one triangle only) at the boundary vertices of
    /// other faces within `reach` of it, nearest segment first (see the module docs).
    fn close_t_junctions(&mut self, reach: f64) {
        let boundary = self.boundary_sides();
        // Each boundary vertex's faces, to look only across faces.
        let mut vertex_faces: BTreeMap<u32, Vec<usize>> = BTreeMap::new();
        for &(t, side) in &boundary {
            let tri = self.triangles[t];
            for c in [tri.corners[side], tri.corners[(side + 1) % 3]] {
                let faces = vertex_faces.entry(c).or_default();
                if !faces.contains(&tri.face) {
                    faces.push(tri.face);
                }
            }
        }
        let grid = SegmentGrid::new(&self.positions, &self.triangles, &boundary, reach);
        // The vertices to insert into each boundary side: for each other face whose boundary
        // passes within reach, its nearest side.
        let mut inserts: Inserts = BTreeMap::new();
        for (&v, faces) in &vertex_faces {
            let p = self.positions[v as usize];
            let mut best: BTreeMap<usize, (f64, f64, (usize, usize))> = BTreeMap::new();
            for &(t, side) in grid.near(p) {
                let tri = self.triangles[t];
                let (a, b) = (tri.corners[side], tri.corners[(side + 1) % 3]);
                if a == v || b == v || faces.contains(&tri.face) {
                    continue;
                }
                let (pa, pb) = (self.positions[a as usize], self.positions[b as usize]);
                let (s, d) = along(p, pa, pb);
                let nearer = best.get(&tri.face).is_none_or(|x| d < x.0);
                if s > 0.0 && s < 1.0 && d <= reach && nearer {
                    best.insert(tri.face, (d, s, (t, side)));
                }
            }
            for (_, (_, s, key)) in best {
                inserts.entry(key).or_default().push((s, v));
            }
        }
        self.split_sides(inserts);
    }

    /// The sides used by one triangle only, as (triangle, side from corner `side` to the next).
    fn boundary_sides(&self) -> Vec<(usize, usize)> {
        let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t.corners[k], t.corners[(k + 1) % 3]);
                *uses.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
        let mut out = Vec::new();
        for (i, t) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t.corners[k], t.corners[(k + 1) % 3]);
                if uses[&(a.min(b), a.max(b))] == 1 {
                    out.push((i, k));
                }
            }
        }
        out
    }

    /// Replaces each triangle with vertices to insert on its sides by a fan from the
    /// opposite corner (one side at a time; a triangle with two split sides is split twice).
    fn split_sides(&mut self, inserts: Inserts) {
        let mut by_triangle: BTreeMap<usize, Vec<SideInserts>> = BTreeMap::new();
        for ((t, side), mut list) in inserts {
            list.sort_by(|x, y| x.0.total_cmp(&y.0));
            by_triangle.entry(t).or_default().push((side, list));
        }
        let mut removed = vec![false; self.triangles.len()];
        let mut added = Vec::new();
        for (t, sides) in by_triangle {
            removed[t] = true;
            // The triangle's boundary with the inserted vertices, corner by corner.
            let tri = self.triangles[t];
            let mut ring: Vec<u32> = Vec::new();
            for k in 0..3 {
                ring.push(tri.corners[k]);
                if let Some((_, list)) = sides.iter().find(|(s, _)| *s == k) {
                    ring.extend(list.iter().map(|&(_, v)| v));
                }
            }
            let n = ring.len();
            let apex = (0..n).find(|&i| {
                [ring[i], ring[(i + 1) % n], ring[(i + n - 1) % n]]
                    .iter()
                    .all(|c| tri.corners.contains(c))
            });
            match apex {
                // One side split: a fan from the corner opposite it.
                Some(apex) => {
                    for k in 1..n - 1 {
                        let (b, c) = (ring[(apex + k) % n], ring[(apex + k + 1) % n]);
                        added.push(Tri {
                            corners: [ring[apex], b, c],
                            face: tri.face,
                        });
                    }
                }
                // More sides split: a fan from the triangle's centroid, a new vertex.
                None => {
                    let p = tri.corners.map(|c| self.positions[c as usize]);
                    self.positions.push((p[0] + p[1] + p[2]) * (1.0 / 3.0));
                    let centre = (self.positions.len() - 1) as u32;
                    for k in 0..n {
                        let (b, c) = (ring[k], ring[(k + 1) % n]);
                        added.push(Tri {
                            corners: [centre, b, c],
                            face: tri.face,
                        });
                    }
                }
            }
        }
        let mut kept: Vec<Tri> = self
            .triangles
            .iter()
            .zip(&removed)
            .filter(|(_, &r)| !r)
            .map(|(t, _)| *t)
            .collect();
        kept.extend(added);
        self.triangles = kept;
    }
}

/// Where `p` projects onto the line `a b` (0 at `a`, 1 at `b`) and its distance from the
/// segment there.
fn along(p: Point3, a: Point3, b: Point3) -> (f64, f64) {
    let d = b - a;
    let len2 = d.dot(d);
    if len2 <= 0.0 {
        return (0.0, p.distance(a));
    }
    let s = (p - a).dot(d) / len2;
    (s, p.distance(a + d * s))
}

/// Vertices to insert into boundary sides, by (triangle, side): (place along the side, vertex).
type Inserts = BTreeMap<(usize, usize), Vec<(f64, u32)>>;
/// One side's insertions: the side (from its corner) and (place along it, vertex).
type SideInserts = (usize, Vec<(f64, u32)>);

/// Boundary sides bucketed by the cubes of side `reach` their boxes touch.
struct SegmentGrid {
    cell: f64,
    buckets: HashMap<[i64; 3], Vec<(usize, usize)>>,
}

impl SegmentGrid {
    fn new(
        positions: &[Point3],
        triangles: &[Tri],
        sides: &[(usize, usize)],
        reach: f64,
    ) -> SegmentGrid {
        // Cells no smaller than the longest side over 8, so a side spans a few cells.
        let longest = sides
            .iter()
            .map(|&(t, k)| {
                let c = triangles[t].corners;
                positions[c[k] as usize].distance(positions[c[(k + 1) % 3] as usize])
            })
            .fold(0.0, f64::max);
        let cell = (longest / 8.0).max(reach).max(f64::MIN_POSITIVE);
        let mut buckets: HashMap<[i64; 3], Vec<(usize, usize)>> = HashMap::new();
        for &(t, k) in sides {
            let c = triangles[t].corners;
            let (a, b) = (positions[c[k] as usize], positions[c[(k + 1) % 3] as usize]);
            let lo = [0, 1, 2].map(|i| ((a[i].min(b[i]) - reach) / cell).floor() as i64);
            let hi = [0, 1, 2].map(|i| ((a[i].max(b[i]) + reach) / cell).floor() as i64);
            for x in lo[0]..=hi[0] {
                for y in lo[1]..=hi[1] {
                    for z in lo[2]..=hi[2] {
                        buckets.entry([x, y, z]).or_default().push((t, k));
                    }
                }
            }
        }
        SegmentGrid { cell, buckets }
    }

    /// The sides whose boxes (grown by the reach) touch `p`'s cell.
    fn near(&self, p: Point3) -> &[(usize, usize)] {
        let key = [0, 1, 2].map(|i| (p[i] / self.cell).floor() as i64);
        self.buckets.get(&key).map_or(&[], Vec::as_slice)
    }
}

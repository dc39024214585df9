//! The point of a shape's faces nearest to given points: inspection of measured points
//! against a CAD model.
//!
//! Every face is cut into cells of its parameter rectangle, each at most `size / 48` across
//! (`size` the shape's diagonal; at most 64 x 64 cells a face); a cell keeps its centre point
//! and a radius bounding its points' distance to the centre (the largest distance to its
//! corners and edge midpoints, or half the sum of its edges' two-chord lengths, times 1.25: the
//! bound of [`SurfaceProjector`](crate::geometry::SurfaceProjector)). Cells outside a trimmed
//! face are dropped, and the edges of trimmed faces are cut into segments kept the same way.
//! All centres go into one k-d tree (the `kiddo` crate), and each face's cells, and each of its
//! edges' segments, into a box (`bounds.rs`); the faces' boxes into a tree of boxes. For a
//! query `q`:
//!
//! 1. a first bound on the distance: the face whose box a descent of the tree of boxes reaches
//!    (the nearer child at each node), solved as in step 3 when it is a plane or a whole
//!    cylinder; else the nearest point known to lie on the shape (a centre inside its face, or
//!    on an edge: a k-d tree of these, also asked when a face of neither form is reached);
//! 2. the faces whose box is nearer than that bound are visited nearest box first, until the
//!    box's distance reaches the best distance found;
//! 3. a face on a plane (`flat.rs`) or a whole cylinder (`cylinder.rs`) has one local minimum
//!    of the distance: it is solved once, in closed form. When that foot lies in the face it
//!    is the face's nearest point (nearer than its edges); when not, the face's nearest point
//!    is on its edges, searched by their boxes: a straight edge or a whole circle in closed
//!    form (`edge_form.rs`), any other edge by Newton's method on the edge curve from each of
//!    its segments whose lower bound `|q - centre| - radius` is below the best distance;
//! 4. the cells of the other faces within the bound plus the largest radius are taken from the
//!    k-d tree and searched nearest lower bound first, until the bound exceeds the best
//!    distance: a cell by Newton's method on the distance from its centre (projected at the
//!    surface's borders, as in [`SurfaceProjector`](crate::geometry::SurfaceProjector)),
//!    accepted when the foot lies in the face ([`FaceDomain::contains`]); a segment by Newton's
//!    method on the edge curve within the edge. A cell of the face found best whose parameters
//!    hold the best foot is skipped (Newton would find the same point).
//!
//! The distance is signed for faces that bound a solid: positive on the side the face's
//! normal points to (outside), from the normal at the foot (at an edge, the normal of the
//! face the edge bounds there; near a sharp concave edge the side may then be the other
//! face's; on a plane or a cylinder the normal is taken in closed form). Cost: building
//! `O(c log c)` for `c` cells; a query a tree search, the closed forms of the one or two
//! nearest faces and a few Newton solves on other faces; batches run in parallel.

use kiddo::immutable::float::kdtree::ImmutableKdTree;
use kiddo::SquaredEuclidean;
use rayon::prelude::*;

use super::bounds::{Bounds, BoxTree};
use super::cylinder::Round;
use super::edge_form::EdgeForm;
use super::flat::Flat;
use super::inside::InsideIndex;
use super::{FaceDomain, Shape};
use crate::bspline::{NurbsCurve, NurbsSurface};
use crate::core::{Curve, Interval, Surface};
use crate::geometry::surface_nearest::newton_foot;
use crate::geometry::{SurfaceNearest, SurfaceProjector};
use crate::{Point3, Result};

/// Cells across the shape's diagonal: the size of a cell.
const CELLS_ACROSS: f64 = 48.0;
/// The most cells along one direction of a face.
const MAX_CELLS: usize = 64;
/// The safety factor on a cell's radius (its points are sampled, not bounded).
const RADIUS_MARGIN: f64 = 1.25;
/// Batches at least this large run in parallel.
const PARALLEL_BATCH: usize = 256;
/// Newton steps on an edge curve.
const CURVE_STEPS: usize = 40;
/// The most surface cells of a face scanned for the start of Newton's method on a face solved
/// once a query (a larger face is scanned at a stride).
const START_SCAN: usize = 256;

/// The point of a shape nearest to a query point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ShapeNearest {
    /// The index of the face (in [`Shape::faces`]).
    pub face: usize,
    /// The foot's parameters on the face's surface.
    pub u: f64,
    /// See [`u`](ShapeNearest::u).
    pub v: f64,
    /// The foot point.
    pub point: Point3,
    /// The distance from the query point to the shape.
    pub distance: f64,
    /// The distance signed by the side of the face (positive outside the solid) for a face
    /// that bounds a solid; `None` otherwise.
    pub signed: Option<f64>,
    /// True when the foot lies on an edge of a trimmed face (found on the edge's curve).
    pub on_edge: bool,
}

impl ShapeNearest {
    /// The result for a query that has none (a non-finite coordinate, an empty shape, a
    /// distance beyond the largest `f64`).
    pub const UNDEFINED: ShapeNearest = ShapeNearest {
        face: usize::MAX,
        u: f64::NAN,
        v: f64::NAN,
        point: Point3::new([f64::NAN; 3]),
        distance: f64::NAN,
        signed: None,
        on_edge: false,
    };
}

/// Where a cell is.
#[derive(Clone, Copy, Debug)]
enum Place {
    /// A rectangle `u x v` of the face's surface.
    Surface { u: (f64, f64), v: (f64, f64) },
    /// A stretch `t` of an edge curve (loop `edge_loop`, edge `edge` of the face), with the
    /// surface parameters near its middle.
    Edge {
        edge_loop: usize,
        edge: usize,
        t: (f64, f64),
        uv: (f64, f64),
    },
}

/// A cell of a face or a segment of an edge.
#[derive(Clone, Copy, Debug)]
struct Cell {
    face: usize,
    place: Place,
    centre: Point3,
    radius: f64,
}

impl Cell {
    /// The surface parameters Newton's method starts from: the cell's centre, or the
    /// segment's middle.
    fn start(&self) -> (f64, f64) {
        match self.place {
            Place::Surface { u, v } => (0.5 * (u.0 + u.1), 0.5 * (v.0 + v.1)),
            Place::Edge { uv, .. } => uv,
        }
    }
}

/// Where a face's cells lie in [`ShapeProjector::cells`] and the boxes that bound them.
#[derive(Clone, Debug)]
struct FaceParts {
    /// A box holding the face (all its cells).
    bounds: Bounds,
    /// Its surface cells.
    surface: std::ops::Range<usize>,
    /// Its edges: a box holding each edge's segments, where they lie, and the edge's closed
    /// form.
    edges: Vec<(Bounds, std::ops::Range<usize>, EdgeForm)>,
}

impl FaceParts {
    /// The parts of the cells `cells[range]` (one face's: surface cells, then edge segments
    /// edge by edge).
    fn of(face: &super::Face, cells: &[Cell], range: std::ops::Range<usize>) -> FaceParts {
        let mut bounds = Bounds::EMPTY;
        let mut surface_end = range.start;
        let mut edges: Vec<(Bounds, std::ops::Range<usize>, EdgeForm)> = Vec::new();
        let mut last: Option<(usize, usize)> = None;
        for i in range.clone() {
            let cell = &cells[i];
            bounds.hold(cell.centre, cell.radius);
            match cell.place {
                Place::Surface { .. } => surface_end = i + 1,
                Place::Edge {
                    edge_loop, edge, ..
                } => {
                    if last != Some((edge_loop, edge)) {
                        let form = EdgeForm::of(&face.loops[edge_loop].edges[edge].curve);
                        edges.push((Bounds::EMPTY, i..i, form));
                        last = Some((edge_loop, edge));
                    }
                    if let Some((b, r, _)) = edges.last_mut() {
                        b.hold(cell.centre, cell.radius);
                        r.end = i + 1;
                    }
                }
            }
        }
        FaceParts {
            bounds,
            surface: range.start..surface_end,
            edges,
        }
    }
}

/// A face's surface in closed form.
#[derive(Clone, Debug)]
enum Form {
    /// A parallelogram of a plane (`flat.rs`).
    Flat(Flat),
    /// A whole turn of a circular cylinder (`cylinder.rs`).
    Round(Round),
    /// Any other surface.
    Other,
}

/// Working lists of one query, kept between queries of a batch.
#[derive(Default)]
struct Scratch {
    /// Faces by lower bound.
    faces: Vec<(f64, usize)>,
    /// Cells by lower bound.
    cells: Vec<(f64, usize)>,
}

/// A shape prepared for nearest-point queries.
///
/// ```
/// use karkas::bspline::sweep::{sphere, Frame};
/// use karkas::shape::{Face, Shape, ShapeProjector};
/// use karkas::Point3;
/// let frame = Frame::new(Point3::ZERO, Point3::new([0.0, 0.0, 1.0]), Point3::new([1.0, 0.0, 0.0])).unwrap();
/// let ball = sphere(&frame, 2.0, (0.0, std::f64::consts::TAU), (-1.5707963267948966, 1.5707963267948966))
///     .unwrap()
///     .with_closed(true, false);
/// let mut face = Face::whole(ball);
/// face.bounds_solid = true;
/// let shape = Shape { faces: vec![face], curves: vec![] };
/// let projector = ShapeProjector::new(&shape, 0.0).unwrap();
/// let near = projector.nearest(Point3::new([0.0, 3.0, 1.0]));
/// assert!((near.distance - (10f64.sqrt() - 2.0)).abs() < 1e-14);
/// assert!(near.signed.unwrap() > 0.0);
/// ```
pub struct ShapeProjector<'a> {
    shape: &'a Shape,
    domains: Vec<FaceDomain>,
    /// The faces' inside tests.
    insides: Vec<InsideIndex>,
    /// The closed form of each face on a plane or a whole cylinder.
    forms: Vec<Form>,
    /// Faces whose surface has one local minimum of the distance (planes, whole cylinders):
    /// searched once per query.
    once: Vec<bool>,
    cells: Vec<Cell>,
    /// Per face: where its cells lie in `cells` and the boxes that bound it and its edges.
    parts: Vec<FaceParts>,
    /// The faces' boxes.
    face_tree: BoxTree,
    tree: ImmutableKdTree<f64, u64, 3, 32>,
    /// Points on the shape (cell centres inside their faces, segment centres): the cell each
    /// is the centre of.
    anchors: Vec<usize>,
    anchor_tree: ImmutableKdTree<f64, u64, 3, 32>,
    max_radius: f64,
    accuracy: f64,
}

impl<'a> ShapeProjector<'a> {
    /// Prepares `shape` for queries. `accuracy` is the tolerance on the foot parameters
    /// (non-positive: full precision).
    ///
    /// Errors: a face whose samples are not finite ([`Error::NonFiniteArgument`](crate::Error)).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::{BSplineSurface, NurbsSurface};
    /// use karkas::shape::{Face, Shape, ShapeProjector};
    /// use karkas::{Grid, Point};
    ///
    /// // One face: the unit square of the plane z = 0.
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let square = NurbsSurface::from_bspline(&BSplineSurface::new(linear.clone(), linear, control)?);
    /// let shape = Shape { faces: vec![Face::whole(square)], curves: Vec::new() };
    /// let projector = ShapeProjector::new(&shape, 0.0)?;
    /// let foot = projector.nearest(Point([0.3, 0.4, 2.0]));
    /// assert!((foot.distance - 2.0).abs() < 1e-9 && foot.face == 0);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(shape: &'a Shape, accuracy: f64) -> Result<Self> {
        let size = shape.size().max(f64::MIN_POSITIVE);
        let target = size / CELLS_ACROSS;
        let domains: Vec<FaceDomain> = shape
            .faces
            .par_iter()
            .map(FaceDomain::of)
            .collect::<Result<_>>()?;
        let insides: Vec<InsideIndex> = domains.par_iter().map(InsideIndex::new).collect();
        let forms: Vec<Form> = shape
            .faces
            .iter()
            .map(|f| match (Flat::of(&f.surface), Round::of(&f.surface)) {
                (Some(flat), _) => Form::Flat(flat),
                (None, Some(round)) => Form::Round(round),
                (None, None) => Form::Other,
            })
            .collect();
        let once = forms.iter().map(|f| !matches!(f, Form::Other)).collect();
        let per_face: Vec<(Vec<Cell>, Vec<usize>)> = shape
            .faces
            .par_iter()
            .zip(domains.par_iter().zip(&insides))
            .enumerate()
            .map(|(k, (face, (domain, inside)))| face_cells(k, face, domain, inside, target, size))
            .collect::<Result<_>>()?;
        let mut cells = Vec::new();
        let mut anchors = Vec::new();
        let mut parts = Vec::with_capacity(per_face.len());
        for (face, (face_cells, inside)) in shape.faces.iter().zip(per_face) {
            let base = cells.len();
            anchors.extend(inside.into_iter().map(|i| base + i));
            cells.extend(face_cells);
            parts.push(FaceParts::of(face, &cells, base..cells.len()));
        }
        let face_tree = BoxTree::new(parts.iter().map(|p| p.bounds).collect());
        let max_radius = cells.iter().map(|c| c.radius).fold(0.0, f64::max);
        let coords: Vec<[f64; 3]> = cells.iter().map(|c| c.centre.0).collect();
        let anchor_coords: Vec<[f64; 3]> = anchors.iter().map(|&i| cells[i].centre.0).collect();
        Ok(ShapeProjector {
            shape,
            domains,
            insides,
            forms,
            once,
            tree: ImmutableKdTree::new_from_slice(&coords),
            anchor_tree: ImmutableKdTree::new_from_slice(&anchor_coords),
            cells,
            parts,
            face_tree,
            anchors,
            max_radius,
            accuracy: accuracy.max(0.0),
        })
    }

    /// The number of cells and edge segments searched.
    pub fn cell_count(&self) -> usize {
        self.cells.len()
    }

    /// Where face `k` lies in its surface's parameters.
    pub fn domain(&self, k: usize) -> &FaceDomain {
        &self.domains[k]
    }

    /// The nearest point of the shape's faces to `q` ([`ShapeNearest::UNDEFINED`] for a
    /// non-finite `q`, a shape without faces, or a `q` so far that its distances overflow).
    pub fn nearest(&self, q: Point3) -> ShapeNearest {
        self.nearest_with(q, &mut Scratch::default())
    }

    /// [`nearest`](ShapeProjector::nearest) with working lists kept between queries.
    ///
    /// The faces are visited by increasing lower bound (their box, `bounds.rs`) until it
    /// reaches the best distance found, within a first bound (module docs, step 1). A face
    /// solved once a query (a plane, a whole cylinder) gives its one foot, or when that lies
    /// outside the face, its edges' nearest point; the other faces' cells are searched from the
    /// k-d tree afterwards, as one list, within the reach the nearest anchor gives.
    fn nearest_with(&self, q: Point3, scratch: &mut Scratch) -> ShapeNearest {
        if !q.is_finite() || self.anchors.is_empty() {
            return ShapeNearest::UNDEFINED;
        }
        let unset = ShapeNearest {
            distance: f64::INFINITY,
            ..ShapeNearest::UNDEFINED
        };
        // A first bound: the face the descent of the faces' box tree reaches, solved when it
        // is solved once a query, else the nearest anchor.
        let mut first: Option<(usize, ShapeNearest)> = None;
        if let Some(k) = self.face_tree.descend(q).filter(|&k| self.once[k]) {
            let mut found = unset;
            self.search_once(k, q, &mut found, &mut scratch.cells);
            first = Some((k, found));
        }
        let bound = match first {
            Some((_, found)) if found.distance.is_finite() => found.distance,
            _ => {
                let mut anchor = unset;
                self.improve_by_anchor(q, &mut anchor);
                anchor.distance
            }
        };
        scratch.faces.clear();
        self.face_tree.within(q, bound, &mut scratch.faces);
        scratch
            .faces
            .sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        // The faces by increasing lower bound, as if no bound were known: the first face's
        // foot is taken in its turn.
        let mut best = unset;
        let mut general = false;
        for i in 0..scratch.faces.len() {
            let (lower, k) = scratch.faces[i];
            if lower >= best.distance {
                break;
            }
            match first {
                Some((first_k, found)) if first_k == k => {
                    if found.distance < best.distance {
                        best = found;
                    }
                    first = None;
                }
                _ if self.once[k] => self.search_once(k, q, &mut best, &mut scratch.cells),
                _ if !general => {
                    // The cells of other faces are searched within a reach of the best
                    // distance: the nearest point known on the shape bounds it.
                    general = true;
                    self.improve_by_anchor(q, &mut best);
                }
                _ => {}
            }
        }
        if let Some((_, found)) = first {
            if found.distance < best.distance {
                best = found;
            }
        }
        if general {
            self.search_cells(q, &mut best, &mut scratch.cells);
        }
        if best.face == usize::MAX {
            // No face held a foot (not expected: the nearest face's foot or edge is found).
            self.improve_by_anchor(q, &mut best);
        }
        if best.face == usize::MAX {
            // Not even an anchor: every distance overflowed (a point beyond 1e154 or so).
            return ShapeNearest::UNDEFINED;
        }
        self.sign(best, q)
    }

    /// Takes the nearest point known to lie on the shape (a cell centre inside its face, or on
    /// an edge) when it is nearer than `best`.
    fn improve_by_anchor(&self, q: Point3, best: &mut ShapeNearest) {
        let first = self.anchor_tree.nearest_one::<SquaredEuclidean>(&q.0).item as usize;
        let anchor = self.at_centre(
            &self.cells[self.anchors[first.min(self.anchors.len() - 1)]],
            q,
        );
        if anchor.distance < best.distance {
            *best = anchor;
        }
    }

    /// Searches face `k`, solved once a query: its one foot, or when that lies outside the
    /// face, its edges (the nearest point of the face is then on its border).
    fn search_once(
        &self,
        k: usize,
        q: Point3,
        best: &mut ShapeNearest,
        candidates: &mut Vec<(f64, usize)>,
    ) {
        let part = &self.parts[k];
        if let Some(found) = self.surface_foot(k, || self.once_start(k, q), q) {
            if found.distance < best.distance {
                *best = found;
            }
            return;
        }
        candidates.clear();
        for (bounds, range, form) in &part.edges {
            if bounds.distance(q) >= best.distance {
                continue;
            }
            if let Some(point) = form.nearest(q) {
                let distance = point.distance(q);
                if distance < best.distance {
                    let (u, v) = self.edge_parameters(k, point, range.clone());
                    *best = ShapeNearest {
                        face: k,
                        u,
                        v,
                        point,
                        distance,
                        signed: None,
                        on_edge: true,
                    };
                }
                continue;
            }
            for i in range.clone() {
                let lower = self.cells[i].centre.distance(q) - self.cells[i].radius;
                if lower < best.distance {
                    candidates.push((lower, i));
                }
            }
        }
        candidates.sort_unstable_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        for &(lower, i) in candidates.iter() {
            if lower >= best.distance {
                break;
            }
            if let Some(found) = self.search(&self.cells[i], q) {
                if found.distance < best.distance {
                    *best = found;
                }
            }
        }
    }

    /// The surface parameters of `point`, on an edge of face `k` whose segments are
    /// `cells[segments]`: in closed form on a plane or a cylinder, else those kept with the
    /// segment whose centre is nearest.
    fn edge_parameters(
        &self,
        k: usize,
        point: Point3,
        segments: std::ops::Range<usize>,
    ) -> (f64, f64) {
        let closed = match &self.forms[k] {
            Form::Flat(flat) => flat.nearest(point),
            Form::Round(round) => round.foot(point).map(|(u, v, _)| (u, v)),
            Form::Other => None,
        };
        closed.unwrap_or_else(|| {
            let mut pick = (f64::INFINITY, segments.start);
            for i in segments {
                let d = self.cells[i].centre.distance_sq(point);
                if d < pick.0 {
                    pick = (d, i);
                }
            }
            self.cells[pick.1].start()
        })
    }

    /// Where Newton's method starts on face `k` (solved once a query): the surface cell of
    /// least lower bound, among at most [`START_SCAN`] of its cells.
    fn once_start(&self, k: usize, q: Point3) -> (f64, f64) {
        let range = self.parts[k].surface.clone();
        if range.is_empty() {
            let d = &self.domains[k];
            return (0.5 * (d.u.start + d.u.end), 0.5 * (d.v.start + d.v.end));
        }
        let stride = range.len().div_ceil(START_SCAN);
        let mut pick = (f64::INFINITY, range.start);
        for i in range.step_by(stride) {
            let lower = self.cells[i].centre.distance(q) - self.cells[i].radius;
            if lower < pick.0 {
                pick = (lower, i);
            }
        }
        self.cells[pick.1].start()
    }

    /// Searches the cells of the faces not solved once a query, within reach of `best`, by
    /// increasing lower bound.
    fn search_cells(&self, q: Point3, best: &mut ShapeNearest, candidates: &mut Vec<(f64, usize)>) {
        let reach = best.distance + self.max_radius;
        candidates.clear();
        for n in self
            .tree
            .within_unsorted::<SquaredEuclidean>(&q.0, reach * reach)
        {
            let k = (n.item as usize).min(self.cells.len() - 1);
            if self.once[self.cells[k].face] {
                continue;
            }
            let lower = n.distance.sqrt() - self.cells[k].radius;
            if lower < best.distance {
                candidates.push((lower, k));
            }
        }
        candidates.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut searched_face_foot = false;
        for &(lower, k) in candidates.iter() {
            if lower >= best.distance {
                break;
            }
            let cell = &self.cells[k];
            if let Place::Surface { u, v } = cell.place {
                if searched_face_foot
                    && cell.face == best.face
                    && !best.on_edge
                    && (u.0..=u.1).contains(&best.u)
                    && (v.0..=v.1).contains(&best.v)
                {
                    continue;
                }
            }
            if let Some(found) = self.search(cell, q) {
                if found.distance < best.distance {
                    searched_face_foot = !found.on_edge;
                    *best = found;
                }
            }
        }
    }

    /// The nearest points to every point of `qs` (in parallel for large batches).
    pub fn nearest_all(&self, qs: &[Point3]) -> Vec<ShapeNearest> {
        if qs.len() < PARALLEL_BATCH {
            let mut scratch = Scratch::default();
            qs.iter()
                .map(|&q| self.nearest_with(q, &mut scratch))
                .collect()
        } else {
            qs.par_iter()
                .with_min_len(64)
                .map_init(Scratch::default, |scratch, &q| {
                    self.nearest_with(q, scratch)
                })
                .collect()
        }
    }

    /// The cell's centre as a result (a point of the shape).
    fn at_centre(&self, cell: &Cell, q: Point3) -> ShapeNearest {
        let (u, v, on_edge) = match cell.place {
            Place::Surface { u, v } => (0.5 * (u.0 + u.1), 0.5 * (v.0 + v.1), false),
            Place::Edge { uv, .. } => (uv.0, uv.1, true),
        };
        ShapeNearest {
            face: cell.face,
            u,
            v,
            point: cell.centre,
            distance: cell.centre.distance(q),
            signed: None,
            on_edge,
        }
    }

    /// The foot of `q` on face `k`'s surface found from the parameters `start` gives (in
    /// closed form on a plane), if it lies on the face.
    fn surface_foot(
        &self,
        k: usize,
        start: impl FnOnce() -> (f64, f64),
        q: Point3,
    ) -> Option<ShapeNearest> {
        let s = &self.shape.faces[k].surface;
        let closed_form = match &self.forms[k] {
            Form::Flat(flat) => flat.nearest(q).map(|(u, v)| (u, v, flat.point(u, v))),
            Form::Round(round) => round.foot(q),
            Form::Other => None,
        };
        let foot = match closed_form {
            Some((u, v, point)) => SurfaceNearest {
                u,
                v,
                distance: point.distance(q),
                point,
            },
            None => {
                let closed = (s.is_closed_u(), s.is_closed_v());
                newton_foot(s, q, start(), closed, self.accuracy)
            }
        };
        self.insides[k]
            .contains(foot.u, foot.v)
            .then_some(ShapeNearest {
                face: k,
                u: foot.u,
                v: foot.v,
                point: foot.point,
                distance: foot.distance,
                signed: None,
                on_edge: false,
            })
    }

    /// The foot of `q` found from `cell`, if it lies on the face.
    fn search(&self, cell: &Cell, q: Point3) -> Option<ShapeNearest> {
        let face = &self.shape.faces[cell.face];
        match cell.place {
            Place::Surface { .. } => self.surface_foot(cell.face, || cell.start(), q),
            Place::Edge {
                edge_loop,
                edge,
                t,
                uv,
            } => {
                let curve = &face.loops[edge_loop].edges[edge].curve;
                let (_, point, distance) = curve_foot(curve, q, t);
                Some(ShapeNearest {
                    face: cell.face,
                    u: uv.0,
                    v: uv.1,
                    point,
                    distance,
                    signed: None,
                    on_edge: true,
                })
            }
        }
    }

    /// `found` with its parameters made exact on an edge (for the normal) and its sign.
    fn sign(&self, mut found: ShapeNearest, q: Point3) -> ShapeNearest {
        let face = &self.shape.faces[found.face];
        if !face.bounds_solid {
            return found;
        }
        let sense = if face.same_sense { 1.0 } else { -1.0 };
        let normal = match &self.forms[found.face] {
            Form::Flat(flat) => {
                if found.on_edge {
                    if let Some((u, v)) = flat.nearest(found.point) {
                        (found.u, found.v) = (u, v);
                    }
                }
                Some(flat.normal() * sense)
            }
            Form::Round(round) => {
                if found.on_edge {
                    if let Some((u, v, _)) = round.foot(found.point) {
                        (found.u, found.v) = (u, v);
                    }
                }
                Some(round.normal(found.point) * sense).filter(|n| n.is_finite())
            }
            Form::Other => None,
        };
        let normal = normal.or_else(|| {
            if found.on_edge {
                let s = &face.surface;
                let closed = (s.is_closed_u(), s.is_closed_v());
                let foot = newton_foot(s, found.point, (found.u, found.v), closed, 0.0);
                found.u = foot.u;
                found.v = foot.v;
            }
            face.normal(found.u, found.v)
        });
        found.signed = normal.map(|n| {
            if (q - found.point).dot(n) >= 0.0 {
                found.distance
            } else {
                -found.distance
            }
        });
        found
    }
}

/// The cells of face `k` (a face cut into rectangles, plus its edges' segments when it is
/// trimmed) and the indices of those whose centre lies on the face.
fn face_cells(
    k: usize,
    face: &super::Face,
    domain: &FaceDomain,
    inside: &InsideIndex,
    target: f64,
    size: f64,
) -> Result<(Vec<Cell>, Vec<usize>)> {
    let s = &face.surface;
    let (nu, nv) = cell_counts(s, target);
    let samples = CellSamples::of(s, nu, nv)?;
    let whole = domain.is_whole();
    let crossed = if whole {
        Vec::new()
    } else {
        crossed_cells(domain, s, nu, nv)
    };
    let mut cells = Vec::with_capacity(nu * nv);
    let mut anchors = Vec::new();
    for a in 0..nu {
        for b in 0..nv {
            let (i, j) = (2 * a + 1, 2 * b + 1);
            let (us, vs) = (&samples.us, &samples.vs);
            let centre_inside = whole || inside.contains(us[i], vs[j]);
            let keep = whole
                || centre_inside
                || crossed[a * nv + b]
                || (0..3)
                    .any(|di| (0..3).any(|dj| inside.contains(us[i + di - 1], vs[j + dj - 1])));
            if !keep {
                continue;
            }
            if centre_inside {
                anchors.push(cells.len());
            }
            cells.push(Cell {
                face: k,
                place: Place::Surface {
                    u: (us[i - 1], us[i + 1]),
                    v: (vs[j - 1], vs[j + 1]),
                },
                centre: samples.at(i, j),
                radius: samples.radius(i, j, size),
            });
        }
    }
    if !whole {
        edge_cells(k, face, target, size, &mut cells, &mut anchors)?;
    }
    Ok((cells, anchors))
}

/// The cells along `u` and `v` of the surface `s`: its extent along each (the longest of 9
/// polylines of 32 chords across it) over `target`, from 1 to [`MAX_CELLS`].
fn cell_counts(s: &NurbsSurface<3>, target: f64) -> (usize, usize) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let probe = |n: usize, along_u: bool| -> f64 {
        (0..=8)
            .map(|j| {
                let mut length = 0.0;
                let mut previous: Option<Point3> = None;
                for i in 0..=n {
                    let (a, b) = (i as f64 / n as f64, j as f64 / 8.0);
                    let p = if along_u {
                        s.eval(du.start + a * du.length(), dv.start + b * dv.length())
                    } else {
                        s.eval(du.start + b * du.length(), dv.start + a * dv.length())
                    };
                    if let Some(q) = previous {
                        length += p.distance(q);
                    }
                    previous = Some(p);
                }
                length
            })
            .fold(0.0, f64::max)
    };
    let count = |length: f64| ((length / target).ceil() as usize).clamp(1, MAX_CELLS);
    (count(probe(32, true)), count(probe(32, false)))
}

/// The surface sampled at the corners and midpoints of `nu x nv` cells: `(2 nu + 1) x (2 nv +
/// 1)` points, cell `(a, b)` centred at sample `(2 a + 1, 2 b + 1)`.
struct CellSamples {
    us: Vec<f64>,
    vs: Vec<f64>,
    grid: Vec<Point3>,
}

impl CellSamples {
    /// The samples of `s`; an error when one is not finite.
    fn of(s: &NurbsSurface<3>, nu: usize, nv: usize) -> Result<CellSamples> {
        let (mu, mv) = (2 * nu + 1, 2 * nv + 1);
        let us: Vec<f64> = (0..mu).map(|i| s.domain_u().uniform(i, mu)).collect();
        let vs: Vec<f64> = (0..mv).map(|j| s.domain_v().uniform(j, mv)).collect();
        let mut grid = vec![Point3::ZERO; mu * mv];
        s.eval_grid_into(&us, &vs, &mut grid);
        if grid.iter().any(|p| !p.is_finite()) {
            return Err(crate::Error::NonFiniteArgument {
                what: "a sample of a face",
            });
        }
        Ok(CellSamples { us, vs, grid })
    }

    /// Sample `(i, j)`.
    fn at(&self, i: usize, j: usize) -> Point3 {
        self.grid[i * self.vs.len() + j]
    }

    /// The radius of the cell centred at sample `(i, j)`: the largest distance from the centre
    /// to its corners and edge midpoints, or half the sum of its edges' two-chord lengths,
    /// times [`RADIUS_MARGIN`], plus `1e-12` of the shape's `size`.
    fn radius(&self, i: usize, j: usize, size: f64) -> f64 {
        let at = |i: usize, j: usize| self.at(i, j);
        let centre = at(i, j);
        let mut far: f64 = 0.0;
        for di in 0..3 {
            for dj in 0..3 {
                far = far.max(centre.distance(at(i + di - 1, j + dj - 1)));
            }
        }
        let two_chords = |p: Point3, m: Point3, q: Point3| p.distance(m) + m.distance(q);
        let lu = two_chords(at(i - 1, j - 1), at(i, j - 1), at(i + 1, j - 1)).max(two_chords(
            at(i - 1, j + 1),
            at(i, j + 1),
            at(i + 1, j + 1),
        ));
        let lv = two_chords(at(i - 1, j - 1), at(i - 1, j), at(i - 1, j + 1)).max(two_chords(
            at(i + 1, j - 1),
            at(i + 1, j),
            at(i + 1, j + 1),
        ));
        RADIUS_MARGIN * far.max(0.5 * (lu + lv)) + 1e-12 * size
    }
}

/// Which of the `nu x nv` cells of `s`'s rectangle hold a vertex of a trim loop of `domain`
/// (they are partly on the face), row by row in `u`.
fn crossed_cells(domain: &FaceDomain, s: &NurbsSurface<3>, nu: usize, nv: usize) -> Vec<bool> {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let mut crossed = vec![false; nu * nv];
    for l in &domain.loops {
        for p in &l.points {
            let a = (((p[0] - du.start) / du.length()) * nu as f64).floor();
            let b = (((p[1] - dv.start) / dv.length()) * nv as f64).floor();
            if a >= 0.0 && b >= 0.0 && (a as usize) < nu && (b as usize) < nv {
                crossed[a as usize * nv + b as usize] = true;
            }
        }
    }
    crossed
}

/// The segments of the edges of a trimmed face, each at most `target` long.
fn edge_cells(
    k: usize,
    face: &super::Face,
    target: f64,
    size: f64,
    cells: &mut Vec<Cell>,
    anchors: &mut Vec<usize>,
) -> Result<()> {
    let s = &face.surface;
    let projector = SurfaceProjector::new(s, (24, 24), 0.0)?;
    let closed = (s.is_closed_u(), s.is_closed_v());
    for (l, edge_loop) in face.loops.iter().enumerate() {
        for (e, edge) in edge_loop.edges.iter().enumerate() {
            let c = &edge.curve;
            let d = c.domain();
            let samples = 64usize;
            let pts: Vec<Point3> = (0..=samples)
                .map(|i| c.eval(d.uniform(i, samples + 1)))
                .collect();
            let length: f64 = pts.windows(2).map(|w| w[0].distance(w[1])).sum();
            let n = ((length / target).ceil() as usize).clamp(1, 4096);
            let mut uv: Option<(f64, f64)> = None;
            for i in 0..n {
                let (t0, t1) = (d.uniform(i, n + 1), d.uniform(i + 1, n + 1));
                let tm = 0.5 * (t0 + t1);
                let centre = c.eval(tm);
                // Half the segment's two-chord length bounds its points' distance to the centre.
                let span = c.eval(t0).distance(c.eval(0.5 * (t0 + tm)))
                    + c.eval(0.5 * (t0 + tm)).distance(centre);
                let span2 = centre.distance(c.eval(0.5 * (tm + t1)))
                    + c.eval(0.5 * (tm + t1)).distance(c.eval(t1));
                let radius = RADIUS_MARGIN * span.max(span2) + 1e-12 * size;
                let foot = match uv {
                    Some(start) => newton_foot(s, centre, start, closed, 0.0),
                    None => projector.nearest(centre),
                };
                uv = Some((foot.u, foot.v));
                anchors.push(cells.len());
                cells.push(Cell {
                    face: k,
                    place: Place::Edge {
                        edge_loop: l,
                        edge: e,
                        t: (t0, t1),
                        uv: (foot.u, foot.v),
                    },
                    centre,
                    radius,
                });
            }
        }
    }
    Ok(())
}

/// The point of `curve` (over its whole domain, the edge) nearest `q` near the stretch `t`:
/// Newton's method on `|C(t) - q|^2 / 2` from the middle of `t`, clamped to the domain, steps
/// halved until the distance does not grow. The parameter, the point and the distance.
fn curve_foot(curve: &NurbsCurve<3>, q: Point3, t: (f64, f64)) -> (f64, Point3, f64) {
    let d: Interval = curve.domain();
    let mut x = 0.5 * (t.0 + t.1);
    let mut p = curve.eval(x);
    let mut dist2 = p.distance_sq(q);
    let floor = 4.0 * f64::EPSILON * d.length().max(1.0);
    for _ in 0..CURVE_STEPS {
        let [c, c1, c2] = curve.eval_with_derivatives(x);
        let r = c - q;
        let g = r.dot(c1);
        let h = c1.norm_sq() + r.dot(c2);
        let mut step = if h > 0.0 {
            -g / h
        } else if c1.norm_sq() > 0.0 {
            -g / c1.norm_sq()
        } else {
            break;
        };
        let mut improved = false;
        for _ in 0..30 {
            let nx = d.clamp(x + step);
            let np = curve.eval(nx);
            let nd2 = np.distance_sq(q);
            if nd2 <= dist2 * (1.0 + 8.0 * f64::EPSILON) {
                (x, p, dist2) = (nx, np, nd2);
                improved = true;
                break;
            }
            step *= 0.5;
        }
        if !improved || step.abs() <= floor {
            break;
        }
    }
    (x, p, dist2.sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::conic::{elliptic_arc, line_segment};
    use crate::bspline::sweep::{cylinder, plane, Frame};
    use crate::shape::{Edge, EdgeLoop, Face};
    use std::f64::consts::TAU;

    fn frame() -> Frame {
        Frame::new(
            Point3::ZERO,
            Point3::new([0.0, 0.0, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap()
    }

    /// A square plate [-2, 2]^2 in z = 0 with a round hole of radius 1 at the origin.
    fn plate_with_hole() -> Shape {
        let f = frame();
        let surface = plane(&f, (-2.0, 2.0), (-2.0, 2.0)).unwrap();
        let corner = |x: f64, y: f64| Point3::new([x, y, 0.0]);
        let side = |a: Point3, b: Point3| Edge {
            curve: line_segment(a, b, (0.0, a.distance(b))).unwrap(),
            forward: true,
        };
        let outer = EdgeLoop::new(
            vec![
                side(corner(-2.0, -2.0), corner(2.0, -2.0)),
                side(corner(2.0, -2.0), corner(2.0, 2.0)),
                side(corner(2.0, 2.0), corner(-2.0, 2.0)),
                side(corner(-2.0, 2.0), corner(-2.0, -2.0)),
            ],
            true,
        );
        let hole = EdgeLoop::new(
            vec![Edge {
                curve: elliptic_arc(Point3::ZERO, f.x, f.y, (0.0, TAU)).unwrap(),
                forward: false,
            }],
            false,
        );
        Shape {
            faces: vec![Face {
                surface,
                loops: vec![outer, hole],
                same_sense: true,
                bounds_solid: false,
            }],
            curves: vec![],
        }
    }

    #[test]
    fn points_over_a_hole_find_its_rim() {
        let shape = plate_with_hole();
        let p = ShapeProjector::new(&shape, 0.0).unwrap();
        // Above the plate: straight down.
        let n = p.nearest(Point3::new([1.5, 1.5, 0.3]));
        assert!((n.distance - 0.3).abs() < 1e-14 && !n.on_edge, "{n:?}");
        // Above the hole: the rim, at distance sqrt(0.5^2 + 0.3^2) from (0.5, 0, 0.3).
        let n = p.nearest(Point3::new([0.5, 0.0, 0.3]));
        assert!((n.distance - 0.5f64.hypot(0.3)).abs() < 1e-13, "{n:?}");
        assert!(n.on_edge && n.point.distance(Point3::new([1.0, 0.0, 0.0])) < 1e-12);
        // Far above the centre: every rim point is as near; the distance is sqrt(1 + 4).
        let n = p.nearest(Point3::new([0.0, 0.0, 2.0]));
        assert!((n.distance - 5f64.sqrt()).abs() < 1e-12, "{n:?}");
        assert_eq!(
            ShapeNearest::UNDEFINED.face,
            p.nearest(Point3::new([f64::NAN, 0.0, 0.0])).face
        );
        // So far that every distance overflows: no result (and no panic), alone and in a batch.
        for far in [1e300, f64::MAX] {
            let q = Point3::new([far, -far, far]);
            assert_eq!(p.nearest(q).face, usize::MAX, "{far:e}");
            let batch = p.nearest_all(&vec![q; 300]);
            assert!(batch
                .iter()
                .all(|n| n.face == usize::MAX && n.distance.is_nan()));
        }
        // Far but finite distances are still found.
        let n = p.nearest(Point3::new([0.0, 0.0, 1e150]));
        assert!(
            n.face != usize::MAX && (n.distance / 1e150 - 1.0).abs() < 1e-12,
            "{n:?}"
        );
    }

    #[test]
    fn distances_equal_a_brute_force_search_and_are_signed_on_solids() {
        let f = frame();
        let side = cylinder(&f, 1.0, (0.0, TAU), (0.0, 2.0))
            .unwrap()
            .with_closed(true, false);
        let mut face = Face::whole(side);
        face.bounds_solid = true;
        let shape = Shape {
            faces: vec![face],
            curves: vec![],
        };
        let p = ShapeProjector::new(&shape, 0.0).unwrap();
        for k in 0..200 {
            let a = 0.37 * k as f64;
            let r = 0.2 + 1.6 * ((k * 7) % 11) as f64 / 10.0;
            let z = -0.5 + 3.0 * ((k * 3) % 13) as f64 / 12.0;
            let q = Point3::new([r * a.cos(), r * a.sin(), z]);
            let n = p.nearest(q);
            // The exact distance to the finite cylinder's side.
            let radial = r - 1.0;
            let axial = if z < 0.0 {
                -z
            } else if z > 2.0 {
                z - 2.0
            } else {
                0.0
            };
            let want = radial.hypot(axial);
            assert!(
                (n.distance - want).abs() < 1e-12,
                "{k}: {q:?} {} {want}",
                n.distance
            );
            let signed = n.signed.unwrap();
            assert_eq!(signed.abs(), n.distance);
            if axial == 0.0 && radial.abs() > 1e-9 {
                assert_eq!(signed > 0.0, radial > 0.0, "{k}");
            }
        }
    }

    /// A block of `scale` about `offset`: a plate `[-2, 2]^2` at z = 0 with a round hole of
    /// radius 1, the hole's wall (a whole cylinder down to z = -1), its bottom (a disc: a plane
    /// trimmed by a circle) and a twisted bilinear patch beside the plate (searched by cells).
    fn holed_block(scale: f64, offset: Point3) -> Shape {
        use crate::bspline::{BSplineSurface, NurbsSurface};
        use crate::Grid;
        let at = |x: f64, y: f64, z: f64| offset + Point3::new([x, y, z]) * scale;
        let f = Frame::new(
            at(0.0, 0.0, 0.0),
            Point3::new([0.0, 0.0, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap();
        let low = Frame::new(at(0.0, 0.0, -1.0), f.z, f.x).unwrap();
        let side = |a: Point3, b: Point3| Edge {
            curve: line_segment(a, b, (0.0, a.distance(b))).unwrap(),
            forward: true,
        };
        let circle = |frame: &Frame, forward: bool| Edge {
            curve: elliptic_arc(frame.origin, frame.x * scale, frame.y * scale, (0.0, TAU))
                .unwrap(),
            forward,
        };
        let outer = EdgeLoop::new(
            vec![
                side(at(-2.0, -2.0, 0.0), at(2.0, -2.0, 0.0)),
                side(at(2.0, -2.0, 0.0), at(2.0, 2.0, 0.0)),
                side(at(2.0, 2.0, 0.0), at(-2.0, 2.0, 0.0)),
                side(at(-2.0, 2.0, 0.0), at(-2.0, -2.0, 0.0)),
            ],
            true,
        );
        let top = Face {
            surface: plane(&f, (-2.0 * scale, 2.0 * scale), (-2.0 * scale, 2.0 * scale)).unwrap(),
            loops: vec![outer, EdgeLoop::new(vec![circle(&f, false)], false)],
            same_sense: true,
            bounds_solid: false,
        };
        let wall = Face::whole(
            cylinder(&low, scale, (0.0, TAU), (0.0, scale))
                .unwrap()
                .with_closed(true, false),
        );
        let bottom = Face {
            surface: plane(&low, (-scale, scale), (-scale, scale)).unwrap(),
            loops: vec![EdgeLoop::new(vec![circle(&low, true)], true)],
            same_sense: true,
            bounds_solid: false,
        };
        let twisted = Grid::from_fn(2, 2, |i, j| {
            at(
                3.0 + i as f64,
                -1.0 + 2.0 * j as f64,
                if i == j { 0.5 } else { -0.5 },
            )
        });
        let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
        let patch = NurbsSurface::from_bspline(
            &BSplineSurface::new(linear.clone(), linear, twisted).unwrap(),
        );
        Shape {
            faces: vec![top, wall, bottom, Face::whole(patch)],
            curves: vec![],
        }
    }

    /// Uniform numbers in `[0, 1)` from a fixed seed.
    fn uniform(seed: u64) -> impl FnMut() -> f64 {
        let mut state = seed;
        move || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        }
    }

    #[test]
    fn face_and_edge_boxes_never_exceed_the_distance_to_their_points() {
        for (scale, offset) in [(1.0, Point3::ZERO), (1e3, Point3::new([1e4, -1e4, 1e4]))] {
            let shape = holed_block(scale, offset);
            let p = ShapeProjector::new(&shape, 0.0).unwrap();
            let mut next = uniform(0x9e37_79b9_7f4a_7c15);
            // Points of every face (inside its domain) and of every edge.
            let mut on_faces: Vec<(usize, Option<usize>, Point3)> = Vec::new();
            for (k, face) in shape.faces.iter().enumerate() {
                let (du, dv) = (face.surface.domain_u(), face.surface.domain_v());
                for _ in 0..400 {
                    let (u, v) = (
                        du.start + next() * du.length(),
                        dv.start + next() * dv.length(),
                    );
                    if p.insides[k].contains(u, v) {
                        on_faces.push((k, None, face.surface.eval(u, v)));
                    }
                }
                for (e, (_, range, _)) in p.parts[k].edges.iter().enumerate() {
                    let Place::Edge {
                        edge_loop, edge, ..
                    } = p.cells[range.start].place
                    else {
                        panic!("a surface cell among the edges");
                    };
                    let c = &face.loops[edge_loop].edges[edge].curve;
                    for i in 0..=50 {
                        on_faces.push((k, Some(e), c.eval(c.domain().uniform(i, 51))));
                    }
                }
            }
            assert!(on_faces.len() > 1000);
            let size = shape.size();
            for _ in 0..300 {
                let q = offset
                    + Point3::new([next() - 0.5, next() - 0.5, next() - 0.6]) * (12.0 * scale);
                for &(k, e, point) in &on_faces {
                    let d = q.distance(point);
                    let face = p.parts[k].bounds.distance(q);
                    assert!(face <= d, "face {k}: {face} > {d} at {q:?}");
                    if let Some(e) = e {
                        let edge = p.parts[k].edges[e].0.distance(q);
                        assert!(edge <= d + 1e-12 * size, "edge {e} of {k}: {edge} > {d}");
                    }
                }
            }
        }
    }

    #[test]
    fn the_search_by_face_equals_a_search_of_every_cell() {
        for (scale, offset, noise) in [
            (1.0, Point3::ZERO, 0.05),
            (1.0, Point3::ZERO, 0.5),
            (1e3, Point3::new([1e4, -1e4, 1e4]), 0.05),
            (1e3, Point3::new([1e4, -1e4, 1e4]), 0.5),
        ] {
            let shape = holed_block(scale, offset);
            let size = shape.size();
            let p = ShapeProjector::new(&shape, 0.0).unwrap();
            assert!(p.once[0] && p.once[1] && p.once[2] && !p.once[3]);
            let mut next = uniform(0x2545_f491_4f6c_dd1d);
            let mut faces_seen = [0usize; 4];
            for k in 0..1500 {
                // Near a random cell's centre, or anywhere around the block.
                let q = if k % 4 == 0 {
                    offset
                        + Point3::new([next() - 0.5, next() - 0.5, next() - 0.6]) * (14.0 * scale)
                } else {
                    let c = p.cells[(next() * p.cells.len() as f64) as usize].centre;
                    c + Point3::new([next() - 0.5, next() - 0.5, next() - 0.5])
                        * (2.0 * noise * size)
                };
                let n = p.nearest(q);
                // Every cell and edge segment of every face, and every once-solved face.
                let mut brute = f64::INFINITY;
                for cell in &p.cells {
                    if let Some(found) = p.search(cell, q) {
                        brute = brute.min(found.distance);
                    }
                }
                for (f, once) in p.once.iter().enumerate() {
                    if *once {
                        if let Some(found) = p.surface_foot(f, || p.once_start(f, q), q) {
                            brute = brute.min(found.distance);
                        }
                    }
                }
                assert!(
                    (n.distance - brute).abs() <= 1e-12 * size,
                    "{scale} {noise} {k}: {q:?} {} {brute}",
                    n.distance
                );
                assert!((q.distance(n.point) - n.distance).abs() <= 1e-12 * size);
                faces_seen[n.face] += 1;
            }
            // Every face is the nearest to some of the points.
            assert!(faces_seen.iter().all(|&c| c > 10), "{faces_seen:?}");
        }
    }
}

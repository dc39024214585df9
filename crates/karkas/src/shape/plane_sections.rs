//! Plane sections of a shape: every face's surface cut by the plane, kept where it lies in
//! the face, and the pieces joined across the faces' shared edges.
//!
//! Each face's NURBS surface is cut by the sectioner of the LL paper's plane sections
//! (Aulchenko et al., formulas (21)–(23); docs/methods.md §1.4) over its whole parameter
//! rectangle, at one chord tolerance `T` for the whole shape. A section polyline carries its
//! surface parameters; each chord between two of its points is cut where it crosses the
//! polygons of the face's loops in the parameters ([`FaceDomain`]; a plane's section is a
//! single chord, which may span a hole), and the parts whose midpoints lie in the face
//! ([`FaceDomain::contains`]) are kept, their ends evaluated on the surface: a piece ends on
//! the face's boundary, to the chord tolerance and the loops' own accuracy. Pieces from all faces are then joined end to
//! end where their ends lie within `2 T` of each other (two faces meeting along an edge each
//! end their piece on it), the shared end replaced by the two ends' midpoint; a piece whose
//! two ends meet so is closed. A section of a closed solid is thus closed loops.
//!
//! Guarantees: every point is on the plane to the sectioner's rounding, except the joined
//! ends, which lie within `T` of both faces' pieces; every point is within `T` of a face.
//! Not handled: a plane that contains a face or runs along an edge (the sectioner warns, and
//! the pieces may come out double).

use super::{FaceDomain, NurbsSurface, Shape};
use crate::core::Surface;
use crate::section::{cells_for_grid, Plane, SectionOptions, SectionWarning, Sectioner};
use crate::{Error, Point3, Result};

/// Ends of two pieces closer than this many chord tolerances are one point.
const JOIN: f64 = 2.0;

/// One piece of a shape's section by a plane.
#[derive(Clone, Debug, PartialEq)]
pub struct ShapeSectionPiece {
    /// The points in order (a closed piece does not repeat its first point).
    pub points: Vec<Point3>,
    /// True when the piece closes on itself.
    pub closed: bool,
    /// The faces the piece runs over (indices into the shape's faces), in order.
    pub faces: Vec<usize>,
}

/// The section of a shape by one plane.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct ShapeSection {
    /// The pieces, joined across faces.
    pub pieces: Vec<ShapeSectionPiece>,
    /// What the sectioner warned on a face (face index, warning).
    pub warnings: Vec<(usize, SectionWarning)>,
}

/// One face prepared for sections.
struct SectionedFace<'s> {
    index: usize,
    surface: &'s NurbsSurface<3>,
    sectioner: Sectioner<'s, NurbsSurface<3>, 3>,
    domain: FaceDomain,
}

/// Cuts a shape's faces by any number of planes; each face's surface is sampled once.
pub struct ShapeSectioner<'s> {
    /// The faces cut: index, surface, its sectioner and where the face lies on it.
    faces: Vec<SectionedFace<'s>>,
    tolerance: f64,
}

impl<'s> ShapeSectioner<'s> {
    /// Prepares sections of `shape` to the chord tolerance `tolerance` (default `1e-4` of the
    /// shape's size).
    ///
    /// Errors: [`Error::InvalidSetting`] for a tolerance that is not positive and finite, or a
    /// shape without faces or of size 0; the errors of [`FaceDomain::of`] and
    /// [`Sectioner::new`] for a face that cannot be sampled.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::{BSplineSurface, NurbsSurface};
    /// use karkas::section::Plane;
    /// use karkas::shape::{Face, Shape, ShapeSectioner};
    /// use karkas::{Grid, Point};
    ///
    /// // A unit square face at z = 0, cut by x = 0.25: one open piece along y.
    /// let control = Grid::from_fn(2, 2, |i, j| Point([i as f64, j as f64, 0.0]));
    /// let linear = (1, vec![0.0, 0.0, 1.0, 1.0]);
    /// let square = BSplineSurface::new(linear.clone(), linear, control)?;
    /// let shape = Shape { faces: vec![Face::whole(NurbsSurface::from_bspline(&square))], curves: vec![] };
    /// let section = ShapeSectioner::new(&shape, None)?.plane(&Plane::coordinate(0, 0.25)?);
    /// assert_eq!(section.pieces.len(), 1);
    /// let ys: Vec<f64> = section.pieces[0].points.iter().map(|p| p[1]).collect();
    /// assert!((ys[0] - ys[ys.len() - 1]).abs() > 1.0 - 1e-9);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(shape: &'s Shape, tolerance: Option<f64>) -> Result<Self> {
        let size = shape.size();
        if shape.faces.is_empty() || !(size > 0.0 && size.is_finite()) {
            return Err(Error::InvalidSetting {
                name: "shape",
                value: size,
                reason: "a section needs faces of a finite, non-zero size",
            });
        }
        let tolerance = tolerance.unwrap_or(1e-4 * size);
        if !(tolerance > 0.0 && tolerance.is_finite()) {
            return Err(Error::InvalidSetting {
                name: "tolerance",
                value: tolerance,
                reason: "the tolerance must be positive and finite",
            });
        }
        let mut faces = Vec::with_capacity(shape.faces.len());
        for (k, face) in shape.faces.iter().enumerate() {
            let s = &face.surface;
            let (rows, cols) = (s.control_points().rows(), s.control_points().cols());
            let options = SectionOptions {
                tolerance: Some(tolerance),
                cells: cells_for_grid(rows, cols),
                ..SectionOptions::default()
            };
            // A face far smaller than the tolerance has no section worth a polyline.
            match Sectioner::new(s, &options) {
                Ok(sectioner) => faces.push(SectionedFace {
                    index: k,
                    surface: s,
                    sectioner,
                    domain: FaceDomain::of(face)?,
                }),
                Err(Error::InvalidSetting {
                    name: "tolerance", ..
                }) => continue,
                Err(e) => return Err(e),
            }
        }
        Ok(ShapeSectioner { faces, tolerance })
    }

    /// The chord tolerance in use.
    pub fn tolerance(&self) -> f64 {
        self.tolerance
    }

    /// The section of the shape by `plane`.
    pub fn plane(&self, plane: &Plane<3>) -> ShapeSection {
        let mut pieces = Vec::new();
        let mut warnings = Vec::new();
        for face in &self.faces {
            let section = face.sectioner.plane(plane);
            warnings.extend(section.warnings.iter().map(|&w| (face.index, w)));
            for curve in &section.curves {
                let runs = inside_runs(face.surface, &face.domain, &curve.params, curve.closed);
                for (points, closed) in runs {
                    pieces.push(ShapeSectionPiece {
                        points,
                        closed,
                        faces: vec![face.index],
                    });
                }
            }
        }
        ShapeSection {
            pieces: join(pieces, JOIN * self.tolerance),
            warnings,
        }
    }
}

/// The runs of a section curve (parameters `params`, closed or not) that lie in the face, as
/// points, each ended on the boundary where it leaves the face; a closed curve wholly inside
/// stays closed.
///
/// Every chord between two points is cut where it crosses a loop of the face's domain (a
/// chord may span a hole: a plane's section is one chord), and each part between crossings is
/// in the face when its midpoint is.
fn inside_runs(
    surface: &NurbsSurface<3>,
    domain: &FaceDomain,
    params: &[(f64, f64)],
    closed: bool,
) -> Vec<(Vec<Point3>, bool)> {
    let n = params.len();
    if n < 2 {
        return Vec::new();
    }
    let chords = if closed { n } else { n - 1 };
    let mut runs: Vec<Vec<Point3>> = Vec::new();
    let mut run: Vec<Point3> = Vec::new();
    let mut starts_inside = false;
    let mut left = false;
    for c in 0..chords {
        let (a, b) = (params[c], params[(c + 1) % n]);
        let at = |s: f64| {
            let (u, v) = lerp(a, b, s);
            surface.eval(u, v)
        };
        let mut cuts = vec![0.0];
        cuts.extend(crossings(domain, a, b));
        cuts.push(1.0);
        for (k, w) in cuts.windows(2).enumerate() {
            let (u, v) = lerp(a, b, 0.5 * (w[0] + w[1]));
            if domain.contains(u, v) {
                if c == 0 && k == 0 {
                    starts_inside = true;
                }
                if run.is_empty() {
                    run.push(at(w[0]));
                }
                run.push(at(w[1]));
            } else {
                left = true;
                if run.len() >= 2 {
                    runs.push(std::mem::take(&mut run));
                }
                run.clear();
            }
        }
    }
    if closed && !left {
        // Wholly inside: the points themselves, without the repeated first one.
        run.pop();
        return vec![(run, true)];
    }
    if run.len() >= 2 {
        if closed && starts_inside && !runs.is_empty() {
            // The run through the curve's start: the last run goes on into the first.
            let first = runs.remove(0);
            run.extend_from_slice(&first[1..]);
        }
        runs.push(run);
    }
    runs.into_iter().map(|r| (r, false)).collect()
}

/// The point at the share `s` of the way from `a` to `b` in the parameters.
fn lerp(a: (f64, f64), b: (f64, f64), s: f64) -> (f64, f64) {
    (a.0 + s * (b.0 - a.0), a.1 + s * (b.1 - a.1))
}

/// Where the chord from `a` to `b` crosses the domain's loops, as shares of its way in
/// `(0, 1)`, in order.
fn crossings(domain: &FaceDomain, a: (f64, f64), b: (f64, f64)) -> Vec<f64> {
    let cross = |x: (f64, f64), y: (f64, f64)| x.0 * y.1 - x.1 * y.0;
    let ab = (b.0 - a.0, b.1 - a.1);
    let mut out = Vec::new();
    for l in &domain.loops {
        let p = &l.points;
        for i in 0..p.len() {
            let (c, d) = (p[i], p[(i + 1) % p.len()]);
            let cd = (d[0] - c[0], d[1] - c[1]);
            let denominator = cross(ab, cd);
            if denominator == 0.0 {
                continue;
            }
            let ac = (c[0] - a.0, c[1] - a.1);
            let s = cross(ac, cd) / denominator;
            let r = cross(ac, ab) / denominator;
            if s > 0.0 && s < 1.0 && (0.0..1.0).contains(&r) {
                out.push(s);
            }
        }
    }
    out.sort_by(f64::total_cmp);
    out
}

/// Joins `pieces` end to end where ends lie within `reach` of each other (nearest first
/// from each end), and closes a piece whose ends meet so.
fn join(pieces: Vec<ShapeSectionPiece>, reach: f64) -> Vec<ShapeSectionPiece> {
    let (mut closed, mut open): (Vec<_>, Vec<_>) = pieces.into_iter().partition(|p| p.closed);
    let mut out = Vec::new();
    while let Some(mut chain) = open.pop() {
        // Grow the chain at its end, then (reversed) at its start.
        for _ in 0..2 {
            while let Some((k, flip)) = nearest_end(&open, chain_end(&chain), reach) {
                let mut next = open.swap_remove(k);
                if flip {
                    next.points.reverse();
                    next.faces.reverse();
                }
                let joint = midpoint(chain_end(&chain), next.points[0]);
                if let Some(last) = chain.points.last_mut() {
                    *last = joint;
                }
                chain.points.extend_from_slice(&next.points[1..]);
                chain.faces.extend(next.faces);
            }
            chain.points.reverse();
            chain.faces.reverse();
        }
        let (first, last) = (chain.points[0], chain_end(&chain));
        if chain.points.len() > 2 && first.distance(last) <= reach {
            chain.points[0] = midpoint(first, last);
            chain.points.pop();
            chain.closed = true;
        }
        out.push(chain);
    }
    closed.append(&mut out);
    closed
}

/// The last point of a piece.
fn chain_end(piece: &ShapeSectionPiece) -> Point3 {
    piece.points[piece.points.len() - 1]
}

/// The open piece with an end nearest `p` within `reach`: its index and whether it must be
/// reversed to start there.
fn nearest_end(open: &[ShapeSectionPiece], p: Point3, reach: f64) -> Option<(usize, bool)> {
    let mut best: Option<(f64, usize, bool)> = None;
    for (k, piece) in open.iter().enumerate() {
        for (end, flip) in [(piece.points[0], false), (chain_end(piece), true)] {
            let d = end.distance(p);
            if d <= reach && best.is_none_or(|b| d < b.0) {
                best = Some((d, k, flip));
            }
        }
    }
    best.map(|(_, k, flip)| (k, flip))
}

/// The midpoint of `a` and `b`.
fn midpoint(a: Point3, b: Point3) -> Point3 {
    a + (b - a) * 0.5
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::conic::{elliptic_arc, line_segment};
    use crate::bspline::sweep::{cylinder, plane, Frame};
    use crate::shape::{Edge, EdgeLoop, Face};
    use std::f64::consts::TAU;

    /// A cup in a plate, `scale` about `offset`: the plate `[-2, 2]^2` at z = 0 with a round
    /// hole of radius 1, the hole's wall (a whole cylinder down to z = -1) and its bottom (a
    /// plane trimmed by a circle).
    fn cup(scale: f64, offset: Point3) -> Shape {
        let at = |x: f64, y: f64, z: f64| offset + Point3::new([x, y, z]) * scale;
        let top = Frame::new(
            at(0.0, 0.0, 0.0),
            Point3::new([0.0, 0.0, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap();
        let low = Frame::new(at(0.0, 0.0, -1.0), top.z, top.x).unwrap();
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
        let plate = Face {
            surface: plane(
                &top,
                (-2.0 * scale, 2.0 * scale),
                (-2.0 * scale, 2.0 * scale),
            )
            .unwrap(),
            loops: vec![outer, EdgeLoop::new(vec![circle(&top, false)], false)],
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
        Shape {
            faces: vec![plate, wall, bottom],
            curves: vec![],
        }
    }

    fn length(piece: &ShapeSectionPiece) -> f64 {
        let p = &piece.points;
        let open: f64 = p.windows(2).map(|w| w[0].distance(w[1])).sum();
        open + if piece.closed {
            p[0].distance(p[p.len() - 1])
        } else {
            0.0
        }
    }

    #[test]
    fn a_plane_through_the_hole_runs_over_the_plate_down_the_wall_and_across_the_bottom() {
        for (scale, offset) in [(1.0, Point3::ZERO), (1e3, Point3::new([1e4, -2e4, 3e4]))] {
            let shape = cup(scale, offset);
            let sectioner = ShapeSectioner::new(&shape, None).unwrap();
            let t = sectioner.tolerance();
            let x = offset[0] + 0.5 * scale;
            let section = sectioner.plane(&Plane::coordinate(0, x).unwrap());
            assert_eq!(section.pieces.len(), 1, "{scale}: {section:?}");
            let piece = &section.pieces[0];
            assert!(!piece.closed);
            assert_eq!(piece.faces, vec![0, 1, 2, 1, 0], "{scale}");
            // Two plate pieces of 2 - sqrt(3)/2, two wall pieces of 1, the bottom's sqrt(3).
            assert!(
                (length(piece) - 6.0 * scale).abs() <= 4.0 * t,
                "{}",
                length(piece)
            );
            for p in &piece.points {
                assert!((p[0] - x).abs() <= 1e-9 * scale, "{p:?} off the plane");
            }
            let ends = [piece.points[0], piece.points[piece.points.len() - 1]];
            let mut ys: Vec<f64> = ends.iter().map(|p| (p[1] - offset[1]) / scale).collect();
            ys.sort_by(f64::total_cmp);
            assert!(
                (ys[0] + 2.0).abs() < 1e-9 && (ys[1] - 2.0).abs() < 1e-9,
                "{ys:?}"
            );
        }
    }

    #[test]
    fn a_plane_across_the_wall_alone_gives_its_circle_and_one_beside_the_shape_nothing() {
        let shape = cup(1.0, Point3::ZERO);
        let sectioner = ShapeSectioner::new(&shape, Some(1e-5)).unwrap();
        let ring = sectioner.plane(&Plane::coordinate(2, -0.5).unwrap());
        assert_eq!(ring.pieces.len(), 1);
        assert!(ring.pieces[0].closed && ring.pieces[0].faces == vec![1]);
        assert!(
            (length(&ring.pieces[0]) - TAU).abs() < 1e-3,
            "{}",
            length(&ring.pieces[0])
        );
        let beside = sectioner.plane(&Plane::coordinate(0, 3.0).unwrap());
        assert!(beside.pieces.is_empty() && beside.warnings.is_empty());
    }

    #[test]
    fn bad_tolerances_and_empty_shapes_are_refused() {
        let shape = cup(1.0, Point3::ZERO);
        for t in [0.0, -1.0, f64::NAN, f64::INFINITY] {
            assert!(ShapeSectioner::new(&shape, Some(t)).is_err(), "{t}");
        }
        let empty = Shape {
            faces: vec![],
            curves: vec![],
        };
        assert!(ShapeSectioner::new(&empty, None).is_err());
    }
}

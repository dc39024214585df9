//! Where a face lies in its surface's parameters: its loops as polygons in `(u, v)`.
//!
//! Each edge is sampled along the loop (16 samples, each gap bisected until the polygon's
//! midpoint is within `1e-7` of the parameter rectangle's size of the inverted midpoint, at
//! most 2^12 gaps per edge). A sample is inverted onto the surface by Newton's method from
//! the previous sample's parameters, or by a global search ([`SurfaceProjector`]) for the
//! first sample of a loop and wherever Newton lands farther than the edge lies from the
//! surface; on a plane, in closed form (`flat.rs`). In a closed (periodic) direction the parameters are unwrapped along the loop; a
//! loop that turns once around that direction (a cap of a cylinder's side, the rim of a
//! hemisphere) is closed along the high side of the parameter rectangle, and when the face
//! does not lie on the high side of the highest such loop (to the left of a loop seen from
//! the face's normal) the whole rectangle is added as a loop, which turns the even-odd count
//! over; every loop is shifted by whole periods into the rectangle. Loops that stay at one point (a vertex loop at a sphere's
//! pole) bound nothing and are dropped.
//!
//! A point is inside the face when a ray from it crosses the loops an odd number of times.
//! A face whose only loop runs along the rectangle's border is the whole surface.

use super::flat::Flat;
use super::{Edge, Face, NurbsSurface};
use crate::core::{Curve, Interval, Surface};
use crate::geometry::surface_nearest::newton_foot;
use crate::geometry::SurfaceProjector;
use crate::{Point3, Result};

/// Samples of an edge before bisection.
const FIRST_SAMPLES: usize = 16;
/// Bisection depth per gap (at most `FIRST_SAMPLES * 2^MAX_DEPTH` samples per edge).
const MAX_DEPTH: usize = 8;
/// The bisection stops when the inverted midpoint is this close (relative to the
/// rectangle's size) to the polygon's.
const CHORD_TOLERANCE: f64 = 1e-7;

/// A closed polygon in a surface's parameters (the last point joins the first).
#[derive(Clone, Debug, PartialEq)]
pub struct ParameterLoop {
    /// The vertices `(u, v)`.
    pub points: Vec<[f64; 2]>,
}

impl ParameterLoop {
    /// Twice the signed area (positive when counter-clockwise in `(u, v)`).
    fn double_area(&self) -> f64 {
        let p = &self.points;
        (0..p.len())
            .map(|i| {
                let (a, b) = (p[i], p[(i + 1) % p.len()]);
                a[0] * b[1] - a[1] * b[0]
            })
            .sum()
    }
}

/// A face in its surface's parameters: the rectangle of the surface's domain and the
/// loops that cut the face out of it.
#[derive(Clone, Debug, PartialEq)]
pub struct FaceDomain {
    /// The surface's `u` interval.
    pub u: Interval,
    /// The surface's `v` interval.
    pub v: Interval,
    /// The loops; empty when the face is the whole rectangle.
    pub loops: Vec<ParameterLoop>,
}

impl FaceDomain {
    /// The domain of `face`: its loops inverted onto its surface (see the module docs).
    ///
    /// Errors: a surface whose samples are not finite (from the global search).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::bspline::{BSplineSurface, NurbsSurface};
    /// use karkas::shape::{Face, FaceDomain};
    /// use karkas::{Grid, Point};
    ///
    /// let control = Grid::from_fn(2, 2, |i, j| Point([2.0 * i as f64, j as f64, 0.0]));
    /// let square = BSplineSurface::new((1, vec![0.0, 0.0, 1.0, 1.0]), (1, vec![0.0, 0.0, 1.0, 1.0]), control)?;
    /// let domain = FaceDomain::of(&Face::whole(NurbsSurface::from_bspline(&square)))?;
    /// assert_eq!((domain.u.start, domain.u.end, domain.v.end), (0.0, 1.0, 1.0));
    /// assert!(domain.loops.is_empty()); // a whole face: no trimming loops
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn of(face: &Face) -> Result<FaceDomain> {
        let s = &face.surface;
        let (du, dv) = (s.domain_u(), s.domain_v());
        let mut domain = FaceDomain {
            u: du,
            v: dv,
            loops: Vec::new(),
        };
        if face.loops.is_empty() {
            return Ok(domain);
        }
        let mut inverter = Inverter::new(s)?;
        let mut turns = Vec::new();
        for edge_loop in &face.loops {
            let mut points: Vec<[f64; 2]> = Vec::new();
            let mut moved = 0.0f64;
            let start = edge_loop.edges.first().map(|e| e.point_along(0.0));
            if !edge_loop.parameter_curves.is_empty() {
                sample_parameter_curves(&edge_loop.parameter_curves, s, &mut points);
                if points.len() >= 3 {
                    let (closed, mut loop_turns) = close_loop(points, s, face.same_sense);
                    domain.loops.push(closed);
                    turns.append(&mut loop_turns);
                }
                continue;
            }
            for edge in &edge_loop.edges {
                inverter.sample_edge(edge, &mut points)?;
                if let Some(a) = start {
                    for s in [0.25, 0.5, 0.75, 1.0] {
                        moved = moved.max(edge.point_along(s).distance(a));
                    }
                }
            }
            // A loop that stays at one point bounds nothing.
            if points.len() < 3 || moved <= 1e-12 * inverter.size {
                continue;
            }
            let (closed, mut loop_turns) = close_loop(points, s, face.same_sense);
            domain.loops.push(closed);
            turns.append(&mut loop_turns);
        }
        complete_turns(&mut domain, &turns);
        if domain.is_whole_rectangle() {
            domain.loops.clear();
        }
        Ok(domain)
    }

    /// True when no loop cuts the rectangle.
    pub fn is_whole(&self) -> bool {
        self.loops.is_empty()
    }

    /// True when `(u, v)` lies in the face: inside the rectangle, and inside an odd number of
    /// loops (when there are loops).
    pub fn contains(&self, u: f64, v: f64) -> bool {
        let margin_u = 1e-12 * self.u.length();
        let margin_v = 1e-12 * self.v.length();
        if u < self.u.start - margin_u
            || u > self.u.end + margin_u
            || v < self.v.start - margin_v
            || v > self.v.end + margin_v
        {
            return false;
        }
        if self.loops.is_empty() {
            return true;
        }
        let mut inside = false;
        for l in &self.loops {
            let p = &l.points;
            let mut j = p.len() - 1;
            for i in 0..p.len() {
                let (a, b) = (p[i], p[j]);
                if (a[1] > v) != (b[1] > v) {
                    let x = a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                    if u < x {
                        inside = !inside;
                    }
                }
                j = i;
            }
        }
        inside
    }

    /// True when the loops are one polygon along the rectangle's border (to `1e-9` of its
    /// size) covering its area.
    fn is_whole_rectangle(&self) -> bool {
        if self.loops.len() != 1 {
            return self.loops.is_empty();
        }
        let (du, dv) = (self.u, self.v);
        let tu = 1e-9 * du.length();
        let tv = 1e-9 * dv.length();
        let on_border = self.loops[0].points.iter().all(|p| {
            (p[0] - du.start).abs() <= tu
                || (p[0] - du.end).abs() <= tu
                || (p[1] - dv.start).abs() <= tv
                || (p[1] - dv.end).abs() <= tv
        });
        let area = 0.5 * self.loops[0].double_area().abs();
        on_border && area >= (1.0 - 1e-6) * du.length() * dv.length()
    }
}

/// A loop that turns once around a periodic direction: the direction (0 for `u`), the mean
/// of its other parameter, and whether the face lies on the high side of it.
#[derive(Clone, Copy, Debug)]
struct Turn {
    axis: usize,
    mean: f64,
    face_high: bool,
}

/// Closes a loop that turns once around a periodic direction along the rectangle's high
/// side in the other direction (the caller completes the parity, see [`complete_turns`]),
/// and shifts it by whole periods into the rectangle.
fn close_loop(
    mut points: Vec<[f64; 2]>,
    s: &NurbsSurface<3>,
    same_sense: bool,
) -> (ParameterLoop, Vec<Turn>) {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let first = points[0];
    let last = points[points.len() - 1];
    let mut turns = Vec::new();
    for (axis, closed, d, other) in [(0, s.is_closed_u(), du, dv), (1, s.is_closed_v(), dv, du)] {
        if !closed {
            continue;
        }
        let period = d.length();
        let turn = last[axis] - first[axis];
        if (turn.abs() - period).abs() > 0.25 * period {
            continue;
        }
        // Running +u with the face on the left, the face lies above (higher v); running +v
        // with the face on the left, it lies at lower u.
        let increasing = turn > 0.0;
        let left = same_sense;
        let face_high = if axis == 0 {
            increasing == left
        } else {
            increasing != left
        };
        let mean = points.iter().map(|p| p[1 - axis]).sum::<f64>() / points.len() as f64;
        turns.push(Turn {
            axis,
            mean,
            face_high,
        });
        let mut a = last;
        let mut b = first;
        a[1 - axis] = other.end;
        b[1 - axis] = other.end;
        points.push(a);
        points.push(b);
    }
    for (axis, closed, d) in [(0, s.is_closed_u(), du), (1, s.is_closed_v(), dv)] {
        if !closed {
            continue;
        }
        let (lo, hi) = points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                (lo.min(p[axis]), hi.max(p[axis]))
            });
        let centre = 0.5 * (lo + hi);
        let mid = 0.5 * (d.start + d.end);
        let k = ((mid - centre) / d.length()).round();
        if k != 0.0 {
            for p in &mut points {
                p[axis] += k * d.length();
            }
        }
    }
    (ParameterLoop { points }, turns)
}

/// Completes the loops closed along the high side by [`close_loop`]: an odd number of them
/// counts the strip beyond the highest as inside, which is right when the face lies above
/// the highest; otherwise the whole rectangle is added as one more loop, which turns every
/// strip over (even-odd).
fn complete_turns(domain: &mut FaceDomain, turns: &[Turn]) {
    for axis in 0..2 {
        let mine: Vec<&Turn> = turns.iter().filter(|t| t.axis == axis).collect();
        let Some(top) = mine.iter().max_by(|a, b| a.mean.total_cmp(&b.mean)) else {
            continue;
        };
        if (mine.len() % 2 == 1) != top.face_high {
            let (u, v) = (domain.u, domain.v);
            domain.loops.push(ParameterLoop {
                points: vec![
                    [u.start, v.start],
                    [u.end, v.start],
                    [u.end, v.end],
                    [u.start, v.end],
                ],
            });
        }
    }
}

/// Samples a loop given in the surface's parameters: each curve at `8 (n + 2)` points for
/// `n` control points (at least 32), each gap halved while the polygon's midpoint is farther
/// than `CHORD_TOLERANCE` of the parameter rectangle's size from the curve's (as the edges'
/// samples are refined: a fixed count left the polygon of a hole's circle 3e-3 inside it on a
/// 70 mm plate), consecutive duplicates dropped. In a closed direction
/// each curve is moved by whole periods to start where the one before it ends: a writer may
/// give the two uses of a seam on either side of the period (Open CASCADE's IGES of a whole
/// torus runs its four pieces from `(2 pi, 2 pi)` to `(0, 2 pi)`, then from `(2 pi, 0)`).
fn sample_parameter_curves(
    curves: &[crate::bspline::NurbsCurve<2>],
    s: &NurbsSurface<3>,
    out: &mut Vec<[f64; 2]>,
) {
    let periods = [
        s.is_closed_u().then(|| s.domain_u().length()),
        s.is_closed_v().then(|| s.domain_v().length()),
    ];
    let tolerance = CHORD_TOLERANCE * s.domain_u().length().hypot(s.domain_v().length());
    for c in curves {
        let d = c.domain();
        let mut shift = [0.0; 2];
        if let Some(&last) = out.last() {
            let start = c.eval(d.start).0;
            for (axis, period) in periods.iter().enumerate() {
                if let Some(period) = period {
                    shift[axis] = ((last[axis] - start[axis]) / period).round() * period;
                }
            }
        }
        let n = (8 * (c.control_points().len() + 2)).max(32);
        let at = |t: f64| {
            let q = c.eval(t).0;
            [q[0] + shift[0], q[1] + shift[1]]
        };
        let mut a = (d.start, at(d.start));
        if out.last() != Some(&a.1) {
            out.push(a.1);
        }
        for k in 1..=n {
            let t = d.uniform(k, n + 1);
            let b = (t, at(t));
            bisect_parameter_curve(&at, a, b, tolerance, 0, out);
            a = b;
        }
    }
}

/// Appends the samples of a parameter curve strictly after `a` up to `b` (parameter, point),
/// halving the gap (to depth `MAX_DEPTH`) while the curve's midpoint lies farther than
/// `tolerance` from the chord's, as the edges' samples are refined.
fn bisect_parameter_curve(
    at: &dyn Fn(f64) -> [f64; 2],
    a: (f64, [f64; 2]),
    b: (f64, [f64; 2]),
    tolerance: f64,
    depth: usize,
    out: &mut Vec<[f64; 2]>,
) {
    if depth < MAX_DEPTH {
        let tm = 0.5 * (a.0 + b.0);
        let pm = at(tm);
        let chord = [0.5 * (a.1[0] + b.1[0]), 0.5 * (a.1[1] + b.1[1])];
        if (pm[0] - chord[0]).hypot(pm[1] - chord[1]) > tolerance {
            bisect_parameter_curve(at, a, (tm, pm), tolerance, depth + 1, out);
            bisect_parameter_curve(at, (tm, pm), b, tolerance, depth + 1, out);
            return;
        }
    }
    if out.last() != Some(&b.1) {
        out.push(b.1);
    }
}

/// Inverts points of a face's edges onto its surface.
struct Inverter<'a> {
    surface: &'a NurbsSurface<3>,
    /// The surface's affine form when it is a plane: feet in closed form.
    flat: Option<Flat>,
    projector: Option<SurfaceProjector<'a, NurbsSurface<3>, 3>>,
    /// The size of the surface's control net.
    size: f64,
    /// The size of the parameter rectangle.
    uv_size: f64,
    /// The parameters of the previous sample of the loop.
    previous: Option<[f64; 2]>,
    /// The largest distance of an edge sample from the surface met so far.
    gap: f64,
}

impl<'a> Inverter<'a> {
    fn new(surface: &'a NurbsSurface<3>) -> Result<Self> {
        let pts = surface.control_points().as_slice();
        let size = pts.iter().map(|p| p.distance(pts[0])).fold(0.0, f64::max);
        let (du, dv) = (surface.domain_u(), surface.domain_v());
        Ok(Inverter {
            surface,
            flat: Flat::of(surface),
            projector: None,
            size,
            uv_size: du.length().hypot(dv.length()),
            previous: None,
            gap: 1e-9 * size,
        })
    }

    /// Appends the parameters of `edge`'s samples along the loop (its end included, its
    /// start only when `out` is empty).
    fn sample_edge(&mut self, edge: &Edge, out: &mut Vec<[f64; 2]>) -> Result<()> {
        let at = |s: f64, me: &mut Self| -> Result<[f64; 2]> { me.invert(edge.point_along(s)) };
        let mut s0 = 0.0;
        let mut p0 = at(0.0, self)?;
        if out.is_empty() {
            out.push(p0);
        } else if let Some(&last) = out.last() {
            p0 = self.unwrap_near(p0, last);
        }
        for k in 1..=FIRST_SAMPLES {
            let s1 = k as f64 / FIRST_SAMPLES as f64;
            let p1 = at(s1, self)?;
            let p1 = self.unwrap_near(p1, p0);
            self.bisect((s0, p0), (s1, p1), 0, &at, out)?;
            (s0, p0) = (s1, p1);
        }
        Ok(())
    }

    /// Appends the samples strictly after `a` up to `b`, bisecting where the polygon is not
    /// yet within the chord tolerance.
    fn bisect(
        &mut self,
        a: (f64, [f64; 2]),
        b: (f64, [f64; 2]),
        depth: usize,
        at: &dyn Fn(f64, &mut Self) -> Result<[f64; 2]>,
        out: &mut Vec<[f64; 2]>,
    ) -> Result<()> {
        if depth < MAX_DEPTH {
            let sm = 0.5 * (a.0 + b.0);
            self.previous = Some(a.1);
            let pm = at(sm, self)?;
            let pm = self.unwrap_near(pm, a.1);
            let chord = [0.5 * (a.1[0] + b.1[0]), 0.5 * (a.1[1] + b.1[1])];
            let off = (pm[0] - chord[0]).hypot(pm[1] - chord[1]);
            if off > CHORD_TOLERANCE * self.uv_size {
                self.bisect(a, (sm, pm), depth + 1, at, out)?;
                self.bisect((sm, pm), b, depth + 1, at, out)?;
                return Ok(());
            }
        }
        out.push(b.1);
        self.previous = Some(b.1);
        Ok(())
    }

    /// `p` moved by whole periods (in the closed directions) to lie nearest `near`.
    fn unwrap_near(&self, mut p: [f64; 2], near: [f64; 2]) -> [f64; 2] {
        let s = self.surface;
        for (axis, closed, d) in [
            (0, s.is_closed_u(), s.domain_u()),
            (1, s.is_closed_v(), s.domain_v()),
        ] {
            if closed {
                let period = d.length();
                p[axis] += ((near[axis] - p[axis]) / period).round() * period;
            }
        }
        p
    }

    /// The parameters of the point of the surface nearest `q`: the orthogonal projection on
    /// a plane, else Newton from the previous sample, or the global search.
    fn invert(&mut self, q: Point3) -> Result<[f64; 2]> {
        if let Some((u, v)) = self.flat.and_then(|flat| flat.foot(q)) {
            self.previous = Some([u, v]);
            return Ok([u, v]);
        }
        let s = self.surface;
        if let Some(start) = self.previous {
            let closed = (s.is_closed_u(), s.is_closed_v());
            let foot = newton_foot(s, q, (start[0], start[1]), closed, 0.0);
            if foot.distance <= 4.0 * self.gap + 1e-9 * self.size {
                let uv = self.unwrap_near([foot.u, foot.v], start);
                self.previous = Some(uv);
                return Ok(uv);
            }
        }
        if self.projector.is_none() {
            self.projector = Some(SurfaceProjector::new(self.surface, (24, 24), 0.0)?);
        }
        let near = self
            .projector
            .as_ref()
            .map(|p| p.nearest(q))
            .ok_or(crate::Error::Internal {
                what: "the face's projector",
            })?;
        self.gap = self.gap.max(near.distance);
        let uv = match self.previous {
            Some(prev) => self.unwrap_near([near.u, near.v], prev),
            None => [near.u, near.v],
        };
        self.previous = Some(uv);
        Ok(uv)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::bspline::conic::{elliptic_arc, line_segment};
    use crate::bspline::sweep::{cylinder, Frame};
    use crate::shape::{Edge, EdgeLoop};
    use std::f64::consts::PI;

    fn frame() -> Frame {
        Frame::new(
            Point3::ZERO,
            Point3::new([0.0, 0.0, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap()
    }

    fn edge(curve: crate::bspline::NurbsCurve<3>, forward: bool) -> Edge {
        Edge { curve, forward }
    }

    /// The side of a cylinder of radius 1, height 3, bounded as Open CASCADE writes it: the
    /// top circle backwards, the seam down, the bottom circle, the seam up.
    fn cylinder_side() -> Face {
        let f = frame();
        let surface = cylinder(&f, 1.0, (0.0, 2.0 * PI), (0.0, 3.0))
            .unwrap()
            .with_closed(true, false);
        let circle = |z: f64| elliptic_arc(f.at(0.0, 0.0, z), f.x, f.y, (0.0, 2.0 * PI)).unwrap();
        let seam = line_segment(f.at(1.0, 0.0, 0.0), f.at(1.0, 0.0, 3.0), (0.0, 3.0)).unwrap();
        Face {
            surface,
            loops: vec![EdgeLoop::new(
                vec![
                    edge(circle(3.0), false),
                    edge(seam.clone(), false),
                    edge(circle(0.0), true),
                    edge(seam, true),
                ],
                false,
            )],
            same_sense: true,
            bounds_solid: true,
        }
    }

    #[test]
    fn a_cylinder_side_with_seams_is_the_whole_rectangle() {
        let d = FaceDomain::of(&cylinder_side()).unwrap();
        assert!(
            d.is_whole(),
            "{:?}",
            d.loops.first().map(|l| l.points.len())
        );
        assert!(d.contains(1.0, 1.0) && !d.contains(1.0, 3.5));
    }

    #[test]
    fn a_band_bounded_by_two_circles_is_closed_across_the_period() {
        // A band 1 <= z <= 2 of the cylinder 0 <= z <= 3, bounded by two circles only (no
        // seam): each loop turns once around u and is closed on the band's side.
        let f = frame();
        let mut face = cylinder_side();
        let circle = |z: f64| elliptic_arc(f.at(0.0, 0.0, z), f.x, f.y, (0.0, 2.0 * PI)).unwrap();
        face.loops = vec![
            EdgeLoop::new(vec![edge(circle(1.0), true)], true),
            EdgeLoop::new(vec![edge(circle(2.0), false)], false),
        ];
        let d = FaceDomain::of(&face).unwrap();
        assert_eq!(d.loops.len(), 2);
        for (u, v, inside) in [
            (0.5, 1.5, true),
            (3.0, 1.01, true),
            (6.0, 1.99, true),
            (1.0, 0.5, false),
            (4.0, 2.5, false),
        ] {
            assert_eq!(d.contains(u, v), inside, "({u}, {v})");
        }
    }

    /// A whole torus (major radius 5, minor 1.5) bounded as Open CASCADE writes it: one loop
    /// of its two seam circles, each used backwards and then forwards.
    fn whole_torus() -> Face {
        use crate::bspline::sweep::torus;
        let f = frame();
        let surface = torus(&f, 5.0, 1.5, (0.0, 2.0 * PI), (0.0, 2.0 * PI))
            .unwrap()
            .with_closed(true, true);
        // The tube's circle at u = 0, and the outer circle at v = 0.
        let tube =
            elliptic_arc(f.at(5.0, 0.0, 0.0), f.x * 1.5, f.z * 1.5, (0.0, 2.0 * PI)).unwrap();
        let outer = elliptic_arc(f.origin, f.x * 6.5, f.y * 6.5, (0.0, 2.0 * PI)).unwrap();
        Face {
            surface,
            loops: vec![EdgeLoop::new(
                vec![
                    edge(tube.clone(), false),
                    edge(outer.clone(), false),
                    edge(tube, true),
                    edge(outer, true),
                ],
                true,
            )],
            same_sense: true,
            bounds_solid: true,
        }
    }

    #[test]
    fn a_whole_torus_bounded_by_its_seams_is_the_whole_rectangle() {
        let d = FaceDomain::of(&whole_torus()).unwrap();
        assert!(
            d.is_whole(),
            "{:?}",
            d.loops
                .iter()
                .map(|l| (l.points.len(), l.double_area()))
                .collect::<Vec<_>>()
        );
        for (u, v) in [(0.1, 0.1), (3.0, 3.0), (6.2, 1.0), (1.0, 6.2)] {
            assert!(d.contains(u, v), "({u}, {v})");
        }
    }

    #[test]
    fn newton_finds_the_foot_on_a_cylinder() {
        let s = cylinder(&frame(), 2.0, (0.0, PI), (0.0, 1.0)).unwrap();
        let q = Point3::new([0.0, 3.0, 0.5]);
        let foot = newton_foot(&s, q, (1.0, 0.2), (false, false), 0.0);
        assert!((foot.distance - 1.0).abs() < 1e-14);
        assert!(
            s.eval(foot.u, foot.v)
                .distance(Point3::new([0.0, 2.0, 0.5]))
                < 1e-14
        );
    }

    #[test]
    fn a_hole_given_in_the_parameters_is_sampled_to_the_chord_tolerance() {
        // A plane [0, 70] x [0, 56] (its parameters are its coordinates) with a hole of
        // radius 2.6 given as a rational circle in the parameters, as IGES entity 142 gives it.
        let f = frame();
        let surface = crate::bspline::sweep::plane(&f, (0.0, 70.0), (0.0, 56.0)).unwrap();
        let centre = crate::Point([35.0, 20.0]);
        let (x, y) = (crate::Point([2.6, 0.0]), crate::Point([0.0, 2.6]));
        let circle = elliptic_arc(centre, x, y, (0.0, 2.0 * PI)).unwrap();
        let mut points = Vec::new();
        sample_parameter_curves(&[circle], &surface, &mut points);
        // Every chord's midpoint within 1e-7 of the rectangle's size of the circle.
        let tolerance = CHORD_TOLERANCE * 70f64.hypot(56.0);
        for w in points.windows(2) {
            let m = [
                0.5 * (w[0][0] + w[1][0]) - 35.0,
                0.5 * (w[0][1] + w[1][1]) - 20.0,
            ];
            let off = 2.6 - m[0].hypot(m[1]);
            assert!(
                off <= tolerance,
                "a chord's midpoint {off:e} inside the circle"
            );
        }
    }
}

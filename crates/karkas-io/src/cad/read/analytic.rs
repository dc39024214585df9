//! The curves and surfaces of CAD files before they become rational B-splines: lines,
//! conics and the analytic surfaces, which are unbounded or periodic and become NURBS only
//! over a stretch of their parameters, the stretch a face's or an edge's bounds give.
//!
//! The parameters are those of ISO 10303-42 and Open CASCADE (see
//! [`karkas::bspline::sweep`]): arc length along a line's unit direction; the angle on a
//! circle or ellipse from the placement's `x` axis; `t` of `a cosh t x + b sinh t y` on a
//! hyperbola and of `f (t² x + 2 t y)` on a parabola. An edge's stretch comes from its
//! vertices' parameters; a face's rectangle from its loops: each loop sampled, each sample's
//! surface parameters found in closed form (angles unwrapped along the loop: a loop that
//! turns around an axis spans the whole turn), the extremes that fall inside an edge refined
//! by golden-section search.

use karkas::bspline::conic::{elliptic_arc, hyperbolic_arc, line_segment, parabolic_arc};
use karkas::bspline::sweep::{cone, cylinder, extrusion, plane, revolution, sphere, torus, Frame};
use karkas::bspline::{NurbsCurve, NurbsSurface};
use karkas::geometry::{parameter_on_curve, CurveProjector, SurfaceProjector};
use karkas::{Curve, Point3};
use std::f64::consts::{FRAC_PI_2, PI, TAU};

/// Samples of an edge when a face's parameter range is measured.
const RANGE_SAMPLES: usize = 32;

/// How near a point must be to a B-spline basis curve for its parameter to be found locally
/// (a vertex on its edge's curve; see [`parameter_on_curve`]): `ON_CURVE` of the curve's
/// control box plus rounding of its coordinates. Farther points take the global search.
fn on_curve_tolerance(c: &NurbsCurve<3>) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
    for p in c.control_points() {
        for k in 0..3 {
            lo[k] = lo[k].min(p[k]);
            hi[k] = hi[k].max(p[k]);
        }
    }
    let extent = (0..3).map(|k| hi[k] - lo[k]).fold(0.0, f64::hypot);
    let far = (0..3)
        .map(|k| lo[k].abs().max(hi[k].abs()))
        .fold(0.0, f64::max);
    ON_CURVE * extent + 64.0 * f64::EPSILON * far
}

/// The share of a curve's size within which a vertex counts as on it (a near-touch of the
/// curve with itself closer than this is below the file's precision).
const ON_CURVE: f64 = 1e-7;

/// A curve as a file defines it.
#[derive(Clone, Debug)]
pub(crate) enum BasisCurve {
    /// A rational B-spline (bounded).
    Nurbs(NurbsCurve<3>),
    /// The line `origin + t dir` (`dir` a unit vector).
    Line { origin: Point3, dir: Point3 },
    /// The ellipse `c + a cos t x + b sin t y` of a frame (a circle when `a == b`).
    Conic { frame: Frame, a: f64, b: f64 },
    /// The hyperbola's branch `c + a cosh t x + b sinh t y` of a frame.
    Hyperbola { frame: Frame, a: f64, b: f64 },
    /// The parabola `c + f (t² x + 2 t y)` of a frame and a focal distance `f`.
    Parabola { frame: Frame, focal: f64 },
}

impl BasisCurve {
    /// The period of a closed curve (a conic, or a B-spline marked closed).
    pub fn period(&self) -> Option<f64> {
        match self {
            BasisCurve::Conic { .. } => Some(TAU),
            BasisCurve::Nurbs(c) if c.is_closed() => Some(c.domain().length()),
            _ => None,
        }
    }

    /// The parameter of the point of the curve nearest `p` (in `[0, 2π)` on a conic).
    pub fn parameter_of(&self, p: Point3) -> Result<f64, String> {
        match self {
            BasisCurve::Line { origin, dir } => Ok((p - *origin).dot(*dir)),
            BasisCurve::Conic { frame, a, b } => {
                let d = p - frame.origin;
                Ok(((d.dot(frame.y) / b).atan2(d.dot(frame.x) / a)).rem_euclid(TAU))
            }
            BasisCurve::Hyperbola { frame, b, .. } => {
                Ok(((p - frame.origin).dot(frame.y) / b).asinh())
            }
            BasisCurve::Parabola { frame, focal } => {
                Ok((p - frame.origin).dot(frame.y) / (2.0 * focal))
            }
            BasisCurve::Nurbs(c) => match parameter_on_curve(c, p, on_curve_tolerance(c)) {
                Some(t) => Ok(t),
                None => CurveProjector::new(c, 0.0)
                    .map(|projector| projector.nearest(p).t)
                    .map_err(|e| e.to_string()),
            },
        }
    }

    /// The point at parameter `t`.
    pub fn point(&self, t: f64) -> Point3 {
        match self {
            BasisCurve::Line { origin, dir } => *origin + *dir * t,
            BasisCurve::Conic { frame, a, b } => {
                frame.origin + frame.x * (a * t.cos()) + frame.y * (b * t.sin())
            }
            BasisCurve::Hyperbola { frame, a, b } => {
                frame.origin + frame.x * (a * t.cosh()) + frame.y * (b * t.sinh())
            }
            BasisCurve::Parabola { frame, focal } => {
                frame.origin + frame.x * (focal * t * t) + frame.y * (2.0 * focal * t)
            }
            BasisCurve::Nurbs(c) => c.eval(t),
        }
    }

    /// The curve over `[t0, t1]` (`t0 < t1`, at most a period apart) as a NURBS.
    pub fn bounded(&self, t0: f64, t1: f64) -> Result<NurbsCurve<3>, String> {
        match self {
            BasisCurve::Line { .. } => line_segment(self.point(t0), self.point(t1), (t0, t1)),
            BasisCurve::Conic { frame, a, b } => {
                elliptic_arc(frame.origin, frame.x * *a, frame.y * *b, (t0, t1))
            }
            BasisCurve::Hyperbola { frame, a, b } => {
                hyperbolic_arc(frame.origin, frame.x * *a, frame.y * *b, (t0, t1))
            }
            BasisCurve::Parabola { frame, focal } => parabolic_arc(
                frame.origin,
                frame.x * *focal,
                frame.y * (2.0 * focal),
                (t0, t1),
            ),
            BasisCurve::Nurbs(c) => {
                let d = c.domain();
                if t0 <= d.start && t1 >= d.end {
                    return Ok(c.clone());
                }
                if c.is_closed() && (t0 < d.start || t1 > d.end) {
                    return self.wrapped_segment(c, t0, t1).map_err(|e| e.to_string());
                }
                c.segment(t0.max(d.start), t1.min(d.end))
            }
        }
        .map_err(|e| e.to_string())
    }

    /// A stretch of a closed B-spline that crosses its seam: returned over one piece when
    /// it fits in the domain after a shift by the period, else over the whole domain (the
    /// stretch is then the whole curve).
    fn wrapped_segment(
        &self,
        c: &NurbsCurve<3>,
        t0: f64,
        t1: f64,
    ) -> karkas::Result<NurbsCurve<3>> {
        let d = c.domain();
        let p = d.length();
        let k = ((t0 - d.start) / p).floor();
        let (a, b) = (t0 - k * p, t1 - k * p);
        if b <= d.end {
            c.segment(a.max(d.start), b.min(d.end))
        } else {
            Ok(c.clone().with_closed(false))
        }
    }

    /// The curve's own bounded stretch, when it has one without an edge (a B-spline's
    /// domain, a conic's full turn).
    pub fn natural_range(&self) -> Option<(f64, f64)> {
        match self {
            BasisCurve::Nurbs(c) => Some((c.domain().start, c.domain().end)),
            BasisCurve::Conic { .. } => Some((0.0, TAU)),
            BasisCurve::Line { .. }
            | BasisCurve::Hyperbola { .. }
            | BasisCurve::Parabola { .. } => None,
        }
    }
}

/// A surface as a file defines it.
#[derive(Clone, Debug)]
pub(crate) enum BasisSurface {
    /// A rational B-spline surface (bounded).
    Nurbs(NurbsSurface<3>),
    /// The plane `c + u x + v y`.
    Plane(Frame),
    /// Cylinder of a radius.
    Cylinder(Frame, f64),
    /// Cone of a radius at `v = 0` and a half-angle (radians).
    Cone(Frame, f64, f64),
    /// Sphere of a radius.
    Sphere(Frame, f64),
    /// Torus of a major and a minor radius.
    Torus(Frame, f64, f64),
    /// A profile turned about the axis through a point.
    Revolution {
        profile: BasisCurve,
        origin: Point3,
        axis: Point3,
    },
    /// A curve swept along a unit direction.
    Extrusion { curve: BasisCurve, dir: Point3 },
}

/// One loop of a face, sampled: for each edge, its samples `(s, point)` in loop order, `s`
/// the share of the edge's way (0 and 1 are its vertices), and the function that gives the
/// point at any share.
pub(crate) struct SampledEdge<'a> {
    pub samples: Vec<(f64, Point3)>,
    pub at: Box<dyn Fn(f64) -> Point3 + 'a>,
}

impl<'a> SampledEdge<'a> {
    /// `RANGE_SAMPLES + 1` samples of `at` over `[0, 1]`.
    pub(crate) fn new(at: Box<dyn Fn(f64) -> Point3 + 'a>) -> Self {
        let samples = (0..=RANGE_SAMPLES)
            .map(|k| {
                let s = k as f64 / RANGE_SAMPLES as f64;
                (s, at(s))
            })
            .collect();
        SampledEdge { samples, at }
    }
}

/// How one surface parameter is read off a point: a function, and whether it is an angle
/// (unwrapped along loops, a full turn when a loop turns around).
struct Coordinate<'f> {
    value: &'f dyn Fn(Point3) -> f64,
    angle: bool,
}

impl Coordinate<'_> {
    /// The value at `p`, unwrapped (for an angle) to lie nearest `near`.
    fn at(&self, p: Point3, near: Option<f64>) -> f64 {
        let x = (self.value)(p);
        match (self.angle, near) {
            (true, Some(n)) => x + ((n - x) / TAU).round() * TAU,
            _ => x,
        }
    }

    /// The range `(lo, hi)` of the coordinate over the loops, and whether it is a full turn.
    fn range(
        &self,
        loops: &[Vec<SampledEdge<'_>>],
        skip: &dyn Fn(Point3) -> bool,
    ) -> Option<(f64, f64, bool)> {
        let mut lo = f64::INFINITY;
        let mut hi = f64::NEG_INFINITY;
        let mut full = false;
        let mut anchor: Option<f64> = None;
        for edges in loops {
            let mut previous: Option<f64> = None;
            let mut first: Option<f64> = None;
            // The loop's values and where each extreme was met: (edge, sample index).
            let mut values: Vec<Vec<Option<f64>>> = Vec::new();
            for edge in edges {
                let mut row = Vec::with_capacity(edge.samples.len());
                for &(_, p) in &edge.samples {
                    if skip(p) {
                        row.push(None);
                        continue;
                    }
                    let x = self.at(p, previous.or(anchor));
                    previous = Some(x);
                    first = first.or(Some(x));
                    row.push(Some(x));
                }
                values.push(row);
            }
            let (Some(first), Some(last)) = (first, previous) else {
                continue;
            };
            if self.angle && (last - first).abs() > PI {
                full = true;
            }
            anchor = anchor.or(Some(first));
            for (e, row) in values.iter().enumerate() {
                for (k, x) in row.iter().enumerate() {
                    let Some(x) = *x else { continue };
                    let n = row.len() - 1;
                    let refine = |sign: f64| -> f64 {
                        if k == 0 || k == n || row[k - 1].is_none() || row[k + 1].is_none() {
                            return x;
                        }
                        let edge = &edges[e];
                        let (a, b) = (edge.samples[k - 1].0, edge.samples[k + 1].0);
                        let f = |s: f64| sign * self.at((edge.at)(s), Some(x));
                        sign * golden_max(&f, a, b).max(sign * x)
                    };
                    if x < lo {
                        lo = refine(-1.0);
                    }
                    if x > hi {
                        hi = refine(1.0);
                    }
                }
            }
        }
        lo.is_finite().then_some((
            lo,
            hi,
            full || (self.angle && hi - lo >= TAU * (1.0 - 1e-9)),
        ))
    }
}

/// The largest value of `f` on `[a, b]` by golden-section search (60 steps).
fn golden_max(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let r = 0.5 * (5f64.sqrt() - 1.0);
    let mut c = b - r * (b - a);
    let mut d = a + r * (b - a);
    let (mut fc, mut fd) = (f(c), f(d));
    for _ in 0..60 {
        if fc > fd {
            b = d;
            d = c;
            fd = fc;
            c = b - r * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + r * (b - a);
            fd = f(d);
        }
    }
    fc.max(fd).max(f(a)).max(f(b))
}

/// An angle range as the surface's: the full turn `[0, 2π]` (or the measured range).
fn angles(range: Option<(f64, f64, bool)>) -> ((f64, f64), bool) {
    match range {
        None => ((0.0, TAU), true),
        Some((_, _, true)) => ((0.0, TAU), true),
        Some((lo, hi, false)) => {
            let shift = (lo / TAU).floor() * TAU;
            ((lo - shift, hi - shift), false)
        }
    }
}

/// A linear range, refused when the loops give none (an unbounded surface without bounds).
fn linear(range: Option<(f64, f64, bool)>, what: &str) -> Result<(f64, f64), String> {
    match range {
        Some((lo, hi, _)) if hi > lo => Ok((lo, hi)),
        Some(_) => Err(format!("the bounds of a face on {what} span no area")),
        None => Err(format!(
            "{what} is unbounded and has no edges that bound it"
        )),
    }
}

impl BasisSurface {
    /// The surface over the rectangle `u x v` of its own parameters (angles in radians), as
    /// a NURBS; a B-spline surface is kept whole.
    pub fn over(&self, u: (f64, f64), v: (f64, f64)) -> Result<NurbsSurface<3>, String> {
        let turn = |r: (f64, f64)| r.1 - r.0 >= TAU * (1.0 - 1e-12);
        let s = match self {
            BasisSurface::Nurbs(s) => return Ok(s.clone()),
            BasisSurface::Plane(f) => plane(f, u, v),
            BasisSurface::Cylinder(f, r) => cylinder(f, *r, u, v),
            BasisSurface::Cone(f, r, a) => cone(f, *r, *a, u, v),
            BasisSurface::Sphere(f, r) => sphere(f, *r, u, v),
            BasisSurface::Torus(f, major, minor) => {
                return torus(f, *major, *minor, u, v)
                    .map(|s| s.with_closed(turn(u), turn(v)))
                    .map_err(|e| e.to_string())
            }
            BasisSurface::Revolution {
                profile,
                origin,
                axis,
            } => revolution(&profile.bounded(v.0, v.1)?, *origin, *axis, u),
            BasisSurface::Extrusion { curve, dir } => {
                return extrusion(&curve.bounded(u.0, u.1)?, *dir, v).map_err(|e| e.to_string())
            }
        };
        s.map(|s| s.with_closed(turn(u), false))
            .map_err(|e| e.to_string())
    }

    /// The surface over the smallest rectangle of its parameters holding the loops (the
    /// whole surface when bounded and without loops), as a NURBS with its closed directions
    /// marked.
    pub fn bounded(&self, loops: &[Vec<SampledEdge<'_>>]) -> Result<NurbsSurface<3>, String> {
        let bounds = LoopBounds { loops };
        match self {
            BasisSurface::Nurbs(s) => Ok(s.clone()),
            BasisSurface::Plane(f) => bounds.plane(f),
            BasisSurface::Cylinder(f, r) => bounds.cylinder(f, *r),
            BasisSurface::Cone(f, r, alpha) => bounds.cone(f, *r, *alpha),
            BasisSurface::Sphere(f, r) => bounds.sphere(f, *r),
            BasisSurface::Torus(f, major, minor) => bounds.torus(f, *major, *minor),
            BasisSurface::Revolution {
                profile,
                origin,
                axis,
            } => bounds.revolution(profile, *origin, *axis),
            BasisSurface::Extrusion { curve, dir } => bounds.extrusion(curve, *dir),
        }
    }
}

/// Never skips a sample.
fn never(_: Point3) -> bool {
    false
}

/// The loops of a face, and each kind of surface bounded by them.
struct LoopBounds<'l, 'e> {
    loops: &'l [Vec<SampledEdge<'e>>],
}

impl LoopBounds<'_, '_> {
    /// The range of a linear coordinate over the loops, refused when empty.
    fn linear(&self, value: &dyn Fn(Point3) -> f64, what: &str) -> Result<(f64, f64), String> {
        linear(
            Coordinate {
                value,
                angle: false,
            }
            .range(self.loops, &never),
            what,
        )
    }

    /// The range of an angle over the loops (samples where `skip` holds left out), and
    /// whether it is a full turn.
    fn angle(
        &self,
        value: &dyn Fn(Point3) -> f64,
        skip: &dyn Fn(Point3) -> bool,
    ) -> ((f64, f64), bool) {
        angles(Coordinate { value, angle: true }.range(self.loops, skip))
    }

    /// The azimuth range about `f`'s axis, samples within `tolerance` of the axis left out.
    fn azimuths(&self, f: &Frame, tolerance: f64) -> ((f64, f64), bool) {
        self.angle(&|p| azimuth(f, p), &|p| radial(f, p) < tolerance)
    }

    fn plane(&self, f: &Frame) -> Result<NurbsSurface<3>, String> {
        let u = self.linear(&|p| (p - f.origin).dot(f.x), "a plane")?;
        let v = self.linear(&|p| (p - f.origin).dot(f.y), "a plane")?;
        plane(f, u, v).map_err(|e| e.to_string())
    }

    fn cylinder(&self, f: &Frame, r: f64) -> Result<NurbsSurface<3>, String> {
        let (u, full) = self.azimuths(f, 1e-9 * r);
        let v = self.linear(&|p| (p - f.origin).dot(f.z), "a cylinder")?;
        let s = cylinder(f, r, u, v).map_err(|e| e.to_string())?;
        Ok(s.with_closed(full, false))
    }

    fn cone(&self, f: &Frame, r: f64, alpha: f64) -> Result<NurbsSurface<3>, String> {
        let (u, full) = self.azimuths(f, 1e-9 * r.abs().max(1.0));
        let c = alpha.cos();
        let v = self.linear(&|p| (p - f.origin).dot(f.z) / c, "a cone")?;
        let s = cone(f, r, alpha, u, v).map_err(|e| e.to_string())?;
        Ok(s.with_closed(full, false))
    }

    fn sphere(&self, f: &Frame, r: f64) -> Result<NurbsSurface<3>, String> {
        let (u, full) = self.azimuths(f, 1e-9 * r);
        let latitude = |p: Point3| ((p - f.origin).dot(f.z) / r).clamp(-1.0, 1.0).asin();
        let v = if full {
            (-FRAC_PI_2, FRAC_PI_2)
        } else {
            self.linear(&latitude, "a sphere")?
        };
        let s = sphere(f, r, u, v).map_err(|e| e.to_string())?;
        Ok(s.with_closed(full, false))
    }

    fn torus(&self, f: &Frame, major: f64, minor: f64) -> Result<NurbsSurface<3>, String> {
        let (u, full_u) = self.azimuths(f, 1e-9 * major);
        let tube = |p: Point3| (p - f.origin).dot(f.z).atan2(radial(f, p) - major);
        let (v, full_v) = self.angle(&tube, &never);
        let s = torus(f, major, minor, u, v).map_err(|e| e.to_string())?;
        Ok(s.with_closed(full_u, full_v))
    }

    fn revolution(
        &self,
        profile: &BasisCurve,
        origin: Point3,
        axis: Point3,
    ) -> Result<NurbsSurface<3>, String> {
        let (v0, v1) = match profile.natural_range() {
            Some(r) => r,
            None => self.line_along_axis(profile, axis)?,
        };
        let g = profile.bounded(v0, v1)?;
        let frame = profile_frame(&g, 0.5 * (v0 + v1), origin, axis)?;
        let near_axis = |p: Point3| radial(&frame, p) < 1e-12 * (1.0 + (p - origin).norm());
        let (u, full) = if in_half_plane(&g, &frame) {
            self.angle(&|p| azimuth(&frame, p), &near_axis)
        } else {
            // The azimuth less that of the profile's point on the same circle, found by
            // projecting onto the whole turn (whose v is the profile's parameter).
            let whole = revolution(&g, origin, axis, (0.0, TAU)).map_err(|e| e.to_string())?;
            let projector =
                SurfaceProjector::new(&whole, (64, 16), 0.0).map_err(|e| e.to_string())?;
            let turn =
                |p: Point3| azimuth(&frame, p) - azimuth(&frame, g.eval(projector.nearest(p).v));
            self.angle(&turn, &near_axis)
        };
        let s = revolution(&g, origin, axis, u).map_err(|e| e.to_string())?;
        Ok(s.with_closed(full, false))
    }

    /// A revolved line's range: its parameter where it meets each sample's circle.
    fn line_along_axis(&self, profile: &BasisCurve, axis: Point3) -> Result<(f64, f64), String> {
        let BasisCurve::Line { origin: o, dir } = profile else {
            return Err("a surface of revolution of an unbounded curve".into());
        };
        let along = dir.dot(axis);
        if along.abs() < 1e-12 {
            return Err("a surface of revolution of a line square to its axis".into());
        }
        self.linear(
            &|p: Point3| (p - *o).dot(axis) / along,
            "a surface of revolution",
        )
    }

    fn extrusion(&self, curve: &BasisCurve, dir: Point3) -> Result<NurbsSurface<3>, String> {
        let g = self.swept_curve(curve, dir)?;
        let v = self.sweep_range(curve, &g, dir)?;
        extrusion(&g, dir, v).map_err(|e| e.to_string())
    }

    /// The extruded curve, bounded to the loops' extent across the sweep.
    fn swept_curve(&self, curve: &BasisCurve, dir: Point3) -> Result<NurbsCurve<3>, String> {
        match curve {
            BasisCurve::Nurbs(c) => Ok(c.clone()),
            BasisCurve::Line { origin, dir: e } => {
                // u along the line after removing the sweep: p - origin = u e + v d.
                let (ee, ed) = (1.0, e.dot(dir));
                let det = ee - ed * ed;
                if det.abs() < 1e-12 {
                    return Err("an extrusion of a line along itself".into());
                }
                let value = |p: Point3| {
                    let w = p - *origin;
                    (w.dot(*e) - ed * w.dot(dir)) / det
                };
                let r = self.linear(&value, "an extrusion")?;
                curve.bounded(r.0, r.1)
            }
            BasisCurve::Conic { frame, .. }
            | BasisCurve::Hyperbola { frame, .. }
            | BasisCurve::Parabola { frame, .. } => {
                let n = frame.z;
                let dn = dir.dot(n);
                if dn.abs() < 1e-12 {
                    return Err("an extrusion of a conic along its own plane".into());
                }
                // The curve's parameter of the point where the sweep through `p` meets the
                // curve's plane.
                let value = |p: Point3| {
                    let q = p - dir * ((p - frame.origin).dot(n) / dn);
                    curve.parameter_of(q).unwrap_or(f64::NAN)
                };
                let r = if matches!(curve, BasisCurve::Conic { .. }) {
                    self.angle(&value, &never).0
                } else {
                    self.linear(&value, "an extrusion")?
                };
                curve.bounded(r.0, r.1)
            }
        }
    }

    /// v: the distance along the sweep, bounded by the samples against the curve's control
    /// points (the curve lies in their hull).
    fn sweep_range(
        &self,
        curve: &BasisCurve,
        g: &NurbsCurve<3>,
        dir: Point3,
    ) -> Result<(f64, f64), String> {
        let along = |p: Point3| p.dot(dir);
        let (cmin, cmax) = g
            .control_points()
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), c| {
                (lo.min(along(*c)), hi.max(along(*c)))
            });
        if let BasisCurve::Nurbs(_) = curve {
            let (lo, hi) = self.linear(&along, "an extrusion")?;
            return Ok((lo - cmax, hi - cmin));
        }
        let value = |p: Point3| match curve {
            BasisCurve::Line { origin, dir: e } => {
                let w = p - *origin;
                let ed = e.dot(dir);
                (w.dot(dir) - ed * w.dot(*e)) / (1.0 - ed * ed)
            }
            BasisCurve::Conic { frame, .. }
            | BasisCurve::Hyperbola { frame, .. }
            | BasisCurve::Parabola { frame, .. } => {
                (p - frame.origin).dot(frame.z) / dir.dot(frame.z)
            }
            BasisCurve::Nurbs(_) => 0.0,
        };
        self.linear(&value, "an extrusion")
    }
}

/// The frame of a revolution: its axis, and its x toward the profile's point at `mid`
/// (any normal of the axis when that point lies on it).
fn profile_frame(
    g: &NurbsCurve<3>,
    mid: f64,
    origin: Point3,
    axis: Point3,
) -> Result<Frame, String> {
    let mid = g.eval(mid);
    let reference = mid - origin - axis * (mid - origin).dot(axis);
    let x = if reference.norm() > 0.0 {
        reference
    } else {
        any_normal(axis)
    };
    Frame::new(origin, axis, x).map_err(|e| e.to_string())
}

/// Whether the profile lies in the half-plane of the frame's x (a revolved sketch), so that
/// the turn carrying it onto a point is that point's azimuth.
fn in_half_plane(g: &NurbsCurve<3>, frame: &Frame) -> bool {
    let origin = frame.origin;
    let size = g.control_points().iter().map(|q| (*q - origin).norm());
    let size = size.fold(0.0, f64::max);
    g.control_points().iter().all(|q| {
        let d = *q - origin;
        d.dot(frame.y).abs() <= 1e-12 * size && d.dot(frame.x) >= -1e-12 * size
    })
}

/// The angle of `p` about `f`'s `z` axis from its `x` axis, in `(-π, π]`.
fn azimuth(f: &Frame, p: Point3) -> f64 {
    let d = p - f.origin;
    d.dot(f.y).atan2(d.dot(f.x))
}

/// The distance of `p` from `f`'s `z` axis.
fn radial(f: &Frame, p: Point3) -> f64 {
    let d = p - f.origin;
    d.dot(f.x).hypot(d.dot(f.y))
}

/// A unit vector square to the unit vector `z`.
pub(crate) fn any_normal(z: Point3) -> Point3 {
    let trial = if z[0].abs() < 0.9 {
        Point3::new([1.0, 0.0, 0.0])
    } else {
        Point3::new([0.0, 1.0, 0.0])
    };
    let x = trial - z * trial.dot(z);
    x * (1.0 / x.norm())
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Surface;

    fn frame() -> Frame {
        Frame::new(
            Point3::new([1.0, 2.0, 3.0]),
            Point3::new([0.0, 0.0, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap()
    }

    fn circle_edge<'a>(f: &'a Frame, r: f64, z: f64, from: f64, to: f64) -> SampledEdge<'a> {
        SampledEdge::new(Box::new(move |s| {
            f.at(
                r * (from + s * (to - from)).cos(),
                r * (from + s * (to - from)).sin(),
                z,
            )
        }))
    }

    #[test]
    fn a_cylinder_face_takes_the_range_of_its_loops() {
        let f = frame();
        // A quarter of the side between z = -1 and z = 2, starting at 300 degrees: the range
        // crosses the seam and is given from 300 to 390 degrees.
        let (a, b) = (300f64.to_radians(), 390f64.to_radians());
        let loops = vec![vec![
            circle_edge(&f, 2.0, -1.0, a, b),
            SampledEdge::new(Box::new(move |s| {
                f.at(2.0 * b.cos(), 2.0 * b.sin(), -1.0 + 3.0 * s)
            })),
            circle_edge(&f, 2.0, 2.0, b, a),
            SampledEdge::new(Box::new(move |s| {
                f.at(2.0 * a.cos(), 2.0 * a.sin(), 2.0 - 3.0 * s)
            })),
        ]];
        let s = BasisSurface::Cylinder(f, 2.0).bounded(&loops).unwrap();
        let (du, dv) = (s.domain_u(), s.domain_v());
        assert!(
            (du.start - a).abs() < 1e-12 && (du.end - b).abs() < 1e-12,
            "{du:?}"
        );
        assert!(
            (dv.start + 1.0).abs() < 1e-12 && (dv.end - 2.0).abs() < 1e-12,
            "{dv:?}"
        );
        assert!(!s.is_closed_u());
        // A loop around the axis: the full turn, closed.
        let around = vec![
            vec![circle_edge(&f, 2.0, 0.5, 0.0, TAU)],
            vec![circle_edge(&f, 2.0, 1.5, TAU, 0.0)],
        ];
        let s = BasisSurface::Cylinder(f, 2.0).bounded(&around).unwrap();
        assert!(s.is_closed_u() && s.domain_u().length() == TAU);
        assert_eq!((s.domain_v().start, s.domain_v().end), (0.5, 1.5));
    }

    #[test]
    fn a_profile_off_the_axis_plane_turns_through_the_loops_range() {
        // A line from (2, 0, 0) to (2, 1, 3) in the frame (not in a plane through the z axis)
        // turned from 0 to 250 degrees: the bottom circle starts at azimuth 0, the top one at
        // atan(1/2); both span 250 degrees of turn.
        let f = frame();
        let (p0, p1) = (f.at(2.0, 0.0, 0.0), f.at(2.0, 1.0, 3.0));
        let profile = BasisCurve::Nurbs(line_segment(p0, p1, (0.0, 1.0)).unwrap());
        let end = 250f64.to_radians();
        let top = 0.5f64.atan();
        let r = 5f64.sqrt();
        let line_at = move |turn: f64, s: f64| {
            let (x, y, z) = (2.0, s, 3.0 * s);
            let (c, sn) = (turn.cos(), turn.sin());
            f.at(c * x - sn * y, sn * x + c * y, z)
        };
        let loops = vec![vec![
            circle_edge(&f, 2.0, 0.0, 0.0, end),
            SampledEdge::new(Box::new(move |s| line_at(end, s))),
            circle_edge(&f, r, 3.0, top + end, top),
            SampledEdge::new(Box::new(move |s| line_at(0.0, 1.0 - s))),
        ]];
        let surface = BasisSurface::Revolution {
            profile,
            origin: f.origin,
            axis: f.z,
        };
        let s = surface.bounded(&loops).unwrap();
        let du = s.domain_u();
        assert!(
            (du.start).abs() < 1e-9 && (du.end - end).abs() < 1e-9,
            "{du:?}"
        );
        let dv = s.domain_v();
        for k in 0..=4 {
            let v = dv.start + dv.length() * k as f64 / 4.0;
            let t = (v - dv.start) / dv.length();
            assert!(s.eval(du.start, v).distance(line_at(0.0, t)) < 1e-12);
            assert!(s.eval(du.end, v).distance(line_at(end, t)) < 1e-12);
        }
    }

    #[test]
    fn extremes_inside_an_edge_are_refined() {
        // An oblique ellipse on a cylinder: its height peaks inside the edge.
        let f = frame();
        let loops = vec![vec![SampledEdge::new(Box::new(move |s: f64| {
            let t = 0.3 + s * TAU;
            f.at(t.cos(), t.sin(), 0.7 * (t - 1.0).sin())
        }))]];
        let s = BasisSurface::Cylinder(f, 1.0).bounded(&loops).unwrap();
        let dv = s.domain_v();
        assert!(
            (dv.start + 0.7).abs() < 1e-12 && (dv.end - 0.7).abs() < 1e-12,
            "{dv:?}"
        );
    }

    #[test]
    fn unbounded_surfaces_without_edges_are_refused() {
        let e = BasisSurface::Plane(frame()).bounded(&[]).unwrap_err();
        assert!(e.contains("unbounded"), "{e}");
        let s = BasisSurface::Sphere(frame(), 2.0).bounded(&[]).unwrap();
        assert_eq!(s.domain_v().start, -FRAC_PI_2);
    }

    #[test]
    fn a_vertex_on_a_nurbs_curve_or_off_it_gets_the_global_searchs_parameter() {
        // A rational circle of radius 3 (three arcs) far from the origin.
        let (x, y) = (Point3::new([3.0, 0.0, 0.0]), Point3::new([0.0, 3.0, 0.0]));
        let c = elliptic_arc(Point3::new([5e4, 1.0, -7.0]), x, y, (0.0, 1.5 * PI)).unwrap();
        let projector = CurveProjector::new(&c, 0.0).unwrap();
        let basis = BasisCurve::Nurbs(c.clone());
        for k in 0..=40 {
            let on = c.eval(c.domain().uniform(k, 41));
            // On the curve (the local path), and 1e-3 off it outward (the global search).
            let off = on + (on - Point3::new([5e4, 1.0, -7.0])) * 1e-3;
            for q in [on, off] {
                let t = basis.parameter_of(q).unwrap();
                let global = projector.nearest(q);
                assert!(
                    (c.eval(t).distance(q) - global.distance).abs() <= 1e-12 * 5e4,
                    "{q:?}: {t} against {}",
                    global.t
                );
                assert!(
                    (t - global.t).abs() < 1e-9,
                    "{q:?}: {t} against {}",
                    global.t
                );
            }
        }
    }
}

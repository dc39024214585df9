//! STEP geometry (ISO 10303-42) to karkas: points, directions, placements, curves and
//! surfaces, each entity resolved once and kept, references followed with cycles and missing
//! instances reported at the instance that refers to them.

use std::collections::{HashMap, HashSet};
use std::path::Path;

use karkas::bspline::sweep::Frame;
use karkas::bspline::{NurbsCurve, NurbsSurface};
use karkas::{Curve, Grid, Point3};

use super::analytic::{any_normal, BasisCurve, BasisSurface};
use super::step_args::{real_of, Args};
use super::step_syntax::{Exchange, Instance, Part, Value};
use crate::error::IoError;

/// How deep references may nest (a face, its loops, edges, curves, points: about 8).
const MAX_NESTING: usize = 64;

/// The curve entity types read (simple names, and the parts of complex instances).
pub(crate) const CURVE_TYPES: &[&str] = &[
    "LINE",
    "CIRCLE",
    "ELLIPSE",
    "HYPERBOLA",
    "PARABOLA",
    "B_SPLINE_CURVE_WITH_KNOTS",
    "B_SPLINE_CURVE",
    "BEZIER_CURVE",
    "UNIFORM_CURVE",
    "QUASI_UNIFORM_CURVE",
    "POLYLINE",
    "TRIMMED_CURVE",
    "SURFACE_CURVE",
    "SEAM_CURVE",
    "INTERSECTION_CURVE",
    "BOUNDED_SURFACE_CURVE",
];

/// The surface entity types read.
pub(crate) const SURFACE_TYPES: &[&str] = &[
    "PLANE",
    "CYLINDRICAL_SURFACE",
    "CONICAL_SURFACE",
    "SPHERICAL_SURFACE",
    "TOROIDAL_SURFACE",
    "SURFACE_OF_REVOLUTION",
    "SURFACE_OF_LINEAR_EXTRUSION",
    "B_SPLINE_SURFACE_WITH_KNOTS",
    "B_SPLINE_SURFACE",
    "BEZIER_SURFACE",
    "UNIFORM_SURFACE",
    "QUASI_UNIFORM_SURFACE",
    "RECTANGULAR_TRIMMED_SURFACE",
];

/// Geometric entity types karkas does not read: met where a curve or surface is expected,
/// they are skipped with their name.
pub(crate) const UNREAD_GEOMETRY: &[&str] = &[
    "OFFSET_CURVE_3D",
    "OFFSET_CURVE_2D",
    "PCURVE",
    "COMPOSITE_CURVE",
    "CLOTHOID",
    "OFFSET_SURFACE",
    "CURVE_BOUNDED_SURFACE",
    "DEGENERATE_TOROIDAL_SURFACE",
    "RECTANGULAR_COMPOSITE_SURFACE",
    "CYLINDRICAL_POINT",
];

/// A curve with the factor from the file's parameter values on it (trims) to the basis
/// curve's parameter: the line's vector length, the plane-angle unit on conics.
#[derive(Clone, Debug)]
pub(crate) struct FileCurve {
    pub basis: BasisCurve,
    pub parameter_scale: f64,
}

/// Why an item is not read: the entity type at fault and what about it.
#[derive(Clone, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) struct Unread {
    pub entity: String,
    pub reason: &'static str,
}

/// What a resolution gives: the value, an item to skip with its reason, or a hard error.
pub(crate) enum Outcome<T> {
    Read(T),
    Skip(Unread),
}

/// `?` for resolutions that may skip: returns the skip from the enclosing function.
macro_rules! read {
    ($e:expr) => {
        match $e? {
            Outcome::Read(v) => v,
            Outcome::Skip(u) => return Ok(Outcome::Skip(u)),
        }
    };
}
pub(crate) use read;

/// Resolves geometry entities of a STEP data section.
pub(crate) struct Geometry<'a> {
    pub path: &'a Path,
    pub exchange: &'a Exchange,
    /// Radians per plane-angle unit of the file.
    pub angle: f64,
    curves: HashMap<u64, FileCurve>,
    surfaces: HashMap<u64, BasisSurface>,
    visiting: HashSet<u64>,
}

impl<'a> Geometry<'a> {
    /// A resolver over `exchange` (of the file `path`) whose angles are in units of `angle`
    /// radians.
    pub(crate) fn new(path: &'a Path, exchange: &'a Exchange, angle: f64) -> Self {
        Geometry {
            path,
            exchange,
            angle,
            curves: HashMap::new(),
            surfaces: HashMap::new(),
            visiting: HashSet::new(),
        }
    }

    /// Instance `id`, referred to by `from`.
    pub fn get(&self, id: u64, from: &Args<'_>) -> Result<&'a Instance, IoError> {
        self.exchange.instances.get(&id).ok_or_else(|| {
            from.error(format!(
                "refers to #{id}, which the file does not define (or defines as an entity that \
                 is not geometry)"
            ))
        })
    }

    /// Enters instance `id` (referred to by `from`): fails on a reference cycle or nesting
    /// beyond [`MAX_NESTING`].
    pub fn enter(&mut self, id: u64, from: &Args<'_>) -> Result<(), IoError> {
        if !self.visiting.insert(id) {
            return Err(from.error(format!(
                "refers to #{id}, which refers back to itself (a cycle)"
            )));
        }
        if self.visiting.len() > MAX_NESTING {
            return Err(from.error(format!("references nest more than {MAX_NESTING} deep")));
        }
        Ok(())
    }

    /// Leaves instance `id`.
    pub fn leave(&mut self, id: u64) {
        self.visiting.remove(&id);
    }

    /// The part of instance `id` named one of `names`, as arguments (an error naming what
    /// was found otherwise).
    pub fn expect(&self, id: u64, from: &Args<'_>, names: &[&str]) -> Result<Args<'a>, IoError> {
        let instance = self.get(id, from)?;
        match instance.parts.iter().find(|p| names.contains(&&*p.name)) {
            Some(part) => Ok(Args::of(self.path, id, instance, part)),
            None => Err(from.error(format!(
                "refers to #{id} ({}) where {} is expected",
                instance.kind(&[]),
                names.join(" or ")
            ))),
        }
    }

    /// A CARTESIAN_POINT (two coordinates are completed with `z = 0`).
    pub fn point(&self, id: u64, from: &Args<'_>) -> Result<Point3, IoError> {
        let a = self.expect(id, from, &["CARTESIAN_POINT"])?;
        a.count(2)?;
        coordinates(&a, 1, "coordinates")
    }

    /// A DIRECTION, not normalized.
    pub fn direction(&self, id: u64, from: &Args<'_>) -> Result<Point3, IoError> {
        let a = self.expect(id, from, &["DIRECTION"])?;
        a.count(2)?;
        let d = coordinates(&a, 1, "direction ratios")?;
        if d.norm() == 0.0 {
            return Err(a.error("a direction of length 0"));
        }
        Ok(d)
    }

    /// A VECTOR: its unit direction and its magnitude.
    pub fn vector(&self, id: u64, from: &Args<'_>) -> Result<(Point3, f64), IoError> {
        let a = self.expect(id, from, &["VECTOR"])?;
        a.count(3)?;
        let d = self.direction(a.reference(1)?, &a)?;
        let m = a.real(2)?;
        if !(m.is_finite() && m != 0.0) {
            return Err(a.error("a vector of magnitude 0"));
        }
        Ok((d * (m.signum() / d.norm()), m.abs()))
    }

    /// An AXIS2_PLACEMENT_3D (or _2D, in the plane z = 0) as a frame.
    pub fn placement(&self, id: u64, from: &Args<'_>) -> Result<Frame, IoError> {
        let a = self.expect(id, from, &["AXIS2_PLACEMENT_3D", "AXIS2_PLACEMENT_2D"])?;
        let origin = self.point(a.reference(1)?, &a)?;
        let z_default = Point3::new([0.0, 0.0, 1.0]);
        let (z, x) = if a.name == "AXIS2_PLACEMENT_3D" {
            a.count(4)?;
            let z = match a.optional_reference(2)? {
                Some(r) => self.direction(r, &a)?,
                None => z_default,
            };
            let x = match a.optional_reference(3)? {
                Some(r) => Some(self.direction(r, &a)?),
                None => None,
            };
            (z, x)
        } else {
            a.count(3)?;
            let x = match a.optional_reference(2)? {
                Some(r) => Some(self.direction(r, &a)?),
                None => None,
            };
            (z_default, x)
        };
        let zn = z * (1.0 / z.norm());
        let x = x.unwrap_or(Point3::new([1.0, 0.0, 0.0]));
        // A reference direction along the axis: any square one (ISO 10303-42 builds one).
        let x = if (x - zn * x.dot(zn)).norm() > 1e-12 * x.norm() {
            x
        } else {
            any_normal(zn)
        };
        Frame::new(origin, zn, x).map_err(|e| a.error(e.to_string()))
    }

    /// An AXIS1_PLACEMENT: a point and a unit axis.
    fn axis1(&self, id: u64, from: &Args<'_>) -> Result<(Point3, Point3), IoError> {
        let a = self.expect(id, from, &["AXIS1_PLACEMENT"])?;
        a.count(3)?;
        let origin = self.point(a.reference(1)?, &a)?;
        let axis = match a.optional_reference(2)? {
            Some(r) => self.direction(r, &a)?,
            None => Point3::new([0.0, 0.0, 1.0]),
        };
        Ok((origin, axis * (1.0 / axis.norm())))
    }

    /// A positive length parameter.
    fn length(a: &Args<'_>, i: usize, what: &str) -> Result<f64, IoError> {
        let r = a.real(i)?;
        if r.is_finite() && r > 0.0 {
            Ok(r)
        } else {
            Err(a.error(format!("{what} must be positive, got {r}")))
        }
    }

    /// The curve entity `id` (read once, then kept).
    pub fn curve(&mut self, id: u64, from: &Args<'_>) -> Result<Outcome<FileCurve>, IoError> {
        if let Some(c) = self.curves.get(&id) {
            return Ok(Outcome::Read(c.clone()));
        }
        self.enter(id, from)?;
        let result = self.curve_uncached(id, from);
        self.leave(id);
        if let Ok(Outcome::Read(c)) = &result {
            self.curves.insert(id, c.clone());
        }
        result
    }

    fn curve_uncached(&mut self, id: u64, from: &Args<'_>) -> Result<Outcome<FileCurve>, IoError> {
        let instance = self.get(id, from)?;
        let kind = instance.kind(CURVE_TYPES);
        if !CURVE_TYPES.contains(&kind) {
            return Ok(Outcome::Skip(Unread {
                entity: kind.to_owned(),
                reason: if UNREAD_GEOMETRY.contains(&kind) {
                    "curve type not read"
                } else {
                    "not a curve karkas reads"
                },
            }));
        }
        let part = instance.part(kind).unwrap_or(&instance.parts[0]);
        let a = Args::of(self.path, id, instance, part);
        let plain = |basis| {
            Ok(Outcome::Read(FileCurve {
                basis,
                parameter_scale: 1.0,
            }))
        };
        match kind {
            "LINE" => {
                a.count(3)?;
                let origin = self.point(a.reference(1)?, &a)?;
                let (dir, magnitude) = self.vector(a.reference(2)?, &a)?;
                Ok(Outcome::Read(FileCurve {
                    basis: BasisCurve::Line { origin, dir },
                    parameter_scale: magnitude,
                }))
            }
            "CIRCLE" | "ELLIPSE" | "HYPERBOLA" | "PARABOLA" => self.conic(kind, &a),
            "POLYLINE" => plain(BasisCurve::Nurbs(self.polyline(&a)?)),
            "SURFACE_CURVE" | "SEAM_CURVE" | "INTERSECTION_CURVE" | "BOUNDED_SURFACE_CURVE" => {
                if a.params.len() < 2 {
                    a.count(4)?;
                }
                let inner = a.reference(1)?;
                self.curve(inner, &a)
            }
            "TRIMMED_CURVE" => self.trimmed_curve(&a),
            _ => {
                let c = read!(self.bspline_curve(id, instance));
                plain(BasisCurve::Nurbs(c))
            }
        }
    }

    /// A TRIMMED_CURVE: its basis curve between its trims, as a NURBS.
    fn trimmed_curve(&mut self, a: &Args<'_>) -> Result<Outcome<FileCurve>, IoError> {
        a.count(6)?;
        let basis = read!(self.curve(a.reference(1)?, a));
        let prefer_parameter = a.enumeration(5)? != Some("CARTESIAN");
        let mut trims = [0.0; 2];
        for (k, t) in trims.iter_mut().enumerate() {
            let list = a.list(2 + k)?;
            let mut parameter = None;
            let mut point = None;
            for v in list {
                match v {
                    Value::Typed(name, inner) if &**name == "PARAMETER_VALUE" => {
                        parameter = real_of(inner).map(|x| x * basis.parameter_scale);
                    }
                    Value::Ref(r) => point = Some(self.point(*r, a)?),
                    _ => {
                        return Err(a.error(format!(
                            "trim {} must list a point or PARAMETER_VALUE",
                            k + 1
                        )))
                    }
                }
            }
            *t = match (parameter, point) {
                (Some(x), Some(_)) if prefer_parameter => x,
                (Some(x), None) => x,
                (_, Some(p)) => basis.basis.parameter_of(p).map_err(|e| a.error(e))?,
                (None, None) => return Err(a.error(format!("trim {} is empty", k + 1))),
            };
        }
        let sense = a.logical(4, true)?;
        let (mut lo, mut hi) = if sense {
            (trims[0], trims[1])
        } else {
            (trims[1], trims[0])
        };
        if let Some(p) = basis.basis.period() {
            while hi <= lo {
                hi += p;
            }
            while hi - lo > p * (1.0 + 1e-12) {
                hi -= p;
            }
        } else if hi < lo {
            std::mem::swap(&mut lo, &mut hi);
        }
        if hi.is_nan() || hi <= lo {
            return Err(a.error("the trims leave nothing of the curve"));
        }
        let c = basis.basis.bounded(lo, hi).map_err(|e| a.error(e))?;
        let c = if sense { c } else { c.reversed() };
        Ok(Outcome::Read(FileCurve {
            basis: BasisCurve::Nurbs(c),
            parameter_scale: 1.0,
        }))
    }

    /// A conic by its placement and sizes (a circle's or an ellipse's parameter an angle in
    /// the file's unit).
    fn conic(&self, kind: &str, a: &Args<'_>) -> Result<Outcome<FileCurve>, IoError> {
        let (basis, parameter_scale) = match kind {
            "CIRCLE" | "ELLIPSE" => {
                a.count(if kind == "CIRCLE" { 3 } else { 4 })?;
                let frame = self.placement(a.reference(1)?, a)?;
                let r1 = Self::length(a, 2, "a radius")?;
                let r2 = if kind == "CIRCLE" {
                    r1
                } else {
                    Self::length(a, 3, "a semi-axis")?
                };
                let conic = BasisCurve::Conic {
                    frame,
                    a: r1,
                    b: r2,
                };
                (conic, self.angle)
            }
            "HYPERBOLA" => {
                a.count(4)?;
                let frame = self.placement(a.reference(1)?, a)?;
                let semi = Self::length(a, 2, "a semi-axis")?;
                let imaginary = Self::length(a, 3, "a semi-imaginary axis")?;
                let hyperbola = BasisCurve::Hyperbola {
                    frame,
                    a: semi,
                    b: imaginary,
                };
                (hyperbola, 1.0)
            }
            _ => {
                a.count(3)?;
                let frame = self.placement(a.reference(1)?, a)?;
                let focal = Self::length(a, 2, "a focal distance")?;
                (BasisCurve::Parabola { frame, focal }, 1.0)
            }
        };
        Ok(Outcome::Read(FileCurve {
            basis,
            parameter_scale,
        }))
    }

    /// A polyline as a B-spline of degree 1 through its points, at least 2.
    fn polyline(&self, a: &Args<'_>) -> Result<NurbsCurve<3>, IoError> {
        a.count(2)?;
        let points = a
            .references(1)?
            .iter()
            .map(|&r| self.point(r, a))
            .collect::<Result<Vec<_>, _>>()?;
        let n = points.len();
        if n < 2 {
            return Err(a.error("a polyline needs at least 2 points"));
        }
        let mut knots = vec![0.0];
        knots.extend((0..n).map(|k| k as f64));
        knots.push((n - 1) as f64);
        NurbsCurve::new(1, knots, points, vec![1.0; n]).map_err(|e| a.error(e.to_string()))
    }

    /// A B-spline curve in any of its forms: B_SPLINE_CURVE_WITH_KNOTS, or a complex
    /// instance of B_SPLINE_CURVE with knots (explicit, Bezier, uniform or quasi-uniform)
    /// and possibly RATIONAL_B_SPLINE_CURVE.
    fn bspline_curve(
        &self,
        id: u64,
        instance: &Instance,
    ) -> Result<Outcome<NurbsCurve<3>>, IoError> {
        let BsplineParts {
            head,
            knots_part,
            rational,
            at,
            explicit,
        } = bspline_parts(self.path, id, instance, &CURVE_LAYOUT)?;
        let degree = positive_degree(&head, at)?;
        let points = head
            .references(at + 1)?
            .iter()
            .map(|&r| self.point(r, &head))
            .collect::<Result<Vec<_>, _>>()?;
        let n = points.len();
        let knots = if at == 1 && explicit {
            expand_knots(&head, 6, 7)?
        } else if let Some(k) = &knots_part {
            k.count(3)?;
            expand_knots(k, 0, 1)?
        } else {
            implied_knots(instance, degree, n)
                .ok_or_else(|| head.error("a B-spline curve without knots"))?
        };
        let weights = match rational {
            Some(w) => {
                w.count(1)?;
                w.reals(0)?
            }
            None => vec![1.0; n],
        };
        let closed = head.logical(at + 3, false)?;
        let curve = NurbsCurve::new(degree, knots, points, weights)
            .map_err(|e| head.error(e.to_string()))?;
        let ends_meet = {
            let p = curve.control_points();
            let size = p.iter().map(|q| q.distance(p[0])).fold(0.0, f64::max);
            p[0].distance(p[n - 1]) <= 1e-12 * size
                || curve
                    .eval(curve.domain().start)
                    .distance(curve.eval(curve.domain().end))
                    <= 1e-10 * size
        };
        Ok(Outcome::Read(curve.with_closed(closed && ends_meet)))
    }

    /// The surface entity `id` (read once, then kept).
    pub fn surface(&mut self, id: u64, from: &Args<'_>) -> Result<Outcome<BasisSurface>, IoError> {
        if let Some(s) = self.surfaces.get(&id) {
            return Ok(Outcome::Read(s.clone()));
        }
        self.enter(id, from)?;
        let result = self.surface_uncached(id, from);
        self.leave(id);
        if let Ok(Outcome::Read(s)) = &result {
            self.surfaces.insert(id, s.clone());
        }
        result
    }

    fn surface_uncached(
        &mut self,
        id: u64,
        from: &Args<'_>,
    ) -> Result<Outcome<BasisSurface>, IoError> {
        let instance = self.get(id, from)?;
        let kind = instance.kind(SURFACE_TYPES);
        if !SURFACE_TYPES.contains(&kind) {
            return Ok(Outcome::Skip(Unread {
                entity: kind.to_owned(),
                reason: if UNREAD_GEOMETRY.contains(&kind) {
                    "surface type not read"
                } else {
                    "not a surface karkas reads"
                },
            }));
        }
        let part = instance.part(kind).unwrap_or(&instance.parts[0]);
        let a = Args::of(self.path, id, instance, part);
        let frame = |g: &Self, i: usize| g.placement(a.reference(i)?, &a);
        Ok(Outcome::Read(match kind {
            "PLANE" => {
                a.count(2)?;
                BasisSurface::Plane(frame(self, 1)?)
            }
            "CYLINDRICAL_SURFACE" => {
                a.count(3)?;
                BasisSurface::Cylinder(frame(self, 1)?, Self::length(&a, 2, "a radius")?)
            }
            "CONICAL_SURFACE" => self.cone(&a)?,
            "SPHERICAL_SURFACE" => {
                a.count(3)?;
                BasisSurface::Sphere(frame(self, 1)?, Self::length(&a, 2, "a radius")?)
            }
            "TOROIDAL_SURFACE" => {
                a.count(4)?;
                let major = Self::length(&a, 2, "a major radius")?;
                let minor = Self::length(&a, 3, "a minor radius")?;
                BasisSurface::Torus(frame(self, 1)?, major, minor)
            }
            "SURFACE_OF_REVOLUTION" => {
                a.count(3)?;
                let profile = read!(self.curve(a.reference(1)?, &a));
                let (origin, axis) = self.axis1(a.reference(2)?, &a)?;
                BasisSurface::Revolution {
                    profile: profile.basis,
                    origin,
                    axis,
                }
            }
            "SURFACE_OF_LINEAR_EXTRUSION" => {
                a.count(3)?;
                let curve = read!(self.curve(a.reference(1)?, &a));
                let (dir, _) = self.vector(a.reference(2)?, &a)?;
                BasisSurface::Extrusion {
                    curve: curve.basis,
                    dir,
                }
            }
            "RECTANGULAR_TRIMMED_SURFACE" => read!(self.rectangular_trimmed(&a)),
            _ => BasisSurface::Nurbs(read!(self.bspline_surface(id, instance))),
        }))
    }

    /// A cone: its placement, a radius `>= 0` at `v = 0` and a half-angle in `(0, 90)`
    /// degrees.
    fn cone(&self, a: &Args<'_>) -> Result<BasisSurface, IoError> {
        a.count(4)?;
        let r = a.real(2)?;
        if !(r.is_finite() && r >= 0.0) {
            return Err(a.error(format!("a cone's radius must not be negative, got {r}")));
        }
        let alpha = a.real(3)? * self.angle;
        if !(alpha.abs() < std::f64::consts::FRAC_PI_2 && alpha != 0.0) {
            return Err(a.error(format!(
                "a cone's half-angle must lie in (0, 90) degrees, got {alpha} rad"
            )));
        }
        Ok(BasisSurface::Cone(
            self.placement(a.reference(1)?, a)?,
            r,
            alpha,
        ))
    }

    /// A surface trimmed to a rectangle of its parameters (angles in the file's unit).
    fn rectangular_trimmed(&mut self, a: &Args<'_>) -> Result<Outcome<BasisSurface>, IoError> {
        a.count(8)?;
        let basis = read!(self.surface(a.reference(1)?, a));
        let (u1, u2) = (
            a.real(2)? * self.parameter_scale(&basis, true),
            a.real(3)? * self.parameter_scale(&basis, true),
        );
        let (v1, v2) = (
            a.real(4)? * self.parameter_scale(&basis, false),
            a.real(5)? * self.parameter_scale(&basis, false),
        );
        let order = |x: f64, y: f64| if x <= y { (x, y) } else { (y, x) };
        let s = basis
            .over(order(u1, u2), order(v1, v2))
            .map_err(|e| a.error(e))?;
        Ok(Outcome::Read(BasisSurface::Nurbs(s)))
    }

    /// The factor to radians of the surface's `u` (or `v`) parameter when it is an angle.
    fn parameter_scale(&self, s: &BasisSurface, u: bool) -> f64 {
        match s {
            BasisSurface::Nurbs(_) => 1.0,
            BasisSurface::Plane(_) => 1.0,
            BasisSurface::Cylinder(..) | BasisSurface::Cone(..) => {
                if u {
                    self.angle
                } else {
                    1.0
                }
            }
            BasisSurface::Revolution { .. } => {
                if u {
                    self.angle
                } else {
                    1.0
                }
            }
            BasisSurface::Extrusion { .. } => 1.0,
            _ => self.angle,
        }
    }

    /// A B-spline surface in any of its forms (see [`Self::bspline_curve`]).
    fn bspline_surface(
        &self,
        id: u64,
        instance: &Instance,
    ) -> Result<Outcome<NurbsSurface<3>>, IoError> {
        let BsplineParts {
            head,
            knots_part,
            rational,
            at,
            explicit,
        } = bspline_parts(self.path, id, instance, &SURFACE_LAYOUT)?;
        let du = positive_degree(&head, at)?;
        let dv = positive_degree(&head, at + 1)?;
        let (points, nu, nv) = self.control_rows(&head, at + 2)?;
        let (knots_u, knots_v) = if at == 1 && explicit {
            (expand_knots(&head, 8, 10)?, expand_knots(&head, 9, 11)?)
        } else if let Some(k) = &knots_part {
            k.count(5)?;
            (expand_knots(k, 0, 2)?, expand_knots(k, 1, 3)?)
        } else {
            match (
                implied_knots(instance, du, nu),
                implied_knots(instance, dv, nv),
            ) {
                (Some(u), Some(v)) => (u, v),
                _ => return Err(head.error("a B-spline surface without knots")),
            }
        };
        let weights = match rational {
            Some(w) => weight_rows(&w, (nu, nv))?,
            None => vec![1.0; nu * nv],
        };
        let control =
            Grid::from_row_major(nu, nv, points).map_err(|e| head.error(e.to_string()))?;
        let weights =
            Grid::from_row_major(nu, nv, weights).map_err(|e| head.error(e.to_string()))?;
        let s = NurbsSurface::new((du, knots_u), (dv, knots_v), control, weights)
            .map_err(|e| head.error(e.to_string()))?;
        let (closed_u, closed_v) = (head.logical(at + 4, false)?, head.logical(at + 5, false)?);
        let (meet_u, meet_v) = lines_meet(&s);
        Ok(Outcome::Read(
            s.with_closed(closed_u && meet_u, closed_v && meet_v),
        ))
    }

    /// The control points of a B-spline surface, rows of references in parameter `k` of
    /// `head`, and the counts of rows and columns.
    fn control_rows(
        &self,
        head: &Args<'_>,
        k: usize,
    ) -> Result<(Vec<Point3>, usize, usize), IoError> {
        let rows = head.list(k)?;
        let mut points = Vec::new();
        let mut cols = None;
        let not_points = || {
            head.error(format!(
                "parameter {} must be a list of lists of points",
                k + 1
            ))
        };
        for row in rows {
            let Value::List(row) = row else {
                return Err(not_points());
            };
            if *cols.get_or_insert(row.len()) != row.len() {
                return Err(head.error("the rows of control points differ in length"));
            }
            for v in row {
                let Value::Ref(r) = v else {
                    return Err(not_points());
                };
                points.push(self.point(*r, head)?);
            }
        }
        let (nu, nv) = (rows.len(), cols.unwrap_or(0));
        if nu == 0 || nv == 0 {
            return Err(head.error("a B-spline surface without control points"));
        }
        Ok((points, nu, nv))
    }
}

/// Whether the first and last rows (columns) of the surface's boundary coincide.
fn lines_meet(s: &NurbsSurface<3>) -> (bool, bool) {
    use karkas::Surface;
    let (du, dv) = (s.domain_u(), s.domain_v());
    let pts = s.control_points().as_slice();
    let size = pts.iter().map(|p| p.distance(pts[0])).fold(0.0, f64::max);
    let tol = 1e-10 * size;
    let meet = |f: &dyn Fn(f64) -> (Point3, Point3)| {
        (0..=16).all(|k| {
            let (a, b) = f(k as f64 / 16.0);
            a.distance(b) <= tol
        })
    };
    (
        meet(&|t| {
            let v = dv.start + t * dv.length();
            (s.eval(du.start, v), s.eval(du.end, v))
        }),
        meet(&|t| {
            let u = du.start + t * du.length();
            (s.eval(u, dv.start), s.eval(u, dv.end))
        }),
    )
}

/// A degree parameter, at least 1.
fn positive_degree(a: &Args<'_>, i: usize) -> Result<usize, IoError> {
    let d = a.int(i)?;
    if (1..=karkas::bspline::MAX_DEGREE as i64).contains(&d) {
        Ok(d as usize)
    } else {
        Err(a.error(format!("the degree must lie in 1..=128, got {d}")))
    }
}

/// The coordinates of parameter `i` (1 to 3 numbers) as a point.
fn coordinates(a: &Args<'_>, i: usize, what: &str) -> Result<Point3, IoError> {
    let c = a.reals(i)?;
    if c.is_empty() || c.len() > 3 {
        return Err(a.error(format!("{} {what}, 1 to 3 expected", c.len())));
    }
    if c.iter().any(|x| !x.is_finite()) {
        return Err(a.error(format!("{what} that are not finite")));
    }
    Ok(Point3::new([
        c[0],
        *c.get(1).unwrap_or(&0.0),
        *c.get(2).unwrap_or(&0.0),
    ]))
}

/// The knot vector from the multiplicities (parameter `m`) and the distinct knots (`k`).
fn expand_knots(a: &Args<'_>, m: usize, k: usize) -> Result<Vec<f64>, IoError> {
    let mult = a.ints(m)?;
    let values = a.reals(k)?;
    if mult.len() != values.len() {
        return Err(a.error(format!(
            "{} knot multiplicities for {} knots",
            mult.len(),
            values.len()
        )));
    }
    let total: i64 = mult.iter().map(|&x| x.max(0)).sum();
    if mult.iter().any(|&x| x < 1) || total > 1 << 24 {
        return Err(a.error("knot multiplicities must be positive (and sum to at most 2^24)"));
    }
    let mut knots = Vec::with_capacity(total as usize);
    for (&x, &n) in values.iter().zip(&mult) {
        knots.extend(std::iter::repeat_n(x, n as usize));
    }
    Ok(knots)
}

/// The weights of a rational B-spline surface of `nu x nv` control points, rows of numbers
/// in the only attribute of `w`.
fn weight_rows(w: &Args<'_>, (nu, nv): (usize, usize)) -> Result<Vec<f64>, IoError> {
    w.count(1)?;
    let count = nu * nv;
    let mut all = Vec::with_capacity(count);
    for row in w.list(0)? {
        let Value::List(row) = row else {
            return Err(w.error("the weights must be a list of lists"));
        };
        for x in row {
            all.push(real_of(x).ok_or_else(|| w.error("the weights must be numbers"))?);
        }
    }
    if all.len() != count {
        return Err(w.error(format!(
            "{} weights for {nu} x {nv} control points",
            all.len()
        )));
    }
    Ok(all)
}

/// Where a B-spline entity's attributes lie in its simple and complex instances.
struct BsplineLayout {
    /// The entity (`B_SPLINE_CURVE`, `B_SPLINE_SURFACE`).
    base: &'static str,
    /// Its subtype with the knots listed.
    with_knots: &'static str,
    /// Its subtype with weights.
    rational: &'static str,
    /// Its subtypes with the knots implied.
    implied: &'static [&'static str],
    /// The attribute counts of a simple instance with the knots listed and with them
    /// implied, and of the base part of a complex instance.
    counts: (usize, usize, usize),
    /// The error when the base part is missing.
    missing: &'static str,
}

const CURVE_LAYOUT: BsplineLayout = BsplineLayout {
    base: "B_SPLINE_CURVE",
    with_knots: "B_SPLINE_CURVE_WITH_KNOTS",
    rational: "RATIONAL_B_SPLINE_CURVE",
    implied: IMPLIED_CURVES,
    counts: (9, 6, 5),
    missing: "a B-spline curve without its B_SPLINE_CURVE part",
};

const SURFACE_LAYOUT: BsplineLayout = BsplineLayout {
    base: "B_SPLINE_SURFACE",
    with_knots: "B_SPLINE_SURFACE_WITH_KNOTS",
    rational: "RATIONAL_B_SPLINE_SURFACE",
    implied: IMPLIED_SURFACES,
    counts: (13, 8, 7),
    missing: "a B-spline surface without its B_SPLINE_SURFACE part",
};

/// The parts of a B-spline instance: `head` holds the base entity's attributes from index
/// `at` (1 in a simple instance, after the name; 0 in a complex one), `knots_part` the listed
/// knots of a complex instance, `rational` the weights; `explicit` whether the knots are
/// listed.
struct BsplineParts<'a> {
    head: Args<'a>,
    knots_part: Option<Args<'a>>,
    rational: Option<Args<'a>>,
    at: usize,
    explicit: bool,
}

/// Finds the parts of a B-spline instance. A simple instance (one part) has every
/// attribute, its count checked here; the subtypes whose knots are implied (Bezier, uniform,
/// quasi-uniform) have the base entity's attributes only. A complex instance's base part has
/// only its own (degrees, points, form, closed, self-intersect).
fn bspline_parts<'a>(
    path: &'a Path,
    id: u64,
    instance: &'a Instance,
    layout: &BsplineLayout,
) -> Result<BsplineParts<'a>, IoError> {
    let args = |name: &str| instance.part(name).map(|p| Args::of(path, id, instance, p));
    let (listed, implied, complex) = layout.counts;
    let one = instance.parts.len() == 1;
    let simple = match (
        args(layout.with_knots),
        implied_simple(instance, layout.implied),
    ) {
        (Some(s), _) if one => {
            s.count(listed)?;
            Some(s)
        }
        (_, Some(part)) if one => {
            let s = Args::of(path, id, instance, part);
            s.count(implied)?;
            Some(s)
        }
        _ => None,
    };
    let explicit = args(layout.with_knots).is_some();
    let (head, knots_part, at) = match (simple, args(layout.base)) {
        (Some(s), None) => (s, None, 1),
        (_, Some(h)) => {
            h.count(complex)?;
            (h, args(layout.with_knots), 0)
        }
        (None, None) => {
            let part = &instance.parts[0];
            return Err(Args::of(path, id, instance, part).error(layout.missing));
        }
    };
    Ok(BsplineParts {
        head,
        knots_part,
        rational: args(layout.rational),
        at,
        explicit,
    })
}

/// The curve subtypes whose knots are implied rather than listed.
const IMPLIED_CURVES: &[&str] = &["BEZIER_CURVE", "UNIFORM_CURVE", "QUASI_UNIFORM_CURVE"];

/// The surface subtypes whose knots are implied rather than listed.
const IMPLIED_SURFACES: &[&str] = &["BEZIER_SURFACE", "UNIFORM_SURFACE", "QUASI_UNIFORM_SURFACE"];

/// The part of `instance` named by one of `names` (a subtype with implied knots), if any.
fn implied_simple<'i>(instance: &'i Instance, names: &[&str]) -> Option<&'i Part> {
    names.iter().find_map(|n| instance.part(n))
}

/// The knots a Bezier, uniform or quasi-uniform B-spline implies (ISO 10303-42).
fn implied_knots(instance: &Instance, degree: usize, count: usize) -> Option<Vec<f64>> {
    let has = |n: &str| instance.part(n).is_some();
    if has("BEZIER_CURVE") || has("BEZIER_SURFACE") {
        // Pieces of degree p sharing end points: knots 0..=k, inner ones p-fold.
        let pieces = (count - 1) / degree;
        if pieces * degree + 1 != count {
            return None;
        }
        let mut k = vec![0.0; degree + 1];
        for i in 1..pieces {
            k.extend(std::iter::repeat_n(i as f64, degree));
        }
        k.extend(std::iter::repeat_n(pieces as f64, degree + 1));
        Some(k)
    } else if has("UNIFORM_CURVE") || has("UNIFORM_SURFACE") {
        Some(
            (0..count + degree + 1)
                .map(|i| i as f64 - degree as f64)
                .collect(),
        )
    } else if has("QUASI_UNIFORM_CURVE") || has("QUASI_UNIFORM_SURFACE") {
        let inner = count - degree;
        let mut k = vec![0.0; degree + 1];
        k.extend((1..inner).map(|i| i as f64));
        k.extend(std::iter::repeat_n(inner as f64, degree + 1));
        Some(k)
    } else {
        None
    }
}

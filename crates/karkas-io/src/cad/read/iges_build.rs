//! IGES 5.3 entities to a karkas [`Shape`]: circular arcs (100), composite curves (102),
//! elliptic arcs (104, form 1: [`elliptic_conic`]), planes (108) under trimmed surfaces,
//! lines (110), surfaces of revolution (120), rational B-spline curves (126) and surfaces
//! (128), curves on a parametric surface (142) and trimmed surfaces (144), each through its
//! transformation matrix (124).
//!
//! A trimmed surface becomes a [`Face`] whose loops are its boundaries: the model-space
//! curves of each 142 as the edges, and its parameter-space curve, when given, as the loop's
//! parameter curves (so the face's domain needs no inversion). Independent curves and
//! surfaces (status: not subordinate) become free curves and whole faces. A B-spline's
//! parameter range (`V0, V1`) cuts the curve exactly; a surface is kept over its knots'
//! whole domain (its trims bound it).

use std::collections::{BTreeMap, HashSet};
use std::io::BufRead;
use std::path::Path;

use karkas::bspline::conic::{elliptic_arc, line_segment};
use karkas::bspline::sweep::revolution;
use karkas::bspline::{NurbsCurve, NurbsSurface};
use karkas::shape::{Edge, EdgeLoop, Face, Shape};
use karkas::{Curve, Grid, Point3, Surface};

use super::iges_plane::PlaneFrame;
use super::iges_records::{read_records, Entry, Field, IgesFile};
use super::model::{CadFormat, CadModel, LengthUnit, Unread};
use crate::error::{IoError, Location};

/// The entity types read.
const READ: &[i64] = &[100, 102, 104, 108, 110, 120, 124, 126, 128, 142, 144];

/// Geometric entity types karkas does not read, with their names.
const UNREAD: &[(i64, &str)] = &[
    (106, "copious data"),
    (112, "parametric spline curve"),
    (114, "parametric spline surface"),
    (118, "ruled surface"),
    (122, "tabulated cylinder"),
    (130, "offset curve"),
    (140, "offset surface"),
    (141, "boundary"),
    (143, "bounded surface"),
    (186, "manifold solid B-rep"),
    (190, "plane surface"),
    (192, "right circular cylindrical surface"),
    (194, "right circular conical surface"),
    (196, "spherical surface"),
    (198, "toroidal surface"),
    (510, "face"),
    (514, "shell"),
];

/// An affine map `x -> R x + t`.
#[derive(Clone, Copy, Debug)]
struct Affine {
    r: [[f64; 3]; 3],
    t: [f64; 3],
}

impl Affine {
    const IDENTITY: Affine = Affine {
        r: [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        t: [0.0; 3],
    };

    fn apply(&self, p: Point3) -> Point3 {
        Point3::new(std::array::from_fn(|i| {
            self.r[i][0] * p[0] + self.r[i][1] * p[1] + self.r[i][2] * p[2] + self.t[i]
        }))
    }

    /// `self` after `inner`.
    fn after(&self, inner: &Affine) -> Affine {
        let mut out = Affine::IDENTITY;
        for i in 0..3 {
            for j in 0..3 {
                out.r[i][j] = (0..3).map(|k| self.r[i][k] * inner.r[k][j]).sum();
            }
            out.t[i] = (0..3).map(|k| self.r[i][k] * inner.t[k]).sum::<f64>() + self.t[i];
        }
        out
    }
}

/// The parameters of one entry, read by position (0 is the type number).
struct Params<'a> {
    path: &'a Path,
    pointer: i64,
    entry: &'a Entry,
    fields: &'a [Field],
}

impl Params<'_> {
    fn error(&self, message: impl AsRef<str>) -> IoError {
        Location::new(self.path, self.entry.param_line.max(self.entry.line)).error(format!(
            "directory entry {} (type {}): {}",
            self.pointer,
            self.entry.kind,
            message.as_ref()
        ))
    }

    fn number(&self, i: usize) -> Result<f64, IoError> {
        match self.fields.get(i) {
            Some(Field::Number(x)) => Ok(*x),
            Some(Field::Empty) => Ok(0.0),
            Some(Field::Text(_)) => {
                Err(self.error(format!("parameter {i} is a string, a number is expected")))
            }
            None => Err(self.error(format!(
                "has {} parameters, at least {} expected",
                self.fields.len().saturating_sub(1),
                i
            ))),
        }
    }

    fn int(&self, i: usize) -> Result<i64, IoError> {
        let x = self.number(i)?;
        if x.fract() == 0.0 && x.abs() < 1e15 {
            Ok(x as i64)
        } else {
            Err(self.error(format!("parameter {i} is {x}, an integer is expected")))
        }
    }

    /// A count parameter in `0..=limit`.
    fn count(&self, i: usize, limit: i64) -> Result<usize, IoError> {
        let n = self.int(i)?;
        if (0..=limit).contains(&n) {
            Ok(n as usize)
        } else {
            Err(self.error(format!(
                "parameter {i} is {n}, a count in 0..={limit} is expected"
            )))
        }
    }

    fn point(&self, i: usize) -> Result<Point3, IoError> {
        Ok(Point3::new([
            self.number(i)?,
            self.number(i + 1)?,
            self.number(i + 2)?,
        ]))
    }
}

/// Builds the shape of an IGES file.
struct Builder<'a> {
    path: &'a Path,
    file: &'a IgesFile,
    visiting: HashSet<i64>,
    used: HashSet<i64>,
    unread: BTreeMap<(String, &'static str), usize>,
}

/// The result of reading an entity: its value or the reason it is skipped.
enum Got<T> {
    Read(T),
    Skip(String, &'static str),
}

impl<'a> Builder<'a> {
    fn entry(&self, pointer: i64, from: Option<&Params<'_>>) -> Result<&'a Entry, IoError> {
        self.file.entries.get(&pointer).ok_or_else(|| {
            let message =
                format!("points to directory entry {pointer}, which the file does not have");
            match from {
                Some(p) => p.error(message),
                None => Location::new(self.path, 1).error(message),
            }
        })
    }

    fn params(&self, pointer: i64, from: Option<&Params<'_>>) -> Result<Params<'a>, IoError> {
        let entry = self.entry(pointer, from)?;
        let fields = entry.params.as_deref().unwrap_or(&[]);
        Ok(Params {
            path: self.path,
            pointer,
            entry,
            fields,
        })
    }

    fn enter(&mut self, pointer: i64, from: &Params<'_>) -> Result<(), IoError> {
        if !self.visiting.insert(pointer) || self.visiting.len() > 64 {
            return Err(from.error(format!(
                "points to directory entry {pointer}, which points back to it (a cycle)"
            )));
        }
        self.used.insert(pointer);
        Ok(())
    }

    /// The transformation of an entry (its matrix after the matrix's own, up to 16 deep).
    fn transform(&self, entry: &Entry, p: &Params<'_>) -> Result<Affine, IoError> {
        let mut out = Affine::IDENTITY;
        let mut next = entry.transform;
        let mut depth = 0;
        while next != 0 {
            depth += 1;
            if depth > 16 || next < 0 {
                return Err(
                    p.error("a chain of transformation matrices that loops or is not a pointer")
                );
            }
            let m = self.params(next, Some(p))?;
            if m.entry.kind != 124 {
                return Err(p.error(format!(
                    "its transformation matrix is entry {next} of type {}",
                    m.entry.kind
                )));
            }
            let v: Vec<f64> = (1..=12).map(|i| m.number(i)).collect::<Result<_, _>>()?;
            let a = Affine {
                r: [[v[0], v[1], v[2]], [v[4], v[5], v[6]], [v[8], v[9], v[10]]],
                t: [v[3], v[7], v[11]],
            };
            out = a.after(&out);
            next = m.entry.transform;
        }
        Ok(out)
    }

    /// The curve entity `pointer` as NURBS pieces in model space (several for a composite).
    fn curve(
        &mut self,
        pointer: i64,
        from: &Params<'_>,
    ) -> Result<Got<Vec<NurbsCurve<3>>>, IoError> {
        self.enter(pointer, from)?;
        let result = self.curve_inner(pointer, from);
        self.visiting.remove(&pointer);
        result
    }

    fn curve_inner(
        &mut self,
        pointer: i64,
        from: &Params<'_>,
    ) -> Result<Got<Vec<NurbsCurve<3>>>, IoError> {
        let p = self.params(pointer, Some(from))?;
        let kind = p.entry.kind;
        let map = self.transform(p.entry, &p)?;
        let pieces = match kind {
            100 => {
                let zt = p.number(1)?;
                let c = Point3::new([p.number(2)?, p.number(3)?, zt]);
                let s = Point3::new([p.number(4)?, p.number(5)?, zt]);
                let e = Point3::new([p.number(6)?, p.number(7)?, zt]);
                let r = c.distance(s);
                if r.is_nan() || r <= 0.0 {
                    return Err(p.error("a circular arc of radius 0"));
                }
                let a0 = (s[1] - c[1]).atan2(s[0] - c[0]);
                let mut a1 = (e[1] - c[1]).atan2(e[0] - c[0]);
                while a1 <= a0 + 1e-12 {
                    a1 += std::f64::consts::TAU;
                }
                let x = Point3::new([r, 0.0, 0.0]);
                let y = Point3::new([0.0, r, 0.0]);
                vec![elliptic_arc(c, x, y, (a0, a1)).map_err(|m| p.error(m.to_string()))?]
            }
            110 => {
                if p.entry.form != 0 {
                    return Ok(Got::Skip(
                        "entity 110 (unbounded line)".into(),
                        "unbounded line",
                    ));
                }
                let (a, b) = (p.point(1)?, p.point(4)?);
                let length = a.distance(b);
                if length.is_nan() || length <= 0.0 {
                    return Ok(Got::Read(Vec::new()));
                }
                vec![line_segment(a, b, (0.0, length)).map_err(|m| p.error(m.to_string()))?]
            }
            104 if p.entry.form == 1 => vec![elliptic_conic(&p)?],
            104 => {
                return Ok(Got::Skip(
                    format!("entity 104 (conic arc) form {}", p.entry.form),
                    "only the ellipse (form 1) is read",
                ))
            }
            126 => vec![self.bspline_curve(&p)?],
            102 => {
                let n = p.count(1, 1 << 20)?;
                let mut out = Vec::new();
                for i in 0..n {
                    let child = p.int(2 + i)?;
                    match self.curve(child, &p)? {
                        Got::Read(mut c) => out.append(&mut c),
                        skip => return Ok(skip),
                    }
                }
                out
            }
            _ => {
                let name = UNREAD
                    .iter()
                    .find(|(k, _)| *k == kind)
                    .map_or("not a curve karkas reads", |(_, n)| n);
                return Ok(Got::Skip(
                    format!("entity {kind} ({name})"),
                    "curve type not read",
                ));
            }
        };
        Ok(Got::Read(
            pieces
                .into_iter()
                .map(|c| c.map_points(|q| map.apply(q)))
                .collect(),
        ))
    }

    /// Entity 126.
    fn bspline_curve(&self, p: &Params<'_>) -> Result<NurbsCurve<3>, IoError> {
        let k = p.count(1, 1 << 24)?;
        let m = p.count(2, karkas::bspline::MAX_DEGREE as i64)?;
        let closed = p.int(4)? == 1;
        let n = k + 1;
        let knots_at = 7;
        let nk = n + m + 1;
        let weights_at = knots_at + nk;
        let points_at = weights_at + n;
        let range_at = points_at + 3 * n;
        let knots: Vec<f64> = (0..nk)
            .map(|i| p.number(knots_at + i))
            .collect::<Result<_, _>>()?;
        let weights: Vec<f64> = (0..n)
            .map(|i| p.number(weights_at + i))
            .collect::<Result<_, _>>()?;
        let points: Vec<Point3> = (0..n)
            .map(|i| p.point(points_at + 3 * i))
            .collect::<Result<_, _>>()?;
        let (v0, v1) = (p.number(range_at)?, p.number(range_at + 1)?);
        let c = NurbsCurve::new(m, knots, points, weights).map_err(|e| p.error(e.to_string()))?;
        let d = c.domain();
        let c = if (v0 > d.start || v1 < d.end) && v0 < v1 && v0 >= d.start && v1 <= d.end {
            c.segment(v0, v1).map_err(|e| p.error(e.to_string()))?
        } else {
            c
        };
        let ends_meet = c.eval(c.domain().start).distance(c.eval(c.domain().end))
            <= 1e-10
                * c.control_points()
                    .iter()
                    .map(|q| q.distance(c.control_points()[0]))
                    .fold(0.0, f64::max);
        Ok(c.with_closed(closed && ends_meet))
    }

    /// Entity 128 or 120 in model space.
    fn surface(
        &mut self,
        pointer: i64,
        from: &Params<'_>,
    ) -> Result<Got<NurbsSurface<3>>, IoError> {
        self.enter(pointer, from)?;
        let p = self.params(pointer, Some(from))?;
        if p.entry.kind == 120 {
            let s = self.revolution(&p);
            self.visiting.remove(&pointer);
            return s;
        }
        self.visiting.remove(&pointer);
        if p.entry.kind != 128 {
            let kind = p.entry.kind;
            let name = UNREAD
                .iter()
                .find(|(k, _)| *k == kind)
                .map_or("not a surface karkas reads", |(_, n)| n);
            return Ok(Got::Skip(
                format!("trimmed surfaces on entity {kind} ({name})"),
                "surface type not read",
            ));
        }
        let k1 = p.count(1, 1 << 20)?;
        let k2 = p.count(2, 1 << 20)?;
        let m1 = p.count(3, karkas::bspline::MAX_DEGREE as i64)?;
        let m2 = p.count(4, karkas::bspline::MAX_DEGREE as i64)?;
        let (closed_u, closed_v) = (p.int(5)? == 1, p.int(6)? == 1);
        let (nu, nv) = (k1 + 1, k2 + 1);
        if nu.saturating_mul(nv) > 1 << 24 {
            return Err(p.error("more than 2^24 control points"));
        }
        let su = 10;
        let sv = su + nu + m1 + 1;
        let w = sv + nv + m2 + 1;
        let pts = w + nu * nv;
        let knots_u: Vec<f64> = (0..nu + m1 + 1)
            .map(|i| p.number(su + i))
            .collect::<Result<_, _>>()?;
        let knots_v: Vec<f64> = (0..nv + m2 + 1)
            .map(|i| p.number(sv + i))
            .collect::<Result<_, _>>()?;
        // The first index (u) runs fastest.
        let mut weights = vec![0.0; nu * nv];
        let mut points = vec![Point3::ZERO; nu * nv];
        for j in 0..nv {
            for i in 0..nu {
                let k = i + nu * j;
                weights[i * nv + j] = p.number(w + k)?;
                points[i * nv + j] = p.point(pts + 3 * k)?;
            }
        }
        let map = self.transform(p.entry, &p)?;
        let control =
            Grid::from_row_major(nu, nv, points.into_iter().map(|q| map.apply(q)).collect())
                .map_err(|e| p.error(e.to_string()))?;
        let weights = Grid::from_row_major(nu, nv, weights).map_err(|e| p.error(e.to_string()))?;
        let s = NurbsSurface::new((m1, knots_u), (m2, knots_v), control, weights)
            .map_err(|e| p.error(e.to_string()))?;
        let (cu, cv) = (
            closed_u && ends_meet(&s, true),
            closed_v && ends_meet(&s, false),
        );
        Ok(Got::Read(s.with_closed(cu, cv)))
    }

    /// Entity 120: the generatrix (one line, arc or B-spline) turned about the axis line from
    /// the start to the terminate angle (radians, right-handed about the axis's direction from
    /// its first point to its second), exactly as a rational surface whose `u` is the angle
    /// at its knots and `v` the generatrix's parameter ([`revolution`]). Its parameter space
    /// is not IGES's (whose angle is linear), so the faces it carries are bounded by their
    /// model-space curves.
    fn revolution(&mut self, p: &Params<'_>) -> Result<Got<NurbsSurface<3>>, IoError> {
        let one = |got: Got<Vec<NurbsCurve<3>>>, what: &str| match got {
            Got::Read(mut pieces) if pieces.len() == 1 => Ok(Ok(pieces.remove(0))),
            Got::Read(pieces) => Err(p.error(format!(
                "a surface of revolution's {what} must be one curve, got {} pieces",
                pieces.len()
            ))),
            Got::Skip(what, why) => Ok(Err(Got::Skip(what, why))),
        };
        let axis = match one(self.curve(p.int(1)?, p)?, "axis")? {
            Ok(c) => c,
            Err(skip) => return Ok(skip),
        };
        let generatrix = match one(self.curve(p.int(2)?, p)?, "generatrix")? {
            Ok(c) => c,
            Err(skip) => return Ok(skip),
        };
        let (start, end) = (p.number(3)?, p.number(4)?);
        let map = self.transform(p.entry, p)?;
        let d = axis.domain();
        let (a, b) = (map.apply(axis.eval(d.start)), map.apply(axis.eval(d.end)));
        let profile = generatrix.map_points(|q| map.apply(q));
        let s = revolution(&profile, a, b - a, (start, end)).map_err(|e| p.error(e.to_string()))?;
        let whole = ((end - start) - std::f64::consts::TAU).abs() <= 1e-9;
        Ok(Got::Read(s.with_closed(whole, false)))
    }

    /// Entity 142: the loop of model-space edges and the parameter-space curves. `surface` is
    /// the surface whose parameters are IGES's; `None` for a plane (108) or a surface of
    /// revolution (120), whose loops are taken in model space only.
    fn boundary(
        &mut self,
        pointer: i64,
        from: &Params<'_>,
        surface: Option<&NurbsSurface<3>>,
        outer: bool,
    ) -> Result<Got<EdgeLoop>, IoError> {
        self.enter(pointer, from)?;
        self.visiting.remove(&pointer);
        let p = self.params(pointer, Some(from))?;
        if p.entry.kind != 142 {
            return Err(p.error("a trimmed surface's boundary must be a curve on a surface (142)"));
        }
        let (b, c, pref) = (p.int(3)?, p.int(4)?, p.int(5)?);
        let mut parameter_curves = Vec::new();
        let Some(surface) = surface else {
            if c == 0 {
                return Ok(Got::Skip(
                    "trimmed surfaces on a plane (108) or a surface of revolution (120) \
                     bounded in parameter space only"
                        .into(),
                    "the face's loop has no model-space curve",
                ));
            }
            return self.model_loop(c, &p, outer);
        };
        if b != 0 && pref != 2 {
            match self.curve(b, &p)? {
                Got::Read(pieces) => {
                    parameter_curves = pieces
                        .iter()
                        .map(|c| c.map_points(|q| karkas::Point2::new([q[0], q[1]])))
                        .collect()
                }
                Got::Skip(..) if c != 0 => {}
                Got::Skip(what, why) => return Ok(Got::Skip(what, why)),
            }
        }
        let edges: Vec<Edge> = if c != 0 {
            match self.curve(c, &p)? {
                Got::Read(pieces) => pieces
                    .into_iter()
                    .map(|curve| Edge {
                        curve,
                        forward: true,
                    })
                    .collect(),
                Got::Skip(what, why) if parameter_curves.is_empty() => {
                    return Ok(Got::Skip(what, why))
                }
                Got::Skip(..) => image_edges(&parameter_curves, surface),
            }
        } else if !parameter_curves.is_empty() {
            image_edges(&parameter_curves, surface)
        } else {
            return Err(
                p.error("a curve on a surface with neither its parameter nor its model curve")
            );
        };
        Ok(Got::Read(EdgeLoop {
            edges,
            outer,
            parameter_curves,
        }))
    }

    /// A loop of the model-space curve `c` of the boundary `p` alone.
    fn model_loop(
        &mut self,
        c: i64,
        p: &Params<'_>,
        outer: bool,
    ) -> Result<Got<EdgeLoop>, IoError> {
        Ok(match self.curve(c, p)? {
            Got::Read(pieces) => Got::Read(EdgeLoop {
                edges: pieces
                    .into_iter()
                    .map(|curve| Edge {
                        curve,
                        forward: true,
                    })
                    .collect(),
                outer,
                parameter_curves: Vec::new(),
            }),
            Got::Skip(what, why) => Got::Skip(what, why),
        })
    }

    /// Entity 144.
    fn trimmed(&mut self, pointer: i64) -> Result<Got<Face>, IoError> {
        let p = self.params(pointer, None)?;
        self.used.insert(pointer);
        let basis = p.int(1)?;
        let kind = self.params(basis, Some(&p))?.entry.kind;
        if kind == 108 {
            return self.trimmed_plane(&p, basis);
        }
        // A surface of revolution's parameters differ from IGES's: its loops are inverted.
        let surface = match self.surface(basis, &p)? {
            Got::Read(s) => s,
            Got::Skip(what, why) => return Ok(Got::Skip(what, why)),
        };
        let own = (kind != 120).then_some(&surface);
        let loops = match self.loops(&p, own)? {
            Got::Read(loops) => loops,
            Got::Skip(what, why) => return Ok(Got::Skip(what, why)),
        };
        Ok(Got::Read(Face {
            surface,
            loops,
            same_sense: true,
            bounds_solid: false,
        }))
    }

    /// Entity 144 on a plane (108): IGES gives a plane no parameters, so the loops are the
    /// model-space curves and the surface the flat patch over them ([`PlaneFrame`]).
    fn trimmed_plane(&mut self, p: &Params<'_>, basis: i64) -> Result<Got<Face>, IoError> {
        self.enter(basis, p)?;
        self.visiting.remove(&basis);
        if p.int(2)? == 0 {
            return Ok(Got::Skip(
                "trimmed surfaces on entity 108 (plane) with no outer boundary".into(),
                "a plane has no bounds of its own",
            ));
        }
        let plane = self.params(basis, Some(p))?;
        let coefficients = [1, 2, 3, 4].map(|i| plane.number(i));
        let [a, b, c, d] = coefficients;
        let map = self.transform(plane.entry, &plane)?;
        let frame = PlaneFrame::new([a?, b?, c?, d?], |q| map.apply(q))
            .ok_or_else(|| plane.error("a plane whose normal (A, B, C) is zero"))?;
        let loops = match self.loops(p, None)? {
            Got::Read(loops) => loops,
            Got::Skip(what, why) => return Ok(Got::Skip(what, why)),
        };
        let Some(surface) = frame.patch_over(&loops) else {
            return Ok(Got::Skip(
                "trimmed surfaces on entity 108 (plane) without an extent".into(),
                "the face's loops span no area",
            ));
        };
        Ok(Got::Read(Face {
            surface,
            loops,
            same_sense: true,
            bounds_solid: false,
        }))
    }

    /// The outer and inner boundaries (142) of the trimmed surface `p` (on `surface`, as for
    /// [`Builder::boundary`]).
    fn loops(
        &mut self,
        p: &Params<'_>,
        surface: Option<&NurbsSurface<3>>,
    ) -> Result<Got<Vec<EdgeLoop>>, IoError> {
        let n1 = p.int(2)?;
        let n2 = p.count(3, 1 << 20)?;
        let mut loops = Vec::new();
        let outer = (n1 != 0).then_some(4);
        for (slot, is_outer) in outer
            .map(|s| (s, true))
            .into_iter()
            .chain((0..n2).map(|i| (5 + i, false)))
        {
            match self.boundary(p.int(slot)?, p, surface, is_outer)? {
                Got::Read(l) => loops.push(l),
                Got::Skip(what, why) => return Ok(Got::Skip(what, why)),
            }
        }
        Ok(Got::Read(loops))
    }

    fn skip(&mut self, what: String, why: &'static str) {
        *self.unread.entry((what, why)).or_insert(0) += 1;
    }
}

/// Entity 104 form 1, an elliptic arc of `A x^2 + B x y + C y^2 + D x + E y + F = 0` in the
/// plane `z = ZT`, counter-clockwise from `(X1, Y1)` to `(X2, Y2)` (the whole ellipse when
/// they coincide): its centre `c` solves `[2A B; B 2C] c = -(D, E)`, its axes are the
/// eigenvectors of `[A B/2; B/2 C]` (the first at `atan2(B, A - C) / 2`), with semi-axes
/// `sqrt(-Q(c) / λ)`, so the arc is `c + cos θ r1 v1 + sin θ r2 v2` with `v2` a quarter
/// turn counter-clockwise from `v1`, exactly ([`elliptic_arc`]).
fn elliptic_conic(p: &Params<'_>) -> Result<NurbsCurve<3>, IoError> {
    let [a, b, c, d, e, f, zt, x1, y1, x2, y2] = [1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11]
        .map(|i| p.number(i))
        .into_iter()
        .collect::<Result<Vec<f64>, _>>()?
        .try_into()
        .map_err(|_| p.error("an elliptic arc needs 11 parameters"))?;
    let not_an_ellipse = || p.error("a conic arc of form 1 whose coefficients are not an ellipse");
    // The quadratic part scaled to order one: an ellipse of radius 1e150 has A = C = 1e-300,
    // whose product would underflow.
    let m = a.abs().max(b.abs()).max(c.abs());
    if !(m > 0.0 && m.is_finite()) {
        return Err(not_an_ellipse());
    }
    let [a, b, c, d, e, f] = [a, b, c, d, e, f].map(|x| x / m);
    let det = 4.0 * a * c - b * b;
    if !(det > 0.0 && det.is_finite()) {
        return Err(not_an_ellipse());
    }
    let (x0, y0) = ((-2.0 * c * d + b * e) / det, (b * d - 2.0 * a * e) / det);
    let value = f + 0.5 * (d * x0 + e * y0);
    let angle = 0.5 * b.atan2(a - c);
    let (cos, sin) = (angle.cos(), angle.sin());
    let l1 = a * cos * cos + b * cos * sin + c * sin * sin;
    let l2 = a * sin * sin - b * cos * sin + c * cos * cos;
    let (r1, r2) = ((-value / l1).sqrt(), (-value / l2).sqrt());
    if !(r1 > 0.0 && r2 > 0.0 && r1.is_finite() && r2.is_finite()) {
        return Err(not_an_ellipse());
    }
    let (v1, v2) = ([cos, sin], [-sin, cos]);
    let theta = |x: f64, y: f64| {
        let (dx, dy) = (x - x0, y - y0);
        ((dx * v2[0] + dy * v2[1]) / r2).atan2((dx * v1[0] + dy * v1[1]) / r1)
    };
    let t0 = theta(x1, y1);
    let mut t1 = theta(x2, y2);
    while t1 <= t0 + 1e-12 {
        t1 += std::f64::consts::TAU;
    }
    let centre = Point3::new([x0, y0, zt]);
    let x = Point3::new([r1 * v1[0], r1 * v1[1], 0.0]);
    let y = Point3::new([r2 * v2[0], r2 * v2[1], 0.0]);
    elliptic_arc(centre, x, y, (t0, t1)).map_err(|m| p.error(m.to_string()))
}

/// Whether the surface's first and last lines in `u` (or `v`) coincide.
fn ends_meet(s: &NurbsSurface<3>, u: bool) -> bool {
    let (du, dv) = (s.domain_u(), s.domain_v());
    let size = s
        .control_points()
        .as_slice()
        .iter()
        .map(|q| q.distance(*s.control_points().get(0, 0)))
        .fold(0.0, f64::max);
    (0..=8).all(|k| {
        let t = k as f64 / 8.0;
        let (a, b) = if u {
            let v = dv.start + t * dv.length();
            (s.eval(du.start, v), s.eval(du.end, v))
        } else {
            let x = du.start + t * du.length();
            (s.eval(x, dv.start), s.eval(x, dv.end))
        };
        a.distance(b) <= 1e-10 * size
    })
}

/// The model-space images of parameter-space curves on `surface`, as polylines of 64
/// segments per curve (a composition of NURBS is no NURBS of small degree): the edges of a
/// boundary whose file gives no model-space curve.
fn image_edges(curves: &[NurbsCurve<2>], surface: &NurbsSurface<3>) -> Vec<Edge> {
    curves
        .iter()
        .filter_map(|c| {
            let d = c.domain();
            let n = 64;
            let points: Vec<Point3> = (0..=n)
                .map(|k| {
                    let q = c.eval(d.uniform(k, n + 1));
                    surface.eval(q[0], q[1])
                })
                .collect();
            let mut knots = vec![0.0];
            knots.extend((0..=n).map(|k| k as f64));
            knots.push(n as f64);
            NurbsCurve::new(1, knots, points, vec![1.0; n + 1])
                .ok()
                .map(|curve| Edge {
                    curve,
                    forward: true,
                })
        })
        .collect()
}

/// The unit of the global section's flag and name.
fn unit(flag: i64, name: &str) -> LengthUnit {
    let (name, metres) = match flag {
        1 => ("inch", 0.0254),
        2 => ("millimetre", 1e-3),
        4 => ("foot", 0.3048),
        5 => ("mile", 1609.344),
        6 => ("metre", 1.0),
        7 => ("kilometre", 1e3),
        8 => ("mil", 2.54e-5),
        9 => ("micrometre", 1e-6),
        10 => ("centimetre", 1e-2),
        11 => ("microinch", 2.54e-8),
        _ => match name.to_ascii_uppercase().as_str() {
            "IN" | "INCH" => ("inch", 0.0254),
            "M" => ("metre", 1.0),
            "CM" => ("centimetre", 1e-2),
            "FT" => ("foot", 0.3048),
            _ => ("millimetre", 1e-3),
        },
    };
    LengthUnit {
        name: name.into(),
        metres,
    }
}

/// Reads an IGES file.
pub(crate) fn read_iges(name: &Path, reader: &mut dyn BufRead) -> Result<CadModel, IoError> {
    let file = read_records(name, reader, &|k| READ.contains(&k))?;
    let mut b = Builder {
        path: name,
        file: &file,
        visiting: HashSet::new(),
        used: HashSet::new(),
        unread: BTreeMap::new(),
    };
    let mut shape = Shape::default();
    let roots: Vec<(i64, i64)> = file
        .entries
        .iter()
        .filter(|(_, e)| (e.subordinate == 0 || e.kind == 144) && READ.contains(&e.kind))
        .map(|(&p, e)| (p, e.kind))
        .collect();
    for &(pointer, kind) in &roots {
        if kind == 144 {
            match b.trimmed(pointer)? {
                Got::Read(face) => shape.faces.push(face),
                Got::Skip(what, why) => b.skip(what, why),
            }
        }
    }
    for &(pointer, kind) in &roots {
        if b.used.contains(&pointer) {
            continue;
        }
        let from = b.params(pointer, None)?;
        match kind {
            120 | 128 => match b.surface(pointer, &from)? {
                Got::Read(s) => shape.faces.push(Face::whole(s)),
                Got::Skip(what, why) => b.skip(what, why),
            },
            108 => b.skip(
                "entity 108 (plane) outside a trimmed surface".into(),
                "entity type not read",
            ),
            100 | 102 | 104 | 110 | 126 => match b.curve(pointer, &from)? {
                Got::Read(mut c) => shape.curves.append(&mut c),
                Got::Skip(what, why) => b.skip(what, why),
            },
            _ => {}
        }
    }
    let mut unread: Vec<Unread> = b
        .unread
        .iter()
        .map(|((what, why), &count)| Unread {
            what: what.clone(),
            count,
            reason: (*why).to_owned(),
        })
        .collect();
    for (kind, &count) in &file.others {
        if let Some((_, n)) = UNREAD.iter().find(|(k, _)| k == kind) {
            unread.push(Unread {
                what: format!("entity {kind} ({n})"),
                count,
                reason: "entity type not read".into(),
            });
        }
    }
    let mut notes = Vec::new();
    if file.scale != 1.0 {
        notes.push(format!(
            "model space scale {} (coordinates kept as written)",
            file.scale
        ));
    }
    Ok(CadModel {
        path: name.to_path_buf(),
        format: CadFormat::Iges,
        shape,
        unit: unit(file.unit_flag, &file.unit_name),
        unread,
        notes,
        entities: file.entries.len(),
    })
}

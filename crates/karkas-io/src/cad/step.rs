//! STEP (ISO 10303-21, AP214 `AUTOMOTIVE_DESIGN`) files of exact B-spline curves and
//! surfaces.
//!
//! Curves are `B_SPLINE_CURVE_WITH_KNOTS` in a `GEOMETRIC_CURVE_SET` of a
//! `GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION`; surfaces are
//! `B_SPLINE_SURFACE_WITH_KNOTS` carried by an `ADVANCED_FACE` bounded by its boundary
//! curves (the iso-lines at the domain ends, exact B-splines too; no edge at a pole, one seam
//! edge used twice for a closed direction: [`CadShell`]), each edge a `SURFACE_CURVE` that
//! also carries its line in the parameter plane of every B-spline face using it once
//! (`PCURVE`), in an `OPEN_SHELL` of a
//! `SHELL_BASED_SURFACE_MODEL` of a `MANIFOLD_SURFACE_SHAPE_REPRESENTATION`: the forms CAD
//! systems import as wires and faces. A closed shell (a body closed by its poles and seams,
//! or capped by planar faces, `PLANE`) is a `CLOSED_SHELL` of a `MANIFOLD_SOLID_BREP` in an
//! `ADVANCED_BREP_SHAPE_REPRESENTATION`: a solid, its faces turned outwards. One product holds all items; lengths are in
//! millimetres (the data's own unit is not known). Reals carry 17 significant digits, so a
//! reader gets the same `f64` back. Closed karkas curves and surfaces are written as clamped
//! B-splines over one period, with their closed flags set (`.T.`). Rational curves and
//! surfaces are the complex instances with `RATIONAL_B_SPLINE_CURVE` / `_SURFACE`.
//!
//! Hand-written: the Rust STEP crates either only read or come with a whole CAD kernel;
//! writing these entities takes a page.

use std::fmt::Write as _;
use std::path::Path;

use karkas::bspline::{BSplineCurve, BSplineSurface, NurbsCurve, NurbsSurface};
use karkas::{Curve, Point, Surface};

use crate::cad::entity::{
    curve_closed, knot_runs, real, surface_closed, surface_shell, write_named, CadEntity,
};
use crate::cad::shell::{CadShell, FaceSurface};
use crate::cad::time_stamp::FileStamp;
use crate::cad::units::LengthUnit;
use crate::error::IoError;

/// The entity instances of a STEP data section, numbered from 1.
struct Data {
    lines: Vec<String>,
    /// The context of parameter-plane curves, once one is written.
    parameter_context: Option<String>,
}

impl Data {
    /// Adds an instance and returns its reference `#n`.
    fn add(&mut self, entity: String) -> String {
        self.lines.push(entity);
        format!("#{}", self.lines.len())
    }

    fn point(&mut self, p: Point<3>) -> String {
        self.add(format!(
            "CARTESIAN_POINT('',({},{},{}))",
            real(p[0]),
            real(p[1]),
            real(p[2])
        ))
    }

    fn curve(&mut self, c: &BSplineCurve<3>, name: &str) -> String {
        let points: Vec<String> = c.control_points().iter().map(|&p| self.point(p)).collect();
        let (values, counts) = knot_runs(c.knots());
        self.add(format!(
            "B_SPLINE_CURVE_WITH_KNOTS('{name}',{},({}),.UNSPECIFIED.,{},.F.,({}),({}),.UNSPECIFIED.)",
            c.degree(),
            points.join(","),
            logical(curve_closed(c)),
            join_usize(&counts),
            join_real(&values),
        ))
    }

    fn surface(&mut self, s: &BSplineSurface<3>, name: &str) -> String {
        let grid = s.control_points();
        let rows: Vec<String> = (0..grid.rows())
            .map(|i| {
                let row: Vec<String> = grid.row(i).iter().map(|&p| self.point(p)).collect();
                format!("({})", row.join(","))
            })
            .collect();
        let (ku, mu) = knot_runs(s.knots_u());
        let (kv, mv) = knot_runs(s.knots_v());
        let (closed_u, closed_v) = surface_closed(s);
        self.add(format!(
            "B_SPLINE_SURFACE_WITH_KNOTS('{name}',{},{},({}),.UNSPECIFIED.,{},{},.F.,({}),({}),({}),({}),.UNSPECIFIED.)",
            s.degree_u(),
            s.degree_v(),
            rows.join(","),
            logical(closed_u),
            logical(closed_v),
            join_usize(&mu),
            join_usize(&mv),
            join_real(&ku),
            join_real(&kv),
        ))
    }

    /// The faces of `shell` (see [`CadShell`]): its vertices, surfaces, edges (each written
    /// once, however many loops use it, with its curve on each B-spline face that uses it
    /// once: [`Data::edge_geometry`]), loops and faces, in an `OPEN_SHELL` or, when it is
    /// closed, a `CLOSED_SHELL`. Returns the shell's reference and whether it is closed.
    fn shell(&mut self, shell: &CadShell, name: &str) -> (String, bool) {
        let vertices: Vec<String> = shell
            .vertices()
            .iter()
            .map(|&p| {
                let point = self.point(p);
                self.add(format!("VERTEX_POINT('',{point})"))
            })
            .collect();
        let names: Vec<String> = (0..shell.faces().len())
            .map(|k| match k {
                0 => name.to_owned(),
                _ => format!("{name}_{k}"),
            })
            .collect();
        let surfaces: Vec<String> = shell
            .faces()
            .iter()
            .zip(&names)
            .map(|(face, face_name)| self.face_surface(&face.surface, face_name))
            .collect();
        let edges: Vec<String> = (0..shell.edges().len())
            .map(|k| {
                let geometry = self.edge_geometry(shell, k, &surfaces);
                let e = &shell.edges()[k];
                self.add(format!(
                    "EDGE_CURVE('',{},{},{geometry},.T.)",
                    vertices[e.start], vertices[e.end]
                ))
            })
            .collect();
        let mut faces = Vec::new();
        for ((face, surface), face_name) in shell.faces().iter().zip(&surfaces).zip(&names) {
            let bound = if face.bound.is_empty() {
                // A face with no edge at all (every side a point): bounded by a vertex.
                let vertex = vertices.first().cloned().unwrap_or_default();
                let vertex_loop = self.add(format!("VERTEX_LOOP('',{vertex})"));
                self.add(format!("FACE_BOUND('',{vertex_loop},.T.)"))
            } else {
                let oriented: Vec<String> = face
                    .bound
                    .iter()
                    .map(|o| {
                        self.add(format!(
                            "ORIENTED_EDGE('',*,*,{},{})",
                            edges[o.edge],
                            logical(o.forward)
                        ))
                    })
                    .collect();
                let edge_loop = self.add(format!("EDGE_LOOP('',({}))", oriented.join(",")));
                self.add(format!("FACE_OUTER_BOUND('',{edge_loop},.T.)"))
            };
            faces.push(self.add(format!(
                "ADVANCED_FACE('{face_name}',({bound}),{surface},{})",
                logical(face.same_sense)
            )));
        }
        let closed = shell.is_closed();
        let kind = if closed { "CLOSED_SHELL" } else { "OPEN_SHELL" };
        (
            self.add(format!("{kind}('',({}))", faces.join(","))),
            closed,
        )
    }

    /// The surface of a face: a B-spline surface or a `PLANE`.
    fn face_surface(&mut self, surface: &FaceSurface, name: &str) -> String {
        match surface {
            FaceSurface::BSpline(s) => self.surface(s, name),
            FaceSurface::Plane(plane) => {
                let origin = self.point(plane.origin);
                let axis = self.direction(plane.normal);
                let x = self.direction(plane.x_axis());
                let placement = self.add(format!("AXIS2_PLACEMENT_3D('',{origin},{axis},{x})"));
                self.add(format!("PLANE('{name}',{placement})"))
            }
        }
    }

    /// The geometry of edge `k` of `shell`: its 3-D curve, in a `SURFACE_CURVE` with one
    /// `PCURVE` per B-spline face that uses the edge once (the side of the face's parameter
    /// rectangle it is, a degree-1 B-spline over the edge curve's parameters). A reader that
    /// derived these by projecting the curve would fold them where a side runs down a line
    /// and back up it (the end section of a whole hull). Planes get none (a projection onto
    /// a plane is exact), nor does a seam (used twice by its face).
    fn edge_geometry(&mut self, shell: &CadShell, k: usize, surfaces: &[String]) -> String {
        let edge = &shell.edges()[k];
        let curve = self.curve(&edge.curve, "");
        let domain = edge.curve.domain();
        let mut pcurves = Vec::new();
        for (face, surface) in shell.faces().iter().zip(surfaces) {
            let uses: Vec<_> = face.bound.iter().filter(|o| o.edge == k).collect();
            if let ([use_], FaceSurface::BSpline(_)) = (uses.as_slice(), &face.surface) {
                if let Some(segment) = use_.on_face {
                    let context = self.parameter_context();
                    let start = self.point_2d(segment.start);
                    let end = self.point_2d(segment.end);
                    let line = self.add(format!(
                        "B_SPLINE_CURVE_WITH_KNOTS('',1,({start},{end}),.POLYLINE_FORM.,.F.,.F.,(2,2),({}),.UNSPECIFIED.)",
                        join_real(&[domain.start, domain.end])
                    ));
                    let representation = self.add(format!(
                        "DEFINITIONAL_REPRESENTATION('',({line}),{context})"
                    ));
                    pcurves.push(self.add(format!("PCURVE('',{surface},{representation})")));
                }
            }
        }
        if pcurves.is_empty() {
            return curve;
        }
        self.add(format!(
            "SURFACE_CURVE('',{curve},({}),.CURVE_3D.)",
            pcurves.join(",")
        ))
    }

    /// The context of the parameter-plane curves, written once.
    fn parameter_context(&mut self) -> String {
        if let Some(context) = &self.parameter_context {
            return context.clone();
        }
        let context = self.add(
            "(GEOMETRIC_REPRESENTATION_CONTEXT(2)PARAMETRIC_REPRESENTATION_CONTEXT()REPRESENTATION_CONTEXT('2D SPACE',''))"
                .into(),
        );
        self.parameter_context = Some(context.clone());
        context
    }

    fn point_2d(&mut self, p: [f64; 2]) -> String {
        self.add(format!(
            "CARTESIAN_POINT('',({},{}))",
            real(p[0]),
            real(p[1])
        ))
    }

    fn direction(&mut self, d: Point<3>) -> String {
        self.add(format!(
            "DIRECTION('',({},{},{}))",
            real(d[0]),
            real(d[1]),
            real(d[2])
        ))
    }
}

/// Rational curves and surfaces: the complex instances of ISO 10303-42 (parts in
/// alphabetical order), which carry the weights; a NURBS whose weights are equal is written
/// as the plain `B_SPLINE_..._WITH_KNOTS` of its control points.
impl Data {
    fn rational_curve(&mut self, c: &NurbsCurve<3>, name: &str) -> String {
        let points: Vec<String> = c.control_points().iter().map(|&p| self.point(p)).collect();
        let (values, counts) = knot_runs(c.knots());
        let (degree, closed) = (c.degree(), logical(c.is_closed()));
        let (points, counts, values) = (points.join(","), join_usize(&counts), join_real(&values));
        if !c.is_rational() {
            return self.add(format!(
                "B_SPLINE_CURVE_WITH_KNOTS('{name}',{degree},({points}),.UNSPECIFIED.,{closed},.F.,({counts}),({values}),.UNSPECIFIED.)"
            ));
        }
        self.add(format!(
            "(BOUNDED_CURVE()B_SPLINE_CURVE({degree},({points}),.UNSPECIFIED.,{closed},.F.)B_SPLINE_CURVE_WITH_KNOTS(({counts}),({values}),.UNSPECIFIED.)CURVE()GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_CURVE(({}))REPRESENTATION_ITEM('{name}'))",
            join_real(c.weights())
        ))
    }

    fn rational_surface(&mut self, s: &NurbsSurface<3>, name: &str) -> String {
        let grid = s.control_points();
        let rows: Vec<String> = (0..grid.rows())
            .map(|i| {
                let row: Vec<String> = grid.row(i).iter().map(|&p| self.point(p)).collect();
                format!("({})", row.join(","))
            })
            .collect();
        let weights: Vec<String> = (0..grid.rows())
            .map(|i| format!("({})", join_real(s.weights().row(i))))
            .collect();
        let (ku, mu) = knot_runs(s.knots_u());
        let (kv, mv) = knot_runs(s.knots_v());
        let head = format!(
            "{},{},({}),.UNSPECIFIED.,{},{},.F.",
            s.degree_u(),
            s.degree_v(),
            rows.join(","),
            logical(s.is_closed_u()),
            logical(s.is_closed_v())
        );
        let knots = format!(
            "({}),({}),({}),({}),.UNSPECIFIED.",
            join_usize(&mu),
            join_usize(&mv),
            join_real(&ku),
            join_real(&kv)
        );
        if !s.is_rational() {
            return self.add(format!(
                "B_SPLINE_SURFACE_WITH_KNOTS('{name}',{head},{knots})"
            ));
        }
        self.add(format!(
            "(BOUNDED_SURFACE()B_SPLINE_SURFACE({head})B_SPLINE_SURFACE_WITH_KNOTS({knots})GEOMETRIC_REPRESENTATION_ITEM()RATIONAL_B_SPLINE_SURFACE(({}))REPRESENTATION_ITEM('{name}')SURFACE())",
            weights.join(",")
        ))
    }

    /// The face of the rational surface `s` bounded by its four boundary iso-curves.
    fn rational_face(&mut self, s: &NurbsSurface<3>, name: &str) -> String {
        let surface = self.rational_surface(s, name);
        let (du, dv) = (s.domain_u(), s.domain_v());
        let corners = [
            s.eval(du.start, dv.start),
            s.eval(du.end, dv.start),
            s.eval(du.end, dv.end),
            s.eval(du.start, dv.end),
        ];
        let vertices: Vec<String> = corners
            .iter()
            .map(|&p| {
                let point = self.point(p);
                self.add(format!("VERTEX_POINT('',{point})"))
            })
            .collect();
        let sides = [
            (s.iso_curve(true, dv.start), 0, 1, true),
            (s.iso_curve(false, du.end), 1, 2, true),
            (s.iso_curve(true, dv.end), 3, 2, false),
            (s.iso_curve(false, du.start), 0, 3, false),
        ];
        let edges: Vec<String> = sides
            .iter()
            .map(|(curve, a, b, sense)| {
                let geometry = self.rational_curve(&curve.clone().with_closed(false), "");
                let edge = self.add(format!(
                    "EDGE_CURVE('',{},{},{geometry},.T.)",
                    vertices[*a], vertices[*b]
                ));
                self.add(format!("ORIENTED_EDGE('',*,*,{edge},{})", logical(*sense)))
            })
            .collect();
        let edge_loop = self.add(format!("EDGE_LOOP('',({}))", edges.join(",")));
        let bound = self.add(format!("FACE_OUTER_BOUND('',{edge_loop},.T.)"));
        self.add(format!("ADVANCED_FACE('{name}',({bound}),{surface},.T.)"))
    }
}

/// A STEP logical: `.T.` or `.F.`.
fn logical(value: bool) -> &'static str {
    if value {
        ".T."
    } else {
        ".F."
    }
}

fn join_usize(values: &[usize]) -> String {
    let v: Vec<String> = values.iter().map(|x| x.to_string()).collect();
    v.join(",")
}

fn join_real(values: &[f64]) -> String {
    let v: Vec<String> = values.iter().map(|&x| real(x)).collect();
    v.join(",")
}

/// Quotes a name for a STEP string (apostrophes doubled, printable ASCII only).
fn step_string(name: &str) -> String {
    name.chars()
        .filter(|c| c.is_ascii() && !c.is_ascii_control() && *c != '\\')
        .collect::<String>()
        .replace('\'', "''")
}

/// The text of a STEP file holding `entities`, named `name` (the product's name), lengths in
/// millimetres.
pub fn step_text(entities: &[CadEntity<'_>], name: &str) -> String {
    step_text_in(entities, name, LengthUnit::Millimetre)
}

/// [`step_text`] with the length unit `unit` ([`crate::cad::units`]).
pub fn step_text_in(entities: &[CadEntity<'_>], name: &str, unit: LengthUnit) -> String {
    let name = step_string(name);
    let mut data = Data {
        lines: Vec::new(),
        parameter_context: None,
    };
    let shape = data.product(&name);
    let context = data.context(unit);
    let placement = data.origin_placement();
    let items = data.items(entities, &name);
    data.representations(&items, (&name, &shape, &context, &placement));
    exchange_text(&name, &data)
}

/// The representation items of a file's entities: curves, open shells and solids.
struct Items {
    curves: Vec<String>,
    open_shells: Vec<String>,
    solids: Vec<String>,
}

impl Data {
    /// The product `name` and its definition, down to its shape (returned).
    fn product(&mut self, name: &str) -> String {
        let app = self.add(
            "APPLICATION_CONTEXT('core data for automotive mechanical design processes')".into(),
        );
        self.add(format!(
            "APPLICATION_PROTOCOL_DEFINITION('international standard','automotive_design',2000,{app})"
        ));
        let product_context = self.add(format!("PRODUCT_CONTEXT('',{app},'mechanical')"));
        let product = self.add(format!("PRODUCT('{name}','{name}','',({product_context}))"));
        self.add(format!(
            "PRODUCT_RELATED_PRODUCT_CATEGORY('part',$,({product}))"
        ));
        let formation = self.add(format!("PRODUCT_DEFINITION_FORMATION('','',{product})"));
        let definition_context = self.add(format!(
            "PRODUCT_DEFINITION_CONTEXT('part definition',{app},'design')"
        ));
        let definition = self.add(format!(
            "PRODUCT_DEFINITION('design','',{formation},{definition_context})"
        ));
        self.add(format!("PRODUCT_DEFINITION_SHAPE('','',{definition})"))
    }

    /// The geometric context: units (lengths in `unit`, angles in radians) and uncertainty.
    fn context(&mut self, unit: LengthUnit) -> String {
        let length = unit.step_instances(&mut |e| self.add(e));
        let angle = self.add("(NAMED_UNIT(*)PLANE_ANGLE_UNIT()SI_UNIT($,.RADIAN.))".into());
        let solid = self.add("(NAMED_UNIT(*)SI_UNIT($,.STERADIAN.)SOLID_ANGLE_UNIT())".into());
        let uncertainty = self.add(format!(
            "UNCERTAINTY_MEASURE_WITH_UNIT(LENGTH_MEASURE(1.E-07),{length},'distance_accuracy_value','confusion accuracy')"
        ));
        self.add(format!(
            "(GEOMETRIC_REPRESENTATION_CONTEXT(3)GLOBAL_UNCERTAINTY_ASSIGNED_CONTEXT(({uncertainty}))GLOBAL_UNIT_ASSIGNED_CONTEXT(({length},{angle},{solid}))REPRESENTATION_CONTEXT('karkas','3D'))"
        ))
    }

    /// The placement at the origin with the global axes.
    fn origin_placement(&mut self) -> String {
        let origin = self.point(Point([0.0, 0.0, 0.0]));
        let z = self.add("DIRECTION('',(0.,0.,1.))".into());
        let x = self.add("DIRECTION('',(1.,0.,0.))".into());
        self.add(format!("AXIS2_PLACEMENT_3D('',{origin},{z},{x})"))
    }

    /// The items of `entities`, named `name_k`.
    fn items(&mut self, entities: &[CadEntity<'_>], name: &str) -> Items {
        let mut curves = Vec::new();
        let mut open_shells = Vec::new();
        let mut solids = Vec::new();
        for (k, entity) in entities.iter().enumerate() {
            let item = format!("{name}_{k}");
            let (shell, closed) = match entity {
                CadEntity::Curve(c) => {
                    curves.push(self.curve(c, &item));
                    continue;
                }
                CadEntity::RationalCurve(c) => {
                    curves.push(self.rational_curve(c, &item));
                    continue;
                }
                CadEntity::Surface(s) => self.shell(&surface_shell(s), &item),
                CadEntity::Shell(shell) => self.shell(shell, &item),
                CadEntity::RationalSurface(s) => {
                    let face = self.rational_face(s, &item);
                    (self.add(format!("OPEN_SHELL('',({face}))")), false)
                }
            };
            if closed {
                solids.push(self.add(format!("MANIFOLD_SOLID_BREP('{item}',{shell})")));
            } else {
                open_shells.push(shell);
            }
        }
        Items {
            curves,
            open_shells,
            solids,
        }
    }

    /// One shape representation per kind of item, each bound to the product's shape.
    fn representations(
        &mut self,
        items: &Items,
        (name, shape, context, placement): (&str, &str, &str, &str),
    ) {
        let mut representations = Vec::new();
        if !items.curves.is_empty() {
            let set = self.add(format!(
                "GEOMETRIC_CURVE_SET('',({}))",
                items.curves.join(",")
            ));
            representations.push(self.add(format!(
                "GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION('{name}',({placement},{set}),{context})"
            )));
        }
        if !items.open_shells.is_empty() {
            let model = self.add(format!(
                "SHELL_BASED_SURFACE_MODEL('',({}))",
                items.open_shells.join(",")
            ));
            representations.push(self.add(format!(
                "MANIFOLD_SURFACE_SHAPE_REPRESENTATION('{name}',({placement},{model}),{context})"
            )));
        }
        if !items.solids.is_empty() {
            representations.push(self.add(format!(
                "ADVANCED_BREP_SHAPE_REPRESENTATION('{name}',({placement},{}),{context})",
                items.solids.join(",")
            )));
        }
        for r in representations {
            self.add(format!("SHAPE_DEFINITION_REPRESENTATION({shape},{r})"));
        }
    }
}

/// The exchange file: its header and the data section.
fn exchange_text(name: &str, data: &Data) -> String {
    let mut text = String::new();
    text.push_str("ISO-10303-21;\nHEADER;\n");
    text.push_str("FILE_DESCRIPTION(('karkas exact B-spline export'),'2;1');\n");
    let _ = writeln!(
        text,
        "FILE_NAME('{name}','{}',(''),(''),'karkas {}','karkas','');",
        FileStamp::now().iso8601(),
        env!("CARGO_PKG_VERSION")
    );
    text.push_str(
        "FILE_SCHEMA(('AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }'));\nENDSEC;\nDATA;\n",
    );
    for (k, line) in data.lines.iter().enumerate() {
        let _ = writeln!(text, "#{}={line};", k + 1);
    }
    text.push_str("ENDSEC;\nEND-ISO-10303-21;\n");
    text
}

/// Writes `entities` to the STEP file `path` (atomically; see
/// [`write_atomic`](crate::write::write_atomic)). The product is named after the file stem.
pub fn write_step(path: &Path, entities: &[CadEntity<'_>]) -> Result<(), IoError> {
    write_named(path, entities, step_text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Grid;

    fn curve() -> BSplineCurve<3> {
        BSplineCurve::new(
            2,
            vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0],
            vec![
                Point([0.0, 0.0, 0.0]),
                Point([1.0, 2.0, 0.0]),
                Point([2.0, -1.0, 0.5]),
                Point([3.0, 0.0, 1.0 / 3.0]),
            ],
        )
        .unwrap()
    }

    fn surface() -> BSplineSurface<3> {
        let grid = Grid::from_fn(3, 4, |i, j| {
            Point([i as f64, j as f64, (i * j) as f64 * 0.1])
        });
        BSplineSurface::new(
            (2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
            (3, vec![0.0, 0.0, 0.0, 0.0, 2.0, 2.0, 2.0, 2.0]),
            grid,
        )
        .unwrap()
    }

    /// The instances `#n=...;` of a STEP text, checking they are numbered 1, 2, 3, ...
    fn instances(text: &str) -> Vec<String> {
        let data = text
            .split("DATA;\n")
            .nth(1)
            .unwrap()
            .split("ENDSEC;")
            .next()
            .unwrap();
        data.lines()
            .enumerate()
            .map(|(k, line)| {
                let prefix = format!("#{}=", k + 1);
                assert!(line.starts_with(&prefix) && line.ends_with(';'), "{line}");
                line[prefix.len()..line.len() - 1].to_owned()
            })
            .collect()
    }

    #[test]
    fn curve_file_has_the_ap214_structure_and_exact_numbers() {
        let c = curve();
        let text = step_text(&[CadEntity::Curve(&c)], "wing's");
        assert!(text.starts_with("ISO-10303-21;\nHEADER;\n"));
        assert!(text.ends_with("ENDSEC;\nEND-ISO-10303-21;\n"));
        assert!(text.contains("AUTOMOTIVE_DESIGN { 1 0 10303 214 1 1 1 1 }"));
        assert!(text.contains("PRODUCT('wing''s','wing''s'"));
        let items = instances(&text);
        let bspline: Vec<&String> = items
            .iter()
            .filter(|l| l.starts_with("B_SPLINE_CURVE_WITH_KNOTS("))
            .collect();
        assert_eq!(bspline.len(), 1);
        assert!(bspline[0].contains(",2,(#"), "{}", bspline[0]);
        assert!(bspline[0]
            .contains("(3,1,3),(0.0000000000000000E0,5.0000000000000000E-1,1.0000000000000000E0)"));
        // Every reference points to an existing instance.
        for line in &items {
            for r in line.split('#').skip(1) {
                let n: usize = r
                    .chars()
                    .take_while(char::is_ascii_digit)
                    .collect::<String>()
                    .parse()
                    .unwrap();
                assert!(n >= 1 && n <= items.len(), "{line}");
            }
        }
        assert!(items
            .iter()
            .any(|l| l.starts_with("GEOMETRIC_CURVE_SET('',(#")));
        assert!(items
            .iter()
            .any(|l| l.starts_with("GEOMETRICALLY_BOUNDED_WIREFRAME_SHAPE_REPRESENTATION(")));
        // The control points read back exactly.
        let third = items
            .iter()
            .filter(|l| l.starts_with("CARTESIAN_POINT"))
            .nth(4)
            .unwrap();
        let coords: Vec<f64> = third
            .trim_start_matches("CARTESIAN_POINT('',(")
            .trim_end_matches("))")
            .split(',')
            .map(|x| x.parse().unwrap())
            .collect();
        assert_eq!(coords, vec![3.0, 0.0, 1.0 / 3.0]);
    }

    #[test]
    fn surface_file_is_a_bounded_face_in_an_open_shell() {
        let s = surface();
        let text = step_text(&[CadEntity::Surface(&s)], "s");
        let items = instances(&text);
        let surf: Vec<&String> = items
            .iter()
            .filter(|l| l.starts_with("B_SPLINE_SURFACE_WITH_KNOTS("))
            .collect();
        assert_eq!(surf.len(), 1);
        // 3 rows of 4 points, degrees 2 and 3, multiplicities and knots per direction.
        assert!(surf[0].starts_with("B_SPLINE_SURFACE_WITH_KNOTS('s_0',2,3,((#"));
        assert_eq!(surf[0].matches("),(#").count(), 2, "{}", surf[0]);
        assert!(surf[0].contains("(3,3),(4,4),(0.0000000000000000E0,1.0000000000000000E0),(0.0000000000000000E0,2.0000000000000000E0)"));
        let count = |prefix: &str| items.iter().filter(|l| l.starts_with(prefix)).count();
        assert_eq!(count("ADVANCED_FACE("), 1);
        assert_eq!(count("EDGE_CURVE("), 4);
        assert_eq!(count("ORIENTED_EDGE("), 4);
        assert_eq!(count("VERTEX_POINT("), 4);
        // Four 3-D sides and their four lines in the parameter plane.
        assert_eq!(count("B_SPLINE_CURVE_WITH_KNOTS("), 8);
        assert_eq!(count("B_SPLINE_CURVE_WITH_KNOTS('',1,"), 4);
        assert_eq!(count("SURFACE_CURVE('',#"), 4);
        assert_eq!(count("PCURVE('',#"), 4);
        assert_eq!(count("(GEOMETRIC_REPRESENTATION_CONTEXT(2)"), 1);
        assert_eq!(count("OPEN_SHELL("), 1);
        assert_eq!(count("SHELL_BASED_SURFACE_MODEL("), 1);
        assert_eq!(count("MANIFOLD_SURFACE_SHAPE_REPRESENTATION("), 1);
        assert_eq!(count("SHAPE_DEFINITION_REPRESENTATION("), 1);
    }

    #[test]
    fn files_are_written_whole() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("c.step");
        write_step(&path, &[CadEntity::Curve(&curve())]).unwrap();
        let text = std::fs::read_to_string(&path).unwrap();
        assert!(text.contains("PRODUCT('c','c'"));
    }
}

//! Reading CAD files: the geometry of STEP (ISO 10303-21 files of AP203, AP214 and AP242)
//! and IGES 5.3 files as a karkas [`Shape`] of rational B-spline faces
//! and curves.
//!
//! [`read_cad`] tells the format by the file's first bytes (`ISO-10303-21;`, or IGES's
//! 80-column records with the section letter in column 73) and returns a [`CadModel`]: the
//! shape, the file's length unit (coordinates are kept as written), and what was not read,
//! by entity type with counts and reasons ([`CadModel::warning`] puts it in one line). Lines,
//! conics and analytic surfaces become exact NURBS (`analytic.rs`, [`karkas::bspline::conic`],
//! [`karkas::bspline::sweep`]).
//!
//! Bad input never panics: a file that is not the format, truncated, with a reference to an
//! instance it does not define, a cycle of references, an entity with the wrong number or
//! kind of parameters, or more data than the memory cap is refused with an
//! [`IoError::Parse`] naming the line and the instance (STEP `#n` and its type; IGES the
//! directory entry and its type). A model whose control points leave the range of coordinates
//! karkas works with (`crate::range`: magnitudes up to 1e152) is refused as a whole.

mod analytic;
mod iges_build;
mod iges_plane;
mod iges_records;
mod model;
mod step_args;
mod step_cycles;
mod step_geometry;
mod step_read;
mod step_syntax;
mod step_topology;
mod step_units;

pub use model::{CadFormat, CadModel, LengthUnit, Unread};

use std::collections::BTreeMap;
use std::io::BufRead;
use std::path::Path;

use crate::error::{data_error, IoError};
use crate::input::{display_name, Input};
use crate::range::check_coordinate_range;
use karkas::shape::Shape;

/// Reads the CAD file `path` (STEP or IGES, told by its content).
///
/// Errors: the file cannot be opened, is neither format, or is malformed (see the module
/// docs).
pub fn read_cad(path: &Path) -> Result<CadModel, IoError> {
    let mut input = Input::open(path)?;
    let name = display_name(path);
    let format = sniff(&name, &mut input)?;
    read_cad_from(&name, format, &mut input)
}

/// Reads `path` as a CAD model when its first bytes are STEP or IGES ([`cad_format_of`]),
/// opening it once (so that a pipe such as `<(cat model.step)` or standard input, `-`, can be
/// read); `Ok(None)` when they are neither, so that the caller may say what else it expected.
///
/// Errors: the input cannot be opened or read, or it is a malformed model (as
/// [`read_cad`]).
pub fn read_cad_if_model(path: &Path) -> Result<Option<CadModel>, IoError> {
    let mut input = Input::open(path)?;
    let name = display_name(path);
    let head = input.fill_buf().map_err(IoError::open(&name))?;
    match cad_format_of(head) {
        Some(format) => read_cad_from(&name, format, &mut input).map(Some),
        None => Ok(None),
    }
}

/// Reads a CAD file of `format` from `reader`, named `name` in messages.
pub fn read_cad_from(
    name: &Path,
    format: CadFormat,
    reader: &mut dyn BufRead,
) -> Result<CadModel, IoError> {
    let model = match format {
        CadFormat::Step => step_read::read_step(name, reader)?,
        CadFormat::Iges => iges_build::read_iges(name, reader)?,
    };
    check_coordinate_range(model_coordinates(&model.shape), name)?;
    Ok(model)
}

/// Every coordinate of the control points of `shape`'s surfaces, trimming edges and free
/// curves.
fn model_coordinates(shape: &Shape) -> impl Iterator<Item = f64> + '_ {
    let surfaces = shape
        .faces
        .iter()
        .flat_map(|f| f.surface.control_points().as_slice());
    let edges = shape
        .faces
        .iter()
        .flat_map(|f| &f.loops)
        .flat_map(|l| &l.edges)
        .flat_map(|e| e.curve.control_points());
    let curves = shape.curves.iter().flat_map(|c| c.control_points());
    surfaces.chain(edges).chain(curves).flat_map(|p| p.0)
}

/// The CAD format the first bytes `head` of a file start (white space skipped): STEP's
/// `ISO-10303-21`, or IGES's first 80-column record with the section letter in column 73;
/// `None` for anything else.
pub fn cad_format_of(head: &[u8]) -> Option<CadFormat> {
    let start = head
        .iter()
        .position(|b| !b.is_ascii_whitespace())
        .unwrap_or(head.len());
    if head[start..].starts_with(b"ISO-10303-21") {
        return Some(CadFormat::Step);
    }
    // IGES: a first line of 72 columns of text and the section letter S in column 73.
    let line_end = head.iter().position(|&b| b == b'\n').unwrap_or(head.len());
    let line = head[..line_end]
        .strip_suffix(b"\r")
        .unwrap_or(&head[..line_end]);
    (line.len() >= 73 && (line[72] == b'S' || line[72] == b'G')).then_some(CadFormat::Iges)
}

/// Tells STEP from IGES by the first bytes ([`cad_format_of`]).
fn sniff(name: &Path, reader: &mut dyn BufRead) -> Result<CadFormat, IoError> {
    let head = reader.fill_buf().map_err(IoError::open(name))?;
    if let Some(format) = cad_format_of(head) {
        return Ok(format);
    }
    Err(data_error(
        name,
        "not a CAD file karkas reads: neither STEP (it would start with ISO-10303-21;) nor IGES \
         (80-column records with S in column 73)",
    ))
}

/// Counts of a model's items, for summaries: faces, curves, edges.
pub fn counts(model: &CadModel) -> BTreeMap<&'static str, usize> {
    let mut out = BTreeMap::new();
    out.insert("faces", model.shape.faces.len());
    out.insert("curves", model.shape.curves.len());
    out.insert(
        "edges",
        model
            .shape
            .faces
            .iter()
            .flat_map(|f| &f.loops)
            .map(|l| l.edges.len())
            .sum(),
    );
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::cad::CadEntity;
    use karkas::bspline::conic::elliptic_arc;
    use karkas::bspline::sweep::{sphere, Frame};
    use karkas::bspline::{NurbsCurve, NurbsSurface};
    use karkas::{Grid, Point3};

    fn read_text(text: &str, format: CadFormat) -> CadModel {
        let mut bytes = text.as_bytes();
        read_cad_from(Path::new("t"), format, &mut bytes).unwrap()
    }

    fn same_curve(a: &NurbsCurve<3>, b: &NurbsCurve<3>) {
        assert_eq!(a.degree(), b.degree());
        assert_eq!(a.knots(), b.knots());
        assert_eq!(a.weights(), b.weights());
        assert_eq!(a.control_points(), b.control_points());
    }

    fn same_surface(a: &NurbsSurface<3>, b: &NurbsSurface<3>) {
        assert_eq!((a.degree_u(), a.degree_v()), (b.degree_u(), b.degree_v()));
        assert_eq!(a.knots_u(), b.knots_u());
        assert_eq!(a.knots_v(), b.knots_v());
        assert_eq!(a.weights(), b.weights());
        assert_eq!(a.control_points(), b.control_points());
    }

    #[test]
    fn rational_curves_and_surfaces_read_back_bit_for_bit() {
        let f = Frame::new(
            Point3::new([0.1, -3.7, 1e-3]),
            Point3::new([0.2, 0.3, 1.0]),
            Point3::new([1.0, 0.0, 0.0]),
        )
        .unwrap();
        let arc = elliptic_arc(f.origin, f.x * 2.5, f.y * (1.0 / 3.0), (0.3, 5.1)).unwrap();
        let patch = sphere(&f, 7.0 / 3.0, (0.1, 4.0), (-1.2, 0.9)).unwrap();
        // A polynomial curve over unclamped knots, with weights all 2.
        let uniform = NurbsCurve::new(
            3,
            (0..10).map(|k| k as f64 * 0.7).collect(),
            (0..6)
                .map(|k| Point3::new([k as f64, (k * k) as f64 / 7.0, 0.0]))
                .collect(),
            vec![2.0; 6],
        )
        .unwrap();
        let weighted = NurbsSurface::new(
            (2, vec![0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0]),
            (1, vec![0.0, 0.0, 1.0, 1.0]),
            Grid::from_fn(4, 2, |i, j| {
                Point3::new([i as f64, j as f64, (i + j) as f64 / 9.0])
            }),
            Grid::from_fn(4, 2, |i, j| 0.5 + (i * 2 + j) as f64 / 7.0),
        )
        .unwrap();
        let entities = [
            CadEntity::RationalCurve(&arc),
            CadEntity::RationalCurve(&uniform),
            CadEntity::RationalSurface(&patch),
            CadEntity::RationalSurface(&weighted),
        ];
        for (format, text) in [
            (CadFormat::Step, crate::step::step_text(&entities, "n")),
            (CadFormat::Iges, crate::iges::iges_text(&entities, "n")),
        ] {
            let m = read_text(&text, format);
            assert!(m.warning().is_none(), "{:?}", m.warning());
            assert_eq!(m.shape.curves.len(), 2, "{format:?}");
            assert_eq!(m.shape.faces.len(), 2, "{format:?}");
            same_curve(&m.shape.curves[0], &arc);
            // Equal weights are written as a polynomial B-spline in STEP (weights 1).
            if format == CadFormat::Iges {
                same_curve(&m.shape.curves[1], &uniform);
            } else {
                assert_eq!(m.shape.curves[1].knots(), uniform.knots());
                assert_eq!(m.shape.curves[1].control_points(), uniform.control_points());
            }
            same_surface(&m.shape.faces[0].surface, &patch);
            same_surface(&m.shape.faces[1].surface, &weighted);
        }
    }

    #[test]
    fn a_written_face_whose_ends_fold_reads_back_whole() {
        // Like a whole hull's end sections: the sides u = 0 and u = 1 run down a line and
        // back up it. The file's edges carry their lines in the parameter plane, so the face
        // read back is the whole rectangle, near its folded sides too.
        let grid = Grid::from_fn(3, 3, |i, j| {
            let y = if i == 1 { 1.0 - j as f64 } else { 0.0 };
            Point3::new([i as f64, y, if j == 1 { -1.0 } else { 0.0 }])
        });
        let k = vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0];
        let s = karkas::bspline::BSplineSurface::new((2, k.clone()), (2, k), grid).unwrap();
        let text = crate::step::step_text(&[CadEntity::Surface(&s)], "fold");
        assert_eq!(text.matches("PCURVE(").count(), 4);
        let m = read_text(&text, CadFormat::Step);
        assert!(m.warning().is_none(), "{:?}", m.warning());
        let domain = karkas::shape::FaceDomain::of(&m.shape.faces[0]).unwrap();
        for (u, v) in [
            (1e-3, 0.25),
            (1e-3, 0.75),
            (0.999, 0.25),
            (0.999, 0.75),
            (0.5, 0.5),
        ] {
            assert!(domain.contains(u, v), "({u}, {v}) left out");
        }
    }

    /// `text` with its instance `from(...)` rewritten as `to(...)` keeping the first `keep`
    /// attributes (a subtype whose knots are implied drops the knot attributes).
    fn implied_form(text: &str, from: &str, to: &str, keep: usize) -> String {
        let start = text.find(&format!("{from}(")).unwrap();
        let open = start + from.len();
        let (mut depth, mut commas, mut cut, mut end) = (0, 0, None, None);
        for (k, c) in text[open..].char_indices() {
            match c {
                '(' => depth += 1,
                ')' => {
                    depth -= 1;
                    if depth == 0 {
                        end = Some(open + k);
                        break;
                    }
                }
                ',' if depth == 1 => {
                    commas += 1;
                    if commas == keep {
                        cut = Some(open + k);
                    }
                }
                _ => {}
            }
        }
        let (cut, end) = (cut.unwrap(), end.unwrap());
        format!("{}{to}{}{}", &text[..start], &text[open..cut], &text[end..])
    }

    #[test]
    fn bezier_uniform_and_quasi_uniform_forms_read_with_the_knots_they_imply() {
        // The knots ISO 10303-42 implies, written out: a Bezier curve of degree 3 in two
        // pieces, a uniform curve of degree 2 (knots from -2 by 1), a quasi-uniform surface of
        // degrees 2 x 1 and a Bezier surface of one piece each way.
        let pt = |k: usize, j: usize| {
            Point3::new([
                k as f64 * 0.75,
                (k * j + 1) as f64 / 3.0,
                (k * k) as f64 / 7.0 - j as f64,
            ])
        };
        let bezier = NurbsCurve::new(
            3,
            vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 2.0, 2.0, 2.0, 2.0],
            (0..7).map(|k| pt(k, 0)).collect(),
            vec![1.0; 7],
        )
        .unwrap();
        let uniform = NurbsCurve::new(
            2,
            (-2..=5).map(f64::from).collect(),
            (0..5).map(|k| pt(k, 1)).collect(),
            vec![1.0; 5],
        )
        .unwrap();
        let quasi = NurbsSurface::new(
            (2, vec![0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 3.0, 3.0]),
            (1, vec![0.0, 0.0, 1.0, 2.0, 3.0, 3.0]),
            Grid::from_fn(5, 4, pt),
            Grid::from_fn(5, 4, |_, _| 1.0),
        )
        .unwrap();
        let bezier_surface = NurbsSurface::new(
            (2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0]),
            (1, vec![0.0, 0.0, 1.0, 1.0]),
            Grid::from_fn(3, 2, pt),
            Grid::from_fn(3, 2, |_, _| 1.0),
        )
        .unwrap();
        let cases: [(CadEntity<'_>, &str); 4] = [
            (CadEntity::RationalCurve(&bezier), "BEZIER_CURVE"),
            (CadEntity::RationalCurve(&uniform), "UNIFORM_CURVE"),
            (CadEntity::RationalSurface(&quasi), "QUASI_UNIFORM_SURFACE"),
            (
                CadEntity::RationalSurface(&bezier_surface),
                "BEZIER_SURFACE",
            ),
        ];
        for (entity, subtype) in cases {
            let explicit = crate::step::step_text(&[entity], "n");
            let text = match entity {
                CadEntity::RationalCurve(_) => {
                    implied_form(&explicit, "B_SPLINE_CURVE_WITH_KNOTS", subtype, 6)
                }
                _ => implied_form(&explicit, "B_SPLINE_SURFACE_WITH_KNOTS", subtype, 8),
            };
            assert!(text.contains(&format!("{subtype}(")) && text.len() < explicit.len());
            let (a, b) = (
                read_text(&explicit, CadFormat::Step),
                read_text(&text, CadFormat::Step),
            );
            assert!(b.warning().is_none(), "{subtype}: {:?}", b.warning());
            match entity {
                CadEntity::RationalCurve(c) => {
                    same_curve(&b.shape.curves[0], c);
                    same_curve(&b.shape.curves[0], &a.shape.curves[0]);
                }
                CadEntity::RationalSurface(s) => {
                    same_surface(&b.shape.faces[0].surface, s);
                    same_surface(&b.shape.faces[0].surface, &a.shape.faces[0].surface);
                }
                _ => unreachable!(),
            }
        }
    }

    #[test]
    fn formats_are_told_by_content() {
        let mut step = "\n ISO-10303-21;".as_bytes();
        assert_eq!(sniff(Path::new("x"), &mut step).unwrap(), CadFormat::Step);
        let iges = format!("{:72}S      1\n", "");
        let mut bytes = iges.as_bytes();
        assert_eq!(sniff(Path::new("x"), &mut bytes).unwrap(), CadFormat::Iges);
        let mut other = "x,y\n1,2\n".as_bytes();
        assert!(sniff(Path::new("x"), &mut other)
            .unwrap_err()
            .to_string()
            .contains("not a CAD file"));
    }
}

#[cfg(test)]
mod conic_tests {
    use super::*;
    use karkas::{Curve, Point3};

    /// An IGES file of independent entities `(type, form, parameters without the type)`.
    fn iges(entities: &[(i64, i64, String)]) -> String {
        let line = |text: &str, letter: char, n: usize| format!("{text:72}{letter}{n:7}\n");
        let mut out = line("", 'S', 1);
        let global = "1H,,1H;,1Ht,1Ht,1Ht,1Ht,32,38,6,308,15,1Ht,1.,2,2HMM,1,0.01,\
                      15H20260101.000000,1E-07,10.,1Ht,,11,0,15H20260101.000000;";
        let globals: Vec<String> = global
            .as_bytes()
            .chunks(72)
            .map(|c| String::from_utf8_lossy(c).into_owned())
            .collect();
        for (k, g) in globals.iter().enumerate() {
            out += &line(g, 'G', k + 1);
        }
        let (mut directory, mut parameters) = (Vec::new(), Vec::new());
        for (k, (kind, form, params)) in entities.iter().enumerate() {
            let pointer = 2 * k + 1;
            let text = format!("{kind},{params};");
            let start = parameters.len() + 1;
            let mut rest = text.as_str();
            while !rest.is_empty() {
                let cut = if rest.len() <= 64 {
                    rest.len()
                } else {
                    rest[..64].rfind(',').map_or(64, |i| i + 1)
                };
                parameters.push(format!("{:64} {pointer:7}", &rest[..cut]));
                rest = &rest[cut..];
            }
            let count = parameters.len() + 1 - start;
            directory.push(format!(
                "{kind:8}{start:8}{:8}{:8}{:8}{:8}{:8}{:8}00000000",
                0, 0, 0, 0, 0, 0
            ));
            directory.push(format!("{kind:8}{:8}{:8}{count:8}{form:8}", 0, 0));
        }
        for (k, d) in directory.iter().enumerate() {
            out += &line(d, 'D', k + 1);
        }
        for (k, p) in parameters.iter().enumerate() {
            out += &line(p, 'P', k + 1);
        }
        let tail = format!(
            "S{:7}G{:7}D{:7}P{:7}",
            1,
            globals.len(),
            directory.len(),
            parameters.len()
        );
        out + &line(&tail, 'T', 1)
    }

    #[test]
    fn an_elliptic_arc_of_general_coefficients_is_read_exactly_and_counter_clockwise() {
        for scale in [1.0, 1e-150, 1e150] {
            elliptic_arc_at(scale);
        }
    }

    /// The elliptic arc of the test above with every length times `scale`.
    fn elliptic_arc_at(scale: f64) {
        // Centre (2, -1), semi-axes 3 and 1, the first turned 30 degrees, in z = 1.5; the arc
        // from angle 0.3 to 2.0 about the centre's frame.
        let (x0, y0, a, b, turn) = (2.0 * scale, -scale, 3.0 * scale, scale, 30f64.to_radians());
        let zt = 1.5 * scale;
        let (c, s) = (turn.cos(), turn.sin());
        let qa = c * c / (a * a) + s * s / (b * b);
        let qb = 2.0 * c * s * (1.0 / (a * a) - 1.0 / (b * b));
        let qc = s * s / (a * a) + c * c / (b * b);
        let qd = -2.0 * qa * x0 - qb * y0;
        let qe = -qb * x0 - 2.0 * qc * y0;
        let qf = qa * x0 * x0 + qb * x0 * y0 + qc * y0 * y0 - 1.0;
        let at = |t: f64| {
            let (u, v) = (a * t.cos(), b * t.sin());
            [x0 + c * u - s * v, y0 + s * u + c * v]
        };
        let (p, q, middle) = (at(0.3), at(2.0), at(1.15));
        let params = format!(
            "{qa:?},{qb:?},{qc:?},{qd:?},{qe:?},{qf:?},{zt:?},{:?},{:?},{:?},{:?}",
            p[0], p[1], q[0], q[1]
        );
        // The same coefficients times -2 are the same ellipse.
        let negated: Vec<String> = [qa, qb, qc, qd, qe, qf]
            .iter()
            .map(|x| format!("{:?}", -2.0 * x))
            .collect();
        let negated = format!(
            "{},{zt:?},{:?},{:?},{:?},{:?}",
            negated.join(","),
            p[0],
            p[1],
            q[0],
            q[1]
        );
        for text in [params, negated] {
            let model = read_cad_from(
                Path::new("e.igs"),
                CadFormat::Iges,
                &mut iges(&[(104, 1, text)]).as_bytes(),
            )
            .unwrap();
            assert!(model.warning().is_none(), "{:?}", model.warning());
            let curve = &model.shape.curves[0];
            let d = curve.domain();
            let ends = [curve.eval(d.start), curve.eval(d.end)];
            assert!(
                ends[0].distance(Point3::new([p[0], p[1], zt])) < 1e-12 * scale,
                "{ends:?}"
            );
            assert!(
                ends[1].distance(Point3::new([q[0], q[1], zt])) < 1e-12 * scale,
                "{ends:?}"
            );
            let mut passes_middle = false;
            for k in 0..=200 {
                let r = curve.eval(d.uniform(k, 201));
                let (x, y) = (r[0], r[1]);
                let value = qa * x * x + qb * x * y + qc * y * y + qd * x + qe * y + qf;
                assert!(
                    value.abs() < 1e-12 && (r[2] - zt).abs() <= 1e-15 * scale,
                    "{r:?}"
                );
                passes_middle |= r.distance(Point3::new([middle[0], middle[1], zt])) < 0.05 * scale;
            }
            // Counter-clockwise from p to q: through the point at angle 1.15, not the
            // other way round the ellipse.
            assert!(passes_middle);
        }
    }

    #[test]
    fn other_conics_are_named_as_not_read_and_a_false_ellipse_is_refused() {
        let hyperbola = "1.,0.,-1.,0.,0.,-1.,0.,1.,0.,2.,1.7320508075688772".to_string();
        let model = read_cad_from(
            Path::new("h.igs"),
            CadFormat::Iges,
            &mut iges(&[(104, 2, hyperbola.clone())]).as_bytes(),
        )
        .unwrap();
        let warning = model.warning().unwrap_or_default();
        assert!(
            warning.contains("entity 104 (conic arc) form 2"),
            "{warning}"
        );
        // Form 1 (ellipse) with a hyperbola's coefficients: an error naming the entry.
        let error = read_cad_from(
            Path::new("h.igs"),
            CadFormat::Iges,
            &mut iges(&[(104, 1, hyperbola)]).as_bytes(),
        )
        .unwrap_err()
        .to_string();
        assert!(
            error.contains("not an ellipse") && error.contains("h.igs"),
            "{error}"
        );
    }
}

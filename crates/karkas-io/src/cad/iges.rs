//! IGES 5.3 files of exact B-spline curves (entity 126) and surfaces (entity 128), and the
//! faces of shells: B-spline faces (128) and planar caps as trimmed surfaces (144 over a
//! planar 128, trimmed by a curve on it, 142, made of the cap's edges, 102 of 126).
//!
//! Fixed 80-column records: Start (`S`), Global (`G`), Directory Entry (`D`, two lines per
//! entity), Parameter Data (`P`, data in columns 1–64, the entity's directory pointer in
//! 66–72) and Terminate (`T`), each line numbered in columns 74–80. Entities are
//! non-rational (all weights 1, `PROP3 = 1`) and not periodic; a closed karkas curve or
//! surface direction is written clamped over one period with its closed flag set. Rational
//! curves and surfaces carry their weights (`PROP3 = 0`) and knots as they are. Units:
//! millimetres (flag 2). Reals carry 17 significant digits. Surfaces are untrimmed (the
//! whole parameter rectangle).
//!
//! Hand-written: no maintained Rust crate writes IGES without a whole CAD kernel.

use crate::cad::units::LengthUnit;
use std::fmt::Write as _;
use std::path::Path;

use karkas::bspline::{BSplineCurve, BSplineSurface, NurbsCurve, NurbsSurface};
use karkas::geometry::{cross, Plane};
use karkas::{Curve, Grid, Point3, Surface};

use crate::cad::entity::{
    curve_closed, max_coordinate, real, surface_closed, write_named, CadEntity,
};
use crate::cad::shell::{CadShell, FaceSurface, ShellFace};
use crate::cad::time_stamp::FileStamp;
use crate::error::IoError;

/// Columns of data in a parameter line.
const P_WIDTH: usize = 64;
/// Columns of data in a global or start line.
const G_WIDTH: usize = 72;

/// One IGES entity: its type number, parameters (type number first), whether it is
/// physically dependent on another (a part of a trimmed surface), and its label.
struct Record {
    kind: u32,
    fields: Vec<String>,
    dependent: bool,
}

impl Record {
    fn label(&self) -> &'static str {
        match self.kind {
            126 => "BSCURVE",
            128 => "BSSURF",
            102 => "CCURVE",
            142 => "CRVONSRF",
            _ => "TRMSURF",
        }
    }
}

/// The records of `entities`, in order.
fn records(entities: &[CadEntity<'_>]) -> Vec<Record> {
    let mut out = Vec::new();
    for entity in entities {
        match entity {
            CadEntity::Curve(c) => out.push(Record {
                kind: 126,
                fields: curve_parameters(c),
                dependent: false,
            }),
            CadEntity::Surface(s) => out.push(Record {
                kind: 128,
                fields: surface_parameters(s),
                dependent: false,
            }),
            CadEntity::RationalCurve(c) => out.push(Record {
                kind: 126,
                fields: rational_curve_parameters(c),
                dependent: false,
            }),
            CadEntity::RationalSurface(s) => out.push(Record {
                kind: 128,
                fields: rational_surface_parameters(s),
                dependent: false,
            }),
            CadEntity::Shell(shell) => shell_records(shell, &mut out),
        }
    }
    out
}

/// The directory pointer of the record of index `k`.
fn pointer(k: usize) -> String {
    (2 * k + 1).to_string()
}

/// The faces of `shell`: each B-spline face an untrimmed surface (entity 128, which readers
/// bound by its parameter rectangle, with its poles and seams), each planar cap a trimmed
/// surface (entity 144): a planar B-spline patch (128) covering the cap, trimmed by its
/// boundary loop (142, the loop's edges as one composite curve, 102, of entities 126 in
/// model space).
fn shell_records(shell: &CadShell, out: &mut Vec<Record>) {
    for face in shell.faces() {
        let plane = match &face.surface {
            FaceSurface::BSpline(s) => {
                out.push(Record {
                    kind: 128,
                    fields: surface_parameters(s),
                    dependent: false,
                });
                continue;
            }
            FaceSurface::Plane(plane) => *plane,
        };
        let curves: Vec<BSplineCurve<3>> = face
            .bound
            .iter()
            .map(|o| {
                let curve = &shell.edges()[o.edge].curve;
                if o.forward {
                    curve.clone()
                } else {
                    reversed(curve)
                }
            })
            .collect();
        if let Some(patch) = cap_patch(&plane, face, &curves) {
            trimmed_cap_records(&patch, &curves, out);
        }
    }
}

/// The patch of a planar cap: the bounding rectangle of its loop `curves` in the plane's
/// axes, widened by a hundredth, its normal the face's.
fn cap_patch(
    plane: &Plane,
    face: &ShellFace,
    curves: &[BSplineCurve<3>],
) -> Option<BSplineSurface<3>> {
    let x = plane.x_axis();
    let normal = if face.same_sense {
        plane.normal
    } else {
        -plane.normal
    };
    let y = cross(normal, x);
    let (mut low, mut high) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in curves.iter().flat_map(|c| c.control_points()) {
        let d = *p - plane.origin;
        for (c, axis) in [x, y].iter().enumerate() {
            low[c] = low[c].min(d.dot(*axis));
            high[c] = high[c].max(d.dot(*axis));
        }
    }
    let margin = 0.01 * (high[0] - low[0]).max(high[1] - low[1]);
    let grid = Grid::from_fn(2, 2, |i, j| {
        let a = if i == 0 {
            low[0] - margin
        } else {
            high[0] + margin
        };
        let b = if j == 0 {
            low[1] - margin
        } else {
            high[1] + margin
        };
        plane.origin + x * a + y * b
    });
    BSplineSurface::new(
        (1, vec![0.0, 0.0, 1.0, 1.0]),
        (1, vec![0.0, 0.0, 1.0, 1.0]),
        grid,
    )
    .ok()
}

/// The records of a planar cap: its patch (128), its boundary `curves` (126, joined by a
/// composite curve, 102, when more than one), the curve on the patch (142) and the trimmed
/// surface (144).
fn trimmed_cap_records(
    patch: &BSplineSurface<3>,
    curves: &[BSplineCurve<3>],
    out: &mut Vec<Record>,
) {
    let surface = out.len();
    out.push(Record {
        kind: 128,
        fields: surface_parameters(patch),
        dependent: true,
    });
    let mut pieces = Vec::new();
    for c in curves {
        pieces.push(pointer(out.len()));
        out.push(Record {
            kind: 126,
            fields: curve_parameters(c),
            dependent: true,
        });
    }
    let boundary = if pieces.len() == 1 {
        pieces[0].clone()
    } else {
        let mut fields = vec!["102".to_owned(), pieces.len().to_string()];
        fields.extend(pieces);
        out.push(Record {
            kind: 102,
            fields,
            dependent: true,
        });
        pointer(out.len() - 1)
    };
    // Curve on a surface: unspecified creation, the plane, no parameter-space curve, the
    // model-space curve, which is preferred.
    out.push(Record {
        kind: 142,
        fields: vec![
            "142".into(),
            "0".into(),
            pointer(surface),
            "0".into(),
            boundary,
            "2".into(),
        ],
        dependent: true,
    });
    let on_surface = pointer(out.len() - 1);
    out.push(Record {
        kind: 144,
        fields: vec![
            "144".into(),
            pointer(surface),
            "1".into(),
            "0".into(),
            on_surface,
        ],
        dependent: false,
    });
}

/// The curve `c` run backwards over the same domain.
fn reversed(c: &BSplineCurve<3>) -> BSplineCurve<3> {
    let (a, b) = (c.knots()[0], c.knots()[c.knots().len() - 1]);
    let knots: Vec<f64> = c.knots().iter().rev().map(|&k| a + b - k).collect();
    let control: Vec<Point3> = c.control_points().iter().rev().copied().collect();
    BSplineCurve::new(c.degree(), knots, control).unwrap_or_else(|_| c.clone())
}

/// Entity 126 of a rational curve: its weights, `PROP3 = 0` unless they are all equal.
fn rational_curve_parameters(c: &NurbsCurve<3>) -> Vec<String> {
    let n = c.control_points().len();
    let planar = c.control_points().iter().all(|p| p[2] == 0.0);
    let d = c.domain();
    let mut p = vec![
        "126".to_owned(),
        (n - 1).to_string(),
        c.degree().to_string(),
        u8::from(planar).to_string(),
        u8::from(c.is_closed()).to_string(),
        u8::from(!c.is_rational()).to_string(),
        "0".to_owned(),
    ];
    p.extend(c.knots().iter().map(|&k| real(k)));
    p.extend(c.weights().iter().map(|&w| real(w)));
    for q in c.control_points() {
        p.extend([real(q[0]), real(q[1]), real(q[2])]);
    }
    p.extend([real(d.start), real(d.end)]);
    let normal = if planar { [0.0, 0.0, 1.0] } else { [0.0; 3] };
    p.extend(normal.iter().map(|&x| real(x)));
    p
}

/// Entity 128 of a rational surface: its weights (first index fastest), `PROP3 = 0` unless
/// they are all equal.
fn rational_surface_parameters(s: &NurbsSurface<3>) -> Vec<String> {
    let grid = s.control_points();
    let (rows, cols) = (grid.rows(), grid.cols());
    let (du, dv) = (s.domain_u(), s.domain_v());
    let mut p = vec![
        "128".to_owned(),
        (rows - 1).to_string(),
        (cols - 1).to_string(),
        s.degree_u().to_string(),
        s.degree_v().to_string(),
        u8::from(s.is_closed_u()).to_string(),
        u8::from(s.is_closed_v()).to_string(),
        u8::from(!s.is_rational()).to_string(),
        "0".to_owned(),
        "0".to_owned(),
    ];
    p.extend(s.knots_u().iter().map(|&k| real(k)));
    p.extend(s.knots_v().iter().map(|&k| real(k)));
    for j in 0..cols {
        for i in 0..rows {
            p.push(real(*s.weights().get(i, j)));
        }
    }
    for j in 0..cols {
        for i in 0..rows {
            let q = grid.get(i, j);
            p.extend([real(q[0]), real(q[1]), real(q[2])]);
        }
    }
    p.extend([real(du.start), real(du.end), real(dv.start), real(dv.end)]);
    p
}

/// Entity 126 of a polynomial curve: unit weights, so `PROP3 = 1`; closed as
/// [`curve_closed`] tells.
fn curve_parameters(c: &BSplineCurve<3>) -> Vec<String> {
    rational_curve_parameters(&NurbsCurve::from_bspline(c).with_closed(curve_closed(c)))
}

/// Entity 128 of a polynomial surface: unit weights, so `PROP3 = 1`; closed as
/// [`surface_closed`] tells.
fn surface_parameters(s: &BSplineSurface<3>) -> Vec<String> {
    let (closed_u, closed_v) = surface_closed(s);
    rational_surface_parameters(&NurbsSurface::from_bspline(s).with_closed(closed_u, closed_v))
}

/// A Hollerith string `nHtext`.
fn hollerith(text: &str) -> String {
    let text: String = text
        .chars()
        .filter(|c| c.is_ascii() && !c.is_ascii_control())
        .collect();
    format!("{}H{text}", text.len())
}

/// Packs delimited `fields` (each followed by `,` and the last by `;`) into lines of at most
/// `width` columns, never splitting a field (a Hollerith string longer than a line is
/// split, as the standard allows for strings).
fn pack(fields: &[String], width: usize) -> Vec<String> {
    let mut lines = Vec::new();
    let mut line = String::new();
    for (k, field) in fields.iter().enumerate() {
        let delimiter = if k + 1 == fields.len() { ';' } else { ',' };
        let token = format!("{field}{delimiter}");
        if line.len() + token.len() > width && !line.is_empty() {
            lines.push(std::mem::take(&mut line));
        }
        let mut rest = token.as_str();
        while rest.len() > width {
            let (head, tail) = rest.split_at(width - line.len());
            line.push_str(head);
            lines.push(std::mem::take(&mut line));
            rest = tail;
        }
        line.push_str(rest);
    }
    if !line.is_empty() {
        lines.push(line);
    }
    lines
}

/// One 80-column line: `data` padded to 72 columns, the section letter, the sequence number.
fn record(text: &mut String, data: &str, section: char, number: usize) {
    let _ = writeln!(text, "{data:<72}{section}{number:>7}");
}

/// The text of an IGES file holding `entities`, named `name`, lengths in millimetres.
pub fn iges_text(entities: &[CadEntity<'_>], name: &str) -> String {
    iges_text_in(entities, name, LengthUnit::Millimetre)
}

/// [`iges_text`] with the length unit `unit` ([`crate::cad::units`]).
pub fn iges_text_in(entities: &[CadEntity<'_>], name: &str, unit: LengthUnit) -> String {
    let mut text = String::new();
    let start = [format!("karkas exact B-spline export: {name}")];
    for (k, line) in start.iter().enumerate() {
        let line: String = line.chars().filter(char::is_ascii).take(G_WIDTH).collect();
        record(&mut text, &line, 'S', k + 1);
    }
    let global_lines = pack(&global_parameters(entities, name, unit), G_WIDTH);
    for (k, line) in global_lines.iter().enumerate() {
        record(&mut text, line, 'G', k + 1);
    }
    let (directory, parameter_lines) = directory_and_parameters(entities);
    for (k, [a, b]) in directory.iter().enumerate() {
        record(&mut text, a, 'D', 2 * k + 1);
        record(&mut text, b, 'D', 2 * k + 2);
    }
    for (k, (line, de)) in parameter_lines.iter().enumerate() {
        let data = format!("{line:<64} {de:>7}");
        record(&mut text, &data, 'P', k + 1);
    }
    let terminate = format!(
        "S{:>7}G{:>7}D{:>7}P{:>7}",
        start.len(),
        global_lines.len(),
        2 * directory.len(),
        parameter_lines.len()
    );
    record(&mut text, &terminate, 'T', 1);
    text
}

/// The global section's parameters: delimiters, names, precision, unit, date, resolution
/// and the largest coordinate.
fn global_parameters(entities: &[CadEntity<'_>], name: &str, unit: LengthUnit) -> [String; 25] {
    let stamp = FileStamp::now().iges();
    [
        "1H,".to_owned(),
        "1H;".to_owned(),
        hollerith("karkas"),
        hollerith(&format!("{name}.igs")),
        hollerith("karkas"),
        hollerith(env!("CARGO_PKG_VERSION")),
        "32".to_owned(),
        "38".to_owned(),
        "6".to_owned(),
        "308".to_owned(),
        "15".to_owned(),
        hollerith("karkas"),
        real(1.0),
        unit.iges().0.to_string(),
        hollerith(unit.iges().1),
        "1".to_owned(),
        real(1.0),
        hollerith(&stamp),
        real(1e-9),
        real(max_coordinate(entities)),
        hollerith(""),
        hollerith(""),
        "11".to_owned(),
        "0".to_owned(),
        hollerith(&stamp),
    ]
}

/// The directory entries (two lines each) of every entity, and the parameter lines they
/// point at, each with its entry's pointer.
fn directory_and_parameters(
    entities: &[CadEntity<'_>],
) -> (Vec<[String; 2]>, Vec<(String, usize)>) {
    let mut parameter_lines: Vec<(String, usize)> = Vec::new();
    let mut directory: Vec<[String; 2]> = Vec::new();
    for (k, entity) in records(entities).iter().enumerate() {
        let de = 2 * k + 1;
        let kind = entity.kind;
        let lines = pack(&entity.fields, P_WIDTH);
        let first = parameter_lines.len() + 1;
        let count = lines.len();
        parameter_lines.extend(lines.into_iter().map(|l| (l, de)));
        let label = entity.label();
        let status = if entity.dependent {
            "00010000"
        } else {
            "00000000"
        };
        directory.push([
            format!(
                "{kind:>8}{first:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{:>8}{status:>8}",
                0, 0, 0, 0, 0, 0
            ),
            format!(
                "{kind:>8}{:>8}{:>8}{count:>8}{:>8}{:>8}{:>8}{label:>8}{:>8}",
                0,
                0,
                0,
                "",
                "",
                k + 1
            ),
        ]);
    }
    (directory, parameter_lines)
}

/// Writes `entities` to the IGES file `path` (atomically; see
/// [`write_atomic`](crate::write::write_atomic)).
pub fn write_iges(path: &Path, entities: &[CadEntity<'_>]) -> Result<(), IoError> {
    write_named(path, entities, iges_text)
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::Point;

    fn curve() -> BSplineCurve<3> {
        BSplineCurve::new(
            3,
            vec![0.0, 0.0, 0.0, 0.0, 0.25, 0.25, 1.0, 1.0, 1.0, 1.0],
            (0..6)
                .map(|i| Point([i as f64, (i * i) as f64 / 7.0, -(i as f64) / 3.0]))
                .collect(),
        )
        .unwrap()
    }

    fn surface() -> BSplineSurface<3> {
        let grid = Grid::from_fn(4, 3, |i, j| {
            Point([i as f64 * 1.5, j as f64, (i + j) as f64 / 9.0])
        });
        BSplineSurface::new(
            (3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0]),
            (2, vec![-1.0, -1.0, -1.0, 1.0, 1.0, 1.0]),
            grid,
        )
        .unwrap()
    }

    /// The lines of each section, checking the 80-column layout and the numbering.
    fn sections(text: &str) -> std::collections::BTreeMap<char, Vec<String>> {
        let mut out: std::collections::BTreeMap<char, Vec<String>> = Default::default();
        for line in text.lines() {
            assert_eq!(line.len(), 80, "{line:?}");
            let section = line.as_bytes()[72] as char;
            let number: usize = line[73..].trim().parse().unwrap();
            let list = out.entry(section).or_default();
            assert_eq!(number, list.len() + 1, "{line}");
            list.push(line[..72].to_owned());
        }
        out
    }

    /// The parameters of the entity whose data lines are `lines`.
    fn fields(lines: &[String]) -> Vec<String> {
        let data: String = lines.iter().map(|l| l[..64].trim_end()).collect();
        data.trim_end_matches(';')
            .split(',')
            .map(str::to_owned)
            .collect()
    }

    #[test]
    fn curve_file_has_all_sections_and_entity_126() {
        let c = curve();
        let text = iges_text(&[CadEntity::Curve(&c)], "c");
        let s = sections(&text);
        assert_eq!(s.keys().collect::<String>(), "DGPST");
        let t = &s[&'T'][0];
        assert_eq!(
            t.trim_end(),
            format!("S      1G{:>7}D      2P{:>7}", s[&'G'].len(), s[&'P'].len())
        );
        let d = &s[&'D'];
        assert_eq!(&d[0][..8], "     126");
        assert_eq!(d[0][8..16].trim(), "1"); // first parameter line
        assert_eq!(d[1][24..32].trim(), s[&'P'].len().to_string());
        for p in &s[&'P'] {
            assert_eq!(p[65..72].trim(), "1"); // back-pointer to the directory entry
        }
        let f = fields(&s[&'P']);
        assert_eq!(&f[..7], ["126", "5", "3", "0", "0", "1", "0"]);
        // 10 knots, 6 weights, 18 coordinates, 2 parameters, 3 normal components.
        assert_eq!(f.len(), 7 + 10 + 6 + 18 + 2 + 3);
        let knots: Vec<f64> = f[7..17].iter().map(|x| x.parse().unwrap()).collect();
        assert_eq!(knots, c.knots());
        let coords: Vec<f64> = f[23..41].iter().map(|x| x.parse().unwrap()).collect();
        for (k, p) in c.control_points().iter().enumerate() {
            assert_eq!(&coords[3 * k..3 * k + 3], &p.0[..]);
        }
        let g: String = s[&'G'].iter().map(|l| l.trim_end()).collect();
        assert!(g.starts_with("1H,,1H;,6Hkarkas,5Hc.igs,"), "{g}");
    }

    #[test]
    fn surface_entity_128_lists_u_fastest() {
        let srf = surface();
        let text = iges_text(&[CadEntity::Curve(&curve()), CadEntity::Surface(&srf)], "s");
        let s = sections(&text);
        let d = &s[&'D'];
        assert_eq!(d.len(), 4);
        assert_eq!(&d[2][..8], "     128");
        let first: usize = d[2][8..16].trim().parse().unwrap();
        let lines: Vec<String> = s[&'P']
            .iter()
            .filter(|l| l[65..72].trim() == "3")
            .cloned()
            .collect();
        assert_eq!(first, s[&'P'].len() - lines.len() + 1);
        let f = fields(&lines);
        assert_eq!(
            &f[..10],
            ["128", "3", "2", "3", "2", "0", "0", "1", "0", "0"]
        );
        let (nku, nkv, nw) = (8, 6, 12);
        let start = 10 + nku + nkv + nw;
        let coords: Vec<f64> = f[start..start + 36]
            .iter()
            .map(|x| x.parse().unwrap())
            .collect();
        // Control point (i, j) at index i + 4 j.
        for j in 0..3 {
            for i in 0..4 {
                let k = 3 * (i + 4 * j);
                assert_eq!(&coords[k..k + 3], &srf.control_points().get(i, j).0[..]);
            }
        }
        let tail: Vec<f64> = f[start + 36..].iter().map(|x| x.parse().unwrap()).collect();
        assert_eq!(tail, vec![0.0, 1.0, -1.0, 1.0]);
    }

    #[test]
    fn long_fields_never_cross_a_line() {
        let fields: Vec<String> = (0..50).map(|k| real(k as f64 / 7.0)).collect();
        let lines = pack(&fields, P_WIDTH);
        let rejoined: String = lines.concat();
        assert_eq!(rejoined.split(',').count(), 50);
        assert!(lines.iter().all(|l| l.len() <= P_WIDTH));
        assert!(lines.iter().all(|l| l.ends_with(',') || l.ends_with(';')));
    }
}

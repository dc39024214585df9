//! A B-spline curve and its input points as an ASCII DXF drawing (AutoCAD R2000, `AC1015`,
//! the first version read by every current CAD and CAM program that has the SPLINE entity of
//! R13): the curve as one exact non-rational SPLINE (degree, knot vector, control points) on
//! layer `CURVE`, the input points as POINT entities on layer `POINTS`.
//!
//! The drawing holds what a DXF R13-or-later file needs to open in AutoCAD and in readers that
//! check the structure (ezdxf's documentation, "Minimal DXF Content"): the header with
//! `$ACADVER` and `$HANDSEED` (and the extents, so that viewers open zoomed on the curve), an
//! empty CLASSES section, the nine symbol tables with their required records (line types
//! ByBlock, ByLayer and Continuous, the layers, text and dimension style Standard, the
//! application ACAD, the block records of model and paper space), the two layout blocks, the
//! entities in model space, and the root dictionary with its ACAD_GROUP dictionary.
//!
//! A closed karkas curve is written as B-spline form gives it: one period as a clamped curve
//! whose ends coincide, with the closed flag (70: 1) and without the periodic flag (70: 2),
//! which DXF keeps for unclamped periodic knot vectors. Planar curves (two coordinates) lie in
//! `z = 0` with the planar flag (70: 8) and the normal (0, 0, 1); curves in space keep `z`.
//!
//! Every real is written as the shortest decimal that reads back as the same `f64` (Rust's
//! round-trip formatting, an exponent only for very small or large magnitudes), so that the
//! file gives the curve to the last bit. The knot and control point tolerances (groups 42 and
//! 43) are the values' own rounding level (machine epsilon times their magnitude) rather than
//! the customary 1e-10: readers round the knots to that tolerance before they evaluate
//! (ezdxf's construction tool keeps `-log10(tolerance)` decimals), and 1e-10 would move the
//! curve by about 1e-10 of its size.
//!
//! Hand-written because the DXF crate of crates.io (`dxf`) writes reals with at most twelve
//! decimals after the point (`{:.12}`, so 1e-13 becomes 0 and a 1e-12 relative agreement is
//! lost on small curves) and brings `image`, `chrono`, `uuid` and `num` along; the subset
//! needed here is a few hundred lines of group codes.

use crate::cad::units::LengthUnit;
use karkas::bspline::BSplineCurve;
use karkas::Point3;
use std::fmt::Write as _;

use crate::error::IoError;
use crate::write::write_atomic;

/// The layer of the SPLINE entity.
pub const CURVE_LAYER: &str = "CURVE";
/// The layer of the POINT entities (the input points).
pub const POINTS_LAYER: &str = "POINTS";

/// What a DXF drawing of a curve holds.
#[derive(Clone, Copy, Debug)]
pub struct DxfCurve<'a> {
    /// The curve in space (a planar curve in `z = 0`).
    pub spline: &'a BSplineCurve<3>,
    /// True when the curve is closed (its ends coincide): the SPLINE's closed flag.
    pub closed: bool,
    /// True for a curve of the plane `z = 0`: the SPLINE's planar flag and normal.
    pub planar: bool,
    /// The input points, written as POINT entities on [`POINTS_LAYER`].
    pub points: &'a [Point3],
}

/// Writes `curve` as a DXF drawing at `path`, atomically.
pub fn write_dxf(path: &std::path::Path, curve: &DxfCurve<'_>) -> Result<(), IoError> {
    let text = dxf_text(curve);
    write_atomic(path, |out| out.write_all(text.as_bytes()))
}

/// The handles of the fixed objects of the drawing (hexadecimal in the file).
mod handle {
    pub const BLOCK_RECORD_TABLE: u32 = 0x1;
    pub const LAYER_TABLE: u32 = 0x2;
    pub const STYLE_TABLE: u32 = 0x3;
    pub const LTYPE_TABLE: u32 = 0x5;
    pub const VIEW_TABLE: u32 = 0x6;
    pub const UCS_TABLE: u32 = 0x7;
    pub const VPORT_TABLE: u32 = 0x8;
    pub const APPID_TABLE: u32 = 0x9;
    pub const DIMSTYLE_TABLE: u32 = 0xA;
    pub const ROOT_DICTIONARY: u32 = 0xC;
    pub const GROUP_DICTIONARY: u32 = 0xD;
    pub const LAYERS: [u32; 3] = [0x10, 0x11, 0x12];
    pub const APPID_ACAD: u32 = 0x13;
    pub const LTYPES: [u32; 3] = [0x14, 0x15, 0x16];
    pub const STYLE_STANDARD: u32 = 0x17;
    pub const DIMSTYLE_STANDARD: u32 = 0x18;
    pub const VPORT_ACTIVE: u32 = 0x19;
    pub const MODEL_SPACE_RECORD: u32 = 0x1A;
    pub const PAPER_SPACE_RECORD: u32 = 0x1B;
    pub const MODEL_SPACE_BLOCK: [u32; 2] = [0x1C, 0x1D];
    pub const PAPER_SPACE_BLOCK: [u32; 2] = [0x1E, 0x1F];
    /// The first handle of the entities.
    pub const FIRST_ENTITY: u32 = 0x100;
}

/// The text of the DXF drawing of `curve`, without a unit (`$INSUNITS 0`).
pub fn dxf_text(curve: &DxfCurve<'_>) -> String {
    dxf_text_in(curve, None)
}

/// [`dxf_text`] stating the length unit `unit` in `$INSUNITS` ([`crate::cad::units`]).
pub fn dxf_text_in(curve: &DxfCurve<'_>, unit: Option<LengthUnit>) -> String {
    let mut dxf = Dxf::default();
    let (low, high) = extents(curve);
    let entity_count = 1 + curve.points.len() as u32;
    let units = unit.map_or(0, LengthUnit::dxf);
    dxf.header(low, high, handle::FIRST_ENTITY + entity_count, units);
    dxf.pair(0, "SECTION");
    dxf.pair(2, "CLASSES");
    dxf.pair(0, "ENDSEC");
    dxf.tables(low, high);
    dxf.blocks();
    dxf.pair(0, "SECTION");
    dxf.pair(2, "ENTITIES");
    dxf.spline(curve, handle::FIRST_ENTITY);
    for (k, p) in curve.points.iter().enumerate() {
        dxf.point_entity(p, handle::FIRST_ENTITY + 1 + k as u32);
    }
    dxf.pair(0, "ENDSEC");
    dxf.objects();
    dxf.pair(0, "EOF");
    dxf.text
}

/// The smallest and largest coordinates of the control points and the input points (the
/// curve lies in its control polygon's hull).
fn extents(curve: &DxfCurve<'_>) -> (Point3, Point3) {
    let mut low = [f64::INFINITY; 3];
    let mut high = [f64::NEG_INFINITY; 3];
    for p in curve.spline.control_points().iter().chain(curve.points) {
        for c in 0..3 {
            low[c] = low[c].min(p[c]);
            high[c] = high[c].max(p[c]);
        }
    }
    (Point3::new(low), Point3::new(high))
}

/// The rounding level of `values`: the machine epsilon times their largest magnitude (1e-10,
/// the usual default, when they are all 0).
fn tolerance(values: impl Iterator<Item = f64>) -> f64 {
    let size = values.map(f64::abs).fold(0.0, f64::max);
    if size > 0.0 {
        f64::EPSILON * size
    } else {
        1e-10
    }
}

/// A real as the shortest decimal that reads back as the same `f64` (no `-0`).
fn real(x: f64) -> String {
    let x = if x == 0.0 { 0.0 } else { x };
    format!("{x:?}")
}

/// A DXF text being built, one group code and one value per line.
#[derive(Default)]
struct Dxf {
    text: String,
}

impl Dxf {
    /// The group `code` with the value `value`.
    fn pair(&mut self, code: u32, value: impl std::fmt::Display) {
        // Writing to a String cannot fail.
        let _ = write!(self.text, "{code:>3}\n{value}\n");
    }

    /// The group `code` with the real `x`.
    fn real(&mut self, code: u32, x: f64) {
        self.pair(code, real(x));
    }

    /// The point `p` under the codes `code`, `code + 10`, `code + 20`.
    fn coordinates(&mut self, code: u32, p: Point3) {
        for c in 0..3 {
            self.real(code + 10 * c as u32, p[c]);
        }
    }

    /// A handle under group code `code` (5 for an object's own, 330 for its owner).
    fn handle(&mut self, code: u32, h: u32) {
        self.pair(code, format!("{h:X}"));
    }

    fn header(&mut self, low: Point3, high: Point3, seed: u32, units: u32) {
        self.pair(0, "SECTION");
        self.pair(2, "HEADER");
        self.pair(9, "$ACADVER");
        self.pair(1, "AC1015");
        self.pair(9, "$DWGCODEPAGE");
        self.pair(3, "ANSI_1252");
        self.pair(9, "$INSBASE");
        self.coordinates(10, Point3::new([0.0; 3]));
        self.pair(9, "$EXTMIN");
        self.coordinates(10, low);
        self.pair(9, "$EXTMAX");
        self.coordinates(10, high);
        // Unitless (0) unless a unit is given: the coordinates are the input's, in whatever
        // unit it was measured.
        self.pair(9, "$INSUNITS");
        self.pair(70, units);
        self.pair(9, "$HANDSEED");
        self.pair(5, format!("{seed:X}"));
        self.pair(0, "ENDSEC");
    }

    /// The start of a symbol table `name` with handle `h` and `count` records.
    fn table(&mut self, name: &str, h: u32, count: usize) {
        self.pair(0, "TABLE");
        self.pair(2, name);
        self.handle(5, h);
        self.handle(330, 0);
        self.pair(100, "AcDbSymbolTable");
        self.pair(70, count);
    }

    /// The start of a record of kind `kind` (subclass `subclass`) with handle `h` in the
    /// table `owner`.
    fn record(&mut self, kind: &str, h: u32, owner: u32, subclass: &str) {
        self.pair(0, kind);
        self.handle(if kind == "DIMSTYLE" { 105 } else { 5 }, h);
        self.handle(330, owner);
        self.pair(100, "AcDbSymbolTableRecord");
        self.pair(100, subclass);
    }

    fn tables(&mut self, low: Point3, high: Point3) {
        use handle::*;
        self.pair(0, "SECTION");
        self.pair(2, "TABLES");
        self.viewport_table(low, high);
        self.linetype_table();
        self.layer_table();
        self.style_table();
        self.table("VIEW", VIEW_TABLE, 0);
        self.pair(0, "ENDTAB");
        self.table("UCS", UCS_TABLE, 0);
        self.pair(0, "ENDTAB");
        self.appid_table();
        self.dimstyle_table();
        self.block_record_table();
        self.pair(0, "ENDSEC");
    }

    /// The active viewport, centred on the drawing's box `low..high`.
    fn viewport_table(&mut self, low: Point3, high: Point3) {
        use handle::*;
        self.table("VPORT", VPORT_TABLE, 1);
        self.record(
            "VPORT",
            VPORT_ACTIVE,
            VPORT_TABLE,
            "AcDbViewportTableRecord",
        );
        self.pair(2, "*Active");
        self.pair(70, 0);
        self.real(10, 0.0);
        self.real(20, 0.0);
        self.real(11, 1.0);
        self.real(21, 1.0);
        let (width, height) = ((high[0] - low[0]).max(0.0), (high[1] - low[1]).max(0.0));
        self.real(12, low[0] + width / 2.0);
        self.real(22, low[1] + height / 2.0);
        let height = if height > 0.0 || width > 0.0 {
            1.1 * height.max(width / 1.5)
        } else {
            1.0
        };
        self.real(40, height);
        self.real(41, 1.5);
        self.pair(0, "ENDTAB");
    }

    fn linetype_table(&mut self) {
        use handle::*;
        self.table("LTYPE", LTYPE_TABLE, 3);
        for (h, (name, description)) in LTYPES.into_iter().zip([
            ("ByBlock", ""),
            ("ByLayer", ""),
            ("Continuous", "Solid line"),
        ]) {
            self.record("LTYPE", h, LTYPE_TABLE, "AcDbLinetypeTableRecord");
            self.pair(2, name);
            self.pair(70, 0);
            self.pair(3, description);
            self.pair(72, 65);
            self.pair(73, 0);
            self.real(40, 0.0);
        }
        self.pair(0, "ENDTAB");
    }

    /// Layer 0 white, the curve white, the points red.
    fn layer_table(&mut self) {
        use handle::*;
        self.table("LAYER", LAYER_TABLE, 3);
        for (h, (name, color)) in
            LAYERS
                .into_iter()
                .zip([("0", 7), (CURVE_LAYER, 7), (POINTS_LAYER, 1)])
        {
            self.record("LAYER", h, LAYER_TABLE, "AcDbLayerTableRecord");
            self.pair(2, name);
            self.pair(70, 0);
            self.pair(62, color);
            self.pair(6, "Continuous");
            self.pair(370, -3);
        }
        self.pair(0, "ENDTAB");
    }

    fn style_table(&mut self) {
        use handle::*;
        self.table("STYLE", STYLE_TABLE, 1);
        self.record(
            "STYLE",
            STYLE_STANDARD,
            STYLE_TABLE,
            "AcDbTextStyleTableRecord",
        );
        self.pair(2, "Standard");
        self.pair(70, 0);
        self.real(40, 0.0);
        self.real(41, 1.0);
        self.real(50, 0.0);
        self.pair(71, 0);
        self.real(42, 2.5);
        self.pair(3, "txt");
        self.pair(4, "");
        self.pair(0, "ENDTAB");
    }

    fn appid_table(&mut self) {
        use handle::*;
        self.table("APPID", APPID_TABLE, 1);
        self.record("APPID", APPID_ACAD, APPID_TABLE, "AcDbRegAppTableRecord");
        self.pair(2, "ACAD");
        self.pair(70, 0);
        self.pair(0, "ENDTAB");
    }

    fn dimstyle_table(&mut self) {
        use handle::*;
        self.table("DIMSTYLE", DIMSTYLE_TABLE, 1);
        self.pair(100, "AcDbDimStyleTable");
        self.record(
            "DIMSTYLE",
            DIMSTYLE_STANDARD,
            DIMSTYLE_TABLE,
            "AcDbDimStyleTableRecord",
        );
        self.pair(2, "Standard");
        self.pair(70, 0);
        self.pair(0, "ENDTAB");
    }

    fn block_record_table(&mut self) {
        use handle::*;
        self.table("BLOCK_RECORD", BLOCK_RECORD_TABLE, 2);
        for (h, name) in [
            (MODEL_SPACE_RECORD, "*Model_Space"),
            (PAPER_SPACE_RECORD, "*Paper_Space"),
        ] {
            self.record(
                "BLOCK_RECORD",
                h,
                BLOCK_RECORD_TABLE,
                "AcDbBlockTableRecord",
            );
            self.pair(2, name);
        }
        self.pair(0, "ENDTAB");
    }

    fn blocks(&mut self) {
        use handle::*;
        self.pair(0, "SECTION");
        self.pair(2, "BLOCKS");
        for (owner, [begin, end], name, paper) in [
            (MODEL_SPACE_RECORD, MODEL_SPACE_BLOCK, "*Model_Space", false),
            (PAPER_SPACE_RECORD, PAPER_SPACE_BLOCK, "*Paper_Space", true),
        ] {
            self.pair(0, "BLOCK");
            self.handle(5, begin);
            self.handle(330, owner);
            self.pair(100, "AcDbEntity");
            if paper {
                self.pair(67, 1);
            }
            self.pair(8, "0");
            self.pair(100, "AcDbBlockBegin");
            self.pair(2, name);
            self.pair(70, 0);
            self.coordinates(10, Point3::new([0.0; 3]));
            self.pair(3, name);
            self.pair(1, "");
            self.pair(0, "ENDBLK");
            self.handle(5, end);
            self.handle(330, owner);
            self.pair(100, "AcDbEntity");
            if paper {
                self.pair(67, 1);
            }
            self.pair(8, "0");
            self.pair(100, "AcDbBlockEnd");
        }
        self.pair(0, "ENDSEC");
    }

    /// The start of an entity of kind `kind` with handle `h` in model space on `layer`.
    fn entity(&mut self, kind: &str, h: u32, layer: &str) {
        self.pair(0, kind);
        self.handle(5, h);
        self.handle(330, handle::MODEL_SPACE_RECORD);
        self.pair(100, "AcDbEntity");
        self.pair(8, layer);
    }

    fn spline(&mut self, curve: &DxfCurve<'_>, h: u32) {
        let spline = curve.spline;
        self.entity("SPLINE", h, CURVE_LAYER);
        self.pair(100, "AcDbSpline");
        if curve.planar {
            self.coordinates(210, Point3::new([0.0, 0.0, 1.0]));
        }
        let linear = if spline.degree() == 1 { 16 } else { 0 };
        let flags = u32::from(curve.closed) | if curve.planar { 8 } else { 0 } | linear;
        self.pair(70, flags);
        self.pair(71, spline.degree());
        self.pair(72, spline.knots().len());
        self.pair(73, spline.control_points().len());
        self.pair(74, 0);
        self.real(42, tolerance(spline.knots().iter().copied()));
        self.real(
            43,
            tolerance(spline.control_points().iter().flat_map(|p| p.0)),
        );
        for &k in spline.knots() {
            self.real(40, k);
        }
        for &p in spline.control_points() {
            self.coordinates(10, p);
        }
    }

    fn point_entity(&mut self, p: &Point3, h: u32) {
        self.entity("POINT", h, POINTS_LAYER);
        self.pair(100, "AcDbPoint");
        self.coordinates(10, *p);
    }

    fn objects(&mut self) {
        use handle::*;
        self.pair(0, "SECTION");
        self.pair(2, "OBJECTS");
        self.pair(0, "DICTIONARY");
        self.handle(5, ROOT_DICTIONARY);
        self.handle(330, 0);
        self.pair(100, "AcDbDictionary");
        self.pair(281, 1);
        self.pair(3, "ACAD_GROUP");
        self.handle(350, GROUP_DICTIONARY);
        self.pair(0, "DICTIONARY");
        self.handle(5, GROUP_DICTIONARY);
        self.handle(330, ROOT_DICTIONARY);
        self.pair(100, "AcDbDictionary");
        self.pair(281, 1);
        self.pair(0, "ENDSEC");
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The group codes and values of a DXF text.
    fn pairs(text: &str) -> Vec<(u32, &str)> {
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len() % 2, 0);
        lines
            .chunks(2)
            .map(|c| (c[0].trim().parse().unwrap(), c[1]))
            .collect()
    }

    #[test]
    fn reals_round_trip_exactly() {
        for x in [0.1, 1.0 / 3.0, -2.5e-300, 1e-13, 123456789.123, f64::MAX] {
            assert_eq!(real(x).parse::<f64>().unwrap(), x);
        }
        assert_eq!(real(-0.0), "0.0");
        assert_eq!(real(1.0), "1.0");
    }

    #[test]
    fn spline_entity_carries_the_exact_form_and_the_points() {
        let control4: Vec<Point3> = [
            [0.0, 0.0, 0.0],
            [1.0, 2.0, 0.0],
            [3.0, -1e-13, 0.0],
            [4.0, 0.5, 0.0],
        ]
        .map(Point3::new)
        .to_vec();
        let knots = vec![0.0, 0.0, 0.0, 1.0 / 3.0, 1.0, 1.0, 1.0];
        let spline = BSplineCurve::new(2, knots.clone(), control4.clone()).unwrap();
        let points = [Point3::new([0.5, 0.25, 0.0])];
        let text = dxf_text(&DxfCurve {
            spline: &spline,
            closed: false,
            planar: true,
            points: &points,
        });
        let all = pairs(&text);
        let start = all.iter().position(|p| *p == (0, "SPLINE")).unwrap();
        let end = start + 1 + all[start + 1..].iter().position(|p| p.0 == 0).unwrap();
        let spline_pairs = &all[start..end];
        let value = |code: u32| {
            spline_pairs
                .iter()
                .filter(|p| p.0 == code)
                .map(|p| p.1)
                .collect::<Vec<_>>()
        };
        assert_eq!(value(8), ["CURVE"]);
        assert_eq!(value(70), ["8"]);
        assert_eq!(value(71), ["2"]);
        assert_eq!(value(72), ["7"]);
        assert_eq!(value(73), ["4"]);
        let read: Vec<f64> = value(40).iter().map(|s| s.parse().unwrap()).collect();
        assert_eq!(read, knots);
        let ys: Vec<f64> = value(20).iter().map(|s| s.parse().unwrap()).collect();
        assert_eq!(ys, control4.iter().map(|p| p[1]).collect::<Vec<_>>());
        let point = all.iter().position(|p| *p == (0, "POINT")).unwrap();
        assert_eq!(all[point + 4], (8, "POINTS"));
        assert_eq!(
            &all[point + 6..point + 9],
            &[(10, "0.5"), (20, "0.25"), (30, "0.0")]
        );
        assert_eq!(all.last(), Some(&(0, "EOF")));
        // The handle seed lies above every handle.
        let seed = all.iter().position(|p| p.1 == "$HANDSEED").unwrap();
        assert_eq!(all[seed + 1], (5, "102"));
    }
}

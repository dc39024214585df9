//! Hostile CAD files: truncated at every cut, dangling references, bad IGES pointers,
//! binary bytes and 10^7-entity streams give positioned errors (line and entity) or
//! a model, never a panic, and what is kept stays under the memory cap.

use std::io::{BufRead, Read};
use std::path::Path;

use karkas::bspline::conic::elliptic_arc;
use karkas::bspline::sweep::{sphere, Frame};
use karkas::Point3;
use karkas_io::cad::read::{read_cad_from, CadFormat, CadModel};
use karkas_io::cad::{iges::iges_text, step::step_text, CadEntity};
use karkas_io::IoError;

fn read(text: &[u8], format: CadFormat) -> Result<CadModel, IoError> {
    let mut bytes = text;
    read_cad_from(Path::new("h.cad"), format, &mut bytes)
}

fn message(text: &str, format: CadFormat) -> String {
    match read(text.as_bytes(), format) {
        Ok(_) => panic!("read:\n{}", &text[text.find("DATA;").unwrap_or(0)..]),
        Err(e) => e.to_string(),
    }
}

/// A karkas file of a rational arc and a spherical patch.
fn sample(format: CadFormat) -> String {
    let f = Frame::new(
        Point3::new([0.5, -1.0, 2.0]),
        Point3::new([0.0, 0.3, 1.0]),
        Point3::new([1.0, 0.0, 0.0]),
    )
    .unwrap();
    let arc = elliptic_arc(f.origin, f.x * 2.0, f.y, (0.2, 4.0)).unwrap();
    let patch = sphere(&f, 3.0, (0.1, 2.0), (-0.5, 0.9)).unwrap();
    let entities = [
        CadEntity::RationalCurve(&arc),
        CadEntity::RationalSurface(&patch),
    ];
    match format {
        CadFormat::Step => step_text(&entities, "h"),
        CadFormat::Iges => iges_text(&entities, "h"),
    }
}

#[test]
fn every_truncation_is_refused_with_a_line() {
    for format in [CadFormat::Step, CadFormat::Iges] {
        let text = sample(format);
        assert!(read(text.as_bytes(), format).is_ok());
        // IGES: cuts before the terminate record (which carries the section counts).
        let end = match format {
            CadFormat::Step => text.len(),
            CadFormat::Iges => text
                .rfind('\n')
                .map_or(text.len(), |k| text[..k].rfind('\n').unwrap_or(k)),
        };
        let cuts: Vec<usize> = (1..end).step_by(7).collect();
        for &cut in &cuts {
            match read(&text.as_bytes()[..cut], format) {
                Err(e) => {
                    let m = e.to_string();
                    assert!(m.starts_with("h.cad:"), "{format:?} cut {cut}: {m}");
                }
                // IGES's terminate record carries the counts: a cut before it is refused;
                // a cut in STEP before END-ISO-10303-21 too.
                Ok(_) => panic!("{format:?}: a file cut at {cut} of {} was read", text.len()),
            }
        }
    }
}

#[test]
fn dangling_references_and_binary_bytes_name_the_entity_and_line() {
    let text = sample(CadFormat::Step);
    let line_of = |needle: &str| text.lines().position(|l| l.contains(needle)).unwrap() + 1;
    // A control point that is not defined.
    let n = line_of("B_SPLINE_SURFACE");
    let dangling = text.replacen(
        "B_SPLINE_SURFACE(2,2,((#",
        "B_SPLINE_SURFACE(2,2,((#987654,#",
        1,
    );
    if dangling != text {
        let m = message(&dangling, CadFormat::Step);
        assert!(
            m.contains("#987654") && m.contains("does not define"),
            "{m}"
        );
        assert!(m.contains(&format!("h.cad:{n}:")), "{m}");
    }
    // A control byte in a string, and raw binary after the header.
    let binary = text.replacen("'h'", "'h\u{1}'", 1);
    assert!(message(&binary, CadFormat::Step).contains("control byte"));
    let mut raw = text.as_bytes()[..text.find("DATA;").unwrap() + 6].to_vec();
    raw.extend((0..4096u32).map(|k| (k.wrapping_mul(2_654_435_761) >> 7) as u8));
    assert!(read(&raw, CadFormat::Step).is_err());
}

/// A STEP file of `data` lines (after the header karkas writes).
fn step_with(data: &str) -> String {
    let text = sample(CadFormat::Step);
    let start = text.find("DATA;\n").unwrap() + 6;
    format!("{}{data}ENDSEC;\nEND-ISO-10303-21;\n", &text[..start])
}

#[test]
fn step_reference_cycles_are_refused_with_entity_and_line() {
    let head = "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=DIRECTION('',(1.,0.,0.));\n\
                #3=VECTOR('',#2,1.);\n#4=LINE('',#1,#3);\n";
    // Two trimmed curves trimming each other, in a curve set and on their own (no instance
    // outside the cycle refers to either).
    for set in ["#7=GEOMETRIC_CURVE_SET('',(#5,#6));\n", ""] {
        let text = step_with(&format!(
            "{head}#5=TRIMMED_CURVE('',#6,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.)),.T.,\
             .PARAMETER.);\n#6=TRIMMED_CURVE('',#5,(PARAMETER_VALUE(0.)),\
             (PARAMETER_VALUE(1.)),.T.,.PARAMETER.);\n{set}"
        ));
        let line = text.lines().position(|l| l.starts_with("#6=")).unwrap() + 1;
        let m = message(&text, CadFormat::Step);
        assert!(m.contains("cycle"), "{m}");
        assert!(
            m.contains(&format!("h.cad:{line}:")) && m.contains("#6 (TRIMMED_CURVE)"),
            "{m}"
        );
    }
    // A curve referring to itself, and a longer cycle through a point.
    let text = step_with(&format!(
        "{head}#5=TRIMMED_CURVE('',#5,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.)),.T.,\
         .PARAMETER.);\n"
    ));
    assert!(message(&text, CadFormat::Step).contains("#5 (TRIMMED_CURVE): refers to #5"));
    let text = step_with(
        "#1=CARTESIAN_POINT('',(0.,0.,0.));\n#2=DIRECTION('',(1.,0.,0.));\n\
         #3=VECTOR('',#2,1.);\n#4=LINE('',#1,#3);\n\
         #5=AXIS2_PLACEMENT_3D('',#1,#8,#2);\n#8=DIRECTION('',(#5));\n\
         #9=CIRCLE('',#5,1.);\n",
    );
    let m = message(&text, CadFormat::Step);
    assert!(m.contains("cycle") && m.contains("#8 (DIRECTION)"), "{m}");
    // The same curves without the cycle read.
    let text = step_with(&format!(
        "{head}#5=TRIMMED_CURVE('',#4,(PARAMETER_VALUE(0.)),(PARAMETER_VALUE(1.)),.T.,\
         .PARAMETER.);\n#6=TRIMMED_CURVE('',#5,(PARAMETER_VALUE(0.2)),\
         (PARAMETER_VALUE(0.8)),.T.,.PARAMETER.);\n#7=GEOMETRIC_CURVE_SET('',(#6));\n"
    ));
    let model = read(text.as_bytes(), CadFormat::Step).unwrap();
    assert_eq!(model.shape.curves.len(), 1);
}

#[test]
fn iges_cycles_and_bad_pointers_are_refused() {
    let text = sample(CadFormat::Iges);
    // Every parameter line's pointer back to its directory entry (columns 66-72) pointed at
    // a directory entry that does not exist.
    let lines: Vec<&str> = text.lines().collect();
    let broken: String = lines
        .iter()
        .map(|l| {
            if l.len() >= 80 && &l[72..73] == "P" {
                format!("{}{:>7}{}\n", &l[..65], 9_999_999, &l[72..])
            } else {
                format!("{l}\n")
            }
        })
        .collect();
    assert!(read(broken.as_bytes(), CadFormat::Iges).is_err());
    // Random bytes in place of the parameter data.
    let mut raw = text.clone().into_bytes();
    let start = text.find("1P").unwrap_or(raw.len() / 2);
    for (k, b) in raw[start..].iter_mut().enumerate().take(800) {
        *b = (k as u32).wrapping_mul(2_654_435_761).to_le_bytes()[1];
    }
    assert!(read(&raw, CadFormat::Iges).is_err());
}

/// A STEP data section of `count` copies of one instance, generated as it is read.
struct Generated {
    head: Vec<u8>,
    line: String,
    count: usize,
    done: usize,
    buffer: Vec<u8>,
    at: usize,
}

impl Generated {
    fn new(line: &str, count: usize) -> Generated {
        let head =
            b"ISO-10303-21;\nHEADER;\nFILE_NAME('g','',(''),(''),'','','');\nENDSEC;\nDATA;\n";
        Generated {
            head: head.to_vec(),
            line: line.to_owned(),
            count,
            done: 0,
            buffer: head.to_vec(),
            at: 0,
        }
    }
}

impl Read for Generated {
    fn read(&mut self, out: &mut [u8]) -> std::io::Result<usize> {
        let n = {
            let b = self.fill_buf()?;
            let n = b.len().min(out.len());
            out[..n].copy_from_slice(&b[..n]);
            n
        };
        self.consume(n);
        Ok(n)
    }
}

impl BufRead for Generated {
    fn fill_buf(&mut self) -> std::io::Result<&[u8]> {
        if self.at == self.buffer.len() {
            self.buffer.clear();
            self.at = 0;
            while self.buffer.len() < 1 << 16 && self.done < self.count {
                self.done += 1;
                self.buffer
                    .extend(format!("#{}={}\n", self.done, self.line).as_bytes());
            }
            if self.done == self.count && self.buffer.is_empty() && !self.head.is_empty() {
                self.buffer.extend(b"ENDSEC;\nEND-ISO-10303-21;\n");
                self.head.clear();
            }
        }
        Ok(&self.buffer[self.at..])
    }

    fn consume(&mut self, n: usize) {
        self.at += n;
    }
}

#[test]
fn millions_of_entities_are_counted_or_refused_at_the_cap() {
    // Instances the geometry does not need are counted, not kept (10^6 here: the read is
    // linear, 10^7 takes about a minute on a loaded machine).
    let mut colours = Generated::new("DRAUGHTING_PRE_DEFINED_COLOUR('red');", 1_000_000);
    let m = read_cad_from(Path::new("g.step"), CadFormat::Step, &mut colours).unwrap();
    assert_eq!(m.entities, 1_000_000);
    assert!(m.shape.faces.is_empty() && m.shape.curves.is_empty());
    // Points are kept: the read stops at the instance that crosses the cap (64 MiB here),
    // long before the ten millionth.
    let before = karkas_io::input::max_input_bytes();
    karkas_io::input::set_max_input_bytes(64 << 20);
    let mut points = Generated::new("CARTESIAN_POINT('',(1.5,-2.25,3.));", 10_000_000);
    let result = read_cad_from(Path::new("g.step"), CadFormat::Step, &mut points);
    karkas_io::input::set_max_input_bytes(before);
    let m = result.unwrap_err().to_string();
    assert!(m.contains("memory cap") && m.starts_with("g.step:"), "{m}");
    assert!(points.done < 10_000_000, "read {} instances", points.done);
}

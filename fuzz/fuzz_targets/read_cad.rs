//! The STEP and IGES readers on arbitrary bytes (the first byte chooses the format): a model
//! whose faces and curves evaluate, or an error naming the file; never a panic, a hang or
//! unbounded memory.
#![no_main]

use std::path::Path;

use karkas::{Curve, Surface};
use karkas_io::cad::read::{read_cad_from, CadFormat};
use libfuzzer_sys::fuzz_target;

fuzz_target!(|data: &[u8]| {
    let Some((&selector, mut rest)) = data.split_first() else {
        return;
    };
    let format = if selector % 2 == 0 {
        CadFormat::Step
    } else {
        CadFormat::Iges
    };
    match read_cad_from(Path::new("part.cad"), format, &mut rest) {
        Ok(model) => {
            for face in &model.shape.faces {
                let (u, v) = (face.surface.domain_u(), face.surface.domain_v());
                let _ = face.surface.eval(u.start, v.start);
                let _ = face.surface.eval(u.end, v.end);
            }
            for curve in &model.shape.curves {
                let d = curve.domain();
                let _ = curve.eval(0.5 * (d.start + d.end));
            }
        }
        Err(e) => assert!(e.to_string().starts_with("part.cad")),
    }
});

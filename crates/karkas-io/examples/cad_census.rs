//! What karkas reads of each CAD file named on the command line: one JSON line per file with
//! its format, length unit, entity count, the seconds the read took, the faces, edges and curves read, what was not read
//! (entity type, count, reason) and notes, or the error that refused it.
//!
//! ```text
//! cargo run --release -p karkas-io --example cad_census -- FILE.step FILE.igs ...
//! ```
//!
//! tests/cad/registry_files.py runs it over the STEP and IGES files of Debian packages.

use std::path::Path;

use karkas_io::cad::read::{counts, read_cad, CadFormat};
use serde_json::json;

fn main() {
    for arg in std::env::args().skip(1) {
        let path = Path::new(&arg);
        let start = std::time::Instant::now();
        let line = match read_cad(path) {
            Ok(model) => {
                let c = counts(&model);
                json!({
                    "file": arg,
                    "format": match model.format {
                        CadFormat::Step => "step",
                        CadFormat::Iges => "iges",
                    },
                    "unit": model.unit.name,
                    "entities": model.entities,
                    "seconds": start.elapsed().as_secs_f64(),
                    "faces": c["faces"],
                    "edges": c["edges"],
                    "curves": c["curves"],
                    "unread": model.unread.iter().map(|u| json!({
                        "what": u.what, "count": u.count, "reason": u.reason,
                    })).collect::<Vec<_>>(),
                    "notes": model.notes,
                })
            }
            Err(e) => json!({ "file": arg, "error": e.to_string() }),
        };
        println!("{line}");
    }
}

//! `karkas section MODEL.step`: plane sections of a CAD model's faces (STEP or IGES, read by
//! `karkas_io::cad::read::read_cad`), cut by `karkas::shape::ShapeSectioner` within each
//! face's trims and joined across shared edges; written as the same CSV as the sections of a
//! grid (`section,t,x,y,z`, a closed piece repeating its first point).

use crate::input::faces_of_model;
use crate::output::console::{note, record};
use crate::output::target::shown;
use anyhow::{bail, Context, Result};
use karkas::section::Plane;
use karkas::shape::{ShapeSection, ShapeSectioner};
use karkas::Point3;
use karkas_io::cad::read::CadModel;
use karkas_io::input::display_name;
use karkas_io::write::write_sections_csv;
use std::path::Path;

/// The smallest `--tolerance`, relative to the model's size (as for a grid's surface).
const MIN_RELATIVE_TOLERANCE: f64 = 1e-12;

/// Cuts the faces of `model`, read from `path`, by the planes of `cuts` (each with how the
/// user wrote it) and writes the pieces to `output`.
pub(super) fn cut_model(
    path: &Path,
    model: &CadModel,
    output: &Path,
    tolerance: Option<f64>,
    cuts: &[(Plane<3>, String)],
) -> Result<()> {
    let name = display_name(path);
    faces_of_model(path, model, "", "cut")?;
    let shape = &model.shape;
    let size = shape.size();
    if let Some(t) = tolerance {
        if t < MIN_RELATIVE_TOLERANCE * size {
            bail!(
                "--tolerance: {t:e} is below what floating point resolves on this model \
                 ({MIN_RELATIVE_TOLERANCE:e} of its size {size:.6e})"
            );
        }
    }
    let sectioner = ShapeSectioner::new(shape, tolerance)
        .with_context(|| format!("{}: a face cannot be sampled", name.display()))?;
    let mut lines: Vec<Vec<Point3>> = Vec::new();
    for (k, (plane, label)) in cuts.iter().enumerate() {
        let section = sectioner.plane(plane);
        report(k, label, &section, lines.len());
        for piece in &section.pieces {
            let mut line = piece.points.clone();
            if piece.closed {
                line.push(piece.points[0]);
            }
            lines.push(line);
        }
    }
    write_sections_csv(output, &lines)?;
    record("pieces", lines.len());
    record("planes", cuts.len());
    note(format!(
        "karkas: wrote {} ({} section pieces of {} from {} planes, tolerance {:e})",
        shown(output).display(),
        lines.len(),
        name.display(),
        cuts.len(),
        sectioner.tolerance()
    ));
    Ok(())
}

/// Prints what one plane gave (pieces, closed ones, faces crossed) and its warnings.
fn report(k: usize, label: &str, section: &ShapeSection, first: usize) {
    let pieces = section.pieces.len();
    let closed = section.pieces.iter().filter(|p| p.closed).count();
    let mut faces: Vec<usize> = section
        .pieces
        .iter()
        .flat_map(|p| p.faces.clone())
        .collect();
    faces.sort_unstable();
    faces.dedup();
    let what = match pieces {
        0 => "no section".to_owned(),
        1 => format!(
            "1 {} piece over {} faces, section {first}",
            if closed == 1 { "closed" } else { "open" },
            faces.len()
        ),
        n => format!(
            "{n} pieces ({closed} closed) over {} faces, sections {first}-{}",
            faces.len(),
            first + n - 1
        ),
    };
    note(format!("karkas: plane {} ({label}): {what}", k + 1));
    for (face, w) in &section.warnings {
        note(format!(
            "karkas: warning: plane {} ({label}), face {face}: {w}",
            k + 1
        ));
    }
}

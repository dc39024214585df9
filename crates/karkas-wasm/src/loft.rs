//! The loft of the workbench (docs/methods.md §7): a wing through airfoil sections placed as
//! a sections table places them (`karkas loft TABLE`), built by the library's
//! [`Loft::wing`] as the command line builds it, with its summary (control points, the
//! largest section deviation) and the surface's curve at every section for the 3-D view.
//!
//! Profiles cross as one flat array of `x, y` pairs with a count per section; placements as
//! six numbers a section (`x, y, z, chord, twist, dihedral`, NaN for no dihedral). Errors
//! name the section by the label the page gives it (the table's row and file), as the
//! command line's do.

use karkas::loft::{Loft, LoftOptions, SpanRule, WingPlacement};
use karkas::{Point2, Point3, Surface};
use karkas_io::export::samples::default_surface_samples;
use karkas_io::sections_table::SectionRow;

/// Numbers a placement takes in the flat array: `x, y, z, chord, twist, dihedral`.
pub const PLACEMENT_WIDTH: usize = 6;

/// A built loft and the sample counts of its meshes (as the command line's).
pub struct WingLoft {
    /// The loft.
    pub loft: Loft,
    /// The default samples along the span and along the sections.
    pub samples: (usize, usize),
}

impl WingLoft {
    /// The surface's curve at every section's station, `n` points each (`v` uniform over
    /// `[0, 1]`), 3 numbers a point, section after section.
    pub fn station_curves(&self, n: usize) -> Vec<f64> {
        let n = n.max(2);
        let mut out = Vec::with_capacity(3 * n * self.loft.stations().len());
        for &u in self.loft.stations() {
            for j in 0..n {
                out.extend(self.loft.eval(u, j as f64 / (n - 1) as f64).0);
            }
        }
        out
    }
}

/// The placements of the flat array `flat` (see the module docs).
pub fn placements(flat: &[f64]) -> Result<Vec<WingPlacement>, String> {
    if !flat.len().is_multiple_of(PLACEMENT_WIDTH) {
        return Err(format!(
            "placements come as {PLACEMENT_WIDTH} numbers a section (x, y, z, chord, twist, \
             dihedral), not {}",
            flat.len()
        ));
    }
    Ok(flat
        .chunks_exact(PLACEMENT_WIDTH)
        .map(|c| WingPlacement {
            leading_edge: Point3::new([c[0], c[1], c[2]]),
            chord: c[3],
            twist: c[4],
            dihedral: (!c[5].is_nan()).then_some(c[5]),
        })
        .collect())
}

/// The flat placements of a sections table's rows.
pub fn row_placements(rows: &[SectionRow]) -> Vec<f64> {
    rows.iter()
        .flat_map(|r| {
            let le = r.leading_edge.0;
            [
                le[0],
                le[1],
                le[2],
                r.chord,
                r.twist,
                r.dihedral.unwrap_or(f64::NAN),
            ]
        })
        .collect()
}

/// The wing lofted through the profiles `coords` (`x, y` pairs, `counts[k]` points for section
/// `k`) at `placements`, with the span rule `rule` (`linear`, `monotone`, `spline`) and the
/// tolerance `tolerance` (a share of each chord); errors name section `k` by `labels[k]`
/// (or its number when there is no label) and the rest by `input`.
pub fn wing_loft(
    coords: &[f64],
    counts: &[usize],
    placements: &[WingPlacement],
    rule: &str,
    tolerance: f64,
    labels: &[String],
    input: &str,
) -> Result<WingLoft, String> {
    let rule: SpanRule = rule.parse().map_err(|e| format!("{input}: {e}"))?;
    if counts.iter().sum::<usize>() * 2 != coords.len() {
        return Err(format!(
            "{input}: the section counts add up to {} points, but {} coordinates came",
            counts.iter().sum::<usize>(),
            coords.len()
        ));
    }
    let mut profiles = Vec::with_capacity(counts.len());
    let mut at = 0;
    for &n in counts {
        profiles.push(
            coords[2 * at..2 * (at + n)]
                .chunks_exact(2)
                .map(|c| Point2::new([c[0], c[1]]))
                .collect::<Vec<_>>(),
        );
        at += n;
    }
    let options = LoftOptions { rule, tolerance };
    let loft = Loft::wing(&profiles, placements, &options).map_err(|e| match e {
        karkas::Error::LoftSection { section, reason } => match labels.get(section) {
            Some(label) => format!("{label}: {reason}"),
            None => format!("{input}: section {}: {reason}", section + 1),
        },
        other => format!("{input}: {other}"),
    })?;
    let longest = counts.iter().copied().max().unwrap_or(0);
    let samples = (
        default_surface_samples(counts.len()),
        default_surface_samples(longest),
    );
    Ok(WingLoft { loft, samples })
}

//! What `curve analyze` reports: the fairness figures of every method as one aligned table or
//! one JSON object keyed by method, and the curvature against the arc length as CSV
//! (`method,t,s,curvature`) or a plot.

use crate::output::console::note;
use crate::output::target::shown;
use anyhow::Result;
use karkas::geometry::{CurvatureSample, CurveFairness};
use karkas::Point2;
use karkas_io::curvature_plot::{write_curvature_picture, CurvatureLine, CurvaturePlot};
use karkas_io::input::display_name;
use karkas_io::write::write_atomic;
use karkas_io::OutputFormat;
use serde_json::{json, Map, Value};
use std::path::Path;

/// The figures of one method on the points.
pub struct MethodReport {
    /// The method's name (`ll`, `spline`, `fit`).
    pub method: &'static str,
    /// Its figures.
    pub fairness: CurveFairness,
    /// The number of input points.
    pub points: usize,
    /// The curvature along the curve (empty unless written).
    pub profile: Vec<CurvatureSample>,
}

impl MethodReport {
    /// The figures as a JSON object.
    fn json(&self) -> Value {
        let f = &self.fairness;
        json!({
            "length": f.length,
            "curvature_min": f.curvature_min,
            "curvature_max": f.curvature_max,
            "curvature_extrema": f.curvature_extrema,
            "inflections": f.inflections,
            "max_distance_to_polygon": finite_or_null(f.max_distance_to_polygon),
            "fairness_energy": f.fairness_energy,
            "pieces": f.pieces,
            "curvature_jump": f.curvature_jump,
            "points": self.points,
        })
    }
}

/// `x`, or JSON null when it is not finite.
fn finite_or_null(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// The table: a header and one row per method, columns aligned (a curvature of -0 shown as
/// 0).
pub fn table(reports: &[MethodReport]) -> String {
    let mut out = format!(
        "{:<8}{:>14}{:>14}{:>14}{:>9}{:>12}{:>14}{:>14}{:>8}\n",
        "method",
        "length",
        "curv. min",
        "curv. max",
        "extrema",
        "inflections",
        "max dist.",
        "energy",
        "pieces"
    );
    for r in reports {
        let f = &r.fairness;
        out += &format!(
            "{:<8}{:>14}{:>14.5e}{:>14.5e}{:>9}{:>12}{:>14.3e}{:>14.5e}{:>8}\n",
            r.method,
            length_text(f.length),
            f.curvature_min + 0.0,
            f.curvature_max + 0.0,
            f.curvature_extrema,
            f.inflections,
            f.max_distance_to_polygon,
            f.fairness_energy,
            f.pieces
        );
    }
    out
}

/// A length with six decimals, or in exponent form outside 1e-3..1e7 (a curve in units near
/// 1e150 would otherwise print 150 digits).
fn length_text(length: f64) -> String {
    if (1e-3..1e7).contains(&length.abs()) {
        format!("{length:.6}")
    } else {
        format!("{length:.6e}")
    }
}

/// Prints the figures: the JSON object on standard output when `json` (the table then goes to
/// standard error), else the table on standard output.
pub fn print(reports: &[MethodReport], json: bool, stdout_taken: bool) -> Result<()> {
    let table = table(reports);
    let object: Map<String, Value> = reports
        .iter()
        .map(|r| (r.method.to_owned(), r.json()))
        .collect();
    if crate::output::console::is_capturing() {
        // In a batch the figures are the record's summary, one object per method.
        crate::output::console::record_all(Value::Object(object));
        return Ok(());
    }
    if json {
        println!("{}", Value::Object(object));
    } else if stdout_taken {
        eprint!("{table}");
    } else {
        print!("{table}");
    }
    Ok(())
}

/// Writes the curvature of every method to `output`: CSV rows `method,t,s,curvature`, or a
/// plot of the curvature against the arc length.
pub fn write_profiles(
    output: &Path,
    format: OutputFormat,
    input: &str,
    reports: &[MethodReport],
) -> Result<()> {
    match format {
        OutputFormat::Csv => write_atomic(output, |w| {
            writeln!(w, "method,t,s,curvature")?;
            for r in reports {
                for p in &r.profile {
                    writeln!(w, "{},{},{},{}", r.method, p.t, p.s, p.curvature)?;
                }
            }
            Ok(())
        })?,
        _ => {
            let lines: Vec<Vec<Point2>> = reports
                .iter()
                .map(|r| {
                    r.profile
                        .iter()
                        .map(|p| Point2::new([p.s, p.curvature]))
                        .collect()
                })
                .collect();
            let labels: Vec<String> = reports
                .iter()
                .map(|r| format!("{} ({} extrema)", r.method, r.fairness.curvature_extrema))
                .collect();
            let curves: Vec<CurvatureLine<'_>> = labels
                .iter()
                .zip(&lines)
                .map(|(label, points)| CurvatureLine { label, points })
                .collect();
            let name = Path::new(input).file_name().map(Path::new);
            let title = format!(
                "curvature along {}",
                display_name(name.unwrap_or(Path::new(input))).display()
            );
            let plot = CurvaturePlot {
                title: &title,
                lines: &curves,
            };
            write_curvature_picture(output, &plot, format == OutputFormat::Png)?;
        }
    }
    note(format!("karkas: wrote {}", shown(output).display()));
    Ok(())
}

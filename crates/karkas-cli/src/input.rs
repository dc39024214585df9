//! Reading the inputs, and the checks of the input points every command makes before
//! building: a frame whose points all lie at one place (or, for a surface, on one line) has
//! nothing to build.
//!
//! Every input path may be `-`, standard input (named `<stdin>` in messages); a command with
//! several inputs refuses `-` for more than one of them ([`one_standard_input`]).

use crate::args::CurveInputOptions;
use crate::output::console::note;
use anyhow::{bail, Result};
use karkas::geometry::points_out_of_order;
use karkas::Point;
use karkas_io::cad::read::CadModel;
use karkas_io::input::{display_name, is_stdin};
use karkas_io::points::{read_curve_points_with, CurvePoints};
use karkas_io::range::check_stray_point;
use karkas_io::OutputFormat;
use std::path::Path;

/// Refuses standard input (`-`) for more than one of a command's `inputs` (the options or
/// arguments as the user named them, and their paths): it can be read only once.
pub fn one_standard_input(inputs: &[(&str, &Path)]) -> Result<()> {
    let named: Vec<&str> = inputs
        .iter()
        .filter(|(_, p)| is_stdin(p))
        .map(|(what, _)| *what)
        .collect();
    if named.len() > 1 {
        let all = if named.len() == 2 { "both" } else { "all" };
        bail!(
            "{} {all} name standard input ('-'), which can be read only once: save all but one \
             to files",
            named.join(" and ")
        );
    }
    Ok(())
}

/// Where the points lie, as far as building a curve or surface goes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Spread {
    /// Every point is the same point.
    OnePoint,
    /// The points lie on one straight line (relative tolerance `1e-12`).
    OneLine,
    /// Anything else: enough for a surface.
    Surface,
}

/// How `points` spread (finite points assumed; the readers refuse others).
fn spread<const D: usize>(points: &[Point<D>]) -> Spread {
    let Some(&first) = points.first() else {
        return Spread::OnePoint;
    };
    // Scale by the largest coordinate difference so that huge and tiny data compare alike.
    let scale = points
        .iter()
        .fold(0.0f64, |m, &p| m.max((p - first).max_abs()));
    if scale == 0.0 || !scale.is_finite() {
        return if scale == 0.0 {
            Spread::OnePoint
        } else {
            Spread::Surface
        };
    }
    let rel = |p: Point<D>| (p - first) * (1.0 / scale);
    let far = points
        .iter()
        .map(|&p| rel(p))
        .max_by(|a, b| a.norm().total_cmp(&b.norm()))
        .unwrap_or(Point::ZERO);
    let axis = far * (1.0 / far.norm());
    let off_line = points.iter().any(|&p| {
        let q = rel(p);
        (q - axis * q.dot(axis)).norm() > 1e-12
    });
    if off_line {
        Spread::Surface
    } else {
        Spread::OneLine
    }
}

/// A command's work on the points of a curve, in the plane or in space.
pub trait CurveJob {
    /// Does the work on `points`.
    fn run<const D: usize>(&self, points: &[Point<D>]) -> Result<()>;

    /// True when the job refuses points out of order itself, in one line ("points not in
    /// order"): the reader's warnings are then not printed for such points.
    fn refuses_disorder(&self) -> bool {
        false
    }
}

/// A curve command's work on the points of its input: the command's arguments and the format
/// of each of its outputs (in the order of the arguments' `-o`).
pub struct CurveCommand<'a, A> {
    /// The command's arguments.
    pub args: &'a A,
    /// The format of each output.
    pub formats: &'a [OutputFormat],
}

impl<'a, A> CurveCommand<'a, A> {
    /// The work of the command with `args` writing in `formats`.
    pub fn new(args: &'a A, formats: &'a [OutputFormat]) -> Self {
        Self { args, formats }
    }
}

/// Reads the curve points of `input` with the user's `options` (`--columns`,
/// `--decimal-comma`), prints the reader's warnings (unless the job refuses the points as out
/// of order), and runs `job` on them in their dimension.
pub fn run_on_curve_points(
    input: &Path,
    options: &CurveInputOptions,
    job: &impl CurveJob,
) -> Result<()> {
    let read = read_curve_points_with(input, &options.read_options())?;
    let refused = job.refuses_disorder()
        && match &read.points {
            CurvePoints::Planar(points) => points_out_of_order(points).is_some(),
            CurvePoints::Spatial(points) => points_out_of_order(points).is_some(),
        };
    if !refused {
        warn_of_reading(input, &read.warnings);
    }
    match read.points {
        CurvePoints::Planar(points) => job.run(&points),
        CurvePoints::Spatial(points) => job.run(&points),
    }
}

/// Prints the warnings a reader gave about `input`, one line each.
pub fn warn_of_reading(input: &Path, warnings: &[String]) {
    for warning in warnings {
        note(format!(
            "karkas: warning: {}: {warning}",
            display_name(input).display()
        ));
    }
}

/// Warns in one line of what the reader of the CAD model `path` skipped, and refuses a model
/// without faces: `{lead}{name}: the model has no faces to {purpose} ({n} curves)`.
pub fn faces_of_model(path: &Path, model: &CadModel, lead: &str, purpose: &str) -> Result<()> {
    if let Some(warning) = model.warning() {
        note(format!("karkas: warning: {warning}"));
    }
    if model.shape.faces.is_empty() {
        bail!(
            "{lead}{}: the model has no faces to {purpose} ({} curves)",
            display_name(path).display(),
            model.shape.curves.len()
        );
    }
    Ok(())
}

/// Refuses a curve input whose points all coincide.
pub fn curve_points<const D: usize>(input: &Path, points: &[Point<D>]) -> Result<()> {
    if points.len() > 1 && spread(points) == Spread::OnePoint {
        bail!(
            "{}: all {} points coincide (at {}): there is no curve to build",
            display_name(input).display(),
            points.len(),
            coordinates(points[0])
        );
    }
    Ok(())
}

/// Refuses a surface grid whose points all coincide or all lie on one line, naming a lone
/// stray point when that is why they seem to.
pub fn grid_points<const D: usize>(input: &Path, points: &[Point<D>]) -> Result<()> {
    if points.len() > 1 {
        let spread = spread(points);
        if spread != Spread::Surface {
            // One stray value sets the model's size, and the rest look like a point or a line.
            check_stray_point(points, &display_name(input))?;
        }
        match spread {
            Spread::OnePoint => bail!(
                "{}: all {} grid points coincide (at {}): there is no surface to build",
                display_name(input).display(),
                points.len(),
                coordinates(points[0])
            ),
            Spread::OneLine => bail!(
                "{}: all {} grid points lie on one straight line: there is no surface to build",
                display_name(input).display(),
                points.len()
            ),
            Spread::Surface => {}
        }
    }
    Ok(())
}

/// `x,y[,z]` of a point.
fn coordinates<const D: usize>(p: Point<D>) -> String {
    p.0.iter()
        .map(|c| c.to_string())
        .collect::<Vec<_>>()
        .join(",")
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn spread_of_points() {
        let p = |x: f64, y: f64, z: f64| Point([x, y, z]);
        assert_eq!(spread(&[p(1., 1., 1.); 4]), Spread::OnePoint);
        let line: Vec<_> = (0..5).map(|k| p(k as f64, 2.0 * k as f64, 1e150)).collect();
        assert_eq!(spread(&line), Spread::OneLine);
        let tiny: Vec<_> = (0..5)
            .map(|k| p(1e-150 * k as f64, 1e-150 * (k * k) as f64, 0.0))
            .collect();
        assert_eq!(spread(&tiny), Spread::Surface);
        assert_eq!(spread::<3>(&[]), Spread::OnePoint);
    }

    #[test]
    fn standard_input_is_read_once() {
        let p = Path::new;
        assert!(one_standard_input(&[("A", p("-")), ("B", p("b.csv"))]).is_ok());
        let e = one_standard_input(&[("A", p("-")), ("B", p("-"))]).unwrap_err();
        assert!(
            e.to_string()
                .starts_with("A and B both name standard input"),
            "{e}"
        );
    }
}

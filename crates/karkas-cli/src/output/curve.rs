//! A sampled curve as a picture (`.svg`, `.png`: x-y projection, with an optional curvature
//! comb and whiskers) or the 3-D viewer page (`.html`).

use super::memory::check_memory;
use super::target::shown;
use anyhow::Result;
use karkas::{Point, Point2};
use karkas_io::picture::budget;
use karkas_io::svg::CurveOverlay;
use karkas_io::viewer::PAGE_POINT;
use karkas_io::OutputFormat;
use std::path::Path;

pub use karkas_io::export::curve::{curvature_comb, to_space};

/// Writes the samples `ts`, `curve` of a curve in `format`: the `t,x,y[,z]` CSV, else as
/// [`write_curve_figure`] does with the curvature comb and whiskers `overlay`.
pub fn write_sampled_curve<const D: usize>(
    output: &Path,
    format: OutputFormat,
    title: &str,
    (ts, curve): (&[f64], &[Point<D>]),
    input: &[Point<D>],
    closed_input: bool,
    (comb, whiskers): (&[[Point2; 2]], &[[Point2; 2]]),
) -> Result<()> {
    if format == OutputFormat::Csv {
        return Ok(karkas_io::write::write_curve_csv(output, ts, curve)?);
    }
    let overlay = CurveOverlay { comb, whiskers };
    write_curve_figure(output, format, title, curve, input, closed_input, &overlay)
}

/// Writes a curve picture (`.svg`, `.png`: x-y projection, equal axis scales) or the viewer
/// page (`.html`, in space) of the samples `curve` over the `input` points.
pub fn write_curve_figure<const D: usize>(
    output: &Path,
    format: OutputFormat,
    title: &str,
    curve: &[Point<D>],
    input: &[Point<D>],
    closed_input: bool,
    overlay: &CurveOverlay<'_>,
) -> Result<()> {
    check_memory(
        &format!(
            "{}: a curve of {} points as {}",
            shown(output).display(),
            curve.len(),
            format.extension()
        ),
        figure_bytes::<D>(format, curve.len() + input.len(), overlay),
    )?;
    Ok(karkas_io::export::curve::write_curve_figure(
        output,
        format,
        title,
        curve,
        input,
        closed_input,
        overlay,
    )?)
}

/// What `points` samples of a curve (held as `Point<D>` with their parameters) take written in
/// `format`: checked by the commands before they sample.
pub fn curve_output_bytes<const D: usize>(format: OutputFormat, points: usize) -> u128 {
    figure_bytes::<D>(format, points, &CurveOverlay::default())
}

/// What drawing `points` points of a curve and its input (held as `Point<D>`, with their
/// parameters) in `format` takes: the points and their copies in space or in the plane, and
/// the picture or the page as their writers estimate them.
fn figure_bytes<const D: usize>(
    format: OutputFormat,
    points: usize,
    overlay: &CurveOverlay<'_>,
) -> u128 {
    let n = points as u128;
    let held = n * (8 + 8 * D as u128);
    let marks = 2 * (overlay.comb.len() + overlay.whiskers.len());
    match format {
        // Copies in space for the scene, and the scene's own.
        OutputFormat::Html => {
            held + n * 48 + n * PAGE_POINT + karkas_io::viewer::page_scripts_bytes()
        }
        OutputFormat::Png | OutputFormat::Svg => {
            held + n * 16 + budget::chart_bytes(points + marks, format == OutputFormat::Png)
        }
        _ => held,
    }
}

//! A sampled curve as a picture (`.svg`, `.png`: x-y projection, with an optional curvature
//! comb and whiskers) or the 3-D viewer page (`.html`).

use super::memory::check_memory;
use super::target::shown;
use anyhow::Result;
use karkas::{Curve, Point, Point2};
use karkas_io::export::curve as io;
use karkas_io::export::curve::CurveDrawing;
use karkas_io::export::samples::sample_curve;
use karkas_io::picture::budget;
use karkas_io::svg::CurveOverlay;
use karkas_io::viewer::PAGE_POINT;
use karkas_io::OutputFormat;
use std::path::Path;

pub use karkas_io::export::curve::{curvature_comb, to_space};

/// Writes the samples `ts`, `curve` of a curve in `format` as karkas-io's
/// [`write_sampled_curve`](io::write_sampled_curve) does, a picture or page after the memory
/// check of [`write_curve_figure`].
pub fn write_sampled_curve<const D: usize>(
    output: &Path,
    format: OutputFormat,
    title: &str,
    (ts, curve): (&[f64], &[Point<D>]),
    input: &[Point<D>],
    closed_input: bool,
    (comb, whiskers): (&[[Point2; 2]], &[[Point2; 2]]),
) -> Result<()> {
    if format != OutputFormat::Csv {
        let overlay = CurveOverlay { comb, whiskers };
        check_figure_memory::<D>(output, format, (curve.len(), input.len()), &overlay)?;
    }
    let (samples, overlay) = ((ts, curve), (comb, whiskers));
    Ok(io::write_sampled_curve(
        output,
        format,
        title,
        samples,
        input,
        closed_input,
        overlay,
    )?)
}

/// Samples `curve` at `n` uniform parameters and writes the samples in `format` as
/// [`write_sampled_curve`] does: drawn as `drawing` asks, with the `whiskers`.
pub fn write_curve_samples<const D: usize>(
    output: &Path,
    format: OutputFormat,
    (curve, n): (&impl Curve<D>, usize),
    drawing: &CurveDrawing<'_, D>,
    whiskers: &[[Point2; 2]],
) -> Result<()> {
    let (ts, samples) = sample_curve(curve, n);
    let comb = match drawing.comb {
        true => curvature_comb(curve, &ts),
        false => Vec::new(),
    };
    let (title, closed) = (drawing.title, drawing.closed_input);
    let overlay = (&comb[..], whiskers);
    write_sampled_curve(
        output,
        format,
        title,
        (&ts, &samples),
        drawing.input,
        closed,
        overlay,
    )
}

/// Whiskers (x-y projection) from every point `p` of `feet` to `curve` at its parameter `t`.
pub fn whiskers<'a, const D: usize>(
    curve: &impl Curve<D>,
    feet: impl IntoIterator<Item = (&'a Point<D>, f64)>,
) -> Vec<[Point2; 2]> {
    let flat = |p: Point<D>| Point2::new([p[0], p[1]]);
    feet.into_iter()
        .map(|(&p, t)| [flat(p), flat(curve.eval(t))])
        .collect()
}

/// Writes a curve picture or the viewer page as karkas-io's
/// [`write_curve_figure`](io::write_curve_figure) does, after a check that it fits in the
/// memory cap.
pub fn write_curve_figure<const D: usize>(
    output: &Path,
    format: OutputFormat,
    title: &str,
    curve: &[Point<D>],
    input: &[Point<D>],
    closed_input: bool,
    overlay: &CurveOverlay<'_>,
) -> Result<()> {
    check_figure_memory::<D>(output, format, (curve.len(), input.len()), overlay)?;
    Ok(io::write_curve_figure(
        output,
        format,
        title,
        curve,
        input,
        closed_input,
        overlay,
    )?)
}

/// Fails when a picture or page of a curve of `curve` samples over `input` points (with
/// `overlay`) in `format` would take more than the memory cap.
fn check_figure_memory<const D: usize>(
    output: &Path,
    format: OutputFormat,
    (curve, input): (usize, usize),
    overlay: &CurveOverlay<'_>,
) -> Result<()> {
    let name = shown(output);
    let request = format!(
        "{}: a curve of {curve} points as {}",
        name.display(),
        format.extension()
    );
    check_memory(&request, figure_bytes::<D>(format, curve + input, overlay))
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

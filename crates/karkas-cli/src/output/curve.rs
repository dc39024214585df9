//! A sampled curve as a picture (`.svg`, `.png`: x-y projection, with an optional curvature
//! comb and whiskers) or the 3-D viewer page (`.html`).

use super::memory::check_memory;
use super::target::shown;
use anyhow::{bail, Result};
use karkas::{Curve, Point, Point2, Point3};
use karkas_io::picture::budget;
use karkas_io::svg::{write_curve_picture, CurveOverlay, CurvePlot};
use karkas_io::viewer::PAGE_POINT;
use karkas_io::viewer::{write_viewer_html, ViewerCurve, ViewerScene};
use karkas_io::write::write_curve_csv;
use karkas_io::OutputFormat;
use std::path::Path;

/// The most teeth a curvature comb gets.
const COMB_TEETH: usize = 300;

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
        return Ok(write_curve_csv(output, ts, curve)?);
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
    match format {
        OutputFormat::Html => write_curve_html(output, title, &to_space(curve), &to_space(input)),
        OutputFormat::Svg | OutputFormat::Png => {
            let title = if D > 2 {
                format!("{title} (x-y projection)")
            } else {
                title.to_owned()
            };
            let plot = CurvePlot {
                title: &title,
                curve: &project(curve),
                input: &project(input),
                closed_input,
            };
            write_curve_picture(output, &plot, overlay, format == OutputFormat::Png)?;
            Ok(())
        }
        _ => bail!("internal: {} is not a curve picture", output.display()),
    }
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

/// Writes a curve (and its input points) as the viewer page at `output`.
pub fn write_curve_html(
    output: &Path,
    title: &str,
    curve: &[Point3],
    points: &[Point3],
) -> Result<()> {
    let scene = ViewerScene {
        title: title.to_owned(),
        curves: vec![ViewerCurve {
            name: title.to_owned(),
            points: curve.to_vec(),
        }],
        points: points.to_vec(),
        ..ViewerScene::default()
    };
    write_viewer_html(output, &scene)?;
    Ok(())
}

/// The curvature comb of the x-y projection of `curve` at (at most [`COMB_TEETH`] of) the
/// parameters `ts`: from each point, a tooth of length proportional to the signed curvature
/// `(x'y'' - y'x'') / |r'|^3`, along the normal away from the centre of curvature, the longest
/// tooth a sixth of the curve's extent.
pub fn curvature_comb<const D: usize>(curve: &impl Curve<D>, ts: &[f64]) -> Vec<[Point2; 2]> {
    let stride = ts.len().div_ceil(COMB_TEETH).max(1);
    let mut raw = Vec::new();
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for (k, &t) in ts.iter().enumerate() {
        let p = curve.eval(t);
        let p = Point2::new([p[0], p[1]]);
        for c in 0..2 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
        if k % stride != 0 && k + 1 != ts.len() {
            continue;
        }
        let (d1, d2) = (curve.deriv(t, 1), curve.deriv(t, 2));
        let speed = d1[0].hypot(d1[1]);
        if !(speed > 0.0 && speed.is_finite()) {
            continue;
        }
        let kappa = (d1[0] * d2[1] - d1[1] * d2[0]) / speed.powi(3);
        // Unit normal to the left of the direction of travel: the centre of curvature is at
        // p + n / kappa, so the tooth -kappa n points away from it.
        let n = Point2::new([-d1[1] / speed, d1[0] / speed]);
        if kappa.is_finite() {
            raw.push((p, n * (-kappa)));
        }
    }
    let extent = (hi[0] - lo[0]).max(hi[1] - lo[1]);
    let longest = raw.iter().map(|(_, v)| v.norm()).fold(0.0, f64::max);
    let scale = if longest > 0.0 && extent.is_finite() {
        extent / 6.0 / longest
    } else {
        0.0
    };
    raw.into_iter().map(|(p, v)| [p, p + v * scale]).collect()
}

/// The x-y projection of points of any dimension.
pub fn project<const D: usize>(points: &[Point<D>]) -> Vec<Point2> {
    points.iter().map(|p| Point2::new([p[0], p[1]])).collect()
}

/// Points of any dimension as points in space (`z = 0` for planar ones).
pub fn to_space<const D: usize>(points: &[Point<D>]) -> Vec<Point3> {
    points
        .iter()
        .map(|p| Point3::new([0, 1, 2].map(|c| if c < D { p[c] } else { 0.0 })))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A circle of radius 2 traversed counter-clockwise: curvature 1/2 everywhere, teeth
    /// pointing outwards, all of the same length (a sixth of the extent 4).
    #[test]
    fn comb_of_a_circle_points_outwards() {
        struct Circle;
        impl Curve<2> for Circle {
            fn domain(&self) -> karkas::Interval {
                karkas::Interval::new(0.0, std::f64::consts::TAU)
            }
            fn is_closed(&self) -> bool {
                true
            }
            fn eval(&self, t: f64) -> Point2 {
                Point2::new([2.0 * t.cos(), 2.0 * t.sin()])
            }
            fn deriv(&self, t: f64, k: usize) -> Point2 {
                match k % 4 {
                    0 => Point2::new([2.0 * t.cos(), 2.0 * t.sin()]),
                    1 => Point2::new([-2.0 * t.sin(), 2.0 * t.cos()]),
                    2 => Point2::new([-2.0 * t.cos(), -2.0 * t.sin()]),
                    _ => Point2::new([2.0 * t.sin(), -2.0 * t.cos()]),
                }
            }
        }
        // t = 0 and t = pi give x = +-2: the extent is 4.
        let ts: Vec<f64> = (0..=50)
            .map(|k| k as f64 * std::f64::consts::TAU / 50.0)
            .collect();
        let comb = curvature_comb(&Circle, &ts);
        assert_eq!(comb.len(), 51);
        for [p, tip] in comb {
            assert!((tip.norm() - (2.0 + 4.0 / 6.0)).abs() < 1e-9, "{tip:?}");
            assert!((p.norm() - 2.0).abs() < 1e-12);
        }
    }
}

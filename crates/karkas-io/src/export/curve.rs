//! A sampled curve as the `t,x,y[,z]` CSV, a picture (`.svg`, `.png`: x-y projection, with an
//! optional curvature comb and whiskers) or the 3-D viewer page (`.html`); a discrete periodic
//! curve's values as CSV, picture or page.

use super::samples::sample_curve;
use crate::picture::svg::{
    render_curve_svg_with, render_discrete_curve_svg, write_curve_picture,
    write_discrete_curve_svg, CurveOverlay, CurvePlot, DiscreteCurvePlot,
};
use crate::png::write_svg_as_png;
use crate::viewer::{render_viewer_html, write_viewer_html, ViewerCurve, ViewerScene};
use crate::write::{write_curve_csv, write_discrete_curve_csv};
use crate::{IoError, OutputFormat};
use karkas::{Curve, Point, Point2, Point3};
use std::path::Path;

/// The most teeth a curvature comb gets (the picture draws at most
/// `DRAWN_TEETH` (300) of them as lines, all as the envelope
/// through their tips, fine enough to show the curvature ripple of every piece of a curve
/// through a few hundred points).
pub const COMB_TEETH: usize = 1200;

/// The formats [`write_curve_figure`] draws.
const FIGURES: [OutputFormat; 3] = [OutputFormat::Svg, OutputFormat::Png, OutputFormat::Html];

/// What a picture of a curve shows besides the curve: its title, the input points (and
/// whether they close), and whether to draw the curvature comb.
#[derive(Debug, Clone, Copy)]
pub struct CurveDrawing<'a, const D: usize> {
    /// The caption of pictures and the page.
    pub title: &'a str,
    /// The input points, drawn over the curve.
    pub input: &'a [Point<D>],
    /// Whether the input polygon is closed.
    pub closed_input: bool,
    /// Whether pictures carry the curvature comb ([`curvature_comb`]).
    pub comb: bool,
}

/// Samples `curve` at `n` uniform parameters and writes the samples to `output` in `format`
/// (one of [`super::formats::CURVE_FORMATS`]): the `t,x,y[,z]` CSV, or as
/// [`write_curve_figure`] draws them, with the curvature comb when `drawing` asks for it.
pub fn write_curve<const D: usize>(
    curve: &impl Curve<D>,
    n: usize,
    format: OutputFormat,
    output: &Path,
    drawing: &CurveDrawing<'_, D>,
) -> Result<(), IoError> {
    let (ts, samples) = sample_curve(curve, n);
    let comb = if drawing.comb && format != OutputFormat::Csv {
        curvature_comb(curve, &ts)
    } else {
        Vec::new()
    };
    write_sampled_curve(
        output,
        format,
        drawing.title,
        (&ts, &samples),
        drawing.input,
        drawing.closed_input,
        (&comb, &[]),
    )
}

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
) -> Result<(), IoError> {
    if format == OutputFormat::Csv {
        return write_curve_csv(output, ts, curve);
    }
    let overlay = CurveOverlay { comb, whiskers };
    write_curve_figure(output, format, title, curve, input, closed_input, &overlay)
}

/// Writes a curve picture (`.svg`, `.png`: x-y projection, equal axis scales, titled
/// `"{title} (x-y projection)"` in space) or the viewer page (`.html`, in space) of the
/// samples `curve` over the `input` points.
pub fn write_curve_figure<const D: usize>(
    output: &Path,
    format: OutputFormat,
    title: &str,
    curve: &[Point<D>],
    input: &[Point<D>],
    closed_input: bool,
    overlay: &CurveOverlay<'_>,
) -> Result<(), IoError> {
    match format.allowed_for(output, &FIGURES)? {
        OutputFormat::Html => write_curve_html(output, title, &to_space(curve), &to_space(input)),
        format => {
            let title = picture_title::<D>(title);
            let plot = CurvePlot {
                title: &title,
                curve: &project(curve),
                input: &project(input),
                closed_input,
            };
            write_curve_picture(output, &plot, overlay, format == OutputFormat::Png)
        }
    }
}

/// The SVG picture [`write_curve`] writes as `.svg` (at most `n` samples), in memory.
pub fn render_curve_svg<const D: usize>(
    curve: &impl Curve<D>,
    n: usize,
    drawing: &CurveDrawing<'_, D>,
) -> Result<String, IoError> {
    let (ts, samples) = sample_curve(curve, n);
    let comb = if drawing.comb {
        curvature_comb(curve, &ts)
    } else {
        Vec::new()
    };
    let title = picture_title::<D>(drawing.title);
    let plot = CurvePlot {
        title: &title,
        curve: &project(&samples),
        input: &project(drawing.input),
        closed_input: drawing.closed_input,
    };
    let overlay = CurveOverlay {
        comb: &comb,
        whiskers: &[],
    };
    render_curve_svg_with(&plot, &overlay).map_err(IoError::picture(Path::new("<svg>")))
}

/// The caption of a picture: `title`, with `(x-y projection)` for curves in space.
fn picture_title<const D: usize>(title: &str) -> String {
    if D > 2 {
        format!("{title} (x-y projection)")
    } else {
        title.to_owned()
    }
}

/// The viewer scene of a curve (and its input points).
fn curve_scene(title: &str, curve: &[Point3], points: &[Point3]) -> ViewerScene {
    ViewerScene {
        title: title.to_owned(),
        curves: vec![ViewerCurve {
            name: title.to_owned(),
            points: curve.to_vec(),
        }],
        points: points.to_vec(),
        ..ViewerScene::default()
    }
}

/// Writes a curve (and its input points) as the viewer page at `output`.
pub fn write_curve_html(
    output: &Path,
    title: &str,
    curve: &[Point3],
    points: &[Point3],
) -> Result<(), IoError> {
    write_viewer_html(output, &curve_scene(title, curve, points))
}

/// The viewer page of a curve (and its input points), in memory.
pub fn render_curve_html(title: &str, curve: &[Point3], points: &[Point3]) -> String {
    render_viewer_html(&curve_scene(title, curve, points))
}

/// The titles of a discrete periodic curve's pictures and page.
#[derive(Debug, Clone, Copy)]
pub struct DiscreteTitles<'a> {
    /// The caption of `.svg` and `.png`.
    pub picture: &'a str,
    /// The caption of `.html`.
    pub page: &'a str,
}

/// Writes the values of a discrete periodic curve (one period) in `format`: the `k,x,y[,z]`
/// CSV, a picture of the closed polygon over the `input` points (x-y projection), or the
/// viewer page (the polygon closed by its first value).
pub fn write_discrete_curve<const D: usize>(
    output: &Path,
    format: OutputFormat,
    values: &[Point<D>],
    input: &[Point<D>],
    titles: &DiscreteTitles<'_>,
) -> Result<(), IoError> {
    match format.allowed_for(output, &super::formats::CURVE_FORMATS)? {
        OutputFormat::Svg | OutputFormat::Png => {
            let plot = DiscreteCurvePlot {
                title: titles.picture,
                values: &project(values),
                dots: false,
                input: &project(input),
            };
            if format == OutputFormat::Png {
                let svg = render_discrete_curve_svg(&plot).map_err(IoError::picture(output))?;
                write_svg_as_png(output, &svg)
            } else {
                write_discrete_curve_svg(output, &plot)
            }
        }
        OutputFormat::Html => {
            let mut closed = to_space(values);
            closed.extend(closed.first().copied());
            write_curve_html(output, titles.page, &closed, &to_space(input))
        }
        _ => write_discrete_curve_csv(output, values),
    }
}

/// The curvature comb of the x-y projection of `curve` over the parameters `ts` (increasing,
/// dense enough that the polygon through their points follows the curve): at most
/// [`COMB_TEETH`] teeth equally spaced along the polygon's length (so that a sharp nose with
/// many samples does not crowd the comb while long flat stretches go bare), each its foot `p`
/// on the curve and the curvature vector there, `-kappa n` with the signed curvature
/// `kappa = (x'y'' - y'x'') / |r'|^3` and `n` the unit normal to the left of the direction of
/// travel (so the vector points away from the centre of curvature and its length is
/// `|kappa|`). The picture scales the teeth
/// ([`ScaledComb`](crate::picture::comb::ScaledComb): a percentile of the lengths, which with
/// equally spaced teeth is a percentile along the arc, to a fixed fraction of the extent).
pub fn curvature_comb<const D: usize>(curve: &impl Curve<D>, ts: &[f64]) -> Vec<[Point2; 2]> {
    let plane = |t: f64| {
        let p = curve.eval(t);
        Point2::new([p[0], p[1]])
    };
    let samples: Vec<(f64, Point2)> = ts
        .iter()
        .map(|&t| (t, plane(t)))
        .filter(|(t, p)| t.is_finite() && p.is_finite())
        .collect();
    // The polygon's length at each sample.
    let mut lengths = Vec::with_capacity(samples.len());
    let mut total = 0.0;
    for (k, (_, p)) in samples.iter().enumerate() {
        if k > 0 {
            total += p.distance(samples[k - 1].1);
        }
        lengths.push(total);
    }
    let teeth = samples.len().min(COMB_TEETH + 1);
    if teeth < 2 || !(total > 0.0 && total.is_finite()) {
        return samples
            .iter()
            .filter_map(|&(t, p)| tooth(curve, t, p))
            .collect();
    }
    let mut segment = 0;
    (0..teeth)
        .filter_map(|j| {
            let target = total * j as f64 / (teeth - 1) as f64;
            while segment + 2 < samples.len() && lengths[segment + 1] < target {
                segment += 1;
            }
            let (l0, l1) = (lengths[segment], lengths[segment + 1]);
            let (t0, t1) = (samples[segment].0, samples[segment + 1].0);
            let f = if l1 > l0 {
                ((target - l0) / (l1 - l0)).clamp(0.0, 1.0)
            } else {
                0.0
            };
            let t = t0 + f * (t1 - t0);
            tooth(curve, t, plane(t))
        })
        .collect()
}

/// The tooth of the comb at `t`, where the curve's x-y projection is at `p`: `p` and the
/// curvature vector (none where the speed vanishes or the curvature is not finite).
fn tooth<const D: usize>(curve: &impl Curve<D>, t: f64, p: Point2) -> Option<[Point2; 2]> {
    let (d1, d2) = (curve.deriv(t, 1), curve.deriv(t, 2));
    let speed = d1[0].hypot(d1[1]);
    if !(speed > 0.0 && speed.is_finite() && p.is_finite()) {
        return None;
    }
    let kappa = (d1[0] * d2[1] - d1[1] * d2[0]) / speed.powi(3);
    // The centre of curvature is at p + n / kappa, so -kappa n points away from it.
    let n = Point2::new([-d1[1] / speed, d1[0] / speed]);
    kappa.is_finite().then(|| [p, n * (-kappa)])
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
    /// pointing outwards.
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
        for [p, vector] in comb {
            assert!((p.norm() - 2.0).abs() < 1e-12);
            // Outwards: along p, of length 1/2.
            assert!((vector - p * 0.25).norm() < 1e-12, "{vector:?} at {p:?}");
        }
    }
}

//! A picture of a planar curve over the points it was made from, as SVG.
//!
//! SVG because it opens in every browser and stays sharp at any zoom. Drawn on a
//! [`Chart`] into a string in memory (coordinates to a
//! hundredth of a pixel, ticks and labels in model units), then written with
//! [`write_atomic`]. The axes have equal scales (a circle looks round), so the picture shows
//! the true shape of the curve: the plot ranges are the bounding box of curve and points
//! padded by 5%, the height follows the aspect of the data (clamped to 300..1200 px at 900 px
//! width), and the shorter range is then enlarged until one unit is the same number of pixels
//! along both axes.
//!
//! The curve is a blue polyline, the input points small red circles joined by a thin grey
//! polygon (closed for a closed curve). A curvature comb is scaled to a percentile of its
//! teeth ([`ScaledComb`]), with the scale in the legend. For a spatial curve the caller passes
//! the projection it wants shown.

use std::path::Path;

use karkas::Point2;

use crate::error::IoError;
use crate::picture::budget;
use crate::picture::chart::{Chart, Frame, LegendEntry};
use crate::picture::comb::ScaledComb;
use crate::picture::error::PictureError;
use crate::write::write_atomic;

/// Colours: the curve, the input points, their polygon, comb teeth, clipped teeth, the comb's
/// envelope, whiskers, a reference curve.
const BLUE: (u8, u8, u8) = (0, 0, 255);
const RED: (u8, u8, u8) = (255, 0, 0);
const GREY: (u8, u8, u8) = (150, 150, 150);
const TEETH: (u8, u8, u8) = (120, 170, 120);
const CLIPPED: (u8, u8, u8) = (20, 90, 20);
const ENVELOPE: (u8, u8, u8) = (40, 140, 40);
const WHISKER: (u8, u8, u8) = (230, 120, 0);
const REFERENCE: (u8, u8, u8) = (0, 150, 60);

/// What to draw.
#[derive(Clone, Copy, Debug)]
pub struct CurvePlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// The sampled curve, drawn as a polyline.
    pub curve: &'a [Point2],
    /// The input points, drawn as circles joined by a polygon.
    pub input: &'a [Point2],
    /// True when the input polygon should be closed (last point joined to the first).
    pub closed_input: bool,
}

/// Optional additions to a curve picture.
#[derive(Clone, Copy, Debug, Default)]
pub struct CurveOverlay<'a> {
    /// A curvature comb: for each tooth its foot on the curve and the curvature vector there
    /// (length the curvature, pointing away from the centre of curvature), as
    /// [`curvature_comb`](crate::export::curve::curvature_comb) gives them. The picture scales
    /// the teeth ([`ScaledComb`]) and draws them thin, their tips joined by a line (the comb's
    /// envelope), with the scale in the legend.
    pub comb: &'a [[Point2; 2]],
    /// Deviation whiskers: from each input point to its point on the curve.
    pub whiskers: &'a [[Point2; 2]],
}

/// Draws `plot` and writes it as SVG to `path`, atomically.
pub fn write_curve_svg(path: &Path, plot: &CurvePlot<'_>) -> Result<(), IoError> {
    write_rendered(path, render_curve_svg(plot))
}

/// Draws `plot` with `overlay` and writes it to `path` atomically, as PNG when `png` is true,
/// otherwise as SVG.
pub fn write_curve_picture(
    path: &Path,
    plot: &CurvePlot<'_>,
    overlay: &CurveOverlay<'_>,
    png: bool,
) -> Result<(), IoError> {
    let points =
        plot.curve.len() + plot.input.len() + 2 * (overlay.comb.len() + overlay.whiskers.len());
    budget::check_output_memory(path, "the picture", budget::chart_bytes(points, png))?;
    let rendered = render_curve_svg_with(plot, overlay);
    if png {
        let svg = rendered.map_err(IoError::picture(path))?;
        crate::picture::png::write_svg_as_png(path, &svg)
    } else {
        write_rendered(path, rendered)
    }
}

/// Draws `plot` into an SVG document in memory.
pub fn render_curve_svg(plot: &CurvePlot<'_>) -> Result<String, PictureError> {
    render_curve_svg_with(plot, &CurveOverlay::default())
}

/// Draws `plot` with `overlay` into an SVG document in memory (the frame takes in the comb's
/// tips, so nothing is clipped).
pub fn render_curve_svg_with(
    plot: &CurvePlot<'_>,
    overlay: &CurveOverlay<'_>,
) -> Result<String, PictureError> {
    let comb = (!overlay.comb.is_empty()).then(|| {
        let feet: Vec<Point2> = overlay.comb.iter().map(|t| t[0]).collect();
        let extent = if plot.curve.is_empty() {
            extent(&feet)
        } else {
            extent(plot.curve)
        };
        ScaledComb::new(overlay.comb, extent)
    });
    let legend: Vec<LegendEntry> = comb
        .iter()
        .map(|c| LegendEntry {
            rgb: ENVELOPE,
            text: c.legend(),
        })
        .collect();
    let tips = comb.iter().flat_map(|c| c.teeth.iter().map(|t| t.0[1]));
    let whiskers = overlay.whiskers.iter().flatten().map(|p| (p[0], p[1]));
    let points = finite(plot.curve)
        .chain(finite(plot.input))
        .chain(tips)
        .chain(whiskers);
    let mut chart = Chart::new(
        plot.title,
        ("x", "y"),
        Frame::new(points, legend.len()),
        &legend,
    );
    let mut polygon: Vec<(f64, f64)> = finite(plot.input).collect();
    if plot.closed_input && polygon.len() > 2 {
        polygon.push(polygon[0]);
    }
    chart.polyline("polygon", polygon, GREY, 1.0);
    if let Some(comb) = &comb {
        for (tooth, clipped) in comb.drawn() {
            let (class, rgb) = if *clipped {
                ("comb-clipped", CLIPPED)
            } else {
                ("comb", TEETH)
            };
            chart.polyline(class, *tooth, rgb, 1.0);
        }
        let tips = comb.teeth.iter().map(|t| t.0[1]);
        chart.polyline("comb-envelope", tips, ENVELOPE, 1.0);
    }
    // The points under the curve, and small enough between their neighbours to leave it in
    // sight: the curve is never hidden by them.
    let radius = dot_radius(chart.frame(), plot.input);
    chart.dots("input", finite(plot.input), RED, radius);
    chart.polyline("curve", plot.curve.iter().map(|p| (p[0], p[1])), BLUE, 2.0);
    for w in overlay.whiskers {
        chart.polyline("whisker", w.map(|p| (p[0], p[1])), WHISKER, 2.0);
    }
    Ok(chart.finish())
}

/// The radius in pixels of the dots of the input `points` in `frame`: 3, or less where the
/// points crowd, a third of the median pixel distance between neighbours (at least 0.75), so
/// that a dense input leaves the curve through it in sight between its dots.
pub fn dot_radius(frame: &Frame, points: &[Point2]) -> f64 {
    let px: Vec<(f64, f64)> = finite(points).map(|p| frame.to_px(p)).collect();
    let mut gaps: Vec<f64> = px
        .windows(2)
        .map(|w| (w[1].0 - w[0].0).hypot(w[1].1 - w[0].1))
        .filter(|g| *g > 0.0)
        .collect();
    if gaps.is_empty() {
        return MAX_DOT_RADIUS;
    }
    let mid = gaps.len() / 2;
    gaps.select_nth_unstable_by(mid, f64::total_cmp);
    (gaps[mid] / 3.0).clamp(MIN_DOT_RADIUS, MAX_DOT_RADIUS)
}

/// The largest and smallest radius of an input dot, in pixels.
const MAX_DOT_RADIUS: f64 = 3.0;
const MIN_DOT_RADIUS: f64 = 0.75;

/// The larger side of the bounding box of the finite `points` (0 for none).
fn extent(points: &[Point2]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    for p in points.iter().filter(|p| p.is_finite()) {
        for c in 0..2 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (hi[0] - lo[0]).max(hi[1] - lo[1]).max(0.0)
}

/// A discrete curve (a closed sequence of points, such as the values of a discrete periodic
/// spline) over its poles or nodes.
#[derive(Clone, Copy, Debug)]
pub struct DiscreteCurvePlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// The values of the curve, in order; the last is joined to the first.
    pub values: &'a [Point2],
    /// Draw the values as dots (`true`) or as the closed polyline through them (`false`).
    pub dots: bool,
    /// The poles or nodes: red circles joined by a thin grey closed polygon.
    pub input: &'a [Point2],
}

/// Draws `plot` and writes it as SVG to `path`, atomically.
pub fn write_discrete_curve_svg(path: &Path, plot: &DiscreteCurvePlot<'_>) -> Result<(), IoError> {
    write_rendered(path, render_discrete_curve_svg(plot))
}

/// Draws `plot` into an SVG document in memory.
pub fn render_discrete_curve_svg(plot: &DiscreteCurvePlot<'_>) -> Result<String, PictureError> {
    if !plot.dots {
        let mut closed: Vec<Point2> = plot.values.to_vec();
        if let Some(&first) = plot.values.first() {
            closed.push(first);
        }
        return render_curve_svg(&CurvePlot {
            title: plot.title,
            curve: &closed,
            input: plot.input,
            closed_input: true,
        });
    }
    let points = finite(plot.values).chain(finite(plot.input));
    let mut chart = Chart::new(plot.title, ("x", "y"), Frame::new(points, 0), &[]);
    let mut polygon: Vec<(f64, f64)> = finite(plot.input).collect();
    if polygon.len() > 2 {
        polygon.push(polygon[0]);
    }
    chart.polyline("polygon", polygon, GREY, 1.0);
    chart.dots("values", finite(plot.values), BLUE, 2.0);
    chart.dots("input", finite(plot.input), RED, 4.0);
    Ok(chart.finish())
}

/// A wireframe: several polylines in one picture with equal axis scales (sections of a
/// surface, a projected 3-D view).
#[derive(Clone, Copy, Debug)]
pub struct LinesPlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// Names of the horizontal and vertical axes: the model axes, or for a projection the
    /// directions of the projection plane's axes in model terms (see
    /// [`View::axis_names`](crate::picture::scene::View::axis_names)).
    pub axes: (&'a str, &'a str),
    /// The groups of polylines, drawn in the order given.
    pub groups: &'a [LineGroup<'a>],
}

/// Polylines drawn in one colour.
#[derive(Clone, Copy, Debug)]
pub struct LineGroup<'a> {
    /// The polylines.
    pub lines: &'a [Vec<Point2>],
    /// Their colour as RGB.
    pub rgb: (u8, u8, u8),
    /// Their stroke width in pixels.
    pub width: u32,
}

/// Draws `plot` and writes it as SVG to `path`, atomically.
pub fn write_lines_svg(path: &Path, plot: &LinesPlot<'_>) -> Result<(), IoError> {
    write_rendered(path, render_lines_svg(plot))
}

/// Draws `plot` into an SVG document in memory.
pub fn render_lines_svg(plot: &LinesPlot<'_>) -> Result<String, PictureError> {
    let points = plot
        .groups
        .iter()
        .flat_map(|g| g.lines.iter())
        .flat_map(|l| finite(l));
    let mut chart = Chart::new(plot.title, plot.axes, Frame::new(points, 0), &[]);
    for group in plot.groups {
        for line in group.lines {
            let line = line.iter().map(|p| (p[0], p[1]));
            chart.polyline("line", line, group.rgb, f64::from(group.width));
        }
    }
    Ok(chart.finish())
}

/// A fit: the points, the fitted curve, and a whisker from every point to its foot point.
#[derive(Clone, Copy, Debug)]
pub struct FitPlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// The sampled curve, drawn as a polyline.
    pub curve: &'a [Point2],
    /// The data points, drawn as circles.
    pub points: &'a [Point2],
    /// The foot point of every data point on the curve (same length as `points`).
    pub feet: &'a [Point2],
    /// A reference curve drawn thin and green under the fit (the true contour where one is
    /// known); empty for none.
    pub reference: &'a [Point2],
}

/// Draws `plot` and writes it as SVG to `path`, atomically.
pub fn write_fit_svg(path: &Path, plot: &FitPlot<'_>) -> Result<(), IoError> {
    write_rendered(path, render_fit_svg(plot))
}

/// Draws `plot` into an SVG document in memory.
pub fn render_fit_svg(plot: &FitPlot<'_>) -> Result<String, PictureError> {
    let points = finite(plot.curve)
        .chain(finite(plot.points))
        .chain(finite(plot.reference));
    let mut chart = Chart::new(plot.title, ("x", "y"), Frame::new(points, 0), &[]);
    if !plot.reference.is_empty() {
        chart.polyline("reference", finite(plot.reference), REFERENCE, 1.0);
    }
    chart.polyline("curve", plot.curve.iter().map(|p| (p[0], p[1])), BLUE, 2.0);
    for (p, f) in plot.points.iter().zip(plot.feet) {
        chart.polyline("whisker", [(p[0], p[1]), (f[0], f[1])], WHISKER, 1.0);
    }
    chart.dots("input", finite(plot.points), RED, 3.0);
    Ok(chart.finish())
}

/// Writes a rendered picture to `path` atomically; a rendering error becomes an
/// [`IoError::Picture`] naming `path`, and nothing is written.
fn write_rendered(path: &Path, rendered: Result<String, PictureError>) -> Result<(), IoError> {
    let svg = rendered.map_err(IoError::picture(path))?;
    write_atomic(path, |out| out.write_all(svg.as_bytes()))
}

/// Width in pixels of pictures drawn with `plotters` on [`chart_builder`]'s layout (the same
/// as the charts of this module).
pub const WIDTH: u32 = 900;

/// The layout of pictures still drawn with `plotters` (caption, margins, label areas). Such
/// pictures get whole-pixel coordinates and plotters' tick labels; give their meshes
/// [`tick_label`](crate::picture::ticks::tick_label) as the label formatter to keep "-0" out.
pub fn chart_builder<'a, 'b, DB: plotters::prelude::DrawingBackend>(
    root: &'a plotters::prelude::DrawingArea<DB, plotters::coord::Shift>,
    title: &'b str,
) -> plotters::prelude::ChartBuilder<'a, 'b, DB> {
    let mut builder = plotters::prelude::ChartBuilder::on(root);
    builder
        .caption(title, ("sans-serif", 24))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(65);
    builder
}

/// The finite points of `points` as plotting coordinates (non-finite ones are left out).
pub(crate) fn finite(points: &[Point2]) -> impl Iterator<Item = (f64, f64)> + '_ {
    points
        .iter()
        .filter(|p| p.is_finite())
        .map(|p| (p[0], p[1]))
}

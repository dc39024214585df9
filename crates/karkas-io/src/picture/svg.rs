//! A picture of a planar curve over the points it was made from, as SVG.
//!
//! SVG because it opens in every browser and stays sharp at any zoom. Drawn with `plotters`
//! into a string in memory, then written with [`write_atomic`]. The axes have equal scales (a
//! circle looks round), so the picture shows the true shape of the curve: the plot ranges are
//! the bounding box of curve and points padded by 5%, the height follows the aspect of the
//! data (clamped to 300..1200 px at 900 px width), and the shorter range is then enlarged until
//! one unit is the same number of pixels along both axes.
//!
//! The curve is a blue polyline, the input points small red circles joined by a thin grey
//! polygon (closed for a closed curve). For a spatial curve the caller passes the projection
//! it wants shown.

use std::ops::Range;
use std::path::Path;

use karkas::Point2;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

use crate::error::IoError;
use crate::picture::budget;
use crate::picture::error::PictureError;
use crate::write::write_atomic;

/// Width of the picture in pixels.
pub(crate) const WIDTH: u32 = 900;
/// Smallest and largest height of the picture in pixels.
const HEIGHTS: Range<u32> = 300..1201;
/// Padding around the data, as a fraction of its extent.
const PADDING: f64 = 0.05;

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
    /// A curvature comb: teeth from curve points to their tips (drawn thin, the tips joined by
    /// a line, the comb's envelope).
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

/// Draws `plot` into an SVG document in memory; the error carries the drawing library's.
pub fn render_curve_svg(plot: &CurvePlot<'_>) -> Result<String, PictureError> {
    render_curve_svg_with(plot, &CurveOverlay::default())
}

/// Draws `plot` with `overlay` into an SVG document in memory (the frame takes in the comb's
/// tips, so nothing is clipped); the error carries the drawing library's.
pub fn render_curve_svg_with(
    plot: &CurvePlot<'_>,
    overlay: &CurveOverlay<'_>,
) -> Result<String, PictureError> {
    let overlays: Vec<Point2> = overlay
        .comb
        .iter()
        .chain(overlay.whiskers)
        .flatten()
        .copied()
        .collect();
    let points = finite(plot.curve)
        .chain(finite(plot.input))
        .chain(finite(&overlays));
    render_chart(plot.title, ("x", "y"), points, |chart| {
        let mut polygon: Vec<(f64, f64)> = finite(plot.input).collect();
        if plot.closed_input && polygon.len() > 2 {
            polygon.push(polygon[0]);
        }
        let grey = RGBColor(150, 150, 150);
        chart.draw_series(LineSeries::new(polygon, grey.stroke_width(1)))?;
        let teeth = RGBColor(120, 170, 120).stroke_width(1);
        for tooth in finite_segments(overlay.comb) {
            chart.draw_series(LineSeries::new(tooth, teeth))?;
        }
        if !overlay.comb.is_empty() {
            let tips = overlay.comb.iter().map(|t| t[1]).filter(|p| p.is_finite());
            chart.draw_series(LineSeries::new(
                tips.map(|p| (p[0], p[1])),
                RGBColor(40, 140, 40).stroke_width(1),
            ))?;
        }
        chart.draw_series(LineSeries::new(finite(plot.curve), BLUE.stroke_width(2)))?;
        let whisker = RGBColor(230, 120, 0).stroke_width(2);
        for w in finite_segments(overlay.whiskers) {
            chart.draw_series(LineSeries::new(w, whisker))?;
        }
        chart.draw_series(finite(plot.input).map(|p| Circle::new(p, 3, RED.filled())))?;
        Ok(())
    })
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

/// Draws `plot` into an SVG document in memory; the error carries the drawing library's.
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
    render_chart(plot.title, ("x", "y"), points, |chart| {
        let mut polygon: Vec<(f64, f64)> = finite(plot.input).collect();
        if polygon.len() > 2 {
            polygon.push(polygon[0]);
        }
        let grey = RGBColor(150, 150, 150);
        chart.draw_series(LineSeries::new(polygon, grey.stroke_width(1)))?;
        chart.draw_series(finite(plot.values).map(|p| Circle::new(p, 2, BLUE.filled())))?;
        chart.draw_series(finite(plot.input).map(|p| Circle::new(p, 4, RED.filled())))?;
        Ok(())
    })
}

/// A wireframe: several polylines in one picture with equal axis scales (sections of a
/// surface, a projected 3-D view).
#[derive(Clone, Copy, Debug)]
pub struct LinesPlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// Names of the horizontal and vertical axes.
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

/// Draws `plot` into an SVG document in memory; the error carries the drawing library's.
pub fn render_lines_svg(plot: &LinesPlot<'_>) -> Result<String, PictureError> {
    let all = plot
        .groups
        .iter()
        .flat_map(|g| g.lines.iter())
        .flat_map(|l| finite(l));
    let points = all;
    render_chart(plot.title, plot.axes, points, |chart| {
        for group in plot.groups {
            let (r, g, b) = group.rgb;
            let style = RGBColor(r, g, b).stroke_width(group.width);
            for line in group.lines {
                chart.draw_series(LineSeries::new(finite(line), style))?;
            }
        }
        Ok(())
    })
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

/// Draws `plot` into an SVG document in memory; the error carries the drawing library's.
pub fn render_fit_svg(plot: &FitPlot<'_>) -> Result<String, PictureError> {
    let points = finite(plot.curve)
        .chain(finite(plot.points))
        .chain(finite(plot.reference));
    render_chart(plot.title, ("x", "y"), points, |chart| {
        if !plot.reference.is_empty() {
            let green = RGBColor(0, 150, 60).stroke_width(1);
            chart.draw_series(LineSeries::new(finite(plot.reference), green))?;
        }
        chart.draw_series(LineSeries::new(finite(plot.curve), BLUE.stroke_width(2)))?;
        let whisker = RGBColor(230, 120, 0).stroke_width(1);
        for (p, f) in plot.points.iter().zip(plot.feet) {
            if p.is_finite() && f.is_finite() {
                chart.draw_series(LineSeries::new([(p[0], p[1]), (f[0], f[1])], whisker))?;
            }
        }
        chart.draw_series(finite(plot.points).map(|p| Circle::new(p, 3, RED.filled())))?;
        Ok(())
    })
}

/// The chart every picture of this module draws on.
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Renders a picture with equal axis scales over `points`: white background, caption, a mesh
/// with the axis names `axes`; `draw` adds the series (its error is the drawing library's
/// message).
fn render_chart(
    title: &str,
    axes: (&str, &str),
    points: impl Iterator<Item = (f64, f64)>,
    draw: impl FnOnce(&mut Chart<'_, '_>) -> Result<(), PictureError>,
) -> Result<String, PictureError> {
    let frame = Frame::new(title, points)?;
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, frame.height)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = chart_builder(&root, title).build_cartesian_2d(frame.x, frame.y)?;
        chart
            .configure_mesh()
            .x_desc(axes.0)
            .y_desc(axes.1)
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 18))
            .draw()?;
        draw(&mut chart)?;
        root.present()?;
    }
    Ok(svg)
}

/// Writes a rendered picture to `path` atomically; a rendering error becomes an
/// [`IoError::Picture`] naming `path`, and nothing is written.
fn write_rendered(path: &Path, rendered: Result<String, PictureError>) -> Result<(), IoError> {
    let svg = rendered.map_err(IoError::picture(path))?;
    write_atomic(path, |out| out.write_all(svg.as_bytes()))
}

/// The chart layout shared by the measuring pass and the real drawing.
pub(crate) fn chart_builder<'a, 'b, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, plotters::coord::Shift>,
    title: &'b str,
) -> ChartBuilder<'a, 'b, DB> {
    let mut builder = ChartBuilder::on(root);
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

/// The segments of `segments` with both ends finite, as plot coordinates.
fn finite_segments(segments: &[[Point2; 2]]) -> impl Iterator<Item = [(f64, f64); 2]> + '_ {
    let finite = |t: &&[Point2; 2]| t.iter().all(|p| p.is_finite());
    segments
        .iter()
        .filter(finite)
        .map(|t| t.map(|p| (p[0], p[1])))
}

/// Picture height and plot ranges with equal axis scales.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Frame {
    pub height: u32,
    pub x: Range<f64>,
    pub y: Range<f64>,
}

impl Frame {
    /// The frame of a picture titled `title` showing `points`.
    pub fn new(
        title: &str,
        points: impl Iterator<Item = (f64, f64)>,
    ) -> Result<Frame, PictureError> {
        let (x, y) = padded_bounds(points);
        let (x_len, y_len) = (x.end - x.start, y.end - y.start);
        // Everything but the plotting area (caption, labels, margins) has a fixed size: measure
        // it once, then choose the height that gives the plotting area the data's aspect.
        let (plot_w, plot_h) = plotting_area(title, 600)?;
        let overhead = 600 - plot_h.min(600);
        let wanted = f64::from(plot_w) * y_len / x_len + f64::from(overhead);
        let height = (wanted.round() as u32).clamp(HEIGHTS.start, HEIGHTS.end - 1);
        let (plot_w, plot_h) = plotting_area(title, height)?;
        let (plot_w, plot_h) = (f64::from(plot_w.max(1)), f64::from(plot_h.max(1)));
        // Enlarge the shorter range (about its middle) to equal units per pixel.
        let (x, y) = if y_len / x_len < plot_h / plot_w {
            (x, widen(y, x_len * plot_h / plot_w))
        } else {
            (widen(x, y_len * plot_w / plot_h), y)
        };
        Ok(Frame { height, x, y })
    }
}

/// Size in pixels of the plotting area of a picture `height` pixels high.
fn plotting_area(title: &str, height: u32) -> Result<(u32, u32), PictureError> {
    let mut scratch = String::new();
    let root = SVGBackend::with_string(&mut scratch, (WIDTH, height)).into_drawing_area();
    let chart = chart_builder(&root, title).build_cartesian_2d(0.0..1.0, 0.0..1.0)?;
    Ok(chart.plotting_area().dim_in_pixel())
}

/// The bounding box of `points` padded by [`PADDING`]; a degenerate extent is opened to the
/// other one (or to 1 for a single point, or the unit square for none).
fn padded_bounds(points: impl Iterator<Item = (f64, f64)>) -> (Range<f64>, Range<f64>) {
    let mut lo = (f64::INFINITY, f64::INFINITY);
    let mut hi = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for (x, y) in points {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    }
    if lo.0 > hi.0 {
        return (0.0..1.0, 0.0..1.0);
    }
    let (mut x_len, mut y_len) = (hi.0 - lo.0, hi.1 - lo.1);
    let fallback = x_len.max(y_len);
    let fallback = if fallback > 0.0 && fallback.is_finite() {
        fallback
    } else {
        1.0
    };
    if x_len <= 0.0 || !x_len.is_finite() {
        x_len = fallback;
    }
    if y_len <= 0.0 || !y_len.is_finite() {
        y_len = fallback;
    }
    let centre = (0.5 * lo.0 + 0.5 * hi.0, 0.5 * lo.1 + 0.5 * hi.1);
    let half = (0.5 + PADDING) * x_len;
    let x = centre.0 - half..centre.0 + half;
    let half = (0.5 + PADDING) * y_len;
    (x, centre.1 - half..centre.1 + half)
}

/// `range` widened about its middle to `length`.
fn widen(range: Range<f64>, length: f64) -> Range<f64> {
    let centre = 0.5 * range.start + 0.5 * range.end;
    centre - 0.5 * length..centre + 0.5 * length
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_padded_and_never_empty() {
        let (x, y) = padded_bounds([(0.0, 0.0), (10.0, 2.0)].into_iter());
        assert!((x.start + 0.5).abs() < 1e-12 && (x.end - 10.5).abs() < 1e-12);
        assert!((y.start + 0.1).abs() < 1e-12 && (y.end - 2.1).abs() < 1e-12);
        let (x, y) = padded_bounds([(3.0, 3.0)].into_iter());
        assert!(x.end > x.start && y.end > y.start);
        assert_eq!(padded_bounds(std::iter::empty()), (0.0..1.0, 0.0..1.0));
    }

    #[test]
    fn tall_data_gets_a_tall_picture_within_limits() {
        let tall = [Point2::new([0.0, 0.0]), Point2::new([1.0, 100.0])];
        let plot = CurvePlot {
            title: "t",
            curve: &tall,
            input: &[],
            closed_input: false,
        };
        let frame = Frame::new(plot.title, finite(plot.curve)).unwrap();
        assert_eq!(frame.height, 1200);
        assert!(frame.x.end - frame.x.start > 10.0);
    }
}

//! A chart with equal axis scales, written as SVG text: caption, legend, frame, grid, ticks
//! and tick labels in model units, axis names, and the data in pixel coordinates with two
//! decimals (a hundredth of a pixel: a 900-pixel picture resolves about 1e-5 of its width,
//! and a zoomed section stays smooth).
//!
//! Written by hand rather than through `plotters`: plotters rounds every coordinate to whole
//! pixels, which turns a zoomed airfoil into a staircase. The layout is fixed: the plotting
//! area is [`WIDTH`] minus the margins wide, its height follows the aspect of the data
//! (the picture's height clamped to [`HEIGHTS`]), and the shorter range is then enlarged about
//! its middle until one model unit is the same number of pixels along both axes.
//!
//! Every element a reader (or a test) may look for carries a class: `tick-x`, `tick-y` (the
//! tick labels, at the tick's exact position), `axis-x`, `axis-y` (the axis names), `legend`,
//! and whatever class the caller gives a series.

use std::fmt::Write as _;

use crate::picture::text::escape;
use crate::picture::ticks::{tick_label, tick_values};

pub use crate::picture::text::Px;

/// Width of the picture in pixels.
pub const WIDTH: f64 = 900.0;
/// Smallest and largest height of the picture in pixels.
pub const HEIGHTS: (f64, f64) = (300.0, 1200.0);
/// Padding around the data, as a fraction of its extent.
pub const PADDING: f64 = 0.05;
/// Margins around the plotting area: left (tick labels and the vertical axis name), right,
/// top (the caption; each legend line adds [`LEGEND_LINE`]) and bottom (tick labels and the
/// horizontal axis name).
const LEFT: f64 = 84.0;
const RIGHT: f64 = 24.0;
const TOP: f64 = 52.0;
const BOTTOM: f64 = 62.0;
/// Height of one legend line in pixels.
const LEGEND_LINE: f64 = 20.0;
/// Least distance between ticks in pixels, horizontally and vertically.
const TICK_GAP: (f64, f64) = (80.0, 50.0);

/// One legend entry: a swatch of a colour and a text.
#[derive(Clone, Debug)]
pub struct LegendEntry {
    /// The swatch colour as RGB.
    pub rgb: (u8, u8, u8),
    /// The text.
    pub text: String,
}

/// The mapping from model units to pixels and the picture's size.
#[derive(Clone, Debug, PartialEq)]
pub struct Frame {
    /// Picture width and height in pixels.
    pub size: (f64, f64),
    /// The model range shown along x and along y.
    pub x: (f64, f64),
    /// See `x`.
    pub y: (f64, f64),
    /// Pixels per model unit (both axes).
    pub scale: f64,
    /// Pixel position of the plotting area's top left corner.
    pub origin: (f64, f64),
}

impl Frame {
    /// The frame showing `points` (their bounding box padded by [`PADDING`]) with equal
    /// scales, with `legend_lines` lines of legend under the caption.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::picture::chart::Frame;
    ///
    /// let frame = Frame::new([(0.0, 0.0), (2.0, 1.0)].into_iter(), 0);
    /// let (left, right) = (frame.to_px((0.0, 0.0)), frame.to_px((2.0, 0.0)));
    /// assert!(right.0 > left.0 && (right.1 - left.1).abs() < 1e-9); // x grows to the right
    /// ```
    pub fn new(points: impl Iterator<Item = (f64, f64)>, legend_lines: usize) -> Frame {
        let (x, y) = padded_bounds(points);
        let top = TOP + LEGEND_LINE * legend_lines as f64;
        let plot_w = WIDTH - LEFT - RIGHT;
        let (x_len, y_len) = (x.1 - x.0, y.1 - y.0);
        let height = (plot_w * y_len / x_len + top + BOTTOM).clamp(HEIGHTS.0, HEIGHTS.1);
        let plot_h = height - top - BOTTOM;
        // Enlarge the shorter range (about its middle) to equal units per pixel.
        let (x, y) = if y_len / x_len < plot_h / plot_w {
            (x, widen(y, x_len * plot_h / plot_w))
        } else {
            (widen(x, y_len * plot_w / plot_h), y)
        };
        Frame {
            size: (WIDTH, height),
            x,
            y,
            scale: plot_w / (x.1 - x.0),
            origin: (LEFT, top),
        }
    }

    /// The pixel position of the model point `(x, y)`.
    pub fn to_px(&self, (x, y): (f64, f64)) -> (f64, f64) {
        (
            self.origin.0 + (x - self.x.0) * self.scale,
            self.origin.1 + (self.y.1 - y) * self.scale,
        )
    }

    /// The plotting area's size in pixels.
    pub fn area(&self) -> (f64, f64) {
        (
            (self.x.1 - self.x.0) * self.scale,
            (self.y.1 - self.y.0) * self.scale,
        )
    }
}

/// An SVG chart being written.
pub struct Chart {
    frame: Frame,
    svg: String,
}

impl Chart {
    /// Starts a chart titled `title` over `frame`: background, caption, `legend`, grid,
    /// ticks, tick labels and the axis names `axes`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::picture::chart::{Chart, Frame, LegendEntry};
    ///
    /// let frame = Frame::new([(0.0, 0.0), (1.0, 1.0)].into_iter(), 1);
    /// let legend = [LegendEntry { rgb: (0, 0, 255), text: "curve".into() }];
    /// let svg = Chart::new("A title", ("x", "y"), frame, &legend).finish();
    /// assert!(svg.starts_with("<svg") && svg.contains("A title") && svg.trim_end().ends_with("</svg>"));
    /// ```
    pub fn new(title: &str, axes: (&str, &str), frame: Frame, legend: &[LegendEntry]) -> Chart {
        let (w, h) = frame.size;
        let mut svg = String::with_capacity(16 * 1024);
        let _ = write!(
            svg,
            r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}"><rect width="100%" height="100%" fill="white"/><text x="{cx}" y="32" font-family="sans-serif" font-size="22" text-anchor="middle">{}</text>"#,
            escape(title),
            cx = Px(w / 2.0),
        );
        for (k, entry) in legend.iter().enumerate() {
            let y = TOP + LEGEND_LINE * k as f64 + 8.0;
            let (r, g, b) = entry.rgb;
            let _ = write!(
                svg,
                r#"<line x1="{x0}" y1="{y1}" x2="{x1}" y2="{y1}" stroke="rgb({r},{g},{b})" stroke-width="3"/><text class="legend" x="{tx}" y="{y}" font-family="sans-serif" font-size="14">{}</text>"#,
                escape(&entry.text),
                x0 = Px(LEFT),
                x1 = Px(LEFT + 24.0),
                y1 = Px(y - 5.0),
                tx = Px(LEFT + 32.0),
                y = Px(y),
            );
        }
        let mut chart = Chart { frame, svg };
        chart.axes(axes);
        chart
    }

    /// The frame.
    pub fn frame(&self) -> &Frame {
        &self.frame
    }

    /// Grid, frame, ticks, tick labels and axis names.
    fn axes(&mut self, (x_name, y_name): (&str, &str)) {
        let f = self.frame.clone();
        let (ox, oy) = f.origin;
        let (aw, ah) = f.area();
        let (xs, x_step) = tick_values(f.x, f.scale, TICK_GAP.0);
        let (ys, y_step) = tick_values(f.y, f.scale, TICK_GAP.1);
        let svg = &mut self.svg;
        svg.push_str(r#"<g stroke="rgb(232,232,232)" stroke-width="1">"#);
        for &v in &xs {
            let x = f.to_px((v, 0.0)).0;
            let _ = write!(
                svg,
                r#"<line x1="{x}" y1="{y0}" x2="{x}" y2="{y1}"/>"#,
                x = Px(x),
                y0 = Px(oy),
                y1 = Px(oy + ah)
            );
        }
        for &v in &ys {
            let y = f.to_px((0.0, v)).1;
            let _ = write!(
                svg,
                r#"<line x1="{x0}" y1="{y}" x2="{x1}" y2="{y}"/>"#,
                y = Px(y),
                x0 = Px(ox),
                x1 = Px(ox + aw)
            );
        }
        svg.push_str("</g>");
        let _ = write!(
            svg,
            r#"<rect x="{ox}" y="{oy}" width="{aw}" height="{ah}" fill="none" stroke="black" stroke-width="1"/>"#,
            ox = Px(ox),
            oy = Px(oy),
            aw = Px(aw),
            ah = Px(ah)
        );
        svg.push_str(r#"<g font-family="sans-serif" font-size="14" fill="black">"#);
        for &v in &xs {
            let x = f.to_px((v, 0.0)).0;
            let _ = write!(
                svg,
                r#"<line x1="{x}" y1="{y0}" x2="{x}" y2="{y1}" stroke="black"/><text class="tick-x" x="{x}" y="{ty}" text-anchor="middle">{}</text>"#,
                tick_label(v, x_step),
                x = Px(x),
                y0 = Px(oy + ah),
                y1 = Px(oy + ah + 5.0),
                ty = Px(oy + ah + 21.0),
            );
        }
        for &v in &ys {
            let y = f.to_px((0.0, v)).1;
            let _ = write!(
                svg,
                r#"<line x1="{x0}" y1="{y}" x2="{x1}" y2="{y}" stroke="black"/><text class="tick-y" x="{tx}" y="{y}" dy="5" text-anchor="end">{}</text>"#,
                tick_label(v, y_step),
                y = Px(y),
                x0 = Px(ox - 5.0),
                x1 = Px(ox),
                tx = Px(ox - 8.0),
            );
        }
        let _ = write!(
            svg,
            r#"<text class="axis-x" x="{x}" y="{y}" font-size="17" text-anchor="middle">{}</text><text class="axis-y" transform="translate({yx},{yy}) rotate(-90)" font-size="17" text-anchor="middle">{}</text></g>"#,
            escape(x_name),
            escape(y_name),
            x = Px(ox + aw / 2.0),
            y = Px(oy + ah + 48.0),
            yx = Px(22.0),
            yy = Px(oy + ah / 2.0),
        );
    }

    /// Draws a polyline through the finite points of `points` (a non-finite point breaks it)
    /// with class `class`.
    pub fn polyline(
        &mut self,
        class: &str,
        points: impl IntoIterator<Item = (f64, f64)>,
        (r, g, b): (u8, u8, u8),
        width: f64,
    ) {
        let mut run: Vec<(f64, f64)> = Vec::new();
        let flush = |run: &mut Vec<(f64, f64)>, svg: &mut String| {
            if run.len() >= 2 {
                let _ = write!(
                    svg,
                    r##"<polyline class="{class}" fill="none" stroke="#{r:02X}{g:02X}{b:02X}" stroke-width="{width}" stroke-linejoin="round" points=""##
                );
                for (k, &(x, y)) in run.iter().enumerate() {
                    let sep = if k == 0 { "" } else { " " };
                    let _ = write!(svg, "{sep}{},{}", Px(x), Px(y));
                }
                svg.push_str(r#""/>"#);
            }
            run.clear();
        };
        for p in points {
            if p.0.is_finite() && p.1.is_finite() {
                run.push(self.frame.to_px(p));
            } else {
                flush(&mut run, &mut self.svg);
            }
        }
        flush(&mut run, &mut self.svg);
    }

    /// Draws a filled circle of `radius` pixels at each finite point of `points`.
    pub fn dots(
        &mut self,
        class: &str,
        points: impl IntoIterator<Item = (f64, f64)>,
        (r, g, b): (u8, u8, u8),
        radius: f64,
    ) {
        let _ = write!(
            self.svg,
            r##"<g class="{class}" fill="#{r:02X}{g:02X}{b:02X}">"##
        );
        for p in points {
            if p.0.is_finite() && p.1.is_finite() {
                let (x, y) = self.frame.to_px(p);
                let _ = write!(
                    self.svg,
                    r#"<circle cx="{}" cy="{}" r="{radius}"/>"#,
                    Px(x),
                    Px(y)
                );
            }
        }
        self.svg.push_str("</g>");
    }

    /// The finished SVG document.
    pub fn finish(mut self) -> String {
        self.svg.push_str("</svg>\n");
        self.svg
    }
}

/// The bounding box of `points` padded by [`PADDING`]; a degenerate extent is opened to the
/// other one (or to 1 for a single point, or the unit square for none).
pub(crate) fn padded_bounds(points: impl Iterator<Item = (f64, f64)>) -> ((f64, f64), (f64, f64)) {
    let mut lo = (f64::INFINITY, f64::INFINITY);
    let mut hi = (f64::NEG_INFINITY, f64::NEG_INFINITY);
    for (x, y) in points.filter(|p| p.0.is_finite() && p.1.is_finite()) {
        lo = (lo.0.min(x), lo.1.min(y));
        hi = (hi.0.max(x), hi.1.max(y));
    }
    if lo.0 > hi.0 {
        return ((0.0, 1.0), (0.0, 1.0));
    }
    let (mut x_len, mut y_len) = (hi.0 - lo.0, hi.1 - lo.1);
    let fallback = x_len.max(y_len);
    let fallback = if fallback > 0.0 && fallback.is_finite() {
        fallback
    } else {
        (0.5 * lo.0.abs().max(lo.1.abs())).max(1.0)
    };
    if !(x_len > 0.0 && x_len.is_finite()) {
        x_len = fallback;
    }
    if !(y_len > 0.0 && y_len.is_finite()) {
        y_len = fallback;
    }
    let centre = (0.5 * lo.0 + 0.5 * hi.0, 0.5 * lo.1 + 0.5 * hi.1);
    let (hx, hy) = ((0.5 + PADDING) * x_len, (0.5 + PADDING) * y_len);
    (
        (centre.0 - hx, centre.0 + hx),
        (centre.1 - hy, centre.1 + hy),
    )
}

/// `range` widened about its middle to `length`.
fn widen(range: (f64, f64), length: f64) -> (f64, f64) {
    let centre = 0.5 * range.0 + 0.5 * range.1;
    (centre - 0.5 * length, centre + 0.5 * length)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_padded_and_never_empty() {
        let (x, y) = padded_bounds([(0.0, 0.0), (10.0, 2.0)].into_iter());
        assert!((x.0 + 0.5).abs() < 1e-12 && (x.1 - 10.5).abs() < 1e-12);
        assert!((y.0 + 0.1).abs() < 1e-12 && (y.1 - 2.1).abs() < 1e-12);
        let (x, y) = padded_bounds([(3.0, 3.0)].into_iter());
        assert!(x.1 > x.0 && y.1 > y.0);
        assert_eq!(padded_bounds(std::iter::empty()), ((0.0, 1.0), (0.0, 1.0)));
    }

    #[test]
    fn tall_data_gets_a_tall_picture_within_limits() {
        let frame = Frame::new([(0.0, 0.0), (1.0, 100.0)].into_iter(), 0);
        assert_eq!(frame.size.1, HEIGHTS.1);
        assert!(frame.x.1 - frame.x.0 > 10.0);
        let (w, h) = frame.area();
        assert!(((frame.x.1 - frame.x.0) / w - (frame.y.1 - frame.y.0) / h).abs() < 1e-12);
    }
}

//! A curvature plot: the curvature of one or more curves against their arc length, one
//! coloured line per curve with a legend, as SVG (or PNG rendered from it).
//!
//! Unlike the shape pictures of [`svg`](super::svg) the two axes have their own scales (a
//! curvature against a length). The length axis spans the data; the curvature axis spans the
//! 1st to the 97th percentile of all values, widened by a fifth, so that one sharp peak (an
//! airfoil's leading edge) does not flatten the ripples elsewhere: values beyond are drawn
//! at the border and the axis name says so. Drawn with `plotters` on the shared chart layout.

use std::ops::Range;
use std::path::Path;

use karkas::Point2;
use plotters::prelude::*;

use crate::error::IoError;
use crate::picture::error::PictureError;
use crate::picture::png::write_svg_as_png;
use crate::picture::svg::{chart_builder, finite, WIDTH};
use crate::picture::ticks::{nice_step, tick_label};
use crate::write::write_atomic;

/// Height of the picture in pixels.
const HEIGHT: u32 = 600;
/// Padding around the data, as a fraction of its extent.
const PADDING: f64 = 0.05;
/// The colours of the lines, in turn.
const COLOURS: [(u8, u8, u8); 6] = [
    (31, 119, 180),
    (214, 39, 40),
    (44, 160, 44),
    (148, 103, 189),
    (255, 127, 14),
    (23, 190, 207),
];

/// One curve's curvature: `(s, κ)` points in order along it.
#[derive(Clone, Copy, Debug)]
pub struct CurvatureLine<'a> {
    /// The name in the legend.
    pub label: &'a str,
    /// The points `(arc length, curvature)`.
    pub points: &'a [Point2],
}

/// What to draw.
#[derive(Clone, Copy, Debug)]
pub struct CurvaturePlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// The curves, drawn in the order given.
    pub lines: &'a [CurvatureLine<'a>],
}

/// The share of the values below the low and the high end of the curvature axis.
const PERCENTILES: (f64, f64) = (0.01, 0.97);
/// How much the percentile range is widened (as a share of its length, each side).
const WIDENING: f64 = 0.2;

/// The curvature axis for `values`: the [`PERCENTILES`] widened by [`WIDENING`], never
/// beyond the values' own range; and whether values are beyond it.
fn curvature_range(mut values: Vec<f64>) -> (f64, f64, bool) {
    values.sort_by(f64::total_cmp);
    let n = values.len();
    if n == 0 {
        return (f64::NAN, f64::NAN, false);
    }
    let at = |q: f64| values[((q * (n - 1) as f64).round() as usize).min(n - 1)];
    let (lo, hi) = (at(PERCENTILES.0), at(PERCENTILES.1));
    let widen = WIDENING * (hi - lo);
    let (lo, hi) = ((lo - widen).max(values[0]), (hi + widen).min(values[n - 1]));
    (lo, hi, lo > values[0] || hi < values[n - 1])
}

/// The step whose decimals label the ticks of `range` (plotters puts about ten ticks on an
/// axis; the labels go through [`tick_label`], so a tick at zero is never "-0").
fn label_step(range: &Range<f64>) -> f64 {
    let span = (range.end - range.start).abs();
    if span > 0.0 && span.is_finite() {
        nice_step(span / 10.0)
    } else {
        1.0
    }
}

/// `lo..hi` padded by [`PADDING`] (opened to a unit around a single value).
fn padded(lo: f64, hi: f64) -> Range<f64> {
    if !(lo.is_finite() && hi.is_finite()) || lo > hi {
        return 0.0..1.0;
    }
    let len = hi - lo;
    let pad = if len > 0.0 {
        PADDING * len
    } else {
        0.5 * lo.abs().max(1.0)
    };
    lo - pad..hi + pad
}

/// Draws `plot` into an SVG document in memory.
pub fn render_curvature_svg(plot: &CurvaturePlot<'_>) -> Result<String, PictureError> {
    let all = || plot.lines.iter().flat_map(|l| finite(l.points));
    let (mut lo, mut hi) = (
        (f64::INFINITY, f64::INFINITY),
        (f64::NEG_INFINITY, f64::NEG_INFINITY),
    );
    for (s, k) in all() {
        lo = (lo.0.min(s), lo.1.min(k));
        hi = (hi.0.max(s), hi.1.max(k));
    }
    let (k_lo, k_hi, clipped) = curvature_range(all().map(|p| p.1).collect());
    let (x, y) = (padded(lo.0, hi.0), padded(k_lo.max(lo.1), k_hi.min(hi.1)));
    let (y_lo, y_hi) = (y.start, y.end);
    let clamp = move |(s, k): (f64, f64)| (s, k.clamp(y_lo, y_hi));
    let y_desc = if clipped {
        "curvature (clipped to its 1st-97th percentile, widened)"
    } else {
        "curvature"
    };
    let (x_step, y_step) = (label_step(&x), label_step(&y));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, HEIGHT)).into_drawing_area();
        root.fill(&WHITE)?;
        let mut chart = chart_builder(&root, plot.title).build_cartesian_2d(x, y)?;
        chart
            .configure_mesh()
            .x_desc("arc length s")
            .y_desc(y_desc)
            .x_label_formatter(&|v| tick_label(*v, x_step))
            .y_label_formatter(&|v| tick_label(*v, y_step))
            .draw()?;
        for (line, &(r, g, b)) in plot.lines.iter().zip(COLOURS.iter().cycle()) {
            let colour = RGBColor(r, g, b);
            chart
                .draw_series(LineSeries::new(
                    finite(line.points).map(clamp),
                    colour.stroke_width(2),
                ))?
                .label(line.label)
                .legend(move |(x, y)| {
                    PathElement::new(vec![(x, y), (x + 20, y)], colour.stroke_width(2))
                });
        }
        chart
            .configure_series_labels()
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()?;
        root.present()?;
    }
    Ok(svg)
}

/// Draws `plot` and writes it to `path` atomically: as PNG when `png`, else as SVG.
pub fn write_curvature_picture(
    path: &Path,
    plot: &CurvaturePlot<'_>,
    png: bool,
) -> Result<(), IoError> {
    let svg = render_curvature_svg(plot).map_err(IoError::picture(path))?;
    if png {
        write_svg_as_png(path, &svg)
    } else {
        write_atomic(path, |out| out.write_all(svg.as_bytes()))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_line_has_its_legend_entry() {
        let a = [Point2::new([0.0, 1.0]), Point2::new([1.0, 2.0])];
        let b = [Point2::new([0.0, -1.0]), Point2::new([2.0, f64::NAN])];
        let lines = [
            CurvatureLine {
                label: "first-method",
                points: &a,
            },
            CurvatureLine {
                label: "second-method",
                points: &b,
            },
        ];
        let svg = render_curvature_svg(&CurvaturePlot {
            title: "k",
            lines: &lines,
        })
        .unwrap();
        assert!(svg.contains("first-method") && svg.contains("second-method"));
        assert!(svg.contains("arc length s"));
        let peak: Vec<Point2> = (0..200)
            .map(|i| Point2::new([i as f64, if i == 100 { 1e6 } else { (i % 2) as f64 }]))
            .collect();
        let lines = [CurvatureLine {
            label: "peak",
            points: &peak,
        }];
        let svg = render_curvature_svg(&CurvaturePlot {
            title: "k",
            lines: &lines,
        })
        .unwrap();
        assert!(svg.contains("clipped") && !svg.contains("1000000"));
        let empty = render_curvature_svg(&CurvaturePlot {
            title: "k",
            lines: &[],
        })
        .unwrap();
        assert!(empty.starts_with("<svg"));
    }

    /// The text of every `<text>` element of `svg`.
    fn texts(svg: &str) -> Vec<&str> {
        svg.split("<text")
            .skip(1)
            .filter_map(|t| {
                t.split_once('>')
                    .and_then(|(_, rest)| rest.split_once("</text>"))
            })
            .map(|(text, _)| text.trim())
            .collect()
    }

    #[test]
    fn a_curvature_axis_through_zero_has_no_negative_zero_label() {
        // Curvature from -0.3 to 0.7 (an inflection): ticks at ..., -0.2, 0, 0.2, ...
        let points: Vec<Point2> = (0..=100)
            .map(|i| Point2::new([0.01 * i as f64, -0.3 + 0.01 * i as f64]))
            .collect();
        let lines = [CurvatureLine {
            label: "s-curve",
            points: &points,
        }];
        let svg = render_curvature_svg(&CurvaturePlot {
            title: "k",
            lines: &lines,
        })
        .unwrap();
        let labels = texts(&svg);
        assert!(labels.contains(&"0.0"), "{labels:?}");
        assert!(labels.iter().any(|l| l.starts_with("-0.")), "{labels:?}");
        for label in labels {
            assert!(!matches!(label, "-0" | "-0.0" | "-0.00"), "{label}");
        }
    }
}

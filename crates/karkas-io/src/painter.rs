//! A shaded picture of a projected 3-D scene, as SVG: filled polygons and line segments drawn
//! from far to near (the painter's algorithm), so nearer parts hide farther ones.
//!
//! A wireframe of a closed surface shows its far side through its near side, and where a
//! surface passes in front of itself (a knotted tube) the picture cannot tell which part is in
//! front. Painting opaque faces far to near settles that with no more than a sort. The caller
//! projects (it chooses the view, as for [`crate::svg::LinesPlot`]) and gives each item its
//! depth along the viewing direction and its colour (shading is the caller's, too). Same frame
//! and equal axis scales as the other pictures of [`crate::svg`]; written with `plotters`.
//!
//! The painter's algorithm is exact for faces that do not overlap in depth; for the small faces
//! of a sampled surface its errors are a pixel or two along silhouettes.

use std::path::Path;

use karkas::Point2;
use plotters::prelude::*;

use crate::error::IoError;
use crate::svg::{chart_builder, finite, Frame, WIDTH};
use crate::write::write_atomic;

/// One thing to draw.
#[derive(Clone, Debug, PartialEq)]
pub enum SceneItem {
    /// A filled polygon with an outline.
    Polygon {
        /// The projected corners, in order.
        corners: Vec<Point2>,
        /// Distance along the viewing direction (larger is farther).
        depth: f64,
        /// Fill colour as RGB.
        fill: (u8, u8, u8),
        /// Outline colour as RGB (1 pixel wide).
        outline: (u8, u8, u8),
    },
    /// A line segment.
    Segment {
        /// The projected ends.
        ends: [Point2; 2],
        /// Distance along the viewing direction (larger is farther).
        depth: f64,
        /// Colour as RGB.
        rgb: (u8, u8, u8),
        /// Stroke width in pixels.
        width: u32,
    },
}

impl SceneItem {
    fn depth(&self) -> f64 {
        match self {
            SceneItem::Polygon { depth, .. } | SceneItem::Segment { depth, .. } => *depth,
        }
    }

    fn points(&self) -> &[Point2] {
        match self {
            SceneItem::Polygon { corners, .. } => corners,
            SceneItem::Segment { ends, .. } => ends,
        }
    }
}

/// What to draw.
#[derive(Clone, Copy, Debug)]
pub struct ScenePlot<'a> {
    /// The caption above the plot.
    pub title: &'a str,
    /// Names of the horizontal and vertical axes.
    pub axes: (&'a str, &'a str),
    /// The items, in any order (they are drawn far to near; a NaN depth is drawn last).
    pub items: &'a [SceneItem],
}

/// Draws `plot` and writes it as SVG to `path`, atomically.
pub fn write_scene_svg(path: &Path, plot: &ScenePlot<'_>) -> Result<(), IoError> {
    let svg = render_scene_svg(plot).map_err(|message| IoError::Write {
        path: path.to_path_buf(),
        source: std::io::Error::other(message),
    })?;
    write_atomic(path, |out| out.write_all(svg.as_bytes()))
}

/// Draws `plot` into an SVG document in memory; the error is the drawing library's message.
pub fn render_scene_svg(plot: &ScenePlot<'_>) -> Result<String, String> {
    let frame = Frame::new(
        plot.title,
        plot.items.iter().flat_map(|i| finite(i.points())),
    )?;
    let mut order: Vec<&SceneItem> = plot.items.iter().collect();
    // Far to near; total_cmp puts NaN depths after everything (drawn on top).
    order.sort_by(|a, b| b.depth().total_cmp(&a.depth()));
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (WIDTH, frame.height)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| e.to_string())?;
        let mut chart = chart_builder(&root, plot.title)
            .build_cartesian_2d(frame.x, frame.y)
            .map_err(|e| e.to_string())?;
        chart
            .configure_mesh()
            .disable_mesh()
            .x_desc(plot.axes.0)
            .y_desc(plot.axes.1)
            .label_style(("sans-serif", 15))
            .axis_desc_style(("sans-serif", 18))
            .draw()
            .map_err(|e| e.to_string())?;
        let rgb = |(r, g, b): (u8, u8, u8)| RGBColor(r, g, b);
        for item in order {
            let points: Vec<(f64, f64)> = finite(item.points()).collect();
            if points.len() < item.points().len() {
                continue; // a corner is not finite: leave the item out
            }
            match item {
                SceneItem::Polygon { fill, outline, .. } => {
                    chart
                        .draw_series(std::iter::once(Polygon::new(
                            points.clone(),
                            rgb(*fill).filled(),
                        )))
                        .map_err(|e| e.to_string())?;
                    let mut closed = points;
                    closed.push(closed[0]);
                    chart
                        .draw_series(LineSeries::new(closed, rgb(*outline).stroke_width(1)))
                        .map_err(|e| e.to_string())?;
                }
                SceneItem::Segment {
                    rgb: colour, width, ..
                } => {
                    chart
                        .draw_series(LineSeries::new(points, rgb(*colour).stroke_width(*width)))
                        .map_err(|e| e.to_string())?;
                }
            }
        }
        root.present().map_err(|e| e.to_string())?;
    }
    Ok(svg)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn near_items_are_drawn_last() {
        let square = |x: f64| {
            vec![
                Point2::new([x, 0.0]),
                Point2::new([x + 1.0, 0.0]),
                Point2::new([x + 1.0, 1.0]),
            ]
        };
        let items = [
            SceneItem::Polygon {
                corners: square(0.0),
                depth: 1.0,
                fill: (1, 2, 3),
                outline: (0, 0, 0),
            },
            SceneItem::Polygon {
                corners: square(0.5),
                depth: 5.0,
                fill: (4, 5, 6),
                outline: (0, 0, 0),
            },
        ];
        let svg = render_scene_svg(&ScenePlot {
            title: "t",
            axes: ("x", "y"),
            items: &items,
        })
        .unwrap();
        let far = svg.find("#040506").expect("far polygon drawn");
        let near = svg.find("#010203").expect("near polygon drawn");
        assert!(far < near, "the far polygon must be painted first");
    }
}

//! A picture of a surface in space with curves on it, hidden parts removed, as SVG.
//!
//! The surface is drawn as a shaded mesh seen by an orthographic camera (azimuth and
//! elevation), its cells painted from the farthest to the nearest (the painter's algorithm, by
//! the depth of each cell's centre), each shaded by the angle between its normal and a light
//! from the viewer's upper left. Curves lying on the surface (sections, say) are drawn over it,
//! but only where they are visible: the mesh is also rasterized into a depth buffer of the
//! picture's pixels, and a curve point is kept when it is not behind the surface at its pixel
//! (by more than a small fraction of the model's size, which absorbs the difference between
//! the mesh and the true surface).
//!
//! Under the drawing: a scale bar with ticks in model units (an orthographic view shows
//! lengths across the picture true), the picture's horizontal and vertical directions named
//! by the model axes ([`View::axis_names`]), and the model axes x, y, z as they appear.
//! Curves are written to a hundredth of a pixel, mesh cells to a tenth.
//!
//! The SVG is written directly rather than through `plotters`: plotters rounds every
//! coordinate to whole pixels, and a mesh of thousands of small cells needs sub-pixel
//! coordinates to look smooth. The rasterizer is a plain loop over each triangle's bounding
//! box: no crate offers a depth buffer for hidden-line removal of polylines over a mesh.

use std::fmt::Write as _;
use std::path::Path;

use karkas::{Point2, Point3};

use crate::error::IoError;
use crate::mesh::normals::cross;
use crate::picture::budget;
use crate::picture::png::write_svg_as_png;
use crate::picture::text::Px;
use crate::picture::ticks::{nice_step, tick_label, without_negative_zero};
use crate::write::write_atomic;

/// Width of the drawing area in pixels.
const DRAWING_WIDTH: f64 = 1100.0;
/// Smallest and largest height of the drawing area in pixels.
const DRAWING_HEIGHTS: (f64, f64) = (260.0, 1100.0);
/// Margins: left and right, above the drawing (the title), below it (the scale bar in model
/// units, the names of the picture's directions, the model axes and the legend).
const MARGIN: f64 = 20.0;
const TOP: f64 = 56.0;
const BOTTOM: f64 = 96.0;
/// Least distance between the scale bar's ticks, and its largest length, in pixels.
const RULER_GAP: f64 = 70.0;
const RULER_LENGTH: f64 = 420.0;
/// Length in pixels of a model axis lying in the picture plane, in the axes symbol.
const TRIAD: f64 = 32.0;
/// How far behind the surface (as a fraction of the model's size) a curve point may lie and
/// still be drawn: the mesh is only a chordal approximation of the surface.
const DEPTH_SLACK: f64 = 0.004;

/// The camera: looking at the model from the direction given by two angles in degrees.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct View {
    /// Angle about the z axis from +x towards +y of the direction to the viewer.
    pub azimuth: f64,
    /// Angle of the direction to the viewer above the x-y plane.
    pub elevation: f64,
}

impl View {
    /// The names of the picture's horizontal and vertical directions in model terms, such as
    /// `("0.26 x + 0.97 y", "-0.85 x + 0.23 y + 0.47 z")` (see [`direction_name`]); a view
    /// along a model axis gets plain names (`"x"`, `"-y"`).
    pub fn axis_names(&self) -> (String, String) {
        let (right, up, _) = self.frame();
        (direction_name(right), direction_name(up))
    }

    /// Unit vectors: screen right, screen up, towards the viewer.
    fn frame(&self) -> (Point3, Point3, Point3) {
        let (az, el) = (self.azimuth.to_radians(), self.elevation.to_radians());
        let toward = Point3::new([el.cos() * az.cos(), el.cos() * az.sin(), el.sin()]);
        let right = Point3::new([-az.sin(), az.cos(), 0.0]);
        let up = Point3::new([-el.sin() * az.cos(), -el.sin() * az.sin(), el.cos()]);
        (right, up, toward)
    }
}

/// The unit vector `d` as a combination of the model axes with two decimals, terms that
/// round to zero left out: `"x"`, `"-z"`, `"0.71 x + 0.71 y"`, `"-0.5 x - 0.87 z"`.
pub fn direction_name(d: Point3) -> String {
    let mut text = String::new();
    for (c, axis) in ["x", "y", "z"].into_iter().enumerate() {
        let v = (d[c] * 100.0).round() / 100.0;
        if v == 0.0 {
            continue;
        }
        let sign = if v < 0.0 { "-" } else { "+" };
        let size = v.abs();
        let coefficient = if size == 1.0 {
            String::new()
        } else {
            format!("{} ", format!("{size:.2}").trim_end_matches('0'))
        };
        if text.is_empty() {
            let sign = if v < 0.0 { "-" } else { "" };
            let _ = write!(text, "{sign}{coefficient}{axis}");
        } else {
            let _ = write!(text, " {sign} {coefficient}{axis}");
        }
    }
    if text.is_empty() {
        text.push('0');
    }
    text
}

/// A surface sampled on a `rows x cols` grid, row-major (as
/// [`Surface::sample_grid_into`](karkas::Surface::sample_grid_into) writes it).
#[derive(Clone, Copy, Debug)]
pub struct SceneMesh<'a> {
    /// Number of rows (samples along `u`).
    pub rows: usize,
    /// Number of columns (samples along `v`).
    pub cols: usize,
    /// The `rows * cols` points.
    pub points: &'a [Point3],
}

/// Curves drawn in one colour, with a label for the legend.
#[derive(Clone, Copy, Debug)]
pub struct SceneCurves<'a> {
    /// The legend text (empty: not in the legend).
    pub label: &'a str,
    /// The polylines (a closed curve repeats its first point at the end).
    pub lines: &'a [Vec<Point3>],
    /// Colour as RGB.
    pub rgb: (u8, u8, u8),
    /// Stroke width in pixels.
    pub width: f64,
}

/// What to draw.
#[derive(Clone, Copy, Debug)]
pub struct Scene<'a> {
    /// The caption above the picture.
    pub title: &'a str,
    /// The surface.
    pub mesh: SceneMesh<'a>,
    /// The curves on it, drawn in this order.
    pub curves: &'a [SceneCurves<'a>],
    /// The camera.
    pub view: View,
}

/// Draws `scene` and writes it to `path` as SVG, atomically.
pub fn write_scene_svg(path: &Path, scene: &Scene<'_>) -> Result<(), IoError> {
    check_scene(path, scene, false)?;
    let svg = render_scene_svg(scene);
    write_atomic(path, |out| out.write_all(svg.as_bytes()))
}

/// Draws `scene` and writes it to `path` as PNG, atomically.
pub fn write_scene_png(path: &Path, scene: &Scene<'_>) -> Result<(), IoError> {
    check_scene(path, scene, true)?;
    write_svg_as_png(path, &render_scene_svg(scene))
}

/// Refuses, before drawing, a scene whose picture would take more memory than the cap.
fn check_scene(path: &Path, scene: &Scene<'_>, png: bool) -> Result<(), IoError> {
    let curve_points = scene
        .curves
        .iter()
        .flat_map(|c| c.lines.iter())
        .map(Vec::len)
        .sum();
    let bytes = budget::scene_bytes(scene.mesh.rows, scene.mesh.cols, curve_points, png);
    budget::check_output_memory(path, "the picture", bytes)
}

/// Maps model points to picture pixels.
struct Camera {
    right: Point3,
    up: Point3,
    toward: Point3,
    /// Model units per pixel is `1 / scale`.
    scale: f64,
    /// Screen coordinates (model units) of the drawing area's top left corner.
    origin: Point2,
    /// Drawing area size in pixels.
    width: usize,
    height: usize,
}

impl Camera {
    /// Pixel position inside the drawing area and depth (larger is nearer).
    fn project(&self, p: Point3) -> (f64, f64, f64) {
        (
            (p.dot(self.right) - self.origin[0]) * self.scale,
            (self.origin[1] - p.dot(self.up)) * self.scale,
            p.dot(self.toward),
        )
    }
}

/// Draws `scene` into an SVG document in memory.
pub fn render_scene_svg(scene: &Scene<'_>) -> String {
    let mesh = scene.mesh;
    let mesh_points = if mesh.rows.checked_mul(mesh.cols) == Some(mesh.points.len()) {
        mesh.points
    } else {
        &[]
    };
    let (camera, height, size) = frame(scene, mesh_points);
    let picture = (DRAWING_WIDTH + 2.0 * MARGIN, height + TOP + BOTTOM);

    let mut svg = String::with_capacity(64 * mesh_points.len() + 4096);
    let _ = write!(
        svg,
        r#"<svg xmlns="http://www.w3.org/2000/svg" width="{w:.0}" height="{h:.0}" viewBox="0 0 {w:.0} {h:.0}">"#,
        w = picture.0,
        h = picture.1
    );
    let _ = write!(
        svg,
        r#"<rect width="100%" height="100%" fill="white"/><text x="{x:.1}" y="34" font-family="sans-serif" font-size="20" text-anchor="middle">{}</text>"#,
        escape(scene.title),
        x = picture.0 / 2.0
    );
    let _ = write!(svg, r#"<g transform="translate({MARGIN},{TOP})">"#);
    let cells = mesh_cells(mesh.rows, mesh.cols, mesh_points, &camera);
    write_cells(&mut svg, &cells);
    let depth = DepthBuffer::of_cells(&camera, &cells);
    let slack = DEPTH_SLACK * size;
    write_curves(&mut svg, scene.curves, &camera, &depth, slack);
    svg.push_str("</g>");
    write_scale_bar(&mut svg, &camera, scene.view, TOP + height + 16.0);
    write_triad(&mut svg, &camera, (picture.0 - 70.0, TOP + height + 50.0));
    write_legend(&mut svg, scene.curves, picture.1 - 16.0);
    svg.push_str("</svg>\n");
    svg
}

/// The camera that fits the finite `mesh_points` and the scene's curves into the drawing
/// area, the drawing area's height in pixels, and the size of the model (the largest distance
/// from its first point).
fn frame(scene: &Scene<'_>, mesh_points: &[Point3]) -> (Camera, f64, f64) {
    let (right, up, toward) = scene.view.frame();
    let all = mesh_points
        .iter()
        .chain(scene.curves.iter().flat_map(|c| c.lines.iter().flatten()))
        .filter(|p| p.is_finite());
    let (mut lo, mut hi) = ([f64::INFINITY; 2], [f64::NEG_INFINITY; 2]);
    let mut size = 0.0f64;
    let mut first = None;
    for &p in all {
        let s = [p.dot(right), p.dot(up)];
        for k in 0..2 {
            lo[k] = lo[k].min(s[k]);
            hi[k] = hi[k].max(s[k]);
        }
        let f = *first.get_or_insert(p);
        size = size.max(p.distance(f));
    }
    if lo[0] > hi[0] {
        (lo, hi) = ([0.0, 0.0], [1.0, 1.0]);
    }
    let extent = [(hi[0] - lo[0]).max(1e-300), (hi[1] - lo[1]).max(1e-300)];
    let pad = 0.03 * extent[0].max(extent[1]);
    let (ex, ey) = (extent[0] + 2.0 * pad, extent[1] + 2.0 * pad);
    let height = (DRAWING_WIDTH * ey / ex).clamp(DRAWING_HEIGHTS.0, DRAWING_HEIGHTS.1);
    let scale = (DRAWING_WIDTH / ex).min(height / ey);
    // Centre the model in the drawing area.
    let origin = Point2::new([
        0.5 * (lo[0] + hi[0]) - 0.5 * DRAWING_WIDTH / scale,
        0.5 * (lo[1] + hi[1]) + 0.5 * height / scale,
    ]);
    let camera = Camera {
        right,
        up,
        toward,
        scale,
        origin,
        width: DRAWING_WIDTH as usize,
        height: height.ceil() as usize,
    };
    (camera, height, size)
}

/// Draws the visible runs of every line of `curves`, a group of polylines a curve group.
fn write_curves(
    svg: &mut String,
    curves: &[SceneCurves<'_>],
    camera: &Camera,
    depth: &DepthBuffer,
    slack: f64,
) {
    for group in curves {
        let (r, g, b) = group.rgb;
        let _ = write!(
            *svg,
            r#"<g fill="none" stroke="rgb({r},{g},{b})" stroke-width="{:.2}" stroke-linejoin="round" stroke-linecap="round">"#,
            group.width
        );
        for line in group.lines {
            for run in visible_runs(line, camera, depth, slack) {
                svg.push_str(r#"<polyline points=""#);
                for (k, (x, y)) in run.iter().enumerate() {
                    let sep = if k == 0 { "" } else { " " };
                    let _ = write!(svg, "{sep}{},{}", Px(*x), Px(*y));
                }
                svg.push_str(r#""/>"#);
            }
        }
        svg.push_str("</g>");
    }
}

/// One mesh cell in pixels: corners, depth of its centre, grey level.
struct Cell {
    corners: [(f64, f64, f64); 4],
    depth: f64,
    shade: f64,
}

/// The projected, shaded cells of the mesh, farthest first.
fn mesh_cells(rows: usize, cols: usize, points: &[Point3], camera: &Camera) -> Vec<Cell> {
    // Light from the viewer's upper left.
    let light = (camera.toward * 0.8 + camera.up * 0.5 - camera.right * 0.35)
        * (1.0 / (0.8f64 * 0.8 + 0.5 * 0.5 + 0.35 * 0.35).sqrt());
    let mut cells = Vec::with_capacity(rows.saturating_sub(1) * cols.saturating_sub(1));
    for i in 0..rows.saturating_sub(1) {
        for j in 0..cols.saturating_sub(1) {
            let q = [
                points[i * cols + j],
                points[i * cols + j + 1],
                points[(i + 1) * cols + j + 1],
                points[(i + 1) * cols + j],
            ];
            if !q.iter().all(|p| p.is_finite()) {
                continue;
            }
            let normal = cross(q[2] - q[0], q[3] - q[1]);
            let length = normal.norm();
            let lambert = if length > 0.0 {
                (normal.dot(light) / length).abs()
            } else {
                0.5
            };
            let corners = q.map(|p| camera.project(p));
            let depth = corners.iter().map(|c| c.2).sum::<f64>() / 4.0;
            cells.push(Cell {
                corners,
                depth,
                shade: 0.35 + 0.65 * lambert,
            });
        }
    }
    cells.sort_by(|a, b| a.depth.total_cmp(&b.depth));
    cells
}

/// The cells as filled polygons (stroked in their own colour, so that no seams show).
fn write_cells(svg: &mut String, cells: &[Cell]) {
    svg.push_str(r#"<g stroke-width="0.6" stroke-linejoin="round">"#);
    for cell in cells {
        // A light blue-grey, darker where the light grazes.
        let c = |base: f64| (base * cell.shade).round().clamp(0.0, 255.0) as u8;
        let (r, g, b) = (c(214.0), c(222.0), c(236.0));
        let _ = write!(
            svg,
            r#"<polygon fill="rgb({r},{g},{b})" stroke="rgb({r},{g},{b})" points=""#
        );
        for (k, (x, y, _)) in cell.corners.iter().enumerate() {
            let sep = if k == 0 { "" } else { " " };
            let _ = write!(svg, "{sep}{x:.1},{y:.1}");
        }
        svg.push_str(r#""/>"#);
    }
    svg.push_str("</g>");
}

/// The nearest surface depth at every pixel of the drawing area.
struct DepthBuffer {
    width: usize,
    height: usize,
    depth: Vec<f64>,
}

impl DepthBuffer {
    fn of_cells(camera: &Camera, cells: &[Cell]) -> Self {
        let (width, height) = (camera.width, camera.height);
        let mut buffer = DepthBuffer {
            width,
            height,
            depth: vec![f64::NEG_INFINITY; width * height],
        };
        for cell in cells {
            let c = cell.corners;
            buffer.triangle([c[0], c[1], c[2]]);
            buffer.triangle([c[0], c[2], c[3]]);
        }
        buffer
    }

    /// Rasterizes one triangle (pixel centres inside it), keeping the nearest depth.
    fn triangle(&mut self, t: [(f64, f64, f64); 3]) {
        let area = (t[1].0 - t[0].0) * (t[2].1 - t[0].1) - (t[2].0 - t[0].0) * (t[1].1 - t[0].1);
        if area.abs() < 1e-12 {
            return;
        }
        let (xs, ys) = (t.map(|p| p.0), t.map(|p| p.1));
        let low =
            |v: [f64; 3]| v.into_iter().fold(f64::INFINITY, f64::min).floor().max(0.0) as usize;
        let high = |v: [f64; 3], limit: usize| {
            (v.into_iter().fold(f64::NEG_INFINITY, f64::max).ceil() as usize).min(limit)
        };
        let (x0, y0) = (low(xs), low(ys));
        let (x1, y1) = (high(xs, self.width), high(ys, self.height));
        for y in y0..y1 {
            for x in x0..x1 {
                let (px, py) = (x as f64 + 0.5, y as f64 + 0.5);
                let w0 = ((t[1].0 - px) * (t[2].1 - py) - (t[2].0 - px) * (t[1].1 - py)) / area;
                let w1 = ((t[2].0 - px) * (t[0].1 - py) - (t[0].0 - px) * (t[2].1 - py)) / area;
                let w2 = 1.0 - w0 - w1;
                const EDGE: f64 = -1e-9;
                if w0 < EDGE || w1 < EDGE || w2 < EDGE {
                    continue;
                }
                let z = w0 * t[0].2 + w1 * t[1].2 + w2 * t[2].2;
                let slot = &mut self.depth[y * self.width + x];
                if z > *slot {
                    *slot = z;
                }
            }
        }
    }

    /// The surface depth at pixel position `(x, y)` (minus infinity off the surface).
    fn at(&self, x: f64, y: f64) -> f64 {
        if !(x >= 0.0 && y >= 0.0) {
            return f64::NEG_INFINITY;
        }
        let (px, py) = (x as usize, y as usize);
        if px >= self.width || py >= self.height {
            return f64::NEG_INFINITY;
        }
        self.depth[py * self.width + px]
    }
}

/// The visible pieces of a polyline, in pixels.
fn visible_runs(
    line: &[Point3],
    camera: &Camera,
    depth: &DepthBuffer,
    slack: f64,
) -> Vec<Vec<(f64, f64)>> {
    let mut runs: Vec<Vec<(f64, f64)>> = Vec::new();
    let mut current: Vec<(f64, f64)> = Vec::new();
    let mut flush = |current: &mut Vec<(f64, f64)>| {
        if current.len() >= 2 {
            runs.push(std::mem::take(current));
        } else {
            current.clear();
        }
    };
    let visible = |p: (f64, f64, f64)| p.2 + slack >= depth.at(p.0, p.1);
    for pair in line.windows(2) {
        if !(pair[0].is_finite() && pair[1].is_finite()) {
            flush(&mut current);
            continue;
        }
        let (a, b) = (camera.project(pair[0]), camera.project(pair[1]));
        let pixels = (b.0 - a.0).hypot(b.1 - a.1);
        // Samples half a pixel apart; only run ends and segment ends become points.
        let steps = ((2.0 * pixels).ceil() as usize).clamp(1, 100_000);
        let mut pending = None;
        for k in 0..=steps {
            if k == 0 && !current.is_empty() {
                continue; // the previous segment's end, already in the run
            }
            let t = k as f64 / steps as f64;
            let p = (
                a.0 + t * (b.0 - a.0),
                a.1 + t * (b.1 - a.1),
                a.2 + t * (b.2 - a.2),
            );
            if visible(p) {
                if current.is_empty() || k == steps {
                    current.push((p.0, p.1));
                    pending = None;
                } else {
                    pending = Some((p.0, p.1));
                }
            } else {
                if let Some(q) = pending.take() {
                    current.push(q);
                }
                flush(&mut current);
            }
        }
    }
    flush(&mut current);
    runs
}

/// The scale bar under the drawing, at height `y`: ticks in model units (an orthographic
/// view shows lengths across the picture true), and the names of the picture's horizontal and
/// vertical directions in model terms.
fn write_scale_bar(svg: &mut String, camera: &Camera, view: View, y: f64) {
    let step = nice_step(RULER_GAP / camera.scale);
    let steps = ((RULER_LENGTH / (step * camera.scale)).floor() as usize).max(1);
    let x0 = MARGIN + 10.0;
    let length = steps as f64 * step * camera.scale;
    let _ = write!(
        svg,
        r#"<g class="scale-bar" font-family="sans-serif" font-size="13"><line x1="{x0}" y1="{y}" x2="{x1}" y2="{y}" stroke="black" stroke-width="1.5"/>"#,
        x0 = Px(x0),
        x1 = Px(x0 + length),
        y = Px(y),
    );
    for k in 0..=steps {
        let x = x0 + k as f64 * step * camera.scale;
        let _ = write!(
            svg,
            r#"<line x1="{x}" y1="{y0}" x2="{x}" y2="{y}" stroke="black"/><text class="tick-scale" x="{x}" y="{ty}" text-anchor="middle">{}</text>"#,
            tick_label(k as f64 * step, step),
            x = Px(x),
            y0 = Px(y - 5.0),
            y = Px(y),
            ty = Px(y + 16.0),
        );
    }
    let (horizontal, vertical) = view.axis_names();
    let _ = write!(
        svg,
        r#"<text class="scale-caption" x="{x}" y="{ty}">model units; across the picture: {}, up the picture: {} (view from azimuth {}°, elevation {}°)</text></g>"#,
        escape(&horizontal),
        escape(&vertical),
        without_negative_zero(format!("{:.0}", view.azimuth)),
        without_negative_zero(format!("{:.0}", view.elevation)),
        x = Px(x0),
        ty = Px(y + 36.0),
    );
}

/// The model axes x, y, z as seen in the picture, drawn from `centre` and labelled.
fn write_triad(svg: &mut String, camera: &Camera, centre: (f64, f64)) {
    let _ = write!(
        svg,
        r#"<g class="triad" font-family="sans-serif" font-size="14" stroke-width="1.5">"#
    );
    let colours = [(200, 30, 30), (30, 140, 30), (30, 60, 200)];
    for (c, name) in ["x", "y", "z"].into_iter().enumerate() {
        let mut axis = Point3::new([0.0; 3]);
        axis[c] = 1.0;
        let (dx, dy) = (axis.dot(camera.right) * TRIAD, -axis.dot(camera.up) * TRIAD);
        let (r, g, b) = colours[c];
        let tip = (centre.0 + dx, centre.1 + dy);
        let norm = dx.hypot(dy).max(1e-9);
        let label = (tip.0 + 9.0 * dx / norm, tip.1 + 9.0 * dy / norm + 5.0);
        let _ = write!(
            svg,
            r#"<line x1="{}" y1="{}" x2="{}" y2="{}" stroke="rgb({r},{g},{b})"/><text class="triad-axis" x="{}" y="{}" fill="rgb({r},{g},{b})" text-anchor="middle">{name}</text>"#,
            Px(centre.0),
            Px(centre.1),
            Px(tip.0),
            Px(tip.1),
            Px(label.0),
            Px(label.1),
        );
    }
    svg.push_str("</g>");
}

/// The legend: a swatch and the label of each group that has one.
fn write_legend(svg: &mut String, groups: &[SceneCurves<'_>], baseline: f64) {
    let mut x = MARGIN + 10.0;
    for g in groups.iter().filter(|g| !g.label.is_empty()) {
        let (r, gr, b) = g.rgb;
        let _ = write!(
            svg,
            r#"<line x1="{x:.1}" y1="{y:.1}" x2="{x2:.1}" y2="{y:.1}" stroke="rgb({r},{gr},{b})" stroke-width="3"/><text x="{tx:.1}" y="{baseline:.1}" font-family="sans-serif" font-size="15">{}</text>"#,
            escape(g.label),
            y = baseline - 5.0,
            x2 = x + 28.0,
            tx = x + 36.0,
        );
        x += 36.0 + 8.5 * g.label.chars().count() as f64 + 30.0;
    }
}

pub(crate) use crate::picture::text::escape;

#[cfg(test)]
mod tests {
    use super::*;

    /// A unit square in the plane z = 0 seen from above, with a line on it and one below it.
    #[test]
    fn lines_behind_the_surface_are_removed() {
        let points: Vec<Point3> = (0..3)
            .flat_map(|i| (0..3).map(move |j| Point3::new([i as f64 * 0.5, j as f64 * 0.5, 0.0])))
            .collect();
        let on = vec![Point3::new([0.1, 0.5, 0.0]), Point3::new([0.9, 0.5, 0.0])];
        let below = vec![Point3::new([0.5, 0.1, -0.5]), Point3::new([0.5, 0.9, -0.5])];
        let beside = vec![Point3::new([2.0, 0.1, -0.5]), Point3::new([2.0, 0.9, -0.5])];
        let lines = [on, below, beside];
        let scene = Scene {
            title: "a <test>",
            mesh: SceneMesh {
                rows: 3,
                cols: 3,
                points: &points,
            },
            curves: &[SceneCurves {
                label: "lines",
                lines: &lines,
                rgb: (255, 0, 0),
                width: 2.0,
            }],
            view: View {
                azimuth: 0.0,
                elevation: 90.0,
            },
        };
        let svg = render_scene_svg(&scene);
        assert!(svg.starts_with("<svg") && svg.ends_with("</svg>\n"));
        assert!(svg.contains("a &lt;test&gt;"));
        assert_eq!(svg.matches("<polygon").count(), 4);
        // The line on the surface and the one beside it are drawn, the one below is not.
        assert_eq!(svg.matches("<polyline").count(), 2);
        // Seen from above with azimuth 0, the picture's right is +y and its up is -x.
        assert!(
            svg.contains("across the picture: y, up the picture: -x"),
            "{svg}"
        );
        assert!(!svg.contains("view x") && !svg.contains("view y"));
        for axis in ["x", "y", "z"] {
            assert!(
                svg.contains(&format!(">{axis}</text>")),
                "triad label {axis}"
            );
        }
    }

    #[test]
    fn directions_are_named_by_the_model_axes() {
        let d = |x: f64, y: f64, z: f64| direction_name(Point3::new([x, y, z]));
        assert_eq!(d(1.0, 0.0, 0.0), "x");
        assert_eq!(d(0.0, 0.0, -1.0), "-z");
        let h = std::f64::consts::FRAC_1_SQRT_2;
        assert_eq!(d(h, h, 0.0), "0.71 x + 0.71 y");
        assert_eq!(d(-0.5, -1e-17, -0.866), "-0.5 x - 0.87 z");
        let (right, up) = View {
            azimuth: -90.0,
            elevation: 0.0,
        }
        .axis_names();
        // Looking from -y towards +y: right is +x, up is +z.
        assert_eq!((right.as_str(), up.as_str()), ("x", "z"));
    }

    /// The scale bar's ticks are round model lengths at the picture's scale: a unit square seen
    /// from above fills about 1000 of the 1100 pixels, so ticks 0.1 apart are about 96 px apart.
    #[test]
    fn the_scale_bar_measures_model_units() {
        let points: Vec<Point3> = (0..2)
            .flat_map(|i| (0..2).map(move |j| Point3::new([i as f64, j as f64, 0.0])))
            .collect();
        let scene = Scene {
            title: "square",
            mesh: SceneMesh {
                rows: 2,
                cols: 2,
                points: &points,
            },
            curves: &[],
            view: View {
                azimuth: 0.0,
                elevation: 90.0,
            },
        };
        let svg = render_scene_svg(&scene);
        let ticks: Vec<(f64, String)> = svg
            .split("<text class=\"tick-scale\" x=\"")
            .skip(1)
            .map(|t| {
                let (x, rest) = t.split_once('"').unwrap();
                let label = rest.split_once('>').unwrap().1.split_once('<').unwrap().0;
                (x.parse().unwrap(), label.to_owned())
            })
            .collect();
        assert!(ticks.len() >= 2, "{ticks:?}");
        // The square spans 1 / 1.06 of the drawing width (3% padding on each side).
        let pixels_per_unit = DRAWING_WIDTH / 1.06;
        for (x, label) in &ticks {
            let value: f64 = label.parse().unwrap();
            let expected = ticks[0].0 + value * pixels_per_unit;
            assert!(
                (x - expected).abs() < 0.01,
                "{label} at {x}, expected {expected}"
            );
        }
    }
}

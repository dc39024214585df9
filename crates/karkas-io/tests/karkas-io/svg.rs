//! The SVG curve picture.

use karkas::{Point, Point2};
use karkas_io::svg::{render_curve_svg, write_curve_svg, CurvePlot};

use crate::util::scratch;

/// The value of attribute `name` in `tag` (text from `<` to `>`).
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    let len = tag[start..].find('"')?;
    Some(&tag[start..start + len])
}

/// The width and height of the document.
fn size(svg: &str) -> (f64, f64) {
    let tag = &svg[svg.find("<svg").unwrap()..];
    let tag = &tag[..tag.find('>').unwrap()];
    (
        attribute(tag, "width").unwrap().parse().unwrap(),
        attribute(tag, "height").unwrap().parse().unwrap(),
    )
}

/// Pixel bounding box (width, height) of the polyline drawn with `stroke`.
fn polyline_extent(svg: &str, stroke: &str) -> (f64, f64) {
    let tag = svg
        .split('<')
        .find(|t| t.starts_with("polyline") && attribute(t, "stroke") == Some(stroke))
        .unwrap_or_else(|| panic!("no polyline with stroke {stroke}"));
    let (mut lo, mut hi) = ([f64::MAX; 2], [f64::MIN; 2]);
    for pair in attribute(tag, "points").unwrap().split_whitespace() {
        let (x, y) = pair.split_once(',').unwrap();
        for (k, v) in [x, y].into_iter().enumerate() {
            let v: f64 = v.parse().unwrap();
            lo[k] = lo[k].min(v);
            hi[k] = hi[k].max(v);
        }
    }
    (hi[0] - lo[0], hi[1] - lo[1])
}

fn ellipse(a: f64, b: f64, n: usize) -> Vec<Point2> {
    (0..=n)
        .map(|k| {
            let t = std::f64::consts::TAU * k as f64 / n as f64;
            Point([a * t.cos() + 3.0, b * t.sin() - 1.0])
        })
        .collect()
}

#[test]
fn circle_is_round() {
    let curve = ellipse(1.0, 1.0, 200);
    let input = ellipse(1.0, 1.0, 8);
    let svg = render_curve_svg(&CurvePlot {
        title: "a circle",
        curve: &curve,
        input: &input[..8],
        closed_input: true,
    })
    .unwrap();
    assert!(svg.contains("<svg") && svg.trim_end().ends_with("</svg>"));
    let text = |t: &str| svg.contains(&format!(">{t}</text>"));
    assert!(
        text("x") && text("y") && text("a circle"),
        "caption and axis labels"
    );
    let (w, h) = size(&svg);
    assert_eq!(w, 900.0);
    assert!((300.0..=1200.0).contains(&h));
    let (cw, ch) = polyline_extent(&svg, "#0000FF");
    assert!(cw > 300.0, "the circle fills the picture: {cw}");
    assert!((cw - ch).abs() <= 0.02, "circle drawn {cw} x {ch} px");
    // Input points are red circles.
    assert_eq!(svg.matches("<circle").count(), 8);
}

#[test]
fn wide_and_tall_shapes_keep_their_aspect() {
    for (a, b) in [(4.0, 1.0), (1.0, 2.0), (1.0, 50.0)] {
        let curve = ellipse(a, b, 400);
        let svg = render_curve_svg(&CurvePlot {
            title: "ellipse",
            curve: &curve,
            input: &[],
            closed_input: false,
        })
        .unwrap();
        let (_, h) = size(&svg);
        assert!((300.0..=1200.0).contains(&h));
        let (cw, ch) = polyline_extent(&svg, "#0000FF");
        // Equal scales: the drawn width is the drawn height times a / b, up to the rounding of
        // both to a hundredth of a pixel.
        let expected_width = ch * a / b;
        assert!(
            (cw - expected_width).abs() <= 0.01 * (1.0 + a / b),
            "{a}x{b}: drawn {cw} x {ch} px"
        );
        assert!(cw.max(ch) > 250.0, "the ellipse fills the picture");
    }
}

#[test]
fn picture_is_written_to_file() {
    let (dir, path) = scratch("c.svg");
    let curve = ellipse(1.0, 1.0, 50);
    let plot = CurvePlot {
        title: "file",
        curve: &curve,
        input: &curve,
        closed_input: false,
    };
    write_curve_svg(&path, &plot).unwrap();
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        render_curve_svg(&plot).unwrap()
    );
    let e = write_curve_svg(&dir.path().join("none/c.svg"), &plot).unwrap_err();
    assert!(matches!(e, karkas_io::IoError::Write { .. }));
}

#[test]
fn degenerate_input_still_draws() {
    for points in [
        vec![],
        vec![Point([1.0, 1.0])],
        vec![Point([f64::NAN, 0.0])],
    ] {
        let svg = render_curve_svg(&CurvePlot {
            title: "<&> \"quoted\"",
            curve: &points,
            input: &points,
            closed_input: true,
        })
        .unwrap();
        assert!(svg.contains("<svg"));
    }
}

/// The tick labels of class `class` (`tick-x`, `tick-y`): position (the `x` or `y` attribute)
/// and text.
fn ticks(svg: &str, class: &str) -> Vec<(f64, String)> {
    let coordinate = if class == "tick-x" { "x" } else { "y" };
    svg.split('<')
        .filter(|t| t.starts_with("text") && attribute(t, "class") == Some(class))
        .map(|t| {
            let (tag, text) = t.split_once('>').unwrap();
            (
                attribute(tag, coordinate).unwrap().parse().unwrap(),
                text.to_owned(),
            )
        })
        .collect()
}

/// The map from pixels back to model units along one axis, read off the first and last tick
/// labels: `(pixel, value)` pairs give `value = a + b * pixel`.
fn inverse_axis(ticks: &[(f64, String)]) -> (f64, f64) {
    assert!(ticks.len() >= 2, "{ticks:?}");
    let (p0, v0) = (ticks[0].0, ticks[0].1.parse::<f64>().unwrap());
    let (p1, v1) = (
        ticks.last().unwrap().0,
        ticks.last().unwrap().1.parse::<f64>().unwrap(),
    );
    let b = (v1 - v0) / (p1 - p0);
    (v0 - b * p0, b)
}

/// The points of the polylines of class `class`, as written.
fn polyline_points(svg: &str, class: &str) -> Vec<Vec<(String, String)>> {
    svg.split('<')
        .filter(|t| t.starts_with("polyline") && attribute(t, "class") == Some(class))
        .map(|t| {
            attribute(t, "points")
                .unwrap()
                .split_whitespace()
                .map(|pair| {
                    let (x, y) = pair.split_once(',').unwrap();
                    (x.to_owned(), y.to_owned())
                })
                .collect()
        })
        .collect()
}

/// A wavy curve sampled densely, whose samples are 1e-4 of the width apart: whole pixels
/// would merge them. Read back through the tick labels (the axes a reader sees), every drawn
/// point lies within a fiftieth of a pixel of its model point.
#[test]
fn coordinates_are_sub_pixel_and_match_the_axes() {
    let n = 10_000;
    let curve: Vec<Point2> = (0..=n)
        .map(|k| {
            let x = k as f64 / n as f64;
            Point([
                x,
                0.06 * (std::f64::consts::PI * x).sin() + 0.002 * (90.0 * x).sin(),
            ])
        })
        .collect();
    let svg = render_curve_svg(&CurvePlot {
        title: "wave",
        curve: &curve,
        input: &[],
        closed_input: false,
    })
    .unwrap();
    let (ax, bx) = inverse_axis(&ticks(&svg, "tick-x"));
    let (ay, by) = inverse_axis(&ticks(&svg, "tick-y"));
    assert!(
        bx > 0.0 && by < 0.0 && (bx + by).abs() < 1e-6 * bx,
        "equal scales"
    );
    let lines = polyline_points(&svg, "curve");
    assert_eq!(lines.len(), 1);
    assert_eq!(lines[0].len(), curve.len());
    let mut fractional = 0;
    for ((x, y), p) in lines[0].iter().zip(&curve) {
        for text in [x, y] {
            let decimals = text.split_once('.').map_or(0, |(_, d)| d.len());
            assert_eq!(decimals, 2, "{text}");
            fractional += usize::from(!text.ends_with(".00"));
        }
        let (px, py): (f64, f64) = (x.parse().unwrap(), y.parse().unwrap());
        let model = (ax + bx * px, ay + by * py);
        let pixels = ((model.0 - p[0]) / bx).hypot((model.1 - p[1]) / by);
        assert!(pixels < 0.02, "{p:?} drawn at {model:?}: {pixels} px off");
    }
    assert!(fractional > curve.len(), "most coordinates have fractions");
}

/// Ranges about zero, large and tiny, never label a tick "-0" (or "-0.0", "-0.00", ...).
#[test]
fn no_tick_label_is_a_negative_zero() {
    for size in [1e-6, 3e-3, 0.3, 1.0, 7.0, 250.0, 4e5] {
        for centre in [0.0, -0.1 * size, 0.37 * size] {
            let curve = ellipse(1.0, 1.0, 64)
                .into_iter()
                .map(|p| Point([(p[0] - 3.0) * size + centre, (p[1] + 1.0) * size * 0.4]))
                .collect::<Vec<_>>();
            let svg = render_curve_svg(&CurvePlot {
                title: "t",
                curve: &curve,
                input: &[],
                closed_input: false,
            })
            .unwrap();
            for class in ["tick-x", "tick-y"] {
                let labels = ticks(&svg, class);
                assert!(labels.len() >= 2, "{size} {class}: {labels:?}");
                for (_, label) in labels {
                    let value: f64 = label.parse().unwrap();
                    assert!(
                        !(label.starts_with('-') && value == 0.0),
                        "{size}: label {label}"
                    );
                }
            }
        }
    }
}

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
    let text = |t: &str| svg.contains(&format!(">\n{t}\n</text>"));
    assert!(
        text("x") && text("y") && text("a circle"),
        "caption and axis labels"
    );
    let (w, h) = size(&svg);
    assert_eq!(w, 900.0);
    assert!((300.0..=1200.0).contains(&h));
    let (cw, ch) = polyline_extent(&svg, "#0000FF");
    assert!(cw > 300.0, "the circle fills the picture: {cw}");
    assert!((cw - ch).abs() <= 2.0, "circle drawn {cw} x {ch} px");
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
        // both to whole pixels.
        let expected_width = ch * a / b;
        assert!(
            (cw - expected_width).abs() <= 1.5 * (1.0 + a / b),
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

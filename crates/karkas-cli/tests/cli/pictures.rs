//! Pictures a designer can inspect: the curvature comb of an airfoil visible along the whole
//! curve with its scale in the legend, and surface pictures labelled in model units.

use crate::common::{karkas, s, stderr, temp_dir, write};

/// The NACA 2412 section (Abbott and von Doenhoff's four-digit formulas) at `per_side`
/// cosine-spaced stations a side: from the upper trailing edge round the nose to the lower one.
fn naca_2412(per_side: usize) -> Vec<(f64, f64)> {
    let (m, p, t) = (0.02, 0.4, 0.12);
    let station = |k: usize| {
        let beta = std::f64::consts::PI * k as f64 / (per_side - 1) as f64;
        let x = 0.5 * (1.0 - beta.cos());
        let yt = 5.0
            * t
            * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                - 0.1015 * x.powi(4));
        let (yc, slope) = if x < p {
            (
                m / (p * p) * (2.0 * p * x - x * x),
                2.0 * m / (p * p) * (p - x),
            )
        } else {
            let q = (1.0 - p) * (1.0 - p);
            (
                m / q * ((1.0 - 2.0 * p) + 2.0 * p * x - x * x),
                2.0 * m / q * (p - x),
            )
        };
        let theta = slope.atan();
        (x, yc, yt, theta)
    };
    let upper = (0..per_side).rev().map(|k| {
        let (x, yc, yt, th) = station(k);
        (x - yt * th.sin(), yc + yt * th.cos())
    });
    let lower = (1..per_side).map(|k| {
        let (x, yc, yt, th) = station(k);
        (x + yt * th.sin(), yc - yt * th.cos())
    });
    upper.chain(lower).collect()
}

/// The value of attribute `name` in `tag`.
fn attribute<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
    let start = tag.find(&format!(" {name}=\""))? + name.len() + 3;
    let len = tag[start..].find('"')?;
    Some(&tag[start..start + len])
}

/// The polylines of class `class` as pixel points.
fn polylines(svg: &str, class: &str) -> Vec<Vec<(f64, f64)>> {
    svg.split('<')
        .filter(|t| t.starts_with("polyline") && attribute(t, "class") == Some(class))
        .map(|t| {
            attribute(t, "points")
                .unwrap()
                .split_whitespace()
                .map(|pair| {
                    let (x, y) = pair.split_once(',').unwrap();
                    (x.parse().unwrap(), y.parse().unwrap())
                })
                .collect()
        })
        .collect()
}

/// The plotting area (the black frame): left, top, width, height.
fn plotting_area(svg: &str) -> [f64; 4] {
    let tag = svg
        .split('<')
        .find(|t| t.starts_with("rect") && attribute(t, "stroke") == Some("black"))
        .expect("a framed plotting area");
    ["x", "y", "width", "height"].map(|a| attribute(tag, a).unwrap().parse().unwrap())
}

/// On a real section, scaled to its largest tooth (the nose) the comb would be flat along
/// most of the chord. Scaled to a percentile, the median tooth is at least 1% of the picture's
/// width, no tooth leaves the plotting area, and the legend states the scale.
#[test]
fn the_comb_of_an_airfoil_is_visible_along_the_whole_curve() {
    let dir = temp_dir();
    let mut text = String::from("x,y\n");
    for (x, y) in naca_2412(65) {
        text.push_str(&format!("{x},{y}\n"));
    }
    let points = write(dir.path(), "naca2412.csv", &text);
    for method in ["ll", "fit"] {
        let out = dir.path().join(format!("{method}.svg"));
        let mut args = vec!["curve", method, "--comb", s(&points), "-o", s(&out)];
        if method == "fit" {
            args.extend(["--tolerance", "1e-5"]);
        }
        let o = karkas(&args);
        assert!(o.status.success(), "{method}: {}", stderr(&o));
        let svg = std::fs::read_to_string(&out).unwrap();
        let width: f64 = attribute(&svg, "width").unwrap().parse().unwrap();
        let mut teeth = polylines(&svg, "comb");
        let clipped = polylines(&svg, "comb-clipped");
        let few = clipped.len() * 8 < teeth.len();
        assert!(
            few,
            "{method}: {} of {} teeth clipped",
            clipped.len(),
            teeth.len()
        );
        teeth.extend(clipped);
        assert!(teeth.len() >= 200, "{method}: {} teeth", teeth.len());
        let mut lengths: Vec<f64> = teeth
            .iter()
            .map(|t| (t[1].0 - t[0].0).hypot(t[1].1 - t[0].1))
            .collect();
        lengths.sort_by(f64::total_cmp);
        let median = lengths[lengths.len() / 2];
        assert!(
            median >= 0.01 * width,
            "{method}: median tooth {median:.2} px in a {width} px picture"
        );
        let [left, top, w, h] = plotting_area(&svg);
        for tip in teeth.iter().map(|t| t[1]) {
            assert!(
                (left..=left + w).contains(&tip.0) && (top..=top + h).contains(&tip.1),
                "{method}: tooth tip {tip:?} outside the plotting area"
            );
        }
        for class in ["tick-x", "tick-y"] {
            let labels: Vec<&str> = svg
                .split(&format!("class=\"{class}\""))
                .skip(1)
                .map(|t| t.split_once('>').unwrap().1.split_once('<').unwrap().0)
                .collect();
            assert!(labels.len() >= 3, "{method} {class}: {labels:?}");
            for label in labels {
                let negative_zero = label.starts_with('-') && label.parse::<f64>() == Ok(0.0);
                assert!(!negative_zero, "{method} {class}: {label}");
            }
        }
        assert!(
            svg.contains("class=\"legend\"")
                && svg.contains("comb: tooth length = curvature \u{d7} "),
            "{method}: the legend names the scale"
        );
    }
    // PNG goes through the same drawing.
    let png = dir.path().join("ll.png");
    let o = karkas(&["curve", "ll", "--comb", s(&points), "-o", s(&png)]);
    assert!(o.status.success(), "{}", stderr(&o));
    assert!(std::fs::read(&png).unwrap().starts_with(b"\x89PNG"));
}

/// A surface picture labels its scale in model units and its directions by the model axes,
/// never "view x" or a negative zero.
#[test]
fn surface_pictures_are_labelled_in_model_units() {
    let dir = temp_dir();
    let mut text = String::from("i,j,x,y,z\n");
    for i in 0..4 {
        for j in 0..5 {
            text.push_str(&format!("{i},{j},{i},{j},{}\n", 0.3 * ((i * j) % 3) as f64));
        }
    }
    let grid = write(dir.path(), "g.csv", &text);
    let out = dir.path().join("s.svg");
    let o = karkas(&["surface", "ll", s(&grid), "-o", s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let svg = std::fs::read_to_string(&out).unwrap();
    assert!(!svg.contains("view x") && !svg.contains("view y"));
    assert!(
        svg.contains("model units; across the picture: "),
        "scale bar caption"
    );
    let labels: Vec<&str> = svg
        .split("class=\"tick-scale\"")
        .skip(1)
        .map(|t| t.split_once('>').unwrap().1.split_once('<').unwrap().0)
        .collect();
    assert!(
        labels.len() >= 2 && labels[0].parse::<f64>() == Ok(0.0),
        "{labels:?}"
    );
    assert!(labels.iter().all(|l| !l.starts_with('-')), "{labels:?}");
    let png = dir.path().join("s.png");
    let o = karkas(&["surface", "ll", s(&grid), "-o", s(&png)]);
    assert!(o.status.success(), "{}", stderr(&o));
}

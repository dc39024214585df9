//! The workbench's loft: the shipped demo wing (data/loft-wing) lofted through the page's
//! function as `karkas loft` lofts it, then one section's twist changed as the page's slider
//! changes it: the surface turns at that section by the change and does not move where the
//! spanwise rule cannot carry it (before the neighbouring section for the ruled surface, two
//! sections away for the monotone one), nor at any other section.

use std::path::Path;

use karkas::loft::{Loft, LoftOptions, SpanRule, WingPlacement};
use karkas::{Point2, Surface};
use karkas_io::points::{read_curve_points, CurvePoints};
use karkas_io::sections_table::read_sections_table;
use karkas_wasm::loft::{placements, row_placements, wing_loft, WingLoft};

/// The demo wing: its profiles as the page sends them (flat pairs and counts) and its flat
/// placements.
fn demo_wing() -> (Vec<f64>, Vec<usize>, Vec<f64>) {
    let table = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../data/loft-wing/wing.csv");
    let rows = read_sections_table(&table).unwrap();
    let (mut coords, mut counts) = (Vec::new(), Vec::new());
    for row in &rows {
        let CurvePoints::Planar(points) = read_curve_points(&row.path).unwrap() else {
            panic!("{} is not planar", row.file);
        };
        counts.push(points.len());
        coords.extend(points.iter().flat_map(|p| p.0));
    }
    (coords, counts, row_placements(&rows))
}

fn build(coords: &[f64], counts: &[usize], flat: &[f64], rule: &str) -> WingLoft {
    wing_loft(
        coords,
        counts,
        &placements(flat).unwrap(),
        rule,
        1e-5,
        &[],
        "wing.csv",
    )
    .unwrap()
}

/// The largest distance between two lofts' points over `(u, v)` samples with `u` in `span`.
fn moved(a: &Loft, b: &Loft, span: (f64, f64)) -> f64 {
    let mut worst = 0.0f64;
    for i in 0..=200 {
        let u = span.0 + (span.1 - span.0) * i as f64 / 200.0;
        for j in 0..=100 {
            let v = j as f64 / 100.0;
            worst = worst.max((a.eval(u, v) - b.eval(u, v)).norm());
        }
    }
    worst
}

/// The trailing-edge midpoint minus the leading edge at station `u`: the chord line.
fn chord_line(loft: &Loft, u: f64) -> karkas::Point3 {
    let te = (loft.eval(u, 0.0) + loft.eval(u, 1.0)) * 0.5;
    te - loft.eval(u, 0.5)
}

#[test]
fn the_demo_wing_lofts_as_the_command_line_lofts_it() {
    let (coords, counts, flat) = demo_wing();
    assert_eq!(counts.len(), 3);
    let built = build(&coords, &counts, &flat, "monotone");
    // The command line's loft: Loft::wing on the same profiles and placements.
    let mut profiles = Vec::new();
    let mut at = 0;
    for &n in &counts {
        profiles.push(
            coords[2 * at..2 * (at + n)]
                .chunks_exact(2)
                .map(|c| Point2::new([c[0], c[1]]))
                .collect::<Vec<_>>(),
        );
        at += n;
    }
    let placed: Vec<WingPlacement> = placements(&flat).unwrap();
    let cli = Loft::wing(&profiles, &placed, &LoftOptions::default()).unwrap();
    assert_eq!(built.loft, cli);
    assert!(built.loft.tolerance_met());
    assert!(built.loft.max_relative_deviation() <= 1e-5);
    // The section curves the page draws: the surface at each station, its leading edge (the
    // middle point of 121) at the profile's point of smallest x, placed.
    let curves = built.station_curves(121);
    assert_eq!(curves.len(), 3 * 121 * 3);
    let (frames, _) = karkas::loft::wing_frames(&placed).unwrap();
    for (k, frame) in frames.iter().enumerate() {
        let nose = profiles[k]
            .iter()
            .min_by(|a, b| a[0].total_cmp(&b[0]))
            .unwrap();
        let want = frame.place(*nose);
        let le = &curves[3 * (121 * k + 60)..3 * (121 * k + 61)];
        for d in 0..3 {
            assert!((le[d] - want[d]).abs() < 1e-12, "{k}: {le:?} {want:?}");
        }
    }
}

#[test]
fn a_twist_moves_the_surface_at_its_section_and_not_before_the_neighbouring_one() {
    let (coords, counts, flat) = demo_wing();
    for rule in ["linear", "monotone", "spline"] {
        let before = build(&coords, &counts, &flat, rule).loft;
        // The tip's twist (section 2, -3 degrees) to +2 degrees, as the slider sets it.
        let mut turned = flat.clone();
        turned[2 * 6 + 4] = 2.0;
        let after = build(&coords, &counts, &turned, rule).loft;
        let s = before.stations().to_vec();
        assert_eq!(s, after.stations());
        // At the tip the chord line turned by 5 degrees about the span, nose up.
        let (a, b) = (chord_line(&before, s[2]), chord_line(&after, s[2]));
        let angle = |c: karkas::Point3| c[2].atan2(c[0]).to_degrees();
        let turn = angle(a) - angle(b);
        assert!(
            (turn - 5.0).abs() < 0.05,
            "{rule}: the tip turned {turn} degrees"
        );
        assert!(moved(&before, &after, (s[2], s[2])) > 0.01, "{rule}");
        // At the root and the middle section the surface is the same section as before.
        for &u in &s[..2] {
            assert!(moved(&before, &after, (u, u)) < 1e-12, "{rule} at {u}");
        }
        // Ruled: nothing moves before the neighbouring section; the others carry the change
        // over the whole span of a three-section wing.
        let inboard = moved(&before, &after, (s[0], s[1]));
        if rule == "linear" {
            assert!(inboard < 1e-12, "linear: {inboard}");
        } else {
            assert!(inboard > 1e-6, "{rule}: {inboard}");
        }
    }
}

#[test]
fn with_more_sections_the_monotone_rule_keeps_the_change_within_two_sections() {
    // The demo's profiles on a seven-section wing: root, mid and tip profiles repeated.
    let (coords, counts, _) = demo_wing();
    let mut pairs: Vec<&[f64]> = Vec::new();
    let mut at = 0;
    for &n in &counts {
        pairs.push(&coords[2 * at..2 * (at + n)]);
        at += n;
    }
    let order = [0, 0, 1, 1, 1, 2, 2];
    let many: Vec<f64> = order
        .iter()
        .flat_map(|&k| pairs[k].iter().copied())
        .collect();
    let many_counts: Vec<usize> = order.iter().map(|&k| counts[k]).collect();
    let mut flat = Vec::new();
    for k in 0..7 {
        let y = k as f64;
        flat.extend([
            0.15 * y,
            y,
            0.05 * y,
            1.6 - 0.15 * y,
            2.0 - 0.8 * y,
            f64::NAN,
        ]);
    }
    let before = build(&many, &many_counts, &flat, "monotone").loft;
    let mut turned = flat.clone();
    turned[3 * 6 + 4] += 4.0;
    let after = build(&many, &many_counts, &turned, "monotone").loft;
    let s = before.stations().to_vec();
    assert!(moved(&before, &after, (s[3], s[3])) > 0.01);
    for k in [0, 1, 2, 4, 5, 6] {
        assert!(moved(&before, &after, (s[k], s[k])) < 1e-12, "section {k}");
    }
    // Hermite slopes at a section come from its neighbours: the change reaches the
    // neighbours' slopes, so it spans from section 1 to section 5 and no further.
    assert!(moved(&before, &after, (s[0], s[1])) < 1e-12);
    assert!(moved(&before, &after, (s[5], s[6])) < 1e-12);
    assert!(moved(&before, &after, (s[1], s[2])) > 1e-6);
    assert_eq!(SpanRule::default(), SpanRule::Monotone);
}

#[test]
fn bad_input_is_an_error_naming_the_section_not_a_panic() {
    let (coords, counts, flat) = demo_wing();
    let labels = [
        "wing.csv: row 2 (naca4415.dat)".to_string(),
        "wing.csv: row 3 (naca2412.dat)".to_string(),
        "wing.csv: row 4 (naca0009.dat)".to_string(),
    ];
    // Stations out of order: the tip's leading edge moved inboard of the middle one.
    let mut back = flat.clone();
    back[2 * 6 + 1] = 1.0;
    let e = wing_loft(
        &coords,
        &counts,
        &placements(&back).unwrap(),
        "monotone",
        1e-5,
        &labels,
        "wing.csv",
    )
    .err()
    .unwrap();
    assert!(e.starts_with("wing.csv: row 4 (naca0009.dat): "), "{e}");
    // A chord of zero, an unknown rule, counts that do not match the points, a profile of
    // two points: errors, each naming where.
    let mut flat_chord = flat.clone();
    flat_chord[6 + 3] = 0.0;
    let zero = wing_loft(
        &coords,
        &counts,
        &placements(&flat_chord).unwrap(),
        "monotone",
        1e-5,
        &labels,
        "wing.csv",
    );
    assert!(zero.err().unwrap().starts_with("wing.csv: row 3"));
    let p = placements(&flat).unwrap();
    let rule = wing_loft(&coords, &counts, &p, "wavy", 1e-5, &labels, "wing.csv");
    assert!(rule.err().unwrap().contains("wavy"));
    let short = wing_loft(
        &coords[2..],
        &counts,
        &p,
        "linear",
        1e-5,
        &labels,
        "wing.csv",
    );
    assert!(short.err().unwrap().contains("coordinates"));
    let mut tiny = coords.clone();
    let mut tiny_counts = counts.clone();
    tiny.truncate(2 * (counts[0] + counts[1]) + 4);
    tiny_counts[2] = 2;
    let few = wing_loft(&tiny, &tiny_counts, &p, "linear", 1e-5, &labels, "wing.csv");
    assert!(few.err().unwrap().starts_with("wing.csv: row 4"));
    assert!(placements(&flat[1..]).is_err());
}

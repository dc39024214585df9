//! The loft of the shipped wing (`data/loft-wing`, docs/methods.md §7): three NACA sections
//! with taper, twist, sweep and dihedral, read from the sections table and airfoil files built
//! into the binary and lofted as `karkas loft data/loft-wing/wing.csv` lofts them (the
//! monotone spanwise rule, tolerance 1e-5 of each chord). The report checks the loft
//! independently of the fit's own figures: every input point's distance from the surface's
//! curve at its station (dense sampling and a golden-section refinement), the leading and
//! trailing edges of the surface at the stations against the placed points, and, on 1000
//! lines along the span, the chord, twist and leading edge between their neighbouring
//! sections' values and the trailing-edge branches in their order.

use super::common::{write_text, write_viewer, Finding, Output};
use crate::output::samples::sample_surface;
use anyhow::{anyhow, Context, Result};
use karkas::bspline::BSplineCurve;
use karkas::loft::{wing_frames, Loft, LoftOptions, WingPlacement, DEFAULT_TOLERANCE};
use karkas::{Curve, Point2, Point3, Surface};
use karkas_io::points::{parse_curve_points, CurvePoints};
use karkas_io::scene::{write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::sections_table::{parse_sections_table, SectionRow};
use std::path::Path;
use std::time::Instant;

/// The shipped wing: its sections table and the profile files it names.
const TABLE: (&str, &str) = (
    "wing.csv",
    include_str!("../../../../data/loft-wing/wing.csv"),
);
const PROFILES: [(&str, &str); 3] = [
    (
        "naca4415.dat",
        include_str!("../../../../data/loft-wing/naca4415.dat"),
    ),
    (
        "naca2412.dat",
        include_str!("../../../../data/loft-wing/naca2412.dat"),
    ),
    (
        "naca0009.dat",
        include_str!("../../../../data/loft-wing/naca0009.dat"),
    ),
];

/// Lines along the span on which the monotone rule is checked.
pub const SPAN_LINES: usize = 1000;

/// The example's name in the report's rows.
pub const EXAMPLE: &str = "loft: shipped wing, 3 sections";

/// The wing's profiles and placements, read by the command line's readers.
pub fn shipped_wing() -> Result<(Vec<Vec<Point2>>, Vec<WingPlacement>)> {
    let rows = parse_sections_table(TABLE.1, Path::new(TABLE.0), Path::new(""))?;
    let mut profiles = Vec::with_capacity(rows.len());
    for row in &rows {
        let (name, text) = PROFILES
            .iter()
            .find(|(name, _)| *name == row.file)
            .ok_or_else(|| anyhow!("{}: no shipped profile {}", TABLE.0, row.file))?;
        match parse_curve_points(text, Path::new(name))? {
            CurvePoints::Planar(points) => profiles.push(points),
            CurvePoints::Spatial(_) => return Err(anyhow!("{name}: not a planar profile")),
        }
    }
    let placements = rows.iter().map(SectionRow::placement).collect();
    Ok((profiles, placements))
}

/// Distance from `q` to `curve` by 4000 samples and a golden-section refinement around the
/// nearest.
fn distance_to(curve: &BSplineCurve<3>, q: Point3) -> f64 {
    let n = 4000;
    let (mut best, mut at) = (f64::INFINITY, 0.0);
    for k in 0..=n {
        let t = k as f64 / n as f64;
        let d = curve.eval(t).distance(q);
        if d < best {
            (best, at) = (d, t);
        }
    }
    let step = 1.0 / n as f64;
    let (mut a, mut b) = ((at - step).max(0.0), (at + step).min(1.0));
    for _ in 0..60 {
        let (c, d) = (a + 0.382 * (b - a), a + 0.618 * (b - a));
        if curve.eval(c).distance(q) < curve.eval(d).distance(q) {
            b = d;
        } else {
            a = c;
        }
    }
    best.min(curve.eval(0.5 * (a + b)).distance(q))
}

/// The placement figures of the surface at span station `u`: leading edge (`v = 1/2`),
/// trailing-edge gap (upper end minus lower), chord and twist (degrees, nose up) of the line
/// from the leading edge to the trailing edge's middle.
pub struct SpanLine {
    /// The leading edge.
    pub leading_edge: Point3,
    /// The upper trailing-edge end minus the lower one.
    pub gap: Point3,
    /// The chord.
    pub chord: f64,
    /// The twist, degrees.
    pub twist: f64,
}

/// The placement figures of `loft` at `u`.
pub fn span_line(loft: &Loft, u: f64) -> SpanLine {
    let le = loft.eval(u, 0.5);
    let (upper, lower) = (loft.eval(u, 0.0), loft.eval(u, 1.0));
    let chord = (upper + lower) * 0.5 - le;
    let down = chord[1].hypot(chord[2]) * if chord[2] > 0.0 { -1.0 } else { 1.0 };
    SpanLine {
        leading_edge: le,
        gap: upper - lower,
        chord: chord.norm(),
        twist: down.atan2(chord[0]).to_degrees(),
    }
}

/// The lines among [`SPAN_LINES`] lines along the span whose chord, twist or leading edge
/// leave the range of the two sections around them, and those whose trailing-edge branches
/// cross (the upper end below the lower one).
pub fn monotone_violations(loft: &Loft) -> (Vec<String>, Vec<String>) {
    let stations = loft.stations();
    let at: Vec<SpanLine> = stations.iter().map(|&u| span_line(loft, u)).collect();
    let within =
        |v: f64, a: f64, b: f64, slack: f64| v >= a.min(b) - slack && v <= a.max(b) + slack;
    let size = at.iter().fold(0.0f64, |m, l| m.max(l.chord));
    let (mut placement, mut crossings) = (Vec::new(), Vec::new());
    let (first, last) = (stations[0], stations[stations.len() - 1]);
    for j in 0..SPAN_LINES {
        let u = first + (last - first) * (j as f64 + 0.5) / SPAN_LINES as f64;
        let k = (stations.partition_point(|&s| s <= u) - 1).min(stations.len() - 2);
        let (a, b, l) = (&at[k], &at[k + 1], span_line(loft, u));
        let mut out = Vec::new();
        for c in 0..3 {
            if !within(
                l.leading_edge[c],
                a.leading_edge[c],
                b.leading_edge[c],
                1e-12 * size,
            ) {
                out.push(format!("leading edge {}", ["x", "y", "z"][c]));
            }
        }
        // Chord and twist to the loft's tolerance (docs/methods.md §7.3: a polynomial surface
        // cannot turn a chord line at constant length), the leading edge exactly.
        if !within(
            l.chord,
            a.chord,
            b.chord,
            DEFAULT_TOLERANCE * a.chord.max(b.chord),
        ) {
            out.push(format!(
                "chord {} not in [{}, {}]",
                l.chord, a.chord, b.chord
            ));
        }
        if !within(l.twist, a.twist, b.twist, DEFAULT_TOLERANCE.to_degrees()) {
            out.push(format!(
                "twist {} not in [{}, {}]",
                l.twist, a.twist, b.twist
            ));
        }
        if !out.is_empty() {
            placement.push(format!("{u}: {}", out.join(", ")));
        }
        // Upper above lower: the gap's component along the section's normal (z for a
        // wing whose twist and dihedral stay well below 90 degrees) keeps its sign.
        if l.gap[2] < -1e-12 * size {
            crossings.push(format!("{u}: the trailing-edge branches cross"));
        }
    }
    (placement, crossings)
}

/// The largest distance of a placed input point from the surface's curve at its station and
/// the largest distances of the surface's leading and trailing edges from the placed ones, each
/// as a share of the section's chord; and the number of input points beyond the tolerance.
pub struct SectionFit {
    /// Largest input point's distance over its chord.
    pub worst: f64,
    /// Input points farther than the tolerance.
    pub beyond: usize,
    /// Largest leading-edge distance over the chord.
    pub leading_edge: f64,
    /// Largest trailing-edge end distance over the chord.
    pub trailing_edge: f64,
    /// Input points in all.
    pub points: usize,
}

/// Measures `loft` against the placed points of `profiles` at `placements`.
pub fn section_fit(
    loft: &Loft,
    profiles: &[Vec<Point2>],
    placements: &[WingPlacement],
) -> Result<SectionFit> {
    let (frames, _) = wing_frames(placements)?;
    let tolerance = loft.options().tolerance;
    let mut fit = SectionFit {
        worst: 0.0,
        beyond: 0,
        leading_edge: 0.0,
        trailing_edge: 0.0,
        points: 0,
    };
    for (k, (profile, frame)) in profiles.iter().zip(&frames).enumerate() {
        let u = loft.stations()[k];
        let chord = placements[k].chord;
        let curve = loft.section_at(u);
        for &p in profile {
            let d = distance_to(&curve, frame.place(p)) / chord;
            fit.worst = fit.worst.max(d);
            fit.beyond += usize::from(d > tolerance);
        }
        fit.points += profile.len();
        // The leading edge: the profile's point of smallest x.
        let le = profile
            .iter()
            .min_by(|a, b| a[0].total_cmp(&b[0]))
            .context("an empty profile")?;
        fit.leading_edge = fit
            .leading_edge
            .max(loft.eval(u, 0.5).distance(frame.place(*le)) / chord);
        // The trailing-edge ends at v = 0 and 1, in the profile's order or (a profile given
        // lower side first) the other way round.
        let ends = [profile[0], profile[profile.len() - 1]].map(|p| frame.place(p));
        let (start, end) = (loft.eval(u, 0.0), loft.eval(u, 1.0));
        let off = (start.distance(ends[0]).max(end.distance(ends[1])))
            .min(start.distance(ends[1]).max(end.distance(ends[0])));
        fit.trailing_edge = fit.trailing_edge.max(off / chord);
    }
    Ok(fit)
}

/// The camera of the wing's picture: behind the right wing, above it.
const WING_VIEW: View = View {
    azimuth: -60.0,
    elevation: 30.0,
};

/// Runs the example into `out`.
pub fn run(out: &Output) -> Result<Vec<Finding>> {
    let (profiles, placements) = shipped_wing()?;
    write_text(&out.file("loft-wing.csv"), TABLE.1)?;
    for (name, text) in PROFILES {
        write_text(&out.file(format!("loft-wing-{name}")), text)?;
    }
    let options = LoftOptions::default();
    let begun = Instant::now();
    let loft = Loft::wing(&profiles, &placements, &options).context("the shipped wing")?;
    let ms = begun.elapsed().as_secs_f64() * 1e3;
    let fit = section_fit(&loft, &profiles, &placements)?;
    let (placement, crossings) = monotone_violations(&loft);
    let (rows, cols) = loft.control_counts();

    write_wing_views(out, &loft)?;
    let e = EXAMPLE;
    Ok(vec![
        Finding::new(e, "sections", profiles.len() as f64),
        Finding::new(e, "control points along the span", rows as f64),
        Finding::new(e, "control points along the sections", cols as f64),
        Finding::new(
            e,
            format!(
                "largest distance of an input point ({} in all) from the surface at its \
                 station, share of the chord (tolerance {DEFAULT_TOLERANCE:e})",
                fit.points
            ),
            fit.worst,
        ),
        Finding::new(
            e,
            format!("input points farther than the tolerance {DEFAULT_TOLERANCE:e}"),
            fit.beyond as f64,
        ),
        Finding::new(
            e,
            "leading-edge line off the placed leading edges, share of the chord",
            fit.leading_edge,
        ),
        Finding::new(
            e,
            "trailing-edge lines off the placed trailing-edge points, share of the chord",
            fit.trailing_edge,
        ),
        Finding::new(
            e,
            format!(
                "{SPAN_LINES} spanwise lines with chord, twist or leading edge outside the \
                 neighbouring sections' range (chord and twist to the tolerance)"
            ),
            placement.len() as f64,
        ),
        Finding::new(
            e,
            format!("{SPAN_LINES} spanwise lines whose trailing-edge branches cross"),
            crossings.len() as f64,
        ),
        Finding::new(e, "loft time, ms", ms).detail(),
    ])
}

/// The wing's mesh with its sections and edges: picture and viewer.
fn write_wing_views(out: &Output, loft: &Loft) -> Result<()> {
    let (nu, nv) = (61, 121);
    let (_, _, mesh) = sample_surface(loft, nu, nv);
    let sections: Vec<Vec<Point3>> = loft
        .stations()
        .iter()
        .map(|&u| {
            (0..nv)
                .map(|j| loft.eval(u, j as f64 / (nv - 1) as f64))
                .collect()
        })
        .collect();
    let edges: Vec<Vec<Point3>> = [0.0, 0.5, 1.0]
        .iter()
        .map(|&v| (0..nu).map(|i| loft.eval(span_u(loft, i, nu), v)).collect())
        .collect();
    let scene = Scene {
        title: "The shipped wing lofted through its 3 sections (monotone spanwise rule)",
        mesh: SceneMesh {
            rows: nu,
            cols: nv,
            points: &mesh,
        },
        curves: &[
            SceneCurves {
                label: "sections",
                lines: &sections,
                rgb: (200, 40, 30),
                width: 1.6,
            },
            SceneCurves {
                label: "leading and trailing edges",
                lines: &edges,
                rgb: (20, 60, 200),
                width: 1.2,
            },
        ],
        view: WING_VIEW,
    };
    write_scene_svg(&out.file("loft-wing-view.svg"), &scene)?;
    write_viewer(
        out,
        "loft-wing.html",
        "The shipped wing lofted through its 3 sections",
        (nu, nv),
        &mesh,
        None,
        vec![("sections", sections.clone()), ("edges", edges.clone())],
    )?;
    Ok(())
}

/// The `i`-th of `n` stations spread evenly over the loft's span.
fn span_u(loft: &Loft, i: usize, n: usize) -> f64 {
    let d = loft.domain_u();
    d.start + d.length() * i as f64 / (n - 1) as f64
}

#[cfg(test)]
mod tests {
    use super::*;
    use karkas::loft::SpanRule;

    #[test]
    fn the_shipped_wing_meets_its_rows() {
        let (profiles, placements) = shipped_wing().unwrap();
        assert_eq!(profiles.len(), 3);
        let loft = Loft::wing(&profiles, &placements, &LoftOptions::default()).unwrap();
        let fit = section_fit(&loft, &profiles, &placements).unwrap();
        assert!(fit.worst <= DEFAULT_TOLERANCE, "{}", fit.worst);
        assert_eq!(fit.beyond, 0);
        assert!(fit.leading_edge < 1e-12 && fit.trailing_edge < 1e-12);
        let (placement, crossings) = monotone_violations(&loft);
        assert!(placement.is_empty(), "{placement:?}");
        assert!(crossings.is_empty(), "{crossings:?}");
    }

    /// The checks can fail: a looser loft leaves points beyond 1e-5, the not-a-knot spline
    /// through a twist that reverses overshoots its neighbours, and a profile moved off its
    /// placed section shows as a leading-edge and trailing-edge error.
    #[test]
    fn the_checks_catch_what_they_are_for() {
        let (profiles, mut placements) = shipped_wing().unwrap();
        let loose = LoftOptions {
            tolerance: 1e-3,
            ..LoftOptions::default()
        };
        let loft = Loft::wing(&profiles, &placements, &loose).unwrap();
        let fit = section_fit(&loft, &profiles, &placements).unwrap();
        // Measured against 1e-3 the loft passes; its points stand farther than 1e-5.
        assert!(
            fit.worst > DEFAULT_TOLERANCE && fit.worst <= 1e-3,
            "{}",
            fit.worst
        );
        // A twist that goes up and down again: the spline overshoots between the sections;
        // the monotone rule, whose slopes act on the placement, keeps it in range.
        placements[1].twist = 6.0;
        let spline = LoftOptions {
            rule: SpanRule::Spline,
            ..LoftOptions::default()
        };
        let loft = Loft::wing(&profiles, &placements, &spline).unwrap();
        let (placement, _) = monotone_violations(&loft);
        assert!(!placement.is_empty());
        let loft = Loft::wing(&profiles, &placements, &LoftOptions::default()).unwrap();
        let (placement, crossings) = monotone_violations(&loft);
        assert!(placement.is_empty(), "{placement:?}");
        assert!(crossings.is_empty(), "{crossings:?}");
        // The surface measured against sections placed elsewhere.
        let mut moved = placements.clone();
        moved[2].leading_edge += Point3::new([0.0, 0.0, 0.01]);
        let fit = section_fit(&loft, &profiles, &moved).unwrap();
        assert!(
            fit.leading_edge > 0.01 && fit.beyond > 0,
            "{}",
            fit.leading_edge
        );
        // The trailing edges: every section's upper end moved below its lower one (their
        // y exchanged; the shipped sections are all blunt) crosses on every line.
        let mut crossed: Vec<Vec<Point2>> = profiles.clone();
        for p in &mut crossed {
            let n = p.len() - 1;
            let (a, b) = (p[0].0[1], p[n].0[1]);
            assert!(a > b);
            (p[0].0[1], p[n].0[1]) = (b, a);
        }
        let inverted = Loft::wing(&crossed, &placements, &LoftOptions::default()).unwrap();
        assert_eq!(monotone_violations(&inverted).1.len(), SPAN_LINES);
    }
}

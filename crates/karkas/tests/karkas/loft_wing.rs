//! Lofted wings: sections within the tolerance, leading and trailing edges through the placed
//! sections, the monotone rule's guarantees between sections, and bad sections refused.

use karkas::bspline::BSplineCurve;
use karkas::loft::{wing_frames, Loft, LoftOptions, SpanRule, WingPlacement};
use karkas::{Curve, Error, Point2, Point3, Surface};

/// A NACA 4-digit section `m p t` with `n` points per side (cosine spacing) in Selig order,
/// with the thickness polynomial's last coefficient `a4` (-0.1036 closes the trailing edge,
/// -0.1015 leaves it blunt).
fn naca(m: f64, p: f64, t: f64, a4: f64, n: usize) -> Vec<Point2> {
    let point = |x: f64, upper: bool| {
        let yt = 5.0
            * t
            * (0.2969 * x.sqrt() - 0.126 * x - 0.3516 * x * x
                + 0.2843 * x.powi(3)
                + a4 * x.powi(4));
        let (yc, slope) = if m == 0.0 {
            (0.0, 0.0)
        } else if x < p {
            (
                m / (p * p) * (2.0 * p * x - x * x),
                2.0 * m / (p * p) * (p - x),
            )
        } else {
            let q = (1.0 - p) * (1.0 - p);
            (
                m / q * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
                2.0 * m / q * (p - x),
            )
        };
        let th = slope.atan();
        let s = if upper { 1.0 } else { -1.0 };
        Point2::new([x - s * yt * th.sin(), yc + s * yt * th.cos()])
    };
    let xs: Vec<f64> = (0..=n)
        .map(|k| 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / n as f64).cos()))
        .collect();
    let mut out: Vec<Point2> = xs.iter().rev().map(|&x| point(x, true)).collect();
    out.extend(xs[1..].iter().map(|&x| point(x, false)));
    out
}

fn at(x: f64, y: f64, z: f64) -> Point3 {
    Point3::new([x, y, z])
}

/// Root, two inner sections and tip: taper, twist, sweep and dihedral; blunt root, sharp tip.
fn wing() -> (Vec<Vec<Point2>>, Vec<WingPlacement>) {
    let profiles = vec![
        naca(0.04, 0.4, 0.15, -0.1015, 90),
        naca(0.03, 0.4, 0.13, -0.1015, 70),
        naca(0.02, 0.4, 0.12, -0.1036, 61),
        naca(0.0, 0.3, 0.10, -0.1036, 45),
    ];
    let place = |x: f64, y: f64, z: f64, chord: f64, twist: f64| WingPlacement {
        leading_edge: at(x, y, z),
        chord,
        twist,
        dihedral: None,
    };
    let placements = vec![
        place(0.0, 0.0, 0.0, 2.0, 3.0),
        place(0.35, 2.0, 0.12, 1.6, 1.5),
        place(0.8, 4.5, 0.35, 1.1, -0.5),
        place(1.3, 6.0, 0.6, 0.6, -2.5),
    ];
    (profiles, placements)
}

/// The placed points of every section.
fn placed(profiles: &[Vec<Point2>], placements: &[WingPlacement]) -> Vec<Vec<Point3>> {
    let (frames, _) = wing_frames(placements).unwrap();
    profiles
        .iter()
        .zip(&frames)
        .map(|(p, f)| p.iter().map(|&q| f.place(q)).collect())
        .collect()
}

/// Distance from `q` to `curve` by dense sampling and a golden-section refinement.
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
    let (mut a, mut b) = (
        (at - 1.0 / n as f64).max(0.0),
        (at + 1.0 / n as f64).min(1.0),
    );
    for _ in 0..80 {
        let (c, d) = (a + 0.382 * (b - a), a + 0.618 * (b - a));
        if curve.eval(c).distance(q) < curve.eval(d).distance(q) {
            b = d;
        } else {
            a = c;
        }
    }
    best.min(curve.eval(0.5 * (a + b)).distance(q))
}

#[test]
fn every_section_point_lies_within_the_tolerance_for_every_rule() {
    let (profiles, placements) = wing();
    let points = placed(&profiles, &placements);
    for rule in [SpanRule::Linear, SpanRule::Monotone, SpanRule::Spline] {
        for tolerance in [1e-4, 1e-5, 3e-6] {
            let options = LoftOptions { rule, tolerance };
            let loft = Loft::wing(&profiles, &placements, &options).unwrap();
            assert!(
                loft.tolerance_met(),
                "{rule:?} {tolerance}: {:?}",
                loft.deviations()
            );
            for (k, section) in points.iter().enumerate() {
                let curve = loft.section_at(loft.stations()[k]);
                let worst = section
                    .iter()
                    .map(|&q| distance_to(&curve, q))
                    .fold(0.0, f64::max);
                let limit = tolerance * placements[k].chord;
                assert!(
                    worst <= limit * 1.0001,
                    "{rule:?} {tolerance} section {k}: {worst} > {limit}"
                );
            }
        }
    }
}

#[test]
fn leading_and_trailing_edges_pass_through_the_placed_sections() {
    let (profiles, placements) = wing();
    let points = placed(&profiles, &placements);
    for rule in [SpanRule::Linear, SpanRule::Monotone, SpanRule::Spline] {
        let loft = Loft::wing(
            &profiles,
            &placements,
            &LoftOptions {
                rule,
                ..Default::default()
            },
        )
        .unwrap();
        for (k, section) in points.iter().enumerate() {
            let u = loft.stations()[k];
            let le = (0..section.len())
                .min_by(|&a, &b| profiles[k][a][0].total_cmp(&profiles[k][b][0]))
                .unwrap();
            let size = placements[k].chord;
            assert!(
                loft.eval(u, 0.5).distance(section[le]) < 1e-12 * size,
                "{rule:?} {k} LE"
            );
            assert!(
                loft.eval(u, 0.0).distance(section[0]) < 1e-12 * size,
                "{rule:?} {k} TE"
            );
            assert!(
                loft.eval(u, 1.0).distance(*section.last().unwrap()) < 1e-12 * size,
                "{rule:?} {k} TE"
            );
        }
    }
}

/// Leading edge, trailing-edge middle and gap, chord and twist of the surface at `u`.
struct Line {
    le: Point3,
    gap: Point3,
    chord: f64,
    twist: f64,
}

fn line(loft: &Loft, u: f64) -> Line {
    let le = loft.eval(u, 0.5);
    let (upper, lower) = (loft.eval(u, 0.0), loft.eval(u, 1.0));
    let e = (upper + lower) * 0.5 - le;
    let yz = e[1].hypot(e[2]) * if e[2] > 0.0 { -1.0 } else { 1.0 };
    Line {
        le,
        gap: upper - lower,
        chord: e.norm(),
        twist: yz.atan2(e[0]).to_degrees(),
    }
}

fn within(v: f64, a: f64, b: f64, slack: f64) -> bool {
    v >= a.min(b) - slack && v <= a.max(b) + slack
}

/// The lines among 1000 along the span of `loft` whose leading edge, chord or twist leave the
/// range of the two sections around them, or whose trailing-edge branches cross (the upper
/// end below the lower one along z, the sections' normal for twists and dihedrals well below
/// 90 degrees); with the trailing-edge gap's coordinates checked too when `gap` is set.
fn monotone_violations(loft: &Loft, gap: bool) -> Vec<String> {
    let stations = loft.stations().to_vec();
    let at_stations: Vec<Line> = stations.iter().map(|&u| line(loft, u)).collect();
    let size = at_stations.iter().fold(0.0f64, |m, l| m.max(l.chord));
    let mut violations = Vec::new();
    let (first, last) = (stations[0], stations[stations.len() - 1]);
    for j in 0..1000 {
        let u = first + (last - first) * (j as f64 + 0.5) / 1000.0;
        let k = (stations.partition_point(|&s| s <= u) - 1).min(stations.len() - 2);
        let (a, b) = (&at_stations[k], &at_stations[k + 1]);
        let l = line(loft, u);
        for c in 0..3 {
            if !within(l.le[c], a.le[c], b.le[c], 1e-12 * size) {
                violations.push(format!("{u}: leading edge {c}"));
            }
            if gap && !within(l.gap[c], a.gap[c], b.gap[c], 1e-12 * size) {
                violations.push(format!("{u}: trailing-edge gap {c}"));
            }
        }
        if !within(l.chord, a.chord, b.chord, 1e-12 * size) {
            violations.push(format!(
                "{u}: chord {} not in [{}, {}]",
                l.chord, a.chord, b.chord
            ));
        }
        if !within(l.twist, a.twist, b.twist, 1e-9) {
            violations.push(format!(
                "{u}: twist {} not in [{}, {}]",
                l.twist, a.twist, b.twist
            ));
        }
        if l.gap[2] < -1e-12 * size {
            violations.push(format!("{u}: trailing edges cross"));
        }
    }
    violations
}

#[test]
fn the_monotone_rule_keeps_placement_between_neighbours_on_1000_lines() {
    let (profiles, placements) = wing();
    let loft = Loft::wing(&profiles, &placements, &LoftOptions::default()).unwrap();
    let stations = loft.stations().to_vec();
    let at_stations: Vec<Line> = stations.iter().map(|&u| line(&loft, u)).collect();
    // The figures at the stations are those of the placed points: the chord within 0.2% of
    // the placed one (a cambered NACA section's point of smallest x lies a little ahead of
    // x = 0), the twist within 0.25 degrees.
    for (k, l) in at_stations.iter().enumerate() {
        assert!(
            (l.chord - placements[k].chord).abs() < 2e-3 * placements[k].chord,
            "{k} {}",
            l.chord
        );
        assert!(
            (l.twist - placements[k].twist).abs() < 0.25,
            "{k} {}",
            l.twist
        );
    }
    let violations = monotone_violations(&loft, true);
    assert!(
        violations.is_empty(),
        "{} violations: {:?}",
        violations.len(),
        &violations[..violations.len().min(10)]
    );
}

/// A small deterministic generator (xorshift) for the sweep of wings.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }

    fn between(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// A wing of 3 to 20 sections from `seed`, drawn to be hard: uneven stations, chords whose
/// ratio to the one before runs from 1/5 to 5 (or repeats it), twists from -20 to 25 degrees
/// that rise and fall at random (or repeat), sweep back and forward, dihedrals given (-30 to
/// 45 degrees) or from leading edges climbing or falling up to 45 degrees, a root as far as
/// 1000 chords from the origin, the whole wing scaled by 1e-3 to 1e3, blunt and sharp
/// trailing edges mixed.
fn random_wing(seed: u64) -> (Vec<Vec<Point2>>, Vec<WingPlacement>) {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15 ^ (seed.wrapping_add(1) * 0x2545_f491_4f6c_dd1d));
    let n = 3 + (rng.next() * 18.0) as usize;
    let scale = 10f64.powf(rng.between(-3.0, 3.0));
    let given_dihedral = rng.next() < 0.4;
    let far = 10f64.powf(rng.between(-1.0, 3.0));
    let mut le = [0, 1, 2].map(|_| scale * far * rng.between(-1.0, 1.0));
    let (mut chord, mut twist) = (scale * rng.between(0.5, 2.0), rng.between(-20.0, 25.0));
    let mut profiles = Vec::with_capacity(n);
    let mut placements = Vec::with_capacity(n);
    for k in 0..n {
        if k > 0 {
            let step = scale * rng.between(0.05, 3.0);
            le[0] += step * rng.between(-0.5, 1.5);
            le[1] += step;
            le[2] += step * rng.between(-1.0, 1.0);
            if rng.next() > 0.15 {
                chord *= 5f64.powf(rng.between(-1.0, 1.0));
            }
            if rng.next() > 0.15 {
                twist = rng.between(-20.0, 25.0);
            }
        }
        let a4 = if rng.next() < 0.5 { -0.1015 } else { -0.1036 };
        profiles.push(naca(
            rng.between(0.0, 0.06),
            rng.between(0.2, 0.6),
            rng.between(0.06, 0.2),
            a4,
            30 + (rng.next() * 60.0) as usize,
        ));
        placements.push(WingPlacement {
            leading_edge: at(le[0], le[1], le[2]),
            chord,
            twist,
            dihedral: given_dihedral.then(|| rng.between(-30.0, 45.0)),
        });
    }
    (profiles, placements)
}

/// The lines among 1000 along the span of `loft` whose leading edge (any coordinate), chord
/// or twist leave the range of the two sections around them by more than the loft's
/// tolerance (the chord and the leading edge by that share of the longer neighbouring chord,
/// the twist by that many radians), or whose trailing-edge branches cross (the upper end
/// below the lower one along z, beyond the coordinates' round-off).
fn violations_beyond_tolerance(loft: &Loft, tolerance: f64) -> Vec<String> {
    let stations = loft.stations().to_vec();
    let at_stations: Vec<Line> = stations.iter().map(|&u| line(loft, u)).collect();
    let (first, last) = (stations[0], stations[stations.len() - 1]);
    let mut violations = Vec::new();
    for j in 0..1000 {
        let u = first + (last - first) * (j as f64 + 0.5) / 1000.0;
        let k = (stations.partition_point(|&s| s <= u) - 1).min(stations.len() - 2);
        let (a, b) = (&at_stations[k], &at_stations[k + 1]);
        let l = line(loft, u);
        let slack = tolerance * a.chord.max(b.chord);
        for c in 0..3 {
            if !within(l.le[c], a.le[c], b.le[c], slack) {
                violations.push(format!("{u}: leading edge {c}"));
            }
        }
        if !within(l.chord, a.chord, b.chord, slack) {
            let beyond = (a.chord.min(b.chord) - l.chord).max(l.chord - a.chord.max(b.chord));
            let share = beyond / a.chord.max(b.chord);
            violations.push(format!("{u}: chord {share:.2e} of it beyond"));
        }
        if !within(l.twist, a.twist, b.twist, tolerance.to_degrees()) {
            let beyond = (a.twist.min(b.twist) - l.twist).max(l.twist - a.twist.max(b.twist));
            violations.push(format!("{u}: twist {beyond:.2e} degrees beyond"));
        }
        let round_off = 1e-12 * (l.chord + l.le.norm());
        if l.gap[2] < -round_off {
            violations.push(format!("{u}: trailing edges cross"));
        }
    }
    violations
}

/// The tapered wing of the other tests with a twist that rises then falls and one that falls
/// then rises: chord, twist and leading edge stay within their neighbours' range on every
/// one of 1000 lines (the rule's slopes act on the placement; with Fritsch and Carlson's
/// slopes of each control point's coordinates the twist passed 6 degrees beside the middle
/// section), with and without changing dihedrals.
#[test]
fn a_twist_that_turns_back_stays_between_its_neighbours() {
    let (profiles, placements) = wing();
    for twists in [
        [2.0, 6.0, -3.0, 1.0],
        [2.0, -4.0, 3.0, -1.0],
        [-1.0, 5.0, 5.5, 0.0],
    ] {
        for dihedral in [None, Some([0.0, 12.0, 3.0, -4.0])] {
            let mut p = placements.clone();
            for k in 0..4 {
                p[k].twist = twists[k];
                p[k].dihedral = dihedral.map(|d| d[k]);
            }
            let loft = Loft::wing(&profiles, &p, &LoftOptions::default()).unwrap();
            let violations = monotone_violations(&loft, false);
            assert!(
                violations.is_empty(),
                "{twists:?} {dihedral:?}: {} lines, {:?}",
                violations.len(),
                &violations[..violations.len().min(3)]
            );
        }
    }
}

/// A sweep of 500 wings not tuned on ([`random_wing`]: 3 to 20 sections, extreme taper,
/// twist and dihedral, far from the origin, at scales 1e-3 to 1e3), and the wing of the
/// other tests with chords that grow then shrink or stay equal: on every one of 1000 lines
/// along the span the leading edge, chord and twist stay within their neighbours' range to
/// the loft's tolerance and the trailing-edge branches never cross. The tolerance is the
/// slack because a polynomial surface cannot do better: where two neighbours' chords are
/// equal and their twists differ, the chord line would have to turn on a circle. Before the
/// rule refined its pieces along the placement's path, 4.3e-3 of the chord and 4.5e-3
/// degrees were passed on wings of a 64-wing sweep.
#[test]
fn the_monotone_rule_keeps_placement_between_neighbours_on_a_sweep_of_wings() {
    let tolerance = LoftOptions::default().tolerance;
    let mut failures = Vec::new();
    let mut check = |name: String, profiles: &[Vec<Point2>], placements: &[WingPlacement]| {
        let loft = Loft::wing(profiles, placements, &LoftOptions::default()).unwrap();
        assert!(loft.tolerance_met(), "{name}");
        let violations = violations_beyond_tolerance(&loft, tolerance);
        if !violations.is_empty() {
            failures.push(format!(
                "{name}: {} lines, {:?}",
                violations.len(),
                &violations[..violations.len().min(3)]
            ));
        }
    };
    let (profiles, placements) = wing();
    for (twists, chords) in [
        ([3.0, 1.5, -0.5, -2.5], [1.0, 1.8, 0.9, 1.2]),
        ([0.0, 8.0, 8.0, -6.0], [1.2, 1.2, 0.7, 0.7]),
    ] {
        let mut p = placements.clone();
        for k in 0..4 {
            p[k].twist = twists[k];
            p[k].chord = chords[k];
        }
        check(
            format!("twists {twists:?} chords {chords:?}"),
            &profiles,
            &p,
        );
        for (k, d) in [0.0, 12.0, 3.0, -4.0].into_iter().enumerate() {
            p[k].dihedral = Some(d);
        }
        check(
            format!("twists {twists:?} chords {chords:?} dihedral"),
            &profiles,
            &p,
        );
    }
    for seed in 0..500u64 {
        let (profiles, placements) = random_wing(seed);
        check(
            format!("seed {seed}, {} sections", profiles.len()),
            &profiles,
            &placements,
        );
    }
    assert!(
        failures.is_empty(),
        "{} wings:\n{}",
        failures.len(),
        failures.join("\n")
    );
}

#[test]
fn a_not_a_knot_span_crosses_a_trailing_edge_the_monotone_rule_keeps() {
    // A blunt root and sharp outboard sections: the not-a-knot spline overshoots the
    // closed gap between the outboard sections; the monotone rule keeps it closed.
    let profiles = vec![
        naca(0.02, 0.4, 0.12, -0.09, 60),
        naca(0.02, 0.4, 0.12, -0.1036, 60),
        naca(0.02, 0.4, 0.12, -0.1036, 60),
        naca(0.02, 0.4, 0.12, -0.1036, 60),
    ];
    let placements: Vec<WingPlacement> = [0.0, 1.0, 2.0, 3.0]
        .iter()
        .map(|&y| WingPlacement {
            leading_edge: at(0.0, y, 0.0),
            chord: 1.0,
            twist: 0.0,
            dihedral: None,
        })
        .collect();
    let gap_min = |rule| {
        let loft = Loft::wing(
            &profiles,
            &placements,
            &LoftOptions {
                rule,
                ..Default::default()
            },
        )
        .unwrap();
        (0..=300)
            .map(|j| line(&loft, 3.0 * j as f64 / 300.0).gap[2])
            .fold(f64::INFINITY, f64::min)
    };
    assert!(
        gap_min(SpanRule::Spline) < -1e-4,
        "{}",
        gap_min(SpanRule::Spline)
    );
    assert!(
        gap_min(SpanRule::Monotone) >= -1e-15,
        "{}",
        gap_min(SpanRule::Monotone)
    );
    assert!(gap_min(SpanRule::Linear) >= -1e-15);
}

#[test]
fn bad_sections_are_refused_naming_the_section() {
    let (mut profiles, placements) = wing();
    let section_of = |e: Error| match e {
        Error::LoftSection { section, reason } => (section, reason),
        other => panic!("{other}"),
    };
    let mut percent = profiles.clone();
    percent[2] = percent[2].iter().map(|&p| p * 100.0).collect();
    let (k, reason) =
        section_of(Loft::wing(&percent, &placements, &LoftOptions::default()).unwrap_err());
    assert_eq!(k, 2);
    assert!(reason.contains("unit chord"), "{reason}");
    profiles[1].truncate(4);
    let (k, reason) =
        section_of(Loft::wing(&profiles, &placements, &LoftOptions::default()).unwrap_err());
    assert_eq!(k, 1);
    assert!(reason.contains("at least 5 points"), "{reason}");
}

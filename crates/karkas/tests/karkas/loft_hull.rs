//! A hull lofted from its table of offsets: the Wigley hull, whose half-breadth is known in
//! closed form, tabulated at stations and waterlines as a ship's table of offsets is, lofted
//! through its station sections; the Hausdorff distance between the loft and the analytic hull
//! measured independently of the loft's own figures (the hull's sections in each station plane,
//! both ways, against polylines of 1,000 segments).

use karkas::loft::{Loft, LoftOptions, LoftSection, Profile, SectionFrame, SpanRule};
use karkas::{Point2, Point3, Surface};

/// Length, beam and draught of the hull (the Wigley hull's usual proportions, `B/L = 0.1`,
/// `T/L = 0.0625`).
const L: f64 = 1.0;
const B: f64 = 0.1;
const T: f64 = 0.0625;

/// The Wigley hull's half-breadth at `x` in `[-L/2, L/2]` and height `z` in `[-T, 0]`
/// (the keel at `-T`, the waterline at 0).
fn half_breadth(x: f64, z: f64) -> f64 {
    0.5 * B * (1.0 - (2.0 * x / L).powi(2)) * (1.0 - (z / T).powi(2))
}

/// The loft of the table of offsets at `stations` x `waterlines` (both uniform), the hull's
/// midship at `x0` along the length.
fn hull(stations: usize, waterlines: usize, rule: SpanRule, x0: f64) -> Loft {
    let sections: Vec<LoftSection> = (0..stations)
        .map(|i| {
            let x = -0.5 * L + L * i as f64 / (stations - 1) as f64;
            // One station's offsets from the keel up: (half-breadth, height) in its plane.
            let offsets: Vec<Point2> = (0..waterlines)
                .map(|j| {
                    let z = -T + T * j as f64 / (waterlines - 1) as f64;
                    Point2::new([half_breadth(x, z), z])
                })
                .collect();
            LoftSection {
                profile: Profile::open(&offsets).unwrap(),
                frame: SectionFrame {
                    origin: Point3::new([x0 + x, 0.0, 0.0]),
                    x_axis: Point3::new([0.0, 1.0, 0.0]),
                    y_axis: Point3::new([0.0, 0.0, 1.0]),
                },
                station: x0 + x,
                scale: B,
            }
        })
        .collect();
    let options = LoftOptions {
        rule,
        tolerance: 1e-5,
    };
    Loft::new(&sections, &options).unwrap()
}

/// The distance from `p` to the polyline `line`.
fn to_polyline(p: [f64; 2], line: &[[f64; 2]]) -> f64 {
    line.windows(2)
        .map(|w| {
            let (a, b) = (w[0], w[1]);
            let (dx, dy) = (b[0] - a[0], b[1] - a[1]);
            let len_sq = dx * dx + dy * dy;
            let t = if len_sq > 0.0 {
                (((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len_sq).clamp(0.0, 1.0)
            } else {
                0.0
            };
            (p[0] - a[0] - t * dx).hypot(p[1] - a[1] - t * dy)
        })
        .fold(f64::INFINITY, f64::min)
}

/// An upper bound of the Hausdorff distance between the loft and the analytic hull: in each of
/// `planes` planes x = const across the length, the largest distance of the loft's section
/// from the hull's and of the hull's from the loft's (distances within a plane bound those in
/// space from above).
fn hausdorff(loft: &Loft, x0: f64, planes: usize) -> f64 {
    const SEGMENTS: usize = 1000;
    const PROBES: usize = 100;
    let mut worst = 0.0f64;
    for k in 0..planes {
        let x = -0.5 * L + L * k as f64 / (planes - 1) as f64;
        let u = x0 + x;
        // The loft's sections are planar: every point of its u-section lies at x = u.
        let loft_line: Vec<[f64; 2]> = (0..=SEGMENTS)
            .map(|j| {
                let p = loft.eval(u, j as f64 / SEGMENTS as f64);
                assert!(
                    (p[0] - u).abs() < 1e-9 * (1.0 + u.abs()),
                    "{p:?} off the plane {u}"
                );
                [p[1], p[2]]
            })
            .collect();
        let hull_line: Vec<[f64; 2]> = (0..=SEGMENTS)
            .map(|j| {
                let z = -T + T * j as f64 / SEGMENTS as f64;
                [half_breadth(x, z), z]
            })
            .collect();
        for j in 0..=PROBES {
            let f = j as f64 / PROBES as f64;
            let on_loft = loft_line[(f * SEGMENTS as f64).round() as usize];
            let on_hull = hull_line[(f * SEGMENTS as f64).round() as usize];
            worst = worst
                .max(to_polyline(on_loft, &hull_line))
                .max(to_polyline(on_hull, &loft_line));
        }
    }
    worst
}

#[test]
fn wigley_hull_from_its_offsets_within_the_tolerance_order() {
    let mut rows = Vec::new();
    for (stations, waterlines) in [(11, 6), (21, 11), (41, 21)] {
        for rule in [SpanRule::Linear, SpanRule::Monotone, SpanRule::Spline] {
            for x0 in [0.0, 250.0] {
                let loft = hull(stations, waterlines, rule, x0);
                assert!(loft.tolerance_met(), "{stations}x{waterlines} {rule:?}");
                // Every offset within the tolerance of the loft: its deviation, in model units.
                assert!(loft.max_relative_deviation() <= 1e-5 * (1.0 + 1e-9));
                let h = hausdorff(&loft, x0, 2 * stations + 1) / B;
                eprintln!(
                    "{stations} stations x {waterlines} waterlines, {rule:?}, x0 {x0}: \
                     Hausdorff {h:.2e} of the beam, {:?} control points",
                    loft.control_counts()
                );
                rows.push(((stations, rule, x0), h));
            }
        }
    }
    let h = |stations: usize, rule: SpanRule, x0: f64| {
        rows.iter()
            .find(|r| r.0 == (stations, rule, x0))
            .map(|r| r.1)
            .unwrap()
    };
    for rule in [SpanRule::Linear, SpanRule::Monotone, SpanRule::Spline] {
        // The distance falls as the table grows, and the hull's place along x changes nothing.
        assert!(h(21, rule, 0.0) < h(11, rule, 0.0), "{rule:?}");
        assert!(h(41, rule, 0.0) < h(21, rule, 0.0), "{rule:?}");
        for s in [11, 21, 41] {
            let (a, b) = (h(s, rule, 0.0), h(s, rule, 250.0));
            assert!((a - b).abs() <= 0.05 * a + 1e-9, "{s} {rule:?}: {a} {b}");
        }
    }
    // The distance is the table's (the hull between its offsets), not the fit's: 4e-4 of the
    // beam on 21 x 11 offsets, and on 41 x 21 offsets the tolerance's order with the spline
    // rule (6.7e-6 of the beam measured) and 7.6e-5 with the monotone one.
    assert!(h(21, SpanRule::Monotone, 0.0) < 1e-3, "{rows:?}");
    assert!(h(21, SpanRule::Spline, 0.0) < 1e-3, "{rows:?}");
    assert!(h(41, SpanRule::Monotone, 0.0) < 2e-4, "{rows:?}");
    assert!(h(41, SpanRule::Spline, 0.0) < 2e-5, "{rows:?}");
}

// The whole hull from the half (`Loft::mirrored`): a V-shaped hull whose sides meet at the
// keel at an angle, and one with a flat bottom.

/// A V-shaped hull of two stations: half sections from the keel at `(bottom, 0)` out to
/// the deck edge at `(1, 1)`, leaving the keel at about 45 degrees.
fn v_half_hull(bottom_half_breadth: f64) -> Loft {
    let sections: Vec<LoftSection> = [0.0, 2.0]
        .iter()
        .map(|&x| {
            let points: Vec<Point2> = (0..9)
                .map(|k| {
                    let z = k as f64 / 8.0;
                    let y = (z + 0.3 * z * z) / 1.3;
                    Point2::new([bottom_half_breadth + (1.0 - bottom_half_breadth) * y, z])
                })
                .collect();
            LoftSection {
                profile: Profile::open(&points).unwrap(),
                frame: SectionFrame {
                    origin: Point3::new([x, 0.0, 0.0]),
                    x_axis: Point3::new([0.0, 1.0, 0.0]),
                    y_axis: Point3::new([0.0, 0.0, 1.0]),
                },
                station: x,
                scale: 2.0,
            }
        })
        .collect();
    Loft::new(&sections, &LoftOptions::default()).unwrap()
}

#[test]
fn the_mirrored_hull_is_symmetric_with_its_keel_at_half() {
    let half = v_half_hull(0.0);
    let whole = half.mirrored(1).unwrap();
    assert_eq!(whole.control_counts().1, 2 * half.control_counts().1 - 1);
    for &u in &[0.0, 0.7, 2.0] {
        let keel = whole.eval(u, 0.5);
        assert!(keel[1].abs() < 1e-15, "{keel:?}");
        assert!(keel[2].abs() < 1e-12, "{keel:?}");
        for k in 0..=50 {
            let v = 0.5 * k as f64 / 50.0;
            let (p, q) = (whole.eval(u, 0.5 - v), whole.eval(u, 0.5 + v));
            assert!((p[1] + q[1]).abs() < 1e-12 && (p[2] - q[2]).abs() < 1e-12);
            // The starboard half is the half loft.
            let h = half.eval(u, 2.0 * v);
            assert!(q.distance(h) < 1e-12, "{q:?} {h:?}");
        }
    }
    // A corner at the keel: the port side comes down (z falls with v), the starboard side
    // goes up, both steeper than about 27 degrees.
    let (l, r) = (
        whole.deriv(1.0, 0.5 - 1e-9, 0, 1),
        whole.deriv(1.0, 0.5 + 1e-9, 0, 1),
    );
    assert!(l[1] > 0.0 && r[1] > 0.0, "{l:?} {r:?}");
    assert!(l[2] < -0.5 * l[1] && r[2] > 0.5 * r[1], "{l:?} {r:?}");
    assert!(v_half_hull(0.0).mirrored(3).is_err());
}

#[test]
fn a_flat_bottom_joins_the_halves_by_a_line() {
    let half = v_half_hull(0.3);
    let whole = half.mirrored(1).unwrap();
    assert_eq!(whole.control_counts().1, 2 * half.control_counts().1 + 2);
    for k in 0..=10 {
        let v = 0.45 + 0.1 * k as f64 / 10.0;
        let p = whole.eval(1.0, v);
        assert!(p[2].abs() < 1e-12, "{p:?}");
        assert!((p[1] - 0.3 * (v - 0.5) / 0.05).abs() < 1e-12, "{p:?}");
    }
    assert!(whole.mirrored(1).is_err());
}

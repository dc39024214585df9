//! A hydrofoil with known truth for the fitting demo (Pavlov, docs/methods.md §4): a section
//! from closed-form equations that resembles the paper's hydrofoil, sampled the way the
//! paper's 20 points are (the same x stations, the upper surface from the trailing edge to
//! the nose, then the lower surface back).
//!
//! The section is the NACA 4-digit mean line and thickness of a "6508" (6% camber at 50% of
//! the chord, 8% thick), its thickness opened linearly to a blunt trailing edge 3% of the
//! chord thick (the paper's trailing edge is open as well), cambered toward its lower
//! surface, 280 units long and turned 40 degrees, its leading edge at (-114.8, -102.6): the
//! chord, angle, camber and thickness a least-squares match to the paper's points gives
//! (without its points 6 to 8), rounded.

use karkas::Point2;

/// Camber (fraction of the chord), negative: toward the lower surface.
pub const CAMBER: f64 = -0.06;
/// Chordwise position of the largest camber.
pub const CAMBER_AT: f64 = 0.5;
/// Largest thickness (fraction of the chord) of the 4-digit thickness law.
pub const THICKNESS: f64 = 0.08;
/// Thickness added linearly along the chord, reaching this at the trailing edge.
pub const BLUNT_TRAILING_EDGE: f64 = 0.03;
/// Chord length in the paper's units.
pub const CHORD: f64 = 280.0;
/// Angle of the chord to the x axis, in degrees.
pub const ANGLE_DEG: f64 = 40.0;
/// The leading edge (chordwise position 0).
pub const LEADING_EDGE: [f64; 2] = [-114.8, -102.6];

/// The paper's x stations, in its order: upper surface from the trailing edge to the nose
/// (`None`: the nose point, the leftmost point of the section), then the lower surface.
pub const STATIONS: [Option<f64>; 20] = [
    Some(94.8),
    Some(71.1),
    Some(47.4),
    Some(23.7),
    Some(0.0),
    Some(-23.7),
    Some(-47.1),
    Some(-74.8),
    Some(-106.6),
    None,
    Some(-106.6),
    Some(-94.8),
    Some(-71.1),
    Some(-47.4),
    Some(-23.7),
    Some(0.0),
    Some(23.7),
    Some(47.4),
    Some(71.1),
    Some(94.8),
];

/// A surface of the section.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Side {
    /// The surface of the paper's points 1 to 10 (the concave one).
    Upper,
    /// The surface of the paper's points 11 to 20.
    Lower,
}

/// The point of surface `side` at chordwise position `u` in `[0, 1]`, in the paper's units.
pub fn section_point(u: f64, side: Side) -> Point2 {
    let (m, p) = (CAMBER, CAMBER_AT);
    let half = 5.0
        * THICKNESS
        * (0.2969 * u.sqrt() - 0.1260 * u - 0.3516 * u * u + 0.2843 * u.powi(3)
            - 0.1015 * u.powi(4))
        + 0.5 * BLUNT_TRAILING_EDGE * u;
    let (camber, slope) = if u < p {
        (
            m / (p * p) * (2.0 * p * u - u * u),
            2.0 * m / (p * p) * (p - u),
        )
    } else {
        (
            m / ((1.0 - p) * (1.0 - p)) * (1.0 - 2.0 * p + 2.0 * p * u - u * u),
            2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - u),
        )
    };
    let theta = slope.atan();
    let sign = match side {
        Side::Upper => 1.0,
        Side::Lower => -1.0,
    };
    let (a, b) = (
        u - sign * half * theta.sin(),
        camber + sign * half * theta.cos(),
    );
    let (s, c) = ANGLE_DEG.to_radians().sin_cos();
    Point2::new([
        LEADING_EDGE[0] + CHORD * (a * c - b * s),
        LEADING_EDGE[1] + CHORD * (a * s + b * c),
    ])
}

/// The chordwise position of the nose point: where the upper surface is leftmost (golden
/// section on `[0, 0.05]`, where x first falls and then rises).
pub fn nose_position() -> f64 {
    let x = |u: f64| section_point(u, Side::Upper)[0];
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let (mut a, mut b) = (0.0, 0.05);
    while b - a > 1e-13 {
        let (c, d) = (b - g * (b - a), a + g * (b - a));
        if x(c) < x(d) {
            b = d;
        } else {
            a = c;
        }
    }
    0.5 * (a + b)
}

/// The chordwise position where surface `side` reaches `x` (bisection beyond the nose, where
/// x grows along each surface).
fn station_position(x: f64, side: Side, nose: f64) -> f64 {
    let (mut a, mut b) = match side {
        Side::Upper => (nose, 1.0),
        Side::Lower => (0.0, 1.0),
    };
    for _ in 0..200 {
        let m = 0.5 * (a + b);
        if section_point(m, side)[0] < x {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// The 20 points at the paper's stations, in the paper's order, with their surface and
/// chordwise position.
pub fn sampled_points() -> Vec<(Point2, Side, f64)> {
    let nose = nose_position();
    STATIONS
        .iter()
        .enumerate()
        .map(|(i, station)| {
            let side = if i < 10 { Side::Upper } else { Side::Lower };
            let u = station.map_or(nose, |x| station_position(x, side, nose));
            (section_point(u, side), side, u)
        })
        .collect()
}

/// The true contour between the first and the last sampled point, around the nose, as a
/// polyline of `2 per_side` points (cosine spacing in the chordwise position, dense at the
/// nose).
pub fn true_contour(per_side: usize) -> Vec<Point2> {
    let samples = sampled_points();
    let (first, last) = (samples[0].2, samples[samples.len() - 1].2);
    let per_side = per_side.max(2);
    let cosine = |k: usize, end: f64| {
        let a = std::f64::consts::PI * k as f64 / (per_side - 1) as f64;
        end * 0.5 * (1.0 - a.cos())
    };
    let upper = (0..per_side)
        .rev()
        .map(|k| section_point(cosine(k, first), Side::Upper));
    let lower = (1..per_side).map(|k| section_point(cosine(k, last), Side::Lower));
    upper.chain(lower).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_points_stand_at_the_paper_stations_in_its_order() {
        let points = sampled_points();
        assert_eq!(points.len(), 20);
        for ((p, _, _), station) in points.iter().zip(STATIONS) {
            if let Some(x) = station {
                assert!((p[0] - x).abs() < 1e-9, "{p:?} at {x}");
            }
        }
        // The nose point is the leftmost of the section and sits where the paper's does.
        let nose = points[9].0;
        assert!((nose[0] + 115.0).abs() < 0.05, "{nose:?}");
        assert!((nose[1] + 101.7).abs() < 0.05, "{nose:?}");
        // Upper surface above the lower one at every shared station (a loop-free polygon).
        for k in 0..9 {
            let (upper, lower) = (points[k].0, points[19 - k].0);
            if (upper[0] - lower[0]).abs() < 1e-9 {
                assert!(upper[1] > lower[1] + 5.0, "station {}", upper[0]);
            }
        }
    }

    #[test]
    fn the_section_is_the_closed_form_at_the_nose_and_the_tail() {
        // At the leading edge both surfaces meet at the leading edge point.
        let (a, b) = (
            section_point(0.0, Side::Upper),
            section_point(0.0, Side::Lower),
        );
        assert!((a[0] - LEADING_EDGE[0]).abs() < 1e-12 && (b[1] - LEADING_EDGE[1]).abs() < 1e-12);
        // At the trailing edge the thickness is the 4-digit law's 0.0021 t / 0.2 ... plus the
        // blunt 3%: 10 t (0.2969 - 0.1260 - 0.3516 + 0.2843 - 0.1015) + 0.03 of the chord.
        let (a, b) = (
            section_point(1.0, Side::Upper),
            section_point(1.0, Side::Lower),
        );
        let gap = ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2)).sqrt();
        let expected = CHORD * (10.0 * THICKNESS * 0.0021 + BLUNT_TRAILING_EDGE);
        assert!((gap - expected).abs() < 1e-9, "{gap} {expected}");
    }
}

//! The monotone rule's spanwise slopes taken through the placement (docs/methods.md §7.3).
//!
//! A placed section's control point is `P = O + X p_x + Y p_y`: the profile's control point
//! `p` in its plane, the plane's origin `O` and axes `X`, `Y` in space. Interpolating each
//! coordinate of `P` with Fritsch and Carlson's slopes keeps every coordinate of every control
//! point in range, but not the quantities a designer placed: a twist that rises and then falls
//! turns the chord line past its largest value just beside the section where it turns back,
//! because the trailing edge's coordinates keep moving there while the twist stands still.
//!
//! Here the slope of `P` at a station is the derivative of the placement itself,
//! `P' = O' + X' p_x + Y' p_y + X p_x' + Y p_y'`, each factor with the shape-preserving
//! slopes of its own quantity:
//!
//! - the frame's rotation (the orthonormal frame of `X` and `Y` by Gram–Schmidt): its angular
//!   velocity, every world component of it by Fritsch and Carlson from the secant angular
//!   velocities (the rotation vector between consecutive frames over the step), so that a
//!   twist about one axis has exactly the slopes of the twist's shape-preserving interpolant —
//!   zero where the twist turns back;
//! - the axes' lengths and shear in that frame (the chord), the origin (the leading edge) and
//!   the profile's control points in its plane, each by Fritsch and Carlson.
//!
//! The surface is still the cubic Hermite interpolant of the placed control points (the
//! sections pass through exactly); only the slopes change. A rotation is not polynomial, so
//! between sections the chord line's turn follows the twist's interpolant to third order in
//! the step rather than exactly.
//!
//! Hand-written: the slopes are Fritsch and Carlson's ([`pchip_from_secants`]); the rotation
//! vector is the closed form of the matrix logarithm of a rotation.

#![allow(clippy::needless_range_loop)] // quantities by station

use super::pchip::pchip_from_secants;
use super::placement::{cross, SectionFrame};
use crate::core::Grid;
use crate::{Point2, Point3};

/// A section's frame as a rotation (orthonormal `e`, `e[0]` along the x axis) and the axes'
/// coordinates in it: `X = x_len e0`, `Y = y1 e0 + y2 e1`.
pub(super) struct SplitFrame {
    pub e: [Point3; 3],
    pub x_len: f64,
    pub y1: f64,
    pub y2: f64,
}

impl SplitFrame {
    pub(super) fn new(f: &SectionFrame) -> Option<SplitFrame> {
        let x_len = f.x_axis.norm();
        let e0 = f.x_axis * (1.0 / x_len);
        let y1 = f.y_axis.dot(e0);
        let rest = f.y_axis - e0 * y1;
        let y2 = rest.norm();
        let e1 = rest * (1.0 / y2);
        let e2 = cross(e0, e1);
        let ok = x_len > 0.0 && y2 > 0.0 && e0.is_finite() && e1.is_finite() && y1.is_finite();
        ok.then_some(SplitFrame {
            e: [e0, e1, e2],
            x_len,
            y1,
            y2,
        })
    }
}

/// The rotation vector (axis times angle, world coordinates) of the rotation taking the
/// orthonormal frame `a` to `b`: with `Q = sum b_j a_j^T`, `sum a_j x b_j = 2 sin(angle) axis`
/// and `trace Q = 1 + 2 cos(angle)`.
fn rotation_vector(a: &[Point3; 3], b: &[Point3; 3]) -> Point3 {
    let mut s = Point3::ZERO;
    let mut trace = 0.0;
    for j in 0..3 {
        s += cross(a[j], b[j]);
        trace += a[j].dot(b[j]);
    }
    let sin = 0.5 * s.norm();
    let angle = sin.atan2(0.5 * (trace - 1.0));
    if sin > 1e-12 {
        s * (0.5 * angle / sin)
    } else {
        s * 0.5
    }
}

/// The shape-preserving slopes of the scalar sequence `values` over steps `h`.
fn slopes_of(h: &[f64], values: &[f64]) -> Vec<f64> {
    let delta: Vec<f64> = (0..h.len())
        .map(|k| (values[k + 1] - values[k]) / h[k])
        .collect();
    let mut out = vec![0.0; values.len()];
    pchip_from_secants(h, &delta, &mut out);
    out
}

/// The frames' world angular velocities at the stations, and the frames split; `None` when a
/// frame has no plane (an axis of zero length or the two axes parallel).
fn turning(h: &[f64], frames: &[SectionFrame]) -> Option<(Vec<SplitFrame>, Vec<Point3>)> {
    let split: Vec<SplitFrame> = frames.iter().map(SplitFrame::new).collect::<Option<_>>()?;
    let n = frames.len();
    let secants: Vec<Point3> = (0..n - 1)
        .map(|k| rotation_vector(&split[k].e, &split[k + 1].e) * (1.0 / h[k]))
        .collect();
    let mut omega = vec![Point3::ZERO; n];
    let mut out = vec![0.0; n];
    for c in 0..3 {
        let delta: Vec<f64> = secants.iter().map(|w| w[c]).collect();
        pchip_from_secants(h, &delta, &mut out);
        for k in 0..n {
            omega[k][c] = out[k];
        }
    }
    Some((split, omega))
}

/// The frames and profiles restated so that every profile's leading edge (the combination
/// `weights` of its control points from `first`) is at `(0, 0)` and its trailing edge's
/// middle (the mean of its end control points) at `(1, 0)`: the same placed points, the
/// frames now carrying the chord line the surface shows. `None` when a chord line has no
/// length.
pub(super) fn on_chord_lines(
    frames: &[SectionFrame],
    profiles: &Grid<Point2>,
    (first, weights): (usize, [f64; 4]),
) -> Option<(Vec<SectionFrame>, Grid<Point2>)> {
    let (n, m) = (profiles.rows(), profiles.cols());
    let mut restated = Vec::with_capacity(n);
    let mut inverse = Vec::with_capacity(n);
    for k in 0..n {
        let row = profiles.row(k);
        let le = (0..4).fold(Point2::ZERO, |p, a| {
            p.add_scaled(weights[a], row[first + a])
        });
        let d = (row[0] + row[m - 1]) * 0.5 - le;
        let len_sq = d.dot(d);
        if !(len_sq > 0.0 && len_sq.is_finite()) {
            return None;
        }
        let f = &frames[k];
        restated.push(SectionFrame {
            origin: f.place(le),
            x_axis: f.x_axis * d[0] + f.y_axis * d[1],
            y_axis: f.x_axis * (-d[1]) + f.y_axis * d[0],
        });
        inverse.push((le, d, len_sq));
    }
    let profiles = Grid::from_fn(n, m, |k, i| {
        let (le, d, len_sq) = inverse[k];
        let q = *profiles.get(k, i) - le;
        Point2::new([
            (q[0] * d[0] + q[1] * d[1]) / len_sq,
            (q[1] * d[0] - q[0] * d[1]) / len_sq,
        ])
    });
    Some((restated, profiles))
}

/// The share (at most 1) of the angular velocity `omega` of section `k` that keeps the
/// Bézier points next to it of its x axis' Hermite curve (`X +- h/3 X'`, `X'` its length's
/// slope `length_slope` along it plus `omega x X` across) within the angle between the
/// section's x axis and its neighbour's and within the larger of their lengths. The curve
/// lies in the convex hull of its Bézier points, so for axes that turn in one plane the chord
/// line's angle stays between the neighbours' and its length below the larger one.
fn turn_limit(
    k: usize,
    h: &[f64],
    frames: &[SectionFrame],
    length_slope: f64,
    omega: Point3,
) -> f64 {
    let x = frames[k].x_axis;
    let across = cross(omega, x).norm();
    if across == 0.0 {
        return 1.0;
    }
    let mut limit = 1.0f64;
    let neighbours = [
        (k > 0).then(|| (k - 1, -1.0)),
        (k + 1 < frames.len()).then_some((k + 1, 1.0)),
    ];
    for (j, side) in neighbours.into_iter().flatten() {
        let step = h[k.min(j)] / 3.0;
        let other = frames[j].x_axis;
        let along = x.norm() + side * step * length_slope;
        let angle = cross(x, other).norm().atan2(x.dot(other));
        let longest = x.norm().max(other.norm());
        let by_angle = angle.tan().max(0.0) * along.max(0.0) / (step * across);
        let by_length = (longest * longest - along * along).max(0.0).sqrt() / (step * across);
        limit = limit.min(by_angle).min(by_length);
    }
    limit.clamp(0.0, 1.0)
}

/// The spanwise slopes of the placed control points `frames[k].place(profiles[k][i])` at the
/// `stations` (see the module docs), with every profile's chord line first made the frame's
/// x axis when the sections have a leading edge (the `leading_edge` combination of control
/// points); `None` when a frame has no plane.
pub(crate) fn placed_slopes(
    stations: &[f64],
    frames: &[SectionFrame],
    profiles: &Grid<Point2>,
    leading_edge: Option<(usize, [f64; 4])>,
) -> Option<Grid<Point3>> {
    let restated = leading_edge.and_then(|le| on_chord_lines(frames, profiles, le));
    let (frames, profiles) = match &restated {
        Some((f, p)) => (f.as_slice(), p),
        None => (frames, profiles),
    };
    let (n, m) = (profiles.rows(), profiles.cols());
    let h: Vec<f64> = stations.windows(2).map(|w| w[1] - w[0]).collect();
    let (split, omega) = turning(&h, frames)?;
    let scalar = |f: &dyn Fn(usize) -> f64| slopes_of(&h, &(0..n).map(f).collect::<Vec<_>>());
    let x_len = scalar(&|k| split[k].x_len);
    let y1 = scalar(&|k| split[k].y1);
    let y2 = scalar(&|k| split[k].y2);
    let origin: Vec<Vec<f64>> = (0..3).map(|c| scalar(&|k| frames[k].origin[c])).collect();
    let mut slopes = Grid::from_fn(n, m, |_, _| Point3::ZERO);
    let mut frame_slopes = Vec::with_capacity(n);
    for k in 0..n {
        let (f, s) = (&frames[k], &split[k]);
        let w = omega[k] * turn_limit(k, &h, frames, x_len[k], omega[k]);
        let dx = cross(w, f.x_axis) + s.e[0] * x_len[k];
        let dy = cross(w, f.y_axis) + s.e[0] * y1[k] + s.e[1] * y2[k];
        let d_origin = Point3::new([origin[0][k], origin[1][k], origin[2][k]]);
        frame_slopes.push((d_origin, dx, dy));
    }
    for i in 0..m {
        let px = scalar(&|k| profiles.get(k, i)[0]);
        let py = scalar(&|k| profiles.get(k, i)[1]);
        for k in 0..n {
            let (f, (d_origin, dx, dy)) = (&frames[k], frame_slopes[k]);
            let p = *profiles.get(k, i);
            *slopes.get_mut(k, i) =
                d_origin + dx * p[0] + dy * p[1] + f.x_axis * px[k] + f.y_axis * py[k];
        }
    }
    slopes
        .as_slice()
        .iter()
        .all(|p| p.is_finite())
        .then_some(slopes)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_rotation_vector_of_a_turn_about_y() {
        let frame = |a: f64| {
            let (s, c) = a.sin_cos();
            [
                Point3::new([c, 0.0, -s]),
                Point3::new([0.0, 1.0, 0.0]),
                Point3::new([s, 0.0, c]),
            ]
        };
        let w = rotation_vector(&frame(0.1), &frame(0.4));
        assert!((w - Point3::new([0.0, 0.3, 0.0])).norm() < 1e-14, "{w:?}");
    }
}

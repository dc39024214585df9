//! The range of coordinates karkas works with, checked as every geometric input is read.
//!
//! Every method is linear in the coordinates (LL, discrete periodic, Coons and bicubic
//! surfaces) or equivariant under scaling (chord parameters, fits, sections, distances): its
//! result for data scaled by `s` is `s` times its result for the data, to round-off. That holds
//! while squared distances and the products of a few coordinates stay normal floating-point
//! numbers, which is why a model's largest coordinate must lie between [`SMALLEST_MODEL`] and
//! [`LARGEST_COORDINATE`] in magnitude: beyond them sums of squares overflow to infinity or
//! fall into the subnormal range, and results would silently lose digits or vanish. Data out
//! of range are refused with a message saying so, not answered wrongly.

use std::path::Path;

use crate::error::{data_error, IoError};
use karkas::Point;

/// The largest coordinate magnitude accepted: squares of differences of such coordinates,
/// summed over three axes and a few terms, stay below `f64::MAX` (about 1.8e308).
pub const LARGEST_COORDINATE: f64 = 1e152;

/// The smallest largest-coordinate magnitude of a model: squares of its distances stay above
/// the smallest normal number (about 2.2e-308), so they keep their 16 digits.
pub const SMALLEST_MODEL: f64 = 1e-152;

/// Refuses `coordinates` (every coordinate of one input, in any order) read from `path` when
/// their largest magnitude lies outside [`SMALLEST_MODEL`]..=[`LARGEST_COORDINATE`]. All zeros
/// pass: what is wrong with them (a single point) is said by the method.
pub fn check_coordinate_range(
    coordinates: impl IntoIterator<Item = f64>,
    path: &Path,
) -> Result<(), IoError> {
    let largest = coordinates.into_iter().fold(0.0_f64, |m, c| m.max(c.abs()));
    check_largest_coordinate(largest, path)
}

/// [`check_coordinate_range`] of coordinates held in one slice: the largest magnitude found in
/// eight independent lanes (one running maximum is a chain of dependent comparisons, a few
/// times slower on a large grid).
pub fn check_coordinate_slice(coordinates: &[f64], path: &Path) -> Result<(), IoError> {
    let mut lanes = [0.0_f64; 8];
    let mut chunks = coordinates.chunks_exact(8);
    for chunk in &mut chunks {
        for (m, &c) in lanes.iter_mut().zip(chunk) {
            *m = m.max(c.abs());
        }
    }
    let rest = chunks
        .remainder()
        .iter()
        .fold(0.0_f64, |m, c| m.max(c.abs()));
    check_largest_coordinate(lanes.iter().fold(rest, |m, &l| m.max(l)), path)
}

/// Refuses a largest coordinate magnitude outside the range.
fn check_largest_coordinate(largest: f64, path: &Path) -> Result<(), IoError> {
    let problem = if largest > LARGEST_COORDINATE {
        format!("above {LARGEST_COORDINATE:e}, the most")
    } else if largest > 0.0 && largest < SMALLEST_MODEL {
        format!("below {SMALLEST_MODEL:e}, the least")
    } else {
        return Ok(());
    };
    Err(data_error(
        path,
        format!(
            "coordinates out of range: the largest magnitude is {largest:e}, {problem} karkas \
             works with (squared distances would leave the floating-point range); rescale the \
             data, e.g. to other units"
        ),
    ))
}

/// A lone point this many times farther from the others than their own extent is taken for
/// a stray value: every tolerance of a method is relative to the model's size, which the one
/// point then sets, so the others would look like one point or one line.
const STRAY_RATIO: f64 = 1e9;

/// The index of a lone point of `points` lying more than `STRAY_RATIO` (1e9) times farther from
/// the others (from the per-axis median) than they spread themselves, and that ratio; `None`
/// when there is no such point, or when the others all coincide. `O(n)`.
pub fn stray_point<const D: usize>(points: &[Point<D>]) -> Option<(usize, f64)> {
    if points.len() < 3 {
        return None;
    }
    let mut centre = [0.0; D];
    let mut axis = Vec::with_capacity(points.len());
    for (k, c) in centre.iter_mut().enumerate() {
        axis.clear();
        axis.extend(points.iter().map(|p| p.0[k]));
        let middle = axis.len() / 2;
        *c = *axis.select_nth_unstable_by(middle, f64::total_cmp).1;
    }
    let centre = Point(centre);
    let (mut far, mut far_at, mut second) = (0.0_f64, 0, 0.0_f64);
    for (i, p) in points.iter().enumerate() {
        let d = (*p - centre).max_abs();
        if d > far {
            (second, far, far_at) = (far, d, i);
        } else if d > second {
            second = d;
        }
    }
    let ratio = far / second;
    (second > 0.0 && ratio > STRAY_RATIO).then_some((far_at, ratio))
}

/// Refuses `points` of `path` holding a stray point ([`stray_point`]), naming it.
pub fn check_stray_point<const D: usize>(points: &[Point<D>], path: &Path) -> Result<(), IoError> {
    match stray_point(points) {
        Some((at, ratio)) => Err(data_error(
            path,
            format!(
                "the point at ({}) lies {ratio:.1e} times farther from the others than they \
                 spread (a stray value, or mixed units?): every tolerance follows the model's \
                 size, which this one point would set",
                points[at].0.map(|c| format!("{c}")).join(","),
            ),
        )),
        None => Ok(()),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn message(values: &[f64]) -> Option<String> {
        check_coordinate_range(values.iter().copied(), Path::new("p.csv"))
            .err()
            .map(|e| e.to_string())
    }

    #[test]
    fn the_limits_themselves_pass_and_beyond_them_is_refused() {
        assert_eq!(message(&[0.0, -1e152, 3.0]), None);
        assert_eq!(message(&[1e-152, 0.0, -1e-200]), None);
        assert_eq!(message(&[0.0, 0.0]), None);
        assert_eq!(message(&[]), None);
        let huge = message(&[1.0, -2e152]).expect("refused");
        assert!(
            huge.starts_with(
                "p.csv: coordinates out of range: the largest magnitude is 2e152, above 1e152"
            ),
            "{huge}"
        );
        let tiny = message(&[9e-153, 0.0]).expect("refused");
        assert!(
            tiny.contains("is 9e-153, below 1e-152, the least karkas works with"),
            "{tiny}"
        );
    }

    #[test]
    fn the_slice_check_in_lanes_agrees_with_the_running_check() {
        // Every length up to two chunks and a remainder, the extreme value at every place,
        // with a NaN beside it (ignored by both, as `f64::max` does).
        for n in 0..20 {
            for at in 0..n {
                for extreme in [3e152, -2e152, 5e-153, 1.0] {
                    let mut values: Vec<f64> = (0..n).map(|k| 1e-160 * k as f64).collect();
                    values[at] = extreme;
                    if at + 1 < n {
                        values[at + 1] = f64::NAN;
                    }
                    let lanes = check_coordinate_slice(&values, Path::new("p.csv"))
                        .err()
                        .map(|e| e.to_string());
                    assert_eq!(lanes, message(&values), "{values:?}");
                }
            }
        }
    }

    #[test]
    fn a_lone_far_point_is_found_and_spread_data_are_not() {
        let mut line: Vec<Point<3>> = (0..10)
            .map(|k| Point([k as f64, 0.5 * k as f64, 0.0]))
            .collect();
        assert_eq!(stray_point(&line), None);
        line[4] = Point([4.0, 2.0, 1e15]);
        let (at, ratio) = stray_point(&line).expect("found");
        assert_eq!(at, 4);
        assert_eq!(ratio, 1e15 / 5.0); // from the median (5, 2.5, 0); the others within 5
        let e = check_stray_point(&line, Path::new("g.csv"))
            .unwrap_err()
            .to_string();
        assert!(
            e.starts_with("g.csv: the point at (4,2,1000000000000000) lies 2.0e14 times farther"),
            "{e}"
        );
        // A model at 1e150 with a point 1e6 times out is data, not a stray value.
        let mut wide: Vec<Point<2>> = (0..10).map(|k| Point([1e150 * k as f64, 0.0])).collect();
        wide[9] = Point([1e156, 1.0]);
        assert_eq!(stray_point(&wide), None);
        // Two far points are not a lone stray one.
        let mut two = line.clone();
        two[7] = Point([7.0, 3.5, 1e15]);
        assert_eq!(stray_point(&two), None);
    }

    #[test]
    fn squares_of_distances_at_the_limits_stay_normal_and_finite() {
        // The reason for the limits: three squared differences of opposite extreme coordinates.
        let far = 3.0 * (2.0 * LARGEST_COORDINATE).powi(2);
        assert!(far.is_finite());
        let near = SMALLEST_MODEL * SMALLEST_MODEL;
        assert!(near.is_normal() && near > 100.0 * f64::MIN_POSITIVE);
    }
}

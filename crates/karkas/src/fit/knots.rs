//! Knot grids and starting parameters of the fit.
//!
//! The paper's grid is `0 = T_1 < ... < T_N = 1`; the data points get parameters
//! `0 = t_1 <= ... <= t_n = 1`, by default in proportion to the cumulative chord length
//! (the paper's starting point), optionally uniform or centripetal (square roots of the
//! chords), which the multi-start check uses.

use super::noise::estimate_noise;
use crate::core::knots;
use crate::{Error, Point, Result};

/// The smallest allowed distance between two knots of a fit (in the parameter, whose range
/// is `[0, 1]`). The paper's own grid has knots `0.004` apart.
pub(crate) const MIN_KNOT_SPACING: f64 = 1e-6;

/// Checks a knot grid for a fit: the rules of every knot sequence
/// ([`crate::core::knots::check_knots`]: finite, strictly increasing, at least two), and the
/// fit's own: `T_1 = 0`, `T_N = 1`, every knot in `[0, 1]` and at least `1e-6` from the one
/// before it.
///
/// Errors: [`Error::TooFewPoints`] for fewer than two knots, [`Error::InvalidKnot`] naming
/// the first offending knot otherwise (at one knot, a range rule before the order, the order
/// before the spacing).
pub fn check_knots(knots: &[f64]) -> Result<()> {
    let offence = |result: Result<()>| match result {
        Err(Error::InvalidKnot { index, reason, .. }) => Ok(Some((index, reason))),
        Err(other) => Err(other),
        Ok(()) => Ok(None),
    };
    let order = offence(knots::check_knots(knots, 2, "a fit (knots)"))?;
    let gap = offence(knots::check_min_gap(
        knots,
        MIN_KNOT_SPACING,
        "closer than 1e-6 to the knot before it",
    ))?;
    let last = knots.len() - 1;
    let range = knots.iter().enumerate().find_map(|(index, &value)| {
        let reason = if !value.is_finite() {
            return None;
        } else if !(0.0..=1.0).contains(&value) {
            "outside [0, 1]"
        } else if index == 0 && value != 0.0 {
            "the first knot must be 0"
        } else if index == last && value != 1.0 {
            "the last knot must be 1"
        } else {
            return None;
        };
        Some((index, reason))
    });
    // The first offending knot; at one knot the rules in the order above.
    let first = [range, order, gap]
        .into_iter()
        .enumerate()
        .filter_map(|(rank, found)| found.map(|(index, reason)| (index, rank, reason)))
        .min_by_key(|&(index, rank, _)| (index, rank));
    match first {
        None => Ok(()),
        Some((index, _, reason)) => Err(Error::InvalidKnot {
            index,
            value: knots[index],
            reason,
        }),
    }
}

/// `n >= 2` uniformly spaced knots from 0 to 1 (the last exactly 1).
pub fn uniform_knots(n: usize) -> Vec<f64> {
    let n = n.max(2);
    (0..n)
        .map(|k| {
            if k + 1 == n {
                1.0
            } else {
                k as f64 / (n - 1) as f64
            }
        })
        .collect()
}

/// The knots of a fit from what the user gave: one whole number `n` means `n` uniform knots
/// ([`uniform_knots`]; `n` at least 2), several numbers are the knots themselves (checked by
/// [`check_knots`]). The rule of the command line's `--knots` and of Python's `knots=`.
///
/// Errors: a single number that is not a whole number of at least 2
/// ([`Error::InvalidSetting`]); knots that [`check_knots`] refuses.
///
/// ```
/// use karkas::fit::knots_from_list;
/// assert_eq!(knots_from_list(&[3.0]).unwrap(), vec![0.0, 0.5, 1.0]);
/// assert_eq!(knots_from_list(&[0.0, 0.25, 1.0]).unwrap(), vec![0.0, 0.25, 1.0]);
/// assert!(knots_from_list(&[1.0]).is_err());
/// ```
pub fn knots_from_list(values: &[f64]) -> Result<Vec<f64>> {
    if let [n] = values {
        if !(n.fract() == 0.0 && *n >= 2.0 && *n <= 1e9) {
            return Err(Error::InvalidSetting {
                name: "knots",
                value: *n,
                reason: "one number is a count of uniform knots: a whole number of at least 2",
            });
        }
        return Ok(uniform_knots(*n as usize));
    }
    check_knots(values)?;
    Ok(values.to_vec())
}

/// How the data points get their starting parameters.
#[derive(Clone, Debug, PartialEq, Default)]
pub enum StartParameters {
    /// In proportion to cumulative chord length (the paper's choice).
    #[default]
    ChordLength,
    /// Centripetal: in proportion to cumulative square roots of the chords.
    Centripetal,
    /// Uniform: `t_i = (i - 1) / (n - 1)`.
    Uniform,
    /// In proportion to cumulative chords raised to this power (finite, at least 0): 1 is
    /// chord length, 0.5 centripetal, 0 uniform; the starts of [`super::FitOptions::starts`].
    ChordPower(f64),
    /// Given by the caller: `n` values, nondecreasing, from 0 to 1.
    Given(Vec<f64>),
}

/// Chords measured over a stride of points at least this many times the noise.
const CHORD_OVER_NOISE: f64 = 10.0;

/// The stride of points over which chords are measured for starting parameters: 1 for
/// points whose spacing exceeds their noise; on dense noisy points, where the chord between
/// neighbours is mostly noise (and chord length grows with the noise, not the curve), the
/// smallest power of two whose mean chord is at least [`CHORD_OVER_NOISE`] times the noise
/// estimated from the points (`sigma`, see [`estimate_noise`]), at most `n / 16`.
fn noise_stride<const D: usize>(points: &[Point<D>], sigma: f64) -> usize {
    let n = points.len();
    let mut stride = 1;
    while sigma > 0.0 && 2 * stride <= n / 16 {
        let step = ((n - stride) / 4096).max(1);
        let (sum, count) = (0..n - stride)
            .step_by(step)
            .fold((0.0, 0usize), |(s, c), i| {
                (s + points[i].distance(points[i + stride]), c + 1)
            });
        if sum / count.max(1) as f64 >= CHORD_OVER_NOISE * sigma {
            break;
        }
        stride *= 2;
    }
    stride
}

/// The starting parameters of `points` by `rule` (`t_1 = 0`, `t_n = 1`): on dense noisy
/// points the chord rules measure chords over a stride of points whose mean chord is at
/// least ten times the noise.
///
/// Errors: points that all coincide (for the chord rules); given parameters of the wrong
/// count, not nondecreasing, or not from 0 to 1 ([`Error::InvalidSetting`]).
pub fn start_parameters<const D: usize>(
    points: &[Point<D>],
    rule: &StartParameters,
) -> Result<Vec<f64>> {
    start_parameters_for(points, rule, estimate_noise(points).sigma)
}

/// [`start_parameters`] with the noise of the points already estimated (`sigma`).
pub(crate) fn start_parameters_for<const D: usize>(
    points: &[Point<D>],
    rule: &StartParameters,
    sigma: f64,
) -> Result<Vec<f64>> {
    let n = points.len();
    let chords = |power: f64| chord_power_parameters(points, power, sigma);
    match rule {
        StartParameters::ChordLength => chords(1.0),
        StartParameters::Centripetal => chords(0.5),
        StartParameters::Uniform => Ok(uniform_knots(n)),
        StartParameters::ChordPower(power) => {
            if !(power.is_finite() && *power >= 0.0) {
                return Err(Error::InvalidSetting {
                    name: "start chord power",
                    value: *power,
                    reason: "must be finite and at least 0",
                });
            }
            chords(*power)
        }
        StartParameters::Given(ts) => {
            if ts.len() != n {
                return Err(Error::InvalidSetting {
                    name: "number of start parameters",
                    value: ts.len() as f64,
                    reason: "must equal the number of points",
                });
            }
            for (i, &t) in ts.iter().enumerate() {
                let bad = !t.is_finite()
                    || !(0.0..=1.0).contains(&t)
                    || (i > 0 && t < ts[i - 1])
                    || (i == 0 && t != 0.0)
                    || (i + 1 == n && t != 1.0);
                if bad {
                    return Err(Error::InvalidSetting {
                        name: "start parameter",
                        value: t,
                        reason: "parameters must rise from 0 to 1",
                    });
                }
            }
            Ok(ts.clone())
        }
    }
}

/// Parameters in proportion to the cumulative chords raised to `power` (1 chord length, 0.5
/// centripetal, 0 uniform), the chords measured over strides of points at least
/// [`CHORD_OVER_NOISE`] times the noise `sigma` apart.
fn chord_power_parameters<const D: usize>(
    points: &[Point<D>],
    power: f64,
    sigma: f64,
) -> Result<Vec<f64>> {
    let n = points.len();
    let stride = noise_stride(points, sigma);
    // Cumulative chords through every `stride`-th point (and the last), in proportion to
    // the index between them.
    let mut acc = vec![0.0; n];
    let mut total = 0.0;
    let mut from = 0;
    while from + 1 < n {
        let to = (from + stride).min(n - 1);
        let chord = points[from].distance(points[to]).powf(power);
        for (j, a) in acc[from + 1..=to].iter_mut().enumerate() {
            *a = total + chord * (j + 1) as f64 / (to - from) as f64;
        }
        total += chord;
        from = to;
    }
    if !(total.is_finite() && total > 0.0) {
        return Err(Error::TooFewPoints {
            what: "a fit (distinct points)",
            needed: 2,
            got: 1,
        });
    }
    for a in &mut acc {
        *a /= total;
    }
    acc[n - 1] = 1.0;
    Ok(acc)
}

/// A previous fit's foot parameters as the next fit's start (the tolerance mode's rounds): clamped to `[0, 1]`,
/// non-decreasing, from 0 to 1.
pub(crate) fn warm_parameters(parameters: &[f64]) -> Vec<f64> {
    let mut start = Vec::with_capacity(parameters.len());
    let mut last = 0.0f64;
    for &t in parameters {
        last = last.max(t.clamp(0.0, 1.0));
        start.push(last);
    }
    if let Some(first) = start.first_mut() {
        *first = 0.0;
    }
    if let Some(end) = start.last_mut() {
        *end = 1.0;
    }
    start
}

/// `count` uniform knots with the corners put in (a uniform knot closer than
/// [`MIN_KNOT_SPACING`] to a corner gives way to it).
pub(crate) fn uniform_with_corners(count: usize, corners: &[f64]) -> Vec<f64> {
    let mut knots = uniform_knots(count);
    for &corner in corners {
        knots.retain(|&k| (k - corner).abs() >= MIN_KNOT_SPACING || k == 0.0 || k == 1.0);
        knots.push(corner);
    }
    knots.sort_by(f64::total_cmp);
    knots.dedup();
    knots
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn knot_rules() {
        assert!(check_knots(&[0.0, 0.445, 0.449, 0.587, 1.0]).is_ok());
        let bad = |k: &[f64]| match check_knots(k) {
            Err(Error::InvalidKnot { index, .. }) => index,
            other => panic!("{other:?}"),
        };
        assert_eq!(bad(&[0.0, 0.6, 0.5, 1.0]), 2);
        assert_eq!(bad(&[0.0, 0.5, 0.5 + 1e-9, 1.0]), 2);
        assert_eq!(bad(&[0.0, 1.5, 1.0]), 1);
        assert_eq!(bad(&[0.1, 0.5, 1.0]), 0);
        assert_eq!(bad(&[0.0, 0.5, 0.9]), 2);
        assert_eq!(bad(&[0.0, f64::NAN, 1.0]), 1);
        assert!(check_knots(&[0.0]).is_err());
    }

    #[test]
    fn chord_length_parameters() {
        let pts = [Point([0.0, 0.0]), Point([3.0, 4.0]), Point([3.0, 9.0])];
        let t = start_parameters(&pts, &StartParameters::ChordLength).unwrap();
        assert_eq!(t, vec![0.0, 0.5, 1.0]);
        let t = start_parameters(&pts, &StartParameters::Uniform).unwrap();
        assert_eq!(t, vec![0.0, 0.5, 1.0]);
        assert!(start_parameters(&[Point([1.0, 1.0]); 3], &StartParameters::ChordLength).is_err());
        assert!(start_parameters(&pts, &StartParameters::Given(vec![0.0, 0.7, 0.6])).is_err());
    }
}

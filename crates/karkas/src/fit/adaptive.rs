//! Knots placed automatically until a tolerance on the largest deviation holds.
//!
//! Start from a few knots uniform in the parameter (the starting parameters are chord
//! lengths, so these are uniform in chord length), plus the corners; fit; while the largest
//! point distance exceeds the tolerance, halve the piece holding the foot point of the worst
//! point (the piece with the largest deviation) and fit again. Pieces that cannot be halved
//! (shorter than twice [`MIN_KNOT_SPACING`], or whose halving leaves the spline undetermined)
//! are skipped; the knots never outnumber the points. Each round is one
//! [`fit_curve`](super::fit_curve), so the cost is the number of knots added times a fit.

use super::guards::with_warnings;
use super::knots::{start_parameters, uniform_knots, MIN_KNOT_SPACING};
use super::penalty::{check_inputs, check_settings, fit_checked, CurveFit, FitOptions};
use crate::{Error, Point, Result};

/// The result of [`fit_curve_adaptive`].
#[derive(Clone, Debug)]
pub struct AdaptiveFit<const D: usize> {
    /// The last fit (on the knots it chose: `fit.spline.knots()`).
    pub fit: CurveFit<D>,
    /// True when every point lies within the tolerance of the curve.
    pub tolerance_met: bool,
}

/// Fits with knots chosen automatically until every point lies within `tolerance` of the
/// curve (or no piece can be split further). `options` as for
/// [`fit_curve`](super::fit_curve); the corners become knots.
///
/// Errors: a tolerance that is not positive and finite ([`Error::InvalidSetting`]), and those
/// of [`fit_curve`](super::fit_curve) for the first fit.
pub fn fit_curve_adaptive<const D: usize>(
    points: &[Point<D>],
    tolerance: f64,
    options: &FitOptions,
) -> Result<AdaptiveFit<D>> {
    if !(tolerance > 0.0 && tolerance.is_finite()) {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "must be positive and finite",
        });
    }
    check_settings(options)?;
    let start = start_parameters(points, &options.start)?;
    let pieces = (points.len() / 4).clamp(1, 4);
    let mut knots = uniform_knots(pieces + 1);
    for &corner in &options.corners {
        knots.retain(|&k| (k - corner).abs() >= MIN_KNOT_SPACING || k == 0.0 || k == 1.0);
        knots.push(corner);
    }
    knots.sort_by(f64::total_cmp);
    knots.dedup();
    let weights = check_inputs(points, &knots, options)?;
    let mut fit = fit_checked(points, &knots, &weights, start.clone(), options)?;
    let mut frozen: Vec<(f64, f64)> = Vec::new();
    loop {
        if fit.max_distance() <= tolerance {
            return Ok(AdaptiveFit {
                fit: with_warnings(points, fit),
                tolerance_met: true,
            });
        }
        let knots = fit.spline.knots().to_vec();
        if knots.len() >= points.len() {
            break;
        }
        // Worst deviation per piece.
        let mut worst = vec![0.0f64; knots.len() - 1];
        for (&t, &d) in fit.parameters.iter().zip(&fit.distances) {
            let piece = fit.spline.locate(t).0;
            worst[piece] = worst[piece].max(d);
        }
        let mut order: Vec<usize> = (0..worst.len()).collect();
        order.sort_by(|&a, &b| worst[b].total_cmp(&worst[a]));
        let mut refined = None;
        for piece in order {
            if worst[piece] <= tolerance {
                break;
            }
            let (a, b) = (knots[piece], knots[piece + 1]);
            if b - a < 2.0 * MIN_KNOT_SPACING || frozen.contains(&(a, b)) {
                continue;
            }
            let mut finer = knots.clone();
            finer.insert(piece + 1, 0.5 * (a + b));
            let weights = check_inputs(points, &finer, options)?;
            match fit_checked(points, &finer, &weights, start.clone(), options) {
                Ok(next) => {
                    refined = Some(next);
                    break;
                }
                Err(Error::SingularSystem { .. }) => frozen.push((a, b)),
                Err(e) => return Err(e),
            }
        }
        match refined {
            Some(next) => fit = next,
            None => break,
        }
    }
    Ok(AdaptiveFit {
        fit: with_warnings(points, fit),
        tolerance_met: false,
    })
}

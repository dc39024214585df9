//! One call of the tolerance mode of Pavlov's fit (docs/methods.md §4): the points checked
//! once, in the units of the fit, with their noise estimate; every trial refit of the
//! rounds, the repairs and the pruning runs on it without checking the points again.

use super::noise::NoiseEstimate;
use super::penalty::Settings;
use super::penalty::{fit_checked, knot_weights};
use super::result::CurveFit;
use crate::{Point, Result};

/// The checked points of one fit call and their noise estimate.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Session<'a, const D: usize> {
    /// The points, checked ([`super::penalty::check_inputs`]) and brought to unit size.
    pub points: &'a [Point<D>],
    /// The noise estimate of the points, shared by every refit.
    pub noise: NoiseEstimate,
}

impl<const D: usize> Session<'_, D> {
    /// The fit of the session's points on `knots` (checked, they change from refit to
    /// refit) from the parameters `start`.
    pub(crate) fn refit(
        &self,
        knots: &[f64],
        start: Vec<f64>,
        options: &Settings<'_>,
    ) -> Result<CurveFit<D>> {
        let weights = knot_weights(knots, options.corners)?;
        fit_checked(self.points, knots, &weights, start, options, &self.noise)
    }
}

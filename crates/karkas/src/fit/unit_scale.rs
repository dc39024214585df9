//! The fit works on points brought to unit size by a power of two, so that it gives the same
//! curve, times the scale, for data of any size in karkas's range (about 1e-150 to 1e150).
//!
//! The objective of Pavlov's fit (docs/methods.md §4) and its Newton model hold squared
//! distances, squared second-derivative jumps and their products: for coordinates near 1e-150
//! they fall into the subnormal range and lose digits (the tolerance mode's steps were decided
//! on differences of such numbers), and near 1e152 they overflow. Multiplying by a power of two
//! is exact, and every step of the fit is equivariant under it, so the result for `s` times
//! the points is `s` times the result for the points, to the last bit when `s` is a power of
//! two.

use super::noise::NoiseEstimate;
use super::result::CurveFit;
use crate::core::Point;
use std::borrow::Cow;

/// Coordinates whose largest magnitude lies between `2^-UNSCALED_EXPONENT` and
/// `2^UNSCALED_EXPONENT` are fitted as they are; others are brought to `[0.5, 1)`.
const UNSCALED_EXPONENT: i32 = 32;

/// The power of two a fit divides its points by (1 for data of ordinary size).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct UnitScale {
    scale: f64,
}

impl UnitScale {
    /// The scale of `points`: 1 when their largest coordinate magnitude is within
    /// `2^-32..=2^32` (or zero, or not finite: the checks that follow say what is wrong),
    /// else the power of two that brings it into `[0.5, 1)`.
    pub(crate) fn of<const D: usize>(points: &[Point<D>]) -> Self {
        let largest = points
            .iter()
            .flat_map(|p| p.0)
            .fold(0.0_f64, |m, c| m.max(c.abs()));
        let bound = 2f64.powi(UNSCALED_EXPONENT);
        if !(largest.is_finite() && largest > 0.0) || (1.0 / bound..=bound).contains(&largest) {
            return UnitScale { scale: 1.0 };
        }
        // largest = m 2^e with m in [0.5, 1): the scale is 2^e.
        let mut exponent = largest.log2().floor() as i32 + 1;
        while 2f64.powi(exponent - 1) > largest {
            exponent -= 1;
        }
        while 2f64.powi(exponent) <= largest {
            exponent += 1;
        }
        UnitScale {
            scale: 2f64.powi(exponent),
        }
    }

    /// The factor the fit's points were divided by.
    pub(crate) fn scale(self) -> f64 {
        self.scale
    }

    /// `points` divided by the scale (borrowed when it is 1).
    pub(crate) fn points<'a, const D: usize>(self, points: &'a [Point<D>]) -> Cow<'a, [Point<D>]> {
        if self.scale == 1.0 {
            return Cow::Borrowed(points);
        }
        let inverse = 1.0 / self.scale;
        Cow::Owned(points.iter().map(|&p| p * inverse).collect())
    }

    /// A length in model units (a tolerance) in the fit's units.
    pub(crate) fn length(self, length: f64) -> f64 {
        length / self.scale
    }

    /// A squared length in model units (the bound `eps` on the squared jumps) in the fit's
    /// units.
    pub(crate) fn squared_length(self, squared: f64) -> f64 {
        squared / self.scale / self.scale
    }

    /// `fit`, found in the fit's units, in model units. Its warnings are dropped: they name
    /// places in the fit's units and are found again on the restored fit.
    pub(crate) fn restore<const D: usize>(self, mut fit: CurveFit<D>) -> CurveFit<D> {
        fit.warnings.clear();
        if self.scale == 1.0 {
            return fit;
        }
        let s = self.scale;
        let (values, derivatives) = fit.spline.coefficients_mut();
        for p in values.iter_mut().chain(derivatives.iter_mut()) {
            *p *= s;
        }
        for d in &mut fit.distances {
            *d *= s;
        }
        fit.data_term *= s * s;
        fit.jump_sum *= s * s;
        fit.bending_energy *= s * s;
        fit.noise = NoiseEstimate {
            sigma: fit.noise.sigma * s,
            size: fit.noise.size * s,
            turning: fit.noise.turning,
        };
        fit
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ordinary_sizes_are_left_alone_and_others_brought_to_unit_size() {
        let at = |c: f64| UnitScale::of(&[Point([c, -0.5 * c])]).scale();
        for c in [1.0, 1e-9, 1e9, 2f64.powi(32), 2f64.powi(-32)] {
            assert_eq!(at(c), 1.0, "{c}");
        }
        for c in [
            1e150,
            3e-151,
            2f64.powi(500),
            2f64.powi(-500),
            0.75 * 2f64.powi(60),
        ] {
            let m = c / at(c);
            assert!((0.5..1.0).contains(&m), "{c}: {m}");
            assert_eq!(at(c).log2().fract(), 0.0, "{c}: a power of two");
        }
        assert_eq!(at(0.0), 1.0);
        assert_eq!(UnitScale::of::<2>(&[]).scale(), 1.0);
    }
}

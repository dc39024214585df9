//! The fit works on points moved to the origin and brought to unit size by a power of two, so
//! that it gives the same curve, moved and times the scale, for data of any size in karkas's
//! range (about 1e-150 to 1e150) and anywhere.
//!
//! The objective of Pavlov's fit (docs/methods.md §4) and its Newton model hold squared
//! distances, squared second-derivative jumps and their products: for coordinates near 1e-150
//! they fall into the subnormal range and lose digits (the tolerance mode's steps were decided
//! on differences of such numbers), and near 1e152 they overflow. Multiplying by a power of two
//! is exact, and every step of the fit is equivariant under it, so the result for `s` times
//! the points is `s` times the result for the points, to the last bit when `s` is a power of
//! two.
//!
//! The move: the points are taken relative to the low corner of their bounding box, less its
//! half-sides. The corner is made of input coordinates, so `p - corner` and the half-sides are
//! exact for points far from the origin (Sterbenz's lemma) and equal for points moved by a
//! representable offset: the fit then sees the same numbers wherever the points lie, and its
//! curve moves with them to the rounding of the final `corner + ...` (a few units in the last
//! place of the offset), where centring on a computed mean would round every point anew.

use super::noise::NoiseEstimate;
use super::result::CurveFit;
use crate::core::Point;

/// Coordinates whose largest magnitude lies between `2^-UNSCALED_EXPONENT` and
/// `2^UNSCALED_EXPONENT` are fitted as they are; others are brought to `[0.5, 1)`.
const UNSCALED_EXPONENT: i32 = 32;

/// The move to the origin and the power of two a fit divides its points by (1 for data of
/// ordinary size).
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct UnitScale<const D: usize> {
    /// The low corner of the points' bounding box.
    corner: Point<D>,
    /// The half-sides of the bounding box.
    half: Point<D>,
    scale: f64,
}

impl<const D: usize> UnitScale<D> {
    /// The frame of `points`: their bounding box's low corner and half-sides (zero for
    /// non-finite coordinates: the checks that follow say what is wrong), and the scale: 1
    /// when the largest magnitude of the moved coordinates is within `2^-32..=2^32` (or zero,
    /// or not finite), else the power of two that brings it into `[0.5, 1)`.
    pub(crate) fn of(points: &[Point<D>]) -> Self {
        let mut corner = Point([0.0; D]);
        let mut half = Point([0.0; D]);
        if let Some(&first) = points.first() {
            let (mut lo, mut hi) = (first, first);
            for p in points {
                for d in 0..D {
                    lo[d] = lo[d].min(p[d]);
                    hi[d] = hi[d].max(p[d]);
                }
            }
            let h = (hi - lo) * 0.5;
            if lo.is_finite() && h.is_finite() {
                (corner, half) = (lo, h);
            }
        }
        let largest = points
            .iter()
            .flat_map(|p| ((*p - corner) - half).0)
            .fold(0.0_f64, |m, c| m.max(c.abs()));
        let bound = 2f64.powi(UNSCALED_EXPONENT);
        if !(largest.is_finite() && largest > 0.0) || (1.0 / bound..=bound).contains(&largest) {
            return UnitScale {
                corner,
                half,
                scale: 1.0,
            };
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
            corner,
            half,
            scale: 2f64.powi(exponent),
        }
    }

    /// The factor the fit's points were divided by.
    pub(crate) fn scale(self) -> f64 {
        self.scale
    }

    /// `points` moved and divided by the scale.
    pub(crate) fn points(self, points: &[Point<D>]) -> Vec<Point<D>> {
        let inverse = 1.0 / self.scale;
        points
            .iter()
            .map(|&p| ((p - self.corner) - self.half) * inverse)
            .collect()
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
    /// places in the fit's units and are found again on the restored fit. With `pinned`
    /// (the first and last input points, [`FitOptions::pin_ends`](super::FitOptions)), the
    /// end values are those points exactly, not their round trip through the fit's units.
    pub(crate) fn restore(
        self,
        mut fit: CurveFit<D>,
        pinned: Option<[Point<D>; 2]>,
    ) -> CurveFit<D> {
        fit.warnings.clear();
        let s = self.scale;
        let (values, derivatives) = fit.spline.coefficients_mut();
        for p in values.iter_mut() {
            *p = self.corner + (self.half + *p * s);
        }
        if let (Some([first, last]), Some(start)) = (pinned, values.first_mut()) {
            *start = first;
            if let Some(end) = values.last_mut() {
                *end = last;
            }
        }
        if s == 1.0 {
            return fit;
        }
        for p in derivatives.iter_mut() {
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
        // Two points whose moved coordinates reach c / 2.
        let at = |c: f64| UnitScale::of(&[Point([c, -0.5 * c]), Point([0.0, 0.0])]).scale();
        for c in [1.0, 1e-9, 1e9, 2f64.powi(33), 2f64.powi(-31)] {
            assert_eq!(at(c), 1.0, "{c}");
        }
        for c in [
            1e150,
            3e-151,
            2f64.powi(500),
            2f64.powi(-500),
            0.75 * 2f64.powi(60),
        ] {
            let m = 0.5 * c / at(c);
            assert!((0.5..1.0).contains(&m), "{c}: {m}");
            assert_eq!(at(c).log2().fract(), 0.0, "{c}: a power of two");
        }
        assert_eq!(at(0.0), 1.0);
        assert_eq!(UnitScale::<2>::of(&[]).scale(), 1.0);
    }
}

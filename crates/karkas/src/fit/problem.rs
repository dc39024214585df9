//! The inner problem of the fit on given knots (Pavlov): its data ([`Problem`]), a point of
//! its search space ([`State`]: the spline and the parameters of the points on it) and its
//! objective `F = H + p f + lambda S` (`S` the bending energy, its pieces weighted by the
//! [`Taper`] towards the ends).

use super::hermite::HermiteSpline;
use super::order::Block;
use crate::Point;

/// The data of one fit, shared by every minimization.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Problem<'a, const D: usize> {
    /// The points, in order.
    pub points: &'a [Point<D>],
    /// `delta_L`, one per knot (the end knots' entries are unused).
    pub delta: &'a [f64],
    /// `lambda`, the weight of the bending energy.
    pub bending: f64,
    /// How `lambda` is shared along the curve.
    pub taper: Taper,
    /// The end values, when the ends are pinned to the first and last points.
    pub pins: Option<[Point<D>; 2]>,
    /// Project the points (foot-point distances) or keep their parameters.
    pub foot_points: bool,
    /// Keep the foot-point parameters in the order of the points ([`super::order`]).
    pub ordered: bool,
}

/// The reaches of the smoothing over which its weight falls at the ends (docs/methods.md §4,
/// "The smoothing falls off at the ends"): on the noisy spiral of the smoothing-fit job, with
/// none of the noise part kept at the ends, 3 leave the ends 0.5-0.6 noise deviations off and
/// 6 leave 0.3-0.4; 10 put one noisy NACA case of the truth table over SciPy's distance.
const TAPER_WIDTHS: f64 = 6.0;
/// The share of the noise part kept at the ends. With none the end pieces are so loosely
/// held that the fit needs more steps on some noise sets (the job's 10^4 points: 7 steps
/// against 3 on 3 of 8 seeds); 5% keeps 3 on all 8, the ends 0.5 noise deviations from the
/// truth instead of 0.3.
const NOISE_KEPT_AT_ENDS: f64 = 0.05;

/// The share of the bending weight on a piece: whole away from the ends, falling to `floor`
/// at them over `length` of the parameter (quadratically). The bending term's natural end
/// condition, `R'' = 0` where no point holds the curve, pulls the end pieces across the
/// curve; with the noise part of the weight tapered there the points hold them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Taper {
    pub floor: f64,
    pub length: f64,
}

impl Taper {
    /// The whole weight everywhere.
    pub const NONE: Taper = Taper {
        floor: 1.0,
        length: 0.0,
    };

    /// The taper for the fairness part `fairness` and the noise part `smoothing` of `lambda`
    /// on `n` points: the noise part falls to [`NOISE_KEPT_AT_ENDS`] of itself at the ends
    /// over [`TAPER_WIDTHS`] of the smoothing's reach `(smoothing / n)^(1/4)`.
    pub(crate) fn towards_ends(fairness: f64, smoothing: f64, n: usize) -> Taper {
        let total = fairness + smoothing;
        if !(smoothing > 0.0 && total.is_finite()) {
            return Taper::NONE;
        }
        Taper {
            floor: (fairness + NOISE_KEPT_AT_ENDS * smoothing) / total,
            length: TAPER_WIDTHS * (smoothing / n as f64).powf(0.25),
        }
    }

    /// The share on the piece `[a, b]` of `[0, 1]`.
    #[inline]
    pub fn share(&self, a: f64, b: f64) -> f64 {
        if self.floor >= 1.0 || self.length <= 0.0 {
            return 1.0;
        }
        let mid = 0.5 * (a + b);
        let r = (mid.min(1.0 - mid).max(0.0) / self.length).min(1.0);
        self.floor + (1.0 - self.floor) * r * r
    }

    /// `S`, the bending energy of `spline` with each piece weighted by its share.
    pub fn bending_energy<const D: usize>(&self, spline: &HermiteSpline<D>) -> f64 {
        spline.bending_energy_by(|a, b| self.share(a, b))
    }
}

impl<const D: usize> Problem<'_, D> {
    /// `lambda` on piece `k` of `knots`.
    #[inline]
    pub fn bending_on(&self, knots: &[f64], k: usize) -> f64 {
        self.bending * self.taper.share(knots[k], knots[k + 1])
    }

    /// `lambda S`, the bending term of `spline`, each piece weighted by its share.
    pub fn bending_term(&self, spline: &HermiteSpline<D>) -> f64 {
        if self.bending > 0.0 {
            self.bending * self.taper.bending_energy(spline)
        } else {
            0.0
        }
    }

    /// How the points get their parameters on a curve.
    pub fn projection(&self) -> Projection {
        Projection {
            foot_points: self.foot_points,
            ordered: self.foot_points && self.ordered,
        }
    }
}

/// How the points get their parameters on a curve.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Projection {
    /// Project the points (else every parameter is held).
    pub foot_points: bool,
    /// Make the foot-point parameters non-decreasing along the points ([`super::order`]).
    pub ordered: bool,
}

impl Projection {
    /// Whether point `i` of `n` is projected (else its parameter is held: the first and the
    /// last point keep `t = 0` and `t = 1`).
    #[inline]
    pub fn is_free(&self, i: usize, n: usize) -> bool {
        self.foot_points && i > 0 && i + 1 < n
    }
}

/// A spline and the parameters and squared distances of the data points on it. The piece of
/// a parameter is not kept: it is found again where needed (`piece_near` from the previous
/// point's piece, which the ordered parameters make the right guess), so that a state costs
/// two numbers a point.
#[derive(Clone, Debug)]
pub(crate) struct State<const D: usize> {
    pub spline: HermiteSpline<D>,
    pub params: Vec<f64>,
    pub dist_sq: Vec<f64>,
    /// Scratch space of the ordering of the parameters.
    pub order: OrderScratch,
}

/// Scratch space of [`super::order::isotonic`]: the pooled runs.
#[derive(Clone, Debug, Default)]
pub(crate) struct OrderScratch {
    pub blocks: Vec<Block>,
    /// The pooled runs of each part, with many points.
    pub parts: Vec<Vec<Block>>,
    /// The parameters before the ordering (allocated by each ordering and released after
    /// it, so that states do not keep one each).
    pub previous: Vec<f64>,
}

impl<const D: usize> State<D> {
    /// A state on `knots` with zero coefficients and the given parameters.
    pub(crate) fn blank(knots: &[f64], params: Vec<f64>) -> Self {
        let n = knots.len();
        State {
            spline: HermiteSpline::from_parts(
                knots.to_vec(),
                vec![Point::ZERO; n],
                vec![Point::ZERO; n],
            ),
            dist_sq: vec![0.0; params.len()],
            order: OrderScratch::default(),
            params,
        }
    }

    /// `H`: the sum of squared distances.
    pub fn data_term(&self) -> f64 {
        self.dist_sq.iter().sum()
    }
}

/// `F = H + p f + lambda S` of a state.
pub(crate) fn objective<const D: usize>(problem: &Problem<D>, state: &State<D>, p: f64) -> f64 {
    state.data_term() + penalties(problem, &state.spline, p)
}

/// `p f + lambda S` of a spline.
pub(crate) fn penalties<const D: usize>(
    problem: &Problem<D>,
    spline: &HermiteSpline<D>,
    p: f64,
) -> f64 {
    let f = if p > 0.0 {
        spline.jump_penalty(problem.delta)
    } else {
        0.0
    };
    p * f + problem.bending_term(spline)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_noise_part_falls_off_quadratically_towards_either_end() {
        // No fairness: the share at the ends is the noise part kept, 0.05. With
        // smoothing / n = (0.05 / 6)^4 the taper runs over 6 (0.05 / 6) = 0.05 of the range.
        let n = 16;
        let taper = Taper::towards_ends(0.0, n as f64 * (0.05f64 / 6.0).powi(4), n);
        assert!((taper.floor - 0.05).abs() < 1e-15);
        assert!((taper.length - 0.05).abs() < 1e-15);
        // Middles 0.01 and 0.985: 0.2 and 0.3 of the way in, 0.05 + 0.95 (0.04 and 0.09).
        assert!((taper.share(0.0, 0.02) - 0.088).abs() < 1e-12);
        assert!((taper.share(0.97, 1.0) - 0.1355).abs() < 1e-12);
        assert_eq!(taper.share(0.04, 0.06), 1.0);
        assert_eq!(taper.share(0.4, 0.6), 1.0);
        // The fairness part stays whole: equal parts put the floor at (1 + 0.05) / 2.
        let half = Taper::towards_ends(1.0, 1.0, n);
        assert!((half.floor - 0.525).abs() < 1e-15);
        // Exact points (no noise part): the whole weight everywhere.
        let none = Taper::towards_ends(3e-9, 0.0, n);
        assert_eq!(none, Taper::NONE);
        assert_eq!(none.share(0.0, 1e-3), 1.0);
    }
}

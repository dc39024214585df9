//! The inner problem of the fit on given knots (Pavlov): its data ([`Problem`]), a point of
//! its search space ([`State`]: the spline and the parameters of the points on it) and its
//! objective `F = H + p f + lambda S`.

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
    /// The end values, when the ends are pinned to the first and last points.
    pub pins: Option<[Point<D>; 2]>,
    /// Project the points (foot-point distances) or keep their parameters.
    pub foot_points: bool,
    /// Keep the foot-point parameters in the order of the points ([`super::order`]).
    pub ordered: bool,
}

impl<const D: usize> Problem<'_, D> {
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

/// A spline and the parameters, squared distances and pieces of the data points on it.
#[derive(Clone, Debug)]
pub(crate) struct State<const D: usize> {
    pub spline: HermiteSpline<D>,
    pub params: Vec<f64>,
    pub dist_sq: Vec<f64>,
    /// The piece of every parameter (a hint kept up to date by the projection).
    pub piece: Vec<usize>,
    /// Scratch space of the ordering of the parameters.
    pub order: OrderScratch,
}

/// Scratch space of [`super::order::isotonic`]: the pooled runs.
#[derive(Clone, Debug, Default)]
pub(crate) struct OrderScratch {
    pub blocks: Vec<Block>,
    /// The pooled runs of each part, with many points.
    pub parts: Vec<Vec<Block>>,
    /// The parameters before the ordering.
    pub previous: Vec<f64>,
}

impl<const D: usize> State<D> {
    /// A state on `knots` with zero coefficients and the given parameters.
    pub fn blank(knots: &[f64], params: Vec<f64>) -> Self {
        let n = knots.len();
        State {
            spline: HermiteSpline::from_parts(
                knots.to_vec(),
                vec![Point::ZERO; n],
                vec![Point::ZERO; n],
            ),
            dist_sq: vec![0.0; params.len()],
            piece: vec![0; params.len()],
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
    let s = if problem.bending > 0.0 {
        spline.bending_energy()
    } else {
        0.0
    };
    p * f + problem.bending * s
}

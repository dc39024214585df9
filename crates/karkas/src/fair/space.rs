//! The cubic spline space of the fairer: `C^2` cubic B-splines on breaks `b_0 < ... < b_m`,
//! clamped at the ends of an open curve or periodic (period `b_m - b_0`) for a closed one.
//!
//! Span `k` (`[b_k, b_{k+1}]`) is served by the four controls `k, k+1, k+2, k+3` (modulo
//! `m` when periodic); the weights of a value or derivative come from
//! [`cubic_span_weights`] on the six knots around the span.

use crate::bspline::{cubic_span_weights, hermite_curve, BSplineCurve};
use crate::{Point, Result};

/// The local positions on every span where the objective samples the curve: the span's ends
/// and the four Gauss–Legendre nodes.
pub(crate) const NODES: [f64; 6] = [
    0.0,
    0.069_431_844_202_973_71,
    0.330_009_478_207_571_87,
    0.669_990_521_792_428_1,
    0.930_568_155_797_026_3,
    1.0,
];

/// The spline space: breaks and closure.
#[derive(Clone, Debug)]
pub(crate) struct Space {
    breaks: Vec<f64>,
    closed: bool,
    /// The weights of derivatives 1..=3 at the [`NODES`] of every span:
    /// `table[(k * NODES.len() + q) * 3 + d - 1]`.
    table: Vec<[f64; 4]>,
    /// Open: the clamped knot vector (`m + 7` knots); closed: the breaks extended by three
    /// periods' worth on each side (`m + 7` knots, index `j + 3` for break `j`).
    knots: Vec<f64>,
}

impl Space {
    /// The space on `breaks` (at least two, increasing; at least four spans when closed).
    pub(crate) fn new(breaks: Vec<f64>, closed: bool) -> Self {
        let m = breaks.len() - 1;
        let knots = if closed {
            let period = breaks[m] - breaks[0];
            (-3..=(m as isize + 3))
                .map(|j| {
                    let wraps = j.div_euclid(m as isize);
                    breaks[j.rem_euclid(m as isize) as usize] + wraps as f64 * period
                })
                .collect()
        } else {
            let mut k = vec![breaks[0]; 3];
            k.extend_from_slice(&breaks);
            k.extend(std::iter::repeat_n(breaks[m], 3));
            k
        };
        let mut space = Space {
            breaks,
            closed,
            knots,
            table: Vec::new(),
        };
        space.table = (0..m)
            .flat_map(|k| NODES.iter().map(move |&s| (k, s)))
            .flat_map(|(k, s)| (1..=3).map(move |d| (k, s, d)))
            .map(|(k, s, d)| space.weights(k, s, d))
            .collect();
        space
    }

    /// The weights of derivative `d` (1 to 3) at node `q` of span `k`.
    #[inline]
    pub(crate) fn node_weights(&self, k: usize, q: usize, d: usize) -> &[f64; 4] {
        &self.table[(k * NODES.len() + q) * 3 + d - 1]
    }

    /// Derivative `d` (1 to 3) at node `q` of span `k` of the spline with `controls`.
    #[inline]
    pub(crate) fn eval_node<const D: usize>(
        &self,
        controls: &[Point<D>],
        k: usize,
        q: usize,
        d: usize,
    ) -> Point<D> {
        let w = self.node_weights(k, q, d);
        (0..4).fold(Point::ZERO, |acc, c| {
            acc.add_scaled(w[c], controls[self.control(k, c)])
        })
    }

    /// The number of spans `m`.
    pub(crate) fn spans(&self) -> usize {
        self.breaks.len() - 1
    }

    /// The breaks.
    pub(crate) fn breaks(&self) -> &[f64] {
        &self.breaks
    }

    /// Whether the space is periodic.
    pub(crate) fn closed(&self) -> bool {
        self.closed
    }

    /// The number of controls: `m + 3` open, `m` closed.
    pub(crate) fn controls(&self) -> usize {
        if self.closed {
            self.spans()
        } else {
            self.spans() + 3
        }
    }

    /// The control serving span `k` as its `c`-th (`c < 4`).
    #[inline]
    pub(crate) fn control(&self, k: usize, c: usize) -> usize {
        if self.closed {
            (k + c) % self.spans()
        } else {
            k + c
        }
    }

    /// The length of span `k`.
    #[inline]
    pub(crate) fn width(&self, k: usize) -> f64 {
        self.breaks[k + 1] - self.breaks[k]
    }

    /// `t` brought into the domain (wrapped by the period when closed, clamped when open).
    pub(crate) fn wrap(&self, t: f64) -> f64 {
        let (a, b) = (self.breaks[0], self.breaks[self.spans()]);
        if self.closed {
            a + (t - a).rem_euclid(b - a)
        } else {
            t.clamp(a, b)
        }
    }

    /// The span holding `t` (in the domain) and its local coordinate in `[0, 1]`.
    pub(crate) fn locate(&self, t: f64) -> (usize, f64) {
        let m = self.spans();
        let k = (self.breaks.partition_point(|&b| b <= t).max(1) - 1).min(m - 1);
        (k, ((t - self.breaks[k]) / self.width(k)).clamp(0.0, 1.0))
    }

    /// The weights of the `d`-th derivative at local coordinate `s` of span `k`, one per
    /// control of the span.
    #[inline]
    pub(crate) fn weights(&self, k: usize, s: f64, d: usize) -> [f64; 4] {
        cubic_span_weights(&self.knots[k + 1..k + 7], s, d)
    }

    /// The `d`-th derivative at local coordinate `s` of span `k` of the spline with
    /// `controls`.
    pub(crate) fn eval<const D: usize>(
        &self,
        controls: &[Point<D>],
        k: usize,
        s: f64,
        d: usize,
    ) -> Point<D> {
        let w = self.weights(k, s, d);
        (0..4).fold(Point::ZERO, |acc, c| {
            acc.add_scaled(w[c], controls[self.control(k, c)])
        })
    }

    /// The spline with `controls` as a clamped B-spline (a closed one over one period,
    /// marked closed).
    pub(crate) fn to_bspline<const D: usize>(
        &self,
        controls: &[Point<D>],
    ) -> Result<BSplineCurve<D>> {
        if !self.closed {
            return BSplineCurve::new(3, self.knots.clone(), controls.to_vec());
        }
        let m = self.spans();
        // The last break repeats the first: the curve closes exactly.
        let at = |j: usize, d: usize| self.eval(controls, j % m, 0.0, d);
        let values: Vec<Point<D>> = (0..=m).map(|j| at(j, 0)).collect();
        let slopes: Vec<Point<D>> = (0..=m).map(|j| at(j, 1)).collect();
        Ok(hermite_curve(&self.breaks, &values, &slopes, 1)?.with_closed(true))
    }
}

//! C^1 cubic Hermite splines: cubic splines of defect 2 (Pavlov; docs/methods.md §4).
//!
//! On knots `T_0 < ... < T_{N-1}` the spline stores a value `R_L` and a derivative `H_L` at
//! every knot. On piece `k` (`[T_k, T_{k+1}]`, length `h`, local `s = (t - T_k)/h`):
//!
//! ```text
//! R(t) = R_k (1-s)^2 (1+2s) + R_{k+1} s^2 (3-2s) + H_k h s (1-s)^2 - H_{k+1} h s^2 (1-s)
//! ```
//!
//! (the paper prints `- h_L` in `F_0` where `+ h_L` is meant). Value and first derivative are
//! continuous at the knots; the second derivative jumps, and the paper measures the jump at an
//! inner knot by its formula (2):
//!
//! ```text
//! J_L = lambda_L H_{L-1} + 2 H_L + mu_L H_{L+1}
//!       - 3 lambda_L (R_L - R_{L-1}) / h_L - 3 mu_L (R_{L+1} - R_L) / h_{L+1},
//! lambda_L = h_{L+1} / (h_L + h_{L+1}),  mu_L = 1 - lambda_L,
//! ```
//!
//! which is the jump `R''(T_L+) - R''(T_L-)` times `-h_L h_{L+1} / (2 (h_L + h_{L+1}))`.
//! `J = 0` at every inner knot makes the spline C^2.
//!
//! Evaluation is `O(log N)` (binary search of the piece) plus `O(D)`.

use crate::core::knots::{check_knots, locate};
use crate::core::parallel::for_each_chunk;
use crate::core::{Curve, Interval, PiecewiseCurve, Side};
pub(crate) use crate::spline::hermite_basis;
use crate::{Error, Point, Result};

/// A C^1 piecewise cubic curve in R^D given by values and derivatives at its knots.
///
/// Outside `[T_0, T_{N-1}]` the polynomials of the end pieces are extended.
#[derive(Clone, Debug, PartialEq)]
pub struct HermiteSpline<const D: usize> {
    knots: Vec<f64>,
    values: Vec<Point<D>>,
    derivatives: Vec<Point<D>>,
}

/// The coefficients of `J_L` (formula (2) of Pavlov) on
/// `[R_{L-1}, H_{L-1}, R_L, H_L, R_{L+1}, H_{L+1}]`, for knots with `h_l = T_L - T_{L-1}` and
/// `h_r = T_{L+1} - T_L`.
#[inline]
pub(crate) fn jump_coefficients(h_l: f64, h_r: f64) -> [f64; 6] {
    let lambda = h_r / (h_l + h_r);
    let mu = h_l / (h_l + h_r);
    [
        3.0 * lambda / h_l,
        lambda,
        -3.0 * lambda / h_l + 3.0 * mu / h_r,
        2.0,
        -3.0 * mu / h_r,
        mu,
    ]
}

/// The Gram matrix of the second derivatives of the four Hermite basis functions of a piece of
/// length `h`: entry `(a, b)` is `int B_a''(t) B_b''(t) dt` over the piece, in the order
/// `[R_k, H_k, R_{k+1}, H_{k+1}]` (the stiffness matrix of the cubic beam element).
#[inline]
pub(crate) fn bending_gram(h: f64) -> [[f64; 4]; 4] {
    let a = 1.0 / (h * h * h);
    let (b, c, d) = (6.0 * h * a, 4.0 * h * h * a, 2.0 * h * h * a);
    [
        [12.0 * a, b, -12.0 * a, b],
        [b, c, -b, d],
        [-12.0 * a, -b, 12.0 * a, -b],
        [b, d, -b, c],
    ]
}

impl<const D: usize> HermiteSpline<D> {
    /// The spline with `values[L]` and `derivatives[L]` at `knots[L]`.
    ///
    /// Errors: fewer than 2 knots; knots not finite or not strictly increasing
    /// ([`Error::InvalidKnot`]); `values` or `derivatives` of another length than `knots`;
    /// a non-finite value or derivative.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::fit::HermiteSpline;
    /// use karkas::{Curve, Point};
    ///
    /// // One cubic piece from (0, 0) to (1, 0) with unit tangents along x: the straight segment.
    /// let values = vec![Point([0.0, 0.0]), Point([1.0, 0.0])];
    /// let tangents = vec![Point([1.0, 0.0]), Point([1.0, 0.0])];
    /// let spline = HermiteSpline::new(vec![0.0, 1.0], values.clone(), tangents.clone())?;
    /// assert!(spline.eval(0.25).distance(Point([0.25, 0.0])) < 1e-14);
    /// assert!(HermiteSpline::new(vec![1.0, 0.0], values, tangents).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(knots: Vec<f64>, values: Vec<Point<D>>, derivatives: Vec<Point<D>>) -> Result<Self> {
        check_knots(&knots, 2, "a Hermite spline (knots)")?;
        for (what, got) in [
            ("values of a Hermite spline (one per knot)", values.len()),
            (
                "derivatives of a Hermite spline (one per knot)",
                derivatives.len(),
            ),
        ] {
            if got != knots.len() {
                return Err(Error::CountMismatch {
                    what,
                    expected: knots.len(),
                    got,
                });
            }
        }
        if let Some(index) = values
            .iter()
            .zip(&derivatives)
            .position(|(v, d)| !v.is_finite() || !d.is_finite())
        {
            return Err(Error::NonFinitePoint { index });
        }
        Ok(HermiteSpline {
            knots,
            values,
            derivatives,
        })
    }

    /// Builds without checks (the fit keeps its knots valid and its coefficients finite).
    pub(crate) fn from_parts(
        knots: Vec<f64>,
        values: Vec<Point<D>>,
        derivatives: Vec<Point<D>>,
    ) -> Self {
        HermiteSpline {
            knots,
            values,
            derivatives,
        }
    }

    /// The knots `T_0 < ... < T_{N-1}`.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }

    /// The values `R_L` at the knots.
    pub fn values(&self) -> &[Point<D>] {
        &self.values
    }

    /// The derivatives `H_L = R'(T_L)` at the knots.
    pub fn derivatives(&self) -> &[Point<D>] {
        &self.derivatives
    }

    /// How far the curve moved across itself from `before` (a spline on the same knots) to
    /// this one: at every knot, the part of the change of the value normal to `before`'s
    /// tangent, and the part of the change of the derivative normal to it times 4/27 of the
    /// longer neighbouring piece (`s (1 - s)^2 <= 4/27`: the most a change of one end
    /// derivative moves a cubic Hermite piece); the largest of these. Changes along the
    /// tangent slide the curve's parameterization, not its shape, and do not count (where
    /// the derivative vanishes the whole change counts).
    pub(crate) fn moved_across(&self, before: &Self) -> f64 {
        let n = self.knots.len();
        let mut moved = 0.0f64;
        for l in 0..n {
            let h_left = if l > 0 {
                self.knots[l] - self.knots[l - 1]
            } else {
                0.0
            };
            let h_right = if l + 1 < n {
                self.knots[l + 1] - self.knots[l]
            } else {
                0.0
            };
            let reach = 4.0 / 27.0 * h_left.max(h_right);
            let tangent = before.derivatives[l];
            let length = tangent.norm();
            let across = |d: Point<D>| {
                if length > 0.0 {
                    let unit = tangent * (1.0 / length);
                    (d - unit * d.dot(unit)).norm()
                } else {
                    d.norm()
                }
            };
            let value = across(self.values[l] - before.values[l]);
            let slope = across(self.derivatives[l] - before.derivatives[l]) * reach;
            moved = moved.max(value).max(slope);
        }
        moved
    }

    /// Mutable access to values and derivatives (the knots stay).
    pub(crate) fn coefficients_mut(&mut self) -> (&mut [Point<D>], &mut [Point<D>]) {
        (&mut self.values, &mut self.derivatives)
    }

    /// The number of pieces, `N - 1`.
    pub fn pieces(&self) -> usize {
        self.knots.len() - 1
    }

    /// The piece holding `t` (the last piece for `t` at or beyond the upper end, the first one
    /// below the lower end or for NaN) and its local coordinate `s` (outside `[0, 1]` when `t`
    /// is outside the domain).
    #[inline]
    pub fn locate(&self, t: f64) -> (usize, f64) {
        locate(&self.knots, false, t, Side::Above)
    }

    /// Local coordinate of `t` on piece `k`.
    #[inline]
    pub(crate) fn local(&self, k: usize, t: f64) -> f64 {
        (t - self.knots[k]) / (self.knots[k + 1] - self.knots[k])
    }

    /// The `k`-th derivative on piece `piece` at local coordinate `s`, per unit `t`.
    #[inline]
    pub fn deriv_on_piece(&self, piece: usize, s: f64, k: usize) -> Point<D> {
        let h = self.knots[piece + 1] - self.knots[piece];
        let b = hermite_basis(s, h, k);
        let mut p = self.values[piece] * b[0];
        p = p.add_scaled(b[1], self.derivatives[piece]);
        p = p.add_scaled(b[2], self.values[piece + 1]);
        p.add_scaled(b[3], self.derivatives[piece + 1])
    }

    /// The jump of the second derivative `R''(T_L+) - R''(T_L-)` at inner knot `L`
    /// (`1 <= L <= N - 2`).
    ///
    /// # Panics
    /// When `L` is not an inner knot.
    pub fn second_derivative_jump(&self, l: usize) -> Point<D> {
        assert!(l >= 1 && l + 1 < self.knots.len(), "not an inner knot");
        self.deriv_on_piece(l, 0.0, 2) - self.deriv_on_piece(l - 1, 1.0, 2)
    }

    /// The paper's jump measure `J_L` at inner knot `L` (formula (2) of Pavlov; see the
    /// module docs): the second-derivative jump times `-h_L h_{L+1} / (2 (h_L + h_{L+1}))`.
    ///
    /// # Panics
    /// When `L` is not an inner knot.
    pub fn jump_measure(&self, l: usize) -> Point<D> {
        assert!(l >= 1 && l + 1 < self.knots.len(), "not an inner knot");
        let c = jump_coefficients(
            self.knots[l] - self.knots[l - 1],
            self.knots[l + 1] - self.knots[l],
        );
        let mut j = Point::ZERO;
        for (slot, &coef) in c.iter().enumerate() {
            let knot = l - 1 + slot / 2;
            let q = if slot % 2 == 0 {
                self.values[knot]
            } else {
                self.derivatives[knot]
            };
            j = j.add_scaled(coef, q);
        }
        j
    }

    /// `f(q) = sum_L weights[L] |J_L|^2` over the inner knots (`weights[L]` is `delta_L`;
    /// entries for the end knots are ignored).
    ///
    /// # Panics
    /// When `weights.len()` differs from the number of knots.
    pub fn jump_penalty(&self, weights: &[f64]) -> f64 {
        assert_eq!(weights.len(), self.knots.len(), "one weight per knot");
        (1..self.knots.len() - 1)
            .map(|l| weights[l] * self.jump_measure(l).norm_sq())
            .sum()
    }

    /// The bending energy `int |R''(t)|^2 dt` over the knots' range, exact: on a piece of
    /// length `h` the second derivative is linear, and the integral is
    /// `h |R''(mid)|^2 + h^3 |R'''|^2 / 12`.
    pub fn bending_energy(&self) -> f64 {
        self.bending_energy_by(|_, _| 1.0)
    }

    /// The bending energy with the piece `[a, b]` weighted by `share(a, b)`.
    pub(crate) fn bending_energy_by(&self, share: impl Fn(f64, f64) -> f64) -> f64 {
        (0..self.pieces())
            .map(|k| {
                let (a, b) = (self.knots[k], self.knots[k + 1]);
                let h = b - a;
                let mid = self.deriv_on_piece(k, 0.5, 2).norm_sq();
                let third = self.deriv_on_piece(k, 0.5, 3).norm_sq();
                share(a, b) * (h * mid + h * h * h / 12.0 * third)
            })
            .sum()
    }

    /// The piece holding `t`, trying `hint` and its neighbours before a binary search (for
    /// parameters that move little between calls).
    #[inline]
    pub(crate) fn piece_near(&self, t: f64, hint: usize) -> usize {
        crate::core::knots::piece_near(&self.knots, t, hint)
    }

    /// The same curve with one more knot at `t` (strictly inside a piece): the value and
    /// derivative there are the curve's own, so the shape does not change.
    ///
    /// Errors: `t` not strictly between two knots ([`Error::InvalidKnot`]).
    pub fn with_knot(&self, t: f64) -> Result<Self> {
        let (piece, s) = self.locate(t);
        if !(s > 0.0 && s < 1.0) {
            return Err(Error::InvalidKnot {
                index: piece + 1,
                value: t,
                reason: "not strictly inside a piece of the spline",
            });
        }
        let mut out = self.clone();
        out.knots.insert(piece + 1, t);
        out.values
            .insert(piece + 1, self.deriv_on_piece(piece, s, 0));
        out.derivatives
            .insert(piece + 1, self.deriv_on_piece(piece, s, 1));
        Ok(out)
    }
}

impl<const D: usize> Curve<D> for HermiteSpline<D> {
    fn domain(&self) -> Interval {
        Interval::new(self.knots[0], self.knots[self.knots.len() - 1])
    }

    fn is_closed(&self) -> bool {
        false
    }

    fn eval(&self, t: f64) -> Point<D> {
        let (piece, s) = self.locate(t);
        self.deriv_on_piece(piece, s, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        let (piece, s) = self.locate(t);
        self.deriv_on_piece(piece, s, k)
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        Some(crate::bspline::PolynomialPieces::uniform_continuity(
            3,
            self.knots.clone(),
            1,
        ))
    }

    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_buffer_len(ts.len(), out.len());
        // Sorted parameters are the common case: try the previous piece first. Large
        // batches run in parallel chunks.
        for_each_chunk(ts, out, |ts, out| {
            let mut piece = 0;
            for (p, &t) in out.iter_mut().zip(ts) {
                let inside = t >= self.knots[piece] && t < self.knots[piece + 1];
                if !inside {
                    piece = self.locate(t).0;
                }
                *p = self.deriv_on_piece(piece, self.local(piece, t), 0);
            }
        });
    }
}

impl<const D: usize> PiecewiseCurve<D> for HermiteSpline<D> {
    fn breakpoints(&self) -> Vec<f64> {
        self.knots.clone()
    }

    fn continuity(&self) -> usize {
        1
    }

    fn deriv_on_side(&self, t: f64, k: usize, side: Side) -> Point<D> {
        let (mut piece, _) = self.locate(t);
        if side == Side::Below && piece > 0 && t <= self.knots[piece] {
            piece -= 1;
        }
        self.deriv_on_piece(piece, self.local(piece, t), k)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point2;

    fn line(shift_value: Point2, shift_slope: Point2) -> HermiteSpline<2> {
        let p = |x: f64, y: f64| Point2::new([x, y]);
        HermiteSpline::from_parts(
            vec![0.0, 0.5, 1.0],
            vec![p(0.0, 0.0), p(1.0, 0.0) + shift_value, p(2.0, 0.0)],
            vec![p(2.0, 0.0), p(2.0, 0.0) + shift_slope, p(2.0, 0.0)],
        )
    }

    #[test]
    fn a_move_along_the_tangent_does_not_count_and_one_across_does() {
        let p = |x: f64, y: f64| Point2::new([x, y]);
        let straight = line(Point2::ZERO, Point2::ZERO);
        // Sliding the middle value and speeding up the middle derivative along the line:
        // a reparameterization.
        let slid = line(p(0.1, 0.0), p(0.5, 0.0));
        assert_eq!(slid.moved_across(&straight), 0.0);
        // The middle value lifted off the line by 0.01.
        let lifted = line(p(0.0, 0.01), Point2::ZERO);
        assert!((lifted.moved_across(&straight) - 0.01).abs() < 1e-15);
        // The middle derivative turned off the line: the pieces move by 4/27 h |dH| at most,
        // and by that much at s = 1/3 of the piece from the knot.
        let turned = line(Point2::ZERO, p(0.0, 0.3));
        let bound = turned.moved_across(&straight);
        assert!((bound - 4.0 / 27.0 * 0.5 * 0.3).abs() < 1e-15);
        let largest = (0..=3000)
            .map(|i| {
                let t = i as f64 / 3000.0;
                turned.eval(t).distance(straight.eval(t))
            })
            .fold(0.0f64, f64::max);
        assert!(
            largest <= bound + 1e-15 && largest > 0.999 * bound,
            "{largest} {bound}"
        );
    }
}

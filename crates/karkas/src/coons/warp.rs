//! Curves whose parameter is bent so that given parameters land on given node values: how
//! point-list curves of a network get the network's parameter (see [`PointNetwork`]).
//!
//! The warp is `phi(v) = sum_j C_j(v) s_j` with the cubic-spline cardinal functions `C_j` of
//! the node values (not-a-knot; for a closed curve `phi(v) = v + sum_j C_j(v) (s_j - v_j)` with
//! periodic ones), so `phi(v_j) = s_j` and `phi` is `C^2`. Derivatives of the warped curve
//! follow from Faa di Bruno's formula.
//!
//! [`PointNetwork`]: super::PointNetwork

use super::blending::{BlendingFamily, SplineBlending, SplineEnds};
use crate::core::{Curve, Interval};
use crate::{Error, Point, Result};

/// A monotone `C^2` map `phi` of a network parameter onto a curve's normalised parameter
/// `[0, 1]` with `phi(v_j) = s_j`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Warp {
    family: SplineBlending,
    /// `s_j` (open) or `s_j - v_j` (closed).
    values: Vec<f64>,
    closed: bool,
}

impl Warp {
    /// The warp with `phi(nodes[j]) = targets[j]`; `nodes` carry the closing node last when
    /// `closed` (period 1). Fails when `phi` would not increase (crossings spaced too unevenly
    /// compared with the node values).
    pub(crate) fn new(nodes: &[f64], targets: &[f64], closed: bool) -> Result<Self> {
        let (family, values) = if closed {
            let values = targets.iter().zip(nodes).map(|(s, v)| s - v).collect();
            (SplineBlending::new(nodes, SplineEnds::Periodic)?, values)
        } else {
            (
                SplineBlending::new(nodes, SplineEnds::NotAKnot)?,
                targets.to_vec(),
            )
        };
        let warp = Warp {
            family,
            values,
            closed,
        };
        warp.check_increasing(nodes)?;
        Ok(warp)
    }

    /// `phi^(k)(v)`, using `weights` (one per node function) as scratch.
    fn derivative(&self, v: f64, k: usize, weights: &mut [f64]) -> f64 {
        let range = self.family.eval_into(v, k, weights);
        let mut sum: f64 = range.map(|j| weights[j] * self.values[j]).sum();
        if self.closed {
            sum += match k {
                0 => v,
                1 => 1.0,
                _ => 0.0,
            };
        }
        sum
    }

    /// Checks `phi' > 0` exactly: on each piece `phi'` is the quadratic
    /// `Delta/h + h/6 (-2A - B + 6A s + 3(B - A) s^2)` in `s`, with `A`, `B` the second
    /// derivatives at the piece's ends.
    fn check_increasing(&self, nodes: &[f64]) -> Result<()> {
        let mut w = vec![0.0; self.family.len()];
        for (l, piece) in nodes.windows(2).enumerate() {
            let h = piece[1] - piece[0];
            let delta = self.derivative(piece[1], 0, &mut w) - self.derivative(piece[0], 0, &mut w);
            let a = self.derivative(piece[0], 2, &mut w);
            let b = self.derivative(piece[1], 2, &mut w);
            let slope =
                |s: f64| delta / h + h / 6.0 * (-2.0 * a - b + 6.0 * a * s + 3.0 * (b - a) * s * s);
            let mut lowest = slope(0.0).min(slope(1.0));
            if a != b {
                let vertex = a / (a - b);
                if vertex > 0.0 && vertex < 1.0 {
                    lowest = lowest.min(slope(vertex));
                }
            }
            if lowest.is_nan() || lowest <= 0.0 {
                return Err(Error::UnevenCrossings { piece: l });
            }
        }
        Ok(())
    }
}

/// A curve of the network parameter `v`: `inner` at `own.start + own.length * phi(v)` with
/// `phi` a [`Warp`], or the identity when the crossings already sit at the node values.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct WarpedCurve<const D: usize, C: Curve<D>> {
    inner: C,
    own: Interval,
    domain: Interval,
    warp: Option<Warp>,
}

impl<const D: usize, C: Curve<D>> WarpedCurve<D, C> {
    /// `inner` over `domain` through `warp` (identity when `None`).
    pub(crate) fn new(inner: C, domain: Interval, warp: Option<Warp>) -> Self {
        WarpedCurve {
            own: inner.domain(),
            inner,
            domain,
            warp,
        }
    }

    /// `tau^(m)(v)` for `m = 0..=k` into `out`, with `tau = own.start + own.length phi`.
    fn inner_derivatives(&self, v: f64, out: &mut [f64], weights: &mut [f64]) {
        for (m, o) in out.iter_mut().enumerate() {
            let phi = match &self.warp {
                Some(w) => w.derivative(v, m, weights),
                None => match m {
                    0 => v,
                    1 => 1.0,
                    _ => 0.0,
                },
            };
            *o = if m == 0 {
                self.own.start + self.own.length() * phi
            } else {
                self.own.length() * phi
            };
        }
    }

    fn weights_len(&self) -> usize {
        self.warp.as_ref().map_or(0, |w| w.family.len())
    }
}

impl<const D: usize, C: Curve<D>> Curve<D> for WarpedCurve<D, C> {
    fn domain(&self) -> Interval {
        self.domain
    }

    fn is_closed(&self) -> bool {
        self.inner.is_closed()
    }

    /// Without a warp the inner curve's pieces, mapped by `tau = own.start + own.length v`;
    /// with one, `None` (a polynomial composed with the cubic warp has other breakpoints and
    /// a higher degree).
    fn polynomial_pieces(&self) -> Option<crate::core::PolynomialPieces> {
        if self.warp.is_some() {
            return None;
        }
        self.inner
            .polynomial_pieces()
            .map(|p| p.mapped(self.own, Interval::new(0.0, 1.0)))
    }

    fn eval(&self, v: f64) -> Point<D> {
        let mut tau = [0.0];
        let mut weights = vec![0.0; self.weights_len()];
        self.inner_derivatives(v, &mut tau, &mut weights);
        self.inner.eval(tau[0])
    }

    /// Faa di Bruno: `d^k/dv^k c(tau(v)) = sum_{m=1..k} c^(m)(tau) B_{k,m}(tau', tau'', ...)`
    /// with the partial Bell polynomials `B_{k,m}`.
    fn deriv(&self, v: f64, k: usize) -> Point<D> {
        if self.warp.is_none() {
            // tau is affine: d^k/dv^k c(tau) = length^k c^(k)(tau).
            let length = self.own.length();
            let scale = (0..k).fold(1.0, |p, _| p * length);
            return self.inner.deriv(self.own.start + length * v, k) * scale;
        }
        let mut tau = vec![0.0; k + 1];
        let mut weights = vec![0.0; self.weights_len()];
        self.inner_derivatives(v, &mut tau, &mut weights);
        if k == 0 {
            return self.inner.eval(tau[0]);
        }
        let bell = partial_bell(k, &tau[1..]);
        (1..=k).fold(Point::ZERO, |sum, m| {
            let b = bell[k][m];
            if b == 0.0 {
                sum
            } else {
                sum.add_scaled(b, self.inner.deriv(tau[0], m))
            }
        })
    }

    fn eval_into(&self, vs: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_buffer_len(vs.len(), out.len());
        const CHUNK: usize = 256;
        let mut own = [0.0; CHUNK];
        let mut weights = vec![0.0; self.weights_len()];
        for (vc, oc) in vs.chunks(CHUNK).zip(out.chunks_mut(CHUNK)) {
            for (o, &v) in own.iter_mut().zip(vc) {
                let mut tau = [0.0];
                self.inner_derivatives(v, &mut tau, &mut weights);
                *o = tau[0];
            }
            self.inner.eval_into(&own[..vc.len()], oc);
        }
    }
}

/// The partial Bell polynomials `B_{n,m}(x_1, ..., x_{n-m+1})` for `n, m <= k`, with
/// `x[i - 1] = x_i`: `B_{0,0} = 1`, `B_{n,m} = sum_{i=1}^{n-m+1} C(n-1, i-1) x_i B_{n-i,m-1}`.
fn partial_bell(k: usize, x: &[f64]) -> Vec<Vec<f64>> {
    let mut b = vec![vec![0.0; k + 1]; k + 1];
    b[0][0] = 1.0;
    for n in 1..=k {
        // binomial C(n-1, i-1) built up along i.
        for m in 1..=n {
            let mut binomial = 1.0;
            let mut sum = 0.0;
            for i in 1..=n - m + 1 {
                if i > 1 {
                    binomial *= (n - i + 1) as f64 / (i - 1) as f64;
                }
                sum += binomial * x[i - 1] * b[n - i][m - 1];
            }
            b[n][m] = sum;
        }
    }
    b
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bell_polynomials_give_the_chain_rule() {
        // B_{3,1} = x3, B_{3,2} = 3 x1 x2, B_{3,3} = x1^3.
        let b = partial_bell(3, &[2.0, 5.0, 7.0]);
        assert_eq!(b[3][1], 7.0);
        assert_eq!(b[3][2], 30.0);
        assert_eq!(b[3][3], 8.0);
        // B_{4,2} = 4 x1 x3 + 3 x2^2.
        let b = partial_bell(4, &[2.0, 5.0, 7.0, 11.0]);
        assert_eq!(b[4][2], 4.0 * 2.0 * 7.0 + 3.0 * 25.0);
    }
}

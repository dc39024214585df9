//! Curves made by a blending family: `base(t) + sum_k H_k(t) c_k` (Chashnikov's functions
//! `H_k` with `L_j(H_k) = delta_jk`, formula (5)).
//!
//! Because the family is dual to its functionals, `L_j` of such a curve is `L_j(base) + c_j`:
//! a base curve shifted so that every functional takes a prescribed value. Two uses:
//! - the cross-derivative curves `A_i`, `B_j` built from twist vectors (no base, the piecewise
//!   Hermite family: values `b_j'(u_i)` and derivatives `d_ij` at the nodes, Chashnikov's §4);
//! - the repair of incompatible data, which moves each curve by the blend of its corrections
//!   (see [`Compatibility::Repair`](super::Compatibility::Repair)).

use std::sync::Arc;

use super::blending::BlendingFamily;
use super::curves::CurveRef;
use crate::core::{Curve, Interval, PolynomialPieces};
use crate::Point;

/// `base(t) + sum_k H_k(t) c_k` over the family's domain (the base, if any, already over it).
#[derive(Clone)]
pub(crate) struct BlendedCurve<const D: usize> {
    base: Option<CurveRef<D>>,
    family: Arc<dyn BlendingFamily>,
    coefficients: Vec<Point<D>>,
    closed: bool,
}

impl<const D: usize> core::fmt::Debug for BlendedCurve<D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("BlendedCurve")
            .field("family", &self.family)
            .field("coefficients", &self.coefficients.len())
            .field("closed", &self.closed)
            .finish_non_exhaustive()
    }
}

impl<const D: usize> BlendedCurve<D> {
    /// The curve `base + sum_k H_k c_k`: one coefficient per function of `family` (the
    /// callers guarantee it), closed as `closed` says (a closed base keeps it closed).
    pub(crate) fn new(
        base: Option<CurveRef<D>>,
        family: Arc<dyn BlendingFamily>,
        coefficients: Vec<Point<D>>,
        closed: bool,
    ) -> Self {
        debug_assert_eq!(coefficients.len(), family.len());
        BlendedCurve {
            base,
            family,
            coefficients,
            closed,
        }
    }

    /// `sum_k H_k^(k)(t) c_k` with the weights buffer `weights`.
    fn blend(&self, t: f64, k: usize, weights: &mut [f64]) -> Point<D> {
        let range = self.family.eval_into(t, k, weights);
        range.fold(Point::ZERO, |s, j| {
            s.add_scaled(weights[j], self.coefficients[j])
        })
    }
}

impl<const D: usize> Curve<D> for BlendedCurve<D> {
    fn domain(&self) -> Interval {
        self.family.domain()
    }

    fn is_closed(&self) -> bool {
        self.closed
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.deriv(t, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        let mut weights = vec![0.0; self.family.len()];
        let blend = self.blend(t, k, &mut weights);
        match &self.base {
            Some(base) => base.deriv(t, k) + blend,
            None => blend,
        }
    }

    /// The family's pieces refined by the base curve's (none when either is unknown).
    fn polynomial_pieces(&self) -> Option<PolynomialPieces> {
        let mut sources = vec![self.family.polynomial_pieces()?];
        if let Some(base) = &self.base {
            sources.push(base.polynomial_pieces()?);
        }
        Some(PolynomialPieces::merge(&sources, self.domain()))
    }

    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        self.deriv_into(ts, 0, out);
    }

    fn deriv_into(&self, ts: &[f64], k: usize, out: &mut [Point<D>]) {
        crate::core::assert_buffer_len(ts.len(), out.len());
        match &self.base {
            Some(base) if k == 0 => base.eval_into(ts, out),
            Some(base) => base.deriv_into(ts, k, out),
            None => out.fill(Point::ZERO),
        }
        let mut weights = vec![0.0; self.family.len()];
        for (o, &t) in out.iter_mut().zip(ts) {
            *o += self.blend(t, k, &mut weights);
        }
    }
}

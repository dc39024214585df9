//! LL interpolating blending (the LL scheme of Aulchenko et al. inside Chashnikov's Boolean sum, docs/methods.md §2).
//!
//! The cardinal functions of the interpolating LL scheme of order `L`: `C_j` is the
//! interpolating LL curve (docs/methods.md §1.2) through the scalar values `delta_jk` at uniform
//! nodes. It is `C^L` and local in its support polygon, but the interpolating prefilter
//! spreads every `C_j` (with geometrically decaying tails) over the whole range.

use super::{reduce, BlendingFamily};
use crate::coons::Functional;
use crate::core::knots::check_knots;
use crate::core::{Curve, Interval};
use crate::ll::{interpolation_controls, LlCurve, LlKernel};
use crate::{Error, Point, Result};
use core::ops::Range;

/// LL interpolating blending of order `L` on `count` uniform nodes over `[start, end]`:
/// functionals `L_j f = f(u_j)`, `u_j = start + j (end - start)/(count - 1)` (open) or
/// `start + j (end - start)/count` (closed, period `end - start`).
///
/// Evaluation costs `O(count)` per parameter (one LL segment per cardinal function); the
/// cardinal curves are built once with `count` `O(count)` solves and kept, `O(count^2)`
/// memory: meant for curve networks (tens to hundreds of curves).
#[derive(Clone, Debug, PartialEq)]
pub struct LlBlending {
    domain: Interval,
    closed: bool,
    /// `C_j` in the LL parameter.
    cardinals: Vec<LlCurve<1>>,
    functionals: Vec<Functional>,
}

impl LlBlending {
    /// The family of order `order` on `count` nodes over `[start, end]`, open or closed.
    ///
    /// Errors: fewer than 3 nodes, `start < end` not finite, `order` outside `1..=64`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{BlendingFamily, LlBlending};
    ///
    /// let family = LlBlending::new(0.0, 1.0, 5, 2, false)?;
    /// assert_eq!(family.len(), 5);
    /// assert!(!family.is_periodic());
    /// assert!(LlBlending::new(0.0, 1.0, 2, 2, false).is_err()); // fewer than 3 nodes
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(start: f64, end: f64, count: usize, order: usize, closed: bool) -> Result<Self> {
        if count < 3 {
            return Err(Error::TooFewPoints {
                what: "an LL blending family (nodes)",
                needed: 3,
                got: count,
            });
        }
        // The interval [start, end] as two knots: finite, start < end.
        check_knots(&[start, end], 2, "an LL blending family (interval)")?;
        let kernel = LlKernel::new(order)?;
        let steps = if closed { count } else { count - 1 };
        let cardinals = (0..count)
            .map(|j| {
                let mut values: Vec<Point<1>> = (0..count)
                    .map(|k| Point([f64::from(u8::from(k == j))]))
                    .collect();
                if closed {
                    values.push(values[0]);
                }
                interpolation_controls(&mut values, kernel.d_l(), closed)?;
                Ok(LlCurve::from_control(kernel.clone(), values, closed))
            })
            .collect::<Result<Vec<_>>>()?;
        let functionals = (0..count)
            .map(|j| Functional::Value {
                at: start + (end - start) * (j as f64 / steps as f64),
            })
            .collect();
        Ok(LlBlending {
            domain: Interval::new(start, end),
            closed,
            cardinals,
            functionals,
        })
    }

    /// The LL order `L`.
    pub fn order(&self) -> usize {
        self.cardinals[0].order()
    }
}

impl BlendingFamily for LlBlending {
    fn len(&self) -> usize {
        self.cardinals.len()
    }

    fn domain(&self) -> Interval {
        self.domain
    }

    fn is_periodic(&self) -> bool {
        self.closed
    }

    fn polynomial_pieces(&self) -> Option<crate::bspline::PolynomialPieces> {
        let cardinal = &self.cardinals[0];
        cardinal
            .polynomial_pieces()
            .map(|p| p.mapped(cardinal.domain(), self.domain))
    }

    fn functionals(&self) -> &[Functional] {
        &self.functionals
    }

    fn eval_into(&self, t: f64, k: usize, out: &mut [f64]) -> Range<usize> {
        let t = reduce(self.domain, self.closed, t);
        let ll = self.cardinals[0].domain();
        let ratio = ll.length() / self.domain.length();
        let tau = ll.start + (t - self.domain.start) * ratio;
        let scale = (0..k).fold(1.0, |p, _| p * ratio);
        for (o, c) in out.iter_mut().zip(&self.cardinals) {
            *o = c.deriv(tau, k)[0] * scale;
        }
        0..self.cardinals.len()
    }
}

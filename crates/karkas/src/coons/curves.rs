//! Boundary curves as the Boolean sum sees them: any [`Curve`] behind a shared pointer, and
//! its parameter stretched onto the surface's.

use std::sync::Arc;

use crate::core::{Curve, Interval};
use crate::Point;

/// A boundary curve of any type: [`LlCurve`](crate::ll::LlCurve), a
/// [`PolylineCurve`](super::PolylineCurve), a closed-form curve, ...
pub type CurveRef<const D: usize> = Arc<dyn Curve<D> + Send + Sync>;

/// Wraps a curve into a [`CurveRef`].
pub fn curve_ref<const D: usize, C: Curve<D> + Send + Sync + 'static>(curve: C) -> CurveRef<D> {
    Arc::new(curve)
}

/// A curve whose own parameter interval is stretched affinely onto `domain`:
/// `t_own = own.start + (t - domain.start) * own.length / domain.length`. Derivatives are
/// scaled by `(own.length / domain.length)^k`. Closed curves stay closed (the period becomes
/// `domain.length()`).
#[derive(Clone)]
pub struct AffineCurve<const D: usize> {
    inner: CurveRef<D>,
    domain: Interval,
    own: Interval,
    ratio: f64,
}

impl<const D: usize> core::fmt::Debug for AffineCurve<D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("AffineCurve")
            .field("domain", &self.domain)
            .field("own", &self.own)
            .finish_non_exhaustive()
    }
}

impl<const D: usize> AffineCurve<D> {
    /// `inner` over `domain` (a nonempty finite interval, as the callers guarantee).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, AffineCurve, PolylineCurve};
    /// use karkas::{Curve, Interval, Point};
    ///
    /// let segment = PolylineCurve::new(&[Point([0.0, 0.0]), Point([2.0, 0.0])], &[0.0, 1.0])?;
    /// // The same segment run over [0, 4] instead of [0, 1].
    /// let stretched = AffineCurve::new(curve_ref(segment), Interval::new(0.0, 4.0));
    /// assert_eq!(stretched.domain().end, 4.0);
    /// assert!(stretched.eval(1.0).distance(Point([0.5, 0.0])) < 1e-14);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(inner: CurveRef<D>, domain: Interval) -> Self {
        let own = inner.domain();
        AffineCurve {
            inner,
            domain,
            own,
            ratio: own.length() / domain.length(),
        }
    }

    /// A [`CurveRef`] of `inner` over `domain`; `inner` itself when it already has that domain.
    pub fn wrap(inner: CurveRef<D>, domain: Interval) -> CurveRef<D> {
        if inner.domain() == domain {
            inner
        } else {
            Arc::new(AffineCurve::new(inner, domain))
        }
    }

    #[inline]
    fn own_parameter(&self, t: f64) -> f64 {
        self.own.start + (t - self.domain.start) * self.ratio
    }
}

impl<const D: usize> Curve<D> for AffineCurve<D> {
    fn domain(&self) -> Interval {
        self.domain
    }

    fn is_closed(&self) -> bool {
        self.inner.is_closed()
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.inner.eval(self.own_parameter(t))
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        let scale = (0..k).fold(1.0, |p, _| p * self.ratio);
        self.inner.deriv(self.own_parameter(t), k) * scale
    }

    fn polynomial_pieces(&self) -> Option<crate::core::PolynomialPieces> {
        self.inner
            .polynomial_pieces()
            .map(|p| p.mapped(self.own, self.domain))
    }

    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        crate::core::assert_buffer_len(ts.len(), out.len());
        // Map in chunks so the inner curve's batch evaluation is used.
        const CHUNK: usize = 256;
        let mut own = [0.0; CHUNK];
        for (tc, oc) in ts.chunks(CHUNK).zip(out.chunks_mut(CHUNK)) {
            for (o, &t) in own.iter_mut().zip(tc) {
                *o = self.own_parameter(t);
            }
            self.inner.eval_into(&own[..tc.len()], oc);
        }
    }
}

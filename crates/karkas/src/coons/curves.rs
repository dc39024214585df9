//! Boundary curves as the Boolean sum sees them: any [`Curve`] behind a shared pointer, its
//! parameter stretched onto the surface's, and curves taken from a surface (cross-derivatives).

use std::sync::Arc;

use super::CoonsSurface;
use crate::core::{Curve, Interval, Surface};
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
        assert_eq!(
            ts.len(),
            out.len(),
            "parameter and output buffers differ in length"
        );
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

/// Which parameter of a surface a cross-derivative curve runs along.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Along {
    /// The curve is a function of `u` on the line `v = at`.
    U,
    /// The curve is a function of `v` on the line `u = at`.
    V,
}

/// The first derivative of a Coons surface across one of its parameter lines, as a curve
/// along the line: for [`Along::V`], `t -> dS/du (at, t)`; for [`Along::U`],
/// `t -> dS/dv (t, at)`.
///
/// This is how omitted cross-derivative curves of a curve network are derived (see
/// [`CrossDerivatives::from_surface`](super::CrossDerivatives::from_surface)). Batch
/// evaluation goes through the surface's grid evaluation.
#[derive(Clone)]
pub struct SurfaceCrossDerivative<const D: usize> {
    surface: Arc<CoonsSurface<D>>,
    along: Along,
    at: f64,
}

impl<const D: usize> core::fmt::Debug for SurfaceCrossDerivative<D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("SurfaceCrossDerivative")
            .field("along", &self.along)
            .field("at", &self.at)
            .finish_non_exhaustive()
    }
}

impl<const D: usize> SurfaceCrossDerivative<D> {
    /// The cross-derivative of `surface` along the line `u = at` ([`Along::V`]) or `v = at`
    /// ([`Along::U`]).
    pub fn new(surface: Arc<CoonsSurface<D>>, along: Along, at: f64) -> Self {
        SurfaceCrossDerivative { surface, along, at }
    }
}

impl<const D: usize> Curve<D> for SurfaceCrossDerivative<D> {
    fn domain(&self) -> Interval {
        match self.along {
            Along::U => self.surface.domain_u(),
            Along::V => self.surface.domain_v(),
        }
    }

    fn is_closed(&self) -> bool {
        match self.along {
            Along::U => self.surface.is_closed_u(),
            Along::V => self.surface.is_closed_v(),
        }
    }

    fn eval(&self, t: f64) -> Point<D> {
        self.deriv(t, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point<D> {
        match self.along {
            Along::U => self.surface.deriv(t, self.at, k, 1),
            Along::V => self.surface.deriv(self.at, t, 1, k),
        }
    }

    /// The surface's pieces along the line (a derivative across it keeps them).
    fn polynomial_pieces(&self) -> Option<crate::core::PolynomialPieces> {
        match self.along {
            Along::U => self.surface.pieces_u().ok(),
            Along::V => self.surface.pieces_v().ok(),
        }
    }

    fn eval_into(&self, ts: &[f64], out: &mut [Point<D>]) {
        self.deriv_into(ts, 0, out);
    }

    fn deriv_into(&self, ts: &[f64], k: usize, out: &mut [Point<D>]) {
        assert_eq!(
            ts.len(),
            out.len(),
            "parameter and output buffers differ in length"
        );
        match self.along {
            Along::U => self.surface.deriv_grid_into(ts, &[self.at], k, 1, out),
            Along::V => self.surface.deriv_grid_into(&[self.at], ts, 1, k, out),
        }
    }
}

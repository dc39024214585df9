//! Curves taken from a Coons surface: its first derivative across a parameter line, a
//! cross-derivative curve of a curve network taken from a surface through it (Chashnikov).

use std::sync::Arc;

use super::CoonsSurface;
use crate::core::{Curve, Interval, Surface};
use crate::Point;

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
/// [`CrossDerivatives::from_surface`](super::CrossDerivatives::from_surface) makes a
/// network's cross-derivative curves of these. Batch evaluation goes through the surface's
/// grid evaluation.
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
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use karkas::coons::{curve_ref, Along, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve, SurfaceCrossDerivative};
    /// use karkas::{Curve, Point};
    ///
    /// let edge = |a: [f64; 3], b: [f64; 3]| -> karkas::Result<_> {
    ///     Ok(curve_ref(PolylineCurve::new(&[Point(a), Point(b)], &[0.0, 1.0])?))
    /// };
    /// let (p00, p10, p01, p11) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 1.0]);
    /// let axis = || NetworkAxis::open(vec![0.0, 1.0]);
    /// let network = CurveNetwork::new(
    ///     axis()?, vec![edge(p00, p01)?, edge(p10, p11)?],
    ///     axis()?, vec![edge(p00, p10)?, edge(p01, p11)?],
    /// )?;
    /// // The bilinear patch is (u, v, u v): along u = 0 its u-derivative is (1, 0, v).
    /// let patch = Arc::new(CoonsSurface::bilinear(&network, 1e-9)?);
    /// let across = SurfaceCrossDerivative::new(patch, Along::V, 0.0);
    /// assert!(across.eval(0.5).distance(Point([1.0, 0.0, 0.5])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
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
        crate::core::assert_buffer_len(ts.len(), out.len());
        match self.along {
            Along::U => self.surface.deriv_grid_into(ts, &[self.at], k, 1, out),
            Along::V => self.surface.deriv_grid_into(&[self.at], ts, 1, k, out),
        }
    }
}

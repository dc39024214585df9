//! Exact conversion of Coons surfaces whose curves and blending functions are piecewise
//! polynomials.
//!
//! Every term of the Boolean sum, `H^u_i(u) f_i(v)`, `H^v_j(v) g_j(u)`,
//! `H^u_i(u) H^v_j(v) L^u_i(g_j)`, is a product of a piecewise polynomial in `u` and one in
//! `v`. On the common refinement of all breakpoints (knot merging), with the largest degree
//! in each direction (degree elevation), the surface is one polynomial per cell: its Bezier
//! net is found from the surface's values at `(p + 1) x (q + 1)` Chebyshev–Lobatto points of
//! the cell (the Bernstein–Vandermonde system of a polynomial of that degree is exactly
//! solvable; it is well conditioned for the degrees allowed here), and the cells are joined
//! into one B-spline with, at each breakpoint, multiplicity `degree - continuity` for the
//! smallest continuity of the functions breaking there.
//!
//! What is exact: any family whose blending functions report their pieces
//! ([`BlendingFamily::polynomial_pieces`]: cubic Hermite, piecewise Hermite, Lagrange,
//! cubic-spline cardinal, LL) combined with curves that report theirs
//! ([`Curve::polynomial_pieces`](crate::Curve::polynomial_pieces): cubic splines, LL curves, polylines, B-splines, their
//! affine reparameterizations and the cross-derivatives of such surfaces). What is not: curves
//! of unknown structure and curves composed with a nonlinear reparameterization (the warp
//! of a [`PointNetwork`](super::PointNetwork) whose crossings do not sit at the node
//! values): [`Error::NotExactlyConvertible`]. Degrees above [`MAX_SAMPLED_DEGREE`] are
//! refused too (the sampling would lose digits). The result is checked against the surface
//! at every cell centre; a mismatch is reported, never returned.

use super::{BlendingFamily, CoonsSurface, CurveRef};
use crate::bspline::{knot_vector, tensor_controls, BSplineSurface, ToBSplineSurface};
use crate::core::{PolynomialPieces, Surface};
use crate::{Error, Point, Result};

/// The largest degree per direction of a Coons surface converted by sampling.
pub const MAX_SAMPLED_DEGREE: usize = 12;

/// The pieces of a Coons surface in one direction: its blending family and the curves that
/// are functions of that parameter.
fn direction_pieces<const D: usize>(
    family: &dyn BlendingFamily,
    curves: &[CurveRef<D>],
    what: &'static str,
) -> Result<PolynomialPieces> {
    let domain = family.domain();
    let mut sources = vec![family
        .polynomial_pieces()
        .ok_or(Error::NotExactlyConvertible {
            what,
            reason: "its blending functions are not known piecewise polynomials".into(),
        })?];
    for (index, curve) in curves.iter().enumerate() {
        let pieces = curve
            .polynomial_pieces()
            .ok_or_else(|| Error::NotExactlyConvertible {
                what,
                reason: format!(
                    "curve {index} is not a polynomial of the surface parameter (a curve given \
                     by points is re-timed to meet the other family when its crossings are not \
                     at the same point numbers as on the other curves of its family): for an \
                     exact STEP or IGES form give every curve of a family as many points \
                     between consecutive crossings (resample them), or write a mesh to a \
                     tolerance (--mesh-tolerance; mesh_tolerance= in Python)"
                ),
            })?;
        sources.push(pieces);
    }
    let merged = PolynomialPieces::merge(&sources, domain);
    if merged.degree > MAX_SAMPLED_DEGREE {
        return Err(Error::NotExactlyConvertible {
            what,
            reason: format!(
                "degree {} is above {MAX_SAMPLED_DEGREE}, the largest converted exactly",
                merged.degree
            ),
        });
    }
    Ok(merged)
}

impl<const D: usize> CoonsSurface<D> {
    /// The pieces in `u` (the u-family and the u-curves `g_j`), if all are known.
    pub fn pieces_u(&self) -> Result<PolynomialPieces> {
        direction_pieces(
            self.u_family().as_ref(),
            self.u_curves(),
            "a Coons surface (in u)",
        )
    }

    /// The pieces in `v` (the v-family and the v-curves `f_i`), if all are known.
    pub fn pieces_v(&self) -> Result<PolynomialPieces> {
        direction_pieces(
            self.v_family().as_ref(),
            self.v_curves(),
            "a Coons surface (in v)",
        )
    }
}

/// The inverse of the Bernstein–Vandermonde matrix of degree `p` at the Chebyshev–Lobatto
/// points `s_i = (1 - cos(pi i / p)) / 2`, row-major, and the points.
fn bernstein_inverse(p: usize) -> Result<(Vec<f64>, Vec<f64>)> {
    let s: Vec<f64> = (0..=p)
        .map(|i| {
            if i == 0 {
                0.0
            } else if i == p {
                1.0
            } else {
                (1.0 - (core::f64::consts::PI * i as f64 / p as f64).cos()) * 0.5
            }
        })
        .collect();
    let n = p + 1;
    let m = nalgebra::DMatrix::from_fn(n, n, |i, k| {
        let binom = (0..k).fold(1.0, |acc, r| acc * (p - r) as f64 / (r + 1) as f64);
        binom * s[i].powi(k as i32) * (1.0 - s[i]).powi((p - k) as i32)
    });
    let inv = m.try_inverse().ok_or(Error::NotExactlyConvertible {
        what: "a Coons surface",
        reason: "the Bernstein interpolation matrix is singular".into(),
    })?;
    let flat = (0..n)
        .flat_map(|i| (0..n).map(move |k| (i, k)))
        .map(|(i, k)| inv[(i, k)])
        .collect();
    Ok((flat, s))
}

/// Coons surfaces over piecewise polynomial data: exact (see the module docs). A closed
/// direction is exported over one period, clamped.
impl<const D: usize> ToBSplineSurface<D> for CoonsSurface<D> {
    fn to_bspline(&self) -> Result<BSplineSurface<D>> {
        let pu = self.pieces_u()?;
        let pv = self.pieces_v()?;
        let (p, q) = (pu.degree.max(1), pv.degree.max(1));
        let (inv_u, su) = bernstein_inverse(p)?;
        let (inv_v, sv) = bernstein_inverse(q)?;
        let (cells_u, cells_v) = (pu.breaks.len() - 1, pv.breaks.len() - 1);
        let (nu, nv) = (p + 1, q + 1);
        // nets[(k * cells_v + l) * nu * nv + a * nv + b]
        let mut nets = vec![Point::<D>::ZERO; cells_u * cells_v * nu * nv];
        let mut us = vec![0.0; nu];
        let mut vs = vec![0.0; nv];
        let mut values = vec![Point::<D>::ZERO; nu * nv];
        let mut half = vec![Point::<D>::ZERO; nu * nv];
        for k in 0..cells_u {
            let (a0, a1) = (pu.breaks[k], pu.breaks[k + 1]);
            for (u, s) in us.iter_mut().zip(&su) {
                *u = a0 + (a1 - a0) * s;
            }
            for l in 0..cells_v {
                let (b0, b1) = (pv.breaks[l], pv.breaks[l + 1]);
                for (v, s) in vs.iter_mut().zip(&sv) {
                    *v = b0 + (b1 - b0) * s;
                }
                self.eval_grid_into(&us, &vs, &mut values);
                // Along v: half[i][b] = sum_j inv_v[b][j] values[i][j].
                for i in 0..nu {
                    for b in 0..nv {
                        half[i * nv + b] = (0..nv).fold(Point::ZERO, |acc, j| {
                            acc.add_scaled(inv_v[b * nv + j], values[i * nv + j])
                        });
                    }
                }
                let net = &mut nets[(k * cells_v + l) * nu * nv..][..nu * nv];
                for a in 0..nu {
                    for b in 0..nv {
                        net[a * nv + b] = (0..nu).fold(Point::ZERO, |acc, i| {
                            acc.add_scaled(inv_u[a * nu + i], half[i * nv + b])
                        });
                    }
                }
            }
        }
        let knots_u = knot_vector(p, &pu.breaks, &pu.multiplicities(p));
        let knots_v = knot_vector(q, &pv.breaks, &pv.multiplicities(q));
        let control = tensor_controls(
            (p, &pu.breaks, &knots_u),
            (q, &pv.breaks, &knots_v),
            |k, l, a, b| nets[(k * cells_v + l) * nu * nv + a * nv + b],
        );
        let result = BSplineSurface::new((p, knots_u), (q, knots_v), control)?
            .with_closed(self.is_closed_u(), self.is_closed_v());
        self.check_cells(&result, &pu.breaks, &pv.breaks)?;
        Ok(result)
    }
}

impl<const D: usize> CoonsSurface<D> {
    /// Compares the conversion with the surface at every cell centre (relative `1e-9`).
    fn check_cells(&self, result: &BSplineSurface<D>, bu: &[f64], bv: &[f64]) -> Result<()> {
        let size = result
            .control_points()
            .as_slice()
            .iter()
            .map(|p| p.norm())
            .fold(0.0, f64::max)
            .max(f64::MIN_POSITIVE);
        for w in bu.windows(2) {
            for z in bv.windows(2) {
                let (u, v) = (0.5 * (w[0] + w[1]), 0.5 * (z[0] + z[1]));
                let gap = self.eval(u, v).distance(result.eval(u, v));
                if gap.is_nan() || gap > 1e-9 * size {
                    return Err(Error::NotExactlyConvertible {
                        what: "a Coons surface",
                        reason: format!(
                            "its curves are not polynomial on the reported pieces: the \
                             converted surface is off by {gap:e} at (u={u}, v={v})"
                        ),
                    });
                }
            }
        }
        Ok(())
    }
}

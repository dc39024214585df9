//! Twist vectors and the cross-derivative curves they make (Chashnikov's §4; METHODS.md §2).
//!
//! The paper builds the composite Coons surface of a network `a_i`, `b_j` from twist vectors
//! `d_ij` at the nodes: the cross-derivative curves `A_i`, `B_j` are chosen with
//!
//! ```text
//! A_i(v_j) = b_j'(u_i),  A_i'(v_j) = d_ij,     B_j(u_i) = a_i'(v_j),  B_j'(u_i) = d_ij,
//! ```
//!
//! which are conditions (11) by construction. The paper leaves the curves between the nodes
//! to its reference \[4\]; karkas takes the piecewise cubic Hermite interpolant of these values
//! and derivatives (the blending functions (17)–(18) of the same nodes), so `A_i` is a cubic on
//! each span, like the patches (13) it borders ([`CrossDerivatives::from_twists`]).
//!
//! The paper takes the `d_ij` as given. When they are not, [`derived_twists`] uses the
//! *spline-of-derivatives* rule (de Boor's rule for bicubic spline surfaces): the cross
//! tangents `b_j'(u_i)` at a v-curve's nodes are interpolated by a cubic spline in `v`
//! (not-a-knot, periodic in a closed direction), whose derivative at `v_j` is one estimate of
//! `S_uv(u_i, v_j)`; the tangents `a_i'(v_j)` along a u-curve give the other, and `d_ij` is
//! their mean. It is exact when the surface's `S_u` is a cubic in `v` and `S_v` a cubic in
//! `u` (four nodes or more each way; a linear one on any nodes): for bicubic and bilinear
//! polynomial surfaces.

use std::sync::Arc;

use super::blended::BlendedCurve;
use super::blending::PiecewiseHermiteBlending;
use super::curves::CurveRef;
use super::instances::{spline_family, DERIVED_CROSS_ENDS};
use super::network::{CrossDerivatives, CurveNetwork, NetworkAxis};
use super::surface::FamilyRef;
use crate::core::Grid;
use crate::{Error, Point, Result};

/// The twists `d_ij` of the spline-of-derivatives rule (see the module docs): a grid with one
/// row per v-curve (node `u_i`) and one column per u-curve (node `v_j`), per unit of the
/// network's parameters.
///
/// Errors: only those of the spline families of the nodes (none for a valid network).
pub fn derived_twists<const D: usize>(network: &CurveNetwork<D>) -> Result<Grid<Point<D>>> {
    let (u_axis, v_axis) = (network.u_axis(), network.v_axis());
    let (m, n) = (u_axis.nodes().len(), v_axis.nodes().len());
    // S_u(u_i, v_j) from the u-curves, S_v(u_i, v_j) from the v-curves.
    let s_u = Grid::from_fn(m, n, |i, j| {
        network.u_curves()[j].deriv(u_axis.nodes()[i], 1)
    });
    let s_v = Grid::from_fn(m, n, |i, j| {
        network.v_curves()[i].deriv(v_axis.nodes()[j], 1)
    });
    let slopes = |axis: &NetworkAxis| -> Result<Vec<Vec<f64>>> {
        let family = spline_family(axis, DERIVED_CROSS_ENDS)?;
        let mut weights = vec![0.0; family.len()];
        Ok(axis
            .nodes()
            .iter()
            .map(|&t| {
                let range = family.eval_into(t, 1, &mut weights);
                let mut row = vec![0.0; family.len()];
                row[range.clone()].copy_from_slice(&weights[range]);
                row
            })
            .collect())
    };
    // c_v[j][k] = C_k'(v_j) for the cardinal splines C_k of the v nodes (same in u).
    let (c_u, c_v) = (slopes(u_axis)?, slopes(v_axis)?);
    Ok(Grid::from_fn(m, n, |i, j| {
        let along_v = (0..n).fold(Point::ZERO, |s, k| s.add_scaled(c_v[j][k], *s_u.get(i, k)));
        let along_u = (0..m).fold(Point::ZERO, |s, k| s.add_scaled(c_u[i][k], *s_v.get(k, j)));
        (along_u + along_v) * 0.5
    }))
}

impl<const D: usize> CrossDerivatives<D> {
    /// The cross-derivative curves of Chashnikov's §4 from twists `d_ij` (one row per v-curve,
    /// one column per u-curve, per unit of the network's parameters): `A_i` is the piecewise
    /// cubic Hermite curve in `v` with `A_i(v_j) = b_j'(u_i)`, `A_i'(v_j) = d_ij`, and `B_j`
    /// the one in `u` with `B_j(u_i) = a_i'(v_j)`, `B_j'(u_i) = d_ij`. They satisfy (11)
    /// exactly, and the composite Coons surface of them has `S_uv(u_i, v_j) = d_ij`.
    ///
    /// Errors: a grid whose shape is not (v-curves) x (u-curves) ([`Error::CountMismatch`]);
    /// a non-finite twist ([`Error::NonFiniteCell`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CrossDerivatives, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::{Grid, Point};
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
    /// let twists = Grid::from_fn(2, 2, |_, _| Point([0.0, 0.0, 1.0]));
    /// let cross = CrossDerivatives::from_twists(&network, &twists)?;
    /// assert_eq!((cross.v_curves.len(), cross.u_curves.len()), (2, 2));
    /// let wrong_shape = Grid::from_fn(3, 2, |_, _| Point([0.0, 0.0, 1.0]));
    /// assert!(CrossDerivatives::from_twists(&network, &wrong_shape).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn from_twists(network: &CurveNetwork<D>, twists: &Grid<Point<D>>) -> Result<Self> {
        let (u_axis, v_axis) = (network.u_axis(), network.v_axis());
        let (m, n) = (u_axis.nodes().len(), v_axis.nodes().len());
        Error::check_counts(&[
            ("rows of twists (one per v-curve)", m, twists.rows()),
            ("columns of twists (one per u-curve)", n, twists.cols()),
        ])?;
        for i in 0..m {
            if let Some(j) = twists.row(i).iter().position(|d| !d.is_finite()) {
                return Err(Error::NonFiniteCell { row: i, col: j });
            }
        }
        let hermite = |axis: &NetworkAxis| -> Result<FamilyRef> {
            Ok(Arc::new(PiecewiseHermiteBlending::new(
                &axis.nodes_with_seam(),
            )?))
        };
        let (family_u, family_v) = (hermite(u_axis)?, hermite(v_axis)?);
        // Values and derivatives at the nodes, the first node again at a closed seam.
        let curve = |family: &FamilyRef,
                     axis: &NetworkAxis,
                     data: &dyn Fn(usize) -> [Point<D>; 2]|
         -> CurveRef<D> {
            let count = axis.nodes().len();
            let coefficients = (0..family.len() / 2)
                .flat_map(|k| data(k % count))
                .collect();
            Arc::new(BlendedCurve::new(
                None,
                family.clone(),
                coefficients,
                axis.is_closed(),
            ))
        };
        let v_curves = (0..m)
            .map(|i| {
                let u = u_axis.nodes()[i];
                curve(&family_v, v_axis, &|j| {
                    [network.u_curves()[j].deriv(u, 1), *twists.get(i, j)]
                })
            })
            .collect();
        let u_curves = (0..n)
            .map(|j| {
                let v = v_axis.nodes()[j];
                curve(&family_u, u_axis, &|i| {
                    [network.v_curves()[i].deriv(v, 1), *twists.get(i, j)]
                })
            })
            .collect();
        Ok(CrossDerivatives { v_curves, u_curves })
    }

    /// The cross-derivative curves of [`from_twists`](Self::from_twists) with the twists of
    /// [`derived_twists`]: what every constructor uses when no cross-derivatives are given.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CrossDerivatives, CurveNetwork, NetworkAxis, PolylineCurve};
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
    /// let cross = CrossDerivatives::derived(&network)?;
    /// // A_0(v_0) is the u-curve's tangent at the corner (0, 0): (1, 0, 0).
    /// assert!(cross.v_curves[0].eval(0.0).distance(Point([1.0, 0.0, 0.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn derived(network: &CurveNetwork<D>) -> Result<Self> {
        Self::from_twists(network, &derived_twists(network)?)
    }
}

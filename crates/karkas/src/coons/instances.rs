//! The classical surfaces as instances of the Boolean sum (Chashnikov's §3 cases 1–3 and §5).

use std::sync::Arc;

use super::blending::{
    CubicHermiteBlending, LagrangeBlending, PiecewiseHermiteBlending, SplineBlending, SplineEnds,
};
use super::curves::CurveRef;
use super::network::{CrossDerivatives, CurveNetwork, NetworkAxis};
use super::surface::{Compatibility, FamilyRef, Names};
use super::CoonsSurface;
use crate::{Error, Result};

/// The end conditions of the splines through the curves' tangents that derive twists, and
/// from them cross-derivatives, when none are given ([`derived_twists`](super::derived_twists);
/// periodic in a closed direction).
pub const DERIVED_CROSS_ENDS: SplineEnds = SplineEnds::NotAKnot;

impl<const D: usize> CoonsSurface<D> {
    /// The bilinear Coons surface (Chashnikov's §3 case 1) of a network of two v-curves (at
    /// `u_0`, `u_1`) and two u-curves (at `v_0`, `v_1`), both directions open: the Boolean sum
    /// with `L f = f(u_0), f(u_1)` and `H = 1 - x, x` on `[u_0, u_1]` (same in `v`).
    ///
    /// Errors: another network shape ([`Error::NotFourSided`]); incompatible corners
    /// ([`Error::IncompatibleCurves`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::{Point, Surface};
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
    /// // Four straight edges: the hyperbolic paraboloid z = u v.
    /// let patch = CoonsSurface::bilinear(&network, 1e-9)?;
    /// assert!(patch.eval(0.5, 0.5).distance(Point([0.5, 0.5, 0.25])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn bilinear(
        network: &CurveNetwork<D>,
        compatibility: impl Into<Compatibility>,
    ) -> Result<Self> {
        let (u0, u1, v0, v1) = four_sided(network, "bilinear Coons")?;
        let u: FamilyRef = Arc::new(LagrangeBlending::new(&[u0, u1])?);
        let v: FamilyRef = Arc::new(LagrangeBlending::new(&[v0, v1])?);
        Self::build(
            u,
            v,
            network.v_curves().to_vec(),
            network.u_curves().to_vec(),
            compatibility.into(),
            (false, false),
            Names {
                v_curve: &|i| format!("v-curve {i}"),
                u_curve: &|j| format!("u-curve {j}"),
            },
        )
    }

    /// The bicubic Coons surface (Chashnikov's §3 case 2) of a two-by-two network with the
    /// cross-derivatives on its four borders: `L f = f(u_0), f'(u_0), f'(u_1), f(u_1)` (the
    /// paper's order (1)) and the cubic Hermite polynomials (3) on `[u_0, u_1]`; the v-curves
    /// family is `a_0, A_0, A_1, a_1` (same in `v`).
    ///
    /// `cross` gives `A_0, A_1` (`dS/du` along the v-curves) and `B_0, B_1` (`dS/dv` along the
    /// u-curves); without it they are the cubic Hermite curves of the curves' tangents at the
    /// corners and the derived twists ([`CrossDerivatives::derived`]; on two nodes the
    /// spline-of-derivatives rule is the difference quotient of the tangents).
    ///
    /// Errors: another network shape ([`Error::NotFourSided`]); cross-derivative counts other
    /// than two ([`Error::CountMismatch`]); a violation of (8) ([`Error::IncompatibleCurves`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::{Point, Surface};
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
    /// let patch = CoonsSurface::bicubic(&network, None, 1e-9)?;
    /// // The surface passes through its boundary curves.
    /// assert!(patch.eval(1.0, 0.5).distance(Point([1.0, 0.5, 0.5])) < 1e-12);
    /// assert!(patch.eval(0.5, 0.0).distance(Point([0.5, 0.0, 0.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn bicubic(
        network: &CurveNetwork<D>,
        cross: Option<&CrossDerivatives<D>>,
        compatibility: impl Into<Compatibility>,
    ) -> Result<Self> {
        let (u0, u1, v0, v1) = four_sided(network, "bicubic Coons")?;
        let cross = cross_or_derived(network, cross)?;
        let (a, b) = (network.v_curves(), network.u_curves());
        let (da, db) = (&cross.v_curves, &cross.u_curves);
        let u: FamilyRef = Arc::new(CubicHermiteBlending::new(u0, u1)?);
        let v: FamilyRef = Arc::new(CubicHermiteBlending::new(v0, v1)?);
        // Formula (1): value, derivative, derivative, value.
        let order = |k: usize| [(0, false), (0, true), (1, true), (1, false)][k];
        let name = |curve: &str, k: usize| {
            let (i, derivative) = order(k);
            if derivative {
                format!("the cross-derivative curve of {curve} {i}")
            } else {
                format!("{curve} {i}")
            }
        };
        Self::build(
            u,
            v,
            vec![a[0].clone(), da[0].clone(), da[1].clone(), a[1].clone()],
            vec![b[0].clone(), db[0].clone(), db[1].clone(), b[1].clone()],
            compatibility.into(),
            (false, false),
            Names {
                v_curve: &|k| name("v-curve", k),
                u_curve: &|k| name("u-curve", k),
            },
        )
    }

    /// The Gordon surface (Chashnikov's §3 case 3): values at the nodes, Lagrange blending in both
    /// directions. In a closed direction the first curve is repeated one period on (Lagrange
    /// polynomials are not periodic: the surface closes with a `C^0` seam).
    ///
    /// Errors: a violation of (8) at a crossing ([`Error::IncompatibleCurves`] naming the
    /// v-curve and u-curve).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::{Point, Surface};
    ///
    /// // Three v-curves and two u-curves of the plane z = 0.
    /// let edge = |a: [f64; 3], b: [f64; 3], c: [f64; 3]| -> karkas::Result<_> {
    ///     Ok(curve_ref(PolylineCurve::new(&[Point(a), Point(b), Point(c)], &[0.0, 1.0, 2.0])?))
    /// };
    /// let v_curves = vec![
    ///     edge([0.0, 0.0, 0.0], [0.0, 0.5, 0.0], [0.0, 1.0, 0.0])?,
    ///     edge([1.0, 0.0, 0.0], [1.0, 0.5, 0.0], [1.0, 1.0, 0.0])?,
    ///     edge([2.0, 0.0, 0.0], [2.0, 0.5, 0.0], [2.0, 1.0, 0.0])?,
    /// ];
    /// let u_curves = vec![
    ///     edge([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [2.0, 0.0, 0.0])?,
    ///     edge([0.0, 1.0, 0.0], [1.0, 1.0, 0.0], [2.0, 1.0, 0.0])?,
    /// ];
    /// let network = CurveNetwork::new(
    ///     NetworkAxis::uniform(3, false)?, v_curves,
    ///     NetworkAxis::open(vec![0.0, 2.0])?, u_curves,
    /// )?;
    /// let surface = CoonsSurface::gordon(&network, 1e-9)?;
    /// assert!(surface.eval(1.5, 1.0).distance(Point([1.5, 0.5, 0.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn gordon(
        network: &CurveNetwork<D>,
        compatibility: impl Into<Compatibility>,
    ) -> Result<Self> {
        let (u_axis, v_axis) = (network.u_axis(), network.v_axis());
        let u: FamilyRef = Arc::new(LagrangeBlending::new(&u_axis.nodes_with_seam())?);
        let v: FamilyRef = Arc::new(LagrangeBlending::new(&v_axis.nodes_with_seam())?);
        let count = (network.v_curves().len(), network.u_curves().len());
        Self::build(
            u,
            v,
            with_seam(network.v_curves(), u_axis),
            with_seam(network.u_curves(), v_axis),
            compatibility.into(),
            (u_axis.is_closed(), v_axis.is_closed()),
            Names {
                v_curve: &|i| format!("v-curve {}", i % count.0),
                u_curve: &|j| format!("u-curve {}", j % count.1),
            },
        )
    }

    /// The Gordon surface with cubic-spline cardinal blending: `ends` in an open direction,
    /// periodic splines in a closed one (`C^2` across the seam).
    ///
    /// Errors: as [`gordon`](Self::gordon).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::param::SplineEnds;
    /// use karkas::{Point, Surface};
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
    /// // On two nodes the natural cubic spline blending is linear: the bilinear patch z = u v.
    /// let patch = CoonsSurface::gordon_spline(&network, SplineEnds::Natural, 1e-9)?;
    /// assert!(patch.eval(0.5, 0.5).distance(Point([0.5, 0.5, 0.25])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn gordon_spline(
        network: &CurveNetwork<D>,
        ends: SplineEnds,
        compatibility: impl Into<Compatibility>,
    ) -> Result<Self> {
        let (u_axis, v_axis) = (network.u_axis(), network.v_axis());
        Self::build(
            spline_family(u_axis, ends)?,
            spline_family(v_axis, ends)?,
            network.v_curves().to_vec(),
            network.u_curves().to_vec(),
            compatibility.into(),
            (u_axis.is_closed(), v_axis.is_closed()),
            Names {
                v_curve: &|i| format!("v-curve {i}"),
                u_curve: &|j| format!("u-curve {j}"),
            },
        )
    }

    /// The composite Coons surface of Chashnikov's §4–5 on a network with cross-derivative curves:
    /// the Boolean sum with the piecewise Hermite families (15)–(18) on the node values
    /// (generalised to uneven nodes, see [`PiecewiseHermiteBlending`]); the v-curve family is
    /// `a_0, A_0, a_1, A_1, ...`. By Proposition 2 it equals the patch-by-patch composite
    /// Coons surface (13); it is `C^1` and satisfies (14): `S(u_i, .) = a_i`,
    /// `S_u(u_i, .) = A_i`, `S(., v_j) = b_j`, `S_v(., v_j) = B_j`.
    ///
    /// `cross` gives `A_i` and `B_j`; without it they are built as Chashnikov's §4 builds them
    /// from twist vectors `d_ij` ([`CrossDerivatives::from_twists`]: `A_i(v_j) = b_j'(u_i)`,
    /// `A_i'(v_j) = d_ij`, piecewise cubic Hermite between the nodes; same for `B_j`), with
    /// the twists of the spline-of-derivatives rule ([`derived_twists`](super::derived_twists)),
    /// which satisfy (11) by construction. Give twists
    /// ([`CrossDerivatives::from_twists`]) or cross-derivatives to prescribe the surface's
    /// tangent planes along the curves. In a
    /// closed direction the first curve and its cross-derivative are repeated one period on
    /// (the piecewise Hermite family is local, so the seam is `C^1` like every other node).
    ///
    /// Errors: cross-derivative counts that differ from the curve counts
    /// ([`Error::CountMismatch`]); a violation of (11)
    /// ([`Error::IncompatibleCurves`] naming the curves and the condition).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CoonsSurface, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::{Point, Surface};
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
    /// let patch = CoonsSurface::composite(&network, None, 1e-9)?;
    /// assert!(patch.eval(1.0, 1.0).distance(Point(p11)) < 1e-12);
    /// assert!(patch.eval(0.0, 0.5).distance(Point([0.0, 0.5, 0.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn composite(
        network: &CurveNetwork<D>,
        cross: Option<&CrossDerivatives<D>>,
        compatibility: impl Into<Compatibility>,
    ) -> Result<Self> {
        let cross = cross_or_derived(network, cross)?;
        let (u_axis, v_axis) = (network.u_axis(), network.v_axis());
        let u: FamilyRef = Arc::new(PiecewiseHermiteBlending::new(&u_axis.nodes_with_seam())?);
        let v: FamilyRef = Arc::new(PiecewiseHermiteBlending::new(&v_axis.nodes_with_seam())?);
        let interleave = |curves: &[CurveRef<D>], derivs: &[CurveRef<D>], axis: &NetworkAxis| {
            let curves = with_seam(curves, axis);
            let derivs = with_seam(derivs, axis);
            curves
                .into_iter()
                .zip(derivs)
                .flat_map(|(c, d)| [c, d])
                .collect::<Vec<_>>()
        };
        let count = (network.v_curves().len(), network.u_curves().len());
        let name = |curve: &str, k: usize, count: usize| {
            if k.is_multiple_of(2) {
                format!("{curve} {}", (k / 2) % count)
            } else {
                format!("the cross-derivative curve of {curve} {}", (k / 2) % count)
            }
        };
        Self::build(
            u,
            v,
            interleave(network.v_curves(), &cross.v_curves, u_axis),
            interleave(network.u_curves(), &cross.u_curves, v_axis),
            compatibility.into(),
            (u_axis.is_closed(), v_axis.is_closed()),
            Names {
                v_curve: &|k| name("v-curve", k, count.0),
                u_curve: &|k| name("u-curve", k, count.1),
            },
        )
    }
}

/// The node values of a two-by-two open network, or an error naming `what`.
fn four_sided<const D: usize>(
    network: &CurveNetwork<D>,
    what: &'static str,
) -> Result<(f64, f64, f64, f64)> {
    let (u, v) = (network.u_axis(), network.v_axis());
    if u.nodes().len() != 2 || v.nodes().len() != 2 || u.is_closed() || v.is_closed() {
        return Err(Error::NotFourSided {
            what,
            v_curves: u.nodes().len(),
            u_curves: v.nodes().len(),
            closed: u.is_closed() || v.is_closed(),
        });
    }
    Ok((u.nodes()[0], u.nodes()[1], v.nodes()[0], v.nodes()[1]))
}

/// `curves`, with the first repeated at the end in a closed direction.
fn with_seam<const D: usize>(curves: &[CurveRef<D>], axis: &NetworkAxis) -> Vec<CurveRef<D>> {
    let mut out = curves.to_vec();
    if axis.is_closed() {
        out.push(curves[0].clone());
    }
    out
}

/// The cubic-spline cardinal family of an axis: `ends` when open, periodic when closed.
pub(crate) fn spline_family(axis: &NetworkAxis, ends: SplineEnds) -> Result<FamilyRef> {
    Ok(if axis.is_closed() {
        Arc::new(SplineBlending::new(
            &axis.nodes_with_seam(),
            SplineEnds::Periodic,
        )?)
    } else {
        Arc::new(SplineBlending::new(axis.nodes(), ends)?)
    })
}

/// The given cross-derivatives (checked against the network's curve counts) or those of the
/// derived twists ([`CrossDerivatives::derived`]).
fn cross_or_derived<const D: usize>(
    network: &CurveNetwork<D>,
    cross: Option<&CrossDerivatives<D>>,
) -> Result<CrossDerivatives<D>> {
    match cross {
        Some(c) => {
            let counts = [
                (
                    "cross-derivative curves of the v-curves",
                    network.v_curves().len(),
                    c.v_curves.len(),
                ),
                (
                    "cross-derivative curves of the u-curves",
                    network.u_curves().len(),
                    c.u_curves.len(),
                ),
            ];
            Error::check_counts(&counts)?;
            Ok(c.clone())
        }
        None => CrossDerivatives::derived(network),
    }
}

//! Curve networks: the input of Gordon and composite Coons surfaces (Chashnikov's §4).
//!
//! A network has *v-curves* `a_i(v)` (each runs along `v` on the line `u = u_i`, the paper's
//! `a_i(beta)`) and *u-curves* `b_j(u)` (along `u` on `v = v_j`, the paper's `b_j(alpha)`),
//! crossing at `a_i(v_j) = b_j(u_i)`. The node values `u_i`, `v_j` are given by a
//! [`NetworkAxis`] per direction; a closed direction (a fuselage's frames, say) is periodic.

use std::sync::Arc;

use super::cross_derivative::{Along, SurfaceCrossDerivative};
use super::curves::{AffineCurve, CurveRef};
use super::CoonsSurface;
use crate::core::knots::check_knots as check_nodes;
use crate::core::Interval;
use crate::{Error, Result};

/// The node values of one direction of a curve network: open (`u_0 < ... < u_m`, the domain
/// `[u_0, u_m]`) or closed (`u_0 < ... < u_{m-1} < u_0 + period`, the domain one period
/// `[u_0, u_0 + period]`).
#[derive(Clone, Debug, PartialEq)]
pub struct NetworkAxis {
    nodes: Vec<f64>,
    period: Option<f64>,
}

impl NetworkAxis {
    /// An open direction with `nodes` (at least two, finite, strictly increasing).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::NetworkAxis;
    ///
    /// let axis = NetworkAxis::open(vec![0.0, 0.5, 2.0])?;
    /// assert_eq!(axis.period(), None);
    /// assert!(NetworkAxis::open(vec![1.0, 0.0]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn open(nodes: Vec<f64>) -> Result<Self> {
        check_nodes(&nodes, 2, "an open network direction")?;
        Ok(NetworkAxis {
            nodes,
            period: None,
        })
    }

    /// A closed direction with `nodes` (at least three, strictly increasing) and `period`:
    /// the last node must lie below `nodes[0] + period`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::NetworkAxis;
    ///
    /// let axis = NetworkAxis::closed(vec![0.0, 1.0, 2.0], 3.0)?;
    /// assert!(axis.is_closed());
    /// assert_eq!(axis.period(), Some(3.0));
    /// // The last node must lie below nodes[0] + period.
    /// assert!(NetworkAxis::closed(vec![0.0, 1.0, 2.0], 2.0).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn closed(nodes: Vec<f64>, period: f64) -> Result<Self> {
        check_nodes(&nodes, 3, "a closed network direction")?;
        let end = nodes[0] + period;
        if !(end.is_finite() && end > nodes[nodes.len() - 1]) {
            return Err(Error::InvalidPeriod {
                period,
                first: nodes[0],
                last: nodes[nodes.len() - 1],
            });
        }
        Ok(NetworkAxis {
            nodes,
            period: Some(period),
        })
    }

    /// The paper's integer nodes `0, 1, ..., count - 1` (open, `count >= 2`) or, closed, the
    /// same with period `count` (`count >= 3`).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::NetworkAxis;
    ///
    /// let axis = NetworkAxis::uniform(4, true)?;
    /// assert_eq!(axis.nodes(), &[0.0, 1.0, 2.0, 3.0]);
    /// assert_eq!(axis.period(), Some(4.0));
    /// assert!(NetworkAxis::uniform(2, true).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn uniform(count: usize, closed: bool) -> Result<Self> {
        let nodes: Vec<f64> = (0..count).map(|i| i as f64).collect();
        if closed {
            Self::closed(nodes, count as f64)
        } else {
            Self::open(nodes)
        }
    }

    /// The node values (one per curve across this direction).
    pub fn nodes(&self) -> &[f64] {
        &self.nodes
    }

    /// True when the direction is periodic.
    pub fn is_closed(&self) -> bool {
        self.period.is_some()
    }

    /// The period of a closed direction.
    pub fn period(&self) -> Option<f64> {
        self.period
    }

    /// The parameter interval: `[u_0, u_m]` open, `[u_0, u_0 + period]` closed.
    pub fn domain(&self) -> Interval {
        let start = self.nodes[0];
        match self.period {
            Some(p) => Interval::new(start, start + p),
            None => Interval::new(start, self.nodes[self.nodes.len() - 1]),
        }
    }

    /// The nodes followed, for a closed direction, by the first node one period on (where
    /// the first curve comes round again): what a non-periodic blending family needs.
    pub fn nodes_with_seam(&self) -> Vec<f64> {
        let mut nodes = self.nodes.clone();
        if let Some(p) = self.period {
            nodes.push(self.nodes[0] + p);
        }
        nodes
    }
}

/// A network of v-curves `a_i` at `u = u_i` and u-curves `b_j` at `v = v_j`.
///
/// Each curve's own parameter interval is stretched affinely onto the network's domain in its
/// direction (a v-curve onto the `v` domain), so the crossing `a_i = b_j` must sit at the
/// curve parameters that this stretching sends to `v_j` and `u_i`; the surfaces check it
/// (conditions (8) / (11)). Closed curves (`Curve::is_closed`) are required exactly in a
/// closed direction; their parameter start is the seam and must be where the first curve of
/// the other family crosses them.
#[derive(Clone)]
pub struct CurveNetwork<const D: usize> {
    u_axis: NetworkAxis,
    v_axis: NetworkAxis,
    v_curves: Vec<CurveRef<D>>,
    u_curves: Vec<CurveRef<D>>,
}

impl<const D: usize> core::fmt::Debug for CurveNetwork<D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("CurveNetwork")
            .field("u_axis", &self.u_axis)
            .field("v_axis", &self.v_axis)
            .finish_non_exhaustive()
    }
}

impl<const D: usize> CurveNetwork<D> {
    /// The network of `v_curves` (one per node of `u_axis`, functions of `v`) and `u_curves`
    /// (one per node of `v_axis`, functions of `u`).
    ///
    /// Errors: curve counts that differ from the node counts ([`Error::CountMismatch`]); an
    /// open v-curve when the `v` direction is closed, or a closed one when it is open (same
    /// for u-curves; [`Error::CurveClosure`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{curve_ref, CurveNetwork, NetworkAxis, PolylineCurve};
    /// use karkas::Point;
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
    /// assert_eq!(network.v_curves().len(), 2);
    /// // One v-curve for two u nodes.
    /// assert!(CurveNetwork::new(axis()?, vec![edge(p00, p01)?], axis()?, vec![edge(p00, p10)?, edge(p01, p11)?]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        u_axis: NetworkAxis,
        v_curves: Vec<CurveRef<D>>,
        v_axis: NetworkAxis,
        u_curves: Vec<CurveRef<D>>,
    ) -> Result<Self> {
        let check = |curves: &[CurveRef<D>],
                     axis: &NetworkAxis,
                     (family, what): (&'static str, &'static str),
                     across: &NetworkAxis| {
            if curves.len() != across.nodes.len() {
                return Err(Error::CountMismatch {
                    what,
                    expected: across.nodes.len(),
                    got: curves.len(),
                });
            }
            match curves
                .iter()
                .position(|c| c.is_closed() != axis.is_closed())
            {
                Some(curve) => Err(Error::CurveClosure {
                    family,
                    curve,
                    closed: !axis.is_closed(),
                }),
                None => Ok(()),
            }
        };
        check(
            &v_curves,
            &v_axis,
            ("v-curve", "v-curves (one per node of the u direction)"),
            &u_axis,
        )?;
        check(
            &u_curves,
            &u_axis,
            ("u-curve", "u-curves (one per node of the v direction)"),
            &v_axis,
        )?;
        let (du, dv) = (u_axis.domain(), v_axis.domain());
        Ok(CurveNetwork {
            v_curves: v_curves
                .into_iter()
                .map(|c| AffineCurve::wrap(c, dv))
                .collect(),
            u_curves: u_curves
                .into_iter()
                .map(|c| AffineCurve::wrap(c, du))
                .collect(),
            u_axis,
            v_axis,
        })
    }

    /// The nodes `u_i` of the v-curves.
    pub fn u_axis(&self) -> &NetworkAxis {
        &self.u_axis
    }

    /// The nodes `v_j` of the u-curves.
    pub fn v_axis(&self) -> &NetworkAxis {
        &self.v_axis
    }

    /// The v-curves `a_i` (functions of `v`, over the `v` domain).
    pub fn v_curves(&self) -> &[CurveRef<D>] {
        &self.v_curves
    }

    /// The u-curves `b_j` (functions of `u`, over the `u` domain).
    pub fn u_curves(&self) -> &[CurveRef<D>] {
        &self.u_curves
    }
}

/// Cross-derivative curves of a network (the paper's `A_i`, `B_j` of (11)): `v_curves[i]` is
/// `A_i(v) = dS/du` along v-curve `i`, `u_curves[j]` is `B_j(u) = dS/dv` along u-curve `j`,
/// both per unit of the network's parameters.
#[derive(Clone)]
pub struct CrossDerivatives<const D: usize> {
    /// `A_i`, one per v-curve, functions of `v`.
    pub v_curves: Vec<CurveRef<D>>,
    /// `B_j`, one per u-curve, functions of `u`.
    pub u_curves: Vec<CurveRef<D>>,
}

impl<const D: usize> core::fmt::Debug for CrossDerivatives<D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("CrossDerivatives")
            .field("v_curves", &self.v_curves.len())
            .field("u_curves", &self.u_curves.len())
            .finish()
    }
}

impl<const D: usize> CrossDerivatives<D> {
    /// The cross-derivatives of a surface through the network: `A_i = dS/du (u_i, .)`,
    /// `B_j = dS/dv (., v_j)`.
    ///
    /// When `surface` interpolates the network (a Gordon surface, by Proposition 1), these
    /// satisfy the compatibility conditions (11) by construction: `A_i(v_j) = S_u(u_i, v_j) =
    /// b_j'(u_i)`, `B_j(u_i) = a_i'(v_j)`, and `A_i'(v_j) = S_uv(u_i, v_j) = B_j'(u_i)`.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::sync::Arc;
    /// use karkas::coons::{curve_ref, CoonsSurface, CrossDerivatives, CurveNetwork, NetworkAxis, PolylineCurve};
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
    /// let patch = Arc::new(CoonsSurface::bilinear(&network, 1e-9)?);
    /// let cross = CrossDerivatives::from_surface(patch, &network);
    /// // S = (u, v, u v): dS/du along u = 1 is (1, 0, v).
    /// assert_eq!(cross.v_curves.len(), 2);
    /// assert!(cross.v_curves[1].eval(0.5).distance(Point([1.0, 0.0, 0.5])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn from_surface(surface: Arc<CoonsSurface<D>>, network: &CurveNetwork<D>) -> Self {
        let across = |along: Along, nodes: &[f64]| -> Vec<CurveRef<D>> {
            nodes
                .iter()
                .map(|&at| {
                    Arc::new(SurfaceCrossDerivative::new(surface.clone(), along, at)) as CurveRef<D>
                })
                .collect()
        };
        CrossDerivatives {
            v_curves: across(Along::V, network.u_axis.nodes()),
            u_curves: across(Along::U, network.v_axis.nodes()),
        }
    }
}

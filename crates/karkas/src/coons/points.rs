//! Curve networks from point lists: interpolated curves reparameterized so that the
//! crossings sit at common node values (see [`PointNetwork`]).

use std::collections::HashMap;

use super::blending::SplineEnds;
use super::curves::CurveRef;
use super::network::{CrossDerivatives, CurveNetwork, NetworkAxis};
use super::warp::{Warp, WarpedCurve};
use crate::core::Interval;
use crate::ll::{interpolation_controls, LlCurve, LlKernel};
use crate::param::CubicSpline;
use crate::{Error, Point, Result};
use std::sync::Arc;

/// How the curves of a [`PointNetwork`] interpolate their points (see there for why the
/// spline is the default).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Default)]
pub enum CurveFit {
    /// A not-a-knot cubic spline, periodic when the curve is closed.
    #[default]
    CubicSpline,
    /// The interpolating LL curve of this order (Aulchenko et al.).
    Ll(usize),
}

/// Relative distance under which the last point of a curve closes it.
const CLOSING: f64 = 1e-12;

/// Crossing parameters that differ from the node values by less than this use no warp.
const SAME_PARAMETER: f64 = 1e-12;

/// How one curve's points become a curve of the network parameter.
#[derive(Clone, Debug, PartialEq)]
struct Parameterization {
    /// Points given (a closed curve's repeated last point included).
    given: usize,
    closed: bool,
    /// Index of the point the closed curve is rotated to start at.
    rotation: usize,
    /// A closed point list interpolated as an open curve from its crossing with curve 0 of
    /// the other family round to it again: a `C^0` seam there (a crease).
    crease: bool,
    fit: CurveFit,
    domain: Interval,
    warp: Option<Warp>,
}

/// Curve networks from point lists: each curve is interpolated through its points, then
/// reparameterized so that the network's crossings sit at common node values.
///
/// How the curves are interpolated ([`CurveFit`]): by default a not-a-knot cubic spline
/// (periodic when closed) in the point-index parameter. Polylines would not do: bicubic and
/// composite Coons surfaces need the curves' tangents at the crossings, and the composite
/// surface is `C^1` only over `C^1` curves. The interpolating LL curve of order 3 (Aulchenko et al.)
/// is offered too ([`CurveFit::Ll`]), but its tangents are only first-order accurate at open
/// ends (its end extension makes the curvature vanish there: a tangent error of 0.16 on a
/// 21-point sample of `sin 2t` where the spline's is below `1e-3`), so cross-derivative data
/// sampled from the same model would fail the compatibility check (11) at any useful
/// tolerance. The spline reproduces cubics: values `O(h^4)`, tangents `O(h^3)`, ends included.
///
/// The parameters:
/// 1. A curve is closed when its last point repeats its first (to a relative `1e-12`); all
///    curves of a family must then be closed, and that direction of the network is periodic.
/// 2. A v-curve and a u-curve cross at a point they share: exactly one point of each lies
///    within `tolerance * size` of the other (`size` = the diagonal of the bounding box of all
///    points). Found with a hash grid of cell `tolerance * size`: `O(total points)`.
/// 3. A curve's own parameter runs from 0 to 1 in proportion to the point index (`k / (K - 1)`
///    at point `k` of `K`, `k / K` when closed, `K` distinct points). A closed curve is first
///    rotated to start at its crossing with curve 0 of the other family.
/// 4. The node value of a u-curve, `v_j`, is the mean over the v-curves of the parameter at
///    which they cross it (same for `u_i`); a closed direction has period 1 and `v_0 = 0`.
///    The crossings must come in the order the other family is listed.
/// 5. Each curve is composed with a warp `phi` sending the node values to its own crossing
///    parameters: `phi(v) = sum_j C_j(v) s_j` with the not-a-knot cubic-spline cardinal
///    functions of the node values (for a closed curve `v + ` a periodic one), checked to
///    increase, derivatives by Faa di Bruno's formula; the identity when the crossings
///    already sit at the node values, as in any network whose curves meet at the same point
///    indices. Each curve then passes through its crossings exactly at the node values.
///
/// Cross-derivative data come as one vector per point of the corresponding curve and are
/// interpolated and reparameterized the same way.
#[derive(Clone, Debug)]
pub struct PointNetwork<const D: usize> {
    network: CurveNetwork<D>,
    v_params: Vec<Parameterization>,
    u_params: Vec<Parameterization>,
    /// Whether a direction is creased ([`PointNetwork::with_creases`]).
    creased: bool,
}

/// One family's curves: distinct points, closedness, and which family it is for messages.
struct Family<'a, const D: usize> {
    name: &'static str,
    curves: &'a [Vec<Point<D>>],
    closed: bool,
}

impl<const D: usize> PointNetwork<D> {
    /// The network through the point lists `v_curves` (each runs along `v`; listed in the
    /// order of increasing `u`) and `u_curves` (along `u`, in the order of increasing `v`),
    /// each curve interpolated as `fit` says.
    ///
    /// `tolerance` is relative to the model size: how far apart two points may be and still
    /// be one crossing.
    ///
    /// Errors: a tolerance that is negative or not finite ([`Error::InvalidSetting`]); a family
    /// with fewer than two curves, three when closed ([`Error::TooFewNetworkCurves`]); a curve
    /// with fewer than two points (an open curve of two is a straight edge) or, closed, three
    /// distinct points, or a non-finite point ([`Error::NetworkCurve`]
    /// around [`Error::TooFewPoints`] or [`Error::NonFinitePoint`]); closed and open curves in
    /// one family ([`Error::MixedClosure`]); [`Error::NetworkCrossing`] for a pair without a
    /// common point, a pair meeting more than once, or crossings out of order; crossings too
    /// unevenly spaced along a curve ([`Error::NetworkCurve`] around
    /// [`Error::UnevenCrossings`]); an LL order outside `1..=64`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::coons::{CurveFit, PointNetwork, POINT_NETWORK_TOLERANCE};
    /// use karkas::Point;
    ///
    /// // Three lines x = 0, 1, 2 and three lines y = 0, 1, 2 of the plane z = 0, crossing at integers.
    /// let line = |f: &dyn Fn(f64) -> [f64; 3]| (0..=4).map(|k| Point(f(k as f64 / 2.0))).collect::<Vec<_>>();
    /// let v_curves: Vec<_> = (0..3).map(|i| line(&move |t| [i as f64, t, 0.0])).collect();
    /// let u_curves: Vec<_> = (0..3).map(|j| line(&move |t| [t, j as f64, 0.0])).collect();
    /// let network = PointNetwork::new(&v_curves, &u_curves, CurveFit::CubicSpline, POINT_NETWORK_TOLERANCE)?;
    /// assert_eq!(network.network().u_axis().nodes().len(), 3);
    /// assert!(PointNetwork::new(&v_curves, &u_curves, CurveFit::Ll(0), POINT_NETWORK_TOLERANCE).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        v_curves: &[Vec<Point<D>>],
        u_curves: &[Vec<Point<D>>],
        fit: CurveFit,
        tolerance: f64,
    ) -> Result<Self> {
        Self::with_creases(v_curves, u_curves, fit, tolerance, (false, false))
    }

    /// The network of [`new`](Self::new) with a crease (a `C^0` seam) in the closed
    /// directions asked by `(crease_u, crease_v)`: for `crease_u` the closed u-curves are
    /// interpolated as open curves from their crossing with v-curve 0 round to it again, and
    /// v-curve 0 is repeated as the last v-curve at `u = 1`; the `u` direction is then open,
    /// with nodes `u_0 = 0, ..., u_{m-1}, 1`, and the surface meets itself along v-curve 0
    /// with a jump of its tangent across it (a sharp trailing edge stays sharp). Same for
    /// `crease_v` with the v-curves and u-curve 0.
    ///
    /// Errors: those of [`new`](Self::new), and a crease in a direction whose curves are not
    /// closed ([`Error::OpenPeriodicData`]).
    ///
    /// ```
    /// use karkas::coons::{CurveFit, PointNetwork, CROSSING_TOLERANCE};
    /// use karkas::{Curve, Point};
    ///
    /// // Three closed diamond sections (u-curves, at z = 0, 1, 2: a closed family needs
    /// // three) and four straight v-curves through their corners.
    /// let corner = |k: usize, z: f64| {
    ///     let (x, y) = [(1.0, 0.0), (0.0, 0.2), (-1.0, 0.0), (0.0, -0.2)][k % 4];
    ///     Point([x, y, z])
    /// };
    /// let u_curves: Vec<Vec<Point<3>>> = [0.0, 1.0, 2.0]
    ///     .iter()
    ///     .map(|&z| (0..5).map(|k| corner(k, z)).collect())
    ///     .collect();
    /// let v_curves: Vec<Vec<Point<3>>> = (0..4)
    ///     .map(|k| vec![corner(k, 0.0), corner(k, 1.0), corner(k, 2.0)])
    ///     .collect();
    /// let net = PointNetwork::with_creases(
    ///     &v_curves, &u_curves, CurveFit::CubicSpline, CROSSING_TOLERANCE, (true, false),
    /// )?;
    /// let network = net.network();
    /// assert!(!network.u_axis().is_closed());
    /// assert_eq!(network.u_axis().nodes(), &[0.0, 0.25, 0.5, 0.75, 1.0]);
    /// // The u-curve at z = 0 starts and ends at the sharp corner (1, 0, 0).
    /// let b = &network.u_curves()[0];
    /// assert!(b.eval(0.0).distance(Point([1.0, 0.0, 0.0])) < 1e-12);
    /// assert!(b.eval(1.0).distance(Point([1.0, 0.0, 0.0])) < 1e-12);
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn with_creases(
        v_curves: &[Vec<Point<D>>],
        u_curves: &[Vec<Point<D>>],
        fit: CurveFit,
        tolerance: f64,
        (crease_u, crease_v): (bool, bool),
    ) -> Result<Self> {
        check_settings(fit, tolerance)?;
        let size = model_size(v_curves.iter().chain(u_curves).flatten());
        let v_family = family("v-curve", v_curves, size)?;
        let u_family = family("u-curve", u_curves, size)?;
        check_creases(&v_family, crease_v, &u_family, crease_u)?;
        let crossings = find_crossings(&v_family, &u_family, tolerance * size, size)?;
        let (m, n) = (v_curves.len(), u_curves.len());
        let v = Side::new(v_family, crease_v, (0..m).map(|i| crossings[i * n].0));
        let u = Side::new(u_family, crease_u, (0..n).map(|j| crossings[j].1));
        // Crossing parameters: on v-curve i at u-curve j, and on u-curve j at v-curve i.
        let on_v: Vec<f64> = (0..m * n)
            .map(|c| v.normalised(c / n, crossings[c].0))
            .collect();
        let on_u: Vec<f64> = (0..m * n)
            .map(|c| u.normalised(c % n, crossings[c].1))
            .collect();
        check_order(&on_v, m, n, false)?;
        check_order(&on_u, m, n, true)?;
        // Node values: v_j averages the v-curves' crossing parameters with u-curve j.
        let v_nodes = (0..n)
            .map(|j| (0..m).map(|i| on_v[i * n + j]).sum::<f64>() / m as f64)
            .collect();
        let u_nodes = (0..m)
            .map(|i| (0..n).map(|j| on_u[i * n + j]).sum::<f64>() / n as f64)
            .collect();
        let v_axis = v.axis(v_nodes)?;
        let u_axis = u.axis(u_nodes)?;
        let mut v_params = v.parameterize(fit, &v_axis, n, &|i, j| on_v[i * n + j])?;
        let mut u_params = u.parameterize(fit, &u_axis, m, &|j, i| on_u[i * n + j])?;
        // A crease repeats curve 0 of the other family at the closing node.
        if crease_u {
            v_params.push(v_params[0].clone());
        }
        if crease_v {
            u_params.push(u_params[0].clone());
        }
        let network = CurveNetwork::new(
            u_axis,
            network_curves(&v_params, v_curves)?,
            v_axis,
            network_curves(&u_params, u_curves)?,
        )?;
        Ok(PointNetwork {
            network,
            v_params,
            u_params,
            creased: crease_u || crease_v,
        })
    }

    /// The network of curves.
    pub fn network(&self) -> &CurveNetwork<D> {
        &self.network
    }

    /// Cross-derivative curves from vectors given at the points of every curve:
    /// `v_derivs[i][k]` is `dS/du` at point `k` of v-curve `i` (a closed curve's repeated last
    /// point included, with the same vector as the first), `u_derivs[j][k]` is `dS/dv` at point
    /// `k` of u-curve `j`, per unit of the network's parameters. They are interpolated like
    /// the curves themselves.
    ///
    /// Errors: counts of curves or vectors that differ from the network's
    /// ([`Error::CountMismatch`], for vectors inside [`Error::NetworkCurve`]), a non-finite
    /// vector ([`Error::NetworkCurve`] around [`Error::NonFinitePoint`]), a closed curve's last
    /// vector differing from its first ([`Error::UnclosedCrossDerivative`]); a creased network
    /// ([`Error::UnsupportedEnds`]: one vector per point cannot give the two sides of a crease).
    pub fn cross_derivatives(
        &self,
        v_derivs: &[Vec<Point<D>>],
        u_derivs: &[Vec<Point<D>>],
    ) -> Result<CrossDerivatives<D>> {
        if self.creased {
            return Err(Error::UnsupportedEnds {
                what: "cross-derivative data of a network",
                ends: "creased",
            });
        }
        // (family, what is counted, the family of the curves' cross-derivatives)
        type Names = (&'static str, &'static str, &'static str);
        let build =
            |params: &[Parameterization], lists: &[Vec<Point<D>>], (name, what, of): Names| {
                if lists.len() != params.len() {
                    return Err(Error::CountMismatch {
                        what,
                        expected: params.len(),
                        got: lists.len(),
                    });
                }
                let in_curve = |curve: usize, source: Error| Error::NetworkCurve {
                    family: of,
                    curve,
                    source: Box::new(source),
                };
                params
                    .iter()
                    .zip(lists)
                    .enumerate()
                    .map(|(c, (p, vectors))| {
                        if vectors.len() != p.given {
                            return Err(in_curve(
                                c,
                                Error::CountMismatch {
                                    what: "vectors (one per point of the curve)",
                                    expected: p.given,
                                    got: vectors.len(),
                                },
                            ));
                        }
                        if let Some(index) = vectors.iter().position(|v| !v.is_finite()) {
                            return Err(in_curve(c, Error::NonFinitePoint { index }));
                        }
                        if p.closed {
                            let scale = vectors.iter().fold(0.0f64, |s, v| s.max(v.max_abs()));
                            let (first, last) = (vectors[0], vectors[vectors.len() - 1]);
                            if (first - last).max_abs() > CLOSING * scale {
                                return Err(Error::UnclosedCrossDerivative {
                                    family: name,
                                    curve: c,
                                });
                            }
                        }
                        p.curve(vectors)
                    })
                    .collect::<Result<Vec<_>>>()
            };
        Ok(CrossDerivatives {
            v_curves: build(
                &self.v_params,
                v_derivs,
                (
                    "v-curve",
                    "cross-derivative curves of the v-curves",
                    "the cross-derivative of v-curve",
                ),
            )?,
            u_curves: build(
                &self.u_params,
                u_derivs,
                (
                    "u-curve",
                    "cross-derivative curves of the u-curves",
                    "the cross-derivative of u-curve",
                ),
            )?,
        })
    }
}

impl Parameterization {
    /// The curve through `values` (given like the curve's points) in the network parameter.
    fn curve<const D: usize>(&self, values: &[Point<D>]) -> Result<CurveRef<D>> {
        let repeats = self.closed || self.crease;
        let k = if repeats { self.given - 1 } else { self.given };
        let mut control: Vec<Point<D>> = (0..k).map(|c| values[(c + self.rotation) % k]).collect();
        if repeats {
            control.push(control[0]);
        }
        Ok(match self.fit {
            CurveFit::CubicSpline => {
                let ends = if self.closed {
                    SplineEnds::Periodic
                } else {
                    SplineEnds::NotAKnot
                };
                // Uniform parameters k / (K - 1) from 0 to 1.
                let last = (control.len().max(2) - 1) as f64;
                let params: Vec<f64> = (0..control.len()).map(|k| k as f64 / last).collect();
                let curve = CubicSpline::new(&params, &control, ends)?;
                Arc::new(WarpedCurve::new(curve, self.domain, self.warp.clone()))
            }
            CurveFit::Ll(order) => {
                let kernel = LlKernel::new(order)?;
                interpolation_controls(&mut control, kernel.d_l(), self.closed)?;
                let curve = LlCurve::from_control(kernel, control, self.closed);
                Arc::new(WarpedCurve::new(curve, self.domain, self.warp.clone()))
            }
        })
    }
}

/// Refuses an LL order the kernel does not have and a crossing tolerance that is not a
/// finite number `>= 0`.
fn check_settings(fit: CurveFit, tolerance: f64) -> Result<()> {
    if let CurveFit::Ll(order) = fit {
        LlKernel::new(order)?;
    }
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "the crossing tolerance must be a finite number >= 0",
        });
    }
    Ok(())
}

/// Refuses a crease along a direction whose curves are open.
fn check_creases<const D: usize>(
    v_family: &Family<'_, D>,
    crease_v: bool,
    u_family: &Family<'_, D>,
    crease_u: bool,
) -> Result<()> {
    for (crease, closed, what) in [
        (crease_u, u_family.closed, "a network creased in u"),
        (crease_v, v_family.closed, "a network creased in v"),
    ] {
        if crease && !closed {
            return Err(Error::OpenPeriodicData {
                what,
                item: "point of every curve along that direction",
            });
        }
    }
    Ok(())
}

/// One family placed on the network: whether it is creased, and the point each closed curve
/// is rotated to start at (its crossing with curve 0 of the other family).
struct Side<'a, const D: usize> {
    family: Family<'a, D>,
    crease: bool,
    rotation: Vec<usize>,
}

impl<'a, const D: usize> Side<'a, D> {
    fn new(family: Family<'a, D>, crease: bool, starts: impl Iterator<Item = usize>) -> Self {
        let closed = family.closed;
        let rotation = starts.map(|k| if closed { k } else { 0 }).collect();
        Side {
            family,
            crease,
            rotation,
        }
    }

    /// The parameter in `[0, 1]` of point `index` of curve `curve` after its rotation.
    fn normalised(&self, curve: usize, index: usize) -> f64 {
        let closed = self.family.closed;
        let k = distinct_len(&self.family.curves[curve], closed);
        let index = (index + k - self.rotation[curve]) % k;
        if closed {
            index as f64 / k as f64
        } else {
            index as f64 / (k - 1) as f64
        }
    }

    /// The network axis through `nodes`: a creased direction is open, its first node (0)
    /// repeated at 1 (the period).
    fn axis(&self, mut nodes: Vec<f64>) -> Result<NetworkAxis> {
        if self.crease {
            nodes.push(1.0);
            NetworkAxis::open(nodes)
        } else if self.family.closed {
            NetworkAxis::closed(nodes, 1.0)
        } else {
            NetworkAxis::open(nodes)
        }
    }

    /// How each curve becomes a curve of the network parameter: warped so that its
    /// `crossings` crossings, at `target(curve, k)` of its own parameter, sit on the nodes.
    fn parameterize(
        &self,
        fit: CurveFit,
        axis: &NetworkAxis,
        crossings: usize,
        target: &dyn Fn(usize, usize) -> f64,
    ) -> Result<Vec<Parameterization>> {
        let nodes = axis.nodes_with_seam();
        let closed = self.family.closed && !self.crease;
        let given = self.family.curves;
        (0..given.len())
            .map(|c| {
                let targets: Vec<f64> = (0..nodes.len())
                    .map(|k| {
                        if k < crossings {
                            target(c, k)
                        } else {
                            1.0 // the closing node of a closed or creased curve
                        }
                    })
                    .collect();
                let same = targets
                    .iter()
                    .zip(&nodes)
                    .all(|(s, v)| (s - v).abs() <= SAME_PARAMETER);
                let warp = if same {
                    None
                } else {
                    Some(
                        Warp::new(&nodes, &targets, closed).map_err(|e| Error::NetworkCurve {
                            family: self.family.name,
                            curve: c,
                            source: Box::new(e),
                        })?,
                    )
                };
                Ok(Parameterization {
                    given: given[c].len(),
                    closed,
                    rotation: self.rotation[c],
                    crease: self.crease,
                    fit,
                    domain: axis.domain(),
                    warp,
                })
            })
            .collect()
    }
}

/// The curves of a family through their points, a creased family's curve 0 again last.
fn network_curves<const D: usize>(
    params: &[Parameterization],
    lists: &[Vec<Point<D>>],
) -> Result<Vec<CurveRef<D>>> {
    params
        .iter()
        .zip(lists.iter().chain(lists.first()))
        .map(|(p, pts)| p.curve(pts))
        .collect()
}

/// The diagonal of the bounding box of `points` (at least the smallest positive number).
fn model_size<'a, const D: usize>(points: impl Iterator<Item = &'a Point<D>>) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    for p in points.filter(|p| p.is_finite()) {
        for c in 0..D {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let d = (0..D)
        .map(|c| (hi[c] - lo[c]).max(0.0).powi(2))
        .sum::<f64>()
        .sqrt();
    if d > 0.0 {
        d
    } else {
        f64::MIN_POSITIVE
    }
}

/// Number of distinct points of a curve (a closed curve's repeated last point dropped).
fn distinct_len<const D: usize>(curve: &[Point<D>], closed: bool) -> usize {
    curve.len() - usize::from(closed)
}

/// Validates one family's point lists and finds whether it is closed.
fn family<'a, const D: usize>(
    name: &'static str,
    curves: &'a [Vec<Point<D>>],
    size: f64,
) -> Result<Family<'a, D>> {
    let closed_of =
        |c: &Vec<Point<D>>| c.len() >= 4 && (c[0] - c[c.len() - 1]).max_abs() <= CLOSING * size;
    let closed = curves.first().is_some_and(closed_of);
    let needed = if closed { 3 } else { 2 };
    if curves.len() < needed {
        return Err(Error::TooFewNetworkCurves {
            family: name,
            needed,
            got: curves.len(),
            closed,
        });
    }
    for (c, curve) in curves.iter().enumerate() {
        let in_curve = |source: Error| Error::NetworkCurve {
            family: name,
            curve: c,
            source: Box::new(source),
        };
        if let Some(index) = curve.iter().position(|p| !p.is_finite()) {
            return Err(in_curve(Error::NonFinitePoint { index }));
        }
        if closed_of(curve) != closed {
            return Err(Error::MixedClosure {
                family: name,
                curve: c,
                closed: !closed,
            });
        }
        // An open curve of 2 points is a straight edge; a closed one needs 3 distinct.
        let distinct = distinct_len(curve, closed);
        let least = if closed { 3 } else { 2 };
        if distinct < least {
            return Err(in_curve(Error::TooFewPoints {
                what: if closed {
                    "a closed curve (its repeated last point not counted)"
                } else {
                    "a curve"
                },
                needed: least,
                got: distinct,
            }));
        }
    }
    Ok(Family {
        name,
        curves,
        closed,
    })
}

/// The crossing `(index on the v-curve, index on the u-curve)` of every pair, row-major by
/// v-curve.
fn find_crossings<const D: usize>(
    v: &Family<'_, D>,
    u: &Family<'_, D>,
    tolerance: f64,
    size: f64,
) -> Result<Vec<(usize, usize)>> {
    // A cell of the tolerance, but not so small that coordinates overflow the cell index
    // (`size` is the model size the tolerance is relative to).
    let cell = tolerance.max(size * 1e-12).max(f64::MIN_POSITIVE);
    let key = |p: &Point<D>| -> [i64; D] { core::array::from_fn(|c| (p[c] / cell).floor() as i64) };
    // A pole (a curve that is one point: the nose of a body) meets every curve of the other
    // family at that point; its crossings are spread over its points in the order of the
    // curves it meets, as a frame's crossings are (see `pole_crossings`).
    let is_pole = |curve: &[Point<D>]| curve.iter().all(|p| p.distance(curve[0]) <= tolerance);
    let u_poles: Vec<bool> = u.curves.iter().map(|c| is_pole(c)).collect();
    let v_poles: Vec<bool> = v.curves.iter().map(|c| is_pole(c)).collect();
    let mut grid: HashMap<[i64; D], Vec<(usize, usize)>> = HashMap::new();
    for (j, curve) in u.curves.iter().enumerate() {
        if u_poles[j] {
            continue;
        }
        for (q, p) in curve[..distinct_len(curve, u.closed)].iter().enumerate() {
            grid.entry(key(p)).or_default().push((j, q));
        }
    }
    let n = u.curves.len();
    let mut found: Vec<Vec<(usize, usize)>> = vec![Vec::new(); v.curves.len() * n];
    let neighbours = 3usize.pow(D as u32);
    for (i, curve) in v.curves.iter().enumerate() {
        if v_poles[i] {
            continue;
        }
        for (k, p) in curve[..distinct_len(curve, v.closed)].iter().enumerate() {
            let base = key(p);
            for code in 0..neighbours {
                let mut cell_key = base;
                let mut rest = code;
                for c in cell_key.iter_mut() {
                    *c = c.saturating_add((rest % 3) as i64 - 1);
                    rest /= 3;
                }
                for &(j, q) in grid.get(&cell_key).into_iter().flatten() {
                    if u.curves[j][q].distance(*p) <= tolerance {
                        let hits = &mut found[i * n + j];
                        hits.push((k, q));
                        if hits.len() > 1 {
                            // Stop at once: degenerate data (many coinciding points) would
                            // otherwise cost a product of the point counts.
                            return Err(meet_twice(i, j, hits[0], hits[1], v.name, u.name));
                        }
                    }
                }
            }
        }
    }
    pole_crossings(v, u, (&v_poles, &u_poles), tolerance, &mut found)?;
    found
        .into_iter()
        .enumerate()
        .map(|(c, hits)| {
            let (v_curve, u_curve) = (c / n, c % n);
            match hits.as_slice() {
                [one] => Ok(*one),
                [] => Err(Error::NetworkCrossing {
                    v_curve,
                    u_curve,
                    problem: format!(
                        "no common point: every crossing must be a point of both curves (to \
                         within {tolerance:.3e})"
                    ),
                }),
                [a, b, ..] => Err(meet_twice(v_curve, u_curve, *a, *b, v.name, u.name)),
            }
        })
        .collect()
}

/// The crossings of the poles (`poles.0` marks the v-curves that are one point, `poles.1` the
/// u-curves) with the curves of the other family, added to `found` (row-major by v-curve): a
/// pole's crossing with the `c`-th of the `count` curves it meets is its point
/// `c * points / count` (`points` its distinct points), so that the crossings advance along it
/// in order and a pole sampled as densely as the other curves has them at the same point
/// indices; the other curve's crossing is its point at the pole (an end, for a nose).
///
/// Errors: a pole with fewer distinct points than the curves it meets; two poles that would
/// cross; a curve that does not pass through a pole.
fn pole_crossings<const D: usize>(
    v: &Family<'_, D>,
    u: &Family<'_, D>,
    (v_poles, u_poles): (&[bool], &[bool]),
    tolerance: f64,
    found: &mut [Vec<(usize, usize)>],
) -> Result<()> {
    let (m, n) = (v.curves.len(), u.curves.len());
    for i in 0..m {
        for j in 0..n {
            if !v_poles[i] && !u_poles[j] {
                continue;
            }
            let problem = |text: String| Error::NetworkCrossing {
                v_curve: i,
                u_curve: j,
                problem: text,
            };
            if v_poles[i] && u_poles[j] {
                return Err(problem("both curves are single points (poles)".into()));
            }
            // (the pole's family, its curve, the other's curve, its index among the curves
            // the pole meets, their count)
            let (pole, other, other_closed, c, count) = if v_poles[i] {
                (&v.curves[i], &u.curves[j], u.closed, j, n)
            } else {
                (&u.curves[j], &v.curves[i], v.closed, i, m)
            };
            let points = distinct_len(pole, if v_poles[i] { v.closed } else { u.closed });
            if points < count {
                return Err(problem(format!(
                    "a curve that is one point (a pole) needs at least as many points as the                      {count} curves it meets, to give each its own crossing; it has {points}"
                )));
            }
            let at = pole[0];
            let Some(q) = other[..distinct_len(other, other_closed)]
                .iter()
                .position(|p| p.distance(at) <= tolerance)
            else {
                return Err(problem(format!(
                    "no common point: the curve does not pass through the pole (to within                      {tolerance:.3e})"
                )));
            };
            let k = c * points / count;
            found[i * n + j] = vec![if v_poles[i] { (k, q) } else { (q, k) }];
        }
    }
    Ok(())
}

/// The error for a pair of curves with two crossings `a` and `b` (point indices on the
/// v-curve and the u-curve).
fn meet_twice(
    v_curve: usize,
    u_curve: usize,
    a: (usize, usize),
    b: (usize, usize),
    v_name: &str,
    u_name: &str,
) -> Error {
    Error::NetworkCrossing {
        v_curve,
        u_curve,
        problem: format!(
            "they meet more than once: point {} of the {v_name} and point {} of the {u_name}, \
             and also point {} and point {}",
            a.0, a.1, b.0, b.1
        ),
    }
}

/// Checks that the crossing parameters increase along every curve: `params[i * n + j]` along
/// v-curve `i` in `j` (or, `along_u`, along u-curve `j` in `i`).
fn check_order(params: &[f64], m: usize, n: usize, along_u: bool) -> Result<()> {
    let (curves, crossings) = if along_u { (n, m) } else { (m, n) };
    for c in 0..curves {
        for k in 1..crossings {
            let at = |k: usize| {
                if along_u {
                    params[k * n + c]
                } else {
                    params[c * n + k]
                }
            };
            if at(k) <= at(k - 1) {
                let (v_curve, u_curve) = if along_u { (k, c) } else { (c, k) };
                let (this, other, previous) = if along_u {
                    ("u-curve", "v-curve", k - 1)
                } else {
                    ("v-curve", "u-curve", k - 1)
                };
                return Err(Error::NetworkCrossing {
                    v_curve,
                    u_curve,
                    problem: format!(
                        "crossed out of order: {this} {c} meets {other} {k} before {other} \
                         {previous}; list the {other}s in the order they are crossed, with \
                         every {this} running the same way"
                    ),
                });
            }
        }
    }
    Ok(())
}

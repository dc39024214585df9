//! The generalized Coons surface: the Boolean sum (9) of Chashnikov over any two blending
//! families and curve families, with the compatibility check (8).

use std::sync::Arc;

use super::blended::BlendedCurve;
use super::blending::{reduce, BlendingFamily};
use super::curves::{AffineCurve, CurveRef};
use crate::core::{Interval, Surface};
use crate::{Error, Point, Result};

/// A blending family behind a shared pointer.
pub type FamilyRef = Arc<dyn BlendingFamily>;

/// The default relative tolerance of the compatibility conditions: `1e-6` of the model size
/// (per node spacing for derivative conditions, see [`CoonsSurface::new`]).
pub const DEFAULT_TOLERANCE: f64 = 1e-6;

/// Points sampled per curve to measure the model size.
const SIZE_SAMPLES: usize = 9;

/// How a constructor treats the compatibility conditions (8) (for the composite family, (11)).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Compatibility {
    /// Check them with this tolerance relative to the model size (per node spacing for
    /// derivative conditions, see [`CoonsSurface::new`]) and refuse a violation
    /// ([`Error::IncompatibleCurves`]). A bare `f64` converts to this.
    Check(f64),
    /// Make them hold: both sides of every condition, `L^u_i(g_j)` and `L^v_j(f_i)`, are
    /// snapped to their mean. Curve `f_i` becomes `f_i + sum_j H^v_j (mean_ij - L^v_j(f_i))`
    /// (and `g_j` likewise with the `u` family): since `L^v_k(H^v_j) = delta_kj` (5), this
    /// changes exactly the data the conditions look at, by half the mismatch, and the
    /// surface then interpolates the repaired curves (Proposition 1). The largest
    /// correction is kept ([`CoonsSurface::repair`]).
    Repair,
}

impl From<f64> for Compatibility {
    fn from(tolerance: f64) -> Self {
        Compatibility::Check(tolerance)
    }
}

/// The largest correction a [`Compatibility::Repair`] made: half the largest mismatch of the
/// conditions (8), the largest measured as the check measures it (relative to the model
/// size, per node spacing for derivatives).
#[derive(Clone, Debug, PartialEq)]
pub struct Repair {
    /// The size of the correction, in the units of the condition (a distance for values,
    /// per unit of the parameter for derivatives); 0 when the data were compatible.
    pub correction: f64,
    /// The correction relative to the model size (times the node spacings for derivative
    /// conditions): what a [`Compatibility::Check`] tolerance is compared with.
    pub relative: f64,
    /// The condition corrected, e.g. `value at u=0.5 of u-curve 1 and derivative in v at
    /// v=0.25 of v-curve 2`.
    pub condition: String,
    /// Where the two curves cross.
    pub u: f64,
    /// Where the two curves cross.
    pub v: f64,
}

/// A generalized Coons surface (Chashnikov, formula (9)):
///
/// ```text
/// c(u,v) = sum_i H^u_i(u) f_i(v) + sum_j H^v_j(v) g_j(u) - sum_i sum_j H^u_i(u) H^v_j(v) L^u_i(g_j)
/// ```
///
/// with blending families `(L^u_i, H^u_i)`, `(L^v_j, H^v_j)` and curve families `f_i` (functions
/// of `v`, here called *v-curves*: each runs along `v`) and `g_j` (functions of `u`, the
/// *u-curves*). When the data are compatible, `L^u_i(g_j) = L^v_j(f_i)` (8), the surface
/// reproduces every curve (Proposition 1): `L^u_i c(., v) = f_i(v)` and `L^v_j c(u, .) = g_j(u)`.
///
/// Evaluation outside the domain clamps an open direction and wraps a closed one.
#[derive(Clone)]
pub struct CoonsSurface<const D: usize> {
    u_family: FamilyRef,
    v_family: FamilyRef,
    v_curves: Vec<CurveRef<D>>,
    u_curves: Vec<CurveRef<D>>,
    /// `L^u_i(g_j)`, row-major `m x n`.
    corners: Vec<Point<D>>,
    closed_u: bool,
    closed_v: bool,
    /// The largest correction, when built with [`Compatibility::Repair`].
    repair: Option<Repair>,
}

impl<const D: usize> core::fmt::Debug for CoonsSurface<D> {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        f.debug_struct("CoonsSurface")
            .field("u_family", &self.u_family)
            .field("v_family", &self.v_family)
            .field("v_curves", &self.v_curves.len())
            .field("u_curves", &self.u_curves.len())
            .field("closed_u", &self.closed_u)
            .field("closed_v", &self.closed_v)
            .finish()
    }
}

/// How the constructors name the curves in error messages.
pub(crate) struct Names<'a> {
    pub v_curve: &'a dyn Fn(usize) -> String,
    pub u_curve: &'a dyn Fn(usize) -> String,
}

impl<const D: usize> CoonsSurface<D> {
    /// The Boolean sum (9) of the v-curves `f_i` (one per function of `u_family`, functions of
    /// `v`) and the u-curves `g_j` (one per function of `v_family`, functions of `u`).
    ///
    /// Each curve's own parameter interval is stretched affinely onto the domain of the family
    /// it is blended across: a v-curve onto `v_family.domain()`, a u-curve onto
    /// `u_family.domain()`. The surface is closed in a direction when that family is periodic.
    ///
    /// The compatibility conditions (8) are checked at every pair: `|L^u_i(g_j) - L^v_j(f_i)|`
    /// may not exceed `tolerance * size / h_u^ku / h_v^kv`, where `size` is the diagonal of the
    /// bounding box of the position curves (sampled), `ku`, `kv` the derivative orders of the
    /// two functionals and `h_u`, `h_v` the smallest distance between the points the
    /// functionals of each family look at (a derivative is a position difference per parameter
    /// step).
    ///
    /// Errors: an empty family ([`Error::EmptyBlendingFamily`]), curve or functional counts
    /// that differ from the family sizes ([`Error::CountMismatch`]), a tolerance that is
    /// negative or not finite ([`Error::InvalidSetting`]), and [`Error::IncompatibleCurves`] naming the first pair that violates (8)
    /// (curves are named `f_i` and `g_j`).
    ///
    /// `compatibility` is a tolerance (`f64`, [`Compatibility::Check`]) or
    /// [`Compatibility::Repair`].
    ///
    /// The bilinear Coons patch of four straight edges (Lagrange blending on the nodes 0 and 1) is
    /// the hyperbolic paraboloid through the corners:
    ///
    /// ```
    /// use std::sync::Arc;
    /// use karkas::coons::{curve_ref, CoonsSurface, FamilyRef, LagrangeBlending, PolylineCurve};
    /// use karkas::{Point, Surface};
    ///
    /// let edge = |a: [f64; 3], b: [f64; 3]| -> karkas::Result<_> {
    ///     Ok(curve_ref(PolylineCurve::new(&[Point(a), Point(b)], &[0.0, 1.0])?))
    /// };
    /// let (p00, p10, p01, p11) = ([0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [1.0, 1.0, 1.0]);
    /// let u: FamilyRef = Arc::new(LagrangeBlending::new(&[0.0, 1.0])?);
    /// let v: FamilyRef = Arc::new(LagrangeBlending::new(&[0.0, 1.0])?);
    /// let v_curves = vec![edge(p00, p01)?, edge(p10, p11)?]; // at u = 0 and u = 1
    /// let u_curves = vec![edge(p00, p10)?, edge(p01, p11)?]; // at v = 0 and v = 1
    /// let patch = CoonsSurface::new(u, v, v_curves, u_curves, 1e-9)?;
    /// let mid = patch.eval(0.5, 0.5);
    /// assert!((mid.0[2] - 0.25).abs() < 1e-12); // z = u v
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(
        u_family: FamilyRef,
        v_family: FamilyRef,
        v_curves: Vec<CurveRef<D>>,
        u_curves: Vec<CurveRef<D>>,
        compatibility: impl Into<Compatibility>,
    ) -> Result<Self> {
        let closed = (u_family.is_periodic(), v_family.is_periodic());
        Self::build(
            u_family,
            v_family,
            v_curves,
            u_curves,
            compatibility.into(),
            closed,
            Names {
                v_curve: &|i| format!("f_{i}"),
                u_curve: &|j| format!("g_{j}"),
            },
        )
    }

    /// [`new`](Self::new) with the closedness given (a non-periodic family over a closed curve
    /// family whose seam curve is repeated still closes the surface) and named curves.
    pub(crate) fn build(
        u_family: FamilyRef,
        v_family: FamilyRef,
        v_curves: Vec<CurveRef<D>>,
        u_curves: Vec<CurveRef<D>>,
        compatibility: Compatibility,
        (closed_u, closed_v): (bool, bool),
        names: Names<'_>,
    ) -> Result<Self> {
        check_sizes(&u_family, &v_family, v_curves.len(), u_curves.len())?;
        let tolerance = check_tolerance(compatibility)?;
        let (du, dv) = (u_family.domain(), v_family.domain());
        let v_curves: Vec<CurveRef<D>> = v_curves
            .into_iter()
            .map(|c| AffineCurve::wrap(c, dv))
            .collect();
        let u_curves: Vec<CurveRef<D>> = u_curves
            .into_iter()
            .map(|c| AffineCurve::wrap(c, du))
            .collect();
        let lu = u_family.functionals();
        let lv = v_family.functionals();
        let corners: Vec<Point<D>> = lu
            .iter()
            .flat_map(|l| u_curves.iter().map(move |g| l.apply(g.as_ref())))
            .collect();
        let conditions = Conditions {
            lu,
            lv,
            size: model_size(&v_curves, lu, dv, &u_curves, lv, du),
            hu: smallest_spacing(u_family.as_ref()),
            hv: smallest_spacing(v_family.as_ref()),
            names: &names,
        };
        if compatibility == Compatibility::Repair {
            return Ok(repaired(
                (u_family.clone(), v_family.clone()),
                (v_curves, u_curves),
                corners,
                (closed_u, closed_v),
                &|i, j| conditions.scale(i, j),
                &|i, j| conditions.describe(i, j),
            ));
        }
        conditions.check(&v_curves, &corners, tolerance)?;
        Ok(CoonsSurface {
            u_family,
            v_family,
            v_curves,
            u_curves,
            corners,
            closed_u,
            closed_v,
            repair: None,
        })
    }

    /// The largest correction of the data, when the surface was built with
    /// [`Compatibility::Repair`]; `None` when the data were checked.
    pub fn repair(&self) -> Option<&Repair> {
        self.repair.as_ref()
    }

    /// The blending family of `u` (functionals `L^u_i`, functions `H^u_i`).
    pub fn u_family(&self) -> &FamilyRef {
        &self.u_family
    }

    /// The blending family of `v`.
    pub fn v_family(&self) -> &FamilyRef {
        &self.v_family
    }

    /// The curves `f_i` (functions of `v`), over the `v` domain.
    pub fn v_curves(&self) -> &[CurveRef<D>] {
        &self.v_curves
    }

    /// The curves `g_j` (functions of `u`), over the `u` domain.
    pub fn u_curves(&self) -> &[CurveRef<D>] {
        &self.u_curves
    }

    /// `L^u_i(g_j)`, the values the correction term of (9) subtracts.
    pub fn corner(&self, i: usize, j: usize) -> Point<D> {
        self.corners[i * self.u_curves.len() + j]
    }

    #[inline]
    fn reduce_u(&self, u: f64) -> f64 {
        reduce(self.u_family.domain(), self.closed_u, u)
    }

    #[inline]
    fn reduce_v(&self, v: f64) -> f64 {
        reduce(self.v_family.domain(), self.closed_v, v)
    }

    /// The partial derivative `d^(ku+kv) c / du^ku dv^kv` on the tensor grid `us x vs`, into
    /// `out` (row-major, `u` outer), in
    /// `O(NU (m n) + NV (m + n) + NU NV (nnz_u + nnz_v))`: the blending weights of every
    /// sample line and the curve samples `f_i^(kv)(v_b)`, `g_j^(ku)(u_a)` are computed once
    /// (the curves' batch evaluation), and (9) is regrouped as
    /// `sum_i H^u_i f_i(v) + sum_j H^v_j(v) q_j(u)` with
    /// `q_j(u) = g_j(u) - sum_i H^u_i(u) L^u_i(g_j)` formed once per `u` line, so each point
    /// costs only the nonzero weights of its lines (8 for a composite Coons surface, `m + n`
    /// for a Gordon surface).
    ///
    /// # Panics
    /// When `out.len() != us.len() * vs.len()`.
    pub fn deriv_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        ku: usize,
        kv: usize,
        out: &mut [Point<D>],
    ) {
        crate::core::assert_grid_len(us.len(), vs.len(), out.len());
        let (m, n) = (self.v_curves.len(), self.u_curves.len());
        let (nu, nv) = (us.len(), vs.len());
        if nu == 0 || nv == 0 {
            return;
        }
        let vr: Vec<f64> = vs.iter().map(|&v| self.reduce_v(v)).collect();
        let ur: Vec<f64> = us.iter().map(|&u| self.reduce_u(u)).collect();
        let sample = |curve: &CurveRef<D>, ts: &[f64], k: usize, out: &mut [Point<D>]| {
            if k == 0 {
                curve.eval_into(ts, out);
            } else {
                curve.deriv_into(ts, k, out);
            }
        };

        // Per v sample: the v weights and the v-curve points.
        let mut weights_v = vec![0.0; nv * n];
        let ranges_v: Vec<_> = vr
            .iter()
            .zip(weights_v.chunks_exact_mut(n))
            .map(|(&v, w)| self.v_family.eval_into(v, kv, w))
            .collect();
        let mut column = vec![Point::ZERO; nv.max(nu)];
        let mut f_table = vec![Point::ZERO; nv * m];
        for (i, f) in self.v_curves.iter().enumerate() {
            sample(f, &vr, kv, &mut column[..nv]);
            for (b, p) in column[..nv].iter().enumerate() {
                f_table[b * m + i] = *p;
            }
        }
        // Per u sample: the u-curve points.
        let mut g_table = vec![Point::ZERO; nu * n];
        for (j, g) in self.u_curves.iter().enumerate() {
            sample(g, &ur, ku, &mut column[..nu]);
            for (a, p) in column[..nu].iter().enumerate() {
                g_table[a * n + j] = *p;
            }
        }

        let mut weights_u = vec![0.0; m];
        let mut q = vec![Point::ZERO; n];
        for (a, (&u, out_row)) in ur.iter().zip(out.chunks_exact_mut(nv)).enumerate() {
            let ru = self.u_family.eval_into(u, ku, &mut weights_u);
            for (j, qj) in q.iter_mut().enumerate() {
                let mut s = g_table[a * n + j];
                for i in ru.clone() {
                    s = s.add_scaled(-weights_u[i], self.corners[i * n + j]);
                }
                *qj = s;
            }
            for (b, p) in out_row.iter_mut().enumerate() {
                let f_row = &f_table[b * m..(b + 1) * m];
                let w_row = &weights_v[b * n..(b + 1) * n];
                let mut s = Point::ZERO;
                for i in ru.clone() {
                    s = s.add_scaled(weights_u[i], f_row[i]);
                }
                for j in ranges_v[b].clone() {
                    s = s.add_scaled(w_row[j], q[j]);
                }
                *p = s;
            }
        }
    }

    /// The partial derivative of (9) at one point: every term differentiated.
    fn derivative_at(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        let (u, v) = (self.reduce_u(u), self.reduce_v(v));
        let (m, n) = (self.v_curves.len(), self.u_curves.len());
        let mut hu = vec![0.0; m];
        let mut hv = vec![0.0; n];
        let ru = self.u_family.eval_into(u, ku, &mut hu);
        let rv = self.v_family.eval_into(v, kv, &mut hv);
        let mut sum = Point::ZERO;
        for i in ru.clone() {
            if hu[i] != 0.0 {
                sum = sum.add_scaled(hu[i], self.v_curves[i].deriv(v, kv));
            }
        }
        for j in rv {
            if hv[j] == 0.0 {
                continue;
            }
            let mut q = self.u_curves[j].deriv(u, ku);
            for i in ru.clone() {
                q = q.add_scaled(-hu[i], self.corners[i * n + j]);
            }
            sum = sum.add_scaled(hv[j], q);
        }
        sum
    }
}

/// Refuses empty blending families and counts of functionals or curves that differ from
/// the families' functions.
fn check_sizes(
    u_family: &FamilyRef,
    v_family: &FamilyRef,
    v_curves: usize,
    u_curves: usize,
) -> Result<()> {
    let (m, n) = (u_family.len(), v_family.len());
    for (direction, count) in [("u", m), ("v", n)] {
        if count == 0 {
            return Err(Error::EmptyBlendingFamily { direction });
        }
    }
    let counts = [
        (
            "functionals of the u-blending family (one per function)",
            m,
            u_family.functionals().len(),
        ),
        (
            "functionals of the v-blending family (one per function)",
            n,
            v_family.functionals().len(),
        ),
        ("v-curves (one per u-blending function)", m, v_curves),
        ("u-curves (one per v-blending function)", n, u_curves),
    ];
    Error::check_counts(&counts)
}

/// The tolerance of the compatibility check (0 when repairing), refused when not a finite
/// number `>= 0`.
fn check_tolerance(compatibility: Compatibility) -> Result<f64> {
    let tolerance = match compatibility {
        Compatibility::Check(t) => t,
        Compatibility::Repair => 0.0,
    };
    if !(tolerance.is_finite() && tolerance >= 0.0) {
        return Err(Error::InvalidSetting {
            name: "tolerance",
            value: tolerance,
            reason: "the compatibility tolerance must be a finite number >= 0",
        });
    }
    Ok(tolerance)
}

/// The compatibility conditions (8) of a network: condition `(i, j)` sets functional `i` of
/// the u-family on u-curve `j` against functional `j` of the v-family on v-curve `i`, its
/// mismatch measured against the model size over the smallest node spacings to the orders.
struct Conditions<'a, 'n> {
    lu: &'a [super::Functional],
    lv: &'a [super::Functional],
    size: f64,
    hu: f64,
    hv: f64,
    names: &'a Names<'n>,
}

impl Conditions<'_, '_> {
    /// The scale of condition `(i, j)`'s mismatch.
    fn scale(&self, i: usize, j: usize) -> f64 {
        self.size
            / self.hu.powi(self.lu[i].order() as i32)
            / self.hv.powi(self.lv[j].order() as i32)
    }

    /// Condition `(i, j)` in words.
    fn describe(&self, i: usize, j: usize) -> String {
        format!(
            "{} of {} and {} of {}",
            self.lu[i].describe('u'),
            (self.names.u_curve)(j),
            self.lv[j].describe('v'),
            (self.names.v_curve)(i)
        )
    }

    /// Refuses a mismatch beyond `tolerance` times the scale (and a NaN, from a non-finite
    /// curve), naming the curves and the condition.
    fn check<const D: usize>(
        &self,
        v_curves: &[CurveRef<D>],
        corners: &[Point<D>],
        tolerance: f64,
    ) -> Result<()> {
        let n = self.lv.len();
        for (i, (f, li)) in v_curves.iter().zip(self.lu).enumerate() {
            for (j, lj) in self.lv.iter().enumerate() {
                let mismatch = corners[i * n + j].distance(lj.apply(f.as_ref()));
                let allowed = tolerance * self.size
                    / self.hu.powi(li.order() as i32)
                    / self.hv.powi(lj.order() as i32);
                if mismatch.is_nan() || mismatch > allowed {
                    let (first, second) = ((self.names.v_curve)(i), (self.names.u_curve)(j));
                    return Err(Error::IncompatibleCurves {
                        condition: format!(
                            "{} of {second} and {} of {first}",
                            li.describe('u'),
                            lj.describe('v')
                        ),
                        first,
                        second,
                        u: li.at(),
                        v: lj.at(),
                        mismatch,
                        tolerance: allowed,
                    });
                }
            }
        }
        Ok(())
    }
}

/// The surface of curves repaired as [`Compatibility::Repair`] says, from the data
/// `corners[i n + j] = L^u_i(g_j)`; `scale(i, j)` turns a correction into the relative figure
/// of the check, `describe(i, j)` names the condition.
fn repaired<const D: usize>(
    (u_family, v_family): (FamilyRef, FamilyRef),
    (v_curves, u_curves): (Vec<CurveRef<D>>, Vec<CurveRef<D>>),
    mut corners: Vec<Point<D>>,
    (closed_u, closed_v): (bool, bool),
    scale: &dyn Fn(usize, usize) -> f64,
    describe: &dyn Fn(usize, usize) -> String,
) -> CoonsSurface<D> {
    let (m, n) = (v_curves.len(), u_curves.len());
    let (lu, lv) = (u_family.functionals(), v_family.functionals());
    // Corrections of f_i (over j) and of g_j (over i), both half the mismatch.
    let mut of_f = vec![Point::ZERO; m * n];
    let mut of_g = vec![Point::ZERO; m * n];
    let mut largest: Option<(f64, f64, usize, usize)> = None;
    for (i, f) in v_curves.iter().enumerate() {
        for (j, lj) in lv.iter().enumerate() {
            let from_g = corners[i * n + j];
            let from_f = lj.apply(f.as_ref());
            let mean = (from_g + from_f) * 0.5;
            of_f[i * n + j] = mean - from_f;
            of_g[i * n + j] = mean - from_g;
            corners[i * n + j] = mean;
            let correction = mean.distance(from_f).max(mean.distance(from_g));
            let relative = correction / scale(i, j);
            if largest.is_none_or(|(r, ..)| relative > r) {
                largest = Some((relative, correction, i, j));
            }
        }
    }
    let shifted = |curve: &CurveRef<D>, family: &FamilyRef, c: Vec<Point<D>>| -> CurveRef<D> {
        if c.iter().all(|p| *p == Point::ZERO) {
            curve.clone()
        } else {
            let closed = curve.is_closed();
            std::sync::Arc::new(BlendedCurve::new(
                Some(curve.clone()),
                family.clone(),
                c,
                closed,
            ))
        }
    };
    let v_curves = v_curves
        .iter()
        .enumerate()
        .map(|(i, f)| shifted(f, &v_family, of_f[i * n..(i + 1) * n].to_vec()))
        .collect();
    let u_curves = u_curves
        .iter()
        .enumerate()
        .map(|(j, g)| shifted(g, &u_family, (0..m).map(|i| of_g[i * n + j]).collect()))
        .collect();
    let repair = largest.map(|(relative, correction, i, j)| Repair {
        correction,
        relative,
        condition: describe(i, j),
        u: lu[i].at(),
        v: lv[j].at(),
    });
    CoonsSurface {
        u_family,
        v_family,
        v_curves,
        u_curves,
        corners,
        closed_u,
        closed_v,
        repair,
    }
}

/// The diagonal of the bounding box of the position curves (those a value functional is
/// applied across), sampled; at least the smallest positive number, so that a zero model still
/// has a usable scale.
fn model_size<const D: usize>(
    v_curves: &[CurveRef<D>],
    lu: &[super::Functional],
    dv: Interval,
    u_curves: &[CurveRef<D>],
    lv: &[super::Functional],
    du: Interval,
) -> f64 {
    let mut lo = [f64::INFINITY; D];
    let mut hi = [f64::NEG_INFINITY; D];
    let positions = v_curves
        .iter()
        .zip(lu)
        .map(|(c, l)| (c, l, dv))
        .chain(u_curves.iter().zip(lv).map(|(c, l)| (c, l, du)));
    for (curve, functional, domain) in positions {
        if functional.order() != 0 {
            continue;
        }
        for k in 0..SIZE_SAMPLES {
            let p = curve.eval(domain.uniform(k, SIZE_SAMPLES));
            for c in 0..D {
                lo[c] = lo[c].min(p[c]);
                hi[c] = hi[c].max(p[c]);
            }
        }
    }
    let diagonal = (0..D)
        .map(|c| (hi[c] - lo[c]).max(0.0).powi(2))
        .sum::<f64>()
        .sqrt();
    if diagonal > 0.0 {
        diagonal
    } else {
        f64::MIN_POSITIVE
    }
}

/// The smallest distance between distinct points the family's functionals look at (the
/// domain length when they all look at one point).
fn smallest_spacing(family: &dyn BlendingFamily) -> f64 {
    let mut points: Vec<f64> = family.functionals().iter().map(|l| l.at()).collect();
    points.sort_by(f64::total_cmp);
    points
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|&d| d > 0.0)
        .fold(family.domain().length(), f64::min)
}

impl<const D: usize> Surface<D> for CoonsSurface<D> {
    fn domain_u(&self) -> Interval {
        self.u_family.domain()
    }

    fn domain_v(&self) -> Interval {
        self.v_family.domain()
    }

    fn is_closed_u(&self) -> bool {
        self.closed_u
    }

    fn is_closed_v(&self) -> bool {
        self.closed_v
    }

    fn eval(&self, u: f64, v: f64) -> Point<D> {
        self.derivative_at(u, v, 0, 0)
    }

    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<D> {
        self.derivative_at(u, v, ku, kv)
    }

    fn eval_grid_into(&self, us: &[f64], vs: &[f64], out: &mut [Point<D>]) {
        self.deriv_grid_into(us, vs, 0, 0, out);
    }
}

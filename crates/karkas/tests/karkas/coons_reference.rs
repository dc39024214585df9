//! Shared helpers of the Coons tests: closed-form surfaces with exact partial derivatives of
//! every order, their parameter lines as curves (the independent source of network data and
//! of expected values), and comparisons.

use std::f64::consts::PI;
use std::sync::Arc;

use karkas::coons::{curve_ref, CurveNetwork, CurveRef, NetworkAxis};
use karkas::{Curve, Interval, Point3};

/// A function of one variable with exact derivatives of every order.
#[derive(Clone, Copy, Debug)]
pub enum F1 {
    /// `sin(a x + phase)`.
    Sin(f64, f64),
    /// `x^n`.
    Pow(u32),
    /// `1`.
    One,
}

impl F1 {
    pub fn deriv(self, x: f64, k: usize) -> f64 {
        match self {
            F1::Sin(a, phase) => a.powi(k as i32) * (a * x + phase + k as f64 * PI / 2.0).sin(),
            F1::Pow(n) => {
                if k as u32 > n {
                    0.0
                } else {
                    let falling: f64 = (0..k).map(|q| (n - q as u32) as f64).product();
                    falling * x.powi((n - k as u32) as i32)
                }
            }
            F1::One => {
                if k == 0 {
                    1.0
                } else {
                    0.0
                }
            }
        }
    }
}

/// `coefficient * fu(u) * fv(v)` added to coordinate `coord`.
#[derive(Clone, Copy, Debug)]
pub struct Term {
    pub coord: usize,
    pub coefficient: f64,
    pub fu: F1,
    pub fv: F1,
}

/// A surface given as a sum of separable terms: exact partials of every order.
#[derive(Clone, Debug)]
pub struct Analytic {
    pub terms: Vec<Term>,
}

impl Analytic {
    pub fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let mut p = Point3::ZERO;
        for t in &self.terms {
            p[t.coord] += t.coefficient * t.fu.deriv(u, ku) * t.fv.deriv(v, kv);
        }
        p
    }

    pub fn eval(&self, u: f64, v: f64) -> Point3 {
        self.deriv(u, v, 0, 0)
    }
}

fn term(coord: usize, coefficient: f64, fu: F1, fv: F1) -> Term {
    Term {
        coord,
        coefficient,
        fu,
        fv,
    }
}

/// A generic smooth sheet over about `[0, 3] x [0, 2]`: no polynomial in either variable, so
/// no blending family reproduces it exactly.
pub fn wavy_sheet() -> Analytic {
    use F1::*;
    Analytic {
        terms: vec![
            term(0, 1.0, Pow(1), One),
            term(0, 0.3, One, Sin(2.0, 0.1)),
            term(1, 1.0, One, Pow(1)),
            term(1, 0.2, Sin(1.5, 0.4), One),
            term(2, 0.5, Sin(1.0, 0.0), Sin(1.0, PI / 2.0)),
            term(2, 0.1, Pow(2), Pow(1)),
            term(2, 0.15, Sin(2.3, 0.2), Sin(1.7, 0.5)),
        ],
    }
}

/// A surface that is a cubic polynomial in `u` (any function of `v`).
pub fn cubic_in_u() -> Analytic {
    use F1::*;
    Analytic {
        terms: vec![
            term(0, 1.0, Pow(1), One),
            term(1, 1.0, One, Pow(1)),
            term(1, 0.3, Pow(3), Sin(1.2, 0.3)),
            term(2, 0.4, Pow(2), Sin(2.0, 0.0)),
            term(2, -0.2, Pow(3), One),
            term(0, 0.1, Pow(2), Pow(2)),
        ],
    }
}

/// A torus-like tube, periodic in both variables with period `2 pi`.
pub fn torus() -> Analytic {
    use F1::*;
    // (R + r cos v) cos u, (R + r cos v) sin u, r sin v + wobble.
    Analytic {
        terms: vec![
            term(0, 3.0, Sin(1.0, PI / 2.0), One),
            term(0, 1.0, Sin(1.0, PI / 2.0), Sin(1.0, PI / 2.0)),
            term(1, 3.0, Sin(1.0, 0.0), One),
            term(1, 1.0, Sin(1.0, 0.0), Sin(1.0, PI / 2.0)),
            term(2, 1.0, One, Sin(1.0, 0.0)),
            term(2, 0.3, Sin(2.0, 0.0), Sin(1.0, 0.5)),
        ],
    }
}

/// A tube, open in `u` (along) and periodic in `v` (around, period `2 pi`).
pub fn tube() -> Analytic {
    use F1::*;
    Analytic {
        terms: vec![
            term(0, 1.0, Pow(1), One),
            term(1, 1.0, One, Sin(1.0, PI / 2.0)),
            term(1, 0.3, Sin(0.8, 0.0), Sin(1.0, PI / 2.0)),
            term(2, 0.7, One, Sin(1.0, 0.0)),
            term(2, 0.2, Sin(1.3, 0.2), Sin(2.0, 0.3)),
        ],
    }
}

/// Which way a parameter line of an [`Analytic`] surface runs.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Dir {
    /// A function of `v` at `u = at` (a v-curve).
    V,
    /// A function of `u` at `v = at` (a u-curve).
    U,
}

/// A parameter line of a surface, or its derivative of order `across` across the line.
pub struct Iso {
    pub surface: Arc<Analytic>,
    pub dir: Dir,
    pub at: f64,
    pub across: usize,
    pub domain: Interval,
    pub closed: bool,
}

impl Curve<3> for Iso {
    fn domain(&self) -> Interval {
        self.domain
    }
    fn is_closed(&self) -> bool {
        self.closed
    }
    fn eval(&self, t: f64) -> Point3 {
        self.deriv(t, 0)
    }
    fn deriv(&self, t: f64, k: usize) -> Point3 {
        match self.dir {
            Dir::V => self.surface.deriv(self.at, t, self.across, k),
            Dir::U => self.surface.deriv(t, self.at, k, self.across),
        }
    }
}

/// The line (or cross-derivative of order `across`) of `s` as a curve over `domain`.
pub fn iso(
    s: &Arc<Analytic>,
    dir: Dir,
    at: f64,
    across: usize,
    domain: Interval,
    closed: bool,
) -> CurveRef<3> {
    curve_ref(Iso {
        surface: s.clone(),
        dir,
        at,
        across,
        domain,
        closed,
    })
}

/// The network of `s` on the given axes: v-curves at the `u` nodes, u-curves at the `v`
/// nodes, each curve over the network domain (closed where the axis is).
pub fn network(s: &Arc<Analytic>, u_axis: &NetworkAxis, v_axis: &NetworkAxis) -> CurveNetwork<3> {
    let (du, dv) = (u_axis.domain(), v_axis.domain());
    let v_curves = u_axis
        .nodes()
        .iter()
        .map(|&u| iso(s, Dir::V, u, 0, dv, v_axis.is_closed()))
        .collect();
    let u_curves = v_axis
        .nodes()
        .iter()
        .map(|&v| iso(s, Dir::U, v, 0, du, u_axis.is_closed()))
        .collect();
    CurveNetwork::new(u_axis.clone(), v_curves, v_axis.clone(), u_curves).unwrap()
}

/// The exact cross-derivatives of `s` along the network's curves.
pub fn exact_cross(
    s: &Arc<Analytic>,
    u_axis: &NetworkAxis,
    v_axis: &NetworkAxis,
) -> karkas::coons::CrossDerivatives<3> {
    let (du, dv) = (u_axis.domain(), v_axis.domain());
    karkas::coons::CrossDerivatives {
        v_curves: u_axis
            .nodes()
            .iter()
            .map(|&u| iso(s, Dir::V, u, 1, dv, v_axis.is_closed()))
            .collect(),
        u_curves: v_axis
            .nodes()
            .iter()
            .map(|&v| iso(s, Dir::U, v, 1, du, u_axis.is_closed()))
            .collect(),
    }
}

/// Asserts `|a - b| <= tol` (Euclidean), with a message.
#[track_caller]
pub fn assert_close(a: Point3, b: Point3, tol: f64, what: &str) {
    let d = a.distance(b);
    assert!(
        d <= tol,
        "{what}: {a:?} vs {b:?} (distance {d:e} > {tol:e})"
    );
}

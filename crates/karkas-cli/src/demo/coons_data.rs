//! The reference bodies of Chashnikov's examples and their curve networks: the paper prints
//! only pictures, so the data are made here from closed-form surfaces, which also give the
//! exact body every surface is measured against.

use karkas::coons::{curve_ref, Along, CurveRef};
use karkas::{Curve, Interval, Point3};
use std::f64::consts::{PI, TAU};

/// A smooth closed-form surface `(u, v) -> S(u, v)` over a parameter rectangle.
#[derive(Clone, Copy, Debug)]
pub struct Body {
    /// The surface.
    pub shape: fn(f64, f64) -> Point3,
    /// The interval of `u`.
    pub u: Interval,
    /// The interval of `v`.
    pub v: Interval,
    /// True when `S` is periodic in `v` over `v`.
    pub closed_v: bool,
}

/// Step of the central differences of [`Body::deriv`] (the bodies vary on unit scales).
const STEP: f64 = 1e-4;

impl Body {
    /// The point at `(u, v)`.
    pub fn eval(&self, u: f64, v: f64) -> Point3 {
        (self.shape)(u, v)
    }

    /// `d^(ku+kv) S / du^ku dv^kv` for `ku, kv <= 1` by central differences (error about
    /// `1e-8`); zero otherwise (not needed by the examples).
    pub fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        let h = STEP;
        match (ku, kv) {
            (0, 0) => self.eval(u, v),
            (1, 0) => (self.eval(u + h, v) - self.eval(u - h, v)) * (0.5 / h),
            (0, 1) => (self.eval(u, v + h) - self.eval(u, v - h)) * (0.5 / h),
            (1, 1) => {
                (self.eval(u + h, v + h) - self.eval(u + h, v - h) - self.eval(u - h, v + h)
                    + self.eval(u - h, v - h))
                    * (0.25 / (h * h))
            }
            _ => Point3::ZERO,
        }
    }
}

/// A parameter line of a body (`across = 0`) or the first derivative across it (`across = 1`).
struct BodyLine {
    body: Body,
    along: Along,
    at: f64,
    across: usize,
}

impl Curve<3> for BodyLine {
    fn domain(&self) -> Interval {
        match self.along {
            Along::U => self.body.u,
            Along::V => self.body.v,
        }
    }

    fn is_closed(&self) -> bool {
        self.along == Along::V && self.body.closed_v
    }

    fn eval(&self, t: f64) -> Point3 {
        self.deriv(t, 0)
    }

    fn deriv(&self, t: f64, k: usize) -> Point3 {
        match self.along {
            Along::U => self.body.deriv(t, self.at, k, self.across),
            Along::V => self.body.deriv(self.at, t, self.across, k),
        }
    }
}

/// The line of `body` along `along` at `at`, or its cross-derivative when `across == 1`.
pub fn body_line(body: Body, along: Along, at: f64, across: usize) -> CurveRef<3> {
    curve_ref(BodyLine {
        body,
        along,
        at,
        across,
    })
}

/// The sheet of the paper's figure 3 over `[0, 2] x [0, 2]` (nodes at the integers, m = n = 2):
/// a doubly curved bump, sheared in the plane, so that no blending family reproduces it.
pub fn figure_3_sheet() -> Body {
    fn shape(u: f64, v: f64) -> Point3 {
        let bump = (PI * u / 2.0).sin() * (PI * v / 2.0).sin();
        Point3::new([
            3.0 * u + 0.35 * (PI * v / 2.0).sin(),
            3.0 * v - 0.3 * (PI * u / 2.0).sin(),
            1.5 * bump + 0.25 * (u - 1.0) * (v - 1.0) * (u + 1.0),
        ])
    }
    Body {
        shape,
        u: Interval::new(0.0, 2.0),
        v: Interval::new(0.0, 2.0),
        closed_v: false,
    }
}

/// `(1 + tanh x) / 2`: a smooth step.
fn smooth_step(x: f64) -> f64 {
    0.5 * (1.0 + x.tanh())
}

/// A fuselage-like body: `u = x` along the axis in `[0, 12]`, `v` the angle around in
/// `[0, 2 pi)` starting at the keel. A blunt nose that swells fast, a long middle, a tail that
/// tapers and sweeps up; slightly taller than wide.
pub fn fuselage() -> Body {
    fn shape(x: f64, v: f64) -> Point3 {
        let radius =
            0.25 + 0.95 * (1.0 - (-x / 1.6).exp()) * (1.0 - 0.6 * smooth_step((x - 8.5) / 1.2));
        let centre = 0.45 * smooth_step((x - 9.0) / 1.3);
        let angle = v - PI / 2.0;
        Point3::new([x, radius * angle.cos(), centre + 1.1 * radius * angle.sin()])
    }
    Body {
        shape,
        u: Interval::new(0.0, 12.0),
        v: Interval::new(0.0, TAU),
        closed_v: true,
    }
}

/// The stations of the seven fuselage frames: closer together at the nose, where the body
/// swells.
pub const FUSELAGE_STATIONS: [f64; 7] = [0.0, 0.8, 2.0, 4.0, 7.0, 9.5, 12.0];

/// The number of fuselage stringers, evenly spaced around.
pub const FUSELAGE_STRINGERS: usize = 5;

/// The fuselage network as point lists, as `karkas surface coons` reads them: 7 closed
/// frames of 40 points (plus the repeated first), the stringers crossing at every 8th point;
/// 5 stringers with 8 points per span between frames (49 points), the frames at every 8th.
/// Returns `(frames, stringers)`: the v-curves and the u-curves.
pub fn fuselage_point_lists() -> (Vec<Vec<Point3>>, Vec<Vec<Point3>>) {
    let body = fuselage();
    let per_frame = 8 * FUSELAGE_STRINGERS;
    let frames = FUSELAGE_STATIONS
        .iter()
        .map(|&x| {
            (0..=per_frame)
                .map(|k| body.eval(x, TAU * (k % per_frame) as f64 / per_frame as f64))
                .collect()
        })
        .collect();
    let stringer_x: Vec<f64> = std::iter::once(FUSELAGE_STATIONS[0])
        .chain(
            FUSELAGE_STATIONS
                .windows(2)
                .flat_map(|w| (1..=8).map(move |k| w[0] + (w[1] - w[0]) * k as f64 / 8.0)),
        )
        .collect();
    let stringers = (0..FUSELAGE_STRINGERS)
        .map(|j| {
            let v = TAU * j as f64 / FUSELAGE_STRINGERS as f64;
            stringer_x.iter().map(|&x| body.eval(x, v)).collect()
        })
        .collect();
    (frames, stringers)
}

/// A curve family as CSV text with header `curve,x,y,z`.
pub fn curve_family_csv(curves: &[Vec<Point3>]) -> String {
    let mut s = String::from("curve,x,y,z\n");
    for (k, curve) in curves.iter().enumerate() {
        for p in curve {
            s.push_str(&format!("{k},{},{},{}\n", p[0], p[1], p[2]));
        }
    }
    s
}

//! LL curves and surfaces (approximating and interpolating, open and closed) from arbitrary
//! floats and orders: an error, or a result whose values and derivatives are finite anywhere,
//! in the domain or outside it (clamped or wrapped), never a panic.
#![no_main]

use karkas::ll::{LlCurve, LlSurface};
use karkas::{Curve, Surface};
use karkas_fuzz::{assert_finite, Input};
use libfuzzer_sys::fuzz_target;

/// Results are promised finite for coordinates up to this size.
const RANGE: f64 = 1e150;

fuzz_target!(|data: &[u8]| {
    let mut input = Input::new(data);
    let order = input.count(0, 66);
    let closed = input.flag();
    let interpolate = input.flag();
    if input.flag() {
        let n = input.count(0, 40);
        let pts = input.points::<2>(n);
        let in_range = pts.iter().all(|p| p.max_abs() <= RANGE);
        let curve = if interpolate {
            LlCurve::interpolating(&pts, order, closed)
        } else {
            LlCurve::new(&pts, order, closed)
        };
        if let Ok(c) = curve {
            for _ in 0..4 {
                let t = input.float();
                let k = input.count(0, 3);
                let (p, d) = (c.eval(t), c.deriv(t, k));
                if in_range && t.is_finite() {
                    assert_finite("LlCurve::eval", p);
                    if k <= order.min(2) {
                        assert_finite("LlCurve::deriv", d);
                    }
                }
            }
        }
    } else {
        let (rows, cols) = (input.count(0, 7), input.count(0, 7));
        let grid = input.grid::<3>(rows, cols);
        let in_range = grid.as_slice().iter().all(|p| p.max_abs() <= RANGE);
        let closed_v = input.flag();
        let surface = if interpolate {
            LlSurface::interpolating(&grid, order, closed, closed_v)
        } else {
            LlSurface::new(&grid, order, closed, closed_v)
        };
        if let Ok(s) = surface {
            for _ in 0..3 {
                let (u, v) = (input.float(), input.float());
                let p = s.eval(u, v);
                let d = s.deriv(u, v, 1, 0);
                if in_range && u.is_finite() && v.is_finite() {
                    assert_finite("LlSurface::eval", p);
                    assert_finite("LlSurface::deriv", d);
                }
            }
        }
    }
});

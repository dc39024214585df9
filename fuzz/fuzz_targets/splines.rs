//! Cubic splines on given knots, bicubic surfaces (every parameterization, open and closed),
//! discrete periodic splines and tubes from arbitrary floats and counts: an error or finite
//! values, never a panic.
#![no_main]

use karkas::dps::{DiscreteSpline, TubeSurface};
use karkas::param::{BicubicSurface, CubicSpline, GridParameterization, SplineEnds};
use karkas::{Curve, Surface};
use karkas_fuzz::{assert_finite, Input};
use libfuzzer_sys::fuzz_target;

/// Results are promised finite for coordinates up to this size.
const RANGE: f64 = 1e150;

fuzz_target!(|data: &[u8]| {
    let mut input = Input::new(data);
    match input.byte() % 4 {
        0 => {
            let n = input.count(0, 24);
            let knots = input.floats(n);
            let values = input.points::<2>(n);
            let ends = match input.byte() % 4 {
                0 => SplineEnds::NotAKnot,
                1 => SplineEnds::Natural,
                2 => SplineEnds::Periodic,
                _ => SplineEnds::Clamped {
                    start: input.point(),
                    end: input.point(),
                },
            };
            let end_slopes_in_range = match ends {
                SplineEnds::Clamped { start, end } => start.max_abs().max(end.max_abs()) <= RANGE,
                _ => true,
            };
            let in_range = end_slopes_in_range
                && values.iter().all(|p| p.max_abs() <= RANGE)
                && knots.iter().all(|t| t.abs() <= RANGE);
            if let Ok(s) = CubicSpline::new(&knots, &values, ends) {
                let t = input.float();
                let p = s.eval(t);
                if in_range && t.is_finite() && t.abs() <= RANGE {
                    let d = s.domain();
                    if d.clamp(t) == t {
                        assert_finite("CubicSpline::eval", p);
                    }
                }
            }
        }
        1 => {
            let (rows, cols) = (input.count(0, 6), input.count(0, 6));
            let grid = input.grid::<3>(rows, cols);
            let param = match input.byte() % 5 {
                0 => GridParameterization::Uniform,
                1 => GridParameterization::Chord {
                    origin_row: input.count(0, 6),
                    origin_col: input.count(0, 6),
                },
                2 => GridParameterization::AveragedChord,
                3 => GridParameterization::Centripetal,
                _ => GridParameterization::Uniform,
            };
            let (cu, cv) = (input.flag(), input.flag());
            let in_range = grid.as_slice().iter().all(|p| p.max_abs() <= RANGE);
            let surface = if input.flag() {
                let ku = input.floats(rows);
                let kv = input.floats(cols);
                BicubicSurface::from_knots(&grid, &ku, &kv, cu, cv)
            } else {
                BicubicSurface::new(&grid, param, cu, cv)
            };
            if let Ok(s) = surface {
                let (du, dv) = (s.domain_u(), s.domain_v());
                let (u, v) = (du.uniform(1, 3), dv.uniform(2, 3));
                let p = s.eval(u, v);
                if in_range
                    && s.knots_u()
                        .iter()
                        .chain(s.knots_v())
                        .all(|t| t.abs() <= RANGE)
                {
                    assert_finite("BicubicSurface::eval", p);
                }
            }
        }
        2 => {
            let m = input.count(0, 12);
            let pts = input.points::<3>(m);
            let (order, n) = (input.count(0, 66), input.count(0, 9));
            let spline = if input.flag() {
                DiscreteSpline::from_poles(&pts, order, n)
            } else {
                DiscreteSpline::interpolating(&pts, order, n)
            };
            if let Ok(s) = spline {
                let values = s.to_values();
                if pts.iter().all(|p| p.max_abs() <= RANGE) {
                    values
                        .iter()
                        .for_each(|&p| assert_finite("DiscreteSpline", p));
                }
            }
        }
        _ => {
            let (m1, m2, n1, n2) = (
                input.count(0, 4),
                input.count(0, 4),
                input.count(0, 4),
                input.count(0, 4),
            );
            let along = input.grid::<3>(m1, m2 * n2);
            let across = input.grid::<3>(m2, m1 * n1);
            let (r1, r2) = (input.count(0, 66), input.count(0, 66));
            if let Ok(t) = TubeSurface::new(&along, &across, n1, n2, r1, r2) {
                let finite_in = along
                    .as_slice()
                    .iter()
                    .chain(across.as_slice())
                    .all(|p| p.max_abs() <= RANGE);
                if finite_in {
                    t.values()
                        .as_slice()
                        .iter()
                        .for_each(|&p| assert_finite("TubeSurface", p));
                }
            }
        }
    }
});

//! Coons, Gordon and composite surfaces through point networks, and the defect-2 fit with
//! given or adaptive knots, from arbitrary floats: an error or finite values, never a panic
//! or a hang.
#![no_main]

use karkas::coons::{CoonsSurface, CurveFit, PointNetwork, SplineEnds};
use karkas::fit::{fit_curve, fit_curve_adaptive, FitOptions};
use karkas::{Curve, Point, Surface};
use karkas_fuzz::{assert_finite, Input};
use libfuzzer_sys::fuzz_target;

/// Results are promised finite for coordinates up to this size.
const RANGE: f64 = 1e150;

fuzz_target!(|data: &[u8]| {
    let mut input = Input::new(data);
    if input.flag() {
        let family = |input: &mut Input| -> Vec<Vec<Point<3>>> {
            let curves = input.count(0, 4);
            (0..curves)
                .map(|_| {
                    let n = input.count(0, 6);
                    input.points(n)
                })
                .collect()
        };
        let v = family(&mut input);
        let u = family(&mut input);
        let fit = if input.flag() {
            CurveFit::CubicSpline
        } else {
            CurveFit::Ll(input.count(0, 66))
        };
        let Ok(network) = PointNetwork::new(&v, &u, fit, 1e-6) else {
            return;
        };
        let net = network.network();
        let surface = match input.byte() % 5 {
            0 => CoonsSurface::bilinear(net, 1e-4),
            1 => CoonsSurface::bicubic(net, None, 1e-4),
            2 => CoonsSurface::gordon(net, 1e-4),
            3 => CoonsSurface::gordon_spline(net, SplineEnds::NotAKnot, 1e-4),
            _ => CoonsSurface::composite(net, None, 1e-4),
        };
        if let Ok(s) = surface {
            let (du, dv) = (s.domain_u(), s.domain_v());
            let p = s.eval(du.uniform(1, 4), dv.uniform(2, 4));
            if u.iter().chain(&v).flatten().all(|p| p.max_abs() <= RANGE) {
                assert_finite("CoonsSurface::eval", p);
            }
        }
    } else {
        let n = input.count(0, 40);
        let points = input.points::<2>(n);
        let mut options = FitOptions::default();
        if input.flag() {
            options.eps = input.float();
        }
        options.ends = [
            karkas::fit::FitEnds::Auto,
            karkas::fit::FitEnds::Shared,
            karkas::fit::FitEnds::Pinned,
            karkas::fit::FitEnds::Free,
        ][input.count(0, 3)];
        options.max_iterations = 20;
        let in_range = points.iter().all(|p| p.max_abs() <= RANGE);
        let spline = if input.flag() {
            let k = input.count(0, 6);
            let knots = input.floats(k);
            fit_curve(&points, &knots, &options).map(|f| f.spline)
        } else {
            let tolerance = input.float();
            fit_curve_adaptive(&points, tolerance, &options).map(|f| f.fit.spline)
        };
        if let Ok(s) = spline {
            let t = s.domain().uniform(1, 3);
            if in_range {
                assert_finite("fit spline", s.eval(t));
            }
        }
    }
});

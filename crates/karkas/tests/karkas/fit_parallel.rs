//! Fits large enough for the parallel projection and assembly (at least 2^15 points): the
//! result does not depend on the number of threads (bitwise), and it is still a fit whose
//! foot points are local minimizers of the distance.

use crate::fit_reference::noisy_spiral;
use karkas::fit::{fit_curve, uniform_knots, CurveFit, FitOptions};
use karkas::{Curve, Point2};

fn fit_on(threads: usize, points: &[Point2], options: &FitOptions) -> CurveFit<2> {
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .build()
        .expect("a thread pool");
    pool.install(|| fit_curve(points, &uniform_knots(120), options).expect("a fit"))
}

fn same_fit(a: &CurveFit<2>, b: &CurveFit<2>) -> bool {
    let bits = |p: &[Point2]| -> Vec<u64> {
        p.iter()
            .flat_map(|q| q.0.iter().map(|c| c.to_bits()))
            .collect()
    };
    let scalar_bits = |v: &[f64]| -> Vec<u64> { v.iter().map(|x| x.to_bits()).collect() };
    bits(a.spline.values()) == bits(b.spline.values())
        && bits(a.spline.derivatives()) == bits(b.spline.derivatives())
        && scalar_bits(&a.parameters) == scalar_bits(&b.parameters)
        && scalar_bits(&a.distances) == scalar_bits(&b.distances)
        && a.iterations == b.iterations
}

#[test]
fn large_fits_do_not_depend_on_the_thread_count() {
    let points = noisy_spiral(40_000, 1e-3, 11);
    // A bound a tenth of the unconstrained fit's jumps: the constrained path runs.
    let free = fit_on(1, &points, &FitOptions::default());
    for options in [
        FitOptions::default(),
        FitOptions {
            eps: 0.1 * free.jump_sum,
            ..FitOptions::default()
        },
    ] {
        let one = fit_on(1, &points, &options);
        let two = fit_on(2, &points, &options);
        let three = fit_on(3, &points, &options);
        assert!(
            same_fit(&one, &two),
            "1 and 2 threads differ (eps {})",
            options.eps
        );
        assert!(
            same_fit(&one, &three),
            "1 and 3 threads differ (eps {})",
            options.eps
        );
        assert!(one.jump_sum <= options.eps * (1.0 + 1e-3));
        if options.eps.is_finite() {
            // The constrained path (penalty search) ran.
            assert!(one.penalty > 0.0, "{}", one.penalty);
        }
        // Every inner foot point outside a pooled run (points out of order sharing one
        // parameter) is a local minimizer: the residual is orthogonal to the tangent, and no
        // sampled parameter nearby is nearer.
        let curve = &one.spline;
        let ts = &one.parameters;
        assert!(ts.windows(2).all(|p| p[0] <= p[1]));
        for i in (1..points.len() - 1).step_by(97) {
            let t = ts[i];
            if ts[i - 1] == t || ts[i + 1] == t {
                continue;
            }
            let e = curve.eval(t) - points[i];
            let d1 = curve.deriv(t, 1);
            if t > 0.0 && t < 1.0 {
                let cosine = e.dot(d1) / (e.norm().max(1e-300) * d1.norm());
                assert!(cosine.abs() < 1e-7, "point {i}: cos {cosine:e}");
            }
            for k in -20..=20 {
                let s = (t + k as f64 * 1e-4).clamp(0.0, 1.0);
                assert!(curve.eval(s).distance(points[i]) >= one.distances[i] - 1e-13);
            }
        }
    }
}

//! Adaptive Gauss–Legendre quadrature of a smooth function of one variable.

/// The positive nodes of the 8-point Gauss–Legendre rule on `[-1, 1]`.
const NODES: [f64; 4] = [
    0.183_434_642_495_649_8,
    0.525_532_409_916_329,
    0.796_666_477_413_626_7,
    0.960_289_856_497_536_3,
];
/// Their weights.
const WEIGHTS: [f64; 4] = [
    0.362_683_783_378_362,
    0.313_706_645_877_887_3,
    0.222_381_034_453_374_5,
    0.101_228_536_290_376_3,
];

/// The deepest bisection (an interval `2^-48` of the original is below any useful accuracy).
const MAX_DEPTH: usize = 48;

/// The nodes and weights of the 8-point Gauss–Legendre rule on `[a, b]` (exact for
/// polynomials of degree 15), for integrals over several variables.
pub(crate) fn gauss8_rule(a: f64, b: f64) -> [(f64, f64); 8] {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    core::array::from_fn(|k| {
        let (x, w) = (NODES[k % 4], WEIGHTS[k % 4]);
        let sign = if k < 4 { -1.0 } else { 1.0 };
        (mid + sign * half * x, w * half)
    })
}

/// The 8-point Gauss–Legendre rule on `[a, b]` (exact for polynomials of degree 15).
fn gauss8(f: &impl Fn(f64) -> f64, a: f64, b: f64) -> f64 {
    let (mid, half) = (0.5 * (a + b), 0.5 * (b - a));
    let sum: f64 = NODES
        .iter()
        .zip(WEIGHTS)
        .map(|(&x, w)| w * (f(mid - half * x) + f(mid + half * x)))
        .sum();
    sum * half
}

/// `∫_a^b f` to about `tolerance` (absolute): the 8-point rule on `[a, b]` is compared with
/// its sum over the two halves; the halves' sum is accepted when they agree to `tolerance`
/// (or to rounding: a tolerance of 0 asks for full precision), otherwise each half is refined
/// with half the tolerance. The difference overestimates the error of the accepted sum for
/// smooth `f` (its error is `2^-16` times smaller). At most [`MAX_REFINEMENTS`] intervals are
/// refined, so that a tolerance below what rounding allows cannot make the work unbounded.
pub(crate) fn integrate(f: &impl Fn(f64) -> f64, a: f64, b: f64, tolerance: f64) -> f64 {
    let whole = gauss8(f, a, b);
    let mut budget = MAX_REFINEMENTS;
    refine(f, a, b, whole, tolerance.max(0.0), 0, &mut budget)
}

/// The most intervals one integration refines (each costs two 8-point rules).
const MAX_REFINEMENTS: usize = 1 << 14;

fn refine(
    f: &impl Fn(f64) -> f64,
    a: f64,
    b: f64,
    whole: f64,
    tolerance: f64,
    depth: usize,
    budget: &mut usize,
) -> f64 {
    let mid = 0.5 * (a + b);
    let (left, right) = (gauss8(f, a, mid), gauss8(f, mid, b));
    let halves = left + right;
    let error = (halves - whole).abs();
    let rounding = 16.0 * f64::EPSILON * (left.abs() + right.abs());
    if !error.is_finite()
        || error <= tolerance.max(rounding)
        || depth >= MAX_DEPTH
        || *budget == 0
        || mid <= a
        || mid >= b
    {
        return halves;
    }
    *budget -= 1;
    refine(f, a, mid, left, 0.5 * tolerance, depth + 1, budget)
        + refine(f, mid, b, right, 0.5 * tolerance, depth + 1, budget)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polynomials_up_to_degree_15_are_exact() {
        let f = |x: f64| x.powi(15) + 3.0 * x.powi(4);
        let exact = (2f64.powi(16) - 1.0) / 16.0 + 3.0 * (32.0 - 1.0) / 5.0;
        assert!((integrate(&f, 1.0, 2.0, 1e-14) - exact).abs() < 1e-11);
    }

    #[test]
    fn a_kink_is_resolved_to_the_tolerance() {
        let f = |x: f64| (x - 0.3).abs();
        let exact = 0.5 * (0.3f64 * 0.3 + 0.7 * 0.7);
        assert!((integrate(&f, 0.0, 1.0, 1e-10) - exact).abs() < 1e-10);
    }

    #[test]
    fn a_zero_tolerance_stops_at_rounding() {
        // Full precision asked: the refinement stops where rounding dominates (a kink never
        // agrees to 0 exactly) instead of bisecting 2^48 times.
        let f = |x: f64| (x - 0.3).abs();
        let exact = 0.5 * (0.3f64 * 0.3 + 0.7 * 0.7);
        assert!((integrate(&f, 0.0, 1.0, 0.0) - exact).abs() < 1e-12);
        let g = |x: f64| x.exp();
        assert!((integrate(&g, 0.0, 1.0, 0.0) - (1f64.exp() - 1.0)).abs() < 1e-15);
    }
}

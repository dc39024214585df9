//! 1-D cubic splines against SciPy's `CubicSpline` (an independent implementation), to 1e-12.
//!
//! Reference values were produced by SciPy 1.x with
//! `x = [0.0, 0.5, 1.3, 2.0, 3.1, 4.0, 5.2]`, `y = [1.0, -0.4, 0.8, 2.2, 1.1, -0.7, 0.3]`,
//! `q = [0.0, 0.2, 0.5, 0.9, 1.7, 2.5, 3.6, 4.4, 5.0, 5.2]` and, for each table,
//! `[list(CubicSpline(x, y, bc_type=BC)(q, k)) for k in range(3)]` with BC as named on it
//! (periodic: `y[-1] = 1.0`; `nak3` / `nak4`: the first 3 / 4 points only, evaluated at the
//! same `q`, so mostly extrapolated).

use karkas::param::{CubicSpline, CurveParameterization, SplineEnds};
use karkas::{Curve, Error, PiecewiseCurve, Point, Point2, Point3, Side};
use proptest::prelude::*;

const X: [f64; 7] = [0.0, 0.5, 1.3, 2.0, 3.1, 4.0, 5.2];
const Y: [f64; 7] = [1.0, -0.4, 0.8, 2.2, 1.1, -0.7, 0.3];
const Q: [f64; 10] = [0.0, 0.2, 0.5, 0.9, 1.7, 2.5, 3.6, 4.4, 5.0, 5.2];

/// `CubicSpline(x, y, bc_type='not-a-knot')(q, k)`, k = 0, 1, 2.
const NOT_A_KNOT: [&[f64]; 3] = NAK;
/// `CubicSpline(x, y, bc_type='natural')(q, k)`.
const NATURAL_REF: [&[f64]; 3] = NATURAL;
/// `CubicSpline(x, y, bc_type=((1, 0.5), (1, -1.0)))(q, k)`.
const CLAMPED_REF: [&[f64]; 3] = CLAMPED;
/// `CubicSpline(x, y[:-1] + [1.0], bc_type='periodic')(q, k)`.
const PERIODIC_REF: [&[f64]; 3] = PERIODIC;
/// `CubicSpline(x[:3], y[:3], bc_type='not-a-knot')(q, k)` (the parabola).
const NAK3_REF: [&[f64]; 3] = NAK3;
/// `CubicSpline(x[:4], y[:4], bc_type='not-a-knot')(q, k)`.
const NAK4_REF: [&[f64]; 3] = NAK4;

const NAK: [&[f64]; 3] = [
    &[
        1.0,
        0.13929667250504407,
        -0.4,
        -0.10615777497604019,
        1.7478817976662124,
        2.122837521399352,
        0.011899826873098124,
        -1.034676124141377,
        -0.3523254888562489,
        0.2999999999999998,
    ],
    &[
        -5.460772864023751,
        -3.208225131552122,
        -0.5265066398907096,
        1.7478588825052541,
        2.017153472832867,
        -1.0452027428583115,
        -2.0695380988830294,
        -0.18341958522442142,
        2.66238043664518,
        3.8835920890066005,
    ],
    &[
        12.192209471752847,
        10.333267852963434,
        7.544855424779315,
        3.826972187200503,
        -2.6986771348058314,
        -2.9430158648788516,
        0.9945899167154979,
        3.7207063674310197,
        5.765293705467657,
        6.446822818146538,
    ],
];
const NATURAL: [&[f64]; 3] = [
    &[
        1.0,
        0.2982756192419434,
        -0.4,
        -0.17891469512677896,
        1.7599021506166526,
        2.137183572738196,
        -0.06418674843430569,
        -0.7499526351967484,
        -0.03435427789857748,
        0.30000000000000027,
    ],
    &[
        -3.643597504512241,
        -3.2386707023463654,
        -1.1128049909755167,
        1.859115757670811,
        1.976642744235827,
        -1.0025897329483264,
        -2.1232989074459527,
        0.5458688569357728,
        1.623860643426628,
        1.6957267625260188,
    ],
    &[
        -1.7763568394002505e-15,
        4.049268021658759,
        10.123170054146897,
        4.73643368908474,
        -2.848193404304822,
        -3.0134355452731216,
        1.8472597660061618,
        2.8746447639756147,
        0.7186611909939042,
        0.0,
    ],
];
const CLAMPED: [&[f64]; 3] = [
    &[
        1.0,
        0.6608706536275452,
        -0.4,
        -0.34591260935579116,
        1.7912070876743964,
        2.1458287965603353,
        -0.15628400256791802,
        -0.3997629432764065,
        0.3573287067797284,
        0.30000000000000027,
    ],
    &[
        0.5,
        -3.307528975816366,
        -2.4514719505738567,
        2.110954451897449,
        1.8868267038927327,
        -0.9436427646960197,
        -2.192536942705623,
        1.4444444444444449,
        0.3451527500935594,
        -1.0,
    ],
    &[
        -27.79411219770457,
        -10.281177560459085,
        15.98822439540914,
        6.823907616947389,
        -3.263728033942264,
        -3.0336935527685425,
        2.8835189696687613,
        1.8380553709940894,
        -5.502361018830376,
        -7.949166482105204,
    ],
];
const PERIODIC: [&[f64]; 3] = [
    &[
        1.0,
        0.46085259097182724,
        -0.4,
        -0.25194117397965266,
        1.7671219574083452,
        2.183254358483608,
        -0.24821350739982245,
        -0.042622526602632355,
        1.1309276010815132,
        1.0,
    ],
    &[
        -1.78403230023873,
        -3.2705633467112465,
        -1.7104774289378315,
        1.9753857795197842,
        1.9318504624554211,
        -0.9091323611991262,
        -2.2478958506195097,
        2.483566322301799,
        0.3555673960208807,
        -1.78403230023873,
    ],
    &[
        -12.485831882338832,
        -2.37947858238633,
        12.78005136754242,
        5.64926467474566,
        -2.9038972239652683,
        -3.268507154797603,
        3.9041376783176442,
        1.81683532598751,
        -8.910165080257242,
        -12.485831882338832,
    ],
];
const NAK3: [&[f64]; 3] = [
    &[
        1.0,
        0.24153846153846148,
        -0.4,
        -0.32923076923076905,
        2.9876923076923085,
        10.538461538461542,
        27.833846153846174,
        45.44000000000005,
        61.42307692307697,
        67.28000000000007,
    ],
    &[
        -4.453846153846154,
        -3.1307692307692303,
        -1.1461538461538459,
        1.5000000000000002,
        6.792307692307694,
        12.084615384615391,
        19.36153846153848,
        24.65384615384618,
        28.623076923076958,
        29.946153846153887,
    ],
    &[
        6.615384615384617,
        6.615384615384617,
        6.615384615384614,
        6.615384615384616,
        6.615384615384619,
        6.615384615384622,
        6.615384615384627,
        6.61538461538463,
        6.615384615384633,
        6.615384615384634,
    ],
];
const NAK4: [&[f64]; 3] = [
    &[
        1.0,
        0.14338461538461517,
        -0.4,
        -0.11507692307692273,
        1.7741538461538457,
        1.615384615384622,
        -10.339076923076858,
        -33.671999999999855,
        -62.38461538461512,
        -74.4719999999997,
    ],
    &[
        -5.420512820512823,
        -3.2051282051282053,
        -0.5512820512820498,
        1.737948717948718,
        2.033333333333334,
        -3.382051282051261,
        -20.152820512820423,
        -39.1312820512819,
        -57.11282051282028,
        -63.82051282051257,
    ],
    &[
        11.96923076923078,
        10.184615384615393,
        7.507692307692304,
        3.938461538461535,
        -3.1999999999999886,
        -10.338461538461498,
        -20.15384615384607,
        -27.29230769230759,
        -32.646153846153716,
        -34.430769230769094,
    ],
];

fn points(ys: &[f64]) -> Vec<Point<1>> {
    ys.iter().map(|&y| Point([y])).collect()
}

fn check(spline: &CubicSpline<1>, reference: [&[f64]; 3], name: &str) {
    for (k, expected) in reference.iter().enumerate() {
        for (&t, &e) in Q.iter().zip(expected.iter()) {
            let got = spline.deriv(t, k)[0];
            let tol = 1e-12 * e.abs().max(1.0);
            assert!(
                (got - e).abs() <= tol,
                "{name}: d{k} at {t}: {got} vs SciPy {e}"
            );
        }
    }
}

#[test]
fn not_a_knot_matches_scipy() {
    let s = CubicSpline::new(&X, &points(&Y), SplineEnds::NotAKnot).unwrap();
    check(&s, NOT_A_KNOT, "not-a-knot");
    let s3 = CubicSpline::new(&X[..3], &points(&Y[..3]), SplineEnds::NotAKnot).unwrap();
    check(&s3, NAK3_REF, "not-a-knot, 3 points");
    let s4 = CubicSpline::new(&X[..4], &points(&Y[..4]), SplineEnds::NotAKnot).unwrap();
    check(&s4, NAK4_REF, "not-a-knot, 4 points");
}

#[test]
fn natural_clamped_periodic_match_scipy() {
    let ys = points(&Y);
    check(
        &CubicSpline::new(&X, &ys, SplineEnds::Natural).unwrap(),
        NATURAL_REF,
        "natural",
    );
    let clamped = SplineEnds::Clamped {
        start: Point([0.5]),
        end: Point([-1.0]),
    };
    check(
        &CubicSpline::new(&X, &ys, clamped).unwrap(),
        CLAMPED_REF,
        "clamped",
    );
    let mut yp = Y;
    yp[6] = 1.0;
    check(
        &CubicSpline::new(&X, &points(&yp), SplineEnds::Periodic).unwrap(),
        PERIODIC_REF,
        "periodic",
    );
}

#[test]
fn vector_values_are_per_coordinate() {
    // A 2-D spline is the pair of scalar splines of its coordinates.
    let pts: Vec<Point<2>> = Y.iter().map(|&y| Point([y, 2.0 * y - 1.0])).collect();
    let s = CubicSpline::new(&X, &pts, SplineEnds::NotAKnot).unwrap();
    for (&t, &e) in Q.iter().zip(NOT_A_KNOT[0].iter()) {
        let p = s.eval(t);
        assert!((p[0] - e).abs() < 1e-12 && (p[1] - (2.0 * e - 1.0)).abs() < 1e-12);
    }
}

#[test]
fn second_derivative_is_continuous_and_third_jumps_only_at_inner_knots() {
    let s = CubicSpline::new(&X, &points(&Y), SplineEnds::NotAKnot).unwrap();
    assert_eq!(s.continuity(), 2);
    for (k, &t) in X.iter().enumerate().take(6).skip(1) {
        for order in 0..=2 {
            let a = s.deriv_on_side(t, order, Side::Below)[0];
            let b = s.deriv_on_side(t, order, Side::Above)[0];
            assert!((a - b).abs() < 1e-11, "order {order} jumps at knot {k}");
        }
        let a = s.deriv_on_side(t, 3, Side::Below)[0];
        let b = s.deriv_on_side(t, 3, Side::Above)[0];
        // Not-a-knot: no third-derivative jump at the second and second-to-last knots.
        if k == 1 || k == 5 {
            assert!((a - b).abs() < 1e-10, "third derivative jumps at knot {k}");
        } else {
            assert!(
                (a - b).abs() > 1e-3,
                "expected a third-derivative jump at knot {k}"
            );
        }
    }
}

#[test]
fn periodic_spline_is_c2_across_the_seam_and_wraps() {
    let mut yp = Y;
    yp[6] = 1.0;
    let s = CubicSpline::new(&X, &points(&yp), SplineEnds::Periodic).unwrap();
    assert!(s.is_closed());
    for order in 0..=2 {
        let a = s.deriv_on_side(X[6], order, Side::Below)[0];
        let b = s.deriv_on_side(X[0], order, Side::Above)[0];
        assert!((a - b).abs() < 1e-11, "order {order} jumps across the seam");
    }
    let period = X[6] - X[0];
    assert!((s.eval(1.7 + period)[0] - s.eval(1.7)[0]).abs() < 1e-12);
    // A last value that does not repeat the first is refused.
    assert!(CubicSpline::new(&X, &points(&Y), SplineEnds::Periodic).is_err());
}

#[test]
fn bad_input_is_an_error() {
    use karkas::Error;
    let ys = points(&Y);
    let mut knots = X;
    knots[3] = knots[2];
    assert_eq!(
        CubicSpline::new(&knots, &ys, SplineEnds::NotAKnot),
        Err(Error::InvalidKnot {
            index: 3,
            value: knots[3],
            reason: "not greater than the knot before it (knots must increase)"
        })
    );
    knots[3] = f64::NAN;
    assert!(CubicSpline::new(&knots, &ys, SplineEnds::Natural).is_err());
    assert!(CubicSpline::new(&X[..1], &ys[..1], SplineEnds::NotAKnot).is_err());
    assert!(CubicSpline::new(&X, &ys[..6], SplineEnds::NotAKnot).is_err());
    let mut bad = ys.clone();
    bad[2] = Point([f64::INFINITY]);
    assert_eq!(
        CubicSpline::new(&X, &bad, SplineEnds::NotAKnot),
        Err(Error::NonFinitePoint { index: 2 })
    );
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn every_spline_interpolates_and_is_c2(
        steps in proptest::collection::vec(0.05f64..3.0, 1..12),
        seed in 0u64..1000,
        kind in 0usize..3,
        periodic in any::<bool>(),
    ) {
        let pts: Vec<Point3> = steps
            .iter()
            .scan(0.0, |t, h| { *t += h; Some(*t) })
            .chain(std::iter::once(0.0))
            .enumerate()
            .map(|(k, t)| {
                let x = (seed as f64 + k as f64 * 1.7).sin();
                Point3::new([t, x, (t * x).cos()])
            })
            .collect();
        let parameterization = [
            CurveParameterization::Uniform,
            CurveParameterization::ChordLength,
            CurveParameterization::Centripetal,
        ][kind];
        let ends = if periodic { SplineEnds::Periodic } else { SplineEnds::NotAKnot };
        let Ok(s) = CubicSpline::through(&pts, parameterization, ends) else {
            // Only a periodic spline of too few distinct points may be refused.
            prop_assert!(periodic);
            return Ok(());
        };
        for (t, p) in s.knots().iter().zip(&pts) {
            prop_assert!(s.eval(*t).distance(*p) < 1e-9 * (1.0 + p.norm()));
        }
        for &t in &s.knots()[1..s.knots().len() - 1] {
            for k in 0..=2 {
                let a = s.deriv_on_side(t, k, Side::Below);
                let b = s.deriv_on_side(t, k, Side::Above);
                let scale = 1.0 + a.norm();
                prop_assert!((a - b).norm() < 1e-7 * scale, "D^{k} jumps at {t}");
            }
        }
    }
}

#[test]
fn values_too_far_apart_for_their_knot_gap_are_refused() {
    // A normal gap of 4.5e-308 under a difference of 425: the slopes overflow, and the
    // spline would evaluate to NaN.
    let values = [Point2::new([0.0, 0.0]), Point2::new([425.0, 1.0])];
    let knots = [1.5e-323, 4.45e-308];
    for ends in [SplineEnds::NotAKnot, SplineEnds::Natural] {
        let made = CubicSpline::new(&knots, &values, ends);
        match made {
            Err(Error::InvalidKnot { index, .. }) => assert_eq!(index, 1),
            other => panic!("{other:?}"),
        }
    }
    // Given finite end slopes, no slope is divided by the gap: the spline is finite.
    let clamped = SplineEnds::Clamped {
        start: Point2::ZERO,
        end: Point2::ZERO,
    };
    let given = CubicSpline::new(&knots, &values, clamped).unwrap();
    assert!(given.eval(2e-308).is_finite());
    // The same values a fair gap apart still make a finite spline.
    let fine = CubicSpline::new(&[0.0, 1e-300], &values, SplineEnds::NotAKnot).unwrap();
    assert!(fine.eval(0.5e-300).is_finite());
}

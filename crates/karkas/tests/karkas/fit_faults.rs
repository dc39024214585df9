//! The tolerance mode repairs a fit that hooks (docs/methods.md §4, "shape guards"): real
//! coordinates whose trailing edge rises steeply from its last point.

use crate::common::Rng;
use karkas::fit::{
    fit_curve, fit_curve_adaptive, uniform_knots, FitOptions, FitWarningKind, StartParameters,
};
use karkas::{Point2, Point3};

/// The AH 80-140 section (Althaus) as the airfoil collection of the corpus gives it
/// (tests/corpus/fetch_corpus.py): 97 points, upper surface first, closed trailing edge.
const AH80140: [[f64; 2]; 97] = [
    [1.0, 0.0],
    [0.99893, 0.00097],
    [0.99572, 0.00161],
    [0.99039, 0.00246],
    [0.98296, 0.00347],
    [0.97347, 0.00477],
    [0.96194, 0.00625],
    [0.94844, 0.00806],
    [0.93301, 0.01008],
    [0.91573, 0.01247],
    [0.89668, 0.01511],
    [0.87592, 0.01816],
    [0.85355, 0.02152],
    [0.82967, 0.02535],
    [0.80438, 0.02953],
    [0.77779, 0.0342],
    [0.75, 0.03927],
    [0.72114, 0.04487],
    [0.69134, 0.05082],
    [0.66072, 0.05724],
    [0.62941, 0.06395],
    [0.59755, 0.07105],
    [0.56526, 0.07822],
    [0.5327, 0.0855],
    [0.5, 0.09256],
    [0.4673, 0.09927],
    [0.43474, 0.10497],
    [0.40245, 0.10925],
    [0.37059, 0.11184],
    [0.33928, 0.11315],
    [0.30866, 0.11312],
    [0.27886, 0.112],
    [0.25, 0.10968],
    [0.22221, 0.10635],
    [0.19562, 0.10198],
    [0.17033, 0.09691],
    [0.14645, 0.09105],
    [0.12408, 0.0847],
    [0.10332, 0.07767],
    [0.08427, 0.07024],
    [0.06699, 0.06229],
    [0.05156, 0.05421],
    [0.03806, 0.04584],
    [0.02653, 0.03774],
    [0.01704, 0.02975],
    [0.00961, 0.02234],
    [0.00428, 0.01511],
    [0.00107, 0.00812],
    [0.0, 0.0],
    [0.00107, -0.00587],
    [0.00428, -0.01064],
    [0.00961, -0.01476],
    [0.01704, -0.01798],
    [0.02653, -0.02065],
    [0.03806, -0.02257],
    [0.05156, -0.02423],
    [0.06699, -0.0254],
    [0.08427, -0.02644],
    [0.10332, -0.0271],
    [0.12408, -0.02766],
    [0.14645, -0.02792],
    [0.17033, -0.02812],
    [0.19562, -0.02804],
    [0.22221, -0.02787],
    [0.25, -0.02748],
    [0.27886, -0.02708],
    [0.30866, -0.02651],
    [0.33928, -0.02595],
    [0.37059, -0.02523],
    [0.40245, -0.02454],
    [0.43474, -0.02369],
    [0.4673, -0.0228],
    [0.5, -0.02175],
    [0.5327, -0.02066],
    [0.56526, -0.01939],
    [0.59755, -0.01812],
    [0.62941, -0.01672],
    [0.66072, -0.01536],
    [0.69134, -0.01392],
    [0.72114, -0.01252],
    [0.75, -0.01107],
    [0.77779, -0.00967],
    [0.80438, -0.00828],
    [0.82967, -0.00703],
    [0.85355, -0.00582],
    [0.87592, -0.00479],
    [0.89668, -0.00382],
    [0.91573, -0.00306],
    [0.93301, -0.00239],
    [0.94844, -0.00193],
    [0.96194, -0.00152],
    [0.97347, -0.00128],
    [0.98296, -0.00108],
    [0.99039, -0.00101],
    [0.99572, -0.00093],
    [0.99893, -0.0008],
    [1.0, 0.0],
];

fn points() -> Vec<Point2> {
    AH80140.iter().map(|&p| Point2::new(p)).collect()
}

fn shape_faults(warnings: &[karkas::fit::FitWarning]) -> Vec<String> {
    warnings
        .iter()
        .filter(|w| {
            matches!(
                w.kind,
                FitWarningKind::SelfIntersection | FitWarningKind::ExcessTurning
            )
        })
        .map(|w| w.message.clone())
        .collect()
}

#[test]
fn the_plain_fit_on_the_knots_the_tolerance_first_reaches_hooks_at_the_trailing_edge() {
    // The premise: 13 uniform knots meet 1e-4 but hook past x = 1 at both ends.
    let fit = fit_curve(
        &points(),
        &karkas::fit::uniform_knots(13),
        &FitOptions::default(),
    )
    .unwrap();
    assert!(fit.max_distance() <= 1e-4, "{}", fit.max_distance());
    let faults = shape_faults(&fit.warnings);
    assert!(faults.len() >= 2, "{faults:?}");
}

#[test]
fn the_tolerance_mode_meets_the_tolerance_without_a_hook_or_a_loop() {
    let adaptive = fit_curve_adaptive(&points(), 1e-4, &FitOptions::default()).unwrap();
    assert!(adaptive.tolerance_met);
    assert!(adaptive.fit.max_distance() <= 1e-4);
    let faults = shape_faults(&adaptive.fit.warnings);
    assert!(faults.is_empty(), "{faults:?}");
    // No point of the curve runs past the trailing edge by more than the tolerance.
    let beyond = (0..=4000)
        .map(|i| karkas::Curve::eval(&adaptive.fit.spline, i as f64 / 4000.0).0[0])
        .fold(f64::NEG_INFINITY, f64::max);
    assert!(beyond <= 1.0 + 1e-4, "the curve reaches x = {beyond}");
}

/// The LRN 1007 section as the airfoil collection of the corpus gives it: 59 points, upper
/// surface first, a leading edge whose lower side starts 5e-4 from its upper side.
const LRN1007: [[f64; 2]; 59] = [
    [1.0, 0.0],
    [0.9605, 0.0078],
    [0.9205, 0.0162],
    [0.8805, 0.02509],
    [0.8405, 0.03467],
    [0.8005, 0.04498],
    [0.7605, 0.05585],
    [0.7205, 0.06679],
    [0.6805, 0.07608],
    [0.63686, 0.0828],
    [0.58975, 0.08837],
    [0.54195, 0.09203],
    [0.49384, 0.09433],
    [0.44577, 0.09527],
    [0.39818, 0.09491],
    [0.35152, 0.09334],
    [0.30628, 0.09056],
    [0.26288, 0.08666],
    [0.22176, 0.08167],
    [0.1833, 0.0757],
    [0.14786, 0.06881],
    [0.11573, 0.06113],
    [0.08722, 0.05281],
    [0.06252, 0.044],
    [0.04183, 0.03492],
    [0.02626, 0.02635],
    [0.01288, 0.0169],
    [0.00471, 0.00864],
    [0.0005, 0.0024],
    [0.0, 0.0],
    [0.0005, 5e-05],
    [0.00471, 0.001],
    [0.01288, 0.00322],
    [0.02626, 0.00646],
    [0.04183, 0.00922],
    [0.06252, 0.01225],
    [0.08722, 0.01499],
    [0.11573, 0.01703],
    [0.14786, 0.01863],
    [0.1833, 0.01948],
    [0.22176, 0.02009],
    [0.26288, 0.02052],
    [0.30628, 0.02081],
    [0.35152, 0.02151],
    [0.39818, 0.02217],
    [0.44577, 0.02277],
    [0.49384, 0.0231],
    [0.54195, 0.02354],
    [0.58975, 0.02378],
    [0.63696, 0.02353],
    [0.6805, 0.02242],
    [0.7205, 0.02067],
    [0.7605, 0.01839],
    [0.8005, 0.01595],
    [0.8405, 0.01286],
    [0.8805, 0.00972],
    [0.9205, 0.00649],
    [0.9605, 0.0032],
    [1.0, 0.0],
];

#[test]
fn a_loop_at_a_sharp_leading_edge_is_repaired_with_more_bending_on_finer_knots() {
    let points: Vec<Point2> = LRN1007.iter().map(|&p| Point2::new(p)).collect();
    // The refinement reaches knots that leave a loop 1.4e-3 ahead of the leading edge, and
    // knots added at the loop alone keep one; the finer knots fitted again from the
    // chord-length parameters with three times the bending weight do not loop.
    let adaptive = fit_curve_adaptive(&points, 1e-4, &FitOptions::default()).unwrap();
    assert!(adaptive.tolerance_met);
    let faults = shape_faults(&adaptive.fit.warnings);
    assert!(faults.is_empty(), "{faults:?}");
    assert!(adaptive.fit.max_distance() <= 1e-4);
}

/// The GOE 114 section as the airfoil collection of the corpus gives it: 33 points, upper
/// surface first, a leading edge that turns 125 degrees at one point.
const GOE114: [[f64; 2]; 33] = [
    [1.0, 0.0],
    [0.94964, 0.01022],
    [0.8993, 0.01995],
    [0.79866, 0.03809],
    [0.69808, 0.05434],
    [0.59764, 0.067],
    [0.49736, 0.07476],
    [0.39726, 0.07762],
    [0.29738, 0.0741],
    [0.19782, 0.06168],
    [0.14818, 0.05163],
    [0.09862, 0.03918],
    [0.07386, 0.03231],
    [0.04919, 0.02294],
    [0.02454, 0.01307],
    [0.01225, 0.00713],
    [0.0, 0.0],
    [0.01271, -0.00585],
    [0.02534, -0.00971],
    [0.05058, -0.01651],
    [0.07575, -0.02133],
    [0.10087, -0.02474],
    [0.15097, -0.02747],
    [0.201, -0.0282],
    [0.30075, -0.02118],
    [0.40038, -0.01067],
    [0.50016, -0.00464],
    [0.60002, -0.00062],
    [0.69997, 0.00091],
    [0.79995, 0.00134],
    [0.89998, 0.00067],
    [0.94999, 0.00033],
    [1.0, 0.0],
];

/// The knots the tolerance mode ends on for GOE 114 without the uniform knots (placed where
/// the deviation was largest).
const GOE114_REFINED: [f64; 10] = [
    0.0,
    0.11300558981435423,
    0.25,
    0.38925666871944825,
    0.42892609317433245,
    0.5,
    0.6757066847988222,
    0.75,
    0.8125,
    1.0,
];

#[test]
fn a_hook_at_a_sparse_sharp_leading_edge_is_repaired_with_uniform_knots() {
    let points: Vec<Point2> = GOE114.iter().map(|&p| Point2::new(p)).collect();
    // The premise: on the refined knots, short ones at the leading edge beside a long piece,
    // the curve turns too much there.
    let plain = fit_curve(&points, &GOE114_REFINED, &FitOptions::default()).unwrap();
    assert!(!shape_faults(&plain.warnings).is_empty());
    // The tolerance mode gives a sound fit within the cap of one knot per two points, and
    // its curve rounds the leading edge instead of looping 3.5e-3 ahead of it.
    let adaptive = fit_curve_adaptive(&points, 1e-4, &FitOptions::default()).unwrap();
    assert!(adaptive.tolerance_met);
    assert!(adaptive.fit.max_distance() <= 1e-4);
    let faults = shape_faults(&adaptive.fit.warnings);
    assert!(faults.is_empty(), "{faults:?}");
    assert!(adaptive.fit.spline.knots().len() <= points.len() / 2);
    let ahead = (0..=40_000)
        .map(|i| karkas::Curve::eval(&adaptive.fit.spline, i as f64 / 40_000.0).0[0])
        .fold(f64::INFINITY, f64::min);
    assert!(ahead >= -2e-3, "the curve reaches x = {ahead}");
}

/// The GOE 165 section as the airfoil collection of the corpus gives it
/// (tests/corpus/fetch_corpus.py): 33 points, 4-5 digits, upper surface first; at the
/// leading edge the polygon turns 94 degrees at one point, between chords of 0.013 and
/// 0.023.
const GOE165: [[f64; 2]; 33] = [
    [1.0, 0.0006],
    [0.94946, 0.01886],
    [0.89911, 0.03133],
    [0.79853, 0.05168],
    [0.69807, 0.06783],
    [0.59766, 0.08247],
    [0.4973, 0.09522],
    [0.39713, 0.10108],
    [0.29708, 0.10294],
    [0.19723, 0.0977],
    [0.1475, 0.08819],
    [0.09793, 0.07288],
    [0.07321, 0.06288],
    [0.04865, 0.04768],
    [0.02408, 0.03248],
    [0.01195, 0.01944],
    [0.0, 0.0],
    [0.01269, -0.00664],
    [0.02531, -0.01088],
    [0.05042, -0.01487],
    [0.07555, -0.01935],
    [0.1006, -0.02094],
    [0.15069, -0.02412],
    [0.20066, -0.0233],
    [0.30042, -0.01467],
    [0.39991, 0.00326],
    [0.49943, 0.01998],
    [0.59922, 0.02742],
    [0.69924, 0.02676],
    [0.79939, 0.0215],
    [0.89964, 0.01275],
    [0.94983, 0.00608],
    [1.0, -0.0006],
];

#[test]
fn a_hook_that_no_least_squares_refit_removes_goes_with_a_curve_through_the_points() {
    let points: Vec<Point2> = GOE165.iter().map(|&p| Point2::new(p)).collect();
    // The premise: no least-squares fit on uniform knots, up to one knot per two points,
    // from chord-length or centripetal parameters, is both within the tolerance and sound.
    for start in [StartParameters::ChordLength, StartParameters::Centripetal] {
        let options = FitOptions {
            smoothing: Some(0.0),
            ends: karkas::fit::FitEnds::Free,
            start,
            ..FitOptions::default()
        };
        for count in 2..=points.len() / 2 {
            let fit = fit_curve(&points, &uniform_knots(count), &options).unwrap();
            let faults = shape_faults(&fit.warnings);
            assert!(
                fit.max_distance() > 1e-4 || !faults.is_empty(),
                "{count} knots"
            );
        }
    }
    let adaptive = fit_curve_adaptive(&points, 1e-4, &FitOptions::default()).unwrap();
    assert!(adaptive.tolerance_met);
    assert!(adaptive.fit.max_distance() <= 1e-4);
    let faults = shape_faults(&adaptive.fit.warnings);
    assert!(faults.is_empty(), "{faults:?}");
    // It comes no farther ahead of the leading edge point than the tolerance (the faulty fit
    // hooked 3.4e-4 ahead of it).
    let ahead = (0..=40_000)
        .map(|i| karkas::Curve::eval(&adaptive.fit.spline, i as f64 / 40_000.0).0[0])
        .fold(f64::INFINITY, f64::min);
    assert!(ahead >= -1e-4, "the curve reaches x = {ahead}");
}

#[test]
fn noisy_points_at_a_tolerance_below_the_noise_are_not_followed_one_by_one() {
    // 200 points of a helix with noise 1e-3, at the tolerance 1e-4: the rounds stop at one
    // knot per two points with a fit that turns too much. Through every point a curve would
    // meet the tolerance; the repair keeps the points within the fit's own deviation instead.
    let mut rng = Rng::new(7);
    let points: Vec<Point3> = (0..200)
        .map(|i| {
            let s = i as f64 / 199.0;
            let noise = Point3::new([rng.normal(), rng.normal(), rng.normal()]) * 1e-3;
            Point3::new([(20.0 * s).cos(), (20.0 * s).sin(), s]) + noise
        })
        .collect();
    let adaptive = fit_curve_adaptive(&points, 1e-4, &FitOptions::default()).unwrap();
    assert!(!adaptive.tolerance_met);
    assert!(
        adaptive.fit.max_distance() > 1e-3,
        "{}",
        adaptive.fit.max_distance()
    );
    let faults = shape_faults(&adaptive.fit.warnings);
    assert!(faults.is_empty(), "{faults:?}");
}

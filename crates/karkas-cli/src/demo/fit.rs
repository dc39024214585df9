//! Pavlov (fitting with bounded second-derivative jumps): the paper's hydrofoil, knots
//! (0, 0.445, 0.449, 0.587, 1), eps = 0.01 (docs/methods.md §4). The paper's deviations are printed
//! beside ours as context: its printed coordinates carry transcription errors, and their
//! polygon crosses itself (reported with where); [`super::fit_clean`] shows the method on a
//! section with known truth sampled the same way.

use super::common::{Finding, Output};
use crate::output::samples::sample_curve;
use anyhow::{Context, Result};
use karkas::fit::polyline_crossings;
use karkas::fit::{
    fit_curve, shape_warnings, CurveFit, FitOptions, FitWarningKind, PenaltyRule, StartParameters,
};
use karkas::{Curve, Point2};
use karkas_io::svg::{write_fit_svg, FitPlot};
use karkas_io::write::{write_atomic, write_curve_csv};

/// The paper's table: x, y and the paper's deviation dR (also in data/hydrofoil-profile.csv).
const HYDROFOIL: [(f64, f64, f64); 20] = [
    (94.80, 78.50, 0.45),
    (71.10, 52.60, 0.19),
    (47.40, 29.90, 0.30),
    (23.70, 7.90, 0.31),
    (0.00, -12.90, 0.38),
    (-23.70, -23.00, 0.60),
    (-47.10, -67.90, 0.64),
    (-74.80, -94.30, 0.59),
    (-106.60, -93.00, 0.56),
    (-115.00, -101.70, 0.71),
    (-106.60, -104.80, 0.23),
    (-94.80, -101.00, 0.34),
    (-71.10, -90.90, 0.30),
    (-47.40, -77.90, 0.20),
    (-23.70, -63.00, 0.12),
    (0.00, -48.50, 0.06),
    (23.70, -25.00, 0.27),
    (47.40, 0.00, 0.18),
    (71.10, 28.60, 0.12),
    (94.80, 62.60, 0.10),
];
const KNOTS: [f64; 5] = [0.0, 0.445, 0.449, 0.587, 1.0];
const EPS: f64 = 0.01;

const EXAMPLE: &str = "003 hydrofoil, 5 knots, eps = 0.01";

/// Runs the example into `out`.
pub fn run(out: &Output) -> Result<Vec<Finding>> {
    let points: Vec<Point2> = HYDROFOIL
        .iter()
        .map(|&(x, y, _)| Point2::new([x, y]))
        .collect();
    let seed = fit_curve(
        &points,
        &KNOTS,
        &FitOptions {
            eps: EPS,
            penalty: PenaltyRule::SeedBound,
            ..Default::default()
        },
    )
    .context("hydrofoil fit, Pavlov's penalty")?;
    let active = fit_curve(
        &points,
        &KNOTS,
        &FitOptions {
            eps: EPS,
            ..Default::default()
        },
    )
    .context("hydrofoil fit")?;
    let per_point = write_deviations(out, &seed, &active)?;
    write_fit(out, &points, &active)?;
    let mut findings = summary(&points, &seed, &active);
    findings.extend(starts(&points)?);
    findings.extend(per_point);
    Ok(findings)
}

/// The powers of the cumulative chords of `--starts 8`, in order (docs/methods.md §4).
const START_POWERS: [f64; 8] = [1.0, 0.5, 0.0, 0.75, 0.25, 1.5, 0.875, 0.625];

/// The paper's objective `H` from each start of `--starts 8` (bound active), how many of
/// those fits cross themselves or turn beyond the points, and what `--starts 8` keeps.
fn starts(points: &[Point2]) -> Result<Vec<Finding>> {
    let (mut lowest, mut highest) = (f64::INFINITY, 0.0f64);
    let mut unsound = 0;
    for power in START_POWERS {
        let options = FitOptions {
            eps: EPS,
            start: StartParameters::ChordPower(power),
            ..Default::default()
        };
        let fit = fit_curve(points, &KNOTS, &options).context("hydrofoil fit, one start")?;
        lowest = lowest.min(fit.data_term);
        highest = highest.max(fit.data_term);
        let faults = shape_warnings(points, &fit).iter().any(|w| {
            matches!(
                w.kind,
                FitWarningKind::SelfIntersection | FitWarningKind::ExcessTurning
            )
        });
        unsound += usize::from(faults);
    }
    let options = FitOptions {
        eps: EPS,
        starts: START_POWERS.len(),
        ..Default::default()
    };
    let kept = fit_curve(points, &KNOTS, &options).context("hydrofoil fit, 8 starts")?;
    Ok(vec![
        Finding::new(
            EXAMPLE,
            "Pavlov's objective H (sum of squared distances) from the chord-length start, bound active",
            fit_curve(points, &KNOTS, &FitOptions { eps: EPS, ..Default::default() })?.data_term,
        ),
        Finding::new(
            EXAMPLE,
            "lowest H of the 8 starts of --starts 8 (cumulative chords to the powers 1, 0.5, 0, 0.75, 0.25, 1.5, 0.875, 0.625)",
            lowest,
        ),
        Finding::new(EXAMPLE, "highest H of the 8 starts", highest),
        Finding::new(
            EXAMPLE,
            "starts of the 8 whose fit crosses itself or turns beyond the points",
            unsound as f64,
        ),
        Finding::new(EXAMPLE, "H kept by --starts 8 (loop-free fits only, else the first start's)", kept.data_term),
    ])
}

/// The table of each point's deviation under both penalties beside the paper's, and the
/// findings of the active bound's.
fn write_deviations(
    out: &Output,
    seed: &CurveFit<2>,
    active: &CurveFit<2>,
) -> Result<Vec<Finding>> {
    let mut table = String::from("point,x,y,paper_dR,t,distance_seed_p,distance_active_p\n");
    let mut per_point = Vec::with_capacity(HYDROFOIL.len());
    for (i, &(x, y, paper)) in HYDROFOIL.iter().enumerate() {
        table.push_str(&format!(
            "{},{x},{y},{paper},{},{},{}\n",
            i + 1,
            active.parameters[i],
            seed.distances[i],
            active.distances[i]
        ));
        per_point.push(
            Finding::new(
                EXAMPLE,
                format!(
                    "deviation of point {} ({x:.2}, {y:.2}), bound active",
                    i + 1
                ),
                active.distances[i],
            )
            .paper(paper)
            .detail(),
        );
    }
    write_atomic(&out.file("hydrofoil-fit-deviations.csv"), |w| {
        w.write_all(table.as_bytes())
    })?;
    Ok(per_point)
}

/// The fitted curve's samples and its picture with the points and their feet.
fn write_fit(out: &Output, points: &[Point2], active: &CurveFit<2>) -> Result<()> {
    let n = 1000;
    let (ts, samples) = sample_curve(&active.spline, n);
    write_curve_csv(&out.file("hydrofoil-fit.csv"), &ts, &samples)?;
    let feet: Vec<Point2> = active
        .parameters
        .iter()
        .map(|&t| active.spline.eval(t))
        .collect();
    write_fit_svg(
        &out.file("hydrofoil-fit.svg"),
        &FitPlot {
            title: "Pavlov's printed hydrofoil (its points cross themselves), eps = 0.01",
            curve: &samples,
            points,
            feet: &feet,
            reference: &[],
        },
    )?;
    Ok(())
}

/// The points' self-crossings, and the deviations, jumps and penalties of both fits.
fn summary(points: &[Point2], seed: &CurveFit<2>, active: &CurveFit<2>) -> Vec<Finding> {
    let crossings = polyline_crossings(points);
    let places: Vec<String> = crossings
        .iter()
        .map(|c| {
            format!(
                "{}-{} x {}-{} at ({:.2}, {:.2})",
                c.first + 1,
                c.first + 2,
                c.second + 1,
                c.second + 2,
                c.at[0],
                c.at[1]
            )
        })
        .collect();
    vec![
        Finding::new(
            EXAMPLE,
            format!(
                "self-crossings of the points' polygon (segments {})",
                places.join("; ")
            ),
            crossings.len() as f64,
        ),
        Finding::new(
            EXAMPLE,
            "max deviation, bound active",
            active.max_distance(),
        )
        .paper(0.71),
        Finding::new(
            EXAMPLE,
            "max deviation, Pavlov's p = H(q*)/eps",
            seed.max_distance(),
        ),
        Finding::new(
            EXAMPLE,
            "f = sum J_L^2 achieved (bound active)",
            active.jump_sum,
        ),
        Finding::new(EXAMPLE, "penalty p (bound active)", active.penalty),
        Finding::new(EXAMPLE, "Pavlov's p = H(q*)/eps", seed.penalty),
    ]
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The crossings named in the demo's note, computed by hand from the paper's table
    /// (segment 7-8 meets 12-13 at parameter 0.8751 of 7-8; 8-9 meets 12-13 at 0.1228 of 8-9).
    #[test]
    fn the_printed_points_cross_where_the_note_says() {
        let points: Vec<Point2> = HYDROFOIL
            .iter()
            .map(|&(x, y, _)| Point2::new([x, y]))
            .collect();
        let found = polyline_crossings(&points);
        assert_eq!(found.len(), 2);
        let expected = [(6, 11, -71.3398, -91.0022), (7, 11, -78.7037, -94.1404)];
        for (c, (i, j, x, y)) in found.iter().zip(expected) {
            assert_eq!((c.first, c.second), (i, j));
            assert!(
                (c.at[0] - x).abs() < 1e-3 && (c.at[1] - y).abs() < 1e-3,
                "{c:?}"
            );
        }
    }

    /// The offsets the note gives: the printed y of points 6 to 8 against the clean section's
    /// upper surface at the same stations, and point 8 against the lower polygon (segment 12-13).
    #[test]
    fn the_printed_points_6_to_8_stand_off_the_clean_section() {
        let clean = super::super::foil_section::sampled_points();
        let offsets: Vec<f64> = (5..8).map(|i| HYDROFOIL[i].1 - clean[i].0[1]).collect();
        for (got, want) in offsets.iter().zip([8.1, -19.7, -26.7]) {
            assert!((got - want).abs() < 0.05, "{offsets:?}");
        }
        let (a, b) = (HYDROFOIL[11], HYDROFOIL[12]);
        let lower = a.1 + (b.1 - a.1) * (-74.8 - a.0) / (b.0 - a.0);
        assert!((lower - HYDROFOIL[7].1 - 1.8).abs() < 0.05, "{lower}");
    }
}

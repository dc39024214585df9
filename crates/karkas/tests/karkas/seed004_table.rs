//! The table of seed 004 (examples 3.1, 3.2): frames along the lines of curvature beat turned
//! frames, and the cylinder's principal frame lands near the paper's 0.011.

use karkas::measure::Hausdorff;
use karkas::param::experiments::{helix_experiment, seed_experiments, SeedSurface};
use std::sync::OnceLock;

/// Every row's label, surface and error, computed once for all tests (the extra helix frame
/// last).
fn table() -> &'static [(&'static str, SeedSurface, Hausdorff)] {
    static TABLE: OnceLock<Vec<(&'static str, SeedSurface, Hausdorff)>> = OnceLock::new();
    TABLE.get_or_init(|| {
        seed_experiments()
            .into_iter()
            .chain(std::iter::once(helix_experiment()))
            .map(|row| {
                let outcome = row.run().unwrap();
                // Every frame is 5 x 9 nodes, the 9th repeating the first (helices: open).
                assert_eq!((outcome.nodes.rows(), outcome.nodes.cols()), (5, 9));
                if row.paper_error.is_some() {
                    for i in 0..5 {
                        assert_eq!(outcome.nodes.get(i, 8), outcome.nodes.get(i, 0));
                    }
                }
                (row.label, row.surface, outcome.error)
            })
            .collect()
    })
}

#[test]
fn principal_frames_beat_turned_frames_in_every_row() {
    let rows = &table()[..7];
    let mut principal = [f64::NAN; 2];
    for &(label, surface, error) in rows {
        let k = match surface {
            SeedSurface::Cylinder => 0,
            SeedSurface::Hyperboloid => 1,
        };
        if label.contains("lines of curvature") {
            principal[k] = error.distance;
            continue;
        }
        assert!(
            error.distance > principal[k],
            "{label}: {} does not exceed the principal frame's {}",
            error.distance,
            principal[k]
        );
    }
    assert!(
        (0.008..=0.013).contains(&principal[0]),
        "the cylinder's principal frame gives {}, the paper 0.011",
        principal[0]
    );
}

#[test]
fn both_directions_of_the_distance_are_measured() {
    // On the principal cylinder frame the worst error is at the seam of the closed circles
    // (their not-a-knot ends, near (1, 0, z)), and both one-sided distances see it.
    let h = table()[0].2;
    assert!((h.forward.distance - h.backward.distance).abs() < 0.1 * h.distance);
    let at = h.worst().from;
    assert!(
        at[1].abs() < 0.4 && at[0] > 0.9,
        "worst point {at:?} is not near the seam"
    );
}

#[test]
fn constant_angle_helices_are_not_worse_on_a_cylinder() {
    // Not in the paper: turning both families by a constant angle gives helices, which on a
    // developable cylinder are interpolated better (they bend less) than the circles.
    let (principal, helices) = (table()[0].2.distance, table()[7].2.distance);
    assert!(helices < principal, "{helices} vs {principal}");
}

//! The table of seed 004 (examples 3.1, 3.2): frames along the lines of curvature beat turned
//! frames, and the cylinder's principal frame lands near the paper's 0.011.

use karkas::param::experiments::{helix_experiment, seed_experiments, SeedSurface};

#[test]
fn principal_frames_beat_turned_frames_in_every_row() {
    let rows = seed_experiments();
    assert_eq!(rows.len(), 7);
    let mut principal = [f64::NAN; 2];
    for row in &rows {
        let outcome = row.run().unwrap();
        let error = outcome.error.distance;
        let k = match row.surface {
            SeedSurface::Cylinder => 0,
            SeedSurface::Hyperboloid => 1,
        };
        // The nodes are the frame: 5 x 9, the 9th repeating the first.
        assert_eq!((outcome.nodes.rows(), outcome.nodes.cols()), (5, 9));
        for i in 0..5 {
            assert_eq!(outcome.nodes.get(i, 8), outcome.nodes.get(i, 0));
        }
        if row.label.contains("lines of curvature") {
            principal[k] = error;
            continue;
        }
        assert!(
            error > principal[k],
            "{}: {error} does not exceed the principal frame's {}",
            row.label,
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
    // (their not-a-knot ends), and both one-sided distances see it.
    let row = &seed_experiments()[0];
    let h = row.run().unwrap().error;
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
    let principal = seed_experiments()[0].run().unwrap().error.distance;
    let helices = helix_experiment().run().unwrap().error.distance;
    assert!(helices < principal, "{helices} vs {principal}");
}

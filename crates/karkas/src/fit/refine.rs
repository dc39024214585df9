//! Where the tolerance mode of the fit (Pavlov's defect-2 spline, docs/methods.md §4) adds
//! knots: every piece whose worst point lies beyond the tolerance gets one new knot at the
//! foot parameter of that point (kept off the piece's ends), so a round at most doubles the
//! pieces and the knots gather where the deviation is largest.

use super::hermite::HermiteSpline;
use super::knots::MIN_KNOT_SPACING;

/// A piece holding fewer points than this is not split (the bending term keeps a piece with
/// no point determined; without it a split that leaves the spline undetermined is undone).
pub(crate) const MIN_POINTS_TO_SPLIT: usize = 1;
/// A new knot stays this share of its piece away from the piece's ends.
const KNOT_MARGIN: f64 = 0.25;

/// The worst point of one knot span.
#[derive(Clone, Copy, Debug, Default)]
pub(crate) struct PieceWorst {
    /// The largest distance of a point whose foot point lies on the piece.
    pub distance: f64,
    /// That point's foot parameter.
    pub parameter: f64,
    /// The points whose foot points lie on the piece.
    pub points: usize,
}

/// The worst point of every piece of `spline`, from the foot `parameters` and `distances`.
pub(crate) fn worst_per_piece<const D: usize>(
    spline: &HermiteSpline<D>,
    parameters: &[f64],
    distances: &[f64],
) -> Vec<PieceWorst> {
    let mut worst = vec![PieceWorst::default(); spline.pieces()];
    let mut piece = 0;
    for (&t, &d) in parameters.iter().zip(distances) {
        piece = spline.piece_near(t, piece);
        let w = &mut worst[piece];
        w.points += 1;
        if d >= w.distance {
            w.distance = d;
            w.parameter = t;
        }
    }
    worst
}

/// The knots after one round: `knots` plus one knot in each piece whose worst distance
/// exceeds `tolerance` and that can be split (at least [`MIN_POINTS_TO_SPLIT`] point, wider
/// than four times [`MIN_KNOT_SPACING`]), the worst pieces first, at most `budget` new knots.
/// Returns the knots and how many were added (0: nothing over the tolerance can be split).
pub(crate) fn refined_knots(
    knots: &[f64],
    worst: &[PieceWorst],
    tolerance: f64,
    budget: usize,
) -> (Vec<f64>, usize) {
    let mut over: Vec<usize> = (0..worst.len())
        .filter(|&p| {
            worst[p].distance > tolerance
                && worst[p].points >= MIN_POINTS_TO_SPLIT
                && knots[p + 1] - knots[p] > 4.0 * MIN_KNOT_SPACING
        })
        .collect();
    over.sort_by(|&a, &b| worst[b].distance.total_cmp(&worst[a].distance));
    over.truncate(budget);
    let mut finer = knots.to_vec();
    for &p in &over {
        let (a, b) = (knots[p], knots[p + 1]);
        let margin = KNOT_MARGIN * (b - a);
        finer.push(worst[p].parameter.clamp(a + margin, b - margin));
    }
    finer.sort_by(f64::total_cmp);
    (finer, over.len())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point;

    #[test]
    fn splits_only_pieces_over_the_tolerance_at_their_worst_point() {
        let knots = vec![0.0, 0.25, 0.5, 1.0];
        let spline = HermiteSpline::from_parts(
            knots.clone(),
            vec![Point([0.0, 0.0]); 4],
            vec![Point([1.0, 0.0]); 4],
        );
        let t: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
        let mut d = vec![0.0; t.len()];
        d[3] = 2.0; // t = 0.15, piece 0
        d[12] = 3.0; // t = 0.6, piece 2
        let worst = worst_per_piece(&spline, &t, &d);
        assert_eq!(worst.len(), 3);
        assert_eq!(worst[0].points, 5);
        assert_eq!(worst[2].parameter, 0.6);
        let (finer, added) = refined_knots(&knots, &worst, 1.0, 10);
        assert_eq!(added, 2);
        assert_eq!(finer, vec![0.0, 0.15, 0.25, 0.5, 0.625, 1.0]);
        let (finer, added) = refined_knots(&knots, &worst, 1.0, 1);
        assert_eq!((finer.len(), added), (5, 1));
        assert!(finer.contains(&0.625));
        assert_eq!(refined_knots(&knots, &worst, 5.0, 10).1, 0);
    }
}

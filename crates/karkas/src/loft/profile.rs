//! A section's points as the loft needs them ([`Profile`]): in order, with the point that sits
//! at `v = 1/2` on every section (an airfoil's leading edge, a mirrored hull section's keel)
//! when there is one.
//!
//! An airfoil ([`Profile::airfoil`]) is a curve from the trailing edge over the upper side to
//! the leading edge and back along the lower side (Selig's order): a profile given the other
//! way round (clockwise) is reversed, so that every section runs the same way. Its leading edge
//! is the point of smallest `x` (the first of equals), which must lie between the two ends with
//! at least two points on each side. Its first and last points are its trailing edge: equal
//! for a sharp edge (the curve ends there on both sides, a corner), apart for a blunt one.

use crate::{Error, Point2, Result};

/// How far an airfoil's smallest and largest `x` may lie from 0 and 1 (a share of the unit
/// chord) for it to count as given in unit chord.
pub const UNIT_CHORD_SLACK: f64 = 0.01;

/// The fewest points a section may have.
pub const MIN_SECTION_POINTS: usize = 5;

/// A section's points in order, and the point fixed at `v = 1/2` if any.
#[derive(Clone, Debug, PartialEq)]
pub struct Profile {
    points: Vec<Point2>,
    split: Option<usize>,
    reversed: bool,
}

impl Profile {
    /// An airfoil in unit chord (see the module docs).
    ///
    /// Errors: fewer than [`MIN_SECTION_POINTS`] points ([`Error::TooFewPoints`]), a
    /// non-finite point, an `x` range that is not `[0, 1]` within [`UNIT_CHORD_SLACK`], a
    /// leading edge with fewer than two points between it and either end
    /// ([`Error::InvalidSetting`]-free messages in [`Error::LoftSection`] of section 0; the
    /// loft renumbers them).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::Profile;
    /// use karkas::Point;
    ///
    /// // A symmetric section in unit chord, in Selig's order: trailing edge, upper side, leading
    /// // edge, lower side, trailing edge.
    /// let foil: Vec<_> = (0..=40)
    ///     .map(|k| {
    ///         let a = k as f64 * std::f64::consts::TAU / 40.0;
    ///         Point([(1.0 + a.cos()) / 2.0, 0.06 * a.sin()])
    ///     })
    ///     .collect();
    /// let profile = Profile::airfoil(&foil)?;
    /// let split = profile.split().expect("an airfoil has a leading edge");
    /// assert!(profile.points()[split].distance(Point([0.0, 0.0])) < 1e-12); // the leading edge
    /// assert!(Profile::airfoil(&foil[..4]).is_err()); // too few points
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn airfoil(points: &[Point2]) -> Result<Profile> {
        check_points(points)?;
        let bad = |reason: String| Error::LoftSection { section: 0, reason };
        let (lo, hi) = points
            .iter()
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(a, b), p| {
                (a.min(p[0]), b.max(p[0]))
            });
        if lo.abs() > UNIT_CHORD_SLACK || (hi - 1.0).abs() > UNIT_CHORD_SLACK {
            return Err(bad(format!(
                "the profile is not in unit chord: its x runs from {lo} to {hi}, not from 0 to 1 \
                 (within {UNIT_CHORD_SLACK})"
            )));
        }
        // Clockwise (lower side first) profiles are reversed: the shoelace area is positive
        // for Selig's order.
        let area: f64 = points
            .windows(2)
            .map(|w| w[0][0] * w[1][1] - w[1][0] * w[0][1])
            .sum::<f64>()
            + {
                let (a, b) = (points[points.len() - 1], points[0]);
                a[0] * b[1] - b[0] * a[1]
            };
        let reversed = area < 0.0;
        let mut points = points.to_vec();
        if reversed {
            points.reverse();
        }
        let le = (0..points.len())
            .min_by(|&a, &b| points[a][0].total_cmp(&points[b][0]))
            .unwrap_or(0);
        if le < 2 || le + 3 > points.len() {
            return Err(bad(format!(
                "no leading edge between the trailing-edge ends: the point of smallest x is point \
                 {} of {}, and each side needs two points more",
                if reversed { points.len() - 1 - le } else { le } + 1,
                points.len()
            )));
        }
        Ok(Profile {
            points,
            split: Some(le),
            reversed,
        })
    }

    /// An open section without a fixed middle (a hull's half section from the keel up):
    /// chord-length parameters over the whole of `[0, 1]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::Profile;
    /// use karkas::Point;
    ///
    /// // A hull's half section from the keel up.
    /// let half = [[0.0, 0.0], [0.5, 0.1], [0.8, 0.4], [1.0, 1.0], [1.0, 1.5]].map(Point);
    /// let profile = Profile::open(&half)?;
    /// assert_eq!((profile.points().len(), profile.split()), (5, None));
    /// assert!(Profile::open(&half[..3]).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn open(points: &[Point2]) -> Result<Profile> {
        check_points(points)?;
        Ok(Profile {
            points: points.to_vec(),
            split: None,
            reversed: false,
        })
    }

    /// A section whose point `split` sits at `v = 1/2` (a whole hull section's keel).
    ///
    /// Errors: as [`open`](Self::open), and a split with fewer than two points on either side.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::Profile;
    /// use karkas::Point;
    ///
    /// // A whole hull section, port to starboard over the keel at point 3.
    /// let whole = [[-1.0, 1.0], [-0.9, 0.4], [-0.5, 0.1], [0.0, 0.0], [0.5, 0.1], [0.9, 0.4], [1.0, 1.0]].map(Point);
    /// let profile = Profile::split_at(&whole, 3)?;
    /// assert_eq!(profile.split(), Some(3));
    /// assert!(Profile::split_at(&whole, 1).is_err()); // one point before the split
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn split_at(points: &[Point2], split: usize) -> Result<Profile> {
        check_points(points)?;
        if split < 2 || split + 3 > points.len() {
            return Err(Error::LoftSection {
                section: 0,
                reason: format!(
                    "point {} of {} cannot be the middle of the section: each side needs two \
                     points more",
                    split + 1,
                    points.len()
                ),
            });
        }
        Ok(Profile {
            points: points.to_vec(),
            split: Some(split),
            reversed: false,
        })
    }

    /// The points, in the order the loft uses (reversed if given clockwise).
    pub fn points(&self) -> &[Point2] {
        &self.points
    }

    /// The index of the point at `v = 1/2`, if any.
    pub fn split(&self) -> Option<usize> {
        self.split
    }

    /// True when the points were given the other way round and have been reversed.
    pub fn is_reversed(&self) -> bool {
        self.reversed
    }
}

/// At least [`MIN_SECTION_POINTS`] finite points.
fn check_points(points: &[Point2]) -> Result<()> {
    if points.len() < MIN_SECTION_POINTS {
        return Err(Error::TooFewPoints {
            what: "a loft section",
            needed: MIN_SECTION_POINTS,
            got: points.len(),
        });
    }
    if let Some(index) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::NonFinitePoint { index });
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn p(x: f64, y: f64) -> Point2 {
        Point2::new([x, y])
    }

    #[test]
    fn airfoils_are_put_in_selig_order_and_checked() {
        let selig = [
            p(1.0, 0.0),
            p(0.5, 0.06),
            p(0.1, 0.04),
            p(0.0, 0.0),
            p(0.1, -0.03),
            p(0.5, -0.04),
            p(1.0, 0.0),
        ];
        let a = Profile::airfoil(&selig).unwrap();
        assert_eq!((a.split(), a.is_reversed()), (Some(3), false));
        let mut clockwise = selig;
        clockwise.reverse();
        let b = Profile::airfoil(&clockwise).unwrap();
        assert_eq!(b.points(), &selig[..]);
        assert!(b.is_reversed());
        let percent: Vec<Point2> = selig.iter().map(|&q| q * 100.0).collect();
        let e = Profile::airfoil(&percent).unwrap_err();
        assert!(e.to_string().contains("not in unit chord"), "{e}");
        let e = Profile::airfoil(&selig[..4]).unwrap_err();
        assert!(matches!(e, Error::TooFewPoints { .. }), "{e}");
        let le_first = [
            p(0.0, 0.0),
            p(0.3, 0.05),
            p(0.6, 0.05),
            p(1.0, 0.0),
            p(0.6, -0.02),
        ];
        let e = Profile::airfoil(&le_first).unwrap_err();
        assert!(e.to_string().contains("no leading edge"), "{e}");
    }
}

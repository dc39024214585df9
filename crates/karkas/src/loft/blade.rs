//! A wind-turbine blade's sections placed as windIO places them ([`BladeShape`],
//! [`blade_frames`], docs/methods.md §7.1).
//!
//! windIO (IEA Wind Task 37's turbine ontology) describes a blade's outer shape by spanwise
//! distributions, each a pair of arrays `grid` (the nondimensional position along the blade's
//! reference axis, 0 at the root, 1 at the tip) and `values`, interpolated by PCHIP (Fritsch and
//! Carlson's shape-preserving cubic Hermite, SciPy's `PchipInterpolator`, whose slopes
//! [`pchip_slopes`] computes): the reference axis `x, y, z` (root frame: `z` along the pitch
//! axis, `x` towards the suction side, `y` towards the trailing edge), the chord, the twist in
//! degrees, `section_offset_y` (the distance along the chord line from the reference axis to
//! the leading edge, positive with the leading edge upstream) and `section_offset_x` (the
//! chord line's shift towards the suction side). A section at position `s` with a profile point
//! `(px, py)` in unit chord (leading edge at the origin, `py` towards the suction side) goes,
//! following the schema's steps 2 to 6:
//!
//! 1. scaled by the chord `c` and offset: `p = (c py + ox, c px - oy, 0)` in the root frame;
//! 2. twisted: turned about `z` by `-(twist + rz)`, so that a positive twist turns the leading
//!    edge towards `-x` (into the wind), as WISDEM and windio2cad do; `rz` is the schema's
//!    twist correction `atan2(Mxy[0][1], Mxy[0][0])` of the tilt below (zero when the
//!    reference axis has no `y` component, as in the IEA reference turbines);
//! 3. tilted normal to the reference axis: `Mxy = My(b) Mx(a)`, the rotations about `x` and
//!    `y` that carry `z` onto the unit tangent `t` of the axis (PCHIP derivatives):
//!    `sin a = -t_y`, `b = atan2(t_x, t_z)`;
//! 4. translated to the axis point `r(s)`.
//!
//! The loft's span station of a section is `s` times the reference axis's length.

use super::pchip::pchip_slopes;
use super::placement::SectionFrame;
use crate::spline::hermite_basis;
use crate::{Error, Point3, Result};

/// A spanwise distribution (windIO's `grid` and `values`) interpolated by PCHIP.
#[derive(Clone, Debug, PartialEq)]
pub struct Distribution {
    grid: Vec<f64>,
    values: Vec<f64>,
    slopes: Vec<f64>,
}

impl Distribution {
    /// The PCHIP interpolant of `values` at `grid`.
    ///
    /// Errors: arrays of different lengths ([`Error::CountMismatch`]), fewer than two
    /// points ([`Error::TooFewPoints`]), an entry that is not finite ([`Error::NonFiniteEntry`],
    /// grid and values entries counted together), a grid that does not increase strictly
    /// ([`Error::InvalidSetting`] with the offending grid value).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::Distribution;
    ///
    /// let chord = Distribution::new(vec![0.0, 0.5, 1.0], vec![2.0, 1.5, 1.0])?;
    /// assert_eq!(chord.at(0.5, 0), 1.5); // through its values
    /// assert!(Distribution::new(vec![0.0, 0.0], vec![1.0, 2.0]).is_err()); // grid not increasing
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(grid: Vec<f64>, values: Vec<f64>) -> Result<Distribution> {
        if grid.len() != values.len() {
            return Err(Error::CountMismatch {
                what: "values of a distribution (one per grid point)",
                expected: grid.len(),
                got: values.len(),
            });
        }
        if grid.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "a spanwise distribution",
                needed: 2,
                got: grid.len(),
            });
        }
        if let Some(index) =
            (0..grid.len()).find(|&k| !(grid[k].is_finite() && values[k].is_finite()))
        {
            return Err(Error::NonFiniteEntry {
                what: "grid point or value",
                index,
            });
        }
        if let Some(k) = (1..grid.len()).find(|&k| grid[k] <= grid[k - 1]) {
            return Err(Error::InvalidSetting {
                name: "grid",
                value: grid[k],
                reason: "the grid must increase strictly",
            });
        }
        let mut slopes = vec![0.0; grid.len()];
        pchip_slopes(&grid, &values, &mut slopes);
        Ok(Distribution {
            grid,
            values,
            slopes,
        })
    }

    /// A constant distribution over `[0, 1]`.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::Distribution;
    ///
    /// let twist = Distribution::constant(3.0)?;
    /// assert_eq!((twist.at(0.7, 0), twist.at(0.7, 1)), (3.0, 0.0));
    /// assert!(Distribution::constant(f64::NAN).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn constant(value: f64) -> Result<Distribution> {
        Distribution::new(vec![0.0, 1.0], vec![value, value])
    }

    /// The interpolant's value (`derivative = 0`) or first derivative (`1`) at `s`; outside
    /// the grid the end pieces are extended, as SciPy's `PchipInterpolator` extrapolates.
    pub fn at(&self, s: f64, derivative: usize) -> f64 {
        let n = self.grid.len();
        let k = self.grid[1..n - 1].partition_point(|&g| g <= s);
        let h = self.grid[k + 1] - self.grid[k];
        let b = hermite_basis((s - self.grid[k]) / h, h, derivative);
        b[0] * self.values[k]
            + b[1] * self.slopes[k]
            + b[2] * self.values[k + 1]
            + b[3] * self.slopes[k + 1]
    }

    /// The grid (positions along the span).
    pub fn grid(&self) -> &[f64] {
        &self.grid
    }
}

/// A blade's outer shape as windIO defines it (see the module docs); lengths in the file's
/// units (metres), the twist in degrees.
#[derive(Clone, Debug, PartialEq)]
pub struct BladeShape {
    /// The reference axis `x`, `y`, `z`.
    pub reference_axis: [Distribution; 3],
    /// The chord.
    pub chord: Distribution,
    /// The twist in degrees (positive: leading edge into the wind).
    pub twist: Distribution,
    /// The distance along the chord from the reference axis to the leading edge.
    pub section_offset_y: Distribution,
    /// The chord line's shift towards the suction side (zero when absent).
    pub section_offset_x: Option<Distribution>,
}

impl BladeShape {
    /// The reference axis's point at `s`.
    pub fn axis_point(&self, s: f64) -> Point3 {
        Point3::new(self.reference_axis.each_ref().map(|d| d.at(s, 0)))
    }

    /// The reference axis's length over `[0, 1]` (a polyline of 4,096 steps of the PCHIP axis:
    /// within `1e-7` of it for the reference turbines).
    pub fn axis_length(&self) -> f64 {
        const STEPS: usize = 4096;
        let mut before = self.axis_point(0.0);
        (1..=STEPS).fold(0.0, |sum, k| {
            let p = self.axis_point(k as f64 / STEPS as f64);
            let step = p.distance(before);
            before = p;
            sum + step
        })
    }

    /// The grid positions of every distribution strictly between `a` and `b` (more than
    /// `1e-9` from either), sorted, each once.
    pub fn grid_between(&self, a: f64, b: f64) -> Vec<f64> {
        let mut all: Vec<f64> = self
            .reference_axis
            .iter()
            .chain([&self.chord, &self.twist, &self.section_offset_y])
            .chain(self.section_offset_x.as_ref())
            .flat_map(|d| d.grid().iter().copied())
            .filter(|&g| g > a + 1e-9 && g < b - 1e-9)
            .collect();
        all.sort_by(f64::total_cmp);
        all.dedup_by(|x, y| (*x - *y).abs() <= 1e-9);
        all
    }

    /// The frame of the section at `s` (module docs) and its chord.
    pub fn frame(&self, s: f64) -> (SectionFrame, f64) {
        let t = Point3::new(self.reference_axis.each_ref().map(|d| d.at(s, 1)));
        let t = t * (1.0 / t.norm());
        let a = (-t[1]).clamp(-1.0, 1.0).asin();
        let b = t[0].atan2(t[2]);
        let (sa, ca) = a.sin_cos();
        let (sb, cb) = b.sin_cos();
        // Mxy = My(b) Mx(a), by columns: the images of x, y and z.
        let mx = Point3::new([cb, 0.0, -sb]);
        let my = Point3::new([sb * sa, ca, cb * sa]);
        let correction = (sb * sa).atan2(cb);
        let rz = self.twist.at(s, 0).to_radians() + correction;
        let (sr, cr) = rz.sin_cos();
        // Rz(-rz): the root frame's x and y turned.
        let ex = mx * cr - my * sr;
        let ey = mx * sr + my * cr;
        let chord = self.chord.at(s, 0);
        let oy = self.section_offset_y.at(s, 0);
        let ox = self.section_offset_x.as_ref().map_or(0.0, |d| d.at(s, 0));
        let frame = SectionFrame {
            origin: self.axis_point(s) + ex * ox - ey * oy,
            x_axis: ey * chord,
            y_axis: ex * chord,
        };
        (frame, chord)
    }
}

/// The frames, span stations and chords of a blade's sections at the positions `positions`
/// (increasing, within `[0, 1]`).
///
/// Errors: a reference axis of zero length ([`Error::InvalidSetting`]); naming the section
/// ([`Error::LoftSection`]): a position outside `[0, 1]` or not after the one before, a chord
/// that is not positive there, a reference axis without a tangent there.
pub fn blade_frames(
    shape: &BladeShape,
    positions: &[f64],
) -> Result<(Vec<SectionFrame>, Vec<f64>, Vec<f64>)> {
    let bad = |section: usize, reason: String| Error::LoftSection { section, reason };
    let length = shape.axis_length();
    if !(length.is_finite() && length > 0.0) {
        return Err(Error::InvalidSetting {
            name: "reference axis length",
            value: length,
            reason: "the blade's reference axis must have a positive finite length",
        });
    }
    let mut frames = Vec::with_capacity(positions.len());
    let mut stations = Vec::with_capacity(positions.len());
    let mut chords = Vec::with_capacity(positions.len());
    for (k, &s) in positions.iter().enumerate() {
        if !(0.0..=1.0).contains(&s) {
            return Err(bad(
                k,
                format!("its spanwise position {s} is outside [0, 1]"),
            ));
        }
        if k > 0 && s <= positions[k - 1] {
            return Err(bad(
                k,
                format!(
                    "its spanwise position {s} is not after section {}'s {}",
                    k - 1,
                    positions[k - 1]
                ),
            ));
        }
        let (frame, chord) = shape.frame(s);
        if !(chord.is_finite() && chord > 0.0) {
            return Err(bad(k, format!("the chord {chord} there is not positive")));
        }
        if !(frame.origin.is_finite() && frame.x_axis.is_finite() && frame.y_axis.is_finite()) {
            return Err(bad(
                k,
                "the reference axis has no direction there (its tangent is zero)".into(),
            ));
        }
        frames.push(frame);
        stations.push(s * length);
        chords.push(chord);
    }
    Ok((frames, stations, chords))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::Point2;

    fn straight(twist: f64) -> BladeShape {
        let d = |a: f64, b: f64| Distribution::new(vec![0.0, 1.0], vec![a, b]).unwrap();
        BladeShape {
            reference_axis: [d(0.0, 0.0), d(0.0, 0.0), d(0.0, 10.0)],
            chord: d(2.0, 1.0),
            twist: d(twist, twist),
            section_offset_y: d(0.5, 0.25),
            section_offset_x: None,
        }
    }

    #[test]
    fn pchip_matches_scipy() {
        // scipy.interpolate.PchipInterpolator([0, 1, 3, 4], [0, 2, 3, 1])(x, nu) at x = 0.5, 2.
        let d = Distribution::new(vec![0.0, 1.0, 3.0, 4.0], vec![0.0, 2.0, 3.0, 1.0]).unwrap();
        assert!(
            (d.at(0.5, 0) - 1.2053571428571428).abs() < 1e-12,
            "{}",
            d.at(0.5, 0)
        );
        assert!(
            (d.at(2.0, 0) - 2.7142857142857144).abs() < 1e-12,
            "{}",
            d.at(2.0, 0)
        );
        assert!(
            (d.at(2.0, 1) - 0.5357142857142857).abs() < 1e-12,
            "{}",
            d.at(2.0, 1)
        );
    }

    #[test]
    fn a_straight_blade_puts_the_leading_edge_upstream_of_the_axis() {
        let (frames, stations, chords) = blade_frames(&straight(0.0), &[0.0, 1.0]).unwrap();
        assert_eq!(stations, vec![0.0, 10.0]);
        assert_eq!(chords, vec![2.0, 1.0]);
        // Leading edge 0.5 ahead of the axis (towards -y), trailing edge at 2 - 0.5.
        let le = frames[0].place(Point2::new([0.0, 0.0]));
        let te = frames[0].place(Point2::new([1.0, 0.0]));
        assert!(le.distance(Point3::new([0.0, -0.5, 0.0])) < 1e-15, "{le:?}");
        assert!(te.distance(Point3::new([0.0, 1.5, 0.0])) < 1e-15, "{te:?}");
        // The suction side towards +x.
        let up = frames[1].place(Point2::new([0.0, 0.1]));
        assert!(
            up.distance(Point3::new([0.1, -0.25, 10.0])) < 1e-15,
            "{up:?}"
        );
    }

    #[test]
    fn a_positive_twist_turns_the_leading_edge_into_the_wind() {
        let (frames, ..) = blade_frames(&straight(30.0), &[0.0, 1.0]).unwrap();
        let le = frames[0].place(Point2::new([0.0, 0.0]));
        let te = frames[0].place(Point2::new([1.0, 0.0]));
        assert!(le[0] < 0.0 && te[0] > 0.0, "{le:?} {te:?}");
        assert!((le[0] + 0.5 * 0.5).abs() < 1e-12, "{le:?}");
    }

    #[test]
    fn sections_stand_normal_to_a_bent_axis() {
        let mut shape = straight(0.0);
        shape.reference_axis[0] =
            Distribution::new(vec![0.0, 0.5, 1.0], vec![0.0, -0.5, -2.0]).unwrap();
        let (frames, ..) = blade_frames(&shape, &[0.3, 0.9]).unwrap();
        for (f, s) in frames.iter().zip([0.3, 0.9]) {
            let t = Point3::new(shape.reference_axis.each_ref().map(|d| d.at(s, 1)));
            assert!(f.x_axis.dot(t).abs() < 1e-12 && f.y_axis.dot(t).abs() < 1e-12);
        }
        let e = blade_frames(&shape, &[0.3, 0.3]).unwrap_err();
        assert!(matches!(e, Error::LoftSection { section: 1, .. }), "{e}");
    }
}

//! Where a section's plane coordinates go in space: [`SectionFrame`], an affine map, and the
//! frames of a wing's sections placed as aerosandbox's `WingXSec` places them
//! ([`wing_frames`], docs/methods.md §7.1).
//!
//! Axes of a wing: `x` downstream (leading edge to trailing edge), `y` along the span (out
//! along the right wing), `z` up. A section's profile is in unit chord, `(x, y)` with the
//! leading edge at the origin and `y` towards the upper side. Its untwisted frame has the
//! chord along `+x`; the span direction `s` is the direction from the section's leading edge to
//! the next one's (the previous one's for the last section) projected onto the `y`-`z` plane,
//! and at an inner section the normalised mean of the directions in and out, with the profile's
//! `y` axis stretched by `sqrt(2 / (1 + cos a))` (`a` the angle between them) so that the wing
//! keeps its thickness across the kink. A section's own dihedral `d`, when given, replaces that
//! direction by `s = (0, cos d, sin d)` without the stretch. The profile's `y` axis is then
//! `x × s` (up for a flat right wing), and the twist turns both axes about `s` by the right-hand
//! rule: a positive twist raises the leading edge (nose up). A point `(px, py)` of the profile
//! lies at `le + chord (px X + py Y)`.

use crate::{Error, Point2, Point3, Result};

/// The affine map of a section's plane coordinates into space:
/// `(px, py) -> origin + px x_axis + py y_axis`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SectionFrame {
    /// Where the origin of the section's plane goes.
    pub origin: Point3,
    /// Where the unit vector along the section's `x` goes (its length is the scale).
    pub x_axis: Point3,
    /// Where the unit vector along the section's `y` goes.
    pub y_axis: Point3,
}

impl SectionFrame {
    /// The point of space of the plane point `p`.
    #[inline]
    pub fn place(&self, p: Point2) -> Point3 {
        self.origin
            .add_scaled(p[0], self.x_axis)
            .add_scaled(p[1], self.y_axis)
    }

    /// The largest factor by which the map stretches a distance of the plane.
    pub fn stretch(&self) -> f64 {
        // The largest singular value of [x_axis y_axis], computed on the axes over their
        // largest component: the Gram matrix's entries are squares of lengths and its
        // discriminant their fourth powers, which overflow for chords beyond about 1e77.
        let unit = self.x_axis.max_abs().max(self.y_axis.max_abs());
        if !(unit > 0.0 && unit.is_finite()) {
            return unit;
        }
        let over_unit = |p: Point3| Point3::new(p.0.map(|c| c / unit));
        let (x, y) = (over_unit(self.x_axis), over_unit(self.y_axis));
        let (a, b, c) = (x.norm_sq(), x.dot(y), y.norm_sq());
        let mean = 0.5 * (a + c);
        let spread = (0.25 * (a - c) * (a - c) + b * b).sqrt();
        (mean + spread).sqrt() * unit
    }
}

/// The placement of one wing section, as a row of a sections table or an aerosandbox
/// `WingXSec`: leading edge, chord, twist and an optional dihedral (both in degrees).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct WingPlacement {
    /// The leading edge.
    pub leading_edge: Point3,
    /// The chord (the profile's unit length).
    pub chord: f64,
    /// The twist in degrees about the section's span direction (positive: nose up).
    pub twist: f64,
    /// The section's dihedral in degrees (its span direction `(0, cos d, sin d)`), or `None`
    /// for aerosandbox's direction from the neighbouring leading edges.
    pub dihedral: Option<f64>,
}

/// The frames of a wing's sections (see the module docs), and their span stations: the
/// distance from the first leading edge along the leading edges' polyline projected onto the
/// `y`-`z` plane (aerosandbox's span).
///
/// Errors ([`Error::LoftSection`] naming the section): fewer than two sections, a non-finite
/// or non-positive chord, a non-finite twist or dihedral, two leading edges at one span
/// station (their `y`-`z` distance below `1e-9` of the wing's size), or a section whose leading
/// edge turns back along the span (more than 90 degrees from the direction before it).
pub fn wing_frames(sections: &[WingPlacement]) -> Result<(Vec<SectionFrame>, Vec<f64>)> {
    let n = sections.len();
    if n < 2 {
        return Err(Error::TooFewPoints {
            what: "a loft (sections)",
            needed: 2,
            got: n,
        });
    }
    check_placements(sections)?;
    let (steps, stations) = span_steps(sections)?;
    let frames = sections
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let (span, z_scale) = match s.dihedral {
                Some(d) => {
                    let d = d.to_radians();
                    (Point3::new([0.0, d.cos(), d.sin()]), 1.0)
                }
                None if k == 0 => (steps[0], 1.0),
                None if k == n - 1 => (steps[n - 2], 1.0),
                None => {
                    let (a, b) = (steps[k - 1], steps[k]);
                    let mean = (a + b) * 0.5;
                    (mean * (1.0 / mean.norm()), (2.0 / (a.dot(b) + 1.0)).sqrt())
                }
            };
            let x = Point3::new([1.0, 0.0, 0.0]);
            let z = cross(x, span) * z_scale;
            let twist = s.twist.to_radians();
            SectionFrame {
                origin: s.leading_edge,
                x_axis: rotate(x, span, twist) * s.chord,
                y_axis: rotate(z, span, twist) * s.chord,
            }
        })
        .collect();
    Ok((frames, stations))
}

/// The error of section `section` for `reason`.
fn bad(section: usize, reason: String) -> Error {
    Error::LoftSection { section, reason }
}

/// Checks that every leading edge, chord, twist and dihedral is finite and every chord
/// positive.
fn check_placements(sections: &[WingPlacement]) -> Result<()> {
    for (k, s) in sections.iter().enumerate() {
        if !s.leading_edge.is_finite() {
            return Err(bad(k, "the leading edge is not finite".into()));
        }
        if !(s.chord.is_finite() && s.chord > 0.0) {
            return Err(bad(k, format!("the chord {} is not positive", s.chord)));
        }
        if !s.twist.is_finite() || s.dihedral.is_some_and(|d| !d.is_finite()) {
            return Err(bad(k, "the twist or dihedral is not finite".into()));
        }
    }
    Ok(())
}

/// The unit `y`-`z` directions of the leading-edge polyline's steps and the span stations;
/// errors for two leading edges at one station or one turning back along the span.
fn span_steps(sections: &[WingPlacement]) -> Result<(Vec<Point3>, Vec<f64>)> {
    let n = sections.len();
    let size = sections.iter().fold(0.0f64, |m, s| {
        m.max((s.leading_edge - sections[0].leading_edge).max_abs())
            .max(s.chord)
    });
    // The y-z directions of the leading-edge polyline's steps.
    let mut steps = Vec::with_capacity(n - 1);
    let mut stations = vec![0.0; n];
    for k in 1..n {
        let d = sections[k].leading_edge - sections[k - 1].leading_edge;
        let length = d[1].hypot(d[2]);
        if length.is_nan() || length <= 1e-9 * size {
            return Err(bad(
                k,
                format!(
                    "its leading edge is at the span station of section {} (y-z distance {length})",
                    k - 1
                ),
            ));
        }
        let step = Point3::new([0.0, d[1] / length, d[2] / length]);
        if let Some(&before) = steps.last() {
            if step.dot(before) < 0.0 {
                return Err(bad(
                    k,
                    format!(
                        "the stations are out of order: its leading edge turns back along the span \
                         from section {}",
                        k - 1
                    ),
                ));
            }
        }
        steps.push(step);
        stations[k] = stations[k - 1] + length;
    }
    Ok((steps, stations))
}

/// `a × b`.
pub(crate) fn cross(a: Point3, b: Point3) -> Point3 {
    Point3::new([
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ])
}

/// `v` turned by `angle` (radians, right-hand rule) about the unit `axis` (Rodrigues).
pub(crate) fn rotate(v: Point3, axis: Point3, angle: f64) -> Point3 {
    let (s, c) = angle.sin_cos();
    v * c + cross(axis, v) * s + axis * (axis.dot(v) * (1.0 - c))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn at(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new([x, y, z])
    }

    #[test]
    fn the_stretch_holds_at_every_scale() {
        // Axes of lengths 3 and 2, 60 degrees apart: the Gram matrix [[9, 3], [3, 4]] has
        // the largest eigenvalue (13 + sqrt(61)) / 2.
        let exact = ((13.0 + 61f64.sqrt()) / 2.0).sqrt();
        let half = 3f64.sqrt();
        for scale in [1e-300, 1e-150, 1e-5, 1.0, 1e5, 1e100, 1e150, 1e300] {
            let frame = SectionFrame {
                origin: at(1e8, -2e8, 0.0),
                x_axis: at(3.0 * scale, 0.0, 0.0),
                y_axis: at(scale, half * scale, 0.0),
            };
            let stretch = frame.stretch();
            assert!(
                (stretch / scale - exact).abs() < 1e-14 * exact,
                "{scale}: {stretch}"
            );
        }
        let flat = SectionFrame {
            origin: at(0.0, 0.0, 0.0),
            x_axis: at(0.0, 0.0, 0.0),
            y_axis: at(0.0, 0.0, 0.0),
        };
        assert_eq!(flat.stretch(), 0.0);
    }

    #[test]
    fn a_flat_untwisted_wing_keeps_its_axes() {
        let place = |y: f64, chord: f64| WingPlacement {
            leading_edge: at(0.1 * y, y, 0.0),
            chord,
            twist: 0.0,
            dihedral: None,
        };
        let (frames, stations) = wing_frames(&[place(0.0, 2.0), place(3.0, 1.0)]).unwrap();
        assert_eq!(stations, vec![0.0, 3.0]);
        assert_eq!(frames[0].x_axis, at(2.0, 0.0, 0.0));
        assert_eq!(frames[0].y_axis, at(0.0, 0.0, 2.0));
        assert_eq!(frames[1].place(Point2::new([1.0, 0.0])), at(1.3, 3.0, 0.0));
    }

    #[test]
    fn positive_twist_raises_the_nose_and_a_kink_stretches_the_thickness() {
        let (frames, _) = wing_frames(&[
            WingPlacement {
                leading_edge: at(0.0, 0.0, 0.0),
                chord: 1.0,
                twist: 10.0,
                dihedral: None,
            },
            WingPlacement {
                leading_edge: at(0.0, 1.0, 0.0),
                chord: 1.0,
                twist: 0.0,
                dihedral: None,
            },
            WingPlacement {
                leading_edge: at(0.0, 2.0, 1.0),
                chord: 1.0,
                twist: 0.0,
                dihedral: None,
            },
        ])
        .unwrap();
        // Trailing edge below the leading edge: nose up.
        let te = frames[0].place(Point2::new([1.0, 0.0]));
        assert!((te[2] + 10f64.to_radians().sin()).abs() < 1e-15);
        // 45 degrees kink at section 1: the thickness axis is stretched 1 / cos(22.5 deg).
        let stretch = frames[1].y_axis.norm();
        assert!((stretch - 1.0 / 22.5f64.to_radians().cos()).abs() < 1e-14);
        assert!(frames[1].y_axis.dot(at(0.0, 1.0, 0.0)) < 0.0);
    }

    #[test]
    fn stations_out_of_order_or_together_are_refused() {
        let place = |y: f64| WingPlacement {
            leading_edge: at(0.0, y, 0.0),
            chord: 1.0,
            twist: 0.0,
            dihedral: None,
        };
        let e = wing_frames(&[place(0.0), place(1.0), place(1.0)]).unwrap_err();
        assert!(matches!(e, Error::LoftSection { section: 2, .. }), "{e}");
        let e = wing_frames(&[place(0.0), place(2.0), place(1.0)]).unwrap_err();
        assert!(e.to_string().contains("out of order"), "{e}");
    }
}

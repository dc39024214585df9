//! The loft itself: [`Loft`], a tensor-product B-spline surface through placed sections, and
//! what it reports (docs/methods.md §7).

use super::blade::{blade_frames, BladeShape};
use super::compatible::{basis_at, fit_compatible, CompatibleFit, FitSection};
use super::placement::{wing_frames, SectionFrame, WingPlacement};
use super::profile::Profile;
use super::span::{span_surface, KeptLines, SpanRule};
use crate::bspline::{BSplineCurve, BSplineSurface, ToBSplineSurface};
use crate::core::{Grid, Interval, Surface};
use crate::{Error, Point2, Point3, Result};

/// The default tolerance of a loft: the largest distance of a section's points from the
/// surface, as a share of the section's chord (its scale).
pub const DEFAULT_TOLERANCE: f64 = 1e-5;

/// One section of a loft: its points in its own plane, where that plane goes in space, its
/// span station and the length its tolerance is a share of.
#[derive(Clone, Debug, PartialEq)]
pub struct LoftSection {
    /// The points, in order, with the point at `v = 1/2` if any.
    pub profile: Profile,
    /// Where the plane coordinates go in space.
    pub frame: SectionFrame,
    /// The span station (the surface's `u` at this section); stations must increase.
    pub station: f64,
    /// The length the tolerance is a share of (a wing section's chord).
    pub scale: f64,
}

/// What a loft is built with.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LoftOptions {
    /// How the surface runs between sections.
    pub rule: SpanRule,
    /// The largest distance of a section's points from the surface, as a share of its scale.
    pub tolerance: f64,
}

impl Default for LoftOptions {
    fn default() -> Self {
        LoftOptions {
            rule: SpanRule::default(),
            tolerance: DEFAULT_TOLERANCE,
        }
    }
}

/// A surface lofted through sections (docs/methods.md §7): `u` runs along the span (the
/// stations), `v` along each section over `[0, 1]` (an airfoil's leading edge at `v = 1/2`,
/// its trailing-edge ends at 0 and 1). The surface at `u = station` is the section's fitted
/// curve, placed; every section's points lie within the tolerance of it unless
/// [`tolerance_met`](Self::tolerance_met) says otherwise.
#[derive(Clone, Debug, PartialEq)]
pub struct Loft {
    pub(super) surface: BSplineSurface<3>,
    pub(super) stations: Vec<f64>,
    pub(super) deviations: Vec<f64>,
    pub(super) scales: Vec<f64>,
    pub(super) options: LoftOptions,
    pub(super) split: bool,
    pub(super) rounds: usize,
}

impl Loft {
    /// Lofts `sections` (at least two, in span order).
    ///
    /// Errors: fewer than two sections, a tolerance that is not positive and finite
    /// ([`Error::InvalidSetting`]); [`Error::LoftSection`] naming the section for a station
    /// that is not finite or not after the one before, a scale that is not positive, or a
    /// section with a middle point (a leading edge) among sections without one or the other
    /// way round.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::{Loft, LoftOptions, LoftSection, Profile, SectionFrame};
    /// use karkas::Point;
    ///
    /// let foil: Vec<_> = (0..=40)
    ///     .map(|k| {
    ///         let a = k as f64 * std::f64::consts::TAU / 40.0;
    ///         Point([(1.0 + a.cos()) / 2.0, 0.06 * a.sin()])
    ///     })
    ///     .collect();
    /// let profile = Profile::airfoil(&foil)?;
    /// // The section in the plane z = station, its chord along x.
    /// let section = |z: f64| LoftSection {
    ///     profile: profile.clone(),
    ///     frame: SectionFrame { origin: Point([0.0, 0.0, z]), x_axis: Point([1.0, 0.0, 0.0]), y_axis: Point([0.0, 1.0, 0.0]) },
    ///     station: z,
    ///     scale: 1.0,
    /// };
    /// let loft = Loft::new(&[section(0.0), section(2.0)], &LoftOptions::default())?;
    /// assert_eq!(loft.stations(), &[0.0, 2.0]);
    /// assert!(loft.tolerance_met());
    /// assert!(Loft::new(&[section(0.0)], &LoftOptions::default()).is_err()); // one section
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn new(sections: &[LoftSection], options: &LoftOptions) -> Result<Loft> {
        let (fit, split) = Loft::fit(sections, options)?;
        let profiles = Grid::from_fn(sections.len(), fit.controls[0].len(), |k, i| {
            fit.controls[k][i]
        });
        // The deviations in model units: at most the plane's by the frame's stretch.
        let deviations = fit
            .deviations
            .iter()
            .zip(sections)
            .map(|(d, s)| d * s.frame.stretch())
            .collect();
        Loft::assemble(
            options,
            (split, fit.rounds),
            fit.knots,
            (sections.iter().map(|s| s.frame).collect(), profiles),
            sections.iter().map(|s| s.station).collect(),
            deviations,
            sections.iter().map(|s| s.scale).collect(),
        )
    }

    /// Checks `sections` (see [`new`](Self::new)) and fits them on one knot vector; true
    /// when they have a middle point.
    fn fit(sections: &[LoftSection], options: &LoftOptions) -> Result<(CompatibleFit, bool)> {
        if sections.len() < 2 {
            return Err(Error::TooFewPoints {
                what: "a loft (sections)",
                needed: 2,
                got: sections.len(),
            });
        }
        if !(options.tolerance.is_finite() && options.tolerance > 0.0) {
            return Err(Error::InvalidSetting {
                name: "tolerance",
                value: options.tolerance,
                reason: "it must be a positive number",
            });
        }
        let bad = |section: usize, reason: String| Error::LoftSection { section, reason };
        let split = sections[0].profile.split().is_some();
        for (k, s) in sections.iter().enumerate() {
            if !s.station.is_finite() {
                return Err(bad(k, "its station is not finite".into()));
            }
            if k > 0 {
                let before = sections[k - 1].station;
                if s.station == before {
                    return Err(bad(
                        k,
                        format!(
                            "two sections at one station: section {} is at {before} too",
                            k - 1
                        ),
                    ));
                }
                if s.station < before {
                    return Err(bad(
                        k,
                        format!(
                            "the stations are out of order: {} comes after section {}'s {before}",
                            s.station,
                            k - 1
                        ),
                    ));
                }
            }
            if !(s.scale.is_finite() && s.scale > 0.0) {
                return Err(bad(k, format!("its scale {} is not positive", s.scale)));
            }
            if s.profile.split().is_some() != split {
                return Err(bad(
                    k,
                    format!(
                        "its correspondence with section 0 cannot be made: one has a leading edge \
                         (a middle point at v = 1/2) and the other {}",
                        "none"
                    ),
                ));
            }
        }
        let fit_sections: Vec<FitSection> = sections
            .iter()
            .map(|s| FitSection {
                points: s.profile.points(),
                split: s.profile.split(),
                tolerance: options.tolerance * s.scale / s.frame.stretch().max(f64::MIN_POSITIVE),
            })
            .collect();
        Ok((fit_compatible(&fit_sections)?, split))
    }

    /// The loft of the control nets `profiles` (a row per station, in the sections' planes)
    /// placed by `frames`, on the sections' knots.
    fn assemble(
        options: &LoftOptions,
        (split, rounds): (bool, usize),
        knots: Vec<f64>,
        (frames, profiles): (Vec<SectionFrame>, Grid<Point2>),
        stations: Vec<f64>,
        deviations: Vec<f64>,
        scales: Vec<f64>,
    ) -> Result<Loft> {
        let nets = Grid::from_fn(profiles.rows(), profiles.cols(), |k, i| {
            frames[k].place(*profiles.get(k, i))
        });
        let kept = KeptLines {
            leading_edge: split.then(|| basis_at(&knots, 0.5)),
            placement: Some((&frames, &profiles)),
            tolerance: options.tolerance,
        };
        let surface = span_surface(options.rule, &stations, &nets, knots, kept)?;
        Ok(Loft {
            surface,
            stations,
            deviations,
            scales,
            options: *options,
            split,
            rounds,
        })
    }

    /// Lofts a wing: airfoil `profiles` in unit chord (Selig's order or the other way round)
    /// placed as aerosandbox's `WingXSec` places them ([`wing_frames`]), at the span stations
    /// it gives; each section's tolerance is a share of its chord.
    ///
    /// Errors: as [`Profile::airfoil`], [`wing_frames`] and [`new`](Self::new), each naming
    /// the section ([`Error::LoftSection`]); a count of profiles that differs from that of
    /// placements ([`Error::CountMismatch`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::{Loft, LoftOptions, WingPlacement};
    /// use karkas::Point;
    ///
    /// let foil: Vec<_> = (0..=40)
    ///     .map(|k| {
    ///         let a = k as f64 * std::f64::consts::TAU / 40.0;
    ///         Point([(1.0 + a.cos()) / 2.0, 0.06 * a.sin()])
    ///     })
    ///     .collect();
    /// // A tapered wing: chord 1 at the root, 0.7 at the tip 3 units out along y.
    /// let placements = [(0.0, 1.0), (3.0, 0.7)].map(|(y, chord)| WingPlacement {
    ///     leading_edge: Point([0.0, y, 0.0]),
    ///     chord,
    ///     twist: 0.0,
    ///     dihedral: None,
    /// });
    /// let wing = Loft::wing(&[foil.clone(), foil.clone()], &placements, &LoftOptions::default())?;
    /// assert_eq!(wing.stations().len(), 2);
    /// assert!(wing.tolerance_met());
    /// assert!(Loft::wing(&[foil], &placements, &LoftOptions::default()).is_err()); // one profile, two placements
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn wing(
        profiles: &[Vec<Point2>],
        placements: &[WingPlacement],
        options: &LoftOptions,
    ) -> Result<Loft> {
        if profiles.len() != placements.len() {
            return Err(Error::CountMismatch {
                what: "profiles of a wing (one per placement)",
                expected: placements.len(),
                got: profiles.len(),
            });
        }
        let (frames, stations) = wing_frames(placements)?;
        let chords: Vec<f64> = placements.iter().map(|p| p.chord).collect();
        Loft::new(
            &airfoil_sections(profiles, &frames, &stations, &chords)?,
            options,
        )
    }

    /// Lofts a wind-turbine blade: airfoil `profiles` in unit chord at the nondimensional
    /// `positions` along its reference axis, placed as windIO places them ([`blade_frames`]);
    /// each section's tolerance is a share of its chord. Between two airfoils the surface
    /// also passes through a section at every grid position of the shape's distributions
    /// (chord, twist, offsets, reference axis), placed there as windIO places it, whose
    /// profile is the two airfoils' fitted curves blended linearly in the position (their
    /// control points, on the shared knots): the chord, twist, offsets and axis then follow
    /// the file's distributions along the whole span, not only at the airfoils. Those
    /// sections have no points of their own: their [`deviations`](Self::deviations) are 0.
    ///
    /// Errors: as [`Profile::airfoil`], [`blade_frames`] and [`new`](Self::new), each naming
    /// the section ([`Error::LoftSection`]); a count of profiles that differs from that of
    /// positions ([`Error::CountMismatch`]); a chord that is not positive at a grid position
    /// ([`Error::InvalidSetting`]).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::loft::{BladeShape, Distribution, Loft, LoftOptions};
    /// use karkas::Point;
    ///
    /// let foil: Vec<_> = (0..=40)
    ///     .map(|k| {
    ///         let a = k as f64 * std::f64::consts::TAU / 40.0;
    ///         Point([(1.0 + a.cos()) / 2.0, 0.06 * a.sin()])
    ///     })
    ///     .collect();
    /// // A straight blade 10 long along z, its chord falling from 2 to 1.
    /// let constant = Distribution::constant;
    /// let shape = BladeShape {
    ///     reference_axis: [constant(0.0)?, constant(0.0)?, Distribution::new(vec![0.0, 1.0], vec![0.0, 10.0])?],
    ///     chord: Distribution::new(vec![0.0, 1.0], vec![2.0, 1.0])?,
    ///     twist: constant(0.0)?,
    ///     section_offset_y: constant(0.5)?,
    ///     section_offset_x: None,
    /// };
    /// let blade = Loft::blade(&[foil.clone(), foil], &[0.0, 1.0], &shape, &LoftOptions::default())?;
    /// assert!(blade.tolerance_met());
    /// assert!(Loft::blade(&[], &[0.0, 1.0], &shape, &LoftOptions::default()).is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn blade(
        profiles: &[Vec<Point2>],
        positions: &[f64],
        shape: &BladeShape,
        options: &LoftOptions,
    ) -> Result<Loft> {
        if profiles.len() != positions.len() {
            return Err(Error::CountMismatch {
                what: "profiles of a blade (one per position)",
                expected: positions.len(),
                got: profiles.len(),
            });
        }
        let (frames, stations, chords) = blade_frames(shape, positions)?;
        let sections = airfoil_sections(profiles, &frames, &stations, &chords)?;
        let (fit, split) = Loft::fit(&sections, options)?;
        let length = shape.axis_length();
        let mut rows: Vec<Vec<Point2>> = Vec::new();
        let mut placed = Vec::new();
        let (mut at, mut deviations, mut scales) = (Vec::new(), Vec::new(), Vec::new());
        for (k, &s) in positions.iter().enumerate() {
            if k > 0 {
                let (a, b) = (&fit.controls[k - 1], &fit.controls[k]);
                for g in shape.grid_between(positions[k - 1], s) {
                    let w = (g - positions[k - 1]) / (s - positions[k - 1]);
                    let (frame, chord) = shape.frame(g);
                    if !(chord.is_finite() && chord > 0.0) {
                        return Err(Error::InvalidSetting {
                            name: "chord",
                            value: chord,
                            reason: "the chord between two airfoils must be positive",
                        });
                    }
                    rows.push(a.iter().zip(b).map(|(&p, &q)| p + (q - p) * w).collect());
                    placed.push(frame);
                    at.push(g * length);
                    deviations.push(0.0);
                    scales.push(chord);
                }
            }
            rows.push(fit.controls[k].clone());
            placed.push(frames[k]);
            at.push(stations[k]);
            deviations.push(fit.deviations[k] * frames[k].stretch());
            scales.push(chords[k]);
        }
        let m = rows[0].len();
        let profiles = Grid::from_fn(rows.len(), m, |k, i| rows[k][i]);
        Loft::assemble(
            options,
            (split, fit.rounds),
            fit.knots,
            (placed, profiles),
            at,
            deviations,
            scales,
        )
    }

    /// The B-spline surface (degree 1 or 3 along the span, 3 along the sections).
    pub fn surface(&self) -> &BSplineSurface<3> {
        &self.surface
    }

    /// The span stations of the sections (the surface's `u` at each).
    pub fn stations(&self) -> &[f64] {
        &self.stations
    }

    /// The surface's section at span station `station` (clamped to the span): the curve
    /// `v -> S(station, v)`.
    pub fn section_at(&self, station: f64) -> BSplineCurve<3> {
        self.surface.curve_at_u(station)
    }

    /// The largest distance of each section's points from the surface at its station, in
    /// model units (an upper bound: the distance to the foot point the fit found).
    pub fn deviations(&self) -> &[f64] {
        &self.deviations
    }

    /// The largest of [`deviations`](Self::deviations), each over its section's scale.
    pub fn max_relative_deviation(&self) -> f64 {
        self.deviations
            .iter()
            .zip(&self.scales)
            .fold(0.0, |m, (d, s)| m.max(d / s))
    }

    /// True when every section's points lie within the tolerance of the surface.
    pub fn tolerance_met(&self) -> bool {
        self.deviations
            .iter()
            .zip(&self.scales)
            .all(|(d, s)| *d <= self.options.tolerance * s * (1.0 + 1e-9))
    }

    /// What the loft was built with.
    pub fn options(&self) -> &LoftOptions {
        &self.options
    }

    /// The surface's `v` of the sections' leading edges (1/2), when they have one.
    pub fn leading_edge_v(&self) -> Option<f64> {
        self.split.then_some(0.5)
    }

    /// The rounds of knot refinement the sections' fit took.
    pub fn rounds(&self) -> usize {
        self.rounds
    }

    /// The control points along the span and along the sections.
    pub fn control_counts(&self) -> (usize, usize) {
        let grid = self.surface.control_points();
        (grid.rows(), grid.cols())
    }
}

/// Airfoil sections: each profile read by [`Profile::airfoil`], with its frame, station and
/// chord (its scale).
fn airfoil_sections(
    profiles: &[Vec<Point2>],
    frames: &[SectionFrame],
    stations: &[f64],
    chords: &[f64],
) -> Result<Vec<LoftSection>> {
    profiles
        .iter()
        .enumerate()
        .map(|(k, points)| {
            Ok(LoftSection {
                profile: Profile::airfoil(points).map_err(|e| in_section(k, e))?,
                frame: frames[k],
                station: stations[k],
                scale: chords[k],
            })
        })
        .collect()
}

/// `e` as the error of section `k`.
fn in_section(k: usize, e: Error) -> Error {
    match e {
        Error::LoftSection { reason, .. } => Error::LoftSection { section: k, reason },
        other => Error::LoftSection {
            section: k,
            reason: other.to_string(),
        },
    }
}

impl Surface<3> for Loft {
    fn domain_u(&self) -> Interval {
        self.surface.domain_u()
    }

    fn domain_v(&self) -> Interval {
        self.surface.domain_v()
    }

    fn is_closed_u(&self) -> bool {
        false
    }

    fn is_closed_v(&self) -> bool {
        false
    }

    fn eval(&self, u: f64, v: f64) -> Point3 {
        self.surface.eval(u, v)
    }

    fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point3 {
        self.surface.deriv(u, v, ku, kv)
    }
}

impl ToBSplineSurface<3> for Loft {
    fn to_bspline(&self) -> Result<BSplineSurface<3>> {
        Ok(self.surface.clone())
    }
}

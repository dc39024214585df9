//! The kinds of Coons surfaces by name, and the tolerances of networks given by points: what
//! the command line's `surface coons` and Python's `CoonsSurface` both build from (Chashnikov;
//! docs/methods.md §2).

use core::str::FromStr;

use super::blending::SplineEnds;
use super::network::{CrossDerivatives, CurveNetwork};
use super::surface::{Compatibility, CoonsSurface};
use crate::{Error, Result};

/// How far apart (relative to the model size) a point of a u-curve and a point of a v-curve
/// may be and still be their crossing, for networks given by points (the default of the
/// command line and of Python's `crossing_tolerance=`).
pub const CROSSING_TOLERANCE: f64 = 1e-6;

/// The tolerance of the compatibility conditions (8) / (11), relative to the model size (per
/// node spacing for derivatives), for networks given by points: cross-derivative data are
/// interpolated like the curves, so they agree with the curves' own tangents only to the
/// interpolation error (the default of the command line and of Python's `tolerance=`).
pub const POINT_NETWORK_TOLERANCE: f64 = 1e-4;

/// A kind of Coons surface over a curve network.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CoonsKind {
    /// Bilinear Coons: two u-curves and two v-curves ([`CoonsSurface::bilinear`]).
    Bilinear,
    /// Bicubic Coons with cross-derivatives ([`CoonsSurface::bicubic`]).
    Bicubic,
    /// Gordon surface with Lagrange blending ([`CoonsSurface::gordon`]).
    Gordon,
    /// Gordon surface with not-a-knot cubic-spline blending, periodic in a closed direction
    /// ([`CoonsSurface::gordon_spline`]).
    GordonSpline,
    /// Composite (C^1, piecewise bicubic) Coons surface ([`CoonsSurface::composite`]).
    Composite,
}

impl CoonsKind {
    /// Every kind, in the order of [`Self::NAMES`].
    pub const ALL: [CoonsKind; 5] = [
        CoonsKind::Bilinear,
        CoonsKind::Bicubic,
        CoonsKind::Gordon,
        CoonsKind::GordonSpline,
        CoonsKind::Composite,
    ];

    /// The names [`FromStr`] accepts, one a kind.
    pub const NAMES: &'static [&'static str] = &[
        "bilinear",
        "bicubic",
        "gordon",
        "gordon-spline",
        "composite",
    ];

    /// The name of the kind.
    pub fn name(self) -> &'static str {
        match self {
            CoonsKind::Bilinear => "bilinear",
            CoonsKind::Bicubic => "bicubic",
            CoonsKind::Gordon => "gordon",
            CoonsKind::GordonSpline => "gordon-spline",
            CoonsKind::Composite => "composite",
        }
    }

    /// True for the kinds that take cross-derivatives (bicubic and composite).
    pub fn takes_cross_derivatives(self) -> bool {
        matches!(self, CoonsKind::Bicubic | CoonsKind::Composite)
    }

    /// The surface of this kind over `network` (cross-derivatives used by bicubic and
    /// composite surfaces only; `compatibility`: the tolerance of the compatibility
    /// conditions, or [`Compatibility::Repair`]).
    pub fn build<const D: usize>(
        self,
        network: &CurveNetwork<D>,
        cross: Option<&CrossDerivatives<D>>,
        compatibility: impl Into<Compatibility>,
    ) -> Result<CoonsSurface<D>> {
        let tolerance = compatibility.into();
        match self {
            CoonsKind::Bilinear => CoonsSurface::bilinear(network, tolerance),
            CoonsKind::Bicubic => CoonsSurface::bicubic(network, cross, tolerance),
            CoonsKind::Gordon => CoonsSurface::gordon(network, tolerance),
            CoonsKind::GordonSpline => {
                CoonsSurface::gordon_spline(network, SplineEnds::NotAKnot, tolerance)
            }
            CoonsKind::Composite => CoonsSurface::composite(network, cross, tolerance),
        }
    }
}

impl FromStr for CoonsKind {
    type Err = Error;

    /// Parses one of [`Self::NAMES`]; `gordon_spline` (an underscore) is accepted too.
    fn from_str(name: &str) -> Result<Self> {
        let wanted = name.replace('_', "-");
        CoonsKind::ALL
            .into_iter()
            .find(|k| k.name() == wanted)
            .ok_or_else(|| Error::UnknownName {
                what: "kind of Coons surface",
                name: name.to_owned(),
                expected: Self::NAMES,
            })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_parse_to_their_kinds() {
        for (kind, name) in CoonsKind::ALL.into_iter().zip(CoonsKind::NAMES) {
            assert_eq!(kind.name(), *name);
            assert_eq!(name.parse::<CoonsKind>().unwrap(), kind);
        }
        assert!("coons".parse::<CoonsKind>().is_err());
    }
}

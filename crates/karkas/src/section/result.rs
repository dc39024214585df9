//! What a section returns: its curves and the warnings met while tracing them.

use crate::Point;
use core::fmt;

/// One connected piece of a section: a polyline on the surface.
#[derive(Clone, Debug, PartialEq)]
pub struct SectionCurve<const D: usize> {
    /// The surface parameters `(u, v)` of the points (in the domain; a closed direction is
    /// wrapped into its period, so the parameters jump by a period where the curve crosses the
    /// seam, and a curve through a pole, a border line that is one point, leaves it at other
    /// parameters than it came in by).
    pub params: Vec<(f64, f64)>,
    /// The points: `points[k]` is the surface's `eval(params[k])`, on the level set to the
    /// precision of the floating point arithmetic.
    pub points: Vec<Point<D>>,
    /// True for a closed curve: the last point joins the first (which is not repeated).
    pub closed: bool,
}

impl<const D: usize> SectionCurve<D> {
    /// The length of the polyline (the closing chord included for a closed curve).
    pub fn length(&self) -> f64 {
        let open: f64 = self.points.windows(2).map(|w| w[0].distance(w[1])).sum();
        match (self.closed, self.points.first(), self.points.last()) {
            (true, Some(first), Some(last)) => open + first.distance(*last),
            _ => open,
        }
    }
}

/// A section of a surface: every piece of the curve where a plane (or another level function)
/// cuts it.
#[derive(Clone, Debug, PartialEq)]
pub struct Section<const D: usize> {
    /// The pieces, each traced once.
    pub curves: Vec<SectionCurve<D>>,
    /// What went wrong while tracing: the curves are then valid but may stop short.
    pub warnings: Vec<SectionWarning>,
    /// True when the section was found as whole parameter lines by the surface itself (the
    /// paper's fast path, Aulchenko et al.'s formula (21)) instead of being traced.
    pub fast_path: bool,
}

/// Something that stopped a traced curve short. Every warning names the surface parameters
/// where it happened.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum SectionWarning {
    /// The plane touches the surface there (a tangency or a saddle of the level function on
    /// the surface): the level set is not a simple curve, and the trace stopped.
    SingularPoint {
        /// Parameter `u`.
        u: f64,
        /// Parameter `v`.
        v: f64,
    },
    /// The step budget of one curve ran out: the curve stops there.
    StepLimit {
        /// Parameter `u`.
        u: f64,
        /// Parameter `v`.
        v: f64,
        /// The number of steps taken.
        steps: usize,
    },
    /// The curve runs through a point where the plane touches the surface (a saddle of the
    /// level function on the surface, where two branches cross): the trace went on along one
    /// branch, so how the branches are joined into curves there is arbitrary.
    ThroughSingularPoint {
        /// Parameter `u`.
        u: f64,
        /// Parameter `v`.
        v: f64,
    },
    /// More warnings were met than are listed.
    More {
        /// How many more.
        count: usize,
    },
    /// The step shrank to nothing without finding the curve again (a cusp, a very sharp turn
    /// or a point close to a singular one): the curve stops there.
    StepTooSmall {
        /// Parameter `u`.
        u: f64,
        /// Parameter `v`.
        v: f64,
    },
}

impl SectionWarning {
    /// The parameters where it happened (none for [`More`](Self::More)).
    pub fn params(&self) -> Option<(f64, f64)> {
        match *self {
            SectionWarning::SingularPoint { u, v }
            | SectionWarning::StepLimit { u, v, .. }
            | SectionWarning::ThroughSingularPoint { u, v }
            | SectionWarning::StepTooSmall { u, v } => Some((u, v)),
            SectionWarning::More { .. } => None,
        }
    }
}

/// The most warnings a section lists; the rest are counted in [`SectionWarning::More`].
pub(crate) const MAX_WARNINGS: usize = 16;

/// Drops repeated warnings (the same kind at the same parameters to `1e-9`) and keeps at most
/// [`MAX_WARNINGS`], counting the rest.
pub(crate) fn condense(warnings: Vec<SectionWarning>) -> Vec<SectionWarning> {
    let mut kept: Vec<SectionWarning> = Vec::new();
    let mut more = 0;
    for w in warnings {
        let repeated = kept.iter().any(|k| {
            core::mem::discriminant(k) == core::mem::discriminant(&w)
                && match (k.params(), w.params()) {
                    (Some(a), Some(b)) => (a.0 - b.0).abs() <= 1e-9 && (a.1 - b.1).abs() <= 1e-9,
                    _ => false,
                }
        });
        if repeated {
            continue;
        }
        if kept.len() < MAX_WARNINGS {
            kept.push(w);
        } else {
            more += 1;
        }
    }
    if more > 0 {
        kept.push(SectionWarning::More { count: more });
    }
    kept
}

impl fmt::Display for SectionWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            SectionWarning::SingularPoint { u, v } => write!(
                f,
                "the plane touches the surface at (u={u:.6}, v={v:.6}) (tangency or saddle); \
                 the section curve stops there"
            ),
            SectionWarning::StepLimit { u, v, steps } => write!(
                f,
                "a section curve took {steps} steps without ending; it stops at \
                 (u={u:.6}, v={v:.6})"
            ),
            SectionWarning::ThroughSingularPoint { u, v } => write!(
                f,
                "a section curve runs through a point where the plane touches the surface \
                 (u={u:.6}, v={v:.6}); the branches crossing there may be joined either way"
            ),
            SectionWarning::More { count } => write!(f, "{count} more warnings like these"),
            SectionWarning::StepTooSmall { u, v } => write!(
                f,
                "a section curve turns too sharply to follow at (u={u:.6}, v={v:.6}); it \
                 stops there"
            ),
        }
    }
}

//! A fit of the tolerance mode (Pavlov's defect-2 spline, docs/methods.md §4, "shape
//! guards") that crosses itself or turns more than its points, made sound.
//!
//! Within the tolerance a curve can still hook past a sharp trailing edge or wiggle between
//! sparse points ([`shape_faults`]). These remedies are tried on such a fit, in turn:
//!
//! 1. more smoothing on the same knots ([`FAULT_SMOOTHING`]): it evens out a wiggle that the
//!    knots allow between sparse points, at no cost in coefficients; then the same knots
//!    from the starting parameters (chord lengths by default), as a loop made while the
//!    knots were coarse can stay in the foot parameters carried from round to round;
//! 2. uniform knots, as many as the fit has and then one more at a time up to the cap of
//!    one knot per two points, each count fitted with no smoothing from the starting
//!    parameters and then from centripetal ones: the refinement puts its knots where the
//!    deviation was largest, short pieces at a sharp leading edge beside long ones, and a
//!    long piece there can spend its parameter range on a loop past the edge; centripetal
//!    parameters shorten the parameter gap across a sharp turn. On the corpus this makes 30
//!    of the 77 files that turned too much sound (11 of them from centripetal parameters).
//!    Only on small problems (points times the cap at most [`REPAIR_WORK`]);
//! 3. knots where the faults are ([`FAULT_ROUNDS`] rounds at most): a hook is a piece too
//!    long for the turn its points make (an end piece ending in a rounded or steep trailing
//!    edge), so each faulty piece is split at the fault (kept a quarter of the piece away
//!    from its ends), and the fit made again from the previous foot parameters; when that
//!    fit is still faulty, the finer knots are fitted from the starting parameters with the
//!    bending weight `rho` raised in steps ([`FAULT_FAIRNESS`]): a loop or a wiggle that the
//!    carried foot parameters keep, or that the tiny default weight lets the points pull
//!    into a blunt leading edge, gives way to a rounder curve still within the tolerance
//!    (on the corpus this removes the one loop, at LRN 1007's sharp leading edge, and 6
//!    of the 83 files that turned too much);
//! 4. one knot fewer beside a knot span that holds no point: such a span gives the curve
//!    freedom that no point checks;
//! 5. a curve through some of the points whose tangents turn as the polygon does
//!    ([`through_points`], its inflecting pieces rounder first): no least-squares refit
//!    follows coordinates that kink or ripple at a leading edge, or a sparse sharp edge,
//!    without swinging past them. On the corpus the 38 files that steps 1-4 left turning too
//!    much are all sound by it, at a cost in knots (a median of 1.9 times the faulty fit's,
//!    0.69 per point). Only on small problems, with foot points, without corners or a bound
//!    on the jumps, and not when the rounds stopped at the noise level. When the fit missed
//!    the tolerance, the curve keeps its points within the fit's deviation instead (through
//!    every point it would meet any tolerance by following noise), and may have more knots
//!    than the cap.
//!
//! On small problems every refit runs to convergence (the iterations asked for, not the
//! capped ones of the refinement rounds): a fit stopped early can keep a loop that the
//! converged one smooths out (on the corpus, 9 of the 77 files are sound by that alone).
//! Of the 39 files sound by steps 1-4, 27 end with fewer knots than their faulty fit had
//! (after the pruning of the tolerance mode), 6 with as many and 6 with one to three more.
//!
//! The first fit without faults whose largest deviation is within the tolerance (or, when
//! the tolerance was not met, at most [`UNMET_SLACK`] times the fit's) is kept; when none is
//! found the fit is returned as it was, and its warnings name the faults.

use super::guards::shape_faults;
use super::knots::{
    start_parameters_for, uniform_with_corners, warm_parameters, StartParameters, MIN_KNOT_SPACING,
};
use super::penalty::Settings;
use super::penalty::TOLERANCE_SMOOTHING;
use super::refine::worst_per_piece;
use super::result::CurveFit;
use super::session::Session;
use super::through_points::{through_points, INFLECTING_SHARES};
use crate::{Point, Result};
use std::cell::OnceCell;
use std::ops::RangeInclusive;

/// Smoothing tried, in turn, as multiples of the smoothing asked for (or of the default
/// where none was asked).
const FAULT_SMOOTHING: [f64; 3] = [1.0, 10.0, 100.0];
/// Bending weights tried on the knots added at the faults, as multiples of
/// [`FitOptions::fairness`] (0 stays 0: no bending asked for, none added).
const FAULT_FAIRNESS: [f64; 4] = [1.0, 3.0, 10.0, 30.0];
/// The most rounds of knots added at the faults.
const FAULT_ROUNDS: usize = 4;
/// When the tolerance was not met, a sound fit may lie this factor farther from the points
/// than the faulty one (measured on the corpus: the first sound refit lies 0.3-0.7% farther).
const UNMET_SLACK: f64 = 1.02;
/// A new knot stays this share of its piece away from the piece's ends.
const KNOT_MARGIN: f64 = 0.25;
/// The largest product of points and the knot cap for which the refits run to convergence
/// and uniform knots are tried (each count is a fit, or two): the corpus's files, not the
/// dense noisy sections, whose faults the noise makes and no refit removes.
const REPAIR_WORK: usize = 200_000;
/// The most points times fits spent on uniform knots: on the corpus a sound count lies at
/// most 20 above the fit's (97 points), and a random walk of 600 points, which no count
/// makes sound, takes 0.34 s instead of 4.2 s through the whole cap (0.18 s without them).
const UNIFORM_WORK: usize = 20_000;

/// What the repairs of [`sound_fit`] may use.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Repairs {
    /// The smoothing asked for (0 for none).
    pub asked: f64,
    /// The most knots of a least-squares refit.
    pub cap: usize,
    /// The most iterations of each refit.
    pub iterations: usize,
    /// Whether the curve through the points may be tried: not when the rounds stopped at the
    /// noise level, where the tolerance asks to follow the noise.
    pub through_points: bool,
}

/// `fit`, or the first refit that neither crosses itself nor turns more than its points and
/// whose largest deviation is within `tolerance` or, when `fit` is not, within
/// [`UNMET_SLACK`] of `fit`'s: the repairs of the module docs tried in turn ([`repairs`]).
pub(crate) fn sound_fit<const D: usize>(
    session: &Session<'_, D>,
    tolerance: f64,
    options: &Settings<'_>,
    repairs: Repairs,
    fit: CurveFit<D>,
) -> Result<CurveFit<D>> {
    let faults = shape_faults(session.points, &fit);
    if faults.is_empty() {
        return Ok(fit);
    }
    let repaired = {
        let mend = Mend::new(*session, tolerance, options, repairs, &fit, faults);
        let mut repaired = None;
        for repair in self::repairs::<D>() {
            repaired = repair(&mend)?;
            if repaired.is_some() {
                break;
            }
        }
        repaired
    };
    Ok(repaired.unwrap_or(fit))
}

/// A repair: the sound refit it finds, if any.
type Repair<const D: usize> = fn(&Mend<'_, D>) -> Result<Option<CurveFit<D>>>;

/// The repairs, in the order they are tried (see the module docs).
fn repairs<const D: usize>() -> [Repair<D>; 6] {
    [
        smoother,
        from_start,
        uniform,
        at_faults,
        beside_empty_spans,
        through_some_points,
    ]
}

/// What every repair of a faulty fit works from.
struct Mend<'a, const D: usize> {
    /// The checked points.
    session: Session<'a, D>,
    points: &'a [Point<D>],
    /// The settings of every refit (on small problems, run to convergence).
    options: Settings<'a>,
    repairs: Repairs,
    /// The faulty fit.
    fit: &'a CurveFit<D>,
    /// Its fault parameters.
    faults: Vec<f64>,
    /// The largest deviation a sound refit may have.
    bound: f64,
    /// Whether the problem is small ([`REPAIR_WORK`]).
    small: bool,
    /// The starting parameters of the points, once a repair asks for them.
    start: OnceCell<Vec<f64>>,
}

impl<'a, const D: usize> Mend<'a, D> {
    fn new(
        session: Session<'a, D>,
        tolerance: f64,
        options: &Settings<'a>,
        repairs: Repairs,
        fit: &'a CurveFit<D>,
        faults: Vec<f64>,
    ) -> Self {
        let points = session.points;
        let small = points.len() * repairs.cap <= REPAIR_WORK;
        let options = Settings {
            max_iterations: if small {
                repairs.iterations
            } else {
                options.max_iterations
            },
            ..*options
        };
        Mend {
            session,
            points,
            options,
            repairs,
            fit,
            faults,
            bound: tolerance.max(fit.max_distance() * UNMET_SLACK),
            small,
            start: OnceCell::new(),
        }
    }

    /// Whether `trial` is within the bound and without faults.
    fn sound(&self, trial: &CurveFit<D>) -> bool {
        trial.max_distance() <= self.bound && shape_faults(self.points, trial).is_empty()
    }

    /// The starting parameters of the points (chord lengths by default).
    fn start(&self) -> Result<&[f64]> {
        if let Some(start) = self.start.get() {
            return Ok(start);
        }
        let start = start_parameters_for(self.points, self.options.start, self.fit.noise.sigma)?;
        Ok(self.start.get_or_init(|| start))
    }

    /// The sound refit on `knots` from the parameters `start` with `options`, if it is one.
    fn sound_refit(
        &self,
        knots: &[f64],
        start: Vec<f64>,
        options: &Settings<'_>,
    ) -> Option<CurveFit<D>> {
        refit(&self.session, knots, start, options).filter(|t| self.sound(t))
    }
}

/// Step 1: More smoothing on the same knots: it evens out a wiggle that the knots allow between
/// sparse points.
fn smoother<const D: usize>(mend: &Mend<'_, D>) -> Result<Option<CurveFit<D>>> {
    let asked = mend.repairs.asked;
    let unit = if asked > 0.0 {
        asked
    } else {
        TOLERANCE_SMOOTHING
    };
    Ok(FAULT_SMOOTHING.iter().find_map(|factor| {
        let smoother = Settings {
            smoothing: Some(unit * factor),
            ..mend.options
        };
        let from = warm_parameters(&mend.fit.parameters);
        mend.sound_refit(mend.fit.spline.knots(), from, &smoother)
    }))
}

/// Step 1: The same knots from the starting parameters: the refinement carries each round's foot
/// parameters to the next, and a loop made on coarse knots can stay.
fn from_start<const D: usize>(mend: &Mend<'_, D>) -> Result<Option<CurveFit<D>>> {
    let start = mend.start()?.to_vec();
    Ok(mend.sound_refit(mend.fit.spline.knots(), start, &mend.options))
}

/// Step 2: Uniform knots, as many as the fit has and more up to the cap (small problems only).
fn uniform<const D: usize>(mend: &Mend<'_, D>) -> Result<Option<CurveFit<D>>> {
    if !mend.small {
        return Ok(None);
    }
    let counts = mend.fit.spline.knots().len()..=mend.repairs.cap;
    let sound = |trial: &CurveFit<D>| mend.sound(trial);
    uniform_refit(
        &mend.session,
        counts,
        mend.start()?,
        &mend.options,
        mend.fit,
        sound,
    )
}

/// Step 3: Knots at the faults, round after round; each round's fit, when still faulty, also from
/// the starting parameters with the bending weight raised ([`FAULT_FAIRNESS`]).
fn at_faults<const D: usize>(mend: &Mend<'_, D>) -> Result<Option<CurveFit<D>>> {
    let (points, options) = (mend.points, &mend.options);
    let start = mend.start()?;
    let mut last = (
        mend.fit.spline.knots().to_vec(),
        mend.fit.parameters.clone(),
        mend.faults.clone(),
    );
    for _ in 0..FAULT_ROUNDS {
        let (knots, parameters, faults) = &last;
        let finer = split_at(knots, faults);
        if finer.len() == knots.len() || finer.len() > mend.repairs.cap {
            break;
        }
        let Some(trial) = refit(&mend.session, &finer, warm_parameters(parameters), options) else {
            break;
        };
        if mend.sound(&trial) {
            return Ok(Some(trial));
        }
        let stiffer = FAULT_FAIRNESS.iter().find_map(|factor| {
            let stiffer = Settings {
                fairness: options.fairness * factor,
                ..*options
            };
            mend.sound_refit(&finer, start.to_vec(), &stiffer)
        });
        if stiffer.is_some() {
            return Ok(stiffer);
        }
        let faults = shape_faults(points, &trial);
        last = (finer, trial.parameters, faults);
    }
    Ok(None)
}

/// Step 4: A knot taken out beside a span that holds no point: such spans let the curve wiggle.
fn beside_empty_spans<const D: usize>(mend: &Mend<'_, D>) -> Result<Option<CurveFit<D>>> {
    let knots = mend.fit.spline.knots();
    Ok(knots_beside_empty_spans(mend.fit)
        .into_iter()
        .find_map(|at| {
            let mut fewer = knots.to_vec();
            fewer.remove(at);
            let from = warm_parameters(&mend.fit.parameters);
            mend.sound_refit(&fewer, from, &mend.options)
        }))
}

/// Step 5: A curve through some of the points that turns as they do, its inflecting pieces
/// rounder first, its points within the tolerance or, when the fit missed it, within the
/// fit's deviation (it could meet any tolerance by following the points one by one).
fn through_some_points<const D: usize>(mend: &Mend<'_, D>) -> Result<Option<CurveFit<D>>> {
    let options = &mend.options;
    let plain = options.corners.is_empty() && options.foot_points && options.eps.is_infinite();
    if !(mend.small && plain && mend.repairs.through_points) {
        return Ok(None);
    }
    Ok(INFLECTING_SHARES.iter().find_map(|&share| {
        through_points(mend.points, mend.bound, share, options, &mend.fit.noise)
            .filter(|t| mend.sound(t))
    }))
}

/// The first sound fit (`sound`) on uniform knots, their count from `counts` in turn (as
/// many as [`UNIFORM_WORK`] allows), with no smoothing, from the parameters `start` and then
/// from centripetal ones (unless `start` is centripetal already).
fn uniform_refit<const D: usize>(
    session: &Session<'_, D>,
    counts: RangeInclusive<usize>,
    start: &[f64],
    options: &Settings<'_>,
    fit: &CurveFit<D>,
    sound: impl Fn(&CurveFit<D>) -> bool,
) -> Result<Option<CurveFit<D>>> {
    let plain = Settings {
        smoothing: Some(0.0),
        ..*options
    };
    let points = session.points;
    let mut starts = vec![start.to_vec()];
    if *options.start != StartParameters::Centripetal {
        let centripetal = StartParameters::Centripetal;
        starts.push(start_parameters_for(points, &centripetal, fit.noise.sigma)?);
    }
    let tries = UNIFORM_WORK / (starts.len() * points.len());
    Ok(counts.take(tries.max(1)).find_map(|count| {
        let even = uniform_with_corners(count, options.corners);
        starts
            .iter()
            .find_map(|from| refit(session, &even, from.clone(), &plain).filter(&sound))
    }))
}

/// The fit of the session's points on `knots` from the parameters `start`; `None` when it
/// cannot be made (a repair is optional: the faulty fit stands).
fn refit<const D: usize>(
    session: &Session<'_, D>,
    knots: &[f64],
    start: Vec<f64>,
    options: &Settings<'_>,
) -> Option<CurveFit<D>> {
    session.refit(knots, start, options).ok()
}

/// The inner knots that bound a knot span holding no point's foot parameter.
fn knots_beside_empty_spans<const D: usize>(fit: &CurveFit<D>) -> Vec<usize> {
    let worst = worst_per_piece(&fit.spline, &fit.parameters, &fit.distances);
    let last = fit.spline.knots().len() - 1;
    let mut beside: Vec<usize> = worst
        .iter()
        .enumerate()
        .filter(|(_, piece)| piece.points == 0)
        .flat_map(|(p, _)| [p, p + 1])
        .filter(|&k| k > 0 && k < last)
        .collect();
    beside.dedup();
    beside
}

/// `knots` with one more knot in every piece that holds a fault parameter, at the fault
/// (at least [`KNOT_MARGIN`] of the piece from its ends); pieces too short to split keep
/// their knots.
fn split_at(knots: &[f64], faults: &[f64]) -> Vec<f64> {
    let mut pieces: Vec<usize> = faults
        .iter()
        .map(|&t| knots.partition_point(|&k| k <= t).clamp(1, knots.len() - 1) - 1)
        .collect();
    pieces.sort_unstable();
    pieces.dedup();
    let mut finer = knots.to_vec();
    for p in pieces {
        let (a, b) = (knots[p], knots[p + 1]);
        if b - a <= 4.0 * MIN_KNOT_SPACING {
            continue;
        }
        let margin = KNOT_MARGIN * (b - a);
        let t = faults
            .iter()
            .copied()
            .find(|&t| t >= a && t <= b)
            .unwrap_or(0.5 * (a + b));
        finer.push(t.clamp(a + margin, b - margin));
    }
    finer.sort_by(f64::total_cmp);
    finer
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_fault_splits_its_piece_away_from_the_piece_ends() {
        let knots = [0.0, 0.25, 0.5, 1.0];
        // At the very end of the first piece, inside the last, and twice in the middle one.
        let finer = split_at(&knots, &[0.001, 0.3, 0.35, 0.75, 1.0]);
        assert_eq!(finer, vec![0.0, 0.0625, 0.25, 0.3125, 0.5, 0.75, 1.0]);
        assert_eq!(split_at(&knots, &[]), knots.to_vec());
    }
}

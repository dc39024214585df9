//! Compatible sections: every section of a loft fitted by a cubic B-spline on one shared knot
//! vector, to a tolerance, with corresponding points at corresponding parameters
//! (docs/methods.md §7.2).
//!
//! Each section's points get chord-length parameters; a section with a split point (the
//! leading edge of a profile) gets `[0, 1/2]` before it and `[1/2, 1]` after it, each part
//! normalised on its own, so the split point sits at `v = 1/2` on every section. The fit is
//! linear least squares in the control points (banded, by Givens rotations: `O(n)` per
//! section) with the first and last points interpolated (clamped end control points), the
//! split point interpolated (a row weighted [`CONSTRAINT_WEIGHT`]), and a vanishing penalty on
//! the third differences of the control points that keeps the problem determined where a
//! sparse section has no point in a knot span. Between fits every point is projected onto its
//! section's curve (Newton's method from its parameter, kept on its side of the split): the
//! deviation is then the distance to the curve, not to one parameter of it.
//!
//! Knots: four spans per part to start, then every span whose worst point (over all sections,
//! relative to each section's tolerance) lies beyond the tolerance is halved, round after
//! round, until every point of every section is within its tolerance or
//! [`MAX_ROUNDS`] rounds have passed (the deviation reached is reported either way).
//!
//! Complexity: each round is `O(n)` in the total number of points `n` (two fits and two
//! projections per section; one of each for a section that starts from its neighbours'
//! parameters and meets the tolerance at once); the rounds number about `log2` of the knots
//! needed over the starting knots.

use crate::bspline::cubic_span_weights;
use crate::solve::BandedLeastSquares;
use crate::{Error, Point2, Result};

/// The weight of the row that makes a section pass through its split point (against weight
/// 1 for every data row): the constraint's residual is the data residual over its square.
const CONSTRAINT_WEIGHT: f64 = 1e6;
/// The weight of the third-difference rows, relative to one data row: vanishing against the
/// data, enough to determine control points no point of a section reaches.
const SMOOTHING_WEIGHT: f64 = 1e-3;
/// Spans per part (each side of the split) the refinement starts from.
const START_SPANS: usize = 4;
/// Rounds of knot refinement at most.
pub(crate) const MAX_ROUNDS: usize = 16;
/// Sections the knots are refined on before every section is checked.
const SAMPLE_SECTIONS: usize = 12;
/// The share of its tolerance the sample's sections are refined to: sections between them
/// may lie a little further off on the same knots.
const SAMPLE_MARGIN: f64 = 0.7;
/// A Newton step shorter than this share of its knot span ends the projection: the distance
/// it would still gain is of the order of its square.
const NEWTON_STOP: f64 = 1e-9;
/// Newton steps per projection of a point onto its curve.
const NEWTON_STEPS: usize = 3;

/// One section to fit: its points, where it splits (`v = 1/2`), and the largest distance its
/// points may lie from its curve.
#[derive(Clone, Copy, Debug)]
pub(crate) struct FitSection<'a> {
    pub points: &'a [Point2],
    pub split: Option<usize>,
    pub tolerance: f64,
}

/// The sections fitted on one knot vector.
#[derive(Clone, Debug)]
pub(crate) struct CompatibleFit {
    /// The clamped cubic knot vector shared by every section.
    pub knots: Vec<f64>,
    /// The control points of each section.
    pub controls: Vec<Vec<Point2>>,
    /// The largest distance of each section's points from its curve.
    pub deviations: Vec<f64>,
    /// The knot refinement rounds run.
    pub rounds: usize,
}

/// Fits every section on one shared knot vector (see the module docs).
pub(crate) fn fit_compatible(sections: &[FitSection]) -> Result<CompatibleFit> {
    let split = sections.iter().any(|s| s.split.is_some());
    let mut breaks = start_breaks(split);
    let mut params: Vec<Vec<f64>> = sections.iter().map(start_parameters).collect();
    let all: Vec<usize> = (0..sections.len()).collect();
    // The knots are refined on a few sections spread along the span first, then checked on
    // all (and refined further on all if any misses the tolerance).
    let sample = sample_sections(sections.len());
    let mut active = sample.clone();
    // A section fitted on the current knots, kept when the sample's last round leaves the
    // knots as they are (its fit is then the whole round's fit of it).
    let mut kept: Vec<Option<(Vec<Point2>, f64)>> = vec![None; sections.len()];
    let mut rounds = 0;
    loop {
        rounds += 1;
        let whole = active.len() == sections.len();
        // The sample is refined with a margin, so the check of every section seldom needs
        // another round over all of them.
        let limit = if whole { 1.0 } else { SAMPLE_MARGIN };
        let knots = clamped(&breaks);
        let mut worst = vec![0.0f64; breaks.len() - 1];
        let mut scratch = Scratch::new(knots.len() - 4);
        let mut local = vec![0.0f64; worst.len()];
        for &k in &active {
            if whole && kept[k].is_some() {
                continue;
            }
            // In the check of every section, a section between two of the sample with as many
            // points starts from their foot-point parameters, interpolated: its first fit is
            // then usually within the tolerance, and the second fit is saved.
            let guessed = whole && guess_parameters(k, &sample, sections, &mut params);
            let (section, t) = (&sections[k], &mut params[k]);
            let mut c = fit_section(section, t, &knots, &mut scratch)?;
            if !guessed {
                project(section, &knots, &c, t, None);
                c = fit_section(section, t, &knots, &mut scratch)?;
            }
            let mut largest = measure(section, &knots, &c, t, &mut local);
            if guessed && largest > section.tolerance {
                c = fit_section(section, t, &knots, &mut scratch)?;
                largest = measure(section, &knots, &c, t, &mut local);
            }
            for (w, l) in worst.iter_mut().zip(&local) {
                *w = w.max(*l);
            }
            kept[k] = Some((c, largest));
        }
        let refine: Vec<usize> = (0..worst.len()).filter(|&k| worst[k] > limit).collect();
        if whole && (refine.is_empty() || rounds >= MAX_ROUNDS) {
            let (controls, deviations) = kept.into_iter().flatten().unzip();
            return Ok(CompatibleFit {
                knots,
                controls,
                deviations,
                rounds,
            });
        }
        if refine.is_empty() || rounds >= MAX_ROUNDS {
            // The sample is within the tolerance on these knots: check every section.
            active.clone_from(&all);
            continue;
        }
        kept.iter_mut().for_each(|k| *k = None);
        let mut next = Vec::with_capacity(breaks.len() + refine.len());
        for k in 0..breaks.len() - 1 {
            next.push(breaks[k]);
            if refine.binary_search(&k).is_ok() {
                next.push(0.5 * (breaks[k] + breaks[k + 1]));
            }
        }
        next.push(1.0);
        breaks = next;
    }
}

/// Projects the section's points onto its curve (see [`project`]) and returns the largest
/// distance; `local[span]` becomes the largest distance in each break span over the section's
/// tolerance.
fn measure(
    section: &FitSection,
    knots: &[f64],
    control: &[Point2],
    t: &mut [f64],
    local: &mut [f64],
) -> f64 {
    local.iter_mut().for_each(|l| *l = 0.0);
    let mut largest = 0.0f64;
    let scale = 1.0 / section.tolerance;
    project(
        section,
        knots,
        control,
        t,
        Some(&mut |span, d| {
            largest = largest.max(d);
            local[span] = local[span].max(d * scale);
        }),
    );
    largest
}

/// Sets section `k`'s parameters to those of the sample's sections around it interpolated
/// by index, when both have as many points as it and the same split; false (nothing set)
/// otherwise.
fn guess_parameters(
    k: usize,
    sample: &[usize],
    sections: &[FitSection],
    params: &mut [Vec<f64>],
) -> bool {
    let after = sample.partition_point(|&j| j < k);
    if after == 0 || after >= sample.len() || sample[after] == k {
        return false;
    }
    let (a, b) = (sample[after - 1], sample[after]);
    let n = sections[k].points.len();
    let alike = |j: usize| sections[j].points.len() == n && sections[j].split == sections[k].split;
    if !(alike(a) && alike(b)) {
        return false;
    }
    let w = (k - a) as f64 / (b - a) as f64;
    let (ta, tb) = (params[a].clone(), params[b].clone());
    for ((t, x), y) in params[k].iter_mut().zip(ta).zip(tb) {
        *t = x + w * (y - x);
    }
    true
}

/// The sections the knots are first refined on: all of up to [`SAMPLE_SECTIONS`], else that
/// many spread evenly along the span (the first and the last among them).
fn sample_sections(count: usize) -> Vec<usize> {
    if count <= SAMPLE_SECTIONS {
        return (0..count).collect();
    }
    let mut picked: Vec<usize> = (0..SAMPLE_SECTIONS)
        .map(|j| j * (count - 1) / (SAMPLE_SECTIONS - 1))
        .collect();
    picked.dedup();
    picked
}

/// The starting breakpoints: [`START_SPANS`] uniform spans per part.
fn start_breaks(split: bool) -> Vec<f64> {
    let spans = if split { 2 * START_SPANS } else { START_SPANS };
    (0..=spans).map(|k| k as f64 / spans as f64).collect()
}

/// The clamped cubic knot vector over `breaks` (simple inner knots).
fn clamped(breaks: &[f64]) -> Vec<f64> {
    let (first, last) = (breaks[0], breaks[breaks.len() - 1]);
    let mut knots = vec![first; 3];
    knots.extend_from_slice(breaks);
    knots.extend([last; 3]);
    knots
}

/// Chord-length parameters, each part of a split section on its own half of `[0, 1]`.
fn start_parameters(section: &FitSection) -> Vec<f64> {
    let points = section.points;
    let mut t = vec![0.0; points.len()];
    let mut spread = |range: std::ops::Range<usize>, (a, b): (f64, f64)| {
        let mut total = 0.0;
        t[range.start] = 0.0;
        for i in range.start + 1..range.end {
            total += points[i].distance(points[i - 1]);
            t[i] = total;
        }
        for i in range.clone() {
            t[i] = if total > 0.0 {
                a + (b - a) * t[i] / total
            } else {
                a + (b - a) * (i - range.start) as f64 / (range.len() - 1).max(1) as f64
            };
        }
    };
    match section.split {
        Some(s) => {
            spread(0..s + 1, (0.0, 0.5));
            spread(s..points.len(), (0.5, 1.0));
        }
        None => spread(0..points.len(), (0.0, 1.0)),
    }
    t
}

/// The knot span `s` (`knots[s] <= t < knots[s + 1]`, `3 <= s < count`) of `t` in `[0, 1]`.
fn span_of(knots: &[f64], count: usize, t: f64) -> usize {
    let s = knots[4..=count].partition_point(|&k| k <= t) + 3;
    s.min(count - 1)
}

/// [`span_of`] found by walking from span `near` (the same span for nondecreasing knots): the
/// points of a section and the steps of a projection move a span or two at a time, where the
/// walk is cheaper than the binary search.
#[inline]
fn span_near(knots: &[f64], count: usize, t: f64, near: usize) -> usize {
    let mut s = near.clamp(3, count - 1);
    while s > 3 && t < knots[s] {
        s -= 1;
    }
    while s + 1 < count && t >= knots[s + 1] {
        s += 1;
    }
    s
}

/// Work buffers of one knot vector's fits.
struct Scratch {
    solver: BandedLeastSquares,
    x: Vec<f64>,
}

impl Scratch {
    fn new(count: usize) -> Self {
        let unknowns = count - 2;
        Scratch {
            solver: BandedLeastSquares::new(unknowns, 4, 2),
            x: vec![0.0; unknowns * 2],
        }
    }
}

/// A row over control points `first..first + 4` with weights `w` and target `r`: the end
/// control points (fixed at the first and last point) move to the right-hand side.
fn add_row(
    solver: &mut BandedLeastSquares,
    (first, w): (usize, [f64; 4]),
    mut r: Point2,
    ends: (Point2, Point2),
    count: usize,
) {
    let mut values = [0.0; 4];
    for (a, &wa) in w.iter().enumerate() {
        let j = first + a;
        if j == 0 {
            r = r.add_scaled(-wa, ends.0);
        } else if j == count - 1 {
            r = r.add_scaled(-wa, ends.1);
        } else {
            values[a] = wa;
        }
    }
    // Columns are the inner control points 1..count-1, so column j - 1.
    let (column, values) = if first == 0 {
        (0, [values[1], values[2], values[3], 0.0])
    } else {
        (first - 1, values)
    };
    let width = (count - 2 - column).min(4);
    solver.add_row(column, &values[..width], &r.0);
}

/// The least-squares control points of `section` at parameters `t` on `knots`.
fn fit_section(
    section: &FitSection,
    t: &[f64],
    knots: &[f64],
    scratch: &mut Scratch,
) -> Result<Vec<Point2>> {
    let points = section.points;
    let count = knots.len() - 4;
    let ends = (points[0], points[points.len() - 1]);
    let solver = &mut scratch.solver;
    solver.clear();
    // Rows in order of their first column (the solver's cost is then O(w^2) a row): the data
    // rows by parameter, the split row and the smoothing rows merged in.
    let mut next_smooth = 0usize;
    let mut split_done = section.split.is_none();
    let smooth_rows = count.saturating_sub(3);
    let smoothing = SMOOTHING_WEIGHT * (points.len() as f64 / count as f64).sqrt();
    let add_smoothing_until = |solver: &mut BandedLeastSquares, next: &mut usize, upto: usize| {
        while *next < smooth_rows && *next <= upto {
            let j = *next;
            let w = [-smoothing, 3.0 * smoothing, -3.0 * smoothing, smoothing];
            add_row(solver, (j, w), Point2::ZERO, ends, count);
            *next += 1;
        }
    };
    let mut s = 3;
    for (i, (&ti, &p)) in t.iter().zip(points).enumerate() {
        s = span_near(knots, count, ti, s);
        add_smoothing_until(solver, &mut next_smooth, s - 3);
        if !split_done && section.split.is_some_and(|k| k <= i) {
            let k = section.split.unwrap_or(i);
            let sk = span_of(knots, count, 0.5);
            let w = weights(knots, sk, 0.5, 0).map(|x| x * CONSTRAINT_WEIGHT);
            add_row(
                solver,
                (sk - 3, w),
                points[k] * CONSTRAINT_WEIGHT,
                ends,
                count,
            );
            split_done = true;
        }
        if i == 0 || i + 1 == points.len() || section.split == Some(i) {
            continue;
        }
        add_row(solver, (s - 3, weights(knots, s, ti, 0)), p, ends, count);
    }
    add_smoothing_until(solver, &mut next_smooth, usize::MAX);
    solver.solve(&mut scratch.x)?;
    let mut control = Vec::with_capacity(count);
    control.push(ends.0);
    control.extend(scratch.x.chunks_exact(2).map(|c| Point2::new([c[0], c[1]])));
    control.push(ends.1);
    if control.iter().any(|p| !p.is_finite()) {
        return Err(Error::Internal {
            what: "a loft section's fit gave a non-finite control point",
        });
    }
    Ok(control)
}

/// The weights of the `k`-th derivative of the four control points of span `s` at `t`.
#[inline]
fn weights(knots: &[f64], s: usize, t: f64, k: usize) -> [f64; 4] {
    let local = &knots[s - 2..s + 4];
    cubic_span_weights(local, (t - local[2]) / (local[3] - local[2]), k)
}

/// The point and first two derivatives of the curve `(knots, control)` at `t` in span `s`.
#[inline]
fn eval3(knots: &[f64], control: &[Point2], s: usize, t: f64) -> [Point2; 3] {
    let w = cubic_derivatives(knots, s, t);
    let mut out = [Point2::ZERO; 3];
    for (o, wk) in out.iter_mut().zip(&w) {
        for (a, &wa) in wk.iter().enumerate() {
            *o = o.add_scaled(wa, control[s - 3 + a]);
        }
    }
    out
}

/// The values and first two derivatives of the four cubic B-splines nonzero on span `s` at
/// `t`, in one pass (Piegl and Tiller's algorithm A2.3 for degree 3; the general weights of
/// [`cubic_span_weights`] take a pass per derivative, three times the work in the projection).
#[allow(clippy::needless_range_loop)] // the algorithm's triangular tables
fn cubic_derivatives(knots: &[f64], s: usize, t: f64) -> [[f64; 4]; 3] {
    const P: usize = 3;
    let mut ndu = [[0.0f64; 4]; 4];
    let (mut left, mut right) = ([0.0f64; 4], [0.0f64; 4]);
    ndu[0][0] = 1.0;
    for j in 1..=P {
        left[j] = t - knots[s + 1 - j];
        right[j] = knots[s + j] - t;
        let mut saved = 0.0;
        for r in 0..j {
            ndu[j][r] = right[r + 1] + left[j - r];
            let temp = ndu[r][j - 1] / ndu[j][r];
            ndu[r][j] = saved + right[r + 1] * temp;
            saved = left[j - r] * temp;
        }
        ndu[j][j] = saved;
    }
    let mut ders = [[0.0f64; 4]; 3];
    for j in 0..=P {
        ders[0][j] = ndu[j][P];
    }
    for r in 0..=P {
        let mut a = [[0.0f64; 4]; 2];
        let (mut s1, mut s2) = (0usize, 1usize);
        a[0][0] = 1.0;
        for k in 1..=2usize {
            let mut d = 0.0;
            let rk = r as isize - k as isize;
            let pk = P - k;
            if rk >= 0 {
                a[s2][0] = a[s1][0] / ndu[pk + 1][rk as usize];
                d = a[s2][0] * ndu[rk as usize][pk];
            }
            let j1 = if rk >= -1 { 1 } else { (-rk) as usize };
            let j2 = if r <= pk { k - 1 } else { P - r };
            for j in j1..=j2 {
                let idx = (rk + j as isize) as usize;
                a[s2][j] = (a[s1][j] - a[s1][j - 1]) / ndu[pk + 1][idx];
                d += a[s2][j] * ndu[idx][pk];
            }
            if r <= pk {
                a[s2][k] = -a[s1][k - 1] / ndu[pk + 1][r];
                d += a[s2][k] * ndu[r][pk];
            }
            ders[k][r] = d;
            std::mem::swap(&mut s1, &mut s2);
        }
    }
    for j in 0..=P {
        ders[1][j] *= 3.0;
        ders[2][j] *= 6.0;
    }
    ders
}

/// The point of the curve at `t` in span `s`.
#[inline]
fn point_at(knots: &[f64], control: &[Point2], s: usize, t: f64) -> Point2 {
    let w = weights(knots, s, t, 0);
    let mut p = Point2::ZERO;
    for (a, &wa) in w.iter().enumerate() {
        p = p.add_scaled(wa, control[s - 3 + a]);
    }
    p
}

/// A curve's cubic on each knot span in powers of `u = t - knots[s]`: the point and its first
/// two derivatives then cost one Horner pass. The projection evaluates every span hundreds of
/// times per fit, and the B-spline weights of [`cubic_derivatives`] (with their divisions by
/// knot differences) would be recomputed at each; the cubics are built once per curve.
struct SpanCubics {
    /// `[a0, a1, a2, a3]` of span `s` at index `s - 3`: the point, the first derivative, half
    /// the second and a sixth of the third at the span's start.
    coefficients: Vec<[Point2; 4]>,
}

impl SpanCubics {
    fn new(knots: &[f64], control: &[Point2]) -> Self {
        let count = knots.len() - 4;
        let coefficients = (3..count)
            .map(|s| {
                let h = knots[s + 1] - knots[s];
                let [d0, d1, d2] = eval3(knots, control, s, knots[s]);
                if h <= 0.0 {
                    return [d0, d1, d2 * 0.5, Point2::ZERO];
                }
                let [_, _, e2] = eval3(knots, control, s, knots[s + 1]);
                [d0, d1, d2 * 0.5, (e2 - d2) * (1.0 / (6.0 * h))]
            })
            .collect();
        SpanCubics { coefficients }
    }

    /// The point and first two derivatives at `t` in span `s`.
    #[inline]
    fn eval3(&self, knots: &[f64], s: usize, t: f64) -> [Point2; 3] {
        let u = t - knots[s];
        let [a0, a1, a2, a3] = self.coefficients[s - 3];
        let value = a0.add_scaled(u, a1.add_scaled(u, a2.add_scaled(u, a3)));
        let first = a1.add_scaled(u, (a2 * 2.0).add_scaled(3.0 * u, a3));
        let second = (a2 * 2.0).add_scaled(6.0 * u, a3);
        [value, first, second]
    }
}

/// The first control point whose basis function is nonzero at `t`, and the values of the
/// four from there.
pub(crate) fn basis_at(knots: &[f64], t: f64) -> (usize, [f64; 4]) {
    let s = span_of(knots, knots.len() - 4, t);
    (s - 3, weights(knots, s, t, 0))
}

/// The point of the curve at `t`.
#[cfg(test)]
pub(crate) fn eval(knots: &[f64], control: &[Point2], t: f64) -> Point2 {
    let count = knots.len() - 4;
    let s = span_of(knots, count, t);
    let w = weights(knots, s, t, 0);
    let mut p = Point2::ZERO;
    for (a, &wa) in w.iter().enumerate() {
        p = p.add_scaled(wa, control[s - 3 + a]);
    }
    p
}

/// Moves every free parameter of `t` to its point's foot on the curve (Newton's method from
/// where it was, kept within its part); `measure` is told the span and distance of every
/// point afterwards.
fn project(
    section: &FitSection,
    knots: &[f64],
    control: &[Point2],
    t: &mut [f64],
    mut measure: Option<&mut dyn FnMut(usize, f64)>,
) {
    let count = knots.len() - 4;
    let n = section.points.len();
    let split = section.split;
    let cubics = SpanCubics::new(knots, control);
    let mut previous = 3;
    for (i, (ti, &p)) in t.iter_mut().zip(section.points).enumerate() {
        let fixed = i == 0 || i + 1 == n || split == Some(i);
        let (lo, hi) = match split {
            Some(k) if i < k => (0.0, 0.5),
            Some(_) => (0.5, 1.0),
            None => (0.0, 1.0),
        };
        let mut s = span_near(knots, count, *ti, previous);
        let dist_sq = if fixed {
            (point_at(knots, control, s, *ti) - p).norm_sq()
        } else {
            // Newton's method on the squared distance, each step at most one knot span long
            // and kept only when it brings the point closer (else halved, up to four times).
            let [mut c, mut d1, mut d2] = cubics.eval3(knots, s, *ti);
            let mut dist_sq = (c - p).norm_sq();
            for _ in 0..NEWTON_STEPS {
                let r = c - p;
                let g = r.dot(d1);
                let h = d1.norm_sq() + r.dot(d2);
                let reach = knots[s + 1] - knots[s];
                let mut step = if h > 0.0 { -g / h } else { -g.signum() * reach };
                if !step.is_finite() || step.abs() <= NEWTON_STOP * reach {
                    break;
                }
                step = step.clamp(-reach, reach);
                let mut moved = false;
                for _ in 0..5 {
                    let next = (*ti + step).clamp(lo, hi);
                    let ns = span_near(knots, count, next, s);
                    let e = cubics.eval3(knots, ns, next);
                    let nd = (e[0] - p).norm_sq();
                    if nd < dist_sq {
                        (*ti, s, dist_sq) = (next, ns, nd);
                        [c, d1, d2] = e;
                        moved = true;
                        break;
                    }
                    step *= 0.5;
                }
                if !moved || step.abs() < 1e-15 {
                    break;
                }
            }
            dist_sq
        };
        previous = s;
        if let Some(m) = measure.as_mut() {
            // The span of the breakpoints (span s of the knot vector is break span s - 3).
            m(s - 3, dist_sq.sqrt());
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A NACA 4-digit section in Selig order with `n` points per side (cosine spacing).
    fn naca(m: f64, p: f64, t: f64, n: usize) -> Vec<Point2> {
        let side = |upper: bool| -> Vec<Point2> {
            (0..=n)
                .map(|k| {
                    let x = 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / n as f64).cos());
                    let yt = 5.0
                        * t
                        * (0.2969 * x.sqrt() - 0.1260 * x - 0.3516 * x * x + 0.2843 * x.powi(3)
                            - 0.1036 * x.powi(4));
                    let (yc, dyc) = if x < p {
                        (
                            m / (p * p) * (2.0 * p * x - x * x),
                            2.0 * m / (p * p) * (p - x),
                        )
                    } else {
                        (
                            m / ((1.0 - p) * (1.0 - p)) * (1.0 - 2.0 * p + 2.0 * p * x - x * x),
                            2.0 * m / ((1.0 - p) * (1.0 - p)) * (p - x),
                        )
                    };
                    let th = dyc.atan();
                    if upper {
                        Point2::new([x - yt * th.sin(), yc + yt * th.cos()])
                    } else {
                        Point2::new([x + yt * th.sin(), yc - yt * th.cos()])
                    }
                })
                .collect()
        };
        let mut upper = side(true);
        upper.reverse();
        let lower = side(false);
        upper.extend_from_slice(&lower[1..]);
        upper
    }

    #[test]
    fn one_pass_derivatives_equal_the_general_weights() {
        let knots = clamped(&[0.0, 0.1, 0.15, 0.5, 0.52, 0.9, 1.0]);
        for s in 3..knots.len() - 4 {
            for f in [0.0, 0.3, 0.99] {
                let t = knots[s] + f * (knots[s + 1] - knots[s]);
                let fast = cubic_derivatives(&knots, s, t);
                for (k, row) in fast.iter().enumerate() {
                    let slow = weights(&knots, s, t, k);
                    for a in 0..4 {
                        assert!(
                            (row[a] - slow[a]).abs() < 1e-9 * (1.0 + slow[a].abs()),
                            "{s} {f} {k} {a}"
                        );
                    }
                }
            }
        }
    }

    #[test]
    fn the_span_walk_finds_the_binary_search_span_from_any_start() {
        let knots = clamped(&[0.0, 0.1, 0.15, 0.5, 0.52, 0.9, 1.0]);
        let count = knots.len() - 4;
        let ts = [
            0.0, 0.05, 0.1, 0.12, 0.15, 0.3, 0.5, 0.51, 0.52, 0.7, 0.9, 0.95, 1.0,
        ];
        for &t in &ts {
            for near in 0..count + 2 {
                assert_eq!(
                    span_near(&knots, count, t, near),
                    span_of(&knots, count, t),
                    "{t} {near}"
                );
            }
        }
    }

    #[test]
    fn span_cubics_equal_the_b_spline_and_its_derivatives() {
        // Uneven breaks (spans from 0.02 to 0.38 long) and control points far from the origin.
        let knots = clamped(&[0.0, 0.1, 0.15, 0.5, 0.52, 0.9, 1.0]);
        let control: Vec<Point2> = (0..knots.len() - 4)
            .map(|j| Point2::new([1e3 + (j as f64 * 1.7).sin(), -2e3 + (j * j) as f64 * 0.3]))
            .collect();
        let cubics = SpanCubics::new(&knots, &control);
        let largest = control.iter().map(|p| p.norm()).fold(0.0, f64::max);
        for s in 3..knots.len() - 4 {
            for f in [0.0, 0.25, 0.5, 0.77, 1.0] {
                let t = knots[s] + f * (knots[s + 1] - knots[s]);
                let want = eval3(&knots, &control, s, t);
                let got = cubics.eval3(&knots, s, t);
                // Both carry the rounding of the control points' size over the span's
                // length to the derivative's order.
                let h = knots[s + 1] - knots[s];
                for (k, (g, w)) in got.iter().zip(&want).enumerate() {
                    let size = largest / h.powi(k as i32);
                    assert!((*g - *w).norm() < 1e-13 * size, "{s} {f} {k} {g:?} {w:?}");
                }
            }
        }
    }

    #[test]
    fn sections_share_knots_and_meet_the_tolerance() {
        let a = naca(0.02, 0.4, 0.12, 80);
        let b = naca(0.0, 0.3, 0.09, 45);
        let sections = [
            FitSection {
                points: &a,
                split: Some(80),
                tolerance: 1e-5,
            },
            FitSection {
                points: &b,
                split: Some(45),
                tolerance: 1e-5,
            },
        ];
        let fit = fit_compatible(&sections).unwrap();
        assert!(
            fit.deviations.iter().all(|&d| d <= 1e-5),
            "{:?} {} {}",
            fit.deviations,
            fit.rounds,
            fit.knots.len()
        );
        assert_eq!(fit.controls[0].len(), fit.controls[1].len());
        for (c, s) in fit.controls.iter().zip(&sections) {
            // Ends and the split point are interpolated.
            assert_eq!(c[0], s.points[0]);
            assert_eq!(*c.last().unwrap(), *s.points.last().unwrap());
            let le = eval(&fit.knots, c, 0.5);
            assert!(le.distance(s.points[s.split.unwrap()]) < 1e-13, "{le:?}");
        }
    }
}

//! Predictor-corrector continuation of a level curve `F(u, v) = f(P(u, v)) = 0` in the
//! parameter plane (Aulchenko et al., formulas (22)–(23); docs/methods.md §1.4).
//!
//! The paper integrates the arc-length ODE (23), `du/dl = F_v / |grad F|`,
//! `dv/dl = -F_u / |grad F|`, and warns that it is often stiff. Continuation avoids the
//! stiffness: each step goes along the tangent `(F_v, -F_u)` (the predictor, scaled to a chosen
//! length on the surface) and Newton's method brings the point back onto `F = 0` (the
//! corrector, the minimum-norm update `-F grad F / |grad F|^2`), so errors never accumulate and
//! every point is on the level set to rounding.
//!
//! Step control: the step is the surface length `h`; it is accepted when Newton converges
//! close to the prediction, the tangent turns by less than [`MAX_TURN`], and the chord's
//! deviation from the arc (estimated as `h theta / 8` from the turn `theta`) is within the
//! tolerance; otherwise `h` is cut. A step never spans more than one grid cell. At an open
//! border the step is clipped to the border and the corrector runs along it; in a closed
//! direction the trace runs across the seam. A curve ends at the border, at a pole (a border
//! line that is one point, such as a body's nose, where the level function vanishes along the
//! whole line), when it comes back to its start (closed), or with a warning: at a singular point (the plane touching the surface),
//! when the step shrinks to nothing, or when the step budget runs out. No loop is unbounded.

use super::plane::LevelFunction;
use super::result::SectionWarning;
use super::sample_grid::SampleGrid;
use crate::core::Surface;
use crate::Point;

/// Largest turn of the tangent over one step, in radians.
const MAX_TURN: f64 = 0.4;
/// Newton iterations per correction.
const NEWTON_ITERATIONS: usize = 12;
/// Under this ratio of the surface gradient of the level function to its full size (the sine
/// of the angle between the plane and the surface, for a plane) a point counts as singular.
const SINGULAR: f64 = 1e-9;
/// Under this parameter step (in cells) the trace gives up.
const MIN_STEP: f64 = 1e-10;

/// A point of a traced curve: cell coordinates (unwrapped) and the surface point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Node<const D: usize> {
    pub(crate) s: [f64; 2],
    pub(crate) point: Point<D>,
}

/// Everything known at one parameter point.
#[derive(Clone, Copy, Debug)]
pub(crate) struct Probe<const D: usize> {
    pub(crate) s: [f64; 2],
    pub(crate) point: Point<D>,
    /// `dP/ds` along each cell coordinate.
    d: [Point<D>; 2],
    /// The level function's value.
    pub(crate) g: f64,
    /// Its derivatives along the cell coordinates.
    dg: [f64; 2],
    /// The size of the level function's gradient in space.
    grad_norm: f64,
}

impl<const D: usize> Probe<D> {
    pub(crate) fn node(&self) -> Node<D> {
        Node {
            s: self.s,
            point: self.point,
        }
    }
}

/// The unit tangent of the level curve.
#[derive(Clone, Copy, Debug)]
struct Tangent<const D: usize> {
    /// Cell coordinates per unit of surface length.
    param: [f64; 2],
    /// The unit tangent vector in space.
    space: Point<D>,
    /// +1 when along `(F_v, -F_u)`, -1 when against it. It changes only where the gradient
    /// of `F` turns round: at a singular point the curve ran through.
    orientation: f64,
}

impl<const D: usize> Tangent<D> {
    /// The larger parameter speed: `1 / param_speed` is the length of a one-cell step.
    fn param_speed(&self) -> f64 {
        self.param[0].abs().max(self.param[1].abs())
    }
}

/// How one direction of a trace ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Ending {
    /// At an open border of the domain.
    Border,
    /// Back at its start: the curve is closed.
    Closed,
    /// Stopped short, with the reason.
    Stopped(SectionWarning),
}

/// What one attempted step of a trace came to.
enum Step<const D: usize> {
    /// Accepted.
    Accepted(Accepted<D>),
    /// Refused: try again with the step scaled by the factor.
    Shrink(f64),
    /// The trace ends.
    End(Ending),
}

/// An accepted step: the new point and its tangent, the chord's length, the chord's
/// deviation from the curve, and the border the point lies on.
struct Accepted<const D: usize> {
    next: Probe<D>,
    next_tangent: Tangent<D>,
    length: f64,
    deviation: f64,
    border: Option<usize>,
}

/// The continuation of the level set of `level` on `surface`.
pub(crate) struct Tracer<'a, S: ?Sized, F, const D: usize> {
    pub(crate) surface: &'a S,
    pub(crate) level: &'a F,
    pub(crate) grid: &'a SampleGrid<D>,
    /// The chord tolerance (a length).
    pub(crate) tolerance: f64,
    /// Step budget per direction.
    pub(crate) max_steps: usize,
    /// `|F|` under which Newton stops at once.
    pub(crate) converged: f64,
    /// `|F|` still accepted when Newton stalls at rounding.
    pub(crate) acceptable: f64,
}

impl<S: Surface<D> + ?Sized, F: LevelFunction<D>, const D: usize> Tracer<'_, S, F, D> {
    /// The level function's value at cell coordinates `s`.
    pub(crate) fn value(&self, s: [f64; 2]) -> f64 {
        let (u, v) = self.grid.params(s);
        self.level.value(self.surface.eval(u, v))
    }

    /// Point, derivatives and level function at cell coordinates `s`.
    pub(crate) fn probe(&self, s: [f64; 2]) -> Probe<D> {
        let (u, v) = self.grid.params(s);
        let point = self.surface.eval(u, v);
        let d = [
            self.surface.deriv(u, v, 1, 0) * self.grid.u.cell(),
            self.surface.deriv(u, v, 0, 1) * self.grid.v.cell(),
        ];
        let gradient = self.level.gradient(point);
        Probe {
            s,
            point,
            d,
            g: self.level.value(point),
            dg: [gradient.dot(d[0]), gradient.dot(d[1])],
            grad_norm: gradient.norm(),
        }
    }

    /// The warning-carrying parameters of cell coordinates `s`.
    fn at(&self, s: [f64; 2]) -> (f64, f64) {
        self.grid.params(s)
    }

    /// Newton's method onto `F = 0` from `start`; with `border = Some(k)` coordinate `k` stays
    /// fixed (the corrector runs along a border line). Returns the converged probe and the
    /// surface point at `start`.
    pub(crate) fn correct(
        &self,
        start: [f64; 2],
        border: Option<usize>,
    ) -> Option<(Probe<D>, Point<D>)> {
        let mut probe = self.probe(start);
        let first = probe.point;
        for _ in 0..NEWTON_ITERATIONS {
            if probe.g.abs() <= self.converged {
                return Some((probe, first));
            }
            let mut s = probe.s;
            let [gu, gv] = probe.dg;
            match border {
                None => {
                    let norm_sq = gu * gu + gv * gv;
                    if !norm_sq.is_finite() || norm_sq <= 0.0 {
                        return None;
                    }
                    s[0] -= probe.g * gu / norm_sq;
                    s[1] -= probe.g * gv / norm_sq;
                }
                Some(k) => {
                    let slope = probe.dg[1 - k];
                    if !slope.is_finite() || slope == 0.0 {
                        return None;
                    }
                    s[1 - k] -= probe.g / slope;
                }
            }
            if (s[0] - start[0]).abs() > 2.0 || (s[1] - start[1]).abs() > 2.0 {
                return None; // running away: not the curve near the prediction
            }
            probe = self.probe(s);
        }
        (probe.g.abs() <= self.acceptable).then_some((probe, first))
    }

    /// The unit tangent at `probe`, oriented along `previous` (or by `sign` without one);
    /// `None` at a singular point.
    fn tangent(
        &self,
        probe: &Probe<D>,
        previous: Option<&Tangent<D>>,
        sign: f64,
    ) -> Option<Tangent<D>> {
        let [gu, gv] = probe.dg;
        // The direction (F_v, -F_u) scaled by the larger of the two: the velocity is then of
        // the surface's size, not its square, so that neither it nor its length overflows
        // or underflows for surfaces near 1e80 or 1e-80 (and well beyond).
        let scale = gu.abs().max(gv.abs());
        let (su, sv) = if scale > 0.0 && scale.is_finite() {
            (gu / scale, gv / scale)
        } else {
            (gu, gv)
        };
        let velocity = probe.d[0] * sv - probe.d[1] * su;
        let speed = velocity.norm();
        let surface_gradient = gu.hypot(gv);
        let reference = probe.grad_norm * (probe.d[0].norm() + probe.d[1].norm());
        // Written so that NaN counts as singular.
        let regular = surface_gradient > SINGULAR * reference && speed > 0.0 && speed.is_finite();
        if !regular {
            return None;
        }
        let mut t = Tangent {
            param: [sv / speed, -su / speed],
            space: velocity * (1.0 / speed),
            orientation: 1.0,
        };
        let flip = match previous {
            Some(p) => t.space.dot(p.space) < 0.0,
            None => sign < 0.0,
        };
        if flip {
            t.param = [-t.param[0], -t.param[1]];
            t.space = -t.space;
            t.orientation = -1.0;
        }
        Some(t)
    }

    /// Traces from `start` in direction `sign` (+1 or -1 along `(F_v, -F_u)`), appending the
    /// new points to `out` (which holds the start) and warnings about singular points run
    /// through to `warnings`. With `closing`, a return to the start ends the trace as closed.
    pub(crate) fn trace(
        &self,
        start: &Probe<D>,
        sign: f64,
        closing: bool,
        out: &mut Vec<Node<D>>,
        warnings: &mut Vec<SectionWarning>,
    ) -> Ending {
        let Some(mut tangent) = self.tangent(start, None, sign) else {
            let (u, v) = self.at(start.s);
            return Ending::Stopped(SectionWarning::SingularPoint { u, v });
        };
        let mut current = *start;
        let mut h = 0.5 / tangent.param_speed();
        let mut steps = 0;
        loop {
            if steps >= self.max_steps {
                let (u, v) = self.at(current.s);
                return Ending::Stopped(SectionWarning::StepLimit { u, v, steps });
            }
            steps += 1;
            h = h.min(1.0 / tangent.param_speed());
            let big_enough = h * tangent.param_speed() >= MIN_STEP; // false for NaN
            if !big_enough {
                let (u, v) = self.at(current.s);
                return Ending::Stopped(SectionWarning::StepTooSmall { u, v });
            }
            let Accepted {
                next,
                next_tangent,
                length,
                deviation,
                border,
            } = match self.step(&current, &tangent, (h, sign), out) {
                Step::Accepted(accepted) => accepted,
                Step::Shrink(factor) => {
                    h *= factor;
                    continue;
                }
                Step::End(ending) => return ending,
            };
            if closing && out.len() >= 3 && self.closes(&out[0], &current, &next) {
                return Ending::Closed;
            }
            out.push(next.node());
            if next_tangent.orientation != tangent.orientation {
                let mid = [
                    0.5 * (current.s[0] + next.s[0]),
                    0.5 * (current.s[1] + next.s[1]),
                ];
                let (u, v) = self.at(mid);
                warnings.push(SectionWarning::ThroughSingularPoint { u, v });
            }
            if border.is_some() {
                return Ending::Border;
            }
            let growth = if deviation > 0.0 {
                (0.9 * (self.tolerance / deviation).sqrt()).clamp(0.5, 2.0)
            } else {
                2.0
            };
            h = length * growth;
            current = next;
            tangent = next_tangent;
        }
    }

    /// One attempted step of length `h` from `current` along `tangent` (`sign` as in
    /// [`Self::trace`]): predicted, corrected back onto the level set inside the domain, and
    /// accepted when it moved forward little turned and within the tolerance of the chord.
    /// A step that ends the trace at a pole or a singular point appends its last point to
    /// `out`.
    fn step(
        &self,
        current: &Probe<D>,
        tangent: &Tangent<D>,
        (h, sign): (f64, f64),
        out: &mut Vec<Node<D>>,
    ) -> Step<D> {
        let (prediction, border) = self.predict(current, tangent, h);
        let Some((prediction, border)) = prediction.map(|p| (p, border)) else {
            return Step::End(Ending::Border); // on the border, heading out
        };
        let Some((next, moved, border)) = self.corrected_inside(prediction, border) else {
            return Step::Shrink(0.5);
        };
        let chord = next.point - current.point;
        let length = chord.norm();
        if self.grid.pole_at(next.s).is_some() {
            // A pole on the level set: the whole line is one point, where the curve ends
            // (and is joined to the curve leaving it; see `scan.rs`).
            if moved > 0.5 * h || length.is_nan() || length <= 0.0 {
                return Step::Shrink(0.5);
            }
            out.push(next.node());
            return Step::End(Ending::Border);
        }
        let Some(next_tangent) = self.tangent(&next, Some(tangent), sign) else {
            if moved <= 0.5 * h && length > 0.0 {
                out.push(next.node());
            }
            let (u, v) = self.at(next.s);
            return Step::End(Ending::Stopped(SectionWarning::SingularPoint { u, v }));
        };
        let turn = angle(tangent.space, next_tangent.space);
        let heading = if length > 0.0 {
            angle(tangent.space, chord * (1.0 / length))
        } else {
            0.0
        };
        let moved_forward = length > 0.0; // false for NaN
        if moved > 0.5 * h || turn > MAX_TURN || heading > MAX_TURN || !moved_forward {
            return Step::Shrink(0.5);
        }
        let deviation = length * turn / 8.0;
        if deviation > self.tolerance {
            return Step::Shrink((0.9 * (self.tolerance / deviation).sqrt()).max(0.25));
        }
        Step::Accepted(Accepted {
            next,
            next_tangent,
            length,
            deviation,
            border,
        })
    }

    /// The predicted cell coordinates of a step of length `h`, clipped to an open border
    /// (then with the border's direction); `None` when the current point is on a border and
    /// the tangent leads out.
    fn predict(
        &self,
        current: &Probe<D>,
        tangent: &Tangent<D>,
        h: f64,
    ) -> (Option<[f64; 2]>, Option<usize>) {
        let s = current.s;
        let step = [h * tangent.param[0], h * tangent.param[1]];
        let mut fraction = 1.0;
        let mut border = None;
        for k in 0..2 {
            let axis = self.grid.axis(k);
            if axis.closed() || step[k] == 0.0 {
                continue;
            }
            let target = s[k] + step[k];
            let limit = if target < 0.0 {
                0.0
            } else if target > axis.cells() as f64 {
                axis.cells() as f64
            } else {
                continue;
            };
            let f = ((limit - s[k]) / step[k]).max(0.0);
            if f < fraction {
                fraction = f;
                border = Some((k, limit));
            }
        }
        match border {
            None => (Some([s[0] + step[0], s[1] + step[1]]), None),
            Some((k, limit)) => {
                if fraction * h * tangent.param_speed() < MIN_STEP {
                    return (None, None);
                }
                let mut p = [s[0] + fraction * step[0], s[1] + fraction * step[1]];
                p[k] = limit;
                (Some(p), Some(k))
            }
        }
    }

    /// Newton from `prediction`, kept in the domain: a result outside an open border is
    /// corrected again along that border. Returns the probe, how far it lies from the
    /// prediction's point, and the border it ends on.
    fn corrected_inside(
        &self,
        prediction: [f64; 2],
        border: Option<usize>,
    ) -> Option<(Probe<D>, f64, Option<usize>)> {
        let (probe, predicted) = self.correct(prediction, border)?;
        if self.grid.contains(probe.s) {
            return Some((probe, probe.point.distance(predicted), border));
        }
        if border.is_some() {
            return None;
        }
        // Crossed an open border while correcting: correct along that border instead.
        let k = if self.grid.u.contains(probe.s[0]) {
            1
        } else {
            0
        };
        let mut s = probe.s;
        for (j, c) in s.iter_mut().enumerate() {
            let axis = self.grid.axis(j);
            if !axis.closed() {
                *c = c.clamp(0.0, axis.cells() as f64);
            }
        }
        let (probe, _) = self.correct(s, Some(k))?;
        self.grid
            .contains(probe.s)
            .then(|| (probe, probe.point.distance(predicted), Some(k)))
    }

    /// True when the step from `a` to `b` passes the start point again.
    fn closes(&self, start: &Node<D>, a: &Probe<D>, b: &Probe<D>) -> bool {
        let db = [
            self.grid.u.reduce(b.s[0] - start.s[0]),
            self.grid.v.reduce(b.s[1] - start.s[1]),
        ];
        let da = [db[0] - (b.s[0] - a.s[0]), db[1] - (b.s[1] - a.s[1])];
        let seg = [db[0] - da[0], db[1] - da[1]];
        let seg_sq = seg[0] * seg[0] + seg[1] * seg[1];
        let lambda = if seg_sq > 0.0 {
            (-(da[0] * seg[0] + da[1] * seg[1]) / seg_sq).clamp(0.0, 1.0)
        } else {
            0.0
        };
        let closest = [da[0] + lambda * seg[0], da[1] + lambda * seg[1]];
        if closest[0].hypot(closest[1]) > 0.5 {
            return false;
        }
        let near = 2.0 * self.tolerance + 1e-9 * self.grid.scale;
        distance_to_segment(start.point, a.point, b.point) <= near
    }
}

/// The angle between two unit vectors.
fn angle<const D: usize>(a: Point<D>, b: Point<D>) -> f64 {
    a.dot(b).clamp(-1.0, 1.0).acos()
}

/// The distance from `p` to the segment `[a, b]`.
pub(crate) fn distance_to_segment<const D: usize>(p: Point<D>, a: Point<D>, b: Point<D>) -> f64 {
    let ab = b - a;
    let len_sq = ab.norm_sq();
    let t = if len_sq > 0.0 {
        ((p - a).dot(ab) / len_sq).clamp(0.0, 1.0)
    } else {
        0.0
    };
    p.distance(a.add_scaled(t, ab))
}

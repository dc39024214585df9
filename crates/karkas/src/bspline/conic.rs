//! Lines, circles, ellipses, hyperbolas and parabolas as exact rational B-splines (Piegl and Tiller, *The NURBS
//! Book*, §7.3, A7.1): what CAD files give as analytic curves, and the generatrices of the
//! analytic surfaces of [`sweep`](super::sweep).
//!
//! An arc `C(θ) = c + cos θ x + sin θ y` (`x`, `y` the semi-axes as vectors: a circle when
//! they are orthogonal and of equal length) over `[θ_0, θ_1]` is split into `n` equal pieces
//! of at most 90°; each piece is the rational quadratic with end points on the arc, the
//! middle control point where the end tangents meet, and the middle weight `cos(Δ/2)`. The
//! knots are the angles of the splits (each of multiplicity 2, the ends 3), so the curve's
//! parameter equals the angle at every split; between splits it is the rational
//! parameterization of the conic, which differs from the angle (`tan((φ - m)/2) = tan(Δ/4)
//! (2s - 1)` on a piece of mid-angle `m`, `s` the local parameter), while the point set is
//! the arc to rounding.

use super::NurbsCurve;
use crate::{Error, Point, Result};
use std::f64::consts::FRAC_PI_2;

/// The straight segment from `a` (at parameter `t0`) to `b` (at `t1`): degree 1, knots
/// `t0, t0, t1, t1`, so the parameter runs linearly.
///
/// Errors: `t0 >= t1` or not finite ([`Error::InvalidKnot`]); a non-finite end
/// ([`Error::NonFinitePoint`]).
pub fn line_segment<const D: usize>(
    a: Point<D>,
    b: Point<D>,
    (t0, t1): (f64, f64),
) -> Result<NurbsCurve<D>> {
    NurbsCurve::new(1, vec![t0, t0, t1, t1], vec![a, b], vec![1.0, 1.0])
}

/// The number of equal pieces of at most 90° an arc of `sweep` radians is split into.
fn pieces(sweep: f64) -> usize {
    // 90° itself (to rounding) is one piece.
    ((sweep / FRAC_PI_2) * (1.0 - 4.0 * f64::EPSILON))
        .ceil()
        .max(1.0) as usize
}

/// The control points, weights and knots of the arc `c + cos θ x + sin θ y`, `θ` in
/// `[start, end]`.
pub(crate) fn arc_parts<const D: usize>(
    c: Point<D>,
    x: Point<D>,
    y: Point<D>,
    (start, end): (f64, f64),
) -> (Vec<Point<D>>, Vec<f64>, Vec<f64>) {
    let n = pieces(end - start);
    let delta = (end - start) / n as f64;
    let w = (0.5 * delta).cos();
    let at = |theta: f64| c + x * theta.cos() + y * theta.sin();
    let mut control = Vec::with_capacity(2 * n + 1);
    let mut weights = Vec::with_capacity(2 * n + 1);
    let mut knots = vec![start; 3];
    let angle = |k: usize| {
        if k == n {
            end
        } else {
            start + delta * k as f64
        }
    };
    control.push(at(start));
    weights.push(1.0);
    for k in 0..n {
        let mid = start + delta * (k as f64 + 0.5);
        control.push(c + (x * mid.cos() + y * mid.sin()) * (1.0 / w));
        weights.push(w);
        control.push(at(angle(k + 1)));
        weights.push(1.0);
        if k + 1 < n {
            knots.extend([angle(k + 1); 2]);
        }
    }
    knots.extend([end; 3]);
    (control, weights, knots)
}

/// The elliptic (or circular) arc `c + cos θ x + sin θ y` for `θ` from `start` to `end`
/// (`start < end`, at most 2π apart up to rounding): a rational quadratic whose parameter is
/// `θ` at every split (see the module docs). A circle of radius `r` has `|x| = |y| = r`,
/// `x . y = 0`.
///
/// Errors: `start` and `end` not finite or not increasing, a sweep beyond `2π`
/// ([`Error::InvalidSetting`]); a non-finite centre or axis ([`Error::NonFinitePoint`]).
pub fn elliptic_arc<const D: usize>(
    c: Point<D>,
    x: Point<D>,
    y: Point<D>,
    (start, end): (f64, f64),
) -> Result<NurbsCurve<D>> {
    check_sweep(start, end)?;
    let (control, weights, knots) = arc_parts(c, x, y, (start, end));
    NurbsCurve::new(2, knots, control, weights)
}

/// Fails unless `start < end` are finite and at most a full turn (and a little) apart.
pub(crate) fn check_sweep(start: f64, end: f64) -> Result<()> {
    let bad = |value, reason| Error::InvalidSetting {
        name: "an arc's end angle",
        value,
        reason,
    };
    if !(start.is_finite() && end.is_finite() && start < end) {
        return Err(bad(end, "the angles must be finite and increase"));
    }
    if end - start > 2.0 * std::f64::consts::PI * (1.0 + 1e-9) {
        return Err(bad(end, "an arc turns at most once (2 pi)"));
    }
    Ok(())
}

/// The hyperbolic arc `c + cosh t x + sinh t y` for `t` from `start` to `end` (`start <
/// end`, both finite): a rational quadratic in pieces of at most 1 in `t`, each with its end
/// points on the branch, the middle control point `c + (cosh m x + sinh m y) / cosh(Δ/2)`
/// where the end tangents meet (`m` the piece's middle, `Δ` its length) and the middle weight
/// `cosh(Δ/2)` (Piegl and Tiller, §7.5). The parameter equals `t` at the splits.
///
/// Errors: `start` and `end` not finite or not increasing ([`Error::InvalidSetting`]); a
/// non-finite centre or axis ([`Error::NonFinitePoint`]).
pub fn hyperbolic_arc<const D: usize>(
    c: Point<D>,
    x: Point<D>,
    y: Point<D>,
    (start, end): (f64, f64),
) -> Result<NurbsCurve<D>> {
    check_open_range(start, end)?;
    let n = ((end - start) * (1.0 - 4.0 * f64::EPSILON)).ceil().max(1.0) as usize;
    let delta = (end - start) / n as f64;
    let w = (0.5 * delta).cosh();
    let at = |t: f64| c + x * t.cosh() + y * t.sinh();
    let split = |k: usize| {
        if k == n {
            end
        } else {
            start + delta * k as f64
        }
    };
    let mut control = vec![at(start)];
    let mut weights = vec![1.0];
    let mut knots = vec![start; 3];
    for k in 0..n {
        let mid = start + delta * (k as f64 + 0.5);
        control.push(c + (x * mid.cosh() + y * mid.sinh()) * (1.0 / w));
        weights.push(w);
        control.push(at(split(k + 1)));
        weights.push(1.0);
        if k + 1 < n {
            knots.extend([split(k + 1); 2]);
        }
    }
    knots.extend([end; 3]);
    NurbsCurve::new(2, knots, control, weights)
}

/// The parabolic arc `c + t² x + t y` for `t` from `start` to `end` (`start < end`, both
/// finite): one quadratic Bézier piece (a polynomial curve, so its parameter is `t`), the
/// middle control point where the end tangents meet.
///
/// Errors: as [`hyperbolic_arc`].
pub fn parabolic_arc<const D: usize>(
    c: Point<D>,
    x: Point<D>,
    y: Point<D>,
    (start, end): (f64, f64),
) -> Result<NurbsCurve<D>> {
    check_open_range(start, end)?;
    let at = |t: f64| c + x * (t * t) + y * t;
    let tangent = x * (2.0 * start) + y;
    let middle = at(start) + tangent * (0.5 * (end - start));
    NurbsCurve::new(
        2,
        vec![start, start, start, end, end, end],
        vec![at(start), middle, at(end)],
        vec![1.0; 3],
    )
}

/// Fails unless `start < end` are finite.
fn check_open_range(start: f64, end: f64) -> Result<()> {
    if start.is_finite() && end.is_finite() && start < end {
        Ok(())
    } else {
        Err(Error::InvalidSetting {
            name: "an arc's end parameter",
            value: end,
            reason: "the parameters must be finite and increase",
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Curve, Point3};
    use std::f64::consts::PI;

    #[test]
    fn hyperbolic_and_parabolic_arcs_lie_on_their_curves_and_meet_the_splits() {
        let c = Point3::new([4.0, -2.0, 0.5]);
        let x = Point3::new([0.0, 3.0, 0.0]);
        let y = Point3::new([0.0, 0.0, 1.5]);
        for (a, b) in [(-2.5, 3.1), (0.0, 0.4), (1.0, 1.0 + 1e-3), (-7.0, -6.0)] {
            let h = hyperbolic_arc(c, x, y, (a, b)).unwrap();
            let p = parabolic_arc(c, x, y, (a, b)).unwrap();
            assert_eq!((h.domain().start, h.domain().end), (a, b));
            assert_eq!((p.domain().start, p.domain().end), (a, b));
            let size = 3.0 * a.abs().max(b.abs()).cosh();
            for k in 0..=400 {
                let t = h.domain().uniform(k, 401);
                // On the branch: ((q - c).x / |x|^2)^2 - ((q - c).y / |y|^2)^2 = 1, x side > 0.
                let d = h.eval(t) - c;
                let (ch, sh) = (d.dot(x) / 9.0, d.dot(y) / 2.25);
                assert!(
                    (ch * ch - sh * sh - 1.0).abs() < 1e-12 * size * size,
                    "t {t}"
                );
                assert!(ch > 0.0 && d.dot(Point3::new([1.0, 0.0, 0.0])).abs() < 1e-12);
                // The parabola's parameter is t itself.
                let q = c + x * (t * t) + y * t;
                assert!(p.eval(t).distance(q) < 1e-12 * (1.0 + t * t) * 3.0, "t {t}");
            }
            let n = ((b - a) * (1.0 - 4.0 * f64::EPSILON)).ceil().max(1.0) as usize;
            for k in 0..=n {
                let t = if k == n {
                    b
                } else {
                    a + (b - a) * k as f64 / n as f64
                };
                let q = c + x * t.cosh() + y * t.sinh();
                assert!(h.eval(t).distance(q) < 1e-12 * size, "split {t}");
            }
        }
        assert!(hyperbolic_arc(c, x, y, (1.0, 1.0)).is_err());
        assert!(parabolic_arc(c, x, y, (0.0, f64::NAN)).is_err());
    }

    #[test]
    fn circle_arcs_lie_on_the_circle_and_meet_the_angles_at_the_splits() {
        let c = Point3::new([1.0, -2.0, 0.5]);
        let x = Point3::new([0.0, 3.0, 0.0]);
        let y = Point3::new([0.0, 0.0, 3.0]);
        for (a, b) in [
            (0.0, 2.0 * PI),
            (0.3, 1.2),
            (-1.0, 3.0),
            (0.0, PI / 2.0),
            (2.0, 2.0 + 1e-3),
        ] {
            let arc = elliptic_arc(c, x, y, (a, b)).unwrap();
            assert_eq!((arc.domain().start, arc.domain().end), (a, b));
            let n = pieces(b - a);
            assert_eq!(arc.control_points().len(), 2 * n + 1);
            for k in 0..=400 {
                let t = arc.domain().uniform(k, 401);
                let p = arc.eval(t);
                assert!(((p - c).norm() - 3.0).abs() < 4e-15 * 3.0, "{a} {b} {t}");
                assert!((p[0] - 1.0).abs() < 1e-15);
            }
            for k in 0..=n {
                let theta = a + (b - a) * k as f64 / n as f64;
                let want = c + x * theta.cos() + y * theta.sin();
                assert!(arc.eval(theta).distance(want) < 1e-14, "{a} {b} {k}");
            }
            // The rational parameterization: tan((φ - m)/2) = tan(Δ/4) (2s - 1).
            let delta = (b - a) / n as f64;
            let s: f64 = 0.3;
            let phi = a + 0.5 * delta + 2.0 * ((delta / 4.0).tan() * (2.0 * s - 1.0)).atan();
            let want = c + x * phi.cos() + y * phi.sin();
            assert!(arc.eval(a + s * delta).distance(want) < 1e-14);
        }
        assert!(elliptic_arc(c, x, y, (0.0, 7.0)).is_err());
        assert!(elliptic_arc(c, x, y, (1.0, 1.0)).is_err());
    }

    #[test]
    fn ellipses_are_affine_images_of_circles() {
        let c = Point3::ZERO;
        let x = Point3::new([5.0, 0.0, 0.0]);
        let y = Point3::new([0.0, 2.0, 0.0]);
        let e = elliptic_arc(c, x, y, (0.0, 2.0 * PI)).unwrap();
        for k in 0..=100 {
            let p = e.eval(2.0 * PI * k as f64 / 100.0);
            let r = (p[0] / 5.0).hypot(p[1] / 2.0);
            assert!((r - 1.0).abs() < 1e-15);
        }
        let s = line_segment(Point3::ZERO, x, (2.0, 7.0)).unwrap();
        assert!(s.eval(3.0).distance(Point3::new([1.0, 0.0, 0.0])) < 1e-15);
    }
}

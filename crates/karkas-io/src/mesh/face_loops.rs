//! The trimming loops of a face as its mesh takes them (`karkas convert`, [`super::shape_mesh`]):
//! each loop thinned to the vertices that keep its image on the surface within the
//! tolerance, its corners kept, and the grid nodes too near a loop left out.

use karkas::bspline::NurbsSurface;
use karkas::core::Surface;
use karkas::shape::FaceDomain;
use karkas::Point3;

use crate::mesh::shape_seams::along;

/// The vertices of the closed loop `points` (in `s`'s parameters) that keep its image on the
/// surface within `tolerance` of the loop's (Douglas and Peucker's rule on the surface points,
/// the loop cut at its first vertex, the one farthest from it and its [`corners`]).
pub(crate) fn simplified(
    s: &NurbsSurface<3>,
    points: &[[f64; 2]],
    tolerance: f64,
) -> Vec<[f64; 2]> {
    let (points, at) = without_jogs(s, points, JOG_IMAGE * tolerance);
    let n = points.len();
    if n < 4 {
        return points;
    }
    let far = (1..n)
        .max_by(|&a, &b| at[a].distance(at[0]).total_cmp(&at[b].distance(at[0])))
        .unwrap_or(n / 2);
    let mut keep = vec![false; n + 1];
    keep[0] = true;
    keep[far] = true;
    keep[n] = true;
    for k in corners(&at, 1e-6 * tolerance, tolerance) {
        keep[k] = true;
    }
    let fixed: Vec<usize> = (0..=n).filter(|&k| keep[k]).collect();
    let mut stack: Vec<(usize, usize)> = fixed.windows(2).map(|w| (w[0], w[1])).collect();
    while let Some((a, b)) = stack.pop() {
        let (pa, pb) = (at[a % n], at[b % n]);
        let worst = (a + 1..b)
            .map(|k| (k, along(at[k], pa, pb)))
            .map(|(k, (t, d))| {
                (
                    k,
                    if (0.0..=1.0).contains(&t) {
                        d
                    } else {
                        at[k].distance(pa).min(at[k].distance(pb))
                    },
                )
            })
            .max_by(|x, y| x.1.total_cmp(&y.1));
        if let Some((k, d)) = worst {
            if d > tolerance {
                keep[k] = true;
                stack.push((a, k));
                stack.push((k, b));
            }
        }
    }
    (0..n).filter(|&k| keep[k]).map(|k| points[k]).collect()
}

/// The points of the closed loop `points` with their images on `s`, less each point whose
/// image lies within `same` of the last point kept and whose parameters differ from its by
/// less than [`JOG`] of the domain: the end of one edge and the start of the next where a
/// model written face by face (IGES) lets them miss each other by the writer's resolution
/// (Open CASCADE's: 1e-7 to 2e-7 apart). Such a jog would be two corners a hair apart,
/// which the faces around it cannot all share, and a sliver triangle between them; the
/// points of a pole, one image over a stretch of parameters, are kept.
fn without_jogs(
    s: &NurbsSurface<3>,
    points: &[[f64; 2]],
    same: f64,
) -> (Vec<[f64; 2]>, Vec<Point3>) {
    let (du, dv) = (s.domain_u().length(), s.domain_v().length());
    let jog = |a: ([f64; 2], Point3), b: ([f64; 2], Point3)| {
        a.1.distance(b.1) <= same
            && (a.0[0] - b.0[0]).abs() <= JOG * du
            && (a.0[1] - b.0[1]).abs() <= JOG * dv
    };
    let mut kept: Vec<([f64; 2], Point3)> = Vec::with_capacity(points.len());
    for &p in points {
        let image = (p, s.eval(p[0], p[1]));
        if kept.last().is_none_or(|&last| !jog(last, image)) {
            kept.push(image);
        }
    }
    // The loop closes: its last point against its first.
    while kept.len() > 1 && jog(kept[kept.len() - 1], kept[0]) {
        kept.pop();
    }
    kept.into_iter().unzip()
}

/// The share of a surface's parameter domain within which two loop points with one image are
/// a jog of the model's edges, not a stretch of a pole.
const JOG: f64 = 1e-6;
/// The share of the tolerance within which the images of a jog's two points lie: far below
/// what the mesh resolves.
const JOG_IMAGE: f64 = 1e-3;

/// The vertices of the closed polygon `at` (a loop's image on the surface) that must stay in
/// its mesh: both ends of a run of vertices at one point (within `same`: a pole, where a
/// stretch of the parameter loop is one point of the surface), and where the loop turns by
/// more than 45 degrees between its points `near` away on either side (where the model's
/// edges meet at an angle: shared corners of the faces around them), the sharpest turn of
/// those within `near` of each other. Dropping such a vertex cut the corner of a sphere's
/// cap by a side that the neighbouring face's side could not meet; a jog shorter than `near`
/// (two edges' ends apart by the model's gap) is one corner, not two.
fn corners(at: &[Point3], same: f64, near: f64) -> Vec<usize> {
    let n = at.len();
    let beyond = |k: usize, step: usize| {
        (1..n)
            .map(|j| (k + j * step) % n)
            .find(|&j| at[j].distance(at[k]) > near)
    };
    let mut out = Vec::new();
    // The sharp turns, as (vertex, cosine of the turn).
    let mut turns: Vec<(usize, f64)> = Vec::new();
    for k in 0..n {
        let (prev, next) = (at[(k + n - 1) % n], at[(k + 1) % n]);
        match (prev.distance(at[k]) <= same, next.distance(at[k]) <= same) {
            (true, true) => continue,
            (true, false) | (false, true) => {
                out.push(k);
                continue;
            }
            (false, false) => {}
        }
        let (Some(b), Some(a)) = (beyond(k, n - 1), beyond(k, 1)) else {
            continue;
        };
        let (d0, d1) = (at[k] - at[b], at[a] - at[k]);
        let cosine = d0.dot(d1) / (d0.norm() * d1.norm());
        if cosine < std::f64::consts::FRAC_1_SQRT_2 {
            match turns.last_mut() {
                Some(last) if at[last.0].distance(at[k]) <= near => {
                    if cosine < last.1 {
                        *last = (k, cosine);
                    }
                }
                _ => turns.push((k, cosine)),
            }
        }
    }
    out.extend(turns.iter().map(|t| t.0));
    out.sort_unstable();
    out
}

/// For each node `(us[i], vs[j])` (row-major), whether it lies within a third of the
/// smaller adjacent step of a loop segment, in scaled parameters.
pub(crate) fn nodes_near_loops(
    domain: &FaceDomain,
    us: &[f64],
    vs: &[f64],
    scale: (f64, f64),
) -> Vec<bool> {
    let mut near = vec![false; us.len() * vs.len()];
    let gap = |lines: &[f64], i: usize| {
        let before = if i > 0 {
            lines[i] - lines[i - 1]
        } else {
            f64::INFINITY
        };
        let after = if i + 1 < lines.len() {
            lines[i + 1] - lines[i]
        } else {
            f64::INFINITY
        };
        before.min(after)
    };
    let widest = |lines: &[f64]| lines.windows(2).map(|w| w[1] - w[0]).fold(0.0, f64::max);
    let (reach_u, reach_v) = (widest(us) / 3.0, widest(vs) / 3.0);
    for l in &domain.loops {
        for k in 0..l.points.len() {
            let (p, q) = (l.points[k], l.points[(k + 1) % l.points.len()]);
            let i0 = us.partition_point(|&u| u < p[0].min(q[0]) - reach_u);
            let i1 = us.partition_point(|&u| u <= p[0].max(q[0]) + reach_u);
            let j0 = vs.partition_point(|&v| v < p[1].min(q[1]) - reach_v);
            let j1 = vs.partition_point(|&v| v <= p[1].max(q[1]) + reach_v);
            for i in i0..i1 {
                for j in j0..j1 {
                    let limit = (gap(us, i) * scale.0).min(gap(vs, j) * scale.1) / 3.0;
                    let d = segment_distance([us[i], vs[j]], p, q, scale);
                    if d < limit {
                        near[i * vs.len() + j] = true;
                    }
                }
            }
        }
    }
    near
}

/// The distance of `x` from the segment `p q`, in parameters scaled by `scale`.
fn segment_distance(x: [f64; 2], p: [f64; 2], q: [f64; 2], scale: (f64, f64)) -> f64 {
    let s = |a: [f64; 2]| [a[0] * scale.0, a[1] * scale.1];
    let (x, p, q) = (s(x), s(p), s(q));
    let d = [q[0] - p[0], q[1] - p[1]];
    let len2 = d[0] * d[0] + d[1] * d[1];
    let t = if len2 > 0.0 {
        (((x[0] - p[0]) * d[0] + (x[1] - p[1]) * d[1]) / len2).clamp(0.0, 1.0)
    } else {
        0.0
    };
    let e = [x[0] - p[0] - t * d[0], x[1] - p[1] - t * d[1]];
    (e[0] * e[0] + e[1] * e[1]).sqrt()
}

#[cfg(test)]
mod tests {
    use super::corners;
    use karkas::Point3;

    fn p(x: f64, y: f64, z: f64) -> Point3 {
        Point3::new([x, y, z])
    }

    #[test]
    fn a_square_loop_keeps_its_four_corners_and_no_point_of_its_sides() {
        let mut at = Vec::new();
        for k in 0..4 {
            at.push(p(k as f64 / 4.0, 0.0, 0.0));
        }
        for k in 0..4 {
            at.push(p(1.0, k as f64 / 4.0, 0.0));
        }
        for k in 0..4 {
            at.push(p(1.0 - k as f64 / 4.0, 1.0, 0.0));
        }
        for k in 0..4 {
            at.push(p(0.0, 1.0 - k as f64 / 4.0, 0.0));
        }
        assert_eq!(corners(&at, 1e-12, 1e-9), vec![0, 4, 8, 12]);
    }

    #[test]
    fn a_circle_sampled_finely_has_no_corner() {
        let at: Vec<Point3> = (0..64)
            .map(|k| {
                let t = k as f64 * std::f64::consts::TAU / 64.0;
                p(t.cos(), t.sin(), 0.5)
            })
            .collect();
        assert!(corners(&at, 1e-12, 1e-9).is_empty());
    }

    #[test]
    fn both_ends_of_a_run_at_one_point_are_kept() {
        // A loop on a sphere's cap: up one meridian, three samples of the pole, down another.
        let pole = p(0.0, 0.0, 1.0);
        let up = |t: f64| p(t.sin(), 0.0, t.cos());
        let down = |t: f64| p(0.0, t.sin(), t.cos());
        let at = vec![
            up(0.6),
            up(0.4),
            up(0.2),
            pole,
            pole,
            pole,
            down(0.2),
            down(0.4),
            down(0.6),
        ];
        let kept = corners(&at, 1e-12, 1e-9);
        assert!(kept.contains(&3) && kept.contains(&5), "{kept:?}");
        assert!(!kept.contains(&4), "{kept:?}");
        assert!(!kept.contains(&1) && !kept.contains(&7), "{kept:?}");
    }
}

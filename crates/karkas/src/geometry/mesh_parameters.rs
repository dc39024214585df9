//! The parameters of a triangle mesh of a surface within a chordal tolerance: a tensor grid
//! of samples, refined where the surface bends, so that the mesh the writers make of it (two
//! triangles per cell, split along the diagonal from `(u_a, v_b)` to `(u_{a+1}, v_{b+1})`)
//! stays within the tolerance of the surface.
//!
//! Method: start from a uniform 9 x 9 grid; in each round measure, for every cell, the
//! distance from the surface to the triangles at seven points of the cell, each compared with
//! the point of the triangles at the same parameters (an upper bound of its distance to the
//! mesh): the midpoints of the four edges, of the diagonal, and the two triangles' centroids.
//! A `u` interval whose edges along `u` miss the tolerance somewhere is halved, and so is a
//! `v` interval; a cell whose diagonal or centroids miss it (its edges being within: the bends
//! along `u` and `v` add up there, and a twist with them) halves the interval of its larger
//! edge deviation, or, when its edges are nearly straight (a twist), the interval whose new
//! line of samples is the shorter. Rounds stop when every cell is within the tolerance, or when the next
//! round would pass the sample budget. A grid keeps one spacing per row and column, so a
//! surface whose bending runs along the parameter lines (a wing's leading edge) gets dense
//! rows there and sparse ones elsewhere: far fewer samples than a uniform grid of the same
//! accuracy. The chord error of a smooth surface is quadratic in the spacing, largest near
//! the points measured; the deviation reported is the largest measured.
//!
//! Cost: each round evaluates the surface about six times per cell; the rounds are about
//! `log2` of the refinement, so the whole costs a few times the final grid's evaluations.

use crate::core::{Point, Surface};

/// The parameters of a mesh of a surface within a tolerance ([`mesh_parameters`]).
#[derive(Clone, Debug, PartialEq)]
pub struct MeshParameters {
    /// The `u` of the sample rows, ascending, the domain's ends included.
    pub us: Vec<f64>,
    /// The `v` of the sample columns, ascending, the domain's ends included.
    pub vs: Vec<f64>,
    /// The largest distance measured from the surface to the triangles' points at the same
    /// parameters (an upper bound of the distance to the mesh at the points measured).
    pub max_deviation: f64,
    /// True when the tolerance was met; false when the sample budget stopped the refinement.
    pub met: bool,
}

/// The default tolerance of a mesh, relative to the size of the surface
/// ([`surface_size`]): what `karkas.export` meshes a surface to when no samples are asked for.
pub const DEFAULT_RELATIVE_TOLERANCE: f64 = 1e-4;

/// The size of `surface`: the diagonal of the bounding box of 33 x 33 samples over its
/// domain (0 for a surface at one point; NaN samples are skipped).
pub fn surface_size<const D: usize>(surface: &impl Surface<D>) -> f64 {
    const N: usize = 33;
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let (us, vs): (Vec<f64>, Vec<f64>) = (
        (0..N).map(|k| du.uniform(k, N)).collect(),
        (0..N).map(|k| dv.uniform(k, N)).collect(),
    );
    let mut points = vec![Point::ZERO; N * N];
    surface.eval_grid_into(&us, &vs, &mut points);
    let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    for p in points.iter().filter(|p| p.0.iter().all(|c| c.is_finite())) {
        for c in 0..D {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let scale = (0..D)
        .map(|c| (hi[c] - lo[c]).abs())
        .filter(|d| d.is_finite())
        .fold(0.0, f64::max);
    if scale == 0.0 {
        return 0.0;
    }
    let sum: f64 = (0..D)
        .map(|c| ((hi[c] - lo[c]) / scale).powi(2))
        .filter(|d| d.is_finite())
        .sum();
    scale * sum.sqrt()
}

/// The points of a cell measured against its triangles, as `(s, t)` in the cell (`s` along
/// `u`, `t` along `v`, 0 to 1) and whether each lies on an edge along `u` (0), along `v` (1),
/// or inside (2).
const PROBES: [(f64, f64, usize); 7] = [
    (0.5, 0.0, 0),
    (0.5, 1.0, 0),
    (0.0, 0.5, 1),
    (1.0, 0.5, 1),
    (0.5, 0.5, 2),
    (2.0 / 3.0, 1.0 / 3.0, 2),
    (1.0 / 3.0, 2.0 / 3.0, 2),
];

/// The initial samples per direction.
const START: usize = 9;

/// The rounds of refinement at most (each at least halves a spacing somewhere).
const MAX_ROUNDS: usize = 40;

/// Sample parameters of `surface` whose mesh lies within `tolerance` of it, with at most
/// `max_samples` samples in all (see the [module docs](self)). A `tolerance` that is not
/// positive (or NaN) is never met: the refinement stops at the budget with `met` false.
pub fn mesh_parameters<const D: usize>(
    surface: &(impl Surface<D> + Sync),
    tolerance: f64,
    max_samples: usize,
) -> MeshParameters {
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let uniform = |lo: f64, hi: f64| -> Vec<f64> {
        (0..START)
            .map(|k| lo + (hi - lo) * k as f64 / (START - 1) as f64)
            .collect()
    };
    let mut us = uniform(du.start, du.end);
    let mut vs = uniform(dv.start, dv.end);
    loop {
        let (split_u, split_v, worst) = measure(surface, &us, &vs, tolerance);
        let done = !split_u.iter().any(|&s| s) && !split_v.iter().any(|&s| s);
        let more_u = split_u.iter().filter(|&&s| s).count();
        let more_v = split_v.iter().filter(|&&s| s).count();
        let next = (us.len() + more_u).saturating_mul(vs.len() + more_v);
        if done || next > max_samples || rounds_exhausted(&us, &vs) {
            return MeshParameters {
                us,
                vs,
                max_deviation: worst,
                met: done,
            };
        }
        us = refined(&us, &split_u);
        vs = refined(&vs, &split_v);
    }
}

/// True when a spacing has been halved [`MAX_ROUNDS`] times or no longer halves in floating
/// point: refining further cannot help.
fn rounds_exhausted(us: &[f64], vs: &[f64]) -> bool {
    let tight = |p: &[f64]| {
        let span = p[p.len() - 1] - p[0];
        p.windows(2)
            .any(|w| w[1] - w[0] <= span * 0.5f64.powi(MAX_ROUNDS as i32) || w[1] <= w[0])
    };
    tight(us) || tight(vs)
}

/// `params` with the midpoint of every interval `k` where `split[k]` added.
fn refined(params: &[f64], split: &[bool]) -> Vec<f64> {
    let mut out = Vec::with_capacity(params.len() + split.len());
    for (k, w) in params.windows(2).enumerate() {
        out.push(w[0]);
        if split[k] {
            out.push(0.5 * (w[0] + w[1]));
        }
    }
    out.extend(params.last());
    out
}

/// Which `u` and `v` intervals of the grid `us x vs` to halve, and the largest deviation
/// measured.
fn measure<const D: usize>(
    surface: &(impl Surface<D> + Sync),
    us: &[f64],
    vs: &[f64],
    tolerance: f64,
) -> (Vec<bool>, Vec<bool>, f64) {
    use rayon::prelude::*;
    let (nu, nv) = (us.len(), vs.len());
    let mut grid = vec![Point::ZERO; nu * nv];
    surface.eval_grid_into(us, vs, &mut grid);
    let at = |a: usize, b: usize| grid[a * nv + b];
    // Per row of cells: (deviation along u edges, along v edges, inside) of each cell, and
    // whether its edges along u are longer than those along v.
    let rows: Vec<Vec<([f64; 3], bool)>> = (0..nu - 1)
        .into_par_iter()
        .map(|a| {
            (0..nv - 1)
                .map(|b| {
                    let corners = [at(a, b), at(a + 1, b), at(a, b + 1), at(a + 1, b + 1)];
                    let mut worst = [0.0f64; 3];
                    for &(s, t, kind) in &PROBES {
                        let u = us[a] + s * (us[a + 1] - us[a]);
                        let v = vs[b] + t * (vs[b + 1] - vs[b]);
                        let deviation = surface.eval(u, v).distance(on_triangles(&corners, s, t));
                        worst[kind] = worst[kind].max(deviation);
                    }
                    let [p00, p10, p01, _] = corners;
                    (worst, p00.distance(p10) >= p00.distance(p01))
                })
                .collect()
        })
        .collect();
    let mut split_u = vec![false; nu - 1];
    let mut split_v = vec![false; nv - 1];
    let mut largest = 0.0f64;
    for (a, row) in rows.iter().enumerate() {
        for (b, &([along_u, along_v, inside], u_longer)) in row.iter().enumerate() {
            largest = largest.max(along_u).max(along_v).max(inside);
            // A NaN deviation (a surface that cannot be evaluated there) is refined too.
            let over = |d: f64| {
                !matches!(
                    d.partial_cmp(&tolerance),
                    Some(std::cmp::Ordering::Less | std::cmp::Ordering::Equal)
                )
            };
            split_u[a] |= over(along_u);
            split_v[b] |= over(along_v);
            if over(inside) && !over(along_u) && !over(along_v) {
                // Inside, the bends along u and v add up (and the twist with them): the
                // direction of the larger edge deviation is halved, which quarters its share.
                // A cell whose edges are nearly straight (a twist alone, `P_uv du dv / 4`)
                // halves the side whose new line of samples is the shorter (a row holds `nv`
                // samples, a column `nu`); a tie halves the longer side.
                let split_along_u = if along_u.max(along_v) < 0.25 * inside {
                    match nv.cmp(&nu) {
                        std::cmp::Ordering::Less => true,
                        std::cmp::Ordering::Greater => false,
                        std::cmp::Ordering::Equal => u_longer,
                    }
                } else {
                    along_u >= along_v
                };
                if split_along_u {
                    split_u[a] = true;
                } else {
                    split_v[b] = true;
                }
            }
        }
    }
    (split_u, split_v, largest)
}

/// The point at `(s, t)` of the two triangles of a cell with corners `[P00, P10, P01, P11]`
/// (`P10` one step along `u`), split along the diagonal `P00`-`P11`.
fn on_triangles<const D: usize>(c: &[Point<D>; 4], s: f64, t: f64) -> Point<D> {
    let [p00, p10, p01, p11] = *c;
    if s >= t {
        p00 + (p10 - p00) * s + (p11 - p10) * t
    } else {
        p00 + (p01 - p00) * t + (p11 - p01) * s
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Interval;

    /// A quarter cylinder of radius 1 along v, bending only in u.
    struct Cylinder;

    impl Surface<3> for Cylinder {
        fn domain_u(&self) -> Interval {
            Interval::new(0.0, std::f64::consts::FRAC_PI_2)
        }
        fn domain_v(&self) -> Interval {
            Interval::new(0.0, 2.0)
        }
        fn is_closed_u(&self) -> bool {
            false
        }
        fn is_closed_v(&self) -> bool {
            false
        }
        fn eval(&self, u: f64, v: f64) -> Point<3> {
            Point([u.cos(), u.sin(), v])
        }
        fn deriv(&self, u: f64, v: f64, ku: usize, kv: usize) -> Point<3> {
            let _ = (u, v, ku, kv);
            Point::ZERO
        }
    }

    #[test]
    fn a_cylinder_is_refined_across_its_bend_only() {
        let tolerance = 1e-4;
        let mesh = mesh_parameters(&Cylinder, tolerance, 1 << 20);
        assert!(mesh.met && mesh.max_deviation <= tolerance, "{mesh:?}");
        // The chord error of an arc of angle h is about h^2 / 8: h <= sqrt(8e-4).
        let steps = mesh.us.windows(2).map(|w| w[1] - w[0]);
        assert!(steps.clone().all(|h| h * h / 8.0 <= 1.01 * tolerance));
        assert!(steps.fold(0.0, f64::max) > 0.5 * (8.0 * tolerance).sqrt());
        // Straight along v: the starting columns stay.
        assert_eq!(mesh.vs.len(), START);
    }

    #[test]
    fn the_size_is_the_diagonal_of_the_box() {
        let size = surface_size(&Cylinder);
        assert!((size - (1.0f64 + 1.0 + 4.0).sqrt()).abs() < 1e-12, "{size}");
    }

    #[test]
    fn the_budget_stops_the_refinement() {
        let mesh = mesh_parameters(&Cylinder, 1e-12, 200);
        assert!(
            !mesh.met && mesh.us.len() * mesh.vs.len() <= 200,
            "{mesh:?}"
        );
        let mesh = mesh_parameters(&Cylinder, f64::NAN, 200);
        assert!(!mesh.met);
    }
}

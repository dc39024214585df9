//! Where a plane polyline crosses itself, for the shape guards (docs/methods.md §4): a sweep
//! over the segments sorted by their lowest x, each tested against the segments whose x-range
//! it overlaps (`O(m log m)` plus the pairs that overlap in x, few on a contour).

/// A proper crossing of segments `a < b` (`b > a + 1`) of a polyline, at fractions `sa` and
/// `sb` along them.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) struct Crossing {
    /// The first segment (from vertex `a` to `a + 1`).
    pub a: usize,
    /// The fraction along segment `a`.
    pub sa: f64,
    /// The second segment.
    pub b: usize,
    /// The fraction along segment `b`.
    pub sb: f64,
}

/// Twice the signed area of the triangle `o, p, q`.
fn orient(o: [f64; 2], p: [f64; 2], q: [f64; 2]) -> f64 {
    (p[0] - o[0]) * (q[1] - o[1]) - (p[1] - o[1]) * (q[0] - o[0])
}

/// The proper crossings of the polyline through `vertices` (segments that share a vertex
/// are not tested; touching without crossing does not count), in no particular order.
pub(crate) fn crossings(vertices: &[[f64; 2]]) -> Vec<Crossing> {
    let m = vertices.len().saturating_sub(1);
    let lo = |k: usize| vertices[k][0].min(vertices[k + 1][0]);
    let hi = |k: usize| vertices[k][0].max(vertices[k + 1][0]);
    let mut order: Vec<usize> = (0..m).collect();
    order.sort_by(|&a, &b| lo(a).total_cmp(&lo(b)));
    let mut active: Vec<usize> = Vec::new();
    let mut found = Vec::new();
    for &k in &order {
        let x = lo(k);
        active.retain(|&j| hi(j) >= x);
        let (p, q) = (vertices[k], vertices[k + 1]);
        let (ylo, yhi) = (p[1].min(q[1]), p[1].max(q[1]));
        for &j in &active {
            let (c, d) = (vertices[j], vertices[j + 1]);
            if c[1].max(d[1]) < ylo || c[1].min(d[1]) > yhi {
                continue;
            }
            found.extend(crossing(vertices, j, k));
        }
        active.push(k);
    }
    found
}

/// The proper crossing of segments `j` and `k` of the polyline through `vertices`, if they
/// cross (`None` for segments that share a vertex): the test of [`crossings`] for one pair,
/// the same whichever is given first.
pub(crate) fn crossing(vertices: &[[f64; 2]], j: usize, k: usize) -> Option<Crossing> {
    if j.abs_diff(k) < 2 {
        return None;
    }
    // The four vertices relative to `p` over their largest offset: the orientations are
    // products of two offsets, which underflow for segments shorter than about 1e-154 (and
    // the sign tests below compare signs, not products of two orientations, which
    // underflowed for segments below about 1e-77).
    // Taken in one order, so that the result is the same whichever segment is given first.
    let (j, k) = (j.min(k), j.max(k));
    let p = vertices[k];
    let offsets =
        [vertices[k + 1], vertices[j], vertices[j + 1]].map(|v| [v[0] - p[0], v[1] - p[1]]);
    let unit = offsets.iter().flatten().fold(0.0f64, |m, c| m.max(c.abs()));
    if !(unit > 0.0 && unit.is_finite()) {
        return None;
    }
    let [q, c, d] = offsets.map(|v| [v[0] / unit, v[1] / unit]);
    let p = [0.0, 0.0];
    let (o1, o2) = (orient(p, q, c), orient(p, q, d));
    let (o3, o4) = (orient(c, d, p), orient(c, d, q));
    let opposite = |a: f64, b: f64| (a < 0.0 && b > 0.0) || (a > 0.0 && b < 0.0);
    if !(opposite(o1, o2) && opposite(o3, o4)) {
        return None;
    }
    Some(Crossing {
        a: j,
        sa: o1 / (o1 - o2),
        b: k,
        sb: o3 / (o3 - o4),
    })
}

/// A jittered Lissajous figure of `n` vertices, which crosses itself many times (tests).
#[cfg(test)]
pub(crate) fn jittered_lissajous(n: usize, jitter: f64) -> Vec<[f64; 2]> {
    let tau = 2.0 * std::f64::consts::PI;
    (0..n)
        .map(|i| {
            let s = i as f64 / (n - 1) as f64;
            let shift = jitter * ((i * 7) % 5) as f64;
            [(3.0 * tau * s).sin() + shift, (2.0 * tau * s + 0.3).sin()]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_bowtie_crosses_once() {
        let v = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        let c = crossings(&v);
        assert_eq!(c.len(), 1, "{c:?}");
        assert_eq!((c[0].a, c[0].b), (0, 2));
        assert!((c[0].sa - 0.5).abs() < 1e-15 && (c[0].sb - 0.5).abs() < 1e-15);
    }

    #[test]
    fn crossings_are_found_at_every_scale_and_offset() {
        let bowtie = [[0.0, 0.0], [1.0, 1.0], [1.0, 0.0], [0.0, 1.0]];
        for scale in [1e-300, 1e-160, 1e-80, 1.0, 1e80, 1e150] {
            for offset in [0.0, 1e3 * scale] {
                let v = bowtie.map(|p| [offset + scale * p[0], offset + scale * p[1]]);
                let c = crossings(&v);
                assert_eq!(c.len(), 1, "scale {scale}, offset {offset}");
                assert!((c[0].sa - 0.5).abs() < 1e-12, "scale {scale}: {:?}", c[0]);
            }
        }
    }

    #[test]
    fn one_pair_agrees_with_the_sweep_either_way_round() {
        let v = jittered_lissajous(120, 0.03);
        let mut swept: Vec<(usize, usize)> = crossings(&v).iter().map(|c| (c.a, c.b)).collect();
        swept.sort_unstable();
        assert!(swept.len() > 5, "{swept:?}");
        let m = v.len() - 1;
        let mut paired = Vec::new();
        for j in 0..m {
            for k in j + 1..m {
                let one = crossing(&v, j, k);
                assert_eq!(one, crossing(&v, k, j), "segments {j} and {k}");
                if let Some(c) = one {
                    paired.push((c.a, c.b));
                }
            }
        }
        assert_eq!(swept, paired);
    }
}

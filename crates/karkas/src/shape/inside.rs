//! The inside test of a [`FaceDomain`] with its loops' segments sorted into strips of `v`.
//!
//! [`FaceDomain::contains`] counts the crossings of a ray `+u` from `(u, v)` with every
//! segment of every loop: a face trimmed by many holes, each sampled finely, has tens of
//! thousands of segments, and inspecting points against it tests each of them for every
//! candidate foot. Only segments whose `v` range holds `v` can be crossed, so the segments are
//! kept in strips of equal height in `v` (a segment in every strip its range meets) and a point
//! tests those of its strip only, with the same arithmetic in the same direction: the answers
//! are those of [`FaceDomain::contains`], bit for bit. A plain bucket grid, not a general
//! spatial index crate, because the test needs every segment that meets one horizontal line,
//! which a grid over `v` gives directly.

use super::FaceDomain;

/// Strips per segment (about eight segments a strip).
const SEGMENTS_PER_STRIP: usize = 8;
/// The most strips.
const MAX_STRIPS: usize = 4096;
/// The most strip entries per segment on average (long segments that span many strips).
const MAX_ENTRIES_PER_SEGMENT: usize = 32;

/// A segment of a loop, from `a` (vertex `i`) to `b` (vertex `i - 1`), as the crossing count
/// takes them.
type Segment = [[f64; 2]; 2];

/// [`FaceDomain::contains`] with the segments sorted into strips of `v`.
#[derive(Clone, Debug)]
pub(super) struct InsideIndex {
    u: (f64, f64),
    v: (f64, f64),
    margin: (f64, f64),
    whole: bool,
    /// The lowest `v` of the segments and the strips' count per unit of `v`.
    low: f64,
    scale: f64,
    strips: Vec<Vec<Segment>>,
}

impl InsideIndex {
    /// The index of `domain`'s loops.
    pub(super) fn new(domain: &FaceDomain) -> InsideIndex {
        let mut segments: Vec<Segment> = Vec::new();
        for l in &domain.loops {
            let p = &l.points;
            let mut j = p.len().saturating_sub(1);
            for i in 0..p.len() {
                segments.push([p[i], p[j]]);
                j = i;
            }
        }
        let (low, high) = segments
            .iter()
            .flat_map(|s| [s[0][1], s[1][1]])
            .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
                (lo.min(v), hi.max(v))
            });
        let mut index = InsideIndex {
            u: (domain.u.start, domain.u.end),
            v: (domain.v.start, domain.v.end),
            margin: (1e-12 * domain.u.length(), 1e-12 * domain.v.length()),
            whole: domain.loops.is_empty(),
            low,
            scale: 0.0,
            strips: vec![Vec::new()],
        };
        if segments.is_empty() || high <= low || !low.is_finite() || !high.is_finite() {
            index.strips[0] = segments;
            return index;
        }
        let mut count = (segments.len() / SEGMENTS_PER_STRIP).clamp(1, MAX_STRIPS);
        loop {
            index.scale = count as f64 / (high - low);
            let entries: usize = segments
                .iter()
                .map(|s| {
                    let (a, b) = index.span(s);
                    b - a + 1
                })
                .sum();
            if count == 1 || entries <= MAX_ENTRIES_PER_SEGMENT * segments.len() {
                break;
            }
            count /= 2;
        }
        index.strips = vec![Vec::new(); count];
        for s in segments {
            let (a, b) = index.span(&s);
            for strip in &mut index.strips[a..=b] {
                strip.push(s);
            }
        }
        index
    }

    /// The strip holding `v` (clamped to the strips).
    fn strip(&self, v: f64) -> usize {
        let k = ((v - self.low) * self.scale).floor();
        if k >= 0.0 {
            (k as usize).min(self.strips.len() - 1)
        } else {
            0
        }
    }

    /// The first and last strips a segment's `v` range meets.
    fn span(&self, s: &Segment) -> (usize, usize) {
        let (a, b) = (s[0][1].min(s[1][1]), s[0][1].max(s[1][1]));
        (self.strip(a), self.strip(b))
    }

    /// True when `(u, v)` lies in the face: [`FaceDomain::contains`].
    pub(super) fn contains(&self, u: f64, v: f64) -> bool {
        if u < self.u.0 - self.margin.0
            || u > self.u.1 + self.margin.0
            || v < self.v.0 - self.margin.1
            || v > self.v.1 + self.margin.1
        {
            return false;
        }
        if self.whole {
            return true;
        }
        if v.is_nan() {
            return false;
        }
        let mut inside = false;
        for [a, b] in &self.strips[self.strip(v)] {
            if (a[1] > v) != (b[1] > v) {
                let x = a[0] + (v - a[1]) / (b[1] - a[1]) * (b[0] - a[0]);
                if u < x {
                    inside = !inside;
                }
            }
        }
        inside
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::core::Interval;
    use crate::shape::ParameterLoop;

    /// A square with many round holes, finely sampled, and a long thin zigzag.
    fn domain() -> FaceDomain {
        let mut loops = vec![ParameterLoop {
            points: vec![[0.0, 0.0], [10.0, 0.0], [10.0, 8.0], [0.0, 8.0]],
        }];
        for i in 0..5 {
            for j in 0..4 {
                let (cu, cv, r) = (
                    1.0 + 2.0 * i as f64,
                    1.0 + 2.0 * j as f64,
                    0.3 + 0.1 * j as f64,
                );
                let n = 200 + 37 * i;
                loops.push(ParameterLoop {
                    points: (0..n)
                        .map(|k| {
                            let t = -std::f64::consts::TAU * k as f64 / n as f64;
                            [cu + r * t.cos(), cv + r * t.sin()]
                        })
                        .collect(),
                });
            }
        }
        loops.push(ParameterLoop {
            points: (0..60)
                .map(|k| [0.05 + 0.15 * k as f64, if k % 2 == 0 { 0.01 } else { 7.9 }])
                .chain([[9.0, 7.95], [0.05, 7.95]])
                .collect(),
        });
        FaceDomain {
            u: Interval::new(0.0, 10.0),
            v: Interval::new(0.0, 8.0),
            loops,
        }
    }

    #[test]
    fn the_index_answers_as_the_domain_does() {
        let d = domain();
        let index = InsideIndex::new(&d);
        assert!(index.strips.len() > 1);
        let mut inside = 0;
        let mut state = 12345u64;
        let mut next = || {
            state = state
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..200_000 {
            let (u, v) = (-0.5 + 11.0 * next(), -0.5 + 9.0 * next());
            assert_eq!(index.contains(u, v), d.contains(u, v), "({u}, {v})");
            inside += usize::from(d.contains(u, v));
        }
        // Vertices, their v exactly, and the rectangle's border.
        for l in &d.loops {
            for p in &l.points {
                for (u, v) in [(p[0], p[1]), (p[0] - 1e-3, p[1]), (0.0, p[1]), (10.0, p[1])] {
                    assert_eq!(index.contains(u, v), d.contains(u, v), "({u}, {v})");
                }
            }
        }
        assert!(inside > 1000 && inside < 199_000, "{inside}");
        let whole = FaceDomain { loops: vec![], ..d };
        let index = InsideIndex::new(&whole);
        assert!(index.contains(5.0, 5.0) && !index.contains(11.0, 5.0));
    }
}

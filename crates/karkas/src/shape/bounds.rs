//! Axis-aligned boxes that bound a face, or one edge of a face, and the lower bound they give
//! on the distance from a point to every point they hold.
//!
//! The nearest-point search ([`ShapeProjector`](super::ShapeProjector)) cuts each face into
//! cells, each a centre `c` and a radius `r` that bounds its points' distance to `c`. The box
//! `[c - r, c + r]` per axis holds the cell, so the union of a face's cell boxes holds the
//! face, and `|q - B|` (the distance from `q` to the box `B`, zero inside it) is a lower bound
//! on the distance from `q` to the face. The search visits faces by increasing bound and stops
//! once the bound reaches the best distance found, so most points touch one or two faces.

use crate::Point3;

/// An axis-aligned box `lo <= x <= hi` (empty while `lo > hi`).
#[derive(Clone, Copy, Debug)]
pub(super) struct Bounds {
    lo: [f64; 3],
    hi: [f64; 3],
}

impl Bounds {
    /// The empty box: its distance to any point is infinite.
    pub(super) const EMPTY: Bounds = Bounds {
        lo: [f64::INFINITY; 3],
        hi: [f64::NEG_INFINITY; 3],
    };

    /// Grows the box to hold the ball of radius `radius` about `centre`.
    pub(super) fn hold(&mut self, centre: Point3, radius: f64) {
        for a in 0..3 {
            self.lo[a] = self.lo[a].min(centre[a] - radius);
            self.hi[a] = self.hi[a].max(centre[a] + radius);
        }
    }

    /// The centre of the box.
    fn centre(&self) -> Point3 {
        Point3::new([
            0.5 * (self.lo[0] + self.hi[0]),
            0.5 * (self.lo[1] + self.hi[1]),
            0.5 * (self.lo[2] + self.hi[2]),
        ])
    }

    /// The distance from `q` to the box: zero inside it, infinite for the empty box. It never
    /// exceeds the distance from `q` to any point the box holds.
    pub(super) fn distance(&self, q: Point3) -> f64 {
        self.distance_sq(q).sqrt()
    }

    /// The square of [`Bounds::distance`], before its square root (the same sum).
    fn distance_sq(&self, q: Point3) -> f64 {
        if self.lo[0] > self.hi[0] {
            return f64::INFINITY;
        }
        let mut sum = 0.0;
        for a in 0..3 {
            let d = (self.lo[a] - q[a]).max(q[a] - self.hi[a]).max(0.0);
            sum += d * d;
        }
        sum
    }
}

/// The most items in a leaf of a [`BoxTree`].
const LEAF: usize = 4;

/// A tree of boxes over items (a shape's faces): each node's box holds its items' boxes, and a
/// query visits only nodes nearer than a given reach.
#[derive(Clone, Debug)]
pub(super) struct BoxTree {
    nodes: Vec<Node>,
    /// The items, in the order the leaves take them.
    items: Vec<usize>,
    boxes: Vec<Bounds>,
}

/// A node: its box, and either two children or a range of `items`.
#[derive(Clone, Copy, Debug)]
struct Node {
    bounds: Bounds,
    /// Children `(left, right)` when `leaf` is false; else the range `first..last` of items.
    first: usize,
    last: usize,
    leaf: bool,
}

impl BoxTree {
    /// The tree over `boxes` (item `k` is `boxes[k]`), split at the median of the boxes'
    /// centres along the widest direction.
    pub(super) fn new(boxes: Vec<Bounds>) -> BoxTree {
        let mut tree = BoxTree {
            nodes: Vec::new(),
            items: (0..boxes.len()).collect(),
            boxes,
        };
        if !tree.items.is_empty() {
            tree.build(0, tree.items.len());
        }
        tree
    }

    /// Builds the node over `items[first..last]`, returning its index.
    fn build(&mut self, first: usize, last: usize) -> usize {
        let mut bounds = Bounds::EMPTY;
        let mut centres = Bounds::EMPTY;
        for &k in &self.items[first..last] {
            let b = self.boxes[k];
            for a in 0..3 {
                bounds.lo[a] = bounds.lo[a].min(b.lo[a]);
                bounds.hi[a] = bounds.hi[a].max(b.hi[a]);
            }
            centres.hold(b.centre(), 0.0);
        }
        let index = self.nodes.len();
        self.nodes.push(Node {
            bounds,
            first,
            last,
            leaf: true,
        });
        if last - first <= LEAF {
            return index;
        }
        let axis = (0..3)
            .max_by(|&a, &b| {
                (centres.hi[a] - centres.lo[a]).total_cmp(&(centres.hi[b] - centres.lo[b]))
            })
            .unwrap_or(0);
        let boxes = &self.boxes;
        let middle = first + (last - first) / 2;
        self.items[first..last].select_nth_unstable_by(middle - first, |&i, &j| {
            boxes[i].centre()[axis].total_cmp(&boxes[j].centre()[axis])
        });
        let left = self.build(first, middle);
        let right = self.build(middle, last);
        self.nodes[index] = Node {
            bounds,
            first: left,
            last: right,
            leaf: false,
        };
        index
    }

    /// An item whose box is near `q`, found without a bound: from the root, the child whose
    /// box is nearer is taken down to a leaf, and there the item of the nearest box (`None`
    /// for an empty tree). Its face gives the search a first bound.
    pub(super) fn descend(&self, q: Point3) -> Option<usize> {
        let mut node = *self.nodes.first()?;
        while !node.leaf {
            let (left, right) = (self.nodes[node.first], self.nodes[node.last]);
            node = if right.bounds.distance(q) < left.bounds.distance(q) {
                right
            } else {
                left
            };
        }
        let mut pick: Option<(f64, usize)> = None;
        for &k in &self.items[node.first..node.last] {
            let lower = self.boxes[k].distance(q);
            if pick.is_none_or(|(best, _)| lower < best) {
                pick = Some((lower, k));
            }
        }
        pick.map(|(_, k)| k)
    }

    /// Appends to `out` every item whose box is nearer `q` than `reach`, with that distance.
    ///
    /// Nodes are passed over by the squared distance, without its square root, only when it
    /// exceeds `reach^2` by more than rounding: such a node's distance is at least `reach`
    /// (the square root is correctly rounded), so the items found are those a test of every
    /// distance finds.
    pub(super) fn within(&self, q: Point3, reach: f64, out: &mut Vec<(f64, usize)>) {
        if self.nodes.is_empty() {
            return;
        }
        let far = reach * reach * (1.0 + 4.0 * f64::EPSILON);
        // The depth is below 64 for any count of items (the tree is balanced).
        let mut stack = [0usize; 64];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = self.nodes[stack[top]];
            if node.bounds.distance_sq(q) > far {
                continue;
            }
            if node.leaf {
                for &k in &self.items[node.first..node.last] {
                    let square = self.boxes[k].distance_sq(q);
                    if square > far {
                        continue;
                    }
                    let lower = square.sqrt();
                    if lower < reach {
                        out.push((lower, k));
                    }
                }
            } else if top + 2 <= stack.len() {
                stack[top] = node.first;
                stack[top + 1] = node.last;
                top += 2;
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_distance_to_a_box_bounds_the_distance_to_its_balls() {
        let mut b = Bounds::EMPTY;
        assert_eq!(b.distance(Point3::ZERO), f64::INFINITY);
        let balls = [
            (Point3::new([1.0e4, -3.0, 2.5]), 0.75),
            (Point3::new([1.0e4 + 2.0, -1.0, 2.0]), 0.25),
            (Point3::new([1.0e4 - 1.0, -3.5, 4.0]), 1.5),
        ];
        for (c, r) in balls {
            b.hold(c, r);
        }
        let mut state = 0x2545_f491_4f6c_dd1du64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for _ in 0..20_000 {
            let q = Point3::new([
                1.0e4 - 8.0 + 16.0 * next(),
                -10.0 + 16.0 * next(),
                -5.0 + 16.0 * next(),
            ]);
            let lower = b.distance(q);
            // A point of some ball, on the line from its centre towards `q` or away from it.
            for (c, r) in balls {
                let dir = q - c;
                let len = dir.norm();
                for s in [-1.0, -0.3, 0.0, 0.5, 1.0] {
                    let p = if len > 0.0 {
                        c + dir * (s * r / len)
                    } else {
                        c
                    };
                    assert!(lower <= q.distance(p), "{q:?} {lower} {p:?}");
                }
                // The nearest point of the ball is at `len - r`; the bound is at most that.
                assert!(lower <= (len - r).max(0.0) * (1.0 + 1e-15), "{q:?}");
            }
        }
        // Exact on an axis: 2 beyond the face x = 1e4 + 2.25.
        let q = Point3::new([1.0e4 + 4.25, -1.0, 2.0]);
        assert!((b.distance(q) - 2.0).abs() < 1e-11);
    }

    #[test]
    fn the_tree_finds_every_box_within_reach() {
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            (state >> 11) as f64 / (1u64 << 53) as f64
        };
        for count in [0, 1, 3, 4, 5, 17, 104, 1000] {
            let boxes: Vec<Bounds> = (0..count)
                .map(|_| {
                    let mut b = Bounds::EMPTY;
                    let c = Point3::new([next(), next(), next()]) * 100.0;
                    b.hold(c, 5.0 * next());
                    b.hold(c + Point3::new([next(), next(), next()]) * 10.0, 0.0);
                    b
                })
                .collect();
            let tree = BoxTree::new(boxes.clone());
            let mut found = Vec::new();
            for _ in 0..200 {
                let q = Point3::new([next(), next(), next()]) * 140.0 - Point3::new([20.0; 3]);
                let reach = 40.0 * next();
                found.clear();
                tree.within(q, reach, &mut found);
                found.sort_by_key(|f| f.1);
                // The descent ends at an item: one within any reach beyond its box.
                let first = tree.descend(q);
                assert_eq!(first.is_some(), count > 0);
                if let Some(k) = first {
                    let lower = boxes[k].distance(q);
                    assert!(lower.is_finite());
                    let mut near = Vec::new();
                    tree.within(q, lower * (1.0 + 1e-12) + 1e-9, &mut near);
                    assert!(near.iter().any(|f| f.1 == k), "{count}");
                }
                let want: Vec<(f64, usize)> = boxes
                    .iter()
                    .enumerate()
                    .map(|(k, b)| (b.distance(q), k))
                    .filter(|f| f.0 < reach)
                    .collect();
                assert_eq!(found, want, "{count}");
                // A reach at a box's distance exactly, and one rounding step either side.
                if let Some((lower, _)) = want.first().copied().filter(|w| w.0 > 0.0) {
                    for reach in [lower.next_down(), lower, lower.next_up()] {
                        found.clear();
                        tree.within(q, reach, &mut found);
                        found.sort_by_key(|f| f.1);
                        let want: Vec<(f64, usize)> = boxes
                            .iter()
                            .enumerate()
                            .map(|(k, b)| (b.distance(q), k))
                            .filter(|f| f.0 < reach)
                            .collect();
                        assert_eq!(found, want, "{count} at {reach}");
                    }
                }
            }
        }
    }
}

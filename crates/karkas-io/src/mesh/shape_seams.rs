//! Joining the meshes of a shape's faces into one surface (`karkas convert`,
//! [`super::shape_mesh`]): vertices welded, and the T-junctions where two faces sampled a
//! shared edge at different points closed by inserting each face's boundary vertices into
//! the other's sides.

use std::collections::{BTreeMap, HashMap};

use karkas::Point3;

/// The cosine of the largest angle between a boundary vertex's own side and another face's
/// side it is inserted into (45 degrees): chords of one edge sampled at two tolerances turn
/// less than that.
const ALONG: f64 = std::f64::consts::FRAC_1_SQRT_2;

/// Triangles of many faces before they are joined.
#[derive(Default)]
pub(crate) struct Soup {
    pub(crate) positions: Vec<Point3>,
    pub(crate) triangles: Vec<Tri>,
}

/// A triangle and the face it came from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) struct Tri {
    pub(crate) corners: [u32; 3],
    pub(crate) face: usize,
}

impl Soup {
    /// Merges vertices within `eps` of each other and drops the triangles that collapse.
    pub(crate) fn weld(&mut self, eps: f64) {
        let cell = |p: Point3| [0, 1, 2].map(|c| (p[c] / eps).floor() as i64);
        let mut buckets: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let mut map = vec![0u32; self.positions.len()];
        let mut kept: Vec<Point3> = Vec::new();
        for (i, &p) in self.positions.iter().enumerate() {
            let c = cell(p);
            let mut found = None;
            'search: for dx in -1..=1 {
                for dy in -1..=1 {
                    for dz in -1..=1 {
                        let key = [c[0] + dx, c[1] + dy, c[2] + dz];
                        if let Some(list) = buckets.get(&key) {
                            if let Some(&k) =
                                list.iter().find(|&&k| kept[k as usize].distance(p) <= eps)
                            {
                                found = Some(k);
                                break 'search;
                            }
                        }
                    }
                }
            }
            map[i] = found.unwrap_or_else(|| {
                kept.push(p);
                let k = (kept.len() - 1) as u32;
                buckets.entry(c).or_default().push(k);
                k
            });
        }
        self.positions = kept;
        self.renumber(&map);
    }

    /// Merges each boundary vertex into a boundary vertex of another face within `eps` of it
    /// (the first in index order), and drops the triangles that collapse: two faces that
    /// sampled a shared edge at the same places, each on its own surface, apart by the
    /// model's gap between edge and surface.
    pub(crate) fn snap_boundaries(&mut self, eps: f64) {
        let faces_of = self.boundary_vertices(&self.boundary_sides());
        let cell = |p: Point3| [0, 1, 2].map(|c| (p[c] / eps).floor() as i64);
        let mut buckets: HashMap<[i64; 3], Vec<u32>> = HashMap::new();
        let mut map: Vec<u32> = (0..self.positions.len() as u32).collect();
        for (&v, faces) in &faces_of {
            let p = self.positions[v as usize];
            let c = cell(p);
            let found = (0..27).find_map(|k| {
                let key = [c[0] + k % 3 - 1, c[1] + (k / 3) % 3 - 1, c[2] + k / 9 - 1];
                buckets.get(&key)?.iter().copied().find(|&w| {
                    self.positions[w as usize].distance(p) <= eps
                        && faces_of[&w].0.iter().all(|f| !faces.0.contains(f))
                })
            });
            match found {
                Some(w) => map[v as usize] = w,
                None => buckets.entry(c).or_default().push(v),
            }
        }
        self.renumber(&map);
    }

    /// Splits each boundary segment (a side of one triangle only) at the boundary vertices of
    /// other faces within `reach` of it, nearest segment first (see the module docs).
    pub(crate) fn close_t_junctions(&mut self, reach: f64) {
        let boundary = self.boundary_sides();
        let vertex_faces = self.boundary_vertices(&boundary);
        let grid = SegmentGrid::new(&self.positions, &self.triangles, &boundary, reach);
        // The vertices to insert into each boundary side: for each other face whose boundary
        // passes within reach, its nearest side.
        let mut inserts: Inserts = BTreeMap::new();
        for (&v, (faces, directions)) in &vertex_faces {
            let p = self.positions[v as usize];
            let mut best: BTreeMap<usize, (f64, f64, (usize, usize))> = BTreeMap::new();
            for &(t, side) in grid.near(p) {
                let tri = self.triangles[t];
                let (a, b) = (tri.corners[side], tri.corners[(side + 1) % 3]);
                if a == v || b == v || faces.contains(&tri.face) {
                    continue;
                }
                let (pa, pb) = (self.positions[a as usize], self.positions[b as usize]);
                let (s, d) = along(p, pa, pb);
                let nearer = best.get(&tri.face).is_none_or(|x| d < x.0);
                if s > 0.0 && s < 1.0 && d <= reach && nearer && runs_along(directions, pb - pa) {
                    best.insert(tri.face, (d, s, (t, side)));
                }
            }
            for (_, (_, s, key)) in best {
                inserts.entry(key).or_default().push((s, v));
            }
        }
        self.split_sides(inserts);
    }

    /// Each boundary vertex (a corner of a side in `boundary`): the faces whose boundary it is
    /// on, to look only across faces, and the directions of its boundary sides.
    fn boundary_vertices(&self, boundary: &[(usize, usize)]) -> BoundaryVertices {
        let mut out = BoundaryVertices::new();
        for &(t, side) in boundary {
            let tri = self.triangles[t];
            let (a, b) = (tri.corners[side], tri.corners[(side + 1) % 3]);
            let direction = self.positions[b as usize] - self.positions[a as usize];
            for c in [a, b] {
                let (faces, directions) = out.entry(c).or_default();
                if !faces.contains(&tri.face) {
                    faces.push(tri.face);
                }
                directions.push(direction);
            }
        }
        out
    }

    /// Renames each triangle's corners by `map` and drops the triangles that collapse.
    fn renumber(&mut self, map: &[u32]) {
        for t in &mut self.triangles {
            t.corners = t.corners.map(|c| map[c as usize]);
        }
        self.triangles.retain(|t| {
            let [a, b, c] = t.corners;
            a != b && b != c && a != c
        });
    }

    /// The sides used by one triangle only, as (triangle, side from corner `side` to the next).
    fn boundary_sides(&self) -> Vec<(usize, usize)> {
        let mut uses: HashMap<(u32, u32), u32> = HashMap::new();
        for t in &self.triangles {
            for k in 0..3 {
                let (a, b) = (t.corners[k], t.corners[(k + 1) % 3]);
                *uses.entry((a.min(b), a.max(b))).or_default() += 1;
            }
        }
        let mut out = Vec::new();
        for (i, t) in self.triangles.iter().enumerate() {
            for k in 0..3 {
                let (a, b) = (t.corners[k], t.corners[(k + 1) % 3]);
                if uses[&(a.min(b), a.max(b))] == 1 {
                    out.push((i, k));
                }
            }
        }
        out
    }

    /// Replaces each triangle with vertices to insert on its sides by fans, one side at a
    /// time: the side's piece (the triangle itself, or the piece of an earlier fan that holds
    /// the side) is cut by a fan from its corner opposite the side. Every piece keeps the
    /// triangle's winding, and no vertex is added off the surface.
    fn split_sides(&mut self, inserts: Inserts) {
        let mut by_triangle: BTreeMap<usize, Vec<SideInserts>> = BTreeMap::new();
        for ((t, side), mut list) in inserts {
            list.sort_by(|x, y| x.0.total_cmp(&y.0));
            by_triangle.entry(t).or_default().push((side, list));
        }
        let mut removed = vec![false; self.triangles.len()];
        let mut added = Vec::new();
        for (t, sides) in by_triangle {
            removed[t] = true;
            let tri = self.triangles[t];
            let mut pieces = vec![tri.corners];
            for (side, list) in sides {
                let (a, b) = (tri.corners[side], tri.corners[(side + 1) % 3]);
                // The piece whose side runs from a to b, turned to start there.
                let Some((i, turn)) = pieces.iter().enumerate().find_map(|(i, p)| {
                    (0..3)
                        .find(|&k| p[k] == a && p[(k + 1) % 3] == b)
                        .map(|k| (i, k))
                }) else {
                    continue;
                };
                let piece = pieces.swap_remove(i);
                let apex = piece[(turn + 2) % 3];
                let mut chain = vec![a];
                chain.extend(list.iter().map(|&(_, v)| v));
                chain.push(b);
                pieces.extend(chain.windows(2).map(|w| [w[0], w[1], apex]));
            }
            added.extend(pieces.into_iter().map(|corners| Tri {
                corners,
                face: tri.face,
            }));
        }
        let mut kept: Vec<Tri> = self
            .triangles
            .iter()
            .zip(&removed)
            .filter(|(_, &r)| !r)
            .map(|(t, _)| *t)
            .collect();
        kept.extend(added);
        self.triangles = kept;
    }
}

/// True when one of a boundary vertex's sides, `directions`, runs along the side `side` of
/// another face, within [`ALONG`]: the two faces sampled one edge there. A vertex near a
/// side but on another edge (where three faces meet at a coarse tolerance) crosses it.
fn runs_along(directions: &[Point3], side: Point3) -> bool {
    directions
        .iter()
        .any(|d| d.dot(side).abs() >= ALONG * d.norm() * side.norm())
}

/// Where `p` projects onto the line `a b` (0 at `a`, 1 at `b`) and its distance from the
/// segment there.
pub(crate) fn along(p: Point3, a: Point3, b: Point3) -> (f64, f64) {
    let d = b - a;
    let len2 = d.dot(d);
    if len2 <= 0.0 {
        return (0.0, p.distance(a));
    }
    let s = (p - a).dot(d) / len2;
    (s, p.distance(a + d * s))
}

/// Boundary vertices: their faces and the directions of their boundary sides.
type BoundaryVertices = BTreeMap<u32, (Vec<usize>, Vec<Point3>)>;
/// Vertices to insert into boundary sides, by (triangle, side): (place along the side, vertex).
type Inserts = BTreeMap<(usize, usize), Vec<(f64, u32)>>;
/// One side's insertions: the side (from its corner) and (place along it, vertex).
type SideInserts = (usize, Vec<(f64, u32)>);

/// Boundary sides bucketed by the cubes of side `reach` their boxes touch.
struct SegmentGrid {
    cell: f64,
    buckets: HashMap<[i64; 3], Vec<(usize, usize)>>,
}

impl SegmentGrid {
    fn new(
        positions: &[Point3],
        triangles: &[Tri],
        sides: &[(usize, usize)],
        reach: f64,
    ) -> SegmentGrid {
        // Cells no smaller than the longest side over 8, so a side spans a few cells.
        let longest = sides
            .iter()
            .map(|&(t, k)| {
                let c = triangles[t].corners;
                positions[c[k] as usize].distance(positions[c[(k + 1) % 3] as usize])
            })
            .fold(0.0, f64::max);
        let cell = (longest / 8.0).max(reach).max(f64::MIN_POSITIVE);
        let mut buckets: HashMap<[i64; 3], Vec<(usize, usize)>> = HashMap::new();
        for &(t, k) in sides {
            let c = triangles[t].corners;
            let (a, b) = (positions[c[k] as usize], positions[c[(k + 1) % 3] as usize]);
            let lo = [0, 1, 2].map(|i| ((a[i].min(b[i]) - reach) / cell).floor() as i64);
            let hi = [0, 1, 2].map(|i| ((a[i].max(b[i]) + reach) / cell).floor() as i64);
            for x in lo[0]..=hi[0] {
                for y in lo[1]..=hi[1] {
                    for z in lo[2]..=hi[2] {
                        buckets.entry([x, y, z]).or_default().push((t, k));
                    }
                }
            }
        }
        SegmentGrid { cell, buckets }
    }

    /// The sides whose boxes (grown by the reach) touch `p`'s cell.
    fn near(&self, p: Point3) -> &[(usize, usize)] {
        let key = [0, 1, 2].map(|i| (p[i] / self.cell).floor() as i64);
        self.buckets.get(&key).map_or(&[], Vec::as_slice)
    }
}

#[cfg(test)]
mod tests {
    use super::{runs_along, Inserts, Soup, Tri};
    use karkas::Point3;

    fn p(x: f64, y: f64) -> Point3 {
        Point3::new([x, y, 0.0])
    }

    /// Twice the signed area of triangle `t` in the plane z = 0.
    fn double_area(soup: &Soup, t: [u32; 3]) -> f64 {
        let [a, b, c] = t.map(|k| soup.positions[k as usize]);
        (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0])
    }

    #[test]
    fn a_triangle_split_on_every_side_keeps_its_area_and_winding_without_new_vertices() {
        // Corners 0, 1, 2; vertices 3, 4 on side 0-1, 5 on side 1-2, 6 on side 2-0.
        let positions = vec![
            p(0.0, 0.0),
            p(4.0, 0.0),
            p(0.0, 4.0),
            p(1.0, 0.0),
            p(3.0, 0.0),
            p(2.0, 2.0),
            p(0.0, 1.0),
        ];
        let mut soup = Soup {
            positions,
            triangles: vec![Tri {
                corners: [0, 1, 2],
                face: 7,
            }],
        };
        let mut inserts = Inserts::new();
        inserts.insert((0, 0), vec![(0.75, 4), (0.25, 3)]);
        inserts.insert((0, 1), vec![(0.5, 5)]);
        inserts.insert((0, 2), vec![(0.75, 6)]);
        soup.split_sides(inserts);
        assert_eq!(soup.positions.len(), 7, "a vertex was added");
        // Side 0-1 fanned from 2 (three pieces), then 1-2 from 4 and 2-0 from 3 (two each, in
        // place of the pieces that held them).
        assert_eq!(soup.triangles.len(), 5);
        let mut total = 0.0;
        for t in &soup.triangles {
            assert_eq!(t.face, 7);
            let a = double_area(&soup, t.corners);
            assert!(a > 1e-9, "{:?} is flat or turned: {a}", t.corners);
            total += a;
        }
        assert!((total - 16.0).abs() < 1e-12, "{total}");
        // Every inserted vertex is now a corner of the pieces along its side.
        for v in 3..7u32 {
            assert!(soup.triangles.iter().any(|t| t.corners.contains(&v)));
        }
    }

    #[test]
    fn boundary_vertices_of_two_faces_a_gap_apart_become_one() {
        // Face 0 above the x axis, face 1 below it, their shared side's ends apart by 1e-6;
        // two vertices of face 0 as close to each other stay two.
        let positions = vec![
            p(0.0, 0.0),
            p(1.0, 0.0),
            p(0.5, 1.0),
            p(1e-6, 0.0),
            p(0.5, -1.0),
            p(1.0 - 1e-6, 0.0),
            p(0.5, 1.0 + 1e-6),
        ];
        let mut soup = Soup {
            positions,
            triangles: vec![
                Tri {
                    corners: [0, 1, 2],
                    face: 0,
                },
                Tri {
                    corners: [1, 6, 2],
                    face: 0,
                },
                Tri {
                    corners: [3, 4, 5],
                    face: 1,
                },
            ],
        };
        soup.snap_boundaries(1e-5);
        let corners: Vec<[u32; 3]> = soup.triangles.iter().map(|t| t.corners).collect();
        assert_eq!(corners, [[0, 1, 2], [1, 6, 2], [0, 4, 1]]);
    }

    #[test]
    fn a_vertex_joins_a_side_it_runs_along_and_not_one_it_crosses() {
        let side = Point3::new([1.0, 0.0, 0.0]);
        let along = [Point3::new([0.9, 0.1, 0.0]), Point3::new([0.0, 0.0, 1.0])];
        assert!(runs_along(&along, side));
        let across = [Point3::new([0.1, 1.0, 0.0]), Point3::new([0.0, -0.5, 0.5])];
        assert!(!runs_along(&across, side));
    }
}

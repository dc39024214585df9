//! One winding for the faces of a CAD model's mesh, and outward when it closes.
//!
//! A STEP face says which side is its outside ([`karkas::shape::Face::same_sense`]); an IGES
//! trimmed surface does not, so the faces of an IGES solid come out of the mesher with the
//! windings of their surfaces, some in and some out (Open CASCADE's IGES of a filleted box:
//! planes one way, blends the other). Where two faces share a side and run it the same way,
//! one of them is turned over: the faces of every connected part are oriented by a walk over
//! their shared sides (each pair of faces decided by the majority of its sides, from the
//! part's largest face, whose winding is kept), and a part that is then closed (every side
//! used once each way) is turned so that it encloses a positive volume (an IGES torus whose
//! one face runs inwards). An open part keeps the winding of its largest face; a closed part
//! already wound outwards is left exactly as it is.
//!
//! Cost: O(triangles) with a hash map of the sides.

use std::collections::{BTreeMap, HashMap, VecDeque};

use karkas::Point3;

use super::shape_seams::Tri;

/// Turns faces of `triangles` over (reversing their corners) so that neighbouring faces run
/// their shared sides in opposite directions, then every closed part outward (see the module
/// docs).
pub(crate) fn orient_faces(positions: &[Point3], triangles: &mut [Tri]) {
    let sides = sides(triangles);
    let faces = triangles.iter().map(|t| t.face + 1).max().unwrap_or(0);
    // Votes between pairs of faces: (same direction, opposite direction) over their sides,
    // in the faces' order, so that the walk and the mesh are the same on every run.
    let mut votes: BTreeMap<(usize, usize), (usize, usize)> = BTreeMap::new();
    for uses in sides.values().filter(|u| u.len() == 2) {
        let ((f, a), (g, b)) = (uses[0], uses[1]);
        if f == g {
            continue;
        }
        let vote = votes.entry((f.min(g), f.max(g))).or_default();
        if a == b {
            vote.0 += 1;
        } else {
            vote.1 += 1;
        }
    }
    let mut neighbours: Vec<Vec<(usize, bool)>> = vec![Vec::new(); faces];
    for (&(f, g), &(same, opposite)) in &votes {
        let flip = same > opposite;
        neighbours[f].push((g, flip));
        neighbours[g].push((f, flip));
    }
    let mut size = vec![0usize; faces];
    for t in triangles.iter() {
        size[t.face] += 1;
    }
    let consistent = sides
        .values()
        .all(|uses| uses.len() != 2 || uses[0].1 != uses[1].1);
    if !consistent {
        let flips = walk(&neighbours, &size);
        for t in triangles.iter_mut() {
            if flips[t.face] == Some(true) {
                t.corners.swap(1, 2);
            }
        }
    }
    outward(positions, triangles, &neighbours);
}

/// The undirected sides of `triangles`, each with the faces that use it and whether they run
/// it from its smaller vertex to its larger.
fn sides(triangles: &[Tri]) -> HashMap<(u32, u32), Vec<(usize, bool)>> {
    let mut out: HashMap<(u32, u32), Vec<(usize, bool)>> = HashMap::new();
    for t in triangles {
        for e in 0..3 {
            let (a, b) = (t.corners[e], t.corners[(e + 1) % 3]);
            out.entry((a.min(b), a.max(b)))
                .or_default()
                .push((t.face, a < b));
        }
    }
    out
}

/// Whether each face is turned over: a breadth-first walk from the largest face of every
/// part not yet reached (kept as it is), each neighbour turned when the pair's sides say so.
fn walk(neighbours: &[Vec<(usize, bool)>], size: &[usize]) -> Vec<Option<bool>> {
    let mut flips: Vec<Option<bool>> = vec![None; neighbours.len()];
    let mut order: Vec<usize> = (0..neighbours.len()).collect();
    order.sort_by(|&a, &b| size[b].cmp(&size[a]).then(a.cmp(&b)));
    for seed in order {
        if flips[seed].is_some() || size[seed] == 0 {
            continue;
        }
        flips[seed] = Some(false);
        let mut queue = VecDeque::from([seed]);
        while let Some(f) = queue.pop_front() {
            let here = flips[f].unwrap_or(false);
            for &(g, flip) in &neighbours[f] {
                if flips[g].is_none() {
                    flips[g] = Some(here ^ flip);
                    queue.push_back(g);
                }
            }
        }
    }
    flips
}

/// Turns every closed part of the mesh (faces joined by `neighbours`) outward.
fn outward(positions: &[Point3], triangles: &mut [Tri], neighbours: &[Vec<(usize, bool)>]) {
    let mut part = vec![usize::MAX; neighbours.len()];
    let mut parts = 0;
    for seed in 0..neighbours.len() {
        if part[seed] != usize::MAX {
            continue;
        }
        part[seed] = parts;
        let mut stack = vec![seed];
        while let Some(f) = stack.pop() {
            for &(g, _) in &neighbours[f] {
                if part[g] == usize::MAX {
                    part[g] = parts;
                    stack.push(g);
                }
            }
        }
        parts += 1;
    }
    let mut volume = vec![0.0; parts];
    let mut directed: Vec<HashMap<(u32, u32), i32>> = vec![HashMap::new(); parts];
    for t in triangles.iter() {
        let p = part[t.face];
        let [a, b, c] = t.corners.map(|k| positions[k as usize]);
        volume[p] += a.dot(b.cross(c));
        for e in 0..3 {
            *directed[p]
                .entry((t.corners[e], t.corners[(e + 1) % 3]))
                .or_default() += 1;
        }
    }
    let closed: Vec<bool> = directed
        .iter()
        .map(|d| {
            d.iter()
                .all(|(&(a, b), &n)| n == 1 && d.get(&(b, a)) == Some(&1))
        })
        .collect();
    for t in triangles.iter_mut() {
        let p = part[t.face];
        if closed[p] && volume[p] < 0.0 {
            t.corners.swap(1, 2);
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The unit cube's six faces, two triangles each, faces in `turned` wound inwards.
    fn cube(turned: &[usize]) -> (Vec<Point3>, Vec<Tri>) {
        let positions: Vec<Point3> = (0..8)
            .map(|k| Point3::new([(k & 1) as f64, ((k >> 1) & 1) as f64, ((k >> 2) & 1) as f64]))
            .collect();
        // Outward quads (counter-clockwise seen from outside).
        let quads = [
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ];
        let mut triangles = Vec::new();
        for (face, q) in quads.iter().enumerate() {
            for mut corners in [[q[0], q[1], q[2]], [q[0], q[2], q[3]]] {
                if turned.contains(&face) {
                    corners.swap(1, 2);
                }
                triangles.push(Tri { corners, face });
            }
        }
        (positions, triangles)
    }

    fn volume(positions: &[Point3], triangles: &[Tri]) -> f64 {
        triangles
            .iter()
            .map(|t| {
                let [a, b, c] = t.corners.map(|k| positions[k as usize]);
                a.dot(b.cross(c)) / 6.0
            })
            .sum()
    }

    #[test]
    fn faces_wound_either_way_come_out_as_one_outward_cube() {
        for turned in [vec![0], vec![1, 2, 3], vec![0, 1, 2, 3, 4], vec![5]] {
            let (positions, mut triangles) = cube(&turned);
            orient_faces(&positions, &mut triangles);
            assert!(
                (volume(&positions, &triangles) - 1.0).abs() < 1e-12,
                "{turned:?}"
            );
            let sides = sides(&triangles);
            assert!(
                sides.values().all(|u| u.len() == 2 && u[0].1 != u[1].1),
                "{turned:?}"
            );
        }
    }

    #[test]
    fn a_closed_mesh_wound_inwards_is_turned_and_one_wound_outwards_left_as_it_is() {
        let (positions, inward) = cube(&[0, 1, 2, 3, 4, 5]);
        let mut turned = inward.clone();
        orient_faces(&positions, &mut turned);
        assert!((volume(&positions, &turned) - 1.0).abs() < 1e-12);
        let (positions, outward) = cube(&[]);
        let mut same = outward.clone();
        orient_faces(&positions, &mut same);
        assert_eq!(same, outward);
    }

    #[test]
    fn an_open_part_is_made_consistent_and_not_turned_by_its_volume() {
        // Five faces of the cube (the top left open), two of them turned: one winding, that
        // of the largest face first met (face 0, all faces being equal).
        let (positions, triangles) = cube(&[1, 3]);
        let mut open: Vec<Tri> = triangles.into_iter().filter(|t| t.face != 5).collect();
        orient_faces(&positions, &mut open);
        let sides = sides(&open);
        assert!(sides.values().all(|u| u.len() != 2 || u[0].1 != u[1].1));
        assert_eq!(open[0].corners, [0, 2, 3]);
    }
}

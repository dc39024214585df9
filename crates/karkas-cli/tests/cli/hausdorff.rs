//! The CLI contract of `karkas hausdorff`: two point sets, or a point set and `--expr`;
//! prints the distance and where it is attained.

use crate::common::{karkas, s, stderr, stdout, temp_dir, write};

/// The number after `label` on its line of the output, and the rest of the line.
fn field(out: &str, label: &str) -> (f64, String) {
    let line = out.lines().find(|l| l.starts_with(label)).unwrap();
    let rest = line[label.len()..].trim();
    let value = rest.split_whitespace().next().unwrap().parse().unwrap();
    (value, rest.to_owned())
}

#[test]
fn two_point_sets() {
    let dir = temp_dir();
    let a = write(dir.path(), "a.csv", "x,y,z\n0,0,0\n1,0,0\n");
    let b = write(dir.path(), "b.obj", "v 0 0 0\nv 1 0 0\nv 1 3 4\nf 1 2 3\n");
    let o = karkas(&["hausdorff", s(&a), s(&b)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    assert_eq!(field(&out, "hausdorff").0, 5.0);
    assert_eq!(field(&out, "A -> B").0, 0.0);
    let (d, rest) = field(&out, "B -> A");
    assert_eq!(d, 5.0);
    assert!(rest.ends_with("at 1,3,4 nearest 1,0,0"), "{rest}");
}

#[test]
fn point_set_against_an_implicit_surface() {
    let dir = temp_dir();
    // Points at radius 1.25 around the cylinder of radius 1, and one on it.
    let a = write(
        dir.path(),
        "a.csv",
        "i,j,x,y,z\n0,0,1.25,0,0\n0,1,0,1.25,3\n1,0,1,0,0\n1,1,0,1,1\n",
    );
    let o = karkas(&["hausdorff", s(&a), "--expr", "x^2+y^2-1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let (d, rest) = field(&out, "A -> B");
    assert!((d - 0.25).abs() < 1e-12);
    assert!(rest.contains("at 1.25,0,0 nearest 1,0,0"), "{rest}");
    // The patch is the quarter cylinder in the box [0, 1.25]^2 x [0, 3], which the four
    // points cover loosely: its far side lies farther from them than they do from it.
    let back = field(&out, "B -> A").0;
    assert!(back > 0.5, "{out}");
    assert_eq!(field(&out, "hausdorff").0, back);
}

/// `F = x^2 + y^2 + z^2 - 1`: each directed distance of `hausdorff A --expr` computed
/// independently, from the patch's definition (the part of `F = 0` in A's bounding box,
/// sampled by projecting the lattice nodes with 64 steps along the box's largest side that
/// lie within 2 steps of the surface, and the closest points of A's points), with the
/// sphere's projections in closed form (`p / |p|`) and nearest points by brute force.
fn sphere_distances(a: &[[f64; 3]]) -> (f64, f64) {
    let norm = |p: [f64; 3]| (p[0] * p[0] + p[1] * p[1] + p[2] * p[2]).sqrt();
    let unit = |p: [f64; 3]| {
        let r = norm(p);
        [p[0] / r, p[1] / r, p[2] / r]
    };
    let forward = a.iter().map(|&p| (norm(p) - 1.0).abs()).fold(0.0, f64::max);
    let mut lo = a[0];
    let mut hi = a[0];
    for p in a {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    let side: Vec<f64> = (0..3).map(|c| hi[c] - lo[c]).collect();
    let largest = side.iter().copied().fold(0.0, f64::max);
    let h = largest / 64.0;
    let steps: Vec<usize> = side
        .iter()
        .map(|&s| ((s / h).ceil() as usize).min(64))
        .collect();
    let mut patch: Vec<[f64; 3]> = a.iter().map(|&p| unit(p)).collect();
    for i in 0..=steps[0] {
        for j in 0..=steps[1] {
            for k in 0..=steps[2] {
                let p: Vec<f64> = [i, j, k]
                    .iter()
                    .enumerate()
                    .map(|(c, &m)| lo[c] + side[c] * m as f64 / steps[c] as f64)
                    .collect();
                let p = [p[0], p[1], p[2]];
                let r = norm(p);
                if (r * r - 1.0).abs() / (2.0 * r) > 2.0 * h {
                    continue;
                }
                let q = unit(p);
                if (0..3).all(|c| q[c] >= lo[c] - 1e-9 && q[c] <= hi[c] + 1e-9) {
                    patch.push(q);
                }
            }
        }
    }
    let distance = |p: [f64; 3], q: [f64; 3]| norm([p[0] - q[0], p[1] - q[1], p[2] - q[2]]);
    let backward = patch
        .iter()
        .map(|&q| {
            a.iter()
                .map(|&p| distance(p, q))
                .fold(f64::INFINITY, f64::min)
        })
        .fold(0.0, f64::max);
    (forward, backward)
}

#[test]
fn the_implicit_side_is_the_patch_in_the_bounding_box() {
    // A 6 x 5 grid over longitudes 0.2-1.1 and latitudes 0.1-0.8 of the unit sphere, each
    // point moved off it radially by up to 0.02: the patch in the box reaches past the
    // grid's corners, so the two directions differ.
    let mut a = Vec::new();
    for i in 0..6 {
        for j in 0..5 {
            let (lon, lat) = (0.2 + 0.18 * i as f64, 0.1 + 0.175 * j as f64);
            let r = 1.0 + 0.02 * ((3 * i + 7 * j) % 5) as f64 / 4.0 - 0.01;
            a.push([
                r * lon.cos() * lat.cos(),
                r * lon.sin() * lat.cos(),
                r * lat.sin(),
            ]);
        }
    }
    let (forward, backward) = sphere_distances(&a);
    let dir = temp_dir();
    let text: String = a
        .iter()
        .map(|p| format!("{},{},{}\n", p[0], p[1], p[2]))
        .collect();
    let file = write(dir.path(), "a.csv", &format!("x,y,z\n{text}"));
    let o = karkas(&["hausdorff", s(&file), "--expr", "x^2+y^2+z^2-1"]);
    assert!(o.status.success(), "{}", stderr(&o));
    let out = stdout(&o);
    let (ab, ba) = (field(&out, "A -> B").0, field(&out, "B -> A").0);
    assert!((ab - forward).abs() < 1e-9, "{ab} vs {forward}");
    assert!((ba - backward).abs() < 1e-9, "{ba} vs {backward}");
    assert!(ba > 2.0 * ab && ab > 0.005, "{ab} {ba}");
    assert_eq!(field(&out, "hausdorff").0, ba.max(ab));
}

#[test]
fn errors_exit_2() {
    let dir = temp_dir();
    let a = write(dir.path(), "a.csv", "x,y,z\n0,0,0\n");
    let o = karkas(&["hausdorff", s(&a), s(&dir.path().join("none.csv"))]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("none.csv"));
    let o = karkas(&["hausdorff", s(&a), s(&a), "--expr", "x"]);
    assert_eq!(o.status.code(), Some(2));
    let o = karkas(&["hausdorff", s(&a)]);
    assert_eq!(o.status.code(), Some(2));
    let o = karkas(&["hausdorff", s(&a), "--expr", "x^^2"]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("character 3"), "{}", stderr(&o));
    let bad = write(dir.path(), "bad.obj", "v 0 0\n");
    let o = karkas(&["hausdorff", s(&a), s(&bad)]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains("bad.obj:1:"), "{}", stderr(&o));
}

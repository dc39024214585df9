//! Meshes through the command line: files other tools export read by `convert`, closed
//! surfaces written with their seams welded, `--flip-normals`, and the refusals.

use std::path::{Path, PathBuf};

use crate::common::{assert_rejected, grid_csv, karkas, read_obj, s, stderr, temp_dir, write};

/// Six times the signed volume the triangles enclose: positive when they wind outwards.
fn signed_volume((positions, triangles): &(Vec<[f64; 3]>, Vec<[usize; 3]>)) -> f64 {
    triangles
        .iter()
        .map(|t| {
            let [p, q, r] = t.map(|k| positions[k]);
            p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                + p[2] * (q[0] * r[1] - q[1] * r[0])
        })
        .sum()
}

/// True when every edge is on exactly two triangles, once in each direction.
fn closed_and_consistent(triangles: &[[usize; 3]]) -> bool {
    let mut directed = std::collections::HashMap::new();
    for t in triangles {
        for e in 0..3 {
            *directed.entry((t[e], t[(e + 1) % 3])).or_insert(0) += 1;
        }
    }
    directed
        .iter()
        .all(|(&(p, q), &n)| n == 1 && directed.get(&(q, p)) == Some(&1))
}

/// A torus skeleton for `surface dps-tube`: 3 curves along of 16 samples, 4 rings of 12.
fn torus_skeleton(dir: &Path) -> (PathBuf, PathBuf) {
    let at = |p: usize, q: usize| {
        let (u, v) = (
            std::f64::consts::TAU * p as f64 / 12.0,
            std::f64::consts::TAU * q as f64 / 16.0,
        );
        let r = 3.0 + u.cos();
        [r * v.cos(), r * v.sin(), u.sin()]
    };
    let mut along = String::from("i,q,x,y,z\n");
    for i in 0..3 {
        for q in 0..16 {
            let [x, y, z] = at(i * 4, q);
            along.push_str(&format!("{i},{q},{x},{y},{z}\n"));
        }
    }
    let mut across = String::from("j,p,x,y,z\n");
    for j in 0..4 {
        for p in 0..12 {
            let [x, y, z] = at(p, j * 4);
            across.push_str(&format!("{j},{p},{x},{y},{z}\n"));
        }
    }
    (write(dir, "f.csv", &along), write(dir, "g.csv", &across))
}

#[test]
fn a_closed_tube_is_a_closed_mesh_and_flips_on_request() {
    let dir = temp_dir();
    let (f, g) = torus_skeleton(dir.path());
    let run = |name: &str, flip: bool| {
        let out = dir.path().join(name);
        let mut args = vec![
            "surface",
            "dps-tube",
            "--along",
            s(&f),
            "--across",
            s(&g),
            "--n1",
            "4",
            "--n2",
            "4",
            "-o",
        ];
        args.push(s(&out));
        if flip {
            args.push("--flip-normals");
        }
        let o = karkas(&args);
        assert!(o.status.success(), "{}", stderr(&o));
        out
    };
    let up = read_obj(&run("up.obj", false));
    let down = read_obj(&run("down.obj", true));
    // 12 x 16 values, both seams welded: 12 * 16 vertices and 2 * 12 * 16 triangles.
    assert_eq!((up.0.len(), up.1.len()), (192, 384));
    assert!(closed_and_consistent(&up.1));
    assert!(closed_and_consistent(&down.1));
    let (a, b) = (signed_volume(&up), signed_volume(&down));
    assert!(a * b < 0.0 && (a + b).abs() < 1e-9 * a.abs(), "{a} {b}");
    // PLY and GLB: the same welded counts.
    let ply = std::fs::read(run("t.ply", false)).unwrap();
    assert!(String::from_utf8_lossy(&ply).contains("element vertex 192\n"));
    // The structured grid keeps the whole closed grid, 13 x 17.
    let vts = std::fs::read_to_string(run("t.vts", true)).unwrap();
    assert!(vts.contains("WholeExtent=\"0 16 0 12 0 0\""));
    let vtk = std::fs::read_to_string(run("t.vtk", false)).unwrap();
    assert!(vtk.contains("NORMALS Normals float") && !vtk.contains("VECTORS"));
}

#[test]
fn flip_normals_on_every_surface_command() {
    let dir = temp_dir();
    // A ring of 8 nodes around x, 4 along: closed in v.
    let ring = grid_csv(4, 8, |i, j| {
        let a = std::f64::consts::TAU * j as f64 / 8.0;
        [i as f64, a.cos(), a.sin()]
    });
    let input = write(dir.path(), "ring.csv", &ring);
    for command in ["ll", "bicubic"] {
        let (a, b) = (dir.path().join("a.obj"), dir.path().join("b.obj"));
        for (out, flip) in [(&a, false), (&b, true)] {
            let mut args = vec!["surface", command, "--closed-v", "--samples", "5,9"];
            args.extend([s(&input), "-o", s(out)]);
            if flip {
                args.push("--flip-normals");
            }
            let o = karkas(&args);
            assert!(o.status.success(), "{command}: {}", stderr(&o));
        }
        let (up, down) = (read_obj(&a), read_obj(&b));
        // 5 x 9 samples, the seam column welded: 5 x 8 vertices.
        assert_eq!(up.0.len(), 40, "{command}");
        // The open tube's volume through the triangles is not closed, but the winding of
        // every triangle reverses: the face normals at the same place point the other way.
        let normal = |m: &(Vec<[f64; 3]>, Vec<[usize; 3]>), k: usize| {
            let [p, q, r] = m.1[k].map(|i| m.0[i]);
            let (d, e) = (
                [q[0] - p[0], q[1] - p[1], q[2] - p[2]],
                [r[0] - p[0], r[1] - p[1], r[2] - p[2]],
            );
            let n = [
                d[1] * e[2] - d[2] * e[1],
                d[2] * e[0] - d[0] * e[2],
                d[0] * e[1] - d[1] * e[0],
            ];
            let c = [
                (p[0] + q[0] + r[0]) / 3.0,
                (p[1] + q[1] + r[1]) / 3.0,
                (p[2] + q[2] + r[2]) / 3.0,
            ];
            // Radial part of the normal at the triangle's centre.
            n[1] * c[1] + n[2] * c[2]
        };
        let outward = |m| (0..64).map(|k| normal(m, k)).sum::<f64>();
        assert!(outward(&up) * outward(&down) < 0.0, "{command}");
    }
    // Coons surfaces and convert take the option too.
    let glb = dir.path().join("g.glb");
    let o = karkas(&["convert", "--flip-normals", s(&input), s(&glb)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let u = write(
        dir.path(),
        "u.csv",
        "curve,x,y,z\n0,0,0,0\n0,1,0,0\n0,2,0,0\n1,0,1,0\n1,1,1,0.5\n1,2,1,0\n",
    );
    let v = write(
        dir.path(),
        "v.csv",
        "curve,x,y,z\n0,0,0,0\n0,0,0.5,0\n0,0,1,0\n1,2,0,0\n1,2,0.5,0\n1,2,1,0\n",
    );
    let stl = dir.path().join("c.stl");
    let o = karkas(&[
        "surface",
        "coons",
        "--kind",
        "bilinear",
        "--u-curves",
        s(&u),
        "--v-curves",
        s(&v),
        "--flip-normals",
        "-o",
        s(&stl),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
}

#[test]
fn flip_normals_is_refused_for_outputs_without_normals() {
    let dir = temp_dir();
    let input = write(
        dir.path(),
        "g.csv",
        &grid_csv(3, 3, |i, j| [i as f64, j as f64, 0.0]),
    );
    let out = dir.path().join("s.csv");
    assert_rejected(
        &["surface", "ll", "--flip-normals", s(&input), "-o", s(&out)],
        "--flip-normals: only meshes (.obj .stl .ply .vtk .vts .glb) have normals to flip, not .csv",
        &out,
        None,
    );
}

#[test]
fn convert_reads_meshes_other_tools_export() {
    let dir = temp_dir();
    let facet = |c: [[f64; 3]; 3]| {
        let mut f = String::from("facet normal 0 0 0\r\n outer loop\r\n");
        for p in c {
            f += &format!("  vertex {} {} {}\r\n", p[0], p[1], p[2]);
        }
        f + " endloop\r\nendfacet\r\n"
    };
    let (a, b, c, d) = (
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [1.0, 1.0, 0.0],
    );
    // A bare `solid` line, CRLF ends, and a second solid.
    let stl = format!(
        "solid\r\n{}endsolid\r\nsolid\tlid\r\n{}endsolid\tlid\r\n",
        facet([a, b, d]),
        facet([a, d, c])
    );
    let input = write(dir.path(), "export.stl", &stl);
    let out = dir.path().join("export.obj");
    let o = karkas(&["convert", s(&input), s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let (positions, triangles) = read_obj(&out);
    assert_eq!((positions.len(), triangles.len()), (4, 2));
    // OBJ with vertex colours and a quad, to ASCII PLY.
    let obj = "mtllib m.mtl\nv 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 1 1 1\n\
               vt 0 0\ng quad\nusemtl red\nf 1/1 2/1 3/1 4/1\n";
    let input = write(dir.path(), "scan.obj", obj);
    let out = dir.path().join("scan.ply");
    let o = karkas(&["convert", "--ascii", s(&input), s(&out)]);
    assert!(o.status.success(), "{}", stderr(&o));
    let ply = std::fs::read_to_string(&out).unwrap();
    assert!(ply.contains("element vertex 4\n") && ply.contains("element face 2\n"));
}

#[test]
fn damaged_and_foreign_mesh_files_are_refused_in_one_line() {
    let dir = temp_dir();
    let out = dir.path().join("out.obj");
    let not_ply = write(dir.path(), "model.ply", "solid model\nfacet normal 0 0 1\n");
    assert_rejected(
        &["convert", s(&not_ply), s(&out)],
        "model.ply: not a PLY file: the first line is 'solid model'",
        &out,
        None,
    );
    // A binary STL whose count is far beyond its size: refused before allocating.
    let mut bytes = vec![b' '; 80];
    bytes.extend_from_slice(&4_000_000_000u32.to_le_bytes());
    bytes.extend_from_slice(&[0; 50]);
    let huge = dir.path().join("huge.stl");
    std::fs::write(&huge, &bytes).unwrap();
    assert_rejected(
        &["convert", s(&huge), s(&out)],
        "huge.stl: not a readable STL file: the binary header counts 4000000000 triangles, which need 200000000084 bytes, but the input has 134",
        &out,
        None,
    );
    // A PLY count its body cannot hold.
    let huge_ply = write(
        dir.path(),
        "huge.ply",
        "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000\nproperty float x\n\
         property float y\nproperty float z\nend_header\n\0\0\0\0",
    );
    assert_rejected(
        &["convert", s(&huge_ply), s(&out)],
        "huge.ply: the PLY header declares 1000000000 'vertex' elements, more than its body of 4 bytes can hold",
        &out,
        None,
    );
    // A damaged ASCII STL line and an OBJ vertex of five numbers, named by their lines.
    let bad_stl = write(
        dir.path(),
        "bad.stl",
        "solid\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 x 0\n",
    );
    assert_rejected(
        &["convert", s(&bad_stl), s(&out)],
        "bad.stl: not a readable STL file: line 5: 'x' is not a finite number",
        &out,
        None,
    );
    let bad_obj = write(dir.path(), "bad.obj", "v 0 0 0\nv 1 0 0 0.5 0.5\n");
    let ply_out = dir.path().join("out.ply");
    assert_rejected(
        &["convert", s(&bad_obj), s(&ply_out)],
        "bad.obj:2: a vertex is x y z, x y z w or x y z r g b [a]: found 5 numbers",
        &ply_out,
        None,
    );
    // A mesh larger than the memory cap.
    let mut big = vec![b' '; 80];
    big.extend_from_slice(&30_000u32.to_le_bytes());
    for k in 0..30_000u32 {
        big.extend_from_slice(&[0; 12]);
        for c in 0..9u32 {
            big.extend_from_slice(&((9 * k + c) as f32).to_le_bytes());
        }
        big.extend_from_slice(&[0, 0]);
    }
    let big_path = dir.path().join("big.stl");
    std::fs::write(&big_path, &big).unwrap();
    assert_rejected(
        &["convert", "--max-memory", "1M", s(&big_path), s(&out)],
        &["big.stl", "memory cap"][..],
        &out,
        None,
    );
}

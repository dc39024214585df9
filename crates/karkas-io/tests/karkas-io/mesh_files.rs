//! Meshes as other tools write them, read through `read_mesh` (and standard input through
//! `read_mesh_from`); closed sample grids written with their seams welded; meshes turned
//! over. Every file is written here, small, in the shape of the real ones.

use std::collections::HashMap;

use karkas::{Grid, Point3};
use karkas_io::input::Input;
use karkas_io::mesh::{read_mesh, read_mesh_from, write_mesh, write_surface_mesh, MeshFormat};
use karkas_io::mesh::{MeshOptions, TriangleMesh};

use crate::util::scratch;

/// Writes `bytes` as `name` in a fresh folder and reads it as a mesh.
fn read_bytes_as(name: &str, bytes: &[u8]) -> Result<TriangleMesh, String> {
    let (_dir, path) = scratch(name);
    std::fs::write(&path, bytes).unwrap();
    read_mesh(&path).map_err(|e| e.to_string())
}

/// One ASCII facet over three corners, with `eol` line ends.
fn facet(corners: [[f64; 3]; 3], eol: &str) -> String {
    let mut s = format!("  facet normal 0 0 1{eol}    outer loop{eol}");
    for c in corners {
        s += &format!("      vertex {} {} {}{eol}", c[0], c[1], c[2]);
    }
    s + &format!("    endloop{eol}  endfacet{eol}")
}

const A: [f64; 3] = [0.0, 0.0, 0.0];
const B: [f64; 3] = [1.0, 0.0, 0.0];
const C: [f64; 3] = [0.0, 1.0, 0.0];
const D: [f64; 3] = [1.0, 1.0, 0.0];

#[test]
fn ascii_stl_with_a_bare_solid_line_tabs_and_crlf() {
    // A bare `solid` (CAD exports without a name), LF line ends.
    let bare = format!(
        "solid\n{}{}endsolid\n",
        facet([A, B, D], "\n"),
        facet([A, D, C], "\n")
    );
    let mesh = read_bytes_as("bare.stl", bare.as_bytes()).unwrap();
    assert_eq!((mesh.positions.len(), mesh.triangles.len()), (4, 2));
    // `solid<TAB>name` and CRLF ends, upper-case keywords as some exporters write them.
    let crlf = format!(
        "solid\tpart 7\r\n{}ENDSOLID\tpart 7\r\n",
        facet([A, B, D], "\r\n").replace("vertex", "VERTEX")
    );
    let mut crlf = crlf.into_bytes();
    // A solid name in Latin-1 ("Bauteil \u{fc}"), as older CAD tools write it.
    crlf.splice(11..11, *b" Bauteil \xfc");
    let mesh = read_bytes_as("crlf.stl", &crlf).unwrap();
    assert_eq!((mesh.positions.len(), mesh.triangles.len()), (3, 1));
    assert_eq!(mesh.positions[2], Point3::new(D));
    // A file of nothing but one line `solid` has no faces.
    let e = read_bytes_as("empty.stl", b"solid\n").unwrap_err();
    assert!(e.ends_with("empty.stl: the mesh has no faces"), "{e}");
}

#[test]
fn ascii_stl_with_several_solids_reads_them_all() {
    let text = format!(
        "solid wing\n{}endsolid wing\nsolid tail\n{}{}endsolid tail\n",
        facet([A, B, D], "\n"),
        facet([A, D, C], "\n"),
        facet([B, D, [2.0, 2.0, 2.0]], "\n")
    );
    let mesh = read_bytes_as("two.stl", text.as_bytes()).unwrap();
    assert_eq!(mesh.triangles.len(), 3);
    // Corners equal across solids are one vertex.
    assert_eq!(mesh.positions.len(), 5);
}

/// A binary STL of `triangles`, its 80-byte header starting with `header`.
fn binary_stl(header: &[u8], triangles: &[[[f32; 3]; 3]]) -> Vec<u8> {
    let mut bytes = vec![b' '; 80];
    bytes[..header.len()].copy_from_slice(header);
    bytes.extend_from_slice(&(triangles.len() as u32).to_le_bytes());
    for t in triangles {
        bytes.extend_from_slice(&[0u8; 12]);
        for c in t.iter().flatten() {
            bytes.extend_from_slice(&c.to_le_bytes());
        }
        bytes.extend_from_slice(&[0, 0]);
    }
    bytes
}

#[test]
fn binary_stl_under_a_solid_header_is_binary_by_its_size() {
    let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let u = [[1.0, 0.0, 0.0], [1.0, 1.0, 0.0], [0.0, 1.0, 0.0]];
    let bytes = binary_stl(b"solid exported by a CAD tool", &[t, u]);
    let mesh = read_bytes_as("b.stl", &bytes).unwrap();
    assert_eq!((mesh.positions.len(), mesh.triangles.len()), (4, 2));
    // Without `solid`, trailing bytes after the counted triangles are ignored.
    let mut padded = binary_stl(b"binary", &[t]);
    padded.extend_from_slice(b"\0\0\0\0");
    assert_eq!(read_bytes_as("p.stl", &padded).unwrap().triangles.len(), 1);
    // Under a `solid` header too, when the records hold binary data (a trailing byte).
    let mut padded = binary_stl(b"solid exported with a trailing byte", &[t, u]);
    padded.push(b'\n');
    assert_eq!(read_bytes_as("q.stl", &padded).unwrap().triangles.len(), 2);
    // A count the file is too short for is refused before anything is allocated.
    let mut huge = binary_stl(b"binary", &[t]);
    huge[80..84].copy_from_slice(&u32::MAX.to_le_bytes());
    let e = read_bytes_as("huge.stl", &huge).unwrap_err();
    assert!(
        e.contains("the binary header counts 4294967295 triangles, which need 214748364834 bytes, but the input has 134"),
        "{e}"
    );
    // A damaged binary file under a `solid` header: said so, not "line 1: binary data".
    let mut damaged = binary_stl(b"solid x", &[t]);
    damaged.truncate(120);
    let e = read_bytes_as("damaged.stl", &damaged).unwrap_err();
    assert!(e.contains("a damaged binary STL"), "{e}");
    let e = read_bytes_as("short.stl", b"abc").unwrap_err();
    assert!(e.contains("3 bytes: too short for a binary STL"), "{e}");
}

#[test]
fn ascii_stl_errors_name_the_line() {
    let text =
        format!("solid s\n{}", facet([A, B, D], "\n")).replace("vertex 1 0 0", "vertex 1 x 0");
    let e = read_bytes_as("bad.stl", text.as_bytes()).unwrap_err();
    assert!(
        e.ends_with("not a readable STL file: line 5: 'x' is not a finite number"),
        "{e}"
    );
    let e = read_bytes_as(
        "odd.stl",
        b"solid s\nfacet normal 0 0 1\nouter loop\nbanana\n",
    )
    .unwrap_err();
    assert!(e.contains("line 4: unexpected 'banana'"), "{e}");
}

#[test]
fn obj_with_colours_w_polygons_and_other_lines() {
    let text = "\u{feff}# exported by a scanner\nmtllib part.mtl\no part\ng group\ns 1\n\
        v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 1 1 0 0 0 1\nv 0 1 0 0.5 0.5 0.5\n\
        v 0.5 1.5 0 2.0\nvt 0 0\nvt 1 0\nvn 0 0 1\nusemtl steel\n\
        f 1/1/1 2/2/1 3/1/1 4/2/1\nf -5 -1 -2\nl 1 2\np 3\nf 2//1 3//1 5//1 4//1 1//1\n";
    let mesh = read_bytes_as("scan.obj", text.as_bytes()).unwrap();
    assert_eq!(mesh.positions.len(), 5);
    // `w` is not divided out: the position is as written.
    assert_eq!(mesh.positions[4], Point3::new([0.5, 1.5, 0.0]));
    // A quad: 2 triangles; a triangle by relative indices; a pentagon: the fan of 3.
    assert_eq!(
        mesh.triangles,
        vec![
            [0, 1, 2],
            [0, 2, 3],
            [0, 4, 3],
            [1, 2, 4],
            [1, 4, 3],
            [1, 3, 0]
        ]
    );
    assert!(
        mesh.normals.is_empty(),
        "the normals do not follow the vertices"
    );
    // A group name in Latin-1 is skipped; a vertex line that is not UTF-8 is not.
    let latin = b"g Fl\xfcgel\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    assert_eq!(
        read_bytes_as("latin.obj", latin).unwrap().triangles.len(),
        1
    );
    let e = read_bytes_as("bad.obj", b"v 0 0 0\xff\n").unwrap_err();
    assert!(e.ends_with("bad.obj:1: not UTF-8 text (binary data, or a file saved in another encoding: save it as UTF-8)"), "{e}");
    let e = read_bytes_as("five.obj", b"v 1 2 3 4 5\n").unwrap_err();
    assert!(
        e.ends_with("five.obj:1: a vertex is x y z, x y z w or x y z r g b [a]: found 5 numbers"),
        "{e}"
    );
    let e = read_bytes_as("red.obj", b"v 1 2 3 red 0 0\n").unwrap_err();
    assert!(
        e.ends_with("red.obj:1: 'red' is not a number (column 5)"),
        "{e}"
    );
}

/// The header lines of a PLY file of 4 vertices (with normals and colours, and a list of
/// texture coordinates per vertex) and one quad face with a list of its own besides the
/// corners, then a `material` element, in `format`.
fn ply_header(format: &str) -> String {
    format!(
        "ply\nformat {format} 1.0\ncomment made by a scanner\nobj_info camera 3\n\
         element vertex 4\nproperty float32 x\nproperty float32 y\nproperty float32 z\n\
         property float32 nx\nproperty float32 ny\nproperty float32 nz\n\
         property uint8 red\nproperty uint8 green\nproperty uint8 blue\n\
         property list uint8 float32 texcoord\n\
         element face 1\nproperty list uchar int32 vertex_index\nproperty list int16 uint16 flags\n\
         element material 2\nproperty float64 shine\nproperty list uint32 int8 tags\n\
         end_header\n"
    )
}

#[test]
fn ply_with_type_aliases_comments_and_list_properties_in_every_encoding() {
    let xyz = [
        [0.0f32, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [1.0, 1.0, 0.0],
        [0.0, 1.0, 0.0],
    ];
    let ascii = ply_header("ascii")
        + "0 0 0 0 0 1 255 0 0 2 0 0\n1 0 0 0 0 1 0 255 0 2 1 0\n\
           1 1 0 0 0 1 0 0 255 2 1 1\n0 1 0 0 0 1 9 9 9 2 0 1\n\
           4 0 1 2 3 3 7 7 7\n0.5 2 -1 1\n0.25 0\n";
    for (format, big) in [("binary_little_endian", false), ("binary_big_endian", true)] {
        let mut bytes = ply_header(format).into_bytes();
        let put = |bytes: &mut Vec<u8>, le: &[u8]| {
            let mut b = le.to_vec();
            if big {
                b.reverse();
            }
            bytes.extend_from_slice(&b);
        };
        for p in xyz {
            for c in p.into_iter().chain([0.0, 0.0, 1.0]) {
                put(&mut bytes, &c.to_le_bytes());
            }
            bytes.extend_from_slice(&[1, 2, 3, 2]);
            for c in [0.5f32, 0.5] {
                put(&mut bytes, &c.to_le_bytes());
            }
        }
        bytes.push(4);
        for k in 0..4i32 {
            put(&mut bytes, &k.to_le_bytes());
        }
        put(&mut bytes, &3i16.to_le_bytes());
        for k in 0..3u16 {
            put(&mut bytes, &k.to_le_bytes());
        }
        for _ in 0..2 {
            put(&mut bytes, &1.5f64.to_le_bytes());
            put(&mut bytes, &2u32.to_le_bytes());
            bytes.extend_from_slice(&[7, 8]);
        }
        let mesh = read_bytes_as("scan.ply", &bytes).unwrap();
        assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]], "{format}");
        assert_eq!(mesh.positions[2], Point3::new([1.0, 1.0, 0.0]), "{format}");
        assert_eq!(mesh.normals.len(), 4);
        // One byte fewer: the material's last list item is missing.
        bytes.pop();
        let e = read_bytes_as("cut.ply", &bytes).unwrap_err();
        assert!(
            e.contains("ends early or is malformed in element 'material'"),
            "{e}"
        );
    }
    let mesh = read_bytes_as("scan.ply", ascii.as_bytes()).unwrap();
    assert_eq!(mesh.triangles, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(mesh.positions[3], Point3::new([0.0, 1.0, 0.0]));
}

#[test]
fn ply_refusals_are_clear() {
    let e = read_bytes_as("x.ply", b"solid not a ply\nfacet\n").unwrap_err();
    assert!(
        e.ends_with("x.ply: not a PLY file: the first line is 'solid not a ply'"),
        "{e}"
    );
    let long = format!("{}\n", "z".repeat(300));
    let e = read_bytes_as("long.ply", long.as_bytes()).unwrap_err();
    assert!(
        e.ends_with(&format!("the first line is '{}...'", "z".repeat(100))),
        "{e}"
    );
    let e = read_bytes_as("empty.ply", b"").unwrap_err();
    assert!(
        e.ends_with("empty.ply: not a PLY file: the input is empty"),
        "{e}"
    );
    // A count the body cannot hold is refused before anything is allocated.
    let huge = "ply\nformat binary_little_endian 1.0\nelement vertex 18446744073709551615\n\
                property float x\nproperty float y\nproperty float z\nend_header\n\0\0\0\0";
    let e = read_bytes_as("huge.ply", huge.as_bytes()).unwrap_err();
    assert!(
        e.ends_with("the PLY header declares 18446744073709551615 'vertex' elements, more than its body of 4 bytes can hold"),
        "{e}"
    );
    let e = read_bytes_as(
        "t.ply",
        b"ply\nformat ascii 1.0\nelement vertex 1\nproperty float128 x\nend_header\n",
    )
    .unwrap_err();
    assert!(
        e.ends_with("t.ply:4: malformed property line 'property float128 x'"),
        "{e}"
    );
}

#[test]
fn standard_input_is_read_once_by_its_content() {
    let stl = format!("solid\r\n{}endsolid\r\n", facet([A, B, D], "\r\n"));
    let ply = "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n\
               property float z\nelement face 1\nproperty list uchar int vertex_indices\n\
               end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    let obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
    let t = [[0.0, 0.0, 0.0], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]];
    let binary = binary_stl(b"solid but binary", &[t]);
    for bytes in [
        stl.into_bytes(),
        ply.as_bytes().to_vec(),
        obj.as_bytes().to_vec(),
        binary,
    ] {
        let input = Input::from_reader("<stdin>", std::io::Cursor::new(bytes));
        let mesh = read_mesh_from(input, None).unwrap();
        assert_eq!(mesh.triangles.len(), 1);
    }
    // A format given is not sniffed.
    let input = Input::from_reader("<stdin>", std::io::Cursor::new(obj.as_bytes().to_vec()));
    let e = read_mesh_from(input, Some(MeshFormat::Ply)).unwrap_err();
    assert_eq!(
        e.to_string(),
        "<stdin>: not a PLY file: the first line is 'v 0 0 0'"
    );
}

/// A torus sampled over both periods: its last row and column repeat the first.
fn torus(nu: usize, nv: usize) -> Grid<Point3> {
    let tau = std::f64::consts::TAU;
    Grid::from_fn(nu, nv, |a, b| {
        let (u, v) = (
            tau * (a % (nu - 1)) as f64 / (nu - 1) as f64,
            tau * (b % (nv - 1)) as f64 / (nv - 1) as f64,
        );
        let r = 2.0 + 0.5 * v.cos();
        Point3::new([r * u.cos(), r * u.sin(), 0.5 * v.sin()])
    })
}

/// The number of triangles at each undirected edge, and whether every edge is used once in
/// each direction (a consistently wound closed surface).
fn edges(triangles: &[[u32; 3]]) -> (HashMap<(u32, u32), usize>, bool) {
    let mut count = HashMap::new();
    let mut directed = HashMap::new();
    for t in triangles {
        for e in 0..3 {
            let (p, q) = (t[e], t[(e + 1) % 3]);
            *count.entry((p.min(q), p.max(q))).or_insert(0) += 1;
            *directed.entry((p, q)).or_insert(0) += 1;
        }
    }
    let consistent = directed
        .iter()
        .all(|(&(p, q), &n)| n == 1 && directed.get(&(q, p)) == Some(&1));
    (count, consistent)
}

#[test]
fn closed_grids_are_written_with_their_seams_welded() {
    let (dir, _) = scratch("");
    let grid = torus(9, 7);
    for ext in ["obj", "ply", "glb", "stl", "vts", "vtk"] {
        let path = dir.path().join(format!("torus.{ext}"));
        write_surface_mesh(&path, &grid, &MeshOptions::default()).unwrap();
        if matches!(ext, "obj" | "ply") {
            let mesh = read_mesh(&path).unwrap();
            assert_eq!(mesh.positions.len(), 8 * 6, "{ext}");
            assert_eq!(mesh.triangles.len(), 2 * 8 * 6, "{ext}");
            let (count, consistent) = edges(&mesh.triangles);
            assert!(
                count.values().all(|&n| n == 2),
                "{ext}: every edge on two triangles"
            );
            assert!(consistent, "{ext}: consistent winding");
        }
    }
    let glb = std::fs::read(dir.path().join("torus.glb")).unwrap();
    let json_len = u32::from_le_bytes(glb[12..16].try_into().unwrap()) as usize;
    let doc: serde_json::Value = serde_json::from_slice(&glb[20..20 + json_len]).unwrap();
    assert_eq!(doc["accessors"][0]["count"], 48);
    // STL has no shared vertices: all the cells, merged back into 48 vertices on reading.
    let stl = read_mesh(&dir.path().join("torus.stl")).unwrap();
    assert_eq!((stl.positions.len(), stl.triangles.len()), (48, 96));
    // The structured grids keep the whole grid.
    let vts = std::fs::read_to_string(dir.path().join("torus.vts")).unwrap();
    assert!(vts.contains("WholeExtent=\"0 6 0 8 0 0\""));
    let vtk = std::fs::read_to_string(dir.path().join("torus.vtk")).unwrap();
    assert!(vtk.contains("POINTS 63 double\n"));
    assert!(
        vtk.contains("POINT_DATA 63\nNORMALS Normals float\n"),
        "{vtk}"
    );
    assert!(!vtk.contains("VECTORS"));
    // An open grid keeps every sample.
    let open = Grid::from_fn(3, 4, |a, b| Point3::new([a as f64, b as f64, 0.0]));
    let path = dir.path().join("open.obj");
    write_surface_mesh(&path, &open, &MeshOptions::default()).unwrap();
    assert_eq!(read_mesh(&path).unwrap().positions.len(), 12);
}

#[test]
fn meshes_are_turned_over_on_request() {
    let (dir, _) = scratch("");
    let grid = torus(9, 7);
    let flip = MeshOptions {
        flip_normals: true,
        ..MeshOptions::default()
    };
    let (a, b) = (dir.path().join("a.ply"), dir.path().join("b.ply"));
    write_surface_mesh(&a, &grid, &MeshOptions::default()).unwrap();
    write_surface_mesh(&b, &grid, &flip).unwrap();
    let (up, down) = (read_mesh(&a).unwrap(), read_mesh(&b).unwrap());
    // Outward on the torus: the normal at the outer equator points away from the axis.
    let outward = |m: &TriangleMesh| {
        let k = (0..m.positions.len())
            .max_by(|&i, &j| m.positions[i][0].total_cmp(&m.positions[j][0]))
            .unwrap();
        m.normals[k][0]
    };
    assert!(outward(&up) * outward(&down) < 0.0);
    let total = |m: &TriangleMesh| {
        // The signed volume: positive when the triangles wind outwards.
        m.triangles
            .iter()
            .map(|t| {
                let [p, q, r] = t.map(|k| m.positions[k as usize]);
                p[0] * (q[1] * r[2] - q[2] * r[1]) - p[1] * (q[0] * r[2] - q[2] * r[0])
                    + p[2] * (q[0] * r[1] - q[1] * r[0])
            })
            .sum::<f64>()
    };
    assert!(total(&up) * total(&down) < 0.0);
    assert!((total(&up) + total(&down)).abs() < 1e-9 * total(&up).abs());
    // A general mesh through write_mesh: corners swapped.
    let general = TriangleMesh {
        grid: None,
        ..up.clone()
    };
    let c = dir.path().join("c.obj");
    write_mesh(&c, &general, &flip).unwrap();
    let back = read_mesh(&c).unwrap();
    assert_eq!(
        back.triangles[0],
        [
            general.triangles[0][0],
            general.triangles[0][2],
            general.triangles[0][1]
        ]
    );
}

#[test]
fn endless_binary_input_is_refused_at_once() {
    // Zeros: a binary header counting no triangles; the rest is never read.
    let zeros = std::io::BufReader::new(std::io::repeat(0));
    let input = Input::from_reader("<stdin>", zeros);
    let e = read_mesh_from(input, None).unwrap_err();
    assert_eq!(e.to_string(), "<stdin>: the mesh has no faces");
    // 0xff bytes: 4294967295 triangles counted, the first one not finite.
    let ones = std::io::BufReader::new(std::io::repeat(0xff));
    let input = Input::from_reader("<stdin>", ones);
    let e = read_mesh_from(input, None).unwrap_err();
    assert_eq!(e.to_string(), "<stdin>: triangle 0: a vertex is not finite");
}

#[test]
fn binary_data_is_not_a_ply_file() {
    let e = read_bytes_as("zero.ply", &[0u8; 64]).unwrap_err();
    assert!(
        e.ends_with("zero.ply: not a PLY file: the first line is binary data or longer than 1 MiB"),
        "{e}"
    );
}

#[test]
fn a_ply_header_line_without_its_comment_keyword_is_skipped() {
    let text = "ply\nformat ascii 1.0\ncomment Created by Blender\n\
                Created by Blender3D 247 - www.blender.org, source file:\n\
                element vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
                element face 1\nproperty list uchar uint vertex_indices\nend_header\n\
                0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n";
    let mesh = read_bytes_as("wuson.ply", text.as_bytes()).unwrap();
    assert_eq!((mesh.positions.len(), mesh.triangles.len()), (3, 1));
}

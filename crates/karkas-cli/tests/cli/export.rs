//! Every command writes meshes, pictures and the viewer page by the output extension; curve
//! pictures take `--comb` and `--whiskers`.

use crate::common::{karkas, s, stderr, temp_dir, write};
#[test]
fn surface_commands_write_every_format() {
    let dir = temp_dir();
    let mut text = String::from("i,j,x,y,z\n");
    for i in 0..4 {
        for j in 0..5 {
            text.push_str(&format!("{i},{j},{i},{j},{}\n", ((i + j) % 2) as f64));
        }
    }
    let grid = write(dir.path(), "g.csv", &text);
    for command in [&["surface", "ll"][..], &["surface", "bicubic"][..]] {
        for ext in [
            "ply", "vtk", "vts", "glb", "stl", "obj", "svg", "png", "html",
        ] {
            let out = dir.path().join(format!("{}.{ext}", command[1]));
            let mut args = command.to_vec();
            args.extend(["--samples", "7,9", s(&grid), "-o", s(&out)]);
            let o = karkas(&args);
            assert!(o.status.success(), "{command:?} {ext}: {}", stderr(&o));
            assert!(std::fs::metadata(&out).unwrap().len() > 0);
        }
    }
    let vtk = std::fs::read_to_string(dir.path().join("ll.vtk")).unwrap();
    assert!(vtk.contains("DIMENSIONS 9 7 1\nPOINTS 63 double\n"));
    let page = std::fs::read_to_string(dir.path().join("ll.html")).unwrap();
    assert!(page.contains("<title>LL surface, L = 3, 4 x 5 grid</title>"));
    let o = karkas(&[
        "surface",
        "ll",
        s(&grid),
        "-o",
        s(&dir.path().join("x.step.txt")),
    ]);
    assert_eq!(o.status.code(), Some(2));
    assert!(stderr(&o).contains(
        ".csv, .svg, .obj, .stl, .png, .step/.stp, .iges/.igs, .ply, .vtk, .vts, .glb, .html"
    ));
}

#[test]
fn curve_pictures_with_comb_and_whiskers() {
    let dir = temp_dir();
    let pts = write(dir.path(), "p.csv", "x,y\n0,0\n1,2\n2,1\n3,3\n4,0\n5,1\n");
    let plain = dir.path().join("plain.svg");
    let decorated = dir.path().join("decorated.svg");
    assert!(karkas(&["curve", "ll", s(&pts), "-o", s(&plain)])
        .status
        .success());
    let o = karkas(&[
        "curve",
        "ll",
        "--comb",
        "--whiskers",
        s(&pts),
        "-o",
        s(&decorated),
    ]);
    assert!(o.status.success(), "{}", stderr(&o));
    let count = |p: &std::path::Path| {
        std::fs::read_to_string(p)
            .unwrap()
            .matches("<polyline")
            .count()
    };
    // The comb adds its drawn teeth (at most 300) and its envelope, the whiskers one line
    // per input point whose node lies in the domain.
    assert!(
        count(&decorated) > count(&plain) + 6,
        "{} vs {}",
        count(&decorated),
        count(&plain)
    );
    for (command, ext) in [
        ("ll", "png"),
        ("ll", "html"),
        ("dps", "png"),
        ("dps", "html"),
    ] {
        let out = dir.path().join(format!("{command}.{ext}"));
        let mut args = vec!["curve", command];
        if command == "dps" {
            args.extend(["--order", "2", "--n", "4"]);
        }
        args.extend([s(&pts), "-o", s(&out)]);
        let o = karkas(&args);
        assert!(o.status.success(), "{command} {ext}: {}", stderr(&o));
    }
}

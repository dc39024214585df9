//! Atomic writing and the CSV writers.

use std::io;
use std::path::Path;

use karkas::{Grid, Point, Point2, Point3};
use karkas_io::grid::read_grid;
use karkas_io::points::{read_curve_points, CurvePoints};
use karkas_io::write::{
    write_atomic, write_curve_csv, write_grid_csv, write_sections_csv, write_surface_csv,
};
use karkas_io::IoError;

use crate::util::scratch;

/// Values whose decimal form is easy to get wrong.
const AWKWARD: [f64; 8] = [
    0.1,
    1.0 / 3.0,
    -0.0,
    1e-300,
    5e-324,
    9.999999999999999e151, // the readers refuse coordinates above 1e152 (range.rs)
    std::f64::consts::PI,
    -123456.789e-7,
];

fn entries(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn curve_csv_round_trip_is_bit_exact() {
    let dir = tempfile::tempdir().unwrap();
    let ts: Vec<f64> = (0..AWKWARD.len()).map(|k| k as f64 / 7.0).collect();

    let planar: Vec<Point2> = AWKWARD
        .iter()
        .zip(AWKWARD.iter().rev())
        .map(|(&x, &y)| Point([x, y]))
        .collect();
    let path = dir.path().join("planar.csv");
    write_curve_csv(&path, &ts, &planar).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with("t,x,y\n0,0.1,"), "{text}");
    let CurvePoints::Planar(back) = read_curve_points(&path).unwrap() else {
        panic!("not planar");
    };
    let bits =
        |p: &[Point2]| -> Vec<[u64; 2]> { p.iter().map(|q| q.0.map(f64::to_bits)).collect() };
    assert_eq!(bits(&back), bits(&planar));

    let spatial: Vec<Point3> = AWKWARD.iter().map(|&x| Point([x, -x, x * 0.5])).collect();
    let path = dir.path().join("spatial.csv");
    write_curve_csv(&path, &ts, &spatial).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(text.starts_with("t,x,y,z\n"), "{text}");
    assert_eq!(text.lines().count(), AWKWARD.len() + 1);
    let CurvePoints::Spatial(back) = read_curve_points(&path).unwrap() else {
        panic!("not spatial");
    };
    let bits =
        |p: &[Point3]| -> Vec<[u64; 3]> { p.iter().map(|q| q.0.map(f64::to_bits)).collect() };
    assert_eq!(bits(&back), bits(&spatial));
}

#[test]
fn surface_csv_is_row_major_u_outer() {
    let (_dir, path) = scratch("s.csv");
    let (us, vs) = ([0.0, 1.0], [0.0, 0.5, 1.0]);
    let points: Vec<Point3> = us
        .iter()
        .flat_map(|&u| vs.iter().map(move |&v| Point([u, v, u + v])))
        .collect();
    write_surface_csv(&path, &us, &vs, &points).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert_eq!(
        text,
        "u,v,x,y,z\n0,0,0,0,0\n0,0.5,0,0.5,0.5\n0,1,0,1,1\n1,0,1,0,1\n1,0.5,1,0.5,1.5\n1,1,1,1,2\n"
    );
}

#[test]
fn mismatched_lengths_write_nothing() {
    let (dir, path) = scratch("bad.csv");
    let e = write_curve_csv(&path, &[0.0], &[Point([0.0, 0.0]), Point([1.0, 1.0])]).unwrap_err();
    assert!(matches!(e, IoError::LengthMismatch { .. }), "{e:?}");
    let e = write_surface_csv(&path, &[0.0, 1.0], &[0.0], &[Point([0.0; 3])]).unwrap_err();
    assert!(matches!(e, IoError::LengthMismatch { .. }), "{e:?}");
    assert!(entries(dir.path()).is_empty());
}

#[test]
fn failed_fill_leaves_destination_and_no_temp_file() {
    let (dir, path) = scratch("out.csv");
    std::fs::write(&path, b"previous content\n").unwrap();
    let e = write_atomic(&path, |out| {
        out.write_all(b"half of the new")?;
        Err(io::Error::other("sampling failed"))
    })
    .unwrap_err();
    assert!(matches!(e, IoError::Write { .. }), "{e:?}");
    assert!(e.to_string().contains("sampling failed"), "{e}");
    assert_eq!(std::fs::read(&path).unwrap(), b"previous content\n");
    assert_eq!(entries(dir.path()), ["out.csv"]);

    // And a successful write replaces it, again without leftovers.
    write_atomic(&path, |out| out.write_all(b"new\n")).unwrap();
    assert_eq!(std::fs::read(&path).unwrap(), b"new\n");
    assert_eq!(entries(dir.path()), ["out.csv"]);
}

#[test]
fn a_large_output_synced_as_it_is_written_arrives_whole() {
    // 40 MiB in pieces of odd sizes: the disk write is asked for in the background every
    // 16 MiB; the file must hold every byte in order, and a failure after those requests
    // must still leave the previous file and no temporary one.
    let (dir, path) = scratch("large.bin");
    let piece: Vec<u8> = (0..99_991u32).map(|k| (k % 251) as u8).collect();
    let total = 40 << 20;
    write_atomic(&path, |out| {
        let mut written = 0;
        while written < total {
            let n = piece.len().min(total - written);
            out.write_all(&piece[..n])?;
            written += n;
        }
        Ok(())
    })
    .unwrap();
    let back = std::fs::read(&path).unwrap();
    assert_eq!(back.len(), total);
    for (k, chunk) in back.chunks(piece.len()).enumerate() {
        assert_eq!(chunk, &piece[..chunk.len()], "piece {k}");
    }
    let e = write_atomic(&path, |out| {
        for _ in 0..300 {
            out.write_all(&piece)?;
        }
        Err(io::Error::other("stopped"))
    })
    .unwrap_err();
    assert!(e.to_string().contains("stopped"), "{e}");
    assert_eq!(std::fs::read(&path).unwrap().len(), total);
    assert_eq!(entries(dir.path()), ["large.bin"]);
}

#[test]
fn missing_directory_is_a_write_error() {
    let (_dir, path) = scratch("no/such/dir/out.csv");
    let e = write_curve_csv(&path, &[0.0], &[Point([0.0, 0.0])]).unwrap_err();
    match &e {
        IoError::Write { path: p, .. } => assert_eq!(p, &path),
        other => panic!("expected a write error, got {other:?}"),
    }
    assert!(e.to_string().starts_with("cannot write "), "{e}");
}

#[cfg(unix)]
#[test]
fn existing_permissions_are_kept() {
    use std::os::unix::fs::PermissionsExt;
    let (_dir, path) = scratch("out.csv");
    std::fs::write(&path, b"old").unwrap();
    std::fs::set_permissions(&path, std::fs::Permissions::from_mode(0o640)).unwrap();
    write_atomic(&path, |out| out.write_all(b"new")).unwrap();
    let mode = std::fs::metadata(&path).unwrap().permissions().mode() & 0o777;
    assert_eq!(mode, 0o640);
}

#[test]
fn grid_csv_reads_back_bit_exact() {
    let dir = tempfile::tempdir().unwrap();
    let grid = Grid::from_fn(2, 4, |i, j| {
        let a = AWKWARD[i * 4 + j];
        Point([a, -a, (i + j) as f64])
    });
    let path = dir.path().join("g.csv");
    write_grid_csv(&path, &grid).unwrap();
    let text = std::fs::read_to_string(&path).unwrap();
    assert!(
        text.starts_with("i,j,x,y,z\n0,0,0.1,-0.1,0\n0,1,"),
        "{text}"
    );
    let back = read_grid(&path).unwrap();
    let bits = |g: &Grid<Point3>| -> Vec<[u64; 3]> {
        g.as_slice().iter().map(|p| p.0.map(f64::to_bits)).collect()
    };
    assert_eq!(bits(&back), bits(&grid));
}

#[test]
fn sections_csv_golden() {
    let dir = tempfile::tempdir().unwrap();
    let square = vec![
        Point([0.0, 0.0, 1.0]),
        Point([3.0, 0.0, 1.0]),
        Point([3.0, 4.0, 1.0]),
        Point([0.0, 0.0, 1.0]),
    ];
    let open = vec![Point([1.0, 2.0, 3.0]), Point([1.0, 2.0, 3.5])];
    let path = dir.path().join("s.csv");
    write_sections_csv(&path, &[square, open]).unwrap();
    assert_eq!(
        std::fs::read_to_string(&path).unwrap(),
        "section,t,x,y,z\n0,0,0,0,1\n0,3,3,0,1\n0,7,3,4,1\n0,12,0,0,1\n1,0,1,2,3\n1,0.5,1,2,3.5\n"
    );
    write_sections_csv(&path, &[]).unwrap();
    assert_eq!(std::fs::read_to_string(&path).unwrap(), "section,t,x,y,z\n");
}

//! `karkas inspect PART.step --points SCAN.csv`: the distance of measured points to a CAD
//! model's faces, signed where a face bounds a solid.
//!
//! The model is read by `karkas_io::cad::read::read_cad` (STEP or IGES, told by content),
//! the points by `karkas_io::pointset::read_point_set`; every point is projected onto the
//! nearest face by `karkas::shape::ShapeProjector` (in parallel). The summary goes to
//! standard output (to standard error when the CSV report goes there), the report to `-o`.

use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::shape::{ShapeNearest, ShapeProjector};
use karkas::Point3;
use karkas_io::cad::read::read_cad;
use karkas_io::input::display_name;
use karkas_io::pointset::read_point_set;
use karkas_io::shortest::push_debug;
use karkas_io::write::{is_stdout, write_atomic};
use karkas_io::OutputFormat;
use std::fmt::Write as _;
use std::io::Write as _;
use std::path::PathBuf;

use crate::input::{faces_of_model, one_standard_input};
use crate::output::console::note;
use crate::output::memory::check_memory;
use crate::output::overwrite::ensure_distinct;
use crate::output::target::output_format;

/// The header of the CSV report (a contract for scripts).
pub const REPORT_HEADER: &str =
    "point,x,y,z,distance,signed_distance,face,u,v,foot_x,foot_y,foot_z,on_edge";

/// The percentiles of the distance the summary gives.
const PERCENTILES: [f64; 5] = [50.0, 90.0, 95.0, 99.0, 99.9];

/// Arguments of `karkas inspect`.
#[derive(Debug, Args)]
pub struct InspectArgs {
    /// The CAD model: a STEP (AP203/AP214/AP242) or IGES 5.3 file, told by its content. Its
    /// faces (B-spline, NURBS and analytic surfaces, trimmed by their edges) are the
    /// reference; a face of a closed shell has an outside, and distances to it are signed.
    model: PathBuf,
    /// The measured points: CSV or whitespace columns x,y,z (any header naming x, y, z) or
    /// the vertices of an .obj mesh, in the model's length unit (coordinates as the file
    /// writes them; the unit is named on standard error). `-` is standard input.
    #[arg(long, value_name = "FILE")]
    points: PathBuf,
    /// The CSV report, one row per point in input order, header
    /// `point,x,y,z,distance,signed_distance,face,u,v,foot_x,foot_y,foot_z,on_edge`:
    /// `point` the 0-based index of the point, `distance` its distance to the nearest face
    /// (>= 0), `signed_distance` the same signed (positive outside the solid; empty where the
    /// face bounds no solid), `face` the 0-based index of that face in the file's order
    /// (karkas's CadModel.shape.faces), `u,v` the foot's parameters on the face's surface,
    /// `foot_x..z` the nearest point, `on_edge` 1 where the foot lies on a trimming edge.
    /// `-o -` writes it to standard output (the summary then goes to standard error).
    #[arg(short, long, value_name = "REPORT.csv")]
    output: Option<PathBuf>,
    /// How many of the farthest points the summary lists.
    #[arg(long, default_value_t = 10, value_name = "N")]
    worst: usize,
}

/// Runs `karkas inspect`.
pub fn run(args: &InspectArgs) -> Result<()> {
    one_standard_input(&[("MODEL", &args.model), ("--points", &args.points)])?;
    if let Some(output) = &args.output {
        output_format(output, &[OutputFormat::Csv])?;
        ensure_distinct(&args.model, output)?;
        ensure_distinct(&args.points, output)?;
    }
    let model = read_cad(&args.model)?;
    let model_name = display_name(&args.model);
    faces_of_model(&args.model, &model, "", "measure against")?;
    let points = read_point_set(&args.points)?;
    if points.is_empty() {
        bail!("{}: no points", display_name(&args.points).display());
    }
    // The report's rows (about 13 numbers of 24 bytes) and the results held meanwhile.
    check_memory(
        &format!("inspect {}", args.points.display()),
        points.len() as u128 * 400,
    )?;
    let start = std::time::Instant::now();
    let projector = ShapeProjector::new(&model.shape, 0.0)
        .with_context(|| format!("{}: a face cannot be sampled", model_name.display()))?;
    let prepared = start.elapsed().as_secs_f64();
    let found = projector.nearest_all(&points);
    note(format!(
        "karkas: {} ({} faces, unit {}), {} ({} points): faces prepared in {prepared:.3} s, \
         points projected in {:.3} s",
        model_name.display(),
        model.shape.faces.len(),
        model.unit.name,
        display_name(&args.points).display(),
        points.len(),
        start.elapsed().as_secs_f64() - prepared
    ));
    let summary = summary(&points, &found, args.worst);
    let report_to_stdout = args.output.as_deref().is_some_and(is_stdout);
    if let Some(output) = &args.output {
        write_atomic(output, |out| write_report(out, &points, &found))?;
    }
    if report_to_stdout {
        eprint!("{summary}");
    } else {
        std::io::stdout()
            .lock()
            .write_all(summary.as_bytes())
            .context("cannot write to standard output")?;
    }
    Ok(())
}

/// The `p`-th percentile of the sorted `values` by the nearest rank: the smallest value at
/// least `p` percent of the values do not exceed.
fn percentile(sorted: &[f64], p: f64) -> f64 {
    let n = sorted.len();
    let rank = ((p / 100.0) * n as f64).ceil() as usize;
    sorted[rank.clamp(1, n) - 1]
}

/// The summary: counts, largest, RMS and mean distance, percentiles, the signed range, and
/// the `worst` farthest points.
fn summary(points: &[Point3], found: &[ShapeNearest], worst: usize) -> String {
    let sorted = sorted_distances(found);
    let n = sorted.len() as f64;
    let rms = (sorted.iter().map(|d| d * d).sum::<f64>() / n).sqrt();
    let mean = sorted.iter().sum::<f64>() / n;
    let mut text = String::new();
    let _ = writeln!(text, "points {}", points.len());
    let _ = writeln!(text, "max {}", sorted[sorted.len() - 1]);
    let _ = writeln!(text, "rms {rms}");
    let _ = writeln!(text, "mean {mean}");
    for p in PERCENTILES {
        let _ = writeln!(text, "p{p} {}", percentile(&sorted, p));
    }
    let (mut count, mut outside, mut inside) = (0usize, 0usize, 0usize);
    let (mut low, mut high) = (f64::INFINITY, f64::NEG_INFINITY);
    for s in found.iter().filter_map(|f| f.signed) {
        count += 1;
        outside += usize::from(s > 0.0);
        inside += usize::from(s < 0.0);
        low = low.min(s);
        high = high.max(s);
    }
    if count > 0 {
        let _ = writeln!(
            text,
            "signed {count} points, min {low}, max {high}, outside {outside}, inside {inside}"
        );
    }
    for (rank, k) in farthest(found, &sorted, worst).into_iter().enumerate() {
        let (q, f) = (points[k], &found[k]);
        let signed = f
            .signed
            .map_or_else(String::new, |s| format!(" signed {s}"));
        let _ = writeln!(
            text,
            "worst {} point {k} distance {}{signed} at {},{},{} face {} foot {},{},{}",
            rank + 1,
            f.distance,
            q[0],
            q[1],
            q[2],
            f.face,
            f.point[0],
            f.point[1],
            f.point[2],
        );
    }
    text
}

/// The distances in increasing order (`f64::total_cmp`): an LSD radix sort of their bits
/// mapped to keys in that order, four passes of 16 bits. Values equal by `total_cmp` have
/// equal bits, so any correct sort gives these very values in this very order.
fn sorted_distances(found: &[ShapeNearest]) -> Vec<f64> {
    const SIGN: u64 = 1 << 63;
    let key = |x: f64| {
        let b = x.to_bits();
        if b & SIGN == 0 {
            b | SIGN
        } else {
            !b
        }
    };
    let value = |k: u64| f64::from_bits(if k & SIGN != 0 { k & !SIGN } else { !k });
    let mut keys: Vec<u64> = found.iter().map(|f| key(f.distance)).collect();
    if keys.len() < 1 << 16 {
        keys.sort_unstable();
        return keys.into_iter().map(value).collect();
    }
    let mut counts = vec![[0usize; 1 << 16]; 4];
    for &k in &keys {
        for (pass, count) in counts.iter_mut().enumerate() {
            count[((k >> (16 * pass)) & 0xffff) as usize] += 1;
        }
    }
    let mut spare = vec![0u64; keys.len()];
    for (pass, count) in counts.iter_mut().enumerate() {
        if count.contains(&keys.len()) {
            continue; // every key has this digit: the pass would not move any
        }
        let mut next = 0;
        for c in count.iter_mut() {
            (*c, next) = (next, next + *c);
        }
        for &k in &keys {
            let digit = ((k >> (16 * pass)) & 0xffff) as usize;
            spare[count[digit]] = k;
            count[digit] += 1;
        }
        std::mem::swap(&mut keys, &mut spare);
    }
    keys.into_iter().map(value).collect()
}

/// The indices of the `worst` farthest points, farthest first (ties by index): those at
/// least as far as the `worst`-th largest of the `sorted` distances, ordered.
fn farthest(found: &[ShapeNearest], sorted: &[f64], worst: usize) -> Vec<usize> {
    let worst = worst.min(sorted.len());
    if worst == 0 {
        return Vec::new();
    }
    let threshold = sorted[sorted.len() - worst];
    let mut order: Vec<usize> = (0..found.len())
        .filter(|&k| found[k].distance.total_cmp(&threshold).is_ge())
        .collect();
    order.sort_unstable_by(|&a, &b| {
        found[b]
            .distance
            .total_cmp(&found[a].distance)
            .then(a.cmp(&b))
    });
    order.truncate(worst);
    order
}

/// Rows of the report formatted at once (in parallel, then written in order).
const ROWS_PER_CHUNK: usize = 8192;

/// Writes the CSV report ([`REPORT_HEADER`]). Rows are formatted in parallel chunks and
/// written in input order.
fn write_report(
    out: &mut dyn std::io::Write,
    points: &[Point3],
    found: &[ShapeNearest],
) -> std::io::Result<()> {
    use rayon::prelude::*;
    let mut out = std::io::BufWriter::new(out);
    writeln!(out, "{REPORT_HEADER}")?;
    let rows = points.len().min(found.len());
    let chunks = rows.div_ceil(ROWS_PER_CHUNK);
    // Two chunks per thread at a time bound the memory the formatted rows take; their
    // buffers are kept from batch to batch.
    let batch = 2 * rayon::current_num_threads().max(1);
    let mut texts: Vec<Vec<u8>> = vec![Vec::new(); batch.min(chunks)];
    for first in (0..chunks).step_by(batch) {
        let count = batch.min(chunks - first);
        texts[..count]
            .par_iter_mut()
            .enumerate()
            .for_each(|(i, text)| {
                let start = (first + i) * ROWS_PER_CHUNK;
                let end = (start + ROWS_PER_CHUNK).min(rows);
                text.clear();
                text.reserve(200 * (end - start));
                for k in start..end {
                    report_row(text, k, points[k], &found[k]);
                }
            });
        for text in &texts[..count] {
            out.write_all(text)?;
        }
    }
    out.flush()
}

/// Appends row `k` of the report: numbers as `{:?}` writes them (`karkas_io::shortest`, the
/// same bytes several times faster than `std::fmt`), integers by `itoa`.
fn report_row(text: &mut Vec<u8>, k: usize, q: Point3, f: &ShapeNearest) {
    let mut integer = itoa::Buffer::new();
    text.extend_from_slice(integer.format(k).as_bytes());
    for x in [q[0], q[1], q[2], f.distance] {
        text.push(b',');
        push_debug(text, x);
    }
    text.push(b',');
    if let Some(s) = f.signed {
        push_debug(text, s);
    }
    text.push(b',');
    text.extend_from_slice(integer.format(f.face).as_bytes());
    for x in [f.u, f.v, f.point[0], f.point[1], f.point[2]] {
        text.push(b',');
        push_debug(text, x);
    }
    text.extend_from_slice(if f.on_edge { b",1\n" } else { b",0\n" });
}

#[cfg(test)]
mod tests {
    use super::{farthest, percentile, report_row, sorted_distances};
    use karkas::shape::ShapeNearest;
    use karkas::Point3;
    use std::fmt::Write as _;

    /// A row as `std::fmt` writes it (the report's form before the fast writer).
    fn row_by_fmt(k: usize, q: Point3, f: &ShapeNearest) -> String {
        let signed = f.signed.map_or_else(String::new, |s| format!("{s:?}"));
        let mut text = String::new();
        let _ = writeln!(
            text,
            "{k},{:?},{:?},{:?},{:?},{signed},{},{:?},{:?},{:?},{:?},{:?},{}",
            q[0],
            q[1],
            q[2],
            f.distance,
            f.face,
            f.u,
            f.v,
            f.point[0],
            f.point[1],
            f.point[2],
            u8::from(f.on_edge)
        );
        text
    }

    #[test]
    fn rows_are_written_as_std_fmt_writes_them() {
        let values = [
            0.0,
            -0.0,
            1.0,
            100.0,
            -2.5,
            0.1,
            1e-4,
            9.9e-5,
            1.5e-7,
            1e16,
            123.456,
            f64::NAN,
            -17.857359283436338,
            1e300,
        ];
        let mut state = 0x9e37_79b9_7f4a_7c15u64;
        let mut next = || {
            state ^= state << 13;
            state ^= state >> 7;
            state ^= state << 17;
            let x = f64::from_bits(state);
            if x.is_finite() {
                x
            } else {
                values[(state % 14) as usize]
            }
        };
        for k in 0..3000usize {
            let pick = |i: usize, r: f64| {
                if (k + i).is_multiple_of(3) {
                    values[(k + i) % values.len()]
                } else {
                    r
                }
            };
            let q = Point3::new([
                pick(0, next()),
                pick(1, next() * 1e-300),
                pick(2, 1e3 * (k as f64).sin()),
            ]);
            let f = ShapeNearest {
                face: k * 7919,
                u: pick(3, next()),
                v: pick(4, (k as f64).sqrt()),
                point: Point3::new([
                    pick(5, next()),
                    pick(6, 1.0 / (k as f64 + 1.0)),
                    pick(7, -(k as f64)),
                ]),
                distance: pick(8, (k as f64 * 0.37).cos().abs()),
                signed: (!k.is_multiple_of(4)).then(|| pick(9, -(k as f64) * 1e-5)),
                on_edge: k.is_multiple_of(5),
            };
            let mut text = Vec::new();
            report_row(&mut text, k, q, &f);
            assert_eq!(String::from_utf8(text).unwrap(), row_by_fmt(k, q, &f));
        }
    }

    /// Results at the distances `d` (other fields fixed).
    fn at_distances(d: &[f64]) -> Vec<ShapeNearest> {
        d.iter()
            .map(|&distance| ShapeNearest {
                distance,
                ..ShapeNearest::UNDEFINED
            })
            .collect()
    }

    #[test]
    fn distances_sort_and_the_farthest_are_those_of_full_sorts() {
        let special = [
            0.0,
            -0.0,
            f64::NAN,
            -f64::NAN,
            f64::INFINITY,
            1e-300,
            5e-324,
            -1.0,
        ];
        let mut state = 0x2545_f491_4f6c_dd1du64;
        for n in [1usize, 7, 1000, 70_000, 200_000] {
            let d: Vec<f64> = (0..n)
                .map(|k| {
                    state ^= state << 13;
                    state ^= state >> 7;
                    state ^= state << 17;
                    match k % 5 {
                        0 => special[(state % 8) as usize],
                        1 => (state % 50) as f64 * 0.25, // many ties
                        2 => f64::from_bits(state),
                        _ => (state >> 11) as f64 / (1u64 << 53) as f64 * 20.0,
                    }
                })
                .collect();
            let found = at_distances(&d);
            let mut want = d.clone();
            want.sort_by(f64::total_cmp);
            let got = sorted_distances(&found);
            let bits = |v: &[f64]| v.iter().map(|x| x.to_bits()).collect::<Vec<u64>>();
            assert_eq!(bits(&got), bits(&want), "{n}");
            let mut order: Vec<usize> = (0..n).collect();
            order.sort_by(|&a, &b| d[b].total_cmp(&d[a]).then(a.cmp(&b)));
            for worst in [0, 1, 3, 10, n / 2, n, n + 5] {
                let want: Vec<usize> = order.iter().copied().take(worst).collect();
                assert_eq!(farthest(&found, &got, worst), want, "{n} {worst}");
            }
        }
    }

    #[test]
    fn percentiles_by_nearest_rank() {
        let v: Vec<f64> = (1..=10).map(f64::from).collect();
        assert_eq!(percentile(&v, 50.0), 5.0);
        assert_eq!(percentile(&v, 90.0), 9.0);
        assert_eq!(percentile(&v, 95.0), 10.0);
        assert_eq!(percentile(&v, 99.9), 10.0);
        assert_eq!(percentile(&[3.0], 50.0), 3.0);
    }
}

//! The library's side of a fairing job without the Python package: reads jobs from standard
//! input, one a line (`T closed n x1 y1 x2 y2 ...`, 2-D points), runs `karkas::fair::fair_curve`
//! and prints one JSON line a job with the B-spline's knots and control points and the CPU
//! time of the call (this thread's, from `/proc/thread-self/schedstat` where there is one).

use karkas::fair::{fair_curve, FairOptions};
use karkas::Point2;
use std::io::{BufRead, Write};
use std::time::Instant;

/// This thread's CPU time in seconds, if the system tells it.
fn thread_cpu() -> Option<f64> {
    let text = std::fs::read_to_string("/proc/thread-self/schedstat").ok()?;
    let ns: f64 = text.split_whitespace().next()?.parse().ok()?;
    Some(ns * 1e-9)
}

fn main() {
    let stdin = std::io::stdin();
    let mut out = std::io::stdout().lock();
    for line in stdin.lock().lines() {
        let line = line.expect("a line");
        let v: Vec<f64> = line
            .split_whitespace()
            .map(|f| f.parse().expect("a number"))
            .collect();
        if v.len() < 3 {
            continue;
        }
        let (tolerance, closed, n) = (v[0], v[1] != 0.0, v[2] as usize);
        let points: Vec<Point2> = (0..n)
            .map(|i| Point2::new([v[3 + 2 * i], v[4 + 2 * i]]))
            .collect();
        let mut options = FairOptions::new(tolerance);
        options.closed = closed;
        let (cpu0, wall) = (thread_cpu(), Instant::now());
        let result = fair_curve(&points, &options);
        let seconds = wall.elapsed().as_secs_f64();
        let cpu = match (cpu0, thread_cpu()) {
            (Some(a), Some(b)) => b - a,
            _ => seconds,
        };
        match result {
            Ok(fair) => {
                let knots: Vec<String> = fair
                    .curve
                    .knots()
                    .iter()
                    .map(|k| format!("{k:e}"))
                    .collect();
                let controls: Vec<String> = fair
                    .curve
                    .control_points()
                    .iter()
                    .map(|c| format!("[{:e},{:e}]", c[0], c[1]))
                    .collect();
                writeln!(
                    out,
                    "{{\"cpu\": {cpu:e}, \"wall\": {seconds:e}, \"knots\": [{}], \"controls\": [{}]}}",
                    knots.join(","),
                    controls.join(",")
                )
                .expect("stdout");
            }
            Err(e) => writeln!(out, "{{\"error\": \"{e}\"}}").expect("stdout"),
        }
        out.flush().expect("stdout");
    }
}

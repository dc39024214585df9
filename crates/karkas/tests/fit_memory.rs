//! The peak memory of the fit on many points, above its input: the resident set's high-water
//! mark (`VmHWM` of `/proc/self/status`, reset through `/proc/self/clear_refs`) less the
//! resident set before the call, as a multiple of the points' own size (`16 n` bytes in 2-D,
//! `24 n` in 3-D).
//!
//! Each case runs in a process of its own (this test binary started again with the case in
//! [`CASE`]), with the C library's allocator told to map every block of 128 KiB or more on its
//! own (`GLIBC_TUNABLES`), so that freed work arrays leave the resident set and what one case
//! freed is not counted as present before the next. Linux only (elsewhere the measure is
//! skipped, with a line saying so).

use karkas::fit::{fit_curve, uniform_knots, FitOptions};
use karkas::Point;
use std::process::Command;

/// The environment variable naming the case a child process measures.
const CASE: &str = "KARKAS_FIT_MEMORY_CASE";

/// Points per case: 4 x 10^5 (6.4 MB in 2-D), where the fixed costs of a fit (its knots'
/// buffers, the thread pool) are below 1% of the points' size.
const POINTS: usize = 400_000;

/// The bound on the growth, as a multiple of the points' size, for the open fit on given
/// knots in 2-D and 3-D (the closed fit and the tolerance mode are measured with the
/// command line, BENCHMARKS.md "The fit's peak memory").
const GROWTH_BOUND: f64 = 5.5;

/// A field of `/proc/self/status` in bytes (`None` off Linux).
fn status_bytes(field: &str) -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with(field))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// The resident set's growth over `work` (the high-water mark during it less the resident
/// set before it), with `work`'s result kept alive until measured.
fn peak_growth<T>(work: impl FnOnce() -> T) -> Option<u64> {
    std::fs::write("/proc/self/clear_refs", "5").ok()?;
    let before = status_bytes("VmRSS:")?;
    let kept = work();
    let peak = status_bytes("VmHWM:")?;
    drop(kept);
    Some(peak.saturating_sub(before))
}

/// A seeded uniform source in `(0, 1)` (a 64-bit linear congruential generator's high bits).
struct Uniform(u64);

impl Uniform {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 + 0.5) / (1u64 << 53) as f64
    }

    /// A standard normal deviate (Box-Muller).
    fn normal(&mut self) -> f64 {
        let (u, v) = (self.next(), self.next());
        (-2.0 * u.ln()).sqrt() * (std::f64::consts::TAU * v).cos()
    }
}

/// `n` points of the ellipse `(0.5 cos th, 0.2 sin th[, 0.1 sin 2 th])` for `th` evenly
/// spread over `[0, reach]`, each coordinate with Gaussian noise of `sigma`; allocated once,
/// at their exact size.
fn noisy_ellipse<const D: usize>(n: usize, reach: f64, sigma: f64, seed: u64) -> Vec<Point<D>> {
    let mut rng = Uniform(seed);
    let mut points = Vec::with_capacity(n);
    for i in 0..n {
        let th = reach * i as f64 / (n - 1) as f64;
        let exact = [0.5 * th.cos(), 0.2 * th.sin(), 0.1 * (2.0 * th).sin()];
        points.push(Point(std::array::from_fn(|d| {
            exact[d] + sigma * rng.normal()
        })));
    }
    points
}

/// The fit's peak growth over the points' size.
fn growth_share<const D: usize, T>(
    points: &[Point<D>],
    fit: impl FnOnce(&[Point<D>]) -> T,
) -> Option<f64> {
    let size = std::mem::size_of_val(points) as f64;
    Some(peak_growth(|| fit(points))? as f64 / size)
}

/// Measures `case` in this process: prints `share=<growth over the points' size>`.
fn measure(case: &str) {
    // Warm up once (the thread pool, lazily built tables) so that they are not counted.
    let small = noisy_ellipse::<2>(2000, std::f64::consts::PI, 1e-4, 7);
    fit_curve(&small, &uniform_knots(5), &FitOptions::default()).expect("warm-up fit");
    drop(small);
    let options = FitOptions::default();
    let half = std::f64::consts::PI;
    let knots = uniform_knots(30);
    let share = match case {
        "open-2d" => growth_share(&noisy_ellipse::<2>(POINTS, half, 1e-4, 1), |p| {
            fit_curve(p, &knots, &options).expect("open fit")
        }),
        "open-3d" => growth_share(&noisy_ellipse::<3>(POINTS, half, 1e-4, 2), |p| {
            fit_curve(p, &knots, &options).expect("3-D fit")
        }),
        other => panic!("no case {other}"),
    };
    match share {
        Some(share) => println!("share={share}"),
        None => println!("unmeasured"),
    }
}

/// The share measured by a child process for `case` (`None` where it cannot measure).
fn measured(case: &str) -> Option<f64> {
    let exe = std::env::current_exe().expect("the test binary");
    let out = Command::new(exe)
        .args([
            "--exact",
            "the_fit_of_many_points_needs_a_bounded_multiple_of_their_size",
        ])
        .args(["--nocapture", "--test-threads", "1"])
        .env(CASE, case)
        .env("GLIBC_TUNABLES", "glibc.malloc.mmap_threshold=131072")
        .output()
        .expect("the child test process");
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(out.status.success(), "{case}: {text}");
    let share = text
        .lines()
        .find_map(|l| l.split("share=").nth(1))
        .and_then(|v| v.trim().parse().ok());
    match share {
        Some(share) => println!("{case}: peak growth {share:.2} x the points' size"),
        None => println!("{case}: not measured here (no /proc/self/clear_refs)"),
    }
    share
}

#[test]
fn the_fit_of_many_points_needs_a_bounded_multiple_of_their_size() {
    if let Ok(case) = std::env::var(CASE) {
        measure(&case);
        return;
    }
    for case in ["open-2d", "open-3d"] {
        if let Some(share) = measured(case) {
            assert!(
                share <= GROWTH_BOUND,
                "{case}: {share:.2} x the points' size"
            );
        }
    }
}

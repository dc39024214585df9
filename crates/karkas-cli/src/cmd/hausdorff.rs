//! `karkas hausdorff`: the two-sided Hausdorff distance between two point sets, or between a
//! point set and an implicit surface (Kuznetsov and Filatov, formula (3.14); docs/methods.md §5).

use anyhow::{bail, Context, Result};
use clap::Args;
use karkas::implicit::ExpressionSurface;
use karkas::measure::{hausdorff_points_implicit, hausdorff_sets, DirectedDistance};
use karkas::Point3;
use karkas_io::input::display_name;
use karkas_io::pointset::read_point_set;

use crate::input::one_standard_input;
use std::path::PathBuf;

/// Arguments of `karkas hausdorff`.
#[derive(Debug, Args)]
pub struct HausdorffArgs {
    /// The sets A and B: files of points (.obj: mesh vertices; .csv or columns: x,y,z, e.g. a
    /// grid i,j,x,y,z or a sampled surface u,v,x,y,z). With --expr, one file (A).
    #[arg(num_args = 1..=2, required = true, value_name = "FILE")]
    inputs: Vec<PathBuf>,
    /// B as the implicit surface F(x, y, z) = 0 (same syntax as `surface implicit --expr`):
    /// its part inside A's bounding box, sampled on a lattice of 64 steps along the box's
    /// largest side, and the closest points of A on it.
    #[arg(long, value_name = "EXPR")]
    expr: Option<String>,
}

/// Runs `karkas hausdorff`.
pub fn run(args: &HausdorffArgs) -> Result<()> {
    let a_path = &args.inputs[0];
    if let Some(b_path) = args.inputs.get(1) {
        one_standard_input(&[("A", a_path), ("B", b_path)])?;
    }
    let a = read_point_set(a_path)?;
    let (h, b_name, b_count) = match (&args.expr, args.inputs.get(1)) {
        (Some(_), Some(_)) => bail!("give either two files or one file and --expr, not both"),
        (None, None) => bail!("give two files, or one file and --expr"),
        (None, Some(b_path)) => {
            let b = read_point_set(b_path)?;
            let h = hausdorff_sets(&a, &b)?;
            (h, display_name(b_path).display().to_string(), Some(b.len()))
        }
        (Some(expr), None) => {
            let surface = ExpressionSurface::parse(expr).context("--expr")?;
            let a_name = || display_name(a_path).display().to_string();
            // The implicit side is the patch A covers: F = 0 inside A's bounding box.
            let h = hausdorff_points_implicit(&a, &surface).with_context(a_name)?;
            (h, format!("F = 0 with F = {expr}"), None)
        }
    };
    let a_name = display_name(a_path).display().to_string();
    let lines = format!(
        "hausdorff {}\n{}\n{}\n",
        h.distance,
        direction_line("A -> B", &h.forward),
        direction_line("B -> A", &h.backward)
    );
    // Written as one result, an error (a closed pipe) returned rather than a panic.
    std::io::Write::write_all(&mut std::io::stdout().lock(), lines.as_bytes())
        .context("cannot write to standard output")?;
    let b_points = b_count.map_or_else(String::new, |n| format!(" ({n} points)"));
    eprintln!(
        "karkas: A = {a_name} ({} points), B = {b_name}{b_points}",
        a.len()
    );
    Ok(())
}

/// One line: the directed distance, the point where it is attained and its nearest point.
fn direction_line(label: &str, d: &DirectedDistance) -> String {
    let p = |q: &Point3| format!("{},{},{}", q[0], q[1], q[2]);
    format!(
        "{label} {} at {} nearest {}",
        d.distance,
        p(&d.from),
        p(&d.to)
    )
}

//! Kuznetsov and Filatov (Theorem 2.1; docs/methods.md §5): turned frames re-laid along the
//! lines of curvature of their own bicubic interpolants (`karkas surface relay`), with the
//! Hausdorff errors of the turned, re-laid and principal frames side by side. Writes every
//! re-laid frame's nodes (grid CSV).

use super::common::{Finding, Output};
use super::param_experiment::{seed_experiments, SeedExperiment, SeedSurface};
use crate::output::samples::sample_surface;
use anyhow::{Context, Result};
use karkas::implicit::{Cylinder, Hyperboloid, ImplicitSurface, NetDirections};
use karkas::measure::hausdorff_surface_implicit;
use karkas::param::{relay_grid, BicubicSurface, GridParameterization, RelayOptions};
use karkas::{Grid, Point3};
use karkas_io::scene::{write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::write::write_grid_csv;
use std::f64::consts::{PI, TAU};

/// Samples of the interpolant in the Hausdorff distance (as the frames of the table).
const SAMPLES: (usize, usize) = (64, 160);

/// The cylinder's frames turned by 30 and 45 degrees (plane sections, as in the table) and
/// the hyperboloid's nets turned by 30 and 45 degrees (both families, open lines), each
/// beside the principal frame of its surface.
pub fn run(out: &Output) -> Result<Vec<Finding>> {
    let table = seed_experiments();
    let cylinder_principal = table[0].run().context("the cylinder's principal frame")?;
    let hyperboloid_principal = table[5]
        .run()
        .context("the hyperboloid's principal frame")?;
    let mut cases: Vec<(SeedExperiment, f64)> = vec![
        (table[1].clone(), cylinder_principal.error.distance),
        (table[2].clone(), cylinder_principal.error.distance),
    ];
    for (degrees, label) in [
        (30.0f64, "hyperboloid, both axes turned 30 deg"),
        (45.0, "hyperboloid, both axes turned 45 deg"),
    ] {
        let mut net = table[5].net;
        net.directions = NetDirections::Turned {
            angle: degrees.to_radians(),
        };
        net.closed_v = false;
        let row = SeedExperiment {
            label,
            paper_error: None,
            surface: SeedSurface::Hyperboloid,
            net,
        };
        cases.push((row, hyperboloid_principal.error.distance));
    }
    let mut findings = Vec::new();
    for (row, principal) in cases {
        let turned = row
            .run()
            .with_context(|| format!("Kuznetsov and Filatov, {}", row.label))?;
        let options = RelayOptions {
            closed: (false, row.net.closed_v),
            ..RelayOptions::default()
        };
        let relaid = relay_grid(&turned.nodes, &options)
            .with_context(|| format!("re-laying {}", row.label))?;
        let relaid_error = match row.surface {
            SeedSurface::Cylinder => {
                relaid_error(&relaid.nodes, &Cylinder { radius: 1.0 }, |_| 1.0)
            }
            SeedSurface::Hyperboloid => {
                relaid_error(&relaid.nodes, &Hyperboloid { neck_radius: 1.0 }, |z| {
                    (1.0 + z * z).sqrt()
                })
            }
        }?;
        let words: Vec<&str> = row
            .label
            .split(|c: char| !c.is_ascii_alphanumeric())
            .filter(|w| !w.is_empty())
            .collect();
        let name = format!("004-relaid-{}", words.join("-"));
        write_grid_csv(&out.file(format!("{name}-nodes.csv")), &relaid.nodes)?;
        write_picture(out, &name, row.label, &relaid.nodes, relaid_error)?;
        let example = format!("004 {}", row.label);
        findings.push(
            Finding::new(
                &example,
                "turned frame: Hausdorff error",
                turned.error.distance,
            )
            .detail(),
        );
        findings.push(Finding::new(
            &example,
            "re-laid along lines of curvature: Hausdorff error",
            relaid_error,
        ));
        findings
            .push(Finding::new(&example, "principal frame: Hausdorff error", principal).detail());
    }
    Ok(findings)
}

/// The two-sided Hausdorff error of the bicubic interpolant (the paper's chord parameters,
/// not-a-knot) of a re-laid frame of a surface of revolution about `z` (radius `rho(z)`)
/// against the exact patch it covers: the heights of its rows (circles) and the angles of its
/// columns (meridians), or the other way round, sampled in closed form four times denser.
fn relaid_error<I: ImplicitSurface>(
    nodes: &Grid<Point3>,
    implicit: &I,
    rho: impl Fn(f64) -> f64,
) -> Result<f64> {
    let surface = BicubicSurface::new(nodes, GridParameterization::default(), false, false)?;
    // Rows are circles when a row keeps its height better than a column does.
    let row_spread = (0..nodes.rows())
        .map(|i| spread((0..nodes.cols()).map(|j| nodes.get(i, j)[2])))
        .fold(0.0, f64::max);
    let col_spread = (0..nodes.cols())
        .map(|j| spread((0..nodes.rows()).map(|i| nodes.get(i, j)[2])))
        .fold(0.0, f64::max);
    let circles = if row_spread <= col_spread {
        nodes.clone()
    } else {
        nodes.transposed()
    };
    let (m, n) = (circles.rows(), circles.cols());
    let centre = circles.get(m / 2, n / 2);
    let base = centre[1].atan2(centre[0]);
    let angle = |p: &Point3| {
        let a = p[1].atan2(p[0]) - base;
        a - TAU * ((a + PI) / TAU).floor()
    };
    let column_angle = |j: usize| (0..m).map(|i| angle(circles.get(i, j))).sum::<f64>() / m as f64;
    let row_height = |i: usize| (0..n).map(|j| circles.get(i, j)[2]).sum::<f64>() / n as f64;
    let (a0, a1) = (column_angle(0), column_angle(n - 1));
    let (z0, z1) = (row_height(0), row_height(m - 1));
    let (pu, pv) = (4 * (m - 1) + 1, 4 * (n - 1) + 1);
    let mut patch = Vec::with_capacity(pu * pv);
    for a in 0..pu {
        let z = z0 + (z1 - z0) * a as f64 / (pu - 1) as f64;
        let r = rho(z);
        for b in 0..pv {
            let t = base + a0 + (a1 - a0) * b as f64 / (pv - 1) as f64;
            patch.push(Point3::new([r * t.cos(), r * t.sin(), z]));
        }
    }
    Ok(hausdorff_surface_implicit(&surface, implicit, &patch, SAMPLES)?.distance)
}

/// `max - min` of the values.
fn spread(values: impl Iterator<Item = f64>) -> f64 {
    let (lo, hi) = values.fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), x| {
        (lo.min(x), hi.max(x))
    });
    hi - lo
}

/// A picture of the re-laid frame's interpolant with its grid lines (lines of curvature).
fn write_picture(
    out: &Output,
    name: &str,
    label: &str,
    nodes: &Grid<Point3>,
    error: f64,
) -> Result<()> {
    let surface = BicubicSurface::new(nodes, GridParameterization::default(), false, false)?;
    let (nu, nv) = (33, 65);
    let (_, _, mesh) = sample_surface(&surface, nu, nv);
    let mut lines: Vec<Vec<Point3>> = (0..nodes.rows()).map(|i| nodes.row(i).to_vec()).collect();
    lines.extend((0..nodes.cols()).map(|j| (0..nodes.rows()).map(|i| *nodes.get(i, j)).collect()));
    let title = format!(
        "Kuznetsov and Filatov: {label}, re-laid along the lines of curvature, Hausdorff error {error:.4}"
    );
    write_scene_svg(
        &out.file(format!("{name}.svg")),
        &Scene {
            title: &title,
            mesh: SceneMesh {
                rows: nu,
                cols: nv,
                points: &mesh,
            },
            curves: &[SceneCurves {
                label: "the re-laid grid's rows and columns",
                lines: &lines,
                rgb: (200, 60, 20),
                width: 1.4,
            }],
            view: View {
                azimuth: 30.0,
                elevation: 25.0,
            },
        },
    )?;
    Ok(())
}

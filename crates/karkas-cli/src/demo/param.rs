//! Kuznetsov and Filatov (parameterization and bicubic interpolation): the table of Hausdorff errors of
//! frames laid along the lines of curvature or turned away from them (docs/methods.md §5), with
//! the paper's figures beside ours. Writes every frame's nodes (grid CSV) and interpolant
//! (OBJ mesh). A second example sweeps the turning angle (figures 3.2, 3.3): the error of
//! every frame against its angle, as a table, a CSV file and a chart.

use super::common::{write_text, write_viewer, Finding, Output};
use super::param_experiment::{
    angle_sweep as sweep_frames, frame_error, helix_experiment, seed_experiments, SeedExperiment,
    SeedSurface, SweepFrame, Turn,
};
use crate::output::samples::sample_surface;
use anyhow::{Context, Result};
use karkas::param::{BicubicEnds, BicubicSurface};
use karkas::{Point3, Surface};
use karkas_io::obj::write_surface_obj;
use karkas_io::scene::{write_scene_svg, Scene, SceneCurves, SceneMesh, View};
use karkas_io::write::write_grid_csv;
use rayon::prelude::*;
use std::fmt::Write as _;

/// Runs the seven rows of the paper's table and the extra helix frame into `out`.
pub fn run(out: &Output) -> Result<Vec<Finding>> {
    let mut findings = Vec::new();
    for row in seed_experiments()
        .into_iter()
        .chain(std::iter::once(helix_experiment()))
    {
        findings.push(experiment(out, &row)?);
    }
    // The same frames with natural ends (zero second derivative at the open ends of every
    // line): the end conditions the paper does not state, measured beside its own.
    let rows: Vec<SeedExperiment> = seed_experiments()
        .into_iter()
        .chain(std::iter::once(helix_experiment()))
        .collect();
    let natural = rows
        .par_iter()
        .map(|row| {
            row.run_with_ends(BicubicEnds::Natural)
                .with_context(|| format!("Kuznetsov and Filatov, {}, natural ends", row.label))
        })
        .collect::<Result<Vec<_>>>()?;
    for (row, outcome) in rows.iter().zip(natural) {
        let finding = Finding::new(
            format!("004 {}, natural ends", row.label),
            "two-sided Hausdorff error, 5 x 9 frame",
            outcome.error.distance,
        );
        findings.push(match row.paper_error {
            Some(p) => finding.paper(p),
            None => finding,
        });
    }
    Ok(findings)
}

/// A file name from a label: `cylinder, both axes turned 30 deg` -> `004-cylinder-both-axes-turned-30-deg`.
fn slug(label: &str) -> String {
    let words: Vec<&str> = label
        .split(|c: char| !c.is_ascii_alphanumeric())
        .filter(|w| !w.is_empty())
        .collect();
    format!("004-{}", words.join("-"))
}

fn experiment(out: &Output, row: &SeedExperiment) -> Result<Finding> {
    let outcome = row
        .run()
        .with_context(|| format!("Kuznetsov and Filatov, {}", row.label))?;
    let name = slug(row.label);
    write_grid_csv(&out.file(format!("{name}-nodes.csv")), &outcome.nodes)?;
    let (nu, nv) = (41, 121);
    let (_, _, mesh) = sample_surface(&outcome.surface, nu, nv);
    write_surface_obj(&out.file(format!("{name}.obj")), nu, nv, &mesh)?;
    let frame = frame_lines(&outcome.surface);
    write_viewer(
        out,
        &format!("{name}.html"),
        &format!(
            "Kuznetsov and Filatov: {}, bicubic interpolant of the 5 x 9 frame",
            row.label
        ),
        (nu, nv),
        &mesh,
        Some(outcome.nodes.clone()),
        vec![("parameter lines through the nodes", frame.clone())],
    )?;
    let title = format!(
        "Kuznetsov and Filatov: {}, bicubic interpolant of the 5 x 9 frame, Hausdorff error {:.4}",
        row.label, outcome.error.distance
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
                label: "parameter lines through the nodes",
                lines: &frame,
                rgb: (20, 60, 200),
                width: 1.4,
            }],
            view: View {
                azimuth: 30.0,
                elevation: 25.0,
            },
        },
    )?;
    Ok(Finding {
        example: format!("004 {}", row.label),
        measure: "two-sided Hausdorff error, 5 x 9 frame".into(),
        value: outcome.error.distance,
        paper: row.paper_error,
        detail: false,
    })
}

/// The interpolant's lines through the nodes: the parameter lines at every knot, sampled
/// densely so that they lie on the surface.
fn frame_lines(surface: &BicubicSurface<3>) -> Vec<Vec<Point3>> {
    const SAMPLES: usize = 97;
    let (du, dv) = (surface.domain_u(), surface.domain_v());
    let along_v = surface.knots_u().iter().map(|&u| {
        (0..SAMPLES)
            .map(|k| surface.eval(u, dv.uniform(k, SAMPLES)))
            .collect()
    });
    let along_u = surface.knots_v().iter().map(|&v| {
        (0..SAMPLES)
            .map(|k| surface.eval(du.uniform(k, SAMPLES), v))
            .collect()
    });
    along_v.chain(along_u).collect()
}

/// The angle sweep of figures 3.2 and 3.3: the error of the cylinder's and the hyperboloid's
/// frames against the turning angle, one family and both families turned (frames computed in
/// parallel, those of the table taken from its run), as detail rows of the report (example `004 sweep: <frame>`, naming the angle as
/// `N deg`, the paper's printed errors beside the frames it measured), a CSV file and a chart.
pub fn angle_sweep(out: &Output) -> Result<Vec<Finding>> {
    let frames = sweep_frames();
    let errors = frames
        .par_iter()
        .map(|f| {
            frame_error(f.surface, &f.net)
                .with_context(|| format!("Kuznetsov and Filatov, {}", f.label()))
        })
        .collect::<Result<Vec<f64>>>()?;
    let mut csv = String::from("surface,turned,degrees,karkas,paper\n");
    let mut findings = Vec::with_capacity(frames.len());
    for (frame, &error) in frames.iter().zip(&errors) {
        let paper = frame.paper_error.map_or(String::new(), |p| p.to_string());
        csv.push_str(&format!(
            "{},{},{},{error},{paper}\n",
            surface_name(frame.surface),
            turn_name(frame.turn),
            frame.degrees
        ));
        let finding = Finding::new(
            format!("004 sweep: {}", frame.label()),
            "two-sided Hausdorff error, 5 x 9 frame",
            error,
        );
        findings.push(
            match frame.paper_error {
                Some(p) => finding.paper(p),
                None => finding,
            }
            .detail(),
        );
    }
    write_text(&out.file("004-angle-sweep.csv"), &csv)?;
    write_text(
        &out.file("004-angle-sweep.svg"),
        &sweep_chart(&frames, &errors),
    )?;
    Ok(findings)
}

fn surface_name(surface: SeedSurface) -> &'static str {
    match surface {
        SeedSurface::Cylinder => "cylinder",
        SeedSurface::Hyperboloid => "hyperboloid",
    }
}

fn turn_name(turn: Turn) -> &'static str {
    match turn {
        Turn::None => "none",
        Turn::Both => "both",
        Turn::One => "one",
    }
}

/// The chart of the sweep: error against angle on a logarithmic axis (the errors span two
/// orders of magnitude), one polyline per surface and series (each starting at its surface's
/// 0 degree frame), the paper's printed errors as hollow squares.
fn sweep_chart(frames: &[SweepFrame], errors: &[f64]) -> String {
    let plot = SweepPlot::around(frames, errors);
    let mut svg = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{}\" height=\"{}\" \
         font-family=\"sans-serif\" font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" \
         fill=\"white\"/>\n<text x=\"{}\" y=\"22\" font-size=\"14\">Kuznetsov and \
         Filatov, figures 3.2 and 3.3: Hausdorff error of the 5 x 9 frame against the turning \
         angle</text>\n",
        SweepPlot::WIDTH,
        SweepPlot::HEIGHT,
        SweepPlot::LEFT
    );
    plot.axes(&mut svg);
    let series = [
        (
            SeedSurface::Cylinder,
            Turn::Both,
            "#1f5fbf",
            "cylinder, both families",
        ),
        (
            SeedSurface::Cylinder,
            Turn::One,
            "#7fa8e8",
            "cylinder, generator",
        ),
        (
            SeedSurface::Hyperboloid,
            Turn::Both,
            "#c0392b",
            "hyperboloid, both families",
        ),
        (
            SeedSurface::Hyperboloid,
            Turn::One,
            "#e8a07f",
            "hyperboloid, meridian",
        ),
    ];
    for (k, (surface, turn, colour, name)) in series.into_iter().enumerate() {
        plot.series(&mut svg, frames, errors, (surface, turn), colour);
        plot.legend_entry(&mut svg, k, colour, name);
    }
    plot.zero_degree_paper_points(&mut svg, frames, errors);
    let x1 = plot.x(90.0);
    let _ = writeln!(
        svg,
        "<rect x=\"{}\" y=\"{}\" width=\"8\" height=\"8\" stroke=\"black\" fill=\"none\"/>\
         <text x=\"{}\" y=\"{}\">the paper's printed error</text>\n</svg>",
        x1 + 28.0,
        SweepPlot::TOP + 80.0 - 4.0,
        x1 + 50.0,
        SweepPlot::TOP + 84.0
    );
    svg
}

/// The sweep chart's frame: angle across, whole decades of the error up.
struct SweepPlot {
    decade_low: f64,
    decade_high: f64,
}

impl SweepPlot {
    const WIDTH: f64 = 760.0;
    const HEIGHT: f64 = 440.0;
    const LEFT: f64 = 70.0;
    const RIGHT: f64 = 230.0;
    const TOP: f64 = 40.0;
    const BOTTOM: f64 = 50.0;

    /// Whole decades around the errors and the paper's figures.
    fn around(frames: &[SweepFrame], errors: &[f64]) -> Self {
        let (low, high) = errors
            .iter()
            .chain(frames.iter().filter_map(|f| f.paper_error.as_ref()))
            .filter(|e| **e > 0.0 && e.is_finite())
            .fold((f64::INFINITY, 0.0f64), |(lo, hi), &e| {
                (lo.min(e), hi.max(e))
            });
        let (decade_low, decade_high) = if low <= high {
            let a = low.log10().floor();
            (a, high.log10().ceil().max(a + 1.0))
        } else {
            (-3.0, 0.0)
        };
        SweepPlot {
            decade_low,
            decade_high,
        }
    }

    fn x(&self, deg: f64) -> f64 {
        Self::LEFT + (Self::WIDTH - Self::LEFT - Self::RIGHT) * deg / 90.0
    }

    fn y(&self, e: f64) -> f64 {
        let t = (e.max(1e-300).log10() - self.decade_low) / (self.decade_high - self.decade_low);
        Self::HEIGHT - Self::BOTTOM - (Self::HEIGHT - Self::TOP - Self::BOTTOM) * t
    }

    /// Axes, ticks every 15 degrees and at 1, 2 and 5 of every decade of the error.
    fn axes(&self, svg: &mut String) {
        let (x0, x1) = (self.x(0.0), self.x(90.0));
        let (y0, y1) = (
            self.y(10f64.powf(self.decade_low)),
            self.y(10f64.powf(self.decade_high)),
        );
        let _ = writeln!(
            svg,
            "<path d=\"M{x0},{y1} L{x0},{y0} L{x1},{y0}\" stroke=\"black\" fill=\"none\"/>"
        );
        for deg in (0..=90).step_by(15) {
            let px = self.x(f64::from(deg));
            let _ = writeln!(
                svg,
                "<line x1=\"{px}\" y1=\"{y0}\" x2=\"{px}\" y2=\"{}\" stroke=\"black\"/>\
                 <text x=\"{px}\" y=\"{}\" text-anchor=\"middle\">{deg}</text>",
                y0 + 5.0,
                y0 + 18.0
            );
        }
        let mut decade = self.decade_low;
        while decade <= self.decade_high {
            for mantissa in [1.0, 2.0, 5.0] {
                let e = mantissa * 10f64.powf(decade);
                if decade == self.decade_high && mantissa > 1.0 {
                    break;
                }
                let py = self.y(e);
                let digits = (-decade).max(0.0) as usize;
                let _ = writeln!(
                    svg,
                    "<line x1=\"{}\" y1=\"{py}\" x2=\"{x0}\" y2=\"{py}\" stroke=\"black\"/>\
                     <text x=\"{}\" y=\"{}\" text-anchor=\"end\">{e:.digits$}</text>",
                    x0 - 5.0,
                    x0 - 8.0,
                    py + 4.0,
                );
            }
            decade += 1.0;
        }
        let _ = writeln!(
            svg,
            "<text x=\"{}\" y=\"{}\" text-anchor=\"middle\">angle to the lines of curvature, \
             degrees</text>\n<text x=\"16\" y=\"{}\" transform=\"rotate(-90 16 {})\" \
             text-anchor=\"middle\">Hausdorff error (logarithmic scale)</text>",
            0.5 * (x0 + x1),
            Self::HEIGHT - 10.0,
            0.5 * (y0 + y1),
            0.5 * (y0 + y1)
        );
    }

    /// One surface's series: its polyline from its 0 degree frame, and the paper's printed
    /// errors as hollow squares.
    fn series(
        &self,
        svg: &mut String,
        frames: &[SweepFrame],
        errors: &[f64],
        (surface, turn): (SeedSurface, Turn),
        colour: &str,
    ) {
        let points: Vec<(f64, f64)> = frames
            .iter()
            .zip(errors)
            .filter(|(f, _)| f.surface == surface && (f.turn == turn || f.turn == Turn::None))
            .map(|(f, &e)| (self.x(f64::from(f.degrees)), self.y(e)))
            .collect();
        let path: Vec<String> = points
            .iter()
            .map(|(a, b)| format!("{a:.1},{b:.1}"))
            .collect();
        let _ = writeln!(
            svg,
            "<polyline points=\"{}\" stroke=\"{colour}\" stroke-width=\"2\" fill=\"none\"/>",
            path.join(" ")
        );
        for (a, b) in &points {
            let _ = writeln!(
                svg,
                "<circle cx=\"{a:.1}\" cy=\"{b:.1}\" r=\"3\" fill=\"{colour}\"/>"
            );
        }
        for f in frames
            .iter()
            .filter(|f| f.surface == surface && f.turn == turn)
        {
            if let Some(p) = f.paper_error {
                let (a, b) = (self.x(f64::from(f.degrees)), self.y(p));
                let _ = writeln!(
                    svg,
                    "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"8\" height=\"8\" stroke=\"{colour}\" \
                     stroke-width=\"1.5\" fill=\"none\"/>",
                    a - 4.0,
                    b - 4.0
                );
            }
        }
    }

    /// Line `k` of the legend.
    fn legend_entry(&self, svg: &mut String, k: usize, colour: &str, name: &str) {
        let x1 = self.x(90.0);
        let ly = Self::TOP + 20.0 * k as f64;
        let _ = writeln!(
            svg,
            "<line x1=\"{}\" y1=\"{ly}\" x2=\"{}\" y2=\"{ly}\" stroke=\"{colour}\" \
             stroke-width=\"2\"/><text x=\"{}\" y=\"{}\">{name}</text>",
            x1 + 20.0,
            x1 + 45.0,
            x1 + 50.0,
            ly + 4.0
        );
    }

    /// The 0 degree frames' paper points (shared by both series of a surface).
    fn zero_degree_paper_points(&self, svg: &mut String, frames: &[SweepFrame], errors: &[f64]) {
        for (f, _) in frames
            .iter()
            .zip(errors)
            .filter(|(f, _)| f.turn == Turn::None)
        {
            if let Some(p) = f.paper_error {
                let _ = writeln!(
                    svg,
                    "<rect x=\"{:.1}\" y=\"{:.1}\" width=\"8\" height=\"8\" stroke=\"black\" \
                     stroke-width=\"1.5\" fill=\"none\"/>",
                    self.x(0.0) - 4.0,
                    self.y(p) - 4.0
                );
            }
        }
    }
}

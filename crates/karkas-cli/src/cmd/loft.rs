//! `karkas loft`: a wing (fin, blade) lofted through the sections of a sections table, or a
//! wind-turbine blade through the airfoils of a windIO turbine file (docs/methods.md §7).

use crate::args::{CadOptions, CapOption, GridSamples, MeshOutput};
use crate::output::cad::write_cad_faces;
use crate::output::console::{note, record_all};
use crate::output::formats::EXACT_SURFACE_FORMATS;
use crate::output::surface::{write_capped_mesh, write_sampled_surface};
use crate::output::target::{output_format, shown};
use anyhow::{anyhow, bail, Context, Result};
use clap::Args;
use karkas::bspline::{BSplineCurve, BSplineSurface, ToBSplineSurface};
use karkas::loft::{
    Loft, LoftOptions, LoftSection, Profile, SectionFrame, SpanRule, WingPlacement,
    DEFAULT_TOLERANCE,
};
use karkas::{Curve, Grid, Point2, Point3, Surface};
use karkas_io::cad::{iges, step, CadEntity};
use karkas_io::offsets_table::read_offsets_table;
use karkas_io::points::{read_curve_points, CurvePoints};
use karkas_io::sections_table::{read_sections_table, SectionRow};
use karkas_io::windio::read_windio_blade;
use karkas_io::OutputFormat;
use serde::Serialize;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `karkas loft`.
#[derive(Debug, Args)]
#[command(mut_arg("samples", |a| a.value_name("NU,NV").help(
    "Samples NU,NV along the span and along the sections, uniform in the parameters, ends \
     included [default: 16 per section along the span, 200 along the sections]"
)))]
pub struct LoftArgs {
    /// The sections table: CSV with the header file,x,y,z,chord,twist[,dihedral], one row per
    /// section in span order; file is a profile in unit chord (airfoil .dat or x,y CSV)
    /// relative to the table's folder, x,y,z its leading edge, twist and dihedral in degrees.
    #[arg(
        required_unless_present_any = ["windio", "offsets"],
        conflicts_with_all = ["windio", "offsets"]
    )]
    pub table: Option<PathBuf>,
    /// Loft the blade of a windIO (version 2) turbine file instead of a sections table: one
    /// section per entry of components.blade.outer_shape.airfoils, at its spanwise_position,
    /// placed as windIO places it (chord, twist, section_offset_y and _x, normal to the
    /// reference axis, in the file's units), and between airfoils through a section at every
    /// grid position of the distributions (the neighbouring airfoils blended linearly). Stations
    /// are the position times the length of the reference axis; --json lists the airfoils' as
    /// airfoil_stations.
    #[arg(long, value_name = "TURBINE.yaml", conflicts_with = "offsets")]
    pub windio: Option<PathBuf>,
    /// Loft a hull from a ship's table of offsets instead: CSV with the header
    /// station,waterline,half_breadth, the rows of a station together from the keel up,
    /// stations increasing; each station's section lies in its plane x = station with y the
    /// half-breadth and z the waterline: the half hull y >= 0. The tolerance is a share of the
    /// beam (twice the largest half-breadth).
    #[arg(long, value_name = "OFFSETS.csv")]
    pub offsets: Option<PathBuf>,
    /// With --offsets: the whole hull, the half hull and its mirror image about the centre
    /// plane y = 0 as one surface. Its sections run from the port deck edge (v = 0) down to the
    /// keel (v = 0.5, where the sides may meet at an angle: a knot of full multiplicity) and up
    /// to the starboard deck edge (v = 1); a keel at half-breadth 0 is shared by both sides, a
    /// flat bottom (half-breadth above 0 at the lowest waterline) is the straight line between
    /// the sides over v in [0.45, 0.55].
    #[arg(long, requires = "offsets")]
    pub mirror: bool,
    /// How the surface runs between sections: linear (ruled, C^0 at the sections), monotone
    /// (shape-preserving cubic Hermite, C^1, no overshoot) or spline (not-a-knot cubic, C^2,
    /// may overshoot).
    #[arg(long, value_name = "RULE", default_value = "monotone", value_parser = parse_rule)]
    span: SpanRule,
    /// The largest distance of a section's points from the surface, as a share of its chord.
    #[arg(long, value_name = "T", default_value_t = DEFAULT_TOLERANCE)]
    tolerance: f64,
    /// Span stations (distance from the first leading edge along the leading edges projected
    /// onto the y-z plane) at which to write the surface's sections into --sections-out.
    #[arg(long, value_name = "S1,S2,...", value_parser = parse_stations, requires = "sections_out")]
    sections_at: Option<Stations>,
    /// Where the sections of --sections-at go: .csv (rows curve,x,y,z, 200 points each), or
    /// the exact B-spline curves as .step/.stp or .iges/.igs.
    #[arg(long, value_name = "FILE", requires = "sections_at")]
    sections_out: Option<PathBuf>,
    #[command(flatten)]
    samples: GridSamples,
    #[command(flatten)]
    mesh: MeshOutput,
    #[command(flatten)]
    cap: CapOption,
    #[command(flatten)]
    cad: CadOptions,
    /// Print the summary as one JSON object on standard output.
    #[arg(long)]
    json: bool,
    /// Output file: the exact B-spline surface as .step/.stp or .iges/.igs, a mesh (.obj .stl
    /// .ply .vtk .vts .glb), a picture (.svg .png), a 3-D viewer page (.html) or the samples
    /// (.csv, u,v,x,y,z).
    #[arg(short, long)]
    output: PathBuf,
}

/// The figures of a loft: the summary line and `--json`.
#[derive(Debug, Serialize)]
struct LoftSummary {
    sections: usize,
    span: &'static str,
    control_points: [usize; 2],
    max_deviation: f64,
    max_relative_deviation: f64,
    tolerance: f64,
    tolerance_met: bool,
    stations: Vec<f64>,
    /// The stations of a windIO blade's airfoils (the other stations are its grid positions).
    #[serde(skip_serializing_if = "Option::is_none")]
    airfoil_stations: Option<Vec<f64>>,
    time_ms: f64,
}

/// The sections whose profiles karkas reads from the table's rows.
struct Sections {
    rows: Vec<SectionRow>,
    profiles: Vec<Vec<Point2>>,
}

/// A loft, the file it came from, the time it took (milliseconds) and, for a windIO blade, the
/// stations of its airfoils.
type Built = (Loft, PathBuf, f64, Option<Vec<f64>>);

/// The loft of the table's sections or of a windIO blade.
fn build_loft(args: &LoftArgs, options: &LoftOptions) -> Result<Built> {
    if args.mirror && args.offsets.is_none() {
        bail!("--mirror mirrors a half hull: give it with --offsets OFFSETS.csv");
    }
    if let Some(path) = &args.windio {
        let blade = read_windio_blade(path)?;
        let profiles: Vec<Vec<Point2>> = blade.sections.iter().map(|s| s.profile.clone()).collect();
        let positions: Vec<f64> = blade.sections.iter().map(|s| s.position).collect();
        let start = Instant::now();
        let loft = Loft::blade(&profiles, &positions, &blade.shape, options).map_err(|e| {
            let name = karkas_io::input::display_name(path);
            match e {
                karkas::Error::LoftSection { section, reason }
                    if section < blade.sections.len() =>
                {
                    let s = &blade.sections[section];
                    anyhow!(
                        "{}: airfoil {} ('{}' at spanwise_position {}): {reason}",
                        name.display(),
                        section + 1,
                        s.airfoil,
                        s.position
                    )
                }
                other => anyhow!("{}: {other}", name.display()),
            }
        })?;
        let time_ms = start.elapsed().as_secs_f64() * 1e3;
        let length = blade.shape.axis_length();
        let airfoils = positions.iter().map(|s| s * length).collect();
        return Ok((loft, path.clone(), time_ms, Some(airfoils)));
    }
    if let Some(path) = &args.offsets {
        let start = Instant::now();
        let mut loft = offsets_loft(path, options)?;
        if args.mirror {
            loft = loft.mirrored(1)?;
        }
        let time_ms = start.elapsed().as_secs_f64() * 1e3;
        return Ok((loft, path.clone(), time_ms, None));
    }
    let Some(table) = args.table.as_deref() else {
        bail!("give a sections table, --windio or --offsets");
    };
    let sections = read_sections(table)?;
    let placements: Vec<WingPlacement> = sections.rows.iter().map(SectionRow::placement).collect();
    let start = Instant::now();
    let loft = Loft::wing(&sections.profiles, &placements, options)
        .map_err(|e| section_error(table, &sections.rows, e))?;
    let time_ms = start.elapsed().as_secs_f64() * 1e3;
    Ok((loft, table.to_path_buf(), time_ms, None))
}

/// Runs `karkas loft`.
pub fn run(args: &LoftArgs) -> Result<()> {
    let format = output_format(&args.output, &EXACT_SURFACE_FORMATS)?;
    args.samples.check()?;
    args.mesh.check(format)?;
    args.cap.check(&[format], None)?;
    args.cad.check(&[format])?;
    if !(args.tolerance.is_finite() && args.tolerance > 0.0) {
        bail!("--tolerance {}: must be a positive number", args.tolerance);
    }
    let sections_format = match &args.sections_out {
        Some(path) => Some(OutputFormat::from_path(
            path,
            &[OutputFormat::Csv, OutputFormat::Step, OutputFormat::Iges],
        )?),
        None => None,
    };
    let options = LoftOptions {
        rule: args.span,
        tolerance: args.tolerance,
    };
    let (loft, source, time_ms, airfoil_stations) = build_loft(args, &options)?;
    let table = source.as_path();
    let cuts = match &args.sections_at {
        Some(at) => Some(cut_sections(&loft, &at.0)?),
        None => None,
    };
    // Everything is checked: write.
    if let (Some(cuts), Some(path), Some(f)) = (&cuts, &args.sections_out, sections_format) {
        write_sections(path, f, cuts)?;
    }
    let blunt = match args.cap.cap {
        true => trailing_edges(&loft, args.offsets.is_some())?,
        false => false,
    };
    write_surface(args, &loft, format, table, blunt)?;
    report(args, &loft, airfoil_stations, time_ms)?;
    Ok(())
}

/// Writes the loft to `--output` in `format`: its B-spline faces (with the trailing-edge
/// strip when capped and `blunt`) to a CAD file, else a sampled (capped) mesh.
fn write_surface(
    args: &LoftArgs,
    loft: &Loft,
    format: OutputFormat,
    table: &Path,
    blunt: bool,
) -> Result<()> {
    let stations = loft.stations();
    let title = format!("loft of {} sections ({})", stations.len(), args.span.name());
    if format.is_cad() {
        let bspline = loft
            .to_bspline()
            .with_context(|| table.display().to_string())?;
        let strip = match blunt {
            true => vec![trailing_edge_strip(&bspline)?],
            false => Vec::new(),
        };
        write_cad_faces(
            &bspline,
            &strip,
            format,
            &args.output,
            &args.cad,
            table.display(),
            args.cap.cap,
        )?;
    } else {
        let samples = args
            .samples
            .samples
            .unwrap_or((16 * (stations.len() - 1) + 1, 200));
        if args.cap.cap {
            write_capped_mesh(
                loft,
                samples,
                format,
                &args.output,
                &args.mesh.options(false),
                blunt,
            )?;
        } else {
            write_sampled_surface(
                loft,
                samples,
                format,
                &args.output,
                &title,
                None,
                &args.mesh.options(false),
            )?;
        }
    }
    Ok(())
}

/// Reports the loft on stderr, in the run record and (with `--json`) on stdout.
fn report(
    args: &LoftArgs,
    loft: &Loft,
    airfoil_stations: Option<Vec<f64>>,
    time_ms: f64,
) -> Result<()> {
    let stations = loft.stations().to_vec();
    let (nu, nv) = loft.control_counts();
    let summary = LoftSummary {
        sections: stations.len(),
        span: args.span.name(),
        control_points: [nu, nv],
        max_deviation: loft.deviations().iter().fold(0.0, |m: f64, &d| m.max(d)),
        max_relative_deviation: loft.max_relative_deviation(),
        tolerance: args.tolerance,
        tolerance_met: loft.tolerance_met(),
        stations,
        airfoil_stations,
        time_ms,
    };
    note(format!(
        "karkas: loft of {} sections ({}): {nu} x {nv} control points, largest section \
         deviation {:.3e} of the chord (tolerance {:e}{}), {:.1} ms",
        summary.sections,
        summary.span,
        summary.max_relative_deviation,
        summary.tolerance,
        if summary.tolerance_met {
            ""
        } else {
            ", NOT met"
        },
        summary.time_ms
    ));
    record_all(serde_json::to_value(&summary)?);
    if args.json && !crate::output::console::is_capturing() {
        println!("{}", serde_json::to_string(&summary)?);
    }
    Ok(())
}

/// The half hull of the table of offsets at `path`.
fn offsets_loft(path: &Path, options: &LoftOptions) -> Result<Loft> {
    let table = read_offsets_table(path)?;
    let name = karkas_io::input::display_name(path);
    let beam = 2.0
        * table
            .iter()
            .flat_map(|s| s.offsets.iter().map(|p| p[0]))
            .fold(0.0f64, f64::max);
    if beam <= 0.0 {
        bail!("{}: every half-breadth is 0: no hull", name.display());
    }
    let at = |k: usize| {
        format!(
            "{}: station {} (line {})",
            name.display(),
            table[k].station,
            table[k].line
        )
    };
    let sections = table
        .iter()
        .enumerate()
        .map(|(k, s)| {
            let profile =
                Profile::open(&s.offsets).map_err(|e| anyhow!("{}: {}", at(k), loft_reason(e)))?;
            Ok(LoftSection {
                profile,
                frame: SectionFrame {
                    origin: Point3::new([s.station, 0.0, 0.0]),
                    x_axis: Point3::new([0.0, 1.0, 0.0]),
                    y_axis: Point3::new([0.0, 0.0, 1.0]),
                },
                station: s.station,
                scale: beam,
            })
        })
        .collect::<Result<Vec<_>>>()?;
    Loft::new(&sections, options).map_err(|e| match e {
        karkas::Error::LoftSection { section, reason } if section < table.len() => {
            anyhow!("{}: {reason}", at(section))
        }
        other => anyhow!("{}: {other}", name.display()),
    })
}

/// The reason of a section's error, without the section number the library gives it.
fn loft_reason(e: karkas::Error) -> String {
    match e {
        karkas::Error::LoftSection { reason, .. } => reason,
        other => other.to_string(),
    }
}

/// Reads the table and every row's profile, naming the row and the file on error.
fn read_sections(table: &Path) -> Result<Sections> {
    let rows = read_sections_table(table)?;
    let mut profiles = Vec::with_capacity(rows.len());
    for row in &rows {
        let at = || row_name(table, row);
        let points = read_curve_points(&row.path).map_err(|e| anyhow!("{}: {e}", at()))?;
        match points {
            CurvePoints::Planar(p) => profiles.push(p),
            CurvePoints::Spatial(_) => bail!(
                "{}: a profile has two coordinates (x, y in unit chord), not three",
                at()
            ),
        }
    }
    Ok(Sections { rows, profiles })
}

/// `TABLE: row LINE (FILE)`.
fn row_name(table: &Path, row: &SectionRow) -> String {
    format!(
        "{}: row {} ({})",
        karkas_io::input::display_name(table).display(),
        row.line,
        row.file
    )
}

/// The library's error about a section, as the row and file of the table.
fn section_error(table: &Path, rows: &[SectionRow], e: karkas::Error) -> anyhow::Error {
    match e {
        karkas::Error::LoftSection { section, reason } if section < rows.len() => {
            anyhow!("{}: {reason}", row_name(table, &rows[section]))
        }
        other => anyhow!(
            "{}: {other}",
            karkas_io::input::display_name(table).display()
        ),
    }
}

/// The surface's sections at the span stations `at`, each inside the span.
fn cut_sections(loft: &Loft, at: &[f64]) -> Result<Vec<BSplineCurve<3>>> {
    let stations = loft.stations();
    let (first, last) = (stations[0], stations[stations.len() - 1]);
    at.iter()
        .map(|&s| {
            if !(first..=last).contains(&s) {
                bail!("--sections-at {s}: outside the span, which runs from {first} to {last}");
            }
            Ok(loft.section_at(s))
        })
        .collect()
}

/// Writes the sections as CSV rows `curve,x,y,z` (200 points each) or exact STEP or IGES.
fn write_sections(path: &Path, format: OutputFormat, cuts: &[BSplineCurve<3>]) -> Result<()> {
    match format {
        OutputFormat::Step | OutputFormat::Iges => {
            let entities: Vec<CadEntity> = cuts.iter().map(CadEntity::Curve).collect();
            if format == OutputFormat::Step {
                step::write_step(path, &entities)?;
            } else {
                iges::write_iges(path, &entities)?;
            }
        }
        _ => {
            let n = 200;
            karkas_io::write::write_atomic(path, |w| {
                writeln!(w, "curve,x,y,z")?;
                for (k, c) in cuts.iter().enumerate() {
                    for j in 0..n {
                        let p = c.eval(j as f64 / (n - 1) as f64);
                        writeln!(w, "{k},{},{},{}", p[0], p[1], p[2])?;
                    }
                }
                Ok(())
            })
            .with_context(|| shown(path).display().to_string())?;
        }
    }
    note(format!(
        "karkas: wrote {} ({} sections)",
        shown(path).display(),
        cuts.len()
    ));
    Ok(())
}

/// Parses `--span`.
fn parse_rule(text: &str) -> Result<SpanRule, String> {
    text.parse().map_err(|e: karkas::Error| e.to_string())
}

/// The span stations of `--sections-at`.
#[derive(Clone, Debug)]
struct Stations(Vec<f64>);

/// Parses `--sections-at`: finite numbers separated by commas.
fn parse_stations(text: &str) -> Result<Stations, String> {
    text.split(',')
        .map(|s| {
            let v: f64 = s
                .trim()
                .parse()
                .map_err(|_| format!("'{}' is not a number", s.trim()))?;
            if v.is_finite() {
                Ok(v)
            } else {
                Err(format!("'{}' is not a finite number", s.trim()))
            }
        })
        .collect::<Result<Vec<f64>, String>>()
        .map(Stations)
}

/// Whether `--cap` needs the flat trailing-edge face: true where every section's trailing edge
/// is blunt, false where every one is sharp (the edge closes by itself); a wing blunt at some
/// stations and sharp at others cannot be capped by planar faces, an error naming `--cap`.
/// A hull's (`hull`) sections run from deck edge to deck edge: its "trailing edge" is the
/// deck, open where the deck has a breadth and closed where both edges meet (a pointed bow or
/// stern), and the message says so.
fn trailing_edges(loft: &Loft, hull: bool) -> Result<bool> {
    let gaps = trailing_edge_gaps(loft);
    if gaps.iter().all(|&blunt| blunt) {
        return Ok(true);
    }
    if gaps.iter().all(|&blunt| !blunt) {
        return Ok(false);
    }
    if hull {
        bail!(
            "--cap: the deck edges meet at some stations (a half-breadth of 0 at the top \
             waterline: a pointed bow or stern) and are apart at others; planar caps close a \
             hull whose deck has a breadth at every station (a transom at each end) or none"
        )
    }
    bail!(
        "--cap: the trailing edge is blunt at some sections and sharp at others; a closed \
         solid needs every section sharp (first point = last) or every one blunt"
    )
}

/// For 65 stations evenly along the span, whether the trailing edge is blunt there: the
/// surface's edges `v = 0` (upper trailing edge) and `v = 1` (lower) more than 1e-9 of the
/// wing's size apart.
fn trailing_edge_gaps(loft: &Loft) -> Vec<bool> {
    let (span, section) = (loft.domain_u(), loft.domain_v());
    let (first, last) = (span.start, span.end);
    let (upper, lower) = (section.start, section.end);
    let size = loft
        .eval(first, upper)
        .distance(loft.eval(last, upper))
        .max(
            loft.eval(first, upper)
                .distance(loft.eval(first, 0.5 * (upper + lower))),
        );
    (0..=64)
        .map(|k| {
            let u = first + (last - first) * k as f64 / 64.0;
            loft.eval(u, upper).distance(loft.eval(u, lower)) > 1e-9 * size
        })
        .collect()
}

/// The flat face of a blunt trailing edge: the ruled surface from the lower trailing-edge line
/// (`v = 1` of `wing`) to the upper one (`v = 0`), on `wing`'s span knots and with its
/// trailing-edge control points, so that the two faces share their edges exactly and `--cap`
/// closes the root and the tip by planar faces (section plus edge segment).
fn trailing_edge_strip(wing: &BSplineSurface<3>) -> Result<BSplineSurface<3>> {
    let net = wing.control_points();
    let last = net.cols() - 1;
    let points = (0..net.rows())
        .flat_map(|i| [*net.get(i, last), *net.get(i, 0)])
        .collect();
    Ok(BSplineSurface::new(
        (wing.degree_u(), wing.knots_u().to_vec()),
        (1, vec![0.0, 0.0, 1.0, 1.0]),
        Grid::from_row_major(net.rows(), 2, points)?,
    )?)
}

//! `karkas surface coons`: Coons, Gordon and composite Coons surfaces through a network of
//! curves given as point lists (Chashnikov, docs/methods.md §2).
//!
//! The curves are interpolated and parameterized by `karkas::coons::PointNetwork` (not-a-knot
//! cubic splines in the point-index parameter, warped so that the crossings sit at common
//! node values in `[0, 1]`); the surface's parameters `u`, `v` are those node values.

use crate::args::{CadOptions, CapOption, GridSamples, MeshOutput, MeshTolerance};
use crate::input::one_standard_input;
use crate::output::console::note;
use crate::output::formats::EXACT_SURFACE_FORMATS;
use crate::output::overwrite::ensure_distinct;
use crate::output::samples::default_surface_samples;
use crate::output::surface::{write_any_surface, SurfaceWriting};
use crate::output::target::output_formats;
use anyhow::{anyhow, bail, Context, Result};
use clap::{Args, ValueEnum};
use karkas::coons::{
    Compatibility, CoonsKind, CoonsSurface, CrossDerivatives, CurveFit, PointNetwork, Repair,
    CROSSING_TOLERANCE, POINT_NETWORK_TOLERANCE,
};
use karkas::Error;
use karkas_io::grid::read_grid;
use karkas_io::network::{read_curve_family, CurveFamily};
use std::path::{Path, PathBuf};

/// Which surface to build.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Kind {
    /// Bilinear Coons: two u-curves and two v-curves.
    Bilinear,
    /// Bicubic Coons: two u-curves and two v-curves and the cross-derivatives along them.
    Bicubic,
    /// Gordon surface with Lagrange blending.
    Gordon,
    /// Gordon surface with cubic-spline blending (not-a-knot; periodic in a closed direction).
    GordonSpline,
    /// Composite Coons surface (C^1, piecewise bicubic) with cross-derivative curves.
    Composite,
}

/// Arguments of `karkas surface coons`.
#[derive(Debug, Args)]
#[command(mut_arg("samples", |a| a.help(
    "Samples NU,NV, uniform over the domain, ends included [default: 4 per point of the \
     longest curve in each direction, at least 50]"
)))]
pub struct SurfaceCoonsArgs {
    /// The surface to build.
    #[arg(long, value_enum)]
    kind: Kind,
    /// The curves running along u (the lines v = const), in the order of increasing v: CSV
    /// with header curve,x,y,z (curves numbered from 0, each curve's points in order; a curve
    /// whose last point repeats its first is closed).
    #[arg(long, value_name = "U.csv")]
    u_curves: PathBuf,
    /// The curves running along v (the lines u = const), in the order of increasing u; same
    /// format. Every v-curve must share exactly one point with every u-curve.
    #[arg(long, value_name = "V.csv")]
    v_curves: PathBuf,
    /// Cross-derivatives dS/dv along the u-curves (bicubic, composite): same format and
    /// point counts as --u-curves, one vector per point, per unit of the surface parameters
    /// [default: built from the twists, see --twists].
    #[arg(long, value_name = "DU.csv")]
    u_derivs: Option<PathBuf>,
    /// Cross-derivatives dS/du along the v-curves (bicubic, composite): same format and
    /// point counts as --v-curves [default: built from the twists].
    #[arg(long, value_name = "DV.csv")]
    v_derivs: Option<PathBuf>,
    /// Twist vectors d2S/dudv at the crossings (bicubic, composite), per unit of the surface
    /// parameters: CSV with header i,j,x,y,z, one row per crossing of v-curve i with u-curve
    /// j, rows in any order. The cross-derivatives are then the cubic Hermite curves of the
    /// curves' tangents and these twists at the crossings (Chashnikov's A_i, B_j) [default:
    /// twists by the spline-of-derivatives rule].
    #[arg(long, value_name = "TWISTS.csv", conflicts_with_all = ["u_derivs", "v_derivs"])]
    twists: Option<PathBuf>,
    /// The tolerance of the compatibility conditions (8)/(11), relative to the model size
    /// (the diagonal of the bounding box of the curves), per node spacing for each
    /// derivative in a condition: data further apart are refused [default: 1e-4].
    #[arg(long, value_name = "T")]
    tolerance: Option<f64>,
    /// Make incompatible data compatible instead of refusing it: both sides of every
    /// condition (the curves' crossings, the cross-derivatives against the curves' tangents,
    /// the twists) are moved to their mean, and the largest correction is reported.
    #[arg(long, conflicts_with = "tolerance")]
    repair: bool,
    /// Close the surface in u with a crease (a C^0 seam, e.g. a wing's sharp trailing edge):
    /// the closed u-curves (last point repeating the first) are interpolated as open curves
    /// from their crossing with v-curve 0 round to it again, and v-curve 0 is used again at
    /// u = 1. Needs closed u-curves; not with --u-derivs, --v-derivs or --twists.
    #[arg(long)]
    crease_u: bool,
    /// Close the surface in v with a crease, as --crease-u: the closed v-curves are
    /// interpolated as open curves from u-curve 0 round to it again. Needs closed v-curves.
    #[arg(long)]
    crease_v: bool,
    #[command(flatten)]
    samples: GridSamples,
    #[command(flatten)]
    mesh: MeshOutput,
    #[command(flatten)]
    cap: CapOption,
    #[command(flatten)]
    mesh_tolerance: MeshTolerance,
    /// Output file: .csv (u,v,x,y,z), a mesh (.obj .stl .ply .vtk .vts .glb), a picture
    /// (.svg .png) a 3-D viewer page (.html), or the
    /// exact B-spline surface as .step/.stp or .iges/.igs. Repeat -o for several outputs of
    /// one surface.
    #[arg(short, long, required = true)]
    output: Vec<PathBuf>,
    #[command(flatten)]
    cad: CadOptions,
}

/// Runs `karkas surface coons`.
pub fn run(args: &SurfaceCoonsArgs) -> Result<()> {
    let formats = output_formats(&args.output, &EXACT_SURFACE_FORMATS)?;
    let options = (&args.samples, &args.mesh, &args.mesh_tolerance);
    let writing = SurfaceWriting::checked(&formats, options, &args.cap, &args.cad)?;
    let files = NetworkFiles {
        u_curves: &args.u_curves,
        v_curves: &args.v_curves,
        u_derivs: args.u_derivs.as_deref(),
        v_derivs: args.v_derivs.as_deref(),
        twists: args.twists.as_deref(),
        tolerance: args.tolerance,
        repair: args.repair,
        creases: (args.crease_u, args.crease_v),
    };
    let (surface, u_family, v_family) = network_surface(args.kind, &files, &args.output)?;
    let longest = |f: &CurveFamily| f.curves.iter().map(Vec::len).max().unwrap_or(0);
    let default = (
        default_surface_samples(longest(&u_family)),
        default_surface_samples(longest(&v_family)),
    );
    let kind = args.kind.to_possible_value();
    let title = format!(
        "{} Coons surface, {} u-curves x {} v-curves",
        kind.as_ref().map_or("", |k| k.get_name()),
        u_family.curves.len(),
        v_family.curves.len()
    );
    let what = format!("{}, {}", args.u_curves.display(), args.v_curves.display());
    for (output, &format) in args.output.iter().zip(&formats) {
        let drawn = (default, title.as_str(), None);
        write_any_surface(&surface, format, output, &writing, drawn, &what)?;
    }
    Ok(())
}

/// The files of a curve network (`--u-curves`, `--v-curves`, the optional `--u-derivs`,
/// `--v-derivs` and `--twists`) and how its compatibility is settled (`--tolerance`,
/// `--repair`).
pub(crate) struct NetworkFiles<'a> {
    pub u_curves: &'a Path,
    pub v_curves: &'a Path,
    pub u_derivs: Option<&'a Path>,
    pub v_derivs: Option<&'a Path>,
    pub twists: Option<&'a Path>,
    pub tolerance: Option<f64>,
    pub repair: bool,
    /// `--crease-u`, `--crease-v`.
    pub creases: (bool, bool),
}

/// Reads the network of `files` (none of which may be `output`) and builds its surface of
/// `kind`; also returns the u- and v-curve families as read. Errors name the options, files
/// and lines at fault.
pub(crate) fn network_surface(
    kind: Kind,
    files: &NetworkFiles<'_>,
    outputs: &[PathBuf],
) -> Result<(CoonsSurface<3>, CurveFamily, CurveFamily)> {
    files.check(kind, outputs)?;
    let u_family = read_family(files.u_curves)?;
    let v_family = read_family(files.v_curves)?;
    check_creases(files, &u_family, &v_family)?;
    let places = Files {
        u: files.u_curves,
        v: files.v_curves,
        u_family: &u_family,
        v_family: &v_family,
    };
    let network = PointNetwork::with_creases(
        &v_family.curves,
        &u_family.curves,
        CurveFit::CubicSpline,
        CROSSING_TOLERANCE,
        files.creases,
    )
    .map_err(|e| places.explain(e))?;
    let cross = files.cross_derivatives(&network, &u_family, &v_family)?;
    if kind == Kind::Gordon {
        warn_lagrange_seam(&network);
    }
    if kind == Kind::Bicubic && files.u_derivs.is_none() {
        warn_bicubic_from_curves(files.twists.is_some());
    }
    let compatibility = if files.repair {
        Compatibility::Repair
    } else {
        Compatibility::Check(files.tolerance.unwrap_or(POINT_NETWORK_TOLERANCE))
    };
    let surface = kind
        .to_library()
        .build(network.network(), cross.as_ref(), compatibility)
        .map_err(|e| places.explain(e))?;
    if let Some(repair) = surface.repair() {
        report_repair(repair);
    }
    Ok((surface, u_family, v_family))
}

impl NetworkFiles<'_> {
    /// Checks the options that go together or with `kind` only, and that no input is one of
    /// `outputs`.
    fn check(&self, kind: Kind, outputs: &[PathBuf]) -> Result<()> {
        if self.u_derivs.is_some() != self.v_derivs.is_some() {
            bail!("--u-derivs and --v-derivs go together: give both or neither");
        }
        if let Some(t) = self.tolerance {
            if !(t.is_finite() && t >= 0.0) {
                bail!("--tolerance must be a finite number >= 0, got {t}");
            }
        }
        let with_derivs = self.u_derivs.is_some();
        if with_derivs && !matches!(kind, Kind::Bicubic | Kind::Composite) {
            bail!("--u-derivs and --v-derivs are used only by --kind bicubic and composite");
        }
        if self.twists.is_some() && !matches!(kind, Kind::Bicubic | Kind::Composite) {
            bail!("--twists is used only by --kind bicubic and composite");
        }
        let mut named = vec![("--u-curves", self.u_curves), ("--v-curves", self.v_curves)];
        named.extend(self.u_derivs.map(|p| ("--u-derivs", p)));
        named.extend(self.v_derivs.map(|p| ("--v-derivs", p)));
        named.extend(self.twists.map(|p| ("--twists", p)));
        one_standard_input(&named)?;
        let inputs = [self.u_curves, self.v_curves]
            .into_iter()
            .chain(self.u_derivs)
            .chain(self.v_derivs)
            .chain(self.twists);
        for input in inputs {
            for output in outputs {
                ensure_distinct(input, output)?;
            }
        }
        Ok(())
    }

    /// The cross-boundary derivatives of `--u-derivs` and `--v-derivs`, or from `--twists`,
    /// or `None`.
    fn cross_derivatives(
        &self,
        network: &PointNetwork<3>,
        u_family: &CurveFamily,
        v_family: &CurveFamily,
    ) -> Result<Option<CrossDerivatives<3>>> {
        Ok(match (self.u_derivs, self.v_derivs) {
            (Some(du), Some(dv)) => {
                let (du_family, dv_family) = (read_family(du)?, read_family(dv)?);
                let derivs = network
                    .cross_derivatives(&dv_family.curves, &du_family.curves)
                    .with_context(|| format!("{}, {}", du.display(), dv.display()))?;
                Some(derivs)
            }
            _ => match self.twists {
                Some(path) => {
                    let twists = read_grid(path)?;
                    let derivs = CrossDerivatives::from_twists(network.network(), &twists)
                        .with_context(|| {
                            format!(
                                "{}: {} v-curves x {} u-curves",
                                path.display(),
                                v_family.curves.len(),
                                u_family.curves.len()
                            )
                        })?;
                    Some(derivs)
                }
                None => None,
            },
        })
    }
}

/// Warns that `--kind bicubic` without `--u-derivs` and `--v-derivs` takes the cross-boundary
/// derivatives from the curves (and the corner twists from `--twists` when `twists`).
fn warn_bicubic_from_curves(twists: bool) {
    note(format!(
        "karkas: warning: --kind bicubic without --u-derivs and --v-derivs takes the \
         cross-boundary derivatives from the two curves of each family ({}), which \
         misses even a surface the operator reproduces from its own derivatives (a \
         cubic); give --u-derivs and --v-derivs to interpolate them",
        if twists {
            "their tangents and the --twists at the corners"
        } else {
            "their tangents and twists by the spline-of-derivatives rule"
        }
    ));
}

impl Kind {
    /// The library's kind of the same name (the names Python's `kind=` takes).
    fn to_library(self) -> CoonsKind {
        match self {
            Kind::Bilinear => CoonsKind::Bilinear,
            Kind::Bicubic => CoonsKind::Bicubic,
            Kind::Gordon => CoonsKind::Gordon,
            Kind::GordonSpline => CoonsKind::GordonSpline,
            Kind::Composite => CoonsKind::Composite,
        }
    }
}

/// Warns that Lagrange blending across a closed direction leaves a `C^0` seam (Lagrange
/// polynomials are not periodic: the first curve is blended as a last node one period on).
fn warn_lagrange_seam(network: &PointNetwork<3>) {
    let net = network.network();
    let closed: Vec<&str> = [
        (net.u_axis().is_closed(), "u"),
        (net.v_axis().is_closed(), "v"),
    ]
    .into_iter()
    .filter_map(|(closed, name)| closed.then_some(name))
    .collect();
    if !closed.is_empty() {
        note(format!(
            "karkas: warning: --kind gordon blends with Lagrange polynomials, which are not \
             periodic: the surface closes in {} with a C^0 seam (a crease along the first \
             curve); --kind gordon-spline or composite blend smoothly across it",
            closed.join(" and ")
        ));
    }
}

/// Refuses `--crease-u` (`--crease-v`) unless the u-curves (v-curves) of the network are
/// closed, and with cross-derivative data (one vector per point cannot give both sides of a
/// crease): one line naming the option.
fn check_creases(files: &NetworkFiles<'_>, u: &CurveFamily, v: &CurveFamily) -> Result<()> {
    let (crease_u, crease_v) = files.creases;
    if !(crease_u || crease_v) {
        return Ok(());
    }
    let option = if crease_u { "--crease-u" } else { "--crease-v" };
    if files.u_derivs.is_some() || files.twists.is_some() {
        let given = if files.twists.is_some() {
            "--twists"
        } else {
            "--u-derivs and --v-derivs"
        };
        bail!(
            "{option}: not with {given} (one vector per point cannot give both sides of a \
             crease)"
        );
    }
    for (crease, option, family, path, name) in [
        (crease_u, "--crease-u", u, files.u_curves, "u-curve"),
        (crease_v, "--crease-v", v, files.v_curves, "v-curve"),
    ] {
        if !crease {
            continue;
        }
        // The library's closing rule (a relative 1e-12 of the model size), measured here to
        // name the curve and the distance.
        let all = u.curves.iter().chain(&v.curves).flatten();
        let (mut low, mut high) = ([f64::INFINITY; 3], [f64::NEG_INFINITY; 3]);
        for p in all {
            for c in 0..3 {
                low[c] = low[c].min(p[c]);
                high[c] = high[c].max(p[c]);
            }
        }
        let size = (0..3)
            .map(|c| (high[c] - low[c]).max(0.0).powi(2))
            .sum::<f64>()
            .sqrt();
        for (k, (curve, line)) in family.curves.iter().zip(&family.first_lines).enumerate() {
            let (first, last) = (curve[0], curve[curve.len() - 1]);
            let gap = (first - last).max_abs();
            if curve.len() < 4 || gap > 1e-12 * size {
                bail!(
                    "{option}: a crease closes the {name}s' direction, but {}:{line} ({name} \
                     {k}) is open (its last point is {gap:.3e} from its first; repeat the first \
                     point exactly as the last to close it)",
                    path.display()
                );
            }
        }
    }
    Ok(())
}

/// Prints the largest correction of `--repair` (the command has no JSON summary).
fn report_repair(repair: &Repair) {
    note(format!(
        "karkas: repaired the compatibility conditions: largest correction {:.3e} ({:.3e} of \
         the model size), {} at (u={}, v={})",
        repair.correction, repair.relative, repair.condition, repair.u, repair.v
    ));
}

/// Reads a curve family, refusing curves too short to interpolate (named by their line).
fn read_family(path: &Path) -> Result<CurveFamily> {
    let family = read_curve_family(path)?;
    for (k, (curve, line)) in family.curves.iter().zip(&family.first_lines).enumerate() {
        if curve.len() < 2 {
            bail!(
                "{}:{line}: curve {k} has {} point{}; at least 2 are needed",
                path.display(),
                curve.len(),
                if curve.len() == 1 { "" } else { "s" }
            );
        }
    }
    Ok(family)
}

/// The input files, to put library errors about curves in terms of files and lines.
struct Files<'a> {
    u: &'a Path,
    v: &'a Path,
    u_family: &'a CurveFamily,
    v_family: &'a CurveFamily,
}

impl Files<'_> {
    /// `path:line (which curve)` for curve `k` of a family.
    fn at(&self, v_family: bool, k: usize) -> String {
        let (path, family, name) = if v_family {
            (self.v, self.v_family, "v-curve")
        } else {
            (self.u, self.u_family, "u-curve")
        };
        match family.first_lines.get(k) {
            Some(line) => format!("{}:{line} ({name} {k})", path.display()),
            None => format!("{} ({name} {k})", path.display()),
        }
    }

    /// A library error with the files (and lines) at fault: a crossing names both curves by
    /// file and line in place of the library's curve numbers.
    fn explain(&self, e: Error) -> anyhow::Error {
        match e {
            Error::NetworkCrossing {
                v_curve,
                u_curve,
                problem,
            } => anyhow!(
                "{} and {}: {problem}",
                self.at(true, v_curve),
                self.at(false, u_curve)
            ),
            other => anyhow::Error::new(other).context(format!(
                "{}, {}",
                self.u.display(),
                self.v.display()
            )),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `--kind` takes exactly the library's names, each for the library's kind of that name.
    #[test]
    fn kind_names_are_the_library_names() {
        let names: Vec<String> = Kind::value_variants()
            .iter()
            .filter_map(|k| k.to_possible_value())
            .map(|v| v.get_name().to_owned())
            .collect();
        assert_eq!(names, CoonsKind::NAMES);
        for kind in Kind::value_variants() {
            let name = kind.to_possible_value().map(|v| v.get_name().to_owned());
            assert_eq!(name.as_deref(), Some(kind.to_library().name()));
        }
    }
}

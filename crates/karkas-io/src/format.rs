//! Output formats, chosen by the extension of the output file name.
//!
//! The user says what they want by naming the file (`wing.svg`, `hull.obj`); each command
//! passes the formats it can produce.

use std::path::Path;

use crate::error::IoError;

/// A kind of output file.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum OutputFormat {
    /// Comma-separated samples (`.csv`).
    Csv,
    /// A picture (`.svg`).
    Svg,
    /// A Wavefront triangle mesh (`.obj`).
    Obj,
    /// A binary STL triangle mesh (`.stl`).
    Stl,
    /// A picture in pixels (`.png`).
    Png,
    /// A STEP file of exact B-spline geometry (`.step` or `.stp`).
    Step,
    /// An IGES file of exact B-spline geometry (`.iges` or `.igs`).
    Iges,
    /// A Stanford PLY triangle mesh (`.ply`, binary little-endian).
    Ply,
    /// A legacy VTK file (`.vtk`): a structured grid for surfaces.
    Vtk,
    /// A VTK XML structured grid (`.vts`).
    Vts,
    /// A binary glTF 2.0 mesh (`.glb`).
    Glb,
    /// A self-contained 3-D viewer page (`.html`).
    Html,
    /// A DXF drawing of an exact B-spline curve and its input points (`.dxf`).
    Dxf,
    /// A NumPy array of the sampled points (`.npy`, `f64` little-endian, C order).
    Npy,
}

impl OutputFormat {
    /// All formats, in the order they are listed in messages.
    pub const ALL: [OutputFormat; 14] = [
        OutputFormat::Csv,
        OutputFormat::Svg,
        OutputFormat::Obj,
        OutputFormat::Stl,
        OutputFormat::Png,
        OutputFormat::Step,
        OutputFormat::Iges,
        OutputFormat::Ply,
        OutputFormat::Vtk,
        OutputFormat::Vts,
        OutputFormat::Glb,
        OutputFormat::Html,
        OutputFormat::Dxf,
        OutputFormat::Npy,
    ];

    /// Every triangle-mesh format a sampled surface can be written in.
    pub const MESHES: [OutputFormat; 6] = [
        OutputFormat::Obj,
        OutputFormat::Stl,
        OutputFormat::Ply,
        OutputFormat::Vtk,
        OutputFormat::Vts,
        OutputFormat::Glb,
    ];

    /// The exact CAD formats (STEP and IGES), for the commands whose result is a piecewise
    /// polynomial.
    pub const CAD: [OutputFormat; 2] = [OutputFormat::Step, OutputFormat::Iges];

    /// The exact formats of a curve: [`CAD`](Self::CAD) and DXF (a SPLINE entity with the
    /// input points).
    pub const CURVE_CAD: [OutputFormat; 3] =
        [OutputFormat::Step, OutputFormat::Iges, OutputFormat::Dxf];

    /// The format named by the extension of `path` (case-insensitive), if it is one of
    /// `allowed`; otherwise [`IoError::UnknownExtension`] listing the allowed extensions.
    ///
    /// # Examples
    ///
    /// ```
    /// use std::path::Path;
    /// use karkas_io::OutputFormat;
    ///
    /// let allowed = [OutputFormat::Csv, OutputFormat::Svg];
    /// assert_eq!(OutputFormat::from_path(Path::new("curve.SVG"), &allowed)?, OutputFormat::Svg);
    /// assert!(OutputFormat::from_path(Path::new("curve.step"), &allowed).is_err()); // not allowed here
    /// # Ok::<(), karkas_io::IoError>(())
    /// ```
    pub fn from_path(path: &Path, allowed: &[OutputFormat]) -> Result<OutputFormat, IoError> {
        let extension = path.extension().and_then(|e| e.to_str());
        allowed
            .iter()
            .copied()
            .find(|f| {
                extension.is_some_and(|e| {
                    e.eq_ignore_ascii_case(f.extension())
                        || f.alias().is_some_and(|a| e.eq_ignore_ascii_case(a))
                })
            })
            .ok_or_else(|| IoError::UnknownExtension {
                path: path.to_path_buf(),
                allowed: allowed_list(allowed),
            })
    }

    /// `self` if it is one of `allowed`, else [`IoError::UnknownExtension`] for `path` listing
    /// the allowed extensions: a format asked for by name that the result cannot be written in.
    pub fn allowed_for(self, path: &Path, allowed: &[OutputFormat]) -> Result<Self, IoError> {
        if allowed.contains(&self) {
            Ok(self)
        } else {
            Err(IoError::UnknownExtension {
                path: path.to_path_buf(),
                allowed: allowed_list(allowed),
            })
        }
    }

    /// The file extension, without the dot: `"csv"`, `"svg"`, `"obj"`, `"stl"`, `"png"`,
    /// `"ply"`, `"vtk"`, `"vts"`, `"glb"`, `"html"`, `"dxf"` or `"npy"`.
    pub fn extension(self) -> &'static str {
        match self {
            OutputFormat::Csv => "csv",
            OutputFormat::Svg => "svg",
            OutputFormat::Obj => "obj",
            OutputFormat::Stl => "stl",
            OutputFormat::Png => "png",
            OutputFormat::Step => "step",
            OutputFormat::Iges => "iges",
            OutputFormat::Ply => "ply",
            OutputFormat::Vtk => "vtk",
            OutputFormat::Vts => "vts",
            OutputFormat::Glb => "glb",
            OutputFormat::Html => "html",
            OutputFormat::Dxf => "dxf",
            OutputFormat::Npy => "npy",
        }
    }

    /// The other accepted extension, if any: `"stp"` for STEP, `"igs"` for IGES.
    pub fn alias(self) -> Option<&'static str> {
        match self {
            OutputFormat::Step => Some("stp"),
            OutputFormat::Iges => Some("igs"),
            _ => None,
        }
    }

    /// True for the exact CAD formats (STEP, IGES, and DXF for curves:
    /// [`CURVE_CAD`](Self::CURVE_CAD)).
    pub fn is_cad(self) -> bool {
        OutputFormat::CURVE_CAD.contains(&self)
    }
}

/// The extensions of `allowed` as a message fragment like `".csv, .svg"`, in the order of
/// [`OutputFormat::ALL`].
fn allowed_list(allowed: &[OutputFormat]) -> String {
    let list: Vec<String> = OutputFormat::ALL
        .iter()
        .filter(|f| allowed.contains(f))
        .map(|f| match f.alias() {
            Some(a) => format!(".{}/.{a}", f.extension()),
            None => format!(".{}", f.extension()),
        })
        .collect();
    if list.is_empty() {
        "(none)".to_owned()
    } else {
        list.join(", ")
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use OutputFormat::*;

    #[test]
    fn extension_decides_case_insensitively() {
        let p = Path::new;
        assert_eq!(
            OutputFormat::from_path(p("a/b.SVG"), &[Csv, Svg]).unwrap(),
            Svg
        );
        assert_eq!(
            OutputFormat::from_path(p("b.csv"), &[Csv, Svg]).unwrap(),
            Csv
        );
        let e = OutputFormat::from_path(p("b.obj"), &[Svg, Csv]).unwrap_err();
        assert_eq!(
            e.to_string(),
            "b.obj: unknown output extension (use one of: .csv, .svg)"
        );
        assert!(OutputFormat::from_path(p("noext"), &[Csv, Svg, Obj]).is_err());
        assert_eq!(allowed_list(&[Obj, Csv, Svg]), ".csv, .svg, .obj");
        assert_eq!(allowed_list(&[Stl, Csv, Obj]), ".csv, .obj, .stl");
        assert_eq!(allowed_list(&[Png, Svg, Csv]), ".csv, .svg, .png");
        assert_eq!(allowed_list(&[]), "(none)");
        for f in OutputFormat::ALL {
            assert!(allowed_list(&[f]).starts_with(&format!(".{}", f.extension())));
        }
        assert_eq!(
            allowed_list(&[Iges, Csv, Step]),
            ".csv, .step/.stp, .iges/.igs"
        );
        assert_eq!(
            OutputFormat::from_path(p("a.STP"), &OutputFormat::CAD).unwrap(),
            Step
        );
        assert_eq!(
            OutputFormat::from_path(p("a.step"), &OutputFormat::CAD).unwrap(),
            Step
        );
        assert_eq!(
            OutputFormat::from_path(p("a.igs"), &OutputFormat::CAD).unwrap(),
            Iges
        );
        assert_eq!(
            OutputFormat::from_path(p("a.Iges"), &OutputFormat::CAD).unwrap(),
            Iges
        );
        assert!(OutputFormat::from_path(p("a.st"), &OutputFormat::CAD).is_err());
        assert_eq!(
            OutputFormat::from_path(p("a.DXF"), &OutputFormat::CURVE_CAD).unwrap(),
            Dxf
        );
        assert!(OutputFormat::from_path(p("a.dxf"), &OutputFormat::CAD).is_err());
    }
}

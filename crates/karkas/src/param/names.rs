//! The names of the parameterizations, shared by every front end (the command line's
//! `--param`, Python's `parameterization=`): [`FromStr`] accepts each spelling in use, and
//! `NAMES` lists them for help texts and error messages.

use core::str::FromStr;

use super::parameterization::{CurveParameterization, GridParameterization};
use crate::Error;

impl CurveParameterization {
    /// The names accepted by [`FromStr`], canonical ones first: `uniform`, `chord`,
    /// `centripetal`, then the aliases `chord-length` and `chordlength`.
    pub const NAMES: &'static [&'static str] = &[
        "uniform",
        "chord",
        "centripetal",
        "chord-length",
        "chordlength",
    ];

    /// The canonical name (`uniform`, `chord` or `centripetal`).
    pub fn name(self) -> &'static str {
        match self {
            CurveParameterization::Uniform => "uniform",
            CurveParameterization::ChordLength => "chord",
            CurveParameterization::Centripetal => "centripetal",
        }
    }
}

impl FromStr for CurveParameterization {
    type Err = Error;

    /// Parses one of [`Self::NAMES`] (exactly, lower case).
    fn from_str(name: &str) -> Result<Self, Error> {
        match name {
            "uniform" => Ok(CurveParameterization::Uniform),
            "chord" | "chord-length" | "chordlength" => Ok(CurveParameterization::ChordLength),
            "centripetal" => Ok(CurveParameterization::Centripetal),
            _ => Err(Error::UnknownName {
                what: "parameterization",
                name: name.to_owned(),
                expected: Self::NAMES,
            }),
        }
    }
}

impl GridParameterization {
    /// The names accepted by [`FromStr`], canonical ones first: `uniform`, `chord` (the paper's
    /// rule with the origin at node `(0, 0)`), `averaged` (the command line's spelling),
    /// `centripetal`, then the alias `averaged-chord`.
    pub const NAMES: &'static [&'static str] = &[
        "uniform",
        "chord",
        "averaged",
        "centripetal",
        "averaged-chord",
    ];

    /// The name of the default rule, [`GridParameterization::default`].
    pub const DEFAULT_NAME: &'static str = "chord";

    /// The canonical name (`uniform`, `chord`, `averaged` or `centripetal`); a chord rule with
    /// another origin than `(0, 0)` is `chord` too.
    pub fn name(self) -> &'static str {
        match self {
            GridParameterization::Uniform => "uniform",
            GridParameterization::Chord { .. } => "chord",
            GridParameterization::AveragedChord => "averaged",
            GridParameterization::Centripetal => "centripetal",
        }
    }
}

impl FromStr for GridParameterization {
    type Err = Error;

    /// Parses one of [`Self::NAMES`] (exactly, lower case).
    fn from_str(name: &str) -> Result<Self, Error> {
        match name {
            "uniform" => Ok(GridParameterization::Uniform),
            "chord" => Ok(GridParameterization::default()),
            "averaged" | "averaged-chord" => Ok(GridParameterization::AveragedChord),
            "centripetal" => Ok(GridParameterization::Centripetal),
            _ => Err(Error::UnknownName {
                what: "parameterization",
                name: name.to_owned(),
                expected: Self::NAMES,
            }),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_name_parses_and_canonical_names_round_trip() {
        for name in CurveParameterization::NAMES {
            let p: CurveParameterization = name.parse().unwrap();
            assert_eq!(p.name().parse::<CurveParameterization>().unwrap(), p);
        }
        for name in GridParameterization::NAMES {
            let p: GridParameterization = name.parse().unwrap();
            assert_eq!(p.name().parse::<GridParameterization>().unwrap(), p);
        }
        assert_eq!(
            "averaged-chord".parse::<GridParameterization>().unwrap(),
            GridParameterization::AveragedChord
        );
        assert_eq!(
            GridParameterization::DEFAULT_NAME
                .parse::<GridParameterization>()
                .unwrap(),
            GridParameterization::default()
        );
        let e = "spline".parse::<GridParameterization>().unwrap_err();
        assert!(e.to_string().contains("averaged-chord"), "{e}");
    }
}

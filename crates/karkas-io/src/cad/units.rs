//! The length unit a CAD file states and the scale its coordinates are written at
//! (`--units mm|cm|m|in`, `--scale S`).
//!
//! karkas does not know the unit of its input: a STEP or IGES file says millimetres unless told
//! otherwise, a DXF says nothing (`$INSUNITS 0`). [`CadUnits::unit`] names the unit the file
//! states: STEP's length unit (`SI_UNIT` with its prefix, or inches as a
//! `CONVERSION_BASED_UNIT` of 25.4 mm), IGES's units flag and name (global parameters 14 and
//! 15), DXF's `$INSUNITS`. The coordinates are written as they are, times
//! [`CadUnits::scale`] (default 1): a unit chord written with `--units m` is one metre, which a
//! CAD program working in millimetres reads as 1000; `--units mm --scale 1000` writes a chord
//! given in metres as 1000 mm.

use std::fmt;
use std::str::FromStr;

/// A length unit of a CAD file.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum LengthUnit {
    /// Millimetres (STEP's and IGES's default here).
    #[default]
    Millimetre,
    /// Centimetres.
    Centimetre,
    /// Metres.
    Metre,
    /// Inches (25.4 mm).
    Inch,
}

impl LengthUnit {
    /// Every unit, in the order the help lists them.
    pub const ALL: [LengthUnit; 4] = [
        LengthUnit::Millimetre,
        LengthUnit::Centimetre,
        LengthUnit::Metre,
        LengthUnit::Inch,
    ];

    /// The short name: `mm`, `cm`, `m`, `in`.
    pub fn name(self) -> &'static str {
        match self {
            LengthUnit::Millimetre => "mm",
            LengthUnit::Centimetre => "cm",
            LengthUnit::Metre => "m",
            LengthUnit::Inch => "in",
        }
    }

    /// The unit in millimetres.
    pub fn millimetres(self) -> f64 {
        match self {
            LengthUnit::Millimetre => 1.0,
            LengthUnit::Centimetre => 10.0,
            LengthUnit::Metre => 1000.0,
            LengthUnit::Inch => 25.4,
        }
    }

    /// IGES's units flag (global parameter 14) and name (15).
    pub fn iges(self) -> (u32, &'static str) {
        match self {
            LengthUnit::Millimetre => (2, "MM"),
            LengthUnit::Centimetre => (10, "CM"),
            LengthUnit::Metre => (6, "M"),
            LengthUnit::Inch => (1, "IN"),
        }
    }

    /// DXF's `$INSUNITS` code.
    pub fn dxf(self) -> u32 {
        match self {
            LengthUnit::Millimetre => 4,
            LengthUnit::Centimetre => 5,
            LengthUnit::Metre => 6,
            LengthUnit::Inch => 1,
        }
    }

    /// The STEP instances of the length unit, the last being the unit itself (`add` adds an
    /// instance and returns its reference `#n`).
    pub fn step_instances(self, add: &mut dyn FnMut(String) -> String) -> String {
        let si = |prefix: &str| format!("(LENGTH_UNIT()NAMED_UNIT(*)SI_UNIT({prefix},.METRE.))");
        match self {
            LengthUnit::Millimetre => add(si(".MILLI.")),
            LengthUnit::Centimetre => add(si(".CENTI.")),
            LengthUnit::Metre => add(si("$")),
            LengthUnit::Inch => {
                let mm = add(si(".MILLI."));
                let measure = add(format!(
                    "LENGTH_MEASURE_WITH_UNIT(LENGTH_MEASURE(25.4),{mm})"
                ));
                let exponents = add("DIMENSIONAL_EXPONENTS(1.,0.,0.,0.,0.,0.,0.)".to_owned());
                add(format!(
                    "(CONVERSION_BASED_UNIT('INCH',{measure})LENGTH_UNIT()NAMED_UNIT({exponents}))"
                ))
            }
        }
    }
}

impl fmt::Display for LengthUnit {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for LengthUnit {
    type Err = String;

    /// `mm`, `cm`, `m` or `in` (also `inch`), in any case.
    fn from_str(text: &str) -> Result<LengthUnit, String> {
        let text = text.trim();
        if text.eq_ignore_ascii_case("inch") {
            return Ok(LengthUnit::Inch);
        }
        LengthUnit::ALL
            .into_iter()
            .find(|u| u.name().eq_ignore_ascii_case(text))
            .ok_or_else(|| format!("'{text}' is not a length unit (one of mm, cm, m, in)"))
    }
}

/// The unit a CAD file states and the factor its coordinates are multiplied by.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CadUnits {
    /// The unit the file states; `None`: the format's default (millimetres in STEP and IGES,
    /// no unit in DXF).
    pub unit: Option<LengthUnit>,
    /// The factor every coordinate is multiplied by (positive and finite; 1 by default).
    pub scale: f64,
}

impl Default for CadUnits {
    fn default() -> CadUnits {
        CadUnits {
            unit: None,
            scale: 1.0,
        }
    }
}

impl CadUnits {
    /// Refuses a scale that is not positive and finite.
    pub fn check(&self) -> Result<(), String> {
        if self.scale > 0.0 && self.scale.is_finite() {
            Ok(())
        } else {
            Err(format!(
                "--scale: the factor must be positive and finite, got {}",
                self.scale
            ))
        }
    }

    /// The unit of STEP and IGES files: the one given, else millimetres.
    pub fn cad_unit(&self) -> LengthUnit {
        self.unit.unwrap_or_default()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn units_parse_and_say_what_they_are() {
        assert_eq!("MM".parse::<LengthUnit>(), Ok(LengthUnit::Millimetre));
        assert_eq!("inch".parse::<LengthUnit>(), Ok(LengthUnit::Inch));
        assert!("ft".parse::<LengthUnit>().is_err());
        assert_eq!(LengthUnit::Metre.iges(), (6, "M"));
        assert_eq!(LengthUnit::Inch.dxf(), 1);
        let mut lines = Vec::new();
        let unit = LengthUnit::Inch.step_instances(&mut |e| {
            lines.push(e);
            format!("#{}", lines.len())
        });
        assert_eq!(unit, "#4");
        assert!(lines[1].contains("25.4") && lines[3].contains("'INCH'"));
        assert!(CadUnits::default().check().is_ok());
        let bad = CadUnits {
            unit: None,
            scale: 0.0,
        };
        assert!(bad.check().is_err());
    }
}

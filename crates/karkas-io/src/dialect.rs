//! The dialects of column files as spreadsheets, scanners and scripts write them: the field
//! separator, the decimal mark, quoted fields and the names in a header.
//!
//! - **Separators**: a comma, a semicolon (spreadsheets in locales whose decimal mark is a
//!   comma), a tab, or runs of spaces and tabs. [`Separator::of_line`] tells them from the
//!   first content line; the rest of the file follows it.
//! - **Decimal commas** (`0,5`): read wherever the comma cannot be the separator, that is
//!   when fields are separated by semicolons, tabs or spaces; a comma-separated file has
//!   decimal points. [`ReadOptions::decimal_comma`] (`--decimal-comma`) says so outright: the
//!   comma then separates fields only between quoted ones (`"0,5","1,25"`).
//! - **Quotes**: fields in double quotes (`"x","y"`, `"0,5";"1,25"`), as Excel writes them.
//! - **Header names**: compared without case, quotes and a unit in brackets or parentheses
//!   (`x [mm]`, `Y (m)`), so `x [mm],y [mm]` names the columns x and y
//!   ([`column_name`]).
//! - **Choosing columns**: [`ColumnChoice`] (`--columns A,B[,C]`) names the x, y (and z)
//!   columns by their header names or by their positions counted from 1, for headers in other
//!   languages or files with more columns.
//!
//! Hand-written: the `csv` crate reads one separator given in advance and no decimal commas;
//! telling the dialect from the content is what this module adds (quoted fields are still
//! read by the `csv` crate, `split_fields`).

use std::borrow::Cow;
use std::fmt;
use std::str::FromStr;

use crate::error::{IoError, Location};
use crate::input::excerpt;

/// What separates the fields of a row.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Separator {
    /// `,` (the decimal mark is then a point).
    Comma,
    /// `;`, as spreadsheets write CSV where the decimal mark is a comma.
    Semicolon,
    /// One tab between fields (a header's names may hold spaces).
    Tab,
    /// Runs of spaces and tabs.
    Whitespace,
}

impl Separator {
    /// The byte that separates fields; `None` for runs of whitespace.
    pub fn byte(self) -> Option<u8> {
        match self {
            Separator::Comma => Some(b','),
            Separator::Semicolon => Some(b';'),
            Separator::Tab => Some(b'\t'),
            Separator::Whitespace => None,
        }
    }

    /// True when a comma in a number field is a decimal comma: the comma does not separate
    /// the fields.
    pub fn allows_decimal_comma(self) -> bool {
        self != Separator::Comma
    }

    /// What the messages call it.
    pub fn name(self) -> &'static str {
        match self {
            Separator::Comma => "commas",
            Separator::Semicolon => "semicolons",
            Separator::Tab => "tabs",
            Separator::Whitespace => "spaces",
        }
    }

    /// The separator of a file whose first content line (comment removed) is `content`; with
    /// `decimal_comma`, a comma is a decimal mark and never the separator.
    ///
    /// A semicolon outside quotes makes the semicolon the separator. Otherwise a line of
    /// numbers is comma-separated when its comma-separated fields are all numbers with decimal
    /// points; else tab- or space-separated, its commas decimal commas. A header (a line that
    /// is not all numbers) is comma-separated when it holds a comma; else tab-separated when
    /// its names hold spaces between the tabs (`X coordinate<TAB>Y coordinate`); else
    /// space-separated.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::dialect::Separator;
    ///
    /// assert_eq!(Separator::of_line("0.5;1,25", false), Separator::Semicolon);
    /// assert_eq!(Separator::of_line("0.5,1.25", false), Separator::Comma);
    /// assert_eq!(Separator::of_line("0,5 1,25", false), Separator::Whitespace); // decimal commas
    /// ```
    pub fn of_line(content: &str, decimal_comma: bool) -> Separator {
        let unquoted = outside_quotes(content);
        if unquoted.contains(';') {
            return Separator::Semicolon;
        }
        let tab_fields = || content.split('\t').map(str::trim);
        let spaced = || content.split_whitespace();
        if decimal_comma && content.contains('"') && unquoted.contains(',') {
            // Quoted fields holding decimal commas, separated by commas.
            return Separator::Comma;
        }
        if !decimal_comma && unquoted.contains(',') {
            let comma_fields = || content.split(',').map(|f| unquote(f.trim()));
            if content.contains('"') || comma_fields().all(|f| parse_number(&f, false).is_some()) {
                return Separator::Comma;
            }
            if spaced().all(|f| parse_number(f, true).is_some()) {
                return Separator::Whitespace;
            }
            if content.contains('\t') && tab_fields().all(|f| parse_number(f, true).is_some()) {
                return Separator::Tab;
            }
            return Separator::Comma;
        }
        if content.contains('\t')
            && tab_fields().any(|f| f.contains(' '))
            && !tab_fields().all(|f| parse_number(f, true).is_some())
        {
            return Separator::Tab;
        }
        Separator::Whitespace
    }
}

/// What a user says about the columns of a curve file (`--columns`, `--decimal-comma`;
/// `columns=`, `decimal_comma=` in Python). The default reads by the rules of
/// [`crate::points`] alone.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ReadOptions {
    /// The x, y (and z) columns, by name or position; `None`: by the header's names or, in
    /// a file without one, the first two or three columns.
    pub columns: Option<ColumnChoice>,
    /// Numbers are written with a decimal comma: the comma separates fields only between
    /// quoted ones.
    pub decimal_comma: bool,
}

/// One column of `--columns`: its name in the header or its position counted from 1.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ColumnRef {
    /// The column at this position, counted from 1.
    Position(usize),
    /// The column of this header name (compared as [`column_name`] compares).
    Name(String),
}

impl fmt::Display for ColumnRef {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ColumnRef::Position(k) => write!(f, "{k}"),
            ColumnRef::Name(name) => write!(f, "'{name}'"),
        }
    }
}

/// The x, y and (for points in space) z columns of a curve file: `--columns A,B[,C]`.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ColumnChoice(Vec<ColumnRef>);

impl ColumnChoice {
    /// The choice of the columns `refs`, two (x, y) or three (x, y, z); `None` for another
    /// number.
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas_io::dialect::{ColumnChoice, ColumnRef};
    ///
    /// let choice = ColumnChoice::new(vec![ColumnRef::Position(2), ColumnRef::Name("y".into())]);
    /// assert!(choice.is_some());
    /// assert!(ColumnChoice::new(vec![ColumnRef::Position(1)]).is_none()); // x alone
    /// ```
    pub fn new(refs: Vec<ColumnRef>) -> Option<ColumnChoice> {
        (2..=3).contains(&refs.len()).then_some(ColumnChoice(refs))
    }

    /// The columns chosen, x first.
    pub fn refs(&self) -> &[ColumnRef] {
        &self.0
    }

    /// True when every column is given by its position (a file without a header can be read).
    pub fn by_position(&self) -> bool {
        self.0.iter().all(|r| matches!(r, ColumnRef::Position(_)))
    }

    /// The 0-based fields of the chosen columns in a row of `width` fields whose header (if
    /// any) is `header`; the error says which column is not there.
    pub fn resolve(&self, header: Option<&[String]>, width: usize) -> Result<Vec<usize>, String> {
        let mut fields = Vec::with_capacity(self.0.len());
        for r in &self.0 {
            let field = match r {
                ColumnRef::Position(k) if (1..=width).contains(k) => k - 1,
                ColumnRef::Position(k) => {
                    return Err(format!(
                        "--columns: column {k} is not there: the rows have {width} fields"
                    ))
                }
                ColumnRef::Name(name) => {
                    let Some(header) = header else {
                        return Err(format!(
                            "--columns: the file has no header to find '{name}' in: give the \
                             columns by position, counted from 1 (e.g. --columns 1,2)"
                        ));
                    };
                    find_name(header, name).ok_or_else(|| {
                        let names: Vec<String> =
                            header.iter().map(|h| crate::input::excerpt(h)).collect();
                        format!(
                            "--columns: the header has no column '{name}' (its columns: {})",
                            names.join(", ")
                        )
                    })?
                }
            };
            if fields.contains(&field) {
                return Err(format!("--columns: column {r} is chosen twice"));
            }
            fields.push(field);
        }
        Ok(fields)
    }
}

impl FromStr for ColumnChoice {
    type Err = String;

    /// Parses `A,B[,C]`: each a header name or a position counted from 1.
    fn from_str(text: &str) -> Result<ColumnChoice, String> {
        let refs: Vec<ColumnRef> = text
            .split(',')
            .map(|f| {
                let f = f.trim();
                match f.parse::<usize>() {
                    Ok(0) => Err("positions count from 1, got 0".to_owned()),
                    Ok(k) => Ok(ColumnRef::Position(k)),
                    Err(_) if f.is_empty() => Err(format!("an empty column name in '{text}'")),
                    Err(_) => Ok(ColumnRef::Name(f.to_owned())),
                }
            })
            .collect::<Result<_, _>>()?;
        ColumnChoice::new(refs).ok_or_else(|| {
            format!(
                "expected two or three columns A,B[,C] (x, y and z; names or positions from 1), \
                 got '{text}'"
            )
        })
    }
}

impl fmt::Display for ColumnChoice {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let parts: Vec<String> = self
            .0
            .iter()
            .map(|r| match r {
                ColumnRef::Position(k) => k.to_string(),
                ColumnRef::Name(n) => n.clone(),
            })
            .collect();
        f.write_str(&parts.join(","))
    }
}

/// The position of the header field that names `name` (see [`column_name`]), if exactly one
/// does; an exact match (case aside) wins over a match without units.
pub(crate) fn find_name(header: &[String], name: &str) -> Option<usize> {
    let exact: Vec<usize> = (0..header.len())
        .filter(|&k| unquote(header[k].trim()).eq_ignore_ascii_case(name.trim()))
        .collect();
    if exact.len() == 1 {
        return Some(exact[0]);
    }
    let wanted = column_name(name);
    let loose: Vec<usize> = (0..header.len())
        .filter(|&k| column_name(&header[k]) == wanted)
        .collect();
    (loose.len() == 1).then(|| loose[0])
}

/// A header name as it is compared: trimmed, without surrounding quotes, without a trailing
/// unit in brackets or parentheses (`x [mm]`, `y (m)`, `z[in]`), lower case.
pub fn column_name(field: &str) -> String {
    let mut name = unquote(field.trim()).trim().to_owned();
    for (open, close) in [('[', ']'), ('(', ')'), ('{', '}')] {
        if name.ends_with(close) {
            if let Some(k) = name.rfind(open) {
                if k > 0 {
                    name.truncate(k);
                    name = name.trim_end().to_owned();
                }
            }
        }
    }
    name.to_lowercase()
}

/// The names of a header line `line` (comment removed), split at its separator and
/// compared as [`column_name`] gives them; `None` when the line is all numbers (no header).
pub fn header_names(line: &str) -> Option<Vec<String>> {
    let sep = Separator::of_line(line, false);
    let at = crate::error::Location::new(std::path::Path::new(""), 1);
    let fields = split_fields(line, sep, at).ok()?;
    let comma = sep.allows_decimal_comma();
    if fields.iter().all(|f| parse_number(f, comma).is_some()) {
        return None;
    }
    let fields = if sep == Separator::Whitespace {
        join_units(fields)
    } else {
        fields
    };
    Some(fields.iter().map(|f| column_name(f)).collect())
}

/// `text`, a CSV file of rows with a header (a grid `i,j,x,y,z`, a curve network, a mask, a
/// sampled surface), as comma-separated rows with decimal points: the file itself when its
/// first content line is separated by commas; else every line split at the separator that
/// line says ([`Separator::of_line`]: semicolons, tabs or spaces), its decimal commas made
/// points, and joined by commas again (a field holding a comma or a quote quoted). Line
/// numbers are kept: one line becomes one line, its `#` comment as it was.
pub fn normalized_csv(text: &str) -> Cow<'_, str> {
    let first = text
        .lines()
        .map(|l| l.split('#').next().unwrap_or("").trim())
        .find(|l| !l.is_empty());
    let sep = first.map_or(Separator::Comma, |l| Separator::of_line(l, false));
    if sep == Separator::Comma {
        return Cow::Borrowed(text);
    }
    let at = crate::error::Location::new(std::path::Path::new(""), 1);
    let mut out = String::with_capacity(text.len() + text.len() / 8);
    for line in text.split_inclusive('\n') {
        let (body, end) = match line.strip_suffix('\n') {
            Some(b) => (b, "\n"),
            None => (line, ""),
        };
        let (content, comment) = match body.find('#') {
            Some(k) => body.split_at(k),
            None => (body, ""),
        };
        if content.trim().is_empty() {
            out.push_str(line);
            continue;
        }
        let fields = split_fields(content.trim(), sep, at)
            .unwrap_or_else(|_| vec![content.trim().to_owned()]);
        let fields = if sep == Separator::Whitespace {
            join_units(fields)
        } else {
            fields
        };
        for (k, field) in fields.iter().enumerate() {
            if k > 0 {
                out.push(',');
            }
            if field.contains(',') && parse_number(field, true).is_some() {
                out.push_str(&field.replace(',', "."));
            } else if field.contains([',', '"']) {
                out.push('"');
                out.push_str(&field.replace('"', "\"\""));
                out.push('"');
            } else {
                out.push_str(field);
            }
        }
        out.push_str(comment);
        out.push_str(end);
    }
    Cow::Owned(out)
}

/// `field` without one pair of surrounding double quotes.
pub(crate) fn unquote(field: &str) -> Cow<'_, str> {
    match field.strip_prefix('"').and_then(|f| f.strip_suffix('"')) {
        Some(inner) => Cow::Owned(inner.replace("\"\"", "\"")),
        None => Cow::Borrowed(field),
    }
}

/// The characters of `line` outside double-quoted parts.
fn outside_quotes(line: &str) -> Cow<'_, str> {
    if !line.contains('"') {
        return Cow::Borrowed(line);
    }
    let mut quoted = false;
    Cow::Owned(
        line.chars()
            .filter(|&c| {
                if c == '"' {
                    quoted = !quoted;
                    return false;
                }
                !quoted
            })
            .collect(),
    )
}

/// The number `field` writes (trimmed), with a decimal comma when `decimal_comma` allows
/// one (a field with one comma and no point: `0,5`, `-1,25e-3`); NaN and infinities
/// included, as [`str::parse`] reads them.
pub(crate) fn parse_number(field: &str, decimal_comma: bool) -> Option<f64> {
    let field = field.trim();
    if let Ok(v) = field.parse::<f64>() {
        return Some(v);
    }
    if decimal_comma && !field.contains('.') && field.bytes().filter(|&b| b == b',').count() == 1 {
        return field.replace(',', ".").parse().ok();
    }
    None
}

/// Header fields split at whitespace with a unit in brackets joined to the name before it
/// (`x [mm] y [mm]` is two names).
pub(crate) fn join_units(fields: Vec<String>) -> Vec<String> {
    let mut joined: Vec<String> = Vec::with_capacity(fields.len());
    for f in fields {
        let is_unit =
            (f.starts_with('[') && f.ends_with(']')) || (f.starts_with('(') && f.ends_with(')'));
        match joined.last_mut() {
            Some(last) if is_unit && !f.is_empty() => {
                last.push(' ');
                last.push_str(&f);
            }
            _ => joined.push(f),
        }
    }
    joined
}

/// The fields of a line's `content` (comment already stripped), split at `sep` and trimmed;
/// a line with a double quote is read with the `csv` crate, so quoted fields work as in
/// [`crate::lines::csv_rows`] (in a space-separated line, a field's surrounding quotes are removed). `at`
/// locates a malformed quoted line.
pub(crate) fn split_fields(
    content: &str,
    sep: Separator,
    at: Location<'_>,
) -> Result<Vec<String>, IoError> {
    let Some(byte) = sep.byte() else {
        return Ok(content
            .split_whitespace()
            .map(|f| unquote(f).into_owned())
            .collect());
    };
    if !content.contains('"') {
        return Ok(content
            .split(char::from(byte))
            .map(|f| f.trim().to_owned())
            .collect());
    }
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .delimiter(byte)
        .trim(csv::Trim::All)
        .from_reader(content.as_bytes());
    let mut record = csv::StringRecord::new();
    reader
        .read_record(&mut record)
        .map_err(|e| at.error(format!("malformed CSV: {}", excerpt(&e.to_string()))))?;
    Ok(record.iter().map(str::to_owned).collect())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn separators_are_told_from_the_first_line() {
        let of = |s: &str| Separator::of_line(s, false);
        assert_eq!(of("1,2,3"), Separator::Comma);
        assert_eq!(of("x,y"), Separator::Comma);
        assert_eq!(of("\"x\",\"y\""), Separator::Comma);
        assert_eq!(of("\"0,5\";\"1,5\""), Separator::Semicolon);
        assert_eq!(of("x;y"), Separator::Semicolon);
        assert_eq!(of("0,5;1,25"), Separator::Semicolon);
        assert_eq!(of("0,5\t1,25"), Separator::Whitespace);
        assert_eq!(of("0,5 1,25"), Separator::Whitespace);
        assert_eq!(of("1.5,\t2.5"), Separator::Comma);
        assert_eq!(of("1 2"), Separator::Whitespace);
        assert_eq!(of("X coordinate\tY coordinate"), Separator::Tab);
        assert_eq!(of("x\ty"), Separator::Whitespace);
        assert_eq!(of("NACA 63,3-418"), Separator::Comma);
        assert_eq!(Separator::of_line("1,5 2,5", true), Separator::Whitespace);
        assert_eq!(Separator::of_line("x,y", true), Separator::Whitespace);
        assert_eq!(Separator::of_line("\"0,5\",\"1\"", true), Separator::Comma);
    }

    #[test]
    fn names_drop_quotes_units_and_case() {
        assert_eq!(column_name(" \"X [mm]\" "), "x");
        assert_eq!(column_name("y (m)"), "y");
        assert_eq!(column_name("z[in]"), "z");
        assert_eq!(column_name("Абсцисса"), "абсцисса");
        assert_eq!(column_name("(x)"), "(x)");
        let header: Vec<String> = ["i", "X [mm]", "y [mm]"].map(str::to_owned).to_vec();
        assert_eq!(find_name(&header, "x"), Some(1));
        assert_eq!(find_name(&header, "Y [MM]"), Some(2));
        assert_eq!(find_name(&header, "z"), None);
        assert_eq!(
            header_names("\"I\";j;x [mm];y;z"),
            Some(["i", "j", "x", "y", "z"].map(str::to_owned).to_vec())
        );
        assert_eq!(header_names("1;2"), None);
        assert_eq!(
            join_units(["x", "[mm]", "y", "(mm)"].map(str::to_owned).to_vec()),
            ["x [mm]", "y (mm)"]
        );
    }

    #[test]
    fn files_of_other_dialects_become_plain_csv() {
        let grid = "i;j;x [mm];y;z\n0;0;0,5;1;-2,25e-3 # c\n\n0;1;\"1,5\";2;3\n";
        assert_eq!(
            normalized_csv(grid),
            "i,j,x [mm],y,z\n0,0,0.5,1,-2.25e-3# c\n\n0,1,1.5,2,3\n"
        );
        let tabs = "curve\tx\ty\tz\r\n0\t0,5\t1\t2\r\n";
        assert_eq!(normalized_csv(tabs), "curve,x,y,z\n0,0.5,1,2\n");
        let plain = "i,j,x,y,z\n0,0,1,2,3\n";
        assert!(matches!(normalized_csv(plain), Cow::Borrowed(_)));
    }

    #[test]
    fn numbers_with_decimal_commas() {
        assert_eq!(parse_number("0,5", true), Some(0.5));
        assert_eq!(parse_number("-1,25e-3", true), Some(-1.25e-3));
        assert_eq!(parse_number("0,5", false), None);
        assert_eq!(parse_number("1,234.5", true), None);
        assert_eq!(parse_number("1,2,3", true), None);
        assert_eq!(parse_number(" 7 ", false), Some(7.0));
    }

    #[test]
    fn column_choices_parse_and_resolve() {
        let c: ColumnChoice = "2, 3".parse().unwrap();
        assert!(c.by_position());
        assert_eq!(c.resolve(None, 3), Ok(vec![1, 2]));
        assert!(c
            .resolve(None, 2)
            .unwrap_err()
            .contains("column 3 is not there"));
        let c: ColumnChoice = "Абсцисса,Ордината".parse().unwrap();
        let header: Vec<String> = ["№", "Абсцисса", "Ордината"].map(str::to_owned).to_vec();
        assert_eq!(c.resolve(Some(&header), 3), Ok(vec![1, 2]));
        assert!(c.resolve(None, 3).unwrap_err().contains("no header"));
        assert!("1".parse::<ColumnChoice>().is_err());
        assert!("0,1".parse::<ColumnChoice>().is_err());
        assert!("1,2,3,4".parse::<ColumnChoice>().is_err());
        let twice: ColumnChoice = "1,1".parse().unwrap();
        assert!(twice.resolve(None, 2).unwrap_err().contains("twice"));
        assert_eq!(c.to_string(), "Абсцисса,Ордината");
    }
}

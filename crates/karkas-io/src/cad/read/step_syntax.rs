//! The clear-text encoding of STEP (ISO 10303-21): tokens and entity instances, read in one
//! streaming pass.
//!
//! The reader keeps only the instances whose entity types the geometry needs (a simple
//! instance `#12=CIRCLE(...)` or a complex one `#13=(A(...)B(...))` with one such part) and
//! counts the types of the others; everything kept is charged to the process-wide memory cap
//! ([`max_input_bytes`](crate::input::max_input_bytes)), so a file of 10^7 entities is read
//! or refused at the instance that crosses the cap, never by exhausting the machine.
//! Parameters nest at most [`MAX_DEPTH`] lists deep and a token (string, name) is at most
//! [`MAX_TOKEN_BYTES`] long. Every error names the line, and the instance when inside one.
//!
//! Hand-written: the Rust STEP crates (`ruststep`, `iso-10303`) read a whole file into an
//! abstract syntax tree of every instance before anything is checked, map it onto structs
//! generated from the full application-protocol schemas (tens of thousands of lines for AP214
//! alone), and report errors by byte offset from a parser combinator; the tokens of Part 21
//! are a page of code.

use std::collections::{BTreeMap, HashMap};
use std::io::BufRead;
use std::path::Path;

use crate::error::{IoError, Location};
use crate::lines::check_held_at;

/// The deepest nesting of parameter lists accepted.
pub const MAX_DEPTH: usize = 32;
/// The longest string, keyword or number accepted, in bytes.
pub const MAX_TOKEN_BYTES: usize = 1 << 20;

/// One parameter of an entity instance.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Value {
    /// A reference `#n` to another instance.
    Ref(u64),
    /// An integer.
    Int(i64),
    /// A real.
    Real(f64),
    /// A string (quotes removed, doubled quotes undone).
    Str(Box<str>),
    /// An enumeration value `.NAME.` (dots removed) or a logical `.T.`, `.F.`, `.U.`.
    Enum(Box<str>),
    /// A list `( ... )`.
    List(Vec<Value>),
    /// A typed value `NAME(value)`, as `LENGTH_MEASURE(1.E-07)`.
    Typed(Box<str>, Box<Value>),
    /// `$`: no value.
    Unset,
    /// `*`: a value derived from others.
    Derived,
    /// A binary `"..."`.
    Binary,
}

impl Value {
    /// The approximate bytes this value holds (for the memory cap).
    fn bytes(&self) -> usize {
        std::mem::size_of::<Value>()
            + match self {
                Value::Str(s) | Value::Enum(s) => s.len(),
                Value::List(v) => v.iter().map(Value::bytes).sum(),
                Value::Typed(n, v) => n.len() + v.bytes(),
                _ => 0,
            }
    }
}

/// One entity of an instance: its type name and parameters (a complex instance has several).
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Part {
    /// The entity type, upper case as in the file.
    pub name: Box<str>,
    /// The parameters.
    pub params: Vec<Value>,
}

/// An entity instance kept by the reader.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Instance {
    /// The line its `#n=` starts on.
    pub line: usize,
    /// Its entity (one part) or entities (a complex instance, in the file's order).
    pub parts: Vec<Part>,
}

impl Instance {
    /// The part named `name`, if the instance has it.
    pub fn part(&self, name: &str) -> Option<&Part> {
        self.parts.iter().find(|p| &*p.name == name)
    }

    /// The name of a simple instance, or of the first part of a complex one that `names`
    /// holds (the first part otherwise).
    pub fn kind<'a>(&'a self, names: &[&str]) -> &'a str {
        self.parts
            .iter()
            .find(|p| names.contains(&&*p.name))
            .or(self.parts.first())
            .map_or("", |p| &p.name)
    }
}

/// The data section of a STEP file as kept: the instances of the wanted types, and how many
/// instances of each other type there were.
#[derive(Debug, Default)]
pub(crate) struct Exchange {
    /// The kept instances by their number `#n`.
    pub instances: HashMap<u64, Instance>,
    /// The count of instances of each type not kept.
    pub others: BTreeMap<String, usize>,
}

/// A token of the exchange structure.
#[derive(Clone, Debug, PartialEq)]
enum Token {
    Instance(u64),
    Keyword(Box<str>),
    Str(Box<str>),
    Enum(Box<str>),
    Int(i64),
    Real(f64),
    Binary,
    Unset,
    Derived,
    Open,
    Close,
    Comma,
    Semicolon,
    Equals,
    End,
}

/// A byte stream with one byte of look-ahead and a line count.
struct Bytes<'r> {
    reader: &'r mut dyn BufRead,
    line: usize,
    peeked: Option<u8>,
}

impl Bytes<'_> {
    fn peek(&mut self) -> Result<Option<u8>, std::io::Error> {
        if self.peeked.is_none() {
            let buf = self.reader.fill_buf()?;
            if let Some(&b) = buf.first() {
                self.reader.consume(1);
                self.peeked = Some(b);
            }
        }
        Ok(self.peeked)
    }

    fn next(&mut self) -> Result<Option<u8>, std::io::Error> {
        let b = self.peek()?;
        self.peeked = None;
        if b == Some(b'\n') {
            self.line += 1;
        }
        Ok(b)
    }
}

/// The tokenizer and the instance reader.
struct Reader<'p, 'r> {
    path: &'p Path,
    bytes: Bytes<'r>,
    /// The instance being read, for errors.
    current: Option<u64>,
    /// Bytes kept so far.
    held: u128,
}

impl Reader<'_, '_> {
    fn error(&self, message: impl Into<String>) -> IoError {
        let message = message.into();
        let message = match self.current {
            Some(id) => format!("#{id}: {message}"),
            None => message,
        };
        Location::new(self.path, self.bytes.line).error(message)
    }

    fn io(&self, e: std::io::Error) -> IoError {
        IoError::Open {
            path: self.path.to_path_buf(),
            source: e,
        }
    }

    fn peek(&mut self) -> Result<Option<u8>, IoError> {
        self.bytes.peek().map_err(|e| self.io(e))
    }

    fn next_byte(&mut self) -> Result<Option<u8>, IoError> {
        self.bytes.next().map_err(|e| self.io(e))
    }

    /// Appends bytes while `keep` holds to `out`, refusing more than [`MAX_TOKEN_BYTES`].
    fn take_while(&mut self, out: &mut Vec<u8>, keep: impl Fn(u8) -> bool) -> Result<(), IoError> {
        while let Some(b) = self.peek()? {
            if !keep(b) {
                break;
            }
            if out.len() >= MAX_TOKEN_BYTES {
                return Err(self.error("a token longer than 1 MiB"));
            }
            out.push(b);
            self.next_byte()?;
        }
        Ok(())
    }

    /// Skips a comment after its `/` (the `*` still to come).
    fn skip_comment(&mut self) -> Result<(), IoError> {
        self.next_byte()?;
        let start = self.bytes.line;
        let mut star = false;
        loop {
            match self.next_byte()? {
                None => {
                    return Err(
                        Location::new(self.path, start).error("a comment /* is never closed")
                    )
                }
                Some(b'/') if star => return Ok(()),
                Some(c) => star = c == b'*',
            }
        }
    }

    /// The instance number after a `#`.
    fn instance_number(&mut self) -> Result<Token, IoError> {
        let mut digits = Vec::new();
        self.take_while(&mut digits, |c| c.is_ascii_digit())?;
        let id = std::str::from_utf8(&digits)
            .ok()
            .and_then(|d| d.parse::<u64>().ok())
            .ok_or_else(|| self.error("'#' must be followed by an instance number"))?;
        Ok(Token::Instance(id))
    }

    /// The next token, skipping white space and comments.
    fn token(&mut self) -> Result<Token, IoError> {
        loop {
            let Some(b) = self.next_byte()? else {
                return Ok(Token::End);
            };
            match b {
                b' ' | b'\t' | b'\r' | b'\n' | b'\x0c' => continue,
                b'/' if self.peek()? == Some(b'*') => {
                    self.skip_comment()?;
                    continue;
                }
                b'(' => return Ok(Token::Open),
                b')' => return Ok(Token::Close),
                b',' => return Ok(Token::Comma),
                b';' => return Ok(Token::Semicolon),
                b'=' => return Ok(Token::Equals),
                b'$' => return Ok(Token::Unset),
                b'*' => return Ok(Token::Derived),
                b'#' => return self.instance_number(),
                b'\'' => return self.string(),
                b'"' => {
                    let mut hex = Vec::new();
                    self.take_while(&mut hex, |c| c.is_ascii_hexdigit())?;
                    if self.next_byte()? != Some(b'"') {
                        return Err(self.error("a binary value \"...\" is not closed"));
                    }
                    return Ok(Token::Binary);
                }
                b'.' => {
                    let mut name = Vec::new();
                    self.take_while(&mut name, |c| c.is_ascii_alphanumeric() || c == b'_')?;
                    if self.next_byte()? != Some(b'.') || name.is_empty() {
                        return Err(self.error("an enumeration value must look like .NAME."));
                    }
                    return Ok(Token::Enum(String::from_utf8_lossy(&name).into()));
                }
                b'+' | b'-' | b'0'..=b'9' => return self.number(b),
                b'A'..=b'Z' | b'a'..=b'z' | b'_' | b'!' => {
                    let mut name = vec![b];
                    self.take_while(&mut name, |c| {
                        c.is_ascii_alphanumeric() || c == b'_' || c == b'-'
                    })?;
                    let name = String::from_utf8_lossy(&name).to_ascii_uppercase();
                    return Ok(Token::Keyword(name.into()));
                }
                other => {
                    return Err(self.error(
                        format!(
                            "unexpected byte {} (0x{other:02x}): not a STEP text file?",
                            if other.is_ascii_graphic() {
                                format!("'{}'", other as char)
                            } else {
                                "".into()
                            }
                        )
                        .replace("byte  (", "byte ("),
                    ))
                }
            }
        }
    }

    /// A string after its opening quote: up to the closing quote, `''` meaning one quote.
    fn string(&mut self) -> Result<Token, IoError> {
        let start = self.bytes.line;
        let mut text = Vec::new();
        loop {
            match self.next_byte()? {
                None => {
                    return Err(Location::new(self.path, start)
                        .error(self.in_instance("a string is never closed")))
                }
                Some(b'\'') if self.peek()? == Some(b'\'') => {
                    self.next_byte()?;
                    text.push(b'\'');
                }
                Some(b'\'') => break,
                Some(b'\n') | Some(b'\r') => {}
                // Part 21 strings hold printable characters (and UTF-8): a control byte
                // is binary data.
                Some(c) if (c < 0x20 && c != b'\t') || c == 0x7f => {
                    return Err(self.error(format!(
                        "a control byte (0x{c:02x}) in a string: not a STEP text file?"
                    )))
                }
                Some(c) => text.push(c),
            }
            if text.len() > MAX_TOKEN_BYTES {
                return Err(self.error("a string longer than 1 MiB"));
            }
        }
        Ok(Token::Str(String::from_utf8_lossy(&text).into()))
    }

    fn in_instance(&self, message: &str) -> String {
        match self.current {
            Some(id) => format!("#{id}: {message}"),
            None => message.to_owned(),
        }
    }

    /// A number starting with `first`: an integer, or a real when it has a decimal point.
    fn number(&mut self, first: u8) -> Result<Token, IoError> {
        let mut text = vec![first];
        self.take_while(&mut text, |c| c.is_ascii_digit())?;
        let mut real = false;
        if self.peek()? == Some(b'.') {
            real = true;
            text.push(b'.');
            self.next_byte()?;
            self.take_while(&mut text, |c| c.is_ascii_digit())?;
        }
        if matches!(self.peek()?, Some(b'E') | Some(b'e')) {
            real = true;
            text.push(b'E');
            self.next_byte()?;
            if let Some(sign @ (b'+' | b'-')) = self.peek()? {
                text.push(sign);
                self.next_byte()?;
            }
            self.take_while(&mut text, |c| c.is_ascii_digit())?;
        }
        let s = std::str::from_utf8(&text).unwrap_or("");
        let bad = || self.error(format!("'{}' is not a number", crate::input::excerpt(s)));
        if real {
            let x: f64 = s.parse().map_err(|_| bad())?;
            if !x.is_finite() {
                return Err(self.error(format!("the real {s} is too large for 64-bit numbers")));
            }
            Ok(Token::Real(x))
        } else {
            // An integer too large for i64 is still a number: keep it as a real.
            match s.parse::<i64>() {
                Ok(i) => Ok(Token::Int(i)),
                Err(_) => s.parse::<f64>().map(Token::Real).map_err(|_| bad()),
            }
        }
    }

    fn expect(&mut self, want: Token, what: &str) -> Result<(), IoError> {
        let got = self.token()?;
        if got == want {
            Ok(())
        } else {
            Err(self.unexpected(&got, what))
        }
    }

    fn unexpected(&self, got: &Token, what: &str) -> IoError {
        match got {
            Token::End => self.error(format!(
                "the file ends where {what} was expected (truncated?)"
            )),
            other => self.error(format!("{} where {what} was expected", describe(other))),
        }
    }

    /// The parameters of an entity after its `(`, up to and including its `)`.
    fn params(&mut self, depth: usize) -> Result<Vec<Value>, IoError> {
        if depth > MAX_DEPTH {
            return Err(self.error(format!("parameter lists nested more than {MAX_DEPTH} deep")));
        }
        let mut out = Vec::new();
        let mut token = self.token()?;
        if token == Token::Close {
            return Ok(out);
        }
        loop {
            let value = self.value(token, depth)?;
            self.held += value.bytes() as u128;
            out.push(value);
            match self.token()? {
                Token::Comma => token = self.token()?,
                Token::Close => return Ok(out),
                other => return Err(self.unexpected(&other, "',' or ')'")),
            }
        }
    }

    fn value(&mut self, token: Token, depth: usize) -> Result<Value, IoError> {
        Ok(match token {
            Token::Instance(id) => Value::Ref(id),
            Token::Int(i) => Value::Int(i),
            Token::Real(x) => Value::Real(x),
            Token::Str(s) => Value::Str(s),
            Token::Enum(e) => Value::Enum(e),
            Token::Unset => Value::Unset,
            Token::Derived => Value::Derived,
            Token::Binary => Value::Binary,
            Token::Open => Value::List(self.params(depth + 1)?),
            Token::Keyword(name) => {
                self.expect(Token::Open, "'(' after a type name")?;
                let mut inner = self.params(depth + 1)?;
                if inner.len() != 1 {
                    return Err(
                        self.error(format!("the typed value {name}(...) must hold one value"))
                    );
                }
                Value::Typed(name, Box::new(inner.remove(0)))
            }
            other => return Err(self.unexpected(&other, "a parameter")),
        })
    }

    /// Skips the parameters of an entity after its `(`, up to and including its `)`.
    fn skip_params(&mut self) -> Result<(), IoError> {
        let mut depth = 1usize;
        while depth > 0 {
            match self.token()? {
                Token::Open => depth += 1,
                Token::Close => depth -= 1,
                Token::End => return Err(self.unexpected(&Token::End, "')'")),
                Token::Semicolon => return Err(self.error("';' inside an entity's parameters")),
                _ => {}
            }
        }
        Ok(())
    }

    /// The rest of a data section's start: `;`, or (edition 3) `('name',('schema'));`.
    fn data_section_start(&mut self) -> Result<(), IoError> {
        match self.token()? {
            Token::Semicolon => {}
            Token::Open => {
                self.skip_params()?;
                self.expect(Token::Semicolon, "';' after DATA(...)")?;
            }
            other => return Err(self.unexpected(&other, "';' after DATA")),
        }
        Ok(())
    }

    /// Instance `#id` after its number: kept in `exchange` when its type is `wanted`,
    /// otherwise counted by type.
    fn instance(
        &mut self,
        id: u64,
        wanted: &dyn Fn(&str) -> bool,
        exchange: &mut Exchange,
    ) -> Result<(), IoError> {
        let line = self.bytes.line;
        self.current = Some(id);
        self.expect(Token::Equals, "'=' after the instance number")?;
        match self.instance_body(wanted)? {
            Body::Kept(parts) => {
                // The map's own entry and its share of the table's spare room.
                self.held += 96;
                check_held_at(self.path, line, self.held)?;
                if exchange
                    .instances
                    .insert(id, Instance { line, parts })
                    .is_some()
                {
                    return Err(Location::new(self.path, line)
                        .error(format!("#{id}: the instance number is used twice")));
                }
            }
            Body::Skipped(name) => {
                let count = exchange.others.entry(name).or_insert(0);
                if *count == 0 {
                    self.held += 64;
                }
                *count += 1;
            }
        }
        self.current = None;
        Ok(())
    }

    /// Reads `KEYWORD ( params )` parts up to `;` (the instance's `=` read), keeping their
    /// parameters when `wanted` holds one of the names.
    fn instance_body(&mut self, wanted: &dyn Fn(&str) -> bool) -> Result<Body, IoError> {
        match self.token()? {
            Token::Keyword(name) => {
                self.expect(Token::Open, "'(' after the entity's name")?;
                let body = if wanted(&name) {
                    let params = self.params(1)?;
                    Body::Kept(vec![Part { name, params }])
                } else {
                    self.skip_params()?;
                    Body::Skipped(name.into())
                };
                self.expect(Token::Semicolon, "';' after the entity")?;
                Ok(body)
            }
            Token::Open => {
                // A complex instance: parts until the closing ')'. They are few and small
                // (units, contexts, rational B-splines): read them all, keep them if wanted.
                let mut parts = Vec::new();
                loop {
                    match self.token()? {
                        Token::Keyword(name) => {
                            self.expect(Token::Open, "'(' after the entity's name")?;
                            let params = self.params(1)?;
                            parts.push(Part { name, params });
                        }
                        Token::Close => break,
                        other => return Err(self.unexpected(&other, "an entity name or ')'")),
                    }
                }
                self.expect(Token::Semicolon, "';' after the entity")?;
                if parts.iter().any(|p| wanted(&p.name)) {
                    Ok(Body::Kept(parts))
                } else {
                    let names: Vec<&str> = parts.iter().map(|p| &*p.name).collect();
                    Ok(Body::Skipped(names.join("+")))
                }
            }
            other => Err(self.unexpected(&other, "an entity name or '('")),
        }
    }
}

/// What [`Reader::instance_body`] did with an instance.
enum Body {
    /// Its parts, kept.
    Kept(Vec<Part>),
    /// Its type name (the names of a complex instance joined by `+`), not kept.
    Skipped(String),
}

/// What a token is, for messages.
fn describe(token: &Token) -> String {
    match token {
        Token::Instance(id) => format!("#{id}"),
        Token::Keyword(k) => format!("'{}'", crate::input::excerpt(k)),
        Token::Str(_) => "a string".into(),
        Token::Enum(e) => format!(".{}.", crate::input::excerpt(e)),
        Token::Int(i) => i.to_string(),
        Token::Real(x) => x.to_string(),
        Token::Binary => "a binary value".into(),
        Token::Unset => "'$'".into(),
        Token::Derived => "'*'".into(),
        Token::Open => "'('".into(),
        Token::Close => "')'".into(),
        Token::Comma => "','".into(),
        Token::Semicolon => "';'".into(),
        Token::Equals => "'='".into(),
        Token::End => "the end of the file".into(),
    }
}

/// Reads the exchange structure of `reader` (the file `path`): its header is checked for
/// form and skipped; of its data sections, the instances whose type (or one of whose
/// parts') `wanted` accepts are kept.
///
/// Errors ([`IoError::Parse`], naming the line and the instance): a file that does not start
/// with `ISO-10303-21;`, a token that is not Part 21 (binary data), a truncated file, an
/// instance number given twice, nesting beyond [`MAX_DEPTH`], more kept than the memory cap.
pub(crate) fn read_exchange(
    path: &Path,
    reader: &mut dyn BufRead,
    wanted: &dyn Fn(&str) -> bool,
) -> Result<Exchange, IoError> {
    let mut r = Reader {
        path,
        bytes: Bytes {
            reader,
            line: 1,
            peeked: None,
        },
        current: None,
        held: 0,
    };
    match r.token()? {
        Token::Keyword(k) if &*k == "ISO-10303-21" => {}
        _ => {
            return Err(Location::new(path, 1)
                .error("not a STEP file: it does not start with ISO-10303-21;"))
        }
    }
    r.expect(Token::Semicolon, "';' after ISO-10303-21")?;
    let mut exchange = Exchange::default();
    let mut in_data = false;
    loop {
        let token = r.token()?;
        match token {
            Token::Keyword(k) if &*k == "END-ISO-10303-21" => {
                r.expect(Token::Semicolon, "';' after END-ISO-10303-21")?;
                return Ok(exchange);
            }
            Token::Keyword(k) if &*k == "HEADER" => {
                r.expect(Token::Semicolon, "';' after HEADER")?
            }
            Token::Keyword(k) if &*k == "DATA" => {
                r.data_section_start()?;
                in_data = true;
            }
            Token::Keyword(k) if &*k == "ENDSEC" => {
                r.expect(Token::Semicolon, "';' after ENDSEC")?;
                in_data = false;
            }
            Token::Keyword(_) if !in_data => {
                // A header entity (FILE_DESCRIPTION, FILE_NAME, FILE_SCHEMA, ...).
                r.expect(Token::Open, "'(' after a header entity's name")?;
                r.skip_params()?;
                r.expect(Token::Semicolon, "';' after a header entity")?;
            }
            Token::Instance(id) if in_data => r.instance(id, wanted, &mut exchange)?,
            Token::End => {
                return Err(r.error("the file ends before END-ISO-10303-21; (truncated?)"));
            }
            other => {
                return Err(r.unexpected(
                    &other,
                    if in_data {
                        "an instance '#n=...;' or ENDSEC"
                    } else {
                        "HEADER, DATA or a section's end"
                    },
                ))
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn read(text: &str) -> Result<Exchange, IoError> {
        let mut bytes = text.as_bytes();
        read_exchange(Path::new("t.step"), &mut bytes, &|n| n != "SKIPPED")
    }

    fn message(text: &str) -> String {
        read(text).unwrap_err().to_string()
    }

    const HEAD: &str =
        "ISO-10303-21;\nHEADER;\nFILE_NAME('a ''b''',$,(''),(),'x','y','z');\nENDSEC;\nDATA;\n";

    #[test]
    fn instances_simple_and_complex_with_every_kind_of_value() {
        let text = format!(
            "{HEAD}#1=CARTESIAN_POINT('p',(0.,-1.5E-3,+2));\n/* a comment ; */\n#2=( LENGTH_UNIT() NAMED_UNIT(*) SI_UNIT(.MILLI.,.METRE.) );\n#3 = SKIPPED('x', #1);\n#4=U(LENGTH_MEASURE(1.E-07),$,\"0FF\",'it''s',\n(#1,#2));\nENDSEC;\nEND-ISO-10303-21;\n"
        );
        let e = read(&text).unwrap();
        assert_eq!(e.instances.len(), 3);
        assert_eq!(e.others.get("SKIPPED"), Some(&1));
        let p = &e.instances[&1];
        assert_eq!(p.line, 6);
        assert_eq!(
            p.parts[0].params[1],
            Value::List(vec![Value::Real(0.0), Value::Real(-1.5e-3), Value::Int(2)])
        );
        let u = &e.instances[&2];
        assert_eq!(u.parts.len(), 3);
        assert_eq!(
            u.part("SI_UNIT").unwrap().params[0],
            Value::Enum("MILLI".into())
        );
        assert_eq!(u.part("NAMED_UNIT").unwrap().params[0], Value::Derived);
        let v = &e.instances[&4];
        assert_eq!(v.line, 10);
        assert_eq!(
            v.parts[0].params[0],
            Value::Typed("LENGTH_MEASURE".into(), Box::new(Value::Real(1e-7)))
        );
        assert_eq!(v.parts[0].params[2], Value::Binary);
        assert_eq!(v.parts[0].params[3], Value::Str("it's".into()));
    }

    #[test]
    fn bad_files_are_refused_with_the_line_and_instance() {
        assert!(message("HELLO").contains("t.step:1: not a STEP file"));
        let truncated = format!("{HEAD}#1=CARTESIAN_POINT('p',(0.,1.");
        let m = message(&truncated);
        assert!(m.contains("t.step:6: #1: the file ends"), "{m}");
        let m = message(&format!(
            "{HEAD}#1=A(1);\n#1=B(2);\nENDSEC;END-ISO-10303-21;"
        ));
        assert!(
            m.contains("t.step:7: #1: the instance number is used twice"),
            "{m}"
        );
        let m = message(&format!("{HEAD}#1=A(1);\n#2=B(\x00);"));
        assert!(m.contains("t.step:7: #2: unexpected byte"), "{m}");
        let m = message(&format!("{HEAD}#1=A(1);\n#2=B('x\x01y');"));
        assert!(m.contains("t.step:7: #2: a control byte (0x01)"), "{m}");
        let deep = format!("{HEAD}#1=A({}1{});", "(".repeat(40), ")".repeat(40));
        assert!(message(&deep).contains("nested more than 32"));
        let m = message(&format!("{HEAD}#1=A(1)\n#2=B(2);"));
        assert!(
            m.contains("#1: #2 where ';' after the entity was expected"),
            "{m}"
        );
        let m = message(&format!("{HEAD}#1=A('abc);\n"));
        assert!(m.contains("t.step:6: #1: a string is never closed"), "{m}");
        let m = message(&format!("{HEAD}#1=A(1);\nENDSEC;\n"));
        assert!(m.contains("ends before END-ISO-10303-21"), "{m}");
        let m = message(&format!("{HEAD}#1=A(1.E999);"));
        assert!(m.contains("too large"), "{m}");
    }
}

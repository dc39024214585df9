//! Typed access to the parameters of a STEP instance, with errors that name the instance,
//! its entity type, its line and the parameter.

use std::path::Path;

use super::step_syntax::{Instance, Part, Value};
use crate::error::{IoError, Location};

/// The parameters of one part of an instance, read by position.
pub(crate) struct Args<'a> {
    pub path: &'a Path,
    pub id: u64,
    pub line: usize,
    pub name: &'a str,
    pub params: &'a [Value],
}

impl<'a> Args<'a> {
    /// The part `part` of `instance` number `id`.
    pub(crate) fn of(path: &'a Path, id: u64, instance: &'a Instance, part: &'a Part) -> Self {
        Args {
            path,
            id,
            line: instance.line,
            name: &part.name,
            params: &part.params,
        }
    }

    /// An error about this instance.
    pub fn error(&self, message: impl AsRef<str>) -> IoError {
        Location::new(self.path, self.line).error(format!(
            "#{} ({}): {}",
            self.id,
            self.name,
            message.as_ref()
        ))
    }

    /// Fails unless there are exactly `n` parameters.
    pub fn count(&self, n: usize) -> Result<(), IoError> {
        if self.params.len() == n {
            Ok(())
        } else {
            Err(self.error(format!(
                "has {} parameters, {n} expected",
                self.params.len()
            )))
        }
    }

    fn at(&self, i: usize) -> Result<&'a Value, IoError> {
        self.params.get(i).ok_or_else(|| {
            self.error(format!(
                "has {} parameters, at least {} expected",
                self.params.len(),
                i + 1
            ))
        })
    }

    fn wrong(&self, i: usize, want: &str, got: &Value) -> IoError {
        self.error(format!(
            "parameter {} must be {want}, not {}",
            i + 1,
            kind(got)
        ))
    }

    /// Parameter `i` as a real (an integer is taken as a real; a typed measure is unwrapped).
    pub fn real(&self, i: usize) -> Result<f64, IoError> {
        let v = self.at(i)?;
        real_of(v).ok_or_else(|| self.wrong(i, "a number", v))
    }

    /// Parameter `i` as an integer.
    pub fn int(&self, i: usize) -> Result<i64, IoError> {
        match self.at(i)? {
            Value::Int(k) => Ok(*k),
            v => Err(self.wrong(i, "an integer", v)),
        }
    }

    /// Parameter `i` as a reference `#n`.
    pub fn reference(&self, i: usize) -> Result<u64, IoError> {
        match self.at(i)? {
            Value::Ref(r) => Ok(*r),
            v => Err(self.wrong(i, "a reference #n", v)),
        }
    }

    /// Parameter `i` as a reference, or `None` when unset (`$`).
    pub fn optional_reference(&self, i: usize) -> Result<Option<u64>, IoError> {
        match self.at(i)? {
            Value::Ref(r) => Ok(Some(*r)),
            Value::Unset => Ok(None),
            v => Err(self.wrong(i, "a reference #n or $", v)),
        }
    }

    /// Parameter `i` as a list.
    pub fn list(&self, i: usize) -> Result<&'a [Value], IoError> {
        match self.at(i)? {
            Value::List(l) => Ok(l),
            v => Err(self.wrong(i, "a list", v)),
        }
    }

    /// Parameter `i` as a list of references.
    pub fn references(&self, i: usize) -> Result<Vec<u64>, IoError> {
        self.list(i)?
            .iter()
            .map(|v| match v {
                Value::Ref(r) => Ok(*r),
                other => Err(self.wrong(i, "a list of references", other)),
            })
            .collect()
    }

    /// Parameter `i` as a list of numbers.
    pub fn reals(&self, i: usize) -> Result<Vec<f64>, IoError> {
        self.list(i)?
            .iter()
            .map(|v| real_of(v).ok_or_else(|| self.wrong(i, "a list of numbers", v)))
            .collect()
    }

    /// Parameter `i` as a list of integers.
    pub fn ints(&self, i: usize) -> Result<Vec<i64>, IoError> {
        self.list(i)?
            .iter()
            .map(|v| match v {
                Value::Int(k) => Ok(*k),
                other => Err(self.wrong(i, "a list of integers", other)),
            })
            .collect()
    }

    /// Parameter `i` as a logical: `.T.` true, `.F.` false, `.U.` (unknown) as `unknown`.
    pub fn logical(&self, i: usize, unknown: bool) -> Result<bool, IoError> {
        match self.at(i)? {
            Value::Enum(e) if &**e == "T" => Ok(true),
            Value::Enum(e) if &**e == "F" => Ok(false),
            Value::Enum(e) if &**e == "U" => Ok(unknown),
            v => Err(self.wrong(i, "a logical .T. or .F.", v)),
        }
    }

    /// Parameter `i` as an enumeration value (dots removed), or `None` when unset.
    pub fn enumeration(&self, i: usize) -> Result<Option<&'a str>, IoError> {
        match self.at(i)? {
            Value::Enum(e) => Ok(Some(e)),
            Value::Unset => Ok(None),
            v => Err(self.wrong(i, "an enumeration value", v)),
        }
    }
}

/// A number (integer, real or typed measure).
pub(crate) fn real_of(v: &Value) -> Option<f64> {
    match v {
        Value::Real(x) => Some(*x),
        Value::Int(k) => Some(*k as f64),
        Value::Typed(_, inner) => real_of(inner),
        _ => None,
    }
}

/// What a value is, for messages.
fn kind(v: &Value) -> &'static str {
    match v {
        Value::Ref(_) => "a reference",
        Value::Int(_) => "an integer",
        Value::Real(_) => "a real",
        Value::Str(_) => "a string",
        Value::Enum(_) => "an enumeration value",
        Value::List(_) => "a list",
        Value::Typed(..) => "a typed value",
        Value::Unset => "unset ($)",
        Value::Derived => "derived (*)",
        Value::Binary => "a binary value",
    }
}

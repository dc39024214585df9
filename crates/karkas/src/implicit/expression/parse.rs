//! Recursive descent over the characters of an expression, with 1-based positions in its
//! errors, emitting the syntax tree in postfix order.
//!
//! Grammar (the usual precedence of mathematics):
//!
//! ```text
//! sum     = product (('+' | '-') product)*
//! product = unary (('*' | '/') unary)*
//! unary   = ('-' | '+')* power                     -x^2 is -(x^2)
//! power   = primary ('^' unary)?                   right-associative: 2^3^2 = 2^9; 2^-1
//! primary = number | name | function '(' sum ')' | '(' sum ')'
//! ```
//!
//! The recursion runs through `sum`, a unary minus and `^`; each of these counts one level
//! of nesting, and more than [`MAX_DEPTH`] levels is an error. Repetition (`x+x+...`,
//! `++x`) is a loop, so no input of any length can exhaust the stack.

use super::function::Function;
use super::program::{Op, Program};
use crate::{Error, Result};

/// Deepest nesting of parentheses, functions, unary minus and powers accepted.
pub(super) const MAX_DEPTH: usize = 32;

/// Parses `text` into a [`Program`].
pub(super) fn parse(text: &str) -> Result<Program> {
    let mut parser = Parser {
        chars: text.chars().collect(),
        at: 0,
        depth: 0,
        ops: Vec::new(),
    };
    if parser.peek().is_none() {
        return parser.error(0, "the expression is empty");
    }
    parser.sum()?;
    match parser.peek() {
        None => Ok(Program::new(parser.ops)),
        Some(')') => parser.error(parser.at, "')' without a matching '('"),
        Some(c) => parser.error(parser.at, format!("expected an operator, found '{c}'")),
    }
}

struct Parser {
    chars: Vec<char>,
    at: usize,
    depth: usize,
    ops: Vec<Op>,
}

impl Parser {
    fn error<T>(&self, position: usize, message: impl Into<String>) -> Result<T> {
        Err(Error::ExpressionParse {
            position: position + 1,
            message: message.into(),
        })
    }

    /// One level deeper, or an error at the current position beyond [`MAX_DEPTH`].
    fn enter(&mut self) -> Result<()> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return self.error(self.at, format!("nested deeper than {MAX_DEPTH} levels"));
        }
        Ok(())
    }

    fn skip_spaces(&mut self) {
        while self.chars.get(self.at).is_some_and(|c| c.is_whitespace()) {
            self.at += 1;
        }
    }

    fn peek(&mut self) -> Option<char> {
        self.skip_spaces();
        self.chars.get(self.at).copied()
    }

    /// `product (('+' | '-') product)*`, one level deeper.
    fn sum(&mut self) -> Result<()> {
        self.enter()?;
        self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.at += 1;
            self.product()?;
            self.ops
                .push(if op == '+' { Op::Add } else { Op::Subtract });
        }
        self.depth -= 1;
        Ok(())
    }

    /// `unary (('*' | '/') unary)*`
    fn product(&mut self) -> Result<()> {
        self.unary()?;
        while let Some(op @ ('*' | '/')) = self.peek() {
            self.at += 1;
            self.unary()?;
            self.ops
                .push(if op == '*' { Op::Multiply } else { Op::Divide });
        }
        Ok(())
    }

    /// `('-' | '+')* power`: each minus one level deeper, a plus ignored.
    fn unary(&mut self) -> Result<()> {
        let mut negations = 0;
        loop {
            match self.peek() {
                Some('-') => {
                    self.at += 1;
                    self.enter()?;
                    negations += 1;
                }
                Some('+') => self.at += 1,
                _ => break,
            }
        }
        self.power()?;
        self.ops.extend(core::iter::repeat_n(Op::Negate, negations));
        self.depth -= negations;
        Ok(())
    }

    /// `primary ('^' unary)?`, right-associative (`2^-1` is allowed).
    fn power(&mut self) -> Result<()> {
        self.primary()?;
        if self.peek() == Some('^') {
            self.at += 1;
            self.enter()?;
            self.unary()?;
            self.depth -= 1;
            self.ops.push(Op::Power);
        }
        Ok(())
    }

    fn primary(&mut self) -> Result<()> {
        match self.peek() {
            None => self.error(
                self.chars.len(),
                "the expression ends where an operand is expected",
            ),
            Some('(') => self.parenthesised(),
            Some(c) if c.is_ascii_digit() || c == '.' => self.number(),
            Some(c) if c.is_alphabetic() || c == '_' => self.name(),
            Some(c) => self.error(
                self.at,
                format!("expected a number, a variable, a function or '(', found '{c}'"),
            ),
        }
    }

    /// `'(' sum ')'`, at a `'('`.
    fn parenthesised(&mut self) -> Result<()> {
        let open = self.at;
        self.at += 1;
        self.sum()?;
        if self.peek() != Some(')') {
            return self.error(open, "'(' is never closed");
        }
        self.at += 1;
        Ok(())
    }

    fn number(&mut self) -> Result<()> {
        let start = self.at;
        let digits = |chars: &[char], mut k: usize| {
            while chars.get(k).is_some_and(|c| c.is_ascii_digit()) {
                k += 1;
            }
            k
        };
        let mut end = digits(&self.chars, start);
        if self.chars.get(end) == Some(&'.') {
            end = digits(&self.chars, end + 1);
        }
        if matches!(self.chars.get(end), Some('e' | 'E')) {
            let mut k = end + 1;
            if matches!(self.chars.get(k), Some('+' | '-')) {
                k += 1;
            }
            let after = digits(&self.chars, k);
            if after > k {
                end = after;
            }
        }
        let text: String = self.chars[start..end].iter().collect();
        let Ok(value) = text.parse::<f64>() else {
            return self.error(start, format!("'{text}' is not a number"));
        };
        self.at = end;
        if self
            .chars
            .get(end)
            .is_some_and(|c| c.is_alphanumeric() || *c == '(')
        {
            return self.error(
                end,
                "a number must be followed by an operator (write 2*x, not 2x)",
            );
        }
        self.ops.push(Op::Number(value));
        Ok(())
    }

    fn name(&mut self) -> Result<()> {
        let start = self.at;
        let mut end = start;
        while self
            .chars
            .get(end)
            .is_some_and(|c| c.is_alphanumeric() || *c == '_')
        {
            end += 1;
        }
        let name: String = self.chars[start..end].iter().collect();
        self.at = end;
        let leaf = match name.as_str() {
            "x" => Some(Op::Variable(0)),
            "y" => Some(Op::Variable(1)),
            "z" => Some(Op::Variable(2)),
            "pi" | "PI" | "π" => Some(Op::Number(core::f64::consts::PI)),
            "e" => Some(Op::Number(core::f64::consts::E)),
            _ => None,
        };
        if let Some(op) = leaf {
            self.ops.push(op);
            return Ok(());
        }
        let Some(function) = Function::named(&name) else {
            return self.error(
                start,
                format!("unknown name '{name}' (variables are x, y, z)"),
            );
        };
        if self.peek() != Some('(') {
            return self.error(
                self.at,
                format!("'{name}' needs its argument in parentheses"),
            );
        }
        self.parenthesised()?;
        self.ops.push(Op::Call(function));
        Ok(())
    }
}

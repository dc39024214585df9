//! Implicit surfaces from an expression `F(x, y, z)` typed by a user.
//!
//! Evaluation and the symbolic first and second partial derivatives are done by the `exmex`
//! crate. In front of it sits a small recursive-descent parser, hand-written for two reasons
//! `exmex` does not cover: errors that name the character position where the expression goes
//! wrong, and the usual precedence of mathematics (`-x^2` is `-(x^2)`, `2^3^2` is `2^(3^2)`,
//! numbers like `1e-3`), which `exmex` reads differently. The checked expression is handed to
//! `exmex` fully parenthesised, so both agree on its meaning.
//!
//! Grammar: `+ - * / ^` (`^` binds tightest and to the right, then unary `-`/`+`), numbers
//! (`2`, `0.5`, `1e-3`), the variables `x`, `y`, `z`, the constants `pi` and `e`, and the
//! functions `sin cos tan asin acos atan sinh cosh tanh exp ln log log2 log10 sqrt` applied
//! with parentheses.

use super::surface::{ImplicitSurface, Matrix3};
use crate::{Error, Point3, Result};
use exmex::{Differentiate, Express, FlatEx};

/// Functions accepted in expressions (all differentiable by `exmex`).
const FUNCTIONS: [&str; 15] = [
    "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "ln", "log",
    "log2", "log10", "sqrt",
];

/// Longest expression accepted, in characters.
const MAX_LENGTH: usize = 1_000;

/// Deepest nesting of parentheses, functions and operators accepted: `exmex` works
/// recursively, so the depth bounds its stack use, and with the length it bounds the size
/// of the symbolic second derivatives (which grows with the square of the depth).
const MAX_DEPTH: usize = 32;

/// Stack of the thread that runs `exmex`'s parser and differentiation: they recurse with
/// large frames (several megabytes for ordinary expressions in unoptimised builds).
const EXMEX_STACK: usize = 256 << 20;

/// An implicit surface `F(x, y, z) = 0` given as an expression.
#[derive(Clone, Debug)]
pub struct ExpressionSurface {
    text: String,
    value: Compiled,
    gradient: [Compiled; 3],
    /// `F_xx, F_xy, F_xz, F_yy, F_yz, F_zz`.
    hessian: [Compiled; 6],
}

/// One expression in `exmex` form, with the positions of its variables in `(x, y, z)`.
#[derive(Clone, Debug)]
struct Compiled {
    /// `None` when the expression is identically zero (a derivative by an absent variable).
    /// Boxed: a `FlatEx` keeps its nodes inline and is about 20 KB.
    expr: Option<Box<FlatEx<f64>>>,
    slots: Vec<usize>,
}

impl Compiled {
    fn new(expr: FlatEx<f64>) -> Self {
        let slots = expr
            .var_names()
            .iter()
            .map(|name| match name.as_str() {
                "x" => 0,
                "y" => 1,
                _ => 2,
            })
            .collect();
        Compiled {
            expr: Some(Box::new(expr)),
            slots,
        }
    }

    /// The derivative by the variable in slot `axis` (0, 1, 2 for x, y, z).
    fn partial(&self, axis: usize) -> Result<Self> {
        let Some(expr) = &self.expr else {
            return Ok(self.clone());
        };
        let Some(index) = self.slots.iter().position(|&s| s == axis) else {
            return Ok(Compiled {
                expr: None,
                slots: Vec::new(),
            });
        };
        let derived = (**expr)
            .clone()
            .partial(index)
            .map_err(|e| Error::ExpressionParse {
                position: 1,
                message: format!("cannot differentiate: {}", first_line(e.msg())),
            })?;
        Ok(Compiled::new(derived))
    }

    #[inline]
    fn eval(&self, p: Point3) -> f64 {
        let Some(expr) = &self.expr else {
            return 0.0;
        };
        let mut args = [0.0; 3];
        for (a, &s) in args.iter_mut().zip(&self.slots) {
            *a = p[s];
        }
        expr.eval(&args[..self.slots.len()]).unwrap_or(f64::NAN)
    }
}

fn first_line(s: &str) -> &str {
    s.lines().next().unwrap_or(s)
}

impl ExpressionSurface {
    /// Parses `text` as `F(x, y, z)` and prepares its first and second partial derivatives.
    ///
    /// Errors: [`Error::ExpressionParse`] with the 1-based character position of the first
    /// problem (an unknown name, a missing operand or parenthesis, a stray character).
    pub fn parse(text: &str) -> Result<Self> {
        if text.chars().count() > MAX_LENGTH {
            return Err(Error::ExpressionParse {
                position: MAX_LENGTH + 1,
                message: format!("the expression is longer than {MAX_LENGTH} characters"),
            });
        }
        let tree = Parser::new(text).parse()?;
        let mut canonical = String::new();
        emit(&tree, &mut canonical);
        // `exmex` recurses deeply: give it a thread with a stack of its own, so that the
        // depth allowed by the parser is safe whatever the caller's stack.
        let work = move || -> Result<(Compiled, [Compiled; 3], [Compiled; 6])> {
            let flat = exmex::parse::<f64>(&canonical).map_err(|e| Error::ExpressionParse {
                position: 1,
                message: first_line(e.msg()).to_owned(),
            })?;
            let value = Compiled::new(flat);
            let gradient = [value.partial(0)?, value.partial(1)?, value.partial(2)?];
            let hessian = [
                gradient[0].partial(0)?,
                gradient[0].partial(1)?,
                gradient[0].partial(2)?,
                gradient[1].partial(1)?,
                gradient[1].partial(2)?,
                gradient[2].partial(2)?,
            ];
            Ok((value, gradient, hessian))
        };
        let (value, gradient, hessian) = std::thread::Builder::new()
            .stack_size(EXMEX_STACK)
            .spawn(work)
            .map_err(|e| Error::InvalidInput(format!("cannot start the expression parser: {e}")))?
            .join()
            .unwrap_or_else(|_| {
                Err(Error::ExpressionParse {
                    position: 1,
                    message: "the expression could not be differentiated".into(),
                })
            })?;
        Ok(ExpressionSurface {
            text: text.to_owned(),
            value,
            gradient,
            hessian,
        })
    }

    /// The expression as given.
    pub fn text(&self) -> &str {
        &self.text
    }
}

impl ImplicitSurface for ExpressionSurface {
    fn value(&self, p: Point3) -> f64 {
        self.value.eval(p)
    }

    fn gradient(&self, p: Point3) -> Point3 {
        Point3::new([
            self.gradient[0].eval(p),
            self.gradient[1].eval(p),
            self.gradient[2].eval(p),
        ])
    }

    fn hessian(&self, p: Point3) -> Matrix3 {
        let h: [f64; 6] = core::array::from_fn(|k| self.hessian[k].eval(p));
        [[h[0], h[1], h[2]], [h[1], h[3], h[4]], [h[2], h[4], h[5]]]
    }
}

/// The syntax tree of a checked expression.
#[derive(Clone, Debug, PartialEq)]
enum Node {
    Number(f64),
    Variable(char),
    Negate(Box<Node>),
    Binary(char, Box<Node>, Box<Node>),
    Call(&'static str, Box<Node>),
}

/// Writes `node` fully parenthesised in `exmex` syntax.
fn emit(node: &Node, out: &mut String) {
    match node {
        // Rust's `Display` of f64 never uses an exponent, which `exmex` would not read.
        Node::Number(v) => out.push_str(&format!("{v}")),
        Node::Variable(c) => out.push(*c),
        Node::Negate(a) => {
            out.push_str("(-(");
            emit(a, out);
            out.push_str("))");
        }
        Node::Binary(op, a, b) => {
            out.push_str("((");
            emit(a, out);
            out.push(')');
            out.push(*op);
            out.push('(');
            emit(b, out);
            out.push_str("))");
        }
        Node::Call(f, a) => {
            out.push_str(f);
            out.push_str("((");
            emit(a, out);
            out.push_str("))");
        }
    }
}

/// Recursive descent over the characters of the expression, with 1-based positions.
struct Parser {
    chars: Vec<char>,
    at: usize,
    depth: usize,
}

impl Parser {
    fn new(text: &str) -> Self {
        Parser {
            chars: text.chars().collect(),
            at: 0,
            depth: 0,
        }
    }

    fn error<T>(&self, position: usize, message: impl Into<String>) -> Result<T> {
        Err(Error::ExpressionParse {
            position: position + 1,
            message: message.into(),
        })
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

    fn parse(mut self) -> Result<Node> {
        if self.peek().is_none() {
            return self.error(0, "the expression is empty");
        }
        let node = self.sum()?;
        match self.peek() {
            None => Ok(node),
            Some(')') => self.error(self.at, "')' without a matching '('"),
            Some(c) => self.error(self.at, format!("expected an operator, found '{c}'")),
        }
    }

    /// `product (('+' | '-') product)*`, one level deeper.
    fn sum(&mut self) -> Result<Node> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return self.error(self.at, format!("nested deeper than {MAX_DEPTH} levels"));
        }
        let mut left = self.product()?;
        while let Some(op @ ('+' | '-')) = self.peek() {
            self.at += 1;
            let right = self.product()?;
            left = Node::Binary(op, Box::new(left), Box::new(right));
        }
        self.depth -= 1;
        Ok(left)
    }

    /// `unary (('*' | '/') unary)*`
    fn product(&mut self) -> Result<Node> {
        let mut left = self.unary()?;
        while let Some(op @ ('*' | '/')) = self.peek() {
            self.at += 1;
            let right = self.unary()?;
            left = Node::Binary(op, Box::new(left), Box::new(right));
        }
        Ok(left)
    }

    /// `('-' | '+') unary | power`
    fn unary(&mut self) -> Result<Node> {
        match self.peek() {
            Some('-') => {
                self.at += 1;
                self.depth += 1;
                if self.depth > MAX_DEPTH {
                    return self.error(self.at, format!("nested deeper than {MAX_DEPTH} levels"));
                }
                let inner = self.unary()?;
                self.depth -= 1;
                Ok(Node::Negate(Box::new(inner)))
            }
            Some('+') => {
                self.at += 1;
                self.unary()
            }
            _ => self.power(),
        }
    }

    /// `primary ('^' unary)?`, right-associative (`2^-1` is allowed).
    fn power(&mut self) -> Result<Node> {
        let base = self.primary()?;
        if self.peek() == Some('^') {
            self.at += 1;
            self.depth += 1;
            if self.depth > MAX_DEPTH {
                return self.error(self.at, format!("nested deeper than {MAX_DEPTH} levels"));
            }
            let exponent = self.unary()?;
            self.depth -= 1;
            return Ok(Node::Binary('^', Box::new(base), Box::new(exponent)));
        }
        Ok(base)
    }

    fn primary(&mut self) -> Result<Node> {
        match self.peek() {
            None => self.error(
                self.chars.len(),
                "the expression ends where an operand is expected",
            ),
            Some('(') => {
                let open = self.at;
                self.at += 1;
                let inner = self.sum()?;
                if self.peek() != Some(')') {
                    return self.error(open, "'(' is never closed");
                }
                self.at += 1;
                Ok(inner)
            }
            Some(c) if c.is_ascii_digit() || c == '.' => self.number(),
            Some(c) if c.is_alphabetic() || c == '_' => self.name(),
            Some(c) => self.error(
                self.at,
                format!("expected a number, a variable, a function or '(', found '{c}'"),
            ),
        }
    }

    fn number(&mut self) -> Result<Node> {
        let start = self.at;
        let mut end = self.at;
        let digits = |chars: &[char], mut k: usize| {
            while chars.get(k).is_some_and(|c| c.is_ascii_digit()) {
                k += 1;
            }
            k
        };
        end = digits(&self.chars, end);
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
        let value: f64 = match text.parse() {
            Ok(v) => v,
            Err(_) => return self.error(start, format!("'{text}' is not a number")),
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
        Ok(Node::Number(value))
    }

    fn name(&mut self) -> Result<Node> {
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
        match name.as_str() {
            "x" | "y" | "z" => return Ok(Node::Variable(name.chars().next().unwrap_or('x'))),
            "pi" | "PI" | "π" => return Ok(Node::Number(core::f64::consts::PI)),
            "e" => return Ok(Node::Number(core::f64::consts::E)),
            _ => {}
        }
        let Some(&function) = FUNCTIONS.iter().find(|f| **f == name) else {
            return self.error(
                start,
                format!("unknown name '{name}' (variables are x, y, z)"),
            );
        };
        if self.peek() != Some('(') {
            return self.error(
                self.at,
                format!("'{function}' needs its argument in parentheses"),
            );
        }
        let open = self.at;
        self.at += 1;
        let argument = self.sum()?;
        if self.peek() != Some(')') {
            return self.error(open, "'(' is never closed");
        }
        self.at += 1;
        Ok(Node::Call(function, Box::new(argument)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn position(text: &str) -> usize {
        match ExpressionSurface::parse(text) {
            Err(Error::ExpressionParse { position, .. }) => position,
            other => panic!("{text:?} parsed: {:?}", other.map(|s| s.text().to_owned())),
        }
    }

    #[test]
    fn errors_name_the_position() {
        assert_eq!(position("x^2+*y"), 5);
        assert_eq!(position("x^2+y^2-"), 9);
        assert_eq!(position("sin(x"), 4);
        assert_eq!(position("x^2 + w"), 7);
        assert_eq!(position("2x"), 2);
        assert_eq!(position("x)"), 2);
        assert_eq!(position(""), 1);
        assert_eq!(position("x y"), 3);
        assert_eq!(position("x # y"), 3);
        assert_eq!(position("sin x"), 5);
        assert_eq!(position(&"(".repeat(500)), 33);
        assert_eq!(position(&"-".repeat(500)), 33);
    }

    #[test]
    fn deep_and_long_expressions_stay_within_the_limits() {
        // Nested functions parse and differentiate; too long an expression is refused.
        let deep = format!("{}x{} - 1", "sin(".repeat(12), ")".repeat(12));
        let f = ExpressionSurface::parse(&deep).unwrap();
        assert!(f.gradient(Point3::new([0.3, 0.0, 0.0]))[0].is_finite());
        let long = "x+".repeat(600) + "x";
        assert!(ExpressionSurface::parse(&long).is_err());
    }

    #[test]
    fn precedence_is_the_usual_one() {
        let at = Point3::new([2.0, 3.0, 0.5]);
        let cases = [
            ("-x^2", -4.0),
            ("2^3^2", 512.0),
            ("-2^2", -4.0),
            ("x/2/2", 0.5),
            ("2*-x", -4.0),
            ("1e-3*x + 2E1", 20.002),
            ("x^-2", 0.25),
            ("-(x)^2 + +y", -1.0),
            ("sqrt(x*8) - ln(e) + pi*0", 3.0),
            ("x*y - z", 5.5),
        ];
        for (text, expected) in cases {
            let f = ExpressionSurface::parse(text).unwrap();
            assert!(
                (f.value(at) - expected).abs() < 1e-12,
                "{text}: {}",
                f.value(at)
            );
        }
    }

    #[test]
    fn derivatives_are_symbolic() {
        let f = ExpressionSurface::parse("x^2*y + sin(z) - x*z^3").unwrap();
        let p = Point3::new([1.5, -0.5, 0.7]);
        let (x, y, z) = (p[0], p[1], p[2]);
        let g = f.gradient(p);
        let expected = [2.0 * x * y - z.powi(3), x * x, z.cos() - 3.0 * x * z * z];
        for k in 0..3 {
            assert!((g[k] - expected[k]).abs() < 1e-12, "F_{k}");
        }
        let h = f.hessian(p);
        let expected = [
            [2.0 * y, 2.0 * x, -3.0 * z * z],
            [2.0 * x, 0.0, 0.0],
            [-3.0 * z * z, 0.0, -z.sin() - 6.0 * x * z],
        ];
        for a in 0..3 {
            for b in 0..3 {
                assert!((h[a][b] - expected[a][b]).abs() < 1e-12, "F_{a}{b}");
            }
        }
        // Every listed function differentiates twice.
        for name in FUNCTIONS {
            let f = ExpressionSurface::parse(&format!("{name}(0.3 + x*y*z/10) - 0.2")).unwrap();
            let h = f.hessian(Point3::new([0.5, 0.6, 0.7]));
            assert!(h.iter().flatten().all(|v| v.is_finite()), "{name}");
        }
    }
}

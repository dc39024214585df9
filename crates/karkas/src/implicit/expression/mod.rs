//! Implicit surfaces from an expression `F(x, y, z)` typed by a user.
//!
//! The expression is parsed by karkas's own recursive-descent parser ([`parse`]), whose errors
//! name the character position where the expression goes wrong, into a syntax tree that is
//! evaluated directly: in plain numbers for `F`, and in second-order forward-mode
//! differentiation ([`jet`]) for the gradient and the Hessian, all in one pass. Both are
//! written here because no maintained crate combines errors with positions, the usual
//! precedence of mathematics (`-x^2` is `-(x^2)`, `2^3^2` is `2^(3^2)`) and exact second
//! derivatives.
//!
//! Grammar: `+ - * / ^` (`^` binds tightest and to the right, then unary `-`/`+`), numbers
//! (`2`, `0.5`, `1e-3`), the variables `x`, `y`, `z`, the constants `pi` and `e`, and the
//! functions `sin cos tan asin acos atan sinh cosh tanh exp ln log log2 log10 sqrt` applied
//! with parentheses (`log` is the natural logarithm, as `ln`).

#[cfg(test)]
mod derivative_tests;
mod function;
mod jet;
mod parse;
mod program;

use super::surface::{ImplicitSurface, Matrix3};
use crate::{Error, Point3, Result};
use jet::Jet;
use program::Program;

/// Longest expression accepted, in characters.
const MAX_LENGTH: usize = 1_000;

/// An implicit surface `F(x, y, z) = 0` given as an expression.
#[derive(Clone, Debug)]
pub struct ExpressionSurface {
    text: String,
    program: Program,
}

impl ExpressionSurface {
    /// Parses `text` as `F(x, y, z)`; its first and second partial derivatives are exact
    /// (forward-mode differentiation).
    ///
    /// Errors: [`Error::ExpressionParse`] with the 1-based character position of the first
    /// problem (an unknown name, a missing operand or parenthesis, a stray character, nesting
    /// deeper than 32 levels, more than 1000 characters).
    ///
    /// # Examples
    ///
    /// ```
    /// use karkas::implicit::{ExpressionSurface, ImplicitSurface};
    /// use karkas::Point;
    ///
    /// let sphere = ExpressionSurface::parse("x*x + y*y + z*z - 4")?;
    /// assert_eq!(sphere.value(Point([2.0, 0.0, 0.0])), 0.0);
    /// assert!(sphere.gradient(Point([0.0, 2.0, 0.0])).distance(Point([0.0, 4.0, 0.0])) < 1e-12);
    /// assert!(ExpressionSurface::parse("x +").is_err());
    /// # Ok::<(), karkas::Error>(())
    /// ```
    pub fn parse(text: &str) -> Result<Self> {
        if text.chars().count() > MAX_LENGTH {
            return Err(Error::ExpressionParse {
                position: MAX_LENGTH + 1,
                message: format!("the expression is longer than {MAX_LENGTH} characters"),
            });
        }
        Ok(ExpressionSurface {
            text: text.to_owned(),
            program: parse::parse(text)?,
        })
    }

    /// The expression as given.
    pub fn text(&self) -> &str {
        &self.text
    }

    fn jet(&self, p: Point3) -> Jet {
        self.program.eval::<Jet>(p)
    }
}

impl ImplicitSurface for ExpressionSurface {
    fn value(&self, p: Point3) -> f64 {
        self.program.eval::<f64>(p)
    }

    fn gradient(&self, p: Point3) -> Point3 {
        Point3::new(self.jet(p).gradient)
    }

    fn hessian(&self, p: Point3) -> Matrix3 {
        self.jet(p).hessian
    }
}

#[cfg(test)]
mod tests {
    use super::function::FUNCTIONS;
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

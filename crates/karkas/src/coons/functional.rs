//! Linear functionals on functions of one parameter (Chashnikov, formulas (1), (5), (15)).
//!
//! A Coons-type surface is defined by what each blending direction "measures" of a function:
//! its value at a point, a derivative at a point, and so on. The same functional applies to a
//! vector-valued curve (coordinate by coordinate, the paper's `\vec L`) and to a scalar blending
//! function.

use crate::{Curve, Point};

/// A linear functional `L` on functions of one parameter: what a blending family interpolates.
///
/// The enum is `#[non_exhaustive]`: more kinds (integrals, one-sided derivatives) can be added
/// without breaking callers.
#[derive(Clone, Copy, Debug, PartialEq)]
#[non_exhaustive]
pub enum Functional {
    /// `L(f) = f(at)`.
    Value {
        /// The parameter where the value is taken.
        at: f64,
    },
    /// `L(f) = f^(order)(at)`, the derivative of order `order >= 1`.
    Derivative {
        /// The parameter where the derivative is taken.
        at: f64,
        /// The derivative order.
        order: usize,
    },
}

impl Functional {
    /// The parameter the functional looks at.
    pub fn at(&self) -> f64 {
        match *self {
            Functional::Value { at } | Functional::Derivative { at, .. } => at,
        }
    }

    /// The derivative order the functional takes (0 for a value).
    pub fn order(&self) -> usize {
        match *self {
            Functional::Value { .. } => 0,
            Functional::Derivative { order, .. } => order,
        }
    }

    /// The functional applied to a curve, coordinate by coordinate: `curve.deriv(at, order)`.
    pub fn apply<const D: usize, C: Curve<D> + ?Sized>(&self, curve: &C) -> Point<D> {
        curve.deriv(self.at(), self.order())
    }

    /// A short description for messages, with `variable` the parameter's name:
    /// `"the value"`, `"d/du"`, `"d^2/du^2"`.
    pub fn describe(&self, variable: char) -> String {
        match self.order() {
            0 => "the value".to_owned(),
            1 => format!("d/d{variable}"),
            k => format!("d^{k}/d{variable}^{k}"),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn accessors_and_descriptions() {
        let v = Functional::Value { at: 0.25 };
        let d = Functional::Derivative { at: 1.0, order: 2 };
        assert_eq!((v.at(), v.order()), (0.25, 0));
        assert_eq!((d.at(), d.order()), (1.0, 2));
        assert_eq!(v.describe('u'), "the value");
        assert_eq!(
            Functional::Derivative { at: 0.0, order: 1 }.describe('v'),
            "d/dv"
        );
        assert_eq!(d.describe('u'), "d^2/du^2");
    }
}

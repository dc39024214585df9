//! The functions an expression may call, with their first and second derivatives.

/// A function of the expression grammar.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(super) enum Function {
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    Exp,
    /// The natural logarithm (`ln` and `log`).
    Ln,
    Log2,
    Log10,
    Sqrt,
}

/// Every function name accepted (as [`Function::named`] reads them), for the tests.
#[cfg(test)]
pub(super) const FUNCTIONS: [&str; 15] = [
    "sin", "cos", "tan", "asin", "acos", "atan", "sinh", "cosh", "tanh", "exp", "ln", "log",
    "log2", "log10", "sqrt",
];

impl Function {
    /// The function named `name`, if any.
    pub(super) fn named(name: &str) -> Option<Function> {
        Some(match name {
            "sin" => Function::Sin,
            "cos" => Function::Cos,
            "tan" => Function::Tan,
            "asin" => Function::Asin,
            "acos" => Function::Acos,
            "atan" => Function::Atan,
            "sinh" => Function::Sinh,
            "cosh" => Function::Cosh,
            "tanh" => Function::Tanh,
            "exp" => Function::Exp,
            "ln" | "log" => Function::Ln,
            "log2" => Function::Log2,
            "log10" => Function::Log10,
            "sqrt" => Function::Sqrt,
            _ => return None,
        })
    }

    /// `g(u)`.
    pub(super) fn value(self, u: f64) -> f64 {
        match self {
            Function::Sin => u.sin(),
            Function::Cos => u.cos(),
            Function::Tan => u.tan(),
            Function::Asin => u.asin(),
            Function::Acos => u.acos(),
            Function::Atan => u.atan(),
            Function::Sinh => u.sinh(),
            Function::Cosh => u.cosh(),
            Function::Tanh => u.tanh(),
            Function::Exp => u.exp(),
            Function::Ln => u.ln(),
            Function::Log2 => u.log2(),
            Function::Log10 => u.log10(),
            Function::Sqrt => u.sqrt(),
        }
    }

    /// `[g(u), g'(u), g''(u)]`.
    pub(super) fn derivatives(self, u: f64) -> [f64; 3] {
        let g = self.value(u);
        let [first, second] = match self {
            Function::Sin => [u.cos(), -g],
            Function::Cos => [-u.sin(), -g],
            // tan' = 1 + tan^2, tan'' = 2 tan (1 + tan^2).
            Function::Tan => {
                let s = 1.0 + g * g;
                [s, 2.0 * g * s]
            }
            // asin' = (1 - u^2)^(-1/2), asin'' = u (1 - u^2)^(-3/2); acos' = -asin'.
            Function::Asin | Function::Acos => {
                let r = 1.0 / (1.0 - u * u).sqrt();
                let sign = if self == Function::Asin { 1.0 } else { -1.0 };
                [sign * r, sign * u * r * r * r]
            }
            // atan' = 1/(1 + u^2), atan'' = -2u/(1 + u^2)^2.
            Function::Atan => {
                let d = 1.0 / (1.0 + u * u);
                [d, -2.0 * u * d * d]
            }
            Function::Sinh => [u.cosh(), g],
            Function::Cosh => [u.sinh(), g],
            // tanh' = 1 - tanh^2, tanh'' = -2 tanh (1 - tanh^2).
            Function::Tanh => {
                let s = 1.0 - g * g;
                [s, -2.0 * g * s]
            }
            Function::Exp => [g, g],
            Function::Ln => [1.0 / u, -1.0 / (u * u)],
            Function::Log2 => [
                1.0 / (u * core::f64::consts::LN_2),
                -1.0 / (u * u * core::f64::consts::LN_2),
            ],
            Function::Log10 => [
                1.0 / (u * core::f64::consts::LN_10),
                -1.0 / (u * u * core::f64::consts::LN_10),
            ],
            // sqrt' = 1/(2 sqrt u), sqrt'' = -1/(4 u sqrt u).
            Function::Sqrt => [0.5 / g, -0.25 / (u * g)],
        };
        [g, first, second]
    }
}

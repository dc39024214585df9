//! Forward-mode differentiation to second order: a number carried with its gradient and
//! Hessian by `x, y, z`, so that one pass over an expression gives `F`, `grad F` and the
//! Hessian of `F` together (Griewank, Walther, "Evaluating Derivatives", 2008, ch. 13: Taylor
//! arithmetic; here the full second-order jet in three variables).

use super::function::Function;

/// `f`, `grad f` and the Hessian of `f` at one point.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) struct Jet {
    /// `f`.
    pub value: f64,
    /// `(f_x, f_y, f_z)`.
    pub gradient: [f64; 3],
    /// `f_ab`, rows and columns in order x, y, z.
    pub hessian: [[f64; 3]; 3],
}

/// The operations an expression is evaluated with: plain numbers, or [`Jet`]s.
pub(super) trait Arithmetic: Copy {
    /// A constant.
    fn constant(value: f64) -> Self;
    /// The variable `axis` (0, 1, 2 for x, y, z) at the value `value`.
    fn variable(axis: usize, value: f64) -> Self;
    /// `self + other`.
    fn add(self, other: Self) -> Self;
    /// `self - other`.
    fn sub(self, other: Self) -> Self;
    /// `self * other`.
    fn mul(self, other: Self) -> Self;
    /// `self / other`.
    fn div(self, other: Self) -> Self;
    /// `-self`.
    fn neg(self) -> Self;
    /// `self ^ other` (`powf`).
    fn pow(self, other: Self) -> Self;
    /// `function(self)`.
    fn call(self, function: Function) -> Self;
}

impl Arithmetic for f64 {
    fn constant(value: f64) -> Self {
        value
    }
    fn variable(_: usize, value: f64) -> Self {
        value
    }
    fn add(self, other: Self) -> Self {
        self + other
    }
    fn sub(self, other: Self) -> Self {
        self - other
    }
    fn mul(self, other: Self) -> Self {
        self * other
    }
    fn div(self, other: Self) -> Self {
        self / other
    }
    fn neg(self) -> Self {
        -self
    }
    fn pow(self, other: Self) -> Self {
        self.powf(other)
    }
    fn call(self, function: Function) -> Self {
        function.value(self)
    }
}

impl Jet {
    const ZERO: Jet = Jet {
        value: 0.0,
        gradient: [0.0; 3],
        hessian: [[0.0; 3]; 3],
    };

    /// `g(self)` from `[g(u), g'(u), g''(u)]` at `u = self.value`, by the chain rule:
    /// `grad g(u) = g' grad u`, `H g(u) = g' H u + g'' grad u grad u^T`.
    fn chain(self, [g, g1, g2]: [f64; 3]) -> Jet {
        let u = &self.gradient;
        Jet {
            value: g,
            gradient: u.map(|d| g1 * d),
            hessian: core::array::from_fn(|a| {
                core::array::from_fn(|b| g1 * self.hessian[a][b] + g2 * u[a] * u[b])
            }),
        }
    }

    /// True when the gradient and Hessian vanish: to second order, a constant.
    fn is_constant(&self) -> bool {
        self.gradient
            .iter()
            .chain(self.hessian.iter().flatten())
            .all(|&d| d == 0.0)
    }

    /// `self ^ c` for a constant `c`: `c u^(c-1)` and `c (c-1) u^(c-2)`, with the factors
    /// that vanish for `c = 0` and `c = 1` left out (so `x^1` and `x^0` are smooth at 0).
    fn pow_constant(self, c: f64) -> Jet {
        let u = self.value;
        let first = if c == 0.0 { 0.0 } else { c * u.powf(c - 1.0) };
        let second = if c == 0.0 || c == 1.0 {
            0.0
        } else {
            c * (c - 1.0) * u.powf(c - 2.0)
        };
        self.chain([u.powf(c), first, second])
    }
}

impl Arithmetic for Jet {
    fn constant(value: f64) -> Self {
        Jet { value, ..Jet::ZERO }
    }

    fn variable(axis: usize, value: f64) -> Self {
        let mut jet = Jet::constant(value);
        jet.gradient[axis] = 1.0;
        jet
    }

    fn add(self, other: Self) -> Self {
        Jet {
            value: self.value + other.value,
            gradient: core::array::from_fn(|a| self.gradient[a] + other.gradient[a]),
            hessian: core::array::from_fn(|a| {
                core::array::from_fn(|b| self.hessian[a][b] + other.hessian[a][b])
            }),
        }
    }

    fn sub(self, other: Self) -> Self {
        self.add(other.neg())
    }

    /// `H(fg) = f H g + g H f + grad f grad g^T + grad g grad f^T`.
    fn mul(self, other: Self) -> Self {
        let (f, g) = (&self, &other);
        Jet {
            value: f.value * g.value,
            gradient: core::array::from_fn(|a| f.value * g.gradient[a] + g.value * f.gradient[a]),
            hessian: core::array::from_fn(|a| {
                core::array::from_fn(|b| {
                    f.value * g.hessian[a][b]
                        + g.value * f.hessian[a][b]
                        + f.gradient[a] * g.gradient[b]
                        + g.gradient[a] * f.gradient[b]
                })
            }),
        }
    }

    /// `q = f/g` from `f = q g`: `grad q = (grad f - q grad g)/g` and
    /// `H q = (H f - q H g - grad q grad g^T - grad g grad q^T)/g`.
    fn div(self, other: Self) -> Self {
        let (f, g) = (&self, &other);
        let q = f.value / g.value;
        let dq: [f64; 3] = core::array::from_fn(|a| (f.gradient[a] - q * g.gradient[a]) / g.value);
        Jet {
            value: q,
            gradient: dq,
            hessian: core::array::from_fn(|a| {
                core::array::from_fn(|b| {
                    (f.hessian[a][b]
                        - q * g.hessian[a][b]
                        - dq[a] * g.gradient[b]
                        - g.gradient[a] * dq[b])
                        / g.value
                })
            }),
        }
    }

    fn neg(self) -> Self {
        Jet {
            value: -self.value,
            gradient: self.gradient.map(|d| -d),
            hessian: self.hessian.map(|row| row.map(|d| -d)),
        }
    }

    /// A constant exponent by the power rule (defined for a negative base); otherwise
    /// `f^g = exp(g ln f)`, which needs `f > 0` for finite derivatives.
    fn pow(self, other: Self) -> Self {
        if other.is_constant() {
            return self.pow_constant(other.value);
        }
        let value = self.value.powf(other.value);
        let exponent = other.mul(self.call(Function::Ln));
        exponent.chain([value, value, value])
    }

    fn call(self, function: Function) -> Self {
        self.chain(function.derivatives(self.value))
    }
}

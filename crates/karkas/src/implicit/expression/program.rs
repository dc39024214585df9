//! The syntax tree of a parsed expression, stored in postfix order, and its evaluation.
//!
//! Postfix order makes the evaluation a loop over a stack instead of a recursion, so a long
//! chain such as `x+x+...+x` costs no stack however deep its tree.

use super::function::Function;
use super::jet::Arithmetic;
use crate::Point3;

/// One node of the tree: operands come before their operator.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(super) enum Op {
    /// A number (or the constants `pi`, `e`).
    Number(f64),
    /// The variable with index 0, 1, 2 (x, y, z).
    Variable(usize),
    /// Unary minus of the top of the stack.
    Negate,
    /// `a + b` of the two top entries (`b` on top).
    Add,
    /// `a - b`.
    Subtract,
    /// `a * b`.
    Multiply,
    /// `a / b`.
    Divide,
    /// `a ^ b`.
    Power,
    /// A function of the top of the stack.
    Call(Function),
}

/// A checked expression: its nodes in postfix order and the deepest stack they need.
#[derive(Clone, Debug, PartialEq)]
pub(super) struct Program {
    ops: Vec<Op>,
    stack: usize,
}

impl Program {
    /// The program of `ops`, which a parser emitted for a well-formed expression.
    pub(super) fn new(ops: Vec<Op>) -> Self {
        let (mut depth, mut stack) = (0usize, 0usize);
        for op in &ops {
            match op {
                Op::Number(_) | Op::Variable(_) => depth += 1,
                Op::Negate | Op::Call(_) => {}
                Op::Add | Op::Subtract | Op::Multiply | Op::Divide | Op::Power => {
                    depth = depth.saturating_sub(1);
                }
            }
            stack = stack.max(depth);
        }
        Program { ops, stack }
    }

    /// The expression at `p`, in the arithmetic `T` (numbers, or jets for derivatives).
    pub(super) fn eval<T: Arithmetic>(&self, p: Point3) -> T {
        let mut stack: Vec<T> = Vec::with_capacity(self.stack);
        for op in &self.ops {
            let top = match *op {
                Op::Number(v) => T::constant(v),
                Op::Variable(axis) => T::variable(axis, p[axis]),
                Op::Negate | Op::Call(_) => {
                    let Some(a) = stack.pop() else {
                        return T::constant(f64::NAN);
                    };
                    match *op {
                        Op::Call(f) => a.call(f),
                        _ => a.neg(),
                    }
                }
                Op::Add | Op::Subtract | Op::Multiply | Op::Divide | Op::Power => {
                    let (Some(b), Some(a)) = (stack.pop(), stack.pop()) else {
                        return T::constant(f64::NAN);
                    };
                    match op {
                        Op::Add => a.add(b),
                        Op::Subtract => a.sub(b),
                        Op::Multiply => a.mul(b),
                        Op::Divide => a.div(b),
                        _ => a.pow(b),
                    }
                }
            };
            stack.push(top);
        }
        stack.pop().unwrap_or(T::constant(f64::NAN))
    }
}

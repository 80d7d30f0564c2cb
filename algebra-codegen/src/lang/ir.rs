//! The language-free form of a kernel: a straight-line program over one scalar type (locals,
//! then the result), the operations in evaluation order. Built from the plan by
//! `lang::linear` and `lang::closed`; printed by the dialects of [`super`].

use crate::naming::product_name;
use crate::ratio::Ratio;
use crate::sums::Build;
use crate::versor::Convention;
use algebra_core::tables::Product;

/// A scalar expression. Binary operations are evaluated as written (printers parenthesise
/// every one), so the order of the floating-point operations is part of the expression.
#[derive(Debug, Clone, PartialEq)]
pub enum Expr {
    /// Field `field` of parameter `param` of the kernel.
    Field {
        /// Parameter index.
        param: usize,
        /// Field index in the parameter's type.
        field: usize,
    },
    /// A local bound earlier by the kernel ([`Kernel::lets`]).
    Local(usize),
    /// The constant `n / d`, rounded once to the scalar type.
    Const(Ratio),
    /// `a + b`.
    Add(Box<Expr>, Box<Expr>),
    /// `a - b`.
    Sub(Box<Expr>, Box<Expr>),
    /// `a * b`.
    Mul(Box<Expr>, Box<Expr>),
    /// `-a`.
    Neg(Box<Expr>),
    /// `a / b`.
    Div(Box<Expr>, Box<Expr>),
    /// `sqrt(a)`.
    Sqrt(Box<Expr>),
    /// A scalar helper function of the file ([`Helper`]), returning three scalars; bound to a
    /// local and read with [`Expr::Part`].
    Call(Helper, Vec<Expr>),
    /// Part `1` of the three returned by the [`Expr::Call`] bound to local `0`.
    Part(usize, usize),
}

/// The scalar helpers of the closed forms (the factors of `algebra_core::closed_form`), emitted
/// once per file when a kernel calls them.
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Helper {
    /// `θ² ↦ (sinc θ, (cos θ - sinc θ)/θ², cos θ)`, by their series below `θ = 10^-3`.
    ExpFactors,
    /// `(sin θ, cos θ) ↦ (θ / sin θ, (θ cos θ - sin θ)/sin³ θ, 0)` with `θ = atan2(sin, cos)`,
    /// by their series below `θ = 10^-3`.
    LogFactors,
}

impl Helper {
    /// The helper's name in function names (`exp_factors`, `log_factors`).
    pub fn name(self) -> &'static str {
        match self {
            Helper::ExpFactors => "exp_factors",
            Helper::LogFactors => "log_factors",
        }
    }
}

/// The operation of a kernel, which names it.
#[derive(Debug, Clone, PartialEq, Eq)]
pub enum Op {
    /// A product of two types (`gp`, `op`, `lc`, `rc`, `sp`, `regressive`, `commutator`,
    /// `anticommutator`).
    Product(Product),
    /// A linear unary map (`reverse`, `grade_involution`, `conjugate`, `dual`, `undual`).
    Unary(&'static str),
    /// `<x rev(x)>_0`.
    NormSquared,
    /// The fused versor action (`sandwich`: `rev(S) x S`; `apply`: `S x rev(S)`).
    Action(Convention),
    /// The unit-versor action (`sandwich_unit`, `apply_unit`).
    UnitAction(Convention),
    /// The closed-form exponential of a bivector type.
    Exp,
    /// The closed-form logarithm of a unit element of an even type.
    LogUnit,
    /// An element of an even type divided by its norm.
    Normalize,
}

impl Op {
    /// The operation's name in function names (`gp`, `reverse`, `apply_unit`, ...).
    ///
    /// ```
    /// use algebra_codegen::lang::ir::Op;
    /// use algebra_codegen::versor::Convention;
    /// assert_eq!(Op::UnitAction(Convention::Apply).name(), "apply_unit");
    /// ```
    pub fn name(&self) -> &'static str {
        match self {
            Op::Product(p) => product_name(*p),
            Op::Unary(n) => n,
            Op::NormSquared => "norm_squared",
            Op::Action(Convention::Sandwich) => "sandwich",
            Op::Action(Convention::Apply) => "apply",
            Op::UnitAction(Convention::Sandwich) => "sandwich_unit",
            Op::UnitAction(Convention::Apply) => "apply_unit",
            Op::Exp => "exp",
            Op::LogUnit => "log_unit",
            Op::Normalize => "normalize",
        }
    }
}

/// What a kernel returns.
#[derive(Debug, Clone, PartialEq)]
pub enum Output {
    /// A value of the declared type with this index, one expression per field.
    Type(usize, Vec<Expr>),
    /// A scalar.
    Scalar(Expr),
}

/// One kernel: `fn name(params) -> output { lets; return output }`.
#[derive(Debug, Clone, PartialEq)]
pub struct Kernel {
    /// The operation.
    pub op: Op,
    /// The parameters' type indices: one (unary) or two (products, actions: versor first).
    pub params: Vec<usize>,
    /// Locals bound in order, each from parameters and earlier locals.
    pub lets: Vec<Expr>,
    /// The result.
    pub output: Output,
    /// One line saying what the kernel computes.
    pub doc: String,
}

pub(super) struct Ir;

impl Build for Ir {
    type E = Expr;
    fn zero() -> Expr {
        Expr::Const((0, 1))
    }
    fn value(x: Expr, _movable: bool) -> Expr {
        x
    }
    fn neg(x: Expr) -> Expr {
        Expr::Neg(Box::new(x))
    }
    fn scaled(k: Ratio, x: Expr) -> Expr {
        mul(Expr::Const(k), x)
    }
    fn scaled_leaf(k: Ratio, x: Expr) -> Expr {
        mul(Expr::Const(k), x)
    }
    fn add(acc: Expr, x: Expr, negative: bool) -> Expr {
        add(acc, x, negative)
    }
    fn add_scaled(acc: Expr, k: Ratio, x: Expr, negative: bool) -> Expr {
        add(acc, mul(Expr::Const(k), x), negative)
    }
    fn add_group(acc: Expr, e: Expr, negative: bool) -> Expr {
        add(acc, e, negative)
    }
    fn tree_add(a: Expr, b: Expr, negative: bool) -> Expr {
        add(a, b, negative)
    }
}

impl Kernel {
    /// Whether the kernel reads parameter `param` (a structurally zero product reads none).
    pub fn reads(&self, param: usize) -> bool {
        fn uses(e: &Expr, param: usize) -> bool {
            match e {
                Expr::Field { param: p, .. } => *p == param,
                Expr::Local(_) | Expr::Const(_) | Expr::Part(..) => false,
                Expr::Add(a, b) | Expr::Sub(a, b) | Expr::Mul(a, b) | Expr::Div(a, b) => {
                    uses(a, param) || uses(b, param)
                }
                Expr::Neg(a) | Expr::Sqrt(a) => uses(a, param),
                Expr::Call(_, args) => args.iter().any(|a| uses(a, param)),
            }
        }
        let outputs: Vec<&Expr> = match &self.output {
            Output::Type(_, es) => es.iter().collect(),
            Output::Scalar(e) => vec![e],
        };
        self.lets.iter().chain(outputs).any(|e| uses(e, param))
    }
}

pub(super) fn mul(a: Expr, b: Expr) -> Expr {
    Expr::Mul(Box::new(a), Box::new(b))
}

pub(super) fn add(a: Expr, b: Expr, negative: bool) -> Expr {
    if negative { Expr::Sub(Box::new(a), Box::new(b)) } else { Expr::Add(Box::new(a), Box::new(b)) }
}

pub(super) fn field(param: usize, field: usize) -> Expr {
    Expr::Field { param, field }
}

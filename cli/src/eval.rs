//! Evaluates an expression tree over any [`CliScalar`], in one algebra and one basis.
//!
//! Identifiers are resolved here: a basis name of the algebra is that basis element in the
//! chosen basis; under `poly` any other identifier is a variable; otherwise it is an error
//! that names the algebra's generators. Errors carry the column of the offending node.

use crate::error::CliError;
use crate::expr::{BinOp, Func, Node, PrefixOp};
use crate::scalar::{CliScalar, Elementary, Failure};
use algebra_core::{Algebra, Basis, Multivector, Poly, Product};
use std::collections::HashMap;
use std::sync::Arc;

/// Evaluates expressions in one algebra and basis (over any scalar, chosen per call).
pub struct Evaluator<'a> {
    algebra: &'a Arc<Algebra>,
    basis: Basis,
    /// Named symbolic values (`gam prove`'s `let` names and builders), seen by `poly` only.
    bindings: Option<&'a HashMap<String, Multivector<Poly>>>,
}

type Mv<T> = Multivector<T>;

/// Turns a scalar-specific failure of operation `what` at `col` into a CLI error.
fn failed(what: &str, col: usize, scalar: &str, f: Failure) -> CliError {
    match f {
        Failure::Unsupported(why) => {
            CliError::usage(format!("{what} at column {col} is not available for --scalar {scalar}: {why}"))
        }
        Failure::Math(why) => CliError::math(format!("{what} at column {col}: {why}")),
    }
}

impl<'a> Evaluator<'a> {
    /// An evaluator for `algebra` whose basis names mean elements of `basis`.
    pub fn new(algebra: &'a Arc<Algebra>, basis: Basis) -> Self {
        Evaluator { algebra, basis, bindings: None }
    }

    /// An evaluator that also knows the named values `bindings` (under `--scalar poly`).
    pub fn with_bindings(
        algebra: &'a Arc<Algebra>,
        basis: Basis,
        bindings: &'a HashMap<String, Multivector<Poly>>,
    ) -> Self {
        Evaluator { algebra, basis, bindings: Some(bindings) }
    }

    /// The value of `node`, with every coefficient finite.
    pub fn eval<T: CliScalar>(&self, node: &Node) -> Result<Mv<T>, CliError> {
        let value = self.value::<T>(node)?;
        if value.coeffs().iter().all(CliScalar::finite) {
            Ok(value)
        } else {
            Err(CliError::math(format!("the result is not finite (overflow): {value}")))
        }
    }

    fn scalar<T: CliScalar>(&self, x: T) -> Mv<T> {
        Multivector::scalar(self.algebra, self.basis, x)
    }

    fn value<T: CliScalar>(&self, node: &Node) -> Result<Mv<T>, CliError> {
        match node {
            Node::Number { text, col } => T::number(text)
                .map(|x| self.scalar(x))
                .map_err(|e| CliError::usage(format!("bad number at column {col}: {e}"))),
            Node::Ident { name, col } => self.identifier(name, *col),
            Node::Prefix { op, operand, .. } => {
                let x = self.value::<T>(operand)?;
                Ok(match op {
                    PrefixOp::Neg => -x,
                    PrefixOp::Reverse => x.reverse(),
                })
            }
            Node::Chain { first, rest } => {
                let mut acc = self.value::<T>(first)?;
                for (op, col, operand) in rest {
                    let y = self.value::<T>(operand)?;
                    acc = match op {
                        BinOp::Add => &acc + &y,
                        BinOp::Sub => &acc - &y,
                        BinOp::Mul => self.product(&acc, &y, Product::Geometric, *col)?,
                        BinOp::Wedge => self.product(&acc, &y, Product::Outer, *col)?,
                        BinOp::Div => self.divide(&acc, &y, "division", *col)?,
                    };
                }
                Ok(acc)
            }
            Node::Call { func, args, col } => self.call(*func, args, *col),
        }
    }

    fn identifier<T: CliScalar>(&self, name: &str, col: usize) -> Result<Mv<T>, CliError> {
        if let Some(v) = self.bindings.and_then(|b| b.get(name))
            && let Some(v) = (v as &dyn std::any::Any).downcast_ref::<Mv<T>>()
        {
            return Ok(v.clone());
        }
        if let Ok(mask) = self.algebra.mask_of(name) {
            return Multivector::from_mask(self.algebra, self.basis, mask).map_err(|e| CliError::usage(e.to_string()));
        }
        if Func::from_name(name).is_some() {
            return Err(CliError::usage(format!("`{name}` at column {col} is a function: call it as {name}(...)")));
        }
        if let Some(v) = T::variable(name) {
            return Ok(self.scalar(v));
        }
        let labels = self.algebra.metric().labels();
        let example = self.algebra.name_of(self.algebra.basis_order().last().copied().unwrap_or(0)).unwrap_or("e1");
        Err(CliError::usage(format!(
            "unknown basis element `{name}` at column {col}: algebra {} has generators {} \
             (basis names are e + labels in declaration order, e.g. {example}; variables need --scalar poly)",
            self.algebra.name(),
            labels.join(", "),
        )))
    }

    /// `product(x, y)` at column `col`, after checking its work against the budget.
    fn product<T: CliScalar>(&self, x: &Mv<T>, y: &Mv<T>, product: Product, col: usize) -> Result<Mv<T>, CliError> {
        crate::budget::check(&format!("the product at column {col}"), T::product_work(x, y, product))?;
        x.try_product(y, product).map_err(|e| CliError::usage(e.to_string()))
    }

    /// `x / d`: by a scalar coefficient-wise, otherwise times the inverse of `d`.
    fn divide<T: CliScalar>(&self, x: &Mv<T>, d: &Mv<T>, what: &str, col: usize) -> Result<Mv<T>, CliError> {
        if d.coeffs().iter().skip(1).all(algebra_core::Ring::is_exact_zero) {
            let s = &d.coeffs()[0];
            let coeffs = x
                .coeffs()
                .iter()
                .map(|c| c.div_scalar(s))
                .collect::<Result<Vec<T>, _>>()
                .map_err(|f| failed(what, col, T::NAME, f))?;
            Multivector::from_coeffs(self.algebra, x.basis(), coeffs).map_err(|e| CliError::math(e.to_string()))
        } else {
            let inv = T::inverse(d).map_err(|f| failed(what, col, T::NAME, f))?;
            Ok(x * &inv)
        }
    }

    fn call<T: CliScalar>(&self, func: Func, args: &[Node], col: usize) -> Result<Mv<T>, CliError> {
        let name = func.name();
        if func == Func::Diff {
            return crate::prove::differentiate(&self.value::<T>(&args[0])?, &args[1], col);
        }
        let vals = args.iter().map(|a| self.value::<T>(a)).collect::<Result<Vec<_>, _>>()?;
        let binary = |p: Product| self.product(&vals[0], &vals[1], p, col);
        let elementary = |f: Elementary| T::elementary(f, &vals[0]).map_err(|e| failed(name, col, T::NAME, e));
        match func {
            Func::Rev => Ok(vals[0].reverse()),
            Func::BasisRev => Ok(vals[0].basis_reverse()),
            Func::Involute => Ok(vals[0].grade_involution()),
            Func::Conj => Ok(vals[0].conjugate()),
            Func::Dual => Ok(vals[0].dual()),
            Func::Undual => Ok(vals[0].undual()),
            Func::Inv => self.divide(&self.scalar(T::one()), &vals[0], name, col),
            Func::Gp => binary(Product::Geometric),
            Func::Op => binary(Product::Outer),
            Func::Lc => binary(Product::LeftContraction),
            Func::Rc => binary(Product::RightContraction),
            Func::Sp => binary(Product::Scalar),
            Func::Rp => binary(Product::Regressive),
            Func::Comm => binary(Product::Commutator),
            Func::Acomm => binary(Product::Anticommutator),
            Func::Exp => elementary(Elementary::Exp),
            Func::Log => elementary(Elementary::Log),
            Func::Sqrt => elementary(Elementary::Sqrt),
            Func::Diff => unreachable!("handled above"),
            Func::Grade | Func::BasisGrade => {
                let k = self.grade_arg(&args[1], name)?;
                Ok(if k > self.algebra.generators() {
                    Multivector::zero(self.algebra, self.basis)
                } else if func == Func::Grade {
                    vals[0].grade(k)
                } else {
                    vals[0].basis_grade(k)
                })
            }
        }
    }

    /// The `k` of `grade(x, k)`: a non-negative integer literal.
    fn grade_arg(&self, node: &Node, name: &str) -> Result<usize, CliError> {
        match node {
            Node::Number { text, .. } if text.bytes().all(|b| b.is_ascii_digit()) => {
                Ok(text.parse::<usize>().unwrap_or(usize::MAX))
            }
            other => Err(CliError::usage(format!(
                "{name} at column {}: k must be a non-negative integer literal",
                column(other)
            ))),
        }
    }
}

/// The column where a node starts.
fn column(node: &Node) -> usize {
    match node {
        Node::Number { col, .. } | Node::Ident { col, .. } | Node::Prefix { col, .. } | Node::Call { col, .. } => *col,
        Node::Chain { first, .. } => column(first),
    }
}

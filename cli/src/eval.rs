//! Evaluates an expression tree over any [`CliScalar`], in one algebra and one basis.
//!
//! Identifiers are resolved here: a basis name of the algebra is that basis element in the
//! chosen basis; under `poly` any other identifier is a variable; otherwise it is an error
//! that names the algebra's generators. Errors carry the column of the offending node.

use crate::error::CliError;
use crate::expr::{BinOp, Func, Node, PrefixOp};
use crate::scalar::{CliScalar, Elementary, Failure};
use algebra_core::{Algebra, Basis, Multivector, Poly, Product};
use std::cell::Cell;
use std::collections::HashMap;
use std::sync::Arc;
use std::time::Instant;

/// Evaluates expressions in one algebra and basis (over any scalar, chosen per call).
pub struct Evaluator<'a> {
    algebra: &'a Arc<Algebra>,
    basis: Basis,
    /// Named symbolic values (`gam prove`'s `let` names and builders), seen by `poly` only.
    bindings: Option<&'a HashMap<String, Multivector<Poly>>>,
    /// When set (`gam prove --timeout`): evaluation stops with [`timeout`] after this instant,
    /// and a product whose work would not fit in the time left is refused the same way.
    deadline: Option<Instant>,
    /// The work of the products and inverses evaluated so far: the budget bounds the whole
    /// expression, not each operation alone (ten products of 100,000-digit rationals, each
    /// within the budget, took minutes together).
    spent: Cell<f64>,
}

/// The start of the message of a spent `--timeout` (see [`is_timeout`]).
const TIMEOUT: &str = "undecided within budget: time limit reached";

/// The error of a spent deadline.
fn timeout(what: &str) -> CliError {
    CliError::math(format!("{TIMEOUT} while evaluating {what}"))
}

/// Whether `e` is the error of a spent deadline ([`Evaluator::until`]).
pub fn is_timeout(e: &CliError) -> bool {
    e.message.starts_with(TIMEOUT)
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
        Evaluator { algebra, basis, bindings: None, deadline: None, spent: Cell::new(0.0) }
    }

    /// The same evaluator, stopping with an "undecided within budget: time limit" error
    /// ([`is_timeout`]) once `deadline` has passed.
    pub fn until(self, deadline: Instant) -> Self {
        Evaluator { deadline: Some(deadline), ..self }
    }

    /// An evaluator that also knows the named values `bindings` (under `--scalar poly`).
    pub fn with_bindings(
        algebra: &'a Arc<Algebra>,
        basis: Basis,
        bindings: &'a HashMap<String, Multivector<Poly>>,
    ) -> Self {
        Evaluator { algebra, basis, bindings: Some(bindings), deadline: None, spent: Cell::new(0.0) }
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
        if self.deadline.is_some_and(|d| Instant::now() > d) {
            return Err(timeout(&format!("the expression at column {}", column(node))));
        }
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
                    // sums in place: `acc = &acc + &y` copied the accumulator, and a sum of
                    // 16,000 polynomial variables took 35 s (quadratic, outside every budget)
                    acc = match op {
                        BinOp::Add => {
                            acc.try_add_assign(&y).map_err(|e| CliError::usage(e.to_string()))?;
                            acc
                        }
                        BinOp::Sub => {
                            acc.try_sub_assign(&y).map_err(|e| CliError::usage(e.to_string()))?;
                            acc
                        }
                        BinOp::Mul => self.product(&acc, &y, Product::Geometric, *col)?,
                        BinOp::Wedge => self.product(&acc, &y, Product::Outer, *col)?,
                        BinOp::Div => self.divide(&acc, &y, "division", *col)?,
                    };
                }
                Ok(acc)
            }
            Node::Call { func, args, col } => self.call(*func, args, *col),
            Node::Power { base, exponent, col } => self.power(&self.value::<T>(base)?, *exponent, *col),
        }
    }

    /// `x ** k` by repeated squaring; every product is checked against the work budget, and
    /// the size of an exact result (its coefficients' bits times `k`) before any of them.
    fn power<T: CliScalar>(&self, x: &Mv<T>, k: u32, col: usize) -> Result<Mv<T>, CliError> {
        let degree = T::degree(x).saturating_mul(u64::from(k));
        if degree > crate::scalar::MAX_DEGREE {
            return Err(CliError::usage(format!(
                "the power at column {col} would have degree {degree}, more than the largest degree {}",
                crate::scalar::MAX_DEGREE
            )));
        }
        let bits = T::size_bits(x) * f64::from(k);
        crate::budget::check(&format!("the power at column {col}"), bits * crate::budget::UNITS_PER_BIT)?;
        let mut acc: Option<Mv<T>> = None;
        let mut square = x.clone();
        let mut k = k;
        while k > 0 {
            if k & 1 == 1 {
                acc = Some(match acc {
                    None => square.clone(),
                    Some(a) => self.product(&a, &square, Product::Geometric, col)?,
                });
            }
            k >>= 1;
            if k > 0 {
                square = self.product(&square, &square, Product::Geometric, col)?;
            }
        }
        Ok(acc.unwrap_or_else(|| self.scalar(T::one())))
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
        let work = T::product_work(x, y, product);
        self.charge(&format!("the product at column {col}"), work)?;
        crate::budget::check_memory(&format!("the product at column {col}"), T::product_bytes(x, y, product))?;
        if let Some(d) = self.deadline {
            let left = d.saturating_duration_since(Instant::now()).as_secs_f64();
            if work > left * crate::budget::UNITS_PER_SECOND {
                return Err(timeout(&format!("the product at column {col} (about {work:.2e} units of work)")));
            }
        }
        let degree = T::degree(x) + T::degree(y);
        if degree > crate::scalar::MAX_DEGREE {
            return Err(CliError::usage(format!(
                "the product at column {col} would have degree {degree}, more than the largest degree {}",
                crate::scalar::MAX_DEGREE
            )));
        }
        x.try_product(y, product).map_err(|e| CliError::usage(e.to_string()))
    }

    /// Checks `work` and the work spent before it against the budget, then counts it as spent.
    fn charge(&self, what: &str, work: f64) -> Result<(), CliError> {
        let before = self.spent.get();
        if before > 0.0 {
            crate::budget::check(&format!("{what} (with the {before:.2e} units before it)"), before + work)?;
        } else {
            crate::budget::check(what, work)?;
        }
        self.spent.set(before + work);
        Ok(())
    }

    /// `x / d`: by a scalar coefficient-wise, otherwise times the inverse of `d`.
    fn divide<T: CliScalar>(&self, x: &Mv<T>, d: &Mv<T>, what: &str, col: usize) -> Result<Mv<T>, CliError> {
        if d.coeffs().iter().skip(1).all(algebra_core::Ring::is_exact_zero) {
            // coefficient-wise, as costly as the product by the scalar
            self.charge(&format!("the {what} at column {col}"), T::product_work(x, d, Product::Geometric))?;
            let s = &d.coeffs()[0];
            let coeffs = x
                .coeffs()
                .iter()
                .map(|c| c.div_scalar(s))
                .collect::<Result<Vec<T>, _>>()
                .map_err(|f| failed(what, col, T::NAME, f))?;
            Multivector::from_coeffs(self.algebra, x.basis(), coeffs).map_err(|e| CliError::math(e.to_string()))
        } else {
            self.charge(&format!("the inverse at column {col}"), T::inverse_work(d))?;
            let inv = T::inverse(d).map_err(|f| failed(what, col, T::NAME, f))?;
            self.product(x, &inv, Product::Geometric, col)
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
        Node::Power { base, .. } => column(base),
        Node::Chain { first, .. } => column(first),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use algebra_core::{Algebra, Ring};
    use proptest::prelude::*;

    /// `text` read by `gam eval --scalar poly` in g3 (its scalar part).
    fn read(text: &str) -> Poly {
        let alg = Algebra::builtin("g3").unwrap();
        let ast = crate::expr::parse(text, &alg).unwrap();
        Evaluator::new(&alg, Basis::Blade).eval::<Poly>(&ast).unwrap().scalar_part()
    }

    /// A polynomial from `(numerator, denominator, exponents of S, S12, x, y1)` terms, built
    /// with algebra_core's arithmetic (not with the parser under test).
    fn poly(terms: &[(i64, i64, [u32; 4])]) -> Poly {
        let names = ["S", "S12", "x", "y1"];
        terms.iter().fold(Poly::zero(), |acc, (p, q, e)| {
            let mono = names.iter().zip(e).fold(Poly::one(), |m, (n, k)| m * Poly::var(n).pow_u32(*k));
            acc + Poly::from_ratio(*p, *q) * mono
        })
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(200))]

        /// A printed polynomial pasted back is the same polynomial (powers print as `**`,
        /// negative leading terms as `-x**2`, coefficients as `p/q`).
        #[test]
        fn printed_polynomials_read_back(
            terms in prop::collection::vec((-40i64..40, 1i64..9, [0u32..4, 0u32..3, 0u32..5, 0u32..3]), 0..7)
        ) {
            let p = poly(&terms);
            prop_assert_eq!(read(&p.to_string()), p);
        }
    }

    #[test]
    fn powers_are_products() {
        assert_eq!(read("-x**2"), -(Poly::var("x") * Poly::var("x")));
        assert_eq!(read("(x + 1)**3"), read("(x + 1)*(x + 1)*(x + 1)"));
        assert_eq!(read("x**0 + 0**0"), Poly::from_i64(2));
        assert_eq!(read("2**10"), Poly::from_i64(1024));
        assert_eq!(read("(1/2)**3"), Poly::from_ratio(1, 8));
        let alg = Algebra::builtin("g3").unwrap();
        let mv = |t: &str| Evaluator::new(&alg, Basis::Blade).eval::<Poly>(&crate::expr::parse(t, &alg).unwrap());
        // (e1 + e12)^2 = e1 e1 + e1 e12 + e12 e1 + e12 e12 = 1 + e2 - e2 - 1 = 0
        assert!(mv("(e1 + e12)**2").unwrap().is_zero());
        assert_eq!(mv("(x*e1 + e2)**2").unwrap().to_string(), "x**2 + 1");
        assert_eq!(mv("e12**4").unwrap().to_string(), "1");
        assert_eq!(mv("e1^e2**2").unwrap().to_string(), "e1");
    }

    #[test]
    fn powers_respect_the_budgets() {
        let alg = Algebra::builtin("g3").unwrap();
        let ev = Evaluator::new(&alg, Basis::Blade);
        let run = |t: &str| ev.eval::<Poly>(&crate::expr::parse(t, &alg).unwrap()).unwrap_err().message;
        assert!(run("(x**1000)**1001").contains("degree 1001000, more than the largest degree 1000000"));
        assert!(run("3**1000000000").contains("the power at column 2 needs about"));
        let q = |t: &str| ev.eval::<algebra_core::rational::Q>(&crate::expr::parse(t, &alg).unwrap());
        assert!(q("7**300000000").unwrap_err().message.contains("GAM_WORK_BUDGET"));
        assert_eq!(q("7**3").unwrap().to_string(), "343");
        // the exact inverse of a non-scalar with a 100,000-digit coefficient (100 s before)
        let digits = "7".repeat(100_000);
        let e = q(&format!("inv({digits}*e1 + e2)")).unwrap_err().message;
        // (after the product `digits*e1`, whose work counts towards the same budget)
        assert!(e.starts_with("the inverse at column 1 (with the") && e.contains("GAM_WORK_BUDGET"), "{e}");
        assert_eq!(q(&format!("inv({digits})")).unwrap().to_string().len(), 100_002);
        assert_eq!(q("inv(2*e1 + e2)").unwrap().to_string(), "2/5*e1 + 1/5*e2");
    }

    #[test]
    fn a_spent_deadline_stops_evaluation() {
        let alg = Algebra::builtin("g3").unwrap();
        let past = Instant::now();
        let ev = Evaluator::new(&alg, Basis::Blade).until(past);
        std::thread::sleep(std::time::Duration::from_millis(2));
        let e = ev.eval::<Poly>(&crate::expr::parse("x + 1", &alg).unwrap()).unwrap_err();
        assert!(is_timeout(&e), "{}", e.message);
        assert_eq!(e.code, crate::error::EXIT_MATH);
    }
}

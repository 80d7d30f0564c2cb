//! Constrained kernels: a type declared with a polynomial constraint (a unit versor,
//! `rev(x) x = 1`; a null vector, `x x = 0`; a simple bivector such as a PGA line, `x ∧ x = 0`)
//! lets the generator shorten the kernels that take it. Every output component of the product
//! (or versor action) is expanded as a polynomial in the input coefficients, reduced modulo the
//! constraint ideal (a reduced Gröbner basis, `algebra_core::ideal`), and the cheapest
//! representative of its residue class is kept. Components whose normal form is zero vanish on
//! every constrained input — *proven* by ideal membership, not assumed — so the output type is
//! the smallest declared type holding the rest (a unit motor acting on a point gives a point).
//!
//! The kernel is laid out as a matrix over the versor part: the distinct monomials of the left
//! (versor) input are computed once and shared, and each output is
//! `Σ_c x_c · (Σ_k r_k m_k(s))` (plus a constant-in-`x` part). The same layout is used for the
//! unconstrained kernel, so [`ConstrainedKernel::stats`] against [`ConstrainedKernel::full`]
//! measures what the constraint saves. The kernel is valid only on inputs that satisfy the
//! constraint; [`ConstrainedKernel::doc`] records which.
//!
//! Declared in the `algebra!` DSL (`Motor = even where unit;`) or in `--types`
//! (`Motor=even where unit`): [`TypeSpec::constraint`](crate::TypeSpec::constraint). The
//! reduction (`constrained_action`, `constrained_product`) needs `algebra-core`'s `rug`
//! (`Poly`, ideals) and is behind the `constraints` feature. The proc macro stays GMP-free: it
//! reads the kernels of the predefined modules from a committed table of reduced term lists
//! ([`table`]), and computes others only when its own `constraints` feature is on.
//!
//! ```
//! # #[cfg(feature = "constraints")] {
//! use algebra_core::{Algebra, Basis};
//! use algebra_codegen::ModuleSpec;
//! use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_action};
//! use algebra_codegen::versor::Convention;
//! let alg = Algebra::builtin("cga-null").unwrap();
//! let types = ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1;Full=all", &alg).unwrap();
//! let spec = ModuleSpec::new("cga_null", alg.metric().clone(), Basis::Product, types).unwrap();
//! let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
//! let k = constrained_action(&spec, Convention::Sandwich, 0, 1, &unit).unwrap();
//! assert_eq!(k.output_type, Some(1)); // proven: a unit motor maps a vector to a vector
//! assert!(k.stats().mul < k.full.stats().mul);
//! # }
//! ```

use crate::ModuleSpec;
#[cfg(feature = "constraints")]
use algebra_core::ideal::IdealError;
use algebra_core::{MvError, Ring};
use std::collections::BTreeSet;
use std::fmt;

mod methods;
#[cfg(feature = "constraints")]
mod reduce;
mod request;
pub mod table;
mod tokens;

pub use methods::methods;
pub(crate) use methods::typed_body;
#[cfg(feature = "constraints")]
pub use reduce::{constrained_action, constrained_product};
pub use request::{compute, kernel, method_name, requests};

/// What a constrained kernel computes.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum KernelOp {
    /// `rev(S) x S` (the module's `sandwich`).
    Sandwich,
    /// `S x rev(S)` (the module's `apply`).
    Apply,
    /// `x x` (left and right are the same value).
    Square,
}

impl KernelOp {
    /// `sandwich`, `apply` or `square`.
    ///
    /// ```
    /// assert_eq!(algebra_codegen::constraint::KernelOp::Square.name(), "square");
    /// ```
    pub fn name(self) -> &'static str {
        match self {
            KernelOp::Sandwich => "sandwich",
            KernelOp::Apply => "apply",
            KernelOp::Square => "square",
        }
    }
}

/// One constrained kernel of a module: the operation and its two type indices (equal for
/// [`KernelOp::Square`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Request {
    /// The operation.
    pub op: KernelOp,
    /// The versor (or squared) type.
    pub left: usize,
    /// The operand type.
    pub right: usize,
}

/// The polynomial constraints a type may declare.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ConstraintKind {
    /// `rev(x) x = 1` (a unit rotor, motor or pose), every component.
    Unit,
    /// `x x = 0` (a null vector: a conformal point).
    Null,
    /// `x ∧ x = 0` (a simple bivector: the Plücker condition of a line).
    Simple,
}

impl ConstraintKind {
    /// The DSL keyword (`unit`, `null`, `simple`).
    ///
    /// ```
    /// use algebra_codegen::constraint::ConstraintKind;
    /// assert_eq!(ConstraintKind::parse("simple"), Some(ConstraintKind::Simple));
    /// assert_eq!(ConstraintKind::Unit.keyword(), "unit");
    /// ```
    pub fn keyword(self) -> &'static str {
        match self {
            ConstraintKind::Unit => "unit",
            ConstraintKind::Null => "null",
            ConstraintKind::Simple => "simple",
        }
    }

    /// The kind of a DSL keyword, if it is one.
    pub fn parse(word: &str) -> Option<ConstraintKind> {
        [ConstraintKind::Unit, ConstraintKind::Null, ConstraintKind::Simple].into_iter().find(|k| k.keyword() == word)
    }
}

/// A constraint on the declared type `ty` (an index into [`ModuleSpec::types`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Constraint {
    /// The constrained type.
    pub ty: usize,
    /// What it satisfies.
    pub kind: ConstraintKind,
}

impl fmt::Display for ConstraintKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            ConstraintKind::Unit => "rev(x) x = 1",
            ConstraintKind::Null => "x x = 0",
            ConstraintKind::Simple => "x ∧ x = 0",
        })
    }
}

/// Errors of the constrained-kernel analysis.
#[derive(Debug, Clone, PartialEq)]
pub enum ConstraintError {
    /// The Gröbner basis or a normal form ran out of budget.
    #[cfg(feature = "constraints")]
    Ideal(IdealError),
    /// A kernel is neither in the precomputed table nor computable (the crate was built
    /// without its `constraints` feature): says which.
    NotPrecomputed(String),
    /// A precomputed table entry does not parse (line and reason).
    BadTable(String),
    /// A type's elements are not elements of the algebra.
    Algebra(MvError),
    /// A type index is out of range.
    NoType(usize),
    /// A reduced coefficient does not fit `T::from_ratio(i64, i64)`.
    CoefficientTooLarge(String),
    /// The constraints contradict each other (the ideal is the whole ring).
    Inconsistent,
}

impl fmt::Display for ConstraintError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            #[cfg(feature = "constraints")]
            ConstraintError::Ideal(e) => write!(f, "constraint ideal: {e}"),
            ConstraintError::NotPrecomputed(what) => write!(
                f,
                "the constrained kernel {what} is not precomputed; turn on the `constraints` feature of algebra-macros (it pulls GMP), generate the module with `gam codegen`, or add it to algebra-codegen's table (tests/constraint_table.rs, BLESS=1)"
            ),
            ConstraintError::BadTable(e) => write!(f, "precomputed constraint table: {e}"),
            ConstraintError::Algebra(e) => write!(f, "constraint: {e}"),
            ConstraintError::NoType(i) => write!(f, "constraint on type #{i}, which is not declared"),
            ConstraintError::CoefficientTooLarge(c) => write!(f, "reduced coefficient {c} does not fit i64/i64"),
            ConstraintError::Inconsistent => write!(f, "the constraints are inconsistent (1 is in their ideal)"),
        }
    }
}

impl std::error::Error for ConstraintError {}

#[cfg(feature = "constraints")]
impl From<IdealError> for ConstraintError {
    fn from(e: IdealError) -> Self {
        ConstraintError::Ideal(e)
    }
}

impl From<MvError> for ConstraintError {
    fn from(e: MvError) -> Self {
        ConstraintError::Algebra(e)
    }
}

/// Operation counts of a kernel in the matrix layout (see the module docs).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct Counts {
    /// Output components computed (the others are structurally or provably zero).
    pub outputs: usize,
    /// Monomial terms over all outputs.
    pub terms: usize,
    /// Multiplications (`setup_mul + apply_mul`).
    pub mul: usize,
    /// Multiplications that depend on the left (versor) input only: the shared monomials and
    /// the constant factors of the matrix entries (done once per versor).
    pub setup_mul: usize,
    /// Multiplications by the right (operand) input: per operand when one versor acts on many.
    pub apply_mul: usize,
    /// Additions and subtractions.
    pub add: usize,
}

/// A monomial as `(variable index, exponent)` pairs.
pub type Monomial = Vec<(usize, u32)>;

/// One term `c · m(left) · m(right)` with `m` monomials as `(variable index, exponent)`.
#[derive(Debug, Clone, PartialEq)]
pub struct KTerm {
    /// The rational factor `(num, den)`.
    pub coeff: (i64, i64),
    /// Index into [`ConstrainedKernel::left_monomials`] (`None`: no left factor).
    pub left: Option<usize>,
    /// The right-input monomial as `(field, exponent)`.
    pub right: Monomial,
}

/// A kernel reduced modulo the constraints of its inputs.
#[derive(Debug, Clone, PartialEq)]
pub struct ConstrainedKernel {
    /// Left (versor) and right (operand) type indices.
    pub left: usize,
    /// See `left`.
    pub right: usize,
    /// The constraints it relies on, as doc text (`Motor: rev(x) x = 1`); empty when none.
    pub relies_on: Vec<String>,
    /// The distinct left-input monomials of degree >= 1, shared by all outputs.
    pub left_monomials: Vec<Monomial>,
    /// Each computed output: its basis mask and its terms.
    pub outputs: Vec<(u32, Vec<KTerm>)>,
    /// Masks of the full product that are structurally non-zero but vanish under the
    /// constraints (proven by ideal membership).
    pub vanishing: Vec<u32>,
    /// The smallest declared type holding every non-vanishing output (`None`: no such type).
    pub output_type: Option<usize>,
    /// The same kernel without constraints (boxed; `None` inside itself).
    pub full: Box<ConstrainedKernelFull>,
}

/// The unconstrained counterpart of a [`ConstrainedKernel`] (for its statistics).
#[derive(Debug, Clone, PartialEq)]
pub struct ConstrainedKernelFull {
    /// Its structurally non-zero output masks.
    pub masks: Vec<u32>,
    /// Its output type.
    pub output_type: Option<usize>,
    /// Its counts.
    pub counts: Counts,
}

impl ConstrainedKernelFull {
    /// The unconstrained kernel's counts.
    pub fn stats(&self) -> Counts {
        self.counts
    }
}

/// The smallest declared type whose elements include every mask.
pub(crate) fn smallest_type(spec: &ModuleSpec, masks: &[u32]) -> Option<usize> {
    (0..spec.types.len())
        .filter(|&t| masks.iter().all(|m| spec.types[t].elements.contains(m)))
        .min_by_key(|&t| spec.types[t].elements.len())
}

fn degree(m: &[(usize, u32)]) -> usize {
    m.iter().map(|&(_, e)| e as usize).sum()
}

impl ConstrainedKernel {
    /// No outputs, no constraints, zero counts (filled in by the reduction or the table).
    pub(crate) fn empty() -> ConstrainedKernel {
        ConstrainedKernel {
            left: 0,
            right: 0,
            relies_on: Vec::new(),
            left_monomials: Vec::new(),
            outputs: Vec::new(),
            vanishing: Vec::new(),
            output_type: None,
            full: Box::new(ConstrainedKernelFull {
                masks: Vec::new(),
                output_type: None,
                counts: Counts { outputs: 0, terms: 0, mul: 0, setup_mul: 0, apply_mul: 0, add: 0 },
            }),
        }
    }

    /// Operation counts in the matrix layout.
    ///
    /// ```
    /// # #[cfg(feature = "constraints")] {
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::ModuleSpec;
    /// use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_product};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
    /// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    /// let k = constrained_product(&spec, 0, 1, &unit).unwrap();
    /// let c = k.stats();
    /// assert_eq!(c.mul, c.setup_mul + c.apply_mul);
    /// assert!(c.mul <= k.full.stats().mul);
    /// # }
    /// ```
    pub fn stats(&self) -> Counts {
        let mut setup: usize = self.left_monomials.iter().map(|m| degree(m).saturating_sub(1)).sum();
        let (mut add, mut terms, mut apply) = (0, 0, 0);
        for (_, ts) in &self.outputs {
            terms += ts.len();
            let groups = group(ts);
            add += groups.len().saturating_sub(1);
            for (right, inner) in &groups {
                add += inner.len() - 1;
                // one multiplication per distinct |coefficient| != 1: c (m1 ± m2 ...)
                let factors: BTreeSet<(i64, i64)> =
                    inner.iter().map(|t| (t.coeff.0.abs(), t.coeff.1)).filter(|&c| c != (1, 1)).collect();
                setup += factors.len();
                let constant_unit =
                    inner.len() == 1 && inner[0].left.is_none() && crate::ratio::is_unit(inner[0].coeff);
                apply += degree(right).saturating_sub(1);
                if !right.is_empty() && !constant_unit {
                    apply += 1;
                }
            }
        }
        Counts { outputs: self.outputs.len(), terms, mul: setup + apply, setup_mul: setup, apply_mul: apply, add }
    }

    /// Evaluates the kernel (in its layout) on coefficient slices of the two inputs, in the
    /// types' element order; returns `(mask, value)` per computed output. Valid only on inputs
    /// satisfying [`ConstrainedKernel::relies_on`].
    ///
    /// ```
    /// # #[cfg(feature = "constraints")] {
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::ModuleSpec;
    /// use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_product};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
    /// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    /// use algebra_core::rational::ratio;
    /// // R = (3 + 4 e12)/5 times e1: (3/5) e1 - (4/5) e2
    /// let k = constrained_product(&spec, 0, 1, &unit).unwrap();
    /// let r = [ratio(3, 5), ratio(4, 5), ratio(0, 1), ratio(0, 1)];
    /// let out = k.eval(&r, &[ratio(1, 1), ratio(0, 1), ratio(0, 1)]);
    /// assert!(out.contains(&(0b001, ratio(3, 5))) && out.contains(&(0b010, ratio(-4, 5))));
    /// # }
    /// ```
    pub fn eval<T: Ring>(&self, a: &[T], b: &[T]) -> Vec<(u32, T)> {
        let pow = |x: &[T], m: &[(usize, u32)]| {
            m.iter().fold(T::one(), |acc, &(i, e)| (0..e).fold(acc, |acc, _| acc.mul_ref(&x[i])))
        };
        let shared: Vec<T> = self.left_monomials.iter().map(|m| pow(a, m)).collect();
        self.outputs
            .iter()
            .map(|(mask, ts)| {
                let mut acc = T::zero();
                for (right, inner) in group(ts) {
                    let mut s = T::zero();
                    for t in inner {
                        let l = t.left.map_or_else(T::one, |i| shared[i].clone());
                        s = s.add_ref(&l.mul_ref(&T::from_ratio(t.coeff.0, t.coeff.1)));
                    }
                    acc = acc.add_ref(&s.mul_ref(&pow(b, &right)));
                }
                (*mask, acc)
            })
            .collect()
    }

    /// Doc lines for the generated kernel: the constraints it relies on and what they saved.
    ///
    /// ```
    /// # #[cfg(feature = "constraints")] {
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::ModuleSpec;
    /// use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_product};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
    /// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    /// let k = constrained_product(&spec, 0, 1, &unit).unwrap();
    /// assert!(k.doc()[0].starts_with(" Valid only for inputs satisfying Rotor: rev(x) x = 1"));
    /// # }
    /// ```
    pub fn doc(&self) -> Vec<String> {
        let (c, f) = (self.stats(), self.full.stats());
        let mut lines = vec![format!(
            " Valid only for inputs satisfying {}; {} multiplications instead of {} ({} terms instead of {}).",
            self.relies_on.join(" and "),
            c.mul,
            f.mul,
            c.terms,
            f.terms
        )];
        if !self.vanishing.is_empty() {
            lines.push(format!(
                " {} output components vanish under the constraints (proven by ideal membership).",
                self.vanishing.len()
            ));
        }
        lines
    }
}

/// Groups terms by their right monomial (the operand factor), in first-seen order.
pub(crate) fn group(ts: &[KTerm]) -> Vec<(Monomial, Vec<&KTerm>)> {
    let mut seen: BTreeSet<Monomial> = BTreeSet::new();
    let mut out: Vec<(Monomial, Vec<&KTerm>)> = Vec::new();
    for t in ts {
        if seen.insert(t.right.clone()) {
            out.push((t.right.clone(), Vec::new()));
        }
        out.iter_mut().find(|(r, _)| *r == t.right).expect("inserted").1.push(t);
    }
    out
}

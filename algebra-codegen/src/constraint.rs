//! Constrained kernels: a type declared with a polynomial constraint (a unit versor,
//! `rev(x) x = 1`; a null vector, `x x = 0`; a simple bivector such as a PGA line, `x ∧ x = 0`)
//! lets the generator shorten the kernels that take it. Every output component of the product
//! (or versor action) is expanded as a polynomial in the input coefficients, reduced modulo the
//! constraint ideal (a reduced Gröbner basis, [`algebra_core::ideal`]), and the cheapest
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
//! Behind the `constraints` feature (it needs `algebra-core`'s `rug` for `Poly` and ideals).
//!
//! ```
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
//! ```

use crate::ModuleSpec;
use crate::versor::Convention;
use algebra_core::ideal::{Budget, GroebnerBasis, IdealError, MonomialOrder, PolyRing};
use algebra_core::{Multivector, MvError, Poly, Ring};
use std::collections::{BTreeMap, BTreeSet};
use std::fmt;

mod tokens;

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
    Ideal(IdealError),
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
            ConstraintError::Ideal(e) => write!(f, "constraint ideal: {e}"),
            ConstraintError::Algebra(e) => write!(f, "constraint: {e}"),
            ConstraintError::NoType(i) => write!(f, "constraint on type #{i}, which is not declared"),
            ConstraintError::CoefficientTooLarge(c) => write!(f, "reduced coefficient {c} does not fit i64/i64"),
            ConstraintError::Inconsistent => write!(f, "the constraints are inconsistent (1 is in their ideal)"),
        }
    }
}

impl std::error::Error for ConstraintError {}

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

/// The versor action `rev(S) x S` (or `S x rev(S)`) of type `versor` on type `operand` with the
/// given constraints (those on other types are ignored).
///
/// # Errors
/// Budget exhausted, inconsistent constraints, unknown types, or huge coefficients.
pub fn constrained_action(
    spec: &ModuleSpec,
    convention: Convention,
    versor: usize,
    operand: usize,
    constraints: &[Constraint],
) -> Result<ConstrainedKernel, ConstraintError> {
    let (s, x) = (symbolic(spec, versor, "a")?, symbolic(spec, operand, "b")?);
    let product = match convention {
        Convention::Sandwich => &(&s.reverse() * &x) * &s,
        Convention::Apply => &(&s * &x) * &s.reverse(),
    };
    build(spec, versor, operand, &s, &x, &product, constraints)
}

/// The geometric product `a b` of types `lhs` and `rhs` with the given constraints.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::ModuleSpec;
/// use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_product};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
/// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
/// let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
/// // unit rotors R1, R2: every output of R1 R2 is kept (their product is again a rotor)
/// let k = constrained_product(&spec, 0, 0, &unit).unwrap();
/// assert_eq!((k.output_type, k.stats().outputs), (Some(0), 4));
/// assert_eq!(k.relies_on, ["Rotor: rev(x) x = 1"]);
/// ```
///
/// # Errors
/// As [`constrained_action`].
pub fn constrained_product(
    spec: &ModuleSpec,
    lhs: usize,
    rhs: usize,
    constraints: &[Constraint],
) -> Result<ConstrainedKernel, ConstraintError> {
    let (a, b) = (symbolic(spec, lhs, "a")?, symbolic(spec, rhs, "b")?);
    build(spec, lhs, rhs, &a, &b, &(&a * &b), constraints)
}

/// A general element of type `ty` with coefficients `{prefix}{field}`.
fn symbolic(spec: &ModuleSpec, ty: usize, prefix: &str) -> Result<Multivector<Poly>, ConstraintError> {
    let t = spec.types.get(ty).ok_or(ConstraintError::NoType(ty))?;
    let mut coeffs = vec![Poly::zero(); spec.algebra.dim()];
    for (i, &m) in t.elements.iter().enumerate() {
        coeffs[m as usize] = Poly::var(&format!("{prefix}{i}"));
    }
    Ok(Multivector::from_coeffs(&spec.algebra, spec.basis, coeffs)?)
}

fn equations(kind: ConstraintKind, x: &Multivector<Poly>) -> Vec<Poly> {
    let m = match kind {
        ConstraintKind::Unit => &(&x.reverse() * x) - &Multivector::scalar(x.algebra(), x.basis(), Poly::one()),
        ConstraintKind::Null => x * x,
        ConstraintKind::Simple => x.op(x),
    };
    m.coeffs().iter().filter(|p| !p.is_exact_zero()).cloned().collect()
}

fn build(
    spec: &ModuleSpec,
    left: usize,
    right: usize,
    a: &Multivector<Poly>,
    b: &Multivector<Poly>,
    product: &Multivector<Poly>,
    constraints: &[Constraint],
) -> Result<ConstrainedKernel, ConstraintError> {
    let mut gens = Vec::new();
    let mut relies_on = Vec::new();
    for c in constraints {
        let t = spec.types.get(c.ty).ok_or(ConstraintError::NoType(c.ty))?;
        for (ty, x) in [(left, a), (right, b)] {
            if c.ty == ty {
                gens.extend(equations(c.kind, x));
            }
        }
        if c.ty == left || c.ty == right {
            relies_on.push(format!("{}: {}", t.name, c.kind));
        }
    }
    let (na, nb) = (spec.types[left].elements.len(), spec.types[right].elements.len());
    let vars: Vec<String> = (0..na).map(|i| format!("a{i}")).chain((0..nb).map(|i| format!("b{i}"))).collect();
    let outputs: Vec<(u32, Poly)> = (0..spec.algebra.dim() as u32)
        .map(|m| (m, product.coeffs()[m as usize].clone()))
        .filter(|(_, p)| !p.is_exact_zero())
        .collect();
    // Gröbner bases under a few variable orders: every normal form is a representative of the
    // same residue class; the cheapest is kept per output.
    let budget = Budget::default();
    let mut bases: Vec<GroebnerBasis> = Vec::new();
    if !gens.is_empty() {
        for rot in 0..na.max(1) {
            let order: Vec<&String> = vars[rot..na].iter().chain(&vars[..rot]).chain(&vars[na..]).collect();
            let g = PolyRing::new(order, MonomialOrder::GrevLex).groebner(&gens, &budget)?;
            if g.is_unit() {
                return Err(ConstraintError::Inconsistent);
            }
            bases.push(g);
        }
    }
    // Candidate representative sets: the unreduced outputs, each basis's normal forms, and the
    // per-output cheapest mix; the cheapest set as a whole wins (shared monomials count once).
    let mut vanishing = Vec::new();
    let mut per_basis: Vec<Vec<(u32, Poly)>> = vec![Vec::new(); bases.len()];
    let mut unreduced = Vec::new();
    let mut mixed = Vec::new();
    for (m, p) in &outputs {
        let forms = bases.iter().map(|g| g.normal_form_within(p, &budget)).collect::<Result<Vec<_>, _>>()?;
        if forms.iter().any(Poly::is_exact_zero) {
            vanishing.push(*m);
            continue;
        }
        let best = forms.iter().chain([p]).min_by_key(|r| cost(r)).expect("non-empty").clone();
        mixed.push((*m, best));
        unreduced.push((*m, p.clone()));
        for (set, r) in per_basis.iter_mut().zip(forms) {
            set.push((*m, r));
        }
    }
    let mut reduced = unreduced;
    for candidate in per_basis.into_iter().chain([mixed]) {
        let (c, r) = (layout(&candidate)?.stats(), layout(&reduced)?.stats());
        if (c.mul, c.terms) < (r.mul, r.terms) {
            reduced = candidate;
        }
    }
    let full_masks: Vec<u32> = outputs.iter().map(|(m, _)| *m).collect();
    let kept: Vec<u32> = reduced.iter().map(|(m, _)| *m).collect();
    let full_kernel = layout(&outputs)?;
    let mut kernel = layout(&reduced)?;
    kernel.left = left;
    kernel.right = right;
    kernel.relies_on = relies_on;
    kernel.vanishing = vanishing;
    kernel.output_type = smallest_type(spec, &kept);
    kernel.full =
        Box::new(ConstrainedKernelFull { output_type: smallest_type(spec, &full_masks), counts: full_kernel.stats() });
    Ok(kernel)
}

/// The smallest declared type whose elements include every mask.
fn smallest_type(spec: &ModuleSpec, masks: &[u32]) -> Option<usize> {
    (0..spec.types.len())
        .filter(|&t| masks.iter().all(|m| spec.types[t].elements.contains(m)))
        .min_by_key(|&t| spec.types[t].elements.len())
}

/// Splits a monomial into its left (`a{i}`) and right (`b{i}`) parts.
fn split(mono: &[(String, u32)]) -> (Monomial, Monomial) {
    let (mut l, mut r) = (Vec::new(), Vec::new());
    for (name, e) in mono {
        let idx: usize = name[1..].parse().expect("variables are a{i} / b{i}");
        if name.starts_with('a') { l.push((idx, *e)) } else { r.push((idx, *e)) }
    }
    (l, r)
}

/// The multiplications of one polynomial in the matrix layout (monomials not shared).
fn cost(p: &Poly) -> (usize, usize) {
    let k = layout(&[(0, p.clone())]).map(|k| k.stats()).unwrap_or(Counts {
        outputs: 0,
        terms: 0,
        mul: usize::MAX,
        setup_mul: 0,
        apply_mul: 0,
        add: 0,
    });
    (k.mul, k.terms)
}

fn small(c: &rug::Rational) -> Result<(i64, i64), ConstraintError> {
    match (c.numer().to_i64(), c.denom().to_i64()) {
        (Some(n), Some(d)) => Ok((n, d)),
        _ => Err(ConstraintError::CoefficientTooLarge(c.to_string())),
    }
}

fn layout(outputs: &[(u32, Poly)]) -> Result<ConstrainedKernel, ConstraintError> {
    let mut monos: BTreeMap<Monomial, usize> = BTreeMap::new();
    let mut out = Vec::new();
    for (m, p) in outputs {
        let mut terms = Vec::new();
        for (c, mono) in p.terms() {
            let (l, r) = split(&mono);
            let left = if l.is_empty() {
                None
            } else {
                let n = monos.len();
                Some(*monos.entry(l).or_insert(n))
            };
            terms.push(KTerm { coeff: small(c)?, left, right: r });
        }
        out.push((*m, terms));
    }
    let mut left_monomials = vec![Vec::new(); monos.len()];
    for (mono, i) in monos {
        left_monomials[i] = mono;
    }
    Ok(ConstrainedKernel {
        left: 0,
        right: 0,
        relies_on: Vec::new(),
        left_monomials,
        outputs: out,
        vanishing: Vec::new(),
        output_type: None,
        full: Box::new(ConstrainedKernelFull {
            output_type: None,
            counts: Counts { outputs: 0, terms: 0, mul: 0, setup_mul: 0, apply_mul: 0, add: 0 },
        }),
    })
}

fn degree(m: &[(usize, u32)]) -> usize {
    m.iter().map(|&(_, e)| e as usize).sum()
}

impl ConstrainedKernel {
    /// Operation counts in the matrix layout.
    ///
    /// ```
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
                    inner.len() == 1 && inner[0].left.is_none() && inner[0].coeff.0.abs() == 1 && inner[0].coeff.1 == 1;
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
    /// use algebra_core::{Algebra, Basis};
    /// use algebra_codegen::ModuleSpec;
    /// use algebra_codegen::constraint::{Constraint, ConstraintKind, constrained_product};
    /// let alg = Algebra::builtin("g3").unwrap();
    /// let types = ModuleSpec::parse_types("Rotor=even;Vector=grade1", &alg).unwrap();
    /// let spec = ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap();
    /// let unit = [Constraint { ty: 0, kind: ConstraintKind::Unit }];
    /// let k = constrained_product(&spec, 0, 1, &unit).unwrap();
    /// assert!(k.doc()[0].starts_with(" Valid only for inputs satisfying Rotor: rev(x) x = 1"));
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

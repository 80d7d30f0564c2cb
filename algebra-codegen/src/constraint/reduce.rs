//! The reduction behind [`super`]: every output of the product or action expanded over
//! [`Poly`], reduced modulo the constraint ideal (reduced Gröbner bases under several variable
//! orders), the cheapest representatives laid out as a [`ConstrainedKernel`]. Needs `rug`
//! (feature `constraints`).

use super::{
    ConstrainedKernel, ConstrainedKernelFull, Constraint, ConstraintError, ConstraintKind, Counts, KTerm, Monomial,
    smallest_type,
};
use crate::ModuleSpec;
use crate::versor::Convention;
use algebra_core::ideal::{Budget, GroebnerBasis, MonomialOrder, PolyRing};
use algebra_core::{Multivector, Poly, Ring};
use std::collections::BTreeMap;

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

/// The square `x x` of a value of type `ty` with the given constraints (one element on both
/// sides, so a null vector squares to zero and a simple bivector to a scalar).
///
/// # Errors
/// As [`constrained_action`].
pub fn constrained_square(
    spec: &ModuleSpec,
    ty: usize,
    constraints: &[Constraint],
) -> Result<ConstrainedKernel, ConstraintError> {
    let a = symbolic(spec, ty, "a")?;
    build(spec, ty, ty, &a, &a, &(&a * &a), constraints)
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
    kernel.full = Box::new(ConstrainedKernelFull {
        output_type: smallest_type(spec, &full_masks),
        masks: full_masks,
        counts: full_kernel.stats(),
    });
    Ok(kernel)
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
    Ok(ConstrainedKernel { left_monomials, outputs: out, ..ConstrainedKernel::empty() })
}

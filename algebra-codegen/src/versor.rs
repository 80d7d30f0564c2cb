//! The fused versor action: for a versor type `V` and an operand type `X`, one straight-line
//! kernel computing only `X`'s components of
//!
//! - `sandwich`: `rev(S) x S` (the main paper's `f_S(x)`, eq. (3)), and
//! - `apply`: `S x rev(S)` (the convention of klein, GATL and ganja),
//!
//! built from the exact tables in two stages: the intermediate `rev(S) x` (or `S x`) keeps only
//! the coefficients that reach an output component, and the output sums their products with
//! `S` (or `rev(S)`). The result is the projection of the full product onto `X`: it *is* the
//! action whenever `S` is a versor whose action preserves `X`'s grades (motors and rotors on
//! vectors, bivectors, points, lines, planes, motors), since the other components then vanish.
//!
//! Versor types are the declared types (other than the full multivector) whose basis elements
//! all have the same parity; every other pair keeps the composed full product.

use super::{CodegenError, ModuleSpec};
use crate::ratio::{Ratio, to_ratio};
use algebra_core::rational::Q;
use algebra_core::tables::{Product, Unary};
use algebra_core::{Basis, Multivector};
use num_traits::Zero;
use std::collections::BTreeMap;

/// Which side of the operand carries the reverse.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Convention {
    /// `rev(S) x S` (`sandwich`, the main paper's).
    Sandwich,
    /// `S x rev(S)` (`apply`, klein/GATL/ganja).
    Apply,
}

/// One fused action kernel.
#[derive(Debug, Clone)]
pub struct ActionKernel {
    /// The convention.
    pub convention: Convention,
    /// Versor type index.
    pub versor: usize,
    /// Operand (and output) type index.
    pub operand: usize,
    /// The intermediate coefficients: each a sum of `c · s[a] · x[b]` as `(a, b, c)`.
    pub stage1: Vec<Vec<(usize, usize, Ratio)>>,
    /// Each output field: a sum of `c · t[k] · s[a]` as `(k, a, c)`.
    pub stage2: Vec<Vec<(usize, usize, Ratio)>>,
    /// The basis masks outside the operand type where the full product is structurally
    /// non-zero: the kernel drops them (they vanish for versors only).
    pub outside: Vec<u32>,
}

impl ActionKernel {
    /// Multiplications and additions (as [`super::plan::KernelStats`] counts them).
    pub fn counts(&self) -> (usize, usize) {
        let terms = |s: &[Vec<(usize, usize, Ratio)>]| -> (usize, usize) {
            let consts = s.iter().flatten().filter(|t| t.2.0.abs() != 1 || t.2.1 != 1).count();
            let products = s.iter().map(Vec::len).sum::<usize>();
            let adds = s.iter().map(|o| o.len().saturating_sub(1)).sum();
            (products + consts, adds)
        };
        let (m1, a1) = terms(&self.stage1);
        let (m2, a2) = terms(&self.stage2);
        (m1 + m2, a1 + a2)
    }
}

/// Whether type `i` is a versor type: not the full type, every element of one parity.
pub fn is_versor_type(spec: &ModuleSpec, full: usize, i: usize) -> bool {
    let els = &spec.types[i].elements;
    i != full && els.iter().all(|m| m.count_ones() % 2 == els[0].count_ones() % 2)
}

/// The fused kernels of every (versor type, operand type other than the full one) pair, in
/// both conventions.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, versor::{Convention, plan_actions}};
/// let alg = Algebra::builtin("cga-null").unwrap();
/// let types = ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1", &alg).unwrap();
/// let spec = ModuleSpec::new("cga_null", alg.metric().clone(), Basis::Product, types).unwrap();
/// let actions = plan_actions(&spec, 2).unwrap();
/// // Motor and Vector are versor types; each acts on vectors, in both conventions, and the
/// // motor on motors. A vector (a sphere inversion) takes a motor out of the `Motor` type, so
/// // that pair has no fused kernel ([`keeps_operand`]).
/// assert_eq!(actions.len(), 6);
/// let k = actions.iter().find(|k| (k.versor, k.operand, k.convention) == (0, 1, Convention::Sandwich)).unwrap();
/// assert_eq!(k.counts(), (64, 43)); // the pose on a conformal point (motor product: 48, 40)
/// ```
pub fn plan_actions(spec: &ModuleSpec, full: usize) -> Result<Vec<ActionKernel>, CodegenError> {
    let mut out = Vec::new();
    for v in (0..spec.types.len()).filter(|&v| is_versor_type(spec, full, v)) {
        for x in (0..spec.types.len()).filter(|&x| x != full) {
            let (s, a) = (action(spec, Convention::Sandwich, v, x)?, action(spec, Convention::Apply, v, x)?);
            if keeps_operand(spec, &s) && keeps_operand(spec, &a) {
                out.extend([s, a]);
            }
        }
    }
    Ok(out)
}

/// The mean number of terms per output at or below which [`order_for_pairing`] reorders a
/// kernel's terms (measured, docs/performance.md "Term order of the fused actions").
const PAIRING_MEAN_TERMS: usize = 6;

/// Reorders the terms of a fused kernel for LLVM's SLP vectoriser, which packs two adjacent
/// outputs (and two adjacent intermediates) into one SSE register when their expression trees
/// have the same shape. Only the order of the summands changes, so every value over exact
/// scalars is the same (and the other languages' kernels, printed from the same terms, keep
/// adding in the Rust kernel's order).
///
/// - Stage 2 (each output a sum of `t[k] · s[a]`): the terms in the order of the versor field
///   `a` (then `k`), so term `i` of two neighbouring outputs multiplies the same versor
///   coefficient (one broadcast) by two intermediates, instead of the intermediate-major order
///   of the tables, where it multiplies one intermediate by two versor fields in no particular
///   order.
///   A row that would start with a negative term starts with its first positive one instead
///   (no negation of the whole sum).
/// - Stage 1 of `sandwich` (`rev(S) x`, where the reverse scatters the signs): the positive
///   terms first (stable), so neighbouring intermediates more often have the same tree of
///   additions and subtractions. `apply`'s stage 1 (`S x`) keeps its order: sorting it was
///   slower.
///
/// Applied only when the outputs have at most 6 terms on average (`PAIRING_MEAN_TERMS`): the
/// conformal point actions (4-8 terms) and `g3`'s rotor action (4) got faster, `pga3`'s
/// point action (4-8, mean 7) and `cga`'s 16-term outputs slower, where the tables' order
/// already gives neighbouring outputs the same deep trees.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, plan::Plan, versor::Convention};
/// let alg = Algebra::builtin("g3").unwrap();
/// let types = ModuleSpec::parse_types("Vector=grade1;Rotor=even", &alg).unwrap();
/// let plan = Plan::new(ModuleSpec::new("g3", alg.metric().clone(), Basis::Blade, types).unwrap()).unwrap();
/// let k = plan.actions.iter().find(|k| (k.versor, k.operand, k.convention) == (1, 0, Convention::Sandwich)).unwrap();
/// // each output's terms by the rotor's field: 1, e12, e13, e23
/// assert!(k.stage2.iter().all(|row| row.iter().map(|t| t.1).collect::<Vec<_>>() == [0, 1, 2, 3]));
/// // each intermediate's positive terms first
/// assert!(k.stage1.iter().all(|row| row.windows(2).all(|w| w[0].2.0 > 0 || w[1].2.0 < 0)));
/// ```
pub fn order_for_pairing(k: &mut ActionKernel) {
    let terms: usize = k.stage2.iter().map(Vec::len).sum();
    if terms > PAIRING_MEAN_TERMS * k.stage2.len() {
        return;
    }
    for row in &mut k.stage2 {
        row.sort_by_key(|&(t, a, _)| (a, t));
        // a positive term first, as the chains do, so that the sum is not negated at the end
        // (the reflections' outputs; the motors' and rotors' start positive already)
        if row.first().is_some_and(|t| t.2.0 < 0)
            && let Some(p) = row.iter().position(|t| t.2.0 > 0)
        {
            let first = row.remove(p);
            row.insert(0, first);
        }
    }
    if k.convention == Convention::Sandwich {
        for row in &mut k.stage1 {
            row.sort_by_key(|t| t.2.0 < 0);
        }
    }
}

/// Whether a fused kernel is the action of every versor of its type: each component it drops
/// (outside the operand type) has a grade the operand type does not have, so it vanishes for
/// every versor, whose action preserves grades. A dropped component of one of the operand's
/// own grades is a real part of the image: a translation moves the plane `e1` of 3D PGA,
/// declared as `Direction = [e1, e2, e3]`, to `e1 + d e0`, and a projection onto `Direction`
/// would silently lose `d`. Such a pair gets no fused kernel (nor a unit one, nor an action
/// matrix): its `sandwich` and `apply` are the composed full products, whose type holds the
/// whole image. Grades are those of the blade expansion, so a product-basis element such as
/// `e0 einf` (grades 0 and 2) counts as both.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, versor::{keeps_operand, plan_actions}};
/// let alg = Algebra::builtin("pga3").unwrap();
/// let types = ModuleSpec::parse_types("Motor=even;Plane=grade1;Direction=e1,e2,e3", &alg).unwrap();
/// let spec = ModuleSpec::new("p", alg.metric().clone(), Basis::Blade, types).unwrap();
/// let actions = plan_actions(&spec, 3).unwrap();
/// // the motor acts on planes through a fused kernel, on `Direction` through full products
/// // (so do planes: a reflection in a plane off the origin moves `e1` off it); reflections in
/// // `Direction`s keep a `Direction` one
/// assert!(actions.iter().any(|k| (k.versor, k.operand) == (0, 1)));
/// assert!(!actions.iter().any(|k| k.operand == 2 && k.versor != 2));
/// assert!(actions.iter().any(|k| (k.versor, k.operand) == (2, 2)));
/// assert!(actions.iter().all(|k| keeps_operand(&spec, k)));
/// ```
pub fn keeps_operand(spec: &ModuleSpec, k: &ActionKernel) -> bool {
    let grades = |mask: u32| -> Vec<u32> {
        let m = Multivector::<Q>::from_mask(&spec.algebra, spec.basis, mask).expect("a mask of the spec's algebra");
        m.in_basis(Basis::Blade).terms().filter(|(_, _, c)| !c.is_zero()).map(|(b, _, _)| b.count_ones()).collect()
    };
    let own: Vec<u32> = spec.types[k.operand].elements.iter().flat_map(|&m| grades(m)).collect();
    k.outside.iter().all(|&m| grades(m).iter().all(|g| !own.contains(g)))
}

/// Whether a type is a kinematic versor type (a motor or rotor): every basis element even, and
/// the scalar `1` among them (so it holds the identity motion). Their action matrices stay
/// straight-line code (`emit::matrix`, the batch transforms); the default standalone file keeps
/// the actions of these types only, and bivector types (`Line`) and odd versors (reflections in
/// planes, point reflections) act there through `--ops` or `--every-type`.
///
/// ```
/// use algebra_codegen::versor::is_kinematic;
/// assert!(is_kinematic(&[0, 0b011, 0b101, 0b110])); // 1, e12, e13, e23: a rotor
/// assert!(!is_kinematic(&[0b011, 0b101, 0b110])); // bivectors: no identity
/// assert!(!is_kinematic(&[0, 0b001])); // 1 + e1: not even
/// ```
pub fn is_kinematic(elements: &[u32]) -> bool {
    elements.contains(&0) && elements.iter().all(|m| m.count_ones() % 2 == 0)
}

fn action(spec: &ModuleSpec, convention: Convention, v: usize, x: usize) -> Result<ActionKernel, CodegenError> {
    action_kernel(spec, convention, v, x, false)
}

/// Whether the blade of `mask` is also the geometric product of its generators: every pair of
/// them is orthogonal, so the element is the same in the blade and the product basis.
fn same_in_both_bases(spec: &ModuleSpec, mask: u32) -> bool {
    let metric = spec.algebra.metric();
    let gens: Vec<usize> = (0..32).filter(|i| mask >> i & 1 == 1).collect();
    gens.iter().enumerate().all(|(n, &i)| gens[n + 1..].iter().all(|&j| metric.gram(i, j).is_ok_and(Zero::is_zero)))
}

/// The two stages of an action; with `commutator`, stage 1 is `L(S) x - x L(S)` instead of
/// `L(S) x` (the unit-versor form of [`super::unit`]).
///
/// In a blade basis with a non-diagonal metric (GATL's conformal `eo, einf`), the intermediate
/// `L(S) x` expanded in blades such as `e1 ∧ eo ∧ einf` multiplies out into more terms than in
/// the product basis (`e1 eo einf`), where a null pair's products stay single terms. When
/// every field of `S` and `x` is the same element in both bases (their generators pairwise
/// orthogonal: motors and points of the conformal model), the intermediate may be taken in
/// either: the kernel with fewer operations is kept (the module's own basis on a tie), its
/// inputs and outputs unchanged. The components dropped outside `x` are named in the
/// module's basis.
pub(super) fn action_kernel(
    spec: &ModuleSpec,
    convention: Convention,
    v: usize,
    x: usize,
    commutator: bool,
) -> Result<ActionKernel, CodegenError> {
    let own = action_kernel_in(spec, spec.basis, convention, v, x, commutator)?;
    let (vm, xm) = (&spec.types[v].elements, &spec.types[x].elements);
    let other = match spec.basis {
        Basis::Blade => Basis::Product,
        Basis::Product => return Ok(own),
    };
    if spec.algebra.metric().is_diagonal() || !vm.iter().chain(xm).all(|&m| same_in_both_bases(spec, m)) {
        return Ok(own);
    }
    let alt = action_kernel_in(spec, other, convention, v, x, commutator)?;
    let cost = |k: &ActionKernel| {
        let (m, a) = k.counts();
        m + a
    };
    Ok(if cost(&alt) < cost(&own) { ActionKernel { outside: own.outside, ..alt } } else { own })
}

fn action_kernel_in(
    spec: &ModuleSpec,
    basis: Basis,
    convention: Convention,
    v: usize,
    x: usize,
    commutator: bool,
) -> Result<ActionKernel, CodegenError> {
    let tables = spec.algebra.tables();
    let gp = tables.product(basis, Product::Geometric);
    let rev = tables.unary(basis, Unary::Reverse);
    let (vm, xm) = (&spec.types[v].elements, &spec.types[x].elements);
    // the versor's field `a` as a sum of basis elements, reversed or not
    let image = |a: usize, reversed: bool| -> Vec<(u32, Q)> {
        if reversed {
            rev.image(vm[a]).expect("a mask of the spec's algebra").to_vec()
        } else {
            vec![(vm[a], Q::from_integer(1.into()))]
        }
    };
    let (left_rev, right_rev) = match convention {
        Convention::Sandwich => (true, false),
        Convention::Apply => (false, true),
    };
    // stage 1: t = L(S) x, keyed by basis mask
    let mut t: BTreeMap<u32, BTreeMap<(usize, usize), Q>> = BTreeMap::new();
    for a in 0..vm.len() {
        for (m, r) in image(a, left_rev) {
            for (b, &mb) in xm.iter().enumerate() {
                for (k, c) in gp.get(m, mb).expect("a mask of the spec's algebra") {
                    *t.entry(*k).or_default().entry((a, b)).or_insert_with(Q::zero) += &r * c;
                }
                if commutator {
                    for (k, c) in gp.get(mb, m).expect("a mask of the spec's algebra") {
                        *t.entry(*k).or_default().entry((a, b)).or_insert_with(Q::zero) -= &r * c;
                    }
                }
            }
        }
    }
    t.values_mut().for_each(|e| e.retain(|_, c| !c.is_zero()));
    t.retain(|_, e| !e.is_empty());
    // stage 2: out_j = Σ t_k R(S)_a, keyed by (j, k, a)
    let mut o: BTreeMap<u32, BTreeMap<(u32, usize), Q>> = BTreeMap::new();
    for &k in t.keys() {
        for a in 0..vm.len() {
            for (m, r) in image(a, right_rev) {
                for (j, c) in gp.get(k, m).expect("a mask of the spec's algebra") {
                    *o.entry(*j).or_default().entry((k, a)).or_insert_with(Q::zero) += &r * c;
                }
            }
        }
    }
    o.values_mut().for_each(|e| e.retain(|_, c| !c.is_zero()));
    // a component outside X is dropped when its polynomial in (s, x) is not identically zero
    // (`s_a s_a'` commute, so `(a, a', b)` and `(a', a, b)` are one monomial)
    let nonzero = |e: &BTreeMap<(u32, usize), Q>| {
        let mut poly: BTreeMap<(usize, usize, usize), Q> = BTreeMap::new();
        for (&(k, a), c) in e {
            for (&(a1, b), c1) in &t[&k] {
                *poly.entry((a.min(a1), a.max(a1), b)).or_insert_with(Q::zero) += c * c1;
            }
        }
        poly.values().any(|c| !c.is_zero())
    };
    let outside: Vec<u32> = o.iter().filter(|(j, e)| !xm.contains(j) && nonzero(e)).map(|(j, _)| *j).collect();
    o.retain(|j, _| xm.contains(j));
    let used: Vec<u32> = t.keys().copied().filter(|k| o.values().any(|e| e.keys().any(|(kk, _)| kk == k))).collect();
    let stage1 = used
        .iter()
        .map(|k| t[k].iter().map(|(&(a, b), c)| Ok((a, b, to_ratio(c)?))).collect::<Result<Vec<_>, _>>())
        .collect::<Result<Vec<_>, _>>()?;
    let stage2 = xm
        .iter()
        .map(|j| {
            o.get(j)
                .map(|e| {
                    e.iter()
                        .map(|(&(k, a), c)| {
                            let ki = used.iter().position(|u| *u == k).expect("used intermediate");
                            Ok((ki, a, to_ratio(c)?))
                        })
                        .collect::<Result<Vec<_>, _>>()
                })
                .unwrap_or(Ok(Vec::new()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    Ok(ActionKernel { convention, versor: v, operand: x, stage1, stage2, outside })
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spec::TypeSpec;
    use algebra_core::{Algebra, Metric, Multivector};

    /// GATL's conformal declaration (blade basis, `eo · einf = -1`): the intermediate is taken
    /// in the product basis (fewer operations), and the kernel still gives the blade-basis
    /// action computed by the runtime product `rev(S) x S` / `S x rev(S)` (exact rationals).
    #[test]
    fn null_pair_in_a_blade_basis_takes_the_cheaper_intermediate() {
        let z = "0";
        let gram: [&[&str]; 5] =
            [&["1", z, z, z, z], &[z, "1", z, z, z], &[z, z, "1", z, z], &[z, z, z, z, "-1"], &[z, z, z, "-1", z]];
        let metric = Metric::from_strs(&["1", "2", "3", "o", "inf"], &gram).unwrap();
        let alg = Algebra::new("gatl", metric.clone());
        let types =
            ModuleSpec::parse_types("Motor=1,e12,e13,e23,e1inf,e2inf,e3inf,e123inf;Vector=grade1", &alg).unwrap();
        let spec = ModuleSpec::new("gatl", metric, Basis::Blade, types).unwrap();
        let alg = spec.algebra.clone();
        let q = |n: i64| Q::from_integer(n.into());
        let s: Vec<Q> = [3, -1, 2, 5, -4, 7, 1, -2].into_iter().map(q).collect();
        let x: Vec<Q> = [2, -3, 1, 4, -5].into_iter().map(q).collect();
        let mv = |t: &TypeSpec, c: &[Q]| {
            let mut coeffs = vec![Q::zero(); alg.dim()];
            for (m, v) in t.elements.iter().zip(c) {
                coeffs[*m as usize] = v.clone();
            }
            Multivector::from_coeffs(&alg, Basis::Blade, coeffs).unwrap()
        };
        let (sm, xm) = (mv(&spec.types[0], &s), mv(&spec.types[1], &x));
        for convention in [Convention::Sandwich, Convention::Apply] {
            let k = action_kernel(&spec, convention, 0, 1, false).unwrap();
            let blade = action_kernel_in(&spec, Basis::Blade, convention, 0, 1, false).unwrap();
            let (total, blade_total) = (k.counts().0 + k.counts().1, blade.counts().0 + blade.counts().1);
            assert!(total < blade_total, "{convention:?}: {total} vs {blade_total}");
            let r = |c: (i64, i64)| Q::new(c.0.into(), c.1.into());
            let t: Vec<Q> =
                k.stage1.iter().map(|row| row.iter().map(|&(a, b, c)| r(c) * &s[a] * &x[b]).sum()).collect();
            let out: Vec<Q> =
                k.stage2.iter().map(|row| row.iter().map(|&(i, a, c)| r(c) * &t[i] * &s[a]).sum()).collect();
            let reference = match convention {
                Convention::Sandwich => &(&sm.reverse() * &xm) * &sm,
                Convention::Apply => &(&sm * &xm) * &sm.reverse(),
            };
            for (j, m) in spec.types[1].elements.iter().enumerate() {
                assert_eq!(&out[j], reference.coeff(*m).unwrap(), "{convention:?} component {m:#b}");
            }
        }
    }
}

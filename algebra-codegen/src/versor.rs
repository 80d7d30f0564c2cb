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
/// // Motor and Vector are versor types; each acts on both, in both conventions
/// assert_eq!(actions.len(), 8);
/// let k = actions.iter().find(|k| (k.versor, k.operand, k.convention) == (0, 1, Convention::Sandwich)).unwrap();
/// assert_eq!(k.counts(), (64, 43)); // the pose on a conformal point (motor product: 48, 40)
/// ```
pub fn plan_actions(spec: &ModuleSpec, full: usize) -> Result<Vec<ActionKernel>, CodegenError> {
    let mut out = Vec::new();
    for v in (0..spec.types.len()).filter(|&v| is_versor_type(spec, full, v)) {
        for x in (0..spec.types.len()).filter(|&x| x != full) {
            for convention in [Convention::Sandwich, Convention::Apply] {
                out.push(action(spec, convention, v, x)?);
            }
        }
    }
    Ok(out)
}

fn action(spec: &ModuleSpec, convention: Convention, v: usize, x: usize) -> Result<ActionKernel, CodegenError> {
    action_kernel(spec, convention, v, x, false)
}

/// The two stages of an action; with `commutator`, stage 1 is `L(S) x - x L(S)` instead of
/// `L(S) x` (the unit-versor form of [`super::unit`]).
pub(super) fn action_kernel(
    spec: &ModuleSpec,
    convention: Convention,
    v: usize,
    x: usize,
    commutator: bool,
) -> Result<ActionKernel, CodegenError> {
    let tables = spec.algebra.tables();
    let gp = tables.product(spec.basis, Product::Geometric);
    let rev = tables.unary(spec.basis, Unary::Reverse);
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

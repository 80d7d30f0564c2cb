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

use super::emit::{Names, SumTerm, tree_sum as sum};
use super::plan::{Ratio, to_ratio};
use super::{CodegenError, ModuleSpec};
use algebra_core::rational::Q;
use algebra_core::tables::{Product, Unary};
use num_traits::Zero;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
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

fn names_of(convention: Convention) -> (TokenStream, TokenStream) {
    match convention {
        Convention::Sandwich => (quote!(Sandwich), quote!(sandwich)),
        Convention::Apply => (quote!(Apply), quote!(apply)),
    }
}

/// The impl of one fused kernel.
pub(super) fn action_items(names: &Names, k: &ActionKernel) -> TokenStream {
    let (vt, xt) = (&names.types[k.versor], &names.types[k.operand]);
    let (trait_name, method) = names_of(k.convention);
    // straight-line kernels are always inlined: LLVM declined the `#[inline]` hint for the
    // conformal point action, and the call cost 7 % (1.38 → 1.31 × the motor product)
    let large = super::size::is_large(names.table_above, k.stage1.iter().chain(&k.stage2).map(Vec::len));
    let (body, inline) = if large {
        (table_body(names, k), quote!(#[inline]))
    } else {
        (unrolled_body(names, k), quote!(#[inline(always)]))
    };
    let product = match k.convention {
        Convention::Sandwich => "rev(self) x self",
        Convention::Apply => "self x rev(self)",
    };
    let doc = if k.outside.is_empty() {
        format!("`{product}` in one fused kernel: every component of the full product is a [`{xt}`] component.")
    } else {
        format!(
            "`{product}` projected onto [`{xt}`] in one fused kernel. The full product also has {} component(s) outside `{xt}`, dropped here: they vanish when `self` is a versor (a product of invertible vectors; for unit ones `{}_unit` is cheaper and says whether that is proven), not for every `{vt}`. The full product: `gp` twice.",
            k.outside.len(),
            method
        )
    };
    quote! {
        impl<T: ::algebra_core::Ring> ::algebra_core::ops::#trait_name<#xt<T>> for #vt<T> {
            type Output = #xt<T>;
            #[doc = #doc]
            #inline
            fn #method(&self, x: &#xt<T>) -> #xt<T> {
                #body
            }
        }
    }
}

/// The two stages as loops over constant tables (the size policy, [`super::size`]).
fn table_body(names: &Names, k: &ActionKernel) -> TokenStream {
    let flat = |stage: &[Vec<(usize, usize, Ratio)>]| -> Vec<(usize, usize, usize, Ratio)> {
        stage.iter().enumerate().flat_map(|(o, ts)| ts.iter().map(move |&(i, j, c)| (i, j, o, c))).collect()
    };
    let (vf, xf, xt) = (&names.fields[k.versor], &names.fields[k.operand], &names.types[k.operand]);
    let s = super::size::refs(quote!(self), vf);
    let x = super::size::refs(quote!(x), xf);
    let stage1 = super::size::table_loop(&flat(&k.stage1), &quote!(s), &quote!(x), &quote!(t), k.stage1.len());
    let stage2 = super::size::table_loop(&flat(&k.stage2), &quote!(tr), &quote!(s), &quote!(out), xf.len());
    quote! {
        let s = #s;
        let x = #x;
        let t = { #stage1 t };
        let tr = t.each_ref();
        let out = { #stage2 out };
        #xt::from_array(out)
    }
}

/// A term `c · self.field · y` as `(±1, (|c| · self.field) · y)` when `|c| != 1`: the constant
/// multiplies the versor's coefficient, which does not depend on the operand, so it leaves the
/// operand's dependency chain (the conformal point action: 1.31 → 1.28 × the motor product,
/// docs/performance.md). The same value exactly over any ring, and in floating point for a
/// power of two such as the 2 of the conformal action.
fn scaled(c: Ratio, field: &proc_macro2::Ident) -> (Ratio, TokenStream) {
    let (n, d) = c;
    if n.abs() == 1 && d == 1 {
        return (c, quote!(self.#field));
    }
    let k = n.abs();
    ((n.signum(), 1), quote!((T::from_ratio(#k, #d) * &self.#field)))
}

/// The first stage as bindings `let t0 = ...;` (sums of `self` fields times `x` fields).
pub(super) fn stage1_binds(names: &Names, k: &ActionKernel) -> Vec<TokenStream> {
    let (vf, xf) = (&names.fields[k.versor], &names.fields[k.operand]);
    let mut binds = Vec::new();
    for (i, terms) in k.stage1.iter().enumerate() {
        let summands: Vec<SumTerm> = terms
            .iter()
            .map(|&(a, b, c)| {
                let (c, fa) = scaled(c, &vf[a]);
                let fb = &xf[b];
                (c, quote!((#fa.mul_ref(&x.#fb))), true)
            })
            .collect();
        let ti = format_ident!("t{}", i);
        let e = sum(summands);
        binds.push(quote!(let #ti = #e;));
    }
    binds
}

/// The two stages as straight-line code.
fn unrolled_body(names: &Names, k: &ActionKernel) -> TokenStream {
    let (xt, vf, xf) = (&names.types[k.operand], &names.fields[k.versor], &names.fields[k.operand]);
    let binds = stage1_binds(names, k);
    let outs = k.stage2.iter().map(|terms| {
        sum(terms
            .iter()
            .map(|&(i, a, c)| {
                let (c, fa) = scaled(c, &vf[a]);
                let ti = format_ident!("t{}", i);
                (c, quote!((#ti.mul_ref(&#fa))), true)
            })
            .collect())
    });
    quote! {
        #(#binds)*
        #xt { #(#xf: #outs),* }
    }
}

/// The impls for a (type, operand) pair without a fused kernel: the composed full products.
pub(super) fn composed_items(names: &Names, v: usize, x: usize, out: (usize, usize)) -> TokenStream {
    let (vt, xt) = (&names.types[v], &names.types[x]);
    let (so, ao) = (&names.types[out.0], &names.types[out.1]);
    let gp = quote!(::algebra_core::ops::GeometricProduct::gp);
    quote! {
        impl<T: ::algebra_core::Ring> ::algebra_core::ops::Sandwich<#xt<T>> for #vt<T> {
            type Output = #so<T>;
            /// `rev(self) x self` as two full products (no fused kernel for this pair).
            fn sandwich(&self, x: &#xt<T>) -> #so<T> { #gp(&#gp(&self.reverse(), x), self) }
        }
        impl<T: ::algebra_core::Ring> ::algebra_core::ops::Apply<#xt<T>> for #vt<T> {
            type Output = #ao<T>;
            /// `self x rev(self)` as two full products (no fused kernel for this pair).
            fn apply(&self, x: &#xt<T>) -> #ao<T> { #gp(&#gp(self, x), &self.reverse()) }
        }
    }
}

/// Every `Sandwich` and `Apply` impl of the module, plus the inherent methods' names.
pub(super) fn module_items(plan: &super::plan::Plan, names: &Names) -> TokenStream {
    let mut items: Vec<TokenStream> = plan.actions.iter().map(|k| action_items(names, k)).collect();
    let n = plan.spec.types.len();
    for v in 0..n {
        for x in 0..n {
            if plan.actions.iter().any(|k| k.versor == v && k.operand == x) {
                continue;
            }
            let rev = plan.unary.iter().find(|k| k.ty == v && k.op == Unary::Reverse).expect("planned").out;
            let s1 = plan.kernel(Product::Geometric, rev, x).out;
            let s = plan.kernel(Product::Geometric, s1, v).out;
            let a1 = plan.kernel(Product::Geometric, v, x).out;
            let a = plan.kernel(Product::Geometric, a1, rev).out;
            items.push(composed_items(names, v, x, (s, a)));
        }
    }
    quote!(#(#items)*)
}

//! The Rust impls of the unit-versor actions ([`crate::unit`]): `UnitAction` for every fused
//! pair, with the constraint-reduced kernel where a type is declared `where unit` and it is
//! cheaper.

use super::Names;
use super::sums::tree_sum as sum;
use crate::constraint::{ConstrainedKernel, ConstraintKind, KernelOp, Request, typed_body};
use crate::unit::{UnitKernel, plan_unit_actions, unit_kernel};
use crate::versor::{Convention, action_kernel};
use crate::{CodegenError, ModuleSpec};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

/// The `UnitAction` impl of one (versor, operand) pair, from its two unit kernels; `proofs`
/// are the reduced kernels of the pair (sandwich, apply) when the versor type is declared
/// `where unit`.
fn unit_items(
    spec: &ModuleSpec,
    names: &Names,
    sandwich: &UnitKernel,
    apply: &UnitKernel,
    proofs: [Option<&ConstrainedKernel>; 2],
) -> TokenStream {
    let (v, x) = (sandwich.kernel.versor, sandwich.kernel.operand);
    let (vt, xt) = (&names.types[v], &names.types[x]);
    let large = |u: &UnitKernel| names.is_large(&[v, x], u.kernel.stage1.iter().chain(&u.kernel.stage2).map(Vec::len));
    let body = |u: &UnitKernel, proof: Option<&ConstrainedKernel>, op: KernelOp, general: TokenStream| match proof
        .filter(|k| reduced_is_cheaper(spec, u, k))
    {
        Some(k) => typed_body(names, Request { op, left: v, right: x }, k, x),
        None if large(u) => quote!(__gam_engine::ops::#general(self, x)),
        None => unrolled_body(names, u),
    };
    let s_body = body(sandwich, proofs[0], KernelOp::Sandwich, quote!(Sandwich::sandwich));
    let a_body = body(apply, proofs[1], KernelOp::Apply, quote!(Apply::apply));
    let s_doc = doc_lines(spec, "`rev(self) x self` for a unit `self`", sandwich, proofs[0]);
    let a_doc = doc_lines(spec, "`self x rev(self)` for a unit `self`", apply, proofs[1]);
    quote! {
        impl<T: __gam_engine::Ring> __gam_engine::ops::UnitAction<#xt<T>> for #vt<T> {
            #(#[doc = #s_doc])*
            #[inline]
            fn sandwich_unit(&self, x: &#xt<T>) -> #xt<T> {
                #s_body
            }
            #(#[doc = #a_doc])*
            #[inline]
            fn apply_unit(&self, x: &#xt<T>) -> #xt<T> {
                #a_body
            }
        }
    }
}

/// Whether the reduced kernel `k` replaces the structural one: strictly fewer multiplications,
/// and every output it computes is a component of the operand type.
fn reduced_is_cheaper(spec: &ModuleSpec, u: &UnitKernel, k: &ConstrainedKernel) -> bool {
    let xm = &spec.types[u.kernel.operand].elements;
    k.stats().mul < u.counts().0 && k.outputs.iter().all(|(m, _)| xm.contains(m))
}

/// The rustdoc of one unit action: what it computes, which kernel, and what is proven about
/// the components outside the operand type.
fn doc_lines(spec: &ModuleSpec, what: &str, u: &UnitKernel, proof: Option<&ConstrainedKernel>) -> Vec<String> {
    let (vn, xn) = (&spec.types[u.kernel.versor].name, &spec.types[u.kernel.operand].name);
    let xm = &spec.types[u.kernel.operand].elements;
    let mut lines = vec![format!(
        " {what}: assumes `self rev(self) = 1`; for any other `self` the result is not the action (use `sandwich`/`apply`)."
    )];
    let (mu, _) = u.counts();
    match proof {
        Some(k) => {
            let (mk, mf) = (k.stats().mul, k.full.stats().mul);
            let kernel = if reduced_is_cheaper(spec, u, k) {
                format!(" The kernel reduced modulo `rev(x) x = 1`: {mk} multiplications (the commutator form: {mu}).")
            } else {
                format!(
                    " The commutator form `x + (L x - x L) R`: {mu} multiplications (reduced modulo `rev(x) x = 1`: {mk}; the unconstrained product: {mf})."
                )
            };
            lines.push(kernel);
            let outside = k.outputs.iter().filter(|(m, _)| !xm.contains(m)).count();
            let vanish = k.vanishing.iter().filter(|m| !xm.contains(m)).count();
            lines.push(match (outside, vanish) {
                (0, 0) => format!(" Every component of the full product is a `{xn}` component."),
                (0, n) => format!(
                    " Proven (ideal membership): on a unit `{vn}` the action on a `{xn}` is a `{xn}`; the {n} component(s) of the full product outside `{xn}` vanish."
                ),
                (n, _) => format!(
                    " Not a `{xn}` in general: {n} component(s) outside `{xn}` do not vanish under `rev(x) x = 1`; this is the projection onto `{xn}`."
                ),
            });
        }
        None => {
            lines.push(format!(" The commutator form `x + (L x - x L) R`: {mu} multiplications."));
            let k = &u.kernel;
            let outside = action_kernel(spec, k.convention, k.versor, k.operand, false).map(|g| g.outside.len());
            lines.push(match outside {
                Ok(0) => format!(" Every component of the full product is a `{xn}` component: this is the whole action."),
                n => format!(
                    " The full product has {} component(s) outside `{xn}`, dropped here: they vanish for versors (products of invertible vectors), which is assumed; declaring `{vn}` `where unit` proves or refutes it for unit ones.",
                    n.map_or_else(|_| "some".to_string(), |n| n.to_string())
                ),
            });
        }
    }
    lines
}

/// The `UnitAction` impl of the pair (`v` a versor type declared `where unit`, `x` an operand
/// type) given the pair's two reduced kernels (sandwich, apply): each convention takes the
/// cheaper of the commutator form and the reduced kernel, and the rustdoc states what the
/// reduction proved. Emitted by [`crate::constraint::methods`], which reads the reduced kernels.
///
/// # Errors
/// A coefficient of the commutator form does not fit `i64/i64`.
pub(crate) fn pair_items(
    spec: &ModuleSpec,
    names: &Names,
    v: usize,
    x: usize,
    proofs: [&ConstrainedKernel; 2],
) -> Result<TokenStream, CodegenError> {
    let sandwich = unit_kernel(spec, Convention::Sandwich, v, x)?;
    let apply = unit_kernel(spec, Convention::Apply, v, x)?;
    Ok(unit_items(spec, names, &sandwich, &apply, proofs.map(Some)))
}

/// Straight-line code: the scaled commutator, then `x_j + scale · correction_j`.
fn unrolled_body(names: &Names, u: &UnitKernel) -> TokenStream {
    let k = &u.kernel;
    let (xt, vf, xf) = (&names.types[k.operand], &names.fields[k.versor], &names.fields[k.operand]);
    let binds = super::versor::stage1_binds(names, k);
    let outs = k.stage2.iter().zip(xf).map(|(terms, f)| {
        if terms.is_empty() {
            return quote!(::core::clone::Clone::clone(&x.#f));
        }
        let y = sum(terms
            .iter()
            .map(|&(i, a, c)| {
                let (ti, fa) = (format_ident!("t{}", i), &vf[a]);
                (c, quote!((#ti.mul_ref(&self.#fa))), true)
            })
            .collect());
        match u.scale {
            (1, 1) => quote!({ x.#f.add_ref(&(#y)) }),
            (2, 1) => quote!({ let y = #y; x.#f.add_ref(&y) + &y }),
            (n, d) => quote!({ x.#f.add_ref(&(T::from_ratio(#n, #d) * &(#y))) }),
        }
    });
    quote! {
        #(#binds)*
        #xt { #(#xf: #outs),* }
    }
}

/// Every `UnitAction` impl of the module (one per fused pair) except those of a versor type
/// declared `where unit`, which [`crate::constraint::methods`] emits with the reduced kernels.
pub(crate) fn module_items(plan: &crate::plan::Plan, names: &Names) -> TokenStream {
    let kernels = match plan_unit_actions(&plan.spec, &plan.actions) {
        Ok(k) => k,
        Err(e) => {
            let msg = e.to_string();
            return quote!(compile_error!(#msg););
        }
    };
    // a `where unit` type's impls come with its reduced kernels ([`pair_items`])
    let declared = |v: usize| plan.spec.types[v].constraint == Some(ConstraintKind::Unit);
    let items = kernels
        .chunks(2)
        .filter(|pair| !declared(pair[0].kernel.versor))
        .map(|pair| unit_items(&plan.spec, names, &pair[0], &pair[1], [None, None]));
    quote!(#(#items)*)
}

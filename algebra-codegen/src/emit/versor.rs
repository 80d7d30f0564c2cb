//! The Rust impls of the fused versor actions ([`crate::versor`]): `Sandwich` and `Apply`,
//! straight-line or table-driven, and the composed full products for pairs without a fused
//! kernel.

use super::Names;
use super::sums::{SumTerm, sum as chain, tree_sum};
use crate::ratio::Ratio;
use crate::versor::{ActionKernel, Convention};
use algebra_core::tables::{Product, Unary};
use proc_macro2::TokenStream;
use quote::{format_ident, quote};

fn names_of(convention: Convention) -> (TokenStream, TokenStream) {
    match convention {
        Convention::Sandwich => (quote!(Sandwich), quote!(sandwich)),
        Convention::Apply => (quote!(Apply), quote!(apply)),
    }
}

/// The impl of one fused kernel.
pub(crate) fn action_items(names: &Names, k: &ActionKernel) -> TokenStream {
    let (vt, xt) = (&names.types[k.versor], &names.types[k.operand]);
    let (trait_name, method) = names_of(k.convention);
    // straight-line kernels are always inlined: LLVM declined the `#[inline]` hint for the
    // conformal point action, and the call cost 7 % (1.38 → 1.31 × the motor product)
    let large = names.is_large(&[k.versor, k.operand], k.stage1.iter().chain(&k.stage2).map(Vec::len));
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
        impl<T: __gam_engine::Ring> __gam_engine::ops::#trait_name<#xt<T>> for #vt<T> {
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
    debug_assert!(k.norm.is_none() && k.flip == 0, "table-driven kernels keep the general form, unflipped");
    let flat = |stage: &[Vec<(usize, usize, Ratio)>]| -> Vec<(usize, usize, usize, Ratio)> {
        stage.iter().enumerate().flat_map(|(o, ts)| ts.iter().map(move |&(i, j, c)| (i, j, o, c))).collect()
    };
    let (xf, xt) = (&names.fields[k.operand], &names.types[k.operand]);
    let stage1 = super::size::table_loop(&flat(&k.stage1), &quote!(s), &quote!(x.each_ref()), k.stage1.len());
    let stage2 = super::size::table_loop(&flat(&k.stage2), &quote!(t.each_ref()), &quote!(s), xf.len());
    quote! {
        let s = self.each_ref();
        let t = #stage1;
        #xt::from_array(#stage2)
    }
}

/// A term `c · self.field · y` as `(±1, (|c| · self.field) · y)` when `|c| != 1`: the constant
/// multiplies the versor's coefficient, which does not depend on the operand, so it leaves the
/// operand's dependency chain (the conformal point action: 1.31 → 1.28 × the motor product,
/// docs/performance.md). The same value exactly over any ring, and in floating point for a
/// power of two such as the 2 of the conformal action. A field the kernel uses negated
/// ([`ActionKernel::flip`]) is `(-self.field)`.
fn scaled(c: Ratio, field: &proc_macro2::Ident, flipped: bool) -> (Ratio, TokenStream) {
    let (n, d) = c;
    let f = if flipped { quote!((__gam_engine::Ring::neg_ref(&self.#field))) } else { quote!(self.#field) };
    if crate::ratio::is_unit(c) {
        return (c, f);
    }
    let k = n.abs();
    ((n.signum(), 1), quote!((T::from_ratio(#k, #d) * &#f)))
}

/// The first stage as bindings `let t0 = ...;` (sums of `self` fields times `x` fields).
pub(crate) fn stage1_binds(names: &Names, k: &ActionKernel) -> Vec<TokenStream> {
    let (vf, xf) = (&names.fields[k.versor], &names.fields[k.operand]);
    let mut binds = Vec::new();
    // `let xc_N_D_B = N/D · x.B;` ([`ActionKernel::operand_constants`])
    let xc = |(n, d): Ratio, b: usize| format_ident!("xc_{}_{}_{}", n.unsigned_abs(), d.unsigned_abs(), b);
    if k.operand_constants {
        for ((n, d), b) in k.operand_constant_fields() {
            let (name, fb) = (xc((n, d), b), &xf[b]);
            binds.push(quote!(let #name = T::from_ratio(#n, #d) * &x.#fb;));
        }
    }
    for (i, terms) in k.stage1.iter().enumerate() {
        let summands: Vec<SumTerm> = terms
            .iter()
            .map(|&(a, b, c)| {
                if k.operand_constants && !crate::ratio::is_unit(c) {
                    let (_, fa) = scaled((1, 1), &vf[a], k.flip >> a & 1 == 1);
                    let name = xc(c, b);
                    return ((c.0.signum(), 1), quote!((#fa.mul_ref(&#name))), true);
                }
                let (c, fa) = scaled(c, &vf[a], k.flip >> a & 1 == 1);
                let fb = &xf[b];
                (c, quote!((#fa.mul_ref(&x.#fb))), true)
            })
            .collect();
        let ti = format_ident!("t{}", i);
        let e = if k.chains[0] { chain(summands) } else { tree_sum(summands) };
        binds.push(quote!(let #ti = #e;));
    }
    binds
}

/// The two stages as straight-line code; in the scalar-norm form ([`crate::versor::NormForm`])
/// the norm `n` is bound after the intermediates and each output is `n · x_j` plus its scaled
/// correction.
pub(super) fn unrolled_body(names: &Names, k: &ActionKernel) -> TokenStream {
    let (xt, vf, xf) = (&names.types[k.operand], &names.fields[k.versor], &names.fields[k.operand]);
    let mut binds = stage1_binds(names, k);
    let outs = k.stage2.iter().zip(xf).map(|(terms, f)| {
        let terms: Vec<SumTerm> = terms
            .iter()
            .map(|&(i, a, c)| {
                let (c, fa) = scaled(c, &vf[a], k.flip >> a & 1 == 1);
                let ti = format_ident!("t{}", i);
                (c, quote!((#ti.mul_ref(&#fa))), true)
            })
            .collect();
        let Some(norm) = &k.norm else {
            return if k.chains[1] { chain(terms) } else { tree_sum(terms) };
        };
        if terms.is_empty() {
            return quote!(n.mul_ref(&x.#f));
        }
        let y = if k.chains[1] { chain(terms) } else { tree_sum(terms) };
        match norm.scale {
            (1, 1) => quote!(n.mul_ref(&x.#f) + &(#y)),
            (2, 1) => quote!({ let y = #y; n.mul_ref(&x.#f) + &(y.add_ref(&y)) }),
            (p, q) => quote!(n.mul_ref(&x.#f) + &(T::from_ratio(#p, #q) * &(#y))),
        }
    });
    if let Some(norm) = &k.norm {
        let terms = norm
            .terms
            .iter()
            .map(|&(a, b, c)| {
                let (fa, fb) = (&vf[a], &vf[b]);
                (c, quote!((self.#fa.mul_ref(&self.#fb))), true)
            })
            .collect();
        let n = tree_sum(terms);
        binds.push(quote!(let n = #n;));
    }
    quote! {
        #(#binds)*
        #xt { #(#xf: #outs),* }
    }
}

/// The impls for a (type, operand) pair without a fused kernel: the composed full products.
pub(crate) fn composed_items(names: &Names, v: usize, x: usize, out: (usize, usize)) -> TokenStream {
    let (vt, xt) = (&names.types[v], &names.types[x]);
    let (so, ao) = (&names.types[out.0], &names.types[out.1]);
    let gp = quote!(__gam_engine::ops::GeometricProduct::gp);
    quote! {
        impl<T: __gam_engine::Ring> __gam_engine::ops::Sandwich<#xt<T>> for #vt<T> {
            type Output = #so<T>;
            /// `rev(self) x self` as two full products (no fused kernel for this pair).
            fn sandwich(&self, x: &#xt<T>) -> #so<T> { #gp(&#gp(&self.reverse(), x), self) }
        }
        impl<T: __gam_engine::Ring> __gam_engine::ops::Apply<#xt<T>> for #vt<T> {
            type Output = #ao<T>;
            /// `self x rev(self)` as two full products (no fused kernel for this pair).
            fn apply(&self, x: &#xt<T>) -> #ao<T> { #gp(&#gp(self, x), &self.reverse()) }
        }
    }
}

/// Every `Sandwich` and `Apply` impl of the module, plus the inherent methods' names.
pub(crate) fn module_items(plan: &crate::plan::Plan, names: &Names) -> TokenStream {
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

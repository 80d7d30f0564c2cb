//! The matrix form of a fused versor action, for transforming many operands by one versor:
//! the action `x ↦ <rev(S) x S>_X` (or `<S x rev(S)>_X`) is linear in `x`, so its matrix
//! `M(S)` (entries quadratic in `S`'s coefficients) is computed once and applied per operand
//! with only the structurally non-zero entries: for a PGA motor on points 13 multiplications
//! per point instead of the fused kernel's 48.
//!
//! Built by composing the two stages of the fused kernel ([`super::versor::ActionKernel`],
//! after the orientation signs are folded in), so `transform(matrix(S), x)` computes the same
//! polynomial as the fused action, exactly. Emitted for pairs whose matrix has at most
//! [`MAX_TERMS`] quadratic terms (motors and rotors on points, vectors, lines, planes of
//! algebras up to 4 generators and conformal points); larger pairs keep only the fused kernel.

use super::emit::{Names, SumTerm, sum};
use super::plan::{Plan, Ratio};
use super::versor::{ActionKernel, Convention};
use algebra_core::rational::{Q, ratio};
use num_traits::Zero;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeMap;

/// Pairs whose matrix has more quadratic terms than this get no matrix form.
pub const MAX_TERMS: usize = 512;

/// One action matrix: `entries[j][b]` is `M_jb = Σ c · s[a] · s[a2]` as `(a, a2, c)`, `a <= a2`.
#[derive(Debug, Clone)]
pub struct MatrixKernel {
    /// The convention of the action.
    pub convention: Convention,
    /// Versor type index.
    pub versor: usize,
    /// Operand type index.
    pub operand: usize,
    /// The entries, row `j` (output field), column `b` (input field).
    pub entries: Vec<Vec<Vec<(usize, usize, Ratio)>>>,
}

/// The matrix of a fused action, or `None` when it is too large or a constant overflows.
pub(crate) fn compose(k: &ActionKernel) -> Option<MatrixKernel> {
    let n = k.stage2.len();
    let q = |(num, den): Ratio| ratio(num, den);
    let mut entries = Vec::with_capacity(n);
    let mut total = 0;
    for row in &k.stage2 {
        let mut cols: Vec<BTreeMap<(usize, usize), Q>> = vec![BTreeMap::new(); n];
        for &(t, a2, c2) in row {
            for &(a, b, c1) in &k.stage1[t] {
                let key = (a.min(a2), a.max(a2));
                *cols[b].entry(key).or_insert_with(Q::zero) += q(c1) * q(c2);
            }
        }
        let mut out_row = Vec::with_capacity(n);
        for col in cols {
            let mut terms = Vec::new();
            for ((a, a2), c) in col.into_iter().filter(|(_, c)| !c.is_zero()) {
                terms.push((a, a2, super::plan::to_ratio(&c).ok()?));
            }
            total += terms.len();
            out_row.push(terms);
        }
        entries.push(out_row);
    }
    (total <= MAX_TERMS).then_some(MatrixKernel {
        convention: k.convention,
        versor: k.versor,
        operand: k.operand,
        entries,
    })
}

/// The matrices of every fused action small enough.
pub(crate) fn plan_matrices(plan: &Plan) -> Vec<MatrixKernel> {
    plan.actions.iter().filter_map(compose).collect()
}

/// The `ActionMatrix` impl of one (versor, operand) pair (both conventions).
pub(super) fn matrix_items(names: &Names, sandwich: &MatrixKernel, apply: &MatrixKernel) -> TokenStream {
    let (vt, xt) = (&names.types[sandwich.versor], &names.types[sandwich.operand]);
    let (vf, xf) = (&names.fields[sandwich.versor], &names.fields[sandwich.operand]);
    let n = xf.len();
    let build = |m: &MatrixKernel| -> TokenStream {
        let mut binds = BTreeMap::new();
        let rows = m.entries.iter().map(|row| {
            let cols = row.iter().map(|terms| {
                let summands: Vec<SumTerm> = terms
                    .iter()
                    .map(|&(a, a2, c)| {
                        let p = format_ident!("q{}_{}", a, a2);
                        let (fa, fa2) = (&vf[a], &vf[a2]);
                        binds.entry((a, a2)).or_insert_with(|| quote!(let #p = self.#fa.mul_ref(&self.#fa2);));
                        (c, quote!(#p), false)
                    })
                    .collect();
                sum(summands)
            });
            quote!([#(#cols),*])
        });
        let rows: Vec<TokenStream> = rows.collect();
        let binds = binds.values();
        quote! {
            #(#binds)*
            [#(#rows),*]
        }
    };
    let (s_body, a_body) = (build(sandwich), build(apply));
    // the product of a row with x, skipping entries that are zero in both conventions
    let outs = (0..n).map(|j| {
        let summands: Vec<SumTerm> = (0..n)
            .filter(|&b| !sandwich.entries[j][b].is_empty() || !apply.entries[j][b].is_empty())
            .map(|b| {
                let fb = &xf[b];
                ((1, 1), quote!((m[#j][#b].mul_ref(&x.#fb))), true)
            })
            .collect();
        sum(summands)
    });
    let doc = format!(
        "The action on [`{xt}`] as a matrix (entries quadratic in `self`), for transforming many values by one versor."
    );
    quote! {
        #[doc = #doc]
        impl<T: ::algebra_core::Ring> ::algebra_core::ops::ActionMatrix<#xt<T>> for #vt<T> {
            type Matrix = [[T; #n]; #n];
            fn sandwich_matrix(&self) -> [[T; #n]; #n] { #s_body }
            fn apply_matrix(&self) -> [[T; #n]; #n] { #a_body }
            #[inline]
            fn transform(m: &[[T; #n]; #n], x: &#xt<T>) -> #xt<T> {
                #xt { #(#xf: #outs),* }
            }
        }
    }
}

/// Every `ActionMatrix` impl of the module.
pub(super) fn module_items(plan: &Plan, names: &Names) -> TokenStream {
    let items = plan.matrices.iter().filter(|m| m.convention == Convention::Sandwich).filter_map(|s| {
        let a = plan
            .matrices
            .iter()
            .find(|m| m.convention == Convention::Apply && (m.versor, m.operand) == (s.versor, s.operand))?;
        Some(matrix_items(names, s, a))
    });
    quote!(#(#items)*)
}

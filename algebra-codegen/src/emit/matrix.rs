//! The Rust impls of the action matrices ([`crate::matrix`]): `ActionMatrix`.

use super::Names;
use super::sums::{SumTerm, sum};
use crate::matrix::MatrixKernel;
use crate::plan::Plan;
use crate::versor::Convention;
use proc_macro2::TokenStream;
use quote::{format_ident, quote};
use std::collections::BTreeMap;

/// The `ActionMatrix` impl of one (versor, operand) pair (both conventions).
pub(crate) fn matrix_items(names: &Names, sandwich: &MatrixKernel, apply: &MatrixKernel) -> TokenStream {
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
    // straight-line code for the matrices of motors and rotors on declared types (the batch
    // transforms); a loop over a table for the other versors (reflections, lines, odd types),
    // whose matrices were 14 % of a 3D PGA module's tokens, and over automatic types
    let kinematic = crate::versor::is_kinematic(&names.masks[sandwich.versor]);
    let table = |m: &MatrixKernel| {
        let counts = m.entries.iter().flatten().map(Vec::len);
        (!kinematic || names.is_large(&[sandwich.versor, sandwich.operand], counts)).then(|| table_body(names, m))
    };
    let (s_body, a_body) =
        (table(sandwich).unwrap_or_else(|| build(sandwich)), table(apply).unwrap_or_else(|| build(apply)));
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
        impl<T: __gam_engine::Ring> __gam_engine::ops::ActionMatrix<#xt<T>> for #vt<T> {
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

/// The matrix built by a loop over its quadratic terms ([`super::size::quadratic`]): the same
/// sums as the straight-line form.
fn table_body(names: &Names, m: &MatrixKernel) -> TokenStream {
    let entries: Vec<(usize, usize, usize, usize, crate::ratio::Ratio)> = m
        .entries
        .iter()
        .enumerate()
        .flat_map(|(j, row)| {
            row.iter().enumerate().flat_map(move |(b, terms)| terms.iter().map(move |&(a, a2, c)| (j, b, a, a2, c)))
        })
        .collect();
    super::size::quadratic(&entries, names.fields[m.operand].len())
}

/// Every `ActionMatrix` impl of the module.
pub(crate) fn module_items(plan: &Plan, names: &Names) -> TokenStream {
    let items = plan.matrices.iter().filter(|m| m.convention == Convention::Sandwich).filter_map(|s| {
        let a = plan
            .matrices
            .iter()
            .find(|m| m.convention == Convention::Apply && (m.versor, m.operand) == (s.versor, s.operand))?;
        Some(matrix_items(names, s, a))
    });
    quote!(#(#items)*)
}

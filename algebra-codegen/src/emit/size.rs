//! The table-driven form of large kernels (the size policy of [`crate::size`]): loops over
//! constant term tables instead of straight-line code.

use crate::ratio::Ratio;
use proc_macro2::TokenStream;
use quote::quote;

/// `out[k] = Σ c · a[i] · b[j]` over the `(i, j, k, c)` in `terms`, as a loop over constant
/// tables. `a` and `b` are arrays of `&T` already in scope (named by the given tokens); the
/// result is bound to `out_name` as `[T; n_out]`.
///
/// The terms are grouped by output (`STARTS[k]..STARTS[k + 1]`), each output summed in four
/// interleaved accumulators held in locals (four independent addition chains instead of one
/// chain through memory), and the constants other than ±1 converted with `T::from_ratio` once
/// per call (`COEFS`), not once per term. Over exact scalars the result is the same sum.
pub(crate) fn table_loop(
    terms: &[(usize, usize, usize, Ratio)],
    a: &TokenStream,
    b: &TokenStream,
    out_name: &TokenStream,
    n_out: usize,
) -> TokenStream {
    let mut sorted = terms.to_vec();
    sorted.sort_by_key(|t| t.2);
    let mut coefs: Vec<Ratio> = Vec::new();
    let rows: Vec<TokenStream> = sorted
        .iter()
        .map(|&(i, j, _, c)| {
            // 0: +1, 1: -1, 2 + n: COEFS[n]
            let code = match c {
                (1, 1) => 0,
                (-1, 1) => 1,
                c => {
                    2 + coefs.iter().position(|x| *x == c).unwrap_or_else(|| {
                        coefs.push(c);
                        coefs.len() - 1
                    })
                }
            };
            let (i, j, code) = (i as u16, j as u16, code as u16);
            quote!((#i, #j, #code))
        })
        .collect();
    let starts: Vec<u16> = (0..=n_out).map(|k| sorted.iter().take_while(|t| t.2 < k).count() as u16).collect();
    let (n, nc, n1) = (sorted.len(), coefs.len(), n_out + 1);
    let coef_rows = coefs.iter().map(|&(num, den)| quote!((#num, #den)));
    quote! {
        const TERMS: [(u16, u16, u16); #n] = [#(#rows),*];
        const STARTS: [u16; #n1] = [#(#starts),*];
        const COEFS: [(i64, i64); #nc] = [#(#coef_rows),*];
        let coefs: [T; #nc] = ::core::array::from_fn(|c| T::from_ratio(COEFS[c].0, COEFS[c].1));
        let term = |acc: &mut T, &(i, j, c): &(u16, u16, u16)| {
            let p = #a[i as usize].mul_ref(#b[j as usize]);
            match c {
                0 => acc.add_assign_ref(&p),
                1 => acc.sub_assign_ref(&p),
                _ => acc.add_assign_ref(&coefs[c as usize - 2].mul_ref(&p)),
            }
        };
        let #out_name: [T; #n_out] = ::core::array::from_fn(|k| {
            let terms = &TERMS[STARTS[k] as usize..STARTS[k + 1] as usize];
            let (mut a0, mut a1, mut a2, mut a3) = (T::zero(), T::zero(), T::zero(), T::zero());
            let mut quads = terms.chunks_exact(4);
            for q in &mut quads {
                term(&mut a0, &q[0]);
                term(&mut a1, &q[1]);
                term(&mut a2, &q[2]);
                term(&mut a3, &q[3]);
            }
            for r in quads.remainder() {
                term(&mut a0, r);
            }
            a0.add_ref(&a1).add_ref(&a2.add_ref(&a3))
        });
    }
}

/// `[&recv.f0, &recv.f1, ...]`.
pub(crate) fn refs(recv: TokenStream, fields: &[proc_macro2::Ident]) -> TokenStream {
    quote!([#(&#recv.#fields),*])
}

/// The table-driven body of a binary kernel.
pub(crate) fn binary_body(names: &super::Names, k: &crate::plan::BinaryKernel) -> TokenStream {
    let terms: Vec<(usize, usize, usize, Ratio)> =
        k.outputs.iter().enumerate().flat_map(|(o, ts)| ts.iter().map(move |t| (t.lhs, t.rhs, o, t.coef))).collect();
    let a = refs(quote!(self), &names.fields[k.lhs]);
    let b = refs(quote!(rhs), &names.fields[k.rhs]);
    let ot = &names.types[k.out];
    let body = table_loop(&terms, &quote!(a), &quote!(b), &quote!(out), names.fields[k.out].len());
    quote! {
        let a = #a;
        let b = #b;
        #body
        #ot::from_array(out)
    }
}

/// The matrix of `y ↦ self * y` inside a closed type, filled by a loop: `l[row][col] += c ·
/// self[lhs]` for every `(lhs, col, row, c)`.
pub(crate) fn matrix_fill(entries: &[(usize, usize, usize, Ratio)], fields: &[proc_macro2::Ident]) -> TokenStream {
    let n = entries.len();
    let a = refs(quote!(self), fields);
    let rows = entries.iter().map(|&(lhs, col, row, (num, den))| {
        let (lhs, col, row) = (lhs as u16, col as u16, row as u16);
        quote!((#lhs, #col, #row, #num, #den))
    });
    quote! {
        const ENTRIES: [(u16, u16, u16, i64, i64); #n] = [#(#rows),*];
        let a = #a;
        for &(lhs, col, row, num, den) in ENTRIES.iter() {
            let slot = &mut l[row as usize][col as usize];
            match (num, den) {
                (1, 1) => slot.add_assign_ref(a[lhs as usize]),
                (-1, 1) => slot.sub_assign_ref(a[lhs as usize]),
                _ => slot.add_assign_ref(&(T::from_ratio(num, den) * a[lhs as usize].clone())),
            }
        }
    }
}

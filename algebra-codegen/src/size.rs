//! The size policy: a kernel with more than [`TABLE_THRESHOLD`] terms is emitted as a compact
//! loop over a constant term table instead of straight-line code.
//!
//! Straight-line code is fastest for the small kernels users call in loops (motor products,
//! versor actions), but a dense 5-generator product (`Multivector * Multivector`: 1024 terms)
//! unrolled for a big-number scalar is megabytes of inlined arithmetic and drop glue that takes
//! minutes to compile. The table form is a few lines per kernel whatever the scalar, and
//! computes the same sum term by term (exact over rationals, with the same constants).

use super::plan::Ratio;
use proc_macro2::TokenStream;
use quote::quote;

/// Kernels with more terms than this are table-driven.
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, emit, plan::Plan};
/// let code = |name: &str, types: &str| {
///     let alg = Algebra::builtin(name).unwrap();
///     let types = ModuleSpec::parse_types(types, &alg).unwrap();
///     let spec = ModuleSpec::new(name, alg.metric().clone(), Basis::Blade, types).unwrap();
///     emit::module(&Plan::new(spec).unwrap()).to_string()
/// };
/// // the text of the `GeometricProduct<X> for X` impl
/// let gp = |code: &str, x: &str| {
///     let head = format!("GeometricProduct < {x} < T >> for {x} < T >");
///     let body = &code[code.find(&head).unwrap()..];
///     body[..body[1..].find("impl").unwrap()].to_string()
/// };
/// // the 64-term motor product stays straight-line code ...
/// assert!(!gp(&code("g123inf", "Motor=even"), "Motor").contains("TERMS"));
/// // ... the 1024-term full product of a 5-generator algebra is a loop over a table
/// assert!(gp(&code("cga", "Multivector=all"), "Multivector").contains("const TERMS"));
/// ```
pub const TABLE_THRESHOLD: usize = 64;

/// `out[k] += c · a[i] · b[j]` for every `(i, j, k, c)` in `terms`, as a loop over a constant
/// table. `a` and `b` are arrays of `&T` already in scope (named by the given tokens); the
/// result is bound to `out_name` as `[T; n_out]`.
pub(super) fn table_loop(
    terms: &[(usize, usize, usize, Ratio)],
    a: &TokenStream,
    b: &TokenStream,
    out_name: &TokenStream,
    n_out: usize,
) -> TokenStream {
    let n = terms.len();
    let rows = terms.iter().map(|&(i, j, k, (num, den))| {
        let (i, j, k) = (i as u16, j as u16, k as u16);
        quote!((#i, #j, #k, #num, #den))
    });
    quote! {
        const TERMS: [(u16, u16, u16, i64, i64); #n] = [#(#rows),*];
        let mut #out_name: [T; #n_out] = ::core::array::from_fn(|_| T::zero());
        for &(i, j, k, num, den) in TERMS.iter() {
            let p = #a[i as usize].mul_ref(#b[j as usize]);
            let slot = &mut #out_name[k as usize];
            match (num, den) {
                (1, 1) => slot.add_assign_ref(&p),
                (-1, 1) => slot.sub_assign_ref(&p),
                _ => slot.add_assign_ref(&(T::from_ratio(num, den) * p)),
            }
        }
    }
}

/// `[&recv.f0, &recv.f1, ...]`.
pub(super) fn refs(recv: TokenStream, fields: &[proc_macro2::Ident]) -> TokenStream {
    quote!([#(&#recv.#fields),*])
}

/// The table-driven body of a binary kernel.
pub(super) fn binary_body(names: &super::emit::Names, k: &super::plan::BinaryKernel) -> TokenStream {
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

/// Whether a kernel with these per-output term counts is table-driven.
pub(super) fn is_large<I: IntoIterator<Item = usize>>(lens: I) -> bool {
    lens.into_iter().sum::<usize>() > TABLE_THRESHOLD
}

/// The matrix of `y ↦ self * y` inside a closed type, filled by a loop: `l[row][col] += c ·
/// self[lhs]` for every `(lhs, col, row, c)`.
pub(super) fn matrix_fill(entries: &[(usize, usize, usize, Ratio)], fields: &[proc_macro2::Ident]) -> TokenStream {
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

//! The size policy: a kernel with more terms than its module's threshold (default
//! [`TABLE_THRESHOLD`], the DSL's `table_above N;`) is emitted as a compact loop over a constant term
//! table instead of straight-line code.
//!
//! Straight-line code is fastest for the small kernels users call in loops (motor products,
//! versor actions), but a dense 5-generator product (`Multivector * Multivector`: 1024 terms)
//! unrolled for a big-number scalar is megabytes of inlined arithmetic and drop glue that takes
//! minutes to compile. The table form is a few lines per kernel whatever the scalar, and
//! computes the same sum term by term (exact over rationals, with the same constants).

use super::plan::Ratio;
use proc_macro2::TokenStream;
use quote::quote;

/// The default threshold: kernels with more terms than this are table-driven (a module may
/// choose another with the DSL's `table_above N;`, [`crate::ModuleSpec::table_above`] or
/// `gam codegen --table-above N`).
///
/// 128 (was 64) from the measurements of docs/performance.md ("Size policy threshold"): at f64
/// straight-line code runs the 65-256-term kernels of `cga` (R^{4,1}) 4.7-9 × faster than the
/// table loop, and unrolling up to 128 terms costs the probe crate (the full 5-generator CGA)
/// about 10 % more compile time, while 256 costs 40-50 % (about 5 s of CPU: the 5 s target) and
/// doubles the compile time of a crate instantiating the 256-term kernels for `BigRational`.
/// The predefined `cga` module of `gam-algebras` declares `table_above 256;` (its motor product
/// and actions are the kernels users call in loops).
///
/// ```
/// use algebra_core::{Algebra, Basis};
/// use algebra_codegen::{ModuleSpec, emit, plan::Plan, size::TABLE_THRESHOLD};
/// let code = |name: &str, types: &str, table_above: usize| {
///     let alg = Algebra::builtin(name).unwrap();
///     let types = ModuleSpec::parse_types(types, &alg).unwrap();
///     let mut spec = ModuleSpec::new(name, alg.metric().clone(), Basis::Blade, types).unwrap();
///     spec.table_above = table_above;
///     emit::module(&Plan::new(spec).unwrap()).to_string()
/// };
/// // the text of the `GeometricProduct<X> for X` impl
/// let gp = |code: &str, x: &str| {
///     let head = format!("GeometricProduct < {x} < T >> for {x} < T >");
///     let body = &code[code.find(&head).unwrap()..];
///     body[..body[1..].find("impl").unwrap()].to_string()
/// };
/// assert_eq!(TABLE_THRESHOLD, 128);
/// // the 48-term motor product of G_{123inf} stays straight-line code ...
/// assert!(!gp(&code("g123inf", "Motor=even", TABLE_THRESHOLD), "Motor").contains("TERMS"));
/// // ... the 256-term motor product of R^{4,1} is a loop over a table by default, straight-line
/// // code under `table_above 256;`
/// assert!(gp(&code("cga", "Motor=even", TABLE_THRESHOLD), "Motor").contains("const TERMS"));
/// assert!(!gp(&code("cga", "Motor=even", 256), "Motor").contains("TERMS"));
/// assert!(gp(&code("cga", "Motor=even", 255), "Motor").contains("const TERMS"));
/// // ... and the 1024-term full product of a 5-generator algebra is a table at either
/// assert!(gp(&code("cga", "Multivector=all", 256), "Multivector").contains("const TERMS"));
/// ```
pub const TABLE_THRESHOLD: usize = 128;

/// `out[k] = Σ c · a[i] · b[j]` over the `(i, j, k, c)` in `terms`, as a loop over constant
/// tables. `a` and `b` are arrays of `&T` already in scope (named by the given tokens); the
/// result is bound to `out_name` as `[T; n_out]`.
///
/// The terms are grouped by output (`STARTS[k]..STARTS[k + 1]`), each output summed in four
/// interleaved accumulators held in locals (four independent addition chains instead of one
/// chain through memory), and the constants other than ±1 converted with `T::from_ratio` once
/// per call (`COEFS`), not once per term. Over exact scalars the result is the same sum.
pub(super) fn table_loop(
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

/// Whether a kernel with these per-output term counts is table-driven under the threshold
/// `table_above` ([`crate::ModuleSpec::table_above`]).
pub(super) fn is_large<I: IntoIterator<Item = usize>>(table_above: usize, lens: I) -> bool {
    lens.into_iter().sum::<usize>() > table_above
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

//! The table-driven form of large kernels (the size policy of [`crate::size`]): loops over
//! constant term tables instead of straight-line code.

use crate::ratio::Ratio;
use proc_macro2::TokenStream;
use quote::quote;

/// The coefficient codes of a term table: 0 is `+1`, 1 is `-1`, `2 + n` is the `n`-th of the
/// returned constants (each listed once).
fn codes(coefs: impl Iterator<Item = Ratio>) -> (Vec<u16>, Vec<Ratio>) {
    let mut distinct: Vec<Ratio> = Vec::new();
    let codes = coefs
        .map(|c| match c {
            (1, 1) => 0,
            (-1, 1) => 1,
            c => {
                let n = distinct.iter().position(|x| *x == c).unwrap_or_else(|| {
                    distinct.push(c);
                    distinct.len() - 1
                });
                (2 + n) as u16
            }
        })
        .collect();
    (codes, distinct)
}

/// Numbers as one byte-string literal, two little-endian bytes each: the form the engine's
/// `kernels` functions read. One token for a whole table, which rustc reads far faster than an
/// array of tuples (docs/performance.md, "Rebuilding a crate that declares an algebra").
fn packed(values: impl IntoIterator<Item = usize>) -> proc_macro2::Literal {
    let bytes: Vec<u8> = values
        .into_iter()
        .flat_map(|v| u16::try_from(v).expect("a kernel table index fits in 16 bits").to_le_bytes())
        .collect();
    proc_macro2::Literal::byte_string(&bytes)
}

/// The constants of a table as `&[(num, den), ...]`.
fn constants(coefs: &[Ratio]) -> TokenStream {
    let rows = coefs.iter().map(|&(num, den)| quote!((#num, #den)));
    quote!(&[#(#rows),*])
}

/// `[T; n_out]` with `out[k] = Σ c · a[i] · b[j]` over the `(i, j, k, c)` in `terms`: a call of
/// the engine's `kernels::bilinear` on a packed term table (grouped by output; four interleaved
/// accumulators; the constants other than ±1 converted once per call). `a` and `b` are
/// expressions of type `[&T; _]`. Over exact scalars the result is the same sum.
pub(crate) fn table_loop(
    terms: &[(usize, usize, usize, Ratio)],
    a: &TokenStream,
    b: &TokenStream,
    n_out: usize,
) -> TokenStream {
    let mut sorted = terms.to_vec();
    sorted.sort_by_key(|t| t.2);
    let (codes, coefs) = codes(sorted.iter().map(|t| t.3));
    let table = packed(sorted.iter().zip(&codes).flat_map(|(&(i, j, _, _), &c)| [i, j, usize::from(c)]));
    let (n, n1) = (sorted.len(), n_out + 1);
    let starts = (0..=n_out).map(|k| sorted.iter().take_while(|t| t.2 < k).count() as u16);
    let coefs = constants(&coefs);
    quote! {{
        const TERMS: [[u16; 3]; #n] = __gam_engine::kernels::unpack(#table);
        const STARTS: [u16; #n1] = [#(#starts),*];
        __gam_engine::kernels::bilinear::<T, #n_out, _, _, _, _, _>(#a, #b, &TERMS, &STARTS, #coefs)
    }}
}

/// The table-driven body of a binary kernel.
pub(crate) fn binary_body(names: &super::Names, k: &crate::plan::BinaryKernel) -> TokenStream {
    let terms: Vec<(usize, usize, usize, Ratio)> =
        k.outputs.iter().enumerate().flat_map(|(o, ts)| ts.iter().map(move |t| (t.lhs, t.rhs, o, t.coef))).collect();
    let ot = &names.types[k.out];
    let out = table_loop(&terms, &quote!(self.each_ref()), &quote!(rhs.each_ref()), names.fields[k.out].len());
    quote!(#ot::from_array(#out))
}

/// The table of an action matrix ([`crate::matrix::MatrixKernel`]): `M[j][b] += c · v[a] ·
/// v[a2]` for every `(j, b, a, a2, c)`, as a call of the engine's `kernels::quadratic` on
/// `self`'s coefficients.
pub(crate) fn quadratic(entries: &[(usize, usize, usize, usize, Ratio)], n: usize) -> TokenStream {
    let (codes, coefs) = codes(entries.iter().map(|e| e.4));
    let table = packed(entries.iter().zip(&codes).flat_map(|(&(j, b, a, a2, _), &c)| [j, b, a, a2, usize::from(c)]));
    let len = entries.len();
    let coefs = constants(&coefs);
    quote! {{
        const ENTRIES: [[u16; 5]; #len] = __gam_engine::kernels::unpack(#table);
        __gam_engine::kernels::quadratic::<T, #n, _, _>(&self.each_ref(), &ENTRIES, #coefs)
    }}
}

/// The matrix of `y ↦ self * y` inside a closed type, filled by a loop: `l[row][col] += c ·
/// self[lhs]` for every `(lhs, col, row, c)`.
pub(crate) fn matrix_fill(entries: &[(usize, usize, usize, Ratio)]) -> TokenStream {
    let n = entries.len();
    let rows = entries.iter().map(|&(lhs, col, row, (num, den))| {
        let (lhs, col, row) = (lhs as u16, col as u16, row as u16);
        quote!((#lhs, #col, #row, #num, #den))
    });
    quote! {
        const ENTRIES: [(u16, u16, u16, i64, i64); #n] = [#(#rows),*];
        let a = self.each_ref();
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

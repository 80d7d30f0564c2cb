//! The loops behind the table-driven kernels of generated modules (the size policy of
//! `algebra_codegen::size`): a kernel above its module's threshold, or over a type the
//! generator added on its own (the full multivector, a parity type), is a constant term table
//! and a call to one of these functions, instead of straight-line code. Written once here, so a
//! generated module holds only its tables: rustc reads a few tokens per term instead of a
//! binding and a sum, and the loop is compiled once per scalar type.
//!
//! Both compute the same sums as the straight-line kernels, term by term (exactly over exact
//! scalars, with the same constants).

use crate::scalar::Ring;

/// The `i`-th number of a packed table (two little-endian bytes each).
#[inline(always)]
fn at(table: &[u8], i: usize) -> usize {
    usize::from(u16::from_le_bytes([table[2 * i], table[2 * i + 1]]))
}

/// `term` added to `acc` with the coefficient of `code`: 0 is `+1`, 1 is `-1`, `2 + n` is
/// `coefs[n]`.
#[inline(always)]
fn accumulate<T: Ring>(acc: &mut T, term: &T, code: usize, coefs: &[T]) {
    match code {
        0 => acc.add_assign_ref(term),
        1 => acc.sub_assign_ref(term),
        c => acc.add_assign_ref(&coefs[c - 2].mul_ref(term)),
    }
}

/// `out[k] = Σ c · a[i] · b[j]` over the terms `(i, j, code)` numbered `starts[k]` to
/// `starts[k + 1]`, where `code` 0 is `+1`, 1 is `-1` and `2 + n` is `coefs[n]` (a ratio
/// `num / den`). `terms` (three numbers per term) and `starts` (`N + 1` numbers) are packed:
/// two little-endian bytes per number, as one byte-string literal in a generated module.
///
/// Each output is summed in four interleaved accumulators (four independent addition chains),
/// and the constants other than `±1` are converted with `T::from_ratio` once per call.
///
/// ```
/// use algebra_core::kernels::bilinear;
/// // (a0 + a1 e12) (b0 + b1 e12) in G_2: scalar a0 b0 - a1 b1, e12 part a0 b1 + a1 b0;
/// // terms (0, 0, +1), (1, 1, -1) | (0, 1, +1), (1, 0, +1); starts 0, 2, 4
/// let terms = b"\0\0\0\0\0\0\x01\0\x01\0\x01\0\0\0\x01\0\0\0\x01\0\0\0\0\0";
/// let (a, b) = ([&2.0, &3.0], [&5.0, &7.0]);
/// let out: [f64; 2] = bilinear(&a, &b, terms, b"\0\0\x02\0\x04\0", &[]);
/// assert_eq!(out, [2.0 * 5.0 - 3.0 * 7.0, 2.0 * 7.0 + 3.0 * 5.0]);
/// // a constant other than ±1: out = (1/2) a0 b0
/// let half: [f64; 1] = bilinear(&a, &b, b"\0\0\0\0\x02\0", b"\0\0\x01\0", &[(1, 2)]);
/// assert_eq!(half, [5.0]);
/// ```
#[inline]
pub fn bilinear<T: Ring, const N: usize, const NC: usize>(
    a: &[&T],
    b: &[&T],
    terms: &[u8],
    starts: &[u8],
    coefs: &[(i64, i64); NC],
) -> [T; N] {
    debug_assert_eq!(starts.len(), 2 * (N + 1));
    let coefs: [T; NC] = core::array::from_fn(|c| T::from_ratio(coefs[c].0, coefs[c].1));
    let term = |acc: &mut T, t: usize| {
        let p = a[at(terms, 3 * t)].mul_ref(b[at(terms, 3 * t + 1)]);
        accumulate(acc, &p, at(terms, 3 * t + 2), &coefs);
    };
    core::array::from_fn(|k| {
        let (start, end) = (at(starts, k), at(starts, k + 1));
        let (mut a0, mut a1, mut a2, mut a3) = (T::zero(), T::zero(), T::zero(), T::zero());
        let mut t = start;
        while t + 4 <= end {
            term(&mut a0, t);
            term(&mut a1, t + 1);
            term(&mut a2, t + 2);
            term(&mut a3, t + 3);
            t += 4;
        }
        while t < end {
            term(&mut a0, t);
            t += 1;
        }
        a0.add_ref(&a1).add_ref(&a2.add_ref(&a3))
    })
}

/// The `N x N` matrix `M[j][b] = Σ c · v[a] · v[a2]` over the entries `(j, b, a, a2, code)`
/// (five packed numbers each, `code` as in [`bilinear`]): the matrix of a versor action, whose
/// entries are quadratic in the versor's coefficients `v`, as the generated `ActionMatrix`
/// impls of large or automatic types build it.
///
/// ```
/// use algebra_core::kernels::quadratic;
/// // the matrix of `rev(R) x R` for the rotor R = c + s e12 on vectors of G_2:
/// // [[c² - s², 2cs], [-2cs, c² - s²]]; codes 0: +1, 1: -1, 2: 2, 3: -2
/// let mut table = Vec::new();
/// for e in [[0, 0, 0, 0, 0], [0, 0, 1, 1, 1], [0, 1, 0, 1, 2], [1, 0, 0, 1, 3], [1, 1, 0, 0, 0], [1, 1, 1, 1, 1]] {
///     table.extend(e.iter().flat_map(|&x: &u16| x.to_le_bytes()));
/// }
/// let (c, s) = (0.6, 0.8);
/// let m: [[f64; 2]; 2] = quadratic(&[&c, &s], &table, &[(2, 1), (-2, 1)]);
/// assert_eq!(m, [[c * c - s * s, 2.0 * c * s], [-2.0 * c * s, c * c - s * s]]);
/// ```
#[inline]
pub fn quadratic<T: Ring, const N: usize, const NC: usize>(
    v: &[&T],
    entries: &[u8],
    coefs: &[(i64, i64); NC],
) -> [[T; N]; N] {
    let coefs: [T; NC] = core::array::from_fn(|c| T::from_ratio(coefs[c].0, coefs[c].1));
    let mut m: [[T; N]; N] = core::array::from_fn(|_| core::array::from_fn(|_| T::zero()));
    for e in 0..entries.len() / 10 {
        let p = v[at(entries, 5 * e + 2)].mul_ref(v[at(entries, 5 * e + 3)]);
        accumulate(&mut m[at(entries, 5 * e)][at(entries, 5 * e + 1)], &p, at(entries, 5 * e + 4), &coefs);
    }
    m
}

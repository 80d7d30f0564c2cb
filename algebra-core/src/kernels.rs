//! The loops behind the table-driven kernels of generated modules (the size policy of
//! `algebra_codegen::size`): a kernel above its module's threshold, or over a type the
//! generator added on its own (the full multivector, a parity type), is a constant term table
//! and a call to one of these functions, instead of straight-line code. Written once here, so a
//! generated module holds only its tables, each one byte-string literal: rustc reads one token
//! per table instead of a binding and a sum per term.
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

/// The terms of a packed table (three little-endian `u16`s each: `i`, `j`, the code), at
/// compile time: a generated kernel writes `const TERMS: [(u16, u16, u16); N] =
/// unpack(b"...")`, one token for the whole table, and its loop then reads a constant array.
///
/// ```
/// use algebra_core::kernels::unpack;
/// const TERMS: [(u16, u16, u16); 2] = unpack(b"\x01\0\x02\0\0\0\x03\0\x04\0\x01\0");
/// assert_eq!(TERMS, [(1, 2, 0), (3, 4, 1)]);
/// ```
pub const fn unpack<const N: usize>(bytes: &[u8]) -> [(u16, u16, u16); N] {
    assert!(bytes.len() == 6 * N, "a packed term table has six bytes per term");
    let mut out = [(0u16, 0u16, 0u16); N];
    let mut t = 0;
    while t < N {
        let b = 6 * t;
        out[t] = (
            u16::from_le_bytes([bytes[b], bytes[b + 1]]),
            u16::from_le_bytes([bytes[b + 2], bytes[b + 3]]),
            u16::from_le_bytes([bytes[b + 4], bytes[b + 5]]),
        );
        t += 1;
    }
    out
}

/// `out[k] = Σ c · a[i] · b[j]` over the terms `(i, j, code)` of `terms[starts[k]..starts[k +
/// 1]]`, where `code` 0 is `+1`, 1 is `-1` and `2 + n` is `coefs[n]` (a ratio `num / den`).
///
/// `starts` has `N + 1` entries (the terms grouped by output). Each output is summed in four
/// interleaved accumulators (four independent addition chains), and the constants other than
/// `±1` are converted with `T::from_ratio` once per call. Every length is a constant of the
/// call (arrays, not slices), and a generated kernel's tables are constants ([`unpack`]), so
/// the optimiser sees the whole loop: measured 5-15 % slower than the same loop written out in
/// each kernel (docs/performance.md), against 3 x slower when the table was decoded from bytes
/// at run time.
///
/// ```
/// use algebra_core::kernels::bilinear;
/// // (a0 + a1 e12) (b0 + b1 e12) in G_2: scalar a0 b0 - a1 b1, e12 part a0 b1 + a1 b0
/// let terms = [(0, 0, 0), (1, 1, 1), (0, 1, 0), (1, 0, 0)];
/// let (a, b) = ([&2.0, &3.0], [&5.0, &7.0]);
/// let out: [f64; 2] = bilinear(a, b, &terms, &[0, 2, 4], &[]);
/// assert_eq!(out, [2.0 * 5.0 - 3.0 * 7.0, 2.0 * 7.0 + 3.0 * 5.0]);
/// // a constant other than ±1: out = (1/2) a0 b0
/// let half: [f64; 1] = bilinear(a, b, &[(0, 0, 2)], &[0, 1], &[(1, 2)]);
/// assert_eq!(half, [5.0]);
/// ```
#[inline(always)]
pub fn bilinear<
    T: Ring,
    const N: usize,
    const NA: usize,
    const NB: usize,
    const NT: usize,
    const NS: usize,
    const NC: usize,
>(
    a: [&T; NA],
    b: [&T; NB],
    terms: &[(u16, u16, u16); NT],
    starts: &[u16; NS],
    coefs: &[(i64, i64); NC],
) -> [T; N] {
    debug_assert_eq!(NS, N + 1);
    let coefs: [T; NC] = core::array::from_fn(|c| T::from_ratio(coefs[c].0, coefs[c].1));
    let term = |acc: &mut T, &(i, j, c): &(u16, u16, u16)| {
        let p = a[usize::from(i)].mul_ref(b[usize::from(j)]);
        accumulate(acc, &p, usize::from(c), &coefs);
    };
    core::array::from_fn(|k| {
        let terms = &terms[usize::from(starts[k])..usize::from(starts[k + 1])];
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

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

/// A packed table (little-endian `u16`s, `W` per row) as an array of rows, at compile time: a
/// generated kernel writes `const TERMS: [[u16; 3]; N] = unpack(b"...")`, one token for the
/// whole table, and its loop then reads a constant array (decoding the bytes at run time made
/// the table kernels 3 x slower, docs/performance.md).
///
/// ```
/// use algebra_core::kernels::unpack;
/// const TERMS: [[u16; 3]; 2] = unpack(b"\x01\0\x02\0\0\0\x03\0\x04\0\x01\0");
/// assert_eq!(TERMS, [[1, 2, 0], [3, 4, 1]]);
/// const ROWS: [[u16; 2]; 1] = unpack(b"\xff\x01\x00\x01");
/// assert_eq!(ROWS, [[0x01ff, 0x0100]]);
/// ```
pub const fn unpack<const N: usize, const W: usize>(bytes: &[u8]) -> [[u16; W]; N] {
    assert!(bytes.len() == 2 * W * N, "a packed table has two bytes per number, W numbers per row");
    let mut out = [[0u16; W]; N];
    let mut t = 0;
    while t < N {
        let mut k = 0;
        while k < W {
            let b = 2 * (W * t + k);
            out[t][k] = u16::from_le_bytes([bytes[b], bytes[b + 1]]);
            k += 1;
        }
        t += 1;
    }
    out
}

/// `out[k] = Σ c · a[i] · b[j]` over the terms `[i, j, code]` of `terms[starts[k]..starts[k +
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
/// let terms = [[0, 0, 0], [1, 1, 1], [0, 1, 0], [1, 0, 0]];
/// let (a, b) = ([&2.0, &3.0], [&5.0, &7.0]);
/// let out: [f64; 2] = bilinear(a, b, &terms, &[0, 2, 4], &[]);
/// assert_eq!(out, [2.0 * 5.0 - 3.0 * 7.0, 2.0 * 7.0 + 3.0 * 5.0]);
/// // a constant other than ±1: out = (1/2) a0 b0
/// let half: [f64; 1] = bilinear(a, b, &[[0, 0, 2]], &[0, 1], &[(1, 2)]);
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
    terms: &[[u16; 3]; NT],
    starts: &[u16; NS],
    coefs: &[(i64, i64); NC],
) -> [T; N] {
    debug_assert_eq!(NS, N + 1);
    let coefs: [T; NC] = core::array::from_fn(|c| T::from_ratio(coefs[c].0, coefs[c].1));
    let term = |acc: &mut T, &[i, j, c]: &[u16; 3]| {
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

/// The `N x N` matrix `M[j][b] = Σ c · v[a] · v[a2]` over the entries `[j, b, a, a2, code]`
/// (`code` as in [`bilinear`]): the matrix of a versor action, whose entries are quadratic in
/// the versor's coefficients `v`, as the generated `ActionMatrix` impls of tables build it.
///
/// ```
/// use algebra_core::kernels::quadratic;
/// // the matrix of `rev(R) x R` for the rotor R = c + s e12 on vectors of G_2:
/// // [[c² - s², 2cs], [-2cs, c² - s²]]; codes 0: +1, 1: -1, 2: 2, 3: -2
/// let entries = [[0, 0, 0, 0, 0], [0, 0, 1, 1, 1], [0, 1, 0, 1, 2], [1, 0, 0, 1, 3], [1, 1, 0, 0, 0], [1, 1, 1, 1, 1]];
/// let (c, s) = (0.6, 0.8);
/// let m: [[f64; 2]; 2] = quadratic(&[&c, &s], &entries, &[(2, 1), (-2, 1)]);
/// assert_eq!(m, [[c * c - s * s, 2.0 * c * s], [-2.0 * c * s, c * c - s * s]]);
/// ```
#[inline]
pub fn quadratic<T: Ring, const N: usize, const NE: usize, const NC: usize>(
    v: &[&T],
    entries: &[[u16; 5]; NE],
    coefs: &[(i64, i64); NC],
) -> [[T; N]; N] {
    let coefs: [T; NC] = core::array::from_fn(|c| T::from_ratio(coefs[c].0, coefs[c].1));
    let mut m: [[T; N]; N] = core::array::from_fn(|_| core::array::from_fn(|_| T::zero()));
    for &[j, b, a, a2, code] in entries {
        let p = v[usize::from(a)].mul_ref(v[usize::from(a2)]);
        accumulate(&mut m[usize::from(j)][usize::from(b)], &p, usize::from(code), &coefs);
    }
    m
}

//! Helpers shared by the integration tests of algebra-core: the built-in algebras (built once,
//! so their lazily built tables are shared by every proptest case), exact multivector
//! constructors, strict comparisons with readable failure messages, and the proptest
//! strategies for random sparse rational multivectors.
#![allow(dead_code)] // each test binary uses its own subset of these helpers

use algebra_core::algebra::BUILTINS;
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Algebra, Basis, Multivector};
use proptest::prelude::*;
use proptest::test_runner::TestCaseError;
use std::sync::{Arc, OnceLock};

/// Exact multivectors.
pub type Mv = Multivector<Q>;

/// One random term before it is fitted to an algebra: `(mask seed, numerator, denominator)`.
pub type RawTerm = (u32, i64, i64);

/// Every built-in algebra, built once per test binary.
pub fn builtins() -> &'static [Arc<Algebra>] {
    static ALL: OnceLock<Vec<Arc<Algebra>>> = OnceLock::new();
    ALL.get_or_init(|| BUILTINS.iter().map(|n| Algebra::builtin(n).expect("built-in algebra")).collect())
}

/// The built-in algebra `name` (shared instance).
pub fn builtin(name: &str) -> Arc<Algebra> {
    builtins().iter().find(|a| a.name() == name).unwrap_or_else(|| panic!("no built-in {name}")).clone()
}

/// Owned labels.
pub fn labels(v: &[&str]) -> Vec<String> {
    v.iter().map(|s| s.to_string()).collect()
}

/// A multivector from `(mask, coefficient)` pairs (repeated masks add up).
pub fn mv(alg: &Arc<Algebra>, basis: Basis, terms: &[(u32, Q)]) -> Mv {
    let mut coeffs = vec![q(0); alg.dim()];
    for (m, c) in terms {
        coeffs[*m as usize] += c;
    }
    Mv::from_coeffs(alg, basis, coeffs).expect("right length")
}

/// A multivector from `(name, coefficient)` pairs.
pub fn named(alg: &Arc<Algebra>, basis: Basis, terms: &[(&str, Q)]) -> Mv {
    Mv::from_terms(alg, basis, terms.iter().map(|(n, c)| (*n, c.clone()))).expect("known names")
}

/// The scalar `c`.
pub fn scalar(alg: &Arc<Algebra>, basis: Basis, c: Q) -> Mv {
    mv(alg, basis, &[(0, c)])
}

/// The zero multivector.
pub fn zero(alg: &Arc<Algebra>, basis: Basis) -> Mv {
    mv(alg, basis, &[])
}

/// Random raw terms fitted to `alg`: masks reduced modulo `2^n`.
pub fn from_raw(alg: &Arc<Algebra>, basis: Basis, raw: &[RawTerm]) -> Mv {
    let dim = alg.dim() as u32;
    let terms: Vec<(u32, Q)> = raw.iter().map(|&(m, n, d)| (m % dim, ratio(n, d))).collect();
    mv(alg, basis, &terms)
}

/// A random vector (grade 1 in both bases: single generators are the same element in both).
pub fn vector_from_raw(alg: &Arc<Algebra>, basis: Basis, raw: &[RawTerm]) -> Mv {
    let n = alg.generators() as u32;
    let terms: Vec<(u32, Q)> = raw.iter().map(|&(m, num, d)| (1 << (m % n), ratio(num, d))).collect();
    mv(alg, basis, &terms)
}

/// The coefficients of a vector on the generators (panics if `v` is not a pure vector).
pub fn vector_coeffs(v: &Mv) -> Vec<Q> {
    let n = v.algebra().generators();
    for (m, c) in v.coeffs().iter().enumerate() {
        assert!(m.count_ones() == 1 || *c == q(0), "not a vector: {v}");
    }
    (0..n).map(|i| v.coeff(1 << i).unwrap().clone()).collect()
}

/// `B(u, v)` computed straight from the Gram matrix.
pub fn bilinear(alg: &Algebra, u: &[Q], v: &[Q]) -> Q {
    let mut s = q(0);
    for (i, ui) in u.iter().enumerate() {
        for (j, vj) in v.iter().enumerate() {
            s += ui * vj * alg.metric().gram(i, j).unwrap();
        }
    }
    s
}

/// `Ok` when `lhs` and `rhs` are stored in the same basis with identical coefficients; else a
/// proptest failure naming `what` and showing both sides.
pub fn check_eq(lhs: &Mv, rhs: &Mv, what: impl std::fmt::Display) -> Result<(), TestCaseError> {
    if lhs.basis() == rhs.basis() && lhs.coeffs() == rhs.coeffs() {
        Ok(())
    } else {
        Err(TestCaseError::fail(format!("{what}\n  left  ({}): {lhs}\n  right ({}): {rhs}", lhs.basis(), rhs.basis())))
    }
}

/// Like [`check_eq`] but panicking, for plain `#[test]`s.
pub fn assert_mv_eq(lhs: &Mv, rhs: &Mv, what: impl std::fmt::Display) {
    if let Err(e) = check_eq(lhs, rhs, what) {
        panic!("{e}");
    }
}

/// Runs `f` for every built-in algebra in both bases; the error names the algebra and basis.
pub fn for_all_algebras(
    mut f: impl FnMut(&Arc<Algebra>, Basis) -> Result<(), TestCaseError>,
) -> Result<(), TestCaseError> {
    for alg in builtins() {
        for basis in Basis::ALL {
            f(alg, basis).map_err(|e| TestCaseError::fail(format!("[{} / {basis} basis] {e}", alg.name())))?;
        }
    }
    Ok(())
}

/// A small non-zero rational coefficient: mostly integers in ±1..4, sometimes a fraction.
pub fn coeff() -> impl Strategy<Value = (i64, i64)> {
    let num = (1i64..=4, any::<bool>()).prop_map(|(n, neg)| if neg { -n } else { n });
    let den = prop_oneof![3 => Just(1i64), 1 => 2i64..=3];
    (num, den)
}

/// 1..=6 random terms (masks are reduced modulo the algebra's dimension later).
pub fn raw_mv() -> impl Strategy<Value = Vec<RawTerm>> {
    prop::collection::vec((0u32..1024, coeff()).prop_map(|(m, (n, d))| (m, n, d)), 1..=6)
}

/// 1..=4 random terms of a vector.
pub fn raw_vector() -> impl Strategy<Value = Vec<RawTerm>> {
    prop::collection::vec((0u32..1024, coeff()).prop_map(|(m, (n, d))| (m, n, d)), 1..=4)
}

/// The sign of reordering `e_A e_B` (orthogonal generators, each index set increasing) into
/// increasing order: `(-1)^#{(a, b) in A x B : a > b}`. Written here independently of the
/// library's `wedge_sign`.
pub fn reorder_sign(a: u32, b: u32) -> i64 {
    let mut swaps = 0u32;
    for i in 0..32 {
        if a >> i & 1 == 1 {
            swaps += (b & ((1u32 << i) - 1)).count_ones();
        }
    }
    if swaps.is_multiple_of(2) { 1 } else { -1 }
}

/// The workspace's deterministic generator for random instances outside proptest.
#[allow(unused_imports)] // not every test file of this crate draws random instances
pub use algebra_core::test_support::Xorshift;

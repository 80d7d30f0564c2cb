//! The symbolic Lemma 2.2 check: eqs. (5)-(9) for a fully symbolic S of G_123inf in
//! G_0123inf (product basis), against the paper's printed polynomials.
//!
//! Three measurements (docs/performance.md compares them with galgebra, timed by
//! `tests/fixtures/galgebra/time_lemma_2_2.py`):
//! - `expansions`: rev(S) S and rev(S) e_i S for e0, e1, e2, e3 (the five products galgebra
//!   expands), tables already built;
//! - `expansions_cold`: the same including building the algebra and its tables;
//! - `statements`: the registered statements Lemma 2.2 (i)-(iii) and eqs. (5)-(9) as
//!   `gam verify` runs them (both bases, with the comparisons).
//!
//! Run with `cargo bench -p gam-verify --bench lemma_2_2`.
#![allow(missing_docs)] // criterion_group! generates undocumented items

use algebra_core::{Algebra, Basis, Multivector, Poly};
use criterion::{Criterion, criterion_group, criterion_main};
use gam_verify::cross2022::formulas::symbolic_s;
use std::hint::black_box;
use std::sync::Arc;

fn expansions(alg: &Arc<Algebra>) -> Vec<Multivector<Poly>> {
    let s = symbolic_s(alg, Basis::Product);
    let mut out = vec![&s.reverse() * &s];
    for name in ["e0", "e1", "e2", "e3"] {
        let x = Multivector::basis_element(alg, Basis::Product, name).expect("basis name");
        out.push(s.sandwich(&x));
    }
    out
}

const LEMMA_2_2: [&str; 8] = [
    "cross2022/lemma-2.2-i",
    "cross2022/lemma-2.2-ii",
    "cross2022/lemma-2.2-iii",
    "cross2022/eq-5",
    "cross2022/eq-6",
    "cross2022/eq-7",
    "cross2022/eq-8",
    "cross2022/eq-9",
];

fn bench(c: &mut Criterion) {
    let alg = Algebra::builtin("cga-null").expect("built-in");
    black_box(expansions(&alg));
    c.bench_function("lemma_2_2/expansions", |b| b.iter(|| black_box(expansions(black_box(&alg)))));
    c.bench_function("lemma_2_2/expansions_cold", |b| {
        b.iter(|| {
            let fresh = Algebra::builtin("cga-null").expect("built-in");
            black_box(expansions(&fresh))
        })
    });
    let statements: Vec<_> = LEMMA_2_2.iter().map(|id| gam_verify::find(id).expect("registered")).collect();
    c.bench_function("lemma_2_2/statements", |b| {
        b.iter(|| {
            for s in &statements {
                let r = s.run();
                assert!(r.outcome.holds());
                black_box(r);
            }
        })
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(20).measurement_time(std::time::Duration::from_secs(4));
    targets = bench
}
criterion_main!(benches);

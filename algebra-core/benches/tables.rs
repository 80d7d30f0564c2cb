//! Time to build product tables from scratch: all tables of every built-in algebra in both
//! bases, and the geometric-product tables of larger non-diagonal algebras (n = 6, 8).
//!
//! Run with `cargo bench -p algebra-core --bench tables`.
#![allow(missing_docs)] // criterion_group! generates undocumented items

use algebra_core::rational::q;
use algebra_core::{Algebra, Basis, Metric, Product};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Duration;

/// A non-diagonal, non-degenerate metric on n generators: 1 on the diagonal except a null
/// pair (first, last) with B = -1, and 1/2 couplings between neighbours 1..n-1.
fn non_diagonal(n: usize) -> Metric {
    let labels = (0..n).map(|i| format!("g{i}x")).collect();
    let mut g = vec![vec![q(0); n]; n];
    for (i, row) in g.iter_mut().enumerate().take(n - 1).skip(1) {
        row[i] = q(1);
    }
    g[0][n - 1] = q(-1);
    g[n - 1][0] = q(-1);
    for i in 1..n - 2 {
        g[i][i + 1] = algebra_core::rational::ratio(1, 2);
        g[i + 1][i] = algebra_core::rational::ratio(1, 2);
    }
    Metric::new(labels, g).expect("valid metric")
}

fn bench_tables(c: &mut Criterion) {
    let mut group = c.benchmark_group("build_all_tables");
    group.sample_size(10).measurement_time(Duration::from_secs(3));
    for name in algebra_core::algebra::BUILTINS {
        let metric = Algebra::builtin(name).unwrap().metric().clone();
        group.bench_function(name, |b| {
            b.iter(|| {
                let alg = Algebra::new(name, black_box(metric.clone()));
                alg.tables().build_all();
            })
        });
    }
    group.finish();

    let mut group = c.benchmark_group("geometric_product_tables");
    group.sample_size(10).measurement_time(Duration::from_secs(5));
    for n in [6, 8] {
        let metric = non_diagonal(n);
        group.bench_function(format!("non_diagonal_n{n}"), |b| {
            b.iter(|| {
                let alg = Algebra::new("bench", black_box(metric.clone()));
                black_box(alg.tables().product(Basis::Blade, Product::Geometric).nonzero_entries());
                black_box(alg.tables().product(Basis::Product, Product::Geometric).nonzero_entries());
            })
        });
    }
    group.finish();
}

criterion_group!(benches, bench_tables);
criterion_main!(benches);

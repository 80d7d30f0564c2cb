//! Gröbner basis + normal form, end to end, on the systems of the sympy fixture
//! (tests/fixtures/sympy/groebner.json, written by tests/fixtures/sympy/groebner.py, which
//! also records sympy's time for `groebner` + `reduced` on the same input).
//!
//! Run with `cargo bench -p algebra-core --bench groebner -- --warm-up-time 1 --measurement-time 3`.
//! After the criterion groups it prints, per system, GAM's median time, sympy's best-of-3 time
//! from the fixture and the ratio.
#![allow(missing_docs)] // criterion_group! generates undocumented items

use algebra_core::Poly;
use algebra_core::ideal::{Budget, MonomialOrder, PolyRing};
use criterion::{Criterion, criterion_group, criterion_main};
use std::hint::black_box;
use std::time::Instant;

#[path = "../tests/sympy_fixture/mod.rs"]
mod sympy_fixture;

struct System {
    name: String,
    vars: Vec<String>,
    order: MonomialOrder,
    gens: Vec<Poly>,
    target: Poly,
    sympy_seconds: f64,
}

fn systems() -> Vec<System> {
    sympy_fixture::systems()
        .iter()
        .map(|s| {
            let vars = sympy_fixture::variables(s);
            let gens =
                s["generators"].as_array().expect("gens").iter().map(|g| sympy_fixture::poly(&vars, g)).collect();
            let target = sympy_fixture::poly(&vars, &s["target"]);
            let sympy_seconds = s["sympy_seconds"].as_f64().expect("time");
            let order = sympy_fixture::order(s);
            System { name: s["name"].as_str().expect("name").into(), vars, order, gens, target, sympy_seconds }
        })
        .collect()
}

/// groebner + reduced, as the sympy script times it.
fn run(s: &System) -> Poly {
    let ring = PolyRing::new(&s.vars, s.order);
    let g = ring.groebner(&s.gens, &Budget::default()).expect("within budget");
    g.normal_form(&s.target).expect("normal form")
}

fn bench_groebner(c: &mut Criterion) {
    let systems = systems();
    let mut group = c.benchmark_group("groebner");
    for s in &systems {
        group.bench_function(&s.name, |b| b.iter(|| black_box(run(black_box(s)))));
    }
    group.finish();
    println!("\nsystem          GAM median     sympy best-of-3   sympy / GAM");
    for s in &systems {
        let mut times: Vec<f64> = (0..15)
            .map(|_| {
                let t = Instant::now();
                black_box(run(s));
                t.elapsed().as_secs_f64()
            })
            .collect();
        times.sort_by(f64::total_cmp);
        let gam = times[times.len() / 2];
        println!(
            "{:<15} {:>10.1} us  {:>12.1} us   {:>8.0}x",
            s.name,
            gam * 1e6,
            s.sympy_seconds * 1e6,
            s.sympy_seconds / gam
        );
    }
}

criterion_group!(benches, bench_groebner);
criterion_main!(benches);

//! Interleaved timing shared by the motion benches: every kernel back to back in each round
//! (rotating order), so ratios stay meaningful when the load of a shared machine changes.

use criterion::{Criterion, Throughput};
use std::hint::black_box;
use std::time::Instant;

/// A timed kernel: returns a number so that the work is not optimised away.
pub type Kernel<D> = fn(&D) -> f64;

/// Per-round times per evaluation (`per` evaluations per kernel call), one list per kernel.
pub fn times<D>(kernels: &[(&str, Kernel<D>)], d: &D, rounds: usize, per: usize) -> Vec<Vec<f64>> {
    let mut times: Vec<Vec<f64>> = vec![Vec::with_capacity(rounds); kernels.len()];
    for round in 0..rounds {
        for j in 0..kernels.len() {
            let i = (j + round) % kernels.len();
            let start = Instant::now();
            black_box(kernels[i].1(black_box(d)));
            times[i].push(start.elapsed().as_secs_f64() / per as f64);
        }
    }
    times
}

/// The median.
pub fn median(mut v: Vec<f64>) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

/// One criterion group timing every kernel on `d` (`per` evaluations per call).
pub fn group<D>(c: &mut Criterion, name: &str, kernels: &[(&str, Kernel<D>)], d: &D, per: usize) {
    let mut g = c.benchmark_group(name);
    g.throughput(Throughput::Elements(per as u64));
    for (name, kernel) in kernels {
        g.bench_function(*name, |b| b.iter(|| kernel(black_box(d))));
    }
    g.finish();
}

/// Prints the median time per evaluation of every kernel.
pub fn print_medians<D>(kernels: &[(&str, Kernel<D>)], times: &[Vec<f64>]) {
    for (i, (name, _)) in kernels.iter().enumerate() {
        println!("  {name:<22} {:>9.1} ns", median(times[i].clone()) * 1e9);
    }
}

/// The median of the per-round ratios `times[a] / times[b]`.
pub fn ratio(times: &[Vec<f64>], a: usize, b: usize) -> f64 {
    median(times[a].iter().zip(&times[b]).map(|(x, y)| x / y).collect())
}

/// Times `kernels` interleaved (`rounds` rounds, `per` elements per call) and prints each one's
/// median time per element and its median ratio to the first kernel (named in `against`).
/// (Used by the `gam-algebras` benches, which include this file by path.)
#[allow(dead_code)]
pub fn report_vs_first<D>(title: &str, against: &str, kernels: &[(&str, Kernel<D>)], d: &D, rounds: usize, per: usize) {
    let t = times(kernels, d, rounds, per);
    println!("\ninterleaved ({rounds} rounds): {title}");
    println!("  {:<32} {:>12} {:>22}", "kernel", "ns/element", format!("ratio to {against}"));
    for (i, (name, _)) in kernels.iter().enumerate() {
        println!("  {name:<32} {:>12.2} {:>22.3}", median(t[i].clone()) * 1e9, ratio(&t, i, 0));
    }
}

//! The inverse-kinematics workload of the ga-benchmark suite over the generated kernels
//! (`ik/arm.rs`: GATL's conformal declaration, the suite's five-joint arm and fourth-order
//! Taylor rotors), timed twice per round, back to back:
//!
//! * **run-time geometry**: the arm's dimensions read from memory on every call (`black_box`),
//!   so every point, line and product of the chain is computed;
//! * **compile-time geometry**: the dimensions a constant ([`arm::ARM`]); the chain is inlined,
//!   and the compiler folds what depends on constants only (the arm's points and lines), as
//!   GATL folds its `c<N>` constants.
//!
//! Per round, 256 angle sets; the report prints the median of the per-round times (ns per
//! chain) and their ratio. The C++ peer (GATL) is measured once outside the repository
//! (docs/performance.md, "Inverse kinematics against GATL"), with the same workload.
//!
//! Run with `cargo bench -p gam-algebras --bench ik` (optionally the number of rounds after
//! `--`), pinned for stable figures: `taskset -c 1 target/release/deps/ik-<hash> 2001`.
#![allow(missing_docs)]

#[path = "ik/arm.rs"]
mod arm;

use algebra_core::test_support::Xorshift;
use std::hint::black_box;
use std::time::Instant;

const N: usize = 256;

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    v[v.len() / 2]
}

fn main() {
    let rounds = std::env::args().skip(1).find_map(|a| a.parse::<usize>().ok()).unwrap_or(401);
    let mut rng = Xorshift(0x9e37_79b9_7f4a_7c15);
    let angles: Vec<[f64; 5]> =
        (0..N).map(|_| std::array::from_fn(|_| (rng.unit() * 2.0 - 1.0) * std::f64::consts::PI)).collect();
    let (mut runtime, mut constant) = (Vec::new(), Vec::new());
    for _ in 0..rounds {
        let t0 = Instant::now();
        for a in &angles {
            black_box(arm::chain(black_box(a), black_box(&arm::ARM)));
        }
        let t1 = Instant::now();
        for a in &angles {
            black_box(arm::chain(black_box(a), &arm::ARM));
        }
        let t2 = Instant::now();
        runtime.push((t1 - t0).as_secs_f64() * 1e9 / N as f64);
        constant.push((t2 - t1).as_secs_f64() * 1e9 / N as f64);
    }
    let (rt, ct) = (median(&mut runtime), median(&mut constant));
    println!("inverse kinematics (ga-benchmark's arm, Taylor rotors), {rounds} rounds of {N} chains, medians:");
    println!("  run-time geometry      {rt:8.1} ns per chain");
    println!("  compile-time geometry  {ct:8.1} ns per chain ({:.2}x the run-time one)", ct / rt);
}

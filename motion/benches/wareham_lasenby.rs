//! Wareham–Lasenby's closed forms in `cga` (motion::wareham_lasenby) against the main paper's
//! pose exp/log on the same screw motions and the runtime `Multivector::exp` of algebra-core, in
//! one process (f64):
//!
//! * `wl/exp`: `Generator::exp` (Theorem 3) on 64 generators `φP + tn`;
//! * `pose/exp`: `Pose::exp` on the same Lie-algebra elements (`a = r`, `c = -t`);
//! * `runtime/exp`: the general `Multivector::exp` of the `cga` bivector;
//! * `wl/log`: `log` (Theorem 9) of the 64 rotors; `pose/log`: `Pose::log` of the 64 poses.
//!
//! After the criterion group, `cargo bench` prints the per-evaluation medians measured
//! interleaved (each kernel back to back per round) and the ratios to the pose exp/log.
//!
//! Run with `cargo bench -p motion --bench wareham_lasenby -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

mod interleaved;

use criterion::{Criterion, criterion_group};
use gam_algebras::cga;
use motion::Pose;
use motion::wareham_lasenby::{Generator, log, to_pose};
use std::hint::black_box;

const N: usize = 64;

struct Data {
    generators: Vec<Generator<f64>>,
    pose_elements: Vec<Pose<f64>>,
    bivectors: Vec<algebra_core::Multivector<f64>>,
    rotors: Vec<cga::Motor<f64>>,
    poses: Vec<Pose<f64>>,
}

fn data() -> Data {
    let generators: Vec<Generator<f64>> = (0..N)
        .map(|i| {
            let x = i as f64 / N as f64;
            Generator::new([0.3 * x, 0.5 - x, 0.2 + 0.4 * x], [1.0 - 2.0 * x, 0.5 + x, -0.7 * x])
        })
        .collect();
    let pose_elements =
        generators.iter().map(|g| Pose::new(0.0, g.r[2], -g.r[1], g.r[0], -g.t[0], -g.t[1], -g.t[2], 0.0)).collect();
    let bivectors = generators.iter().map(|g| g.to_bivector().to_multivector()).collect();
    let rotors: Vec<cga::Motor<f64>> = generators.iter().map(|g| g.exp().unwrap()).collect();
    let poses = rotors.iter().map(to_pose).collect();
    Data { generators, pose_elements, bivectors, rotors, poses }
}

type Kernel = fn(&Data) -> f64;

const KERNELS: [(&str, Kernel); 5] = [
    ("wl/exp", |d| d.generators.iter().map(|g| black_box(g).exp().unwrap().scalar).sum()),
    ("pose/exp", |d| d.pose_elements.iter().map(|m| Pose::exp(black_box(m)).unwrap().scalar).sum()),
    ("runtime/exp", |d| d.bivectors.iter().map(|b| black_box(b).exp().unwrap().coeffs()[0]).sum()),
    ("wl/log", |d| d.rotors.iter().map(|r| log(black_box(r)).unwrap().r[0]).sum()),
    ("pose/log", |d| d.poses.iter().map(|p| black_box(p).log().unwrap().e12).sum()),
];

fn closed_forms(c: &mut Criterion) {
    interleaved::group(c, "wareham_lasenby", &KERNELS, &data(), N);
}

/// Median per-evaluation times, every kernel back to back in each round, and the median
/// per-round ratios against the pose exp / log.
fn interleaved_report(rounds: usize) {
    let times = interleaved::times(&KERNELS, &data(), rounds, N);
    println!("\ninterleaved ({rounds} rounds, median per evaluation, f64):");
    interleaved::print_medians(&KERNELS, &times);
    for (what, a, b) in [("wl/exp / pose/exp", 0, 1), ("runtime/exp / wl/exp", 2, 0), ("wl/log / pose/log", 3, 4)] {
        println!("  {what} = {:.2}", interleaved::ratio(&times, a, b));
    }
}

criterion_group!(benches, closed_forms);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    if std::env::args().any(|a| a == "--bench") {
        interleaved_report(500);
    } else {
        // Sanity when run as a test: the three exps agree.
        let d = data();
        for ((g, m), b) in d.generators.iter().zip(&d.pose_elements).zip(&d.bivectors) {
            let r = g.exp().unwrap();
            assert!(to_pose(&r).is_equivalent(&Pose::exp(m).unwrap(), &1e-12).unwrap());
            assert!((b.exp().unwrap().coeffs()[0] - r.scalar).abs() < 1e-12);
        }
    }
}

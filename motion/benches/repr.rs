//! Hexanions against the main paper's pose exp/log (f64), in one process:
//!
//! * `exp`: Angelidis' closed form (66) to a 4x4 matrix (`Hexanion::exp_matrix`) and to a pose
//!   (`Hexanion::to_pose`), against `Pose::exp` of the same generator followed by
//!   `Pose::to_matrix` (the peer), on 64 generic twists;
//! * `log`: matrix -> hexanion by Angelidis' Sec. 6 (`Hexanion::from_matrix_sec6`) and through
//!   the pose (`Hexanion::from_matrix`), against `Pose::from_matrix` + `Pose::log` (the peer).
//!
//! After the criterion groups the bench prints the ratios to the peers measured interleaved
//! (every kernel back to back in each round; median of the per-round ratios).
//!
//! Run with `cargo bench -p motion --bench repr -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

mod interleaved;

use criterion::{Criterion, criterion_group};
use motion::repr::hexanion::Hexanion;
use motion::{Matrix4, Pose};
use std::hint::black_box;

const N: usize = 64;

struct Data {
    hexanions: Vec<Hexanion<f64>>,
    generators: Vec<Pose<f64>>,
    matrices: Vec<Matrix4<f64>>,
}

fn data() -> Data {
    let hexanions: Vec<Hexanion<f64>> = (0..N)
        .map(|i| {
            let x = i as f64 / N as f64;
            Hexanion::new([0.3 + x, -0.7 * x, 1.1 - x], [1.0 - 2.0 * x, 0.5 + x, 0.25 * x])
        })
        .collect();
    let generators = hexanions.iter().map(generator).collect();
    let matrices = hexanions.iter().map(|h| h.exp_matrix()).collect();
    Data { hexanions, generators, matrices }
}

fn generator(h: &Hexanion<f64>) -> Pose<f64> {
    Pose::new(0.0, 0.5 * h.omega[2], -0.5 * h.omega[1], 0.5 * h.omega[0], 0.5 * h.m[0], 0.5 * h.m[1], 0.5 * h.m[2], 0.0)
}

type Kernel = interleaved::Kernel<Data>;

/// The `exp` kernels; the first is the peer.
const EXP: [(&str, Kernel); 3] = [
    ("pose exp + to_matrix (peer)", |d| {
        d.generators.iter().map(|g| Pose::exp(black_box(g)).unwrap().to_matrix().unwrap()[0][3]).sum()
    }),
    ("hexanion exp_matrix (66)", |d| d.hexanions.iter().map(|h| black_box(h).exp_matrix()[0][3]).sum()),
    ("hexanion to_pose", |d| d.hexanions.iter().map(|h| black_box(h).to_pose().unwrap().to_array()[4]).sum()),
];

/// The `log` kernels; the first is the peer.
const LOG: [(&str, Kernel); 3] = [
    ("pose from_matrix + log (peer)", |d| {
        d.matrices.iter().map(|m| Pose::from_matrix(black_box(m), &1e-9).unwrap().log().unwrap().e12).sum()
    }),
    ("hexanion from_matrix_sec6", |d| {
        d.matrices.iter().map(|m| Hexanion::from_matrix_sec6(black_box(m), &1e-9).unwrap().m[0]).sum()
    }),
    ("hexanion from_matrix", |d| {
        d.matrices.iter().map(|m| Hexanion::from_matrix(black_box(m), &1e-9).unwrap().m[0]).sum()
    }),
];

fn bench(c: &mut Criterion) {
    let d = data();
    interleaved::group(c, "exp", &EXP, &d, N);
    interleaved::group(c, "log", &LOG, &d, N);
}

/// Interleaved ratios kernel / peer (the first kernel of each group), median over rounds.
fn ratios(rounds: usize) {
    let d = data();
    for kernels in [&EXP, &LOG] {
        let times = interleaved::times(kernels, &d, rounds, N);
        println!("\ninterleaved ({rounds} rounds, median per evaluation, f64):");
        interleaved::print_medians(kernels, &times);
        for (i, (name, _)) in kernels.iter().enumerate() {
            println!("ratio {name} / {}: {:.2}", kernels[0].0, interleaved::ratio(&times, i, 0));
        }
    }
}

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    if std::env::args().any(|a| a == "--bench") {
        ratios(500);
    } else {
        // Sanity when run as a test: the two exps give the same matrix.
        let d = data();
        for (h, g) in d.hexanions.iter().zip(&d.generators) {
            let (a, b) = (h.exp_matrix(), Pose::exp(g).unwrap().to_matrix().unwrap());
            assert!(a.iter().flatten().zip(b.iter().flatten()).all(|(x, y)| (x - y).abs() < 1e-12));
        }
    }
}

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

use criterion::{Criterion, criterion_group};
use motion::repr::hexanion::Hexanion;
use motion::{Matrix4, Pose};
use std::hint::black_box;
use std::time::Instant;

const N: usize = 64;

fn hexanions() -> Vec<Hexanion<f64>> {
    (0..N)
        .map(|i| {
            let x = i as f64 / N as f64;
            Hexanion::new([0.3 + x, -0.7 * x, 1.1 - x], [1.0 - 2.0 * x, 0.5 + x, 0.25 * x])
        })
        .collect()
}

fn generator(h: &Hexanion<f64>) -> Pose<f64> {
    Pose::new(0.0, 0.5 * h.omega[2], -0.5 * h.omega[1], 0.5 * h.omega[0], 0.5 * h.m[0], 0.5 * h.m[1], 0.5 * h.m[2], 0.0)
}

type Kernel<'a> = (&'static str, Box<dyn Fn() -> f64 + 'a>);

fn kernels<'a>(hs: &'a [Hexanion<f64>], gens: &'a [Pose<f64>], mats: &'a [Matrix4<f64>]) -> [Vec<Kernel<'a>>; 2] {
    let exp: Vec<Kernel<'a>> = vec![
        (
            "pose exp + to_matrix (peer)",
            Box::new(move || gens.iter().map(|g| Pose::exp(g).unwrap().to_matrix().unwrap()[0][3]).sum()),
        ),
        ("hexanion exp_matrix (66)", Box::new(move || hs.iter().map(|h| h.exp_matrix()[0][3]).sum())),
        ("hexanion to_pose", Box::new(move || hs.iter().map(|h| h.to_pose().unwrap().to_array()[4]).sum())),
    ];
    let log: Vec<Kernel<'a>> = vec![
        (
            "pose from_matrix + log (peer)",
            Box::new(move || mats.iter().map(|m| Pose::from_matrix(m, &1e-9).unwrap().log().unwrap().e12).sum()),
        ),
        (
            "hexanion from_matrix_sec6",
            Box::new(move || mats.iter().map(|m| Hexanion::from_matrix_sec6(m, &1e-9).unwrap().m[0]).sum()),
        ),
        (
            "hexanion from_matrix",
            Box::new(move || mats.iter().map(|m| Hexanion::from_matrix(m, &1e-9).unwrap().m[0]).sum()),
        ),
    ];
    [exp, log]
}

fn bench(c: &mut Criterion) {
    let hs = hexanions();
    let gens: Vec<_> = hs.iter().map(generator).collect();
    let mats: Vec<_> = hs.iter().map(|h| h.exp_matrix()).collect();
    for (group, ks) in ["exp", "log"].into_iter().zip(kernels(&hs, &gens, &mats)) {
        let mut g = c.benchmark_group(group);
        for (name, k) in &ks {
            g.bench_function(*name, |b| b.iter(|| black_box(k())));
        }
        g.finish();
    }
}

/// Interleaved ratios kernel / peer (the first kernel of each group), median over rounds.
fn ratios() {
    let hs = hexanions();
    let gens: Vec<_> = hs.iter().map(generator).collect();
    let mats: Vec<_> = hs.iter().map(|h| h.exp_matrix()).collect();
    for ks in kernels(&hs, &gens, &mats) {
        let mut per: Vec<Vec<f64>> = vec![Vec::new(); ks.len()];
        for _ in 0..200 {
            let times: Vec<f64> = ks
                .iter()
                .map(|(_, k)| {
                    let t = Instant::now();
                    for _ in 0..20 {
                        black_box(k());
                    }
                    t.elapsed().as_secs_f64()
                })
                .collect();
            for (i, t) in times.iter().enumerate() {
                per[i].push(t / times[0]);
            }
        }
        for ((name, _), mut r) in ks.iter().zip(per) {
            r.sort_by(f64::total_cmp);
            println!("ratio {name} / {}: {:.2}", ks[0].0, r[r.len() / 2]);
        }
    }
}

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    ratios();
}

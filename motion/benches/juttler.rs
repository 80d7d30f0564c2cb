//! A body point's trajectory under a Q-motion (Jüttler), per sample, in one process:
//! evaluating the rational Bézier form (`RationalBezier::point`, degree 16 for Algorithm 1's
//! degree-8 motion through 5 positions) against transforming the point through the sampled
//! motion (`Motion::pose` + `Pose::transform_point`, the peer), on 256 parameters.
//!
//! After the criterion group the bench prints the ratio to the peer measured interleaved
//! (every kernel back to back in each round; median of the per-round ratios).
//!
//! Run with `cargo bench -p motion --bench juttler -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

use criterion::{Criterion, criterion_group};
use motion::juttler::tr::algorithm1;
use motion::juttler::{QMotion, RationalBezier};
use motion::{Motion, Pose};
use std::hint::black_box;
use std::time::Instant;

const N: usize = 256;
const X: [f64; 3] = [0.3, -1.0, 2.0];

fn motion() -> QMotion<f64> {
    let p: Vec<Pose<f64>> = [
        ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
        ([0.0, 1.0, 1.0], 1.0, [1.0, 2.0, 0.5]),
        ([1.0, 0.0, 0.0], 2.5, [2.0, -1.0, 1.0]),
        ([1.0, 2.0, 3.0], -3.0, [4.0, 0.0, 0.0]),
        ([0.0, 0.0, 1.0], 0.3, [5.0, 1.0, -2.0]),
    ]
    .iter()
    .map(|(a, phi, t)| Pose::from_axis_angle_translation(a, phi, t).unwrap())
    .collect();
    algorithm1(&p, &[0.0, 0.2, 0.45, 0.7, 1.0]).unwrap()
}

type Kernel<'a> = (&'static str, Box<dyn Fn() -> f64 + 'a>);

fn kernels<'a>(m: &'a QMotion<f64>, path: &'a RationalBezier<f64>, ts: &'a [f64]) -> Vec<Kernel<'a>> {
    vec![
        (
            "pose + transform_point (peer)",
            Box::new(move || ts.iter().map(|t| m.pose(t).unwrap().transform_point(&X).unwrap()[0]).sum()),
        ),
        ("rational Bézier point", Box::new(move || ts.iter().map(|t| path.point(t).unwrap()[0]).sum())),
        (
            "Q(t) + point_image (12)",
            Box::new(move || {
                ts.iter()
                    .map(|t| {
                        let y = motion::repr::dual_quaternion::point_image(&m.eval(t), &[1.0, X[0], X[1], X[2]]);
                        y[1] / y[0]
                    })
                    .sum()
            }),
        ),
    ]
}

fn params() -> Vec<f64> {
    (0..N).map(|i| i as f64 / (N - 1) as f64).collect()
}

fn bench(c: &mut Criterion) {
    let m = motion();
    let path = m.trajectory(&X);
    let ts = params();
    let mut g = c.benchmark_group("trajectory");
    for (name, k) in &kernels(&m, &path, &ts) {
        g.bench_function(*name, |b| b.iter(|| black_box(k())));
    }
    g.finish();
}

/// Interleaved ratios kernel / peer (the first kernel), median over rounds.
fn ratios() {
    let m = motion();
    let path = m.trajectory(&X);
    let ts = params();
    let ks = kernels(&m, &path, &ts);
    let mut per: Vec<Vec<f64>> = vec![Vec::new(); ks.len()];
    for _ in 0..100 {
        let times: Vec<f64> = ks
            .iter()
            .map(|(_, k)| {
                let t = Instant::now();
                for _ in 0..5 {
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

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    ratios();
}

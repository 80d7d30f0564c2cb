//! Batches across lanes and cores (`motion::batch`), each against the single-core scalar loop
//! measured in the same process:
//!
//! * `cloud`: 1e6 points transformed by one pose. Peers: the scalar loop a user writes
//!   (`Pose::transform_point` per point over `Vec<[f64; 3]>`) and the batch kernel over the
//!   scalar lane type on one core (`Points::transform::<f64>`: `1/α` once, then
//!   `Pose::transform_point`'s formula per point); candidates: the same kernel over both cores
//!   and over SIMD lanes.
//! * `sampling`: 10,000 additive cubic Bézier motions at 100 parameters each, with `dS/dt`
//!   (dual numbers). Peers: `velocity::pose_derivative` per sample (lifts the motion each call)
//!   and `batch::sample_many::<f64>` (lifts once per motion), one core; candidates: over both
//!   cores and over lanes.
//!
//!   The same with the motions across the lanes (`batch::sample_beziers`: lane `i` = motion `i`
//!   at one parameter) against the parameters across the lanes (`sample_many`).
//! * `pairs`: 16,384 pose pairs (in cache: 3 MB of columns), `a[i] * b[i]` (`Poses::compose`) and
//!   pose `i` on point `i` (`Poses::transform_points`), over `f64` and the SIMD lanes, one core.
//!
//! After the criterion groups the kernels run interleaved (every kernel in each round, rotating
//! order) and the report prints medians and the median per-round ratio to each peer.
//!
//! Run with `cargo bench -p motion --bench batch -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

use algebra_core::scalar::{F64x2, F64x4};
use criterion::{Criterion, criterion_group};
use motion::batch::{Points, Poses, par_sample_beziers, par_sample_many, sample_beziers, sample_many};
use motion::velocity::pose_derivative;
use motion::{AdditiveBezier, Pose};
use std::hint::black_box;

mod interleaved;

/// Full sizes under `cargo bench`; small ones when run as a test (`cargo test --benches`).
fn full() -> bool {
    std::env::args().any(|a| a == "--bench")
}

struct Cloud {
    pose: Pose<f64>,
    aos: Vec<[f64; 3]>,
    soa: Points<f64>,
}

fn cloud(n: usize) -> Cloud {
    let pose = Pose::from_axis_angle_translation(&[0.3, 0.4, 0.87], &1.1, &[1.0, -2.0, 0.5]).unwrap();
    let aos: Vec<[f64; 3]> =
        (0..n).map(|i| [(i % 997) as f64 * 0.01, (i % 101) as f64 * 0.1, (i % 13) as f64]).collect();
    let soa = Points::from_points(&aos).unwrap();
    Cloud { pose, aos, soa }
}

fn checksum(p: &Points<f64>) -> f64 {
    p.x()[0] + p.y()[p.len() / 2] + p.z()[p.len() - 1]
}

/// The loop a user writes without batches.
fn cloud_transform_point(d: &Cloud) -> f64 {
    let out: Vec<[f64; 3]> = d.aos.iter().map(|p| d.pose.transform_point(p).unwrap()).collect();
    out[0][0] + out[out.len() / 2][1] + out[out.len() - 1][2]
}

const CLOUD: [(&str, interleaved::Kernel<Cloud>); 7] = [
    ("transform_point loop", cloud_transform_point),
    ("batch f64, 1 core", |d| checksum(&d.soa.transform::<f64>(&d.pose).unwrap())),
    ("batch f64, par", |d| checksum(&d.soa.par_transform::<f64>(&d.pose).unwrap())),
    ("batch F64x2, 1 core", |d| checksum(&d.soa.transform::<F64x2>(&d.pose).unwrap())),
    ("batch F64x2, par", |d| checksum(&d.soa.par_transform::<F64x2>(&d.pose).unwrap())),
    ("batch F64x4, 1 core", |d| checksum(&d.soa.transform::<F64x4>(&d.pose).unwrap())),
    ("batch F64x4, par", |d| checksum(&d.soa.par_transform::<F64x4>(&d.pose).unwrap())),
];

struct Sampling {
    motions: Vec<AdditiveBezier<f64>>,
    ts: Vec<f64>,
}

fn sampling(motions: usize, parameters: usize) -> Sampling {
    let screw = |i: usize, k: usize| {
        let x = (i * 4 + k) as f64;
        let axis = [0.3 + (x * 0.37).sin(), 0.4 + (x * 0.11).cos(), 0.87];
        Pose::from_axis_angle_translation(&axis, &(0.2 + (x * 0.7).sin()), &[x.cos(), 1.0, x.sin()]).unwrap()
    };
    let motions = (0..motions).map(|i| AdditiveBezier::new((0..4).map(|k| screw(i, k)).collect()).unwrap()).collect();
    let ts = (0..parameters).map(|k| k as f64 / (parameters - 1) as f64).collect();
    Sampling { motions, ts }
}

/// The loop a user writes without batches: `pose_derivative` per sample, results kept.
fn sampling_pose_derivative(d: &Sampling) -> f64 {
    let out: Vec<_> = d.motions.iter().flat_map(|m| d.ts.iter().map(|t| pose_derivative(m, t).unwrap())).collect();
    out[0].0.scalar + out[out.len() - 1].1.e12
}

fn samples_checksum(s: &motion::batch::Samples<f64>) -> f64 {
    s.poses().column(0)[0] + s.derivatives().column(1)[s.poses().len() - 1]
}

const SAMPLING: [(&str, interleaved::Kernel<Sampling>); 11] = [
    ("pose_derivative loop", sampling_pose_derivative),
    ("sample_many f64, 1 core", |d| samples_checksum(&sample_many::<f64, _>(&d.motions, &d.ts).unwrap())),
    ("sample_many f64, par", |d| samples_checksum(&par_sample_many::<f64, _>(&d.motions, &d.ts).unwrap())),
    ("sample_many F64x2, 1 core", |d| samples_checksum(&sample_many::<F64x2, _>(&d.motions, &d.ts).unwrap())),
    ("sample_many F64x2, par", |d| samples_checksum(&par_sample_many::<F64x2, _>(&d.motions, &d.ts).unwrap())),
    ("sample_many F64x4, 1 core", |d| samples_checksum(&sample_many::<F64x4, _>(&d.motions, &d.ts).unwrap())),
    ("sample_many F64x4, par", |d| samples_checksum(&par_sample_many::<F64x4, _>(&d.motions, &d.ts).unwrap())),
    ("sample_beziers F64x2, 1 core", |d| samples_checksum(&sample_beziers::<F64x2, _>(&d.motions, &d.ts).unwrap())),
    ("sample_beziers F64x2, par", |d| samples_checksum(&par_sample_beziers::<F64x2, _>(&d.motions, &d.ts).unwrap())),
    ("sample_beziers F64x4, 1 core", |d| samples_checksum(&sample_beziers::<F64x4, _>(&d.motions, &d.ts).unwrap())),
    ("sample_beziers F64x4, par", |d| samples_checksum(&par_sample_beziers::<F64x4, _>(&d.motions, &d.ts).unwrap())),
];

struct Pairs {
    a: Poses<f64>,
    b: Poses<f64>,
    points: Points<f64>,
}

fn pairs(n: usize) -> Pairs {
    let s = sampling(n.div_ceil(4), 2);
    let all: Vec<Pose<f64>> = s.motions.iter().flat_map(|m| m.poses().to_vec()).take(n).collect();
    let rev: Vec<Pose<f64>> = all.iter().rev().cloned().collect();
    let c = cloud(n);
    Pairs { a: Poses::from_poses(&all).unwrap(), b: Poses::from_poses(&rev).unwrap(), points: c.soa }
}

fn poses_checksum(p: &Poses<f64>) -> f64 {
    p.column(0)[0] + p.column(7)[p.len() - 1]
}

const PAIRS: [(&str, interleaved::Kernel<Pairs>); 6] = [
    ("compose f64", |d| poses_checksum(&d.a.compose::<f64>(&d.b).unwrap())),
    ("compose F64x2", |d| poses_checksum(&d.a.compose::<F64x2>(&d.b).unwrap())),
    ("compose F64x4", |d| poses_checksum(&d.a.compose::<F64x4>(&d.b).unwrap())),
    ("transform_points f64", |d| checksum(&d.a.transform_points::<f64>(&d.points).unwrap())),
    ("transform_points F64x2", |d| checksum(&d.a.transform_points::<F64x2>(&d.points).unwrap())),
    ("transform_points F64x4", |d| checksum(&d.a.transform_points::<F64x4>(&d.points).unwrap())),
];

fn sizes() -> (usize, usize, usize) {
    if full() { (1_000_000, 10_000, 100) } else { (1_003, 10, 7) }
}

/// Pose pairs in the `pairs` group.
fn pair_count() -> usize {
    if full() { 16_384 } else { 1_003 }
}

fn bench(c: &mut Criterion) {
    let (points, motions, parameters) = sizes();
    interleaved::group(c, "batch/cloud", &CLOUD, &cloud(points), points);
    // A tenth of a second and more per call: ten criterion samples per kernel.
    let d = sampling(motions, parameters);
    let mut g = c.benchmark_group("batch/sampling");
    g.sample_size(10).throughput(criterion::Throughput::Elements((motions * parameters) as u64));
    for (name, kernel) in &SAMPLING {
        g.bench_function(*name, |b| b.iter(|| kernel(black_box(&d))));
    }
    g.finish();
    interleaved::group(c, "batch/pairs", &PAIRS, &pairs(pair_count()), pair_count());
}

fn report<D>(
    title: &str,
    kernels: &[(&str, interleaved::Kernel<D>)],
    d: &D,
    rounds: usize,
    per: usize,
    peers: &[usize],
) {
    println!("\n{title} ({rounds} interleaved rounds, median per element):");
    let times = interleaved::times(kernels, d, rounds, per);
    interleaved::print_medians(kernels, &times);
    for &peer in peers {
        for (i, (name, _)) in kernels.iter().enumerate().filter(|&(i, _)| i != peer) {
            println!("  {name:<28} / {:<24} = {:.3}", kernels[peer].0, interleaved::ratio(&times, i, peer));
        }
    }
}

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    let (points, motions, parameters) = sizes();
    let rounds = if full() { 15 } else { 1 };
    report("cloud: one pose on 1e6 points", &CLOUD, &cloud(points), rounds, points, &[0, 1]);
    let s = sampling(motions, parameters);
    report(
        "sampling: 10,000 cubic motions x 100 parameters, S and dS/dt",
        &SAMPLING,
        &s,
        rounds.min(5),
        motions * parameters,
        &[0, 1],
    );
    let n = pair_count();
    report("pairs: 16,384 poses, compose and pose i on point i", &PAIRS, &pairs(n), rounds * 20, n, &[0, 3]);
}

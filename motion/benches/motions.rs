//! Additive vs multiplicative cubic Bezier motions (f64), in one process so the ratios are
//! meaningful on a shared machine.
//!
//! Both motions have the same four unit control poses (screw motions: rotations about tilted
//! axes combined with translations). For each kind the bench measures
//!
//! * `pose`: `Motion::pose` at 64 parameter values in [0, 1] (additive: Bernstein form, eq. 18;
//!   multiplicative: the slerp de Casteljau tableau of Fig. 2, six slerps per value);
//! * `psi`: the velocity indicatrix `Ψ = 2 S⁻¹ dS/dt` (eq. 11, by dual numbers) at the same 64
//!   values.
//!
//! After the criterion groups, `cargo bench` also prints ratios multiplicative / additive measured
//! **interleaved** (every kernel back to back in each round, rotating order; median of the
//! per-round ratios), which is robust to load changing between criterion groups.
//!
//! Run with `cargo bench -p motion --bench motions`.
#![allow(missing_docs)]

mod interleaved;

use criterion::{Criterion, criterion_group};
use motion::velocity::velocity_indicatrix;
use motion::{AdditiveBezier, Motion, MultiplicativeBezier, Pose};
use std::hint::black_box;
use std::time::Duration;

/// Parameter values per iteration.
const N: usize = 64;

fn control_poses() -> Vec<Pose<f64>> {
    let screw = |axis: [f64; 3], angle: f64, t: [f64; 3]| Pose::from_axis_angle_translation(&axis, &angle, &t).unwrap();
    vec![
        Pose::identity(),
        screw([0.3, 0.4, 0.87], 0.5, [1.0, 0.5, 0.2]),
        screw([0.1, 1.0, 0.2], 1.2, [2.0, 1.5, -0.5]),
        screw([0.0, 0.3, 1.0], 2.0, [3.0, 1.0, 1.0]),
    ]
}

struct Data {
    additive: AdditiveBezier<f64>,
    multiplicative: MultiplicativeBezier<f64>,
    ts: Vec<f64>,
}

fn data() -> Data {
    let poses = control_poses();
    Data {
        additive: AdditiveBezier::new(poses.clone()).unwrap(),
        multiplicative: MultiplicativeBezier::new(poses).unwrap(),
        ts: (0..N).map(|i| i as f64 / (N - 1) as f64).collect(),
    }
}

fn poses<M: Motion<f64>>(m: &M, ts: &[f64]) -> f64 {
    ts.iter().map(|t| black_box(m.pose(black_box(t)).unwrap()).scalar).sum()
}

fn psis<M: motion::MapScalar<f64, algebra_core::Jet<f64>>>(m: &M, ts: &[f64]) -> f64 {
    ts.iter().map(|t| black_box(velocity_indicatrix(m, black_box(t)).unwrap()).e12).sum()
}

type Kernel = fn(&Data) -> f64;

const KERNELS: [(&str, Kernel); 4] = [
    ("additive/pose", |d| poses(&d.additive, &d.ts)),
    ("multiplicative/pose", |d| poses(&d.multiplicative, &d.ts)),
    ("additive/psi", |d| psis(&d.additive, &d.ts)),
    ("multiplicative/psi", |d| psis(&d.multiplicative, &d.ts)),
];

fn cubic_motions(c: &mut Criterion) {
    interleaved::group(c, "cubic_motion", &KERNELS, &data(), N);
}

/// Times every kernel back to back in each round and reports the median time per evaluation and
/// the median per-round ratios multiplicative / additive.
fn interleaved_report(rounds: usize) {
    let times = interleaved::times(&KERNELS, &data(), rounds, N);
    println!("\ninterleaved ({rounds} rounds, median per evaluation, f64, cubic, {N} parameter values):");
    interleaved::print_medians(&KERNELS, &times);
    for (what, a, m) in [("pose", 0, 1), ("psi", 2, 3)] {
        println!("  {what}: multiplicative / additive = {:.2}", interleaved::ratio(&times, m, a));
    }
    println!("  additive: psi / pose = {:.2}", interleaved::ratio(&times, 2, 0));
    println!("  multiplicative: psi / pose = {:.2}", interleaved::ratio(&times, 3, 1));
}

fn config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(3))
        .sample_size(30)
}

criterion_group! {
    name = benches;
    config = config();
    targets = cubic_motions
}

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // `cargo bench` passes `--bench`; run as a test (`cargo test --benches`) skip the report.
    if std::env::args().any(|a| a == "--bench") {
        interleaved_report(2000);
    } else {
        // Sanity when run as a test: both kinds interpolate the end poses.
        let d = data();
        let end = control_poses().pop().unwrap();
        assert!(d.additive.pose(&1.0).unwrap().is_equivalent(&end, &1e-12).unwrap());
        assert!(d.multiplicative.pose(&1.0).unwrap().is_equivalent(&end, &1e-12).unwrap());
    }
}

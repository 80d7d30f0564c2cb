//! A body point's trajectory under Jüttler's rational motions and the main paper's additive
//! Bézier motion, per sample, in one process: evaluating the rational Bézier form
//! (`RationalBezier::point`, de Casteljau) against transforming the point through the sampled
//! motion (`Motion::pose` + `Pose::transform_point`, the peer), on 256 parameters, for
//!
//! * `q-motion`: Algorithm 1's degree-8 Q-motion through 5 positions (trajectory degree 16),
//!   plus `Q(t)` + Jüttler's point image (12) without the pose map;
//! * `spline`: Algorithm 2's C1 spline Q-motion through the same positions (4 segments of
//!   degree 6, trajectories of degree 12 per segment);
//! * `additive`: the main paper's additive cubic Bézier motion (trajectory degree 6).
//!
//! Interleaved kernels (the benches' shared `interleaved` module): criterion groups, then every
//! kernel back to back per round, medians of per-round ratios to the peer (robust to the load
//! of a shared machine). docs/performance.md has the numbers.
//!
//! Run with `cargo bench -p motion --bench juttler -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

use criterion::{Criterion, criterion_group};
use motion::juttler::spline::algorithm2;
use motion::juttler::tr::algorithm1;
use motion::juttler::{QMotion, RationalBezier, RationalMotion, SplineQMotion};
use motion::{AdditiveBezier, Motion, Pose};
use std::hint::black_box;

mod interleaved;

const N: usize = 256;
const X: [f64; 3] = [0.3, -1.0, 2.0];
const PARAMS: [f64; 5] = [0.0, 0.2, 0.45, 0.7, 1.0];

/// 5 generic positions.
fn poses() -> Vec<Pose<f64>> {
    (0..5)
        .map(|i| {
            let x = i as f64;
            let axis = [0.2 + x, 1.0 - 0.3 * x, 0.5 * x * x - 1.0];
            Pose::from_axis_angle_translation(&axis, &(0.7 * x - 1.1), &[x, 2.0 - x * x, 0.4 * x]).unwrap()
        })
        .collect()
}

/// The motions, the trajectories of `X`, and the parameters.
struct Data {
    q: QMotion<f64>,
    q_path: RationalBezier<f64>,
    spline: SplineQMotion<f64>,
    spline_paths: Vec<RationalBezier<f64>>,
    additive: AdditiveBezier<f64>,
    additive_path: RationalBezier<f64>,
    ts: Vec<f64>,
}

fn data() -> Data {
    let p = poses();
    let q = algorithm1(&p, &PARAMS).unwrap();
    let spline = algorithm2(&p, &PARAMS, None).unwrap();
    let additive = AdditiveBezier::new(p[..4].to_vec()).unwrap();
    Data {
        q_path: q.trajectory(&X),
        spline_paths: spline.segments().iter().map(|s| s.trajectory(&X)).collect(),
        additive_path: additive.rational_trajectory(&X).unwrap(),
        q,
        spline,
        additive,
        ts: (0..N).map(|i| i as f64 / (N - 1) as f64).collect(),
    }
}

/// The peer: pose at every parameter, then the point's image.
fn sampled<M: Motion<f64>>(m: &M, ts: &[f64]) -> f64 {
    ts.iter().map(|t| m.pose(black_box(t)).unwrap().transform_point(&X).unwrap()[0]).sum()
}

/// The rational Bézier form at every parameter.
fn rational(path: &RationalBezier<f64>, ts: &[f64]) -> f64 {
    ts.iter().map(|t| path.point(black_box(t)).unwrap()[0]).sum()
}

type Kernels = [(&'static str, interleaved::Kernel<Data>); 2];

const Q_MOTION: [(&str, interleaved::Kernel<Data>); 3] = [
    ("pose + transform_point", |d| sampled(&d.q, &d.ts)),
    ("rational Bézier point", |d| rational(&d.q_path, &d.ts)),
    ("Q(t) + point_image (12)", |d| {
        d.ts.iter()
            .map(|t| {
                let y = motion::repr::dual_quaternion::point_image(&d.q.eval(black_box(t)), &[1.0, X[0], X[1], X[2]]);
                y[1] / y[0]
            })
            .sum()
    }),
];

const SPLINE: Kernels = [
    ("pose + transform_point", |d| sampled(&d.spline, &d.ts)),
    ("rational Bézier point", |d| {
        d.ts.iter()
            .map(|t| {
                let (i, u) = d.spline.local(black_box(t));
                d.spline_paths[i].point(&u).unwrap()[0]
            })
            .sum()
    }),
];

const ADDITIVE: Kernels = [
    ("pose + transform_point", |d| sampled(&d.additive, &d.ts)),
    ("rational Bézier point", |d| rational(&d.additive_path, &d.ts)),
];

fn bench(c: &mut Criterion) {
    let d = data();
    interleaved::group(c, "trajectory/q-motion", &Q_MOTION, &d, N);
    interleaved::group(c, "trajectory/spline", &SPLINE, &d, N);
    interleaved::group(c, "trajectory/additive", &ADDITIVE, &d, N);
}

/// Every kernel of a motion back to back per round; medians per sample and of the per-round
/// ratios to the peer (kernel 0).
fn interleaved_report(rounds: usize) {
    let d = data();
    println!("\ninterleaved ({rounds} rounds, median per sample):");
    let report = |name: &str, kernels: &[(&str, interleaved::Kernel<Data>)]| {
        let times = interleaved::times(kernels, &d, rounds, N);
        println!(" {name}:");
        interleaved::print_medians(kernels, &times);
        for (i, (k, _)) in kernels.iter().enumerate().skip(1) {
            println!("  ratio {k} / peer = {:.2}", interleaved::ratio(&times, i, 0));
        }
    };
    report("q-motion (trajectory degree 16)", &Q_MOTION);
    report("spline (4 segments, trajectory degree 12)", &SPLINE);
    report("additive cubic (trajectory degree 6)", &ADDITIVE);
}

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // `cargo bench` passes `--bench`; as a test (`cargo test --benches`) only check the paths agree.
    if std::env::args().any(|a| a == "--bench") {
        interleaved_report(300);
    } else {
        let d = data();
        for kernels in [&Q_MOTION[..2], &SPLINE, &ADDITIVE] {
            let (a, b) = (kernels[0].1(&d), kernels[1].1(&d));
            assert!((a - b).abs() < 1e-9 * a.abs().max(1.0), "{} vs {}", a, b);
        }
    }
}

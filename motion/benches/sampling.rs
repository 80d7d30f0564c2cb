//! Sampling a 5-segment C1 motion per sample: the pose, the twist and one body point's
//! acceleration, for the additive and the multiplicative kind, by two paths measured in the
//! same process:
//!
//! * `sample`: [`Trajectory::sample`] (one second-order dual-number evaluation gives the pose,
//!   the space and body twists, the twist rate and the body point's position, velocity and
//!   acceleration);
//! * `velocity+kinematics`: the path before the trajectory sampler, [`velocity`] (pose and
//!   twist, first order) plus [`body_point_kinematics`] (second order) on the same piecewise
//!   motion.
//!
//! The motion: six key poses (screws about tilted axes) at times 0, 1, 2.5, 3.5, 5, 6, cubic
//! segments, Catmull-Rom velocities; 100 samples per iteration.
//!
//! Run with `cargo bench -p motion --bench sampling -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

use criterion::{Criterion, criterion_group};
use motion::trajectory::{Trajectory, Velocities};
use motion::velocity::{body_point_kinematics, velocity};
use motion::{HermiteShapes, Pose, SegmentKind};
use std::hint::black_box;

mod interleaved;

const SAMPLES: usize = 100;
const TOOL: [f64; 3] = [0.1, 0.0, 0.3];

fn trajectory(kind: SegmentKind) -> Trajectory<f64> {
    let screw = |axis: [f64; 3], angle: f64, t: [f64; 3]| Pose::from_axis_angle_translation(&axis, &angle, &t).unwrap();
    let poses = [
        Pose::identity(),
        screw([0.3, 0.4, 0.87], 0.5, [1.0, 0.5, 0.2]),
        screw([0.1, 1.0, 0.2], 1.2, [2.0, 1.5, -0.5]),
        screw([0.0, 0.3, 1.0], 2.0, [3.0, 1.0, 1.0]),
        screw([1.0, 0.2, 0.1], 1.0, [3.5, 0.0, 2.0]),
        screw([0.2, 0.2, 1.0], 0.4, [4.0, -1.0, 2.5]),
    ];
    let times = [0.0, 1.0, 2.5, 3.5, 5.0, 6.0];
    Trajectory::through(&poses, &times, &Velocities::CatmullRom, kind, &HermiteShapes::unit()).unwrap()
}

fn ts() -> Vec<f64> {
    (0..SAMPLES).map(|i| 6.0 * i as f64 / (SAMPLES - 1) as f64).collect()
}

/// The sampler path over all sample times.
fn by_sampler(tr: &Trajectory<f64>, ts: &[f64]) -> f64 {
    ts.iter()
        .map(|t| {
            let s = tr.sample(black_box(t), &[TOOL]).unwrap();
            s.pose.scalar + s.space_twist.angular.x + s.points[0].acceleration[0]
        })
        .sum()
}

/// The velocity + body_point_kinematics path over all sample times.
fn by_kinematics(tr: &Trajectory<f64>, ts: &[f64]) -> f64 {
    ts.iter()
        .map(|t| {
            let v = velocity(tr.motion(), black_box(t)).unwrap();
            let k = body_point_kinematics(tr.motion(), black_box(t), &TOOL).unwrap();
            v.pose.scalar + v.twist().angular.x + k.acceleration[0]
        })
        .sum()
}

fn bench(c: &mut Criterion) {
    for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
        interleaved::group(c, &format!("sampling/{kind}"), &KERNELS, &(trajectory(kind), ts()), SAMPLES);
    }
}

/// What both paths sample: the trajectory and the sample times.
type Data = (Trajectory<f64>, Vec<f64>);

/// The two paths as interleaved kernels, sampler first.
const KERNELS: [(&str, interleaved::Kernel<Data>); 2] =
    [("sample", |d| by_sampler(&d.0, &d.1)), ("velocity+kinematics", |d| by_kinematics(&d.0, &d.1))];

/// Both paths back to back in every round (rotating order), median of the per-round ratios:
/// robust to the load changing between criterion groups on a shared machine.
fn interleaved_report(rounds: usize) {
    println!("\ninterleaved ({rounds} rounds, median per sample):");
    for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
        let times = interleaved::times(&KERNELS, &(trajectory(kind), ts()), rounds, SAMPLES);
        println!(" {kind}:");
        interleaved::print_medians(&KERNELS, &times);
        println!("  ratio (velocity+kinematics) / sample = {:.2}", interleaved::ratio(&times, 1, 0));
    }
}

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
    // `cargo bench` passes `--bench`; as a test (`cargo test --benches`) only check the paths agree.
    if std::env::args().any(|a| a == "--bench") {
        interleaved_report(300);
    } else {
        let tr = trajectory(SegmentKind::Multiplicative);
        let (s, k) = (tr.sample(&1.7, &[TOOL]).unwrap(), body_point_kinematics(tr.motion(), &1.7, &TOOL).unwrap());
        assert!((0..3).all(|i| (s.points[0].acceleration[i] - k.acceleration[i]).abs() < 1e-9));
    }
}

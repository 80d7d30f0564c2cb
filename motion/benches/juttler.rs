//! A body point's trajectory under a Q-motion (Jüttler), per sample, in one process:
//! evaluating the rational Bézier form (`RationalBezier::point`, degree 16 for Algorithm 1's
//! degree-8 motion through 5 positions) against transforming the point through the sampled
//! motion (`Motion::pose` + `Pose::transform_point`, the peer), on 256 parameters.
//!
//! The ratios in docs/performance.md are of criterion's medians, all measured in this one
//! process.
//!
//! Run with `cargo bench -p motion --bench juttler -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

use criterion::{Criterion, criterion_group};
use motion::juttler::tr::algorithm1;
use motion::juttler::{QMotion, RationalBezier};
use motion::{Motion, Pose};
use std::hint::black_box;

const N: usize = 256;
const X: [f64; 3] = [0.3, -1.0, 2.0];

/// Algorithm 1 through 5 generic positions at uneven parameters: degree 8.
fn motion() -> QMotion<f64> {
    let p: Vec<Pose<f64>> = (0..5)
        .map(|i| {
            let x = i as f64;
            let axis = [0.2 + x, 1.0 - 0.3 * x, 0.5 * x * x - 1.0];
            Pose::from_axis_angle_translation(&axis, &(0.7 * x - 1.1), &[x, 2.0 - x * x, 0.4 * x]).unwrap()
        })
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

criterion_group!(benches, bench);

fn main() {
    benches();
    Criterion::default().configure_from_args().final_summary();
}

//! The branch-free pose exp and log ([`motion::branch_free`]) over lane scalars against the
//! `Real` versions over the scalar, per element, in one process: `Pose::exp` / `Pose::log` on
//! 1024 f64 (and f32) elements against `Pose::exp_branch_free` / `Pose::log_branch_free` on the
//! same elements packed into `F64x4` (and `F32x8`). The branch-free forms compute every case
//! (series and closed form) per lane, so the lanes must pay for that first.
//!
//! After the criterion group, `cargo bench` prints per-element medians measured interleaved
//! and the ratios to the scalar version.
//!
//! Run with `cargo bench -p motion --bench branch_free -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

mod interleaved;

use algebra_core::scalar::{F32x8, F64x4};
use criterion::Criterion;
use motion::{Even, Pose};
use std::hint::black_box;

const N: usize = 1024;

struct Data {
    g64: Vec<Even<f64>>,
    g32: Vec<Even<f32>>,
    g64x4: Vec<Even<F64x4>>,
    g32x8: Vec<Even<F32x8>>,
    p64: Vec<Pose<f64>>,
    p32: Vec<Pose<f32>>,
    p64x4: Vec<Pose<F64x4>>,
    p32x8: Vec<Pose<F32x8>>,
}

/// Generators with half-angles in [0, 3) and translations in [-1, 1]: both the series and the
/// closed-form branches of the scalar versions are taken.
fn components() -> Vec<[f64; 8]> {
    (0..N)
        .map(|i| {
            let x = i as f64 / N as f64;
            let a = 3.0 * x;
            [0.0, a * 0.6, -a * 0.8 * (7.0 * x).cos(), a * 0.8 * (7.0 * x).sin(), 1.0 - 2.0 * x, 0.5 - x, 0.3, 0.0]
        })
        .collect()
}

fn pose<T: algebra_core::Ring>(c: [T; 8]) -> Pose<T> {
    let [s, b12, b13, b23, b1, b2, b3, w] = c;
    Pose::new(s, b12, b13, b23, b1, b2, b3, w)
}

fn pack<L: algebra_core::Ring, const W: usize>(v: &[[f64; 8]], lane: impl Fn([f64; W]) -> L) -> Vec<Pose<L>> {
    v.chunks(W).map(|c| pose(std::array::from_fn(|k| lane(std::array::from_fn(|i| c[i][k]))))).collect()
}

fn data() -> Data {
    let g = components();
    let p: Vec<[f64; 8]> = g.iter().map(|c| Pose::exp(&pose(*c)).unwrap().components().map(|x| *x)).collect();
    Data {
        g64: g.iter().map(|c| pose(*c)).collect(),
        g32: g.iter().map(|c| pose(c.map(|x| x as f32))).collect(),
        g64x4: pack(&g, F64x4::from),
        g32x8: pack(&g, |a: [f64; 8]| F32x8::from(a.map(|x| x as f32))),
        p64: p.iter().map(|c| pose(*c)).collect(),
        p32: p.iter().map(|c| pose(c.map(|x| x as f32))).collect(),
        p64x4: pack(&p, F64x4::from),
        p32x8: pack(&p, |a: [f64; 8]| F32x8::from(a.map(|x| x as f32))),
    }
}

macro_rules! kernels {
    ($($name:ident: $field:ident => |$x:ident| $body:expr;)*) => {
        $(fn $name(d: &Data) -> f64 {
            for $x in &d.$field {
                black_box($body.ok());
            }
            0.0
        })*
    };
}
kernels! {
    exp_f64: g64 => |g| Pose::exp(black_box(g));
    exp_f64x4: g64x4 => |g| Pose::exp_branch_free(black_box(g));
    log_f64: p64 => |p| black_box(p).log();
    log_f64x4: p64x4 => |p| black_box(p).log_branch_free();
    exp_f32: g32 => |g| Pose::exp(black_box(g));
    exp_f32x8: g32x8 => |g| Pose::exp_branch_free(black_box(g));
    log_f32: p32 => |p| black_box(p).log();
    log_f32x8: p32x8 => |p| black_box(p).log_branch_free();
}

/// A scalar kernel and its lane counterpart.
type Pair = [(&'static str, interleaved::Kernel<Data>); 2];

const GROUPS: [(&str, Pair); 4] = [
    ("exp f64", [("Pose<f64>::exp", exp_f64), ("Pose<F64x4>::exp_branch_free", exp_f64x4)]),
    ("log f64", [("Pose<f64>::log", log_f64), ("Pose<F64x4>::log_branch_free", log_f64x4)]),
    ("exp f32", [("Pose<f32>::exp", exp_f32), ("Pose<F32x8>::exp_branch_free", exp_f32x8)]),
    ("log f32", [("Pose<f32>::log", log_f32), ("Pose<F32x8>::log_branch_free", log_f32x8)]),
];

fn main() {
    let d = data();
    let mut c = Criterion::default().configure_from_args();
    for (name, kernels) in &GROUPS {
        interleaved::group(&mut c, name, kernels, &d, N);
    }
    c.final_summary();
    // `cargo bench` passes `--bench`; skip the report when the bench is run as a test.
    if std::env::args().any(|a| a == "--bench") {
        for (name, kernels) in &GROUPS {
            let t = interleaved::times(kernels, &d, 400, N);
            println!("\ninterleaved (400 rounds, per element): {name}");
            interleaved::print_medians(kernels, &t);
            println!("  lanes / scalar: {:.3}", interleaved::ratio(&t, 1, 0));
        }
    }
}

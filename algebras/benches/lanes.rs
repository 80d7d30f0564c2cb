//! Lane scalars through the generated kernels: the g123inf `Motor * Motor` (48 mul, 40 add,
//! straight-line code) over `F32x4`/`F32x8` against the scalar `f32` kernel, and over
//! `F64x2`/`F64x4` against the scalar `f64` kernel, **per element** (a lane product computes
//! 4 or 8 element products). The generated types take a lane scalar as they are: no generator
//! change.
//!
//! The kernels are timed interleaved (every kernel back to back in each round, rotating order;
//! the shared loop of the motion benches) and the report gives the median time per element and
//! the median of the per-round ratios to the scalar kernel of the same element type. Targets
//! (issue 14): f32 lanes ≤ 0.25x scalar f32, `F64x4` ≤ 0.5x scalar f64.
//!
//! ```text
//! cargo bench -p gam-algebras --bench lanes -- --warm-up-time 1 --measurement-time 3
//! RUSTFLAGS="-C target-cpu=native" CARGO_TARGET_DIR=target/native \
//!     cargo bench -p gam-algebras --bench lanes -- --warm-up-time 1 --measurement-time 3
//! ```
#![allow(missing_docs)]

#[path = "../../motion/benches/interleaved/mod.rs"]
#[allow(dead_code)]
mod interleaved;

use algebra_core::scalar::{F32x4, F32x8, F64x2, F64x4};
use algebra_core::test_support::Xorshift;
use criterion::Criterion;
use gam_algebras::g123inf::Motor;
use interleaved::{Kernel, median, ratio, times};
use std::hint::black_box;
use std::time::Duration;

/// Element products per kernel call.
const BATCH: usize = 1024;

/// The operands: `2 * BATCH` elements, as scalars and packed into lanes (element `i` pairs with
/// element `BATCH + i`; lane vectors pack consecutive elements).
struct Data {
    f32s: Vec<Motor<f32>>,
    f32x4: Vec<Motor<F32x4>>,
    f32x8: Vec<Motor<F32x8>>,
    f64s: Vec<Motor<f64>>,
    f64x2: Vec<Motor<F64x2>>,
    f64x4: Vec<Motor<F64x4>>,
}

/// `n` motors' coefficients in [-1, 1), from the workspace's test generator.
fn values(n: usize) -> Vec<[f64; 8]> {
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    (0..n).map(|_| std::array::from_fn(|_| rng.symmetric())).collect()
}

/// Packs consecutive groups of `N` elements into lane motors.
fn pack<L: algebra_core::Ring, const N: usize>(v: &[[f64; 8]], lane: impl Fn([f64; N]) -> L) -> Vec<Motor<L>> {
    v.chunks(N).map(|c| Motor::from_array(std::array::from_fn(|k| lane(std::array::from_fn(|i| c[i][k]))))).collect()
}

fn data() -> Data {
    let v = values(2 * BATCH);
    Data {
        f32s: v.iter().map(|c| Motor::from_array(c.map(|x| x as f32))).collect(),
        f32x4: pack(&v, |a: [f64; 4]| F32x4::from(a.map(|x| x as f32))),
        f32x8: pack(&v, |a: [f64; 8]| F32x8::from(a.map(|x| x as f32))),
        f64s: v.iter().map(|c| Motor::from_array(*c)).collect(),
        f64x2: pack(&v, F64x2::from),
        f64x4: pack(&v, F64x4::from),
    }
}

/// `x[i] * x[half + i]` for every pair.
fn products<T: algebra_core::Ring>(m: &[Motor<T>]) -> f64 {
    let (xs, ys) = m.split_at(m.len() / 2);
    for (x, y) in xs.iter().zip(ys) {
        black_box(black_box(x) * black_box(y));
    }
    0.0
}

macro_rules! kernel {
    ($name:ident, $field:ident) => {
        fn $name(d: &Data) -> f64 {
            products(&d.$field)
        }
    };
}
kernel!(scalar_f32, f32s);
kernel!(lanes_f32x4, f32x4);
kernel!(lanes_f32x8, f32x8);
kernel!(scalar_f64, f64s);
kernel!(lanes_f64x2, f64x2);
kernel!(lanes_f64x4, f64x4);

const F32_KERNELS: [(&str, Kernel<Data>); 3] = [
    ("Motor<f32> * Motor<f32>", scalar_f32),
    ("Motor<F32x4> * Motor<F32x4>", lanes_f32x4),
    ("Motor<F32x8> * Motor<F32x8>", lanes_f32x8),
];
const F64_KERNELS: [(&str, Kernel<Data>); 3] = [
    ("Motor<f64> * Motor<f64>", scalar_f64),
    ("Motor<F64x2> * Motor<F64x2>", lanes_f64x2),
    ("Motor<F64x4> * Motor<F64x4>", lanes_f64x4),
];

fn report(title: &str, kernels: &[(&str, Kernel<Data>)], d: &Data) {
    let t = times(kernels, d, 4000, BATCH);
    println!("\ninterleaved (4000 rounds, per element): {title}");
    println!("  {:<32} {:>10} {:>18}", "kernel", "ns/element", "ratio to scalar");
    for (i, (name, _)) in kernels.iter().enumerate() {
        println!("  {name:<32} {:>10.3} {:>18.3}", median(t[i].clone()) * 1e9, ratio(&t, i, 0));
    }
}

fn main() {
    let d = data();
    // the lane products are the scalar products, lane by lane
    let (x, y) = (&d.f64x4[0], &d.f64x4[BATCH / 4]);
    let (xs, ys) = (&d.f64s[0..4], &d.f64s[BATCH..BATCH + 4]);
    let p = (x * y).to_array();
    for i in 0..4 {
        assert_eq!(p.map(|l| l.lane(i)), (xs[i] * ys[i]).to_array());
    }
    let mut c = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3))
        .configure_from_args();
    interleaved::group(&mut c, "motor_product_f32_per_element", &F32_KERNELS, &d, BATCH);
    interleaved::group(&mut c, "motor_product_f64_per_element", &F64_KERNELS, &d, BATCH);
    c.final_summary();
    // `cargo bench` passes `--bench`; skip the report when the bench is run as a test.
    if std::env::args().any(|a| a == "--bench") {
        report("g123inf motor product, f32 lanes vs scalar f32", &F32_KERNELS, &d);
        report("g123inf motor product, f64 lanes vs scalar f64", &F64_KERNELS, &d);
    }
}

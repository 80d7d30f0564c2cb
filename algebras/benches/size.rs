//! The size policy's threshold measured: the `cga` (R^{4,1}) kernels of 65-256 terms emitted
//! as a table loop and as straight-line code, against the g123inf motor product, interleaved in
//! one process (every kernel back to back in each round, rotating order; the shared loop of the
//! motion benches). The same `cga` module is declared here three times with `table_above 64;`,
//! `128;` and `256;` (the DSL option), so every form runs in the same process on the same
//! inputs.
//!
//! | kernel | terms |
//! |---|---|
//! | `Vector * Motor` (output `Odd`) | 80 |
//! | `Bivector * Motor` | 160 |
//! | `Motor::sandwich(&Vector)` (two stages) | 160 |
//! | `Motor * Motor` | 256 |
//!
//! ```text
//! cargo bench -p gam-algebras --bench size -- --warm-up-time 1 --measurement-time 3
//! ```
//! (`target/release/deps/size-* --bench zzz` runs only the interleaved report.)
#![allow(missing_docs)]

#[path = "../../motion/benches/interleaved/mod.rs"]
#[allow(dead_code)]
mod interleaved;

use algebra_core::test_support::Xorshift;
use criterion::Criterion;
use interleaved::{Kernel, median, ratio, times};
use std::hint::black_box;
use std::time::Duration;

/// Elements per kernel call.
const BATCH: usize = 256;

/// The `cga` module of `gam_algebras` (without `Multivector = all`, which the kernels
/// measured here do not use) at one threshold.
macro_rules! cga_at {
    ($name:ident, $t:literal) => {
        algebra_macros::algebra! {
            pub mod $name {
                metric builtin "cga";
                table_above $t;
                types { Vector = grade 1; Bivector = grade 2; Motor = even; }
            }
        }
    };
}
cga_at!(t64, 64);
cga_at!(t128, 128);
cga_at!(t256, 256);

/// Random coefficients: motors, bivectors and vectors (same layout in every module).
struct Data {
    g123inf: Vec<gam_algebras::g123inf::Motor<f64>>,
    motors: Vec<[f64; 16]>,
    bivectors: Vec<[f64; 10]>,
    vectors: Vec<[f64; 5]>,
}

fn data() -> Data {
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    let mut draw = || rng.symmetric();
    Data {
        g123inf: (0..2 * BATCH)
            .map(|_| gam_algebras::g123inf::Motor::from_array(std::array::from_fn(|_| draw())))
            .collect(),
        motors: (0..2 * BATCH).map(|_| std::array::from_fn(|_| draw())).collect(),
        bivectors: (0..BATCH).map(|_| std::array::from_fn(|_| draw())).collect(),
        vectors: (0..BATCH).map(|_| std::array::from_fn(|_| draw())).collect(),
    }
}

fn g123inf_motor(d: &Data) -> f64 {
    let (xs, ys) = d.g123inf.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys) {
        black_box(black_box(x) * black_box(y));
    }
    0.0
}

/// The four kernels of one module, as functions of the shared data (converted to the
/// module's types once, outside the timed loops).
macro_rules! kernels {
    ($k:ident, $m:ident) => {
        mod $k {
            use super::*;
            use $m::{Bivector, Motor, Vector};
            struct Inputs {
                motors: Vec<Motor<f64>>,
                bivectors: Vec<Bivector<f64>>,
                vectors: Vec<Vector<f64>>,
            }
            static INPUTS: std::sync::OnceLock<Inputs> = std::sync::OnceLock::new();
            fn inputs(d: &Data) -> &'static Inputs {
                INPUTS.get_or_init(|| Inputs {
                    motors: d.motors.iter().map(|c| Motor::from_array(*c)).collect(),
                    bivectors: d.bivectors.iter().map(|c| Bivector::from_array(*c)).collect(),
                    vectors: d.vectors.iter().map(|c| Vector::from_array(*c)).collect(),
                })
            }
            pub fn motor_motor(d: &Data) -> f64 {
                let (xs, ys) = inputs(d).motors.split_at(BATCH);
                for (x, y) in xs.iter().zip(ys) {
                    black_box(black_box(x) * black_box(y));
                }
                0.0
            }
            pub fn sandwich_vector(d: &Data) -> f64 {
                let i = inputs(d);
                for (m, v) in i.motors.iter().zip(&i.vectors) {
                    black_box(black_box(m).sandwich(black_box(v)));
                }
                0.0
            }
            pub fn bivector_motor(d: &Data) -> f64 {
                let i = inputs(d);
                for (b, m) in i.bivectors.iter().zip(&i.motors) {
                    black_box(black_box(b) * black_box(m));
                }
                0.0
            }
            pub fn vector_motor(d: &Data) -> f64 {
                let i = inputs(d);
                for (v, m) in i.vectors.iter().zip(&i.motors) {
                    black_box(black_box(v) * black_box(m));
                }
                0.0
            }
        }
    };
}
kernels!(k64, t64);
kernels!(k128, t128);
kernels!(k256, t256);

const KERNELS: [(&str, Kernel<Data>); 13] = [
    ("g123inf Motor * Motor", g123inf_motor),
    ("cga Vector * Motor (80), 64", k64::vector_motor),
    ("cga Vector * Motor (80), 128", k128::vector_motor),
    ("cga Vector * Motor (80), 256", k256::vector_motor),
    ("cga Bivector * Motor (160), 64", k64::bivector_motor),
    ("cga Bivector * Motor (160), 128", k128::bivector_motor),
    ("cga Bivector * Motor (160), 256", k256::bivector_motor),
    ("cga Motor.sandwich(Vector) (160), 64", k64::sandwich_vector),
    ("cga Motor.sandwich(Vector) (160), 128", k128::sandwich_vector),
    ("cga Motor.sandwich(Vector) (160), 256", k256::sandwich_vector),
    ("cga Motor * Motor (256), 64", k64::motor_motor),
    ("cga Motor * Motor (256), 128", k128::motor_motor),
    ("cga Motor * Motor (256), 256", k256::motor_motor),
];

fn main() {
    let d = data();
    let short = Criterion::default().warm_up_time(Duration::from_secs(1)).measurement_time(Duration::from_secs(3));
    let mut c = short.configure_from_args();
    interleaved::group(&mut c, "size_policy_per_element", &KERNELS, &d, BATCH);
    c.final_summary();
    // only under `cargo bench` (which passes `--bench`), not when the bench runs as a test
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let rounds = 2000;
    let t = times(&KERNELS, &d, rounds, BATCH);
    println!("\ninterleaved ({rounds} rounds): cga kernels at thresholds 64 / 128 / 256 (f64)");
    println!(
        "  {:<40} {:>12} {:>16} {:>14}",
        "kernel (terms), table_above", "ns/element", "ratio to g123inf", "ratio to 64"
    );
    for (i, (name, _)) in KERNELS.iter().enumerate() {
        // the same kernel at threshold 64: the first of its group of three
        let base = if i == 0 { 0 } else { 1 + 3 * ((i - 1) / 3) };
        let ns = median(t[i].clone()) * 1e9;
        println!("  {name:<40} {ns:>12.2} {:>16.3} {:>14.3}", ratio(&t, i, 0), ratio(&t, i, base));
    }
}

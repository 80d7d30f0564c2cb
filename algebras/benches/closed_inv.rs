//! The invariant-decomposition closed forms (`algebra_codegen::closed_inv`) on a user-declared
//! CGA `R^{4,1}` (`tests/user/cga41.rs`: 10-coefficient `Bivector`, 16-coefficient `Motor`),
//! against the module's own 16x16 `Motor * Motor` product and the runtime series
//! (`Multivector::exp` / `log`, the only route before), measured interleaved in one process
//! (every kernel back to back in each round, rotating order; the motion benches' loop).
//!
//! ```text
//! cargo bench -p gam-algebras --bench closed_inv
//! ```
#![allow(missing_docs)]

#[path = "../../motion/benches/interleaved/mod.rs"]
#[allow(dead_code)]
mod interleaved;

#[path = "../tests/user/cga41.rs"]
mod user_cga41;

use algebra_core::test_support::Xorshift;
use interleaved::{Kernel, report_vs_first};
use std::hint::black_box;
use user_cga41::cga41::{Bivector, Motor};

/// Elements per kernel call.
const BATCH: usize = 256;
/// Elements per call of the runtime series (slow).
const SERIES: usize = 8;

struct Data {
    motors: Vec<Motor<f64>>,
    bivectors: Vec<Bivector<f64>>,
    units: Vec<Motor<f64>>,
}

fn data() -> Data {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    let mut draw = || rng.symmetric();
    let motors = (0..2 * BATCH).map(|_| Motor::from_array(std::array::from_fn(|_| draw()))).collect();
    // rotations, boosts (e_i5, e45), translations and transversions mixed, coefficients in [-1, 1]
    let bivectors: Vec<Bivector<f64>> =
        (0..BATCH).map(|_| Bivector::from_array(std::array::from_fn(|_| draw()))).collect();
    let units = bivectors.iter().map(Bivector::exp).collect();
    Data { motors, bivectors, units }
}

fn motor_product(d: &Data, n: usize) {
    let (xs, ys) = d.motors.split_at(BATCH);
    for (x, y) in xs[..n].iter().zip(ys) {
        black_box(black_box(x) * black_box(y));
    }
}

fn product(d: &Data) -> f64 {
    motor_product(d, BATCH);
    0.0
}

fn product_few(d: &Data) -> f64 {
    motor_product(d, SERIES);
    0.0
}

fn exp(d: &Data) -> f64 {
    for b in &d.bivectors {
        black_box(black_box(b).exp());
    }
    0.0
}

fn log_unit(d: &Data) -> f64 {
    for m in &d.units {
        black_box(black_box(m).log_unit().ok());
    }
    0.0
}

fn exp_series(d: &Data) -> f64 {
    for b in &d.bivectors[..SERIES] {
        black_box(black_box(b).to_multivector().exp().ok());
    }
    0.0
}

fn log_series(d: &Data) -> f64 {
    for m in &d.units[..SERIES] {
        black_box(black_box(m).to_multivector().log().ok());
    }
    0.0
}

fn main() {
    // `cargo bench` passes `--bench`; skip the report when the bench is run as a test.
    if !std::env::args().any(|a| a == "--bench") {
        return;
    }
    let d = data();
    let closed: [(&str, Kernel<Data>); 3] =
        [("cga41 Motor * Motor", product), ("cga41 Bivector::exp", exp), ("cga41 Motor::log_unit", log_unit)];
    report_vs_first(
        "invariant decomposition vs the R^{4,1} motor product (f64)",
        "motor product",
        &closed,
        &d,
        2000,
        BATCH,
    );
    let series: [(&str, Kernel<Data>); 3] =
        [("cga41 Motor * Motor", product_few), ("runtime series exp", exp_series), ("runtime series log", log_series)];
    report_vs_first("runtime series vs the motor product (f64)", "motor product", &series, &d, 100, SERIES);
}

//! Closed-form exp and log emitted by the generator (`algebra_codegen::closed`) against the
//! generated motor product and the runtime series, measured interleaved in one process (every
//! kernel back to back in each round, rotating order; the shared loop of the motion benches).
//! Targets (issue 12): closed-form `exp` <= 2.7x and `log` <= 3.9x the motor product.
//!
//! - `g123inf` (predefined, dual family): `Bivector::exp`, `Motor::log_unit`, `Motor::log`;
//! - a user-declared 2D PGA (scalar family), declared below: `Line::exp`, `Motor::log_unit`;
//! - the runtime series `Multivector::exp` / `log` on the same g123inf inputs (fewer rounds).
//!
//! ```text
//! cargo bench -p gam-algebras --bench closed -- --warm-up-time 1 --measurement-time 3
//! ```
#![allow(missing_docs)]

#[path = "../../motion/benches/interleaved/mod.rs"]
#[allow(dead_code)]
mod interleaved;

use algebra_core::test_support::Xorshift;
use criterion::Criterion;
use gam_algebras::g123inf::{Bivector, Motor};
use interleaved::{Kernel, report_vs_first};
use std::hint::black_box;
use std::time::Duration;

#[path = "../tests/user/pga2.rs"]
mod user_pga2;
use user_pga2::pga2;

/// Elements per kernel call.
const BATCH: usize = 256;
/// Elements per call of the runtime series (slow).
const SERIES: usize = 8;

struct Data {
    motors: Vec<Motor<f64>>,
    bivectors: Vec<Bivector<f64>>,
    units: Vec<Motor<f64>>,
    lines: Vec<pga2::Line<f64>>,
    pga2_units: Vec<pga2::Motor<f64>>,
}

fn data() -> Data {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    let mut draw = || rng.symmetric();
    let motors = (0..2 * BATCH).map(|_| Motor::from_array(std::array::from_fn(|_| draw()))).collect();
    // half-angles up to 1.5 and translations up to 1
    let bivectors: Vec<Bivector<f64>> = (0..BATCH)
        .map(|_| Bivector::from_array(std::array::from_fn(|i| draw() * if i < 3 { 0.85 } else { 1.0 })))
        .collect();
    let units = bivectors.iter().map(Bivector::exp).collect();
    let lines: Vec<pga2::Line<f64>> =
        (0..BATCH).map(|_| pga2::Line::from_array(std::array::from_fn(|_| 1.5 * draw()))).collect();
    let pga2_units = lines.iter().map(pga2::Line::exp).collect();
    Data { motors, bivectors, units, lines, pga2_units }
}

fn motor_product(d: &Data) -> f64 {
    let (xs, ys) = d.motors.split_at(BATCH);
    for (x, y) in xs.iter().zip(ys) {
        black_box(black_box(x) * black_box(y));
    }
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

fn log(d: &Data) -> f64 {
    for m in &d.units {
        black_box(black_box(m).log().ok());
    }
    0.0
}

fn pga2_exp(d: &Data) -> f64 {
    for b in &d.lines {
        black_box(black_box(b).exp());
    }
    0.0
}

fn pga2_log_unit(d: &Data) -> f64 {
    for m in &d.pga2_units {
        black_box(black_box(m).log_unit().ok());
    }
    0.0
}

fn motor_product_few(d: &Data) -> f64 {
    let (xs, ys) = d.motors.split_at(BATCH);
    for (x, y) in xs[..SERIES].iter().zip(ys) {
        black_box(black_box(x) * black_box(y));
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

const KERNELS: [(&str, Kernel<Data>); 6] = [
    ("g123inf Motor * Motor", motor_product),
    ("g123inf Bivector::exp", exp),
    ("g123inf Motor::log_unit", log_unit),
    ("g123inf Motor::log", log),
    ("user pga2 Line::exp", pga2_exp),
    ("user pga2 Motor::log_unit", pga2_log_unit),
];

const SERIES_KERNELS: [(&str, Kernel<Data>); 3] = [
    ("g123inf Motor * Motor", motor_product_few),
    ("runtime series exp", exp_series),
    ("runtime series log", log_series),
];

fn main() {
    let d = data();
    let mut c = Criterion::default()
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(3))
        .configure_from_args();
    interleaved::group(&mut c, "closed_form_per_element", &KERNELS, &d, BATCH);
    c.final_summary();
    // `cargo bench` passes `--bench`; skip the report when the bench is run as a test.
    if std::env::args().any(|a| a == "--bench") {
        report_vs_first("closed forms vs the g123inf motor product (f64)", "motor product", &KERNELS, &d, 4000, BATCH);
        report_vs_first("runtime series vs the motor product (f64)", "motor product", &SERIES_KERNELS, &d, 100, SERIES);
    }
}

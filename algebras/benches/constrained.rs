//! The unit action `sandwich_unit` of types declared `where unit` (the kernel the generator
//! chose: the cheaper of the commutator form and the kernel reduced modulo `rev(S) S = 1`)
//! against the general fused `sandwich` it replaces on unit motors, in one criterion group each
//! (same run):
//!
//! * `cga_null` point action: `Motor::sandwich_unit` on a `Vector` (the commutator form, 36
//!   multiplications; the σ part proven zero) vs the fused `Motor::sandwich` (64, σ dropped),
//!   both `rev(S) x S`, over f64 unit motors;
//! * the same `cga_null` pair over exact rationals (`BigRational`), on exact rational unit
//!   motors `R T` with `R = r r / |r|²`;
//! * `g123inf` pseudoscalar action: `Motor::sandwich_unit` (a copy) vs `Motor::sandwich` (12).
//!
//! Every iteration acts with a batch of pre-generated unit motors on a batch of vectors;
//! throughput is per action. Run with
//! `cargo bench -p gam-algebras --bench constrained -- --warm-up-time 1 --measurement-time 3`.
#![allow(missing_docs)]

use criterion::{Criterion, Throughput, criterion_group, criterion_main};
use gam_algebras::{cga_null, g123inf};
use std::hint::black_box;

/// Actions per criterion iteration.
const BATCH: usize = 1024;

/// Deterministic floats in [-1, 1): the golden-ratio sequence `frac(k φ)`, spread to [-1, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 += 1;
        2.0 * (self.0 as f64 * 0.618_033_988_749_895).fract() - 1.0
    }
}

/// One criterion group timing `unit` and `generic` on the same (motor, operand) pairs.
fn pair<M, X, A, B>(
    c: &mut Criterion,
    title: &str,
    data: (&[M], &[X]),
    unit: fn(&M, &X) -> A,
    generic: fn(&M, &X) -> B,
) {
    let (motors, xs) = data;
    let mut g = c.benchmark_group(title);
    g.throughput(Throughput::Elements(motors.len() as u64));
    g.bench_function("sandwich_unit (chosen kernel)", |b| {
        b.iter(|| motors.iter().zip(xs).for_each(|(m, x)| drop(black_box(unit(black_box(m), black_box(x))))))
    });
    g.bench_function("generic sandwich (fused)", |b| {
        b.iter(|| motors.iter().zip(xs).for_each(|(m, x)| drop(black_box(generic(black_box(m), black_box(x))))))
    });
    g.finish();
}

/// Unit motor coefficients `[1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf]` (the same order
/// in both modules): a unit quaternion rotor `r` times the translator `1 + ½ t einf`.
fn unit_motor(rng: &mut Rng) -> [f64; 8] {
    let r = [rng.next(), rng.next(), rng.next(), rng.next()];
    let n = r.iter().map(|x| x * x).sum::<f64>().sqrt();
    let [w, x, y, z] = r.map(|c| c / n);
    let t = [rng.next() * 0.5, rng.next() * 0.5, rng.next() * 0.5];
    // (w + x e12 + y e13 + z e23)(1 + t1 e1inf + t2 e2inf + t3 e3inf), einf central in the
    // products below up to the signs of the rotor's action on e_i
    let (a, b, c) = (t[0], t[1], t[2]);
    [w, x, y, z, w * a - x * b - y * c, w * b + x * a - z * c, w * c + y * a + z * b, x * c - y * b + z * a]
}

fn cga_null_point_action(c: &mut Criterion) {
    let mut rng = Rng(0x9e37_79b9_7f4a_7c15);
    let motors: Vec<cga_null::Motor<f64>> = (0..BATCH)
        .map(|_| {
            let m = unit_motor(&mut rng);
            cga_null::Motor::new(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7])
        })
        .collect();
    // the samples really are unit motors (the unit kernel is exact only there)
    let rm = motors[0].to_multivector();
    assert!((&rm.reverse() * &rm).coeffs().iter().enumerate().all(|(i, v)| (v - f64::from(i == 0)).abs() < 1e-12));
    let points: Vec<cga_null::Vector<f64>> =
        (0..BATCH).map(|_| cga_null::Vector::new(rng.next(), rng.next(), rng.next(), rng.next(), rng.next())).collect();
    for (m, x) in motors.iter().zip(&points).take(16) {
        let (a, b) = (m.sandwich_unit(x), m.sandwich(x));
        assert!(
            a.to_multivector().coeffs().iter().zip(b.to_multivector().coeffs()).all(|(p, q)| (p - q).abs() < 1e-12)
        );
    }
    pair(
        c,
        "cga_null unit motor on a point (f64)",
        (&motors, &points),
        |m, x| m.sandwich_unit(x),
        cga_null::Motor::sandwich,
    );
}

/// Actions per iteration over exact rationals.
const Q_BATCH: usize = 32;

fn cga_null_point_action_exact(c: &mut Criterion) {
    use algebra_core::Ring;
    use algebra_core::ops::GeometricProduct;
    use algebra_core::rational::{Q, ratio};
    let mut seed = 7i64;
    let mut small = || {
        seed = (seed * 1_103_515_245 + 12_345) % 2_147_483_648;
        ratio(seed % 19 - 9, seed % 5 + 1)
    };
    let zero = Q::zero;
    let motors: Vec<cga_null::Motor<Q>> = (0..Q_BATCH)
        .map(|_| {
            let r = cga_null::Motor::new(
                small() + Q::from_i64(10),
                small(),
                small(),
                small(),
                zero(),
                zero(),
                zero(),
                zero(),
            );
            let n2 =
                r.scalar.clone() * &r.scalar + r.e12.clone() * &r.e12 + r.e13.clone() * &r.e13 + r.e23.clone() * &r.e23;
            let rotor: cga_null::Motor<Q> = r.gp(&r).scale(&(Q::one() / n2));
            let half = ratio(1, 2);
            let t = cga_null::Motor::new(
                Q::one(),
                zero(),
                zero(),
                zero(),
                small() * &half,
                small() * &half,
                small() * &half,
                zero(),
            );
            rotor.gp(&t)
        })
        .collect();
    let points: Vec<cga_null::Vector<Q>> =
        (0..Q_BATCH).map(|_| cga_null::Vector::new(small(), small(), small(), small(), small())).collect();
    for (m, x) in motors.iter().zip(&points) {
        let rm = m.to_multivector();
        assert!((&rm.reverse() * &rm).coeffs().iter().enumerate().all(|(i, v)| *v == Q::from_i64(i64::from(i == 0))));
        assert_eq!(m.sandwich_unit(x), m.sandwich(x));
    }
    pair(
        c,
        "cga_null unit motor on a point (exact rationals)",
        (&motors, &points),
        |m, x| m.sandwich_unit(x),
        cga_null::Motor::sandwich,
    );
}

fn g123inf_pseudoscalar_action(c: &mut Criterion) {
    let mut rng = Rng(0x2545_f491_4f6c_dd1d);
    let motors: Vec<g123inf::Motor<f64>> = (0..BATCH)
        .map(|_| {
            let m = unit_motor(&mut rng);
            g123inf::Motor::new(m[0], m[1], m[2], m[3], m[4], m[5], m[6], m[7])
        })
        .collect();
    let ps: Vec<g123inf::Pseudoscalar<f64>> =
        (0..BATCH).map(|_| g123inf::Pseudoscalar::new(rng.next(), rng.next())).collect();
    for (m, p) in motors.iter().zip(&ps).take(16) {
        let (a, b) = (m.sandwich_unit(p), m.sandwich(p));
        assert!((a.scalar - b.scalar).abs() < 1e-12 && (a.e123inf - b.e123inf).abs() < 1e-12);
    }
    pair(
        c,
        "g123inf unit motor on a pseudoscalar (f64)",
        (&motors, &ps),
        |m, p| m.sandwich_unit(p),
        g123inf::Motor::sandwich,
    );
}

criterion_group!(benches, cga_null_point_action, cga_null_point_action_exact, g123inf_pseudoscalar_action);
criterion_main!(benches);

//! The pose layer against the kernels under it and against nalgebra (issue 31, item 1),
//! measured interleaved in one process (every kernel back to back in each round, rotating
//! order; the shared loop of the motion benches), f64, the same inputs on both sides, every
//! whole result through `black_box` (so no component is left uncomputed). A fallible
//! operation's value goes through it after the caller's `match`, as nalgebra's value does:
//! `black_box` on the whole `Result` would also time a copy of its 56 bytes, which the inlined
//! `Pose::transform_point` pays as a store-forwarding stall (docs/performance.md, thirteenth
//! session):
//!
//! - `Pose::exp` / the generated `g123inf::Bivector::exp` (target <= 1.4x);
//! - `Pose::log` / the generated `g123inf::Motor::log_unit` on unit motors (target <= 1.7x);
//! - `Pose::transform_point` / nalgebra `UnitDualQuaternion::transform_point` (<= 1.0x);
//! - `Pose::slerp` / nalgebra `UnitDualQuaternion::sclerp` (<= 1.0x), and `Pose::power`;
//! - the same action and slerp of `UnitPose` (normalised once, like nalgebra's unit type) /
//!   the same nalgebra rows: like with like, both promise a unit pose;
//! - for scale, `Pose::slerp` between the same poses made non-unit (`A` times 1.5, `B` times
//!   `0.8 + 0.3ω`), which takes the general form: the same motions, so / nalgebra's `sclerp`.
//!
//! ```text
//! cargo bench -p motion --features nalgebra --bench pose_layer
//! ```
#![allow(missing_docs)]

#[allow(dead_code)]
mod interleaved;

use algebra_core::test_support::Xorshift;
use gam_algebras::g123inf;
use interleaved::{Kernel, median, print_medians, ratio, times};
use motion::{Even, Pose, Pseudoscalar, UnitPose};
use nalgebra::{Point3, UnitDualQuaternion};
use std::hint::black_box;

/// Elements per kernel call.
const BATCH: usize = 256;

struct Data {
    poses: Vec<Pose<f64>>,
    others: Vec<Pose<f64>>,
    units: Vec<UnitPose<f64>>,
    scaled: Vec<Pose<f64>>,
    other_scaled: Vec<Pose<f64>>,
    other_units: Vec<UnitPose<f64>>,
    generators: Vec<Even<f64>>,
    bivectors: Vec<g123inf::Bivector<f64>>,
    motors: Vec<g123inf::Motor<f64>>,
    duals: Vec<UnitDualQuaternion<f64>>,
    other_duals: Vec<UnitDualQuaternion<f64>>,
    points: Vec<[f64; 3]>,
    na_points: Vec<Point3<f64>>,
    ts: Vec<f64>,
}

/// Unit poses: rotation half-angles up to about 1.3, translations up to 1.
fn data() -> Data {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    let mut draw = || rng.symmetric();
    let mut generator = || Even::new(0.0, 0.75 * draw(), 0.75 * draw(), 0.75 * draw(), draw(), draw(), draw(), 0.0);
    let generators: Vec<Even<f64>> = (0..BATCH).map(|_| generator()).collect();
    let unit = |g: &Even<f64>| Pose::exp(g).expect("finite generator");
    let poses: Vec<Pose<f64>> = generators.iter().map(unit).collect();
    // each `b` signed so that rev(a) b has non-negative scalar part: Pose::slerp takes the
    // element's logarithm (the long way otherwise), nalgebra's sclerp the short way
    let others: Vec<Pose<f64>> = poses
        .iter()
        .map(|a| {
            let b = unit(&generator());
            if (a.reverse() * b).scalar < 0.0 { -&b } else { b }
        })
        .collect();
    let bivectors = generators
        .iter()
        .map(|g| g123inf::Bivector::from_array([g.e12, g.e13, g.e23, g.e1inf, g.e2inf, g.e3inf]))
        .collect();
    let motors = poses.iter().map(Pose::to_motor).collect();
    let to_unit = |p: &Pose<f64>| p.to_unit().expect("unit pose");
    let units = poses.iter().map(to_unit).collect();
    let other_units = others.iter().map(to_unit).collect();
    let scaled = poses.iter().map(|p| p.scale(&1.5)).collect();
    let other_scaled = others.iter().map(|p| p.scale_pseudoscalar(&Pseudoscalar::new(0.8, 0.3))).collect();
    let dual = |p: &Pose<f64>| p.to_unit_dual_quaternion().expect("unit pose");
    let duals = poses.iter().map(dual).collect();
    let other_duals = others.iter().map(dual).collect();
    let points: Vec<[f64; 3]> = (0..BATCH).map(|_| [3.0 * draw(), 3.0 * draw(), 3.0 * draw()]).collect();
    let na_points = points.iter().map(|p| Point3::new(p[0], p[1], p[2])).collect();
    let ts = (0..BATCH).map(|_| 0.5 + 0.5 * draw()).collect();
    Data {
        poses,
        others,
        units,
        scaled,
        other_scaled,
        other_units,
        generators,
        bivectors,
        motors,
        duals,
        other_duals,
        points,
        na_points,
        ts,
    }
}

fn kernel_exp(d: &Data) -> f64 {
    d.bivectors.iter().map(|b| black_box(black_box(b).exp()).scalar).sum()
}

fn pose_exp(d: &Data) -> f64 {
    d.generators.iter().map(|g| Pose::exp(black_box(g)).map_or(0.0, |p| black_box(p).scalar)).sum()
}

fn kernel_log_unit(d: &Data) -> f64 {
    d.motors.iter().map(|m| black_box(m).log_unit().map_or(0.0, |l| black_box(l).e12)).sum()
}

fn pose_log(d: &Data) -> f64 {
    d.poses.iter().map(|p| black_box(p).log().map_or(0.0, |l| black_box(l).e12)).sum()
}

fn nalgebra_transform_point(d: &Data) -> f64 {
    d.duals.iter().zip(&d.na_points).map(|(q, p)| black_box(black_box(q).transform_point(black_box(p))).x).sum()
}

fn pose_transform_point(d: &Data) -> f64 {
    d.poses
        .iter()
        .zip(&d.points)
        .map(|(s, p)| black_box(s).transform_point(black_box(p)).map_or(0.0, |q| black_box(q)[0]))
        .sum()
}

fn unit_transform_point(d: &Data) -> f64 {
    d.units.iter().zip(&d.points).map(|(s, p)| black_box(black_box(s).transform_point(black_box(p)))[0]).sum()
}

fn nalgebra_sclerp(d: &Data) -> f64 {
    let pairs = d.duals.iter().zip(&d.other_duals).zip(&d.ts);
    pairs.map(|((a, b), t)| black_box(black_box(a).sclerp(black_box(b), *t)).dual.w).sum()
}

fn pose_slerp(d: &Data) -> f64 {
    let pairs = d.poses.iter().zip(&d.others).zip(&d.ts);
    pairs.map(|((a, b), t)| Pose::slerp(black_box(a), black_box(b), t).map_or(0.0, |s| black_box(s).e1inf)).sum()
}

fn unit_slerp(d: &Data) -> f64 {
    let pairs = d.units.iter().zip(&d.other_units).zip(&d.ts);
    pairs.map(|((a, b), t)| UnitPose::slerp(black_box(a), black_box(b), t).map_or(0.0, |s| black_box(s).e1inf)).sum()
}

fn pose_slerp_non_unit(d: &Data) -> f64 {
    let pairs = d.scaled.iter().zip(&d.other_scaled).zip(&d.ts);
    pairs.map(|((a, b), t)| Pose::slerp(black_box(a), black_box(b), t).map_or(0.0, |s| black_box(s).e1inf)).sum()
}

fn pose_power(d: &Data) -> f64 {
    d.poses.iter().zip(&d.ts).map(|(s, t)| black_box(s).power(t).map_or(0.0, |p| black_box(p).e1inf)).sum()
}

/// The kernels; each pose-layer row follows the reference it is compared with.
const KERNELS: [(&str, Kernel<Data>); 12] = [
    ("g123inf Bivector::exp", kernel_exp),
    ("Pose::exp", pose_exp),
    ("g123inf Motor::log_unit", kernel_log_unit),
    ("Pose::log", pose_log),
    ("nalgebra transform_point", nalgebra_transform_point),
    ("Pose::transform_point", pose_transform_point),
    ("nalgebra sclerp", nalgebra_sclerp),
    ("Pose::slerp", pose_slerp),
    ("Pose::power", pose_power),
    ("UnitPose::transform_point", unit_transform_point),
    ("UnitPose::slerp", unit_slerp),
    ("Pose::slerp, non-unit poses", pose_slerp_non_unit),
];

/// (pose-layer row, reference row, target ratio)
const RATIOS: [(usize, usize, f64); 8] = [
    (1, 0, 1.4),
    (3, 2, 1.7),
    (5, 4, 1.0),
    (9, 4, 1.0),
    (7, 6, 1.0),
    (10, 6, 1.0),
    (11, 6, f64::NAN),
    (8, 6, f64::NAN),
];

fn main() {
    let d = data();
    // the same motions on both sides
    for (i, (s, q)) in d.poses.iter().zip(&d.duals).enumerate() {
        let (a, b) = (s.transform_point(&d.points[i]).unwrap(), q.transform_point(&d.na_points[i]));
        assert!((a[0] - b.x).abs() + (a[1] - b.y).abs() + (a[2] - b.z).abs() < 1e-12, "transform_point {i}");
        let p = Pose::slerp(s, &d.others[i], &d.ts[i]).unwrap().to_unit_dual_quaternion().unwrap();
        let n = q.sclerp(&d.other_duals[i], d.ts[i]);
        let close = (p.into_inner().as_ref().iter().zip(n.into_inner().as_ref())).all(|(x, y)| (x - y).abs() < 1e-12);
        let flipped = (p.into_inner().as_ref().iter().zip(n.into_inner().as_ref())).all(|(x, y)| (x + y).abs() < 1e-12);
        assert!(close || flipped, "slerp {i}");
        let u = d.units[i].transform_point(&d.points[i]);
        assert!((0..3).all(|k| (u[k] - a[k]).abs() < 1e-12), "UnitPose::transform_point {i}");
        let us = UnitPose::slerp(&d.units[i], &d.other_units[i], &d.ts[i]).unwrap();
        let ps = Pose::slerp(s, &d.others[i], &d.ts[i]).unwrap();
        assert!((us.as_pose() - &ps).components().iter().all(|x| x.abs() < 1e-12), "UnitPose::slerp {i}");
        let ns = Pose::slerp(&d.scaled[i], &d.other_scaled[i], &d.ts[i]).unwrap();
        assert!(ns.is_equivalent(&ps, &1e-12).unwrap(), "non-unit slerp {i}");
    }
    let rounds = std::env::args().nth(1).and_then(|a| a.parse().ok()).unwrap_or(2001);
    let t = times(&KERNELS, &d, rounds, BATCH);
    println!("pose layer, interleaved ({rounds} rounds of {BATCH} elements), median ns per element:");
    print_medians(&KERNELS, &t);
    println!("\n  {:<50} {:>7} {:>8}", "ratio (median of per-round ratios)", "ratio", "target");
    for (a, b, target) in RATIOS {
        let name = format!("{} / {}", KERNELS[a].0, KERNELS[b].0);
        let target = if target.is_nan() { "-".to_string() } else { format!("<= {target}") };
        println!("  {name:<50} {:>6.2}x {target:>8}", ratio(&t, a, b));
    }
    black_box(median(t[0].clone()));
}

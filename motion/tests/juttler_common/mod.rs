//! Helpers shared by the Jüttler tests: random rational instances (TRT, minimal order), one
//! f64 pose set, the 1000-parameter trajectory check.
#![allow(dead_code)]

pub use super::common::Xorshift as Rng;
use algebra_core::rational::{Q, q, ratio};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::Pose;
use motion::juttler::QMotion;
use motion::juttler::rotational::affine;
use motion::juttler::tr::rotation_translation;
use motion::repr::dual_quaternion::from_dual_quaternion_exact;

/// Integers in `[-5, 5]` from the motion tests' shared generator.
pub fn int(g: &mut Rng) -> i64 {
    (g.unit() * 11.0).floor() as i64 - 5
}

/// The position `(2 + ε s) * R` (14) as a pose.
pub fn position(r: &Quaternion<Q>, s: &[Q; 3]) -> Pose<Q> {
    let dq = DualQuaternion::new(r.clone(), &Quaternion::pure(s).scale(&ratio(1, 2)) * r);
    from_dual_quaternion_exact(&dq).unwrap()
}

/// `m + 1` random rational positions (rotations with non-zero scalar part) and parameters.
pub fn instance(seed: u64, m: usize) -> (Vec<Pose<Q>>, Vec<Q>) {
    let mut g = Rng(seed);
    let poses = (0..=m)
        .map(|_| {
            let w = int(&mut g).abs() + 1;
            let r = Quaternion::new(q(w), q(int(&mut g)), q(int(&mut g)), q(int(&mut g)));
            position(&r, &[ratio(int(&mut g), 2), q(int(&mut g)), ratio(int(&mut g), 3)])
        })
        .collect();
    let t = (0..=m).map(|i| ratio(i as i64 * i as i64 + i as i64, (m * m + m) as i64)).collect();
    (poses, t)
}

pub fn rot_of(poses: &[Pose<Q>], t: &[Q]) -> QMotion<Q> {
    let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
    affine(&rots, t).unwrap()
}

/// Four poses in f64 with different rotation axes.
pub fn f64_poses() -> Vec<Pose<f64>> {
    let turn = |axis: [f64; 3], angle: f64, t: [f64; 3]| Pose::from_axis_angle_translation(&axis, &angle, &t).unwrap();
    vec![
        Pose::identity(),
        turn([0.0, 0.0, 1.0], 1.2, [1.0, 2.0, 0.0]),
        turn([1.0, 1.0, 0.0], 0.7, [3.0, 0.0, 1.0]),
        turn([0.0, 1.0, 0.0], -0.4, [2.0, -1.0, 2.0]),
    ]
}

/// The largest component-wise distance between a trajectory's point and the reference point
/// (the point's image under the sampled motion) at 1000 parameters evenly over `[0, 1]`.
pub fn worst_at_1000(path: impl Fn(&f64) -> [f64; 3], reference: impl Fn(&f64) -> [f64; 3]) -> f64 {
    (0..1000)
        .map(|k| {
            let t = k as f64 / 999.0;
            let (a, b) = (path(&t), reference(&t));
            (0..3).map(|i| (a[i] - b[i]).abs()).fold(0.0, f64::max)
        })
        .fold(0.0, f64::max)
}

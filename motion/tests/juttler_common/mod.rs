//! Helpers shared by the Jüttler tests: random rational instances (TRT, minimal order) and the
//! 1000-parameter comparison of trajectories.
#![allow(dead_code)]

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::Pose;
use motion::juttler::QMotion;
use motion::juttler::rotational::affine;
use motion::juttler::tr::rotation_translation;
use motion::repr::dual_quaternion::from_dual_quaternion_exact;

/// A small deterministic generator of integers in `[-5, 5]`.
pub struct Rng(pub u64);

impl Rng {
    pub fn int(&mut self) -> i64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        (self.0 % 11) as i64 - 5
    }
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
            let w = g.int().abs() + 1;
            let r = Quaternion::new(q(w), q(g.int()), q(g.int()), q(g.int()));
            position(&r, &[ratio(g.int(), 2), q(g.int()), ratio(g.int(), 3)])
        })
        .collect();
    let t = (0..=m).map(|i| ratio(i as i64 * i as i64 + i as i64, (m * m + m) as i64)).collect();
    (poses, t)
}

pub fn rot_of(poses: &[Pose<Q>], t: &[Q]) -> QMotion<Q> {
    let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
    affine(&rots, t).unwrap()
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

//! `λS` is the same pose as `S` (Theorem 2.8), so every interpolation method must give the same
//! motion whatever non-zero multiples of the key poses it is handed (issue 30: ccm-multiplicative
//! through `2·S` key poses failed its C1 check). Reference: the same method on the unit key
//! poses, compared through the sampled rigid matrices.

use crate::common;

use common::{Xorshift, centered};
use motion::method::{Method, MethodInput};
use motion::{Motion, Pose};

fn key_poses(rng: &mut Xorshift, n: usize) -> Vec<Pose<f64>> {
    (0..n)
        .map(|_| {
            let mut next = || centered(rng);
            let axis = [next(), next(), next() + 0.1];
            Pose::from_axis_angle_translation(&axis, &(2.0 * next()), &[3.0 * next(), 3.0 * next(), 3.0 * next()])
                .unwrap()
        })
        .collect()
}

fn sampled(method: Method, poses: &[Pose<f64>]) -> Vec<[[f64; 4]; 4]> {
    let m = method.build(&MethodInput::new(poses.to_vec())).unwrap_or_else(|e| panic!("{method}: {e}"));
    (0..=20).map(|i| m.pose(&(f64::from(i) / 20.0)).unwrap().to_matrix().unwrap()).collect()
}

fn largest_difference(a: &[[[f64; 4]; 4]], b: &[[[f64; 4]; 4]]) -> f64 {
    a.iter().flatten().flatten().zip(b.iter().flatten().flatten()).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}

#[test]
fn scaled_key_poses_give_the_same_motion_in_every_method() {
    let mut rng = Xorshift(0xd1b5_4a32_d192_ed03);
    for round in 0..4 {
        let poses = key_poses(&mut rng, 3 + round % 2);
        for method in Method::ALL {
            let name = method.name();
            // the projective method takes 5, 9, ... poses: its own test below
            if method == Method::JuttlerProjective {
                continue;
            }
            let want = sampled(method, &poses);
            for _ in 0..3 {
                // λ_i = ±10^e, e in [-6, 6], a different one per key pose
                let scaled: Vec<Pose<f64>> = poses
                    .iter()
                    .map(|p| {
                        let e = 6.0 * centered(&mut rng) * 2.0;
                        let sign = if centered(&mut rng) < 0.0 { -1.0 } else { 1.0 };
                        p.scale(&(sign * 10f64.powf(e)))
                    })
                    .collect();
                let got = sampled(method, &scaled);
                let d = largest_difference(&got, &want);
                assert!(d < 1e-9, "{name}, round {round}: sampled matrices differ by {d:e}");
            }
        }
    }
}

#[test]
fn scaled_key_poses_give_the_same_projective_motion() {
    // five key poses (the projective method's smallest count), each scaled by its own λ
    let keys: [([f64; 3], f64, [f64; 3]); 5] = [
        ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
        ([0.0, 0.0, 1.0], 0.8, [3.0, 1.0, 0.0]),
        ([1.0, 0.0, 0.0], 1.2, [6.0, 0.0, 1.0]),
        ([0.0, 1.0, 1.0], 1.6, [8.0, 2.0, 0.0]),
        ([1.0, 1.0, 0.0], 2.0, [12.0, 0.0, 0.0]),
    ];
    let poses: Vec<Pose<f64>> =
        keys.iter().map(|(a, phi, t)| Pose::from_axis_angle_translation(a, phi, t).unwrap()).collect();
    let want = sampled(Method::JuttlerProjective, &poses);
    let scaled: Vec<Pose<f64>> = poses.iter().zip([1.0, -2.0, 1e-5, 3e4, -0.5]).map(|(p, l)| p.scale(&l)).collect();
    let d = largest_difference(&sampled(Method::JuttlerProjective, &scaled), &want);
    assert!(d < 1e-9, "{d:e}");
}

#[test]
fn the_issue_reproducer_ccm_multiplicative_through_dual_quaternion_multiples() {
    // [2,0,0,0,0,1,0,0] is 2·(1 + ½ j ε): the translation by (0, 1, 0)... given as non-unit multiples
    let unit = vec![Pose::identity(), Pose::translation(&[0.0, 1.0, 0.0]), Pose::translation(&[1.0, 1.0, 0.0])];
    let scaled: Vec<Pose<f64>> = unit.iter().zip([1.0, 2.0, -3.0]).map(|(p, l)| p.scale(&l)).collect();
    let method = Method::CcmMultiplicative;
    let d = largest_difference(&sampled(method, &scaled), &sampled(method, &unit));
    assert!(d < 1e-12, "{d:e}");
}

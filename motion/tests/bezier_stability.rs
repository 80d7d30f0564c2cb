//! Multiplicative Bezier motions stay unit over high degrees (the plain slerp recursion drifted
//! off unit exponentially: 4e-7 at degree 20, failure from about 40), and agree with the plain
//! definition (de Casteljau with `Pose::slerp`) evaluated at 256 bits.

use crate::common;

use algebra_core::{MpFloat, PrecisionGuard, Real};
use common::{Xorshift, centered};
use motion::{Motion, MultiplicativeBSpline, MultiplicativeBezier, Pose};

fn random_unit_poses(rng: &mut Xorshift, n: usize) -> Vec<Pose<f64>> {
    (0..=n)
        .map(|_| {
            let axis = [centered(rng), centered(rng), centered(rng)];
            let v = [4.0 * centered(rng), 4.0 * centered(rng), 4.0 * centered(rng)];
            Pose::from_axis_angle_translation(&axis, &(2.0 * centered(rng)), &v).unwrap()
        })
        .collect()
}

/// The paper's definition, unmodified, at 256 bits (control poses unitized at 256 bits first
/// when `unitize`: the definition raises each pose's factor to a power growing like
/// `(1 + 2t)^n`, so f64 rounding of a unit pose would otherwise dominate the reference).
fn plain_mpfr(poses: &[Pose<f64>], t: f64, unitize: bool) -> Pose<f64> {
    let _g = PrecisionGuard::new(256);
    let mut column: Vec<Pose<MpFloat>> = poses.iter().map(|p| p.map_scalar(&|x: &f64| MpFloat::from_f64(*x))).collect();
    if unitize {
        column = column.iter().map(|p| p.unitize().unwrap()).collect();
    }
    let t = MpFloat::from_f64(t);
    while column.len() > 1 {
        column = column.windows(2).map(|w| Pose::slerp(&w[0], &w[1], &t).unwrap()).collect();
    }
    column[0].map_scalar(&|x: &MpFloat| x.to_f64())
}

fn max_diff(a: &Pose<f64>, b: &Pose<f64>) -> f64 {
    a.components().iter().zip(b.components()).map(|(x, y)| (*x - *y).abs()).fold(0.0, f64::max)
}

#[test]
fn high_degree_multiplicative_bezier_stays_unit_and_matches_256_bits() {
    let mut rng = Xorshift(0x853c49e6748fea9b);
    for n in [20, 40, 60] {
        let poses = random_unit_poses(&mut rng, n);
        let m = MultiplicativeBezier::new(poses.clone()).unwrap();
        for t in [0.1, 0.37, 0.5, 0.9] {
            let s = m.pose(&t).unwrap();
            assert!(s.is_unitary(&1e-13), "degree {n}, t {t}: {:?}", s.norm_squared());
            let want = plain_mpfr(&poses, t, true);
            assert!(max_diff(&s, &want) < 1e-9, "degree {n}, t {t}: {}", max_diff(&s, &want));
        }
    }
}

#[test]
fn very_high_degree_stays_unit() {
    let mut rng = Xorshift(0x2545f4914f6cdd1d);
    let poses = random_unit_poses(&mut rng, 300);
    let m = MultiplicativeBezier::new(poses.clone()).unwrap();
    let b = MultiplicativeBSpline::clamped_uniform(300, poses).unwrap();
    for t in [0.05, 0.5, 0.95] {
        let s = m.pose(&t).unwrap();
        assert!(s.is_unitary(&1e-12) && s.is_finite(), "t {t}: {:?}", s.norm_squared());
        assert!(b.pose(&t).unwrap().is_unitary(&1e-12));
    }
}

#[test]
fn non_unit_control_poses_keep_the_definitions_factors() {
    let mut rng = Xorshift(0x9e3779b97f4a7c15);
    let n = 5;
    let poses: Vec<_> = random_unit_poses(&mut rng, n)
        .into_iter()
        .map(|p| {
            p.scale_pseudoscalar(&motion::Pseudoscalar::new(1.0 + 0.3 * centered(&mut rng), 0.2 * centered(&mut rng)))
        })
        .collect();
    let m = MultiplicativeBezier::new(poses.clone()).unwrap();
    for t in [0.2, 0.6, 0.8] {
        let s = m.pose(&t).unwrap();
        let want = plain_mpfr(&poses, t, false);
        let scale = want.components().iter().map(|x| x.abs()).fold(0.0, f64::max);
        assert!(max_diff(&s, &want) < 1e-11 * scale, "t {t}: {s} vs {want}");
    }
}

/// The first and second derivatives (dual numbers through the same tableau, what `gam plot`
/// and the trajectory sampler evaluate) stay finite and right at high degree: the acceleration
/// of a body point against central differences of its velocity, and the velocity against
/// central differences of its position. Factoring every tableau entry again from its expanded
/// pose let the derivative parts of rounding grow with the degree until, from degree about 150,
/// the second-order dual numbers overflowed to a zero pose.
#[test]
fn high_degree_derivatives_stay_finite_and_match_differences() {
    let mut rng = Xorshift(0x6a09e667f3bcc909);
    for n in [160] {
        let m = MultiplicativeBezier::new(random_unit_poses(&mut rng, n)).unwrap();
        let body = [[1.0, -0.5, 0.25]];
        for t in [0.5, 0.77] {
            let at = |t: f64| motion::trajectory::sample_motion(&m, &t, &body).unwrap().points[0].clone();
            let (p, h) = (at(t), 1e-5);
            let (lo, hi) = (at(t - h), at(t + h));
            for k in 0..3 {
                let dv = (hi.velocity[k] - lo.velocity[k]) / (2.0 * h);
                let dp = (hi.position[k] - lo.position[k]) / (2.0 * h);
                let (a, v) = (p.acceleration[k], p.velocity[k]);
                assert!(
                    a.is_finite() && (a - dv).abs() <= 1e-5 * a.abs().max(dv.abs()).max(1.0),
                    "n {n}, t {t}: {a} vs {dv}"
                );
                assert!((v - dp).abs() <= 1e-6 * v.abs().max(dp.abs()).max(1.0), "n {n}, t {t}: {v} vs {dp}");
            }
        }
    }
}

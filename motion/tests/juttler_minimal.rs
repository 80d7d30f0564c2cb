//! Jüttler's rational motions of minimal order (35)-(39), Theorem 6: interpolation exactly
//! over rationals, order 2m, trajectories of degree n that agree with the point image under
//! the motion and with the (higher-degree) trajectories of the Q-motion (36), the matrix (35)
//! against the trajectory; a general w0*; f64 through the elliptic method.

use crate::juttler_common;

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::dual_quaternion::Quaternion;
use juttler_common::{Rng, f64_poses, instance, int, rot_of};
use motion::Motion;
use motion::juttler::minimal::{MinimalMotion, minimal, minimal_method};
use motion::juttler::{JuttlerError, RationalMotion};

/// `(1, x)` mapped by the 4x4 matrix `m`.
fn apply(m: &[[Q; 4]; 4], x: &[Q; 3]) -> [Q; 4] {
    std::array::from_fn(|r| &m[r][0] + &(&m[r][1] * &x[0]) + &m[r][2] * &x[1] + &m[r][3] * &x[2])
}

#[test]
fn minimal_order_interpolates_exactly_with_order_2m() {
    for (seed, m) in [(5, 2), (9, 3), (13, 4)] {
        let (poses, t) = instance(seed, m);
        let rot = rot_of(&poses, &t); // affine: k = m
        let mm = minimal_method(&rot, &poses, &t).unwrap();
        assert_eq!(mm.order(), 2 * m);
        for (p, ti) in poses.iter().zip(&t) {
            assert!(mm.pose_exact(ti).unwrap().is_equivalent_exact(p), "m = {m}, t = {ti}");
        }
        // w0* = 1 (37)
        assert!(mm.coefficients().0.iter().all(|w| *w == q(1)));
        // the Q-motion (36) has degree 3m, the same poses
        let qm = mm.q_motion();
        assert_eq!(qm.degree(), 3 * m);
        assert!(qm.study_polynomial().iter().all(|c| *c == q(0)));
        let x = [ratio(1, 2), q(-1), q(2)];
        let (path, qpath) = (mm.rational_trajectory(&x).unwrap(), qm.trajectory(&x));
        assert_eq!((path.degree(), qpath.degree()), (2 * m, 6 * m));
        for s in [ratio(1, 9), ratio(2, 5), ratio(7, 8)] {
            let p = mm.pose_exact(&s).unwrap();
            assert!(qm.pose_exact(&s).unwrap().is_equivalent_exact(&p));
            let y = p.transform_point(&x).unwrap();
            assert_eq!(path.point(&s).unwrap(), y);
            assert_eq!(qpath.point(&s).unwrap(), y);
            assert_eq!(path.homogeneous(&s), apply(&mm.matrix(&s), &x));
        }
    }
}

#[test]
fn theorem_6_general_w0() {
    // random w0* (degree n - 2k), w (degree n), D (degree k) with n = 5, k = 2
    let mut g = Rng(21);
    let w0: Vec<Q> = (0..2).map(|_| q(int(&mut g).abs() + 1)).collect();
    let w: Vec<[Q; 3]> = (0..6).map(|_| [q(int(&mut g)), q(int(&mut g)), q(int(&mut g))]).collect();
    let d: Vec<_> = (0..3)
        .map(|_| Quaternion::new(q(int(&mut g).abs() + 1), q(int(&mut g)), q(int(&mut g)), q(int(&mut g))))
        .collect();
    let m = MinimalMotion::new(w0, w, d).unwrap();
    assert_eq!(m.order(), 5);
    let qm = m.q_motion();
    assert_eq!(qm.degree(), 7);
    let x = [q(3), ratio(-1, 4), q(1)];
    let path = m.trajectory(&x);
    assert_eq!(path.degree(), 5);
    for s in [q(0), ratio(1, 3), ratio(3, 4), q(1)] {
        let y = m.pose_exact(&s).unwrap().transform_point(&x).unwrap();
        assert_eq!(path.point(&s).unwrap(), y);
        assert_eq!(qm.trajectory(&x).point(&s).unwrap(), y);
        assert_eq!(path.homogeneous(&s), apply(&m.matrix(&s), &x));
    }
}

#[test]
fn minimal_errors_are_typed() {
    let (poses, t) = instance(3, 2);
    let rot = rot_of(&poses, &t);
    let tr = motion::juttler::tr::tr_method(&rot, &poses, &t).unwrap();
    assert!(matches!(minimal_method(&tr, &poses, &t), Err(JuttlerError::NotRotational { .. })));
    assert!(matches!(minimal_method(&rot, &poses, &t[..2]), Err(JuttlerError::Parameters { .. })));
    let one = vec![Quaternion::one()];
    assert!(matches!(
        MinimalMotion::new(vec![q(1), q(1)], vec![[q(0), q(0), q(0)]], one),
        Err(JuttlerError::Parameters { .. })
    ));
}

#[test]
fn minimal_in_f64_through_the_elliptic_method() {
    let poses = &f64_poses()[..3];
    let t = [0.0, 0.45, 1.0];
    let m = minimal(poses, &t).unwrap();
    assert_eq!(m.order(), 4);
    for (p, ti) in poses.iter().zip(&t) {
        assert!(m.pose(ti).unwrap().is_equivalent(p, &1e-12).unwrap());
    }
    let x = [0.3, -0.2, 1.0];
    let path = m.trajectory(&x);
    for i in 0..=100 {
        let s = f64::from(i) / 100.0;
        let y = m.pose(&s).unwrap().transform_point(&x).unwrap();
        let z = path.point(&s).unwrap();
        assert!((0..3).all(|k| (y[k] - z[k]).abs() < 1e-12), "{s}");
    }
}

#[test]
fn minimal_refuses_nan() {
    let poses = f64_poses();
    assert!(matches!(minimal(&poses[..3], &[0.0, 0.5, 0.5]), Err(JuttlerError::Parameters { .. })));
    let nan = MinimalMotion::new(vec![f64::NAN], vec![[0.0; 3]], vec![Quaternion::one()]);
    assert!(matches!(nan, Err(JuttlerError::Parameters { .. })));
}

#[test]
fn point_velocities_through_the_motion_vocabulary_match_the_trajectory_derivative() {
    // velocity() lifts the motion to dual numbers (MapScalar) and differentiates the pose; the
    // rational trajectory is differentiated by its hodograph: two independent routes
    let poses = f64_poses();
    let t = [0.0, 0.3, 0.6, 1.0];
    let m = minimal(&poses, &t).unwrap();
    let trt = motion::juttler::trt::trt(&poses, &t, 2).unwrap();
    let x = [0.4, -1.0, 0.7];
    for s in [0.05, 0.3, 0.55, 0.9] {
        for (v, path) in [
            (motion::velocity::velocity(&m, &s).unwrap(), m.trajectory(&x)),
            (motion::velocity::velocity(&trt, &s).unwrap(), trt.trajectory(&x)),
        ] {
            let (q, dq) = v.body_point_velocity(&x).unwrap();
            let (p, dp) = (path.point(&s).unwrap(), path.derivative(&s).unwrap());
            assert!((0..3).all(|k| (q[k] - p[k]).abs() < 1e-12 && (dq[k] - dp[k]).abs() < 1e-10), "{s}: {dq:?} {dp:?}");
        }
    }
}

//! Trajectories of Q-motions as rational Bézier curves (Jüttler Sec. 1): against the point
//! image under the motion's pose, exactly over rationals and to 1e-12 in f64; the derivative
//! against dual numbers over rationals (exact); degree elevation.

use algebra_core::Jet;
use algebra_core::rational::{Q, q, ratio, rational_to_f64};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;
use motion::Motion;
use motion::juttler::{JuttlerError, QMotion, RationalBezier};

use crate::juttler_common;
use juttler_common::worst_at_1000;

fn quat(c: [i64; 4]) -> Quaternion<Q> {
    let [w, x, y, z] = c.map(q);
    Quaternion::new(w, x, y, z)
}

/// `(2 + ε Σ b_j p_j) * Σ b_j C_j`: a Q-motion of degree 4 (TR form (30)).
fn motion() -> QMotion<Q> {
    let rot = [[1, 0, 0, 0], [2, 1, -1, 3], [1, 2, 0, -1]];
    let rot = QMotion::new_exact(rot.iter().map(|c| DualQuaternion::from_real(quat(*c))).collect()).unwrap();
    let p = [[q(0), q(0), q(0)], [q(3), ratio(-1, 2), q(1)], [q(1), q(4), ratio(2, 3)]];
    let tr = p.iter().map(|p| DualQuaternion::new(quat([2, 0, 0, 0]), Quaternion::pure(p))).collect();
    QMotion::new_exact(tr).unwrap().product(&rot)
}

fn body_point() -> [Q; 3] {
    [q(1), ratio(-2, 3), q(5)]
}

#[test]
fn degree_is_2n_and_exact_at_rational_parameters() {
    let m = motion();
    let x = body_point();
    let path = m.trajectory(&x);
    assert_eq!(path.degree(), 2 * m.degree());
    for k in -3..=23 {
        let t = ratio(k, 20);
        let want = m.pose_exact(&t).unwrap().transform_point(&x).unwrap();
        assert_eq!(path.point(&t).unwrap(), want, "t = {t}");
    }
    // the end control points are the end positions of x
    let pts = path.points().unwrap();
    assert_eq!(pts[0], m.pose_exact(&q(0)).unwrap().transform_point(&x).unwrap());
    assert_eq!(pts[8], m.pose_exact(&q(1)).unwrap().transform_point(&x).unwrap());
}

#[test]
fn f64_at_1000_parameters_matches_the_motion_to_1e_12() {
    let m = motion().map_ring(&rational_to_f64);
    let x = body_point().map(|c| rational_to_f64(&c));
    let path = m.trajectory(&x);
    let worst = worst_at_1000(|t| path.point(t).unwrap(), |t| m.pose(t).unwrap().transform_point(&x).unwrap());
    assert!(worst < 1e-12, "{worst:e}");
}

#[test]
fn derivative_is_the_exact_velocity() {
    // the reference: the pose of Q(t) over Jet<Q> (dual numbers over rationals), then x's image
    let m = motion();
    let x = body_point();
    let path = m.trajectory(&x);
    let mj = m.map_ring(&|c: &Q| Jet::constant(c.clone()));
    let xj = x.clone().map(Jet::constant);
    for t in [q(0), ratio(1, 5), ratio(1, 2), ratio(2, 3), q(1)] {
        let want = mj.pose_exact(&Jet::variable(t.clone())).unwrap().transform_point(&xj).unwrap();
        assert_eq!(path.derivative(&t).unwrap(), want.map(|c| c.eps), "t = {t}");
    }
}

#[test]
fn elevation_keeps_the_curve_exactly() {
    let path = motion().trajectory(&body_point());
    let e = path.elevate().elevate();
    assert_eq!(e.degree(), 10);
    for t in [q(0), ratio(1, 7), ratio(1, 2), ratio(9, 10), q(1)] {
        assert_eq!(e.point(&t).unwrap(), path.point(&t).unwrap());
        assert_eq!(e.derivative(&t).unwrap(), path.derivative(&t).unwrap());
    }
}

#[test]
fn weight_zero_is_a_typed_error() {
    // R(t) = (1 - t) - t vanishes at t = 1/2: the trajectory has a pole there
    let c = vec![DualQuaternion::from_real(quat([1, 0, 0, 0])), DualQuaternion::from_real(quat([-1, 0, 0, 0]))];
    let path = QMotion::new_exact(c).unwrap().trajectory(&body_point());
    assert!(matches!(path.point(&ratio(1, 2)), Err(JuttlerError::ZeroWeight { .. })));
    assert!(matches!(path.derivative(&ratio(1, 2)), Err(JuttlerError::ZeroWeight { .. })));
    let r = RationalBezier::new(vec![[q(0), q(1), q(0), q(0)]]).unwrap();
    assert!(matches!(r.points(), Err(JuttlerError::ZeroWeight { .. })));
}

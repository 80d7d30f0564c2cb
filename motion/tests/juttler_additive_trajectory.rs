//! Trajectories of the main paper's additive Bézier motions as rational Bézier curves of
//! degree 2n (`RationalMotion for AdditiveBezier`): against the point image under the motion
//! exactly over rationals and to 1e-12 at 1000 f64 parameters, the derivative against dual
//! numbers over Q, and against Jüttler's dual-quaternion route (12) where the additive motion
//! is a Q-motion.

use algebra_core::Jet;
use algebra_core::rational::{Q, q, ratio, rational_to_f64};
use gam_algebras::DualQuaternion;
use motion::juttler::{QMotion, RationalMotion};
use motion::repr::dual_quaternion::to_dual_quaternion_exact;
use motion::{AdditiveBezier, Motion, Pose};

use crate::juttler_common;
use juttler_common::worst_at_1000;

/// A cubic through general even elements: non-unit, with `e123∞` parts (off the Study quadric).
fn cubic() -> AdditiveBezier<Q> {
    let c =
        [[1, 0, 0, 0, 0, 0, 0, 0], [2, 1, -1, 0, 3, 0, 1, 1], [1, 0, 2, -1, -2, 1, 4, -1], [3, -1, 1, 2, 0, 2, -1, 2]];
    AdditiveBezier::new(c.iter().map(|c| Pose::from_array(c.map(q))).collect()).unwrap()
}

fn body_point() -> [Q; 3] {
    [ratio(1, 2), q(-3), q(2)]
}

#[test]
fn a_cubic_gives_degree_6_exact_at_rational_parameters_with_exact_derivatives() {
    let m = cubic();
    let x = body_point();
    let path = m.rational_trajectory(&x).unwrap();
    assert_eq!(path.degree(), 6);
    // the derivative's reference: the motion over Jet<Q> (dual numbers over rationals)
    let mj = m.map_ring(&|c: &Q| Jet::constant(c.clone()));
    let xj = x.clone().map(Jet::constant);
    for k in -3..=23 {
        let t = ratio(k, 20);
        let image = mj.evaluate(&Jet::variable(t.clone())).unwrap().transform_point(&xj).unwrap();
        assert_eq!(path.point(&t).unwrap(), image.clone().map(|c| c.re), "t = {t}");
        assert_eq!(path.derivative(&t).unwrap(), image.map(|c| c.eps), "t = {t}");
    }
    let pts = path.points().unwrap();
    assert_eq!(pts[0], m.poses()[0].transform_point(&x).unwrap());
    assert_eq!(pts[6], m.poses()[3].transform_point(&x).unwrap());
}

#[test]
fn f64_at_1000_parameters_matches_the_motion_to_1e_12() {
    let poses: Vec<Pose<f64>> = (0..4)
        .map(|i| {
            let x = i as f64;
            let axis = [0.2 + x, 1.0 - 0.3 * x, 0.5 * x * x - 1.0];
            let p = Pose::from_axis_angle_translation(&axis, &(0.7 * x - 1.1), &[x, 2.0 - x * x, 0.4 * x]).unwrap();
            p.scale(&(1.0 + 0.25 * x))
        })
        .collect();
    let m = AdditiveBezier::new(poses).unwrap();
    let x = [0.3, -1.0, 2.0];
    let path = m.rational_trajectory(&x).unwrap();
    assert_eq!(path.degree(), 6);
    let worst = worst_at_1000(|t| path.point(t).unwrap(), |t| m.pose(t).unwrap().transform_point(&x).unwrap());
    assert!(worst < 1e-12, "{worst:e}");
    // the same curve as the exact one, rounded
    let exact = cubic().rational_trajectory(&body_point()).unwrap();
    let rounded =
        cubic().map_ring(&rational_to_f64).rational_trajectory(&body_point().map(|c| rational_to_f64(&c))).unwrap();
    for (a, b) in exact.control().iter().zip(rounded.control()) {
        assert!((0..4).all(|k| (rational_to_f64(&a[k]) - b[k]).abs() < 1e-12));
    }
}

#[test]
fn on_the_study_quadric_it_is_the_q_motion_trajectory() {
    // control poses that are rigid and whose linear combinations stay rigid: rotations about
    // the origin (dual part zero) composed with one fixed translation on the left
    let rot = [[1, 0, 0, 0], [2, 1, -1, 3], [1, 2, 0, -1]];
    let shift = Pose::translation(&[q(1), q(-2), ratio(1, 3)]);
    let poses: Vec<Pose<Q>> = rot
        .iter()
        .map(|[c, a, b, d]| shift.clone() * Pose::from_array([q(*c), q(*a), q(*b), q(*d), q(0), q(0), q(0), q(0)]))
        .collect();
    let m = AdditiveBezier::new(poses.clone()).unwrap();
    let qm =
        QMotion::new_exact(poses.iter().map(to_dual_quaternion_exact).collect::<Vec<DualQuaternion<Q>>>()).unwrap();
    let x = body_point();
    let a = m.rational_trajectory(&x).unwrap();
    let b = qm.rational_trajectory(&x).unwrap();
    assert_eq!(a.degree(), b.degree());
    // the same affine control points, weights in one constant ratio
    assert_eq!(a.points().unwrap(), b.points().unwrap());
    let ratio0 = a.weights()[0].clone() / b.weights()[0].clone();
    assert!(a.weights().iter().zip(b.weights()).all(|(u, v)| u.clone() == ratio0.clone() * v));
}

//! Jüttler's TRT method (32)-(34), Result 5: interpolation exactly over rationals for every
//! split l1 + l2 = m - 1, independence of the moving origin (TRT) against the dependence of
//! the TR method (Prop. 4), both exactly on a random rational instance; typed errors.

use crate::juttler_common;
use algebra_core::rational::{q, ratio};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;

use juttler_common::{f64_poses, instance, position, rot_of};
use motion::juttler::JuttlerError;
use motion::juttler::rotational::elliptic_normalised;
use motion::juttler::tr::tr_method;
use motion::juttler::trt::{trt, trt_method};
use motion::{Motion, Pose};

#[test]
fn trt_interpolates_exactly_for_every_split() {
    let (poses, t) = instance(7, 4);
    let rot = rot_of(&poses, &t);
    for l1 in 0..4 {
        let m = trt_method(&rot, &poses, &t, l1).unwrap();
        assert_eq!(m.degree(), l1.max(3 - l1) + 4, "l1 = {l1}");
        assert!(m.study_polynomial().iter().all(|c| *c == q(0)));
        for (p, ti) in poses.iter().zip(&t) {
            assert!(m.pose_exact(ti).unwrap().is_equivalent_exact(p), "l1 = {l1}, t = {ti}");
        }
        // the real part is the rotational motion, doubled and elevated (32)
        let s = ratio(2, 7);
        assert_eq!(m.eval(&s).real, rot.eval(&s).real.scale(&q(2)));
    }
}

#[test]
fn trt_with_elliptic_rotations_over_rationals() {
    let r = [
        Quaternion::new(q(1), q(0), q(0), q(0)),
        Quaternion::new(ratio(3, 5), ratio(4, 5), q(0), q(0)),
        Quaternion::new(ratio(-1, 3), ratio(2, 3), q(0), ratio(2, 3)),
    ];
    let s = [[q(0), q(0), q(0)], [q(1), q(2), q(0)], [q(3), q(-1), ratio(1, 2)]];
    let poses: Vec<_> = r.iter().zip(&s).map(|(r, s)| position(r, s)).collect();
    let t = [q(0), ratio(1, 3), q(1)];
    let m = trt_method(&elliptic_normalised(&r, &t).unwrap(), &poses, &t, 0).unwrap();
    assert_eq!(m.degree(), 3);
    for (p, ti) in poses.iter().zip(&t) {
        assert!(m.pose_exact(ti).unwrap().is_equivalent_exact(p));
    }
}

#[test]
fn trt_does_not_depend_on_the_moving_origin_tr_does() {
    let (poses, t) = instance(11, 3);
    let c = [ratio(1, 2), q(-2), ratio(3, 4)];
    // the moving origin moved by c: x' = x + c in the old frame, i.e. translate first
    let moved: Vec<_> = poses.iter().map(|p| &Pose::translation(&c) * p).collect();
    let rot = rot_of(&poses, &t);
    assert_eq!(rot, rot_of(&moved, &t)); // same rotational parts
    let (a, b) = (trt_method(&rot, &poses, &t, 1).unwrap(), trt_method(&rot, &moved, &t, 1).unwrap());
    // Result 5: the new motion is the old one after the fixed translation, as curves exactly:
    // B'_i = B_i * (1 + ε c/2)
    let shift = DualQuaternion::new(Quaternion::one(), Quaternion::pure(&c).scale(&ratio(1, 2)));
    let expect: Vec<_> = a.control().iter().map(|b| b * &shift).collect();
    assert_eq!(b.control(), expect.as_slice());
    for s in [ratio(1, 7), ratio(1, 2), ratio(5, 6)] {
        let expect = &Pose::translation(&c) * &a.pose_exact(&s).unwrap();
        assert!(b.pose_exact(&s).unwrap().is_equivalent_exact(&expect));
    }
    // Prop. 4: the TR motion of the moved positions is not the moved TR motion
    let (a, b) = (tr_method(&rot, &poses, &t).unwrap(), tr_method(&rot, &moved, &t).unwrap());
    let s = ratio(1, 3); // not a parameter t_i
    assert!(!t.contains(&s));
    let expect = &Pose::translation(&c) * &a.pose_exact(&s).unwrap();
    assert!(!b.pose_exact(&s).unwrap().is_equivalent_exact(&expect));
    // both still interpolate
    for (p, ti) in moved.iter().zip(&t) {
        assert!(b.pose_exact(ti).unwrap().is_equivalent_exact(p));
    }
}

#[test]
fn trt_errors_are_typed() {
    let (poses, t) = instance(3, 2);
    let rot = rot_of(&poses, &t);
    assert_eq!(trt_method(&rot, &poses, &t, 2), Err(JuttlerError::Split { l1: 2, max: 1 }));
    assert_eq!(trt_method(&rot, &poses[..1], &t[..1], 0), Err(JuttlerError::TooFewPositions { need: 2, got: 1 }));
    let tr = tr_method(&rot, &poses, &t).unwrap();
    assert!(matches!(trt_method(&tr, &poses, &t, 0), Err(JuttlerError::NotRotational { .. })));
    // the same orientation everywhere: U = |R|² I, a + b cannot be split (rank 3(m+1) - 3)
    let same: Vec<_> = [[q(0), q(0), q(0)], [q(1), q(0), q(0)], [q(0), q(2), q(1)]]
        .iter()
        .map(|s| position(&Quaternion::new(q(1), q(1), q(0), q(0)), s))
        .collect();
    // two positions: b along the relative rotation's axis, a = -Rot(t_i) b solve (34) with zero
    // right-hand side, always
    let t2 = [q(0), q(1)];
    let r2 = rot_of(&poses[..2], &t2);
    assert!(matches!(trt_method(&r2, &poses[..2], &t2, 0), Err(JuttlerError::SingularSystem { rank: 5, .. })));
    let rot = rot_of(&same, &t);
    assert_eq!(
        trt_method(&rot, &same, &t, 1),
        Err(JuttlerError::SingularSystem {
            system: "(34)",
            rank: 6,
            unknowns: 9,
            why: "the positions do not determine both translation curves (their relative rotations share an axis, as in a planar motion)"
        })
    );
}

#[test]
fn trt_in_f64_interpolates() {
    let poses = f64_poses();
    let t = [0.0, 0.3, 0.6, 1.0];
    for l1 in 0..3 {
        let m = trt(&poses, &t, l1).unwrap();
        for (p, ti) in poses.iter().zip(&t) {
            assert!(m.pose(ti).unwrap().is_equivalent(p, &1e-12).unwrap(), "l1 = {l1}");
        }
    }
}

#[test]
fn trt_refuses_nan_and_equal_parameters() {
    let mut poses = f64_poses();
    let t = [0.0, 0.3, 0.6, 1.0];
    assert!(matches!(trt(&poses, &[0.0, 0.3, 0.3, 1.0], 1), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(trt(&poses, &[0.0, f64::NAN, 0.6, 1.0], 1), Err(JuttlerError::Parameters { .. })));
    let rot = motion::juttler::rotational::elliptic(
        &poses.iter().map(|p| motion::juttler::tr::rotation_translation(p).unwrap().0).collect::<Vec<_>>(),
        &t,
    )
    .unwrap();
    poses[2] = Pose::translation(&[f64::NAN, 0.0, 0.0]);
    assert!(matches!(trt_method(&rot, &poses, &t, 1), Err(JuttlerError::Parameters { .. })));
}

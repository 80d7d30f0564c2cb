//! Jüttler's rotational interpolation (affine (19)-(21), elliptic (22)-(25)) and Algorithm 1
//! (elliptic + TR): interpolation exactly over rationals (as rigid motions, up to λ_i),
//! Proposition 2's invariance exactly, Proposition 1's dependence, Algorithm 1 in f64.

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::dual_quaternion::Quaternion;
use motion::juttler::rotational::{affine, elliptic, elliptic_normalised};
use motion::juttler::tr::{algorithm1, rotation_translation, tr_method};
use motion::juttler::{JuttlerError, Parametrisation, parameters};
use motion::{Motion, Pose};

fn quat(c: [Q; 4]) -> Quaternion<Q> {
    let [w, x, y, z] = c;
    Quaternion::new(w, x, y, z)
}

/// `a = λ b` for some `λ ≠ 0` (all 2x2 minors vanish).
fn proportional(a: &Quaternion<Q>, b: &Quaternion<Q>) -> bool {
    let (a, b) = ([&a.w, &a.x, &a.y, &a.z], [&b.w, &b.x, &b.y, &b.z]);
    (0..4).all(|k| (0..4).all(|l| a[k] * b[l] == a[l] * b[k])) && a.iter().any(|x| **x != q(0))
}

/// Rational unit quaternions (Pythagorean quadruples).
fn unit_rotations() -> Vec<Quaternion<Q>> {
    vec![
        quat([q(1), q(0), q(0), q(0)]),
        quat([ratio(3, 5), ratio(4, 5), q(0), q(0)]),
        quat([ratio(-1, 3), ratio(2, 3), q(0), ratio(2, 3)]),
        quat([ratio(2, 7), ratio(3, 7), ratio(-6, 7), q(0)]),
    ]
}

fn params() -> Vec<Q> {
    vec![q(0), ratio(1, 4), ratio(2, 3), q(1)]
}

#[test]
fn affine_interpolates_with_scalar_part_one() {
    let r = [quat([q(2), q(1), q(0), q(0)]), quat([q(1), q(0), q(3), q(-1)]), quat([q(-3), q(1), q(1), q(1)])];
    let t = [q(0), ratio(1, 3), q(1)];
    let rot = affine(&r, &t).unwrap();
    assert_eq!(rot.degree(), 2);
    assert!(rot.control().iter().all(|c| c.real.w == q(1)));
    for (ri, ti) in r.iter().zip(&t) {
        let v = rot.eval(ti).real;
        assert_eq!(v, ri.scale(&(q(1) / &ri.w)));
    }
    // (19): the scalar part is 1 everywhere
    assert_eq!(rot.eval(&ratio(5, 7)).real.w, q(1));
}

#[test]
fn affine_depends_on_the_fixed_orientation_elliptic_does_not() {
    let r = unit_rotations();
    let t = params();
    let d = quat([ratio(2, 3), ratio(-2, 3), ratio(1, 3), q(0)]); // |D| = 1
    let rotated: Vec<_> = r.iter().map(|x| &d * x).collect();
    // Proposition 2: elliptic(D R_i) = D elliptic(R_i), exactly
    let e = elliptic_normalised(&r, &t).unwrap();
    let de = elliptic_normalised(&rotated, &t).unwrap();
    for s in [ratio(1, 8), ratio(1, 2), ratio(9, 10)] {
        assert_eq!(de.eval(&s).real, &d * &e.eval(&s).real);
    }
    // Proposition 1: the affine result of D R_i is not D times the affine result (not even up to a factor)
    let a = affine(&r, &t).unwrap();
    let da = affine(&rotated, &t).unwrap();
    let s = ratio(1, 2);
    assert!(!proportional(&da.eval(&s).real, &(&d * &a.eval(&s).real)));
}

#[test]
fn elliptic_interpolates_up_to_the_sign_rule() {
    let mut r = unit_rotations();
    r[2] = r[2].scale(&q(-1)); // the sign rule (24) picks the other sign back where needed
    let e = elliptic_normalised(&r, &params()).unwrap();
    for (i, (ri, ti)) in r.iter().zip(params()).enumerate() {
        let v = e.eval(&ti).real;
        assert!(v == *ri || v == ri.scale(&q(-1)), "{i}");
        assert_eq!(v.norm_squared(), q(1)); // (22)
    }
    // neighbours on the same side (24)
    for w in params().windows(2) {
        assert!(e.eval(&w[0]).real.dot(&e.eval(&w[1]).real) >= q(0));
    }
}

#[test]
fn tr_with_exact_rotations_interpolates_the_positions_exactly() {
    // positions built from their dual quaternions: rotation R_i, translation s_i
    let s = [[q(0), q(0), q(0)], [q(1), q(2), q(0)], [q(3), q(-1), ratio(1, 2)], [q(0), q(4), q(2)]];
    let poses: Vec<Pose<Q>> = unit_rotations()
        .iter()
        .zip(&s)
        .map(|(r, s)| {
            let dq = gam_algebras::DualQuaternion::new(r.clone(), Quaternion::pure(s).scale(&ratio(1, 2)) * r.clone());
            motion::repr::dual_quaternion::from_dual_quaternion_exact(&dq).unwrap()
        })
        .collect();
    let t = params();
    for (p, si) in poses.iter().zip(&s) {
        assert_eq!(&rotation_translation(p).unwrap().1, si);
    }
    let rots: Vec<_> = poses.iter().map(|p| rotation_translation(p).unwrap().0).collect();
    for rot in [elliptic_normalised(&rots, &t).unwrap(), affine(&rots, &t).unwrap()] {
        let m = tr_method(&rot, &poses, &t).unwrap();
        assert_eq!(m.degree(), 6);
        assert!(m.study_polynomial().iter().all(|c| *c == q(0)));
        for (p, ti) in poses.iter().zip(&t) {
            assert!(m.pose_exact(ti).unwrap().is_equivalent_exact(p));
        }
    }
}

#[test]
fn tr_depends_on_the_moving_origin() {
    // Proposition 4: moving the moving frame's origin by c (P_i -> T_c P_i) changes the motion
    let p = [
        Pose::<f64>::identity(),
        Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &1.2, &[1.0, 2.0, 0.0]).unwrap(),
        Pose::from_axis_angle_translation(&[1.0, 1.0, 0.0], &0.7, &[3.0, 0.0, 1.0]).unwrap(),
    ];
    let c = [0.5, -1.0, 2.0];
    let moved: Vec<_> = p.iter().map(|s| Pose::translation(&c) * *s).collect();
    let t = [0.0, 0.5, 1.0];
    let (a, b) = (algorithm1(&p, &t).unwrap(), algorithm1(&moved, &t).unwrap());
    // the point c of the moving space under `a` and the origin under `b` are the same at t_i ...
    let ya = |s: f64| a.pose(&s).unwrap().transform_point(&c).unwrap();
    let yb = |s: f64| b.pose(&s).unwrap().transform_point(&[0.0; 3]).unwrap();
    for s in t {
        assert!((0..3).all(|i| (ya(s)[i] - yb(s)[i]).abs() < 1e-12));
    }
    // ... but not in between
    assert!((0..3).any(|i| (ya(0.25)[i] - yb(0.25)[i]).abs() > 1e-3));
}

#[test]
fn algorithm1_in_f64_passes_through_the_positions() {
    let p: Vec<Pose<f64>> = [
        ([0.0, 0.0, 1.0], 0.0, [0.0, 0.0, 0.0]),
        ([0.0, 1.0, 1.0], 1.0, [1.0, 2.0, 0.5]),
        ([1.0, 0.0, 0.0], 2.5, [2.0, -1.0, 1.0]),
        ([1.0, 2.0, 3.0], -3.0, [4.0, 0.0, 0.0]),
        ([0.0, 0.0, 1.0], 0.3, [5.0, 1.0, -2.0]),
    ]
    .iter()
    .map(|(a, phi, t)| Pose::from_axis_angle_translation(a, phi, t).unwrap())
    .collect();
    let t = parameters(&p, &Parametrisation::Centripetal).unwrap();
    let m = algorithm1(&p, &t).unwrap();
    assert_eq!(m.degree(), 8);
    for (pi, ti) in p.iter().zip(&t) {
        assert!(m.pose(ti).unwrap().is_equivalent(pi, &1e-12).unwrap());
    }
    // (22): the rotational part is a unit quaternion at every t_i, so |Q⁰(t_i)|² = 2² · 1
    for ti in &t {
        let r = m.eval(ti).real.norm_squared();
        assert!((r - 4.0).abs() < 1e-12, "{r}"); // |Q_trans⁰|² |R|² = 4
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let r = [quat([q(1), q(0), q(0), q(0)]), quat([q(0), q(0), q(1), q(0)])];
    assert_eq!(affine(&r, &[q(0), q(1)]).unwrap_err(), JuttlerError::AtInfinity { index: 1 });
    assert!(matches!(affine(&r, &[q(0)]), Err(JuttlerError::Parameters { .. })));
    let r = [quat([q(1), q(0), q(0), q(0)]), quat([q(1), q(0), q(1), q(0)])];
    assert!(matches!(affine(&r, &[q(1), q(1)]), Err(JuttlerError::Parameters { .. })));
    let z = [Quaternion::new(1.0, 0.0, 0.0, 0.0), Quaternion::new(0.0, 0.0, 0.0, 0.0)];
    assert_eq!(elliptic(&z, &[0.0, 1.0]).unwrap_err(), JuttlerError::ZeroQuaternion { index: 1 });
    assert!(matches!(algorithm1::<f64>(&[], &[]), Err(JuttlerError::TooFewPositions { .. })));
}

/// Equal parameters and a collocation matrix that is singular only in f64 get different errors:
/// `t = [0, 1e-17, 1]` is distinct, but the second pivot `2e-17` is below f64's threshold; over
/// Q the same (distinct) parameters solve exactly.
#[test]
fn equal_parameters_and_a_numerically_singular_system_are_told_apart() {
    let r = [quat([q(1), q(0), q(0), q(0)]), quat([q(1), q(0), q(1), q(0)]), quat([q(1), q(1), q(0), q(0)])];
    assert_eq!(
        affine(&r, &[q(0), q(1), q(1)]).unwrap_err(),
        JuttlerError::Parameters { why: "parameters 1 and 2 are equal".into() }
    );
    let tiny = ratio(1, 100_000_000_000_000_000);
    let exact = affine(&r, &[q(0), tiny.clone(), q(1)]).unwrap();
    assert_eq!(exact.eval(&tiny).real, r[1]);
    let rf =
        [Quaternion::new(1.0, 0.0, 0.0, 0.0), Quaternion::new(1.0, 0.0, 1.0, 0.0), Quaternion::new(1.0, 1.0, 0.0, 0.0)];
    let e = affine(&rf, &[0.0, 1e-17, 1.0]).unwrap_err();
    assert!(matches!(e, JuttlerError::NumericallySingular { unknowns: 3, .. }), "{e:?}");
    assert!(e.to_string().contains("numerically singular: the parameters are distinct"), "{e}");
    assert_eq!(
        affine(&rf, &[0.0, 1.0, 1.0]).unwrap_err(),
        JuttlerError::Parameters { why: "parameters 1 and 2 are equal".into() }
    );
}

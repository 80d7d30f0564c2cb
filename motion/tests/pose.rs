//! Poses: Lemmas 2.3-2.7 and Theorem 2.8 of Cross, Cripps and Mullineux (2022), the action on
//! points and directions against Rodrigues' formula and the G_{0123inf} sandwich, and 4x4
//! matrices both ways. Exact over rationals wherever no square root is involved.

use crate::common;

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{MpFloat, PrecisionGuard, Real, Ring};
use common::*;
use motion::{Even, MotionError, Pose, Pseudoscalar, pseudoscalar};
use proptest::prelude::*;

fn qpose(c: [i64; 8]) -> Pose<Q> {
    let [a, b, cc, d, e, f, g, h] = c.map(q);
    Pose::new(a, b, cc, d, e, f, g, h)
}

fn qpoint(p: [i64; 3]) -> [Q; 4] {
    [q(p[0]), q(p[1]), q(p[2]), q(1)]
}

fn mat_mul(a: &[[Q; 4]; 4], b: &[[Q; 4]; 4]) -> [[Q; 4]; 4] {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).map(|k| &a[i][k] * &b[k][j]).fold(q(0), |s, x| s + x)))
}

#[test]
fn conventions_rotor_translator_and_r_t_order() {
    // R for a = e3 is cos(φ/2) + sin(φ/2) e12 and turns e1 towards e2.
    let r = Pose::rotation(&[0.0, 0.0, 1.0], &1.0).unwrap();
    assert_eq!((r.scalar, r.e12), (0.5f64.cos(), 0.5f64.sin()));
    let p = r.transform_point(&[1.0, 0.0, 0.0]).unwrap();
    assert!((p[1] - 1.0f64.sin()).abs() < 1e-15);
    // S = R T rotates first, then translates: F_S(p) = Rot(p) + v.
    let s =
        Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2, &[5.0, 0.0, 0.0]).unwrap();
    let p = s.transform_point(&[1.0, 0.0, 0.0]).unwrap();
    assert!(diff_n(&p, &[5.0, 1.0, 0.0]) < 1e-15, "{p:?}");
}

/// Lemma 2.3: F_{UV} = F_V F_U, exactly over Q, on points, on the projective matrices, and
/// through the independent G_{0123inf} sandwich.
#[test]
fn lemma_2_3_composition_exact() {
    let u = qpose([1, 2, -1, 3, 4, -2, 1, 5]);
    let v = qpose([2, -1, 0, 1, -3, 1, 2, -1]);
    let uv = &u * &v;
    for p in [[0, 0, 0], [1, 2, 3], [-4, 0, 7]] {
        let x = qpoint(p);
        assert_eq!(uv.apply_homogeneous(&x), v.apply_homogeneous(&u.apply_homogeneous(&x)));
        let fp = uv.transform_point(&[q(p[0]), q(p[1]), q(p[2])]).unwrap();
        let step = v.transform_point(&u.transform_point(&[q(p[0]), q(p[1]), q(p[2])]).unwrap()).unwrap();
        assert_eq!(fp, step);
        assert_eq!(fp, cga_null_action(&uv, &[q(p[0]), q(p[1]), q(p[2])]).0);
    }
    assert_eq!(uv.to_homogeneous_matrix(), mat_mul(&v.to_homogeneous_matrix(), &u.to_homogeneous_matrix()));
    // The other order is a different transform here.
    assert_ne!((&v * &u).to_matrix().unwrap(), uv.to_matrix().unwrap());
}

/// Eqs. (6)-(9) against the generated G_{0123inf} sandwich, exactly, including the e0
/// coefficient α of Lemma 2.2(ii).
#[test]
fn closed_form_action_matches_cga_null_sandwich_exactly() {
    for c in [[1, 2, -1, 3, 4, -2, 1, 5], [0, 1, 0, 0, 3, 0, -2, 7], [3, 0, 0, 0, 1, 1, 1, 1]] {
        let s = qpose(c);
        for p in [[1, 0, 0], [2, -3, 5]] {
            let pq = [q(p[0]), q(p[1]), q(p[2])];
            let (image, w) = cga_null_action(&s, &pq);
            assert_eq!(s.transform_point(&pq).unwrap(), image);
            assert_eq!(w, s.pseudo_norm_squared().scalar);
        }
    }
}

#[test]
fn point_action_matches_rodrigues_plus_translation() {
    let cases = [
        ([1.0, 2.0, 3.0], 0.7, [1.0, -2.0, 0.5]),
        ([0.0, 0.0, 1.0], std::f64::consts::PI, [0.0, 0.0, 0.0]),
        ([1.0, -1.0, 0.5], 5.5, [100.0, -3.0, 2.0]),
        ([0.2, 0.1, -0.7], 1e-9, [0.0, 1.0, 0.0]),
    ];
    for (axis, phi, v) in cases {
        let s = Pose::from_axis_angle_translation(&axis, &phi, &v).unwrap();
        let scaled = s.scale_pseudoscalar(&Pseudoscalar::new(0.3, -2.0));
        for p in [[1.0, 0.0, 0.0], [0.5, -2.0, 3.0], [0.0, 0.0, 0.0]] {
            let expected = rodrigues(axis, phi, v, p);
            assert!(diff_n(&s.transform_point(&p).unwrap(), &expected) < 1e-13);
            assert!(diff_n(&scaled.transform_point(&p).unwrap(), &expected) < 1e-12);
            assert!(diff_n(&cga_null_action(&s, &p).0, &expected) < 1e-13);
            let dir = rodrigues(axis, phi, [0.0; 3], p);
            assert!(diff_n(&s.transform_direction(&p).unwrap(), &dir) < 1e-13);
        }
    }
}

/// Lemma 2.4: (i) the inverse (a - bω)/a² and (ii) the square roots ±(2a + bω)/(2√a), exactly
/// over Q where √a is rational; over f64 and 256-bit floats otherwise.
#[test]
fn lemma_2_4_pseudoscalar_inverse_and_square_roots() {
    let c = Pseudoscalar::new(ratio(9, 4), ratio(-5, 3));
    let inv = pseudoscalar::inverse(&c).unwrap();
    assert_eq!(&c * &inv, Pseudoscalar::new(q(1), q(0)));
    assert_eq!(inv, Pseudoscalar::new(ratio(4, 9), ratio(5, 3) * ratio(16, 81)));
    for root in [ratio(3, 2), ratio(-3, 2)] {
        let r = pseudoscalar::sqrt_with_root(&c, &root).unwrap();
        assert_eq!(&r * &r, c);
        assert_eq!(r.scalar, root);
    }
    assert!(matches!(pseudoscalar::inverse(&Pseudoscalar::new(q(0), q(2))), Err(MotionError::Pseudoscalar { .. })));
    let r = pseudoscalar::sqrt(&Pseudoscalar::new(2.0, 3.0)).unwrap();
    let back = r * r;
    assert!((back.scalar - 2.0f64).abs() < 1e-15 && (back.e123inf - 3.0f64).abs() < 1e-15);
    let _g = PrecisionGuard::new(256);
    let c = Pseudoscalar::new(MpFloat::from_i64(2), MpFloat::from_ratio(1, 3));
    let r = pseudoscalar::sqrt(&c).unwrap();
    let back = &r * &r;
    assert!(back.scalar.sub_ref(&c.scalar).magnitude() < 1e-75 && back.e123inf.sub_ref(&c.e123inf).magnitude() < 1e-75);
    assert!(pseudoscalar::sqrt(&Pseudoscalar::new(MpFloat::from_i64(-1), MpFloat::zero())).is_err());
}

/// Lemma 2.5: a non-singular pseudoscalar generates the identity; a singular one the zero
/// transform (an error here).
#[test]
fn lemma_2_5_pseudoscalar_transforms() {
    let c = Even::new(q(3), q(0), q(0), q(0), q(0), q(0), q(0), q(-7));
    assert_eq!(c.transform_point(&[q(1), q(2), q(3)]).unwrap(), [q(1), q(2), q(3)]);
    let z = Even::new(q(0), q(0), q(0), q(0), q(0), q(0), q(0), q(5));
    assert!(matches!(z.transform_point(&[q(1), q(2), q(3)]), Err(MotionError::Singular { .. })));
    assert_eq!(z.apply_homogeneous(&qpoint([1, 2, 3]))[..3], [q(0), q(0), q(0)]);
}

/// Lemma 2.6: (i) U = S/|S| is unitary and generates the same transform; (ii) V = rev(S)/|S|²
/// is the inverse (exactly over Q); singular S has neither.
#[test]
fn lemma_2_6_unitize_and_inverse() {
    let s = qpose([1, 2, -1, 3, 4, -2, 1, 5]);
    let v = s.try_inverse().unwrap();
    assert_eq!(&s * &v, Pose::identity());
    assert_eq!(&v * &s, Pose::identity());
    let sing = qpose([0, 0, 0, 0, 1, 2, 3, 4]);
    assert!(sing.is_singular());
    assert!(matches!(sing.try_inverse(), Err(MotionError::Singular { .. })));

    for s in sample_poses() {
        let u = s.unitize().unwrap();
        assert!(u.is_unitary(&1e-14), "{u}");
        let (ms, mu) = (s.to_matrix().unwrap(), u.to_matrix().unwrap());
        for i in 0..4 {
            assert!(diff_n(&ms[i], &mu[i]) < 1e-13);
        }
        let n = s.norm().unwrap();
        let n2 = n * n;
        assert!(
            diff_n(&[n2.scalar, n2.e123inf], &[s.pseudo_norm_squared().scalar, s.pseudo_norm_squared().e123inf])
                < 1e-13
        );
        assert!(n.scalar > 0.0);
        let prod = s * s.try_inverse().unwrap();
        assert!(diff(&prod, &Even::one()) < 1e-14);
    }
    let fsing = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0);
    assert!(fsing.norm().is_err() && fsing.unitize().is_err() && fsing.to_matrix().is_err());

    let _g = PrecisionGuard::new(256);
    let s = screw([1, 2, 2], MpFloat::from_ratio(7, 3), [3, -1, 4], 2)
        .scale_pseudoscalar(&Pseudoscalar::new(MpFloat::from_ratio(5, 2), MpFloat::from_ratio(-1, 7)));
    let u = s.unitize().unwrap();
    assert!(u.is_unitary(&MpFloat::from_f64(1e-74)));
    let prod = &s * &s.try_inverse().unwrap();
    assert!(diff(&prod, &Even::one()) < 1e-74);
}

/// Lemma 2.7: a pose generating the identity is a pseudoscalar, ±1 if unitary.
#[test]
fn lemma_2_7_identity_transform() {
    let id = [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    assert_eq!(Pose::from_matrix(&id, &1e-15).unwrap(), Pose::identity());
    let g = Pose::new(-2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 3.0);
    assert_eq!(g.to_matrix().unwrap(), id);
    assert_eq!(g.unitize().unwrap(), Pose::identity().scale(&-1.0));
}

/// Theorem 2.8: same non-zero transform ⇔ equivalent (V = γU, γ a non-singular pseudoscalar).
#[test]
fn theorem_2_8_equivalence() {
    // Exactly: γU is equivalent to U and has the same (rigid) matrix; a different transform is not.
    let u = qpose([1, 2, -1, 3, 4, -2, 1, 5]);
    for gamma in [Pseudoscalar::new(q(-3), q(2)), Pseudoscalar::new(ratio(1, 5), q(0)), Pseudoscalar::new(q(1), q(9))] {
        let v = u.scale_pseudoscalar(&gamma);
        assert!(u.is_equivalent_exact(&v) && v.is_equivalent_exact(&u));
        assert_eq!(u.to_matrix().unwrap(), v.to_matrix().unwrap());
    }
    let w = qpose([1, 2, -1, 3, 4, -2, 2, 5]);
    assert!(!u.is_equivalent_exact(&w));
    assert_ne!(u.to_matrix().unwrap(), w.to_matrix().unwrap());
    // A singular multiple (γ = ω) is not equivalent: F is the zero transform.
    assert!(!u.is_equivalent_exact(&u.scale_pseudoscalar(&Pseudoscalar::new(q(0), q(1)))));

    // Conversely: the pose recovered from U's matrix alone is equivalent to U.
    for s in sample_poses() {
        let back = Pose::from_matrix(&s.to_matrix().unwrap(), &1e-12).unwrap();
        assert!(back.is_equivalent(&s, &1e-12).unwrap(), "{s} vs {back}");
        let other = s * Pose::translation(&[1e-6, 0.0, 0.0]);
        assert!(!other.is_equivalent(&s, &1e-12).unwrap());
    }
    let sing = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    assert!(Pose::<f64>::identity().is_equivalent(&sing, &1e-12).is_err());
}

#[test]
fn matrix_round_trips_and_rejections() {
    for s in sample_poses() {
        let m = s.to_matrix().unwrap();
        let back = Pose::from_matrix(&m, &1e-12).unwrap();
        assert!(back.is_unitary(&1e-14) && back.scalar >= 0.0);
        let m2 = back.to_matrix().unwrap();
        for i in 0..4 {
            assert!(diff_n(&m[i], &m2[i]) < 1e-13);
        }
    }
    // Every branch of Shepperd's method: half turns about each axis and the identity.
    for axis in [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0], [1.0, 1.0, 1.0]] {
        let s = Pose::rotation(&axis, &std::f64::consts::PI).unwrap();
        let back = Pose::from_matrix(&s.to_matrix().unwrap(), &1e-12).unwrap();
        assert!(back.is_equivalent(&s, &1e-15).unwrap());
    }
    let good =
        Pose::from_axis_angle_translation(&[1.0, 2.0, 3.0], &0.4, &[1.0, 2.0, 3.0]).unwrap().to_matrix().unwrap();
    let not_rigid = |m: &[[f64; 4]; 4]| matches!(Pose::from_matrix(m, &1e-9), Err(MotionError::NotRigid { .. }));
    let mut scaled = good;
    (0..3).for_each(|i| (0..3).for_each(|j| scaled[i][j] *= 1.01));
    assert!(not_rigid(&scaled));
    let mut reflected = good;
    (0..4).for_each(|j| reflected[0][j] = -reflected[0][j]);
    assert!(not_rigid(&reflected));
    let mut bottom = good;
    bottom[3][0] = 0.5;
    assert!(not_rigid(&bottom));
    let mut nan = good;
    nan[1][1] = f64::NAN;
    assert!(matches!(Pose::from_matrix(&nan, &1e-9), Err(MotionError::NotFinite { .. })));
    // Exact: the projective matrix of a non-unit pose is α times the rigid one.
    let s = qpose([1, 2, -1, 3, 4, -2, 1, 5]);
    let (h, r) = (s.to_homogeneous_matrix(), s.to_matrix().unwrap());
    let alpha = s.pseudo_norm_squared().scalar;
    for i in 0..4 {
        for j in 0..4 {
            assert_eq!(h[i][j], &r[i][j] * &alpha);
        }
    }
}

#[test]
fn matrix_round_trip_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let s = screw([2, -1, 2], MpFloat::from_ratio(31, 10), [7, 1, -3], 3);
    let m = s.to_matrix().unwrap();
    let back = Pose::from_matrix(&m, &MpFloat::from_f64(1e-70)).unwrap();
    assert!(diff(&back, &s) < 1e-74 || diff(&back, &(-&s)) < 1e-74);
}

#[test]
fn constructor_errors() {
    assert_eq!(Pose::rotation(&[0.0, 0.0, 0.0], &1.0).unwrap_err(), MotionError::ZeroAxis);
    assert!(matches!(Pose::rotation(&[f64::NAN, 0.0, 0.0], &1.0), Err(MotionError::NotFinite { .. })));
    assert!(matches!(Pose::rotation(&[1.0, 0.0, 0.0], &f64::INFINITY), Err(MotionError::NotFinite { .. })));
    assert!(Pose::from_axis_angle_translation(&[1.0, 0.0, 0.0], &1.0, &[0.0, f64::NAN, 0.0]).is_err());
    // The axis is normalised.
    let a = Pose::rotation(&[0.0, 0.0, 5.0], &1.0).unwrap();
    assert!(a.is_unitary(&1e-15));
}

fn arb_pose() -> impl Strategy<Value = Pose<f64>> {
    (prop::array::uniform3(-1.0f64..1.0), 0.0f64..7.0, prop::array::uniform3(-10.0f64..10.0), 0.2f64..3.0, -2.0f64..2.0)
        .prop_filter("non-zero axis", |(a, ..)| a.iter().map(|x| x * x).sum::<f64>() > 1e-3)
        .prop_map(|(axis, phi, t, g0, g1)| {
            Pose::from_axis_angle_translation(&axis, &phi, &t).unwrap().scale_pseudoscalar(&Pseudoscalar::new(g0, g1))
        })
}

proptest! {
    #[test]
    fn prop_lemma_2_3_and_matrices(u in arb_pose(), v in arb_pose(), p in prop::array::uniform3(-5.0f64..5.0)) {
        let uv = u * v;
        let step = v.transform_point(&u.transform_point(&p).unwrap()).unwrap();
        prop_assert!(diff_n(&uv.transform_point(&p).unwrap(), &step) < 1e-10);
        let back = Pose::from_matrix(&uv.to_matrix().unwrap(), &1e-10).unwrap();
        prop_assert!(back.is_equivalent(&uv, &1e-10).unwrap());
        prop_assert!(diff(&(uv * uv.try_inverse().unwrap()), &Even::one()) < 1e-12);
    }

    #[test]
    fn prop_exact_composition_over_q(c in prop::array::uniform8(-9i64..9), d in prop::array::uniform8(-9i64..9), p in prop::array::uniform3(-9i64..9)) {
        let (u, v) = (qpose(c), qpose(d));
        let x = qpoint(p);
        prop_assert_eq!((&u * &v).apply_homogeneous(&x), v.apply_homogeneous(&u.apply_homogeneous(&x)));
        if !u.is_singular() {
            prop_assert_eq!(&u * &u.try_inverse().unwrap(), Pose::identity());
        }
    }
}

#[test]
fn real_trait_is_enough_for_jets() {
    // The same pose code over Jet<f64>: d/dφ of the image of e1 under a rotation about e3.
    let r = Pose::rotation(&v3(0, 0, 1, 1), &algebra_core::Jet::variable(0.3f64)).unwrap();
    let p = r.transform_point(&v3(1, 0, 0, 1)).unwrap();
    assert!((p[0].eps + 0.3f64.sin()).abs() < 1e-15 && (p[1].eps - 0.3f64.cos()).abs() < 1e-15);
    let _ = Real::abs(&p[0].re);
}

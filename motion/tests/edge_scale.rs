//! Poses of any finite size (issue 30): `λS` for λ from 1e-300 to 1e300 is the same transform
//! as `S`, and every method gives the right answer for it or a typed error, never Ok(NaN), a
//! wrong Ok(true) or an inverse of 0. References: hand computations (the quarter turn
//! `1 + e12` about e3) and the same call at unit scale (a power-of-ten rescaling is not exact
//! in binary, so it exercises more than the code's power-of-two path).

use crate::common;

use common::{Xorshift, centered};
use motion::{MotionError, Pose};

fn max_abs_diff(a: &[f64], b: &[f64]) -> f64 {
    a.iter().zip(b).map(|(x, y)| (x - y).abs()).fold(0.0, f64::max)
}

fn flat(m: &[[f64; 4]; 4]) -> Vec<f64> {
    m.iter().flatten().copied().collect()
}

/// `c (1 + e12)`: the quarter turn about e3 at scale `c` (rotor `cos 45° + sin 45° e12`, times `c√2`).
fn quarter_turn(c: f64) -> Pose<f64> {
    Pose::new(c, c, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)
}

#[test]
fn the_issue_reproducer_at_every_scale() {
    // hand computation: the quarter turn maps e1 to e2, e2 to -e1
    let want_matrix = [[0.0, -1.0, 0.0, 0.0], [1.0, 0.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    let turn = Pose::rotation(&[0.0, 0.0, 1.0], &std::f64::consts::FRAC_PI_2).unwrap();
    for c in [1e300, 1e-300, 1e-320, 1e200, 1e-200, f64::MAX / 2.0, 1.0] {
        let s = quarter_turn(c);
        let what = format!("scale {c:e}");
        assert!(!s.is_equivalent(&Pose::identity(), &1e-12).unwrap(), "{what}: a quarter turn is not the identity");
        assert!(s.is_equivalent(&turn, &1e-15).unwrap(), "{what}");
        assert!(turn.is_equivalent(&s, &1e-15).unwrap(), "{what}");
        assert!(max_abs_diff(&flat(&s.to_matrix().unwrap()), &flat(&want_matrix)) < 1e-15, "{what}");
        let p = s.transform_point(&[1.0, 2.0, 3.0]).unwrap();
        assert!(max_abs_diff(&p, &[-2.0, 1.0, 3.0]) < 1e-15, "{what}: {p:?}");
        let d = s.transform_direction(&[1.0, 0.0, 0.0]).unwrap();
        assert!(max_abs_diff(&d, &[0.0, 1.0, 0.0]) < 1e-15, "{what}: {d:?}");
        assert!(!s.is_singular(), "{what}");
        // S⁻¹ = rev(S)/|S|² = (1 - e12)/(2c): exactly representable for these c (or an overflow)
        match s.try_inverse() {
            Ok(inv) => {
                let want = 0.5 / c;
                assert!(want.is_finite(), "{what}");
                assert!(
                    (inv.scalar - want).abs() <= 1e-15 * want && (inv.e12 + want).abs() <= 1e-15 * want,
                    "{what}: {inv}"
                );
                assert!(inv.e13 == 0.0 && inv.e1inf == 0.0 && inv.e123inf == 0.0, "{what}: {inv}");
            }
            Err(e) => {
                assert!(!(0.5 / c).is_finite(), "{what}: {e}");
                assert!(matches!(e, MotionError::NotFinite { .. }), "{what}: {e}");
            }
        }
    }
}

#[test]
fn tiny_motors_are_not_singular() {
    for c in [1e-300, 1e-170, 5e-324] {
        let s: Pose<f64> = Pose::new(c, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
        assert!(!s.is_singular(), "{c:e}");
        let u = s.unitize().unwrap();
        assert!((u.scalar - 1.0).abs() < 1e-15 && u.components()[1..].iter().all(|x| **x == 0.0), "{c:e}: {u}");
        let id = flat(&Pose::<f64>::identity().to_matrix().unwrap());
        assert!(max_abs_diff(&flat(&s.to_matrix().unwrap()), &id) < 1e-15, "{c:e}");
    }
    assert!(Pose::new(0.0, 0.0, 0.0, 0.0, 1e-300, 0.0, 0.0, 0.0).is_singular());
}

#[test]
fn results_that_overflow_are_typed_errors() {
    // a translation by 1e308 then another by 1e308: the image overflows
    let t = Pose::translation(&[1e308, 0.0, 0.0]);
    assert!(matches!(t.transform_point(&[1e308, 0.0, 0.0]), Err(MotionError::NotFinite { .. })));
    assert_eq!(t.transform_point(&[-1e308, 0.0, 0.0]).unwrap(), [0.0, 0.0, 0.0]);
    let huge = Pose::new(1e-300, 0.0, 0.0, 0.0, 1e10, 0.0, 0.0, 0.0); // translation by 2e310
    assert!(matches!(huge.to_matrix(), Err(MotionError::NotFinite { .. })));
    assert!(matches!(huge.transform_point(&[0.0; 3]), Err(MotionError::NotFinite { .. })));
}

#[test]
fn random_poses_at_random_scales_act_the_same() {
    let mut rng = Xorshift(0x9e37_79b9_7f4a_7c15);
    for _ in 0..400 {
        let mut next = || centered(&mut rng);
        let axis = [next(), next(), next()];
        let s = Pose::from_axis_angle_translation(&axis, &(6.0 * next()), &[4.0 * next(), 4.0 * next(), 4.0 * next()])
            .unwrap();
        let e = (600.0 * next()).round() as i32;
        let lambda = 10f64.powi(e) * if next() < 0.0 { -1.0 } else { 1.0 };
        let scaled = s.scale(&lambda);
        let what = format!("{s} x {lambda:e}");
        let m = flat(&s.to_matrix().unwrap());
        assert!(max_abs_diff(&flat(&scaled.to_matrix().unwrap()), &m) < 1e-14, "{what}");
        let p = [next(), next(), next()];
        assert!(max_abs_diff(&scaled.transform_point(&p).unwrap(), &s.transform_point(&p).unwrap()) < 1e-14, "{what}");
        assert!(scaled.is_equivalent(&s, &1e-13).unwrap(), "{what}");
        // (λS)⁻¹ λS is the identity transform
        if let Ok(inv) = scaled.try_inverse() {
            let id = inv * scaled;
            assert!(
                max_abs_diff(&flat(&id.to_matrix().unwrap()), &flat(&Pose::<f64>::identity().to_matrix().unwrap()))
                    < 1e-13,
                "{what}"
            );
        } else {
            assert!(lambda.abs() < 1e-290, "{what}: only an inverse beyond the f64 range may fail");
        }
    }
}

#[test]
fn a_spline_through_parameters_1e300_apart_is_finite_and_hits_its_key_poses() {
    // the estimated velocity between t = 0 and 1e-300 is 1e300 (a unit step over 1e-300):
    // the motion is extreme (control points near 1e299) but finite, and evaluates right
    use motion::Motion;
    use motion::juttler::spline::algorithm2;
    let poses = [Pose::identity(), Pose::translation(&[1.0, 0.0, 0.0]), quarter_turn(1.0)];
    let params = [0.0, 1e-300, 1.0];
    let m = algorithm2(&poses, &params, None).unwrap();
    for (p, t) in poses.iter().zip(params) {
        assert!(m.pose(&t).unwrap().is_equivalent(p, &1e-15).unwrap(), "t = {t:e}");
    }
    for t in [5e-301, 0.25, 0.5, 0.75] {
        assert!(m.pose(&t).unwrap().is_finite(), "t = {t}");
    }
}

#[test]
fn from_matrix_validates_its_tolerance() {
    let shear = [[1.0, 1.5, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    let id = Pose::<f64>::identity().to_matrix().unwrap();
    for tol in [f64::NAN, -1e-12, f64::INFINITY] {
        for m in [&shear, &id] {
            let e = Pose::from_matrix(m, &tol).unwrap_err();
            assert!(matches!(e, MotionError::BadTolerance { op: "from_matrix", .. }), "{tol}: {e}");
        }
    }
    assert_eq!(Pose::from_matrix(&id, &0.0).unwrap(), Pose::identity());
    assert!(Pose::from_matrix(&shear, &1e300).is_ok(), "a finite tolerance is the caller's choice");
}

#[test]
fn reparametrized_over_the_whole_f64_range_evaluates_at_the_right_place() {
    use motion::{AdditiveBezier, Motion, Reparametrized};
    let inner = AdditiveBezier::new(vec![Pose::identity(), Pose::translation(&[2.0, 0.0, 0.0])]).unwrap();
    let m = Reparametrized::new(inner, [-1e308, 1e308]).unwrap();
    // t = 0 is the middle (inner 1/2), t = 5e307 three quarters: hand computation
    for (t, want) in [(0.0f64, 1.0f64), (5e307, 1.5), (-1e308, 0.0), (1e308, 2.0)] {
        assert!((m.inner_parameter(&t) - want / 2.0).abs() < 1e-15, "t = {t:e}");
        let p = m.pose(&t).unwrap().transform_point(&[0.0; 3]).unwrap();
        assert!(max_abs_diff(&p, &[want, 0.0, 0.0]) < 1e-15, "t = {t:e}: {p:?}");
    }
}

/// A dual quaternion `c ((1 + k) + ε i)` at any scale `c` is the quarter turn about z followed
/// by the translation `2 Q^ε Q̃⁰/|Q⁰|² = (1, 1, 0)` (hand computation); `|Q⁰|²` underflowed to
/// 0 below `c ≈ 1e-154`, and the reader refused it as "a zero real part".
#[test]
fn dual_quaternions_of_any_size_are_read() {
    use gam_algebras::DualQuaternion;
    use motion::repr::dual_quaternion::{from_dual_quaternion, study_cosine};
    let want = [[0.0, -1.0, 0.0, 1.0], [1.0, 0.0, 0.0, 1.0], [0.0, 0.0, 1.0, 0.0], [0.0, 0.0, 0.0, 1.0]];
    for c in [1.0, 1e-150, 1e-160, 1e-200, 1e-300, 1e-320, 1e150, 1e200, 1e300] {
        let q = DualQuaternion::from_coeffs([c, 0.0, 0.0, c, 0.0, c, 0.0, 0.0]);
        assert_eq!(study_cosine(&q), 0.0, "{c:e}");
        let s = from_dual_quaternion(&q, &1e-9).unwrap_or_else(|e| panic!("{c:e}: {e}"));
        let m = s.to_matrix().unwrap();
        assert!(max_abs_diff(&flat(&m), &flat(&want)) < 1e-15, "{c:e}: {m:?}");
        // off the Study quadric at every scale too (cosine 1/√2 between real and dual part)
        let off = DualQuaternion::from_coeffs([c, 0.0, 0.0, c, c, 0.0, 0.0, 0.0]);
        assert!((study_cosine(&off) - std::f64::consts::FRAC_1_SQRT_2).abs() < 1e-15, "{c:e}");
        assert!(from_dual_quaternion(&off, &1e-9).is_err(), "{c:e}");
    }
    let zero = DualQuaternion::from_coeffs([0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0]);
    assert!(matches!(from_dual_quaternion(&zero, &1e-9), Err(motion::repr::ReprError::ZeroRealPart)));
}

//! `UnitPose` (issue 31, item 1): a pose normalised once, whose action skips `1/α` and whose
//! slerp skips the normalisation of `rev(A) B`. Checked against independent references: the
//! generated `cga_null` sandwich for the action, the same slerp in 256-bit MPFR (careful path)
//! and, for its derivative in `t`, `S(t) log(rev(A) B)`; nalgebra in `nalgebra_conv.rs`'s
//! feature (below, `#[cfg]`). Inputs cross the thresholds of the direct paths (half-angles
//! near 0, at π/6, near π/2 and past it), with non-unit, huge and tiny poses before `to_unit`.

use crate::common;

use algebra_core::test_support::Xorshift;
use algebra_core::{MpFloat, PrecisionGuard, Real};
use common::{cga_null_action, diff, size, value_and_derivative};
use motion::{MotionError, Pose, Pseudoscalar, UnitPose};
use num_dual::Dual64;

/// Unit generators' poses `exp(θ n e123 + c einf)` at the half-angles that bracket the
/// thresholds of the direct paths, with translations up to 2 (and 10⁴ for every sixth).
fn unit_poses() -> Vec<Pose<f64>> {
    let mut rng = Xorshift(0x9E37_79B9_7F4A_7C15);
    let halves = [
        0.0,
        1e-12,
        2f64.powi(-10),
        0.3,
        std::f64::consts::FRAC_PI_6 - 1e-9,
        std::f64::consts::FRAC_PI_6 + 1e-9,
        std::f64::consts::FRAC_PI_4 - 1e-9,
        std::f64::consts::FRAC_PI_4 + 1e-9,
        1.0,
        std::f64::consts::FRAC_PI_2 - 1e-7,
        std::f64::consts::FRAC_PI_2 + 1e-7,
        2.0,
        3.1,
    ];
    common::generators_at(&mut rng, &halves, false).iter().map(|g| Pose::exp(g).unwrap()).collect()
}

/// The condition of the logarithm of `s` (grows like `1/sin θ` near a rotation by 2π).
fn log_condition(s: &Pose<f64>) -> f64 {
    let l = s.log().unwrap();
    1.0 / l.e12.hypot(l.e13).hypot(l.e23).sin().abs().max(0.05)
}

#[test]
fn to_unit_fails_with_typed_errors() {
    let singular = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0);
    assert!(matches!(singular.to_unit(), Err(MotionError::Singular { .. })));
    assert!(matches!(UnitPose::try_from(singular), Err(MotionError::Singular { .. })));
    assert!(matches!(UnitPose::try_from(&Pose::<f64>::zero()), Err(MotionError::Singular { .. })));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for k in 0..8 {
            let mut c = [1.0, 0.0, 0.0, 0.0, 0.5, 0.0, 0.0, 0.0];
            c[k] = bad;
            let s = Pose::from_array(c);
            assert!(matches!(s.to_unit(), Err(MotionError::NotFinite { .. })), "{s}");
        }
    }
}

#[test]
fn to_unit_is_unit_and_the_same_transform_at_any_scale() {
    let mut rng = Xorshift(11);
    for s in unit_poses() {
        for scale in [1.0, 3.0, -0.25, 1e300, 1e-300] {
            let gamma = Pseudoscalar::new(scale, scale * rng.symmetric());
            let v = s.scale_pseudoscalar(&gamma);
            let u = v.to_unit().unwrap_or_else(|e| panic!("{s} {scale} {gamma:?} {:?} {e}", v.components()));
            let n2 = u.pseudo_norm_squared();
            assert!((n2.scalar - 1.0).abs() <= 8.0 * f64::EPSILON, "{v}: α = {}", n2.scalar);
            assert!(n2.e123inf.abs() <= 8.0 * f64::EPSILON * size(u.as_pose()).max(1.0), "{v}: β = {}", n2.e123inf);
            assert!(u.is_equivalent(&s, &(2e-15 * size(&s).max(1.0))).unwrap(), "{v}");
        }
    }
}

#[test]
fn transform_point_equals_pose_transform_point_and_the_cga_sandwich() {
    let mut rng = Xorshift(0x2545_F491_4F6C_DD1D);
    for s in unit_poses() {
        let mut d = || rng.symmetric();
        // non-unit before the normalisation: 0.3 to 3 times a pseudoscalar with a dual part
        let v = s.scale_pseudoscalar(&Pseudoscalar::new(1.65 + 1.35 * d(), d()));
        let u = v.to_unit().unwrap();
        let p = [5.0 * d(), 5.0 * d(), 5.0 * d()];
        let fast = u.transform_point(&p);
        let general = v.transform_point(&p).unwrap();
        let (reference, _) = cga_null_action(&v, &p);
        let scale = reference.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for k in 0..3 {
            assert!((fast[k] - reference[k]).abs() <= 4e-15 * scale, "{v} on {p:?}: {fast:?} vs {reference:?}");
            assert!((fast[k] - general[k]).abs() <= 4e-15 * scale, "{v} on {p:?}: {fast:?} vs {general:?}");
        }
    }
}

#[test]
fn transform_point_of_a_non_finite_point_is_not_finite() {
    let u = Pose::from_axis_angle_translation(&[0.0, 0.0, 1.0], &0.5, &[1.0, 2.0, 3.0]).unwrap().to_unit().unwrap();
    for bad in [f64::NAN, f64::INFINITY] {
        let out = u.transform_point(&[bad, 0.0, 0.0]);
        assert!(out.iter().any(|x| !x.is_finite()), "{out:?}");
    }
    assert_eq!(UnitPose::identity().transform_point(&[1.0, -2.0, 3.0]), [1.0, -2.0, 3.0]);
}

#[test]
fn slerp_equals_the_256_bit_careful_path() {
    let _g = PrecisionGuard::new(256);
    let to_mp = |x: &Pose<f64>| x.map_scalar(&|c: &f64| MpFloat::from_f64(*c));
    let to_f64 = |x: &Pose<MpFloat>| x.map_scalar(&|c: &MpFloat| c.to_f64());
    let poses = unit_poses();
    let mut fallbacks = 0;
    for (i, a) in poses.iter().enumerate() {
        let b = &poses[(i * 7 + 3) % poses.len()];
        let (ua, ub) = (a.to_unit().unwrap(), b.to_unit().unwrap());
        let rel = ua.reverse() * *ub;
        fallbacks += usize::from(rel.scalar < 0.0);
        for t in [0.0, 0.25, 0.5, 1.0, 1.7] {
            let s = UnitPose::slerp(&ua, &ub, &t).unwrap();
            let reference = to_f64(&Pose::slerp(&to_mp(&ua), &to_mp(&ub), &MpFloat::from_f64(t)).unwrap());
            let input = size(&*ua).max(1.0) * size(&*ub).max(1.0) * log_condition(&rel);
            assert!(diff(&*s, &reference) <= 1e-14 * input, "slerp({ua:?}, {ub:?}, {t}): {s:?} vs {reference}");
            // unit, up to rounding
            let n2 = s.pseudo_norm_squared();
            assert!((n2.scalar - 1.0).abs() <= 1e-14 * log_condition(&rel), "{s:?}");
            assert!(n2.e123inf.abs() <= 1e-14 * input, "{s:?}");
        }
        // the MPFR unit poses take the general path; the same value
        let (ma, mb) = (to_mp(&ua).to_unit().unwrap(), to_mp(&ub).to_unit().unwrap());
        let mp = UnitPose::slerp(&ma, &mb, &MpFloat::from_f64(0.5));
        let general = Pose::slerp(&ma, &mb, &MpFloat::from_f64(0.5)).unwrap();
        assert!(diff(&to_f64(&mp.unwrap()), &to_f64(&general)) <= 1e-30 * size(&*ua).max(1.0) * size(&*ub).max(1.0));
    }
    // both signs of rev(A) B occur: the unit path and the element's long way
    assert!(fallbacks > 0 && fallbacks < poses.len(), "{fallbacks}");
}

#[test]
fn slerp_derivative_is_the_pose_times_the_log() {
    // d/dt A (rev(A) B)^t = A (rev(A) B)^t log(rev(A) B): the dual-number path against f64
    let poses = unit_poses();
    for (i, a) in poses.iter().enumerate() {
        let b = &poses[(i * 5 + 1) % poses.len()];
        let (ua, ub) = (a.to_unit().unwrap(), b.to_unit().unwrap());
        let rel = ua.reverse() * *ub;
        let lift = |u: &UnitPose<f64>| u.map_scalar(&|x: &f64| Dual64::from(*x)).to_unit().unwrap();
        let (da, db) = (lift(&ua), lift(&ub));
        for t in [0.0, 0.3, 0.5, 1.0] {
            let s = UnitPose::slerp(&da, &db, &Dual64::new(t, 1.0)).unwrap();
            let (value, derivative) = value_and_derivative(&s);
            let expected_value = UnitPose::slerp(&ua, &ub, &t).unwrap().into_pose();
            let expected = expected_value * rel.log().unwrap();
            let scale = size(&*ua).max(1.0) * size(&*ub).max(1.0) * log_condition(&rel);
            // the value as the f64 path's, to the bound of the MPFR comparison above: the dual
            // numbers' arctangent (the long way, S∅ < 0) is libm's, the f64 one the inlined kernel
            assert!(diff(&value, &expected_value) <= 1e-14 * scale, "{ua:?} {ub:?} {t}");
            assert!(
                diff(&derivative, &expected) <= 1e-13 * scale * size(&expected).max(1.0),
                "{ua:?} {ub:?} {t}: {derivative} vs {expected}"
            );
        }
    }
}

#[test]
fn slerp_ends_and_errors() {
    let a = Pose::rotation(&[1.0, 2.0, 0.0], &0.4).unwrap().to_unit().unwrap();
    let b = Pose::from_axis_angle_translation(&[0.0, 1.0, 1.0], &2.5, &[3.0, -1.0, 2.0]).unwrap().to_unit().unwrap();
    assert!(diff(&*UnitPose::slerp(&a, &b, &0.0).unwrap(), &*a) <= 1e-15);
    assert!(diff(&*UnitPose::slerp(&a, &b, &1.0).unwrap(), &*b) <= 4e-15 * size(&*b));
    for bad in [f64::NAN, f64::INFINITY] {
        assert!(matches!(UnitPose::slerp(&a, &b, &bad), Err(MotionError::NotFinite { .. })), "{bad}");
    }
}

#[cfg(feature = "nalgebra")]
#[test]
fn transform_point_equals_nalgebra() {
    use nalgebra::Point3;
    let mut rng = Xorshift(5);
    for s in unit_poses() {
        let mut d = || rng.symmetric();
        let v = s.scale(&(0.5 + d().abs()));
        let u = v.to_unit().unwrap();
        let q = v.to_unit_dual_quaternion().unwrap();
        let p = [4.0 * d(), 4.0 * d(), 4.0 * d()];
        let (fast, reference) = (u.transform_point(&p), q.transform_point(&Point3::new(p[0], p[1], p[2])));
        let scale = fast.iter().fold(1.0f64, |m, x| m.max(x.abs()));
        for k in 0..3 {
            assert!((fast[k] - reference[k]).abs() <= 4e-15 * scale, "{v} on {p:?}: {fast:?} vs {reference}");
        }
    }
}

#[test]
fn power_and_slerp_of_poses_unit_in_value_keep_the_derivative_of_the_norm() {
    // Pose::power and Pose::slerp take the unit form when rev(S) S = 1 up to rounding; over
    // dual numbers every part must be: S = (1 + kε) U is unit in value, and
    // d/dε S^t = t k U^t, d/dε slerp(S, B; t) = (1 + t) k slerp(U, B; t) (eq. 16).
    for (i, u) in unit_poses().iter().enumerate() {
        let u = u.to_unit().unwrap();
        let b = unit_poses()[(i * 3 + 2) % unit_poses().len()].to_unit().unwrap();
        let k = 0.75;
        let s = u.map_scalar(&|x: &f64| Dual64::new(*x, k * x));
        let lift = |p: &Pose<f64>| p.map_scalar(&|x: &f64| Dual64::from(*x));
        for t in [0.3, 1.0] {
            let scale = size(&*u).max(1.0) * size(&*b).max(1.0);
            if u.scalar >= 0.0 {
                let (value, derivative) = value_and_derivative(&s.power(&Dual64::from(t)).unwrap());
                let expected = u.power(&t).unwrap();
                assert!(diff(&value, &expected) <= 1e-14 * scale, "{u:?} {t}");
                assert!(diff(&derivative, &expected.scale(&(t * k))) <= 1e-14 * scale, "{u:?} {t}: {derivative}");
            }
            let (value, derivative) = value_and_derivative(&Pose::slerp(&s, &lift(&b), &Dual64::from(t)).unwrap());
            let expected = Pose::slerp(&u, &b, &t).unwrap();
            let cond = log_condition(&(u.reverse() * *b));
            assert!(diff(&value, &expected) <= 1e-14 * scale * cond, "{u:?} {b:?} {t}");
            let d = expected.scale(&((1.0 + t) * k));
            assert!(diff(&derivative, &d) <= 1e-14 * scale * cond, "{u:?} {b:?} {t}: {derivative} vs {d}");
        }
    }
}

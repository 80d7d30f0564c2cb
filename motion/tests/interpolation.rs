//! Powers, slerp (eq. 15) and the additive interpolation (eq. 17): endpoints, constant speed,
//! eq. (16) and its hidden hypothesis, exact additive motions over Q.

use crate::common;

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{MpFloat, PrecisionGuard, Ring};
use common::*;
use motion::{Even, Pose, Pseudoscalar, pseudoscalar};
use proptest::prelude::*;

fn bivector_norm(m: &Even<f64>) -> f64 {
    [m.e12, m.e13, m.e23, m.e1inf, m.e2inf, m.e3inf].iter().map(|x| x * x).sum::<f64>().sqrt()
}

fn unit_pair() -> (Pose<f64>, Pose<f64>) {
    let a = Pose::from_axis_angle_translation(&[1.0, 0.5, -0.2], &0.8, &[1.0, 2.0, -1.0]).unwrap();
    let b = Pose::from_axis_angle_translation(&[-0.3, 1.0, 0.4], &2.9, &[-2.0, 0.5, 4.0]).unwrap();
    (a, b)
}

#[test]
fn power_laws() {
    let s = Pose::from_axis_angle_translation(&[1.0, 2.0, 3.0], &2.0, &[1.0, -1.0, 2.0]).unwrap().scale(&1.5);
    assert!(diff(&s.power(&1.0).unwrap(), &s) < 1e-14);
    assert!(diff(&s.power(&0.0).unwrap(), &Even::one()) < 1e-15);
    let prod = s.power(&0.3).unwrap() * s.power(&0.45).unwrap();
    assert!(diff(&prod, &s.power(&0.75).unwrap()) < 1e-14);
    let sq = s.power(&0.5).unwrap();
    assert!(diff(&(sq * sq), &s) < 1e-14);
    assert!(diff(&s.power(&-1.0).unwrap(), &s.try_inverse().unwrap()) < 1e-14);
}

#[test]
fn slerp_endpoints() {
    let (a, b) = unit_pair();
    assert!(diff(&Pose::slerp(&a, &b, &0.0).unwrap(), &a) < 1e-15);
    assert!(diff(&Pose::slerp(&a, &b, &1.0).unwrap(), &b) < 1e-14);
    // Unitary throughout.
    for t in [0.1, 0.5, 0.9] {
        assert!(Pose::slerp(&a, &b, &t).unwrap().is_unitary(&1e-14));
    }
    // Non-unit A: S(1) = |A|² B, equivalent to B but not equal (the paper's remark needs
    // unitary A); unitizing A first restores S(1) = B.
    let a2 = a.scale_pseudoscalar(&Pseudoscalar::new(2.0, 0.7));
    let end = Pose::slerp(&a2, &b, &1.0).unwrap();
    assert!(diff(&end, &b) > 0.1);
    assert!(end.is_equivalent(&b, &1e-13).unwrap());
    assert!(diff(&end, &b.scale_pseudoscalar(&a2.pseudo_norm_squared())) < 1e-13);
    let end = Pose::slerp(&a2.unitize().unwrap(), &b, &1.0).unwrap();
    assert!(diff(&end, &b) < 1e-14);
}

/// |log(rev(S(t)) S(t + h))| is the same for every t: slerp moves at constant speed.
#[test]
fn slerp_has_constant_speed() {
    let (a, b) = unit_pair();
    let h = 0.01;
    let speeds: Vec<f64> = (0..=99)
        .map(|i| {
            let t = f64::from(i) / 100.0;
            let s0 = Pose::slerp(&a, &b, &t).unwrap();
            let s1 = Pose::slerp(&a, &b, &(t + h)).unwrap();
            bivector_norm(&(s0.reverse() * s1).log().unwrap())
        })
        .collect();
    let first = speeds[0];
    assert!(first > 1e-3);
    assert!(speeds.iter().all(|v| (v - first).abs() < 1e-12), "{speeds:?}");
}

/// The same at 256 bits.
#[test]
fn slerp_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let a = screw([1, 2, 2], MpFloat::from_ratio(4, 5), [1, 2, -1], 1);
    let b = screw([-3, 1, 4], MpFloat::from_ratio(29, 10), [-4, 1, 8], 2);
    let end = Pose::slerp(&a, &b, &MpFloat::one()).unwrap();
    assert!(diff(&end, &b) < 1e-70);
    let h = MpFloat::from_ratio(1, 10);
    let speed = |t: MpFloat| {
        let s0 = Pose::slerp(&a, &b, &t).unwrap();
        let s1 = Pose::slerp(&a, &b, &t.add_ref(&h)).unwrap();
        (&s0.reverse() * &s1).log().unwrap()
    };
    let (v0, v1) = (speed(MpFloat::zero()), speed(MpFloat::from_ratio(7, 10)));
    assert!(diff(&v0, &v1) < 1e-70);
}

/// Eq. (16): Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t) for pseudoscalars α, β — it holds when α and
/// β have positive scalar parts (so that log(αβX) = log α + log β + log X); with α = -1 it
/// fails: -A turns the other way round.
#[test]
fn eq_16_pseudoscalar_factors() {
    let (a, b) = unit_pair();
    let pow = |c: &Pseudoscalar<f64>, t: f64| {
        let l = pseudoscalar::ln(c).unwrap();
        pseudoscalar::exp(&Pseudoscalar::new(l.scalar * t, l.e123inf * t))
    };
    let (al, be) = (Pseudoscalar::new(1.7, -0.4), Pseudoscalar::new(0.6, 2.0));
    for t in [0.0, 0.3, 1.0] {
        let lhs = Pose::slerp(&a.scale_pseudoscalar(&al), &b.scale_pseudoscalar(&be), &t).unwrap();
        let factor = pow(&al, 1.0 + t) * pow(&be, t);
        let rhs = Pose::slerp(&a, &b, &t).unwrap().scale_pseudoscalar(&factor);
        assert!(diff(&lhs, &rhs) < 1e-13, "t {t}");
    }
    let neg = Pose::slerp(&-&a, &b, &0.5).unwrap();
    let pos = Pose::slerp(&a, &b, &0.5).unwrap();
    assert!(!neg.is_equivalent(&pos, &1e-6).unwrap());
}

/// Eq. (17), exactly over Q: endpoints, a non-unit interior, and the zero transform where the
/// motion passes through a singular pseudoscalar.
#[test]
fn lerp_exact() {
    let a = Pose::<Q>::rotor_from_parts(&q(1), &q(2), &[q(1), q(0), q(0)]) * Pose::translation(&[q(1), q(2), q(3)]);
    let b = Pose::<Q>::translation(&[q(-2), q(0), q(5)]);
    assert_eq!(Pose::lerp(&a, &b, &q(0)), a);
    assert_eq!(Pose::lerp(&a, &b, &q(1)), b);
    let mid = Pose::lerp(&a, &b, &ratio(1, 3));
    assert!(!mid.is_singular());
    assert_eq!(mid.transform_point(&[q(0), q(0), q(0)]).unwrap(), cga_null_action(&mid, &[q(0), q(0), q(0)]).0);
    let one = Pose::<Q>::identity();
    let through_zero = Pose::lerp(&one, &-&one, &ratio(1, 2));
    assert!(through_zero.is_singular());
    assert!(through_zero.transform_point(&[q(1), q(1), q(1)]).is_err());
}

fn arb_unit() -> impl Strategy<Value = Pose<f64>> {
    (prop::array::uniform3(-1.0f64..1.0), 0.0f64..6.0, prop::array::uniform3(-5.0f64..5.0))
        .prop_filter("non-zero axis", |(a, ..)| a.iter().map(|x| x * x).sum::<f64>() > 1e-3)
        .prop_map(|(axis, phi, t)| Pose::from_axis_angle_translation(&axis, &phi, &t).unwrap())
}

proptest! {
    #[test]
    fn prop_slerp_endpoints_and_speed(a in arb_unit(), b in arb_unit(), t in 0.0f64..0.9) {
        // Away from the ill-conditioned 2π relative rotation.
        let rel = a.reverse() * b;
        prop_assume!(rel.scalar > -0.99);
        prop_assert!(diff(&Pose::slerp(&a, &b, &1.0).unwrap(), &b) < 1e-11);
        let h = 0.1;
        let v = |t: f64| {
            let s0 = Pose::slerp(&a, &b, &t).unwrap();
            bivector_norm(&(s0.reverse() * Pose::slerp(&a, &b, &(t + h)).unwrap()).log().unwrap())
        };
        prop_assert!((v(t) - v(0.0)).abs() < 1e-9);
    }
}

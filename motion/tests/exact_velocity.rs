//! An additive motion over exact rationals and its velocity indicatrix through the same
//! `Motion` API as floats (`velocity_indicatrix` lifts the motion to `Jet<Q>` by
//! `MapScalar`): exact equality with the hand-derived closed form.

use algebra_core::rational::{Q, q, ratio};
use motion::velocity::{velocity, velocity_bivector, velocity_indicatrix};
use motion::{AdditiveBezier, Bivector, Even, Motion, Pose};

/// `S(t) = (1 - t) S0 + t S1` with `S0 = 1`, `S1 = 1 + e12 + e1inf`: `S = 1 + t(e12 + e1inf)`,
/// `rev(S) S = 1 + t²` (no ω part), so `Ψ = 2 rev(S) S'/(1 + t²) = 2(t + e12 + e1inf)/(1 + t²)`
/// (by hand: `e12 e12 = -1`, `e12 e1inf = -e2inf`, `e1inf e12 = e2inf`, `e1inf e1inf = 0`).
fn expected_psi(t: &Q) -> Even<Q> {
    let c = q(2) / (q(1) + t.clone() * t.clone());
    Even::new(c.clone() * t.clone(), c.clone(), q(0), q(0), c, q(0), q(0), q(0))
}

fn line() -> AdditiveBezier<Q> {
    let s1 = Pose::new(q(1), q(1), q(0), q(0), q(1), q(0), q(0), q(0));
    AdditiveBezier::new(vec![Pose::identity(), s1]).unwrap()
}

#[test]
fn additive_indicatrix_over_rationals_is_exact() {
    let m = line();
    for t in [q(0), ratio(1, 2), ratio(2, 7), q(1)] {
        assert_eq!(m.pose(&t).unwrap(), Pose::new(q(1), t.clone(), q(0), q(0), t.clone(), q(0), q(0), q(0)));
        assert_eq!(velocity_indicatrix(&m, &t).unwrap(), expected_psi(&t), "t = {t}");
    }
    // t = 1/2: Ψ = 4/5 + 8/5 e12 + 8/5 e1inf; ν its bivector part, γ = 4/5.
    let half = ratio(1, 2);
    let nu = velocity_bivector(&m, &half).unwrap();
    assert_eq!(nu, Bivector::new(ratio(8, 5), q(0), q(0), ratio(8, 5), q(0), q(0)));
    let v = velocity(&m, &half).unwrap();
    assert_eq!(v.derivative, Even::new(q(0), q(1), q(0), q(0), q(1), q(0), q(0), q(0)));
    assert_eq!(v.indicatrix.scalar, ratio(4, 5));
    // the end indicatrices of eq. (20) agree with Ψ(0) and Ψ(1)
    assert_eq!(m.end_indicatrices().unwrap(), [expected_psi(&q(0)), expected_psi(&q(1))]);
    // outside [0, 1]: a typed error, as over floats
    assert!(velocity_indicatrix(&m, &q(2)).is_err());
}

#[test]
fn degree_elevation_keeps_the_exact_indicatrix() {
    // the same motion as a cubic: de Casteljau over Jet<Q> through three levels
    let m = line().elevated().elevated();
    assert_eq!(m.degree(), 3);
    for t in [ratio(1, 3), ratio(3, 4)] {
        assert_eq!(velocity_indicatrix(&m, &t).unwrap(), expected_psi(&t), "t = {t}");
    }
}

#[test]
fn piecewise_additive_motion_over_rationals_is_exact() {
    use motion::Piecewise;
    // segment 0: translation 0 -> 4 e1 over [0, 1/2]; segment 1: 4 e1 -> 4 e1 + 6 e2 over [1/2, 2]
    let tr = |x: i64, y: i64| Pose::translation(&[q(x), q(y), q(0)]);
    let a = AdditiveBezier::new(vec![tr(0, 0), tr(4, 0)]).unwrap();
    let b = AdditiveBezier::new(vec![tr(4, 0), tr(4, 6)]).unwrap();
    let m = Piecewise::new(vec![q(0), ratio(1, 2), q(2)], vec![a, b]).unwrap();
    assert_eq!(m.domain(), [q(0), q(2)]);
    // t = 1/8: a quarter through segment 0; t = 1: a third through segment 1 (both by hand)
    assert_eq!(m.pose(&ratio(1, 8)).unwrap(), tr(1, 0));
    assert_eq!(m.pose(&q(1)).unwrap(), tr(4, 2));
    assert_eq!(m.pose(&ratio(1, 2)).unwrap(), tr(4, 0));
    assert!(m.pose(&ratio(9, 4)).is_err());
    // breakpoints must increase: a typed error over Q as over floats
    let c = AdditiveBezier::new(vec![tr(0, 0), tr(1, 0)]).unwrap();
    assert!(Piecewise::new(vec![q(1), q(1)], vec![c]).is_err());
}

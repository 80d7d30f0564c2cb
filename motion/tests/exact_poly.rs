//! An additive motion over polynomials (`Poly`, symbolic parameter `t` and a symbolic control
//! coefficient `a`) through the generic `Motion` API, and its derivative through `Jet<Poly>`
//! (`MapScalar`): both equal the hand-derived polynomials, `S'` also equals the term-wise
//! derivative `Poly::derivative` (a second route), and the ring part of the velocity,
//! `Ψ |S|² = 2 rev(S) S'` (`|S|² = rev(S) S`, a pseudoscalar here), agrees after substitution
//! with the velocity indicatrix the library computes over exact rationals.

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Jet, Poly, Ring};
use motion::velocity::velocity_indicatrix;
use motion::{Additive, Bezier, MapScalar, Motion, Pose};

fn p(n: i64) -> Poly {
    Poly::from_ratio(n, 1)
}

/// `S0 = 1`, `S1 = 1 + a e12`, `S2 = 1 + e3inf`, over any ring (`a` given).
fn controls<T: Ring>(a: T) -> Vec<Pose<T>> {
    let (z, o) = (T::zero(), T::one());
    vec![
        Pose::identity(),
        Pose::new(o.clone(), a, z.clone(), z.clone(), z.clone(), z.clone(), z.clone(), z.clone()),
        Pose::new(o, z.clone(), z.clone(), z.clone(), z.clone(), z.clone(), T::one(), z),
    ]
}

/// The pose with coefficients `(scalar, e12, e3inf, e123inf)`, the rest zero.
fn pose4<T: Ring>(s: T, e12: T, e3inf: T, w: T) -> Pose<T> {
    Pose::new(s, e12, T::zero(), T::zero(), T::zero(), T::zero(), e3inf, w)
}

/// By hand (Bernstein, eq. 18): `S = (1-t)² + 2t(1-t)(1 + a e12) + t²(1 + e3inf)
/// = 1 + b e12 + c e3inf` with `b = 2a(t - t²)`, `c = t²`; `S' = b' e12 + c' e3inf` with
/// `b' = 2a(1 - 2t)`, `c' = 2t`. With `e12 e12 = -1`, `e3inf e3inf = 0` and
/// `e12 e3inf = e3inf e12 = ω`: `rev(S) S = 1 + b² - 2bc ω` and
/// `2 rev(S) S' = 2bb' + 2b' e12 + 2c' e3inf - 2(bc' + cb') ω`.
struct Hand {
    b: Poly,
    c: Poly,
    db: Poly,
    dc: Poly,
}

fn hand(a: &Poly, t: &Poly) -> Hand {
    let two = p(2);
    let b = two.clone() * a.clone() * (t.clone() - t.clone() * t.clone());
    let db = two.clone() * a.clone() * (p(1) - two.clone() * t.clone());
    Hand { b, c: t.clone() * t.clone(), db, dc: two * t.clone() }
}

#[test]
fn additive_bezier_over_poly_and_its_derivative_through_jet() {
    let (a, t) = (Poly::var("a"), Poly::var("t"));
    let m: Bezier<Poly, Additive> = Bezier::new(controls(a.clone())).unwrap();
    let h = hand(&a, &t);
    let zero = Poly::zero();
    // S(t) through Motion::evaluate at the symbolic t (pose() needs an order; evaluate does not)
    let s = m.evaluate(&t).unwrap();
    assert_eq!(s, pose4(p(1), h.b.clone(), h.c.clone(), zero.clone()));
    // S'(t) through Jet<Poly>: the motion lifted by MapScalar, evaluated at t + ε
    let lifted = m.map_scalar(&|x: &Poly| Jet::constant(x.clone()));
    let jet = lifted.evaluate(&Jet::variable(t.clone())).unwrap();
    let (value, ds) = (jet.map_scalar(&|x: &Jet<Poly>| x.re.clone()), jet.map_scalar(&|x: &Jet<Poly>| x.eps.clone()));
    assert_eq!(value, s);
    assert_eq!(ds, pose4(zero.clone(), h.db.clone(), h.dc.clone(), zero.clone()));
    // a second route to S': the term-wise derivative of each coefficient of S(t)
    assert_eq!(ds, s.map_scalar(&|x: &Poly| x.derivative("t")));
    // |S|² = rev(S) S and 2 rev(S) S' (Ψ |S|², the ring part of the velocity)
    let norm2 = &s.reverse() * &s;
    let two = p(2);
    let w = two.clone() * h.b.clone() * h.c.clone();
    assert_eq!(norm2, pose4(p(1) + h.b.clone() * h.b.clone(), zero.clone(), zero.clone(), zero.clone() - w));
    let psi_norm2 = (&s.reverse() * &ds).scale(&two);
    let wd = two.clone() * (h.b.clone() * h.dc.clone() + h.c.clone() * h.db.clone());
    let want = pose4(two.clone() * h.b.clone() * h.db.clone(), two.clone() * h.db, two * h.dc, zero - wd);
    assert_eq!(psi_norm2, want);

    // After substituting rationals for a and t: Ψ (from the library over Q) times |S|² is the
    // substituted polynomial 2 rev(S) S'.
    for (av, tv) in [(ratio(3, 2), ratio(1, 3)), (q(-2), ratio(3, 4)), (ratio(1, 5), q(1))] {
        let sub = |x: &Poly| x.substitute("a", &Poly::from_q(&av)).substitute("t", &Poly::from_q(&tv));
        let mq: Bezier<Q, Additive> = Bezier::new(controls(av.clone())).unwrap();
        let psi = velocity_indicatrix(&mq, &tv).unwrap();
        let sq = mq.evaluate(&tv).unwrap();
        let lhs = &psi * &(&sq.reverse() * &sq);
        let lhs = lhs.map_scalar(&|x: &Q| Poly::from_q(x));
        assert_eq!(lhs, psi_norm2.map_scalar(&sub), "a = {av}, t = {tv}");
    }
}

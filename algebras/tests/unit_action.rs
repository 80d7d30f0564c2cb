//! `apply_unit` / `sandwich_unit` (the `UnitAction` kernels for unit versors) against the
//! runtime sandwich `S x rev(S)` / `rev(S) x S` of `algebra_core::Multivector`, exactly over
//! rationals, on unit versors built as products of rational unit vectors (every versor is
//! one): pga3 and g123inf motors (four planes with translation parts), cga-null poses, g3
//! rotors, cga even and odd versors (vectors of square 1 with an e5 part). A non-unit motor
//! shows the kernels rely on the unit condition.

use algebra_core::Multivector as Mv;
use algebra_core::rational::{Q, q, ratio};
use gam_algebras::{cga, cga_null, g3, g123inf, pga3};
use proptest::prelude::*;

fn small() -> BoxedStrategy<Q> {
    prop_oneof![1 => Just(q(0)), 4 => (-6i64..=6, 1i64..=4).prop_map(|(n, d)| ratio(n, d))].boxed()
}

/// A rational point on the unit sphere of `R^(u.len() + 1)` (inverse stereographic projection).
fn unit_vector(u: &[Q]) -> Vec<Q> {
    let s: Q = u.iter().map(|x| x * x).sum();
    let den = &s + q(1);
    let mut v: Vec<Q> = u.iter().map(|x| q(2) * x / &den).collect();
    v.push((s - q(1)) / den);
    v
}

/// The product of the runtime multivectors.
fn product(factors: &[Mv<Q>]) -> Mv<Q> {
    factors[1..].iter().fold(factors[0].clone(), |acc, f| &acc * f)
}

/// Checks both unit kernels of versor `$s` (a runtime multivector, exactly unit) on `$x`.
macro_rules! check_unit {
    ($v:ty, $x:ty, $s:expr, $coeffs:expr) => {{
        let s_mv: &Mv<Q> = $s;
        let s = <$v>::try_from(s_mv).expect("the versor has the declared type");
        let mut x = <$x>::zero();
        for (slot, c) in x.iter_mut().zip($coeffs.iter().cycle()) {
            *slot = c.clone();
        }
        let x_mv = x.to_multivector();
        let apply = <$x>::try_from(&product(&[s_mv.clone(), x_mv.clone(), s_mv.reverse()])).expect("grade kept");
        let sandwich = <$x>::try_from(&product(&[s_mv.reverse(), x_mv, s_mv.clone()])).expect("grade kept");
        prop_assert_eq!(s.apply_unit(&x), apply, "apply_unit {} on {}", stringify!($v), stringify!($x));
        prop_assert_eq!(s.sandwich_unit(&x), sandwich, "sandwich_unit {} on {}", stringify!($v), stringify!($x));
    }};
}

/// A runtime vector of `$m` with the given coefficients on the named generators.
macro_rules! vector {
    ($m:ident, [$($f:ident),*], $c:expr) => {{
        let c: &[Q] = &$c;
        let mut v = $m::Vector::<Q>::zero();
        let mut it = c.iter();
        $(v.$f = it.next().expect("one coefficient per generator").clone();)*
        v.to_multivector()
    }};
}

fn planes() -> impl Strategy<Value = Vec<(Vec<Q>, Q)>> {
    proptest::collection::vec((proptest::collection::vec(small(), 2), small()), 4)
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    #[test]
    fn pga3_motors(planes in planes(), x in proptest::collection::vec(small(), 8)) {
        // four planes u + t e0 with |u| = 1: their product is a general unit motor
        let vs: Vec<Mv<Q>> = planes.iter().map(|(u, t)| {
            let u = unit_vector(u);
            vector!(pga3, [e0, e1, e2, e3], [t.clone(), u[0].clone(), u[1].clone(), u[2].clone()])
        }).collect();
        let m = product(&vs);
        prop_assert_eq!(&m * &m.reverse(), Mv::scalar(m.algebra(), m.basis(), q(1)));
        check_unit!(pga3::Motor<Q>, pga3::Trivector<Q>, &m, x);
        check_unit!(pga3::Motor<Q>, pga3::Bivector<Q>, &m, x);
        check_unit!(pga3::Motor<Q>, pga3::Vector<Q>, &m, x);
        check_unit!(pga3::Motor<Q>, pga3::Motor<Q>, &m, x);
    }

    #[test]
    fn g123inf_and_cga_null_poses(planes in planes(), x in proptest::collection::vec(small(), 8)) {
        let vs: Vec<Mv<Q>> = planes.iter().map(|(u, t)| {
            let u = unit_vector(u);
            vector!(g123inf, [e1, e2, e3, einf], [u[0].clone(), u[1].clone(), u[2].clone(), t.clone()])
        }).collect();
        let m = product(&vs);
        check_unit!(g123inf::Motor<Q>, g123inf::Vector<Q>, &m, x);
        check_unit!(g123inf::Motor<Q>, g123inf::Bivector<Q>, &m, x);
        check_unit!(g123inf::Motor<Q>, g123inf::Motor<Q>, &m, x);
        let vs: Vec<Mv<Q>> = planes.iter().map(|(u, t)| {
            let u = unit_vector(u);
            vector!(cga_null, [e1, e2, e3, einf], [u[0].clone(), u[1].clone(), u[2].clone(), t.clone()])
        }).collect();
        let m = product(&vs);
        check_unit!(cga_null::Motor<Q>, cga_null::Vector<Q>, &m, x);
    }

    #[test]
    fn g3_rotors(us in proptest::collection::vec(proptest::collection::vec(small(), 2), 2), x in proptest::collection::vec(small(), 4)) {
        let vs: Vec<Mv<Q>> = us.iter().map(|u| {
            let u = unit_vector(u);
            vector!(g3, [e1, e2, e3], [u[0].clone(), u[1].clone(), u[2].clone()])
        }).collect();
        let r = product(&vs);
        check_unit!(g3::Rotor<Q>, g3::Vector<Q>, &r, x);
        check_unit!(g3::Rotor<Q>, g3::Bivector<Q>, &r, x);
        check_unit!(g3::Rotor<Q>, g3::Trivector<Q>, &r, x);
        check_unit!(g3::Rotor<Q>, g3::Rotor<Q>, &r, x);
    }

    #[test]
    fn cga_versors(
        vs in proptest::collection::vec((proptest::collection::vec(small(), 3), (1i64..=5, 1i64..=4)), 4),
        x in proptest::collection::vec(small(), 16),
    ) {
        // p u + q e5 with |u| = 1 and p² - q² = 1: a vector of square 1 in R^{4,1}
        let vs: Vec<Mv<Q>> = vs.iter().map(|(u, (n, d))| {
            let (u, r) = (unit_vector(u), ratio(*n, *d));
            let (p, h) = ((q(1) + &r * &r) / (q(2) * &r), (q(1) - &r * &r) / (q(2) * &r));
            vector!(cga, [e1, e2, e3, e4, e5], [&p * &u[0], &p * &u[1], &p * &u[2], &p * &u[3], h])
        }).collect();
        let m = product(&vs);
        prop_assert_eq!(&m * &m.reverse(), Mv::scalar(m.algebra(), m.basis(), q(1)));
        check_unit!(cga::Motor<Q>, cga::Vector<Q>, &m, x);
        check_unit!(cga::Motor<Q>, cga::Bivector<Q>, &m, x);
        check_unit!(cga::Motor<Q>, cga::Motor<Q>, &m, x);
        let odd = product(&vs[..3]);
        check_unit!(cga::OddVersor<Q>, cga::Vector<Q>, &odd, x);
        check_unit!(cga::OddVersor<Q>, cga::Bivector<Q>, &odd, x);
    }
}

/// The unit kernels assume `S rev(S) = 1`: for `2 S` they differ from the action.
#[test]
fn a_non_unit_motor_is_not_acted_correctly() {
    let mut m = pga3::Motor::<Q>::one();
    (m.scalar, m.e12, m.e01) = (q(2), q(1), ratio(1, 2));
    let x = pga3::Trivector::<Q>::new(q(1), q(2), q(3), q(1));
    assert_ne!(m.apply_unit(&x), m.apply(&x));
    // a 3-4-5 rotation with the same translation part is unit: then they agree
    (m.scalar, m.e12) = (ratio(3, 5), ratio(4, 5));
    assert_eq!(m.apply_unit(&x), m.apply(&x));
}

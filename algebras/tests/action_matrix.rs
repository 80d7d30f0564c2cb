//! The matrix form of the fused versor actions (`ActionMatrix`): the matrix applied to an
//! operand equals the fused action, exactly over rationals, in both conventions.

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::{cga_null, g3, g123inf, pga3};
use proptest::prelude::*;

fn small() -> BoxedStrategy<Q> {
    prop_oneof![1 => Just(q(0)), 4 => (-6i64..=6, 1i64..=4).prop_map(|(n, d)| ratio(n, d))].boxed()
}

macro_rules! val {
    ($t:ty, $c:expr) => {{
        let mut x = <$t>::zero();
        for (slot, c) in x.iter_mut().zip($c.iter()) {
            *slot = c.clone();
        }
        x
    }};
}

/// `transform(matrix(s), x)` against the fused `sandwich` and `apply`.
macro_rules! check {
    ($m:ident::$v:ident, $m2:ident::$x:ident, $a:expr, $b:expr) => {{
        let s = val!($m::$v<Q>, $a);
        let x = val!($m2::$x<Q>, $b);
        let ms = s.sandwich_matrix::<$m2::$x<Q>>();
        let ma = s.apply_matrix::<$m2::$x<Q>>();
        prop_assert_eq!($m::$v::transform(&ms, &x), s.sandwich(&x), "sandwich {}", stringify!($v on $x));
        prop_assert_eq!($m::$v::transform(&ma, &x), s.apply(&x), "apply {}", stringify!($v on $x));
    }};
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(32))]

    #[test]
    fn the_matrix_is_the_fused_action(a in proptest::collection::vec(small(), 8), b in proptest::collection::vec(small(), 8)) {
        check!(pga3::Motor, pga3::Trivector, a, b);
        check!(pga3::Motor, pga3::Bivector, a, b);
        check!(pga3::Motor, pga3::Vector, a, b);
        check!(g3::Rotor, g3::Vector, a, b);
        check!(g123inf::Motor, g123inf::Vector, a, b);
        check!(cga_null::Motor, cga_null::Vector, a, b);
    }
}

/// A unit PGA motor moves a point as a rotation matrix plus a translation: the matrix has
/// the point's weight row `(0, 0, 0, 1)` for a unit motor.
#[test]
fn unit_motor_matrix_keeps_the_weight() {
    // a translation by (1, 2, 3): T = 1 + (e01 + 2 e02 + 3 e03)/2 in pga3's blade basis
    let mut t = pga3::Motor::<Q>::one();
    (t.e01, t.e02, t.e03) = (ratio(1, 2), q(1), ratio(3, 2));
    let m = t.apply_matrix::<pga3::Trivector<Q>>();
    assert_eq!(m[3], [q(0), q(0), q(0), q(1)]);
    let p = pga3::Trivector::<Q>::new(q(1), q(-2), ratio(1, 3), q(1));
    assert_eq!(pga3::Motor::transform(&m, &p), t.apply(&p));
}

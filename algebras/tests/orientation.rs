//! Orientation-aware basis names: a module naming PGA blades in ganja's orientation
//! (`e31`, `e021`, `e032`) gives the same geometry as the canonical `pga3` module, exactly
//! over rationals: every field holds the coefficient of the blade as written
//! (`e31 = -e13`), the sign being folded into the kernels' constants.

use algebra_core::Multivector as Mv;
use algebra_core::rational::{Q, q, ratio};
use gam_algebras::pga3;
use proptest::prelude::*;

algebra_macros::algebra! {
    /// pga3 in ganja's orientation.
    pub mod pga_ganja {
        metric builtin "pga3";
        types {
            /// Planes `d e0 + a e1 + b e2 + c e3`.
            Plane = grade 1;
            /// Lines.
            Line = [e01, e02, e03, e12, e31, e23];
            /// Points `e123 + x e032 + y e013 + z e021`.
            Point = [e021, e013, e032, e123];
            /// Motors.
            Motor = [1, e01, e02, e03, e12, e31, e23, e0123];
            /// Every element.
            Multivector = all;
        }
    }
}

use pga_ganja::{Line, Motor, Plane, Point};

fn small() -> BoxedStrategy<Q> {
    prop_oneof![1 => Just(q(0)), 4 => (-6i64..=6, 1i64..=4).prop_map(|(n, d)| ratio(n, d))].boxed()
}

fn coeffs(n: usize) -> impl Strategy<Value = Vec<Q>> {
    proptest::collection::vec(small(), n)
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

/// The runtime basis blade `name` of pga3 (canonical names only).
fn blade(name: &str) -> Mv<Q> {
    Mv::basis_element(&pga3::algebra(), algebra_core::Basis::Blade, name).unwrap()
}

#[test]
fn fields_are_named_and_signed_as_declared() {
    assert_eq!(Line::<Q>::ELEMENTS, ["e01", "e02", "e03", "e12", "e31", "e23"]); // as declared
    assert_eq!(Point::<Q>::ELEMENTS, ["e021", "e013", "e032", "e123"]);
    assert_eq!(Line::<Q>::e31().to_string(), "e31");
    assert_eq!(Line::<Q>::e31().to_multivector(), -blade("e13"));
    assert_eq!(Point::<Q>::e021().to_multivector(), -blade("e012"));
    assert_eq!(Point::<Q>::e032().to_multivector(), -blade("e023"));
    assert_eq!(Point::<Q>::e013().to_multivector(), blade("e013"));
    // e3 e1 = e31 in this module; a runtime -e13 reads back as e31
    assert_eq!(&Plane::<Q>::e3() * &Plane::<Q>::e1(), Motor::from(&Line::e31()));
    assert_eq!(Line::try_from(&(-blade("e13"))).unwrap(), Line::<Q>::e31());
}

#[test]
fn a_point_is_the_meet_of_three_planes_in_ganja_coordinates() {
    let (x, y, z) = (ratio(1, 2), q(-3), ratio(7, 4));
    let plane = |d: Q, a: i64, b: i64, c: i64| Plane::new(d, q(a), q(b), q(c));
    let meet = &(&plane(-x.clone(), 1, 0, 0) ^ &plane(-y.clone(), 0, 1, 0)) ^ &plane(-z.clone(), 0, 0, 1);
    let mut point = Point::<Q>::zero();
    (point.e032, point.e013, point.e021, point.e123) = (x, y, z, q(1));
    assert_eq!(meet, point);
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(48))]

    /// Every kernel of the oriented module agrees with the canonical module and the runtime.
    #[test]
    fn same_geometry_as_the_canonical_module(a in coeffs(8), b in coeffs(8), c in coeffs(6)) {
        let (m, n, p, l) = (val!(Motor<Q>, a), val!(Motor<Q>, b), val!(Point<Q>, b), val!(Line<Q>, c));
        let (mm, nm, pm, lm) = (m.to_multivector(), n.to_multivector(), p.to_multivector(), l.to_multivector());
        // canonical twins
        let (cm, cp) = (pga3::Motor::project(&mm), pga3::Trivector::project(&pm));
        prop_assert_eq!((&m * &n).to_multivector(), &mm * &nm);
        prop_assert_eq!(m.sandwich(&p).to_multivector(), cm.sandwich(&cp).to_multivector());
        prop_assert_eq!(Motor::transform(&m.sandwich_matrix::<Point<Q>>(), &p), m.sandwich(&p));
        prop_assert_eq!(m.apply(&l).to_multivector(), Mv::from(&pga3::Bivector::project(&(&mm * &lm * mm.reverse()))));
        prop_assert_eq!((&l & &p).to_multivector(), lm.regressive(&pm));
        prop_assert_eq!((&l ^ &val!(Plane<Q>, a)).to_multivector(), lm.op(&val!(Plane<Q>, a).to_multivector()));
        let into: Line<Q> = m.gp_into(&n);
        prop_assert_eq!(into, Line::project(&(&mm * &nm)));
        prop_assert_eq!(m.reverse().to_multivector(), mm.reverse());
        prop_assert_eq!(l.dual().to_multivector(), lm.dual());
        prop_assert_eq!(m.norm_squared(), cm.norm_squared());
        prop_assert_eq!(pga_ganja::Multivector::from(&l).to_multivector(), lm.clone());
        prop_assert_eq!(m.project_to_line().to_multivector(), Mv::from(&pga3::Bivector::project(&mm)));
        match (m.inverse(), cm.inverse()) {
            (Ok(mi), Ok(ci)) => prop_assert_eq!(mi.to_multivector(), ci.to_multivector()),
            (Err(_), Err(_)) => {}
            (x, y) => prop_assert!(false, "inverse differs: {:?} vs {:?}", x, y),
        }
    }
}

/// The unit-versor kernels of the oriented module: for a unit motor (rotation by the
/// Pythagorean angle cos = 3/5 about the e31 axis, then a translation), `apply_unit` and
/// `sandwich_unit` equal the general actions exactly, on points and lines.
#[test]
fn unit_actions_fold_the_orientation_signs() {
    let r = Motor::new(ratio(3, 5), q(0), q(0), q(0), q(0), ratio(4, 5), q(0), q(0));
    let mut t = Motor::<Q>::one();
    (t.e01, t.e02, t.e03) = (ratio(1, 2), q(-2), ratio(3, 4));
    let m = &t * &r;
    assert_eq!(&m * &m.reverse(), Motor::one());
    let p = Point::new(ratio(1, 3), q(2), q(-1), q(1));
    let l = Line::new(q(1), q(2), q(3), q(-1), ratio(1, 2), q(5));
    assert_eq!(m.apply_unit(&p), m.apply(&p));
    assert_eq!(m.sandwich_unit(&p), m.sandwich(&p));
    assert_eq!(m.apply_unit(&l), m.apply(&l));
    assert_eq!(m.sandwich_unit(&l), m.sandwich(&l));
}

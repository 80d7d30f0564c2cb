//! The join (`&`, `join`, `regressive`) and the output-typed geometric products
//! (`gp_into`) of the generated types, exactly over rationals:
//!
//! - the join against the runtime regressive product, and against formulas that do not use
//!   the regressive table: the bracket `<a ^ b>_n` for complementary grades, the Euclidean
//!   metric form `rev((rev(a) I ^ rev(b) I) I^-1)` in g3, and PGA incidence geometry (the
//!   plane through three points against the cross-product formula);
//! - `gp_into::<Out>` against the projection of the runtime geometric product onto `Out`;
//! - the automatic `Even`/`Odd` fallback types of a module that does not declare them.

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Multivector as Mv, Ring};
use proptest::prelude::*;

/// Small rationals, zero one time in five.
fn small() -> BoxedStrategy<Q> {
    prop_oneof![1 => Just(q(0)), 4 => (-6i64..=6, 1i64..=4).prop_map(|(n, d)| ratio(n, d))].boxed()
}

fn coeffs(n: usize) -> impl Strategy<Value = Vec<Q>> {
    proptest::collection::vec(small(), n)
}

/// A value of a generated type from a coefficient list (in `ELEMENTS` order).
macro_rules! value {
    ($m:ident::$t:ident, $c:expr) => {{
        let mut x = gam_algebras::$m::$t::<Q>::zero();
        for (slot, c) in x.iter_mut().zip($c.iter()) {
            *slot = c.clone();
        }
        x
    }};
}

/// The coefficient of the pseudoscalar (the top blade) of a runtime multivector.
fn top(m: &Mv<Q>) -> Q {
    let n = m.algebra().generators();
    m.coeff((1u32 << n) - 1).expect("the top blade is in range").clone()
}

mod join {
    use super::*;
    use gam_algebras::pga3;

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// `&`, `join` and `regressive` are one kernel, equal to the runtime product.
        #[test]
        fn operator_method_and_runtime_agree(a in coeffs(8), b in coeffs(16)) {
            let (x, y) = (value!(pga3::Motor, a), value!(pga3::Multivector, b));
            let j = &x & &y;
            prop_assert_eq!(&j, &x.join(&y));
            prop_assert_eq!(&j, &(x.clone() & y.clone()));
            prop_assert_eq!(j.to_multivector(), x.to_multivector().regressive(&y.to_multivector()));
            let (u, v) = (value!(cga::Vector, a[..5]), value!(cga::Motor, b));
            prop_assert_eq!((&u & &v).to_multivector(), u.to_multivector().regressive(&v.to_multivector()));
        }

        /// For complementary grades the join is the bracket: the pseudoscalar coefficient of
        /// the outer product (degenerate pga3, Euclidean g3, conformal cga).
        #[test]
        fn complementary_grades_give_the_bracket(a in coeffs(10), b in coeffs(10)) {
            let (plane, point) = (value!(pga3::Vector, a[..4]), value!(pga3::Trivector, b[..4]));
            prop_assert_eq!((&plane & &point).scalar, top(&(&plane ^ &point).to_multivector()));
            let (l1, l2) = (value!(pga3::Bivector, a[..6]), value!(pga3::Bivector, b[..6]));
            prop_assert_eq!((&l1 & &l2).scalar, top(&(&l1 ^ &l2).to_multivector()));
            let (v, bv) = (value!(g3::Vector, a[..3]), value!(g3::Bivector, b[..3]));
            prop_assert_eq!((&v & &bv).scalar, top(&(&v ^ &bv).to_multivector()));
            let (cv, cm) = (value!(cga::Vector, a[..5]), value!(cga::Motor, b));
            let grade4: Mv<Q> = cm.to_multivector().grade(4);
            prop_assert_eq!((&cv & &cm).to_multivector().grade(0).scalar_part(), top(&(cv.to_multivector() ^ grade4)));
        }

        /// In a Euclidean algebra the complement is `dual(x) = rev(x) I`, so the join is
        /// `rev((rev(a) I ^ rev(b) I) I^-1)`, computed here with runtime geometric products.
        #[test]
        fn euclidean_join_is_the_metric_formula(a in coeffs(8), b in coeffs(8)) {
            let (x, y) = (value!(g3::Multivector, a), value!(g3::Multivector, b));
            let (xm, ym) = (x.to_multivector(), y.to_multivector());
            let alg = xm.algebra().clone();
            let i = Mv::<Q>::from_mask(&alg, xm.basis(), 0b111).expect("e123 is in g3");
            let i_inv = i.inverse().unwrap();
            let metric = ((xm.reverse() * &i).op(&(ym.reverse() * &i)) * &i_inv).reverse();
            prop_assert_eq!((&x & &y).to_multivector(), metric);
        }

        /// PGA: the plane through three points, against the cross-product formula. Points are
        /// built as meets of the planes `x = px`, `y = py`, `z = pz` (outer products, no
        /// join), planes read `d e0 + a e1 + b e2 + c e3` (`a x + b y + c z + d = 0`).
        #[test]
        fn pga_plane_through_three_points(p in coeffs(9)) {
            let point = |x: &Q, y: &Q, z: &Q| {
                let plane = |c: [Q; 4]| value!(pga3::Vector, c);
                &(&plane([-x.clone(), q(1), q(0), q(0)]) ^ &plane([-y.clone(), q(0), q(1), q(0)]))
                    ^ &plane([-z.clone(), q(0), q(0), q(1)])
            };
            let (p1, p2, p3) = (point(&p[0], &p[1], &p[2]), point(&p[3], &p[4], &p[5]), point(&p[6], &p[7], &p[8]));
            let line = &p1 & &p2;
            let plane = &line & &p3;
            let d1: Vec<Q> = (0..3).map(|k| p[3 + k].clone() - p[k].clone()).collect();
            let d2: Vec<Q> = (0..3).map(|k| p[6 + k].clone() - p[k].clone()).collect();
            let n = [
                d1[1].clone() * &d2[2] - d1[2].clone() * &d2[1],
                d1[2].clone() * &d2[0] - d1[0].clone() * &d2[2],
                d1[0].clone() * &d2[1] - d1[1].clone() * &d2[0],
            ];
            let d = -(n[0].clone() * &p[0] + n[1].clone() * &p[1] + n[2].clone() * &p[2]);
            // the pinned orientation: P1 & P2 & P3 = d e0 + n . e with n = (p2 - p1) x (p3 - p1)
            let expected = value!(pga3::Vector, [d, n[0].clone(), n[1].clone(), n[2].clone()]);
            prop_assert_eq!(&plane, &expected);
            // incidence: a point of the line p1 p2 joins it to zero, the third point does not
            let on_line = point(&(p[0].clone() * q(2) - &p[3]), &(p[1].clone() * q(2) - &p[4]), &(p[2].clone() * q(2) - &p[5]));
            prop_assert_eq!(&line & &on_line, pga3::Vector::zero());
            prop_assert_eq!(plane == pga3::Vector::zero(), n.iter().all(|c| c.is_exact_zero()));
        }
    }
}

mod typed {
    use super::*;
    use gam_algebras::{cga, cga_null, g3, g123inf, pga3};

    /// `a.gp_into::<Out>(&b)` is the projection of the runtime product onto `Out`.
    macro_rules! check_into {
        ($a:expr, $b:expr, $m:ident::$out:ident) => {{
            let r: $m::$out<Q> = $a.gp_into(&$b);
            let reference = $m::$out::project(&($a.to_multivector() * $b.to_multivector()));
            prop_assert_eq!(&r, &reference, "{} into {}", stringify!($m), stringify!($out));
            prop_assert_eq!(&r, &$a.gp_into::<$m::$out<Q>, _>(&$b));
        }};
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        #[test]
        fn gp_into_is_the_projected_product(a in coeffs(32), b in coeffs(32)) {
            let (v, w) = (value!(g3::Vector, a), value!(g3::Vector, b));
            let (r, s) = (value!(g3::Rotor, a), value!(g3::Rotor, b));
            check_into!(v, w, g3::Scalar);
            check_into!(v, w, g3::Bivector);
            check_into!(v, w, g3::Rotor);
            check_into!(v, w, g3::Multivector);
            check_into!(r, v, g3::Vector);
            check_into!(r, v, g3::Trivector);
            check_into!(r, s, g3::Bivector);
            let (m, n) = (value!(g123inf::Motor, a), value!(g123inf::Motor, b));
            check_into!(m, n, g123inf::Pseudoscalar);
            check_into!(m, n, g123inf::Bivector);
            let (pm, pn) = (value!(pga3::Motor, a), value!(pga3::Motor, b));
            let pt = value!(pga3::Trivector, b);
            check_into!(pm, pn, pga3::Bivector);
            check_into!(pm, pt, pga3::Trivector);
            check_into!(pm, pt, pga3::Vector);
            let (cm, cv) = (value!(cga::Motor, a), value!(cga::Vector, b));
            check_into!(cm, cv, cga::Vector);
            check_into!(cm, cm, cga::Bivector);
            let (x, y) = (value!(cga::Multivector, a), value!(cga::Multivector, b));
            check_into!(x, y, cga::Motor);
            check_into!(x, y, cga::Vector);
            let (nm, nv) = (value!(cga_null::Motor, a), value!(cga_null::Vector, b));
            check_into!(nm, nv, cga_null::Vector);
        }
    }
}

algebra_macros::algebra! {
    /// A user module without even or odd types: vectors and points of PGA.
    pub mod pga_user {
        metric builtin "pga3";
        types {
            /// Planes.
            Plane = grade 1;
            /// Points.
            Point = grade 3;
        }
    }
}

mod fallback {
    use super::pga_user::{Even, Multivector, Odd, Plane, Point};
    use super::*;

    macro_rules! val {
        ($t:ident, $c:expr) => {{
            let mut x = $t::<Q>::zero();
            for (slot, c) in x.iter_mut().zip($c.iter()) {
                *slot = c.clone();
            }
            x
        }};
    }

    #[test]
    fn even_and_odd_are_declared_automatically() {
        assert_eq!(Even::<Q>::LEN, 8);
        assert_eq!(Odd::<Q>::LEN, 8);
        assert_eq!(Multivector::<Q>::LEN, 16);
    }

    proptest! {
        #![proptest_config(ProptestConfig::with_cases(32))]

        /// Products land in the parity type (checked by the annotated types) and agree with
        /// the runtime product.
        #[test]
        fn products_land_in_the_parity_types(a in coeffs(8), b in coeffs(8)) {
            let (p, x) = (val!(Plane, a), val!(Point, b));
            let e: Even<Q> = &p * &x;
            prop_assert_eq!(e.to_multivector(), p.to_multivector() * x.to_multivector());
            let e2: Even<Q> = &x * &x;
            prop_assert_eq!(e2.to_multivector(), x.to_multivector() * x.to_multivector());
            let o: Odd<Q> = &e * &p;
            prop_assert_eq!(o.to_multivector(), e.to_multivector() * p.to_multivector());
            let ee: Even<Q> = &o * &o;
            prop_assert_eq!(ee.to_multivector(), o.to_multivector() * o.to_multivector());
            let j: Even<Q> = &p & &x;
            prop_assert_eq!(j.to_multivector(), p.to_multivector().regressive(&x.to_multivector()));
            let (ev, od) = (val!(Even, a), val!(Odd, b));
            let moved: Point<Q> = ev.sandwich(&x);
            prop_assert_eq!(moved, Point::project(&ev.to_multivector().sandwich(&x.to_multivector())));
            let mixed: Multivector<Q> = Multivector::from(&ev) + Multivector::from(&od);
            prop_assert_eq!((&mixed * &p).to_multivector(), mixed.to_multivector() * p.to_multivector());
        }
    }
}

algebra_macros::algebra! {
    /// The same user module with the automatic parity types turned off.
    pub mod pga_user_full {
        metric builtin "pga3";
        fallback full;
        types {
            /// Planes.
            Plane = grade 1;
            /// Points.
            Point = grade 3;
        }
    }
}

mod fallback_full {
    use super::pga_user_full::{Multivector, Plane, Point};
    use super::*;

    /// With `fallback full;` the module declares no `Even`/`Odd`: products of planes and
    /// points land in the full multivector (checked by the annotated types).
    #[test]
    fn products_land_in_the_full_multivector() {
        let (mut p, mut x) = (Plane::<Q>::zero(), Point::<Q>::zero());
        (p.e1, p.e0, x.e123, x.e012) = (q(2), q(-1), q(1), ratio(1, 3));
        let m: Multivector<Q> = &p * &x;
        assert_eq!(m.to_multivector(), p.to_multivector() * x.to_multivector());
        let j: Multivector<Q> = &p & &x;
        assert_eq!(j.to_multivector(), p.to_multivector().regressive(&x.to_multivector()));
        assert_eq!(Multivector::<Q>::LEN, 16);
    }
}

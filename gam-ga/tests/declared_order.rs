//! The declared list order is the storage order, seen from a user crate of the front door:
//! a type declared as a list (`Line = [e01, e02, e03, e12, e31, e23]`) stores, constructs,
//! indexes, iterates, prints and lays out (`repr(C)`) its fields in the declared order, and
//! its products are the canonical module's products, component by component by name, exactly
//! over rationals. Grade selectors keep the algebra's canonical order.

use gam_ga::rational::{Q, q};
use gam_ga::{GeometricProduct, OuterProduct, RegressiveProduct};
use std::collections::BTreeMap;

gam_ga::algebra! {
    /// 3D PGA with the types as a kernel author lists them (ganja's orientation).
    pub mod pga_user {
        metric builtin "pga3";
        types {
            /// Lines, in the declared order.
            Line = [e01, e02, e03, e12, e31, e23];
            /// Points.
            Point = [e032, e013, e021, e123];
            /// Planes.
            Plane = [e1, e2, e3, e0];
        }
    }
}

gam_ga::algebra! {
    /// 3D PGA with every type a permutation of a canonical grade type (canonical names).
    pub mod pga_permuted {
        metric builtin "pga3";
        types {
            /// Grade 1, reversed.
            Vector = [e3, e2, e1, e0];
            /// Grade 2, shuffled.
            Bivector = [e23, e01, e13, e02, e12, e03];
            /// Grade 3, shuffled.
            Trivector = [e123, e012, e023, e013];
            /// The even subalgebra, shuffled.
            Motor = [e0123, e23, 1, e13, e12, e03, e02, e01];
            /// Every element, reversed.
            Multivector = [e0123, e123, e023, e013, e012, e23, e13, e03, e12, e02, e01, e3, e2, e1, e0, 1];
        }
    }
}

gam_ga::algebra! {
    /// The same algebra with the canonical (grade-selector) types.
    pub mod pga_canonical {
        metric builtin "pga3";
        types {
            /// Grade 1.
            Vector = grade 1;
            /// Grade 2.
            Bivector = grade 2;
            /// Grade 3.
            Trivector = grade 3;
            /// The even subalgebra.
            Motor = even;
            /// Every element.
            Multivector = all;
        }
    }
}

#[test]
fn a_declared_line_reads_back_in_the_declared_order() {
    use pga_user::Line;
    let l = Line::<f64>::new(1.0, 2.0, 3.0, 4.0, 5.0, 6.0);
    assert_eq!(Line::<f64>::ELEMENTS, ["e01", "e02", "e03", "e12", "e31", "e23"]);
    assert_eq!((l.e01, l.e02, l.e03, l.e12, l.e31, l.e23), (1.0, 2.0, 3.0, 4.0, 5.0, 6.0));
    assert_eq!(l.to_array(), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(Line::from_array([1.0, 2.0, 3.0, 4.0, 5.0, 6.0]), l);
    assert_eq!((l[3], l[4]), (4.0, 5.0));
    assert_eq!(l.iter().copied().collect::<Vec<_>>(), [1.0, 2.0, 3.0, 4.0, 5.0, 6.0]);
    assert_eq!(l.to_string(), "e01 + 2*e02 + 3*e03 + 4*e12 + 5*e31 + 6*e23");
    // the repr(C) layout: field k at byte 8k, so a GPU buffer in the declared order matches
    let offsets = [
        core::mem::offset_of!(Line<f64>, e01),
        core::mem::offset_of!(Line<f64>, e02),
        core::mem::offset_of!(Line<f64>, e03),
        core::mem::offset_of!(Line<f64>, e12),
        core::mem::offset_of!(Line<f64>, e31),
        core::mem::offset_of!(Line<f64>, e23),
    ];
    assert_eq!(offsets, [0, 8, 16, 24, 32, 40]);
    assert_eq!(core::mem::size_of::<Line<f32>>(), 24);
    assert_eq!(core::mem::offset_of!(Line<f32>, e31), 16);
    // Line::new(0, 0, 0, a, 0, 0) is a line of the plane z = 0's direction: e12 (a rotation
    // generator about the z axis), never the translation generator e03
    let r = Line::<f64>::new(0.0, 0.0, 0.0, -0.5, 0.0, 0.0);
    assert_eq!(r.to_string(), "-0.5*e12");
    assert_eq!(pga_user::Point::<f64>::ELEMENTS, ["e032", "e013", "e021", "e123"]);
    assert_eq!(pga_user::Plane::<f64>::ELEMENTS, ["e1", "e2", "e3", "e0"]);
    // a type the generator adds keeps the canonical order
    assert_eq!(pga_user::Multivector::<f64>::ELEMENTS[..5], ["1", "e0", "e1", "e2", "e3"]);
}

#[test]
fn basis_constants_sit_where_the_declaration_puts_them() {
    use pga_permuted::{Bivector, Motor};
    for (k, name) in Bivector::<Q>::ELEMENTS.iter().enumerate() {
        let mut unit = [q(0), q(0), q(0), q(0), q(0), q(0)];
        unit[k] = q(1);
        assert_eq!(Bivector::from_array(unit).to_string(), *name);
    }
    assert_eq!(Bivector::<Q>::e13().to_array(), [q(0), q(0), q(1), q(0), q(0), q(0)]);
    assert_eq!(Motor::<Q>::e0123().to_array()[0], q(1));
    assert_eq!(Motor::<Q>::one().to_array()[2], q(1));
}

/// Coefficients by basis name (zeros dropped), the comparison the test is about.
trait Named {
    fn named(&self) -> BTreeMap<String, Q>;
}

macro_rules! named {
    ($($m:ident :: $t:ident),*) => {$(
        impl Named for $m::$t<Q> {
            fn named(&self) -> BTreeMap<String, Q> {
                Self::ELEMENTS
                    .iter()
                    .zip(self.iter())
                    .filter(|(_, c)| **c != q(0))
                    .map(|(n, c)| (n.to_string(), c.clone()))
                    .collect()
            }
        }
    )*};
}

named!(
    pga_permuted::Vector,
    pga_permuted::Bivector,
    pga_permuted::Trivector,
    pga_permuted::Motor,
    pga_permuted::Multivector,
    pga_canonical::Vector,
    pga_canonical::Bivector,
    pga_canonical::Trivector,
    pga_canonical::Motor,
    pga_canonical::Multivector
);

/// The value of a permuted type with the canonical value's coefficients, placed by name.
fn by_name<P: Default + core::ops::IndexMut<usize, Output = Q>>(
    elements: &[&str],
    canonical: &BTreeMap<String, Q>,
) -> P {
    let mut p = P::default();
    for (name, c) in canonical {
        p[elements.iter().position(|e| e == name).expect("same elements")] = c.clone();
    }
    p
}

/// Every basis element of a canonical type as a value (the products are bilinear, so the
/// products of basis pairs decide them).
fn basis<C: Default + core::ops::IndexMut<usize, Output = Q>>(len: usize) -> Vec<C> {
    (0..len)
        .map(|k| {
            let mut c = C::default();
            c[k] = q(1);
            c
        })
        .collect()
}

macro_rules! same_products {
    ($l:ident, $r:ident) => {{
        let cl = basis::<pga_canonical::$l<Q>>(pga_canonical::$l::<Q>::LEN);
        let cr = basis::<pga_canonical::$r<Q>>(pga_canonical::$r::<Q>::LEN);
        for a in &cl {
            for b in &cr {
                let pa: pga_permuted::$l<Q> = by_name(&pga_permuted::$l::<Q>::ELEMENTS, &a.named());
                let pb: pga_permuted::$r<Q> = by_name(&pga_permuted::$r::<Q>::ELEMENTS, &b.named());
                let what = format!("{a} and {b}");
                assert_eq!(pa.gp(&pb).named(), a.gp(b).named(), "gp of {what}");
                assert_eq!(pa.op(&pb).named(), a.op(b).named(), "op of {what}");
                assert_eq!(pa.regressive(&pb).named(), a.regressive(b).named(), "join of {what}");
                assert_eq!(pa.reverse().named(), a.reverse().named(), "reverse of {a}");
                assert_eq!(pa.dual().named(), a.dual().named(), "dual of {a}");
            }
        }
    }};
}

#[test]
fn products_of_permuted_types_equal_the_canonical_ones_by_name() {
    same_products!(Vector, Vector);
    same_products!(Vector, Bivector);
    same_products!(Bivector, Trivector);
    same_products!(Trivector, Vector);
    same_products!(Motor, Motor);
    same_products!(Motor, Vector);
    same_products!(Multivector, Bivector);
    same_products!(Multivector, Multivector);
}

#[test]
fn versor_actions_of_permuted_types_equal_the_canonical_ones_by_name() {
    // a motor with every coefficient distinct (not a unit motor: the actions are polynomial)
    let canonical = pga_canonical::Motor::from_array([1, 2, 3, 5, 7, 11, 13, 17].map(q));
    let m: pga_permuted::Motor<Q> = by_name(&pga_permuted::Motor::<Q>::ELEMENTS, &canonical.named());
    for x in basis::<pga_canonical::Trivector<Q>>(4) {
        let px: pga_permuted::Trivector<Q> = by_name(&pga_permuted::Trivector::<Q>::ELEMENTS, &x.named());
        assert_eq!(m.apply(&px).named(), canonical.apply(&x).named());
        assert_eq!(m.sandwich(&px).named(), canonical.sandwich(&x).named());
    }
    assert_eq!(m.norm_squared(), canonical.norm_squared());
}

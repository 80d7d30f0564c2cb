//! A custom algebra declared with the macro: a non-diagonal (and degenerate-free but
//! indefinite) bilinear form, in both bases. The generated kernels obey the defining relation
//! `ea eb + eb ea = 2 B(a, b)` exactly and agree with the runtime reference.

use algebra_core::ops::{AnticommutatorProduct, RegressiveProduct, ScalarProduct};
use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Basis, Multivector, Ring};

algebra_macros::algebra! {
    /// Three generators with off-diagonal terms: B(a,b) = 1/2, B(b,c) = -3/4, B(a,c) = 0.
    pub mod skew {
        generators { ea, eb, ec }
        metric { (ea, ea) = 1, (ea, eb) = 1/2, (eb, eb) = 2, (eb, ec) = -3/4, (ec, ec) = -1 }
        types {
            /// Vectors.
            Vector = grade 1;
            /// The even subalgebra.
            Even = even;
        }
    }
}

algebra_macros::algebra! {
    /// The same form, with basis elements that are geometric products of generators.
    pub mod skew_product {
        generators { ea, eb, ec }
        metric { (ea, ea) = 1, (ea, eb) = 1/2, (eb, eb) = 2, (eb, ec) = -3/4, (ec, ec) = -1 }
        basis product;
        types {
            Vector = grade 1;
            Even = even;
            Pair = [1, eab];
        }
    }
}

/// The Gram matrix declared above.
fn gram(i: usize, j: usize) -> Q {
    let g = [[q(1), ratio(1, 2), q(0)], [ratio(1, 2), q(2), ratio(-3, 4)], [q(0), ratio(-3, 4), q(-1)]];
    g[i][j].clone()
}

/// The `i`-th generator as a generated vector.
fn generator<T: Ring>(i: usize) -> [T; 3] {
    let mut c = [T::zero(), T::zero(), T::zero()];
    c[i] = T::one();
    c
}

#[test]
fn anticommutator_of_generators_is_twice_the_form_blade_basis() {
    for i in 0..3 {
        for j in 0..3 {
            let [a0, a1, a2] = generator::<Q>(i);
            let [b0, b1, b2] = generator::<Q>(j);
            let (ei, ej) = (skew::Vector::new(a0, a1, a2), skew::Vector::new(b0, b1, b2));
            // a vector times a vector lands in the even subalgebra
            let sum: skew::Even<Q> = &(&ei * &ej) + &(&ej * &ei);
            let expected = skew::Even::one().scale(&(q(2) * gram(i, j)));
            assert_eq!(sum, expected, "e{i} e{j} + e{j} e{i}");
            // the anticommutator product is half of it, the scalar product is B itself
            assert_eq!(ei.anticommutator(&ej).to_multivector(), expected.scale(&ratio(1, 2)).to_multivector());
            assert_eq!(ei.sp(&ej).to_multivector().scalar_part(), gram(i, j));
        }
    }
}

#[test]
fn anticommutator_of_generators_is_twice_the_form_product_basis() {
    for i in 0..3 {
        for j in 0..3 {
            let [a0, a1, a2] = generator::<Q>(i);
            let [b0, b1, b2] = generator::<Q>(j);
            let (ei, ej) = (skew_product::Vector::new(a0, a1, a2), skew_product::Vector::new(b0, b1, b2));
            let sum = (&(&ei * &ej) + &(&ej * &ei)).to_multivector();
            let expected = Multivector::scalar(&skew_product::algebra(), Basis::Product, q(2) * gram(i, j));
            assert_eq!(sum, expected, "e{i} e{j} + e{j} e{i}");
        }
    }
    // in the product basis `eab` is literally ea eb
    let ea = skew_product::Vector::new(q(1), q(0), q(0));
    let eb = skew_product::Vector::new(q(0), q(1), q(0));
    let eab = skew_product::Pair::<Q>::new(q(0), q(1));
    assert_eq!((&ea * &eb).to_multivector(), eab.to_multivector());
    // and ea eb = B(a,b) + ea^eb, so its blade coordinates are 1/2 + eab
    assert_eq!(eab.to_multivector().in_basis(Basis::Blade).to_string(), "1/2 + eab");
}

#[test]
fn custom_kernels_match_the_runtime() {
    let x = skew::Even::<Q>::new(ratio(1, 2), q(-1), ratio(2, 3), q(3));
    let y = skew::Even::<Q>::new(q(2), ratio(-1, 5), q(1), ratio(-3, 2));
    let v = skew::Vector::<Q>::new(q(1), ratio(-2, 3), ratio(1, 4));
    let (xm, ym, vm) = (x.to_multivector(), y.to_multivector(), v.to_multivector());
    assert_eq!((&x * &y).to_multivector(), &xm * &ym);
    assert_eq!((&x ^ &v).to_multivector(), &xm ^ &vm);
    assert_eq!((&v | &x).to_multivector(), vm.lc(&xm));
    assert_eq!(x.regressive(&v).to_multivector(), xm.regressive(&vm));
    assert_eq!(x.sandwich(&v), skew::Vector::project(&xm.sandwich(&vm)));
    assert_eq!(x.norm_squared(), xm.sp(&xm.reverse()).scalar_part());
    let inv = x.inverse().expect("invertible");
    assert_eq!(&x * &inv, skew::Even::one());
    assert_eq!(inv.to_multivector(), xm.inverse().expect("invertible"));
    // the auto-added full type holds everything
    assert_eq!(skew::Multivector::<Q>::ELEMENTS.len(), 8);
    assert_eq!(skew::Multivector::from(&x).to_multivector(), xm);
    assert_eq!(skew::Even::<Q>::ELEMENTS, ["1", "eab", "eac", "ebc"]);
}

// `closed_forms off;` leaves out the detected closed forms, so a crate can give the types its own
// methods of those names (as `motion` does for `Pose::log`); with the default they are emitted.
mod closed_forms {
    algebra_macros::algebra! {
        pub mod with {
            generators { e1, e2 }
            metric { (e1, e1) = 1, (e2, e2) = 1 }
            types {
                Bivector = grade 2;
                Rotor = even;
            }
        }
    }
    algebra_macros::algebra! {
        pub mod without {
            generators { e1, e2 }
            metric { (e1, e1) = 1, (e2, e2) = 1 }
            closed_forms off;
            types {
                Bivector = grade 2;
                Rotor = even;
            }
        }
    }
    impl<T: algebra_core::Real> without::Rotor<T> {
        /// Compiles only because no generated `log` exists on this type.
        pub fn log(&self) -> T {
            self.e12.atan2(&self.scalar)
        }
    }

    #[test]
    fn off_leaves_the_names_free_and_on_emits_them() {
        let b = with::Bivector::<f64>::e12() * 0.25;
        let r = b.exp();
        assert!((r.scalar - 0.25f64.cos()).abs() < 1e-15 && (r.e12 - 0.25f64.sin()).abs() < 1e-15);
        let own = without::Rotor { scalar: 0.25f64.cos(), e12: 0.25f64.sin() };
        assert!((own.log() - 0.25).abs() < 1e-15);
    }
}

// `table_above N;` sets the size policy's threshold: `table_above 0;` makes every kernel the
// table loop (products, fused actions, the inverse's matrix), the default keeps these 3D kernels
// (at most 64 terms) straight-line. Both forms agree exactly over Q, and with the runtime.
mod table_above {
    use algebra_core::Multivector;
    use algebra_core::ops::{GeometricProduct, LeftContraction, OuterProduct};
    use algebra_core::rational::{Q, ratio};

    algebra_macros::algebra! {
        pub mod tables {
            metric builtin "g3";
            table_above 0;
            types { Vector = grade 1; Rotor = even; Multivector = all; }
        }
    }
    algebra_macros::algebra! {
        pub mod lines {
            metric builtin "g3";
            types { Vector = grade 1; Rotor = even; Multivector = all; }
        }
    }

    fn coefs<const N: usize>(seed: i64) -> [Q; N] {
        std::array::from_fn(|i| ratio((seed * 7 + 3 * i as i64) % 11 - 5, 1 + (i as i64 + seed) % 4))
    }

    #[test]
    fn table_loops_and_straight_line_code_agree_exactly() {
        for seed in 0..8 {
            let (a, b) = (coefs::<8>(seed), coefs::<8>(seed + 1));
            let (r, v) = (coefs::<4>(seed + 2), coefs::<3>(seed + 3));
            let (ta, tb) = (tables::Multivector::from_array(a.clone()), tables::Multivector::from_array(b.clone()));
            let (la, lb) = (lines::Multivector::from_array(a), lines::Multivector::from_array(b));
            assert_eq!(ta.gp(&tb).to_array(), la.gp(&lb).to_array());
            assert_eq!(ta.op(&tb).to_array(), la.op(&lb).to_array());
            assert_eq!(ta.lc(&tb).to_array(), la.lc(&lb).to_array());
            let reference: Multivector<Q> = &la.to_multivector() * &lb.to_multivector();
            assert_eq!(ta.gp(&tb).to_multivector(), reference);
            let (tr, lr) = (tables::Rotor::from_array(r.clone()), lines::Rotor::from_array(r));
            let (tv, lv) = (tables::Vector::from_array(v.clone()), lines::Vector::from_array(v));
            assert_eq!(tr.sandwich(&tv).to_array(), lr.sandwich(&lv).to_array());
            assert_eq!(tr.inverse().ok().map(|x| x.to_array()), lr.inverse().ok().map(|x| x.to_array()));
        }
    }
}

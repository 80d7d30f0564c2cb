//! Value semantics of the generated types, over a non-`Copy` scalar (`Q`) as well as `f64`,
//! and the optional `serde` derive (`cargo test -p gam-algebras --features serde`).

use algebra_core::rational::{Q, q, ratio};
use gam_algebras::{cga, g3, g123inf};

#[test]
fn arrays_index_and_iteration_follow_elements() {
    let v = cga::Vector::<Q>::new(q(1), q(2), q(3), q(4), q(5));
    let a = v.to_array();
    assert_eq!(a, [q(1), q(2), q(3), q(4), q(5)]);
    assert_eq!(cga::Vector::from_array(a.clone()), v);
    assert_eq!(cga::Vector::from(a.clone()), v);
    assert_eq!(v.clone().into_array(), a);
    for (i, c) in v.iter().enumerate() {
        assert_eq!(&v[i], c);
        assert_eq!(c, v.to_multivector().coeff(cga::Vector::<Q>::MASKS[i]).unwrap());
    }
    assert_eq!(v.clone().into_iter().collect::<Vec<_>>(), a.to_vec());
    assert_eq!((&v).into_iter().count(), cga::Vector::<Q>::LEN);
    let mut w = v.clone();
    for c in w.iter_mut() {
        *c = c.clone() * q(2);
    }
    w[4] = q(0);
    assert_eq!(w, cga::Vector::new(q(2), q(4), q(6), q(8), q(0)));
    assert!(std::panic::catch_unwind(|| v[5].clone()).is_err(), "out of range panics like an array");
}

#[test]
fn basis_constants_are_the_runtime_basis_elements() {
    let alg = g123inf::algebra();
    for (name, e) in [
        ("e1", g123inf::Vector::<Q>::e1().to_multivector()),
        ("einf", g123inf::Vector::<Q>::einf().to_multivector()),
        ("e12", g123inf::Motor::<Q>::e12().to_multivector()),
        ("e123inf", g123inf::Motor::<Q>::e123inf().to_multivector()),
    ] {
        let reference = algebra_core::Multivector::basis_element(&alg, g123inf::BASIS, name).expect("a basis name");
        assert_eq!(e, reference, "{name}");
    }
}

#[test]
fn scalar_operators_and_assignment() {
    let r = g3::Rotor::<Q>::new(q(1), ratio(1, 2), q(-2), q(3));
    let s = ratio(2, 3);
    let scaled = r.scale(&s);
    assert_eq!(r.clone() * s.clone(), scaled);
    assert_eq!(&r * s.clone(), scaled);
    assert_eq!(scaled.clone() / s.clone(), r);
    assert_eq!(&scaled / s.clone(), r);
    let mut t = r.clone();
    t *= s.clone();
    assert_eq!(t, scaled);
    t /= s;
    assert_eq!(t, r);
    t += r.clone();
    assert_eq!(t, &r + &r);
    t -= r.clone();
    assert_eq!(t, r);
    assert_eq!(g3::Rotor::<Q>::default(), g3::Rotor::zero());
    assert_eq!(2.0 * g3::Vector::<f64>::e3(), g3::Vector::new(0.0, 0.0, 2.0));
}

#[test]
fn mixed_value_and_reference_operators_agree() {
    let a = cga::Motor::<Q>::one() + cga::Motor::e12() * ratio(1, 2) + cga::Motor::e45();
    let v = cga::Vector::<Q>::e1() + cga::Vector::e5();
    let gp = &a * &v;
    assert_eq!(a.clone() * &v, gp);
    assert_eq!(&a * v.clone(), gp);
    let op = &a ^ &v;
    assert_eq!(a.clone() ^ &v, op);
    assert_eq!(&a ^ v.clone(), op);
    let lc = &v | &a;
    assert_eq!(v.clone() | &a, lc);
    assert_eq!(&v | a.clone(), lc);
}

/// `Copy` comes from a derive, so it holds exactly when the scalar is `Copy`.
#[test]
fn copy_when_the_scalar_is_copy() {
    fn is_copy<X: Copy>(_: &X) {}
    let m = cga::Motor::<f64>::one();
    is_copy(&m);
    let n = m; // a copy, `m` stays usable
    assert_eq!(m, n);
    is_copy(&g3::Rotor::<num_dual::Dual64>::one());
    assert_eq!(std::mem::size_of::<cga::Motor<f64>>(), 16 * 8);
}

#[cfg(feature = "serde")]
#[test]
fn serde_round_trip() {
    let m = g123inf::Motor::<f64>::new(1.0, 0.5, -0.25, 2.0, 0.0, 3.0, -1.0, 0.125);
    let json = serde_json::to_string(&m).expect("serialises");
    assert_eq!(
        json,
        r#"{"scalar":1.0,"e12":0.5,"e13":-0.25,"e23":2.0,"e1inf":0.0,"e2inf":3.0,"e3inf":-1.0,"e123inf":0.125}"#
    );
    assert_eq!(serde_json::from_str::<g123inf::Motor<f64>>(&json).expect("parses"), m);
}

/// `new` is a `const fn`: geometry known at compile time is a constant, and a product of
/// constants is the same as of the runtime values (checked against the runtime engine).
#[test]
fn constants_built_by_new_at_compile_time() {
    const AXIS: g3::Bivector<f64> = g3::Bivector::new(0.0, 0.0, 1.0);
    const X: g3::Vector<f64> = g3::Vector::new(1.0, 2.0, 3.0);
    const PAIR: [g3::Vector<f64>; 2] = [g3::Vector::new(1.0, 0.0, 0.0), X];
    let r = X * AXIS;
    assert_eq!(r.to_multivector(), X.to_multivector().gp(&AXIS.to_multivector()));
    assert_eq!(PAIR[1], X);
    // e23 * (e1 + 2 e2 + 3 e3) = e123 - 2 e3 + 3 e2 (blade order e1 e2 e3)
    assert_eq!((AXIS * X).to_multivector().to_string(), "3*e2 - 2*e3 + e123");
}

//! First check: the generated g123inf Motor product equals the runtime product.
use algebra_core::rational::{Q, q};
use gam_algebras::g123inf::{Motor, Vector};

#[test]
fn motor_product_matches_runtime() {
    let a = Motor::<Q>::new(q(1), q(2), q(-3), q(4), q(5), q(-6), q(7), q(8));
    let b = Motor::<Q>::new(q(-2), q(1), q(5), q(-1), q(3), q(2), q(-4), q(6));
    let c = &a * &b;
    assert_eq!(c.to_multivector(), a.to_multivector() * b.to_multivector());
    let v = Vector::<Q>::new(q(1), q(2), q(3), q(4));
    let s = a.sandwich(&v);
    // a random even element is not a versor: the fused sandwich is the projection onto Vector
    assert_eq!(s, Vector::project(&a.to_multivector().sandwich(&v.to_multivector())));
    let inv = a.inverse().unwrap();
    assert_eq!(&a * &inv, Motor::one());
}

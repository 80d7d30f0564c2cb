//! The vendored module written by `gam codegen` (committed as a snapshot in
//! `tests/vendored/g3_vendored.rs`, regenerated and compared by the CLI's snapshot test)
//! compiles on its own and agrees with the runtime reference.

include!("vendored/g3_vendored.rs");

use algebra_core::rational::{Q, q, ratio};
use g3_vendored::{Rotor, Vector};

#[test]
fn vendored_kernels_agree_with_the_runtime() {
    let r = Rotor::<Q>::new(q(1), ratio(1, 2), q(-2), q(3));
    let v = Vector::<Q>::new(q(2), q(-1), ratio(5, 3));
    let rv = &r * &v;
    assert_eq!(rv.to_multivector(), r.to_multivector() * v.to_multivector());
    let s = r.sandwich(&v);
    assert_eq!(s.to_multivector(), r.to_multivector().sandwich(&v.to_multivector()));
    // rev(R) v R is a vector, scaled in length by |R|^2
    let sv = Vector::try_from(&s.to_multivector()).expect("a rotor sandwich of a vector is a vector");
    let norm2 = r.norm_squared();
    assert_eq!(norm2, q(1) + ratio(1, 4) + q(4) + q(9));
    assert_eq!(sv.norm_squared(), norm2.clone() * norm2 * v.norm_squared());
    assert_eq!(&r * &r.inverse().unwrap(), Rotor::one());
}

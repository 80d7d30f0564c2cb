//! Kernels of types declared with a constraint (`where unit` / `where simple` in the `algebra!`
//! DSL): the unit actions `sandwich_unit` / `apply_unit` of `where unit` types (the cheaper of
//! the commutator form and the reduced kernel, output type proven) and `square_simple` agree
//! exactly over Q with the runtime product and the general fused action on random inputs that
//! satisfy the constraint, and are wrong on an input that violates it.
//!
//! The unit motors are exact rational unit motors `S = R T`: `R = r r / |r|²` for a random
//! rational rotor `r` (so `rev(R) R = 1` exactly) and a translator `T = 1 + ½ t einf`.

use algebra_core::rational::{Q, ratio};
use algebra_core::{Multivector as Mv, Ring};
use gam_algebras::{cga_null, g123inf};
use proptest::prelude::*;

fn small() -> impl Strategy<Value = Q> {
    (-9i64..=9, 1i64..=7).prop_map(|(n, d)| ratio(n, d))
}

/// A unit motor `R T` built in a module with elements `1, e12, e13, e23, e1inf, e2inf, e3inf`
/// (the algebra and basis of `alg`), from seeds `(w, x, y, z)` of the rotor and `t` of the
/// translation.
fn unit_motor(
    alg: &std::sync::Arc<algebra_core::Algebra>,
    basis: algebra_core::Basis,
    r: &[Q; 4],
    t: &[Q; 3],
) -> Mv<Q> {
    let w = &r[0] + &Q::from_i64(10); // never the zero rotor
    let rotor =
        Mv::from_terms(alg, basis, [("1", w), ("e12", r[1].clone()), ("e13", r[2].clone()), ("e23", r[3].clone())])
            .unwrap();
    let n2 = (&rotor.reverse() * &rotor).scalar_part();
    let rotor = (&rotor * &rotor).scale(&(Q::one() / n2));
    let half = ratio(1, 2);
    let translator = Mv::from_terms(
        alg,
        basis,
        [("1", Q::one()), ("e1inf", &t[0] * &half), ("e2inf", &t[1] * &half), ("e3inf", &t[2] * &half)],
    )
    .unwrap();
    let s = &rotor * &translator;
    assert_eq!(&s.reverse() * &s, Mv::scalar(alg, basis, Q::one()), "a unit motor");
    s
}

fn arrays() -> impl Strategy<Value = ([Q; 4], [Q; 3], [Q; 5])> {
    ([small(), small(), small(), small()], [small(), small(), small()], [small(), small(), small(), small(), small()])
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(24))]

    /// cga-null: the unit motor's actions on a vector (a point of the paper's G_{0123inf})
    /// are vectors (the σ part proven zero), computed with fewer multiplications than the
    /// general fused action (36 against 64), which agrees with them on unit motors.
    #[test]
    fn cga_null_unit_motor_on_a_vector((r, t, x) in arrays()) {
        let (alg, basis) = (cga_null::algebra(), cga_null::BASIS);
        let s = unit_motor(&alg, basis, &r, &t);
        let m = cga_null::Motor::project(&s);
        let v = cga_null::Vector::new(x[0].clone(), x[1].clone(), x[2].clone(), x[3].clone(), x[4].clone());
        let xv = v.to_multivector();
        let sandwich: cga_null::Vector<Q> = m.sandwich_unit(&v);
        prop_assert_eq!(sandwich.to_multivector(), &(&s.reverse() * &xv) * &s);
        prop_assert_eq!(&sandwich, &m.sandwich(&v));
        prop_assert_eq!(m.apply_unit(&v), m.apply(&v));
        let apply: cga_null::Vector<Q> = m.apply_unit(&v);
        prop_assert_eq!(apply.to_multivector(), &(&s * &xv) * &s.reverse());
    }

    /// g123inf: a unit pose fixes every pseudoscalar `α + β ω` (the kernel is a copy, 0
    /// multiplications instead of 12).
    #[test]
    fn g123inf_unit_motor_on_a_pseudoscalar((r, t, x) in arrays()) {
        let (alg, basis) = (g123inf::algebra(), g123inf::BASIS);
        let s = unit_motor(&alg, basis, &r, &t);
        let m = g123inf::Motor::project(&s);
        let p = g123inf::Pseudoscalar::new(x[0].clone(), x[1].clone());
        let xp = p.to_multivector();
        prop_assert_eq!(m.sandwich_unit(&p).to_multivector(), &(&s.reverse() * &xp) * &s);
        prop_assert_eq!(m.apply_unit(&p).to_multivector(), &(&s * &xp) * &s.reverse());
        prop_assert_eq!(m.sandwich_unit(&p), p);
    }
}

/// `S = 2 + e123inf` is not unit (rev(S) S = 4 + 4 e123inf): the exact sandwich of e0 + 3 e1
/// has a part outside the vectors, so `sandwich_unit` is wrong, and the general fused
/// `sandwich` returns exactly the projection onto the vectors (the σ part its doc says it
/// drops).
#[test]
fn cga_null_kernel_is_wrong_on_a_non_unit_motor() {
    let (alg, basis) = (cga_null::algebra(), cga_null::BASIS);
    let s = Mv::from_terms(&alg, basis, [("1", Q::from_i64(2)), ("e123inf", Q::one())]).unwrap();
    let m = cga_null::Motor::project(&s);
    let v = cga_null::Vector::new(Q::one(), Q::from_i64(3), Q::zero(), Q::zero(), Q::zero());
    let exact = &(&s.reverse() * &v.to_multivector()) * &s;
    assert_ne!(m.sandwich_unit(&v).to_multivector(), exact);
    let outside = cga_null::Vector::<Q>::MASKS.iter().fold(exact.clone(), |r, &mask| {
        let mut r = r;
        r.coeffs_mut()[mask as usize] = Q::zero();
        r
    });
    assert!(!outside.is_zero());
    assert_eq!(m.sandwich(&v).to_multivector(), &exact - &outside);
    assert_ne!(m.sandwich_unit(&v), m.sandwich(&v));
}

/// A non-unit pose scales a pseudoscalar by rev(S) S: the copy kernel is wrong.
#[test]
fn g123inf_kernel_is_wrong_on_a_non_unit_motor() {
    let m = g123inf::Motor::new(
        Q::from_i64(2),
        Q::zero(),
        Q::zero(),
        Q::zero(),
        Q::zero(),
        Q::zero(),
        Q::zero(),
        Q::zero(),
    );
    let p = g123inf::Pseudoscalar::new(Q::one(), Q::one());
    assert_eq!(m.sandwich(&p).to_multivector(), p.scale(&Q::from_i64(4)).to_multivector());
    assert_ne!(m.sandwich_unit(&p).to_multivector(), m.sandwich(&p).to_multivector());
}

algebra_macros::algebra! {
    /// PGA lines declared simple (the Plücker condition) and conformal points declared null.
    mod pga_lines {
        metric builtin "pga3";
        types {
            Scalar = grade 0;
            /// Lines: simple bivectors.
            Line = grade 2 where simple;
            Multivector = all;
        }
    }
}

algebra_macros::algebra! {
    /// Conformal points declared null: their square vanishes identically, so no method is
    /// emitted (no declared type would hold an empty output).
    mod null_points {
        metric builtin "cga-null";
        basis product;
        types {
            Point = grade 1 where null;
            Multivector = all;
        }
    }
}

/// The line through two points: `p ∨ q` is simple; for such lines `square_simple` (3
/// multiplications, output a scalar) equals `L L` of the runtime, whose pseudoscalar part is
/// `2 L ∧ L = 0`; on a non-simple bivector the dropped pseudoscalar part is non-zero.
#[test]
fn pga_simple_line_squares_to_a_scalar() {
    let alg = pga_lines::algebra();
    let bv = |c: [i64; 6]| {
        let names = ["e01", "e02", "e03", "e12", "e13", "e23"];
        Mv::from_terms(&alg, pga_lines::BASIS, names.iter().zip(c).map(|(n, v)| (*n, Q::from_i64(v)))).unwrap()
    };
    let mut checked = 0;
    for a in -2i64..=2 {
        for b in -1i64..=2 {
            // L = u ∧ v of two vectors (planes) is simple
            let u = Mv::from_terms(
                &alg,
                pga_lines::BASIS,
                [("e0", Q::from_i64(a)), ("e1", Q::one()), ("e2", Q::from_i64(b))],
            )
            .unwrap();
            let v = Mv::from_terms(
                &alg,
                pga_lines::BASIS,
                [("e0", Q::from_i64(b)), ("e2", Q::from_i64(a)), ("e3", Q::one())],
            )
            .unwrap();
            let l = u.op(&v);
            assert!(l.op(&l).is_zero());
            let line = pga_lines::Line::project(&l);
            let s: pga_lines::Scalar<Q> = line.square_simple();
            assert_eq!(s.to_multivector(), &l * &l);
            checked += 1;
        }
    }
    assert_eq!(checked, 20);
    // e01 + e23 is not simple: L L = -1 + 2 e0123, and the kernel keeps only the -1
    let l = bv([1, 0, 0, 0, 0, 1]);
    let full = &l * &l;
    let line = pga_lines::Line::project(&l);
    assert_ne!(line.square_simple().to_multivector(), full);
    assert_eq!(line.square_simple().to_multivector(), Mv::scalar(&alg, pga_lines::BASIS, full.scalar_part()));
    let _ = null_points::Point::<Q>::zero();
}

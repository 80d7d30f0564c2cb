//! The same generated code over every scalar type: `f64`, num-dual's `Dual64` (derivatives),
//! `MpFloat` (256-bit MPFR floats), `MpRational` (GMP rationals, exact) and `Poly` (symbolic
//! polynomials, exact identities such as the paper's eq. (5)).

use algebra_core::ops::{CommutatorProduct, RegressiveProduct};
use algebra_core::rational::{Q, q, ratio, rational_to_f64};
use algebra_core::{MpFloat, MpRational, Multivector as Mv, Poly, PrecisionGuard, Ring};
use gam_algebras::{cga_null, g3, g123inf};
use num_dual::Dual64;

/// `n` fixed rational coefficients with varied signs and denominators 2..=6.
fn rationals(n: usize, shift: i64) -> Vec<Q> {
    (0..n as i64).map(|k| ratio(3 * (k + shift) % 11 - 5, (k + shift) % 5 + 2)).collect()
}

/// `n` fixed dyadic coefficients (quarters: exact in f64, and so are their small products).
fn dyadics(n: usize, shift: i64) -> Vec<Q> {
    (0..n as i64).map(|k| ratio((5 * (k + shift)) % 13 - 6, 4)).collect()
}

/// A g123inf motor over any scalar from rational coefficients.
fn motor<T: Ring>(c: &[Q]) -> g123inf::Motor<T> {
    let c: Vec<T> = c.iter().map(T::from_rational).collect();
    g123inf::Motor::new(
        c[0].clone(),
        c[1].clone(),
        c[2].clone(),
        c[3].clone(),
        c[4].clone(),
        c[5].clone(),
        c[6].clone(),
        c[7].clone(),
    )
}

/// A full cga_null multivector over any scalar from 32 rational coefficients (product basis).
fn full_cga_null<T: Ring>(c: &[Q]) -> cga_null::Multivector<T> {
    let coeffs = c.iter().map(T::from_rational).collect();
    let m = Mv::from_coeffs(&cga_null::algebra(), cga_null::BASIS, coeffs).expect("32 coefficients");
    cga_null::Multivector::project(&m)
}

#[test]
fn f64_kernels_match_the_runtime() {
    let a = motor::<f64>(&rationals(8, 0));
    let b = motor::<f64>(&rationals(8, 3));
    let c = a * b;
    let reference = a.to_multivector() * b.to_multivector();
    assert!((c.to_multivector() - reference).magnitude() < 1e-12);
    let inv = a.inverse().expect("invertible");
    assert!((a * inv - g123inf::Motor::one()).to_multivector().magnitude() < 1e-12);
    let x = full_cga_null::<f64>(&rationals(32, 1));
    let y = full_cga_null::<f64>(&rationals(32, 4));
    let xy = x * y;
    let reference = x.to_multivector() * y.to_multivector();
    assert!((xy.to_multivector() - &reference).magnitude() < 1e-12 * reference.magnitude());
}

/// Dual numbers `c0 + t c1 + ε c1` (the value at `t` and the derivative in `t`).
fn duals_at(m0: &[Q], m1: &[Q], t: &Q) -> Vec<Dual64> {
    m0.iter().zip(m1).map(|(a, b)| Dual64::new(rational_to_f64(&(a + t * b)), rational_to_f64(b))).collect()
}

/// A g123inf motor over Dual64 from its eight dual coefficients.
fn dual_motor(c: Vec<Dual64>) -> g123inf::Motor<Dual64> {
    let mut full = vec![Dual64::from(0.0); g123inf::algebra().dim()];
    for (mask, v) in g123inf::Motor::<Dual64>::MASKS.iter().zip(c) {
        full[*mask as usize] = v;
    }
    g123inf::Motor::project(&Mv::from_coeffs(&g123inf::algebra(), g123inf::BASIS, full).expect("16 coefficients"))
}

/// The value and derivative parts of a Dual64 multivector equal two exact ones.
fn assert_dual_parts(what: &str, got: &Mv<Dual64>, value: &Mv<Q>, derivative: &Mv<Q>) {
    for mask in 0..got.coeffs().len() as u32 {
        let g = got.coeff(mask).unwrap();
        assert_eq!(g.re, rational_to_f64(value.coeff(mask).unwrap()), "{what}: value, mask {mask}");
        assert_eq!(g.eps, rational_to_f64(derivative.coeff(mask).unwrap()), "{what}: derivative, mask {mask}");
    }
}

/// `d/dt (M(t) M(t)) = M1 M0 + M0 M1` at `t = 0` for `M(t) = M0 + t M1` (and
/// `M1 M(t) + M(t) M1` at `t = 1/2`): the derivative comes from dual numbers through the
/// generated kernel, the right side is computed exactly over Q. Coefficients are dyadic, so
/// every f64 operation is exact and `==` applies.
#[test]
fn dual64_derivative_of_a_square() {
    for t in [ratio(0, 1), ratio(1, 2)] {
        // g123inf motors
        let (m0, m1) = (dyadics(8, 0), dyadics(8, 5));
        let m = dual_motor(duals_at(&m0, &m1, &t));
        let (a, b) = (motor::<Q>(&m0), motor::<Q>(&m1));
        let at_t = &a + &b.scale(&t);
        let derivative = &(&b * &at_t) + &(&at_t * &b);
        if t == ratio(0, 1) {
            assert_eq!(derivative, &(&b * &a) + &(&a * &b));
        }
        let what = format!("g123inf Motor, t = {t}");
        assert_dual_parts(
            &what,
            &(m * m).to_multivector(),
            &(&at_t * &at_t).to_multivector(),
            &derivative.to_multivector(),
        );

        // the full cga_null multivector (product basis, the heaviest kernel)
        let (m0, m1) = (dyadics(32, 1), dyadics(32, 7));
        let (a, b) = (full_cga_null::<Q>(&m0), full_cga_null::<Q>(&m1));
        let m = cga_null::Multivector::<Dual64>::project(
            &Mv::from_coeffs(&cga_null::algebra(), cga_null::BASIS, duals_at(&m0, &m1, &t)).expect("32 coefficients"),
        );
        let at_t = &a + &b.scale(&t);
        let derivative = &(&b * &at_t) + &(&at_t * &b);
        let what = format!("cga_null Multivector, t = {t}");
        assert_dual_parts(
            &what,
            &(m * m).to_multivector(),
            &(&at_t * &at_t).to_multivector(),
            &derivative.to_multivector(),
        );
    }
}

/// `|x - reference|_1 <= 1e-70 · max(1, |reference|_1)` at 256 bits.
fn assert_mp_close(what: &str, x: &Mv<MpFloat>, reference: &Mv<Q>) {
    let r = reference.map_coeffs(MpFloat::from_rational);
    let err = (x - &r).magnitude();
    assert!(err <= 1e-70 * r.magnitude().max(1.0), "{what}: error {err:e}");
}

/// 256-bit MPFR floats through the generated kernels agree with the exact rational results to
/// 1e-70 (products, sandwich, inverse, norm).
#[test]
fn mpfloat_256_bits_agrees_with_rationals() {
    let _guard = PrecisionGuard::new(256);
    let (cq, dq) = (rationals(8, 0), rationals(8, 2));
    let (a, b) = (motor::<MpFloat>(&cq), motor::<MpFloat>(&dq));
    let (aq, bq) = (motor::<Q>(&cq), motor::<Q>(&dq));
    assert_eq!(a.scalar.precision(), 256);
    assert_mp_close("Motor * Motor", &(&a * &b).to_multivector(), &(&aq * &bq).to_multivector());
    let v = g123inf::Vector::<MpFloat>::new(
        MpFloat::from_ratio(1, 3),
        MpFloat::from_ratio(-2, 7),
        MpFloat::from_ratio(5, 11),
        MpFloat::from_ratio(1, 13),
    );
    let vq = g123inf::Vector::<Q>::new(ratio(1, 3), ratio(-2, 7), ratio(5, 11), ratio(1, 13));
    assert_mp_close("Motor sandwich Vector", &a.sandwich(&v).to_multivector(), &aq.sandwich(&vq).to_multivector());
    let inv = a.inverse().expect("invertible");
    assert_mp_close("Motor inverse", &inv.to_multivector(), &aq.inverse().expect("invertible").to_multivector());
    let n = a.norm_squared().sub_ref(&MpFloat::from_rational(&aq.norm_squared()));
    assert!(n.magnitude() < 1e-70);
    // the heaviest kernel: full cga_null products
    let (xq, yq) = (full_cga_null::<Q>(&rationals(32, 1)), full_cga_null::<Q>(&rationals(32, 6)));
    let (x, y) = (full_cga_null::<MpFloat>(&rationals(32, 1)), full_cga_null::<MpFloat>(&rationals(32, 6)));
    assert_mp_close("cga_null gp", &(&x * &y).to_multivector(), &(&xq * &yq).to_multivector());
    assert_mp_close("cga_null regressive", &x.regressive(&y).to_multivector(), &xq.regressive(&yq).to_multivector());
    assert_mp_close(
        "cga_null inverse",
        &x.inverse().expect("inv").to_multivector(),
        &xq.inverse().expect("inv").to_multivector(),
    );
}

/// GMP rationals give exactly the num-rational results.
#[test]
fn mprational_is_exact_against_q() {
    let to_q = |m: &Mv<MpRational>| m.map_coeffs(MpRational::to_q);
    let (cq, dq) = (rationals(8, 1), rationals(8, 4));
    let (a, b) = (motor::<MpRational>(&cq), motor::<MpRational>(&dq));
    let (aq, bq) = (motor::<Q>(&cq), motor::<Q>(&dq));
    assert_eq!(to_q(&(&a * &b).to_multivector()), (&aq * &bq).to_multivector());
    assert_eq!(to_q(&a.commutator(&b).to_multivector()), aq.commutator(&bq).to_multivector());
    assert_eq!(
        to_q(&a.inverse().expect("invertible").to_multivector()),
        aq.inverse().expect("invertible").to_multivector()
    );
    assert_eq!(a.norm_squared().to_q(), aq.norm_squared());
    let (xq, yq) = (full_cga_null::<Q>(&rationals(32, 2)), full_cga_null::<Q>(&rationals(32, 9)));
    let (x, y) = (full_cga_null::<MpRational>(&rationals(32, 2)), full_cga_null::<MpRational>(&rationals(32, 9)));
    assert_eq!(to_q(&(&x * &y).to_multivector()), (&xq * &yq).to_multivector());
    assert_eq!(to_q(&(&x ^ &y).to_multivector()), (&xq ^ &yq).to_multivector());
    assert_eq!(
        to_q(&x.inverse().expect("invertible").to_multivector()),
        xq.inverse().expect("invertible").to_multivector()
    );
    let r = g3::Rotor::<MpRational>::new(
        MpRational::from_ratio(1, 2),
        MpRational::from_ratio(-1, 3),
        MpRational::from_ratio(2, 5),
        MpRational::from_ratio(3, 7),
    );
    let rq = g3::Rotor::<Q>::new(ratio(1, 2), ratio(-1, 3), ratio(2, 5), ratio(3, 7));
    let v =
        g3::Vector::<MpRational>::new(MpRational::from_i64(1), MpRational::from_i64(-2), MpRational::from_ratio(1, 2));
    let vq = g3::Vector::<Q>::new(q(1), q(-2), ratio(1, 2));
    assert_eq!(to_q(&r.sandwich(&v).to_multivector()), rq.sandwich(&vq).to_multivector());
}

/// The symbolic pose `S` of the paper with the coefficients of eq. (4).
fn symbolic_motor() -> g123inf::Motor<Poly> {
    let v = Poly::var;
    g123inf::Motor::new(v("S"), v("S12"), v("S13"), v("S23"), v("S1inf"), v("S2inf"), v("S3inf"), v("Sw"))
}

/// The generated sandwich `rev(S) x S` of a symbolic vector by a symbolic motor equals the
/// runtime `Multivector<Poly>` sandwich as polynomials (an identity in 12 variables).
#[test]
fn poly_symbolic_sandwich_matches_the_runtime() {
    let s = symbolic_motor();
    let v = Poly::var;
    let x = g123inf::Vector::new(v("x1"), v("x2"), v("x3"), v("xinf"));
    let generated = s.sandwich(&x);
    let runtime = s.to_multivector().sandwich(&x.to_multivector());
    // the fused kernel is typed as a Vector, and the sandwich of a vector by any even element
    // of G_{123inf} is a vector (the runtime result converts exactly)
    let back = g123inf::Vector::try_from(&runtime).expect("a motor maps vectors to vectors");
    assert_eq!(generated, back);
}

/// Eq. (5): `S rev(S)` is the pseudoscalar `(S^2 + S12^2 + S13^2 + S23^2)
/// + 2(S Sw - S12 S3inf + S13 S2inf - S23 S1inf) e123inf`, from the generated kernels.
#[test]
fn poly_eq5_motor_times_its_reverse() {
    let s = symbolic_motor();
    let product = &s * &s.reverse();
    let v = Poly::var;
    let two = Poly::from_i64(2);
    let alpha = v("S") * v("S") + v("S12") * v("S12") + v("S13") * v("S13") + v("S23") * v("S23");
    let beta = two * (v("S") * v("Sw") - v("S12") * v("S3inf") + v("S13") * v("S2inf") - v("S23") * v("S1inf"));
    let expected = g123inf::Motor::new(
        alpha.clone(),
        Poly::zero(),
        Poly::zero(),
        Poly::zero(),
        Poly::zero(),
        Poly::zero(),
        Poly::zero(),
        beta.clone(),
    );
    assert_eq!(product, expected, "S rev(S) = {product}");
    assert_eq!(alpha.to_string(), "S**2 + S12**2 + S13**2 + S23**2");
    // it is a pseudoscalar of the declared type, and rev(S) S agrees (S rev(S) = rev(S) S)
    let p = g123inf::Pseudoscalar::try_from(&product.to_multivector()).expect("a pseudoscalar");
    assert_eq!((&p.scalar, &p.e123inf), (&alpha, &beta));
    assert_eq!(&s.reverse() * &s, product);
    // and the generated norm_squared is its scalar part
    assert_eq!(s.norm_squared(), p.scalar);
}

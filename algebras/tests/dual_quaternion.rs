//! The dual quaternions and the isomorphism of the main paper's Appendix 2 with
//! `G_{123inf}^+`: exact checks over rationals (bijection, homomorphism, conjugates, the norm of
//! eq. (5), the velocity bivector, the pose action `F_S`), then float checks against the
//! standard unit dual quaternion of a rigid motion and against nalgebra.

use algebra_core::rational::{Q, q, ratio};
use algebra_core::test_support::Xorshift;
use algebra_core::{Algebra, Basis, Field, Multivector, Ring};
use g123inf::Motor;
use gam_algebras::dual_quaternion::Quaternion;
use gam_algebras::{DualQuaternion, cga_null, g123inf};
use proptest::prelude::*;

/// The motor with coefficients in field order `(1, e12, e13, e23, e1inf, e2inf, e3inf, e123inf)`.
fn motor<T: Ring>(c: [T; 8]) -> Motor<T> {
    let [s, e12, e13, e23, e1inf, e2inf, e3inf, w] = c;
    Motor::new(s, e12, e13, e23, e1inf, e2inf, e3inf, w)
}

fn coeffs<T: Ring>(m: &Motor<T>) -> [T; 8] {
    [
        m.scalar.clone(),
        m.e12.clone(),
        m.e13.clone(),
        m.e23.clone(),
        m.e1inf.clone(),
        m.e2inf.clone(),
        m.e3inf.clone(),
        m.e123inf.clone(),
    ]
}

/// The image of `einf -> -einf` (an orthogonal map of the generators, hence an automorphism).
fn flip_einf<T: Ring>(m: &Motor<T>) -> Motor<T> {
    let [s, e12, e13, e23, e1inf, e2inf, e3inf, w] = coeffs(m);
    motor([s, e12, e13, e23, e1inf.neg_ref(), e2inf.neg_ref(), e3inf.neg_ref(), w.neg_ref()])
}

/// The paper's `F_S(p) = P(rev(S) E(p) S)`, computed in the generated `cga_null` algebra
/// (G_{0123inf}, product basis) with `E(p) = e0 + p1 e1 + p2 e2 + p3 e3` and `P` dividing the
/// e1, e2, e3 coefficients by the e0 coefficient.
fn ga_transform<T: Field>(s: &Motor<T>, p: &[T; 3]) -> Option<[T; 3]> {
    let [s0, e12, e13, e23, e1inf, e2inf, e3inf, w] = coeffs(s);
    let s = cga_null::Motor::new(s0, e12, e13, e23, e1inf, e2inf, e3inf, w);
    let x = cga_null::Vector::new(T::one(), p[0].clone(), p[1].clone(), p[2].clone(), T::zero());
    let y = s.sandwich(&x);
    let inv = y.e0.try_recip()?;
    Some([y.e1.mul_ref(&inv), y.e2.mul_ref(&inv), y.e3.mul_ref(&inv)])
}

fn rational() -> impl Strategy<Value = Q> {
    (-30i64..=30, 1i64..=7).prop_map(|(n, d)| ratio(n, d))
}

fn rational_motor() -> impl Strategy<Value = Motor<Q>> {
    prop::array::uniform8(rational()).prop_map(motor)
}

fn rational_dq() -> impl Strategy<Value = DualQuaternion<Q>> {
    prop::array::uniform8(rational()).prop_map(DualQuaternion::from_coeffs)
}

fn rational_point() -> impl Strategy<Value = [Q; 3]> {
    prop::array::uniform3(rational())
}

/// The printed table of Appendix 2, basis element by basis element.
#[test]
fn appendix_2_table() {
    let dq = |c: [i64; 8]| DualQuaternion::from_coeffs(c.map(q));
    let table = [
        ("1", dq([1, 0, 0, 0, 0, 0, 0, 0])),       // 1
        ("e12", dq([0, 0, 0, -1, 0, 0, 0, 0])),    // -k
        ("e13", dq([0, 0, 1, 0, 0, 0, 0, 0])),     // +j
        ("e23", dq([0, -1, 0, 0, 0, 0, 0, 0])),    // -i
        ("e1inf", dq([0, 0, 0, 0, 0, 1, 0, 0])),   // ε i
        ("e2inf", dq([0, 0, 0, 0, 0, 0, 1, 0])),   // ε j
        ("e3inf", dq([0, 0, 0, 0, 0, 0, 0, 1])),   // ε k
        ("e123inf", dq([0, 0, 0, 0, 1, 0, 0, 0])), // ε
    ];
    let alg = Algebra::builtin("g123inf").unwrap();
    for (name, image) in table {
        let e = Motor::<Q>::project(&Multivector::basis_element(&alg, Basis::Blade, name).unwrap());
        assert_eq!(DualQuaternion::from(&e), image, "{name}");
        assert_eq!(Motor::from(&image), e, "{name}");
    }
}

/// `phi(e_a e_b) = phi(e_a) phi(e_b)` for all 64 pairs of basis elements, with the product taken
/// from the runtime tables (independent of the generated Motor kernel): by bilinearity this
/// proves that the paper's map, with the printed signs, is an algebra homomorphism.
#[test]
fn appendix_2_map_is_a_homomorphism_on_the_basis() {
    let alg = Algebra::builtin("g123inf").unwrap();
    for a in Motor::<Q>::ELEMENTS {
        for b in Motor::<Q>::ELEMENTS {
            let ea = Multivector::<Q>::basis_element(&alg, Basis::Blade, a).unwrap();
            let eb = Multivector::<Q>::basis_element(&alg, Basis::Blade, b).unwrap();
            let prod = Motor::try_from(&(&ea * &eb)).expect("the even subalgebra is closed");
            let lhs = DualQuaternion::from(&prod);
            let rhs = &DualQuaternion::from(&Motor::project(&ea)) * &DualQuaternion::from(&Motor::project(&eb));
            assert_eq!(lhs, rhs, "{a} * {b}");
        }
    }
}

/// The Appendix 2 form of Theorem 3.2: the velocity bivector `ν = Ω e123 + u einf` maps to
/// `ε (u1 i + u2 j + u3 k) - (Ω1 i + Ω2 j + Ω3 k)`.
#[test]
fn velocity_bivector_maps_as_in_appendix_2() {
    let alg = Algebra::builtin("g123inf").unwrap();
    let e = |n: &str| Multivector::<Q>::basis_element(&alg, Basis::Blade, n).unwrap();
    let (omega, u) = ([q(2), ratio(-1, 3), q(5)], [q(-7), ratio(1, 2), q(3)]);
    let vec = |c: &[Q; 3]| &(&e("e1").scale(&c[0]) + &e("e2").scale(&c[1])) + &e("e3").scale(&c[2]);
    let nu = &(&vec(&omega) * &e("e123")) + &(&vec(&u) * &e("einf"));
    let image = DualQuaternion::from(&Motor::try_from(&nu).unwrap());
    let expected = DualQuaternion::new(Quaternion::pure(&omega).scale(&q(-1)), Quaternion::pure(&u));
    assert_eq!(image, expected);
}

proptest! {
    #[test]
    fn map_is_a_bijection(s in rational_motor(), d in rational_dq()) {
        prop_assert_eq!(Motor::from(&DualQuaternion::from(&s)), s.clone());
        prop_assert_eq!(DualQuaternion::from(&Motor::from(&d)), d.clone());
        // by value too
        prop_assert_eq!(Motor::from(DualQuaternion::from(s.clone())), s);
    }

    #[test]
    fn map_is_a_homomorphism(a in rational_motor(), b in rational_motor()) {
        let lhs = DualQuaternion::from(&(&a * &b));
        let rhs = &DualQuaternion::from(&a) * &DualQuaternion::from(&b);
        prop_assert_eq!(&lhs, &rhs);
        prop_assert_eq!(lhs, DualQuaternion::from(a) * DualQuaternion::from(b));
    }

    #[test]
    fn dual_quaternion_product_is_associative(a in rational_dq(), b in rational_dq(), c in rational_dq()) {
        prop_assert_eq!(&(&a * &b) * &c, &a * &(&b * &c));
    }

    #[test]
    fn reverse_and_einf_flip_are_the_conjugates(s in rational_motor()) {
        let phi = DualQuaternion::from(&s);
        prop_assert_eq!(DualQuaternion::from(&s.reverse()), phi.conjugate());
        prop_assert_eq!(DualQuaternion::from(&flip_einf(&s)), phi.dual_conjugate());
        prop_assert_eq!(DualQuaternion::from(&flip_einf(&s.reverse())), phi.conjugate_both());
    }

    #[test]
    fn conjugates_reverse_or_preserve_products(a in rational_dq(), b in rational_dq()) {
        let ab = &a * &b;
        prop_assert_eq!(ab.conjugate(), &b.conjugate() * &a.conjugate());
        prop_assert_eq!(ab.dual_conjugate(), &a.dual_conjugate() * &b.dual_conjugate());
        prop_assert_eq!(ab.conjugate_both(), &b.conjugate_both() * &a.conjugate_both());
    }

    /// `rev(S) S = α + β ω` (eq. (5)) maps to the dual-quaternion norm `q* q = q q*`.
    #[test]
    fn eq_5_norm_is_the_dual_quaternion_norm(s in rational_motor()) {
        let ss = &s.reverse() * &s;
        let (alpha, beta) = DualQuaternion::from(&s).norm_squared();
        // eq. (5), literally
        let paper_alpha = s.scalar.clone() * &s.scalar + &(s.e12.clone() * &s.e12) + &(s.e13.clone() * &s.e13)
            + &(s.e23.clone() * &s.e23);
        let paper_beta = q(2) * (s.scalar.clone() * &s.e123inf - &(s.e12.clone() * &s.e3inf)
            + &(s.e13.clone() * &s.e2inf) - &(s.e23.clone() * &s.e1inf));
        prop_assert_eq!(&ss, &motor([paper_alpha.clone(), q(0), q(0), q(0), q(0), q(0), q(0), paper_beta.clone()]));
        prop_assert_eq!((&alpha, &beta), (&paper_alpha, &paper_beta));
        let phi = DualQuaternion::from(&s);
        let n = DualQuaternion::dual_number(alpha, beta);
        prop_assert_eq!(DualQuaternion::from(&ss), n.clone());
        prop_assert_eq!(&phi.conjugate() * &phi, n.clone());
        prop_assert_eq!(&phi * &phi.conjugate(), n);
    }

    /// `from_pose` is an anti-isomorphism (`F_{UV} = F_V F_U`) inverted by `to_pose`.
    #[test]
    fn pose_map_is_an_anti_homomorphism(u in rational_motor(), v in rational_motor()) {
        let qu = DualQuaternion::from_pose(&u);
        prop_assert_eq!(DualQuaternion::from_pose(&(&u * &v)), &DualQuaternion::from_pose(&v) * &qu);
        prop_assert_eq!(qu.to_pose(), u);
    }

    /// Exactly, for any non-singular (non-unit) pose: the paper's `F_S(p) = P(rev(S) E(p) S)`
    /// equals the dual-quaternion action of `from_pose(S)` on `1 + ε p`.
    #[test]
    fn pose_acts_as_its_dual_quaternion(s in rational_motor(), p in rational_point()) {
        let ga = ga_transform(&s, &p);
        let dq = DualQuaternion::from_pose(&s).transform_point(&p);
        prop_assert_eq!(ga.is_none(), DualQuaternion::from(&s).norm_squared().0 == q(0));
        prop_assert_eq!(ga, dq);
    }
}

// ---------------------------------------------------------------------------------------------
// Floats: the standard unit dual quaternion of a rigid motion, and nalgebra.

/// A random unit vector (a normalised [`Xorshift::vec3`]).
fn unit3(rng: &mut Xorshift) -> [f64; 3] {
    let v = rng.vec3();
    let n = (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt();
    v.map(|x| x / n)
}

fn close(a: &[f64], b: &[f64], tol: f64) -> bool {
    a.iter().zip(b).all(|(x, y)| (x - y).abs() <= tol * (1.0 + y.abs()))
}

/// The paper's rotation `R = cos(φ/2) + sin(φ/2) (a e123)`, `a e123 = a1 e23 - a2 e13 + a3 e12`.
fn paper_rotation(axis: [f64; 3], phi: f64) -> Motor<f64> {
    let (c, s) = ((phi / 2.0).cos(), (phi / 2.0).sin());
    motor([c, s * axis[2], -s * axis[1], s * axis[0], 0.0, 0.0, 0.0, 0.0])
}

/// The paper's translation `T = 1 + 1/2 v einf`.
fn paper_translation(v: [f64; 3]) -> Motor<f64> {
    motor([1.0, 0.0, 0.0, 0.0, v[0] / 2.0, v[1] / 2.0, v[2] / 2.0, 0.0])
}

/// Rodrigues: the rotation of `p` by `phi` about the unit `axis`, then the translation by `v`.
fn rotate_then_translate(axis: [f64; 3], phi: f64, v: [f64; 3], p: [f64; 3]) -> [f64; 3] {
    let [a1, a2, a3] = axis;
    let (c, s) = (phi.cos(), phi.sin());
    let dot = a1 * p[0] + a2 * p[1] + a3 * p[2];
    let cross = [a2 * p[2] - a3 * p[1], a3 * p[0] - a1 * p[2], a1 * p[1] - a2 * p[0]];
    [0, 1, 2].map(|i| p[i] * c + cross[i] * s + axis[i] * dot * (1.0 - c) + v[i])
}

/// `S = R T` (rotate, then translate, as in the design notes) maps to the standard unit dual
/// quaternion `q = r + ε (1/2) t r`, with `r = cos(φ/2) + sin(φ/2) (a1 i + a2 j + a3 k)`;
/// the point computed by the paper's `F_S`, by the dual quaternion `q (1 + ε p) q̄`, by
/// `r p r* + t` and by Rodrigues' formula agree to 1e-12.
#[test]
fn rotation_and_translation_map_to_the_standard_unit_dual_quaternion() {
    let mut rng = Xorshift(0x9e37_79b9_7f4a_7c15);
    for _ in 0..200 {
        let (axis, phi, v, p) = (unit3(&mut rng), 3.0 * rng.symmetric(), rng.vec3().map(|x| 4.0 * x), rng.vec3());
        let s = paper_rotation(axis, phi) * paper_translation(v);
        let qdq = DualQuaternion::from_pose(&s);
        // the textbook construction
        let r = Quaternion::new((phi / 2.0).cos(), 0.0, 0.0, 0.0);
        let r = Quaternion {
            x: (phi / 2.0).sin() * axis[0],
            y: (phi / 2.0).sin() * axis[1],
            z: (phi / 2.0).sin() * axis[2],
            ..r
        };
        let standard = DualQuaternion::new(r.clone(), (&Quaternion::pure(&v) * &r).scale(&0.5));
        assert!(close(&qdq.coeffs(), &standard.coeffs(), 1e-12), "{qdq} vs {standard}");
        let (n0, n1) = qdq.norm_squared();
        assert!((n0 - 1.0).abs() < 1e-12 && n1.abs() < 1e-12, "unit");

        let expected = rotate_then_translate(axis, phi, v, p);
        let by_ga = ga_transform(&s, &p).unwrap();
        let by_dq = qdq.transform_point(&p).unwrap();
        let t = (&qdq.dual * &qdq.real.conjugate()).scale(&2.0).vector();
        let rpr = (&(&qdq.real * &Quaternion::pure(&p)) * &qdq.real.conjugate()).vector();
        let by_formula = [0, 1, 2].map(|i| rpr[i] + t[i]);
        for (name, x) in [("GA F_S", by_ga), ("DQ", by_dq), ("r p r* + t", by_formula)] {
            assert!(close(&x, &expected, 1e-12), "{name}: {x:?} vs {expected:?}");
        }
        // the translation recovered from the dual quaternion is v
        assert!(close(&t, &v, 1e-12));
    }
}

fn to_nalgebra(d: &DualQuaternion<f64>) -> nalgebra::DualQuaternion<f64> {
    let nq = |q: &Quaternion<f64>| nalgebra::Quaternion::new(q.w, q.x, q.y, q.z);
    nalgebra::DualQuaternion::from_real_and_dual(nq(&d.real), nq(&d.dual))
}

fn nalgebra_coeffs(d: &nalgebra::DualQuaternion<f64>) -> [f64; 8] {
    let (r, e) = (&d.real, &d.dual);
    [r.w, r.i, r.j, r.k, e.w, e.i, e.j, e.k]
}

/// Our product (and the generated Motor product through the isomorphism) against nalgebra's
/// `DualQuaternion` product, for random values.
#[test]
fn product_matches_nalgebra() {
    let mut rng = Xorshift(0x2545_f491_4f6c_dd1d);
    for _ in 0..1000 {
        let a = DualQuaternion::from_coeffs([(); 8].map(|_| rng.symmetric()));
        let b = DualQuaternion::from_coeffs([(); 8].map(|_| rng.symmetric()));
        let ours = (&a * &b).coeffs();
        let theirs = nalgebra_coeffs(&(to_nalgebra(&a) * to_nalgebra(&b)));
        assert!(close(&ours, &theirs, 1e-12), "{ours:?} vs {theirs:?}");
        let via_motor = DualQuaternion::from(&(Motor::from(&a) * Motor::from(&b))).coeffs();
        assert!(close(&via_motor, &theirs, 1e-12), "{via_motor:?} vs {theirs:?}");
        let conj = nalgebra_coeffs(&to_nalgebra(&a).conjugate());
        assert!(close(&a.conjugate().coeffs(), &conj, 0.0));
    }
}

/// The paper's pose and nalgebra's `UnitDualQuaternion` built from the same rotation and
/// translation move points identically.
#[test]
fn pose_matches_nalgebra_unit_dual_quaternion() {
    use nalgebra::{Point3, Translation3, UnitDualQuaternion, UnitQuaternion, Vector3};
    let mut rng = Xorshift(0x0123_4567_89ab_cdef);
    for _ in 0..200 {
        let (axis, phi, v, p) = (unit3(&mut rng), 3.0 * rng.symmetric(), rng.vec3(), rng.vec3());
        let s = paper_rotation(axis, phi) * paper_translation(v);
        let rotation = UnitQuaternion::from_axis_angle(&nalgebra::Unit::new_normalize(Vector3::from(axis)), phi);
        let theirs = UnitDualQuaternion::from_parts(Translation3::from(Vector3::from(v)), rotation);
        let ours = DualQuaternion::from_pose(&s);
        assert!(close(&ours.coeffs(), &nalgebra_coeffs(theirs.dual_quaternion()), 1e-12));
        let moved = theirs.transform_point(&Point3::from(p));
        assert!(close(&ga_transform(&s, &p).unwrap(), &[moved.x, moved.y, moved.z], 1e-12));
    }
}

#[test]
fn display() {
    let d = DualQuaternion::from_coeffs([q(1), q(0), ratio(-1, 2), q(0), q(0), q(2), q(0), q(-1)]);
    assert_eq!(d.to_string(), "1 - 1/2*j + 2*ε*i - ε*k");
    assert_eq!(DualQuaternion::<Q>::zero().to_string(), "0");
    assert_eq!(DualQuaternion::<Q>::one().to_string(), "1");
}

//! Section 2.4: powers of B = φP + tn (Lemmas 1-2) and the closed-form exponential
//! (Theorem 3).

use super::common::{cga, in_plane, mv, n, plane, pythagorean, scalar, sinc, theorem_3_form, vector};
use crate::Checker;
use algebra_core::{Algebra, Field, MpFloat, Multivector, Poly, PrecisionGuard, Real, Ring, rational::Q};
use std::sync::Arc;

/// Highest power checked directly.
const K_MAX: usize = 7;

/// A fully symbolic B = φP + tn: P = P_u/N with the Pythagorean plane P_u of symbols u, v, w,
/// φ = N φ0 (so φP = φ0 P_u and φ² = N² φ0² are polynomials), t = (t1, t2, t3).
struct SymbolicB {
    /// Q = φP.
    q: Multivector<Poly>,
    /// φ².
    phi2: Poly,
    /// tn.
    tn: Multivector<Poly>,
}

fn symbolic_b(alg: &Arc<Algebra>) -> SymbolicB {
    let (m, big_n) = pythagorean(&Poly::var("u"), &Poly::var("v"), &Poly::var("w"));
    let phi0 = Poly::var("phi0");
    let q = plane(alg, &m).scale(&phi0);
    let phi = big_n.mul_ref(&phi0);
    let t = vector(alg, [Poly::var("t1"), Poly::var("t2"), Poly::var("t3")]);
    SymbolicB { q, phi2: phi.mul_ref(&phi), tn: &t * &n(alg) }
}

/// The α's of Lemma 1 from the recurrences (multivector-valued: α4_k contains (φP)^(k-1);
/// each multiplies its term from the left), for k = 0..=k_max.
fn alphas<T: Ring>(alg: &Arc<Algebra>, q: &Multivector<T>, phi2: &T, k_max: usize) -> Vec<[Multivector<T>; 4]> {
    let zero = Multivector::zero(alg, algebra_core::Basis::Blade);
    let mut out = vec![[zero.clone(), zero.clone(), zero.clone(), zero]];
    let mut q_prev = scalar(alg, T::one()); // (φP)^(k-1)
    for _ in 1..=k_max {
        let [a1, a2, a3, a4] = out.last().expect("non-empty").clone();
        let next = [a2.scale(&phi2.neg_ref()), a1, a4, &q_prev - &a3.scale(phi2)];
        q_prev = &q_prev * q;
        out.push(next);
    }
    out
}

/// (B^k by repeated products, Lemma 1's right-hand side) for k = 0..=k_max.
pub(crate) fn lemma_1_pairs<T: Ring>(
    alg: &Arc<Algebra>,
    q: &Multivector<T>,
    phi2: &T,
    tn: &Multivector<T>,
    k_max: usize,
) -> Vec<(Multivector<T>, Multivector<T>)> {
    let b = q + tn;
    let (qtn, tnq) = (q * tn, tn * q);
    let qtnq = &qtn * q;
    let mut bk = scalar(alg, T::one());
    let mut qk = bk.clone();
    let mut out = Vec::new();
    for (k, [a1, a2, a3, a4]) in alphas(alg, q, phi2, k_max).into_iter().enumerate() {
        if k > 0 {
            bk = &bk * &b;
            qk = &qk * q;
        }
        let rhs = &(&(&(&qk + &(&a1 * &qtn)) + &(&a2 * &qtnq)) + &(&a3 * &tnq)) + &(&a4 * tn);
        out.push((bk.clone(), rhs));
    }
    out
}

pub(super) fn lemma_1(c: &mut Checker) {
    let alg = cga();
    let s = symbolic_b(&alg);
    c.equal_mv("the parametrised plane: (φP)² = -φ²", &(&s.q * &s.q), &scalar(&alg, s.phi2.neg_ref()));
    for (k, (bk, rhs)) in lemma_1_pairs(&alg, &s.q, &s.phi2, &s.tn, K_MAX).into_iter().enumerate() {
        c.equal_mv(format!("B^{k} = Lemma 1's form (symbolic φ, P, t)"), &bk, &rhs);
    }
    // Without the hypothesis that P is Euclidean (P n = n P): P = e1 e (= e14) also has P² = -1.
    let phi = Poly::var("phi");
    let q = mv(&alg, vec![("e14", phi.clone())]);
    c.equal_mv("e14² = -1", &(&q * &q), &scalar(&alg, phi.mul_ref(&phi).neg_ref()));
    let tn = &vector(&alg, [Poly::var("t1"), Poly::var("t2"), Poly::var("t3")]) * &n(&alg);
    let first_bad = lemma_1_pairs(&alg, &q, &phi.mul_ref(&phi), &tn, K_MAX).into_iter().position(|(l, r)| l != r);
    c.counterexample(
        "Lemma 1 for a 2-blade P with P² = -1 that is not Euclidean",
        first_bad.is_none(),
        format!(
            "P = e1 e (e14): B^{} differs from the formula; the hypothesis P n = n P (P built from \
             vectors of R^3, Section 2.3) is needed so that P commutes with n",
            first_bad.unwrap_or(0)
        ),
    );
    c.note("the α's are not scalars: α4_k contains (φP)^(k-1), so they multiply their terms from the left");
}

/// φ² E(k) = φ² - k (tnQ + Qtn) where B^(2k) = (-1)^k φ^(2k) E(k) (Lemma 2).
fn even_form(s: &SymbolicB, k: &Poly) -> Multivector<Poly> {
    let alg = s.q.algebra().clone();
    &scalar(&alg, s.phi2.clone()) - &(&(&s.tn * &s.q) + &(&s.q * &s.tn)).scale(k)
}

/// φ² O(k) = φ² Q + (k+1) φ² tn - k Q tn Q where B^(2k+1) = (-1)^k φ^(2k) O(k) (Lemma 2).
fn odd_form(s: &SymbolicB, k: &Poly) -> Multivector<Poly> {
    let k1 = k.add_ref(&Poly::one());
    let qtnq = &(&s.q * &s.tn) * &s.q;
    &(&s.q.scale(&s.phi2) + &s.tn.scale(&k1.mul_ref(&s.phi2))) - &qtnq.scale(k)
}

pub(super) fn lemma_2(c: &mut Checker) {
    let alg = cga();
    let s = symbolic_b(&alg);
    let b = &s.q + &s.tn;
    // The proof: α1 = α2 = 0 and α4_k = k/2 (φP)^(k-1) (k even), (k+1)/2 (φP)^(k-1) (k odd).
    let mut qk1 = scalar(&alg, Poly::one()); // (φP)^(k-1)
    for (k, [a1, a2, _, a4]) in alphas(&alg, &s.q, &s.phi2, 2 * K_MAX).into_iter().enumerate().skip(1) {
        let zero = Multivector::zero(&alg, algebra_core::Basis::Blade);
        c.equal_mv(format!("α1_{k} = 0"), &a1, &zero);
        c.equal_mv(format!("α2_{k} = 0"), &a2, &zero);
        let half = if k % 2 == 0 { k } else { k + 1 };
        c.equal_mv(format!("α4_{k} closed form"), &a4, &qk1.scale(&Poly::from_ratio(half as i64, 2)));
        qk1 = &qk1 * &s.q;
    }
    // Direct powers against the stated forms, k = 0..=3.
    let mut bk = scalar(&alg, Poly::one());
    let mut sign_phi2k = Poly::one(); // (-1)^k φ^(2k)
    for k in 0..=3i64 {
        let kk = Poly::from_i64(k);
        // φ^(2k) B^(2k) ... compare (-1)^k φ^(2k) E(k) with φ² E(k) = even_form: multiply B^(2k) by φ².
        c.equal_mv(format!("B^{} (Lemma 2, even)", 2 * k), &bk.scale(&s.phi2), &even_form(&s, &kk).scale(&sign_phi2k));
        bk = &bk * &b;
        c.equal_mv(
            format!("B^{} (Lemma 2, odd)", 2 * k + 1),
            &bk.scale(&s.phi2),
            &odd_form(&s, &kk).scale(&sign_phi2k),
        );
        bk = &bk * &b;
        sign_phi2k = sign_phi2k.mul_ref(&s.phi2).neg_ref();
    }
    // Induction with a symbolic k: E(k) B = O(k) and O(k) B = -φ² E(k+1), from B^0 = 1 = E(0).
    let k = Poly::var("k");
    let k1 = k.add_ref(&Poly::one());
    c.equal_mv("φ²E(0) = φ² (B^0 = 1)", &even_form(&s, &Poly::zero()), &scalar(&alg, s.phi2.clone()));
    c.equal_mv("E(k) B = O(k) for symbolic k", &(&even_form(&s, &k) * &b), &odd_form(&s, &k));
    c.equal_mv(
        "O(k) B = -φ² E(k+1) for symbolic k",
        &(&odd_form(&s, &k) * &b),
        &even_form(&s, &k1).scale(&s.phi2.neg_ref()),
    );
}

/// One float instance: φ as a ratio, the (u, v, w) of the plane, t as three ratios.
pub(super) type Instance = ((i64, i64), (i64, i64, i64), [(i64, i64); 3]);

/// Concrete instances for the float checks.
pub(super) const INSTANCES: &[Instance] = &[
    ((3, 10), (1, 2, 3), [(1, 2), (-2, 3), (5, 4)]),
    ((17, 10), (2, -1, 1), [(3, 1), (1, 5), (-1, 7)]),
    ((29, 10), (0, 0, 1), [(2, 3), (3, 4), (7, 5)]),
    ((-6, 5), (1, 1, 1), [(-1, 3), (2, 1), (1, 9)]),
    ((4, 1), (3, -2, 5), [(1, 1), (1, 1), (1, 1)]),
    ((0, 1), (1, 2, 3), [(5, 2), (-1, 3), (2, 7)]),
];

/// (φ, unit plane P, t) over MpFloat for one instance.
pub(super) fn instance(
    alg: &Arc<Algebra>,
    ((pn, pd), (u, v, w), t): &Instance,
) -> (MpFloat, Multivector<MpFloat>, Multivector<MpFloat>) {
    let (m, big_n) = pythagorean(&Q::from_i64(*u), &Q::from_i64(*v), &Q::from_i64(*w));
    let p = plane(alg, &m).scale(&Q::one().div_ref(&big_n));
    let tv = vector(alg, t.map(|(a, b)| Q::from_ratio(a, b)));
    let f = |x: &Q| MpFloat::from_rational(x);
    (MpFloat::from_ratio(*pn, *pd), p.map_coeffs(f), tv.map_coeffs(f))
}

/// Σ B^k/k! until the terms vanish at the working precision.
fn taylor(b: &Multivector<MpFloat>) -> Multivector<MpFloat> {
    let alg = b.algebra().clone();
    let mut term = scalar(&alg, MpFloat::one());
    let mut sum = term.clone();
    for k in 1..400 {
        term = (&term * b).scale(&MpFloat::from_ratio(1, k));
        sum = &sum + &term;
        if term.magnitude() < 1e-90 {
            break;
        }
    }
    sum
}

pub(super) fn theorem_3(c: &mut Checker) {
    let alg = cga();
    // The two identities of the proof, symbolically: t = t_par + t_perp with t_par = x⌋P_u in
    // the plane and t_perp = h m along its normal; P = P_u/N.
    let (m, big_n) = pythagorean(&Poly::var("u"), &Poly::var("v"), &Poly::var("w"));
    let pu = plane(&alg, &m);
    let t_par = vector(&alg, [Poly::var("x1"), Poly::var("x2"), Poly::var("x3")]).lc(&pu);
    let t_perp = vector(&alg, m.clone()).scale(&Poly::var("h"));
    let zero = Multivector::zero(&alg, algebra_core::Basis::Blade);
    c.equal_mv("t_par lies in the plane of P", &t_par.op(&pu), &zero);
    c.equal_mv("t_perp is normal to the plane of P", &t_perp.lc(&pu), &zero);
    let nn = n(&alg);
    let tn = &(&t_par + &t_perp) * &nn;
    c.equal_mv(
        "tnP + Ptn = 2 P t_perp n",
        &(&(&tn * &pu) + &(&pu * &tn)),
        &(&(&pu * &t_perp) * &nn).scale(&Poly::from_i64(2)),
    );
    c.equal_mv(
        "P tn P = (t_par - t_perp) n",
        &(&(&pu * &tn) * &pu),
        &(&(&t_par - &t_perp) * &nn).scale(&big_n.mul_ref(&big_n)),
    );
    // The closed form as the solution of G' = B G, G(0) = 1 (which characterises exp(λB)):
    // G(λ) = [c + sP][1 + λ t_perp n] + (s/φ) t_par n with c = cos λφ, s = sin λφ, so
    // d/dλ = ∂_λ - φ s ∂_c + φ c ∂_s. With φ = N φ0 (φP = φ0 P_u) the multiple φG is polynomial.
    let (cc, ss, lam, phi0) = (Poly::var("c"), Poly::var("s"), Poly::var("lambda"), Poly::var("phi0"));
    let phi = big_n.mul_ref(&phi0);
    let one = scalar(&alg, Poly::one());
    let phi_g = &(&(&scalar(&alg, phi.mul_ref(&cc)) + &pu.scale(&phi0.mul_ref(&ss)))
        * &(&one + &(&t_perp * &nn).scale(&lam)))
        + &(&t_par * &nn).scale(&ss);
    let d = |p: &Poly| {
        p.derivative("lambda")
            .sub_ref(&phi.mul_ref(&ss).mul_ref(&p.derivative("c")))
            .add_ref(&phi.mul_ref(&cc).mul_ref(&p.derivative("s")))
    };
    let b = &pu.scale(&phi0) + &tn;
    c.equal_mv("d/dλ G(λ) = B G(λ) for Theorem 3's form at (λφ, λt) (symbolic)", &phi_g.map_coeffs(d), &(&b * &phi_g));
    let at0 = phi_g.map_coeffs(|p| {
        p.substitute("lambda", &Poly::zero()).substitute("c", &Poly::one()).substitute("s", &Poly::zero())
    });
    c.equal_mv("G(0) = 1", &at0, &one.scale(&phi));
    // The closed form against the runtime exp (scaling and squaring) and the Taylor series.
    let _g = PrecisionGuard::new(256);
    for inst in INSTANCES {
        let (phi, p, t) = instance(&alg, inst);
        let b = &p.scale(&phi) + &(&t * &n(&alg));
        let form = theorem_3_form(&alg, (&phi.cos(), &phi.sin(), &sinc(&phi)), &p, &t);
        let label = format!("φ = {}/{}", inst.0.0, inst.0.1);
        if let Some(r) = c.ok(format!("runtime exp, {label}"), b.exp()) {
            c.close_mv(format!("Theorem 3 = runtime exp(B), {label}"), &form, &r, 70);
        }
        c.close_mv(format!("Theorem 3 = Σ B^k/k!, {label}"), &form, &taylor(&b), 70);
        let t_par = in_plane(&t, &p);
        c.close_mv(
            format!("t_par in plane, {label}"),
            &t_par.op(&p),
            &Multivector::zero(&alg, algebra_core::Basis::Blade),
            70,
        );
    }
    super::library::theorem_3(c, &alg);
    c.note("the statement says 'of the form given in theorem 1': the form is that of Lemma 1 (numbering typo)");
}

//! Sections 2.4-2.6: the twist form (Lemmas 5-6), exp(B) is a rotor (Theorems 7-8) and the
//! rotor logarithm ℓ(R) (Theorem 9).

use super::common::{cga, e, in_plane, mv, n, plane, pythagorean, scalar, sinc, theorem_3_form, twist, up, vector};
use super::powers::{INSTANCES, instance};
use crate::Checker;
use algebra_core::{Algebra, Basis, Field, MpFloat, Multivector, Poly, PrecisionGuard, Real, Ring, rational::Q};
use std::sync::Arc;

/// One exact instance: q, (u, v, w), t, σ as ratios.
type ExactData = ((i64, i64), (i64, i64, i64), [(i64, i64); 3], (i64, i64));

/// Exact instances: (q with cos = (1-q²)/(1+q²), sin = 2q/(1+q²)), (u, v, w), t, σ (a rational
/// stand-in for sinc(ψ/2): the identities hold for every value of it).
const EXACT: &[ExactData] = &[
    ((1, 3), (1, 2, 3), [(1, 2), (-2, 3), (5, 4)], (5, 7)),
    ((2, 7), (2, -1, 1), [(3, 1), (1, 5), (-1, 7)], (-3, 11)),
    ((-5, 4), (3, -2, 5), [(1, 1), (1, 1), (1, 1)], (1, 1)),
];

/// Rational point (c, s) on the circle.
fn circle(q: Q) -> (Q, Q) {
    let q2 = q.mul_ref(&q);
    let d = Q::one().add_ref(&q2);
    (Q::one().sub_ref(&q2).div_ref(&d), Q::from_i64(2).mul_ref(&q).div_ref(&d))
}

type ExactInstance = ((Q, Q), Multivector<Q>, Multivector<Q>, Q);

fn exact_instance(alg: &Arc<Algebra>, i: usize) -> ExactInstance {
    let ((qn, qd), (u, v, w), t, (sn, sd)) = EXACT[i];
    let (m, big_n) = pythagorean(&Q::from_i64(u), &Q::from_i64(v), &Q::from_i64(w));
    let p = plane(alg, &m).scale(&Q::one().div_ref(&big_n));
    (circle(Q::from_ratio(qn, qd)), p, vector(alg, t.map(|(a, b)| Q::from_ratio(a, b))), Q::from_ratio(sn, sd))
}

/// Lemma 5's right-hand side [1 + σ t_par n/2 rev(τ)] τ and eq. (2)'s τ + σ t_par n/2, with
/// τ = τ(ψ, P, -t_perp), from (cos(ψ/2), sin(ψ/2)) and σ = sinc(ψ/2).
fn lemma_5_sides<T: Ring>(
    alg: &Arc<Algebra>,
    (cs, ss): (&T, &T),
    sigma: &T,
    p: &Multivector<T>,
    t: &Multivector<T>,
) -> (Multivector<T>, Multivector<T>, Multivector<T>) {
    let t_par = in_plane(t, p);
    let t_perp = t - &t_par;
    let tau = twist(alg, (cs, ss), p, &-&t_perp);
    let half_tpar_n = (&t_par * &n(alg)).scale(&sigma.mul_ref(&T::from_ratio(1, 2)));
    let rhs = &(&scalar(alg, T::one()) + &(&half_tpar_n * &tau.reverse())) * &tau;
    let eq2 = &tau + &half_tpar_n;
    (rhs, eq2, tau)
}

/// Symbolic parts: (P_u, c, s0, σ, t_par = x⌋P_u, t_perp = h m, c² + s²) with P = P_u/N,
/// cos = c, sin = s0 N (so sin P = s0 P_u), σ standing for sinc.
struct SymbolicParts {
    pu: Multivector<Poly>,
    c: Poly,
    s0: Poly,
    sigma: Poly,
    t_par: Multivector<Poly>,
    t_perp: Multivector<Poly>,
    norm: Poly,
}

fn symbolic_parts(alg: &Arc<Algebra>) -> SymbolicParts {
    let (m, big_n) = pythagorean(&Poly::var("u"), &Poly::var("v"), &Poly::var("w"));
    let pu = plane(alg, &m);
    let (c, s0) = (Poly::var("c"), Poly::var("s0"));
    let t_par = vector(alg, [Poly::var("x1"), Poly::var("x2"), Poly::var("x3")]).lc(&pu);
    let t_perp = vector(alg, m).scale(&Poly::var("h"));
    let s = s0.mul_ref(&big_n);
    let norm = c.mul_ref(&c).add_ref(&s.mul_ref(&s));
    SymbolicParts { pu, c, s0, sigma: Poly::var("sigma"), t_par, t_perp, norm }
}

/// Symbolic Lemma 5/6 pieces: (τ = τ(ψ, P, -t_perp), X = 1 + σ t_par n/2 rev(τ)).
fn symbolic_twist(alg: &Arc<Algebra>, sp: &SymbolicParts) -> (Multivector<Poly>, Multivector<Poly>) {
    let one = scalar(alg, Poly::one());
    let half = Poly::from_ratio(1, 2);
    let rot = &scalar(alg, sp.c.clone()) + &sp.pu.scale(&sp.s0);
    let tau = &rot * &(&one - &(&n(alg) * &sp.t_perp).scale(&half));
    let x = &one + &(&(&sp.t_par * &n(alg)).scale(&sp.sigma.mul_ref(&half)) * &tau.reverse());
    (tau, x)
}

pub(super) fn lemma_5(c: &mut Checker) {
    let alg = cga();
    // Symbolic: rev(τ) τ = cos² + sin² (= 1), so [1 + σ t_par n/2 rev(τ)] τ = τ + σ t_par n/2.
    let sp = symbolic_parts(&alg);
    let (tau, x) = symbolic_twist(&alg, &sp);
    c.equal_mv("rev(τ) τ = cos² + sin² (symbolic)", &(&tau.reverse() * &tau), &scalar(&alg, sp.norm.clone()));
    let eq2_term = (&sp.t_par * &n(&alg)).scale(&sp.sigma.mul_ref(&Poly::from_ratio(1, 2)));
    c.equal_mv(
        "[1 + σ t_par n/2 rev(τ)] τ = τ + (cos² + sin²) σ t_par n/2 (symbolic)",
        &(&x * &tau),
        &(&tau + &eq2_term.scale(&sp.norm)),
    );
    let one = scalar(&alg, Q::one());
    for i in 0..EXACT.len() {
        let ((cs, ss), p, t, sigma) = exact_instance(&alg, i);
        let (rhs, eq2, tau) = lemma_5_sides(&alg, (&cs, &ss), &sigma, &p, &t);
        c.equal_mv(format!("twist is a rotor: τ rev(τ) = 1 (exact {i})"), &(&tau * &tau.reverse()), &one);
        c.equal_mv(format!("rev(τ) τ = 1 (exact {i})"), &(&tau.reverse() * &tau), &one);
        c.equal_mv(format!("Lemma 5 form = eq. (2) (exact {i})"), &rhs, &eq2);
        // eq. (2) is Theorem 3 with φ = ψ/2 and t/2.
        let half_t = t.scale(&Q::from_ratio(1, 2));
        c.equal_mv(
            format!("eq. (2) = Theorem 3 at (ψ/2, t/2) (exact {i})"),
            &eq2,
            &theorem_3_form(&alg, (&cs, &ss, &sigma), &p, &half_t),
        );
    }
    let _g = PrecisionGuard::new(256);
    let half = MpFloat::from_ratio(1, 2);
    for inst in INSTANCES {
        let (psi, p, t) = instance(&alg, inst);
        let h = psi.mul_ref(&half);
        let b = &p.scale(&h) + &(&t * &n(&alg)).scale(&half);
        let (rhs, _, _) = lemma_5_sides(&alg, (&h.cos(), &h.sin()), &sinc(&h), &p, &t);
        if let Some(r) = c.ok("runtime exp", b.exp()) {
            c.close_mv(format!("Lemma 5 = runtime exp(ψ/2 P + tn/2), ψ = {}/{}", inst.0.0, inst.0.1), &rhs, &r, 70);
        }
    }
}

pub(super) fn lemma_6(c: &mut Checker) {
    let alg = cga();
    // Symbolic: X = 1 + n t'_par/2 with t'_par = -σ t_par (cos - sin P), a vector in the plane.
    let sp = symbolic_parts(&alg);
    let (_, x) = symbolic_twist(&alg, &sp);
    let tp_sym = (&sp.t_par * &(&scalar(&alg, sp.c.clone()) - &sp.pu.scale(&sp.s0))).scale(&sp.sigma.neg_ref());
    c.equal_mv("t'_par is a vector (symbolic)", &tp_sym.grade(1), &tp_sym);
    c.equal_mv("t'_par lies in the plane (symbolic)", &tp_sym.op(&sp.pu), &Multivector::zero(&alg, Basis::Blade));
    c.equal_mv(
        "1 + σ t_par n/2 rev(τ) = 1 + n t'_par/2 (symbolic)",
        &x,
        &(&scalar(&alg, Poly::one()) + &(&n(&alg) * &tp_sym).scale(&Poly::from_ratio(1, 2))),
    );
    let one = scalar(&alg, Q::one());
    let nn = n::<Q>(&alg);
    let half = Q::from_ratio(1, 2);
    let y = vector(&alg, [Q::from_ratio(2, 3), Q::from_ratio(-1, 5), Q::from_i64(3)]);
    for i in 0..EXACT.len() {
        let ((cs, ss), p, t, sigma) = exact_instance(&alg, i);
        let t_par = in_plane(&t, &p);
        let t_perp = &t - &t_par;
        let tau = twist(&alg, (&cs, &ss), &p, &-&t_perp);
        let x = &one + &(&(&t_par * &nn).scale(&sigma.mul_ref(&half)) * &tau.reverse());
        let tp = (&t_par * &(&scalar(&alg, cs.clone()) - &p.scale(&ss))).scale(&sigma.neg_ref());
        c.equal_mv(format!("t'_par is a vector (exact {i})"), &tp.grade(1), &tp);
        c.equal_mv(
            format!("t'_par lies in the plane of P (exact {i})"),
            &tp.op(&p),
            &Multivector::zero(&alg, Basis::Blade),
        );
        let translator = &one + &(&nn * &tp).scale(&half);
        c.equal_mv(format!("1 + σ t_par n/2 rev(τ) = T_(t'_par) = 1 + n t'_par/2 (exact {i})"), &x, &translator);
        c.equal_mv(format!("it is a rotor (exact {i})"), &(&x * &x.reverse()), &one);
        c.equal_mv(
            format!("it translates by t'_par: X F(y) rev(X) = F(y + t'_par) (exact {i})"),
            &(&(&x * &up(&alg, &y)) * &x.reverse()),
            &up(&alg, &(&y + &tp)),
        );
        // Section 2.2: T_a = 1 + na/2 maps F(y) to F(y + a).
        let ta = &one + &(&nn * &t).scale(&half);
        c.equal_mv(
            format!("T_a F(y) rev(T_a) = F(y + a) (exact {i})"),
            &(&(&ta * &up(&alg, &y)) * &ta.reverse()),
            &up(&alg, &(&y + &t)),
        );
        // The prose after Lemma 6: R first translates along t_perp. exp(t_perp n/2) = 1 + t_perp n/2
        // (the series stops: (t_perp n)² = 0) = T_(-t_perp).
        let tn = &t_perp * &nn;
        c.equal_mv(format!("(t_perp n)² = 0 (exact {i})"), &(&tn * &tn), &Multivector::zero(&alg, Basis::Blade));
        let e_tn = &one + &tn.scale(&half);
        c.check(
            format!("exp(t_perp n/2) translates by -t_perp (exact {i})"),
            (&(&e_tn * &up(&alg, &y)) * &e_tn.reverse()) == up(&alg, &(&y - &t_perp)),
        );
    }
    c.note(
        "sign in the prose after Lemma 6 (and Sec. 4.1): exp(ψ/2 P + tn/2) first translates along -t_perp, not \
         t_perp: exp(t n/2) = 1 + tn/2 = 1 - nt/2 = T_(-t) with the paper's own T_a = 1 + na/2 and x -> R x rev(R); \
         consistent with Lemma 5's twist τ(ψ, P, -t_perp)",
    );
    let _g = PrecisionGuard::new(256);
    let h = MpFloat::from_ratio(1, 2);
    let onef = scalar(&alg, MpFloat::one());
    let nf = n::<MpFloat>(&alg);
    for inst in INSTANCES {
        let (psi, p, t) = instance(&alg, inst);
        let (hc, hs, sg) = (psi.mul_ref(&h).cos(), psi.mul_ref(&h).sin(), sinc(&psi.mul_ref(&h)));
        let t_par = in_plane(&t, &p);
        let tau = twist(&alg, (&hc, &hs), &p, &-&(&t - &t_par));
        let x = &onef + &(&(&t_par * &nf).scale(&sg.mul_ref(&h)) * &tau.reverse());
        let tp = (&t_par * &(&scalar(&alg, hc) - &p.scale(&hs))).scale(&sg.neg_ref());
        let label = format!("ψ = {}/{}", inst.0.0, inst.0.1);
        c.close_mv(format!("X = 1 + n t'_par/2, {label}"), &x, &(&onef + &(&nf * &tp).scale(&h)), 70);
        c.close_mv(format!("t'_par is a vector, {label}"), &tp.grade(1), &tp, 70);
    }
    super::library::rotor_and_helix(c, &alg);
}

/// Theorem 3's closed form with symbolic cos = c, sin = s0 N, σ = sinc, P = P_u/N,
/// t_perp = h m, t_par = x⌋P_u: returns (R, c² + s²).
fn symbolic_rotor(alg: &Arc<Algebra>) -> (Multivector<Poly>, Poly) {
    let sp = symbolic_parts(alg);
    let nn = n(alg);
    let rot = &scalar(alg, sp.c.clone()) + &sp.pu.scale(&sp.s0);
    let r = &(&rot * &(&scalar(alg, Poly::one()) + &(&sp.t_perp * &nn))) + &(&sp.t_par * &nn).scale(&sp.sigma);
    (r, sp.norm)
}

pub(super) fn theorem_7(c: &mut Checker) {
    let alg = cga();
    let (r, norm) = symbolic_rotor(&alg);
    c.equal_mv(
        "R rev(R) = cos² + sin² (symbolic; = 1 on the circle)",
        &(&r * &r.reverse()),
        &scalar(&alg, norm.clone()),
    );
    c.equal_mv("rev(R) R = cos² + sin² (symbolic)", &(&r.reverse() * &r), &scalar(&alg, norm));
    c.note("R rev(R) = cos²φ + sin²φ holds for every value standing for sinc φ: the t_par term never contributes");
    let _g = PrecisionGuard::new(256);
    let one = scalar(&alg, MpFloat::one());
    for inst in INSTANCES {
        let (phi, p, t) = instance(&alg, inst);
        let b = &p.scale(&phi) + &(&t * &n(&alg));
        if let Some(r) = c.ok("runtime exp", b.exp()) {
            c.close_mv(
                format!("runtime exp(B) rev(exp(B)) = 1, φ = {}/{}", inst.0.0, inst.0.1),
                &(&r * &r.reverse()),
                &one,
                70,
            );
        }
    }
}

pub(super) fn theorem_8(c: &mut Checker) {
    let alg = cga();
    let (r, norm) = symbolic_rotor(&alg);
    let nn = n::<Poly>(&alg);
    c.equal_mv("R n = n R (symbolic)", &(&r * &nn), &(&nn * &r));
    c.equal_mv("R n rev(R) = (cos² + sin²) n (symbolic)", &(&(&r * &nn) * &r.reverse()), &nn.scale(&norm));
    // Without P n = n P: P = e1 e = e14 (P² = -1), R = cos φ + sin φ P exactly (rational point).
    let (cs, ss) = circle(Q::from_ratio(1, 2));
    let rq = mv(&alg, vec![("1", cs), ("e14", ss)]);
    let nq = n::<Q>(&alg);
    c.equal_mv("R rev(R) = 1 still holds for P = e14", &(&rq * &rq.reverse()), &scalar(&alg, Q::one()));
    c.counterexample(
        "Theorem 8 for a 2-blade P with P² = -1 that is not Euclidean",
        (&(&rq * &nq) * &rq.reverse()) == nq,
        "P = e1 e (e14), R = exp(φP) = 3/5 + 4/5 e14: R n rev(R) != n; needs P built from vectors of R^3 (Sec. 2.3)",
    );
    let _g = PrecisionGuard::new(256);
    let nf = n::<MpFloat>(&alg);
    for inst in INSTANCES {
        let (phi, p, t) = instance(&alg, inst);
        let b = &p.scale(&phi) + &(&t * &nf);
        if let Some(r) = c.ok("runtime exp", b.exp()) {
            c.close_mv(
                format!("runtime exp(B) n rev = n, φ = {}/{}", inst.0.0, inst.0.1),
                &(&(&r * &nf) * &r.reverse()),
                &nf,
                70,
            );
        }
    }
}

/// ℓ(R) by Theorem 9's formulas, typed in from the paper.
fn ell(r: &Multivector<MpFloat>) -> Multivector<MpFloat> {
    let alg = r.algebra().clone();
    let r0 = r.scalar_part();
    let norm = Real::sqrt(&MpFloat::one().sub_ref(&r0.mul_ref(&r0))).atan2(&r0); // acos
    let sc = sinc(&norm);
    let r2 = r.grade(2);
    let ab = (&r2 * &n(&alg)).rc(&e(&alg)).scale(&MpFloat::one().div_ref(&sc));
    let den = MpFloat::one().div_ref(&norm.mul_ref(&norm).mul_ref(&sc)).neg_ref();
    let c_perp_n = (&ab * &r.grade(4)).scale(&den);
    let c_par_n = (&ab * &(&ab * &r2).grade(2)).scale(&den);
    &(&ab + &c_perp_n) + &c_par_n
}

pub(super) fn theorem_9(c: &mut Checker) {
    let alg = cga();
    let _g = PrecisionGuard::new(256);
    let nf = n::<MpFloat>(&alg);
    for inst in INSTANCES.iter().filter(|i| {
        let phi = i.0.0 as f64 / i.0.1 as f64;
        phi.abs() > 0.0 && phi.abs() < std::f64::consts::PI
    }) {
        let (phi, p, t) = instance(&alg, inst);
        let b = &p.scale(&phi) + &(&t * &nf);
        let label = format!("φ = {}/{}", inst.0.0, inst.0.1);
        let Some(r) = c.ok("runtime exp", b.exp()) else { continue };
        let l = ell(&r);
        c.close_mv(format!("ℓ(exp B) = B for 0 < |φ| < π, {label}"), &l, &b, 70);
        if let Some(back) = c.ok("runtime exp", l.exp()) {
            c.close_mv(format!("exp(ℓ(R)) = R, {label}"), &back, &r, 70);
        }
        if let Some(log) = c.ok(format!("runtime log, {label}"), r.log()) {
            c.close_mv(format!("ℓ(R) = runtime log(R), {label}"), &l, &log, 70);
        }
    }
    // |φ| in (π, 2π): ℓ returns another generator (2π - φ, -P, rescaled t_par), still exp(ℓ(R)) = R.
    let (phi, p, t) = instance(&alg, &((4, 1), (3, -2, 5), [(1, 1), (1, 1), (1, 1)]));
    let b = &p.scale(&phi) + &(&t * &nf);
    if let Some(r) = c.ok("runtime exp", b.exp()) {
        let l = ell(&r);
        if let Some(back) = c.ok("runtime exp", l.exp()) {
            c.close_mv("exp(ℓ(R)) = R for φ = 4 (> π)", &back, &r, 70);
        }
        c.check("ℓ(exp B) != B for φ = 4: the principal generator has ||ab|| = 2π - 4", (&l - &b).magnitude() > 1e-3);
        c.note("for ||φ|| in (π, 2π) ℓ(exp B) is the principal generator ((2π - φ)(-P), t_par rescaled), not B; exp(ℓ(R)) = R still holds");
    }
    // Hypothesis 0 < ||ab|| < π: the pure translation R = 1 + tn (||ab|| = 0) and R = -(1 + t n),
    // t ⟂ P (= exp(πP + tn), ||ab|| = π).
    let (_, p, t) = instance(&alg, &INSTANCES[0]);
    let t_perp = &t - &in_plane(&t, &p);
    let one = scalar(&alg, MpFloat::one());
    for (what, r) in [
        ("R = 1 + tn (pure translation, ||ab|| = 0)", &one + &(&t * &nf)),
        ("R = -(1 + t_perp n) = exp(πP + t_perp n) (||ab|| = π)", -(&one + &(&t_perp * &nf))),
    ] {
        let l = ell(&r);
        let works =
            l.coeffs().iter().all(Real::is_finite) && l.exp().map(|x| (&x - &r).magnitude() < 1e-60).unwrap_or(false);
        c.counterexample(
            format!("Theorem 9 without 0 < ||ab|| < π: {what}"),
            works,
            format!(
                "the formulas give {}",
                if l.coeffs().iter().all(Real::is_finite) {
                    "a bivector whose exp is not R"
                } else {
                    "0/0 (not finite)"
                }
            ),
        );
    }
    super::library::theorem_9(c, &alg, ell);
    c.note("hypothesis: 0 < ||ab|| < π (<R>_0 in (-1, 1)); at ||ab|| = 0 (pure translation) ℓ(R) = <R>_2 is the limit; '·e' is with the basis vector e (e² = 1, n·e = 1)");
}

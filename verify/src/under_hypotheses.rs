//! Statements proved symbolically under their polynomial hypotheses (method
//! `symbolic-under-hypotheses`): the claim's components must lie in the ideal the hypotheses
//! generate over Q (`algebra_core::ideal::decide`, a reduced Gröbner basis). Each statement
//! also records that the hypothesis is needed: without it the claim is not in the ideal, and a
//! concrete rational instance fails.
//!
//! The main paper's statements (here) use only the runtime `Multivector<Poly>` of `cga-null`
//! in the paper's product basis, with symbolic elements (`Multivector::symbolic`), no motion
//! types. The other papers' statements are in the submodules, registered after each paper's
//! own statements: [`juttler::STATEMENTS`] (eq. (9) on the Study quadric),
//! [`juttler_interpolation::STATEMENTS`] (Propositions 1-4 with symbolic data),
//! [`wareham_lasenby::STATEMENTS`] (Lemma 1, Theorem 8 under P n = n P, P² = -1) and
//! [`angelidis::STATEMENTS`] (the rotation case of (14) under ω·m = 0).

pub mod angelidis;
pub mod juttler;
pub mod juttler_interpolation;
pub mod wareham_lasenby;

use crate::check::Checker;
use crate::statement::{Method, Paper, Statement};
use algebra_core::ideal::{Budget, Hypotheses, decide};
use algebra_core::multivector::symbolic::Part;
use algebra_core::{Basis, Multivector, Poly, Ring};

type Mv = Multivector<Poly>;

/// The statements of this module (all of the main paper).
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "cross2022/lemma-2.2-null",
        paper: Paper::Cross2022,
        label: "Lemma 2.2 (null vectors)",
        statement: "for a unitary pose S (rev(S) S = 1) of G_123inf and a null vector x of G_0123inf (x x = 0), \
                    F_S(x) = rev(S) x S is null: (rev(S) x S)² = 0",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "rev(S) S = 1 is needed for the ideal-membership proof: from x x = 0 alone the claim is not in \
                     the ideal (the counterexample records its normal form); S and x are fully symbolic",
        check: null_vectors,
    },
    Statement {
        id: "cross2022/lemma-2.2-inner-product",
        paper: Paper::Cross2022,
        label: "Lemma 2.2 (inner product)",
        statement: "for a unitary pose S of G_123inf and vectors x, y of G_0123inf, \
                    <F_S(x) F_S(y)>_0 = <x y>_0 (F_S is an isometry)",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "rev(S) S = 1 is needed: S = 2 scales every inner product by 16",
        check: inner_product,
    },
    Statement {
        id: "cross2022/lemma-3.4-symbolic",
        paper: Paper::Cross2022,
        label: "Lemma 3.4 (symbolic)",
        statement: "if rev(S(t)) S(t) = 1 for all t, then Ψ = 2 rev(S) Ṡ is a bivector: Ψ = ν (γ = 0); \
                    proved for symbolic S and Ṡ from rev(S) S = 1 and its derivative rev(Ṡ) S + rev(S) Ṡ = 0",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "the unitarity is needed (the direction that holds): without rev(S) S = 1 and its derivative \
                     the claim is not in the ideal (S = 1 + t has Ψ = 2 (1 + t), a scalar)",
        check: lemma_3_4,
    },
    Statement {
        id: "cross2022/theorem-3.2-symbolic",
        paper: Paper::Cross2022,
        label: "Theorem 3.2 and Corollary 3.3 (symbolic)",
        statement: "for a pose S of G_123inf with α = <S rev(S)>_0 != 0, a derivative Ṡ and a body point p, the \
                    point q = F_S(p) moves with v = dq/dt = u + Ω × q, where Ψ = 2 S⁻¹ Ṡ = γ + ν, γ a pseudoscalar \
                    (1, ω) and ν = Ω e123 + u einf (eq. 14); and ν = Ω e123 + v einf + (Ω ∧ q) ω (Corollary 3.3); \
                    S, Ṡ and p fully symbolic, not unit",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "α != 0 (S non-singular; its Rabinowitsch inverse makes S⁻¹ and F_S polynomial) is needed: \
                     without it the claim is not in the ideal",
        check: theorem_3_2,
    },
];

fn algebra() -> std::sync::Arc<algebra_core::Algebra> {
    crate::algebra("cga-null")
}

/// The basis elements of a pose of G_123inf inside G_0123inf (product basis).
const POSE: [&str; 8] = ["1", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "e123inf"];

fn pose(prefix: &str) -> Mv {
    let names = POSE.iter().map(|s| s.to_string()).collect();
    Multivector::symbolic(&algebra(), Basis::Product, prefix, &Part::Elements(names)).expect("pose elements")
}

fn vector(prefix: &str) -> Mv {
    Multivector::symbolic(&algebra(), Basis::Product, prefix, &Part::Grade(1)).expect("vectors")
}

fn scalar(x: i64) -> Mv {
    Multivector::scalar(&algebra(), Basis::Product, Poly::from_i64(x))
}

fn equations(m: &Mv) -> Vec<Poly> {
    m.components().into_iter().map(|(_, p)| p).collect()
}

/// Checks that `claim = 0` follows from `hyps` and that it does not follow from `without`.
fn proves(c: &mut Checker, what: &str, claim: &Mv, hyps: &Hypotheses, without: &Hypotheses) {
    let claims = equations(claim);
    holds_under(c, what, &claims, hyps);
    needs(c, what, "the hypothesis", &claims, without);
}

/// Checks that every `claims[i] = 0` follows from `hyps` (ideal membership over Q), that the
/// claims are not all trivially zero and that the hypotheses are consistent.
pub(crate) fn holds_under(c: &mut Checker, what: &str, claims: &[Poly], hyps: &Hypotheses) {
    c.check(format!("{what}: the claim is not trivially zero"), claims.iter().any(|p| !p.is_exact_zero()));
    if let Some(d) = c.ok(what, decide(claims, hyps, &Budget::default())) {
        c.check(format!("{what}: in the ideal of the hypotheses ({} components)", claims.len()), d.holds);
        c.check(format!("{what}: the hypotheses are consistent"), !d.inconsistent);
    }
}

/// Records the counterexample "`claims` without `dropped`": the claims must not follow from
/// `without` (the hypotheses less `dropped`); the note gives the first non-zero normal form.
pub(crate) fn needs(c: &mut Checker, what: &str, dropped: &str, claims: &[Poly], without: &Hypotheses) {
    if let Some(d) = c.ok(what, decide(claims, without, &Budget::default())) {
        let found = d.failures.first().map(|(_, nf)| format!("normal form {}", abbreviated(nf))).unwrap_or_default();
        c.counterexample(format!("{what} without {dropped}"), d.holds, found);
    }
}

/// A polynomial as text, its first 160 characters and its number of terms when longer (a normal
/// form of a large claim runs to thousands of terms).
fn abbreviated(p: &Poly) -> String {
    let text = p.to_string();
    match text.char_indices().nth(160) {
        Some((cut, _)) => format!("{} ... ({} terms)", &text[..cut], p.term_count()),
        None => text,
    }
}

fn unitary(s: &Mv) -> Vec<Poly> {
    equations(&(&(&s.reverse() * s) - &scalar(1)))
}

fn null_vectors(c: &mut Checker) {
    let (s, x) = (pose("S"), vector("x"));
    let fx = &(&s.reverse() * &x) * &s;
    let claim = &fx * &fx;
    let null = equations(&(&x * &x));
    let hyps = Hypotheses { equations: unitary(&s).into_iter().chain(null.clone()).collect(), nonzero: vec![] };
    proves(c, "(rev(S) x S)² = 0", &claim, &hyps, &Hypotheses { equations: null, nonzero: vec![] });
}

fn inner_product(c: &mut Checker) {
    let (s, x, y) = (pose("S"), vector("x"), vector("y"));
    let f = |v: &Mv| &(&s.reverse() * v) * &s;
    let claim = &(&f(&x) * &f(&y)).grade(0) - &(&x * &y).grade(0);
    let hyps = Hypotheses { equations: unitary(&s), nonzero: vec![] };
    proves(c, "<F_S(x) F_S(y)>_0 = <x y>_0", &claim, &hyps, &Hypotheses::default());
    // The instance S = 2 (not unitary): <F(x) F(y)>_0 - <x y>_0 = 15 <x y>_0 != 0.
    let two = scalar(2);
    let g = |v: &Mv| &(&two.reverse() * v) * &two;
    let off = &(&g(&x) * &g(&y)).grade(0) - &(&x * &y).grade(0);
    let expected = (&x * &y).grade(0).scale(&Poly::from_i64(15));
    c.equal_mv("S = 2: <F(x) F(y)>_0 - <x y>_0 = 15 <x y>_0", &off, &expected);
    c.counterexample("isometry for S = 2", off.is_zero(), format!("S = 2 gives {off}"));
}

fn lemma_3_4(c: &mut Checker) {
    let (s, d) = (pose("S"), pose("D"));
    let psi = (&s.reverse() * &d).scale(&Poly::from_i64(2));
    let claim = &psi - &psi.grade(2);
    let derivative = equations(&(&(&d.reverse() * &s) + &(&s.reverse() * &d)));
    let hyps = Hypotheses { equations: unitary(&s).into_iter().chain(derivative).collect(), nonzero: vec![] };
    proves(c, "Ψ - <Ψ>_2 = 0", &claim, &hyps, &Hypotheses::default());
}

/// The conformal point `e0 + p + |p|²/2 einf` of symbols `p1, p2, p3`.
fn conformal_point(prefix: &str) -> (Mv, [Poly; 3]) {
    let p = [1, 2, 3].map(|i| Poly::var(&format!("{prefix}{i}")));
    let half_square = p
        .iter()
        .fold(Poly::zero(), |s, x| s.add_ref(&x.mul_ref(x)))
        .mul_ref(&Poly::from_q(&algebra_core::rational::ratio(1, 2)));
    let terms =
        [("e0", Poly::one()), ("e1", p[0].clone()), ("e2", p[1].clone()), ("e3", p[2].clone()), ("einf", half_square)];
    (
        Multivector::from_terms(&algebra(), Basis::Product, terms.iter().map(|(n, c)| (*n, c.clone())))
            .expect("vector names"),
        p,
    )
}

fn coeff(m: &Mv, name: &str) -> Poly {
    m.coeff_by_name(name).expect("a basis name").clone()
}

fn theorem_3_2(c: &mut Checker) {
    let (s, d) = (pose("S"), pose("D"));
    let (x, _) = conformal_point("p");
    let r = Poly::var("r");
    let norm = &s * &s.reverse();
    let (alpha, beta) = (coeff(&norm, "1"), coeff(&norm, "e123inf"));
    // S⁻¹ = rev(S) (α - β ω) / α² with r = 1/α
    let inv_norm = Multivector::from_terms(
        &algebra(),
        Basis::Product,
        [("1", r.mul_ref(&r).mul_ref(&alpha)), ("e123inf", r.mul_ref(&r).mul_ref(&beta).neg_ref())],
    )
    .expect("names");
    let psi = (&(&inv_norm * &s.reverse()) * &d).scale(&Poly::from_i64(2));
    let omega = [coeff(&psi, "e23"), coeff(&psi, "e13").neg_ref(), coeff(&psi, "e12")];
    let u = [coeff(&psi, "e1inf"), coeff(&psi, "e2inf"), coeff(&psi, "e3inf")];
    // F_S(X) = rev(S) X S, a multiple w of the image's conformal point; q = Y / w
    let y = &(&s.reverse() * &x) * &s;
    let ydot = &(&(&d.reverse() * &x) * &s) + &(&(&s.reverse() * &x) * &d);
    // the weight of the image is α (checked: Y's e0 coefficient), so q = Y r and
    // v = d/dt (Y / α) = (Ẏ α - Y α̇) r² with α̇ = Ẏ's e0 coefficient
    c.check("the weight of rev(S) X S is α", coeff(&y, "e0").sub_ref(&alpha).is_exact_zero());
    let (adot, r2) = (coeff(&ydot, "e0"), r.mul_ref(&r));
    let names = ["e1", "e2", "e3"];
    let q = names.map(|n| coeff(&y, n).mul_ref(&r));
    let v = names.map(|n| coeff(&ydot, n).mul_ref(&alpha).sub_ref(&coeff(&y, n).mul_ref(&adot)).mul_ref(&r2));
    let cross = |a: &[Poly; 3], b: &[Poly; 3]| {
        [(1, 2), (2, 0), (0, 1)].map(|(i, j)| a[i].mul_ref(&b[j]).sub_ref(&a[j].mul_ref(&b[i])))
    };
    let wq = cross(&omega, &q);
    let claims: Vec<Poly> = (0..3).map(|i| v[i].sub_ref(&u[i]).sub_ref(&wq[i])).collect();
    let inverse = r.mul_ref(&alpha).sub_ref(&Poly::one());
    let hyps = Hypotheses { equations: vec![inverse], nonzero: vec![] };
    holds_under(c, "v = u + Ω × q (eq. 14)", &claims, &hyps);
    needs(c, "v = u + Ω × q (eq. 14)", "α != 0", &claims, &Hypotheses::default());
    // Corollary 3.3 at the body point q with velocity v: ν = Ω e123 + v einf + (Ω ∧ q) ω, the
    // paper's ∧ of vectors being the commutator product
    let vec3 = |c: &[Poly; 3]| {
        Multivector::from_terms(&algebra(), Basis::Product, names.iter().zip(c).map(|(n, x)| (*n, x.clone())))
            .expect("vector names")
    };
    let el = |n: &str| Multivector::from_terms(&algebra(), Basis::Product, [(n, Poly::one())]).expect("a name");
    let (om, qv, vv) = (vec3(&omega), vec3(&q), vec3(&v));
    let formula = &(&(&om * &el("e123")) + &(&vv * &el("einf"))) + &(&om.commutator(&qv) * &el("e123inf"));
    holds_under(c, "ν = Ω e123 + v einf + (Ω ∧ q) ω (Corollary 3.3)", &equations(&(&psi.grade(2) - &formula)), &hyps);
    // Ψ = γ + ν: besides ν, only the scalar and ω parts (γ); and for unit S, γ = 0 is Lemma 3.4
    let rest = &psi - &psi.grade(2);
    let gamma_only: Vec<Poly> =
        rest.terms().filter(|(_, n, _)| *n != "1" && *n != "e123inf").map(|(_, _, p)| p.clone()).collect();
    c.check("Ψ - ν has only the parts 1 and ω (γ)", gamma_only.iter().all(Poly::is_exact_zero));
}

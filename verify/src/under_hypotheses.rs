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
        let found = d.failures.first().map(|(_, nf)| format!("normal form {nf}")).unwrap_or_default();
        c.counterexample(format!("{what} without {dropped}"), d.holds, found);
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

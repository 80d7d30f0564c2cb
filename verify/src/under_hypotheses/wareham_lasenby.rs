//! Wareham–Lasenby's Lemma 1 and Theorem 8 proved for a general bivector P of R^{4,1} (ten
//! symbols) under the polynomial hypotheses their proofs use, instead of a parametrised
//! Euclidean plane: P² = -1 (a unit 2-blade), P n = n P, and for Lemma 1 t · n = 0.
//!
//! P n = n P is the hypothesis the proof of Lemma 1 uses ("nPt = -Ptn"): for a bivector P it
//! says P ⌋ n = 0. It holds for every Euclidean plane (Sec. 2.3) but is weaker: P may also be a
//! rotation plane about a translated axis (P = P_E + a ∧ n with a in the plane of P_E). The
//! outer-product condition P ∧ n = 0 would instead make P contain n, and then P² >= 0.

use super::{holds_under, needs};
use crate::wareham_lasenby::powers::lemma_1_pairs;
use crate::{Checker, Method, Paper, Statement};
use algebra_core::ideal::Hypotheses;
use algebra_core::multivector::symbolic::Part;
use algebra_core::{Basis, Multivector, Poly, Ring};
use std::sync::Arc;

/// The statements of this module.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "wareham-lasenby/lemma-1-symbolic",
        paper: Paper::WarehamLasenby,
        label: "Lemma 1 (symbolic)",
        statement: "for a general bivector P of R^{4,1} with P² = -1 and P n = n P, a general vector t with \
                    t · n = 0 and a symbol φ, B = φP + tn has B^k = Lemma 1's form with its recurrences, k = 0..4",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "each hypothesis is needed (without it the claim is not in the ideal): P n = n P (P ⌋ n = 0, \
                     what 'P Euclidean' is used for; weaker than P in R^3), P² = -1, t · n = 0 (t need not lie in \
                     R^3); P ∧ n = 0 is not the condition (it forces P² >= 0)",
        check: lemma_1,
    },
    Statement {
        id: "wareham-lasenby/theorem-8-symbolic",
        paper: Paper::WarehamLasenby,
        label: "Theorem 8 (symbolic)",
        statement: "for R = [c + sP][1 + t_perp n] + σ t_par n (Theorem 3's form of exp(B), c = cos φ, \
                    s = sin φ, σ = sinc φ any symbol) with a general bivector P, P² = -1, P n = n P and \
                    c² + s² = 1: R n rev(R) = n",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "each of P n = n P, P² = -1, c² + s² = 1 is needed (not in the ideal without it); t is a \
                     general vector of R^{4,1} (t · n = 0 is not needed) and σ is free",
        check: theorem_8,
    },
];

type Mv = Multivector<Poly>;

fn cga() -> Arc<algebra_core::Algebra> {
    crate::algebra("cga")
}

fn symbolic(prefix: &str, part: Part) -> Mv {
    Multivector::symbolic(&cga(), Basis::Blade, prefix, &part).expect("parts of cga")
}

fn scalar(x: Poly) -> Mv {
    Multivector::scalar(&cga(), Basis::Blade, x)
}

/// n = e + ē = e4 + e5.
fn n() -> Mv {
    Multivector::from_terms(&cga(), Basis::Blade, vec![("e4", Poly::one()), ("e5", Poly::one())]).expect("e4, e5")
}

fn equations(m: &Mv) -> Vec<Poly> {
    m.components().into_iter().map(|(_, p)| p).collect()
}

/// The hypotheses on P: P² + 1 = 0 and P n - n P = 0, component-wise.
fn unit_blade(p: &Mv) -> Vec<Poly> {
    equations(&(&(p * p) + &scalar(Poly::one())))
}

fn commutes_with_n(p: &Mv) -> Vec<Poly> {
    let n = n();
    equations(&(&(p * &n) - &(&n * p)))
}

fn hypotheses(parts: &[&[Poly]]) -> Hypotheses {
    Hypotheses { equations: parts.concat(), nonzero: vec![] }
}

fn lemma_1(c: &mut Checker) {
    let (p, t, phi) = (symbolic("P", Part::Grade(2)), symbolic("t", Part::Grade(1)), Poly::var("phi"));
    let n = n();
    let tn = &t * &n;
    // The claims B^k - form, k = 0..=4; the counterexamples need only k <= 3 (the first power
    // where each dropped hypothesis shows).
    let mut claims = Vec::new();
    let mut low = 0;
    for (k, (bk, rhs)) in lemma_1_pairs(&cga(), &p.scale(&phi), &phi.mul_ref(&phi), &tn, 4).into_iter().enumerate() {
        claims.extend(equations(&(&bk - &rhs)));
        if k == 3 {
            low = claims.len();
        }
    }
    let (unit, comm) = (unit_blade(&p), commutes_with_n(&p));
    let tdotn = equations(&(&(&t * &n) + &(&n * &t)));
    holds_under(c, "B^k = Lemma 1's form, k <= 4", &claims, &hypotheses(&[&unit, &comm, &tdotn]));
    let (what, claims) = ("B^k = Lemma 1's form, k <= 3", &claims[..low]);
    needs(c, what, "P n = n P", claims, &hypotheses(&[&unit, &tdotn]));
    needs(c, what, "P² = -1", claims, &hypotheses(&[&comm, &tdotn]));
    needs(c, what, "t · n = 0", claims, &hypotheses(&[&unit, &comm]));
}

fn theorem_8(c: &mut Checker) {
    let (p, t) = (symbolic("P", Part::Grade(2)), symbolic("t", Part::Grade(1)));
    let (cc, ss, sigma) = (Poly::var("c"), Poly::var("s"), Poly::var("sigma"));
    let n = n();
    // t_par = (t ⌋ P) P^{-1} = -(t ⌋ P) P, t_perp = t - t_par.
    let t_par = -(&t.lc(&p) * &p);
    let t_perp = &t - &t_par;
    let rot = &scalar(cc.clone()) + &p.scale(&ss);
    let r = &(&rot * &(&scalar(Poly::one()) + &(&t_perp * &n))) + &(&t_par * &n).scale(&sigma);
    let claims = equations(&(&(&(&r * &n) * &r.reverse()) - &n));
    let (unit, comm) = (unit_blade(&p), commutes_with_n(&p));
    let circle = [cc.mul_ref(&cc).add_ref(&ss.mul_ref(&ss)).sub_ref(&Poly::one())];
    let what = "R n rev(R) = n";
    holds_under(c, what, &claims, &hypotheses(&[&unit, &comm, &circle]));
    needs(c, what, "P n = n P", &claims, &hypotheses(&[&unit, &circle]));
    needs(c, what, "P² = -1", &claims, &hypotheses(&[&comm, &circle]));
    needs(c, what, "c² + s² = 1", &claims, &hypotheses(&[&unit, &comm]));
}

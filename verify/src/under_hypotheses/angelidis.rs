//! Angelidis' rotation case of (14) proved under ω · m = 0 and |ω|² = θ² (θ a symbol for |ω|),
//! with the general formula (66) as the contrast that needs no ω · m = 0.
//!
//! exp is not polynomial; as for Wareham–Lasenby's Theorem 3, the closed form is checked as the
//! solution of G' = M G, G(0) = I, which characterises G(λ) = exp(λM): with c = cos λθ,
//! s = sin λθ the derivation d/dλ = ∂_λ - θ s ∂_c + θ c ∂_s acts on polynomials in λ, c, s, and
//! the denominators are cleared (θ² G for (14), θ³ G for (66); θ != 0).

use super::{holds_under, needs};
use crate::angelidis::{M4, dot, flat, hex, ident, madd, mmul, mscale};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::ideal::Hypotheses;
use algebra_core::{Poly, Ring};

/// The statements of this module.
pub const STATEMENTS: &[Statement] = &[Statement {
    id: "angelidis/eq-14-symbolic",
    paper: Paper::Angelidis,
    label: "Eq. (14) (symbolic)",
    statement: "for a rotation hexanion (ω·m = 0) with |ω| = θ != 0: G(λ) = I + (1 - cos λθ)/θ² M² + \
                sin λθ/θ M, M = (ω, m), solves G' = M G, G(0) = I, so G(1) = exp(ω, m) is the rotation case \
                of (14); (66)'s G(λ) = I + λM + (1 - cos λθ)/θ² M² + (λθ - sin λθ)/θ³ M³ solves it for every twist",
    method: Method::SymbolicUnderHypotheses,
    hypotheses: "ω·m = 0 is needed for (14) (without it not in the ideal; the series check angelidis/eq-14 records \
                 a numeric counterexample) and not for (66); |ω|² = θ² is needed for both; θ != 0 to divide",
    check: eq_14,
}];

fn v(name: &str) -> Poly {
    Poly::var(name)
}

/// d/dλ of an entry, with c = cos λθ and s = sin λθ.
fn d_lambda(p: &Poly, theta: &Poly) -> Poly {
    let (c, s) = (v("c"), v("s"));
    p.derivative("lambda")
        .sub_ref(&theta.mul_ref(&s).mul_ref(&p.derivative("c")))
        .add_ref(&theta.mul_ref(&c).mul_ref(&p.derivative("s")))
}

/// The entries of d/dλ (g) - M g, and of g at λ = 0 (c = 1, s = 0) minus `at0`.
fn ode(g: &M4<Poly>, m: &M4<Poly>, theta: &Poly, at0: &M4<Poly>) -> (Vec<Poly>, Vec<Poly>) {
    let dg = g.clone().map(|row| row.map(|p| d_lambda(&p, theta)));
    let lhs = madd(&dg, &mscale(&Poly::from_i64(-1), &mmul(m, g)));
    let start = g.clone().map(|row| {
        row.map(|p| p.substitute("lambda", &Poly::zero()).substitute("c", &Poly::one()).substitute("s", &Poly::zero()))
    });
    (flat(&lhs), flat(&madd(&start, &mscale(&Poly::from_i64(-1), at0))))
}

fn eq_14(c: &mut Checker) {
    let (w, m) = (["w1", "w2", "w3"].map(v), ["m1", "m2", "m3"].map(v));
    let (theta, cc, ss, lambda) = (v("theta"), v("c"), v("s"), v("lambda"));
    let h = hex(&w, &m);
    let (h2, one) = (mmul(&h, &h), ident::<Poly>());
    let theta2 = theta.mul_ref(&theta);
    let length = dot(&w, &w).sub_ref(&theta2);
    let rotation = dot(&w, &m);
    // θ² G = θ² I + (1 - c) M² + θ s M (rotation case of (14)).
    let g14 =
        madd(&madd(&mscale(&theta2, &one), &mscale(&Poly::one().sub_ref(&cc), &h2)), &mscale(&theta.mul_ref(&ss), &h));
    let (claims, start) = ode(&g14, &h, &theta, &mscale(&theta2, &one));
    c.equal("(14): θ² G(0) = θ² I", &start, &vec![Poly::zero(); 16]);
    let both = Hypotheses { equations: vec![length.clone(), rotation.clone()], nonzero: vec![] };
    let what = "(14): d/dλ (θ² G) = M θ² G";
    holds_under(c, what, &claims, &both);
    needs(c, what, "ω·m = 0", &claims, &Hypotheses { equations: vec![length.clone()], nonzero: vec![] });
    needs(c, what, "|ω|² = θ²", &claims, &Hypotheses { equations: vec![rotation], nonzero: vec![] });
    // θ³ G = θ³ (I + λM) + θ (1 - c) M² + (λθ - s) M³ ((66), every twist).
    let theta3 = theta2.mul_ref(&theta);
    let h3 = mmul(&h2, &h);
    let g66 = madd(
        &madd(
            &mscale(&theta3, &madd(&one, &mscale(&lambda, &h))),
            &mscale(&theta.mul_ref(&Poly::one().sub_ref(&cc)), &h2),
        ),
        &mscale(&lambda.mul_ref(&theta).sub_ref(&ss), &h3),
    );
    let (claims, start) = ode(&g66, &h, &theta, &mscale(&theta3, &one));
    c.equal("(66): θ³ G(0) = θ³ I", &start, &vec![Poly::zero(); 16]);
    let what = "(66): d/dλ (θ³ G) = M θ³ G";
    holds_under(c, what, &claims, &Hypotheses { equations: vec![length.clone()], nonzero: vec![] });
    needs(c, what, "|ω|² = θ²", &claims, &Hypotheses::default());
}

//! Section 2: the algebra G_{0123inf}, the sandwich f_S(x) = rev(S) x S, pseudoscalars,
//! unitary poses and equivalence (Lemmas 2.1-2.7, Theorem 2.8, eqs. 5-9, Appendix 1).
//!
//! Polynomial statements are checked for fully symbolic elements (`Poly` coefficients named
//! as in the paper: S, S12, ..., Sw for S; x0, x1, x2, x3, xinf for a vector x); statements
//! about transforms F_S = P f_S E also on exact rational instances, comparing homogeneous
//! coordinates exactly. The paper's `·` and `∧` are our anticommutator and commutator
//! (docs/conventions.md).

use super::formulas::{eq5, eq6, eq7, eq8, eq9_vector_part, symbolic_s};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::rational::{Q, q};
use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use std::sync::Arc;

/// The statements of Section 2 and Appendix 1, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "cross2022/lemma-2.1",
        paper: Paper::Cross2022,
        label: "Lemma 2.1",
        statement: "for a, b in R^3 (as vectors of G_123), a × b corresponds to -(a ∧ b) e123",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_1,
    },
    Statement {
        id: "cross2022/lemma-2.2-i",
        paper: Paper::Cross2022,
        label: "Lemma 2.2 (i)",
        statement: "for even S in G_123inf and a vector x in G_0123inf, rev(S) x S = v + λσ with v a vector, λ real \
                    and σ = e0 · ω = -e123 + e0123inf",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_2_i,
    },
    Statement {
        id: "cross2022/lemma-2.2-ii",
        paper: Paper::Cross2022,
        label: "Lemma 2.2 (ii)",
        statement: "rev(S) S = α + β e123inf, and the coefficient of e0 in rev(S) x S is α times that of x",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_2_ii,
    },
    Statement {
        id: "cross2022/lemma-2.2-iii",
        paper: Paper::Cross2022,
        label: "Lemma 2.2 (iii)",
        statement: "σ commutes with every element of G_0123inf, equivalently σ ∧ x = 0 for all x",
        method: Method::Exact,
        hypotheses: "the paper's ∧ is the commutator product (σx - xσ)/2 (its Sec. 2 definition); for the \
                     outer product of blades σ ^ 1 = σ ≠ 0",
        check: lemma_2_2_iii,
    },
    Statement {
        id: "cross2022/eq-5",
        paper: Paper::Cross2022,
        label: "Eq. (5)",
        statement: "rev(S) S = (S² + S12² + S13² + S23²) + 2(S Sw - S12 S3inf + S13 S2inf - S23 S1inf) ω for the \
                    general even S of eq. (4)",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_5,
    },
    Statement {
        id: "cross2022/eq-6",
        paper: Paper::Cross2022,
        label: "Eq. (6)",
        statement: "rev(S) e1 S as printed (coefficients of e1, e2, e3, einf)",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_6,
    },
    Statement {
        id: "cross2022/eq-7",
        paper: Paper::Cross2022,
        label: "Eq. (7)",
        statement: "rev(S) e2 S as printed (coefficients of e1, e2, e3, einf)",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_7,
    },
    Statement {
        id: "cross2022/eq-8",
        paper: Paper::Cross2022,
        label: "Eq. (8)",
        statement: "rev(S) e3 S as printed (coefficients of e1, e2, e3, einf)",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_8,
    },
    Statement {
        id: "cross2022/eq-9",
        paper: Paper::Cross2022,
        label: "Eq. (9)",
        statement: "the vector part of rev(S) e0 S as printed (coefficients of e0, e1, e2, e3, einf)",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_9,
    },
    Statement {
        id: "cross2022/lemma-2.3",
        paper: Paper::Cross2022,
        label: "Lemma 2.3",
        statement: "for U, V in G_123inf^+, F_UV = F_V F_U",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_3,
    },
    Statement {
        id: "cross2022/lemma-2.4",
        paper: Paper::Cross2022,
        label: "Lemma 2.4",
        statement: "a non-singular pseudoscalar c = a + bω has the inverse (a - bω)/a² and, for a > 0, the square \
                    roots ±(2a + bω)/(2√a)",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_4,
    },
    Statement {
        id: "cross2022/lemma-2.5",
        paper: Paper::Cross2022,
        label: "Lemma 2.5",
        statement: "a pseudoscalar c = a + bω generates the identity transform if a ≠ 0 and the zero transform if \
                    a = 0; rev(c) v c = a² v + 2abWσ + 2b²W einf for v = W e0 + d",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_5,
    },
    Statement {
        id: "cross2022/lemma-2.6",
        paper: Paper::Cross2022,
        label: "Lemma 2.6",
        statement: "rev(S) S is a pseudoscalar, non-singular iff F_S is non-zero; then U = S/|S| is unitary with \
                    F_U = F_S, and V = rev(S)/|S|² satisfies SV = 1",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_6,
    },
    Statement {
        id: "cross2022/lemma-2.7",
        paper: Paper::Cross2022,
        label: "Lemma 2.7",
        statement: "if S in G_123inf^+ generates the identity transform, then (i) S is a pseudoscalar and (ii) if S \
                    is unitary, S = ±1",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_2_7,
    },
    Statement {
        id: "cross2022/theorem-2.8",
        paper: Paper::Cross2022,
        label: "Theorem 2.8",
        statement: "two poses generate the same non-zero transforms of RP^3 and R^3 iff they are equivalent (one is \
                    a non-singular pseudoscalar times the other)",
        method: Method::Symbolic,
        hypotheses: "",
        check: theorem_2_8,
    },
    Statement {
        id: "cross2022/appendix-1-reverse",
        paper: Paper::Cross2022,
        label: "Appendix 1",
        statement: "the reverse of a product is the product of the reverses in the other order in G_123inf, but \
                    not in G_0123inf (for the paper's reverse, which reverses the order of the generators in each \
                    product-basis element)",
        method: Method::Exact,
        hypotheses: "the true reverse (an anti-automorphism for every metric) and the paper's subset-size reverse \
                     agree on G_123inf, where every statement of the paper applies it; they differ on G_0123inf \
                     (rev(e0 einf) = einf e0 = -2 - e0inf, not -e0inf)",
        check: appendix_1_reverse,
    },
];

fn builtin(name: &str) -> Arc<Algebra> {
    crate::algebra(name)
}

fn expected(alg: &Arc<Algebra>, terms: Vec<(&str, Poly)>) -> Multivector<Poly> {
    Multivector::from_terms(alg, Basis::Product, terms.iter().map(|(n, p)| (*n, p.clone())))
        .expect("the paper's basis names exist")
}

fn var(name: &str) -> Poly {
    Poly::var(name)
}

fn int(n: i64) -> Poly {
    Poly::from_i64(n)
}

/// The symbolic vector x = x0 e0 + x1 e1 + x2 e2 + x3 e3 + xinf einf of G_0123inf.
fn symbolic_vector(alg: &Arc<Algebra>) -> Multivector<Poly> {
    expected(
        alg,
        vec![("e0", var("x0")), ("e1", var("x1")), ("e2", var("x2")), ("e3", var("x3")), ("einf", var("xinf"))],
    )
}

/// A second symbolic even element of G_123inf, with coefficients T, T12, ..., Tw.
fn symbolic_t(alg: &Arc<Algebra>) -> Multivector<Poly> {
    let names = ["1", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "e123inf"];
    let vars = ["T", "T12", "T13", "T23", "T1inf", "T2inf", "T3inf", "Tw"];
    expected(alg, names.iter().zip(vars).map(|(n, v)| (*n, var(v))).collect())
}

fn element<T: Ring>(alg: &Arc<Algebra>, name: &str) -> Multivector<T> {
    Multivector::basis_element(alg, Basis::Product, name).expect("basis name")
}

/// σ = -e123 + e0123inf in the product basis.
fn sigma<T: Ring>(alg: &Arc<Algebra>) -> Multivector<T> {
    &element::<T>(alg, "e0123inf") - &element::<T>(alg, "e123")
}

/// The homogeneous coordinates P(y) = (y0, y1, y2, y3) of a multivector of G_0123inf.
fn project<T: Ring>(y: &Multivector<T>) -> [T; 4] {
    ["e0", "e1", "e2", "e3"].map(|n| y.coeff_by_name(n).expect("basis name").clone())
}

/// E(W, X, Y, Z) = W e0 + X e1 + Y e2 + Z e3 (the homogeneous form of the paper's E).
fn embed<T: Ring>(alg: &Arc<Algebra>, p: &[T; 4]) -> Multivector<T> {
    Multivector::from_terms(alg, Basis::Product, ["e0", "e1", "e2", "e3"].into_iter().zip(p.iter().cloned()))
        .expect("basis names")
}

/// A deterministic sequence of small non-zero rationals (an LCG), for exact instances.
struct Rationals(u64);

impl Rationals {
    fn next(&mut self) -> Q {
        self.0 = self.0.wrapping_mul(6364136223846793005).wrapping_add(1442695040888963407);
        let num = ((self.0 >> 33) % 19) as i64 - 9;
        let den = ((self.0 >> 17) % 7) as i64 + 1;
        algebra_core::rational::ratio(if num == 0 { 5 } else { num }, den)
    }

    fn even(&mut self, alg: &Arc<Algebra>) -> Multivector<Q> {
        let names = ["1", "e12", "e13", "e23", "e1inf", "e2inf", "e3inf", "e123inf"];
        Multivector::from_terms(alg, Basis::Product, names.iter().map(|n| (*n, self.next()))).expect("basis names")
    }

    fn point(&mut self) -> [Q; 4] {
        [self.next(), self.next(), self.next(), self.next()]
    }
}

/// Exact projective equality of homogeneous coordinates: a ∝ b with a non-zero factor.
fn proportional(a: &[Q; 4], b: &[Q; 4]) -> bool {
    let zero = Q::from(num_bigint::BigInt::from(0));
    let a_zero = a.iter().all(|x| *x == zero);
    let b_zero = b.iter().all(|x| *x == zero);
    if a_zero || b_zero {
        return a_zero && b_zero;
    }
    (0..4).all(|i| (0..4).all(|j| &a[i] * &b[j] == &a[j] * &b[i]))
}

/// F_S(p) in homogeneous coordinates: P(rev(S) E(p) S).
fn transform(s: &Multivector<Q>, p: &[Q; 4]) -> [Q; 4] {
    project(&s.sandwich(&embed(s.algebra(), p)))
}

fn lemma_2_1(c: &mut Checker) {
    let alg = builtin("cga-null");
    let a = expected(&alg, vec![("e1", var("a1")), ("e2", var("a2")), ("e3", var("a3"))]);
    let b = expected(&alg, vec![("e1", var("b1")), ("e2", var("b2")), ("e3", var("b3"))]);
    let (a1, a2, a3, b1, b2, b3) = (var("a1"), var("a2"), var("a3"), var("b1"), var("b2"), var("b3"));
    let cross = expected(
        &alg,
        vec![
            ("e1", a2.mul_ref(&b3) - a3.mul_ref(&b2)),
            ("e2", a3.mul_ref(&b1) - a1.mul_ref(&b3)),
            ("e3", a1.mul_ref(&b2) - a2.mul_ref(&b1)),
        ],
    );
    let e123 = element::<Poly>(&alg, "e123");
    let via_commutator = (&a.commutator(&b) * &e123).scale(&int(-1));
    let via_outer = (&(&a ^ &b) * &e123).scale(&int(-1));
    c.equal_mv("a × b = -(a ∧ b) e123 with the paper's ∧ = commutator", &via_commutator, &cross);
    c.equal_mv("a × b = -(a ^ b) e123 with the outer product (same for vectors)", &via_outer, &cross);
}

fn lemma_2_2_i(c: &mut Checker) {
    let alg = builtin("cga-null");
    let s = symbolic_s(&alg, Basis::Product);
    let y = s.sandwich(&symbolic_vector(&alg));
    let v = y.basis_grade(1);
    let rest = &y - &v;
    let lambda = rest.coeff_by_name("e0123inf").expect("basis name").clone();
    c.check("λ is a non-zero polynomial (the σ part is really there)", !lambda.is_exact_zero());
    c.equal_mv("rev(S) x S - vec(rev(S) x S) = λσ", &rest, &sigma::<Poly>(&alg).scale(&lambda));
    let e0 = element::<Poly>(&alg, "e0");
    let omega = element::<Poly>(&alg, "e123inf");
    let half = Poly::from_q(&algebra_core::rational::ratio(1, 2));
    c.equal_mv("σ = e0 · ω = (e0 ω + ω e0)/2", &e0.anticommutator(&omega), &sigma(&alg));
    c.equal_mv(
        "(e0 ω + ω e0)/2 computed from products",
        &(&(&e0 * &omega) + &(&omega * &e0)).scale(&half),
        &sigma(&alg),
    );
    // The vector part of the sandwich of e_i, x in G_123inf, has no σ part (Appendix 1: λ = 0).
    let x123 = expected(&alg, vec![("e1", var("x1")), ("e2", var("x2")), ("e3", var("x3")), ("einf", var("xinf"))]);
    let y123 = s.sandwich(&x123);
    c.equal_mv("for x in G_123inf, rev(S) x S is a vector (λ = 0)", &y123, &y123.basis_grade(1));
}

fn lemma_2_2_ii(c: &mut Checker) {
    let alg = builtin("cga-null");
    let s = symbolic_s(&alg, Basis::Product);
    let ss = &s.reverse() * &s;
    let alpha = ss.scalar_part();
    let beta = ss.coeff_by_name("e123inf").expect("basis name").clone();
    let form =
        &Multivector::scalar(&alg, Basis::Product, alpha.clone()) + &element::<Poly>(&alg, "e123inf").scale(&beta);
    c.equal_mv("rev(S) S = α + β e123inf", &ss, &form);
    let y = s.sandwich(&symbolic_vector(&alg));
    c.equal(
        "coefficient of e0 in rev(S) x S = α x0",
        y.coeff_by_name("e0").expect("basis name"),
        &alpha.mul_ref(&var("x0")),
    );
}

fn lemma_2_2_iii(c: &mut Checker) {
    let alg = builtin("cga-null");
    let sigma_def = element::<Q>(&alg, "e0").anticommutator(&element(&alg, "e123inf"));
    c.equal_mv("σ = e0 · ω = -e123 + e0123inf", &sigma_def, &sigma(&alg));
    for m in 0..alg.dim() as u32 {
        let x = Multivector::from_mask(&alg, Basis::Product, m).expect("m < dim");
        let name = alg.name_of(m).expect("m < dim");
        c.equal_mv(format!("σ {name} = {name} σ"), &(&sigma_def * &x), &(&x * &sigma_def));
        c.check(format!("σ ∧ {name} = 0 (commutator)"), sigma_def.commutator(&x).is_zero());
    }
    c.counterexample(
        "σ ^ x = 0 for the outer product of blades",
        (&sigma_def ^ &Multivector::scalar(&alg, Basis::Product, Q::one())).is_zero(),
        "σ ^ 1 = σ",
    );
}

fn sandwich_eq(c: &mut Checker, x_name: &str, eq: Vec<(&str, Poly)>, label: &str) {
    for basis in Basis::ALL {
        let alg = builtin("cga-null");
        let s = symbolic_s(&alg, basis);
        let x = Multivector::<Poly>::basis_element(&alg, basis, x_name).expect("basis name");
        c.equal_mv(format!("{label} ({basis} basis)"), &s.sandwich(&x), &expected(&alg, eq.clone()));
    }
}

fn eq_5(c: &mut Checker) {
    for alg in [builtin("cga-null"), builtin("g123inf")] {
        for basis in Basis::ALL {
            let s = symbolic_s(&alg, basis);
            c.equal_mv(
                format!("rev(S) S in {} ({basis} basis)", alg.name()),
                &(&s.reverse() * &s),
                &expected(&alg, eq5()),
            );
        }
    }
}

fn eq_6(c: &mut Checker) {
    sandwich_eq(c, "e1", eq6(), "rev(S) e1 S");
}

fn eq_7(c: &mut Checker) {
    sandwich_eq(c, "e2", eq7(), "rev(S) e2 S");
}

fn eq_8(c: &mut Checker) {
    sandwich_eq(c, "e3", eq8(), "rev(S) e3 S");
}

fn eq_9(c: &mut Checker) {
    for basis in Basis::ALL {
        let alg = builtin("cga-null");
        let s = symbolic_s(&alg, basis);
        let y = s.sandwich(&Multivector::basis_element(&alg, basis, "e0").expect("e0"));
        c.equal_mv(
            format!("vec(rev(S) e0 S) ({basis} basis)"),
            &y.in_basis(Basis::Product).basis_grade(1),
            &expected(&alg, eq9_vector_part()),
        );
    }
}

fn lemma_2_3(c: &mut Checker) {
    let alg = builtin("cga-null");
    let (u, v) = (symbolic_s(&alg, Basis::Product), symbolic_t(&alg));
    let x = symbolic_vector(&alg);
    let uv = &u * &v;
    c.equal_mv("rev(UV) = rev(V) rev(U) in G_123inf", &uv.reverse(), &(&v.reverse() * &u.reverse()));
    c.equal_mv("f_UV(x) = f_V(f_U(x)) for symbolic U, V, x", &uv.sandwich(&x), &v.sandwich(&u.sandwich(&x)));
    // F_V F_U goes through P and E between the sandwiches (dropping the einf and σ parts);
    // compare the composed projective maps exactly on rational instances.
    let mut r = Rationals(23);
    for _ in 0..20 {
        let (u, v, p) = (r.even(&alg), r.even(&alg), r.point());
        let composed = transform(&v, &transform(&u, &p));
        c.check(format!("F_UV(p) ∝ F_V(F_U(p)) for p = {p:?}"), proportional(&transform(&(&u * &v), &p), &composed));
    }
}

fn lemma_2_4(c: &mut Checker) {
    let alg = builtin("g123inf");
    let (a, b, r) = (var("a"), var("b"), var("r"));
    let omega = element::<Poly>(&alg, "e123inf");
    let one = Multivector::scalar(&alg, Basis::Product, Poly::one());
    let cc = &one.scale(&a) + &omega.scale(&b);
    // (a + bω)(a - bω)/a² = 1, with the denominator cleared exactly.
    let inv_times_a2 = &one.scale(&a) - &omega.scale(&b);
    c.equal_mv("(a + bω)(a - bω) = a²", &(&cc * &inv_times_a2), &one.scale(&a.mul_ref(&a)));
    c.equal_mv("(a - bω)(a + bω) = a²", &(&inv_times_a2 * &cc), &one.scale(&a.mul_ref(&a)));
    // Square roots: write a = r² with r = √a > 0; then ((2a + bω)/(2r))² = a + bω means
    // (2r² + bω)² = 4r² (r² + bω), a polynomial identity in r and b.
    let a_sq = r.mul_ref(&r);
    let c_r = &one.scale(&a_sq) + &omega.scale(&b);
    let root_times_2r = &one.scale(&(a_sq.clone() + a_sq.clone())) + &omega.scale(&b);
    let four_r2 = int(4).mul_ref(&a_sq);
    c.equal_mv("(2a + bω)² = 4a (a + bω), a = r²", &(&root_times_2r * &root_times_2r), &c_r.scale(&four_r2));
    let neg = root_times_2r.scale(&int(-1));
    c.equal_mv("(-(2a + bω))² = 4a (a + bω)", &(&neg * &neg), &c_r.scale(&four_r2));
    // The library's exact inverse agrees (a = 3, b = 5).
    let c35 = Multivector::<Q>::from_terms(&alg, Basis::Product, [("1", q(3)), ("e123inf", q(5))]).expect("names");
    let printed = Multivector::<Q>::from_terms(
        &alg,
        Basis::Product,
        [("1", algebra_core::rational::ratio(1, 3)), ("e123inf", algebra_core::rational::ratio(-5, 9))],
    )
    .expect("names");
    if let Some(inv) = c.ok("inverse of 3 + 5ω", c35.inverse()) {
        c.equal_mv("library inverse of 3 + 5ω = (3 - 5ω)/9", &inv, &printed);
    }
}

fn lemma_2_5(c: &mut Checker) {
    let alg = builtin("cga-null");
    let (a, b) = (var("a"), var("b"));
    let cc = expected(&alg, vec![("1", a.clone()), ("e123inf", b.clone())]);
    let v = expected(&alg, vec![("e0", var("W")), ("e1", var("X")), ("e2", var("Y")), ("e3", var("Z"))]);
    c.equal_mv("rev(c) = c", &cc.reverse(), &cc);
    let w = var("W");
    let rhs = &(&v.scale(&a.mul_ref(&a)) + &sigma::<Poly>(&alg).scale(&int(2).mul_ref(&a).mul_ref(&b).mul_ref(&w)))
        + &element::<Poly>(&alg, "einf").scale(&int(2).mul_ref(&b).mul_ref(&b).mul_ref(&w));
    let y = cc.sandwich(&v);
    c.equal_mv("rev(c) v c = a² v + 2abW σ + 2b²W einf", &y, &rhs);
    let p = project(&y);
    let expected_p = [var("W"), var("X"), var("Y"), var("Z")].map(|t| a.mul_ref(&a).mul_ref(&t));
    c.equal("P(rev(c) v c) = a² (W, X, Y, Z): identity for a ≠ 0", &p, &expected_p);
    let p0 = p.clone().map(|t| t.substitute("a", &Poly::zero()));
    c.check("a = 0: P(rev(c) v c) = 0, the zero transform", p0.iter().all(Poly::is_exact_zero));
}

fn lemma_2_6(c: &mut Checker) {
    let alg = builtin("cga-null");
    let s = symbolic_s(&alg, Basis::Product);
    let ss = &s.reverse() * &s;
    let (alpha, beta) = (ss.scalar_part(), ss.coeff_by_name("e123inf").expect("name").clone());
    let omega = element::<Poly>(&alg, "e123inf");
    let one = Multivector::scalar(&alg, Basis::Product, Poly::one());
    c.equal_mv("rev(S) S is a pseudoscalar α + βω", &ss, &(&one.scale(&alpha) + &omega.scale(&beta)));
    // Singular (S = S12 = S13 = S23 = 0): P(f_S(x)) = 0 for every vector x: the zero transform.
    let singular =
        ["S", "S12", "S13", "S23"].iter().fold(s.clone(), |m, n| m.map_coeffs(|p| p.substitute(n, &Poly::zero())));
    let p = project(&singular.sandwich(&symbolic_vector(&alg)));
    c.check("singular S: P(rev(S) x S) = 0", p.iter().all(Poly::is_exact_zero));
    // Non-singular: the e0 coefficient of f_S(e0) is α ≠ 0, so F_S is non-zero (eq. 9).
    let e0 = element::<Poly>(&alg, "e0");
    c.equal("coefficient of e0 in rev(S) e0 S = α", s.sandwich(&e0).coeff_by_name("e0").expect("name"), &alpha);
    // (ii) V = rev(S)/|S|² with |S|^-2 = (α - βω)/α² (Lemma 2.4): S rev(S) (α - βω) = α².
    let inv_norm_a2 = &one.scale(&alpha) - &omega.scale(&beta);
    let a2 = one.scale(&alpha.mul_ref(&alpha));
    c.equal_mv("S V = 1: S rev(S) (α - βω) = α²", &(&(&s * &s.reverse()) * &inv_norm_a2), &a2);
    c.equal_mv("V S = 1: rev(S) S (α - βω) = α²", &(&ss * &inv_norm_a2), &a2);
    // (i) U = S/|S|: rev(U) U = rev(S) S / |S|² = 1 (the same identity), and F_U = F_S because
    // |S| is a non-singular pseudoscalar (Lemmas 2.3, 2.5). Exactly on instances where |S| is
    // rational: (S, S12, S13, S23) = k (1, 2, 2, 4) has α = 25 k².
    let mut r = Rationals(7);
    for k in 1..=4 {
        let mut s_q = r.even(&alg);
        for (name, m) in [("1", 1), ("e12", 2), ("e13", 2), ("e23", 4)] {
            let mask = alg.mask_of(name).expect("name");
            *s_q.coeff_mut(mask).expect("mask of a name") = q(k * m);
        }
        let ss_q = &s_q.reverse() * &s_q;
        let (a, b) = (ss_q.scalar_part(), ss_q.coeff_by_name("e123inf").expect("name").clone());
        let root_a = q(5 * k);
        // |S| = (2a + bω)/(2√a), and 1/|S| = (2a - bω)/(2a√a)... compute U = S |S|^-1 exactly.
        let norm = Multivector::<Q>::from_terms(
            &alg,
            Basis::Product,
            [("1", root_a.clone()), ("e123inf", &b / (q(2) * &root_a))],
        )
        .expect("names");
        c.equal_mv(format!("|S|² = rev(S) S (k = {k})"), &(&norm * &norm), &ss_q);
        let Some(norm_inv) = c.ok("|S|^-1", norm.inverse()) else { continue };
        let u = &s_q * &norm_inv;
        c.equal_mv(
            format!("rev(U) U = 1 (k = {k})"),
            &(&u.reverse() * &u),
            &Multivector::scalar(&alg, Basis::Product, Q::one()),
        );
        let p = r.point();
        c.check(format!("F_U(p) ∝ F_S(p) (k = {k})"), proportional(&transform(&u, &p), &transform(&s_q, &p)));
        c.check(format!("a = α > 0 (k = {k})"), a > Q::zero());
    }
}

fn lemma_2_7(c: &mut Checker) {
    let alg = builtin("cga-null");
    let s = symbolic_s(&alg, Basis::Product);
    let alpha = (&s.reverse() * &s).scalar_part();
    let sq = |n: &str| var(n).mul_ref(&var(n));
    // The proof: F_S = identity makes the e_i coefficient of f_S(e0 + e_i) equal to the e0
    // coefficient α; the differences are sums of squares, so S12 = S13 = S23 = 0.
    for (i, eq, squares) in [(1, eq6(), ["S12", "S13"]), (2, eq7(), ["S12", "S23"]), (3, eq8(), ["S13", "S23"])] {
        let ei = format!("e{i}");
        let coeff = eq.iter().find(|(n, _)| *n == ei).map(|(_, p)| p.clone()).unwrap_or_default();
        let e_ei = element::<Poly>(&alg, &ei);
        c.equal(
            format!("e{i} coefficient of f_S(e{i}) is the printed one"),
            s.sandwich(&e_ei).coeff_by_name(&ei).expect("name"),
            &coeff,
        );
        c.equal(
            format!("α - [e{i}]f_S(e{i}) = 2({}² + {}²)", squares[0], squares[1]),
            &(alpha.clone() - coeff),
            &(int(2).mul_ref(&(sq(squares[0]) + sq(squares[1])))),
        );
    }
    // With S12 = S13 = S23 = 0: f_S(e0) = S²e0 + 2S(S1inf e1 + S2inf e2 + S3inf e3) + ...; F_S(e0) = e0
    // forces S_iinf = 0 (S ≠ 0 since α = S² ≠ 0). What is left is S + Sw ω: a pseudoscalar (i).
    let reduced = ["S12", "S13", "S23"].iter().fold(s.clone(), |m, n| m.map_coeffs(|p| p.substitute(n, &Poly::zero())));
    let y = reduced.sandwich(&element::<Poly>(&alg, "e0"));
    for (i, n) in [(1, "S1inf"), (2, "S2inf"), (3, "S3inf")] {
        c.equal(
            format!("[e{i}] f_S(e0) = 2 S {n} once S12 = S13 = S23 = 0"),
            y.coeff_by_name(&format!("e{i}")).expect("name"),
            &int(2).mul_ref(&var("S")).mul_ref(&var(n)),
        );
    }
    // (ii) unitary: then the ω part 2 S Sw of rev(S)S (eq. 5) vanishes, so Sw = 0 and S² = 1.
    let ps = expected(&alg, vec![("1", var("S")), ("e123inf", var("Sw"))]);
    let ps2 = &ps.reverse() * &ps;
    c.equal(
        "rev(S + Sw ω)(S + Sw ω) = S² + 2 S Sw ω",
        &ps2,
        &expected(&alg, vec![("1", sq("S")), ("e123inf", int(2).mul_ref(&var("S")).mul_ref(&var("Sw")))]),
    );
    // Conversely every pseudoscalar generates the identity (Lemma 2.5), and ±1 are unitary.
    let mut r = Rationals(99);
    for _ in 0..10 {
        let ps_q = Multivector::<Q>::from_terms(&alg, Basis::Product, [("1", r.next()), ("e123inf", r.next())])
            .expect("names");
        let p = r.point();
        c.check("a non-singular pseudoscalar fixes p projectively", proportional(&transform(&ps_q, &p), &p));
    }
    // And a non-pseudoscalar does not generate the identity (sanity of the comparison).
    let s_q = r.even(&alg);
    let moved = (0..4).map(|_| r.point()).any(|p| !proportional(&transform(&s_q, &p), &p));
    c.check("a generic S moves some point", moved);
}

fn theorem_2_8(c: &mut Checker) {
    let alg = builtin("cga-null");
    let u = symbolic_s(&alg, Basis::Product);
    let gamma = expected(&alg, vec![("1", var("a")), ("e123inf", var("b"))]);
    let x = expected(&alg, vec![("e0", var("W")), ("e1", var("X")), ("e2", var("Y")), ("e3", var("Z"))]);
    // Equivalent ⇒ same transform: P(f_{γU}(x)) = a² P(f_U(x)) for symbolic γ, U, x.
    let lhs = project(&(&gamma * &u).sandwich(&x));
    let rhs = project(&u.sandwich(&x)).map(|t| var("a").mul_ref(&var("a")).mul_ref(&t));
    c.equal("P(f_γU(x)) = a² P(f_U(x))", &lhs, &rhs);
    // Same transform ⇒ equivalent: V U^-1 generates the identity, so it is a pseudoscalar
    // (Lemma 2.7). On instances: V = γU gives V U^-1 = γ exactly, and a V that is not
    // equivalent to U moves some point differently.
    let mut r = Rationals(5);
    for _ in 0..10 {
        let u = r.even(&alg);
        let g = Multivector::<Q>::from_terms(&alg, Basis::Product, [("1", r.next()), ("e123inf", r.next())])
            .expect("names");
        let v = &g * &u;
        let Some(u_inv) = c.ok("U^-1", u.inverse()) else { continue };
        c.equal_mv("V U^-1 = γ for V = γU", &(&v * &u_inv), &g);
        let p = r.point();
        c.check("F_V(p) ∝ F_U(p)", proportional(&transform(&v, &p), &transform(&u, &p)));
        let w = r.even(&alg);
        let differs = (0..4).map(|_| r.point()).any(|p| !proportional(&transform(&w, &p), &transform(&u, &p)));
        c.check("an unrelated W generates a different transform", differs);
    }
}

fn appendix_1_reverse(c: &mut Checker) {
    // In G_123inf both reverses agree and are anti-automorphisms on every pair of basis elements.
    let g = builtin("g123inf");
    let mut all = true;
    for i in 0..g.dim() as u32 {
        let x = Multivector::<Q>::from_mask(&g, Basis::Product, i).expect("i < dim");
        all &= x.basis_reverse() == x.reverse();
        for j in 0..g.dim() as u32 {
            let y = Multivector::<Q>::from_mask(&g, Basis::Product, j).expect("j < dim");
            all &= (&x * &y).basis_reverse() == &y.basis_reverse() * &x.basis_reverse();
        }
    }
    c.check("G_123inf: rev_paper(xy) = rev_paper(y) rev_paper(x) and rev_paper = reverse on all basis pairs", all);
    // In G_0123inf the true reverse is an anti-automorphism; the paper's is not.
    let alg = builtin("cga-null");
    let (e0, einf) = (element::<Q>(&alg, "e0"), element::<Q>(&alg, "einf"));
    let prod = &e0 * &einf;
    c.equal_mv("reverse(e0 einf) = einf e0", &prod.reverse(), &(&einf * &e0));
    c.counterexample(
        "rev_paper(e0 einf) = rev_paper(einf) rev_paper(e0) in G_0123inf",
        prod.basis_reverse() == &einf.basis_reverse() * &e0.basis_reverse(),
        format!("rev_paper(e0inf) = {}, einf e0 = {}", prod.basis_reverse(), &einf * &e0),
    );
}

//! Section 2: the algebra G_{0123inf}, the sandwich f_S(x) = rev(S) x S, pseudoscalars,
//! unitary poses and equivalence (Lemmas 2.1-2.7, Theorem 2.8, eqs. 5-9).

use super::formulas::{eq5, eq6, eq7, eq8, eq9_vector_part, symbolic_s};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::{Algebra, Basis, Multivector, Poly, Ring};
use std::sync::Arc;

/// The statements of Section 2, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "cross2022/eq-5",
        paper: Paper::Cross2022,
        label: "Eq. (5)",
        statement: "rev(S) S = (S² + S12² + S13² + S23²) + 2(S Sw - S12 S3inf + S13 S2inf - S23 S1inf) ω for \
                    the general even S of eq. (4)",
        method: Method::Symbolic,
        hypotheses: "",
        check: eq_5,
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
];

fn cga_null() -> Arc<Algebra> {
    Algebra::builtin("cga-null").expect("built-in algebra")
}

fn expected(alg: &Arc<Algebra>, terms: Vec<(&str, Poly)>) -> Multivector<Poly> {
    Multivector::from_terms(alg, Basis::Product, terms.iter().map(|(n, p)| (*n, p.clone())))
        .expect("the paper's basis names exist")
}

fn eq_5(c: &mut Checker) {
    for alg in [cga_null(), Algebra::builtin("g123inf").expect("built-in algebra")] {
        for basis in Basis::ALL {
            let s = symbolic_s(&alg, basis);
            c.equal_mv(format!("rev(S) S in {} ({basis} basis)", alg.name()), &(&s.reverse() * &s), &expected(&alg, eq5()));
        }
    }
}

fn lemma_2_4(c: &mut Checker) {
    // Symbolic a, b and the symbol r standing for √a (r² = a is substituted).
    let alg = Algebra::builtin("g123inf").expect("built-in algebra");
    let (a, b, r) = (Poly::var("a"), Poly::var("b"), Poly::var("r"));
    let omega = Multivector::<Poly>::basis_element(&alg, Basis::Product, "e123inf").expect("ω");
    let one = Multivector::scalar(&alg, Basis::Product, Poly::one());
    let cc = &one.scale(&a) + &omega.scale(&b);
    // (a + bω)(a - bω)/a² = 1: check a² · product = a² (clearing the denominator exactly).
    let inv_times_a2 = &one.scale(&a) - &omega.scale(&b);
    c.equal_mv("(a + bω)(a - bω) = a²", &(&cc * &inv_times_a2), &one.scale(&a.mul_ref(&a)));
    c.equal_mv("(a - bω)(a + bω) = a²", &(&inv_times_a2 * &cc), &one.scale(&a.mul_ref(&a)));
    // Square roots: write a = r² with r = √a > 0; then ((2a + bω)/(2r))² = a + bω means
    // (2r² + bω)² = 4r² (r² + bω), a polynomial identity in r and b.
    let a_sq = r.mul_ref(&r);
    let c_r = &one.scale(&a_sq) + &omega.scale(&b);
    let root_times_2r = &one.scale(&(a_sq.clone() + a_sq.clone())) + &omega.scale(&b);
    let four_r2 = Poly::from_i64(4).mul_ref(&a_sq);
    c.equal_mv("(2a + bω)² = 4a (a + bω), a = r²", &(&root_times_2r * &root_times_2r), &c_r.scale(&four_r2));
    let neg = root_times_2r.scale(&Poly::from_i64(-1));
    c.equal_mv("(-(2a + bω))² = 4a (a + bω)", &(&neg * &neg), &c_r.scale(&four_r2));
}

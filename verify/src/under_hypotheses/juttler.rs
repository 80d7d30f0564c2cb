//! Jüttler's eq. (9) proved on the Study quadric: for a general dual quaternion Q (eight
//! symbols) with Plücker's relation (8) and Q0 Q~0 != 0 (a symbol r with r Q0 Q~0 = 1, the
//! Rabinowitsch form of the condition, so that Rot(Q) = r Q0 is a polynomial).

use super::{holds_under, needs};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::ideal::Hypotheses;
use algebra_core::{Poly, Ring};
use gam_algebras::DualQuaternion;
use gam_algebras::dual_quaternion::Quaternion;

/// The statements of this module.
pub const STATEMENTS: &[Statement] = &[Statement {
    id: "juttler/eq-9-symbolic",
    paper: Paper::Juttler,
    label: "Eq. (9) (symbolic)",
    statement: "a general dual quaternion Q on the Study quadric (8) with Q0 Q~0 != 0 is a displacement: \
                Trans(Q) / (Q0 Q~0) = Q Q~0 / (Q0 Q~0) is a unit translation 1 + ε t (real part 1, dual part a \
                pure vector), Trans(Q) Rot(Q) = Q with Rot(Q) = Q0 / (Q0 Q~0), and Rot Rot~ = 1/(Q0 Q~0)",
    method: Method::SymbolicUnderHypotheses,
    hypotheses: "both hypotheses are needed: without (8) the dual scalar part of Q Q~0 is not in the ideal; \
                 without Q0 Q~0 != 0 (r Q0 Q~0 = 1) the unit real part is not; Rot Rot~ = 1 does not follow \
                 ('normalized' in (9) means only Trans Rot = Q)",
    check: eq_9,
}];

type Dq = DualQuaternion<Poly>;

fn coeffs(q: &Quaternion<Poly>) -> [Poly; 4] {
    [q.w.clone(), q.x.clone(), q.y.clone(), q.z.clone()]
}

fn components(x: &Dq) -> Vec<Poly> {
    x.coeffs().to_vec()
}

fn eq_9(c: &mut Checker) {
    let q = Dq::from_coeffs(["q0", "q1", "q2", "q3", "p0", "p1", "p2", "p3"].map(Poly::var));
    let r = Poly::var("r");
    let q0 = Dq::from_real(q.real.clone());
    let q0n = q.real.norm_squared();
    // (8): q0 qε + q0·qε = 0, and Q0 Q~0 != 0 as r Q0 Q~0 - 1 = 0.
    let study = q.real.dot(&q.dual);
    let nonzero = r.mul_ref(&q0n).sub_ref(&Poly::one());
    let both = Hypotheses { equations: vec![study.clone(), nonzero.clone()], nonzero: vec![] };
    let trans = &q * &q0.conjugate();
    let rot = q0.scale(&r);
    // Trans(Q)/(Q0 Q~0) = r Trans(Q) is 1 + ε t: real part 1, dual scalar part 0.
    let unit = trans.scale(&r);
    let mut unit_translation: Vec<Poly> = coeffs(&unit.real).to_vec();
    unit_translation[0] = unit_translation[0].sub_ref(&Poly::one());
    unit_translation.push(unit.dual.w.clone());
    let what = "r Q Q~0 = 1 + ε t (a unit translation)";
    holds_under(c, what, &unit_translation, &both);
    needs(c, what, "(8)", &unit_translation, &Hypotheses { equations: vec![nonzero.clone()], nonzero: vec![] });
    needs(c, what, "Q0 Q~0 != 0", &unit_translation, &Hypotheses { equations: vec![study.clone()], nonzero: vec![] });
    let product = components(&(&(&trans * &rot) - &q));
    let what = "Trans(Q) Rot(Q) = Q";
    holds_under(c, what, &product, &both);
    needs(c, what, "Q0 Q~0 != 0", &product, &Hypotheses { equations: vec![study.clone()], nonzero: vec![] });
    let rr = &rot * &rot.conjugate();
    let mut norm = components(&rr);
    norm[0] = norm[0].sub_ref(&r);
    holds_under(c, "Rot Rot~ = 1/(Q0 Q~0)", &norm, &both);
    let mut unit_norm = components(&rr);
    unit_norm[0] = unit_norm[0].sub_ref(&Poly::one());
    needs(c, "Rot(Q) is normalized (Rot Rot~ = 1)", "Q0 Q~0 = 1", &unit_norm, &both);
}

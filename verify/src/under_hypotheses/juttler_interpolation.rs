//! Jüttler's Propositions 1-4 proved with symbolic data (two positions, `m = 1`): the parts of
//! each proposition that are ideal membership statements about its linear interpolation system,
//! over symbolic rotations, positions, parameters `t_i` and control points. `juttler/proposition-N`
//! (`super::super::juttler::interpolation`) checks the same propositions on rational instances,
//! with the rank statements (nonsingular systems, degrees) that are not membership; the same
//! ideals are in the Gröbner benchmark suite against Singular (`algebra-core/benches/groebner_suite.rs`).
//!
//! Quaternions are `gam_algebras`' [`Quaternion`] over [`Poly`] (its Hamilton product); Bézier
//! curves use the Bernstein basis of `crate::juttler`. "The parameters are distinct" is the
//! non-zero condition `Π_{i<l} (t_l - t_i) != 0`, and `r_i0 != 0` likewise (the engine adds a
//! Rabinowitsch variable for each).

use super::{holds_under, needs};
use crate::juttler::bernstein;
use crate::{Checker, Method, Paper, Statement};
use algebra_core::ideal::Hypotheses;
use algebra_core::{Poly, Ring};
use gam_algebras::dual_quaternion::Quaternion;

/// The statements of this module.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "juttler/proposition-1-symbolic",
        paper: Paper::Juttler,
        label: "Proposition 1 (symbolic)",
        statement: "for two symbolic rotations R_i = r_i0 + r_i at distinct symbolic parameters t_i, any two \
                    solutions C, C' of the affine system (21) (Scal C_j = 1, r_i0 Vec Q(t_i) = r_i) are equal, and \
                    r_i0 Q(t_i) = R_i: the Q-motion interpolates with λ_i = 1/r_i0 (18), (20)",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "distinct parameters are needed for uniqueness (t_0 = t_1 leaves C free); r_i0 != 0 as in (20)",
        check: proposition_1,
    },
    Statement {
        id: "juttler/proposition-2-symbolic",
        paper: Paper::Juttler,
        label: "Proposition 2 (symbolic)",
        statement: "for two symbolic unit rotations R_i at distinct symbolic parameters and a symbolic unit rotation \
                    D, any two solutions C, C' of the elliptic system (25) are equal, and D Q and Q D satisfy (25) \
                    for the data D R_i and R_i D with |D Q(t_i)|² = |Q(t_i) D|² = 1 (22): the result does not \
                    depend on the orientations of the fixed and the moving space",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "distinct parameters are needed for uniqueness; |R_i| = |D| = 1 (23); the sign choice (24) is an \
                     inequality and not encoded",
        check: proposition_2,
    },
    Statement {
        id: "juttler/proposition-3-symbolic",
        paper: Paper::Juttler,
        label: "Proposition 3 (symbolic)",
        statement: "at an interpolation point, symbolic quaternions q = Q(t_i) and R with (27), r_0 Vec q = Scal q \
                    Vec R, and r_0 != 0 satisfy q = λ R with λ = q_0/r_0 (18), and (27) holds again for \
                    D q, D R and for q D, R D with a symbolic D (invariance under the orientations)",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "r_0 != 0 is needed: at a half turn (r_0 = 0) (27) does not make q a multiple of R",
        check: proposition_3,
    },
    Statement {
        id: "juttler/proposition-4-symbolic",
        paper: Paper::Juttler,
        label: "Proposition 4 (symbolic)",
        statement: "for two symbolic positions P_i = (2 + ε s_i) R_i at distinct symbolic parameters and a \
                    rotational motion of degree 1 with Q_rot(t_i) = λ_i R_i (18), any two solutions p, p' of (31) \
                    are equal, and Q = 2 Q_rot + ε p Q_rot (30) interpolates: Q(t_i) = λ_i P_i (real and dual part)",
        method: Method::SymbolicUnderHypotheses,
        hypotheses: "distinct parameters are needed for uniqueness; the degree k + m and the dependence on the \
                     origin are not membership statements and are checked on instances (juttler/proposition-4)",
        check: proposition_4,
    },
];

type Quat = Quaternion<Poly>;

fn var(name: &str) -> Poly {
    Poly::var(name)
}

/// `prefix0 + prefix1 i + prefix2 j + prefix3 k`.
fn symbolic(prefix: &str) -> Quat {
    let v = |c: usize| var(&format!("{prefix}{c}"));
    Quat::new(v(0), v(1), v(2), v(3))
}

/// The pure quaternion `prefix1 i + prefix2 j + prefix3 k` (a vector of R³).
fn pure(prefix: &str) -> Quat {
    Quat::pure(&[1, 2, 3].map(|c| var(&format!("{prefix}{c}"))))
}

fn coords(q: &Quat) -> [Poly; 4] {
    [q.w.clone(), q.x.clone(), q.y.clone(), q.z.clone()]
}

/// The four coordinates of `a - b`.
fn diff(a: &Quat, b: &Quat) -> Vec<Poly> {
    coords(a).iter().zip(coords(b)).map(|(x, y)| x.sub_ref(&y)).collect()
}

/// `Σ_j b_j^n(t) C_j`, Jüttler's (17).
fn bezier(cs: &[Quat], t: &Poly) -> Quat {
    let n = (cs.len() - 1) as u32;
    let terms: Vec<Quat> = cs.iter().enumerate().map(|(j, c)| c.scale(&bernstein(n, j as u32, t))).collect();
    let sum = |f: fn(&Quat) -> &Poly| terms.iter().fold(Poly::zero(), |s, q| s.add_ref(f(q)));
    Quat::new(sum(|q| &q.w), sum(|q| &q.x), sum(|q| &q.y), sum(|q| &q.z))
}

/// The parameters `t0, t1` and the condition that they differ.
fn parameters() -> (Vec<Poly>, Poly) {
    let ts = vec![var("t0"), var("t1")];
    let distinct = ts[1].sub_ref(&ts[0]);
    (ts, distinct)
}

/// Control points `prefix0, prefix1` of a degree-1 curve (as symbolic quaternions).
fn control(prefix: &str, make: fn(&str) -> Quat) -> Vec<Quat> {
    (0..2).map(|j| make(&format!("{prefix}{j}_"))).collect()
}

fn uniqueness(a: &[Quat], b: &[Quat]) -> Vec<Poly> {
    a.iter().zip(b).flat_map(|(x, y)| diff(x, y)).collect()
}

fn proposition_1(c: &mut Checker) {
    let (ts, distinct) = parameters();
    let rs = [symbolic("r0_"), symbolic("r1_")];
    let mut equations = Vec::new();
    let solutions: Vec<Vec<Quat>> = ["c", "d"]
        .iter()
        .map(|name| {
            let cs = control(name, symbolic);
            // (19) Scal C_j = 1, and (21) with the denominator r_i0 cleared
            equations.extend(cs.iter().map(|q| q.w.sub_ref(&Poly::one())));
            for (t, r) in ts.iter().zip(&rs) {
                let q = coords(&bezier(&cs, t));
                let r = coords(r);
                equations.extend((1..4).map(|k| r[0].mul_ref(&q[k]).sub_ref(&r[k])));
            }
            cs
        })
        .collect();
    let nonzero: Vec<Poly> = rs.iter().map(|r| r.w.clone()).collect();
    let hyps = Hypotheses { equations: equations.clone(), nonzero: [vec![distinct], nonzero.clone()].concat() };
    let unique = uniqueness(&solutions[0], &solutions[1]);
    holds_under(c, "C_j = C'_j", &unique, &hyps);
    needs(c, "C_j = C'_j", "distinct parameters", &unique, &Hypotheses { equations, nonzero });
    let interpolation: Vec<Poly> =
        ts.iter().zip(&rs).flat_map(|(t, r)| diff(&bezier(&solutions[0], t).scale(&r.w), r)).collect();
    holds_under(c, "r_i0 Q(t_i) = R_i", &interpolation, &hyps);
}

fn proposition_2(c: &mut Checker) {
    let (ts, distinct) = parameters();
    let rs = [symbolic("r0_"), symbolic("r1_")];
    let d = symbolic("q");
    let unit = |q: &Quat| q.norm_squared().sub_ref(&Poly::one());
    let mut equations = vec![unit(&d)];
    equations.extend(rs.iter().map(unit));
    let solutions: Vec<Vec<Quat>> = ["c", "e"]
        .iter()
        .map(|name| {
            let cs = control(name, symbolic);
            for (t, r) in ts.iter().zip(&rs) {
                equations.extend(diff(&bezier(&cs, t), r));
            }
            cs
        })
        .collect();
    let hyps = Hypotheses { equations: equations.clone(), nonzero: vec![distinct] };
    let unique = uniqueness(&solutions[0], &solutions[1]);
    holds_under(c, "C_j = C'_j", &unique, &hyps);
    needs(c, "C_j = C'_j", "distinct parameters", &unique, &Hypotheses { equations, nonzero: vec![] });
    let mut invariance = Vec::new();
    for (t, r) in ts.iter().zip(&rs) {
        let q = bezier(&solutions[0], t);
        let (fixed, moving) = (&d * &q, &q * &d);
        invariance.extend(diff(&fixed, &(&d * r)));
        invariance.extend(diff(&moving, &(r * &d)));
        invariance.push(unit(&fixed));
        invariance.push(unit(&moving));
    }
    holds_under(c, "D Q and Q D solve (25) for D R_i, R_i D, with (22)", &invariance, &hyps);
}

/// `r_0 Vec q - Scal q Vec r`, Jüttler's (27).
fn projective(q: &Quat, r: &Quat) -> Vec<Poly> {
    let (q, r) = (coords(q), coords(r));
    (1..4).map(|k| r[0].mul_ref(&q[k]).sub_ref(&q[0].mul_ref(&r[k]))).collect()
}

fn proposition_3(c: &mut Checker) {
    let (q, r, d) = (symbolic("q"), symbolic("r"), symbolic("d"));
    // v = 1/r_0 (v r_0 = 1), so that λ = q_0 v is a polynomial; without it v is a free symbol
    let v = var("v");
    let equations = projective(&q, &r);
    let inverse = v.mul_ref(&r.w).sub_ref(&Poly::one());
    let hyps = Hypotheses { equations: [equations.clone(), vec![inverse]].concat(), nonzero: vec![] };
    let multiple = diff(&q, &r.scale(&q.w.mul_ref(&v)));
    holds_under(c, "q = λ R with λ = q_0 / r_0", &multiple, &hyps);
    needs(c, "q = λ R with λ = q_0 / r_0", "r_0 != 0", &multiple, &Hypotheses { equations, nonzero: vec![] });
    let invariance = [projective(&(&d * &q), &(&d * &r)), projective(&(&q * &d), &(&r * &d))].concat();
    holds_under(c, "(27) for D q, D R and q D, R D", &invariance, &hyps);
}

fn proposition_4(c: &mut Checker) {
    let (ts, distinct) = parameters();
    let rs = [symbolic("r0_"), symbolic("r1_")];
    let ss = [pure("s0_"), pure("s1_")];
    let lambda = [var("l0"), var("l1")];
    let cs = control("c", symbolic);
    let mut equations = Vec::new();
    // (18): the rotational motion passes through the rotations, up to λ_i
    for ((t, r), l) in ts.iter().zip(&rs).zip(&lambda) {
        equations.extend(diff(&bezier(&cs, t), &r.scale(l)));
    }
    // (31): the vector parts of Σ b_j(t_i) p_j = s_i
    let solutions: Vec<Vec<Quat>> = ["p", "q"]
        .iter()
        .map(|name| {
            let ps = control(name, pure);
            for (t, s) in ts.iter().zip(&ss) {
                equations.extend(diff(&bezier(&ps, t), s).into_iter().skip(1));
            }
            ps
        })
        .collect();
    let hyps = Hypotheses { equations: equations.clone(), nonzero: vec![distinct] };
    let unique: Vec<Poly> =
        solutions[0].iter().zip(&solutions[1]).flat_map(|(p, q)| diff(p, q).into_iter().skip(1)).collect();
    holds_under(c, "p_j = p'_j", &unique, &hyps);
    needs(c, "p_j = p'_j", "distinct parameters", &unique, &Hypotheses { equations, nonzero: vec![] });
    let two = Poly::from_i64(2);
    let mut interpolation = Vec::new();
    for (((t, r), s), l) in ts.iter().zip(&rs).zip(&ss).zip(&lambda) {
        let rot = bezier(&cs, t);
        // real part 2 Q_rot(t_i) = 2 λ_i R_i; dual part p(t_i) Q_rot(t_i) = λ_i s_i R_i
        interpolation.extend(diff(&rot.scale(&two), &r.scale(&two.mul_ref(l))));
        interpolation.extend(diff(&(&bezier(&solutions[0], t) * &rot), &(s * r).scale(l)));
    }
    holds_under(c, "Q(t_i) = λ_i P_i", &interpolation, &hyps);
}

//! Section 4: motion construction (slerp, additive interpolation, Bezier motions) and the end
//! derivatives.
//!
//! * `eq-15`: `Φ(A, B; t) = A (rev(A) B)^t` (the OCR lost the bar) from the motion crate against
//!   the formula typed in with the runtime multivector exp/log of G_{123inf}; `Φ(0) = A`, and for
//!   unit poses `Φ(1) = B` and `Φ(t)` unitary; counterexample without unit poses.
//! * `eq-16`: `Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)` with `α^s = exp(s ln α)`; needs positive
//!   scalar parts of α, β (counterexample β = -1).
//! * `lemma-4.1`: multiplicative Bezier motions of pseudoscalar multiples of the control poses are
//!   equivalent (every tableau entry) and move points identically.
//! * `lemma-4.2`: symbolic: additive Bezier of symbolic control poses, degrees 1-4, derivative by
//!   `Poly::derivative`; `Ṡ(0) = n(S1 - S0)` and the remainder is divisible by t².
//! * `lemma-4.3`: `[X + tY]^t` over nested dual numbers at t = 0: value 1, derivative `log X`,
//!   finite second derivative (so the remainder is O(t²)); plus a 512-bit finite difference.
//! * `lemma-4.4`, `theorem-4.5-*`, `corollary-4.6-*`: end derivatives and indicatrices from dual
//!   numbers (the motion crate), from finite differences at 512 bits (multiplicative), from
//!   `Poly::derivative` and exact dual numbers over Q (additive), against the printed formulas.
//!   The t = 1 formulas and the reversal of multiplicative motions need unit control poses
//!   (counterexample S0 = 2, S1 = 1).

use super::sec3::{comps, mp, sample_poses};
use crate::{Checker, Method, Paper, Statement};
use algebra_core::rational::Q;
use algebra_core::{Field, Jet, MpFloat, Poly, PrecisionGuard, Real, Ring};
use motion::velocity::{indicatrix_from_derivative, pose_derivative, split_jet, velocity_indicatrix};
use motion::{AdditiveBezier, Even, Motion, MultiplicativeBezier, Pose, Pseudoscalar, pseudoscalar};

/// The statements of Section 4, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "cross2022/eq-15",
        paper: Paper::Cross2022,
        label: "Eq. (15)",
        statement: "slerp Φ(A, B; t) = A (rev(A) B)^t; if A and B are unitary so is Φ(t), Φ(0) = A and Φ(1) = B",
        method: Method::MpFloat,
        hypotheses: "Φ(1) = A rev(A) B = |A|² B, which is B only for unit A (S0 = 2, S1 = 1 gives 4); the \
                     printed A(AB)^t lost the bar over A",
        check: eq_15,
    },
    Statement {
        id: "cross2022/eq-16",
        paper: Paper::Cross2022,
        label: "Eq. (16)",
        statement: "for pseudoscalars α, β: Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)",
        method: Method::MpFloat,
        hypotheses: "α^s = exp(s ln α) needs α, β with positive scalar parts (for β = -1 the slerp turns the other \
                     way and is not a pseudoscalar multiple); α^{1+t} = α α^t",
        check: eq_16,
    },
    Statement {
        id: "cross2022/lemma-4.1",
        paper: Paper::Cross2022,
        label: "Lemma 4.1",
        statement: "equivalent control poses give an equivalent multiplicative motion, hence the same transforms",
        method: Method::MpFloat,
        hypotheses: "the pseudoscalar factors need positive scalar parts (eq. 16); S1 → -S1 changes the motion",
        check: lemma_4_1,
    },
    Statement {
        id: "cross2022/lemma-4.2",
        paper: Paper::Cross2022,
        label: "Lemma 4.2",
        statement: "additive Bezier of degree n: Ṡ(0) = n(S1 - S0), S(t) = S(0) + nt(S1 - S0) + O(t²)",
        method: Method::Symbolic,
        hypotheses: "",
        check: lemma_4_2,
    },
    Statement {
        id: "cross2022/lemma-4.3",
        paper: Paper::Cross2022,
        label: "Lemma 4.3",
        statement: "for non-singular X, Y: [X + tY]^t = 1 + t log X + O(t²)",
        method: Method::MpFloatDual,
        hypotheses: "only X needs to be non-singular (X + tY is then non-singular near t = 0)",
        check: lemma_4_3,
    },
    Statement {
        id: "cross2022/lemma-4.4",
        paper: Paper::Cross2022,
        label: "Lemma 4.4",
        statement: "multiplicative Bezier of degree n: S(t) = S0 [1 + nt log(rev(S0) S1)] + O(t²)",
        method: Method::MpFloatDual,
        hypotheses: "holds for non-unit control poses too",
        check: lemma_4_4,
    },
    Statement {
        id: "cross2022/theorem-4.5-additive",
        paper: Paper::Cross2022,
        label: "Theorem 4.5 (i)",
        statement: "additive Bezier: Ṡ(0) = n(S1 - S0), Ṡ(1) = n(Sn - Sn-1); S_{0..n}(t) = S_{n..0}(1 - t)",
        method: Method::Symbolic,
        hypotheses: "",
        check: theorem_4_5_additive,
    },
    Statement {
        id: "cross2022/theorem-4.5-multiplicative",
        paper: Paper::Cross2022,
        label: "Theorem 4.5 (ii)",
        statement: "multiplicative Bezier: Ṡ(0) = n S0 log(rev(S0) S1), Ṡ(1) = -n Sn log(rev(Sn) Sn-1), via \
                    S_{0..n}(t) = S_{n..0}(1 - t)",
        method: Method::MpFloatDual,
        hypotheses: "the t = 1 formula and the reversal need unit control poses (S0 = 2, S1 = 1: S(t) = 2^{1+t}, \
                     Ṡ(1) = 4 ln 2 but the formula gives -ln 2); t = 0 holds for any non-singular poses",
        check: theorem_4_5_multiplicative,
    },
    Statement {
        id: "cross2022/corollary-4.6-additive",
        paper: Paper::Cross2022,
        label: "Corollary 4.6 (i)",
        statement: "additive Bezier: Ψ(0) = 2n S0⁻¹ (S1 - S0), Ψ(1) = 2n Sn⁻¹ (Sn - Sn-1) (eq. 20)",
        method: Method::Exact,
        hypotheses: "S0 and Sn non-singular",
        check: corollary_4_6_additive,
    },
    Statement {
        id: "cross2022/corollary-4.6-multiplicative",
        paper: Paper::Cross2022,
        label: "Corollary 4.6 (ii)",
        statement: "multiplicative Bezier: Ψ(0) = 2n log(rev(S0) S1), Ψ(1) = -2n log(rev(Sn) Sn-1) (eq. 21)",
        method: Method::MpFloatDual,
        hypotheses: "Ψ(1) needs unit control poses (S0 = 2, S1 = 1: Ψ(1) = 2 ln 2, formula -2 ln 2); Ψ(0) holds \
                     for any non-singular poses",
        check: corollary_4_6_multiplicative,
    },
];

fn s<E: std::fmt::Display>(r: Result<Pose<MpFloat>, E>) -> Result<Pose<MpFloat>, String> {
    r.map_err(|e| e.to_string())
}

/// `X^t` typed in with the runtime multivector exp/log (a second implementation).
fn runtime_power(x: &Even<MpFloat>, t: &MpFloat) -> Result<Even<MpFloat>, String> {
    let l = x.to_multivector().log().map_err(|e| e.to_string())?;
    let p = l.scale(t).exp().map_err(|e| e.to_string())?;
    Even::try_from(&p).map_err(|e| e.to_string())
}

fn agree(a: &Even<MpFloat>, b: &Even<MpFloat>) -> bool {
    Checker::new().close("", &comps(a), &comps(b), 70)
}

fn eq_15(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    for (a, b) in [(&unit[0], &unit[1]), (&unit[1], &unit[2]), (&non_unit[0], &non_unit[1])] {
        for t in [mp(0, 1), mp(1, 3), mp(9, 10), mp(1, 1)] {
            let Some(phi) = c.ok("slerp", s(Pose::slerp(a, b, &t))) else { return };
            let rel = &a.reverse() * b;
            if let Some(p) = c.ok("runtime power", runtime_power(&rel, &t)) {
                c.close("Pose::slerp = A (rev(A) B)^t with runtime exp/log", &comps(&phi), &comps(&(a * &p)), 70);
            }
        }
        let Some(at0) = c.ok("slerp", s(Pose::slerp(a, b, &mp(0, 1)))) else { return };
        c.close("Φ(0) = A", &comps(&at0), &comps(a), 70);
        let Some(at1) = c.ok("slerp", s(Pose::slerp(a, b, &mp(1, 1)))) else { return };
        let n2 = a.pseudo_norm_squared();
        c.close("Φ(1) = |A|² B", &comps(&at1), &comps(&b.scale_pseudoscalar(&n2)), 70);
    }
    for t in [mp(1, 3), mp(1, 1)] {
        let Some(phi) = c.ok("slerp", s(Pose::slerp(&unit[0], &unit[2], &t))) else { return };
        let n2 = phi.pseudo_norm_squared();
        c.close("unit A, B: Φ(t) unitary", &[n2.scalar, n2.e123inf], &[mp(1, 1), mp(0, 1)], 70);
    }
    let Some(at1) = c.ok("slerp", s(Pose::slerp(&unit[0], &unit[2], &mp(1, 1)))) else { return };
    c.close("unit A, B: Φ(1) = B", &comps(&at1), &comps(&unit[2]), 70);
    let two = Pose::identity().scale(&mp(2, 1));
    if let Some(end) = c.ok("slerp", s(Pose::slerp(&two, &Pose::identity(), &mp(1, 1)))) {
        c.counterexample(
            "Φ(A, B; 1) = B without unit poses",
            agree(&end, &Even::one()),
            format!("A = 2, B = 1: Φ(1) = {}", end.scalar.to_f64()),
        );
    }
}

fn ps_power(alpha: &Pseudoscalar<MpFloat>, e: &MpFloat) -> Result<Pseudoscalar<MpFloat>, String> {
    let l = pseudoscalar::ln(alpha).map_err(|e| e.to_string())?;
    Ok(pseudoscalar::exp(&Pseudoscalar::new(l.scalar.mul_ref(e), l.e123inf.mul_ref(e))))
}

fn eq_16(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    let alpha = Pseudoscalar::new(mp(3, 1), mp(-1, 2));
    let beta = Pseudoscalar::new(mp(1, 5), mp(7, 3));
    for (a, b) in [(&unit[0], &unit[1]), (&non_unit[1], &non_unit[2])] {
        for t in [mp(0, 1), mp(2, 7), mp(1, 1)] {
            let lhs = s(Pose::slerp(&a.scale_pseudoscalar(&alpha), &b.scale_pseudoscalar(&beta), &t));
            let (Some(lhs), Some(phi)) = (c.ok("slerp", lhs), c.ok("slerp", s(Pose::slerp(a, b, &t)))) else { return };
            let (Some(a1t), Some(at), Some(bt)) = (
                c.ok("α^{1+t}", ps_power(&alpha, &t.add_ref(&MpFloat::one()))),
                c.ok("α^t", ps_power(&alpha, &t)),
                c.ok("β^t", ps_power(&beta, &t)),
            ) else {
                return;
            };
            c.close(
                "α^{1+t} = α α^t",
                &comps(&Pose::identity().scale_pseudoscalar(&a1t)),
                &comps(&Pose::identity().scale_pseudoscalar(&(&alpha * &at))),
                70,
            );
            let rhs = phi.scale_pseudoscalar(&(&a1t * &bt));
            c.close("Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)", &comps(&lhs), &comps(&rhs), 70);
        }
    }
    // β = -1 (same transform as B): the slerp is not a pseudoscalar multiple of Φ(A, B; t).
    let t = mp(1, 2);
    let (Some(phi), Some(neg)) = (
        c.ok("slerp", s(Pose::slerp(&unit[0], &unit[1], &t))),
        c.ok("slerp", s(Pose::slerp(&unit[0], &-&unit[1], &t))),
    ) else {
        return;
    };
    let eqv = neg.is_equivalent(&phi, &mp(1, 1_000_000_000_000));
    c.counterexample(
        "eq. (16) with β = -1 (negative scalar part)",
        eqv.unwrap_or(true),
        "A, B unit, t = 1/2: Φ(A, -B; t) is not equivalent to Φ(A, B; t) (turns the other way)",
    );
}

fn lemma_4_1(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    let (Some(m), Some(m2)) = (
        c.ok("bezier", MultiplicativeBezier::new(unit.clone())),
        c.ok("bezier", MultiplicativeBezier::new(non_unit.clone())),
    ) else {
        return;
    };
    let tol = mp(1, 1).div_ref(&MpFloat::from_i64(10).pow_u32(70));
    for t in [mp(1, 5), mp(2, 3)] {
        let (Some(tab), Some(tab2)) = (c.ok("tableau", m.tableau(&t)), c.ok("tableau", m2.tableau(&t))) else { return };
        let all =
            tab.iter().flatten().zip(tab2.iter().flatten()).all(|(x, y)| y.is_equivalent(x, &tol).unwrap_or(false));
        c.check("every tableau entry of the equivalent poses is a pseudoscalar multiple", all);
        let (Some(x), Some(y)) = (c.ok("pose", m.pose(&t)), c.ok("pose", m2.pose(&t))) else { return };
        for p in [[mp(1, 1), mp(2, 1), mp(-3, 1)], [mp(0, 1), mp(1, 2), mp(5, 1)]] {
            let (Some(px), Some(py)) = (c.ok("F", x.transform_point(&p)), c.ok("F", y.transform_point(&p))) else {
                return;
            };
            c.close("the two motions move points identically", &px, &py, 70);
        }
    }
    let mut flipped = unit.clone();
    flipped[1] = -&flipped[1];
    if let Some(m3) = c.ok("bezier", MultiplicativeBezier::new(flipped)) {
        let (Some(x), Some(y)) = (c.ok("pose", m.pose(&mp(1, 2))), c.ok("pose", m3.pose(&mp(1, 2)))) else { return };
        c.counterexample(
            "Lemma 4.1 with a negative factor (S1 → -S1)",
            y.is_equivalent(&x, &mp(1, 1_000_000_000_000)).unwrap_or(true),
            "unit poses, t = 1/2: the motion with -S1 is not equivalent",
        );
    }
}

/// `n + 1` fully symbolic control poses `Si_*` and the additive Bezier over `Poly` at `t`.
fn symbolic_bezier(n: usize) -> (Vec<Pose<Poly>>, Even<Poly>) {
    let names = ["s", "s12", "s13", "s23", "s1i", "s2i", "s3i", "sw"];
    let poses: Vec<Pose<Poly>> = (0..=n)
        .map(|i| {
            let v: Vec<Poly> = names.iter().map(|x| Poly::var(&format!("S{i}{x}"))).collect();
            Even::new(
                v[0].clone(),
                v[1].clone(),
                v[2].clone(),
                v[3].clone(),
                v[4].clone(),
                v[5].clone(),
                v[6].clone(),
                v[7].clone(),
            )
        })
        .collect();
    let m =
        AdditiveBezier::new(poses.clone()).map(|b| b.de_casteljau(&Poly::var("t"))).unwrap_or_else(|_| Even::zero());
    (poses, m)
}

fn map_motor(m: &Even<Poly>, f: impl Fn(&Poly) -> Poly) -> Even<Poly> {
    let p = m.clone();
    let c = p.components().map(f);
    let [a, b, d, e, g, h, i, j] = c;
    Even::new(a, b, d, e, g, h, i, j)
}

fn at(m: &Even<Poly>, t: i64) -> Even<Poly> {
    map_motor(m, |x| x.substitute("t", &Poly::from_i64(t)))
}

fn lemma_4_2(c: &mut Checker) {
    for n in 1..=4 {
        let (poses, m) = symbolic_bezier(n);
        let dm = map_motor(&m, |x| x.derivative("t"));
        let nn = Poly::from_i64(n as i64);
        let expected = (&poses[1] - &poses[0]).scale(&nn);
        c.equal(format!("n = {n}: S(0) = S0"), &at(&m, 0), &poses[0]);
        c.equal(format!("n = {n}: Ṡ(0) = n(S1 - S0)"), &at(&dm, 0), &expected);
        // Remainder R = S(t) - S0 - nt(S1 - S0): R(0) = R'(0) = 0, so R = t² Q(t).
        let r = &(&m - &poses[0]) - &expected.scale(&Poly::var("t"));
        let dr = map_motor(&r, |x| x.derivative("t"));
        c.equal(
            format!("n = {n}: remainder and its derivative vanish at 0 (O(t²))"),
            &(at(&r, 0), at(&dr, 0)),
            &(Even::zero(), Even::zero()),
        );
    }
}

/// `df/dt` at `t0` by the 6th-order central difference at 512 bits with h = 1e-20.
fn finite_difference(
    f: &dyn Fn(&MpFloat) -> Result<Even<MpFloat>, String>,
    t0: &MpFloat,
) -> Result<Vec<MpFloat>, String> {
    let _g = PrecisionGuard::new(512);
    let h = mp(1, 1).div_ref(&MpFloat::from_i64(10).pow_u32(20));
    let weights = [(1, 45), (2, -9), (3, 1)];
    let mut acc = vec![MpFloat::zero(); 8];
    for (k, w) in weights {
        let dk = h.mul_ref(&MpFloat::from_i64(k));
        let (plus, minus) = (comps(&f(&t0.add_ref(&dk))?), comps(&f(&t0.sub_ref(&dk))?));
        for i in 0..8 {
            acc[i] = acc[i].add_ref(&plus[i].sub_ref(&minus[i]).mul_ref(&MpFloat::from_i64(w)));
        }
    }
    let den = h.mul_ref(&MpFloat::from_i64(60));
    Ok(acc.into_iter().map(|x| x.div_ref(&den)).collect())
}

fn lemma_4_3(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    for (x, y) in [(&non_unit[0], &unit[1]), (&unit[2], &non_unit[3])] {
        // Nested dual numbers: t = 0 + ε1 + ε2 gives f, f', f''.
        let lift = |p: &Pose<MpFloat>| p.map_scalar(&|v: &MpFloat| Jet::constant(Jet::constant(v.clone())));
        let t = Jet::new(Jet::variable(MpFloat::zero()), Jet::constant(MpFloat::one()));
        let (xj, yj) = (lift(x), lift(y));
        let base = &xj + &yj.scale(&t);
        let Some(f) = c.ok("power", base.power(&t)) else { return };
        let (value, deriv) = split_jet(&f);
        let (f0, _) = split_jet(&value);
        let (f1, f2) = split_jet(&deriv);
        let Some(lx) = c.ok("log X", x.log()) else { return };
        c.close("[X + tY]^t at t = 0 is 1", &comps(&f0), &comps(&Even::one()), 70);
        c.close("d/dt [X + tY]^t at 0 = log X", &comps(&f1), &comps(&lx), 70);
        c.check("second derivative finite: the remainder is O(t²)", comps(&f2).iter().all(Real::is_finite));
        let fx = |tt: &MpFloat| s((x + &y.scale(tt)).power(tt));
        if let Some(fd) = c.ok("finite difference", finite_difference(&fx, &MpFloat::zero())) {
            c.close("finite difference at 512 bits: d/dt [X + tY]^t at 0 = log X", &fd, &comps(&lx), 70);
        }
    }
}

fn mul_end_checks(c: &mut Checker, poses: &[Pose<MpFloat>], ends: bool) {
    let n = poses.len() - 1;
    let nn = MpFloat::from_i64(n as i64);
    let Some(m) = c.ok("bezier", MultiplicativeBezier::new(poses.to_vec())) else { return };
    let Some((s0, d0)) = c.ok("derivative", pose_derivative(&m, &MpFloat::zero())) else { return };
    let Some(l0) = c.ok("log", (&poses[0].reverse() * &poses[1]).log()) else { return };
    let formula0 = (&poses[0] * &l0).scale(&nn);
    c.close(format!("n = {n}: S(0) = S0"), &comps(&s0), &comps(&poses[0]), 70);
    c.close(format!("n = {n}: Ṡ(0) = n S0 log(rev(S0) S1) (dual numbers)"), &comps(&d0), &comps(&formula0), 70);
    let f = |t: &MpFloat| m.evaluate(t).map_err(|e| e.to_string());
    if let Some(fd) = c.ok("finite difference", finite_difference(&f, &MpFloat::zero())) {
        c.close(format!("n = {n}: Ṡ(0) by finite differences"), &fd, &comps(&formula0), 70);
    }
    if !ends {
        return;
    }
    let Some((_, d1)) = c.ok("derivative", pose_derivative(&m, &MpFloat::one())) else { return };
    let Some(l1) = c.ok("log", (&poses[n].reverse() * &poses[n - 1]).log()) else { return };
    let formula1 = (&poses[n] * &l1).scale(&nn.neg_ref());
    c.close(format!("n = {n}: Ṡ(1) = -n Sn log(rev(Sn) Sn-1) (dual numbers)"), &comps(&d1), &comps(&formula1), 70);
    if let Some(fd) = c.ok("finite difference", finite_difference(&f, &MpFloat::one())) {
        c.close(format!("n = {n}: Ṡ(1) by finite differences"), &fd, &comps(&formula1), 70);
    }
    let r = m.reversed();
    for t in [mp(0, 1), mp(1, 3), mp(1, 1)] {
        let (Some(a), Some(b)) = (c.ok("pose", m.pose(&t)), c.ok("pose", r.pose(&MpFloat::one().sub_ref(&t)))) else {
            return;
        };
        c.close(format!("n = {n}: S_(0..n)(t) = S_(n..0)(1 - t)"), &comps(&a), &comps(&b), 70);
    }
}

fn lemma_4_4(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    for k in 1..=3 {
        mul_end_checks(c, &unit[..=k], false);
        mul_end_checks(c, &non_unit[..=k], false);
    }
}

/// The counterexample S0 = 2, S1 = 1: S(t) = 2^{1+t}.
fn two_one() -> Vec<Pose<MpFloat>> {
    vec![Pose::identity().scale(&mp(2, 1)), Pose::identity()]
}

fn theorem_4_5_multiplicative(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    for k in 1..=3 {
        mul_end_checks(c, &unit[..=k], true);
        mul_end_checks(c, &non_unit[..=k], false);
    }
    let poses = two_one();
    let Some(m) = c.ok("bezier", MultiplicativeBezier::new(poses.clone())) else { return };
    let Some((_, d1)) = c.ok("derivative", pose_derivative(&m, &MpFloat::one())) else { return };
    let Some(l1) = c.ok("log", (&poses[1].reverse() * &poses[0]).log()) else { return };
    let formula1 = (&poses[1] * &l1).scale(&mp(-1, 1));
    c.counterexample(
        "Ṡ(1) = -n Sn log(rev(Sn) Sn-1) for non-unit poses",
        agree(&d1, &formula1),
        format!("S0 = 2, S1 = 1: Ṡ(1) = {} (4 ln 2), formula {} (-ln 2)", d1.scalar.to_f64(), formula1.scalar.to_f64()),
    );
    let (Some(a), Some(b)) = (c.ok("pose", m.pose(&mp(1, 4))), c.ok("pose", m.reversed().pose(&mp(3, 4)))) else {
        return;
    };
    c.counterexample(
        "S_(0..n)(t) = S_(n..0)(1 - t) for non-unit poses",
        agree(&a, &b),
        format!("S0 = 2, S1 = 1, t = 1/4: 2^(5/4) = {} against 2^(3/4) = {}", a.scalar.to_f64(), b.scalar.to_f64()),
    );
}

fn theorem_4_5_additive(c: &mut Checker) {
    for n in 1..=4 {
        let (poses, m) = symbolic_bezier(n);
        let dm = map_motor(&m, |x| x.derivative("t"));
        let nn = Poly::from_i64(n as i64);
        c.equal(format!("n = {n}: Ṡ(0) = n(S1 - S0)"), &at(&dm, 0), &(&poses[1] - &poses[0]).scale(&nn));
        c.equal(format!("n = {n}: Ṡ(1) = n(Sn - Sn-1)"), &at(&dm, 1), &(&poses[n] - &poses[n - 1]).scale(&nn));
        let rev = AdditiveBezier::new(poses.iter().rev().cloned().collect())
            .map(|b| b.de_casteljau(&Poly::one().sub_ref(&Poly::var("t"))))
            .unwrap_or_else(|_| Even::zero());
        c.equal(format!("n = {n}: S_(0..n)(t) = S_(n..0)(1 - t)"), &m, &rev);
    }
    // The motion crate's dual-number derivative agrees (256 bits, non-unit poses).
    let _g = PrecisionGuard::new(256);
    let Some((_, non_unit)) = c.ok("poses", sample_poses()) else { return };
    let Some(m) = c.ok("bezier", AdditiveBezier::new(non_unit.clone())) else { return };
    let three = MpFloat::from_i64(3);
    for (t, a, b) in [(0, 0, 1), (1, 2, 3)] {
        let Some((_, d)) = c.ok("derivative", pose_derivative(&m, &MpFloat::from_i64(t))) else { return };
        let f = (&non_unit[b] - &non_unit[a]).scale(&three);
        c.close(format!("dual numbers, n = 3, t = {t}"), &comps(&d), &comps(&f), 70);
    }
}

fn q_pose(v: [i64; 8]) -> Pose<Q> {
    let [a, b, d, e, f, g, h, i] = v.map(Q::from_i64);
    Even::new(a, b, d, e, f, g, h, i)
}

fn corollary_4_6_additive(c: &mut Checker) {
    // Exact: non-unit rational control poses, S and Ṡ from dual numbers over Q.
    let poses = [
        q_pose([2, 1, 0, -1, 3, 0, 1, 2]),
        q_pose([1, -2, 1, 0, 0, 1, -1, 1]),
        q_pose([3, 0, 2, 1, -2, 1, 0, 0]),
        q_pose([1, 1, 1, 1, 1, -1, 2, -3]),
    ];
    for n in 1..=3 {
        let ps = &poses[..=n];
        let Some(m) = c.ok("bezier", AdditiveBezier::new(ps.to_vec())) else { return };
        let lifted = m.map_ring(&|x: &Q| Jet::constant(x.clone()));
        let two_n = Q::from_i64(2 * n as i64);
        for (t, s, a, b) in [(0, 0, 0, 1), (1, n, n - 1, n)] {
            let sj = lifted.de_casteljau(&Jet::variable(Q::from_i64(t as i64)));
            let (sv, sd) = split_jet(&sj);
            let Some(psi) = c.ok("Ψ", indicatrix_from_derivative(&(sv), &sd)) else { return };
            let Some(inv) = c.ok("inverse", ps[s].inverse()) else { return };
            let formula = (&inv * &(&ps[b] - &ps[a])).scale(&two_n);
            c.equal(format!("n = {n}: Ψ({t}) = 2n S{s}⁻¹ (S{b} - S{a}) exactly"), &psi, &formula);
        }
    }
    // The motion crate's velocity_indicatrix at 256 bits agrees.
    let _g = PrecisionGuard::new(256);
    let Some((_, non_unit)) = c.ok("poses", sample_poses()) else { return };
    let Some(m) = c.ok("bezier", AdditiveBezier::new(non_unit.clone())) else { return };
    for (t, s, a, b) in [(0, 0, 0, 1), (1, 3, 2, 3)] {
        let Some(psi) = c.ok("Ψ", velocity_indicatrix(&m, &MpFloat::from_i64(t))) else { return };
        let Some(inv) = c.ok("inverse", non_unit[s].inverse()) else { return };
        let formula = (&inv * &(&non_unit[b] - &non_unit[a])).scale(&MpFloat::from_i64(6));
        c.close(format!("velocity_indicatrix, n = 3, t = {t}"), &comps(&psi), &comps(&formula), 70);
    }
}

fn corollary_4_6_multiplicative(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let Some((unit, non_unit)) = c.ok("poses", sample_poses()) else { return };
    for k in 1..=3 {
        let two_n = MpFloat::from_i64(2 * k as i64);
        for (poses, both) in [(&unit[..=k], true), (&non_unit[..=k], false)] {
            let Some(m) = c.ok("bezier", MultiplicativeBezier::new(poses.to_vec())) else { return };
            let Some(psi0) = c.ok("Ψ", velocity_indicatrix(&m, &MpFloat::zero())) else { return };
            let Some(l0) = c.ok("log", (&poses[0].reverse() * &poses[1]).log()) else { return };
            c.close(format!("n = {k}: Ψ(0) = 2n log(rev(S0) S1)"), &comps(&psi0), &comps(&l0.scale(&two_n)), 70);
            if both {
                let Some(psi1) = c.ok("Ψ", velocity_indicatrix(&m, &MpFloat::one())) else { return };
                let Some(l1) = c.ok("log", (&poses[k].reverse() * &poses[k - 1]).log()) else { return };
                c.close(
                    format!("n = {k}: Ψ(1) = -2n log(rev(Sn) Sn-1)"),
                    &comps(&psi1),
                    &comps(&l1.scale(&two_n.neg_ref())),
                    70,
                );
            }
        }
    }
    let poses = two_one();
    let Some(m) = c.ok("bezier", MultiplicativeBezier::new(poses.clone())) else { return };
    let Some(psi1) = c.ok("Ψ", velocity_indicatrix(&m, &MpFloat::one())) else { return };
    let Some(l1) = c.ok("log", (&poses[1].reverse() * &poses[0]).log()) else { return };
    let formula = l1.scale(&mp(-2, 1));
    c.counterexample(
        "Ψ(1) = -2n log(rev(Sn) Sn-1) for non-unit poses",
        agree(&psi1, &formula),
        format!(
            "S0 = 2, S1 = 1: Ψ(1) = {} (2 ln 2), formula {} (-2 ln 2)",
            psi1.scalar.to_f64(),
            formula.scalar.to_f64()
        ),
    );
}

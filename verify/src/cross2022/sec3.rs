//! Section 3: the velocity bivector and the velocity indicatrix.
//!
//! * `lemma-3.1`: `r ∧ ṙ` (the paper's `∧` is the commutator product) for the fully symbolic
//!   moving point `r = W e0 + X e1 + Y e2 + Z e3 + K einf + λσ` and its symbolic derivative
//!   (`Wd, Xd, ...`), computed in G_{0123inf} (product basis), against the expansion printed
//!   before the lemma, then the shape (10): `k + W² e0 v + μ e0inf + C` with `C` a bivector of
//!   G_{123inf}; the velocity `v_i = (W Ẋ - Ẇ X)/W²` is checked against the quotient rule over
//!   exact dual numbers.
//! * `theorem-3.2`: for a non-unit multiplicative and a non-unit additive Bezier motion
//!   (256-bit MPFR, dual numbers), `Ψ = γ + ν` with `γ` a pseudoscalar; `Ω` and `u` read off
//!   `ν = Ω e123 + u einf` (runtime multivectors) give, by eq. (14), the velocities of body
//!   points obtained independently by differentiating their trajectories `F_{S(t)}(p)`; the body
//!   point instantaneously at the origin moves with `u`.
//! * `corollary-3.3`: `ν = Ω e123 + v einf + (Ω ∧ r) ω` built from the current position `r` and
//!   velocity `v` (trajectory derivative) of body points, against `ν` from `Ψ`.
//! * `lemma-3.4`: unitary motions have `γ = 0`: exactly for a rational unitary motion (dual
//!   numbers over Q), and at 256 bits for a multiplicative Bezier motion with unit poses; an
//!   additive motion between unit poses (not unitary) has `γ ≠ 0`.

use crate::{Checker, Method, Paper, Statement};
use algebra_core::rational::{Q, ratio};
use algebra_core::{Algebra, Basis, Field, Jet, MpFloat, Multivector, Poly, PrecisionGuard, Real, Ring};
use motion::velocity::{bivector_from_point_velocity, split_indicatrix, velocity};
use motion::{AdditiveBezier, MapScalar, Motion, MultiplicativeBezier, Pose};
use motion::{Bivector, Even, Pseudoscalar};
use std::sync::Arc;

/// The statements of Section 3, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "cross2022/lemma-3.1",
        paper: Paper::Cross2022,
        label: "Lemma 3.1",
        statement: "for r = W e0 + X e1 + Y e2 + Z e3 + K einf + λσ (σ = e0·ω), r ∧ ṙ = (W K' - W' K) + \
                    Σ (W X_i' - W' X_i) e0i + (W K' - W' K) e0inf + (X_i X_j' - X_i' X_j) e_ij + (X_i K' - X_i' K) e_iinf, \
                    i.e. r ∧ ṙ = k + W² e0 v + μ e0inf + C (eq. 10) with k, μ scalars, v = d/dt (X/W, Y/W, Z/W) \
                    the point's velocity and C a bivector of G_{123inf}",
        method: Method::Symbolic,
        hypotheses: "∧ is the commutator product (xy - yx)/2; e0inf is the product e0 einf; k = μ = W K' - W' K",
        check: lemma_3_1,
    },
    Statement {
        id: "cross2022/theorem-3.2",
        paper: Paper::Cross2022,
        label: "Theorem 3.2",
        statement: "for a motion S(t), Ψ = 2 S⁻¹ Ṡ = γ + ν with γ a pseudoscalar and ν = Ω e123 + u einf; Ω is \
                    the angular velocity, u the velocity of the body point instantaneously at the origin, and the \
                    point at e0 + q moves with v_Q = u + (q ∧ Ω) e123 (eq. 14)",
        method: Method::MpFloatDual,
        hypotheses: "S(t) non-singular and differentiable; holds for non-unit motions",
        check: theorem_3_2,
    },
    Statement {
        id: "cross2022/corollary-3.3",
        paper: Paper::Cross2022,
        label: "Corollary 3.3",
        statement: "if the body point instantaneously at r has velocity v, then ν = Ω e123 + v einf + (Ω ∧ r) ω",
        method: Method::MpFloatDual,
        hypotheses: "",
        check: corollary_3_3,
    },
    Statement {
        id: "cross2022/lemma-3.4",
        paper: Paper::Cross2022,
        label: "Lemma 3.4",
        statement: "if rev(S(t)) S(t) = 1 for all t, then Ψ = 2 rev(S) Ṡ is a bivector: Ψ = ν (γ = 0)",
        method: Method::MpFloatDual,
        hypotheses: "",
        check: lemma_3_4,
    },
];

pub(super) fn cga_null() -> Arc<Algebra> {
    crate::algebra("cga-null")
}

pub(super) fn mp(n: i64, d: i64) -> MpFloat {
    MpFloat::from_ratio(n, d)
}

/// The eight coefficients of an even element, for [`Checker::close`].
pub(super) fn comps(m: &Even<MpFloat>) -> Vec<MpFloat> {
    (m.clone()).components().into_iter().cloned().collect()
}

/// A unit pose: rotation by `angle` about `axis` (normalised here), then translation.
pub(super) fn unit_pose(axis: [i64; 3], angle: (i64, i64), tr: [(i64, i64); 3]) -> Result<Pose<MpFloat>, String> {
    let axis = axis.map(MpFloat::from_i64);
    let n = Real::sqrt(&(axis.iter().map(|a| a.mul_ref(a)).fold(MpFloat::zero(), |s, x| s + x)));
    let axis = axis.map(|a| a.div_ref(&n));
    Pose::from_axis_angle_translation(&axis, &mp(angle.0, angle.1), &tr.map(|(a, b)| mp(a, b)))
        .map_err(|e| e.to_string())
}

/// `γ S` for the pseudoscalar `γ = a + bω`.
pub(super) fn times(s: &Pose<MpFloat>, a: (i64, i64), b: (i64, i64)) -> Pose<MpFloat> {
    s.scale_pseudoscalar(&Pseudoscalar::new(mp(a.0, a.1), mp(b.0, b.1)))
}

/// Unit control poses and pseudoscalar multiples of them.
pub(super) type Poses = (Vec<Pose<MpFloat>>, Vec<Pose<MpFloat>>);

/// Three unit control poses and non-unit versions of them (pseudoscalar multiples).
pub(super) fn sample_poses() -> Result<Poses, String> {
    let unit = vec![
        unit_pose([1, 2, 2], (3, 10), [(1, 2), (-1, 1), (1, 4)])?,
        unit_pose([0, -1, 3], (6, 5), [(2, 1), (1, 3), (-1, 2)])?,
        unit_pose([2, 1, -1], (-9, 10), [(-1, 1), (3, 2), (1, 1)])?,
        unit_pose([1, 0, 1], (2, 1), [(1, 5), (2, 1), (-3, 2)])?,
    ];
    let scales = [((2, 1), (1, 3)), ((1, 2), (-2, 1)), ((3, 1), (1, 1)), ((5, 4), (0, 1))];
    let non_unit = unit.iter().zip(scales).map(|(s, (a, b))| times(s, a, b)).collect();
    Ok((unit, non_unit))
}

fn lemma_3_1(c: &mut Checker) {
    let alg = cga_null();
    let v = |n: &str| Poly::var(n);
    let mv = |terms: Vec<(&str, Poly)>| Multivector::from_terms(&alg, Basis::Product, terms);
    let Some(sigma_printed) = c.ok("σ", mv(vec![("e123", Poly::from_i64(-1)), ("e0123inf", Poly::one())])) else {
        return;
    };
    let (Some(e0), Some(omega)) =
        (c.ok("e0", mv(vec![("e0", Poly::one())])), c.ok("ω", mv(vec![("e123inf", Poly::one())])))
    else {
        return;
    };
    c.equal_mv("σ = e0 · ω = -e123 + e0123inf (Lemma 2.2)", &e0.anticommutator(&omega), &sigma_printed);
    let point = |w: &str, x: &str, y: &str, z: &str, k: &str, l: &str| {
        mv(vec![("e0", v(w)), ("e1", v(x)), ("e2", v(y)), ("e3", v(z)), ("einf", v(k))])
            .map(|m| &m + &sigma_printed.scale(&v(l)))
    };
    let (Some(r), Some(rd)) =
        (c.ok("r", point("W", "X", "Y", "Z", "K", "l")), c.ok("ṙ", point("Wd", "Xd", "Yd", "Zd", "Kd", "ld")))
    else {
        return;
    };
    let wedge = r.commutator(&rd);
    // The printed expansion.
    let d = |a: &str, ad: &str, b: &str, bd: &str| v(a) * v(bd) - v(ad) * v(b);
    let printed = vec![
        ("1", d("W", "Wd", "K", "Kd")),
        ("e01", d("W", "Wd", "X", "Xd")),
        ("e02", d("W", "Wd", "Y", "Yd")),
        ("e03", d("W", "Wd", "Z", "Zd")),
        ("e0inf", d("W", "Wd", "K", "Kd")),
        ("e12", d("X", "Xd", "Y", "Yd")),
        ("e13", d("X", "Xd", "Z", "Zd")),
        ("e23", d("Y", "Yd", "Z", "Zd")),
        ("e1inf", d("X", "Xd", "K", "Kd")),
        ("e2inf", d("Y", "Yd", "K", "Kd")),
        ("e3inf", d("Z", "Zd", "K", "Kd")),
    ];
    let Some(printed) = c.ok("printed r ∧ ṙ", mv(printed)) else { return };
    c.equal_mv("r ∧ ṙ (commutator) = the printed expansion", &wedge, &printed);
    // Eq. (10): W² e0 v with W² v_i = W X_i' - W' X_i; k = μ = W K' - W' K.
    let k = d("W", "Wd", "K", "Kd");
    let Some(w2v) = c.ok(
        "W² v",
        mv(vec![("e1", d("W", "Wd", "X", "Xd")), ("e2", d("W", "Wd", "Y", "Yd")), ("e3", d("W", "Wd", "Z", "Zd"))]),
    ) else {
        return;
    };
    let Some(e0inf) = c.ok("e0inf", mv(vec![("e0inf", Poly::one())])) else { return };
    let head = &(&(&e0 * &w2v) + &e0inf.scale(&k)) + &Multivector::scalar(&alg, Basis::Product, k.clone());
    let rest = &wedge - &head;
    let allowed = ["e12", "e13", "e23", "e1inf", "e2inf", "e3inf"];
    let outside: Vec<String> = rest
        .terms()
        .filter(|(_, n, x)| !allowed.contains(n) && !x.is_exact_zero())
        .map(|(_, n, _)| n.to_string())
        .collect();
    c.check(
        format!("C = r ∧ ṙ - k - W² e0 v - μ e0inf is a bivector of G_123inf (terms outside: {outside:?})"),
        outside.is_empty(),
    );
    // v_i = d/dt (X_i / W): the quotient rule over exact dual numbers on rational samples.
    for (w, wd, x, xd) in [(3, -2, 5, 7), (-1, 4, 2, -3), (7, 1, -6, 11)] {
        let (w, wd, x, xd) = (Q::from_i64(w), Q::from_i64(wd), Q::from_i64(x), Q::from_i64(xd));
        let quotient = Jet::new(x.clone(), xd.clone()).div_ref(&Jet::new(w.clone(), wd.clone()));
        let w2 = w.mul_ref(&w);
        c.equal("W² d/dt(X/W) = W X' - W' X", &quotient.eps.mul_ref(&w2), &w.mul_ref(&xd).sub_ref(&wd.mul_ref(&x)));
    }
}

/// `(Ω, u)` from `ν = Ω e123 + u einf`, read with runtime multivectors of G_{123inf}:
/// `Ω = -(ν_rot e123)` (`e123² = -1`), `u_i` = the `e_i einf` coefficients.
fn omega_u(nu: &Bivector<MpFloat>) -> Option<([MpFloat; 3], [MpFloat; 3])> {
    let m = nu.to_multivector();
    let alg = m.algebra().clone();
    let get = |n: &str| m.coeff_by_name(n).ok().cloned();
    let rot = Multivector::from_terms(
        &alg,
        Basis::Product,
        [("e12", get("e12")?), ("e13", get("e13")?), ("e23", get("e23")?)],
    )
    .ok()?;
    let e123 = Multivector::basis_element(&alg, Basis::Product, "e123").ok()?;
    let om = -(&rot * &e123);
    let omega = [
        om.coeff_by_name("e1").ok()?.clone(),
        om.coeff_by_name("e2").ok()?.clone(),
        om.coeff_by_name("e3").ok()?.clone(),
    ];
    Some((omega, [get("e1inf")?, get("e2inf")?, get("e3inf")?]))
}

fn vector(alg: &Arc<Algebra>, x: &[MpFloat; 3]) -> Option<Multivector<MpFloat>> {
    Multivector::from_terms(alg, Basis::Product, [("e1", x[0].clone()), ("e2", x[1].clone()), ("e3", x[2].clone())])
        .ok()
}

/// Current position and velocity of the body point `p`, by differentiating its trajectory
/// `F_{S(t)}(p)` over dual numbers.
fn trajectory<M: MapScalar<MpFloat, Jet<MpFloat>>>(
    m: &M,
    t: &MpFloat,
    p: &[MpFloat; 3],
) -> Result<([MpFloat; 3], [MpFloat; 3]), String> {
    let lifted = m.map_scalar(&|x: &MpFloat| Jet::constant(x.clone()));
    let s = lifted.pose(&Jet::variable(t.clone())).map_err(|e| e.to_string())?;
    let q = s.transform_point(&p.clone().map(Jet::constant)).map_err(|e| e.to_string())?;
    Ok((q.clone().map(|x| x.re), q.map(|x| x.eps)))
}

fn body_points() -> Vec<[MpFloat; 3]> {
    vec![[mp(0, 1), mp(0, 1), mp(0, 1)], [mp(1, 1), mp(-2, 1), mp(3, 2)], [mp(-5, 3), mp(1, 7), mp(2, 1)]]
}

/// Runs `f` on a non-unit multiplicative and a non-unit additive Bezier motion at two times.
fn on_sample_motions(
    c: &mut Checker,
    mut f: impl FnMut(&mut Checker, &str, &dyn Fn(&[MpFloat; 3]) -> Result<Sample, String>),
) {
    let Some((_, poses)) = c.ok("poses", sample_poses()) else { return };
    let (Some(mul), Some(add)) = (
        c.ok("multiplicative", MultiplicativeBezier::new(poses[..3].to_vec())),
        c.ok("additive", AdditiveBezier::new(poses.clone())),
    ) else {
        return;
    };
    for t in [mp(3, 10), mp(4, 5)] {
        f(c, &format!("multiplicative, t = {}", t.to_f64()), &|p| sample(&mul, &t, p));
        f(c, &format!("additive, t = {}", t.to_f64()), &|p| sample(&add, &t, p));
    }
}

/// `(Ψ, ν, position, velocity)` of body point `p`, and the body point at the origin.
struct Sample {
    psi: Even<MpFloat>,
    nu: Bivector<MpFloat>,
    gamma: Pseudoscalar<MpFloat>,
    q: [MpFloat; 3],
    v: [MpFloat; 3],
    at_origin_velocity: [MpFloat; 3],
}

fn sample<M: MapScalar<MpFloat, Jet<MpFloat>>>(m: &M, t: &MpFloat, p: &[MpFloat; 3]) -> Result<Sample, String> {
    let vel = velocity(m, t).map_err(|e| e.to_string())?;
    let (gamma, nu) = split_indicatrix(&vel.indicatrix);
    let (q, v) = trajectory(m, t, p)?;
    let inv = vel.pose.inverse().map_err(|e| e.to_string())?;
    let origin_body = inv.transform_point(&[mp(0, 1), mp(0, 1), mp(0, 1)]).map_err(|e| e.to_string())?;
    let (_, at_origin_velocity) = trajectory(m, t, &origin_body)?;
    Ok(Sample { psi: vel.indicatrix, nu, gamma, q, v, at_origin_velocity })
}

fn theorem_3_2(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let alg = Even::<MpFloat>::zero().to_multivector().algebra().clone();
    on_sample_motions(c, |c, what, run| {
        for p in body_points() {
            let Some(s) = c.ok(what, run(&p)) else { return };
            let g = Even::new(
                s.gamma.scalar.clone(),
                mp(0, 1),
                mp(0, 1),
                mp(0, 1),
                mp(0, 1),
                mp(0, 1),
                mp(0, 1),
                s.gamma.e123inf.clone(),
            );
            c.close(format!("{what}: Ψ = γ + ν"), &comps(&s.psi), &comps(&(&g + &Even::from(&s.nu))), 70);
            let Some((omega, u)) = omega_u(&s.nu) else {
                c.fail(format!("{what}: reading Ω, u"));
                return;
            };
            let (Some(q), Some(om)) = (vector(&alg, &s.q), vector(&alg, &omega)) else { return };
            let Some(e123) = c.ok("e123", Multivector::basis_element(&alg, Basis::Product, "e123")) else { return };
            let w = &q.commutator(&om) * &e123;
            let eq14: Vec<MpFloat> = (0..3)
                .map(|i| {
                    u[i].add_ref(w.coeff_by_name(["e1", "e2", "e3"][i]).cloned().as_ref().unwrap_or(&MpFloat::zero()))
                })
                .collect();
            c.close(format!("{what}: v_Q = u + (q ∧ Ω) e123 (eq. 14) = d/dt F_S(p)"), &eq14, &s.v, 70);
            c.close(format!("{what}: u = velocity of the body point at the origin"), &u, &s.at_origin_velocity, 70);
        }
    });
}

fn corollary_3_3(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let alg = Even::<MpFloat>::zero().to_multivector().algebra().clone();
    on_sample_motions(c, |c, what, run| {
        for p in body_points() {
            let Some(s) = c.ok(what, run(&p)) else { return };
            let Some((omega, _)) = omega_u(&s.nu) else {
                c.fail(format!("{what}: reading Ω"));
                return;
            };
            let (Some(r), Some(om), Some(v)) = (vector(&alg, &s.q), vector(&alg, &omega), vector(&alg, &s.v)) else {
                return;
            };
            let el = |n: &str| Multivector::<MpFloat>::basis_element(&alg, Basis::Product, n);
            let (Some(e123), Some(einf), Some(w)) =
                (c.ok("e123", el("e123")), c.ok("einf", el("einf")), c.ok("ω", el("e123inf")))
            else {
                return;
            };
            let formula = &(&(&om * &e123) + &(&v * &einf)) + &(&om.commutator(&r) * &w);
            c.close_mv(format!("{what}: ν = Ω e123 + v einf + (Ω ∧ r) ω"), &formula, &s.nu.to_multivector(), 70);
            let motion_crate = bivector_from_point_velocity(&omega, &s.q, &s.v);
            c.close(
                format!("{what}: motion::bivector_from_point_velocity agrees"),
                &comps(&Even::from(&motion_crate)),
                &comps(&Even::from(&s.nu)),
                70,
            );
        }
    });
}

fn lemma_3_4(c: &mut Checker) {
    // Exact: S(t) = R(t) T(t), R = ((1 - t²) + 2t e12)/(1 + t²), T = 1 + ½ (t, t², 1) einf, unitary
    // for all t; Ψ = 2 S⁻¹ Ṡ over dual numbers of Q.
    for (n, d) in [(0, 1), (1, 3), (-5, 2)] {
        let t = Jet::variable(ratio(n, d));
        let one = Jet::constant(Q::one());
        let den = one.add_ref(&t.mul_ref(&t));
        let z = Jet::<Q>::zero;
        let rot = Even::new(
            one.sub_ref(&t.mul_ref(&t)).div_ref(&den),
            t.add_ref(&t).div_ref(&den),
            z(),
            z(),
            z(),
            z(),
            z(),
            z(),
        );
        let tr = Pose::translation(&[t.clone(), t.mul_ref(&t), one.clone()]);
        let s = &rot * &tr;
        let n2 = s.pseudo_norm_squared();
        let unit = n2.scalar.re == Q::one()
            && n2.scalar.eps.is_exact_zero()
            && n2.e123inf.re.is_exact_zero()
            && n2.e123inf.eps.is_exact_zero();
        c.check(format!("t = {n}/{d}: rev(S) S = 1 (and its derivative 0)"), unit);
        let (value, deriv) = motion::velocity::split_jet(&s);
        let Some(psi) = c.ok("Ψ", motion::velocity::indicatrix_from_derivative(&(value.clone()), &deriv)) else {
            return;
        };
        let (gamma, _) = split_indicatrix(&psi);
        c.equal(format!("t = {n}/{d}: γ = 0 exactly"), &gamma, &Pseudoscalar::new(Q::zero(), Q::zero()));
        let two_rev = (&value.reverse() * &deriv).scale(&Q::from_i64(2));
        c.equal(format!("t = {n}/{d}: Ψ = 2 rev(S) Ṡ"), &psi, &two_rev);
    }
    let _g = PrecisionGuard::new(256);
    let Some((unit, _)) = c.ok("poses", sample_poses()) else { return };
    let Some(mul) = c.ok("multiplicative", MultiplicativeBezier::new(unit.clone())) else { return };
    let zero = vec![mp(0, 1), mp(0, 1)];
    for t in [mp(0, 1), mp(1, 4), mp(7, 10), mp(1, 1)] {
        let Some(vel) = c.ok("velocity", velocity(&mul, &t)) else { return };
        let n2 = vel.pose.pseudo_norm_squared();
        c.close("unit multiplicative Bezier: rev(S) S = 1", &[n2.scalar, n2.e123inf], &[mp(1, 1), mp(0, 1)], 70);
        let g = vel.gamma();
        c.close(format!("unit multiplicative Bezier, t = {}: γ = 0", t.to_f64()), &[g.scalar, g.e123inf], &zero, 70);
    }
    // Without the hypothesis: the additive motion between the same unit poses is not unitary.
    let Some(add) = c.ok("additive", AdditiveBezier::new(unit[..2].to_vec())) else { return };
    if let Some(vel) = c.ok("velocity", velocity(&add, &mp(1, 4))) {
        let g = vel.gamma();
        let mut probe = Checker::new();
        let holds = probe.close("", &[g.scalar.clone(), g.e123inf.clone()], &zero, 70);
        c.counterexample(
            "Ψ is a bivector for a non-unitary motion",
            holds,
            format!(
                "additive (1 - t) S0 + t S1 of unit poses at t = 1/4: γ = {} + {} ω",
                g.scalar.to_f64(),
                g.e123inf.to_f64()
            ),
        );
    }
}

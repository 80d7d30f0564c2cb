//! Angelidis, "Hexanions: 6D space for twists", statement by statement.
//!
//! A hexanion `<ω, m>` has the matrix form `(ω, m) = [[ [ω]x, m ], [0, 0]]` of eq. (4). The
//! small helpers below (4x4 matrices over any ring, the hexanion matrix `hex`, the paper's
//! closed forms typed in) are an independent reference. Two other computations are compared
//! with them, at 256-bit MPFR (agreement to >= 70 digits):
//!
//! * the exponential **power series** (13) of the 4x4 matrix, summed until the terms are below
//!   `10^-90`;
//! * GAM's closed-form [`Pose::exp`] of the generator `½(ω e123 + m einf)` (the same element of
//!   se(3): rotation by |ω| about ω, translation m at first order), as a 4x4 matrix
//!   ([`Pose::to_matrix`]) and acting on points/directions ([`Pose::transform_point`],
//!   [`Pose::transform_direction`]).
//!
//! Per statement:
//!
//! * `angelidis/eq-14`: (66) and the three cases of (14) against the series and the library,
//!   on translations, rotations (ω·m = 0), general twists and angles beyond π; the derivation
//!   steps (62) exactly (`Poly`); the rotation case applied to a twist is a recorded
//!   counterexample (its hypothesis ω·m = 0 is needed).
//! * `angelidis/eq-29`: the rotation point transform against series and library; needs
//!   ω·m = 0 (counterexample recorded) and ω != 0.
//! * `angelidis/eq-30`, `angelidis/eq-36`: the vector transform, on rotations resp. general
//!   twists; needs ω != 0 (0/0 at ω = 0, recorded).
//! * `angelidis/eq-35`: the twist point transform, on twists and rotations; needs ω != 0.
//! * `angelidis/eq-37`, `-38`, `-39`: the cube, Rot via the cube, Rot² = M²: symbolic
//!   polynomial identities (denominators |ω|² cleared), including Rot + Trs = <ω, m> of (32)-(33).
//! * `angelidis/eq-60`: the trajectory (60) of the decoupled motion (58)-(59), symbolically
//!   against the poses of the main paper and at 256 bits against the series and the library;
//!   the printed form holds only at u = 1 (details in `decoupled.rs`).

mod decoupled;
mod library;

use crate::{Checker, Method, Paper, Statement};
use algebra_core::{Field, MpFloat, Poly, PrecisionGuard, Real, Ring};
use motion::{Even, Pose};
use std::fmt::Display;

/// The statements of this paper, in paper order.
pub const STATEMENTS: &[Statement] = &[
    Statement {
        id: "angelidis/eq-14",
        paper: Paper::Angelidis,
        label: "Eqs. (14), (66)",
        statement: "exp(ω, m) = I + (ω, m) + (1 - cos|ω|)/|ω|² (ω, m)² + (|ω| - sin|ω|)/|ω|³ (ω, m)³ (66), which \
                    reduces to I + (ω, m) if |ω| = 0 and to I + (1 - cos|ω|)/|ω|² (ω, m)² + sin|ω|/|ω| (ω, m) if \
                    ω·m = 0 (14); exp is the power series (13)",
        method: Method::MpFloat,
        hypotheses: "(66) needs ω != 0; the second case of (14) needs ω·m = 0 (counterexample recorded)",
        check: eq_14,
    },
    Statement {
        id: "angelidis/eq-22",
        paper: Paper::Angelidis,
        label: "Eq. (22)",
        statement: "the inverse of <ω, m> is <-ω, -m>: <-ω, -m> * (<ω, m> * p) = p",
        method: Method::MpFloat,
        hypotheses: "none (library Hexanion::inverse/transform_point against the series)",
        check: library::eq_22,
    },
    Statement {
        id: "angelidis/eq-27",
        paper: Paper::Angelidis,
        label: "Eq. (27)",
        statement: "a rotation hexanion <ω, c × ω> has centre c = ω × m/|ω|², angle θ = |ω|, axis n = ω/|ω|",
        method: Method::MpFloat,
        hypotheses: "ω != 0, ω·m = 0 (library Hexanion::classify against fixed points and the trace of the series)",
        check: library::eq_27,
    },
    Statement {
        id: "angelidis/eq-29",
        paper: Paper::Angelidis,
        label: "Eq. (29)",
        statement: "for a rotation (ω·m = 0): <ω, m> * p = p + (1 - cos|ω|)/|ω|² ω × ξ + sin|ω|/|ω| ξ, \
                    ξ = ω × p + m, where <ω, m> * p = exp(ω, m) p",
        method: Method::MpFloat,
        hypotheses: "ω·m = 0 is needed (counterexample recorded); ω != 0",
        check: eq_29,
    },
    Statement {
        id: "angelidis/eq-30",
        paper: Paper::Angelidis,
        label: "Eq. (30)",
        statement: "for a rotation: <ω, m> * v = v + (1 - cos|ω|)/|ω|² ω × (ω × v) + sin|ω|/|ω| ω × v",
        method: Method::MpFloat,
        hypotheses: "ω != 0 (0/0 at ω = 0; the limit is v); ω·m = 0 is not needed",
        check: eq_30,
    },
    Statement {
        id: "angelidis/eq-35",
        paper: Paper::Angelidis,
        label: "Eq. (35)",
        statement: "for a twist: <ω, m> * p = p + m + ω × (ω × (a p + (1 - b)/|ω|² m) + a m + b p), \
                    a = (1 - cos|ω|)/|ω|², b = sin|ω|/|ω|",
        method: Method::MpFloat,
        hypotheses: "ω != 0 (0/0 at ω = 0, recorded)",
        check: eq_35,
    },
    Statement {
        id: "angelidis/eq-36",
        paper: Paper::Angelidis,
        label: "Eq. (36)",
        statement: "for a twist: <ω, m> * v = v + (1 - cos|ω|)/|ω|² ω × (ω × v) + sin|ω|/|ω| ω × v (as (30))",
        method: Method::MpFloat,
        hypotheses: "ω != 0 (0/0 at ω = 0, recorded)",
        check: eq_36,
    },
    Statement {
        id: "angelidis/eq-37",
        paper: Paper::Angelidis,
        label: "Eq. (37)",
        statement: "(ω, m)³ = (-|ω|² ω, -ω × m × ω)",
        method: Method::Symbolic,
        hypotheses: "ω × m × ω is unambiguous: (ω × m) × ω = ω × (m × ω) = |ω|² m - (ω·m) ω",
        check: eq_37,
    },
    Statement {
        id: "angelidis/eq-38",
        paper: Paper::Angelidis,
        label: "Eq. (38)",
        statement: "Rot(ω, m) = -1/|ω|² (ω, m)³ with Rot<ω, m> = <ω, ω × m × ω/|ω|²> (33), and \
                    <ω, m> = Rot + Trs, Trs = <0, (m·ω)/|ω|² ω> (32)",
        method: Method::Symbolic,
        hypotheses: "ω != 0 (denominators cleared: |ω|² Rot = -(ω, m)³)",
        check: eq_38,
    },
    Statement {
        id: "angelidis/eq-39",
        paper: Paper::Angelidis,
        label: "Eq. (39)",
        statement: "Rot(ω, m)² = (ω, m)²",
        method: Method::Symbolic,
        hypotheses: "ω != 0 (denominators cleared: (|ω|² Rot)² = |ω|⁴ (ω, m)²)",
        check: eq_39,
    },
    Statement {
        id: "angelidis/eq-41",
        paper: Paper::Angelidis,
        label: "Eq. (41)",
        statement: "d/dh M^h at h = 0 is (ω, m), for M = exp(ω, m)",
        method: Method::MpFloat,
        hypotheses: "|ω| < π, M^h by the principal logarithm (counterexample recorded for |ω| > π)",
        check: library::eq_41,
    },
    Statement {
        id: "angelidis/sec-6",
        paper: Paper::Angelidis,
        label: "Sec. 6, eqs. (43)-(53)",
        statement: "the matrix -> hexanion conversion: n from (46)-(47), t = o·n (49), c from (50)-(51), θ from \
                    (52)-(53), <θ n, θ c × n + t n> (44)",
        method: Method::MpFloat,
        hypotheses: "θ is only defined mod 2π: the principal branch θ ∈ [0, π] recovers <ω, m> when |ω| < π",
        check: library::sec_6,
    },
    Statement {
        id: "angelidis/eq-60",
        paper: Paper::Angelidis,
        label: "Eqs. (58)-(60)",
        statement: "the decoupled motion (59) <uω, (<0, um> * c) × (uω)> * <0, um>, u ∈ [0, 1], moves a point p along \
                    C(p, u) = p + um + (1 - cos|uω|)/|uω|² ω × ξ + sin|uω|/|uω| ξ, ξ = ω × (p - c) (60)",
        method: Method::Symbolic,
        hypotheses: "(60) as printed holds only at u = 1 (the end pose (58)): the rotation by uω about c + um gives \
                     C(p, u) = p + um + (1 - cos|uω|)/|uω|² u² ω × ξ + sin|uω|/|uω| u ξ; the printed form does not start \
                     at p (it tends to p + ξ + ω × ξ/2 as u -> 0). ω != 0. The text's 'from a point c to another point \
                     p + m' is the centre's path from c to c + m",
        check: decoupled::eq_60,
    },
];

pub(crate) type M4<T> = [[T; 4]; 4];
pub(crate) type V3<T> = [T; 3];

pub(crate) fn dot<T: Ring>(a: &V3<T>, b: &V3<T>) -> T {
    a[0].mul_ref(&b[0]) + a[1].mul_ref(&b[1]) + a[2].mul_ref(&b[2])
}

fn cross<T: Ring>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    [
        a[1].mul_ref(&b[2]).sub_ref(&a[2].mul_ref(&b[1])),
        a[2].mul_ref(&b[0]).sub_ref(&a[0].mul_ref(&b[2])),
        a[0].mul_ref(&b[1]).sub_ref(&a[1].mul_ref(&b[0])),
    ]
}

fn vadd<T: Ring>(a: &V3<T>, b: &V3<T>) -> V3<T> {
    std::array::from_fn(|i| a[i].add_ref(&b[i]))
}

fn vscale<T: Ring>(s: &T, a: &V3<T>) -> V3<T> {
    a.clone().map(|x| s.mul_ref(&x))
}

/// The hexanion's matrix form (4): `[[0, -ωz, ωy, mx], [ωz, 0, -ωx, my], [-ωy, ωx, 0, mz], 0]`.
pub(crate) fn hex<T: Ring>(w: &V3<T>, m: &V3<T>) -> M4<T> {
    let z = T::zero;
    [
        [z(), w[2].neg_ref(), w[1].clone(), m[0].clone()],
        [w[2].clone(), z(), w[0].neg_ref(), m[1].clone()],
        [w[1].neg_ref(), w[0].clone(), z(), m[2].clone()],
        [z(), z(), z(), z()],
    ]
}

pub(crate) fn mmul<T: Ring>(a: &M4<T>, b: &M4<T>) -> M4<T> {
    std::array::from_fn(|i| std::array::from_fn(|j| (0..4).fold(T::zero(), |acc, k| acc + a[i][k].mul_ref(&b[k][j]))))
}

pub(crate) fn madd<T: Ring>(a: &M4<T>, b: &M4<T>) -> M4<T> {
    std::array::from_fn(|i| std::array::from_fn(|j| a[i][j].add_ref(&b[i][j])))
}

pub(crate) fn mscale<T: Ring>(s: &T, a: &M4<T>) -> M4<T> {
    a.clone().map(|r| r.map(|x| s.mul_ref(&x)))
}

pub(crate) fn ident<T: Ring>() -> M4<T> {
    std::array::from_fn(|i| std::array::from_fn(|j| if i == j { T::one() } else { T::zero() }))
}

pub(crate) fn flat<T: Clone>(a: &M4<T>) -> Vec<T> {
    a.iter().flatten().cloned().collect()
}

fn apply<T: Ring>(a: &M4<T>, x: &[T; 4]) -> [T; 4] {
    std::array::from_fn(|i| (0..4).fold(T::zero(), |acc, k| acc + a[i][k].mul_ref(&x[k])))
}

/// The power series (13), summed until every entry of a term is below 10^-90.
fn series<T: Real>(h: &M4<T>) -> M4<T> {
    let tol = (0..90).fold(T::one(), |acc, _| acc.mul_ref(&T::from_ratio(1, 10)));
    let mut sum = ident::<T>();
    let mut term = ident::<T>();
    for k in 1..400i64 {
        term = mscale(&T::from_ratio(1, k), &mmul(&term, h));
        sum = madd(&sum, &term);
        if term.iter().flatten().all(|x| x.abs() < tol) {
            break;
        }
    }
    sum
}

/// The trigonometric coefficients `(|ω|, a, b)`: `a = (1 - cos|ω|)/|ω|²`, `b = sin|ω|/|ω|`.
fn coeffs<T: Real>(w: &V3<T>) -> (T, T, T) {
    let th2 = dot(w, w);
    let th = Real::sqrt(&th2);
    let a = T::one().sub_ref(&Real::cos(&th)).div_ref(&th2);
    let b = Real::sin(&th).div_ref(&th);
    (th, a, b)
}

/// (66): `I + M + a M² + (|ω| - sin|ω|)/|ω|³ M³`.
fn closed66<T: Real>(w: &V3<T>, m: &V3<T>) -> M4<T> {
    let h = hex(w, m);
    let h2 = mmul(&h, &h);
    let h3 = mmul(&h2, &h);
    let (th, a, _) = coeffs(w);
    let c3 = th.sub_ref(&Real::sin(&th)).div_ref(&th.mul_ref(&th).mul_ref(&th));
    madd(&madd(&ident(), &h), &madd(&mscale(&a, &h2), &mscale(&c3, &h3)))
}

/// The rotation case of (14) (and (28)): `I + a M² + b M`.
fn closed_rotation<T: Real>(w: &V3<T>, m: &V3<T>) -> M4<T> {
    let h = hex(w, m);
    let (_, a, b) = coeffs(w);
    madd(&ident(), &madd(&mscale(&a, &mmul(&h, &h)), &mscale(&b, &h)))
}

/// (14), its cases tried in the printed order (exact zero tests).
fn closed14<T: Real>(w: &V3<T>, m: &V3<T>) -> M4<T> {
    if dot(w, w).is_exact_zero() {
        madd(&ident(), &hex(w, m))
    } else if dot(w, m).is_exact_zero() {
        closed_rotation(w, m)
    } else {
        closed66(w, m)
    }
}

/// GAM's pose `exp(½(ω e123 + m einf))` (motion::exp_log convention `a e123 = a1 e23 - a2 e13 +
/// a3 e12`, translation `exp(½ v einf)` by `v`).
fn library_pose<T: Real>(w: &V3<T>, m: &V3<T>) -> Result<Pose<T>, motion::MotionError> {
    let h = T::from_ratio(1, 2);
    let [w1, w2, w3] = vscale(&h, w);
    let [m1, m2, m3] = vscale(&h, m);
    Pose::exp(&Even::new(T::zero(), w3, w2.neg_ref(), w1, m1, m2, m3, T::zero()))
}

/// Sample hexanions, all dyadic (exact in binary, so ω·m = 0 is exact for the rotations).
/// `(name, ω, m)`.
fn samples() -> Vec<(&'static str, V3<MpFloat>, V3<MpFloat>)> {
    let f = |n: i64, d: i64| MpFloat::from_ratio(n, d);
    let rot = |w: V3<MpFloat>, c: V3<MpFloat>| (cross(&c, &w), w);
    let (m_r1, w_r1) = rot([f(3, 8), f(-5, 8), f(9, 8)], [f(1, 1), f(2, 1), f(-1, 1)]);
    let (m_r2, w_r2) = rot([f(0, 1), f(3, 1), f(4, 1)], [f(1, 2), f(-1, 4), f(3, 1)]);
    vec![
        ("translation", [f(0, 1), f(0, 1), f(0, 1)], [f(1, 1), f(-2, 1), f(3, 2)]),
        ("rotation |ω| < π", w_r1, m_r1),
        ("rotation |ω| = 5 > π", w_r2, m_r2),
        ("pure rotation about the origin", [f(1, 4), f(1, 2), f(-1, 8)], [f(0, 1), f(0, 1), f(0, 1)]),
        ("twist", [f(3, 8), f(-5, 8), f(9, 8)], [f(1, 2), f(1, 4), f(-3, 8)]),
        ("twist |ω| = 3", [f(2, 1), f(-1, 1), f(2, 1)], [f(1, 1), f(1, 1), f(1, 1)]),
        ("twist |ω| = 5", [f(0, 1), f(3, 1), f(4, 1)], [f(1, 1), f(-2, 1), f(1, 2)]),
        ("small twist", [f(1, 64), f(-1, 32), f(1, 128)], [f(1, 1), f(1, 2), f(1, 4)]),
    ]
}

fn is_rotation(w: &V3<MpFloat>, m: &V3<MpFloat>) -> bool {
    !dot(w, w).is_exact_zero() && dot(w, m).is_exact_zero()
}

fn is_twist(w: &V3<MpFloat>) -> bool {
    !dot(w, w).is_exact_zero()
}

/// Whether two lists agree to 70 digits (a scratch checker, for counterexamples).
fn agrees<T: Real + Display>(a: &[T], b: &[T]) -> bool {
    let mut tmp = Checker::new();
    tmp.close("", a, b, 70);
    tmp.finish().holds()
}

const DIGITS: u32 = 70;

fn eq_14(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    for (name, w, m) in samples() {
        let s = series(&hex(&w, &m));
        c.close(format!("{name}: (14) = power series (13)"), &flat(&closed14(&w, &m)), &flat(&s), DIGITS);
        if is_twist(&w) {
            c.close(format!("{name}: (66) = power series (13)"), &flat(&closed66(&w, &m)), &flat(&s), DIGITS);
        }
        if let Some(p) = c.ok(format!("{name}: Pose::exp"), library_pose(&w, &m))
            && let Some(lib) = c.ok(format!("{name}: Pose::to_matrix"), p.to_matrix())
        {
            c.close(
                format!("{name}: (14) = Pose::exp(½(ω e123 + m einf)) as a matrix"),
                &flat(&closed14(&w, &m)),
                &flat(&lib),
                DIGITS,
            );
        }
    }
    c.note(
        "OCR: the Notation paragraph is garbled (it says · and × denote the dot product, + and * the cross \
         products); read · = dot, × = cross, * = the hexanion action (16), (18), as the formulas require",
    );
    // The rotation case applied to a twist.
    let (name, w, m) = samples().swap_remove(4);
    let s = series(&hex(&w, &m));
    c.counterexample(
        "the rotation case of (14) without ω·m = 0",
        agrees(&flat(&closed_rotation(&w, &m)), &flat(&s)),
        format!(
            "{name} ω = (3/8, -5/8, 9/8), m = (1/2, 1/4, -3/8), ω·m = {}: I + aM² + bM != exp M",
            dot(&w, &m).to_f64()
        ),
    );
    // (62), exactly: M^(2k+1) = (-|ω|²)^k Rot M (cleared: |ω|² Rot = -M³), M^(2k) = (-|ω|²)^(k-1) M².
    let (w, m) = sym();
    let h = hex(&w, &m);
    let n2 = dot(&w, &w);
    let neg = n2.neg_ref();
    let h2 = mmul(&h, &h);
    let h3 = mmul(&h2, &h);
    let mut pow = h3.clone();
    for k in 1..=3u32 {
        // pow = M^(2k+1)
        c.equal(
            format!("(62): M^{} = (-|ω|²)^{} Rot M, cleared: -|ω|² M^{} = (-|ω|²)^{} M³", 2 * k + 1, k, 2 * k + 1, k),
            &mscale(&neg, &pow),
            &mscale(&neg.pow_u32(k), &h3),
        );
        let even = mmul(&pow, &h);
        c.equal(format!("(62): M^{} = (-|ω|²)^{} M²", 2 * k + 2, k), &even, &mscale(&neg.pow_u32(k), &h2));
        pow = mmul(&even, &h);
    }
    c.equal(
        "translation: M² = 0, so exp M = I + M",
        &mmul(&hex(&zero3(), &m), &hex(&zero3(), &m)),
        &mscale(&Poly::zero(), &h2),
    );
}

fn zero3() -> V3<Poly> {
    [Poly::zero(), Poly::zero(), Poly::zero()]
}

fn sym() -> (V3<Poly>, V3<Poly>) {
    (["wx", "wy", "wz"].map(Poly::var), ["mx", "my", "mz"].map(Poly::var))
}

fn point4(p: &V3<MpFloat>) -> [MpFloat; 4] {
    [p[0].clone(), p[1].clone(), p[2].clone(), MpFloat::one()]
}

fn dir4(v: &V3<MpFloat>) -> [MpFloat; 4] {
    [v[0].clone(), v[1].clone(), v[2].clone(), MpFloat::zero()]
}

fn test_point() -> V3<MpFloat> {
    [MpFloat::from_ratio(7, 4), MpFloat::from_ratio(-1, 2), MpFloat::from_ratio(5, 8)]
}

/// (29): `p + a ω × ξ + b ξ`, `ξ = ω × p + m`.
fn eq29_formula(w: &V3<MpFloat>, m: &V3<MpFloat>, p: &V3<MpFloat>) -> V3<MpFloat> {
    let (_, a, b) = coeffs(w);
    let xi = vadd(&cross(w, p), m);
    vadd(p, &vadd(&vscale(&a, &cross(w, &xi)), &vscale(&b, &xi)))
}

/// (30) = (36): `v + a ω × (ω × v) + b ω × v`.
fn eq30_formula(w: &V3<MpFloat>, v: &V3<MpFloat>) -> V3<MpFloat> {
    let (_, a, b) = coeffs(w);
    let wv = cross(w, v);
    vadd(v, &vadd(&vscale(&a, &cross(w, &wv)), &vscale(&b, &wv)))
}

/// (35): `p + m + ω × (ω × (a p + (1 - b)/|ω|² m) + a m + b p)`.
fn eq35_formula(w: &V3<MpFloat>, m: &V3<MpFloat>, p: &V3<MpFloat>) -> V3<MpFloat> {
    let (th, a, b) = coeffs(w);
    let k = MpFloat::one().sub_ref(&b).div_ref(&th.mul_ref(&th));
    let inner = cross(w, &vadd(&vscale(&a, p), &vscale(&k, m)));
    let outer = cross(w, &vadd(&inner, &vadd(&vscale(&a, m), &vscale(&b, p))));
    vadd(p, &vadd(m, &outer))
}

/// Compares a point formula with `exp(ω, m) p` (series) and with `Pose::transform_point`.
fn point_against_references(
    c: &mut Checker,
    label: &str,
    name: &str,
    w: &V3<MpFloat>,
    m: &V3<MpFloat>,
    ours: &V3<MpFloat>,
) {
    let p = test_point();
    let img = apply(&series(&hex(w, m)), &point4(&p));
    c.close(format!("{name}: {label} = exp(ω, m) p by the power series"), ours, &img[..3], DIGITS);
    c.check(format!("{name}: the series image is a point (w = 1)"), agrees(&img[3..], &[MpFloat::one()]));
    if let Some(pose) = c.ok(format!("{name}: Pose::exp"), library_pose(w, m))
        && let Some(lib) = c.ok(format!("{name}: Pose::transform_point"), pose.transform_point(&p))
    {
        c.close(format!("{name}: {label} = Pose::transform_point"), ours, &lib, DIGITS);
    }
}

fn direction_against_references(c: &mut Checker, label: &str, name: &str, w: &V3<MpFloat>, m: &V3<MpFloat>) {
    let v = test_point();
    let ours = eq30_formula(w, &v);
    let img = apply(&series(&hex(w, m)), &dir4(&v));
    c.close(format!("{name}: {label} = exp(ω, m) v by the power series"), &ours, &img[..3], DIGITS);
    if let Some(pose) = c.ok(format!("{name}: Pose::exp"), library_pose(w, m))
        && let Some(lib) = c.ok(format!("{name}: Pose::transform_direction"), pose.transform_direction(&v))
    {
        c.close(format!("{name}: {label} = Pose::transform_direction"), &ours, &lib, DIGITS);
    }
}

/// The counterexample at ω = 0: the closed form is 0/0 there.
fn zero_omega_counterexample(c: &mut Checker, label: &str, f: impl Fn(&V3<MpFloat>, &V3<MpFloat>) -> V3<MpFloat>) {
    let (name, w, m) = samples().swap_remove(0);
    let ours = f(&w, &m);
    let exact = apply(&series(&hex(&w, &m)), &point4(&test_point()));
    c.counterexample(
        format!("{label} at ω = 0 ({name})"),
        ours.iter().all(Real::is_finite) && agrees(&ours, &exact[..3]),
        "ω = 0: (1 - cos|ω|)/|ω|² and sin|ω|/|ω| are 0/0 (NaN); only their limits 1/2, 1 give the translation",
    );
}

fn eq_29(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let p = test_point();
    for (name, w, m) in samples().into_iter().filter(|(_, w, m)| is_rotation(w, m)) {
        let ours = eq29_formula(&w, &m, &p);
        point_against_references(c, "(29)", name, &w, &m, &ours);
    }
    let (name, w, m) = samples().swap_remove(4);
    let img = apply(&series(&hex(&w, &m)), &point4(&p));
    c.counterexample(
        "(29) without ω·m = 0",
        agrees(&eq29_formula(&w, &m, &p), &img[..3]),
        format!("{name} ω = (3/8, -5/8, 9/8), m = (1/2, 1/4, -3/8), p = (7/4, -1/2, 5/8): (29) != exp(ω, m) p"),
    );
    zero_omega_counterexample(c, "(29)", |w, m| eq29_formula(w, m, &test_point()));
}

fn eq_30(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    for (name, w, m) in samples().into_iter().filter(|(_, w, m)| is_rotation(w, m)) {
        direction_against_references(c, "(30)", name, &w, &m);
    }
    c.note("(30) also holds for twists (ω·m != 0): see eq-36");
    let (name, w, m) = samples().swap_remove(0);
    let ours = eq30_formula(&w, &test_point());
    let exact = apply(&series(&hex(&w, &m)), &dir4(&test_point()));
    c.counterexample(
        format!("(30) at ω = 0 ({name})"),
        ours.iter().all(Real::is_finite) && agrees(&ours, &exact[..3]),
        "ω = 0: 0/0 (NaN); the limit is v",
    );
}

fn eq_35(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    let p = test_point();
    for (name, w, m) in samples().into_iter().filter(|(_, w, _)| is_twist(w)) {
        let ours = eq35_formula(&w, &m, &p);
        point_against_references(c, "(35)", name, &w, &m, &ours);
    }
    zero_omega_counterexample(c, "(35)", |w, m| eq35_formula(w, m, &test_point()));
}

fn eq_36(c: &mut Checker) {
    let _g = PrecisionGuard::new(256);
    for (name, w, m) in samples().into_iter().filter(|(_, w, m)| is_twist(w) && !is_rotation(w, m)) {
        direction_against_references(c, "(36)", name, &w, &m);
    }
    let (name, w, m) = samples().swap_remove(0);
    let ours = eq30_formula(&w, &test_point());
    let exact = apply(&series(&hex(&w, &m)), &dir4(&test_point()));
    c.counterexample(
        format!("(36) at ω = 0 ({name})"),
        ours.iter().all(Real::is_finite) && agrees(&ours, &exact[..3]),
        "ω = 0: 0/0 (NaN); the limit is v",
    );
}

/// `|ω|² Rot<ω, m> = <|ω|² ω, (ω × m) × ω>` (33), as a matrix.
fn rot_cleared(w: &V3<Poly>, m: &V3<Poly>) -> M4<Poly> {
    hex(&vscale(&dot(w, w), w), &cross(&cross(w, m), w))
}

fn eq_37(c: &mut Checker) {
    let (w, m) = sym();
    let h = hex(&w, &m);
    let h3 = mmul(&mmul(&h, &h), &h);
    let n2 = dot(&w, &w);
    let minus = Poly::from_i64(-1);
    let left = vscale(&minus, &cross(&cross(&w, &m), &w));
    let right = vscale(&minus, &cross(&w, &cross(&m, &w)));
    c.equal("(37): (ω, m)³ = (-|ω|² ω, -(ω × m) × ω)", &h3, &hex(&vscale(&n2.neg_ref(), &w), &left));
    c.equal("(37): (ω, m)³ = (-|ω|² ω, -ω × (m × ω))", &h3, &hex(&vscale(&n2.neg_ref(), &w), &right));
    c.note("ω × m × ω is the same vector in either grouping, |ω|² m - (ω·m) ω");
    c.equal(
        "(37): the cube is a rotation hexanion: (-|ω|² ω)·(-ω × m × ω) = 0",
        &dot(&vscale(&n2.neg_ref(), &w), &left),
        &Poly::zero(),
    );
}

fn eq_38(c: &mut Checker) {
    let (w, m) = sym();
    let h = hex(&w, &m);
    let h3 = mmul(&mmul(&h, &h), &h);
    let n2 = dot(&w, &w);
    c.equal("(38): |ω|² Rot(ω, m) = -(ω, m)³", &rot_cleared(&w, &m), &mscale(&Poly::from_i64(-1), &h3));
    // (32)-(33): |ω|² (Rot + Trs) = |ω|² <ω, m>.
    let rot_m = cross(&cross(&w, &m), &w);
    let trs_m = vscale(&dot(&m, &w), &w);
    c.equal("(32)-(33): |ω|² (Rot + Trs) = |ω|² <ω, m>", &vadd(&rot_m, &trs_m), &vscale(&n2, &m));
    c.equal("(33): Rot is a rotation hexanion: ω·(ω × m × ω) = 0", &dot(&w, &rot_m), &Poly::zero());
}

fn eq_39(c: &mut Checker) {
    let (w, m) = sym();
    let h = hex(&w, &m);
    let n2 = dot(&w, &w);
    let r = rot_cleared(&w, &m);
    c.equal("(39): (|ω|² Rot)² = |ω|⁴ (ω, m)²", &mmul(&r, &r), &mscale(&n2.mul_ref(&n2), &mmul(&h, &h)));
    c.note(format!(
        "the squares agree although Rot and (ω, m) differ by Trs; (ω, m)² is not a hexanion matrix: its 3x3 block is symmetric, e.g. [0][0] = {}",
        mmul(&h, &h)[0][0]
    ));
}

//! Velocity (Sec. 3) and end derivatives (Sec. 4) of Cross, Cripps and Mullineux (2022), with
//! every derivative from dual numbers: Theorem 4.5 and Corollary 4.6 for degrees 1..5 (exactly
//! over the rationals for additive motions, at 256 bits for multiplicative ones), the
//! unit-pose hypothesis of Theorem 4.5(ii) at `t = 1`, the Sec. 4 quadrant example, Theorem 3.2
//! and eq. (14) against dual numbers and finite differences, Corollary 3.3, Lemma 3.4,
//! second derivatives against num-dual's `Dual2_64`, and B-spline continuity at a knot.

use crate::common;

use algebra_core::rational::{Q, q, ratio};
use algebra_core::{Jet, MpFloat, PrecisionGuard, Ring};
use common::*;
use motion::velocity::{
    Twist, acceleration, bivector_from_point_velocity, body_point_kinematics, indicatrix_from_derivative,
    pose_derivative, pose_second_derivative, split_indicatrix, split_jet, velocity, velocity_indicatrix_derivative,
};
use motion::{
    AdditiveBSpline, AdditiveBezier, AnyMotion, Even, MapScalar, Motion, MultiplicativeBSpline, MultiplicativeBezier,
    Piecewise, Pose, Pseudoscalar, velocity_bivector, velocity_indicatrix,
};
use num_dual::{Dual2_64, Dual64};

fn pseudo_motor(g: &Pseudoscalar<f64>) -> Even<f64> {
    Even::new(g.scalar, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, g.e123inf)
}

/// `|a - b|` relative to `max(1, |b|)`.
fn rel(a: &Even<f64>, b: &Even<f64>) -> f64 {
    diff(a, b) / size(b).max(1.0)
}

fn log_of(a: &Pose<f64>, b: &Pose<f64>) -> Even<f64> {
    (a.reverse() * b).log().unwrap()
}

// ---------------------------------------------------------------------------------------------
// Theorem 4.5 and Corollary 4.6

/// Theorem 4.5(i) and Corollary 4.6(i) exactly: the additive motion over `Jet<Q>` (dual numbers
/// over the rationals) gives `dS/dt(0) = n(S_1 - S_0)`, `dS/dt(1) = n(S_n - S_{n-1})`, and the
/// end indicatrices `2n S_0⁻¹(S_1 - S_0)`, `2n S_n⁻¹(S_n - S_{n-1})` (eq. 20), degrees 1..5,
/// with non-unit control poses.
#[test]
fn theorem_4_5_i_and_corollary_4_6_i_exact() {
    for n in 1..=5usize {
        let poses: Vec<Pose<Q>> = (0..=n as i64)
            .map(|i| Even::new(q(2 + i), q(1 - i), q(i * i), q(3), q(i), q(-2 * i), q(1), q(i - 1)))
            .collect();
        let m = AdditiveBezier::new(poses.clone()).unwrap();
        let lifted = m.map_ring(&|x: &Q| Jet::constant(x.clone()));
        let (nq, two_n) = (q(n as i64), q(2 * n as i64));
        // t = 0
        let (s, ds) = split_jet(&lifted.de_casteljau(&Jet::variable(q(0))));
        assert_eq!((s.clone()), poses[0]);
        assert_eq!(ds, (&poses[1] - &poses[0]).scale(&nq), "dS/dt(0), degree {n}");
        let eq20 = (&poses[0].try_inverse().unwrap() * &(&poses[1] - &poses[0])).scale(&two_n);
        assert_eq!(indicatrix_from_derivative(&(s), &ds).unwrap(), eq20, "Ψ(0), degree {n}");
        // t = 1
        let (s, ds) = split_jet(&lifted.de_casteljau(&Jet::variable(q(1))));
        assert_eq!((s.clone()), poses[n]);
        assert_eq!(ds, (&poses[n] - &poses[n - 1]).scale(&nq), "dS/dt(1), degree {n}");
        let eq20 = (&poses[n].try_inverse().unwrap() * &(&poses[n] - &poses[n - 1])).scale(&two_n);
        assert_eq!(indicatrix_from_derivative(&(s), &ds).unwrap(), eq20, "Ψ(1), degree {n}");
        // The Bernstein sum over dual numbers gives the same derivatives.
        for t in [q(0), ratio(1, 3), q(1)] {
            let (_, ds_b) = split_jet(&lifted.bernstein(&Jet::variable(t.clone())));
            let (_, ds_c) = split_jet(&lifted.de_casteljau(&Jet::variable(t)));
            assert_eq!(ds_b, ds_c);
        }
    }
}

/// Theorem 4.5(i) over f64 through the generic [`Motion`] path (dual numbers of `Jet<f64>` and
/// num-dual's `Dual64` agree).
#[test]
fn theorem_4_5_i_f64_and_dual64() {
    for n in 1..=5 {
        let poses = non_unit(&unit_poses(n));
        let m = AdditiveBezier::new(poses.clone()).unwrap();
        let nf = n as f64;
        let (_, d0) = pose_derivative(&m, &0.0).unwrap();
        let (_, d1) = pose_derivative(&m, &1.0).unwrap();
        assert!(rel(&d0, &(poses[1] - poses[0]).scale(&nf)) < 1e-14);
        assert!(rel(&d1, &(poses[n] - poses[n - 1]).scale(&nf)) < 1e-14);
        let dual = m.map_scalar(&|x: &f64| Dual64::from(*x)).pose(&Dual64::new(1.0, 1.0)).unwrap();
        let eps = Even::new(
            dual.scalar.eps,
            dual.e12.eps,
            dual.e13.eps,
            dual.e23.eps,
            dual.e1inf.eps,
            dual.e2inf.eps,
            dual.e3inf.eps,
            dual.e123inf.eps,
        );
        assert!(rel(&eps, &d1) < 1e-15);
    }
}

/// Theorem 4.5(ii) and Corollary 4.6(ii) with unit control poses, degrees 1..5:
/// `dS/dt(0) = n S_0 log(rev(S_0) S_1)`, `dS/dt(1) = -n S_n log(rev(S_n) S_{n-1})`,
/// `Ψ(0) = 2n log(rev(S_0) S_1)`, `Ψ(1) = -2n log(rev(S_n) S_{n-1})` (eq. 21).
#[test]
fn theorem_4_5_ii_and_corollary_4_6_ii_unit_poses() {
    for n in 1..=5 {
        let p = unit_poses(n);
        let m = MultiplicativeBezier::new(p.clone()).unwrap();
        let nf = n as f64;
        let (s0, d0) = pose_derivative(&m, &0.0).unwrap();
        let (s1, d1) = pose_derivative(&m, &1.0).unwrap();
        assert!(diff(&s0, &p[0]) < 1e-15 && diff(&s1, &p[n]) < 1e-12);
        let l0 = log_of(&p[0], &p[1]);
        let l1 = log_of(&p[n], &p[n - 1]);
        assert!(rel(&d0, &(p[0] * l0).scale(&nf)) < 1e-13, "dS/dt(0), degree {n}");
        assert!(rel(&d1, &(p[n] * l1).scale(&-nf)) < 1e-12, "dS/dt(1), degree {n}");
        let psi0 = velocity_indicatrix(&m, &0.0).unwrap();
        let psi1 = velocity_indicatrix(&m, &1.0).unwrap();
        assert!(rel(&psi0, &l0.scale(&(2.0 * nf))) < 1e-13, "Ψ(0), degree {n}");
        assert!(rel(&psi1, &l1.scale(&(-2.0 * nf))) < 1e-12, "Ψ(1), degree {n}");
    }
}

/// Theorem 4.5(ii) needs unit control poses at `t = 1` (the paper's proof reverses the tableau,
/// which needs `rev(S) = S⁻¹`). With non-unit control poses:
/// * at `t = 0` both formulas still hold (Lemmas 4.3-4.4 need only non-singular poses);
/// * at `t = 1` `dS/dt(1) = -n S_n log(rev(S_n) S_{n-1})` fails, and so does
///   `Ψ(1) = -2n log(rev(S_n) S_{n-1})` — but only in its pseudoscalar part: the bivector part
///   `ν(1)` is right, because the motion is a pseudoscalar multiple of the unitized one
///   (Lemma 4.1) and a pseudoscalar factor changes only `γ`;
/// * unitizing the control poses restores both formulas exactly.
#[test]
fn theorem_4_5_ii_at_t1_needs_unit_poses() {
    for n in 1..=5 {
        let raw = MultiplicativeBezier::new(non_unit(&unit_poses(n))).unwrap();
        let p = raw.poses().to_vec();
        let nf = n as f64;
        // t = 0 holds for non-unit poses.
        let (_, d0) = pose_derivative(&raw, &0.0).unwrap();
        let l0 = log_of(&p[0], &p[1]);
        assert!(rel(&d0, &(p[0] * l0).scale(&nf)) < 1e-13, "dS/dt(0), degree {n}");
        assert!(rel(&velocity_indicatrix(&raw, &0.0).unwrap(), &l0.scale(&(2.0 * nf))) < 1e-13);
        // t = 1: the counterexample.
        let (_, d1) = pose_derivative(&raw, &1.0).unwrap();
        let l1 = log_of(&p[n], &p[n - 1]);
        let formula = (p[n] * l1).scale(&-nf);
        assert!(rel(&d1, &formula) > 1e-2, "dS/dt(1) formula unexpectedly holds, degree {n}");
        let psi1 = velocity_indicatrix(&raw, &1.0).unwrap();
        let psi_formula = l1.scale(&(-2.0 * nf));
        let (g_true, nu_true) = split_indicatrix(&psi1);
        let (g_formula, nu_formula) = split_indicatrix(&psi_formula);
        assert!(rel(&pseudo_motor(&g_true), &pseudo_motor(&g_formula)) > 1e-2, "γ(1), degree {n}");
        assert!(rel(&Even::from(&nu_true), &Even::from(&nu_formula)) < 1e-12, "ν(1), degree {n}");
        // Unitized control poses: both formulas hold.
        let unit = raw.unitized().unwrap();
        let u = unit.poses().to_vec();
        let (_, d1u) = pose_derivative(&unit, &1.0).unwrap();
        let l1u = log_of(&u[n], &u[n - 1]);
        assert!(rel(&d1u, &(u[n] * l1u).scale(&-nf)) < 1e-12, "unitized dS/dt(1), degree {n}");
        assert!(rel(&velocity_indicatrix(&unit, &1.0).unwrap(), &l1u.scale(&(-2.0 * nf))) < 1e-12);
    }
}

/// The smallest counterexample, spelled out: degree 1, `S_0 = 2`, `S_1 = 1`. Then
/// `S(t) = 2 (rev(2) · 1)^t = 2^{1+t}`, `S(1) = 4`, `dS/dt(1) = 4 ln 2`, while the formula gives
/// `-S_1 log(rev(S_1) S_0) = -ln 2`.
#[test]
fn theorem_4_5_ii_counterexample_degree_1() {
    let m = MultiplicativeBezier::new(vec![Pose::<f64>::identity().scale(&2.0), Pose::identity()]).unwrap();
    let (s1, d1) = pose_derivative(&m, &1.0).unwrap();
    let ln2 = 2f64.ln();
    assert!((s1.scalar - 4.0).abs() < 1e-14); // S(1) = |S_0|² S_1 = 4, not S_1 = 1
    assert!((d1.scalar - 4.0 * ln2).abs() < 1e-14);
    let formula = -(Pose::<f64>::identity() * log_of(&Pose::identity(), &Pose::identity().scale(&2.0))).scalar;
    assert!((formula + ln2).abs() < 1e-15);
}

/// Theorem 4.5(ii) at 256 bits (`Jet<MpFloat>`): the formulas hold to 1e-70 for unit poses.
#[test]
fn theorem_4_5_ii_at_256_bits() {
    let _g = PrecisionGuard::new(256);
    let p: Vec<Pose<MpFloat>> = vec![
        screw([1, 2, 2], MpFloat::from_ratio(4, 5), [1, 2, -1], 1),
        screw([-3, 1, 4], MpFloat::from_ratio(13, 10), [-4, 1, 8], 2),
        screw([0, 1, 0], MpFloat::from_ratio(21, 10), [3, 0, 1], 1),
        screw([2, -1, 1], MpFloat::from_ratio(27, 10), [1, 1, 1], 3),
    ];
    let m = MultiplicativeBezier::new(p.clone()).unwrap();
    let three = MpFloat::from_i64(3);
    let (_, d0) = pose_derivative(&m, &MpFloat::zero()).unwrap();
    let l0 = (&p[0].reverse() * &p[1]).log().unwrap();
    assert!(diff(&d0, &(&p[0] * &l0).scale(&three)) < 1e-70);
    let (_, d1) = pose_derivative(&m, &MpFloat::one()).unwrap();
    let l1 = (&p[3].reverse() * &p[2]).log().unwrap();
    assert!(diff(&d1, &(&p[3] * &l1).scale(&three.neg_ref())) < 1e-70);
}

// ---------------------------------------------------------------------------------------------
// The Sec. 4 quadrant example

use motion::paper::sec_4::{exact_arc, printed_arc, printed_line};

fn round4(x: f64) -> f64 {
    (x * 1e4).round() / 1e4
}

/// Ψ at the end of the arc. The printed value `0.5858 - 1.4142 e12 + 5.6569 e2inf` is exactly
/// `(2 - √2) - √2 e12 + 4√2 e2inf`, the value for the exact poses, which the printed
/// `U_0..U_3` round to 4 decimals. Computed from the printed 4-decimal poses themselves, Ψ(1)
/// is `0.5856 - 1.4142 e12 + 0.0006 e1inf + 5.6574 e2inf` (exactly, up to f64 rounding): the
/// rounding of the control poses, amplified by `2n = 6`, changes the 4th decimal (by up to
/// 6e-4).
#[test]
#[allow(clippy::approx_constant)] // the paper's printed values
fn quadrant_example_indicatrix_at_end_of_arc() {
    let printed_psi = motion::paper::sec_4::PRINTED_PSI_END_OF_ARC;
    // The exact poses reproduce the printed Ψ to all 4 printed decimals...
    let exact = exact_arc();
    for (e, p) in exact.iter().zip(printed_arc()) {
        assert_eq!(e.components().map(|x| round4(*x)), p.components().map(|x| *x), "printed U_i = exact, rounded");
    }
    let psi = velocity_indicatrix(&AdditiveBezier::new(exact).unwrap(), &1.0).unwrap();
    let r2 = std::f64::consts::SQRT_2;
    assert!(diff(&psi, &Even::new(2.0 - r2, -r2, 0.0, 0.0, 0.0, 4.0 * r2, 0.0, 0.0)) < 1e-14);
    assert_eq!([psi.scalar, psi.e12, psi.e2inf].map(round4), printed_psi);
    assert_eq!([psi.e13, psi.e23, psi.e1inf, psi.e3inf, psi.e123inf].map(round4), [0.0; 5]);
    // ... the printed poses only to 6e-4.
    let psi = velocity_indicatrix(&AdditiveBezier::new(printed_arc()).unwrap(), &1.0).unwrap();
    assert_eq!([psi.scalar, psi.e12, psi.e1inf, psi.e2inf].map(round4), [0.5856, -1.4142, 0.0006, 5.6574]);
    assert!(diff(&psi, &Even::new(printed_psi[0], printed_psi[1], 0.0, 0.0, 0.0, printed_psi[2], 0.0, 0.0)) < 6.001e-4);
    // γ = 2 - √2 is a real scalar: the arc is not unitary at its end (U_3 is, but the motion's
    // norm is changing).
    let (gamma, nu) = split_indicatrix(&psi);
    assert!(gamma.scalar > 0.5 && gamma.e123inf.abs() < 1e-12);
    assert!(nu.e12 < 0.0); // turning clockwise: from the quarter turn back to 0
}

/// The rest of the example: the block's centre (the body origin) runs along a quadrant of the
/// circle of radius 4 about (4, 0, 0), then along a line, and "the distances travelled by the
/// centre of the block in the two parts of the motion are the same" (2π each), from the speed
/// by eq. (14) integrated over each unit interval. The speed jumps at the join (Fig. 3).
#[test]
#[allow(clippy::approx_constant)] // the paper's printed values
fn quadrant_example_path_and_distances() {
    let arc = AdditiveBezier::new(exact_arc()).unwrap();
    let line = AdditiveBezier::new(printed_line()).unwrap();
    let m = Piecewise::uniform(vec![arc, line]).unwrap();
    let speed = |t: f64| {
        let (_, v) = velocity(&m, &t).unwrap().body_point_velocity(&[0.0; 3]).unwrap();
        (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
    };
    for k in 0..=20 {
        let c = m.pose(&(f64::from(k) / 20.0)).unwrap().transform_point(&[0.0; 3]).unwrap();
        assert!((((c[0] - 4.0).powi(2) + c[1] * c[1]).sqrt() - 4.0).abs() < 1e-14 && c[2] == 0.0);
    }
    // Composite Simpson on [0, 1) and [1, 2].
    let simpson = |a: f64, b: f64, f: &dyn Fn(f64) -> f64| {
        let n = 2000;
        let h = (b - a) / f64::from(n);
        let inner: f64 = (1..n).map(|i| f(a + h * f64::from(i)) * if i % 2 == 1 { 4.0 } else { 2.0 }).sum();
        (f(a) + inner + f(b)) * h / 3.0
    };
    let tau = 2.0 * std::f64::consts::PI;
    let arc_length = simpson(0.0, 1.0, &|t| if t < 1.0 { speed(t) } else { left_speed(&m, 0, 1.0) });
    let line_length = simpson(1.0, 2.0, &speed);
    assert!((arc_length - tau).abs() < 1e-10, "{arc_length}");
    assert!((line_length - tau).abs() < 5e-4, "{line_length}"); // printed V_i: 4 decimals
    // The speed graph of Fig. 3: not constant on the arc, a jump at the join.
    let (s_end_arc, s_line) = (left_speed(&m, 0, 1.0), speed(1.0));
    assert!((s_end_arc - 4.0 * std::f64::consts::SQRT_2).abs() < 1e-12);
    assert!((speed(0.0) - 4.0 * std::f64::consts::SQRT_2).abs() < 1e-12);
    assert!((speed(0.5) - speed(0.0)).abs() > 0.1);
    assert!((s_line - 3.0 * 2.0 * 1.0472).abs() < 1e-12);
}

/// The speed of the body origin at `t` on piece `k` alone (one-sided at a join).
fn left_speed<M: MapScalar<f64, Jet<f64>> + Clone>(m: &Piecewise<f64, M>, k: usize, t: f64) -> f64 {
    let piece = m.piece(k).unwrap();
    let (_, v) = velocity(&piece, &t).unwrap().body_point_velocity(&[0.0; 3]).unwrap();
    (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]).sqrt()
}

// ---------------------------------------------------------------------------------------------
// Theorem 3.2, eq. (14), Corollary 3.3, Lemma 3.4

/// A set of test motions of every kind, unit and non-unit.
fn motions() -> Vec<(&'static str, AnyMotion<f64>)> {
    let u = unit_poses(5);
    let n = non_unit(&u);
    vec![
        ("additive cubic", AdditiveBezier::new(u[..4].to_vec()).unwrap().into()),
        ("additive quintic, non-unit", AdditiveBezier::new(n.clone()).unwrap().into()),
        ("multiplicative cubic", MultiplicativeBezier::new(u[..4].to_vec()).unwrap().into()),
        ("multiplicative quartic, non-unit", MultiplicativeBezier::new(n[..5].to_vec()).unwrap().into()),
        (
            "additive B-spline",
            AdditiveBSpline::new(2, vec![0.0, 0.0, 0.0, 0.3, 0.5, 0.8, 1.0, 1.0, 1.0], n[..6].to_vec()).unwrap().into(),
        ),
        ("multiplicative B-spline", MultiplicativeBSpline::clamped_uniform(3, u.clone()).unwrap().into()),
    ]
}

/// Eq. (14): the velocity `u + Ω × q` of the body point currently at `q` equals the derivative
/// of its path `F_{S(t)}(p)` from dual numbers (tight) and from central finite differences
/// (loose), for every kind of motion, unit and not, including the body point at the origin
/// (Theorem 3.2: `u` is its velocity).
#[test]
fn equation_14_point_velocity() {
    for (name, m) in motions() {
        let [a, b] = m.domain();
        for k in 1..=5 {
            let t = a + (b - a) * f64::from(k) / 6.0;
            let v = velocity(&m, &t).unwrap();
            let origin_body = v.pose.try_inverse().unwrap().transform_point(&[0.0; 3]).unwrap();
            for p in [[0.0, 0.0, 0.0], [1.0, -2.0, 0.5], [3.0, 1.0, -4.0], origin_body] {
                let (q, vq) = v.body_point_velocity(&p).unwrap();
                // Dual numbers: transform_point over Jet.
                let lifted = m.map_scalar(&|x: &f64| Jet::constant(*x));
                let s = lifted.pose(&Jet::variable(t)).unwrap();
                let x = s.transform_point(&p.map(Jet::constant)).unwrap();
                let dual = x.clone().map(|c| c.eps);
                assert!(diff_n(&vq, &dual) < 1e-12 * (1.0 + diff_n(&dual, &[0.0; 3])), "{name} t = {t}");
                assert!(diff_n(&q, &x.map(|c| c.re)) < 1e-13);
                // Finite differences.
                let h = 1e-6;
                let xp = m.pose(&(t + h)).unwrap().transform_point(&p).unwrap();
                let xm = m.pose(&(t - h)).unwrap().transform_point(&p).unwrap();
                let fd: [f64; 3] = std::array::from_fn(|i| (xp[i] - xm[i]) / (2.0 * h));
                assert!(diff_n(&vq, &fd) < 1e-6 * (1.0 + diff_n(&fd, &[0.0; 3])), "{name} t = {t}: fd");
            }
            // The body point at the origin moves with u.
            let (_, v0) = v.body_point_velocity(&origin_body).unwrap();
            assert!(diff_n(&v0, &v.twist().linear.to_array()) < 1e-12 * (1.0 + diff_n(&v0, &[0.0; 3])));
        }
    }
}

/// Theorem 3.2's sign conventions on motions with known velocities: rotating about e3 at rate
/// 2 gives `ν = 2 e12` (`Ω = (0, 0, 2)`: `Ω e123 = Ω3 e12`); a rotation about e2 gives
/// `ν13 = -Ω2`; translating with velocity `w` gives `ν = w einf`; and the screw
/// `exp(t(a e123 + c einf)/2)`... has `Ω = a`, `u = c`.
#[test]
fn theorem_3_2_sign_conventions() {
    let spin =
        MultiplicativeBezier::new(vec![Pose::identity(), Pose::rotation(&[0.0, 0.0, 1.0], &2.0).unwrap()]).unwrap();
    let nu = velocity_bivector(&spin, &0.3).unwrap();
    assert!(diff(&nu, &Even::new(0.0, 2.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0)) < 1e-15);
    let spin_y =
        MultiplicativeBezier::new(vec![Pose::identity(), Pose::rotation(&[0.0, 1.0, 0.0], &2.0).unwrap()]).unwrap();
    let nu = velocity_bivector(&spin_y, &0.3).unwrap();
    assert!(diff(&nu, &Even::new(0.0, 0.0, -2.0, 0.0, 0.0, 0.0, 0.0, 0.0)) < 1e-15);
    assert!(diff_n(&Twist::from_bivector(&nu).angular.to_array(), &[0.0, 2.0, 0.0]) < 1e-15);
    let slide = AdditiveBezier::new(vec![Pose::identity(), Pose::translation(&[1.0, -2.0, 3.0])]).unwrap();
    let v = velocity(&slide, &0.7).unwrap();
    assert!(diff_n(&v.twist().linear.to_array(), &[1.0, -2.0, 3.0]) < 1e-15);
    // exp(t B) with B = ½(Ω e123 + u einf): ν = 2B (Ψ = 2 S⁻¹ S' = 2B).
    let (omega, u) = ([0.3, -1.0, 0.5], [2.0, 0.5, -1.0]);
    let b = Even::from(&Twist { angular: omega.into(), linear: u.into() }.to_bivector().scale(&0.5));
    let screw_end = Pose::exp(&b).unwrap();
    let screw = MultiplicativeBezier::new(vec![Pose::identity(), screw_end]).unwrap();
    for t in [0.0, 0.4, 1.0] {
        let tw = velocity(&screw, &t).unwrap().twist();
        assert!(diff_n(&tw.angular.to_array(), &omega) < 1e-14 && diff_n(&tw.linear.to_array(), &u) < 1e-14, "t = {t}");
    }
}

/// Corollary 3.3: `ν = Ω e123 + v einf + (Ω ∧ r) ω` for any body point at `r` with velocity `v`
/// (from dual numbers, independent of Ψ), for every kind of motion.
#[test]
fn corollary_3_3() {
    for (name, m) in motions() {
        for t in [0.2, 0.55, 0.9] {
            let nu = velocity_bivector(&m, &t).unwrap();
            let omega = Twist::from_bivector(&nu).angular;
            for p in [[1.0, 2.0, 3.0], [-0.5, 0.0, 4.0]] {
                let k = body_point_kinematics(&m, &t, &p).unwrap();
                let from_point = bivector_from_point_velocity(&omega.to_array(), &k.position, &k.velocity);
                assert!(rel(&Even::from(&from_point), &Even::from(&nu)) < 1e-12, "{name} t = {t}");
            }
        }
    }
}

/// Lemma 3.4: a unitary motion has `Ψ = ν` (γ = 0); a non-unit one generally does not, and a
/// pseudoscalar factor (here: non-unit control poses of a multiplicative motion, Lemma 4.1)
/// changes only γ, never ν.
#[test]
fn lemma_3_4_and_pseudoscalar_factors() {
    let unit = MultiplicativeBezier::new(unit_poses(4)).unwrap();
    let raw = MultiplicativeBezier::new(non_unit(&unit_poses(4))).unwrap();
    for t in [0.0, 0.3, 0.8, 1.0] {
        let vu = velocity(&unit, &t).unwrap();
        let g = vu.gamma();
        assert!(g.scalar.abs() < 1e-13 && g.e123inf.abs() < 1e-13);
        let vr = velocity(&raw, &t).unwrap();
        let gr = vr.gamma();
        assert!(gr.scalar.abs() > 1e-2 || gr.e123inf.abs() > 1e-2);
        assert!(rel(&Even::from(&vr.nu()), &Even::from(&vu.nu())) < 1e-12, "t = {t}");
    }
}

/// Piecewise motions: the reparametrisation's chain-rule factor comes out of the dual numbers:
/// a segment on an interval of length `h` has `h⁻¹` times the segment's own Ψ.
#[test]
fn piecewise_chain_rule() {
    let u = unit_poses(3);
    let seg = MultiplicativeBezier::new(u.clone()).unwrap();
    let m = Piecewise::new(vec![0.0, 0.5, 2.0], vec![seg.clone(), seg.clone()]).unwrap();
    let own = velocity_indicatrix(&seg, &0.5).unwrap();
    assert!(rel(&velocity_indicatrix(&m, &0.25).unwrap(), &own.scale(&2.0)) < 1e-14);
    assert!(rel(&velocity_indicatrix(&m, &1.25).unwrap(), &own.scale(&(1.0 / 1.5))) < 1e-14);
    // At the join the right segment is used; piece(0) gives the left value.
    let right = velocity_indicatrix(&m, &0.5).unwrap();
    let left = velocity_indicatrix(&m.piece(0).unwrap(), &0.5).unwrap();
    assert!(rel(&right, &velocity_indicatrix(&seg, &0.0).unwrap().scale(&(1.0 / 1.5))) < 1e-14);
    assert!(rel(&left, &velocity_indicatrix(&seg, &1.0).unwrap().scale(&2.0)) < 1e-13);
}

/// Velocities of a singular additive motion fail with a typed error instead of a NaN: the
/// linear motion from 1 to -1 passes through 0 at t = ½.
#[test]
fn velocity_at_a_singular_pose_is_an_error() {
    let m = AdditiveBezier::new(vec![Pose::<f64>::identity(), Pose::identity().scale(&-1.0)]).unwrap();
    assert!(matches!(
        velocity_indicatrix(&m, &0.5),
        Err(motion::CurveError::Pose(motion::MotionError::Singular { .. }))
    ));
    assert!(velocity_indicatrix(&m, &0.25).is_ok());
    assert!(matches!(velocity(&m, &1.5), Err(motion::CurveError::OutOfDomain { .. })));
}

// ---------------------------------------------------------------------------------------------
// Second derivatives

fn dual2_parts(m: &Even<Dual2_64>) -> [Even<f64>; 3] {
    let f = |g: &dyn Fn(&Dual2_64) -> f64| {
        Even::new(g(&m.scalar), g(&m.e12), g(&m.e13), g(&m.e23), g(&m.e1inf), g(&m.e2inf), g(&m.e3inf), g(&m.e123inf))
    };
    [f(&|x| x.re), f(&|x| x.v1), f(&|x| x.v2)]
}

/// `d²S/dt²` from nested `Jet<Jet<f64>>` equals num-dual's `Dual2_64` through the same motion
/// code, for every kind of motion; `dΨ/dt` matches finite differences of Ψ.
#[test]
fn second_derivatives_nested_jets_vs_dual2() {
    for (name, m) in motions() {
        for t in [0.15, 0.45, 0.85] {
            let (s, ds, dds) = pose_second_derivative(&m, &t).unwrap();
            let d2 = m.map_scalar(&|x: &f64| Dual2_64::from(*x)).pose(&Dual2_64::new(t, 1.0, 0.0)).unwrap();
            let [s2, ds2, dds2] = dual2_parts(&d2);
            assert!(rel(&s, &s2) < 1e-15 && rel(&ds, &ds2) < 1e-13, "{name} t = {t}");
            assert!(rel(&dds, &dds2) < 1e-12, "{name} t = {t}: {dds} vs {dds2}");
            let (psi, dpsi) = velocity_indicatrix_derivative(&m, &t).unwrap();
            assert!(rel(&psi, &velocity_indicatrix(&m, &t).unwrap()) < 1e-15);
            let h = 1e-5;
            let fd = (velocity_indicatrix(&m, &(t + h)).unwrap() - velocity_indicatrix(&m, &(t - h)).unwrap())
                .scale(&(0.5 / h));
            assert!(rel(&dpsi, &fd) < 1e-7, "{name} t = {t}: dΨ/dt");
        }
    }
}

/// The acceleration of a body point from dual numbers (`transform_point` over `Jet<Jet>`)
/// agrees with the rigid-body kinematics of the twist and its derivative:
/// `a = du/dt + dΩ/dt × q + Ω × v` (all from Ψ and dΨ/dt), and with second differences.
#[test]
fn body_point_acceleration() {
    let cross =
        |a: &[f64; 3], b: &[f64; 3]| [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]];
    for (name, m) in motions() {
        for t in [0.25, 0.6] {
            let acc = acceleration(&m, &t).unwrap();
            let tw = acc.velocity.twist();
            let dtw = acc.twist_derivative();
            for p in [[0.0, 0.0, 0.0], [1.0, -1.0, 2.0]] {
                let k = body_point_kinematics(&m, &t, &p).unwrap();
                let (q, v) = acc.velocity.body_point_velocity(&p).unwrap();
                assert!(diff_n(&q, &k.position) < 1e-13 && diff_n(&v, &k.velocity) < 1e-11, "{name}");
                let a1 = cross(&dtw.angular.to_array(), &q);
                let a2 = cross(&tw.angular.to_array(), &v);
                let expected: [f64; 3] = std::array::from_fn(|i| dtw.linear[i] + a1[i] + a2[i]);
                assert!(diff_n(&k.acceleration, &expected) < 1e-10 * (1.0 + diff_n(&expected, &[0.0; 3])), "{name}");
                let h = 1e-4;
                let x = |s: f64| m.pose(&s).unwrap().transform_point(&p).unwrap();
                let (xp, x0, xm) = (x(t + h), x(t), x(t - h));
                let fd: [f64; 3] = std::array::from_fn(|i| (xp[i] - 2.0 * x0[i] + xm[i]) / (h * h));
                assert!(diff_n(&k.acceleration, &fd) < 1e-4 * (1.0 + diff_n(&fd, &[0.0; 3])), "{name}: fd");
            }
            // The second derivative in the Acceleration matches pose_second_derivative.
            let (_, _, dds) = pose_second_derivative(&m, &t).unwrap();
            assert_eq!(acc.second_derivative, dds);
        }
    }
}

/// Additive motions differentiate exactly over the rationals at second order too:
/// `d²S/dt²(0) = n(n-1)(S_2 - 2S_1 + S_0)`.
#[test]
fn additive_second_derivative_exact() {
    let poses: Vec<Pose<Q>> =
        (0..4i64).map(|i| Even::new(q(1 + i * i), q(i), q(2), q(-i), q(3 * i), q(1), q(i - 2), q(i))).collect();
    let m = AdditiveBezier::new(poses.clone()).unwrap();
    let lifted = m.map_ring(&|x: &Q| Jet::constant(Jet::constant(x.clone())));
    let s = lifted.bernstein(&Jet::new(Jet::variable(ratio(0, 1)), Jet::constant(q(1))));
    let (_, d) = split_jet(&s);
    let (_, dds) = split_jet(&d);
    let expected = (&(&poses[2] - &poses[1].scale(&q(2))) + &poses[0]).scale(&q(6));
    assert_eq!(dds, expected);
}

/// Continuity at a simple interior knot of cubic B-spline motions, from one-sided dual-number
/// derivatives (the right span at the knot, the left span just below it): the additive motion is
/// C2 like a B-spline curve; the multiplicative one (de Boor with slerps) is C1 but its second
/// derivative jumps — the slerp generalisation does not inherit C2.
#[test]
fn bspline_continuity_at_a_knot() {
    let poses = unit_poses(5);
    let add = AdditiveBSpline::clamped_uniform(3, poses.clone()).unwrap();
    let mul = MultiplicativeBSpline::clamped_uniform(3, poses).unwrap();
    let (knot, h) = (1.0 / 3.0, 1e-9);
    let jumps = |m: &dyn Fn(f64) -> (Even<f64>, Even<f64>)| {
        let ((d_left, a_left), (d_right, a_right)) = (m(knot - h), m(knot));
        (diff(&d_left, &d_right), diff(&a_left, &a_right))
    };
    let (d_add, a_add) = jumps(&|t| {
        let (_, d, a) = pose_second_derivative(&add, &t).unwrap();
        (d, a)
    });
    let (d_mul, a_mul) = jumps(&|t| {
        let (_, d, a) = pose_second_derivative(&mul, &t).unwrap();
        (d, a)
    });
    assert!(d_add < 1e-7 && a_add < 1e-6, "additive: {d_add:e} {a_add:e}");
    assert!(d_mul < 1e-7, "multiplicative S': {d_mul:e}");
    assert!(a_mul > 1e-4, "multiplicative S'' unexpectedly continuous: {a_mul:e}");
}

/// The body twist against an independent reference: with `A` the rotation of `F_S` (its
/// matrix, read off `Pose::to_matrix`), `Ω_b = Aᵀ Ω` and `u_b = Aᵀ v_0`, where `v_0` is the
/// velocity of the body origin from dual numbers (`body_point_kinematics`), not from `ν`.
/// Also: the body twist's point velocity of body coordinates `p` is `Aᵀ` times the space
/// velocity of that body point.
#[test]
fn body_twist_is_the_space_twist_seen_from_the_body() {
    let a = Pose::from_axis_angle_translation(&[1.0, 2.0, -1.0], &0.7, &[0.5, -1.0, 2.0]).unwrap();
    let b = Pose::from_axis_angle_translation(&[-0.3, 1.0, 0.4], &2.1, &[3.0, 1.0, -2.0]).unwrap();
    let c = Pose::from_axis_angle_translation(&[0.0, 0.2, 1.0], &-0.9, &[1.0, 4.0, 0.0]).unwrap();
    let m = MultiplicativeBezier::new(vec![a, b, c]).unwrap();
    let add = AdditiveBezier::new(vec![a, b.scale(&2.0), c]).unwrap(); // non-unit poses too
    for t in [0.0, 0.35, 0.8] {
        for (name, v, k0, kp) in [
            (
                "multiplicative",
                velocity(&m, &t).unwrap(),
                body_point_kinematics(&m, &t, &[0.0; 3]).unwrap(),
                body_point_kinematics(&m, &t, &[0.3, -1.0, 2.0]).unwrap(),
            ),
            (
                "additive",
                velocity(&add, &t).unwrap(),
                body_point_kinematics(&add, &t, &[0.0; 3]).unwrap(),
                body_point_kinematics(&add, &t, &[0.3, -1.0, 2.0]).unwrap(),
            ),
        ] {
            let rot = v.pose.to_matrix().unwrap();
            let at =
                |x: &[f64; 3]| -> [f64; 3] { std::array::from_fn(|j| (0..3).map(|i| rot[i][j] * x[i]).sum::<f64>()) };
            let body = v.body_twist().unwrap();
            let omega = v.space_twist().angular.to_array();
            assert!(diff_n(&body.angular.to_array(), &at(&omega)) < 1e-12, "{name} t = {t}: Ω_b");
            assert!(diff_n(&body.linear.to_array(), &at(&k0.velocity)) < 1e-12, "{name} t = {t}: u_b");
            let vp = body.point_velocity(&[0.3, -1.0, 2.0]).to_array();
            assert!(diff_n(&vp, &at(&kp.velocity)) < 1e-12, "{name} t = {t}: body point");
        }
    }
}

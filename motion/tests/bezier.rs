//! Motion curves of Sec. 4 of Cross, Cripps and Mullineux (2022): additive Bezier motions by
//! two algorithms (Bernstein, eq. 18, and de Casteljau), multiplicative Bezier motions (Fig. 2),
//! the reversal `S_{0..n}(t) = S_{n..0}(1 - t)` and where it fails, Lemma 4.1, B-spline motions
//! (de Boor against Cox-de Boor basis functions, Bezier knots, knot validation) and piecewise
//! motions.

use crate::common;

use algebra_core::Real;
use algebra_core::rational::{Q, q, ratio};
use common::*;
use motion::{
    AdditiveBSpline, AdditiveBezier, AnyMotion, CurveError, Even, Motion, MultiplicativeBSpline, MultiplicativeBezier,
    Piecewise, Pose, Reparametrized,
};
use proptest::prelude::*;

fn qpose(c: [i64; 8]) -> Pose<Q> {
    let [a, b, cc, d, e, f, g, h] = c.map(q);
    Pose::new(a, b, cc, d, e, f, g, h)
}

// ---------------------------------------------------------------------------------------------
// Additive Bezier motions

/// Eq. (18) and the de Casteljau tableau agree exactly over the rationals, for degrees 0..6,
/// inside and outside [0, 1], and interpolate the end poses exactly.
#[test]
fn additive_bernstein_equals_de_casteljau_exactly() {
    let all: Vec<Pose<Q>> = (0..7).map(|i| qpose([1 + i, 2 - i, i * i - 3, 1, 5 - 2 * i, i, -i, 3 * i - 4])).collect();
    for n in 0..=6 {
        let m = AdditiveBezier::new(all[..=n].to_vec()).unwrap();
        assert_eq!(m.degree(), n);
        for t in [ratio(0, 1), ratio(1, 3), ratio(1, 2), ratio(5, 7), ratio(1, 1), ratio(-2, 3), ratio(9, 4)] {
            assert_eq!(m.bernstein(&t), m.de_casteljau(&t), "degree {n}, t = {t}");
        }
        assert_eq!(m.de_casteljau(&q(0)), all[0]);
        assert_eq!(m.de_casteljau(&q(1)), all[n]);
        // The tableau's apex is S(t), its left column the control poses.
        let tab = m.tableau(&ratio(2, 5));
        assert_eq!(tab[0], all[..=n].to_vec());
        assert_eq!(tab[n][0], m.bernstein(&ratio(2, 5)));
    }
}

/// The in-place de Casteljau evaluation (an array on the stack up to 8 control poses, one
/// `Vec` beyond) is bit for bit the apex of the tableau, whose columns are built separately, on
/// both sides of the stack limit: exactly over Q (and equal to eq. 18) and in f64, additive and
/// multiplicative.
#[test]
fn in_place_de_casteljau_is_the_tableau_apex_bit_for_bit() {
    let exact: Vec<Pose<Q>> = (0..12).map(|i| qpose([2 + i, 1 - i, i * i - 5, 3, 4 - i, 2 * i, -i, i - 7])).collect();
    let floats = non_unit(&unit_poses(12));
    let units = unit_poses(12);
    for n in [0, 1, 3, 7, 8, 11] {
        let m = AdditiveBezier::new(exact[..=n].to_vec()).unwrap();
        let t = ratio(3, 7);
        assert_eq!(m.de_casteljau(&t), m.tableau(&t)[n][0], "degree {n}");
        assert_eq!(m.evaluate(&t).unwrap(), m.bernstein(&t), "degree {n}");
        let f = AdditiveBezier::new(floats[..=n].to_vec()).unwrap();
        for t in [0.0, 0.3, 0.77, 1.0] {
            assert_eq!(f.de_casteljau(&t), f.tableau(&t)[n][0], "degree {n}, t = {t}");
            assert_eq!(f.evaluate(&t).unwrap(), f.de_casteljau(&t), "degree {n}, t = {t}");
        }
        // over dual numbers (what the velocity code evaluates)
        let jet = f.map_ring(&|x: &f64| algebra_core::Jet::constant(*x));
        let tj = algebra_core::Jet::variable(0.3);
        assert_eq!(jet.de_casteljau(&tj), jet.tableau(&tj)[n][0], "degree {n}, over Jet");
        let mul = MultiplicativeBezier::new(units[..=n].to_vec()).unwrap();
        assert_eq!(mul.de_casteljau(&0.6).unwrap(), mul.tableau(&0.6).unwrap()[n][0], "degree {n}");
    }
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(128))]

    /// Bernstein and de Casteljau agree over f64 for random control poses (non-unit, any
    /// degree up to 7) and parameters, to rounding.
    #[test]
    fn additive_bernstein_equals_de_casteljau_f64(
        coeffs in prop::collection::vec(prop::array::uniform8(-10.0f64..10.0), 1..9),
        t in -0.5f64..1.5,
    ) {
        let poses: Vec<Pose<f64>> = coeffs.iter().map(|c| Pose::new(c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7])).collect();
        let m = AdditiveBezier::new(poses.clone()).unwrap();
        let scale = poses.iter().map(size).fold(1.0, f64::max) * 4f64.powi(m.degree() as i32);
        prop_assert!(diff(&m.bernstein(&t), &m.de_casteljau(&t)) <= 1e-14 * scale);
    }

    /// The multiplicative tableau of unit poses stays unitary and is symmetric under reversal.
    #[test]
    fn multiplicative_unit_poses_stay_unitary(n in 1usize..5, t in 0.0f64..1.0) {
        let m = MultiplicativeBezier::new(unit_poses(n)).unwrap();
        let s = m.pose(&t).unwrap();
        prop_assert!(s.is_unitary(&1e-13));
        prop_assert!(diff(&s, &m.reversed().pose(&(1.0 - t)).unwrap()) < 1e-12);
    }
}

/// The reversal identity of the proof of Theorem 4.5 holds for additive motions with any
/// control poses, exactly (the Bernstein basis is symmetric).
#[test]
fn additive_reversal_exact() {
    for n in 1..=5 {
        let poses: Vec<Pose<Q>> = (0..=n as i64).map(|i| qpose([2 * i - 3, i, 1, -i, i * i, 4, 1 - i, 2])).collect();
        let m = AdditiveBezier::new(poses).unwrap();
        let r = m.reversed();
        for t in [ratio(0, 1), ratio(1, 4), ratio(3, 7), ratio(1, 1), ratio(-1, 2)] {
            assert_eq!(m.bernstein(&t), r.bernstein(&(q(1) - &t)));
        }
    }
}

/// Degree elevation gives the same motion (the Sec. 4 arc is an elevated line: see the velocity
/// tests).
#[test]
fn additive_degree_elevation() {
    let m = AdditiveBezier::new(vec![
        qpose([1, 2, 0, 0, 3, 0, 1, 0]),
        qpose([0, 1, 1, 2, 0, 5, 0, 1]),
        qpose([3, 0, 0, 1, 1, 1, 1, 1]),
    ])
    .unwrap();
    let e = m.elevated().elevated();
    assert_eq!(e.degree(), 4);
    for t in [ratio(0, 1), ratio(1, 3), ratio(4, 5), ratio(1, 1), ratio(7, 3)] {
        assert_eq!(e.bernstein(&t), m.bernstein(&t));
    }
}

// ---------------------------------------------------------------------------------------------
// Multiplicative Bezier motions

/// The tableau of Fig. 2 by hand for a cubic: `S(t) = Φ(S_012, S_123; t)` with
/// `Φ(A, B; t) = A (rev(A) B)^t`.
#[test]
fn multiplicative_cubic_matches_figure_2() {
    let p = non_unit(&unit_poses(3));
    let m = MultiplicativeBezier::new(p.clone()).unwrap();
    let t = 0.37;
    let phi = |a: &Pose<f64>, b: &Pose<f64>| a * (a.reverse() * b).power(&t).unwrap();
    let (s01, s12, s23) = (phi(&p[0], &p[1]), phi(&p[1], &p[2]), phi(&p[2], &p[3]));
    let (s012, s123) = (phi(&s01, &s12), phi(&s12, &s23));
    let s = phi(&s012, &s123);
    assert!(diff(&m.pose(&t).unwrap(), &s) < 1e-12 * size(&s));
    let tab = m.tableau(&t).unwrap();
    assert!(diff(&tab[1][1], &s12) < 1e-13 * size(&s12));
    assert!(diff(&tab[2][0], &s012) < 1e-12 * size(&s012));
}

/// Unit control poses: the reversal `S_{0..n}(t) = S_{n..0}(1 - t)` holds (degrees 1..5). Non-unit
/// control poses: it fails as an identity of elements (already `S(0) = S_0` vs the reversed
/// motion's `S(1) = |S_1|² ... S_0`), but holds up to a pseudoscalar (Theorem 2.8: the same
/// transforms).
#[test]
fn multiplicative_reversal_needs_unit_poses() {
    for n in 1..=5 {
        let unit = MultiplicativeBezier::new(unit_poses(n)).unwrap();
        let raw = MultiplicativeBezier::new(non_unit(&unit_poses(n))).unwrap();
        for t in [0.0, 0.2, 0.5, 0.9, 1.0] {
            let a = unit.pose(&t).unwrap();
            let b = unit.reversed().pose(&(1.0 - t)).unwrap();
            assert!(diff(&a, &b) < 1e-12, "unit, degree {n}, t = {t}");

            let a = raw.pose(&t).unwrap();
            let b = raw.reversed().pose(&(1.0 - t)).unwrap();
            assert!(diff(&a, &b) > 1e-2, "non-unit, degree {n}, t = {t}: unexpectedly equal");
            assert!(a.is_equivalent(&b, &1e-11).unwrap(), "non-unit, degree {n}, t = {t}: not equivalent");
        }
    }
}

/// Lemma 4.1: equivalent control poses give an equivalent motion (the same transforms), and the
/// unitized poses give a unitary motion with `S(0) = U_0`, `S(1) = U_n`.
#[test]
fn lemma_4_1_equivalent_control_poses() {
    let unit = MultiplicativeBezier::new(unit_poses(4)).unwrap();
    let raw = MultiplicativeBezier::new(non_unit(&unit_poses(4))).unwrap();
    let unitized = raw.unitized().unwrap();
    for t in [0.0, 0.3, 0.64, 1.0] {
        let (u, r) = (unit.pose(&t).unwrap(), raw.pose(&t).unwrap());
        assert!(u.is_equivalent(&r, &1e-11).unwrap());
        let p = [0.3, -1.2, 2.0];
        assert!(diff_n(&u.transform_point(&p).unwrap(), &r.transform_point(&p).unwrap()) < 1e-11);
        assert!(diff(&u, &unitized.pose(&t).unwrap()) < 1e-12);
    }
    assert!(diff(&raw.pose(&0.0).unwrap(), &raw.poses()[0]) < 1e-15);
    assert!(diff(&raw.pose(&1.0).unwrap(), &raw.poses()[4]) > 0.1); // only equivalent
    assert!(diff(&unitized.pose(&1.0).unwrap(), &unit.poses()[4]) < 1e-12);
}

/// With all control poses on one screw (powers of one element), the multiplicative motion of
/// any degree is the screw itself at constant speed; the additive one is not.
#[test]
fn multiplicative_motion_of_collinear_screw_poses() {
    let g = Pose::from_axis_angle_translation(&[1.0, 2.0, -1.0], &1.2, &[0.5, 0.0, 2.0]).unwrap();
    for n in 1..=4 {
        let poses = (0..=n).map(|i| g.power(&(i as f64 / n as f64)).unwrap()).collect();
        let m = MultiplicativeBezier::new(poses).unwrap();
        for t in [0.1, 0.45, 0.8] {
            assert!(diff(&m.pose(&t).unwrap(), &g.power(&t).unwrap()) < 1e-13, "degree {n}");
        }
    }
}

/// Errors: no control poses; parameters outside [0, 1] or NaN; a singular pose in a slerp.
#[test]
fn bezier_errors() {
    assert_eq!(MultiplicativeBezier::<f64>::new(vec![]), Err(CurveError::TooFewPoses { need: 1, got: 0 }));
    let m = MultiplicativeBezier::new(unit_poses(2)).unwrap();
    assert!(matches!(m.pose(&-0.01), Err(CurveError::OutOfDomain { .. })));
    assert!(matches!(m.pose(&f64::NAN), Err(CurveError::OutOfDomain { .. })));
    assert!(m.evaluate(&1.2).is_ok()); // the continuation is available unchecked
    let singular = Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0);
    let bad = MultiplicativeBezier::new(vec![Pose::identity(), singular]).unwrap();
    assert!(matches!(bad.pose(&0.5), Err(CurveError::Pose(motion::MotionError::Singular { .. }))));
    let e = CurveError::OutOfDomain { t: "2".into(), start: "0".into(), end: "1".into() };
    assert_eq!(e.to_string(), "the parameter 2 is outside the domain [0, 1]");
}

// ---------------------------------------------------------------------------------------------
// B-spline motions

/// Cox-de Boor basis functions `N_{i,p}(t)`: right-continuous, except at the end of the domain,
/// where the last non-empty span `last` is used (its left limit).
fn basis(knots: &[f64], i: usize, p: usize, t: f64, last: usize) -> f64 {
    if p == 0 {
        let (a, b) = (knots[i], knots[i + 1]);
        let on = if t == knots[last + 1] { i == last } else { a <= t && t < b };
        return if on { 1.0 } else { 0.0 };
    }
    let mut out = 0.0;
    let d1 = knots[i + p] - knots[i];
    if d1 > 0.0 {
        out += (t - knots[i]) / d1 * basis(knots, i, p - 1, t, last);
    }
    let d2 = knots[i + p + 1] - knots[i + 1];
    if d2 > 0.0 {
        out += (knots[i + p + 1] - t) / d2 * basis(knots, i + 1, p - 1, t, last);
    }
    out
}

/// The additive B-spline by de Boor equals `Σ N_{i,p}(t) S_i` (Cox-de Boor): non-uniform knots,
/// interior multiplicities, several degrees.
#[test]
fn additive_bspline_de_boor_equals_basis_sum() {
    let poses = non_unit(&unit_poses(6));
    for (p, knots) in [
        (1, vec![0.0, 0.0, 0.1, 0.3, 0.3, 0.6, 0.8, 1.0, 1.0]),
        (2, vec![0.0, 0.0, 0.0, 0.2, 0.5, 0.5, 0.7, 1.0, 1.0, 1.0]),
        (3, vec![-1.0, -0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0]),
        (3, vec![0.0, 0.0, 0.0, 0.0, 0.4, 0.4, 0.4, 1.0, 1.0, 1.0, 1.0]),
    ] {
        let m = AdditiveBSpline::new(p, knots.clone(), poses.clone()).unwrap();
        let [a, b] = m.domain();
        // The index of the last non-empty span, where the basis functions are closed at the end.
        let last = (p..poses.len()).rev().find(|&k| knots[k] < knots[k + 1]).unwrap();
        for k in 0..=20 {
            let t = a + (b - a) * f64::from(k) / 20.0;
            let mut sum = Even::zero();
            for (i, s) in poses.iter().enumerate() {
                let w = basis(&knots, i, p, t, last);
                sum += s.scale(&w);
            }
            let got = m.pose(&t).unwrap();
            assert!(diff(&got, &sum) < 1e-12 * size(&sum), "degree {p}, t = {t}");
        }
    }
}

/// Bezier knots (0 and 1, each `p + 1` times) give the Bezier motion, bit for bit, for both
/// kinds and degrees 0..5.
#[test]
fn bspline_with_bezier_knots_is_bezier() {
    for n in 0..=5 {
        let poses = non_unit(&unit_poses(n));
        let knots: Vec<f64> = [vec![0.0; n + 1], vec![1.0; n + 1]].concat();
        let add = AdditiveBSpline::new(n, knots.clone(), poses.clone()).unwrap();
        let mul = MultiplicativeBSpline::new(n, knots, poses.clone()).unwrap();
        assert_eq!(add, AdditiveBSpline::clamped_uniform(n, poses.clone()).unwrap());
        let (add_bz, mul_bz) = (AdditiveBezier::new(poses.clone()).unwrap(), MultiplicativeBezier::new(poses).unwrap());
        for t in [0.0, 0.125, 0.3, 0.5, 0.77, 1.0] {
            assert_eq!(add.pose(&t).unwrap(), add_bz.pose(&t).unwrap(), "additive, degree {n}, t = {t}");
            assert_eq!(mul.pose(&t).unwrap(), mul_bz.pose(&t).unwrap(), "multiplicative, degree {n}, t = {t}");
        }
    }
}

/// Knot validation: each failure is its own typed error.
#[test]
fn bspline_knot_validation() {
    let poses = unit_poses(3); // 4 poses
    let err = |p: usize, k: Vec<f64>| AdditiveBSpline::new(p, k, poses.clone()).unwrap_err();
    assert_eq!(err(2, vec![0.0; 6]), CurveError::KnotCount { degree: 2, poses: 4, expected: 7, got: 6 });
    assert_eq!(err(4, vec![0.0; 9]), CurveError::TooFewPoses { need: 5, got: 4 });
    assert!(matches!(err(2, vec![0.0, 0.0, 0.0, 0.5, 0.4, 1.0, 1.0]), CurveError::KnotsDecreasing { index: 4, .. }));
    assert!(matches!(
        err(1, vec![0.0, 0.5, 0.5, 0.5, 1.0, 1.0]),
        CurveError::KnotMultiplicity { multiplicity: 3, degree: 1, .. }
    ));
    assert!(matches!(
        err(2, vec![0.0, 0.0, 0.0, f64::NAN, 1.0, 1.0, 1.0]),
        CurveError::NotFiniteParameter { what: "knot", index: 3, .. }
    ));
    assert!(matches!(err(1, vec![0.0, 1.0, 1.0, 1.0, 1.0, 2.0]), CurveError::KnotMultiplicity { .. }));
    // u_p = u_{n+1}: the domain is a point.
    assert!(matches!(
        MultiplicativeBSpline::new(1, vec![0.0, 1.0, 1.0, 2.0], unit_poses(1)),
        Err(CurveError::EmptyDomain { .. })
    ));
    // Out of the domain [u_p, u_{n+1}] = [0.5, 1.5].
    let m = AdditiveBSpline::new(2, vec![-0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5], poses.clone()).unwrap();
    assert_eq!(m.domain(), [0.5, 1.5]);
    assert!(matches!(m.pose(&0.4), Err(CurveError::OutOfDomain { .. })));
    assert!(m.pose(&1.5).is_ok());
    let msg = err(2, vec![0.0; 6]).to_string();
    assert_eq!(msg, "a B-spline of degree 2 with 4 control poses needs 7 knots, got 6");
}

/// Multiplicative B-splines: unit poses stay unitary, constant poses give a constant motion,
/// and local support (moving one control pose changes the motion on `p + 1` spans only).
#[test]
fn multiplicative_bspline_properties() {
    let poses = unit_poses(6);
    let m = MultiplicativeBSpline::clamped_uniform(3, poses.clone()).unwrap();
    assert_eq!(m.knots().len(), 11);
    for k in 0..=10 {
        assert!(m.pose(&(f64::from(k) / 10.0)).unwrap().is_unitary(&1e-13));
    }
    let constant = MultiplicativeBSpline::clamped_uniform(2, vec![poses[2]; 5]).unwrap();
    assert!(diff(&constant.pose(&0.61).unwrap(), &poses[2]) < 1e-14);
    // Move S_0: the spans from u_4 = 1/4 on are unaffected (S_0 acts on [u_0, u_4)).
    let mut moved = poses.clone();
    moved[0] = Pose::translation(&[5.0, 5.0, 5.0]);
    let m2 = MultiplicativeBSpline::clamped_uniform(3, moved).unwrap();
    assert_eq!(m.knots()[4], 0.25);
    for t in [0.25, 0.5, 0.7, 1.0] {
        assert_eq!(m.pose(&t).unwrap(), m2.pose(&t).unwrap());
    }
    assert!(diff(&m.pose(&0.2).unwrap(), &m2.pose(&0.2).unwrap()) > 1e-3);
}

// ---------------------------------------------------------------------------------------------
// Piecewise motions

/// Segment selection, reparametrisation onto each segment's domain, the domain error, and the
/// breakpoint validation.
#[test]
fn piecewise_motion() {
    let u = unit_poses(3);
    let first = AdditiveBezier::new(vec![u[0], u[1]]).unwrap();
    let second = AdditiveBezier::new(vec![u[1], u[2], u[3]]).unwrap();
    let m = Piecewise::new(vec![1.0, 1.5, 3.5], vec![first.clone(), second.clone()]).unwrap();
    assert_eq!(m.domain(), [1.0, 3.5]);
    assert_eq!(m.segment_index(&1.5).unwrap(), 1);
    assert_eq!(m.pose(&1.25).unwrap(), first.pose(&0.5).unwrap());
    assert_eq!(m.pose(&3.0).unwrap(), second.pose(&0.75).unwrap());
    assert_eq!(m.pose(&3.5).unwrap(), u[3]);
    assert_eq!(m.pose(&1.5).unwrap(), u[1]);
    assert!(matches!(m.pose(&0.999), Err(CurveError::OutOfDomain { .. })));
    assert!(matches!(m.pose(&3.6), Err(CurveError::OutOfDomain { .. })));
    // One-sided pieces at the join.
    assert_eq!(m.piece(0).unwrap().pose(&1.5).unwrap(), u[1]);
    assert!(m.piece(2).is_none());
    // Validation.
    assert_eq!(Piecewise::<f64, AdditiveBezier<f64>>::new(vec![0.0], vec![]), Err(CurveError::NoSegments));
    assert!(matches!(
        Piecewise::new(vec![0.0, 2.0, 1.0], vec![first.clone(), first.clone()]),
        Err(CurveError::BreaksNotIncreasing { index: 2, .. })
    ));
    assert!(matches!(
        Piecewise::new(vec![0.0, f64::INFINITY], vec![first.clone()]),
        Err(CurveError::NotFiniteParameter { what: "breakpoint", index: 1, .. })
    ));
    assert_eq!(Piecewise::new(vec![0.0, 1.0, 2.0], vec![first]), Err(CurveError::BreakCount { segments: 1, got: 3 }));
}

/// A piecewise motion over segments of different kinds and domains (B-spline on [0.5, 1.5]),
/// and nested reparametrisations.
#[test]
fn piecewise_of_mixed_kinds() {
    let u = unit_poses(4);
    let bspline = AdditiveBSpline::new(2, vec![-0.5, 0.0, 0.5, 1.0, 1.5, 2.0, 2.5], u[..4].to_vec()).unwrap();
    let mul = MultiplicativeBezier::new(u[3..].to_vec()).unwrap();
    let m = Piecewise::uniform(vec![AnyMotion::from(bspline.clone()), AnyMotion::from(mul.clone())]).unwrap();
    assert_eq!(m.pose(&0.25).unwrap(), bspline.pose(&0.75).unwrap());
    assert_eq!(m.pose(&1.5).unwrap(), mul.pose(&0.5).unwrap());
    let r = Reparametrized::new(m.clone(), [10.0, 12.0]).unwrap();
    assert_eq!(r.domain(), [10.0, 12.0]);
    assert_eq!(r.pose(&10.25).unwrap(), m.pose(&0.25).unwrap());
    assert_eq!(r.inner_parameter(&11.0), 1.0);
    // Rounding at the ends: the inner parameter may leave the inner domain by an ulp.
    let awkward = Reparametrized::new(bspline.clone(), [0.1, 0.7]).unwrap();
    for t in [0.1, 0.7] {
        assert!(awkward.pose(&t).is_ok());
    }
}

/// `map_ring` changes the scalar of an additive motion (here rationals to f64).
#[test]
fn additive_bezier_map_ring_to_f64() {
    let m = AdditiveBezier::new(vec![qpose([1, 0, 0, 0, 2, 0, 0, 0]), qpose([0, 1, 0, 0, 0, 0, 0, 3])]).unwrap();
    let f = m.map_ring(&algebra_core::rational::rational_to_f64);
    assert_eq!(f.pose(&0.5).unwrap(), Pose::new(0.5, 0.5, 0.0, 0.0, 1.0, 0.0, 0.0, 1.5));
}

/// Generic code over any motion.
#[test]
fn generic_over_motions() {
    fn mid<T: Real, M: Motion<T>>(m: &M) -> Pose<T> {
        let [a, b] = m.domain();
        m.pose(&a.add_ref(&b).mul_ref(&T::from_ratio(1, 2))).unwrap()
    }
    let u = unit_poses(2);
    assert_eq!(
        mid(&AdditiveBezier::new(u.clone()).unwrap()),
        AdditiveBezier::new(u.clone()).unwrap().de_casteljau(&0.5)
    );
    assert!(mid(&MultiplicativeBSpline::clamped_uniform(1, u).unwrap()).is_unitary(&1e-14));
}

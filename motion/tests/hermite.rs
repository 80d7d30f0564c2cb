//! Hermite interpolation (Sec. 5.3): the Jaklič et al. example of `motion::paper::jaklic` (nine
//! precision poses, eight cubic segments) with common shape factors 0.5, 1 and 1.5 (Fig. 10),
//! both kinds; every segment's end indicatrices and every join's jump in ν from dual-number
//! derivatives of a local Bernstein sum or de Casteljau tableau; per-pose (C1) and
//! per-segment (G1) shapes; non-uniform parameters; higher degrees; errors; 256-bit floats.

use crate::common;

use algebra_core::{MpFloat, PrecisionGuard, Real};
use common::{bernstein, de_casteljau, diff, size, value_and_derivative};
use motion::hermite::{self, AnyHermiteSegment, HermiteShapes};
use motion::joins;
use motion::paper::jaklic;
use motion::{Continuity, EndCondition, Even, JoinError, Pose, Pseudoscalar, SegmentKind, Shape};
use num_dual::Dual64;

const KINDS: [SegmentKind; 2] = [SegmentKind::Additive, SegmentKind::Multiplicative];

/// A segment evaluated at a dual parameter: Bernstein sum (eq. 18) or slerp tableau (Fig. 2).
fn evaluate(seg: &AnyHermiteSegment<f64>, t: Dual64) -> Pose<Dual64> {
    match seg.kind() {
        SegmentKind::Additive => bernstein(seg.control_poses(), &t),
        SegmentKind::Multiplicative => de_casteljau(seg.control_poses(), &t),
    }
}

/// `(S(t), Ψ(t) = 2 S⁻¹ S')` of a segment at `t` by a dual number.
fn pose_and_indicatrix(seg: &AnyHermiteSegment<f64>, t: f64) -> (Pose<f64>, Even<f64>) {
    let (s, ds) = value_and_derivative(&evaluate(seg, Dual64::new(t, 1.0)));
    let psi = (s.try_inverse().unwrap() * ds).scale(&2.0);
    (s, psi)
}

fn bivector(m: &Even<f64>) -> Even<f64> {
    Even::new(0.0, m.e12, m.e13, m.e23, m.e1inf, m.e2inf, m.e3inf, 0.0)
}

/// The end conditions of the example are those of the Jaklič motion itself: its dual-number
/// `Ψ = 2 S⁻¹ S'` (a unitary motion, so `Ψ = ν`) is the ν of Theorem 3.2 from `c'`, `Ω`, `c`.
#[test]
fn jaklic_end_conditions_match_the_motion() {
    let poses = jaklic::precision_poses().unwrap();
    assert_eq!(poses.len(), 9);
    for (k, cond) in poses.iter().enumerate() {
        let t = (k + 1) as f64;
        let (s, ds) = value_and_derivative(&jaklic::pose(&Dual64::new(t, 1.0)).unwrap());
        assert!(s.is_unitary(&1e-14));
        let psi = (s.reverse() * ds).scale(&2.0);
        assert!(diff(&psi, &cond.velocity_bivector()) < 1e-13, "t = {t}: {psi} vs {}", cond.velocity_bivector());
        assert!(diff(&s, &cond.pose) < 1e-15);
        // The reference point is where the body origin goes.
        let origin = s.transform_point(&[0.0; 3]).unwrap();
        assert!(common::diff_n(&origin, &cond.position) < 1e-14);
    }
}

/// Fig. 10: eight cubic segments through the nine precision poses for each common shape factor;
/// every segment interpolates its precision poses and has `Ψ = λ ν` at both ends (dual numbers),
/// and every join is C1: zero jump in ν (and here in Ψ).
#[test]
fn jaklic_segments_are_c1_for_every_common_shape() {
    let poses = jaklic::precision_poses().unwrap();
    for kind in KINDS {
        for lambda in [0.5, 1.0, 1.5] {
            let segs = jaklic::segments(kind, lambda).unwrap();
            assert_eq!(segs.len(), 8);
            for (k, seg) in segs.iter().enumerate() {
                assert_eq!(seg.degree(), 3);
                let (s0, psi0) = pose_and_indicatrix(seg, 0.0);
                let (s1, psi1) = pose_and_indicatrix(seg, 1.0);
                assert!(diff(&s0, &poses[k].pose) < 1e-14, "{kind} λ = {lambda} segment {k}");
                assert!(diff(&s1, &poses[k + 1].pose) < 1e-12, "{kind} λ = {lambda} segment {k}");
                let want0 = poses[k].velocity_bivector().scale(&lambda);
                let want1 = poses[k + 1].velocity_bivector().scale(&lambda);
                let tol = 1e-12 * (1.0 + size(&want0).max(size(&want1)));
                assert!(diff(&psi0, &want0) < tol, "{kind} λ = {lambda} segment {k} start: {psi0} vs {want0}");
                assert!(diff(&psi1, &want1) < tol, "{kind} λ = {lambda} segment {k} end: {psi1} vs {want1}");
            }
            for (k, pair) in segs.windows(2).enumerate() {
                let (left_end, left_psi) = pose_and_indicatrix(&pair[0], 1.0);
                let (right_start, right_psi) = pose_and_indicatrix(&pair[1], 0.0);
                let check = joins::check_join(&left_end, &left_psi, &right_start, &right_psi, &1e-10).unwrap();
                assert_eq!(check.continuity, Continuity::C1, "{kind} λ = {lambda} join {k}");
                assert!(size(&check.nu_jump) < 1e-11 * (1.0 + size(&left_psi)), "{kind} λ = {lambda} join {k}");
                assert!(size(&check.pose_jump) < 1e-12);
                let by_controls = joins::check_segment_join(
                    (pair[0].kind(), pair[0].control_poses()),
                    (pair[1].kind(), pair[1].control_poses()),
                    &1e-10,
                )
                .unwrap();
                assert_eq!(by_controls.continuity, Continuity::C1);
            }
        }
    }
}

/// "Other motions can be created by taking any combination of segments from the three cases.
/// Such combinations are G1-continuous across the joins": per-segment shapes give
/// `ν_right = (λ_right/λ_left) ν_left` at each join.
#[test]
fn jaklic_mixed_segments_are_g1() {
    let poses = jaklic::precision_poses().unwrap();
    let cases = [0.5, 1.0, 1.5];
    let per_segment: Vec<[Shape<f64>; 2]> =
        (0..8).map(|k| [Shape::factor(cases[k % 3]), Shape::factor(cases[k % 3])]).collect();
    for kind in KINDS {
        let segs = hermite::hermite(kind, 3, &poses, &HermiteShapes::PerSegment(per_segment.clone())).unwrap();
        // The same segments as taking segment k from the common-λ case k mod 3.
        for (k, seg) in segs.iter().enumerate() {
            let common = &jaklic::segments(kind, cases[k % 3]).unwrap()[k];
            for (a, b) in seg.control_poses().iter().zip(common.control_poses()) {
                assert!(diff(a, b) < 1e-15);
            }
        }
        for (k, pair) in segs.windows(2).enumerate() {
            let (left_end, left_psi) = pose_and_indicatrix(&pair[0], 1.0);
            let (right_start, right_psi) = pose_and_indicatrix(&pair[1], 0.0);
            let check = joins::check_join(&left_end, &left_psi, &right_start, &right_psi, &1e-10).unwrap();
            let want = cases[(k + 1) % 3] / cases[k % 3];
            match check.continuity {
                Continuity::G1 { factor } => assert!((factor - want).abs() < 1e-10, "{kind} join {k}: {factor}"),
                other => panic!("{kind} join {k}: {other:?}"),
            }
            let expected_jump = bivector(&left_psi).scale(&(want - 1.0));
            assert!(diff(&check.nu_jump, &expected_jump) < 1e-10 * (1.0 + size(&left_psi)));
        }
    }
}

/// Per-pose shapes (λ and γ at each precision pose, shared by the two segments meeting there)
/// keep ν continuous: C1, with Ψ continuous for additive segments.
#[test]
fn per_pose_shapes_are_c1() {
    let poses = jaklic::precision_poses().unwrap();
    let shapes: Vec<Shape<f64>> = (0..9)
        .map(|k| Shape::new(0.5 + 0.125 * k as f64, Pseudoscalar::new(0.1 * k as f64 - 0.4, 0.25 - 0.05 * k as f64)))
        .collect();
    for kind in KINDS {
        let segs = hermite::hermite(kind, 3, &poses, &HermiteShapes::PerPose(shapes.clone())).unwrap();
        for (k, pair) in segs.windows(2).enumerate() {
            let (left_end, left_psi) = pose_and_indicatrix(&pair[0], 1.0);
            let (right_start, right_psi) = pose_and_indicatrix(&pair[1], 0.0);
            let check = joins::check_join(&left_end, &left_psi, &right_start, &right_psi, &1e-10).unwrap();
            assert_eq!(check.continuity, Continuity::C1, "{kind} join {k}");
            let want = shapes[k + 1].indicatrix(&poses[k + 1].velocity_bivector());
            assert!(diff(&bivector(&right_psi), &bivector(&want)) < 1e-11 * (1.0 + size(&want)));
            if kind == SegmentKind::Additive {
                assert!(size(&check.indicatrix_jump) < 1e-11 * (1.0 + size(&want)), "{kind} join {k}");
                assert!(diff(&right_psi, &want) < 1e-11 * (1.0 + size(&want)));
            }
        }
    }
}

/// Parameters `t_k` with unequal spacing: each segment runs over `[0, 1]`, so with respect to
/// the global parameter `dS/dt = S'(s)/h`; the global ν is the prescribed one on both sides of
/// every join (C1 in `t`), although the local ones differ by the ratio of the interval lengths.
#[test]
fn non_uniform_parameters() {
    let poses: Vec<EndCondition<f64>> =
        [1.0, 1.5, 3.0, 3.25].iter().map(|&t| jaklic::end_condition(t).unwrap()).collect();
    let params = [1.0, 1.5, 3.0, 3.25];
    for kind in KINDS {
        let segs = hermite::hermite_with_parameters(kind, 3, &poses, &params, &HermiteShapes::unit()).unwrap();
        for (k, seg) in segs.iter().enumerate() {
            let h = params[k + 1] - params[k];
            for (end, s) in [(0usize, 0.0), (1, 1.0)] {
                let (_, psi) = pose_and_indicatrix(seg, s);
                let want = poses[k + end].velocity_bivector();
                assert!(
                    diff(&psi.scale(&(1.0 / h)), &want) < 1e-11 * (1.0 + size(&want)),
                    "{kind} segment {k} end {end}"
                );
                assert_eq!(seg.velocity_bivectors()[end], want);
            }
        }
    }
    let err = |p: &[f64]| hermite::hermite_with_parameters(SegmentKind::Additive, 3, &poses, p, &HermiteShapes::unit());
    assert!(matches!(err(&[1.0, 2.0, 3.0]), Err(JoinError::Input(_))));
    assert!(matches!(err(&[1.0, 2.0, 2.0, 3.0]), Err(JoinError::Input(_))));
    assert!(matches!(err(&[1.0, 2.0, f64::NAN, 3.0]), Err(JoinError::Input(_))));
    assert!(matches!(err(&[1.0, 2.0, 3.0, f64::INFINITY]), Err(JoinError::Input(_))));
}

/// Degrees above 3: `S0, S1, S_{n-1}, Sn` from the end conditions (ends as prescribed, by the
/// Bernstein sum / tableau of that degree), the poses in between spread from `S1` to `S_{n-1}`.
#[test]
fn higher_degrees() {
    let a = jaklic::end_condition(2.0).unwrap();
    let b = jaklic::end_condition(3.0).unwrap();
    let shape0 = Shape::new(1.2, Pseudoscalar::zero());
    let shape1 = Shape::new(0.8, Pseudoscalar::zero());
    for kind in KINDS {
        for n in [3usize, 4, 5, 7] {
            let seg = hermite::hermite_segment(kind, n, &a, &b, &shape0, &shape1).unwrap();
            assert_eq!(seg.degree(), n);
            let (s0, psi0) = pose_and_indicatrix(&seg, 0.0);
            let (s1, psi1) = pose_and_indicatrix(&seg, 1.0);
            // The pairwise slerp scales non-unit keys, Φ(αA, βB; t) = α^{1+t} β^t Φ(A, B; t)
            // (eq. 16), so the control poses' rounding-level norms (|N - 1| up to 4e-16) are
            // raised to powers up to 2^n along the tableau: the end pose's error grows as 2^n
            // (n = 7: 3e-13 to 1.1e-12 depending on the slerp's rounding; the same tableau
            // evaluated at 256 bits is 0.9e-12 to 1.2e-12 from the prescribed pose).
            let amplified = f64::from(1u32 << n);
            assert!(diff(&s0, &a.pose) < 1e-14 && diff(&s1, &b.pose) < amplified * 2e-14, "{kind} n = {n}");
            let want0 = shape0.indicatrix(&a.velocity_bivector());
            let want1 = shape1.indicatrix(&b.velocity_bivector());
            assert!(diff(&psi0, &want0) < 1e-11, "{kind} n = {n}: {psi0} vs {want0}");
            assert!(diff(&psi1, &want1) < amplified * 2e-13, "{kind} n = {n}: {psi1} vs {want1}");
            let c = seg.control_poses();
            for i in 2..n - 1 {
                let t = (i - 1) as f64 / (n - 2) as f64;
                let want = match kind {
                    SegmentKind::Additive => Pose::lerp(&c[1], &c[n - 1], &t),
                    SegmentKind::Multiplicative => Pose::slerp(&c[1], &c[n - 1], &t).unwrap(),
                };
                assert!(diff(&c[i], &want) < 1e-14);
            }
        }
    }
}

#[test]
fn input_errors() {
    let poses = jaklic::precision_poses().unwrap();
    for kind in KINDS {
        for n in [0usize, 1, 2] {
            assert_eq!(
                hermite::hermite(kind, n, &poses, &HermiteShapes::unit()),
                Err(JoinError::Degree { degree: n, min: 3 })
            );
        }
        assert!(matches!(hermite::hermite(kind, 3, &poses[..1], &HermiteShapes::unit()), Err(JoinError::Input(_))));
        assert!(matches!(hermite::hermite(kind, 3, &[], &HermiteShapes::<f64>::unit()), Err(JoinError::Input(_))));
        let short = HermiteShapes::PerPose(vec![Shape::unit(); 8]);
        assert!(matches!(hermite::hermite(kind, 3, &poses, &short), Err(JoinError::Input(_))));
        let short = HermiteShapes::PerSegment(vec![[Shape::unit(), Shape::unit()]; 9]);
        assert!(matches!(hermite::hermite(kind, 3, &poses, &short), Err(JoinError::Input(_))));
    }
    // A singular precision pose (the zero transform) still gives control poses; the end
    // indicatrices (Corollary 4.6), which need its inverse, report it as an error.
    let singular = EndCondition::new(Pose::new(0.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0), [0.0; 3], [1.0; 3], [0.0; 3]);
    let seg = hermite::hermite_segment(SegmentKind::Additive, 3, &poses[0], &singular, &Shape::unit(), &Shape::unit());
    let seg = seg.unwrap();
    assert!(joins::end_indicatrices(SegmentKind::Additive, seg.control_poses()).is_err());
}

/// The construction is generic: over 256-bit floats it agrees with f64 and the additive end
/// indicatrices (Corollary 4.6) come back to 70 digits.
#[test]
fn multiple_precision() {
    let _precision = PrecisionGuard::new(256);
    let m = |x: f64| MpFloat::from_f64(x);
    let pi = MpFloat::pi();
    let quarter = pi.clone() / m(4.0);
    let a = EndCondition::from_axis_angle(
        &[m(0.0), m(0.0), m(0.0)],
        &[m(1.0), m(0.0), m(0.0)],
        &m(0.0),
        &[m(0.0), m(0.0), m(8.0)],
        &[-quarter.clone(), m(0.0), m(0.0)],
    )
    .unwrap();
    let b = EndCondition::from_axis_angle(
        &[m(0.0), m(10.0), m(0.0)],
        &[m(1.0), m(0.0), m(0.0)],
        &(-(pi.clone() / m(2.0))),
        &[m(0.0), m(4.0), m(0.0)],
        &[pi.clone() / m(8.0), m(0.0), m(0.0)],
    )
    .unwrap();
    let g0 = Pseudoscalar::new(m(0.5), m(0.5));
    let g3 = Pseudoscalar::new(m(1.0), m(-0.5));
    for kind in KINDS {
        let seg =
            hermite::hermite_segment(kind, 3, &a, &b, &Shape::new(m(4.0), g0.clone()), &Shape::new(m(4.0), g3.clone()))
                .unwrap();
        // Against f64 (the Sec. 5.2 λ = 4 poses).
        let (a64, b64) = motion::paper::sec_5_2::end_conditions();
        let seg64 = hermite::hermite_segment(
            kind,
            3,
            &a64,
            &b64,
            &Shape::new(4.0, Pseudoscalar::new(0.5, 0.5)),
            &Shape::new(4.0, Pseudoscalar::new(1.0, -0.5)),
        )
        .unwrap();
        for (x, y) in seg.control_poses().iter().zip(seg64.control_poses()) {
            let xs = x.components().map(Real::to_f64);
            let ys = y.components().map(|v| *v);
            assert!(common::diff_n(&xs, &ys) < 1e-13, "{kind}: {x} vs {y}");
        }
        if kind == SegmentKind::Additive {
            let [p0, p1] = joins::end_indicatrices(kind, seg.control_poses()).unwrap();
            let e0 = &p0 - &seg.velocity_indicatrices()[0];
            let e1 = &p1 - &seg.velocity_indicatrices()[1];
            assert!(common::size(&e0) < 1e-70 && common::size(&e1) < 1e-70, "{e0} {e1}");
        }
    }
}

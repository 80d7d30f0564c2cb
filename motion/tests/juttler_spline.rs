//! Jüttler's Algorithm 2 (C1 spline Q-motions, (40)-(44)) and step 1's velocity estimate:
//! through the key poses and C1 there exactly over rationals with rational velocities (the
//! velocities read back by dual numbers over Q, an independent route: frame derivative
//! `ω = ½ Σ a_k × a_k'`); the estimate exact on quadratic data; the `Motion` over f64 against
//! the library's dual-number velocities; typed errors.

use algebra_core::Jet;
use algebra_core::rational::{Q, q, ratio, rational_to_f64};
use motion::juttler::spline::algorithm2;
use motion::juttler::velocity::{bessel, estimate_velocities, key_velocity};
use motion::juttler::{JuttlerError, KeyVelocity, SplineQMotion};
use motion::velocity::velocity;
use motion::{Motion, MotionError, Pose};

fn v3(c: [i64; 3]) -> [Q; 3] {
    c.map(q)
}

/// Four rational poses, non-unit rotors `c + s a` (one needing the sign rule (24)).
fn poses() -> Vec<Pose<Q>> {
    let data = [
        (1, 0, [0, 0, 1], [0, 0, 0]),
        (2, 1, [1, -1, 2], [1, 2, -1]),
        (-1, -3, [0, 2, 1], [4, 0, 3]),
        (3, 1, [1, 1, 0], [2, -5, 1]),
    ];
    data.iter()
        .map(|(c, s, a, t)| Pose::rotor_from_parts(&q(*c), &q(*s), &v3(*a)) * Pose::translation(&v3(*t)))
        .collect()
}

fn params() -> Vec<Q> {
    vec![q(0), ratio(1, 3), ratio(1, 2), q(2)]
}

fn velocities() -> Vec<KeyVelocity<Q>> {
    vec![
        KeyVelocity::new([q(1), q(0), ratio(-1, 2)], [q(0), q(2), q(1)]),
        KeyVelocity::new([q(3), q(1), q(2)], [ratio(1, 3), q(-1), q(0)]),
        KeyVelocity::new([q(-2), q(0), q(1)], [q(0), q(0), q(4)]),
        KeyVelocity::new([q(0), q(5), q(0)], [q(1), q(1), q(-1)]),
    ]
}

fn cross(a: &[Q; 3], b: &[Q; 3]) -> [Q; 3] {
    [
        a[1].clone() * b[2].clone() - a[2].clone() * b[1].clone(),
        a[2].clone() * b[0].clone() - a[0].clone() * b[2].clone(),
        a[0].clone() * b[1].clone() - a[1].clone() * b[0].clone(),
    ]
}

/// The velocity of the body origin and the angular velocity of segment `i` at `t`, by dual
/// numbers over Q through the pose: `v` from the origin's image, `ω = ½ Σ a_k × a_k'` from the
/// images `a_k` of the frame's directions (orthonormal).
fn jet_velocity(m: &SplineQMotion<Q>, i: usize, t: &Q) -> KeyVelocity<Q> {
    let [t0, t1] = [m.breaks()[i].clone(), m.breaks()[i + 1].clone()];
    let dt = t1 - t0.clone();
    let u = Jet { re: (t.clone() - t0) / dt.clone(), eps: q(1) / dt };
    let seg = m.segments()[i].map_ring(&|c: &Q| Jet::constant(c.clone()));
    let pose = seg.pose_exact(&u).unwrap();
    let zero = [q(0), q(0), q(0)].map(Jet::constant);
    let v = pose.transform_point(&zero).unwrap().map(|c| c.eps);
    let mut w = [q(0), q(0), q(0)];
    for k in 0..3 {
        let e: [Jet<Q>; 3] = std::array::from_fn(|j| Jet::constant(if j == k { q(1) } else { q(0) }));
        let a = pose.transform_direction(&e).unwrap();
        let c = cross(&a.clone().map(|x| x.re), &a.map(|x| x.eps));
        w = std::array::from_fn(|j| w[j].clone() + c[j].clone() * ratio(1, 2));
    }
    KeyVelocity::new(v, w)
}

#[test]
fn exact_over_rationals_through_the_poses_and_c1_with_the_given_velocities() {
    let (p, t, vel) = (poses(), params(), velocities());
    let m = SplineQMotion::hermite(&p, &t, &vel).unwrap();
    assert_eq!(m.segments().len(), 3);
    for (i, ti) in t.iter().enumerate() {
        // through P_i, from the segment on each side
        for k in [i.saturating_sub(1), i.min(2)] {
            let (qk, _) = m.segment_jet(k, ti).unwrap();
            let pose = motion::repr::dual_quaternion::from_dual_quaternion_exact(&qk).unwrap();
            assert!(pose.is_equivalent_exact(&p[i]), "segment {k} at t_{i}");
        }
        assert!(m.pose_exact(ti).unwrap().is_equivalent_exact(&p[i]));
        // the velocities read back, two ways, from both sides
        for k in [i.saturating_sub(1), i.min(2)] {
            let (qk, dq) = m.segment_jet(k, ti).unwrap();
            assert_eq!(key_velocity(&qk, &dq).unwrap(), vel[i], "segment {k} at t_{i}");
            assert_eq!(jet_velocity(&m, k, ti), vel[i], "dual numbers, segment {k} at t_{i}");
        }
    }
    // C1 as a dual-quaternion curve: value and derivative equal at the interior t_i
    for (i, ti) in t.iter().enumerate().take(3).skip(1) {
        assert_eq!(m.segment_jet(i - 1, ti), m.segment_jet(i, ti), "t_{i}");
    }
    // between the key poses the motion is rigid (every segment a Q-motion of degree 6)
    for s in m.segments() {
        assert_eq!(s.degree(), 6);
        assert!(s.study_polynomial().iter().all(|c| *c == q(0)));
    }
}

#[test]
fn segment_trajectories_are_exact() {
    let m = SplineQMotion::hermite(&poses(), &params(), &velocities()).unwrap();
    let x = [ratio(1, 2), q(-3), q(2)];
    let paths = m.trajectories(&x);
    assert_eq!(paths.len(), 3);
    for k in 0..=40 {
        let t = ratio(k, 20);
        let (i, u) = m.local(&t);
        assert_eq!(paths[i].degree(), 12);
        assert_eq!(paths[i].point(&u).unwrap(), m.pose_exact(&t).unwrap().transform_point(&x).unwrap(), "t = {t}");
    }
}

#[test]
fn estimate_is_exact_on_quadratic_translations_and_rotation_angles() {
    // s(t) = (1, -2, 3) + (2, 0, 1) t + (1, 3, -1) t², θ(t) = 0.3 + 0.5 t - 0.2 t² about a fixed axis
    let ts = [0.0, 0.25, 1.0, 1.5, 2.75];
    let axis = [0.6, 0.0, 0.8];
    let s = |t: f64| [1.0 + 2.0 * t + t * t, -2.0 + 3.0 * t * t, 3.0 + t - t * t];
    let ds = |t: f64| [2.0 + 2.0 * t, 6.0 * t, 1.0 - 2.0 * t];
    let theta = |t: f64| 0.3 + 0.5 * t - 0.2 * t * t;
    let dtheta = |t: f64| 0.5 - 0.4 * t;
    let p: Vec<Pose<f64>> =
        ts.iter().map(|&t| Pose::from_axis_angle_translation(&axis, &theta(t), &s(t)).unwrap()).collect();
    let v = estimate_velocities(&p, &ts).unwrap();
    for (i, &t) in ts.iter().enumerate() {
        for (k, a) in axis.iter().enumerate() {
            assert!((v[i].velocity[k] - ds(t)[k]).abs() < 1e-12, "v at t_{i}: {:?}", v[i].velocity);
            assert!(
                (v[i].angular_velocity[k] - dtheta(t) * a).abs() < 1e-12,
                "ω at t_{i}: {:?}",
                v[i].angular_velocity
            );
        }
    }
}

#[test]
fn bessel_reproduces_a_parabola_exactly() {
    // f(t) = 2 - t + 3t² at uneven rational parameters
    let t = [q(-1), ratio(1, 2), q(1), ratio(7, 3), q(4)];
    let f = |t: &Q| q(2) - t.clone() + q(3) * t.clone() * t.clone();
    let d: Vec<[Q; 1]> = t.windows(2).map(|w| [(f(&w[1]) - f(&w[0])) / (w[1].clone() - w[0].clone())]).collect();
    let want: Vec<[Q; 1]> = t.iter().map(|t| [q(6) * t.clone() - q(1)]).collect();
    assert_eq!(bessel(&t, &d).unwrap(), want);
    // two parameters: the chord for both
    assert_eq!(bessel(&t[..2], &d[..1]).unwrap(), vec![d[0].clone(), d[0].clone()]);
    assert!(bessel(&t[..2], &d).is_err());
}

/// Five generic poses: screws about tilted axes, angles from -0.9 to 1.9.
fn generic_poses() -> Vec<Pose<f64>> {
    [
        ([0.5, -0.2, 0.8], -0.9, [0.0, 0.3, -0.1]),
        ([0.1, 0.9, 0.4], 0.3, [0.7, 1.1, 0.5]),
        ([-0.6, 0.2, 0.7], 1.1, [1.9, 0.4, 1.3]),
        ([0.3, 0.3, -0.9], 1.9, [2.2, -0.8, 2.0]),
        ([0.9, -0.4, 0.1], 0.6, [3.1, -0.2, 2.6]),
    ]
    .iter()
    .map(|(axis, angle, t)| Pose::from_axis_angle_translation(axis, angle, t).unwrap())
    .collect()
}

#[test]
fn f64_motion_passes_the_poses_with_the_estimated_velocities() {
    let p = generic_poses();
    let ts = [0.0, 0.2, 0.45, 0.7, 1.0];
    let m = algorithm2(&p, &ts, None).unwrap();
    let est = estimate_velocities(&p, &ts).unwrap();
    assert_eq!(m.domain(), [0.0, 1.0]);
    for (i, t) in ts.iter().enumerate() {
        assert!(m.pose(t).unwrap().is_equivalent(&p[i], &1e-12).unwrap(), "t_{i}");
        // the library's dual-number velocity (right-hand segment) against the estimate
        let vel = velocity(&m, t).unwrap();
        let w = vel.space_twist().angular;
        let (_, v) = vel.body_point_velocity(&[0.0, 0.0, 0.0]).unwrap();
        let w: [f64; 3] = w.into();
        for k in 0..3 {
            assert!((w[k] - est[i].angular_velocity[k]).abs() < 1e-11, "ω at t_{i}: {w:?} vs {:?}", est[i]);
            assert!((v[k] - est[i].velocity[k]).abs() < 1e-11, "v at t_{i}: {v:?} vs {:?}", est[i]);
        }
    }
    // the f64 `Motion` of the rational spline against its exact poses at rational t
    let exact = SplineQMotion::hermite(&poses(), &params(), &velocities()).unwrap();
    let float = exact.map_ring(&rational_to_f64);
    let x = [ratio(3, 10), q(-1), q(2)];
    let xf = x.clone().map(|c| rational_to_f64(&c));
    for k in 0..=40 {
        let t = ratio(k, 20);
        let a = float.pose(&rational_to_f64(&t)).unwrap().transform_point(&xf).unwrap();
        let b = exact.pose_exact(&t).unwrap().transform_point(&x).unwrap().map(|c| rational_to_f64(&c));
        assert!((0..3).all(|j| (a[j] - b[j]).abs() < 1e-12), "t = {t}: {a:?} vs {b:?}");
    }
}

#[test]
fn bad_input_is_a_typed_error() {
    let p = generic_poses();
    let v = vec![KeyVelocity::new([0.0; 3], [0.0; 3]); 5];
    let ts = [0.0, 0.2, 0.45, 0.7, 1.0];
    assert!(matches!(algorithm2(&p[..1], &ts[..1], None), Err(JuttlerError::TooFewPositions { need: 2, got: 1 })));
    assert!(matches!(algorithm2(&p, &ts[..4], None), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(algorithm2(&p, &[0.0, 0.2, 0.2, 0.7, 1.0], None), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(algorithm2(&p, &[0.0, 0.2, f64::NAN, 0.7, 1.0], None), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(algorithm2(&p, &[0.0, 0.2, 0.4, 0.7, f64::INFINITY], None), Err(JuttlerError::Parameters { .. })));
    assert!(matches!(algorithm2(&p, &ts, Some(&v[..4])), Err(JuttlerError::Parameters { .. })));
    let mut bad = v.clone();
    bad[3].angular_velocity[1] = f64::NAN;
    assert!(matches!(algorithm2(&p, &ts, Some(&bad)), Err(JuttlerError::Motion(MotionError::NotFinite { .. }))));
    let mut zero = p.clone();
    zero[2] = Pose::new(0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0);
    assert!(algorithm2(&zero, &ts, None).is_err());
    assert!(estimate_velocities(&zero, &ts).is_err());
    let exact_zero = vec![Pose::<Q>::identity(), Pose::new(q(0), q(0), q(0), q(0), q(1), q(0), q(0), q(0))];
    let vq = vec![KeyVelocity::new(v3([0, 0, 0]), v3([0, 0, 0])); 2];
    assert!(SplineQMotion::hermite(&exact_zero, &[q(0), q(1)], &vq).is_err());
}

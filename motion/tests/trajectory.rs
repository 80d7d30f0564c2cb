//! The trajectory builder (`motion::trajectory`): the robotics scenario of issue 9 (five
//! nalgebra `Isometry3` key poses at t = 0, 1, 2.5, 3.5, 5, C1 through all of them in one call,
//! sampled at 1 kHz with space and body twists), checked against independent routes: nalgebra's
//! own action and rotation, finite differences of the sampled path, `body_point_kinematics`
//! (a separate second-order dual-number evaluation), and a screw motion whose twist is known.
#![cfg(feature = "nalgebra")]

use motion::trajectory::{Trajectory, Velocities, align_signs};
use motion::velocity::{Twist, body_point_kinematics, velocity};
use motion::{Bivector, HermiteShapes, Motion, Pose, SegmentKind, Vec3};
use nalgebra::{Isometry3, Point3, Vector3};

const TIMES: [f64; 5] = [0.0, 1.0, 2.5, 3.5, 5.0];
const TOOL: [f64; 3] = [0.1, -0.05, 0.3];

/// Five robot key poses (translation in metres, rotation vector in radians).
fn key_isometries() -> Vec<Isometry3<f64>> {
    [
        ([0.5, 0.0, 0.4], [0.0, 0.0, 0.0]),
        ([0.6, 0.2, 0.5], [0.0, 0.3, 0.4]),
        ([0.4, 0.5, 0.6], [0.2, 0.5, 1.2]),
        ([0.1, 0.6, 0.4], [-0.3, 0.2, 2.0]),
        ([-0.2, 0.4, 0.3], [0.0, 0.0, 2.8]),
    ]
    .into_iter()
    .map(|(t, r)| Isometry3::new(Vector3::from(t), Vector3::from(r)))
    .collect()
}

fn build(kind: SegmentKind) -> Trajectory<f64> {
    let poses: Vec<Pose<f64>> = key_isometries().iter().map(Pose::from_na_isometry).collect();
    Trajectory::through(&poses, &TIMES, &Velocities::CatmullRom, kind, &HermiteShapes::unit()).unwrap()
}

fn dist<A: Clone + Into<[f64; 3]>, B: Clone + Into<[f64; 3]>>(a: &A, b: &B) -> f64 {
    let (a, b): ([f64; 3], [f64; 3]) = (a.clone().into(), b.clone().into());
    (0..3).map(|i| (a[i] - b[i]).powi(2)).sum::<f64>().sqrt()
}

fn norm<A: Clone + Into<[f64; 3]>>(a: &A) -> f64 {
    dist(a, &[0.0; 3])
}

#[test]
fn robotics_scenario_passes_through_the_key_poses_with_c1_joins() {
    for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
        let tr = build(kind);
        assert_eq!(tr.motion().domain(), [0.0, 5.0]);
        assert_eq!(tr.segments().len(), 4);
        // Through every key pose, as nalgebra moves the tool point.
        for (iso, t) in key_isometries().iter().zip(TIMES) {
            let s = tr.motion().pose(&t).unwrap();
            let want = iso.transform_point(&Point3::from(TOOL));
            let got = s.transform_point(&TOOL).unwrap();
            assert!(dist(&got, &[want.x, want.y, want.z]) < 1e-14, "{kind} t = {t}");
        }
        // C1 at each inner pose: the library's check...
        let joins = tr.joins();
        assert_eq!(joins.iter().map(|j| j.time).collect::<Vec<_>>(), [1.0, 2.5, 3.5]);
        assert!(joins.iter().all(|j| j.is_c1(1e-12)), "{kind}: {joins:?}");
        // ... and one-sided finite differences of the tool path, from either side of each join,
        // agree with each other and with the twist the builder chose.
        let h = 1e-6;
        let at = |t: f64| tr.motion().pose(&t).unwrap().transform_point(&TOOL).unwrap();
        for (i, &t) in TIMES.iter().enumerate().take(4).skip(1) {
            let p = at(t);
            let left: [f64; 3] =
                std::array::from_fn(|k| (3.0 * p[k] - 4.0 * at(t - h)[k] + at(t - 2.0 * h)[k]) / (2.0 * h));
            let right: [f64; 3] =
                std::array::from_fn(|k| (-3.0 * p[k] + 4.0 * at(t + h)[k] - at(t + 2.0 * h)[k]) / (2.0 * h));
            let want = tr.key_twists()[i].point_velocity(&p);
            assert!(dist(&left, &want) < 1e-6 * (1.0 + norm(&want)), "{kind} t = {t}: {left:?} vs {want:?}");
            assert!(dist(&right, &want) < 1e-6 * (1.0 + norm(&want)), "{kind} t = {t}: {right:?} vs {want:?}");
        }
        // At rest at both ends (the estimate's end rule).
        for t in [0.0, 5.0] {
            let v = velocity(tr.motion(), &t).unwrap().twist();
            assert!(norm(&v.angular) < 1e-12 && norm(&v.linear) < 1e-12, "{kind} t = {t}");
        }
    }
}

#[test]
fn robotics_scenario_sampled_at_1_khz() {
    for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
        let tr = build(kind);
        let samples = tr.sample_at_rate(1000.0, &[TOOL]).unwrap();
        assert_eq!(samples.len(), 5001);
        assert_eq!(samples[5000].t, 5.0);
        let dt = 1e-3;
        for (k, s) in samples.iter().enumerate() {
            assert!((s.t - k as f64 * dt).abs() < 1e-12);
            // Body twist = the space twist seen from the body (nalgebra's rotation, inverted).
            let iso = s.pose.to_na_isometry().unwrap();
            let w_body = iso.rotation.inverse() * Vector3::from(s.space_twist.angular.to_array());
            assert!(dist(&s.body_twist.angular, &<[f64; 3]>::from(w_body)) < 1e-12, "{kind} {k}");
            // The tool point's kinematics against a separate dual-number evaluation, at some
            // samples (every one would only repeat the same check).
            if k % 97 == 0 {
                let kin = body_point_kinematics(tr.motion(), &s.t, &TOOL).unwrap();
                let p = &s.points[0];
                let tol = 1e-11 * (1.0 + norm(&kin.acceleration));
                assert!(dist(&p.position, &kin.position) < 1e-14);
                assert!(dist(&p.velocity, &kin.velocity) < 1e-12 * (1.0 + norm(&kin.velocity)));
                assert!(dist(&p.acceleration, &kin.acceleration) < tol, "{kind} {k}: {p:?} vs {kin:?}");
            }
        }
        // Central differences of the sampled path: the body origin's velocity (body twist,
        // linear part, rotated back) and the tool point's velocity, O(dt²) away from the joins.
        for k in (1..5000).step_by(37) {
            let t = samples[k].t;
            if TIMES.iter().any(|&b| (t - b).abs() < 2.0 * dt) {
                continue;
            }
            let (prev, cur, next) = (&samples[k - 1], &samples[k], &samples[k + 1]);
            let fd: [f64; 3] =
                std::array::from_fn(|i| (next.points[0].position[i] - prev.points[0].position[i]) / (2.0 * dt));
            assert!(dist(&fd, &cur.points[0].velocity) < 1e-4 * (1.0 + norm(&fd)), "{kind} t = {t}");
            let o = |s: &motion::trajectory::TrajectorySample<f64>| s.pose.transform_point(&[0.0; 3]).unwrap();
            let fd: [f64; 3] = std::array::from_fn(|i| (o(next)[i] - o(prev)[i]) / (2.0 * dt));
            let iso = cur.pose.to_na_isometry().unwrap();
            let v_space = iso.rotation * Vector3::from(cur.body_twist.linear.to_array());
            assert!(dist(&fd, &<[f64; 3]>::from(v_space)) < 1e-4 * (1.0 + norm(&fd)), "{kind} t = {t}");
        }
    }
}

/// Key poses on one screw motion `S(t) = exp(t L)` at uniform times: the estimate gives every
/// inner pose the screw's own twist (`Ψ = 2L`); at non-uniform times too (a screw's one-sided
/// twists are equal).
#[test]
fn catmull_rom_estimate_reproduces_a_screw() {
    let l = Bivector::new(0.3, -0.2, 0.5, 0.4, 0.1, -0.7);
    let want = Twist::from_bivector(&l.scale(&2.0));
    for times in [[0.0, 1.0, 2.0, 3.0], [0.0, 0.5, 2.0, 2.25]] {
        let poses: Vec<Pose<f64>> = times.iter().map(|t| Pose::exp(&Pose::from(&l.scale(t))).unwrap()).collect();
        let tr = Trajectory::through(
            &poses,
            &times,
            &Velocities::CatmullRom,
            SegmentKind::Multiplicative,
            &HermiteShapes::unit(),
        )
        .unwrap();
        for w in &tr.key_twists()[1..3] {
            assert!(dist(&w.angular, &want.angular) < 1e-14 && dist(&w.linear, &want.linear) < 1e-14, "{w:?}");
        }
    }
}

#[test]
fn given_velocities_and_errors() {
    let poses: Vec<Pose<f64>> = key_isometries().iter().map(Pose::from_na_isometry).collect();
    let w = Twist { angular: Vec3::new(0.0, 0.0, 1.0), linear: Vec3::new(0.2, 0.0, 0.0) };
    let given = Velocities::Given(vec![w.clone(); 5]);
    let tr = Trajectory::through(&poses, &TIMES, &given, SegmentKind::Multiplicative, &HermiteShapes::unit()).unwrap();
    for t in TIMES {
        let v = velocity(tr.motion(), &t).unwrap().twist();
        assert!(dist(&v.angular, &w.angular) < 1e-12 && dist(&v.linear, &w.linear) < 1e-12, "t = {t}");
    }
    let err = |v: &Velocities<f64>, times: &[f64]| {
        Trajectory::through(&poses, times, v, SegmentKind::Additive, &HermiteShapes::unit()).unwrap_err().to_string()
    };
    assert!(err(&Velocities::Given(vec![w; 2]), &TIMES).contains("2 velocities given for 5 key poses"));
    assert!(err(&Velocities::Zero, &TIMES[..4]).contains("4 times given for 5 key poses"));
    assert!(err(&Velocities::Zero, &[0.0, 1.0, 1.0, 2.0, 3.0]).contains("strictly increasing"));
    assert!(err(&Velocities::Zero, &[0.0, 1.0, f64::NAN, 2.0, 3.0]).contains("strictly increasing"));
    // Per-segment shapes give G1 joins, which the builder accepts as asked.
    let shapes = HermiteShapes::PerSegment(vec![[motion::Shape::factor(1.0), motion::Shape::factor(2.0)]; 4]);
    let tr = Trajectory::through(&poses, &TIMES, &Velocities::CatmullRom, SegmentKind::Additive, &shapes).unwrap();
    assert!(!tr.joins().iter().all(|j| j.is_c1(1e-9)));
}

/// Sign alignment: a key pose given as `-S` is the same rigid motion, and the trajectory is the
/// same as with `S`.
#[test]
fn negated_key_poses_are_aligned() {
    let mut poses: Vec<Pose<f64>> = key_isometries().iter().map(Pose::from_na_isometry).collect();
    let plain =
        Trajectory::through(&poses, &TIMES, &Velocities::CatmullRom, SegmentKind::Additive, &HermiteShapes::unit())
            .unwrap();
    poses[2] = -&poses[2];
    poses[3] = -&poses[3];
    let flipped =
        Trajectory::through(&poses, &TIMES, &Velocities::CatmullRom, SegmentKind::Additive, &HermiteShapes::unit())
            .unwrap();
    assert_eq!(plain.key_poses(), flipped.key_poses());
    let mut again = poses.clone();
    align_signs(&mut again);
    assert_eq!(again, plain.key_poses());
}

/// The Jacobian of the tool point (and of its velocity and the space twist) at t = 1.7 with
/// respect to all 30 key-pose parameters and 5 key times, in one dual-number pass, against
/// central finite differences of the f64 trajectory rebuilt with each parameter moved by ±h
/// (key pose `S_i exp(±h ν_k / 2)`, key time `t_i ± h`): agreement to 1e-7 relative.
#[test]
fn jacobian_of_a_tool_point_matches_central_differences() {
    use motion::jacobian::key_sensitivity;
    use motion::velocity::velocity as vel;
    let poses: Vec<Pose<f64>> = key_isometries().iter().map(Pose::from_na_isometry).collect();
    let t = 1.7;
    for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
        let s = key_sensitivity::<35>(&poses, &TIMES, &Velocities::CatmullRom, kind, &HermiteShapes::unit(), t, &TOOL)
            .unwrap();
        // The value part is the f64 result.
        let tr = build(kind);
        let v0 = vel(tr.motion(), &t).unwrap();
        let (q0, _) = v0.body_point_velocity(&TOOL).unwrap();
        assert!(dist(&s.position.map(|x| x.re), &q0) < 1e-15);
        // Everything as one vector of 9 outputs: position, point velocity, Ω.
        let outputs = |p: &[Pose<f64>], times: &[f64]| -> [f64; 9] {
            let tr = Trajectory::through(p, times, &Velocities::CatmullRom, kind, &HermiteShapes::unit()).unwrap();
            let v = vel(tr.motion(), &t).unwrap();
            let (q, qv) = v.body_point_velocity(&TOOL).unwrap();
            let w = v.twist().angular;
            [q[0], q[1], q[2], qv[0], qv[1], qv[2], w[0], w[1], w[2]]
        };
        let ad: Vec<[f64; 35]> =
            s.position.iter().chain(&s.velocity).chain(&s.space_twist.angular.to_array()).map(|x| x.eps).collect();
        let scale = ad.iter().flatten().fold(0.0f64, |m, x| m.max(x.abs()));
        assert!(scale > 0.1, "a non-trivial Jacobian");
        let h = 1e-5;
        let mut worst = 0.0f64;
        for j in 0..35 {
            let moved = |sign: f64| {
                let mut p = poses.clone();
                let mut times = TIMES.to_vec();
                if j < 30 {
                    let (i, k) = (j / 6, j % 6);
                    let mut c = [0.0; 6];
                    c[k] = sign * h * 0.5;
                    let g = Twist { angular: Vec3::new(c[0], c[1], c[2]), linear: Vec3::new(c[3], c[4], c[5]) }
                        .to_bivector();
                    p[i] = p[i] * Pose::exp(&Pose::from(&g)).unwrap();
                } else {
                    times[j - 30] += sign * h;
                }
                outputs(&p, &times)
            };
            let (plus, minus) = (moved(1.0), moved(-1.0));
            for r in 0..9 {
                let fd = (plus[r] - minus[r]) / (2.0 * h);
                worst = worst.max((fd - ad[r][j]).abs() / scale);
            }
        }
        assert!(worst < 1e-7, "{kind}: worst relative difference {worst:e}");
        // The key times matter (t = 1.7 is inside the second segment [1, 2.5]).
        assert!(s.position.iter().any(|x| x.eps[31].abs() > 1e-3 && x.eps[32].abs() > 1e-3));
    }
}

/// `key_jacobian` (no const parameter, one single-direction pass per parameter, over
/// `Jet<f64>`) gives the derivatives of `key_sensitivity::<35>` (over `JetN<35>`), which the test
/// above checks against central differences: the same derivatives, to rounding (the two dual
/// number types order a few operations differently, so they agree to a few ulps, not bit for bit).
#[test]
fn key_jacobian_needs_no_const_parameter_and_equals_key_sensitivity() {
    use motion::jacobian::{key_jacobian, key_sensitivity};
    let poses: Vec<Pose<f64>> = key_isometries().iter().map(Pose::from_na_isometry).collect();
    let close = |a: &[f64], b: &[f64], what: &str| {
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= 1e-14 * (1.0 + y.abs()), "{what}: {x} vs {y}");
        }
    };
    for kind in [SegmentKind::Additive, SegmentKind::Multiplicative] {
        let shapes = HermiteShapes::unit();
        let s = key_sensitivity::<35>(&poses, &TIMES, &Velocities::CatmullRom, kind, &shapes, 1.7, &TOOL).unwrap();
        let j = key_jacobian(&poses, &TIMES, &Velocities::CatmullRom, kind, &shapes, 1.7, &TOOL).unwrap();
        close(&j.position, &s.position.map(|x| x.re), "position");
        close(&j.velocity, &s.velocity.map(|x| x.re), "velocity");
        assert_eq!(j.d_position.len(), 35);
        for k in 0..35 {
            close(&j.d_position[k], &s.position.map(|x| x.eps[k]), &format!("{kind} position {k}"));
            close(&j.d_velocity[k], &s.velocity.map(|x| x.eps[k]), &format!("{kind} velocity {k}"));
            let w = &s.space_twist;
            let want = [w.angular.x, w.angular.y, w.angular.z, w.linear.x, w.linear.y, w.linear.z].map(|x| x.eps[k]);
            close(&j.d_space_twist[k], &want, &format!("{kind} twist {k}"));
        }
    }
    let err =
        key_jacobian(&poses, &TIMES[..2], &Velocities::Zero, SegmentKind::Additive, &HermiteShapes::unit(), 0.5, &TOOL);
    assert!(matches!(err, Err(motion::trajectory::TrajectoryError::Input(_))));
}

/// `key_jacobian` over MPFR at 200 bits: equal to the f64 Jacobian to 1e-12 (the same
/// derivatives), and against central differences of the 200-bit trajectory with the key times
/// and the key poses moved by ±1e-20, to 1e-30 relative: derivatives far beyond f64, checked by
/// an independent route (differences need no dual numbers).
#[test]
fn key_jacobian_over_mpfr_matches_f64_and_high_precision_differences() {
    use algebra_core::{MpFloat, PrecisionGuard, Real};
    use motion::jacobian::key_jacobian;
    use motion::velocity::velocity as vel;
    let _bits = PrecisionGuard::new(200);
    let lo: Vec<Pose<f64>> = key_isometries().iter().map(Pose::from_na_isometry).collect();
    let m = |x: &f64| MpFloat::from_f64(*x);
    let poses: Vec<Pose<MpFloat>> = lo.iter().map(|p| p.map_scalar(&m)).collect();
    let times: Vec<MpFloat> = TIMES.iter().map(m).collect();
    let (t, tool) = (MpFloat::from_f64(1.7), TOOL.each_ref().map(m));
    let kind = SegmentKind::Multiplicative;
    let hi =
        key_jacobian(&poses, &times, &Velocities::CatmullRom, kind, &HermiteShapes::unit(), t.clone(), &tool).unwrap();
    let f = key_jacobian(&lo, &TIMES, &Velocities::CatmullRom, kind, &HermiteShapes::unit(), 1.7, &TOOL).unwrap();
    let scale = f.d_position.iter().flatten().fold(0.0f64, |a, x| a.max(x.abs()));
    for (a, b) in hi.d_position.iter().flatten().zip(f.d_position.iter().flatten()) {
        assert!((a.to_f64() - b).abs() < 1e-12 * scale, "{} vs {b}", a.to_f64());
    }
    let position = |p: &[Pose<MpFloat>], times: &[MpFloat]| -> [MpFloat; 3] {
        let tr = Trajectory::through(p, times, &Velocities::CatmullRom, kind, &HermiteShapes::unit()).unwrap();
        vel(tr.motion(), &t).unwrap().body_point_velocity(&tool).unwrap().0
    };
    let h = MpFloat::from_f64(1e-20);
    let two_h = h.clone() + h.clone();
    let mut worst = 0.0f64;
    // the key times (5) and the six twist directions of key pose 2
    let directions: Vec<usize> = (30..35).chain(12..18).collect();
    for j in directions {
        let moved = |sign: f64| {
            let (mut p, mut ts) = (poses.clone(), times.clone());
            let step = h.clone() * MpFloat::from_f64(sign);
            if j < 30 {
                let (i, k) = (j / 6, j % 6);
                let mut c: [MpFloat; 6] = std::array::from_fn(|_| MpFloat::from_f64(0.0));
                c[k] = step * MpFloat::from_f64(0.5);
                let [a, b, cc, d, e, g] = c;
                let tw = Twist { angular: Vec3::new(a, b, cc), linear: Vec3::new(d, e, g) }.to_bivector();
                p[i] = p[i].clone() * Pose::exp(&Pose::from(&tw)).unwrap();
            } else {
                ts[j - 30] = ts[j - 30].clone() + step;
            }
            position(&p, &ts)
        };
        let (plus, minus) = (moved(1.0), moved(-1.0));
        for r in 0..3 {
            let fd = (plus[r].clone() - minus[r].clone()) / two_h.clone();
            worst = worst.max((fd - hi.d_position[j][r].clone()).to_f64().abs() / scale);
        }
    }
    assert!(worst < 1e-30, "worst relative difference {worst:e}");
}
